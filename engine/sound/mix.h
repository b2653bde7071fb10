/*
 * mix: the mixer. Exactly one game tick of stereo samples per call, from
 * the voices the game describes (engine/game/g_sound.c: g_sound_voices),
 * in integer arithmetic only, so a replay reproduces every sample on every
 * compiler and CPU and each tick's buffer can be hashed (mix_hash).
 *
 * Timing: tick t covers output frames F(t) .. F(t + 1) - 1, where
 * F(t) = floor(t * rate / 60): 800 frames a tick at 48 kHz; at a rate that
 * does not divide by 60 (44,056 Hz, say) the remainder is carried by the
 * floor, so ticks are 734 or 735 frames and none is lost. A voice that
 * started `age` ticks before tick t has played F(t) - F(t - age) frames.
 *
 * Resampling: output frame j of a voice reads the sound at position
 * j * src / rate (src: the sound's rate), exactly, as an integer part i
 * and a remainder r < rate, kept by additions only (no division per
 * sample); the sample is the linear interpolation of samples i and i + 1
 * (0 past the end) with weight w = floor(r * 65536 / rate):
 * s[i] + (s[i+1] - s[i]) * w / 65536, rounded down.
 *
 * Gains: each voice has a left and a right gain 0..MIX_GAIN_MAX, as
 * Doom's sound code gives them (g_sound.c); a channel's sample is
 * sum(sample * gain) * volume / (MIX_GAIN_MAX * MIX_VOLUME_MAX), rounded
 * towards zero, then clamped to -32768..32767: saturation, never
 * wrap-around.
 */
#ifndef ARCADED_ENGINE_MIX_H
#define ARCADED_ENGINE_MIX_H

#include <stddef.h>
#include <stdint.h>

struct snd;

#define MIX_GAIN_MAX 255
#define MIX_VOLUME_MAX 100             /* master volume, percent */
#define MIX_RATE_MIN 8000
#define MIX_RATE_MAX 192000
#define MIX_RATE_DEFAULT 48000
/* Frames in one tick at most (MIX_RATE_MAX / 60, plus the carry). */
#define MIX_FRAMES_MAX (MIX_RATE_MAX / 60 + 1)
#define MIX_VOICES_MAX 64

struct mix_voice {
	const struct snd *snd;         /* NULL or an empty sound: silent */
	uint32_t age;                  /* ticks since it started: 0 in its first tick */
	uint16_t left, right;          /* 0..MIX_GAIN_MAX */
};

/* F(t): the first output frame of tick t at rate (see above). */
int64_t mix_frame_at(uint32_t rate, int64_t t);

/* Frames of tick t at rate: F(t + 1) - F(t). */
uint32_t mix_frames(uint32_t rate, uint32_t t);

/* Mixes tick t's frames of the n voices (at most MIX_VOICES_MAX; more are
 * ignored) at output rate (MIX_RATE_MIN..MAX) and master volume
 * (0..MIX_VOLUME_MAX, clamped) into out, interleaved left, right, 16-bit.
 * out has room for 2 * mix_frames(rate, t) samples. Returns the frames. */
uint32_t mix_tick(uint32_t rate, uint32_t t, int volume, const struct mix_voice *v, int n,
		  int16_t *out);

/* The audio hash of a tick: FNV-1a (engine/core/hash.h) of its frames'
 * samples as little-endian 16-bit values, left then right. */
uint64_t mix_hash(const int16_t *buf, uint32_t frames);

#endif
