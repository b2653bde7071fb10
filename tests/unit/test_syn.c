/*
 * syn: the built-in sounds. Their lengths follow from the recipes' last
 * parts (syn.c: the coin's clink ends at 180 ms, the jingle at 2600 ms,
 * the test tone at 1000 ms, at 22050 Hz); the test tone is a 1 kHz sine
 * (its zero crossings are counted); every sound is there and audible; two
 * syntheses give the same samples.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "engine/sound/sfx.h"
#include "engine/sound/snd.h"
#include "engine/sound/syn.h"

static void lengths_follow_the_recipes(void **state)
{
	(void)state;
	assert_int_equal(syn_len(SFX_COIN), 180 * 22050 / 1000);      /* 3969 */
	assert_int_equal(syn_len(SFX_JINGLE), 2600 * 22050 / 1000);   /* 57330 */
	assert_int_equal(syn_len(SFX_TONE), 22050);
	assert_int_equal(syn_len(SFX_NONE), 0);
	assert_int_equal(syn_len(SFX_COUNT), 0);
	assert_int_equal(syn_len(-1), 0);
}

static void every_sound_is_there_and_audible(void **state)
{
	struct snd_set *set;

	(void)state;
	assert_int_equal(snd_builtin(&set), 0);
	for (int id = 1; id < SFX_COUNT; id++) {
		const struct snd *s = &set->s[id];
		int peak = 0;

		assert_int_equal(s->rate, SYN_RATE);
		assert_int_equal(s->len, syn_len(id));
		assert_true(s->len > 0);
		for (uint32_t i = 0; i < s->len; i++)
			peak = abs(s->pcm[i]) > peak ? abs(s->pcm[i]) : peak;
		/* louder than -20 dBFS, and no part of the recipe clipped (every
		 * recipe's parts add up to less than full scale) */
		if (peak < 3277 || peak >= 32767)
			fail_msg("%s: peak %d", sfx_info(id)->name, peak);
	}
	snd_free(set);
}

static void the_tone_is_1khz(void **state)
{
	struct snd_set *set;
	const struct snd *s;
	int crossings = 0, peak = 0;

	(void)state;
	assert_int_equal(snd_builtin(&set), 0);
	s = &set->s[SFX_TONE];
	/* the middle half second: 500 periods, two crossings each */
	for (uint32_t i = 11025 / 2 + 1; i < 11025 / 2 + 11025; i++) {
		crossings += (s->pcm[i - 1] < 0) != (s->pcm[i] < 0);
		peak = abs(s->pcm[i]) > peak ? abs(s->pcm[i]) : peak;
	}
	assert_in_range(crossings, 998, 1002);
	assert_in_range(peak, 19800, 20000);         /* amplitude 20000 */
	snd_free(set);
}

/* The coin's clink is heard from its start (the latency and the
 * correlation tests look for it). */
static void the_coin_starts_at_once(void **state)
{
	struct snd_set *set;
	const struct snd *s;
	uint32_t first = UINT32_MAX;

	(void)state;
	assert_int_equal(snd_builtin(&set), 0);
	s = &set->s[SFX_COIN];
	for (uint32_t i = 0; i < s->len && first == UINT32_MAX; i++)
		if (abs(s->pcm[i]) >= 328)
			first = i;
	assert_true(first < 22);                     /* within 1 ms */
	snd_free(set);
}

static void two_syntheses_are_the_same(void **state)
{
	struct snd_set *a, *b;

	(void)state;
	assert_int_equal(snd_builtin(&a), 0);
	assert_int_equal(snd_builtin(&b), 0);
	assert_true(snd_set_hash(a) == snd_set_hash(b));
	for (int id = 1; id < SFX_COUNT; id++)
		assert_memory_equal(a->s[id].pcm, b->s[id].pcm, 2 * a->s[id].len);
	/* and the sounds differ from each other */
	assert_memory_not_equal(a->s[SFX_COIN].pcm, a->s[SFX_CREDIT].pcm, 2000);
	snd_free(a);
	snd_free(b);
}

/* Recordings store the hash of the sounds they were mixed from, and a
 * replay compares it: the golden recordings (tests/replay/golden-*.rec,
 * header bytes 88..95) were made with the built-in sounds and carry this
 * value. A change of any built-in sample breaks their --verify. */
static void the_builtin_sounds_are_the_recorded_ones(void **state)
{
	struct snd_set *set;

	(void)state;
	assert_int_equal(snd_builtin(&set), 0);
	assert_true(snd_set_hash(set) == 0x62f6da6ff13f9423ull);
	snd_free(set);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(lengths_follow_the_recipes),
		cmocka_unit_test(every_sound_is_there_and_audible),
		cmocka_unit_test(the_tone_is_1khz),
		cmocka_unit_test(the_coin_starts_at_once),
		cmocka_unit_test(two_syntheses_are_the_same),
		cmocka_unit_test(the_builtin_sounds_are_the_recorded_ones),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
