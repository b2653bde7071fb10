/*
 * snd: the sounds the game plays, as mono 16-bit samples at their own
 * rate, and where they come from: Doom's sound lumps (DS*, "DMX" format)
 * in the loaded WADs, or the project's own synthesizer (syn.h).
 *
 * A set holds one sound per enum sfx_id (sfx.h). Every sound of a set is
 * playable: a WAD that lacks a lump, or whose lump is malformed, gets the
 * built-in sound in its place (the malformed lump is reported by name and
 * reason). The set's hash covers every sound's rate and samples, so a
 * recording can say which sounds its audio hashes were made with.
 *
 * The engine does no I/O: WADs come in memory (engine/map/wad.h). Nothing
 * here logs.
 */
#ifndef ARCADED_ENGINE_SND_H
#define ARCADED_ENGINE_SND_H

#include <stddef.h>
#include <stdint.h>

#include "engine/sound/sfx.h"

struct wad;

/* Sample rates a sound may have (a DS lump outside them is refused). */
#define SND_RATE_MIN 1000
#define SND_RATE_MAX 96000
/* Longest sound, in samples (about 11 s at 44.1 kHz; Doom's longest are a
 * few seconds): a length field beyond it is refused, not trusted. */
#define SND_LEN_MAX (1u << 19)

/* One sound: len mono samples at rate Hz. */
struct snd {
	const int16_t *pcm;            /* owned by the set; NULL when len is 0 */
	uint32_t len;
	uint32_t rate;
};

struct snd_set {
	struct snd s[SFX_COUNT];       /* s[SFX_NONE] is empty */
	uint8_t from_lump[SFX_COUNT];  /* 1: the WAD's lump, 0: built-in */
	int16_t *store;                /* every sound's samples, owned */
	/* snd_set_hash's: made on its first call, not at load (2 ms for
	 * Freedoom 1's sounds, serial by nature, and only a recording needs it) */
	uint64_t lazy_hash;
	int hashed;
};

/* ---- Doom sound lumps ("DMX", format 3) ------------------------------ */

/* What a DS lump holds: `count` 8-bit unsigned samples (128 is silence)
 * at `rate` Hz, pointing into the lump. */
struct snd_ds {
	uint32_t rate;
	uint32_t count;
	const uint8_t *u8;
};

/* Parses a DS lump of len bytes: little-endian uint16 format (3),
 * uint16 sample rate, uint32 sample count, then the samples, of which
 * DMX (and so Doom) skips 16 padding bytes at each end. 0 and *out, or
 * -EINVAL with the reason appended to why (msg_cat): "5 bytes, shorter
 * than the 8-byte header", "format 0, not 3 (Doom's digital sound)",
 * "sample rate 0 out of range 1000..96000", "header says 40000 samples,
 * the lump holds 12000", "20 samples: less than the 32 padding bytes and
 * one sample", "600000 samples, more than 524288". out->u8 points into p. */
int snd_ds_parse(const uint8_t *p, size_t len, struct snd_ds *out, char *why, size_t whylen);

/* A DS lump's samples as 16-bit: (u8 - 128) * 256, so 0 stays silence and
 * the full 8-bit range fills the 16-bit one. out holds d->count values. */
void snd_ds_decode(const struct snd_ds *d, int16_t *out);

/* ---- sets --------------------------------------------------------------- */

/* The built-in set: every sound synthesized (syn.h). 0 and a new set, or
 * -ENOMEM. Always the same samples (the synthesizer is integer only). */
int snd_builtin(struct snd_set **out);

/* The set for the WADs in w: each sound with a lump name (sfx.h) takes
 * the last lump of that name (later files override, as for maps), when it
 * parses; every other sound is built in. Each malformed lump is appended
 * to report ("DSPEDTH: format 0, not 3 (Doom's digital sound); ...") and
 * its built-in sound used. 0 and a new set, or -ENOMEM. */
int snd_load_wad(const struct wad *w, struct snd_set **out, char *report, size_t reportlen);

/* The hash of sounds s[0..n): FNV-1a of each one's rate, length and
 * samples as little-endian integers. */
uint64_t snd_hash(const struct snd *s, int n);

/* The hash of every sound of set (snd_hash over s[0..SFX_COUNT)), which
 * recordings store so a replay knows it mixes the same sounds. Made on
 * the first call and kept: call it from one thread at a time (the
 * samples are only read, so a mixer may play them meanwhile). */
uint64_t snd_set_hash(struct snd_set *set);

/* Length of sound s in game ticks (60 Hz), rounded up, counting one
 * sample more than it has (the resampler reads one past a sample to
 * interpolate); 0 for an empty sound, at most 65535. */
uint16_t snd_ticks(const struct snd *s);

/* NULL-safe. */
void snd_free(struct snd_set *set);

#endif
