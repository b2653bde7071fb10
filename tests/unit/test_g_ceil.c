/*
 * Tests for engine/game/g_ceil.c: the lift (Doom's plat down-wait-up-stay)
 * started by a switch (SR 62), and the crushers (below).
 *
 * Expected values from Doom's rules: a lift moves PLATSPEED * 4 = 4 units
 * a Doom tic (35 Hz), so its 64 units take 16 tics = 16 * 60 / 35 = 27.4
 * sim ticks (60 Hz: reached on tick 28); it waits 3 s (105 tics, 180
 * ticks) at the bottom, goes up as fast and stops at its old height.
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

/* Room A (x 0..256, floor 0) | lift (256..384, floor 64, tag 1) | room B
 * (384..640, floor 64); line 2 (x = 256, front A) is an SR 62 lift switch
 * tagged 1. The player stands at (200, 64) facing it. */
static struct map *lift_map(void)
{
	static const int w[] = { 256, 128, 256 };
	static const struct fix_sector s[] = { { 0, 192, 160 }, { 64, 192, 160 }, { 64, 192, 160 } };
	struct map *m = fix_row(w, s, 3, 128, 200, 64, 0, NULL, 0);

	assert_non_null(m);
	m->lines[2].special = 62;
	m->lines[2].tag = 1;
	m->sectors[1].tag = 1;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

static void lift_goes_down_waits_and_comes_up(void **state)
{
	struct map *m = lift_map();
	struct sim s;
	const struct sim_cmd u = { .buttons = SIM_BT_USE }, none = { 0 };
	int t;
	(void)state;
	sim_init(&s, m, &spec_play);
	assert_int_equal(s.w.sec[1].floor_h, 64 * FX_ONE);
	sim_tick(&s, &u);                          /* tick 1: it starts down */
	assert_int_equal(s.w.num_movers, 1);
	assert_int_equal(s.w.mv[0].kind, G_MV_PLAT);
	spec_run(&s, &none, 26);                        /* tick 27: not yet */
	assert_true(s.w.sec[1].floor_h > 0);
	spec_run(&s, &none, 1);                         /* tick 28: the bottom (room A's floor) */
	assert_int_equal(s.w.sec[1].floor_h, 0);
	for (t = 0; t < 300 && s.w.sec[1].floor_h == 0; t++)
		sim_tick(&s, &none);
	assert_in_range(t, 180, 181);              /* 3 s at the bottom */
	for (t = 0; t < 300 && s.w.num_movers > 0; t++)
		sim_tick(&s, &none);
	assert_in_range(t, 26, 28);                /* back up as fast, then it stays */
	assert_int_equal(s.w.sec[1].floor_h, 64 * FX_ONE);
	spec_run(&s, &none, 400);
	assert_int_equal(s.w.sec[1].floor_h, 64 * FX_ONE);
	map_free(m);
}

static void a_lift_in_motion_is_not_started_twice(void **state)
{
	struct map *m = lift_map();
	struct sim s;
	const struct sim_cmd u = { .buttons = SIM_BT_USE }, none = { 0 };
	(void)state;
	sim_init(&s, m, &spec_play);
	sim_tick(&s, &u);
	spec_run(&s, &none, 10);
	sim_tick(&s, &u);
	assert_int_equal(s.w.num_movers, 1);
	map_free(m);
}

/*
 * The other platforms, from Doom's p_plats.c: the perpetual one (53, 87)
 * moves PLATSPEED, 1 unit a Doom tic, between the lowest and the highest
 * floor around (128 units: 128 tics = 219.4 sim ticks, reached on tick
 * 220) and waits 3 s (105 tics = 180 ticks) at each end; 54/89 stop it,
 * 87 starts it again. Raise-and-change (15: by 24; 20: to the next floor
 * up, clearing the special) takes the switch's front sector's flat at once
 * and moves PLATSPEED / 2: 24 units in 48 tics (82.3 ticks: tick 83), 32
 * in 64 (109.7: tick 110).
 *
 * A (x 0..256, floor a, the player at (200, 64)) | T (256..320, floor 64,
 * tag 1) | B (320..576, floor 128); line 2 (x = 256) has `special`, line 5
 * (x = 320) `stop`, both tagged 1.
 */
static struct map *plat_map(int special, int stop, int a)
{
	static const int w[] = { 256, 64, 256 };
	struct fix_sector s[] = { { a, 256, 160 }, { 64, 256, 160 }, { 128, 256, 160 } };
	struct map *m = fix_row(w, s, 3, 128, 200, 64, 0, NULL, 0);

	assert_non_null(m);
	m->lines[2].special = (uint16_t)special;
	m->lines[2].tag = 1;
	m->lines[5].special = (uint16_t)stop;
	m->lines[5].tag = 1;
	m->sectors[1].tag = 1;
	return m;
}

/* Ticks until sector 1's floor is h (the mover may stay), or -1. */
static int floor_ticks(struct sim *s, fx_t h, int max)
{
	for (int t = 1; t <= max; t++) {
		sim_tick(s, &spec_none);
		if (s->w.sec[1].floor_h == h)
			return t;
	}
	return -1;
}

static void perpetual_platform_travels_and_waits_3_s(void **state)
{
	struct map *m = plat_map(87, 89, 0);
	struct sim s;
	fx_t h;
	int t;
	(void)state;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	sim_init(&s, m, &spec_play);
	spec_cross(&s, G_WHO_PLAYER, 256, 64, 1);
	/* first to whichever end the random start chose, then the cycle */
	t = floor_ticks(&s, 0, 300);
	if (t < 0)
		t = floor_ticks(&s, 0, 700);
	assert_true(t > 0);
	for (int i = 0; i < 2; i++) {
		/* 180 ticks of wait, then the tick that leaves (counted here):
		 * the travel's other 219 follow */
		for (t = 0; t < 300 && s.w.sec[1].floor_h == 0; t++)
			sim_tick(&s, &spec_none);
		assert_in_range(t, 180, 181);
		assert_in_range(floor_ticks(&s, 128 * FX_ONE, 500), 218, 220);
		for (t = 0; t < 300 && s.w.sec[1].floor_h == 128 * FX_ONE; t++)
			sim_tick(&s, &spec_none);
		assert_in_range(t, 180, 181);
		assert_in_range(floor_ticks(&s, 0, 500), 218, 220);
	}
	/* stopped where it is, and started again */
	spec_run(&s, &spec_none, 200);
	spec_cross(&s, G_WHO_PLAYER, 320, 64, 1);
	h = s.w.sec[1].floor_h;
	assert_true(h > 0 && h < 128 * FX_ONE);
	spec_run(&s, &spec_none, 500);
	assert_int_equal(s.w.sec[1].floor_h, h);
	spec_cross(&s, G_WHO_PLAYER, 256, 64, 1);
	spec_run(&s, &spec_none, 10);
	assert_int_not_equal(s.w.sec[1].floor_h, h);
	assert_int_equal(s.w.num_movers, 1);
	map_free(m);
}

static void raise_and_change_takes_the_front_flat(void **state)
{
	struct map *m = plat_map(15, 0, 0);
	struct sim s;
	(void)state;
	m->sectors[0].floor_tex = 6;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	sim_init(&s, m, &spec_play);
	sim_tick(&s, &spec_use_cmd);               /* tick 1 */
	assert_int_equal(s.w.sec[1].floor_tex, 6);
	assert_int_equal(floor_ticks(&s, 88 * FX_ONE, 300) + 1, 83);
	assert_int_equal(s.w.num_movers, 0);
	map_free(m);
}

static void raise_to_next_and_change_clears_the_special(void **state)
{
	struct map *m = plat_map(20, 0, 96);
	struct sim s;
	(void)state;
	m->sectors[0].floor_tex = 6;
	m->sectors[1].special = 7;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	sim_init(&s, m, &spec_play);
	sim_tick(&s, &spec_use_cmd);
	assert_int_equal(s.w.sec[1].floor_tex, 6);
	assert_int_equal(s.w.sec[1].special, 0);
	assert_int_equal(floor_ticks(&s, 96 * FX_ONE, 300) + 1, 110);
	assert_int_equal(s.w.num_movers, 0);
	map_free(m);
}

/*
 * Crushers. Expected values from Doom's rules (p_ceilng.c, p_map.c): a
 * crusher's ceiling moves CEILSPEED, 1 unit a Doom tic (the fast one 2),
 * down to 8 above the floor and back up to where it started, for ever;
 * while a body does not fit under it (56 high here) it hurts it by 10
 * every 4 Doom tics (leveltime & 3) and the normal and silent crushers slow
 * to CEILSPEED / 8. 120 units at 1 unit a tic are 120 tics = 205.7 sim
 * ticks (60 Hz): reached on tick 206; at 2 units, 60 tics = 102.9: tick 103.
 *
 * Room A (x 0..1400, the player at (ax, 64)) | C (1400..1464, floor 0,
 * ceiling 128, tag 1) | room B (1464..1720); line 2 (x = 1400) has
 * `start`, line 5 (x = 1464) `stop`, both tagged 1; `enemy`: a zombieman
 * in C (further than the 1024 units at which it would see the player).
 */
static struct map *crusher_map(int start, int stop, int ax, int enemy)
{
	static const int w[] = { 1400, 64, 256 };
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 } };
	static const struct fix_thing zombie = { 1432, 64, 0, 3004, 7 };
	struct map *m = fix_row(w, s, 3, 128, ax, 64, 0, &zombie, enemy);

	assert_non_null(m);
	m->lines[2].special = (uint16_t)start;
	m->lines[2].tag = 1;
	m->lines[5].special = (uint16_t)stop;
	m->lines[5].tag = 1;
	m->sectors[1].tag = 1;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

/* Ticks until sector 1's ceiling is h (the mover stays: a crusher). */
static int ceil_ticks(struct sim *s, fx_t h, int max)
{
	for (int t = 1; t <= max; t++) {
		sim_tick(s, &spec_none);
		if (s->w.sec[1].ceil_h == h)
			return t;
	}
	return -1;
}

/* 73 (WR): down to 8 on tick 206, back up to 128 206 ticks later, and
 * down again. */
static void crusher_goes_down_and_up_for_ever(void **state)
{
	struct map *m = crusher_map(73, 0, 40, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	spec_cross(&s, G_WHO_PLAYER, 1400, 64, 1);
	assert_int_equal(ceil_ticks(&s, 8 * FX_ONE, 400), 206);
	assert_int_equal(ceil_ticks(&s, 128 * FX_ONE, 400), 206);
	spec_run(&s, &spec_none, 5);
	assert_true(s.w.sec[1].ceil_h < 128 * FX_ONE);
	assert_int_equal(s.w.num_movers, 1);
	map_free(m);
}

/* 77 (WR fast): down to 8 in 60 tics, tick 103. */
static void fast_crusher_goes_down_twice_as_fast(void **state)
{
	struct map *m = crusher_map(77, 0, 40, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	spec_cross(&s, G_WHO_PLAYER, 1400, 64, 1);
	assert_int_equal(ceil_ticks(&s, 8 * FX_ONE, 400), 103);
	map_free(m);
}

/* 25 (W1) with the player under it: nothing while the ceiling is 56 or
 * more above the floor, then 10 every 4 Doom tics; the ceiling slows to an
 * eighth: in the 32 tics from the first hit to the ninth it comes down 4
 * units (32 at full speed). 100 of health is ten hits. */
static void crusher_hurts_the_player_under_it(void **state)
{
	struct map *m = crusher_map(25, 0, 1432, 0);
	struct sim s;
	fx_t last, first_h = 0;
	uint32_t hit = 0;
	int hits = 0;
	(void)state;
	sim_init(&s, m, &spec_play);
	assert_int_equal(s.pl.sector, 1);
	spec_cross(&s, G_WHO_PLAYER, 1400, 64, 1);
	last = s.pl.health;
	for (int t = 0; t < 600 && s.g.phase == G_PH_PLAY; t++) {
		sim_tick(&s, &spec_none);
		if (s.pl.health == last)
			continue;
		assert_true(s.w.sec[1].ceil_h < 56 * FX_ONE);
		assert_int_equal(last - s.pl.health, 10 * FX_ONE);
		if (hits++)
			assert_int_equal(g_dtic(&s) - hit, 4);
		else
			first_h = s.w.sec[1].ceil_h;
		if (hits == 9)
			assert_in_range(first_h - s.w.sec[1].ceil_h, 3 * FX_ONE, 5 * FX_ONE);
		hit = g_dtic(&s);
		last = s.pl.health;
	}
	assert_int_equal(hits, 10);
	assert_int_equal(s.g.phase, G_PH_DEAD);
	map_free(m);
}

/* 25 with a zombieman (30 of health) under it: three hits of 10, 4 Doom
 * tics apart, kill it. */
static void crusher_kills_a_monster_under_it(void **state)
{
	struct map *m = crusher_map(25, 0, 40, 1);
	struct sim s;
	int16_t last;
	uint32_t hit = 0;
	int hits = 0;
	(void)state;
	sim_init(&s, m, &spec_play);
	assert_int_equal(s.g.num_enemies, 1);
	assert_int_equal(s.g.en[0].sector, 1);
	last = s.g.en[0].health;
	assert_int_equal(last, 30);
	spec_cross(&s, G_WHO_PLAYER, 1400, 64, 1);
	for (int t = 0; t < 600 && s.g.en[0].state != G_E_DEAD; t++) {
		sim_tick(&s, &spec_none);
		if (s.g.en[0].health == last)
			continue;
		assert_int_equal(s.g.en[0].sector, 1);
		assert_int_equal(last - s.g.en[0].health, 10);
		if (hits++)
			assert_int_equal(g_dtic(&s) - hit, 4);
		hit = g_dtic(&s);
		last = s.g.en[0].health;
	}
	assert_int_equal(hits, 3);
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	map_free(m);
}

/* 74 (WR) stops the crusher where it is; crossing its 73 (WR) again starts
 * the same one (no second mover) going the way it went. */
static void crusher_stops_and_starts_again(void **state)
{
	struct map *m = crusher_map(73, 74, 40, 0);
	struct sim s;
	fx_t h;
	(void)state;
	sim_init(&s, m, &spec_play);
	spec_cross(&s, G_WHO_PLAYER, 1400, 64, 1);
	spec_run(&s, &spec_none, 50);
	spec_cross(&s, G_WHO_PLAYER, 1464, 64, 1);
	h = s.w.sec[1].ceil_h;
	assert_true(h < 128 * FX_ONE && h > 8 * FX_ONE);
	spec_run(&s, &spec_none, 300);
	assert_int_equal(s.w.sec[1].ceil_h, h);
	spec_cross(&s, G_WHO_PLAYER, 1400, 64, 0);
	spec_run(&s, &spec_none, 10);
	assert_true(s.w.sec[1].ceil_h < h);
	assert_int_equal(s.w.num_movers, 1);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(lift_goes_down_waits_and_comes_up),
		cmocka_unit_test(a_lift_in_motion_is_not_started_twice),
		cmocka_unit_test(perpetual_platform_travels_and_waits_3_s),
		cmocka_unit_test(raise_and_change_takes_the_front_flat),
		cmocka_unit_test(raise_to_next_and_change_clears_the_special),
		cmocka_unit_test(crusher_goes_down_and_up_for_ever),
		cmocka_unit_test(fast_crusher_goes_down_twice_as_fast),
		cmocka_unit_test(crusher_hurts_the_player_under_it),
		cmocka_unit_test(crusher_kills_a_monster_under_it),
		cmocka_unit_test(crusher_stops_and_starts_again),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
