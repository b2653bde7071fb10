/*
 * dp: the ordered backend list, the automatic choice and the emergency
 * restore (contracts in dp.h). Backends live in dp_<name>.c.
 */
#include "display/con.h"
#include "display/dp.h"
#include "display/dp_int.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* Automatic choice tries these in order. */
static const struct dp_backend *const dp_backends[] = { &dp_kms, &dp_fbdev, &dp_term, &dp_file,
								     &dp_null };

#define DP_NBACKENDS (sizeof(dp_backends) / sizeof(dp_backends[0]))

/* Appends "name: reason" to the list of skipped backends in why. */
static void dp_skipped(char *why, size_t whylen, const char *name, const char *reason)
{
	size_t n = strnlen(why, whylen);

	if (n + 1 < whylen)
		snprintf(why + n, whylen - n, "%s%s: %s", n ? "; " : "", name, reason);
}

int dp_open(const struct dp_config *cfg, const struct dp_backend **be, struct dp **out,
	    char *why, size_t whylen)
{
	char reason[512];
	size_t i;
	int rc;

	*be = NULL;
	*out = NULL;
	if (whylen)
		why[0] = '\0';
	if (cfg->backend && cfg->backend[0] && strcmp(cfg->backend, "auto") != 0) {
		for (i = 0; i < DP_NBACKENDS; i++) {
			if (strcmp(cfg->backend, dp_backends[i]->name) == 0)
				break;
		}
		if (i == DP_NBACKENDS) {
			snprintf(why, whylen, "unknown display backend \"%s\"", cfg->backend);
			return -EINVAL;
		}
		rc = dp_backends[i]->open(cfg, out, why, whylen);
		if (rc == 0)
			*be = dp_backends[i];
		return rc;
	}

	/* auto: on success why lists the backends skipped, and why. */
	for (i = 0; i < DP_NBACKENDS; i++) {
		const struct dp_backend *b = dp_backends[i];

		reason[0] = '\0';
		if (b == &dp_term && !isatty(1)) {
			dp_skipped(why, whylen, b->name, "stdout is not a terminal");
			continue;
		}
		if (b == &dp_file && (!cfg->file || !cfg->file[0])) {
			dp_skipped(why, whylen, b->name, "no file configured");
			continue;
		}
		rc = b->open(cfg, out, reason, sizeof(reason));
		if (rc == 0) {
			*be = b;
			return 0;
		}
		dp_skipped(why, whylen, b->name, reason[0] ? reason : strerror(-rc));
	}
	/* The null display only fails without memory. */
	return -ENOMEM;
}

int dp_nodes(const char **out, int max)
{
	int n = 0;

	for (size_t i = 0; i < DP_NBACKENDS && n < max; i++)
		if (dp_backends[i]->node)
			out[n++] = dp_backends[i]->node;
	return n;
}

int dp_open_stand_in(const struct dp_config *cfg, const struct dp_backend **be, struct dp **out)
{
	char why[64];

	*be = NULL;
	*out = NULL;
	for (size_t i = 0; i < DP_NBACKENDS; i++)
		if ((dp_backends[i]->flags & DP_SHOWS_NOTHING) &&
		    dp_backends[i]->open(cfg, out, why, sizeof(why)) == 0) {
			*be = dp_backends[i];
			return 0;
		}
	return -ENOMEM;
}

void dp_emergency_restore(void)
{
	con_emergency();
	dp_term_emergency();
}
