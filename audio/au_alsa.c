/*
 * au_alsa: sound through ALSA (libasound2), the cabinet's sound card.
 *
 * Latency: the device's period is at most AU_ALSA_PERIOD_US (5 ms) and its
 * buffer at most AU_ALSA_BUFFER_US (20 ms), as close to those as it
 * allows (a device that cannot go that low, such as a dmix "default",
 * plays with what it can and describe() says so). The stream starts with
 * the first write and is kept full: after a start, silence fills the
 * buffer up to one tick's frames short of full, then each tick's frames
 * go in right after the tick, so a frame is heard at most a buffer's time
 * after its tick (and about buffer - tick ahead of the next write is all
 * the jitter the main loop may have).
 *
 * Writes never block (SND_PCM_NONBLOCK): frames that do not fit (the card's
 * clock runs slower than the tick clock, or a late tick was followed by
 * quick ones) are dropped and counted. An underrun (the buffer ran dry: a
 * tick came late) is recovered with snd_pcm_recover and counted, and the
 * stream starts again as above. Underruns that keep coming (AU_ALSA_RAISE_AT
 * within AU_ALSA_WINDOW ticks: the machine does not keep up with so small a
 * buffer, such as an emulated one or one busy with other work) double the
 * buffer, up to AU_ALSA_BUFFER_MAX_US, and write() says so (st->raised):
 * a steady sound a few ms later beats one broken up every second, as
 * sound servers do when they raise their watermark. A device that goes away (USB audio
 * unplugged: -ENODEV, or the stream's state DISCONNECTED) returns -ENODEV;
 * the app closes it and opens it again when it returns.
 */
#include "audio/au.h"

#include <alsa/asoundlib.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#define AU_ALSA_PERIOD_US 5000
#define AU_ALSA_BUFFER_US 20000
#define AU_ALSA_BUFFER_MAX_US 160000   /* the most the raises go to */
#define AU_ALSA_RAISE_AT 4             /* underruns within a window that raise */
#define AU_ALSA_WINDOW 300             /* ticks (5 s at 60 Hz) */
#define AU_ALSA_TICK 60                /* ticks per second: a tick's frames */

struct au_dev {
	snd_pcm_t *pcm;
	uint32_t rate;
	snd_pcm_uframes_t period, buffer;
	int running;                   /* prefilled since the last (re)start */
	int16_t *zero;                 /* buffer frames of silence */
	unsigned int buffer_us;        /* the buffer asked for (raised by underruns) */
	uint32_t window, window_xruns; /* writes and underruns in this window */
	char arg[64];
	char desc[320];
};

/* The hardware parameters: the period at most 5 ms (or a sixteenth of a
 * raised buffer) and the buffer at most d->buffer_us when the device
 * allows (limit 1), else as it gives them (limit 0). 0 or a negative ALSA
 * error. */
static int alsa_hw(struct au_dev *d, int limit, char *why, size_t whylen)
{
	snd_pcm_hw_params_t *hw;
	unsigned int period_us = d->buffer_us / 16 > AU_ALSA_PERIOD_US ? d->buffer_us / 16
								     : AU_ALSA_PERIOD_US;
	snd_pcm_uframes_t pmax = (snd_pcm_uframes_t)((uint64_t)d->rate * period_us / 1000000u);
	snd_pcm_uframes_t bmax = (snd_pcm_uframes_t)((uint64_t)d->rate * d->buffer_us / 1000000u);
	unsigned int rate = d->rate;
	int dir = 0, rc;

	snd_pcm_hw_params_alloca(&hw);
	rc = snd_pcm_hw_params_any(d->pcm, hw);
	if (rc == 0)
		rc = snd_pcm_hw_params_set_access(d->pcm, hw, SND_PCM_ACCESS_RW_INTERLEAVED);
	if (rc == 0)
		rc = snd_pcm_hw_params_set_format(d->pcm, hw, SND_PCM_FORMAT_S16_LE);
	if (rc == 0)
		rc = snd_pcm_hw_params_set_channels(d->pcm, hw, 2);
	if (rc == 0)
		rc = snd_pcm_hw_params_set_rate_resample(d->pcm, hw, 1);
	if (rc == 0)
		rc = snd_pcm_hw_params_set_rate(d->pcm, hw, rate, 0);
	if (rc < 0) {
		snprintf(why, whylen, "no 16-bit stereo at %u Hz: %s", d->rate, snd_strerror(rc));
		return rc;
	}
	if (limit) {
		rc = snd_pcm_hw_params_set_buffer_size_max(d->pcm, hw, &bmax);
		if (rc == 0)
			rc = snd_pcm_hw_params_set_period_size_max(d->pcm, hw, &pmax, &dir);
		if (rc == 0)
			rc = snd_pcm_hw_params_set_buffer_size_near(d->pcm, hw, &bmax);
		if (rc == 0)
			rc = snd_pcm_hw_params_set_period_size_near(d->pcm, hw, &pmax, &dir);
		if (rc < 0)
			return rc;
	}
	rc = snd_pcm_hw_params(d->pcm, hw);
	if (rc < 0) {
		snprintf(why, whylen, "hardware parameters: %s", snd_strerror(rc));
		return rc;
	}
	snd_pcm_hw_params_get_period_size(hw, &d->period, &dir);
	snd_pcm_hw_params_get_buffer_size(hw, &d->buffer);
	return 0;
}

static int alsa_sw(struct au_dev *d)
{
	snd_pcm_sw_params_t *sw;
	int rc;

	snd_pcm_sw_params_alloca(&sw);
	rc = snd_pcm_sw_params_current(d->pcm, sw);
	/* start with the first write (the prefill), wake for a period */
	if (rc == 0)
		rc = snd_pcm_sw_params_set_start_threshold(d->pcm, sw, 1);
	if (rc == 0)
		rc = snd_pcm_sw_params_set_avail_min(d->pcm, sw, d->period);
	if (rc == 0)
		rc = snd_pcm_sw_params(d->pcm, sw);
	return rc;
}

/* libasound's own messages ("ALSA lib confmisc.c:855: cannot find card
 * '0'") go nowhere: a cabinet without a card looks for one every second,
 * and what failed is said once, by the app, with snd_strerror's reason. */
__attribute__((format(printf, 5, 6)))
static void alsa_quiet(const char *file, int line, const char *fn, int err, const char *fmt, ...)
{
	(void)file;
	(void)line;
	(void)fn;
	(void)err;
	(void)fmt;
}

/* -ENODEV for errors that mean the device is gone or unusable now. */
static int alsa_gone(int rc)
{
	return rc == -ENODEV || rc == -ENOENT || rc == -EBADFD || rc == -ENXIO || rc == -EIO ||
	       rc == -ENOTTY;
}

/* d->desc from the sizes the device took. */
static void alsa_desc(struct au_dev *d)
{
	const char *note = "";

	if (d->buffer_us > AU_ALSA_BUFFER_US)
		note = " (raised: underruns kept coming with a smaller one)";
	else if (d->period * 1000000ull > (uint64_t)AU_ALSA_PERIOD_US * d->rate ||
		 d->buffer * 1000000ull > (uint64_t)AU_ALSA_BUFFER_US * d->rate)
		note = " (the device allows no less than this: above 5 ms / 20 ms; a "
		       "direct device, plughw:CARD, goes lower)";
	snprintf(d->desc, sizeof(d->desc),
		 "alsa %s: %u Hz, period %lu frames (%.1f ms), buffer %lu frames (%.1f ms)%s",
		 d->arg, d->rate, (unsigned long)d->period, d->period * 1000.0 / d->rate,
		 (unsigned long)d->buffer, d->buffer * 1000.0 / d->rate, note);
}

/* The hardware and software parameters at d->buffer_us (the device's own
 * sizes if it refuses those), and the silence for a prefill. 0 or a
 * negative error, with why set when there is more to say than the code. */
static int alsa_setup(struct au_dev *d, char *why, size_t whylen)
{
	int16_t *zero;
	int rc = alsa_hw(d, 1, why, whylen);

	if (rc < 0) {
		why[0] = '\0';
		rc = alsa_hw(d, 0, why, whylen);   /* the device's own sizes */
	}
	if (rc == 0)
		rc = alsa_sw(d);
	if (rc < 0)
		return rc;
	zero = calloc(d->buffer * 2, sizeof(int16_t));
	if (!zero)
		return -ENOMEM;
	free(d->zero);
	d->zero = zero;
	return 0;
}

static int alsa_open(const char *arg, uint32_t rate, struct au_dev **out, char *why,
		     size_t whylen)
{
	struct au_dev *d = calloc(1, sizeof(*d));
	int rc;

	if (!d) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	d->rate = rate;
	snd_lib_error_set_handler(alsa_quiet);
	rc = snd_pcm_open(&d->pcm, arg, SND_PCM_STREAM_PLAYBACK, SND_PCM_NONBLOCK);
	if (rc < 0) {
		snprintf(why, whylen, "%s", snd_strerror(rc));
		free(d);
		/* every failure to find a card: play silent, look again later */
		return -ENODEV;
	}
	d->buffer_us = AU_ALSA_BUFFER_US;
	snprintf(d->arg, sizeof(d->arg), "%s", arg);
	rc = alsa_setup(d, why, whylen);
	if (rc < 0) {
		if (why[0] == '\0')
			snprintf(why, whylen, "%s", snd_strerror(rc));
		snd_pcm_close(d->pcm);
		free(d->zero);
		free(d);
		return alsa_gone(rc) ? -ENODEV : rc < 0 ? rc : -EIO;
	}
	alsa_desc(d);
	*out = d;
	return 0;
}

/* Writes n frames of buf, what fits; returns the frames written or a
 * negative ALSA error. */
static snd_pcm_sframes_t alsa_put(struct au_dev *d, const int16_t *buf, snd_pcm_uframes_t n)
{
	snd_pcm_uframes_t done = 0;

	while (done < n) {
		snd_pcm_sframes_t w = snd_pcm_writei(d->pcm, buf + 2 * done, n - done);
		if (w == -EAGAIN)
			break;                 /* full */
		if (w < 0)
			return w;
		done += (snd_pcm_uframes_t)w;
	}
	return (snd_pcm_sframes_t)done;
}

/* After a (re)start: silence up to one tick short of a full buffer. */
static int alsa_prefill(struct au_dev *d, uint32_t frames, struct au_status *st)
{
	snd_pcm_uframes_t fill = d->buffer > frames ? d->buffer - frames : 0;
	snd_pcm_sframes_t w = fill ? alsa_put(d, d->zero, fill) : 0;

	if (w < 0)
		return (int)w;
	st->delay = w;
	d->running = 1;
	return 0;
}

/* After a write: AU_ALSA_RAISE_AT underruns within a window of
 * AU_ALSA_WINDOW writes double the buffer (up to AU_ALSA_BUFFER_MAX_US);
 * the stream starts again with the next write. 0, or -ENODEV when the
 * device will not take new parameters (it is closed and opened again). */
static int alsa_raise(struct au_dev *d, struct au_status *st)
{
	char why[160] = "";
	int rc;

	d->window_xruns += st->underruns;
	if (++d->window < AU_ALSA_WINDOW && d->window_xruns < AU_ALSA_RAISE_AT)
		return 0;
	/* not when the device's own buffer is that large already (dmix) */
	rc = d->window_xruns >= AU_ALSA_RAISE_AT && d->buffer_us < AU_ALSA_BUFFER_MAX_US &&
	     d->buffer * 1000000ull < (uint64_t)d->buffer_us * 2 * d->rate;
	d->window = 0;
	d->window_xruns = 0;
	if (!rc)
		return 0;
	d->buffer_us *= 2;
	snd_pcm_drop(d->pcm);
	rc = snd_pcm_hw_free(d->pcm);
	if (rc == 0)
		rc = alsa_setup(d, why, sizeof(why));
	if (rc < 0)
		return -ENODEV;
	d->running = 0;
	alsa_desc(d);
	st->raised = 1;
	return 0;
}

static int alsa_write(struct au_dev *d, const int16_t *buf, uint32_t frames,
		      struct au_status *st)
{
	snd_pcm_sframes_t delay = 0, w = 0;
	int rc = 0;

	memset(st, 0, sizeof(*st));
	st->delay = -1;
	for (int tries = 0; tries < 2; tries++) {
		switch (snd_pcm_state(d->pcm)) {
		case SND_PCM_STATE_DISCONNECTED:
			return -ENODEV;
		case SND_PCM_STATE_XRUN:
			rc = -EPIPE;
			break;
		case SND_PCM_STATE_SUSPENDED:
			rc = -ESTRPIPE;
			break;
		default:
			rc = 0;
			break;
		}
		if (rc == 0 && !d->running)
			rc = alsa_prefill(d, frames, st);
		else if (rc == 0 && snd_pcm_delay(d->pcm, &delay) == 0)
			st->delay = delay;
		if (rc == 0) {
			w = alsa_put(d, buf, frames);
			rc = w < 0 ? (int)w : 0;
		}
		if (rc == 0)
			break;
		if (alsa_gone(rc))
			return -ENODEV;
		/* an underrun (or a suspend): recover, start again */
		if (rc == -EPIPE)
			st->underruns++;
		rc = snd_pcm_recover(d->pcm, rc, 1);
		if (rc < 0)
			return alsa_gone(rc) ? -ENODEV : rc;
		d->running = 0;
		w = 0;
	}
	if (rc < 0)
		return alsa_gone(rc) ? -ENODEV : rc;
	st->dropped = frames - (uint32_t)w;
	return alsa_raise(d, st);
}

static void alsa_close(struct au_dev *d)
{
	if (!d)
		return;
	/* what was written plays out only if the device is still there; a
	 * closing cabinet need not wait for it */
	snd_pcm_drop(d->pcm);
	snd_pcm_close(d->pcm);
	free(d->zero);
	free(d);
}

static const char *alsa_describe(struct au_dev *d)
{
	return d->desc;
}

/* `arcaded devices`: every card and its playback devices. */
static int alsa_list(FILE *out)
{
	int card = -1, n = 0;

	snd_lib_error_set_handler(alsa_quiet);
	while (snd_card_next(&card) == 0 && card >= 0) {
		char hw[16], *name = NULL, *lname = NULL;
		snd_ctl_t *ctl;
		int dev = -1;

		snprintf(hw, sizeof(hw), "hw:%d", card);
		snd_card_get_name(card, &name);
		snd_card_get_longname(card, &lname);
		fprintf(out, "sound: card %d: %s (%s)\n", card, name ? name : "?",
			lname ? lname : "?");
		free(name);
		free(lname);
		n++;
		if (snd_ctl_open(&ctl, hw, 0) < 0)
			continue;
		while (snd_ctl_pcm_next_device(ctl, &dev) == 0 && dev >= 0) {
			snd_pcm_info_t *info;
			snd_pcm_info_alloca(&info);
			snd_pcm_info_set_device(info, (unsigned int)dev);
			snd_pcm_info_set_subdevice(info, 0);
			snd_pcm_info_set_stream(info, SND_PCM_STREAM_PLAYBACK);
			if (snd_ctl_pcm_info(ctl, info) < 0)
				continue;     /* capture only */
			fprintf(out, "sound:   plughw:%d,%d %s (audio.device = plughw:%d,%d)\n", card,
				dev, snd_pcm_info_get_name(info), card, dev);
		}
		snd_ctl_close(ctl);
	}
	if (n == 0)
		fprintf(out, "sound: no sound cards (the cabinet plays silent)\n");
	return 0;
}

const struct au_backend au_alsa = {
	.name = "alsa",
	.open = alsa_open,
	.write = alsa_write,
	.close = alsa_close,
	.describe = alsa_describe,
	.list = alsa_list,
	.live = 1,
};
