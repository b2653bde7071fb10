/*
 * out: the cabinet's outputs follow the game, once per tick.
 *
 * Lamps and meters: each input device with outputs (in_backend.outputs:
 * GPIO's coin meter and start lamp, input/gpo.h) gets the game's coins,
 * credits and whether a game is being played. A device whose outputs went
 * away is dropped like one whose read did (its controls released,
 * reopened later).
 *
 * Sound: each tick's mixed frames (app/hear.h) go to the sound output
 * (audio/au.h, reached only through its table) right after the tick. The
 * output is chosen by its spec (audio.output): "auto" is ALSA's
 * audio.device on a live cabinet and nothing for scripts and replays. A
 * live output that cannot open (no sound card) or goes away (USB audio
 * unplugged) is not an error: the cabinet plays silent, says so once, and
 * tries to open it again every OUT_AUDIO_RETRY_NS while the game goes on;
 * when it opens, that is said too.
 */
#ifndef ARCADED_APP_OUT_H
#define ARCADED_APP_OUT_H

#include <stdint.h>

#include "config/cfg.h"

struct sim;
struct slot_set;
struct stats;
struct hear;
struct au_backend;
struct au_dev;

#define OUT_AUDIO_RETRY_NS 1000000000ull

struct out_audio {
	const struct au_backend *be;   /* NULL: no output at all */
	struct au_dev *dev;            /* NULL: closed (silent), retried at retry_ns */
	char arg[CFG_PATH_MAX];        /* the backend's device or file */
	uint32_t rate;
	uint64_t retry_ns;             /* UINT64_MAX: not before out_audio_start */
	int silent_said;               /* "playing silent" was logged for this loss */
};

/* Drives every open slot's outputs for the state of s. */
void out_update(struct slot_set *set, const struct sim *s);

/* Opens the sound output c->audio names at rate (headless: "auto" is no
 * output). 0, or -EINVAL for a spec that names no output (logged); a live
 * output that does not open is not an error (logged once, retried). A
 * live output of the daemon (not headless) is only chosen here: its
 * device is opened by out_audio_start, after the first frame, and is
 * silent until then. */
int out_audio_open(struct out_audio *o, const struct cfg *c, uint32_t rate, int headless);

/* Opens the live output out_audio_open left for later (logged as a
 * retry is); nothing when there is none, or it is open. */
void out_audio_start(struct out_audio *o);

/* Plays h's frames of this tick; the input-to-sound latency of a sound
 * that began (h->onset) and the output's underruns and drops go to st. A
 * live output that went away is closed (logged once) and retried. */
void out_audio_play(struct out_audio *o, const struct hear *h, struct stats *st);

/* Closes the output (a WAV file gets its sizes); safe when none is open. */
void out_audio_close(struct out_audio *o);

#endif
