/*
 * dp_null: the headless display. Accepts every frame and shows nothing, so
 * the daemon and the script tests run without any output device.
 */
#include "display/dp.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct dp {
	unsigned long frames;   /* presents accepted (wraps; informative only) */
};

static int null_open(const struct dp_config *cfg, struct dp **out, char *why, size_t whylen)
{
	(void)cfg;
	*out = calloc(1, sizeof(**out));
	if (!*out) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	return 0;
}

static void null_set_palette(struct dp *d, const uint8_t rgb[256][3])
{
	(void)d;
	(void)rgb;
}

static int null_present(struct dp *d, const uint8_t *px, int w, int h, int pitch)
{
	(void)px;
	if (w < 1 || h < 1 || pitch < w)
		return -EINVAL;
	d->frames++;
	return 0;
}

static void null_close(struct dp *d)
{
	free(d);
}

static const char *null_describe(struct dp *d)
{
	(void)d;
	return "null";
}

const struct dp_backend dp_null = {
	.name = "null",
	.open = null_open,
	.set_palette = null_set_palette,
	.present = null_present,
	.close = null_close,
	.describe = null_describe,
	.flags = DP_SHOWS_NOTHING,
};
