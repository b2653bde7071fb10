/*
 * Tests for engine/game/g_ceil.c's platforms: the lift (Doom's plat
 * down-wait-up-stay) started by a switch (SR 62).
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
#include "map_fixture.h"

static const struct sim_settings play = { 1, 0, 1, 0, 0, 100, 1 };

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

static void run(struct sim *s, const struct sim_cmd *c, int ticks)
{
	for (int i = 0; i < ticks; i++)
		sim_tick(s, c);
}

static void lift_goes_down_waits_and_comes_up(void **state)
{
	struct map *m = lift_map();
	struct sim s;
	const struct sim_cmd u = { .buttons = SIM_BT_USE }, none = { 0 };
	int t;
	(void)state;
	sim_init(&s, m, &play);
	assert_int_equal(s.w.sec[1].floor_h, 64 * FX_ONE);
	sim_tick(&s, &u);                          /* tick 1: it starts down */
	assert_int_equal(s.w.num_movers, 1);
	assert_int_equal(s.w.mv[0].kind, G_MV_PLAT);
	run(&s, &none, 26);                        /* tick 27: not yet */
	assert_true(s.w.sec[1].floor_h > 0);
	run(&s, &none, 1);                         /* tick 28: the bottom (room A's floor) */
	assert_int_equal(s.w.sec[1].floor_h, 0);
	for (t = 0; t < 300 && s.w.sec[1].floor_h == 0; t++)
		sim_tick(&s, &none);
	assert_in_range(t, 180, 181);              /* 3 s at the bottom */
	for (t = 0; t < 300 && s.w.num_movers > 0; t++)
		sim_tick(&s, &none);
	assert_in_range(t, 26, 28);                /* back up as fast, then it stays */
	assert_int_equal(s.w.sec[1].floor_h, 64 * FX_ONE);
	run(&s, &none, 400);
	assert_int_equal(s.w.sec[1].floor_h, 64 * FX_ONE);
	map_free(m);
}

static void a_lift_in_motion_is_not_started_twice(void **state)
{
	struct map *m = lift_map();
	struct sim s;
	const struct sim_cmd u = { .buttons = SIM_BT_USE }, none = { 0 };
	(void)state;
	sim_init(&s, m, &play);
	sim_tick(&s, &u);
	run(&s, &none, 10);
	sim_tick(&s, &u);
	assert_int_equal(s.w.num_movers, 1);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(lift_goes_down_waits_and_comes_up),
		cmocka_unit_test(a_lift_in_motion_is_not_started_twice),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
