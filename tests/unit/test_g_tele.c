/*
 * Tests for engine/game/g_tele.c: teleporters started by walking over
 * their line (g_line.c's g_cross).
 *
 * Doom's rules (p_telept.c EV_Teleport, p_map.c P_TeleportMove): a body
 * crossing a teleport line from its front side goes to the teleport
 * destination thing (type 14) in the sector tagged like the line, on that
 * sector's floor, facing the thing's angle, its momentum gone; the player
 * is then held still for 18 Doom tics (its reactiontime: 18 * 60 / 35 =
 * 30.9 sim ticks). Crossing from the back does nothing. The player kills
 * whatever stands on the destination (a telefrag); a monster is stopped
 * there by any body. 39 and 97 move players and monsters, 125 and 126
 * monsters only.
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

#define NORTH 0x40000000u
#define WEST 0x80000000u
#define DEST_X (512 * FX_ONE)
#define DEST_Y (64 * FX_ONE)

/* A (x 0..256) | P (256..320) | G (320..384) | D (384..640, floor 16,
 * tag 1) with the destination at (512, 64) facing north; line 2 (x = 256,
 * front A) has `special`, tag 1. The player starts at (px, py) facing pa;
 * `zombie`: a zombieman at (zx, zy) facing east. */
static struct map *tele_map(int special, int px, int py, ang_t pa, int zombie, int zx, int zy)
{
	static const int w[] = { 256, 64, 64, 256 };
	static const struct fix_sector s[] = {
		{ 0, 128, 160 }, { 0, 128, 160 }, { 0, 128, 160 }, { 16, 128, 160 },
	};
	const struct fix_thing th[] = { { 512, 64, NORTH, 14, 7 }, { zx, zy, 0, 3004, 7 } };
	struct map *m = fix_row(w, s, 4, 128, px, py, pa, th, 1 + zombie);

	assert_non_null(m);
	m->lines[2].special = (uint16_t)special;
	m->lines[2].tag = 1;
	m->sectors[3].tag = 1;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

static void the_player_lands_on_the_destination_facing_its_angle(void **state)
{
	struct map *m = tele_map(97, 200, 64, 0, 0, 0, 0);
	const struct sim_cmd fwd = { .forward = 127 };
	struct sim s;
	int t;
	(void)state;
	sim_init(&s, m, &spec_play);
	for (t = 0; t < 60 && s.pl.sector != 3; t++)
		sim_tick(&s, &fwd);
	assert_int_equal(s.pl.sector, 3);
	assert_int_equal(s.pl.x, DEST_X);
	assert_int_equal(s.pl.y, DEST_Y);
	assert_int_equal(s.pl.angle, NORTH);
	assert_int_equal(s.pl.z, 16 * FX_ONE);
	assert_int_equal(s.pl.momx, 0);
	assert_int_equal(s.pl.momy, 0);
	/* held still for 18 Doom tics (30.9 ticks) however hard it pushes */
	spec_run(&s, &fwd, 30);
	assert_int_equal(s.pl.x, DEST_X);
	assert_int_equal(s.pl.y, DEST_Y);
	spec_run(&s, &fwd, 10);
	assert_true(s.pl.y > DEST_Y);
	map_free(m);
}

static void crossing_from_the_back_does_nothing(void **state)
{
	struct map *m = tele_map(97, 300, 64, WEST, 0, 0, 0);
	const struct sim_cmd fwd = { .forward = 127 };
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	assert_int_equal(s.pl.sector, 1);
	spec_run(&s, &fwd, 30);
	assert_int_equal(s.pl.sector, 0);
	assert_true(s.pl.x < 256 * FX_ONE);
	assert_int_equal(s.pl.angle, WEST);
	map_free(m);
}

static void a_monster_teleports_too(void **state)
{
	struct map *m = tele_map(97, 40, 120, 0, 1, 100, 32);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	assert_int_equal(s.g.num_enemies, 1);
	spec_cross(&s, 0, 256, 32, 1);
	assert_int_equal(s.g.en[0].x, DEST_X);
	assert_int_equal(s.g.en[0].y, DEST_Y);
	assert_int_equal(s.g.en[0].angle, NORTH);
	assert_int_equal(s.g.en[0].sector, 3);
	assert_int_equal(s.g.en[0].z, 16 * FX_ONE);
	map_free(m);
}

/* The player standing on the destination: the monster stays where it was. */
static void a_monster_is_blocked_by_a_body_on_the_destination(void **state)
{
	struct map *m = tele_map(97, 512, 64, 0, 1, 100, 32);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	spec_cross(&s, 0, 256, 32, 1);
	assert_int_equal(s.g.en[0].x, 100 * FX_ONE);
	assert_int_equal(s.g.en[0].sector, 0);
	assert_int_not_equal(s.g.en[0].state, G_E_DEAD);
	map_free(m);
}

/* A zombieman standing on the destination: the player arrives and it dies. */
static void the_player_telefrags_a_monster_on_the_destination(void **state)
{
	struct map *m = tele_map(97, 200, 64, 0, 1, 520, 70);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	assert_int_not_equal(s.g.en[0].state, G_E_DEAD);
	spec_cross(&s, G_WHO_PLAYER, 256, 64, 1);
	assert_int_equal(s.pl.x, DEST_X);
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	map_free(m);
}

/* 126 (WR, monsters only): the player walks over it and stays in P; a
 * monster goes. */
static void a_monster_only_teleporter_leaves_the_player(void **state)
{
	struct map *m = tele_map(126, 200, 64, 0, 1, 100, 32);
	struct sim s;
	(void)state;
	sim_init(&s, m, &spec_play);
	spec_cross(&s, G_WHO_PLAYER, 256, 64, 1);
	assert_int_equal(s.pl.x, 200 * FX_ONE);
	assert_int_equal(s.pl.angle, 0);
	spec_cross(&s, 0, 256, 32, 1);
	assert_int_equal(s.g.en[0].x, DEST_X);
	assert_int_equal(s.g.en[0].sector, 3);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_player_lands_on_the_destination_facing_its_angle),
		cmocka_unit_test(crossing_from_the_back_does_nothing),
		cmocka_unit_test(a_monster_teleports_too),
		cmocka_unit_test(a_monster_is_blocked_by_a_body_on_the_destination),
		cmocka_unit_test(the_player_telefrags_a_monster_on_the_destination),
		cmocka_unit_test(a_monster_only_teleporter_leaves_the_player),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
