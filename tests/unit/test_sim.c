/* Tests for engine/game/sim.c: movement, collision, modes, determinism, hash. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/render/r_game.h"
#include "engine/render/r_main.h"
#include "g_fixture.h"
#include "map_fixture.h"

#define R (SIM_PLAYER_RADIUS)
#define TOL (FX_ONE / 256)             /* how close to a wall "stops at" means */

static const struct sim_settings play = { 1, 0, 1, 0, 0, 100, 1, 0, 0, 0 };
static const struct sim_settings attract2 = { 2, 0, 0, 0, 0, 100, 1, 0, 0, 0 };

/* A room 2048 x 256 with the start at (sx, sy) facing a. */
static struct map *room(int sx, int sy, ang_t a)
{
	static const int v[][2] = { { 0, 0 }, { 0, 256 }, { 2048, 256 }, { 2048, 0 } };
	static const struct fix_sector s[] = { { 0, 128, 160 } };
	static const struct fix_line l[] = {
		{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, -1 }, { 3, 0, 0, -1 },
	};
	struct fix_map f = { v, 4, s, 1, l, 4, sx, sy, a };
	struct map *m = fix_build(&f, NULL, 0);
	assert_non_null(m);
	return m;
}

/* Floors 0 | 16 | 48 side by side (x 0..256..512..768), y 0..128. */
static struct map *steps(void)
{
	static const int v[][2] = {
		{ 0, 0 }, { 0, 128 }, { 256, 128 }, { 256, 0 },
		{ 512, 128 }, { 512, 0 }, { 768, 128 }, { 768, 0 },
	};
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 16, 128, 160 }, { 48, 128, 160 } };
	static const struct fix_line l[] = {
		{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, 1 }, { 3, 0, 0, -1 },
		{ 2, 4, 1, -1 }, { 4, 5, 1, 2 }, { 5, 3, 1, -1 },
		{ 4, 6, 2, -1 }, { 6, 7, 2, -1 }, { 7, 5, 2, -1 },
	};
	static const struct fix_map f = { v, 8, s, 3, l, 10, 128, 64, 0 };
	struct map *m = fix_build(&f, NULL, 0);
	assert_non_null(m);
	return m;
}

/* Two rooms (floor 0, ceiling 128) joined through a 16-deep opening x
 * 256..272 whose floor is 8 (an easy step) and ceiling 56 (48 units of
 * room: too low for the player). */
static struct map *low_opening(void)
{
	static const int v[][2] = {
		{ 0, 0 }, { 0, 128 }, { 256, 128 }, { 256, 0 },
		{ 272, 128 }, { 272, 0 }, { 528, 128 }, { 528, 0 },
	};
	static const struct fix_sector s[] = { { 0, 128, 160 }, { 8, 56, 160 }, { 0, 128, 160 } };
	static const struct fix_line l[] = {
		{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, 1 }, { 3, 0, 0, -1 },
		{ 2, 4, 1, -1 }, { 4, 5, 1, 2 }, { 5, 3, 1, -1 },
		{ 4, 6, 2, -1 }, { 6, 7, 2, -1 }, { 7, 5, 2, -1 },
	};
	static const struct fix_map f = { v, 8, s, 3, l, 10, 128, 64, 0 };
	struct map *m = fix_build(&f, NULL, 0);
	assert_non_null(m);
	return m;
}

/* The built-in levels have enemies; movement tests take them out. */
static void no_enemies(struct sim *s)
{
	s->g.num_enemies = 0;
	s->g.alive = 0;
}

static void run(struct sim *s, const struct sim_cmd *c, int ticks)
{
	for (int i = 0; i < ticks; i++)
		sim_tick(s, c);
}

static void walking_into_a_wall_stops_at_the_radius(void **state)
{
	struct map *m = room(1800, 128, 0);
	struct sim s;
	struct sim_cmd fwd = { .forward = 127 };
	(void)state;
	sim_init(&s, m, &play);
	run(&s, &fwd, 200);
	assert_true(s.pl.x <= fx_from_int(2048) - R);
	assert_true(s.pl.x >= fx_from_int(2048) - R - TOL);
	assert_int_equal(s.pl.y, fx_from_int(128));
	/* and backwards into the west wall */
	fwd.forward = -127;
	run(&s, &fwd, 400);
	assert_true(s.pl.x >= R && s.pl.x <= R + TOL);
	map_free(m);
}

static void full_speed_is_about_eight_units_per_tick(void **state)
{
	struct map *m = room(64, 128, 0);
	struct sim s;
	struct sim_cmd fwd = { .forward = 127 };
	fx_t x;
	(void)state;
	sim_init(&s, m, &play);
	run(&s, &fwd, 100);
	x = s.pl.x;
	sim_tick(&s, &fwd);
	assert_true(s.pl.x - x > 7 * FX_ONE + FX_HALF && s.pl.x - x <= 8 * FX_ONE);
	/* friction brings it to rest once the stick is released */
	fwd.forward = 0;
	run(&s, &fwd, 120);
	assert_int_equal(s.pl.momx, 0);
	assert_int_equal(s.pl.momy, 0);
	x = s.pl.x;
	sim_tick(&s, &fwd);
	assert_int_equal(s.pl.x, x);
	map_free(m);
}

static void sliding_along_a_wall_at_45_degrees_moves_along_it(void **state)
{
	struct map *m = room(256, 200, ANG45);
	struct sim s;
	struct sim_cmd fwd = { .forward = 127 };
	fx_t x;
	(void)state;
	sim_init(&s, m, &play);
	run(&s, &fwd, 30);
	/* pressed against the north wall (y = 256) ... */
	assert_true(s.pl.y <= fx_from_int(256) - R && s.pl.y >= fx_from_int(256) - R - TOL);
	/* ... and still moving east along it, at about cos 45 of full speed */
	x = s.pl.x;
	run(&s, &fwd, 10);
	assert_true(s.pl.x - x > 10 * 5 * FX_ONE);
	assert_true(s.pl.y <= fx_from_int(256) - R && s.pl.y >= fx_from_int(256) - R - TOL);
	/* into the north-east corner, where it stops at the radius from both */
	run(&s, &fwd, 600);
	assert_true(s.pl.x <= fx_from_int(2048) - R && s.pl.x >= fx_from_int(2048) - R - TOL);
	assert_true(s.pl.y <= fx_from_int(256) - R && s.pl.y >= fx_from_int(256) - R - TOL);
	map_free(m);
}

static void strafing_and_turning(void **state)
{
	struct map *m = room(1024, 128, 0);
	struct sim s;
	struct sim_cmd c = { .turn = 16384 };  /* a quarter turn left */
	(void)state;
	sim_init(&s, m, &play);
	sim_tick(&s, &c);
	assert_int_equal(s.pl.angle, ANG90);
	c.turn = -16384;
	sim_tick(&s, &c);
	sim_tick(&s, &c);
	assert_int_equal(s.pl.angle, ANG270);
	/* facing south, strafing right goes west */
	c.turn = 0;
	c.side = 127;
	run(&s, &c, 10);
	assert_true(s.pl.x < fx_from_int(1024) - 20 * FX_ONE);
	assert_int_equal(s.pl.y, fx_from_int(128));
	map_free(m);
}

static void a_16_step_is_climbed_and_a_32_step_blocks(void **state)
{
	struct map *m = steps();
	struct sim s;
	struct sim_cmd fwd = { .forward = 127 };
	(void)state;
	sim_init(&s, m, &play);
	assert_int_equal(s.pl.z, 0);
	assert_int_equal(s.pl.viewz, SIM_VIEW_HEIGHT);
	run(&s, &fwd, 200);
	assert_int_equal(s.pl.sector, 1);
	assert_int_equal(s.pl.z, 16 * FX_ONE);
	assert_int_equal(s.pl.viewz, 16 * FX_ONE + SIM_VIEW_HEIGHT);
	/* the 48 floor is 32 above: blocked at the radius from its edge */
	assert_true(s.pl.x <= fx_from_int(512) - R && s.pl.x >= fx_from_int(512) - R - TOL);
	map_free(m);
}

static void stepping_down_is_immediate(void **state)
{
	struct map *m = steps();
	struct sim s;
	struct sim_cmd back = { .forward = -127 };
	(void)state;
	sim_init(&s, m, &play);
	s.pl.x = fx_from_int(384);             /* on the 16 step */
	run(&s, &back, 1);
	assert_int_equal(s.pl.z, 16 * FX_ONE);
	run(&s, &back, 100);
	assert_int_equal(s.pl.sector, 0);
	assert_int_equal(s.pl.z, 0);
	map_free(m);
}

static void an_opening_lower_than_the_player_blocks(void **state)
{
	struct map *m = low_opening();
	struct sim s;
	struct sim_cmd fwd = { .forward = 127 };
	(void)state;
	sim_init(&s, m, &play);
	run(&s, &fwd, 200);
	assert_int_equal(s.pl.sector, 0);
	assert_true(s.pl.x <= fx_from_int(256) - R && s.pl.x >= fx_from_int(256) - R - TOL);
	map_free(m);
}

/* ARENA1 (levels/arena1.txt): the start faces the window at x = 640. */
static void builtin_window_blocks_and_door_passes(void **state)
{
	struct map *m;
	struct sim s;
	struct sim_cmd fwd = { .forward = 127 };
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	sim_init(&s, m, &play);
	no_enemies(&s);
	assert_int_equal(s.pl.x, fx_from_int(96));
	assert_int_equal(s.pl.y, fx_from_int(192));
	run(&s, &fwd, 200);
	assert_int_equal(s.pl.sector, 0);
	assert_true(s.pl.x <= fx_from_int(640) - R && s.pl.x >= fx_from_int(640) - R - TOL);
	assert_int_equal(s.pl.y, fx_from_int(192));
	/* the doorway (y 320..416, ceiling 120) leads into the yard */
	s.pl.y = fx_from_int(368);
	run(&s, &fwd, 60);
	assert_int_equal(s.pl.sector, 5);
	assert_true(s.pl.x > fx_from_int(656));
	map_free(m);
}

static void builtin_ledge_is_a_one_way_drop(void **state)
{
	struct map *m;
	struct sim s;
	struct sim_cmd fwd = { .forward = 127 };
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	sim_init(&s, m, &play);
	no_enemies(&s);
	s.pl.x = fx_from_int(500);             /* on the gallery (floor 64) */
	s.pl.y = fx_from_int(900);
	s.pl.angle = 0;
	run(&s, &fwd, 1);
	assert_int_equal(s.pl.z, 64 * FX_ONE);
	run(&s, &fwd, 60);
	assert_int_equal(s.pl.sector, 5);      /* the yard */
	assert_int_equal(s.pl.z, 0);
	fwd.forward = -127;                    /* back west: a 64 wall now */
	run(&s, &fwd, 200);
	assert_int_equal(s.pl.sector, 5);
	assert_true(s.pl.x >= fx_from_int(656) + R && s.pl.x <= fx_from_int(656) + R + TOL);
	map_free(m);
}

/* ARENA1's sectors from its tables (-1: void). */
static int arena1_sector(double x, double y)
{
	if (x > 0 && x < 640 && y > 0 && y < 640) {
		if ((x > 448 && y > 448) || (x > 224 && x < 288 && y > 320 && y < 384))
			return -1;
		return 0;
	}
	if (x > 128 && x < 320 && y > 640 && y < 736)
		return 1 + (int)((y - 640) / 32);
	if (x > 0 && x < 656 && y > 736 && y < 1024)
		return 4;
	if (x > 656 && x < 1024 && y > 0 && y < 1024)
		return (x > 800 && x < 928 && y > 448 && y < 576) ? 6 : 5;
	if (x > 640 && x < 656 && y > 320 && y < 416)
		return 7;
	if (x > 640 && x < 656 && y > 128 && y < 256)
		return 8;
	return -1;
}

/* Distance (map units) from (x, y) to the nearest line (only one-sided ones
 * with walls_only). */
static double line_distance(const struct map *m, double x, double y, int walls_only)
{
	double best = 1e30;
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_vertex *a = &m->vertices[m->lines[i].v1];
		const struct map_vertex *b = &m->vertices[m->lines[i].v2];
		double ax = a->x / 65536.0, ay = a->y / 65536.0;
		double dx = b->x / 65536.0 - ax, dy = b->y / 65536.0 - ay;
		double t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);
		if (walls_only && m->lines[i].side[1] != MAP_NONE)
			continue;
		t = t < 0 ? 0 : t > 1 ? 1 : t;
		best = fmin(best, hypot(ax + t * dx - x, ay + t * dy - y));
	}
	return best;
}

/* A broken map: the player start lies outside its lines, 84 units from the
 * edge of the coordinate range (MAP_COORD_MAX, which every map keeps to).
 * Walking on east stops at the edge, a radius short of it, as at a wall;
 * a shot into the open misses at its full range, which would end past the
 * edge and so ends at it; and the state passes its own restore's checks
 * (what the flight recorder's recording of such a game needs). A start
 * 4 units from the edge, closer than a radius, still walks away from it. */
static void the_edge_of_the_coordinate_range_stops_a_body(void **state)
{
	struct map *m = room(16300, 128, 0);
	struct sim *s = malloc(sizeof(*s));
	(void)state;
	assert_non_null(s);
	sim_init(s, m, &play);
	run(s, &(struct sim_cmd){ .forward = 100 }, 100);
	assert_true(s->pl.x <= MAP_COORD_MAX - R);
	assert_true(s->pl.x > MAP_COORD_MAX - R - 8 * FX_ONE);
	run(s, &(struct sim_cmd){ .buttons = SIM_BT_FIRE }, 1);
	assert_int_equal(s->g.shot, G_SHOT_MISS);
	assert_int_equal(s->g.shot_x, MAP_COORD_MAX);
	assert_int_equal(gf_restores(s, m, &play, NULL), 0);
	map_free(m);
	/* placed within a radius of the edge, a body still moves inwards */
	m = room(16380, 128, ANG180);
	sim_init(s, m, &play);
	run(s, &(struct sim_cmd){ .forward = 100 }, 10);
	assert_true(s->pl.x < 16380 * FX_ONE - R);
	free(s);
	map_free(m);
}

/* Random commands for a long time: the player stays inside the level, out
 * of the walls, on the floor of the sector it is in. */
static void random_walk_stays_inside_the_level(void **state)
{
	struct map *m;
	struct sim s;
	uint32_t r = 99, visited = 0;
	struct sim_cmd c = { 0 };
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	sim_init(&s, m, &play);
	no_enemies(&s);
	for (int t = 0; t < 30000; t++) {
		double x, y;
		int sec;
		if (t % 20 == 0) {
			r = r * 1664525u + 1013904223u;
			c.forward = (int8_t)((int)(r >> 24) - 128 < -127 ? -127 : (int)(r >> 24) - 128);
			c.side = (int8_t)(((int)(r >> 16) & 0xff) - 128 < -127 ? -127
									 : ((int)(r >> 16) & 0xff) - 128);
			c.turn = (int16_t)((int)(r & 0x7ff) - 1024);
		}
		sim_tick(&s, &c);
		x = s.pl.x / 65536.0;
		y = s.pl.y / 65536.0;
		sec = arena1_sector(x, y);
		if (sec < 0 || line_distance(m, x, y, 1) < 16.0 - 1.0 / 256)
			fail_msg("tick %d: (%f, %f) sector %d wall %f", t, x, y, sec,
				 line_distance(m, x, y, 1));
		assert_int_equal(s.pl.z, m->sectors[s.pl.sector].floor_h);
		/* the sector is the one under the centre (either, on a portal) */
		if ((uint32_t)sec != s.pl.sector)
			assert_true(line_distance(m, x, y, 0) < 1.0 / 4096);
		visited |= 1u << s.pl.sector;
	}
	/* the walk went up the stairs and through the door */
	assert_true((visited & 0xbf) == 0xbf);
	map_free(m);
}

static void coins_make_credits_and_start_consumes_one(void **state)
{
	struct map *m = room(64, 64, 0);
	struct sim s;
	struct sim_cmd c = { .coins = 1 };
	(void)state;
	sim_init(&s, m, &attract2);
	assert_int_equal(s.mode, SIM_ATTRACT);
	sim_tick(&s, &c);
	assert_int_equal(s.credits, 0);
	assert_int_equal(s.coin_rem, 1);
	c.coins = 3;
	sim_tick(&s, &c);
	assert_int_equal(s.credits, 2);
	assert_int_equal(s.coin_rem, 0);
	assert_int_equal(s.coins_total, 4);
	c.coins = 0;
	c.buttons = SIM_BT_START;
	sim_tick(&s, &c);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.credits, 1);
	assert_int_equal(s.plays, 1);
	/* coins still count while playing */
	c.coins = 2;
	sim_tick(&s, &c);
	assert_int_equal(s.credits, 2);
	assert_int_equal(s.coins_total, 6);
	assert_int_equal(s.mode, SIM_PLAY);
	map_free(m);
}

static void start_needs_a_credit_and_a_fresh_press(void **state)
{
	struct map *m = room(64, 64, 0);
	struct sim s;
	struct sim_cmd c = { .buttons = SIM_BT_START };
	(void)state;
	sim_init(&s, m, &attract2);
	sim_tick(&s, &c);                      /* no credit */
	assert_int_equal(s.mode, SIM_ATTRACT);
	c.coins = 2;                           /* a credit while START is held */
	sim_tick(&s, &c);
	assert_int_equal(s.credits, 1);
	c.coins = 0;
	run(&s, &c, 5);                        /* still held: no new press */
	assert_int_equal(s.mode, SIM_ATTRACT);
	c.buttons = 0;
	sim_tick(&s, &c);
	c.buttons = SIM_BT_START;
	sim_tick(&s, &c);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.credits, 0);
	map_free(m);
}

static void freeplay_starts_without_credits(void **state)
{
	static const struct sim_settings fp = { 1, 1, 0, 0, 0, 100, 1, 0, 0, 0 };
	struct map *m = room(64, 64, 0);
	struct sim s;
	struct sim_cmd c = { .coins = 1 };
	(void)state;
	sim_init(&s, m, &fp);
	sim_tick(&s, &c);
	assert_int_equal(s.credits, 1);
	c.coins = 0;
	c.buttons = SIM_BT_START;
	sim_tick(&s, &c);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.credits, 1);        /* not consumed */
	assert_int_equal(s.plays, 1);
	map_free(m);
}

static void attract_ignores_movement_and_start_resets_the_player(void **state)
{
	static const struct sim_settings fp = { 1, 1, 0, 0, 0, 100, 1, 0, 0, 0 };
	struct map *m = room(300, 100, ANG90);
	struct sim s;
	struct sim_cmd c = { .forward = 127, .side = 50, .turn = 1000 };
	(void)state;
	sim_init(&s, m, &fp);
	run(&s, &c, 60);
	assert_int_equal(s.pl.x, fx_from_int(300));
	assert_int_equal(s.pl.y, fx_from_int(100));
	assert_int_equal(s.pl.momx, 0);
	assert_true(s.pl.angle != ANG90);      /* the idle camera turns */
	c = (struct sim_cmd){ .buttons = SIM_BT_START };
	sim_tick(&s, &c);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.pl.angle, ANG90);
	assert_int_equal(s.pl.x, fx_from_int(300));
	map_free(m);
}

static void start_in_play_skips_attract(void **state)
{
	struct map *m = room(64, 64, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &play);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.plays, 0);
	map_free(m);
}

static void without_a_start_the_player_spawns_inside_sector_0(void **state)
{
	struct map *m = room(64, 64, 0);
	struct sim s;
	(void)state;
	m->num_things = 0;
	sim_init(&s, m, &play);
	/* first line of sector 0 is the west wall (0,0)->(0,256): 32 east of
	 * its middle, facing north along it */
	assert_int_equal(s.pl.x, fx_from_int(32));
	assert_int_equal(s.pl.y, fx_from_int(128));
	assert_int_equal(s.pl.angle, ANG90);
	assert_int_equal(s.pl.sector, 0);
	map_free(m);
}

static struct sim_cmd scripted(int t)
{
	struct sim_cmd c = { 0 };
	c.forward = (int8_t)(t % 90 < 60 ? 127 : -40);
	c.side = (int8_t)(t % 37 < 10 ? 90 : 0);
	c.turn = (int16_t)(t % 50 < 25 ? 300 : -170);
	c.buttons = (uint8_t)(t == 5 || t == 400 ? SIM_BT_START : 0);
	c.coins = (uint8_t)(t == 3 ? 2 : 0);
	return c;
}

static void same_commands_give_same_hashes_every_tick(void **state)
{
	struct map *m;
	struct sim a, b;
	int t;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	sim_init(&a, m, &attract2);
	sim_init(&b, m, &attract2);
	assert_true(sim_hash(&a) == sim_hash(&b));
	for (t = 0; t < 2000; t++) {
		struct sim_cmd c = scripted(t);
		sim_tick(&a, &c);
		sim_tick(&b, &c);
		assert_true(sim_hash(&a) == sim_hash(&b));
	}
	assert_int_equal(a.mode, SIM_PLAY);
	map_free(m);
}

static void a_different_command_changes_the_hash(void **state)
{
	struct map *m;
	struct sim a, b;
	int t;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	sim_init(&a, m, &play);
	sim_init(&b, m, &play);
	for (t = 0; t < 100; t++) {
		struct sim_cmd c = scripted(t), d = c;
		if (t == 50)
			d.turn++;              /* 1/65536 of a turn, once */
		sim_tick(&a, &c);
		sim_tick(&b, &d);
		if (t < 50)
			assert_true(sim_hash(&a) == sim_hash(&b));
		else
			assert_true(sim_hash(&a) != sim_hash(&b));
	}
	map_free(m);
}

/* The current map (a borrowed pointer, walked by its own rule: its content
 * hash) is hashed. Every other field is, by the field lists: see
 * test_sim_hash.c, every_field_is_hashed_unless_spare_and_saved_in_place. */
static void hash_covers_the_current_map(void **state)
{
	struct map *m = room(64, 64, 0), *m2 = room(64, 64, ANG90);
	struct sim s, t;
	uint64_t h;
	(void)state;
	sim_init(&s, m, &play);
	h = sim_hash(&s);
	t = s;
	t.map = m2;
	assert_true(sim_hash(&t) != h);
	t.map = NULL;
	assert_true(sim_hash(&t) != h);
	map_free(m);
	map_free(m2);
}

/* A line's opening: the higher floor and the lower ceiling of its two
 * sectors (the fixture's 0/128 room and 8/56 opening: 8 and 56); none for
 * a one-sided or ML_BLOCKING line. */
static void a_line_opening_is_the_higher_floor_and_lower_ceiling(void **state)
{
	struct map *m = low_opening();
	struct sim s;
	fx_t floor = 7, ceil = 7;
	(void)state;
	sim_init(&s, m, &play);
	assert_int_equal(g_opening(&s, &m->lines[2], &floor, &ceil), 0);
	assert_int_equal(floor, 8 * FX_ONE);
	assert_int_equal(ceil, 56 * FX_ONE);
	assert_int_equal(g_opening(&s, &m->lines[0], &floor, &ceil), -1);
	m->lines[2].flags |= ML_BLOCKING;
	assert_int_equal(g_opening(&s, &m->lines[2], &floor, &ceil), -1);
	map_free(m);
}

static void view_follows_the_player(void **state)
{
	struct map *m = steps();
	struct sim s;
	struct r_view v;
	(void)state;
	sim_init(&s, m, &play);
	memset(&v, 0x55, sizeof v);
	r_game_view(&s, 320, &v);
	assert_int_equal(v.x, s.pl.x);
	assert_int_equal(v.y, s.pl.y);
	assert_int_equal(v.z, SIM_VIEW_HEIGHT);
	assert_int_equal(v.angle, s.pl.angle);
	assert_int_equal(v.shear, 0);
	/* looking up by a slope of 1/2: the horizon 80 rows down at 320
	 * wide (focal 160), 320 at 1280; looking down moves it up */
	s.pl.pitch = FX_HALF;
	r_game_view(&s, 320, &v);
	assert_int_equal(v.shear, 80);
	r_game_view(&s, 1280, &v);
	assert_int_equal(v.shear, 320);
	s.pl.pitch = -FX_HALF;
	r_game_view(&s, 320, &v);
	assert_int_equal(v.shear, -80);
	map_free(m);
}

static void mode_names_round_trip(void **state)
{
	(void)state;
	assert_string_equal(sim_mode_name(SIM_ATTRACT), "attract");
	assert_string_equal(sim_mode_name(SIM_PLAY), "play");
	assert_null(sim_mode_name(SIM_MODE_COUNT));
	assert_int_equal(sim_mode_from_name("attract"), SIM_ATTRACT);
	assert_int_equal(sim_mode_from_name("play"), SIM_PLAY);
	assert_int_equal(sim_mode_from_name("Play"), -1);
	assert_int_equal(sim_mode_from_name(""), -1);
}


/* ---- the game flow -------------------------------------------------- */

static const struct sim_cmd nothing = { 0 };
static const struct sim_cmd coin = { .coins = 1 };
static const struct sim_cmd start = { .buttons = SIM_BT_START };
static const struct sim_cmd shoot = { .buttons = SIM_BT_FIRE };

/* Two stages: a room with one grunt 300 ahead of the start, and a room
 * with the start elsewhere and two grunts. */
static void two_stages(struct map **a, struct map **b)
{
	static const struct gf_thing ta[] = { { 100, 128, 0, 1, 0 }, { 400, 128, ANG180, 3004, 0 } };
	static const struct gf_thing tb[] = { { 200, 64, ANG90, 1, 0 },
					      { 200, 400, 0, 3004, 0 }, { 900, 400, 0, 3004, 0 } };
	*a = gf_room(1024, 256, ta, 2, NULL, 0);
	*b = gf_room(1024, 512, tb, 3, NULL, 0);
	assert_non_null(*a);
	assert_non_null(*b);
}

static void kill_all(struct sim *s)
{
	for (int i = 0; i < s->g.num_enemies; i++)
		g_hurt_enemy(s, i, 1000);
}

static void clearing_a_stage_scores_a_bonus_and_loads_the_next(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
	const struct map *maps[2];
	struct map *a, *b;
	struct sim s;
	(void)state;
	two_stages(&a, &b);
	maps[0] = a;
	maps[1] = b;
	sim_init_stages(&s, maps, 2, &set, NULL, NULL);
	assert_ptr_equal(s.map, a);
	assert_int_equal(s.g.alive, 1);
	/* two shots kill the grunt 300 ahead */
	run(&s, &shoot, G_REFIRE + 1);
	assert_int_equal(s.g.alive, 0);
	assert_int_equal(s.g.phase, G_PH_CLEAR);
	/* the grunt's 100, stage 1's bonus, and the time bonus: 13 ticks off
	 * the 5-minute clock leave 299.8 s, 300 whole seconds rounded up */
	assert_int_equal(s.g.time_bonus, 300 * G_TIME_BONUS);
	assert_int_equal(s.g.score, 100 + G_STAGE_BONUS * 1 + 300 * G_TIME_BONUS);
	run(&s, &nothing, G_CLEAR_TICKS - 1);
	assert_int_equal(s.g.stage, 0);
	sim_tick(&s, &nothing);
	assert_int_equal(s.g.stage, 1);
	assert_ptr_equal(s.map, b);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.g.alive, 2);
	assert_int_equal(s.pl.x, fx_from_int(200));
	assert_int_equal(s.pl.y, fx_from_int(64));
	assert_int_equal(s.pl.angle, ANG90);
	assert_int_equal(s.pl.ammo, G_AMMO_START);        /* topped up to the start's */
	/* clearing the last stage loops to the first, one loop harder; more
	 * ammo than the start's is carried over */
	s.pl.ammo = 120;
	kill_all(&s);
	run(&s, &nothing, G_CLEAR_TICKS + 1);
	assert_int_equal(s.g.stage, 0);
	assert_int_equal(s.g.loop, 1);
	assert_int_equal(s.pl.ammo, 120);
	/* stage 2 cleared on its first tick: 17999 ticks left, 300 s again */
	assert_int_equal(s.g.score, 100 + G_STAGE_BONUS + 300 * G_TIME_BONUS + 200 +
					    2 * G_STAGE_BONUS + 300 * G_TIME_BONUS);
	assert_int_equal(g_enemy_damage(&s, G_GRUNT), 5 * FX_ONE * 125 / 100);
	map_free(a);
	map_free(b);
}

static void a_map_without_enemies_is_never_cleared(void **state)
{
	struct map *m = room(64, 64, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &play);
	run(&s, &nothing, 600);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.g.score, 0);
	map_free(m);
}

static void dying_costs_a_life_and_respawns_with_enemies_reset(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 2, 100, 1, 0, 0, 0 };
	struct map *a, *b;
	struct sim s;
	(void)state;
	two_stages(&a, &b);
	sim_init(&s, a, &set);
	assert_int_equal(s.g.lives, 2);
	s.g.en[0].x = fx_from_int(700);        /* moved away from its spawn point */
	s.g.en[0].state = G_E_CHASE;
	s.pl.x = fx_from_int(150);
	s.pl.ammo = 3;
	g_hurt_player(&s, fx_from_int(150));
	assert_int_equal(s.g.phase, G_PH_DEAD);
	assert_int_equal(s.pl.health, 0);
	run(&s, &nothing, G_DEAD_TICKS - 1);
	assert_int_equal(s.g.lives, 2);
	assert_true(s.pl.viewz < s.pl.z + SIM_VIEW_HEIGHT);  /* sank */
	sim_tick(&s, &nothing);
	assert_int_equal(s.g.lives, 1);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.pl.health, fx_from_int(G_HEALTH_MAX));
	assert_int_equal(s.pl.ammo, G_AMMO_START);
	assert_int_equal(s.pl.x, fx_from_int(100));
	assert_int_equal(s.pl.viewz, SIM_VIEW_HEIGHT);
	assert_int_equal(s.g.en[0].x, fx_from_int(400));
	assert_int_equal(s.g.en[0].state, G_E_IDLE);
	map_free(a);
	map_free(b);
}

static void die(struct sim *s)
{
	g_hurt_player(s, fx_from_int(1000));
	run(s, &nothing, G_DEAD_TICKS);
}

static void the_last_life_leads_to_the_continue_countdown(void **state)
{
	static const struct sim_settings set = { 1, 0, 0, 1, 1, 100, 1, 0, 0, 0 };
	struct map *a, *b;
	struct sim s;
	(void)state;
	two_stages(&a, &b);
	sim_init(&s, a, &set);
	sim_tick(&s, &coin);
	sim_tick(&s, &start);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.g.lives, 1);
	s.g.score = 700;
	die(&s);
	assert_int_equal(s.mode, SIM_GAMEOVER);
	assert_int_equal(s.countdown, G_CONTINUE_TICKS);
	/* start without a credit does nothing; the countdown runs */
	run(&s, &start, 60);
	assert_int_equal(s.mode, SIM_GAMEOVER);
	assert_int_equal(s.countdown, G_CONTINUE_TICKS - 60);
	/* a fire press takes a second off */
	sim_tick(&s, &shoot);
	assert_int_equal(s.countdown, G_CONTINUE_TICKS - 120);
	/* coin, then start: continue, score kept, lives back */
	sim_tick(&s, &coin);
	assert_int_equal(s.credits, 1);
	sim_tick(&s, &start);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.credits, 0);
	assert_int_equal(s.g.continues, 1);
	assert_int_equal(s.g.lives, 1);
	assert_int_equal(s.g.score, 700);
	assert_int_equal(s.plays, 1);          /* a continue is not a new play */
	assert_int_equal(s.pl.health, fx_from_int(G_HEALTH_MAX));
	map_free(a);
	map_free(b);
}

static void a_low_score_goes_back_to_attract_after_the_countdown(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 1, 100, 1, 0, 0, 0 };
	struct map *a, *b;
	struct sim s;
	(void)state;
	two_stages(&a, &b);
	sim_init(&s, a, &set);
	s.g.score = 999;                       /* the table's lowest is 1000 */
	die(&s);
	run(&s, &nothing, G_CONTINUE_TICKS - 1);
	assert_int_equal(s.mode, SIM_GAMEOVER);
	sim_tick(&s, &nothing);
	assert_int_equal(s.mode, SIM_ATTRACT);
	assert_int_equal(s.page, SIM_PAGE_TITLE);
	map_free(a);
	map_free(b);
}

static void initials_are_chosen_letter_by_letter_and_enter_the_table(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 1, 100, 1, 0, 0, 0 };
	static const struct sim_cmd fwd = { .forward = 127 }, left = { .turn = 384 };
	struct map *a, *b;
	struct sim s;
	(void)state;
	two_stages(&a, &b);
	sim_init(&s, a, &set);
	s.g.score = 5500;                      /* between 6000 and 5000: rank 5 (0-based) */
	s.g.stage = 0;
	die(&s);
	run(&s, &nothing, G_CONTINUE_TICKS);
	assert_int_equal(s.mode, SIM_INITIALS);
	assert_int_equal(s.ini_rank, 5);
	/* letter 1: forward twice (press, release, press): A -> C */
	sim_tick(&s, &fwd);
	sim_tick(&s, &nothing);
	sim_tick(&s, &fwd);
	sim_tick(&s, &nothing);
	sim_tick(&s, &shoot);
	sim_tick(&s, &nothing);
	/* letter 2 starts at C; turn left once: B */
	assert_int_equal(s.ini_pos, 1);
	assert_int_equal(s.ini[1], 2);
	sim_tick(&s, &left);
	sim_tick(&s, &nothing);
	sim_tick(&s, &shoot);
	sim_tick(&s, &nothing);
	/* letter 3: held forward repeats: 1 + one repeat after 20 ticks */
	run(&s, &fwd, 21);
	sim_tick(&s, &nothing);
	assert_int_equal(s.ini[2], 1 + 2);     /* B -> D */
	sim_tick(&s, &shoot);
	assert_int_equal(s.mode, SIM_ATTRACT);
	assert_int_equal(s.page, SIM_PAGE_SCORES);
	assert_int_equal(s.new_rank, 5);
	assert_memory_equal(s.scores.e[5].name, "CBD", 3);
	assert_int_equal(s.scores.e[5].score, 5500);
	assert_int_equal(s.scores.e[5].stage, 1);
	assert_int_equal(s.scores.e[6].score, 5000);  /* moved down */
	assert_int_equal(s.scores.e[9].score, 2000);  /* 1000 dropped */
	assert_int_equal(s.scores_gen, 1);
	map_free(a);
	map_free(b);
}

static void initials_time_out_with_the_letters_shown(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 1, 100, 1, 0, 0, 0 };
	struct map *a, *b;
	struct sim s;
	(void)state;
	two_stages(&a, &b);
	sim_init(&s, a, &set);
	s.g.score = 20000;
	die(&s);
	run(&s, &nothing, G_CONTINUE_TICKS);
	assert_int_equal(s.mode, SIM_INITIALS);
	run(&s, &nothing, G_INITIALS_TICKS);
	assert_int_equal(s.mode, SIM_ATTRACT);
	assert_memory_equal(s.scores.e[0].name, "AAA", 3);
	assert_int_equal(s.scores.e[0].score, 20000);
	map_free(a);
	map_free(b);
}

static void attract_pages_cycle_title_scores_demo(void **state)
{
	struct map *m = room(64, 64, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &attract2);
	assert_int_equal(s.page, SIM_PAGE_TITLE);
	run(&s, &nothing, SIM_TITLE_TICKS - 1);
	assert_int_equal(s.page, SIM_PAGE_TITLE);
	sim_tick(&s, &nothing);
	assert_int_equal(s.page, SIM_PAGE_SCORES);
	run(&s, &nothing, SIM_SCORES_TICKS);
	assert_int_equal(s.page, SIM_PAGE_DEMO);
	run(&s, &nothing, SIM_DEMO_TICKS);
	assert_int_equal(s.page, SIM_PAGE_TITLE);
	assert_int_equal(s.mode, SIM_ATTRACT);
	map_free(m);
}

static void service_enters_the_menu_from_play_and_leaves_to_attract(void **state)
{
	static const struct sim_cmd svc = { .buttons = SIM_BT_SERVICE };
	struct map *m = room(64, 64, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &play);
	sim_tick(&s, &svc);
	assert_int_equal(s.mode, SIM_SERVICE);
	assert_int_equal(s.menu.page, MENU_MAIN);
	run(&s, &svc, 10);                     /* held: no new press */
	assert_int_equal(s.mode, SIM_SERVICE);
	sim_tick(&s, &nothing);
	sim_tick(&s, &svc);
	assert_int_equal(s.mode, SIM_ATTRACT);
	assert_int_equal(s.page, SIM_PAGE_TITLE);
	map_free(m);
}

static void bookkeeping_counts_coins_plays_and_time(void **state)
{
	static const struct g_books base = { 10, 3, 1000, 5000 };
	struct map *m = room(64, 64, 0);
	const struct map *mp = m;
	struct sim s;
	(void)state;
	sim_init_stages(&s, &mp, 1, &attract2, NULL, &base);
	sim_tick(&s, &(struct sim_cmd){ .coins = 2 });
	sim_tick(&s, &start);
	run(&s, &nothing, 100);
	assert_int_equal(s.books.coins, 12);
	assert_int_equal(s.books.plays, 4);
	assert_int_equal(s.books.play_ticks, 1000 + 100);
	assert_int_equal(s.books.on_ticks, 5000 + 102);
	assert_int_equal(s.books_gen, 2);      /* the coins, the play */
	map_free(m);
}

static void the_table_given_at_init_decides_initials(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 1, 100, 1, 0, 0, 0 };
	struct g_scores high;
	struct map *a, *b;
	const struct map *mp;
	struct sim s;
	(void)state;
	two_stages(&a, &b);
	mp = a;
	g_scores_default(&high);
	for (int i = 0; i < G_SCORES; i++)
		high.e[i].score = 100000u - (uint32_t)i;
	sim_init_stages(&s, &mp, 1, &set, &high, NULL);
	s.g.score = 50000;                     /* would make the default table */
	die(&s);
	run(&s, &nothing, G_CONTINUE_TICKS);
	assert_int_equal(s.mode, SIM_ATTRACT);
	map_free(a);
	map_free(b);
}

static void difficulty_picks_things_by_skill_bits(void **state)
{
	static const struct gf_thing t[] = {
		{ 100, 128, 0, 1, 7 },
		{ 300, 128, 0, 3004, 1 },          /* easy only */
		{ 400, 128, 0, 3004, 2 },          /* normal only */
		{ 500, 128, 0, 3004, 4 },          /* hard only */
		{ 600, 128, 0, 3004, 6 },          /* normal and hard */
		{ 700, 128, 0, 3004, 0 },          /* no bits: every skill */
	};
	static const int want[4] = { 2, 3, 3, 3 };
	struct map *m = gf_room(1024, 256, t, 6, NULL, 0);
	(void)state;
	assert_non_null(m);
	for (int d = 0; d < 4; d++) {
		struct sim_settings set = { 1, 0, 1, (uint8_t)d, 1, 100, 1, 0, 0, 0 };
		struct sim s;
		sim_init(&s, m, &set);
		assert_int_equal(s.g.num_enemies, want[d]);
	}
	map_free(m);
}

static void difficulty_scales_speed(void **state)
{
	struct map *m = room(64, 64, 0);
	static const int pct[4] = { 80, 100, 115, 130 };
	(void)state;
	for (int d = 0; d < 4; d++) {
		struct sim_settings set = { 1, 0, 1, (uint8_t)d, 1, 100, 1, 0, 0, 0 };
		struct sim s;
		sim_init(&s, m, &set);
		assert_int_equal(g_enemy_speed(&s, G_BRUTE), 7 * FX_HALF * pct[d] / 100);
		assert_int_equal(g_enemy_speed(&s, G_SENTRY), 0);
	}
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(walking_into_a_wall_stops_at_the_radius),
		cmocka_unit_test(full_speed_is_about_eight_units_per_tick),
		cmocka_unit_test(sliding_along_a_wall_at_45_degrees_moves_along_it),
		cmocka_unit_test(strafing_and_turning),
		cmocka_unit_test(a_16_step_is_climbed_and_a_32_step_blocks),
		cmocka_unit_test(stepping_down_is_immediate),
		cmocka_unit_test(an_opening_lower_than_the_player_blocks),
		cmocka_unit_test(builtin_window_blocks_and_door_passes),
		cmocka_unit_test(builtin_ledge_is_a_one_way_drop),
		cmocka_unit_test(random_walk_stays_inside_the_level),
		cmocka_unit_test(the_edge_of_the_coordinate_range_stops_a_body),
		cmocka_unit_test(coins_make_credits_and_start_consumes_one),
		cmocka_unit_test(start_needs_a_credit_and_a_fresh_press),
		cmocka_unit_test(freeplay_starts_without_credits),
		cmocka_unit_test(attract_ignores_movement_and_start_resets_the_player),
		cmocka_unit_test(start_in_play_skips_attract),
		cmocka_unit_test(without_a_start_the_player_spawns_inside_sector_0),
		cmocka_unit_test(same_commands_give_same_hashes_every_tick),
		cmocka_unit_test(a_different_command_changes_the_hash),
		cmocka_unit_test(hash_covers_the_current_map),
		cmocka_unit_test(a_line_opening_is_the_higher_floor_and_lower_ceiling),
		cmocka_unit_test(view_follows_the_player),
		cmocka_unit_test(mode_names_round_trip),
		cmocka_unit_test(clearing_a_stage_scores_a_bonus_and_loads_the_next),
		cmocka_unit_test(a_map_without_enemies_is_never_cleared),
		cmocka_unit_test(dying_costs_a_life_and_respawns_with_enemies_reset),
		cmocka_unit_test(the_last_life_leads_to_the_continue_countdown),
		cmocka_unit_test(a_low_score_goes_back_to_attract_after_the_countdown),
		cmocka_unit_test(initials_are_chosen_letter_by_letter_and_enter_the_table),
		cmocka_unit_test(initials_time_out_with_the_letters_shown),
		cmocka_unit_test(attract_pages_cycle_title_scores_demo),
		cmocka_unit_test(service_enters_the_menu_from_play_and_leaves_to_attract),
		cmocka_unit_test(bookkeeping_counts_coins_plays_and_time),
		cmocka_unit_test(the_table_given_at_init_decides_initials),
		cmocka_unit_test(difficulty_picks_things_by_skill_bits),
		cmocka_unit_test(difficulty_scales_speed),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
