/*
 * Tests for engine/game/g_floor.c: the moving floors (raise and lower to
 * a neighbour's floor or ceiling, by 24 and 512, with a flat and special
 * change, the crushing raise) and the stairs, started by their lines.
 *
 * Expected values come from Doom's rules (p_floor.c), not from this code:
 * a floor moves FLOORSPEED, 1 unit a Doom tic (35 Hz), so d units take d
 * tics = d * 60 / 35 sim ticks (60 Hz), reached on the tick after that
 * rounded down (24 units: 41.1 ticks, tick 42). Stairs (build by 8) move
 * FLOORSPEED / 4 and the fast ones (by 16) FLOORSPEED * 4. The
 * destinations: to the lowest neighbour (own floor included), the highest
 * neighbour floor, the next neighbour floor above, the lowest neighbour
 * ceiling (at most its own), and that minus 8 for the crushing raise.
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

#define U(v) ((v) * FX_ONE)

/* Sector 0 (A, x 0..256, the player at (200, 64) facing east) | sector 1
 * (T, 256..320, tag 1) | sector 2 (B, 320..384); line 2 (x = 256, front A,
 * back T) has `special`, tag 1. Floors and ceilings as given. */
static struct map *floor_map(int special, const struct fix_sector s[3], int player_in_t)
{
	static const int w[] = { 256, 64, 64 };
	struct map *m = fix_row(w, s, 3, 128, player_in_t ? 288 : 200, 64, 0, NULL, 0);

	assert_non_null(m);
	m->lines[2].special = (uint16_t)special;
	m->lines[2].tag = 1;
	m->sectors[1].tag = 1;
	return m;
}

static void finish(struct map *m, struct sim *s)
{
	assert_int_equal(map_finish(m, NULL, 0), 0);
	sim_init(s, m, &spec_play);
	assert_int_equal(s->mode, SIM_PLAY);
}

/* USE on the switch (tick 1, the floor's first move): the tick on which T
 * reached h and stopped. */
static int use_ticks(struct sim *s, fx_t h, int max)
{
	int t;

	sim_tick(s, &spec_use_cmd);
	assert_true(g_world_bit(s->w.switched, 2));
	t = spec_ticks_to(s, 1, 0, h, max);
	assert_true(t > 0);
	return 1 + t;
}

/* 18 (S1): A at 32 and B at 64 are above T (0): T rises to the nearer, 32,
 * in 32 tics = 54.9 ticks: tick 55. */
static void raise_to_next_floor(void **state)
{
	static const struct fix_sector s[] = { { 32, 128, 160 }, { 0, 128, 160 }, { 64, 128, 160 } };
	struct map *m = floor_map(18, s, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	assert_int_equal(use_ticks(&sim, U(32), 400), 55);
	spec_run(&sim, &spec_none, 100);
	assert_int_equal(sim.w.sec[1].floor_h, U(32));
	map_free(m);
}

/* 102 (S1): T at 96 lowers to the highest neighbour floor, B's 64 (not
 * A's 32): 32 units, tick 55. */
static void lower_to_highest_neighbour(void **state)
{
	static const struct fix_sector s[] = { { 32, 128, 160 }, { 96, 200, 160 }, { 64, 128, 160 } };
	struct map *m = floor_map(102, s, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	assert_int_equal(use_ticks(&sim, U(64), 400), 55);
	map_free(m);
}

/* 23 (S1): T at 96 lowers to the lowest floor around, A's 32: 64 units,
 * 64 tics = 109.7 ticks: tick 110. */
static void lower_to_lowest_neighbour(void **state)
{
	static const struct fix_sector s[] = { { 32, 128, 160 }, { 96, 200, 160 }, { 64, 128, 160 } };
	struct map *m = floor_map(23, s, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	assert_int_equal(use_ticks(&sim, U(32), 400), 110);
	map_free(m);
}

/* 101 (S1): T (floor 0, ceiling 200) rises to the lowest ceiling around,
 * B's 128 (A's is 160): 128 tics = 219.4 ticks: tick 220. */
static void raise_to_lowest_neighbour_ceiling(void **state)
{
	static const struct fix_sector s[] = { { 0, 160, 160 }, { 0, 200, 160 }, { 0, 128, 160 } };
	struct map *m = floor_map(101, s, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	assert_int_equal(use_ticks(&sim, U(128), 400), 220);
	map_free(m);
}

/* 58 (W1): T rises 24 units (tick 42); the line is used up, so crossing
 * it again does nothing. */
static void raise_by_24_once(void **state)
{
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 } };
	struct map *m = floor_map(58, s, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 1);
	assert_int_equal(spec_ticks_to(&sim, 1, 0, U(24), 400), 42);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 0);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 1);
	spec_run(&sim, &spec_none, 100);
	assert_int_equal(sim.w.sec[1].floor_h, U(24));
	map_free(m);
}

/* 140 (S1): T (ceiling 1024) rises 512 units: 512 tics = 877.7 ticks,
 * tick 878. */
static void raise_by_512(void **state)
{
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 0, 1024, 160 }, { 0, 128, 160 } };
	struct map *m = floor_map(140, s, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	assert_int_equal(use_ticks(&sim, U(512), 1000), 878);
	map_free(m);
}

/* 140 (S1) on a floor 100 units below the height limit (MAP_HEIGHT_MAX,
 * which the loader holds every map to and the renderer's and the eye's
 * fixed point need): the floor stops at the limit, not 412 units past it. */
static void raise_by_512_stops_at_the_height_limit(void **state)
{
	static const struct fix_sector s[] = { { 0, 128, 160 },
					       { 16283, 16383, 160 },
					       { 0, 128, 160 } };
	struct map *m = floor_map(140, s, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	sim_tick(&sim, &spec_use_cmd);
	spec_run(&sim, &spec_none, 1000);
	assert_int_equal(sim.w.sec[1].floor_h, MAP_HEIGHT_MAX);
	map_free(m);
}

/* 59 (W1): raise by 24 and change: T takes the flat and the special of the
 * line's front sector (A) when it starts (Doom's raiseFloor24AndChange). */
static void raise_by_24_takes_the_front_flat_at_once(void **state)
{
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 } };
	struct map *m = floor_map(59, s, 0);
	struct sim sim;
	(void)state;
	m->sectors[0].floor_tex = 6;
	m->sectors[1].special = 7;                 /* damage 5: to be replaced by A's none */
	finish(m, &sim);
	assert_int_equal(sim.w.sec[1].special, 7);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 1);
	assert_int_equal(sim.w.sec[1].floor_tex, 6);
	assert_int_equal(sim.w.sec[1].special, 0);
	assert_int_equal(spec_ticks_to(&sim, 1, 0, U(24), 400), 42);
	map_free(m);
}

/* 37 (W1): lower to the lowest floor around and change: T (96) goes to
 * B's 32 and takes B's flat and special when it gets there (Doom changes
 * them at the end), not before. */
static void lower_and_change_takes_the_lowest_flat_at_the_end(void **state)
{
	static const struct fix_sector s[] = { { 64, 128, 160 }, { 96, 200, 160 }, { 32, 128, 160 } };
	struct map *m = floor_map(37, s, 0);
	struct sim sim;
	(void)state;
	m->sectors[2].floor_tex = 9;
	m->sectors[2].special = 5;
	finish(m, &sim);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 1);
	spec_run(&sim, &spec_none, 50);
	assert_true(sim.w.sec[1].floor_h < U(96) && sim.w.sec[1].floor_h > U(32));
	assert_int_equal(sim.w.sec[1].floor_tex, 1);
	assert_int_equal(sim.w.sec[1].special, 0);
	/* 64 units: 109.7 ticks in all, 50 of them gone */
	assert_int_equal(spec_ticks_to(&sim, 1, 0, U(32), 400), 110 - 50);
	assert_int_equal(sim.w.sec[1].floor_tex, 9);
	assert_int_equal(sim.w.sec[1].special, 5);
	map_free(m);
}

/* 56 (W1): the crushing raise goes to the lowest ceiling around - 8 = 120
 * (128 tics less 8: 120 tics = 205.7 ticks, tick 206) even with the player
 * in the way, hurting 10 every 4 Doom tics once the player (56 high) no
 * longer fits: from floor 72 on. */
static void crushing_raise_crushes_and_goes_on(void **state)
{
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 } };
	struct map *m = floor_map(56, s, 1);
	struct sim sim;
	fx_t last;
	uint32_t hit = 0;
	int t, hits = 0;
	(void)state;
	finish(m, &sim);
	assert_int_equal(sim.pl.sector, 1);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 1);
	last = sim.pl.health;
	for (t = 1; t <= 400 && g_mover_of(&sim, 1); t++) {
		sim_tick(&sim, &spec_none);
		if (sim.pl.health == last)
			continue;
		assert_true(sim.w.sec[1].floor_h > U(72));
		assert_int_equal(last - sim.pl.health, U(10));
		if (hits++)
			assert_int_equal(g_dtic(&sim) - hit, 4);
		hit = g_dtic(&sim);
		last = sim.pl.health;
	}
	assert_int_equal(t - 1, 206);
	assert_int_equal(sim.w.sec[1].floor_h, U(120));
	/* 72..120 is 48 tics: 12 hits of 10, so the 100 of health is gone */
	assert_in_range(hits, 10, 12);
	assert_int_equal(sim.g.phase, G_PH_DEAD);
	map_free(m);
}

/* The fast floors move FLOORSPEED * 4, 4 units a tic. 36 (W1): T at 96
 * lowers to the highest neighbour floor + 8 = 72: 24 units, 6 tics = 10.3
 * ticks, tick 11. 130 (W1): T at 0 rises to the next floor up, A's 32: 8
 * tics = 13.7 ticks, tick 14. */
static void fast_floors_move_4_units_a_tic(void **state)
{
	static const struct fix_sector low[] = { { 32, 128, 160 }, { 96, 200, 160 }, { 64, 128, 160 } };
	static const struct fix_sector up[] = { { 32, 128, 160 }, { 0, 128, 160 }, { 64, 128, 160 } };
	struct map *m = floor_map(36, low, 0);
	struct sim sim;
	(void)state;
	finish(m, &sim);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 1);
	assert_int_equal(spec_ticks_to(&sim, 1, 0, U(72), 400), 11);
	map_free(m);
	m = floor_map(130, up, 0);
	finish(m, &sim);
	spec_cross(&sim, G_WHO_PLAYER, 256, 64, 1);
	assert_int_equal(spec_ticks_to(&sim, 1, 0, U(32), 400), 14);
	map_free(m);
}

/* Stairs: A | steps 1..4 (tag 1 on the first) | a step of another flat |
 * one more of the first flat, each 32 wide; line 2 has `special`. */
static struct map *stairs_map(int special)
{
	static const int w[] = { 256, 32, 32, 32, 32, 32, 32 };
	static const struct fix_sector s[] = {
		{ 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 },
		{ 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 },
	};
	struct map *m = fix_row(w, s, 7, 128, 200, 64, 0, NULL, 0);

	assert_non_null(m);
	m->lines[2].special = (uint16_t)special;
	m->lines[2].tag = 1;
	m->sectors[1].tag = 1;
	m->sectors[5].floor_tex = 4;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

/* 7 (S1, by 8): the steps end at 8, 16, 24, 32; the differently textured
 * sector and the one beyond it stay at 0. All steps move FLOORSPEED / 4
 * together: the first reaches 8 in 32 tics (54.9 ticks: tick 55), the
 * fourth 32 in 128 tics (219.4 ticks: tick 220). */
static void stairs_by_8(void **state)
{
	struct map *m = stairs_map(7);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	sim_tick(&s, &spec_use_cmd);               /* tick 1 */
	assert_int_equal(s.w.num_movers, 4);
	spec_run(&s, &spec_none, 53);              /* tick 54 */
	assert_true(s.w.sec[1].floor_h < U(8));
	spec_run(&s, &spec_none, 1);               /* tick 55 */
	assert_int_equal(s.w.sec[1].floor_h, U(8));
	assert_int_equal(spec_ticks_to(&s, 4, 0, U(32), 400) + 55, 220);
	for (int i = 1; i <= 4; i++)
		assert_int_equal(s.w.sec[i].floor_h, U(8 * i));
	assert_int_equal(s.w.sec[5].floor_h, 0);
	assert_int_equal(s.w.sec[6].floor_h, 0);
	assert_int_equal(s.w.num_movers, 0);
	map_free(m);
}

/* 127 (S1, fast by 16): 16, 32, 48, 64 at 4 units a tic: the fourth's 64
 * units take 16 tics = 27.4 ticks, tick 28. */
static void stairs_by_16_fast(void **state)
{
	struct map *m = stairs_map(127);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	sim_tick(&s, &spec_use_cmd);
	assert_int_equal(spec_ticks_to(&s, 4, 0, U(64), 400) + 1, 28);
	for (int i = 1; i <= 4; i++)
		assert_int_equal(s.w.sec[i].floor_h, U(16 * i));
	assert_int_equal(s.w.sec[5].floor_h, 0);
	assert_int_equal(s.w.sec[6].floor_h, 0);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(raise_to_next_floor),
		cmocka_unit_test(lower_to_highest_neighbour),
		cmocka_unit_test(lower_to_lowest_neighbour),
		cmocka_unit_test(raise_to_lowest_neighbour_ceiling),
		cmocka_unit_test(raise_by_24_once),
		cmocka_unit_test(raise_by_512),
		cmocka_unit_test(raise_by_512_stops_at_the_height_limit),
		cmocka_unit_test(raise_by_24_takes_the_front_flat_at_once),
		cmocka_unit_test(lower_and_change_takes_the_lowest_flat_at_the_end),
		cmocka_unit_test(crushing_raise_crushes_and_goes_on),
		cmocka_unit_test(fast_floors_move_4_units_a_tic),
		cmocka_unit_test(stairs_by_8),
		cmocka_unit_test(stairs_by_16_fast),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
