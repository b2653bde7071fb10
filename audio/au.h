/*
 * au: sound outputs. Every backend is one file (au_alsa.c, au_wav.c,
 * au_null.c) implementing struct au_backend; au.c holds the list and
 * picks one by its spec. Only backend files include Linux or library
 * headers (au_alsa.c: libasound2).
 *
 * An output takes each tick's frames as they are mixed (app/hear.h):
 * interleaved left, right, signed 16-bit, at the rate it was opened with,
 * written right after the tick without blocking the main loop.
 */
#ifndef ARCADED_AUDIO_AU_H
#define ARCADED_AUDIO_AU_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

struct au_dev;

/* What one write did. */
struct au_status {
	int64_t delay;                 /* frames the device plays before the first frame
					  written (latency), -1 unknown */
	uint32_t underruns;            /* underruns found and recovered from (each one
					  restarts the stream) */
	uint32_t dropped;              /* frames that did not fit and were left out */
	int raised;                    /* 1: the device's buffer was made larger after
					  underruns (describe() has the new sizes) */
};

struct au_backend {
	const char *name;
	/* Opens output arg (ALSA device name, WAV file path; "" for null) at
	 * rate frames per second, stereo 16-bit. 0, or -errno with a reason
	 * in why; -ENODEV: no such device now (a sound card may come later). */
	int (*open)(const char *arg, uint32_t rate, struct au_dev **out, char *why, size_t whylen);
	/* Writes frames (2 * frames samples) without blocking. 0, or -ENODEV
	 * when the device went away (close it; it may be opened again when
	 * it returns), or another -errno. */
	int (*write)(struct au_dev *d, const int16_t *buf, uint32_t frames, struct au_status *st);
	/* NULL-safe; finishes what open began (a WAV file's sizes). */
	void (*close)(struct au_dev *d);
	/* One line: "alsa default: 48000 Hz, period 240 frames (5.0 ms), buffer 960
	 * frames (20.0 ms)". */
	const char *(*describe)(struct au_dev *d);
	/* Optional (NULL: none): lists the devices it could open, one line each
	 * ("sound: hw:0,0 HDA Intel PCH: ALC892 Analog"), for `arcaded devices`.
	 * 0 or -errno. */
	int (*list)(FILE *out);
	/* 1: a device that plays in real time, which may go away and come back
	 * (the app retries its open); 0: a file or nothing. */
	int live;
};

extern const struct au_backend au_alsa, au_wav, au_null;

/* The backends, in the order `arcaded devices` lists them; NULL-terminated. */
extern const struct au_backend *const au_backends[];

/* The backend a spec names and its argument: "alsa" (device `device`),
 * "alsa:NAME", "wav:FILE", "null". 0 with *be and *arg (pointing into spec
 * or device), or -EINVAL with the reason in why ("unknown sound output
 * \"oss\" (alsa, wav:FILE, null)", "wav needs a file: wav:FILE"). */
int au_parse(const char *spec, const char *device, const struct au_backend **be,
	     const char **arg, char *why, size_t whylen);

#endif
