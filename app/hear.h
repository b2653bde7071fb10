/*
 * hear: what the cabinet plays after each tick: the game's sounds mixed
 * into one tick of stereo samples (engine/sound/mix.h) and its audio hash.
 * The daemon (app/app.c) and the cross-build replayer
 * (tests/xbuild/replay.c) both mix through here, so their audio hashes are
 * the same by construction. Only engine code is called: no platform
 * headers; where the samples go is app/out.c's business.
 */
#ifndef ARCADED_APP_HEAR_H
#define ARCADED_APP_HEAR_H

#include <stdint.h>

#include "engine/sound/mix.h"

struct sim;
struct snd_set;

/* A sample at or above this (in magnitude; -40 dBFS) is audible: where a
 * new sound's first audible sample is looked for (latency). */
#define HEAR_AUDIBLE 328

struct hear {
	const struct snd_set *set;     /* borrowed: the content's sounds */
	uint32_t rate;                 /* output frames per second */
	int16_t buf[2 * MIX_FRAMES_MAX]; /* the last tick's frames, left, right */
	uint32_t frames;
	uint64_t hash;                 /* mix_hash of buf */
	int32_t onset;                 /* a sound began this tick: its first audible
					  frame in buf; -1 none */
};

/* Prepares h to mix set's sounds at rate (MIX_RATE_MIN..MIX_RATE_MAX). */
void hear_init(struct hear *h, const struct snd_set *set, uint32_t rate);

/* After a tick of s (and of under, the attract demo's sim drawn under it,
 * or NULL): mixes the tick's frames (s->tick - 1 is the tick that ran, at
 * s's master volume), hashes them and finds the onset. */
void hear_tick(struct hear *h, const struct sim *s, const struct sim *under);

#endif
