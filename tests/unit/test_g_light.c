/*
 * Tests for engine/game/g_light.c: the sector light effects and the lines
 * that set lights.
 *
 * Doom's rules (p_lights.c), on its own 35 Hz clock (the sim runs them on
 * each Doom tic of the stage, g_dtic): an effect's dark level is the
 * darkest neighbour (here 96), its bright level the sector's own (160). A
 * strobe is 5 tics bright and 15 (fast: 2, 4, 13) or 35 (slow: 3, 12)
 * dark; the synchronized ones (12, 13) all go dark on the first tic, the
 * others after 1..8 random tics. A blink (1) is dark 1..8 tics ((rand & 7)
 * + 1) and bright 1 or 65 ((rand & 64) + 1). A glow (8) moves 8 a tic and
 * turns back when the next step would reach either level, so it runs
 * 152..104 and back: 6 steps each way with the end value held a tic, a
 * period of 14 tics. A flicker (17) changes every 4 tics to 160, 144, 128
 * or 112 (the bright level less 0..3 times 16, never under the darkest
 * neighbour + 16). The lines: 35 and 13 set 35 and 255, 12 the brightest
 * neighbour, 104 the darkest, 17 starts a slow strobe.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "spec_fixture.h"

#define TICS 600
#define DARK 96
#define BRIGHT 160

/* A (x 0..256, light 200, the player) | L1 (light 160, special sp, tag
 * 1) | N (96) | L2 (160, special sp2) | B (200); line 2 (x = 256, front
 * A, back L1) has `line`, tag 1. */
static struct map *light_map(int sp, int sp2, int line)
{
	static const int w[] = { 256, 64, 64, 64, 64 };
	static const struct fix_sector s[] = {
		{ 0, 128, 200 }, { 0, 128, BRIGHT }, { 0, 128, DARK }, { 0, 128, BRIGHT },
		{ 0, 128, 200 },
	};
	struct map *m = fix_row(w, s, 5, 128, 200, 64, 0, NULL, 0);

	assert_non_null(m);
	m->sectors[1].special = (uint16_t)sp;
	m->sectors[1].tag = 1;
	m->sectors[3].special = (uint16_t)sp2;
	m->lines[2].special = (uint16_t)line;
	m->lines[2].tag = 1;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

/* Runs the sim to its next Doom tic; returns that tic. */
static uint32_t next_dtic(struct sim *s)
{
	do
		sim_tick(s, &spec_none);
	while (!g_dtic_now(s));
	return g_dtic(s);
}

/* Sector sec's light on Doom tics 1..n (l[0]: before the first). */
static void sample(struct sim *s, uint32_t sec, uint8_t *l, int n)
{
	l[0] = s->w.sec[sec].light;
	for (int t = 1; t <= n; t++) {
		assert_int_equal(next_dtic(s), (uint32_t)t);
		l[t] = s->w.sec[sec].light;
	}
}

/* The lengths of the whole runs of level v in l[0..n] (not the first run
 * nor the last, which the sample cuts): how many, their lengths in len. */
static int runs(const uint8_t *l, int n, uint8_t v, int *len, int max)
{
	int k = 0, start = -1;

	for (int t = 1; t <= n; t++) {
		if (l[t] == l[t - 1])
			continue;
		if (start >= 0 && l[t - 1] == v && k < max)
			len[k++] = t - start;
		start = t;
	}
	return k;
}

/* At least ten whole runs of v in l[0..n], each `want` tics long. */
static void runs_are(const uint8_t *l, int n, uint8_t v, int want)
{
	int len[64], k = runs(l, n, v, len, 64);

	assert_true(k >= 10);
	for (int i = 0; i < k; i++)
		assert_int_equal(len[i], want);
}

static void only_dark_and_bright(const uint8_t *l, int n)
{
	for (int t = 0; t <= n; t++)
		assert_true(l[t] == DARK || l[t] == BRIGHT);
}

static void strobe(int special, int dark)
{
	struct map *m = light_map(special, 0, 0);
	struct sim s;
	uint8_t l[TICS + 1];

	sim_init(&s, m, &spec_play);
	sample(&s, 1, l, TICS);
	only_dark_and_bright(l, TICS);
	runs_are(l, TICS, BRIGHT, 5);
	runs_are(l, TICS, DARK, dark);
	map_free(m);
}

static void strobe_fast_is_5_bright_15_dark(void **state)
{
	(void)state;
	strobe(2, 15);
}

static void strobe_slow_is_5_bright_35_dark(void **state)
{
	(void)state;
	strobe(3, 35);
}

/* Two sectors of 13 (or 12) go dark on the first tic and stay in step. */
static void synchronized(int special, int dark)
{
	struct map *m = light_map(special, special, 0);
	struct sim s;
	uint8_t a[TICS + 1], b[TICS + 1];

	sim_init(&s, m, &spec_play);
	for (int t = 0; t <= TICS; t++) {
		if (t)
			assert_int_equal(next_dtic(&s), (uint32_t)t);
		a[t] = s.w.sec[1].light;
		b[t] = s.w.sec[3].light;
		assert_int_equal(a[t], b[t]);
	}
	assert_int_equal(a[0], BRIGHT);
	assert_int_equal(a[1], DARK);
	runs_are(a, TICS, DARK, dark);
	map_free(m);
}

static void synchronized_strobes_stay_in_step(void **state)
{
	(void)state;
	synchronized(13, 15);
	synchronized(12, 35);
}

static void blink_is_dark_1_to_8_bright_1_or_65(void **state)
{
	struct map *m = light_map(1, 0, 0);
	struct sim s;
	static uint8_t l[4 * TICS + 1];
	int len[256], k;
	(void)state;
	sim_init(&s, m, &spec_play);
	sample(&s, 1, l, 4 * TICS);
	only_dark_and_bright(l, 4 * TICS);
	k = runs(l, 4 * TICS, DARK, len, 256);
	assert_true(k >= 10);
	for (int i = 0; i < k; i++)
		assert_in_range(len[i], 1, 8);
	k = runs(l, 4 * TICS, BRIGHT, len, 256);
	assert_true(k >= 10);
	for (int i = 0; i < k; i++)
		assert_true(len[i] == 1 || len[i] == 65);
	map_free(m);
}

static void glow_runs_152_to_104_every_14_tics(void **state)
{
	struct map *m = light_map(8, 0, 0);
	struct sim s;
	uint8_t l[TICS + 1];
	(void)state;
	sim_init(&s, m, &spec_play);
	sample(&s, 1, l, TICS);
	assert_int_equal(l[0], BRIGHT);
	for (int t = 1; t <= 7; t++)               /* falling first */
		assert_int_equal(l[t], BRIGHT - 8 * t);
	assert_int_equal(l[8], 104);
	for (int t = 1; t <= TICS; t++) {
		int d = l[t] - l[t - 1];
		assert_true(d == 0 || d == 8 || d == -8);
		assert_in_range(l[t], 104, 152);
		if (t + 14 <= TICS)
			assert_int_equal(l[t + 14], l[t]);
	}
	map_free(m);
}

static void flicker_changes_every_4_tics_within_its_range(void **state)
{
	struct map *m = light_map(17, 0, 0);
	struct sim s;
	uint8_t l[TICS + 1];
	int last = -1, seen = 0;
	(void)state;
	sim_init(&s, m, &spec_play);
	sample(&s, 1, l, TICS);
	for (int t = 1; t <= TICS; t++) {
		assert_true(l[t] == 160 || l[t] == 144 || l[t] == 128 || l[t] == 112);
		seen |= 1 << ((160 - l[t]) / 16);
		if (l[t] == l[t - 1])
			continue;
		if (last >= 0)
			assert_int_equal((t - last) % 4, 0);
		last = t;
	}
	assert_int_equal(seen, 15);                /* all four levels show */
	map_free(m);
}

/* The light lines, walked over: L1 is tagged, its neighbours are A (200)
 * and N (96). */
static void light_lines_set_levels(void **state)
{
	static const int line[][2] = { { 35, 35 }, { 13, 255 }, { 12, 200 }, { 104, DARK } };
	(void)state;
	for (size_t i = 0; i < sizeof line / sizeof line[0]; i++) {
		struct map *m = light_map(0, 0, line[i][0]);
		struct sim s;
		sim_init(&s, m, &spec_play);
		assert_int_equal(s.w.sec[1].light, BRIGHT);
		spec_cross(&s, G_WHO_PLAYER, 256, 64, 1);
		spec_run(&s, &spec_none, 100);
		assert_int_equal(s.w.sec[1].light, line[i][1]);
		assert_int_equal(s.w.sec[3].light, BRIGHT);
		map_free(m);
	}
}

/* 17: the tagged sector starts a slow strobe (5 bright, 35 dark). */
static void the_strobe_line_starts_a_slow_strobe(void **state)
{
	struct map *m = light_map(0, 0, 17);
	struct sim s;
	uint8_t l[TICS + 1];
	(void)state;
	sim_init(&s, m, &spec_play);
	spec_run(&s, &spec_none, 100);
	assert_int_equal(s.w.sec[1].light, BRIGHT);
	spec_cross(&s, G_WHO_PLAYER, 256, 64, 1);
	for (int t = 0; t <= TICS; t++) {
		if (t)
			next_dtic(&s);
		l[t] = s.w.sec[1].light;
	}
	only_dark_and_bright(l, TICS);
	runs_are(l, TICS, DARK, 35);
	runs_are(l, TICS, BRIGHT, 5);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(strobe_fast_is_5_bright_15_dark),
		cmocka_unit_test(strobe_slow_is_5_bright_35_dark),
		cmocka_unit_test(synchronized_strobes_stay_in_step),
		cmocka_unit_test(blink_is_dark_1_to_8_bright_1_or_65),
		cmocka_unit_test(glow_runs_152_to_104_every_14_tics),
		cmocka_unit_test(flicker_changes_every_4_tics_within_its_range),
		cmocka_unit_test(light_lines_set_levels),
		cmocka_unit_test(the_strobe_line_starts_a_slow_strobe),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
