/*
 * au_wav: a WAV file (RIFF, PCM, 2 channels, 16-bit little-endian) of
 * everything the cabinet plays, for tests and for making clips
 * (`--audio wav:FILE`). Written as fast as the loop runs (no clock). The
 * RIFF and data sizes are written at open as for an empty file and set
 * right about once a second and at close, so a file cut short by a crash
 * still says how much of it is whole up to that point.
 */
#include "audio/au.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine/core/le.h"
#include "input/io.h"

#define WAV_HEADER 44
#define WAV_SIZES_EVERY 60             /* writes between size updates */

struct au_dev {
	int fd;
	uint32_t rate;
	uint64_t bytes;                /* sample bytes written */
	uint32_t since;                /* writes since the sizes were set */
	int err;                       /* first failure, returned from then on */
	char desc[300];
};

static void wav_header(uint8_t h[WAV_HEADER], uint32_t rate, uint64_t bytes)
{
	uint32_t data = bytes > 0xffffffffu - 36 ? 0xffffffffu - 36 : (uint32_t)bytes;

	memcpy(h, "RIFF", 4);
	le_put32(h + 4, 36 + data);
	memcpy(h + 8, "WAVEfmt ", 8);
	le_put32(h + 16, 16);          /* fmt chunk size */
	le_put16(h + 20, 1);           /* PCM */
	le_put16(h + 22, 2);           /* channels */
	le_put32(h + 24, rate);
	le_put32(h + 28, rate * 4);    /* bytes per second */
	le_put16(h + 32, 4);           /* bytes per frame */
	le_put16(h + 34, 16);          /* bits per sample */
	memcpy(h + 36, "data", 4);
	le_put32(h + 40, data);
}

/* Sets the header's sizes to what is written. 0 or -errno. */
static int wav_sizes(struct au_dev *d)
{
	uint8_t h[WAV_HEADER];

	wav_header(h, d->rate, d->bytes);
	d->since = 0;
	errno = 0;
	if (pwrite(d->fd, h, WAV_HEADER, 0) != WAV_HEADER)
		return errno ? -errno : -EIO;
	return 0;
}

static int wav_open(const char *arg, uint32_t rate, struct au_dev **out, char *why,
		    size_t whylen)
{
	uint8_t h[WAV_HEADER];
	struct au_dev *d = calloc(1, sizeof(*d));
	int rc;

	if (!d) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	d->rate = rate;
	d->fd = open(arg, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (d->fd < 0) {
		rc = -errno;
		snprintf(why, whylen, "%s", strerror(-rc));
		free(d);
		return rc;
	}
	wav_header(h, rate, 0);
	rc = io_write_all(d->fd, h, WAV_HEADER);
	if (rc < 0) {
		snprintf(why, whylen, "%s", strerror(-rc));
		close(d->fd);
		free(d);
		return rc;
	}
	snprintf(d->desc, sizeof(d->desc), "wav %s: %u Hz, 2 channels, 16-bit", arg, rate);
	*out = d;
	return 0;
}

static int wav_write(struct au_dev *d, const int16_t *buf, uint32_t frames,
		     struct au_status *st)
{
	uint8_t b[4096];
	uint32_t n = 2 * frames, i = 0;

	memset(st, 0, sizeof(*st));
	st->delay = 0;
	if (d->err)
		return d->err;
	while (i < n) {
		uint32_t m = 0;
		for (; m < sizeof(b) / 2 && i < n; m++, i++)
			le_put16(b + 2 * m, (uint16_t)buf[i]);
		d->err = io_write_all(d->fd, b, 2 * (size_t)m);
		if (d->err)
			return d->err;
		d->bytes += 2 * (uint64_t)m;
	}
	if (++d->since >= WAV_SIZES_EVERY)
		d->err = wav_sizes(d);
	return d->err;
}

static void wav_close(struct au_dev *d)
{
	if (!d)
		return;
	if (!d->err)
		wav_sizes(d);
	close(d->fd);
	free(d);
}

static const char *wav_describe(struct au_dev *d)
{
	return d->desc;
}

const struct au_backend au_wav = {
	.name = "wav",
	.open = wav_open,
	.write = wav_write,
	.close = wav_close,
	.describe = wav_describe,
};
