/*
 * Tests for engine/game/g_spec.c: what the sector under the player does
 * (Doom's P_PlayerInSpecialSector): damaging floors, the exit floor (11)
 * and the secret (9).
 *
 * Doom's rules: 7 hurts 5, 5 hurts 10, 16 and 4 hurt 20, each when
 * leveltime & 31 is 0: once every 32 Doom tics (35 Hz). The sim counts
 * Doom tics from the stage start (g_dtic: sim ticks * 35 / 60), so a hit
 * comes on every 32nd Doom tic, 32 * 60 / 35 = 54.9 sim ticks apart (54
 * or 55). The radiation suit keeps 5 and 10 off. 11 hurts 20 on the same
 * clock and ends the map once health is 10 or less. A secret (9) counts
 * once, with its message.
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

/* A (x 0..256, `special`, the player at (128, 64)) | B (256..512). */
static struct map *floor_map(int special)
{
	static const int w[] = { 256, 256 };
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 0, 128, 160 } };
	struct map *m = fix_row(w, s, 2, 128, 128, 64, 0, NULL, 0);

	assert_non_null(m);
	m->sectors[0].special = (uint16_t)special;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

/* Standing on `special` with `health` for 700 Doom tics (or until dead,
 * checked): every hit takes
 * dmg, comes on a Doom tic that is a multiple of 32 and 32 tics after the
 * one before (54 or 55 sim ticks); returns the hits. */
static int hits_of(int special, int dmg, int health)
{
	struct map *m = floor_map(special);
	struct sim s;
	fx_t last;
	uint32_t prev_dtic = 0, prev_tick = 0;
	int hits = 0;

	sim_init(&s, m, &spec_play);
	s.pl.health = health * FX_ONE;
	last = s.pl.health;
	while (g_dtic(&s) < 700 && s.g.phase == G_PH_PLAY) {
		sim_tick(&s, &spec_none);
		if (s.pl.health == last)
			continue;
		assert_int_equal(last - s.pl.health, dmg * FX_ONE);
		assert_int_equal(g_dtic(&s) % 32, 0);
		if (hits++) {
			assert_int_equal(g_dtic(&s) - prev_dtic, 32);
			assert_in_range(s.tick - prev_tick, 54, 55);
		} else {
			assert_true(g_dtic(&s) <= 32);
		}
		prev_dtic = g_dtic(&s);
		prev_tick = s.tick;
		last = s.pl.health;
	}
	assert_int_equal(s.g.phase, hits * dmg >= health ? G_PH_DEAD : G_PH_PLAY);
	map_free(m);
	return hits;
}

/* 100 of health lasts 20 hits of 5 (the last on tic 640, within the 700)
 * and 10 of 10; 30 of health 6 hits of 5. */
static void damage_5_and_10_every_32_tics(void **state)
{
	(void)state;
	assert_int_equal(hits_of(7, 5, 100), 20);
	assert_int_equal(hits_of(7, 5, 30), 6);
	assert_int_equal(hits_of(5, 10, 100), 10);
}

/* 20 a hit: 100 of health is five hits, then the player is dead. */
static void damage_20_every_32_tics(void **state)
{
	(void)state;
	assert_int_equal(hits_of(16, 20, 100), 5);
	assert_int_equal(hits_of(4, 20, 100), 5);
}

static void the_suit_keeps_10_off(void **state)
{
	struct map *m = floor_map(5);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	s.w.suit = 1000;
	spec_run(&s, &spec_none, 600);             /* 350 Doom tics, 10 hits' time */
	assert_int_equal(s.pl.health, 100 * FX_ONE);
	map_free(m);
}

/* 11 with 50 of health: 30 after the first hit, 10 after the second, and
 * the map ends there (normal exit), the player alive. */
static void the_exit_floor_ends_the_map_at_10(void **state)
{
	struct map *m = floor_map(11);
	struct sim s;
	int t;
	(void)state;
	sim_init(&s, m, &spec_play);
	s.pl.health = 50 * FX_ONE;
	for (t = 0; t < 200 && s.pl.health == 50 * FX_ONE; t++)
		sim_tick(&s, &spec_none);
	assert_int_equal(s.pl.health, 30 * FX_ONE);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	for (t = 0; t < 200 && s.pl.health == 30 * FX_ONE; t++)
		sim_tick(&s, &spec_none);
	assert_in_range(t, 54, 55);
	assert_int_equal(s.pl.health, 10 * FX_ONE);
	assert_int_equal(s.g.phase, G_PH_INTER);
	assert_int_equal(s.w.exit, G_EXIT_NORMAL);
	map_free(m);
}

static void a_secret_counts_once(void **state)
{
	struct map *m = floor_map(9);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	assert_int_equal(s.w.secrets_total, 1);
	sim_tick(&s, &spec_none);
	assert_int_equal(s.w.secrets, 1);
	assert_int_equal(s.w.msg, G_MSG_SECRET);
	spec_run(&s, &spec_none, 100);
	assert_int_equal(s.w.secrets, 1);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(damage_5_and_10_every_32_tics),
		cmocka_unit_test(damage_20_every_32_tics),
		cmocka_unit_test(the_suit_keeps_10_off),
		cmocka_unit_test(the_exit_floor_ends_the_map_at_10),
		cmocka_unit_test(a_secret_counts_once),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
