/*
 * au_null: no sound. Accepts every tick's frames and plays nothing, so a
 * cabinet without a sound card, and scripts and replays, run the same
 * loop.
 */
#include "audio/au.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

struct au_dev {
	uint64_t frames;               /* written (informative only) */
};

static int null_open(const char *arg, uint32_t rate, struct au_dev **out, char *why,
		     size_t whylen)
{
	(void)arg;
	(void)rate;
	*out = calloc(1, sizeof(**out));
	if (!*out) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	return 0;
}

static int null_write(struct au_dev *d, const int16_t *buf, uint32_t frames,
		      struct au_status *st)
{
	(void)buf;
	d->frames += frames;
	memset(st, 0, sizeof(*st));
	st->delay = 0;
	return 0;
}

static void null_close(struct au_dev *d)
{
	free(d);
}

static const char *null_describe(struct au_dev *d)
{
	(void)d;
	return "null (silent)";
}

const struct au_backend au_null = {
	.name = "null",
	.open = null_open,
	.write = null_write,
	.close = null_close,
	.describe = null_describe,
};
