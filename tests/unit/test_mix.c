/*
 * mix: the mixer. Expected samples are worked out by hand in the comments
 * (two known inputs at known gains, saturation), or computed here from the
 * definition in mix.h by plain division per frame, which the mixer avoids
 * (it keeps position and weight by additions): the two must agree on
 * every frame, and stay within one step below the exact rational linear
 * interpolation.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "engine/sound/mix.h"
#include "engine/sound/snd.h"

static int16_t out[2 * MIX_FRAMES_MAX];

/* A sound of n copies of v at rate. */
static struct snd flat(int16_t *pcm, uint32_t n, int16_t v, uint32_t rate)
{
	for (uint32_t i = 0; i < n; i++)
		pcm[i] = v;
	return (struct snd){ pcm, n, rate };
}

static void frames_per_tick_carry_the_remainder(void **state)
{
	uint32_t sum = 0;

	(void)state;
	/* 48000 / 60 = 800 exactly */
	assert_int_equal(mix_frames(48000, 0), 800);
	assert_int_equal(mix_frames(48000, 12345), 800);
	/* 22050 / 60 = 367.5: ticks of 367 and 368, F(t) = floor(t * 367.5) */
	assert_int_equal(mix_frames(22050, 0), 367);
	assert_int_equal(mix_frames(22050, 1), 368);
	assert_int_equal(mix_frames(22050, 2), 367);
	/* 44056 / 60 = 734.27: over a second every frame is there */
	for (uint32_t t = 0; t < 60; t++)
		sum += mix_frames(44056, t);
	assert_int_equal(sum, 44056);
	assert_int_equal(mix_frame_at(22050, 3), 1102);    /* 3 * 367.5 = 1102.5 */
	assert_int_equal(mix_frame_at(22050, -1), -368);   /* floor(-367.5) */
}

/* Two inputs at known gains, no resampling: hand-worked. */
static void two_voices_at_known_gains(void **state)
{
	static int16_t a[2000], b[2000];
	struct snd sa = flat(a, 2000, 1000, 48000), sb = flat(b, 2000, -3000, 48000);
	struct mix_voice v[2] = { { &sa, 0, 255, 128 }, { &sb, 0, 64, 255 } };

	(void)state;
	assert_int_equal(mix_tick(48000, 0, 100, v, 2, out), 800);
	/* left: (1000 * 255 - 3000 * 64) / 255 = 63000 / 255 = 247.06 -> 247;
	 * right: (1000 * 128 - 3000 * 255) / 255 = -637000 / 255 = -2498.04 ->
	 * -2498 (towards zero) */
	for (int j = 0; j < 800; j++) {
		assert_int_equal(out[2 * j], 247);
		assert_int_equal(out[2 * j + 1], -2498);
	}
	/* master volume 50: (63000 * 50) / (255 * 100) = 123.5 -> 123;
	 * (-637000 * 50) / 25500 = -1249.02 -> -1249 */
	mix_tick(48000, 0, 50, v, 2, out);
	assert_int_equal(out[0], 123);
	assert_int_equal(out[1], -1249);
	/* volume 0 is silence; above 100 counts as 100 */
	mix_tick(48000, 0, 0, v, 2, out);
	assert_int_equal(out[0], 0);
	assert_int_equal(out[1], 0);
	mix_tick(48000, 0, 250, v, 2, out);
	assert_int_equal(out[0], 247);
	/* 2000 samples: the second tick has 800 more, the third 400 then silence */
	mix_tick(48000, 2, 100, (struct mix_voice[]){ { &sa, 2, 255, 0 } }, 1, out);
	assert_int_equal(out[2 * 399], 1000);
	assert_int_equal(out[2 * 400], 0);
	assert_int_equal(out[2 * 400 + 1], 0);
}

static void saturation_never_wraps(void **state)
{
	static int16_t hi[1000], lo[1000];
	struct snd sh = flat(hi, 1000, 30000, 48000), sl = flat(lo, 1000, -30000, 48000);
	struct mix_voice v[16];

	(void)state;
	for (int k = 0; k < 16; k++)
		v[k] = (struct mix_voice){ k % 2 ? &sl : &sh, 0, k % 2 ? 0 : 255, k % 2 ? 255 : 0 };
	mix_tick(48000, 0, 100, v, 16, out);
	/* left: 8 * 30000 = 240000 -> 32767; right: 8 * -30000 -> -32768 */
	assert_int_equal(out[0], 32767);
	assert_int_equal(out[1], -32768);
	/* two just past the top: 30000 + 30000, still the top, not negative */
	mix_tick(48000, 0, 100, (struct mix_voice[]){ { &sh, 0, 255, 255 }, { &sh, 0, 255, 255 } },
		 2, out);
	assert_int_equal(out[0], 32767);
	assert_int_equal(out[1], 32767);
}

/* The definition of mix.h, by division per frame: frame j of a sound
 * played at gain 255 and volume 100 (which leave the sample as it is). */
static int32_t by_division(const struct snd *s, uint64_t j, uint32_t rate)
{
	uint64_t pos = j * s->rate, i = pos / rate, r = pos % rate;
	uint64_t w = (r << 16) / rate;
	int64_t a, b;

	if (i >= s->len)
		return 0;
	a = s->pcm[i];
	b = i + 1 < s->len ? s->pcm[i + 1] : 0;
	/* floor(a + (b - a) * w / 65536), by floor division */
	int64_t num = (a * 65536) + (b - a) * (int64_t)w;
	return (int32_t)(num >= 0 ? num / 65536 : -((-num + 65535) / 65536));
}

/* 11025 Hz to 48000 Hz: frame j reads position j * 147 / 640. */
static void resampling_11025_to_48000(void **state)
{
	static int16_t pcm[3000];
	struct snd s;
	uint32_t seed = 12345;

	(void)state;
	/* hand-worked on a ramp 0, 6400, 12800: frame 1 at 147/640 of the
	 * way: weight floor(147 * 65536 / 640) = 15052, 6400 * 15052 / 65536
	 * = 1469.9 -> 1469; frame 2: weight floor(294 * 65536 / 640) = 30105,
	 * 6400 * 30105 / 65536 = 2939.9 -> 2939; frame 5 at 735/640 = 1 +
	 * 95/640: weight 9728, 6400 + 6400 * 9728 / 65536 = 7350 exactly */
	pcm[0] = 0;
	pcm[1] = 6400;
	pcm[2] = 12800;
	s = (struct snd){ pcm, 3, 11025 };
	mix_tick(48000, 0, 100, (struct mix_voice[]){ { &s, 0, 255, 255 } }, 1, out);
	assert_int_equal(out[0], 0);
	assert_int_equal(out[2], 1469);
	assert_int_equal(out[4], 2939);
	assert_int_equal(out[10], 7350);
	assert_int_equal(out[3], out[2]);                /* both sides alike */
	/* position 3 is past the end: silence from frame ceil(3 * 640 / 147) = 14 */
	assert_int_equal(out[2 * 13] != 0, 1);
	assert_int_equal(out[2 * 14], 0);

	/* noise, over five ticks: the incremental bookkeeping against the
	 * division, and against the exact interpolation: the weight is
	 * rounded down, so the result is at most one below it on a rising
	 * step and at most one above it on a falling one */
	for (int i = 0; i < 3000; i++) {
		seed ^= seed << 13;
		seed ^= seed >> 17;
		seed ^= seed << 5;
		pcm[i] = (int16_t)((int32_t)(seed >> 16) - 32768);
	}
	s = (struct snd){ pcm, 3000, 11025 };
	for (uint32_t t = 100; t < 105; t++) {
		/* started at tick 100 */
		mix_tick(48000, t, 100, (struct mix_voice[]){ { &s, t - 100, 255, 255 } }, 1, out);
		for (uint32_t k = 0; k < 800; k++) {
			uint64_t j = (t - 100) * 800 + k, pos = j * 11025, i = pos / 48000;
			int64_t want = by_division(&s, j, 48000);
			assert_int_equal(out[2 * k], want);
			if (i + 1 < 3000) {
				/* exact: a + (b - a) * r / 48000, as a fraction */
				int64_t a = pcm[i], b = pcm[i + 1], r = (int64_t)(pos % 48000);
				int64_t num = a * 48000 + (b - a) * r;
				int64_t fl = num >= 0 ? num / 48000 : -((-num + 47999) / 48000);
				if (b >= a)
					assert_true(out[2 * k] == fl || out[2 * k] == fl - 1);
				else
					assert_true(out[2 * k] == fl || out[2 * k] == fl + 1);
			}
		}
	}
}

/* A rate 60 does not divide: a sound mixed tick by tick is the sound mixed
 * in one stretch (the definition by division over the whole). */
static void ticks_join_without_a_seam(void **state)
{
	static int16_t pcm[5000];
	struct snd s = { pcm, 5000, 22050 };
	uint64_t j = 0;

	(void)state;
	for (int i = 0; i < 5000; i++)
		pcm[i] = (int16_t)((i * 7919) % 60000 - 30000);
	for (uint32_t t = 7; t < 20; t++) {
		/* output 44056 Hz: 734 or 735 frames a tick */
		uint32_t n = mix_tick(44056, t, 100, (struct mix_voice[]){ { &s, t - 7, 255, 255 } },
				      1, out);
		assert_int_equal(n, mix_frames(44056, t));
		for (uint32_t k = 0; k < n; k++, j++)
			assert_int_equal(out[2 * k], by_division(&s, j, 44056));
	}
	/* upwards too: a 96 kHz sound read two samples a frame at 48 kHz */
	s.rate = 96000;
	mix_tick(48000, 0, 100, (struct mix_voice[]){ { &s, 0, 255, 255 } }, 1, out);
	assert_int_equal(out[0], pcm[0]);
	assert_int_equal(out[2], pcm[2]);
	assert_int_equal(out[2 * 100], pcm[200]);
}

/* FNV-1a of the samples' little-endian bytes, written out here. */
static void the_hash_is_fnv1a_of_little_endian_samples(void **state)
{
	int16_t buf[4] = { 1, -2, 0x1234, -32768 };
	const uint8_t bytes[8] = { 0x01, 0x00, 0xfe, 0xff, 0x34, 0x12, 0x00, 0x80 };
	uint64_t h = 0xcbf29ce484222325ull;

	(void)state;
	for (int i = 0; i < 8; i++) {
		h ^= bytes[i];
		h *= 0x100000001b3ull;
	}
	assert_true(mix_hash(buf, 2) == h);
	assert_true(mix_hash(buf, 1) != h);
}

static void silent_voices_and_empty_sounds_add_nothing(void **state)
{
	static int16_t a[100];
	struct snd sa = flat(a, 100, 5000, 48000), empty = { NULL, 0, 11025 };
	struct mix_voice v[3] = { { &sa, 0, 0, 0 }, { &empty, 0, 255, 255 }, { NULL, 0, 255, 255 } };

	(void)state;
	memset(out, 0x55, sizeof(out));
	mix_tick(48000, 0, 100, v, 3, out);
	for (int i = 0; i < 1600; i++)
		assert_int_equal(out[i], 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(frames_per_tick_carry_the_remainder),
		cmocka_unit_test(two_voices_at_known_gains),
		cmocka_unit_test(saturation_never_wraps),
		cmocka_unit_test(resampling_11025_to_48000),
		cmocka_unit_test(ticks_join_without_a_seam),
		cmocka_unit_test(the_hash_is_fnv1a_of_little_endian_samples),
		cmocka_unit_test(silent_voices_and_empty_sounds_add_nothing),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
