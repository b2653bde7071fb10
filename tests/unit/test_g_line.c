/*
 * Tests for engine/game/g_line.c: switches (SW1/SW2 state, buttons popping
 * back after Doom's one second, 35 tics = 60 sim ticks), exits (normal and
 * secret, switched and walked over), a used line with nothing to do, and
 * USE opening the first door of Freedoom's E1M1 (skipped, and counted so,
 * without the freedoom package).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"
#include "input/io.h"
#include "spec_fixture.h"

static const struct sim_settings play = { 1, 0, 1, 0, 0, 100, 1, 0, 0, 0 };

/* Room A (x 0..256) | sector 1 (256..272, floor 0, ceiling 128, tag 1) |
 * room B; line 1 (y = 128, A's north wall) has `wall`, line 2 (x = 256)
 * has `special` tagged 1. The player stands at (sx, sy) facing `a`. */
static struct map *line_map(int special, int wall, int sx, int sy, ang_t a)
{
	static const int w[] = { 256, 16, 256 };
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 0, 0, 160 }, { 0, 128, 160 } };
	struct map *m = fix_row(w, s, 3, 128, sx, sy, a, NULL, 0);

	assert_non_null(m);
	m->lines[1].special = (uint16_t)wall;
	m->lines[2].special = (uint16_t)special;
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

static const struct sim_cmd use_cmd = { .buttons = SIM_BT_USE }, none = { 0 };

static void a_switch_stays_pressed_once_used(void **state)
{
	struct map *m = line_map(103, 0, 200, 64, 0);  /* S1 door open stay */
	struct sim s;
	(void)state;
	sim_init(&s, m, &play);
	assert_false(g_world_bit(s.w.switched, 2));
	sim_tick(&s, &use_cmd);
	assert_true(g_world_bit(s.w.switched, 2));
	assert_true(g_world_bit(s.w.used, 2));
	run(&s, &none, 300);
	assert_true(g_world_bit(s.w.switched, 2));
	assert_int_equal(s.w.sec[1].ceil_h, 124 * FX_ONE);
	map_free(m);
}

static void a_button_pops_back_after_a_second(void **state)
{
	struct map *m = line_map(63, 0, 200, 64, 0);   /* SR door open wait close */
	struct sim s;
	int t;
	(void)state;
	sim_init(&s, m, &play);
	sim_tick(&s, &use_cmd);
	assert_true(g_world_bit(s.w.switched, 2));
	assert_false(g_world_bit(s.w.used, 2));
	for (t = 0; t < 200 && g_world_bit(s.w.switched, 2); t++)
		sim_tick(&s, &none);
	assert_in_range(t, 59, 60);
	map_free(m);
}

static void exits_end_the_map(void **state)
{
	struct map *m = line_map(0, 11, 128, 80, 0x40000000u);  /* facing the north wall */
	struct sim s;
	(void)state;
	sim_init(&s, m, &play);
	sim_tick(&s, &use_cmd);
	assert_int_equal(s.g.phase, G_PH_INTER);
	assert_int_equal(s.w.exit, G_EXIT_NORMAL);
	map_free(m);
	m = line_map(0, 51, 128, 80, 0x40000000u);
	sim_init(&s, m, &play);
	sim_tick(&s, &use_cmd);
	assert_int_equal(s.g.phase, G_PH_INTER);
	assert_int_equal(s.w.exit, G_EXIT_SECRET);
	map_free(m);
}

/* The walk-over exits: 52 (W1) normal, 124 (W1) secret. */
static void walk_over_exits_end_the_map(void **state)
{
	static const int sp[][2] = { { 52, G_EXIT_NORMAL }, { 124, G_EXIT_SECRET } };
	(void)state;
	for (int i = 0; i < 2; i++) {
		struct map *m = line_map(sp[i][0], 0, 200, 64, 0);
		struct sim s;
		sim_init(&s, m, &play);
		run(&s, &none, 10);
		assert_int_equal(s.g.phase, G_PH_PLAY);
		spec_cross(&s, G_WHO_PLAYER, 256, 64, 1);
		assert_int_equal(s.g.phase, G_PH_INTER);
		assert_int_equal(s.w.exit, sp[i][1]);
		map_free(m);
	}
}

static void a_plain_wall_says_so(void **state)
{
	struct map *m = line_map(0, 0, 128, 80, 0x40000000u);
	struct sim s;
	(void)state;
	sim_init(&s, m, &play);
	sim_tick(&s, &use_cmd);
	assert_int_equal(s.w.msg, G_MSG_NOTHING);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	map_free(m);
}

/* The whole file (input/io.h), NULL when it cannot be read. */
static uint8_t *slurp(const char *path, size_t *len)
{
	uint8_t *d;

	return io_read_file(path, (size_t)1 << 30, 0, &d, len) == 0 ? d : NULL;
}

/* Freedoom's E1M1 (freedoom1.wad as Debian 12 ships it): the first door
 * east of the start, line 537 (DR, x = 544, y 672..752), closes sector 48
 * (floor and ceiling -128) between sectors 52 and 33 (ceilings 64). From
 * (500, 712) facing east USE opens it to 64 - 4 = 60, and the player walks
 * through into the sector beyond. */
static void e1m1_first_door_opens_and_the_player_walks_through(void **state)
{
	static const char path[] = "/usr/share/games/doom/freedoom1.wad";
	size_t len = 0;
	uint8_t *d = slurp(path, &len);
	struct wad *w;
	struct tex_set *t;
	struct map *m;
	struct sim s;
	char err[256];
	const struct sim_cmd fwd = { .forward = 127 };
	(void)state;
	if (!d) {
		print_message("SKIPPED: %s is not installed (Debian package freedoom)\n", path);
		skip();
	}
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, d, len, path, err, sizeof err), 0);
	assert_int_equal(tex_load_wad(w, &t, err, sizeof err), 0);
	assert_int_equal(map_load_wad(w, t, "E1M1", &m, err, sizeof err), 0);
	assert_int_equal(m->lines[537].special, 1);
	sim_init(&s, m, &play);
	s.g.num_enemies = 0;                   /* nobody shoots the test */
	s.g.alive = 0;
	s.pl.x = 500 * FX_ONE;
	s.pl.y = 712 * FX_ONE;
	s.pl.angle = 0;
	s.pl.sector = map_point_sector(m, s.pl.x, s.pl.y);
	assert_int_equal(s.pl.sector, 52);
	assert_int_equal(s.w.sec[48].ceil_h, -128 * FX_ONE);
	/* closed: forward stops at the door */
	run(&s, &fwd, 30);
	assert_int_equal(s.pl.sector, 52);
	sim_tick(&s, &use_cmd);
	run(&s, &none, 250);
	assert_int_equal(s.w.sec[48].ceil_h, 60 * FX_ONE);
	run(&s, &fwd, 40);
	assert_int_not_equal(s.pl.sector, 52);
	assert_true(s.pl.x > 560 * FX_ONE);
	map_free(m);
	tex_free(t);
	wad_free(w);
	free(d);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_switch_stays_pressed_once_used),
		cmocka_unit_test(a_button_pops_back_after_a_second),
		cmocka_unit_test(exits_end_the_map),
		cmocka_unit_test(walk_over_exits_end_the_map),
		cmocka_unit_test(a_plain_wall_says_so),
		cmocka_unit_test(e1m1_first_door_opens_and_the_player_walks_through),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
