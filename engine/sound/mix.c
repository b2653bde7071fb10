/*
 * mix: one tick of stereo samples (contract in mix.h).
 */
#include "engine/sound/mix.h"

#include <string.h>

#include "engine/core/hash.h"
#include "engine/core/le.h"
#include "engine/sound/snd.h"

int64_t mix_frame_at(uint32_t rate, int64_t t)
{
	int64_t p = t * (int64_t)rate;

	/* floor, also for a negative t (a voice older than the tick count) */
	return p >= 0 ? p / 60 : -((-p + 59) / 60);
}

uint32_t mix_frames(uint32_t rate, uint32_t t)
{
	return (uint32_t)(mix_frame_at(rate, (int64_t)t + 1) - mix_frame_at(rate, t));
}

/* Adds frames [j0, j0 + n) of voice v to acc (interleaved left, right). */
static void mix_voice(const struct mix_voice *v, uint32_t rate, uint64_t j0, uint32_t n,
		      int32_t *acc)
{
	const struct snd *s = v->snd;
	const int16_t *pcm = s->pcm;
	uint32_t src = s->rate, len = s->len, di = src / rate, dr = src % rate;
	/* the weight's step: dr * 65536 / rate, as a quotient and remainder */
	uint32_t dq = (uint32_t)(((uint64_t)dr << 16) / rate);
	uint32_t dqr = (uint32_t)(((uint64_t)dr << 16) % rate);
	uint64_t pos = j0 * src;
	uint64_t i = pos / rate;
	uint32_t r = (uint32_t)(pos % rate);
	uint32_t q = (uint32_t)(((uint64_t)r << 16) / rate);
	uint32_t qr = (uint32_t)(((uint64_t)r << 16) % rate);
	int32_t gl = v->left, gr = v->right;

	for (uint32_t k = 0; k < n && i < len; k++) {
		/* samples as 0..65535, so the interpolation stays unsigned */
		uint32_t a = (uint32_t)(pcm[i] + 32768);
		uint32_t b = (uint32_t)((i + 1 < len ? pcm[i + 1] : 0) + 32768);
		int32_t x = (int32_t)((a * (65536u - q) + b * q) >> 16) - 32768;

		acc[2 * k] += x * gl;
		acc[2 * k + 1] += x * gr;
		/* the next frame's position: + src / rate */
		i += di;
		r += dr;
		q += dq;
		qr += dqr;
		if (qr >= rate) {
			qr -= rate;
			q++;
		}
		if (r >= rate) {
			r -= rate;
			i++;
			q -= 65536;        /* floor((r - rate) * 65536 / rate), exactly */
		}
	}
}

uint32_t mix_tick(uint32_t rate, uint32_t t, int volume, const struct mix_voice *v, int n,
		  int16_t *out)
{
	int32_t acc[2 * MIX_FRAMES_MAX];
	int64_t f0 = mix_frame_at(rate, t);
	uint32_t frames = mix_frames(rate, t);
	const int64_t den = (int64_t)MIX_GAIN_MAX * MIX_VOLUME_MAX;

	if (volume < 0)
		volume = 0;
	if (volume > MIX_VOLUME_MAX)
		volume = MIX_VOLUME_MAX;
	if (n > MIX_VOICES_MAX)
		n = MIX_VOICES_MAX;
	memset(acc, 0, 2 * frames * sizeof(acc[0]));
	for (int k = 0; k < n; k++) {
		const struct snd *s = v[k].snd;
		int64_t j0;

		if (!s || !s->len || !s->rate || (!v[k].left && !v[k].right))
			continue;
		/* frames this voice has played before this tick */
		j0 = f0 - mix_frame_at(rate, (int64_t)t - v[k].age);
		mix_voice(&v[k], rate, (uint64_t)j0, frames, acc);
	}
	for (uint32_t i = 0; i < 2 * frames; i++) {
		int64_t y = (int64_t)acc[i] * volume / den;
		out[i] = (int16_t)(y > 32767 ? 32767 : y < -32768 ? -32768 : y);
	}
	return frames;
}

uint64_t mix_hash(const int16_t *buf, uint32_t frames)
{
	uint8_t b[2 * 2 * 64];
	uint64_t h = HASH_INIT;
	uint32_t n = 2 * frames;

	/* in blocks, as explicit little-endian bytes */
	for (uint32_t i = 0; i < n;) {
		uint32_t m = 0;
		for (; m < sizeof(b) / 2 && i < n; m++, i++)
			le_put16(b + 2 * m, (uint16_t)buf[i]);
		h = hash_bytes(h, b, 2 * m);
	}
	return h;
}
