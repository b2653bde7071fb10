/* Tests for engine/game/g_combat.c: line of sight, the hitscan shot, damage to
 * the player at the enemies' rates, pickups. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "g_fixture.h"
#include "map_fixture.h"

#define U(v) fx_from_int(v)

static const struct sim_settings normal = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };

static const struct sim_cmd idle = { 0 };
static const struct sim_cmd fire = { .buttons = SIM_BT_FIRE };

static void run(struct sim *s, const struct sim_cmd *c, int n)
{
	for (int i = 0; i < n; i++)
		sim_tick(s, c);
}

/* gf_arena, which a test needs to have built. */
static struct map *arena(const struct gf_thing *th, int n, const struct gf_box *b, int nb)
{
	struct map *m = gf_arena(th, n, b, nb);

	assert_non_null(m);
	return m;
}

static void sight_crosses_an_open_room_but_not_a_pillar(void **state)
{
	static const struct gf_box pillar = { 500, 200, 600, 300 };
	struct map *m = arena(NULL, 0, &pillar, 1);
	static const struct sim_settings set = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
	struct sim sim, *sm = &sim;
	fx_t z = U(40);
	(void)state;
	sim_init(&sim, m, &set);
	assert_true(g_sight(sm, U(100), U(100), z, U(1000), U(100), z));
	assert_false(g_sight(sm, U(100), U(250), z, U(1000), U(250), z));
	/* a line that just touches the pillar's corner (500, 300) is blocked */
	assert_false(g_sight(sm, U(400), U(200), z, U(600), U(400), z));
	/* one unit above the corner passes */
	assert_true(g_sight(sm, U(400), U(201), z, U(599), U(400), z));
	/* symmetric */
	assert_false(g_sight(sm, U(1000), U(250), z, U(100), U(250), z));
	map_free(m);
}

/* ARENA1's window (x 640..656, y 128..256, floor 40, ceiling 88). */
static void sight_through_a_window_depends_on_the_heights(void **state)
{
	struct map *m;
	static const struct sim_settings set = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
	struct sim sim, *sm = &sim;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	sim_init(&sim, m, &set);
	assert_true(g_sight(sm, U(600), U(192), U(41), U(700), U(192), U(41)));
	assert_true(g_sight(sm, U(600), U(192), U(20), U(700), U(192), U(60)));
	assert_false(g_sight(sm, U(600), U(192), U(20), U(700), U(192), U(39)));
	assert_false(g_sight(sm, U(600), U(192), U(100), U(700), U(192), U(90)));
	/* beside the window the hall's east wall blocks at any height */
	assert_false(g_sight(sm, U(600), U(100), U(60), U(700), U(100), U(60)));
	map_free(m);
}

static void a_grunt_at_300_units_takes_two_shots(void **state)
{
	static const struct gf_thing t[] = { { 428, 256, ANG180, 3004, 0 },
					     { 1900, 60, 0, 3004, 0 } };
	struct map *m = arena(t, 2, NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.num_enemies, 2);
	assert_int_equal(s.g.en[0].kind, G_GRUNT);
	assert_int_equal(s.g.en[0].health, 30);
	sim_tick(&s, &fire);                   /* shot 1 at once */
	assert_int_equal(s.g.shot, G_SHOT_ENEMY);
	assert_int_equal(s.g.en[0].health, 30 - G_SHOT_DAMAGE);
	assert_int_equal(s.pl.ammo, G_AMMO_START - 1);
	/* entry point: 300 - radius 20 along the ray */
	assert_int_equal(s.g.shot_x, U(128 + 300 - 20));
	run(&s, &fire, G_REFIRE - 1);          /* refire not yet over */
	assert_int_equal(s.pl.ammo, G_AMMO_START - 1);
	sim_tick(&s, &fire);                   /* shot 2 */
	assert_int_equal(s.pl.ammo, G_AMMO_START - 2);
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	assert_int_equal(s.g.alive, 1);
	assert_int_equal(s.g.kills, 1);
	assert_int_equal(s.g.score, g_kinds[G_GRUNT].score);
	/* the corpse is not solid and not a target: the next shot flies on */
	run(&s, &fire, G_REFIRE);
	assert_true(s.g.shot == G_SHOT_WALL);
	assert_int_equal(s.g.shot_x, U(2048));
	map_free(m);
}

static void a_shot_past_the_radius_misses(void **state)
{
	/* centre 21 units off the ray: the 20-unit circle is missed */
	static const struct gf_thing t[] = { { 428, 277, 0, 3004, 0 } };
	struct map *m = arena(t, 1, NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	sim_tick(&s, &fire);
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.en[0].health, 30);
	/* 19 off: hit */
	s.g.en[0].y = U(256 + 19);
	run(&s, &fire, G_REFIRE);
	assert_int_equal(s.g.shot, G_SHOT_ENEMY);
	assert_int_equal(s.g.en[0].health, 15);
	map_free(m);
}

static void the_nearest_enemy_on_the_ray_is_hit(void **state)
{
	static const struct gf_thing t[] = { { 900, 256, 0, 3004, 0 }, { 600, 256, 0, 3004, 0 } };
	struct map *m = arena(t, 2, NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	sim_tick(&s, &fire);
	assert_int_equal(s.g.en[0].health, 30);
	assert_int_equal(s.g.en[1].health, 15);
	map_free(m);
}

static void a_wall_in_front_of_the_enemy_takes_the_shot(void **state)
{
	static const struct gf_thing t[] = { { 900, 256, 0, 3004, 0 } };
	static const struct gf_box pillar = { 500, 200, 600, 300 };
	struct map *m = arena(t, 1, &pillar, 1);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	sim_tick(&s, &fire);
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.en[0].health, 30);
	/* the puff is on the pillar's west face, x = 500 */
	assert_true(s.g.shot_x >= U(500) - FX_ONE / 16 && s.g.shot_x <= U(500) + FX_ONE / 16);
	map_free(m);
}

static void no_ammo_no_shot(void **state)
{
	static const struct gf_thing t[] = { { 428, 256, 0, 3004, 0 } };
	struct map *m = arena(t, 1, NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	s.pl.ammo = 0;
	run(&s, &fire, 30);
	assert_int_equal(s.g.en[0].health, 30);
	assert_int_equal(s.g.shot, G_SHOT_NONE);
	map_free(m);
}

/* Runs until enemy 0 is in ATTACK; returns the ticks that took. */
static int until_attack(struct sim *s)
{
	int n = 0;
	while (s->g.en[0].state != G_E_ATTACK && n < 200) {
		sim_tick(s, &idle);
		n++;
	}
	assert_int_equal(s->g.en[0].state, G_E_ATTACK);
	return n;
}

/* A grunt attacks `reaction` ticks after it came into range, then every
 * `period` ticks, for `damage` each: 5 every 60 ticks is 5 per second. */
static void a_grunt_in_range_does_five_damage_per_second(void **state)
{
	static const struct gf_thing t[] = { { 428, 256, ANG180, 3004, 0 } };
	struct map *m = arena(t, 1, NULL, 0);
	const struct g_kind_info *k = &g_kinds[G_GRUNT];
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	assert_true(until_attack(&s) <= 9);    /* it looks every 8 ticks */
	assert_int_equal(k->damage * SIM_TICRATE / k->period, 5);
	run(&s, &idle, k->reaction - 1);
	assert_int_equal(s.pl.health, U(100));
	sim_tick(&s, &idle);
	assert_int_equal(s.pl.health, U(95));
	/* 10 seconds more: 10 more attacks, exactly 50 damage */
	run(&s, &idle, 10 * SIM_TICRATE - 1);
	assert_int_equal(s.pl.health, U(50));
	sim_tick(&s, &idle);
	assert_int_equal(s.pl.health, U(45));
	assert_true(s.pl.hurt > 0);
	/* the grunt stood still all the while: in range, it does not chase */
	assert_int_equal(s.g.en[0].x, U(428));
	map_free(m);
}

static void difficulty_scales_enemy_damage(void **state)
{
	static const struct gf_thing t[] = { { 428, 256, ANG180, 3004, 0 } };
	static const fx_t per_attack[4] = { 5 * FX_HALF, 5 * FX_ONE, 15 * FX_HALF, 10 * FX_ONE };
	struct map *m = arena(t, 1, NULL, 0);
	(void)state;
	for (int d = 0; d < 4; d++) {
		struct sim_settings set = normal;
		struct sim s;
		set.difficulty = (uint8_t)d;
		sim_init(&s, m, &set);
		assert_int_equal(g_enemy_damage(&s, G_GRUNT), per_attack[d]);
		until_attack(&s);
		run(&s, &idle, g_kinds[G_GRUNT].reaction);
		assert_int_equal(s.pl.health, U(100) - per_attack[d]);
	}
	map_free(m);
}

static void a_brute_chases_into_melee_range_and_hits_harder(void **state)
{
	static const struct gf_thing t[] = { { 900, 256, ANG180, 3002, 0 } };
	struct map *m = arena(t, 1, NULL, 0);
	const struct g_kind_info *k = &g_kinds[G_BRUTE];
	struct sim s;
	int n = 0;
	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.en[0].kind, G_BRUTE);
	/* 772 units at 3.5 per tick: about 3.5 s of walking */
	while (s.g.en[0].state != G_E_ATTACK && n < 600) {
		fx_t x = s.g.en[0].x;
		sim_tick(&s, &idle);
		if (s.g.en[0].state == G_E_CHASE)
			assert_true(x - s.g.en[0].x <= k->speed);
		n++;
	}
	assert_int_equal(s.g.en[0].state, G_E_ATTACK);
	assert_true(n > (772 - 64) * 2 / 7 && n < (772 - 64) * 2 / 7 + 20);
	assert_true(s.g.en[0].x - s.pl.x <= k->range);
	assert_true(s.g.en[0].x - s.pl.x > k->range - k->speed - 1);
	assert_int_equal(s.g.en[0].y, U(256));
	run(&s, &idle, k->reaction + 2 * k->period);
	assert_int_equal(s.pl.health, U(100 - 3 * 10));
	map_free(m);
}

static void a_sentry_never_moves(void **state)
{
	static const struct gf_thing t[] = { { 1800, 256, ANG180, 3005, 0 } };
	struct map *m = arena(t, 1, NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.en[0].kind, G_SENTRY);
	run(&s, &idle, 600);
	assert_int_equal(s.g.en[0].x, U(1800));
	/* 1672 away: beyond its sight distance (1024), it never woke */
	assert_int_equal(s.g.en[0].state, G_E_IDLE);
	s.pl.x = U(1200);                      /* 600 away: within range 768 */
	run(&s, &idle, 8 + g_kinds[G_SENTRY].reaction + 1);
	assert_int_equal(s.g.en[0].x, U(1800));
	assert_int_equal(s.pl.health, U(100 - 12));
	map_free(m);
}

static void a_chasing_enemy_slides_round_a_pillar_and_stays_out_of_walls(void **state)
{
	static const struct gf_thing t[] = { { 1000, 256, ANG180, 3002, 0 } };
	static const struct gf_box pillar = { 500, 180, 560, 330 };
	struct map *m = arena(t, 1, &pillar, 1);
	struct sim s;
	int reached = 0;
	(void)state;
	sim_init(&s, m, &normal);
	s.g.en[0].state = G_E_CHASE;           /* awake, behind the pillar */
	for (int i = 0; i < 1200 && !reached; i++) {
		const struct g_enemy *e = &s.g.en[0];
		int64_t r = g_kinds[G_BRUTE].radius;
		sim_tick(&s, &idle);
		/* the body never overlaps the pillar: the nearest point of the
		 * box is at least a radius away */
		int64_t nx = e->x < U(500) ? U(500) : e->x > U(560) ? U(560) : e->x;
		int64_t ny = e->y < U(180) ? U(180) : e->y > U(330) ? U(330) : e->y;
		int64_t dx = e->x - nx, dy = e->y - ny;
		assert_true(dx * dx + dy * dy >= r * r);
		reached = e->state == G_E_ATTACK;
	}
	assert_true(reached);
	map_free(m);
}

static void pickups_heal_and_give_ammo_only_when_useful(void **state)
{
	static const struct gf_thing t[] = { { 300, 256, 0, 2012, 0 },   /* medikit 25 */
					     { 600, 256, 0, 2007, 0 } }; /* clip 10 */
	struct map *m = arena(t, 2, NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.num_pickups, 2);
	/* at full health the medikit stays where it is */
	s.pl.x = U(300);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.pk[0].taken, 0);
	s.pl.health = U(90);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.pk[0].taken, 1);
	assert_int_equal(s.pl.health, U(100));  /* capped */
	assert_true(s.pl.bonus > 0);
	/* the clip: touching distance is the two radii, 16 + 20 */
	s.pl.x = U(600 - 36);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.pk[1].taken, 0);
	s.pl.x = U(600 - 35);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.pk[1].taken, 1);
	assert_int_equal(s.pl.ammo, G_AMMO_START + 10);
	map_free(m);
}

static void ammo_is_capped(void **state)
{
	static const struct gf_thing t[] = { { 300, 256, 0, 2048, 0 } };  /* 50 bullets */
	struct map *m = arena(t, 1, NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	s.pl.ammo = G_AMMO_MAX - 5;
	s.pl.x = U(300);
	sim_tick(&s, &idle);
	assert_int_equal(s.pl.ammo, G_AMMO_MAX);
	map_free(m);
}

/*
 * Vertical aim: a hall (floor 0, ceiling 256) x 0..768 with a ledge (floor
 * 96) x 768..1024 across its east end; the player at (128, 256) facing
 * east (eye 41), a grunt on the ledge at (900, 256) (feet 96, top 152). The
 * shot's line enters the grunt's circle 752 units out and crosses the
 * ledge's riser 640 out: it hits for slopes from 55/640 (over the riser's
 * top) to 111/752 (under the grunt's top), about 0.086 to 0.148.
 */
static struct map *ledge(void)
{
	static const int v[][2] = { { 0, 0 }, { 0, 512 }, { 768, 512 }, { 768, 0 },
				    { 1024, 512 }, { 1024, 0 } };
	static const struct fix_sector sc[] = { { 0, 256, 160 }, { 96, 256, 160 } };
	static const struct fix_line l[] = {
		{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, 1 }, { 3, 0, 0, -1 },
		{ 2, 4, 1, -1 }, { 4, 5, 1, -1 }, { 5, 3, 1, -1 },
	};
	static const struct fix_map f = { v, 6, sc, 2, l, 7, 128, 256, 0 };
	static const struct fix_thing t[] = { { 900, 256, ANG180, 3004, 0 } };
	struct map *m = fix_alloc_things(&f, t, 1);

	assert_non_null(m);
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

/* The sim on the ledge map with auto-aim on (free 0) or off, the pitch
 * raised by `up` ticks of LOOK_UP, then one shot. */
static void ledge_shot(struct sim *s, const struct map *m, int free, int up)
{
	struct sim_settings set = normal;
	struct sim_cmd look = { .buttons = SIM_BT_LOOK_UP };

	set.free_aim = (uint8_t)free;
	sim_init(s, m, &set);
	assert_int_equal(s->g.num_enemies, 1);
	assert_int_equal(s->g.en[0].z, U(96));
	run(s, &look, up);
	assert_int_equal(s->pl.pitch, up * G_PITCH_STEP);
	sim_tick(s, &fire);
}

static void the_pitch_moves_by_steps_within_its_range_and_both_centre(void **state)
{
	struct map *m = arena(NULL, 0, NULL, 0);
	struct sim s;
	const struct sim_cmd up = { .buttons = SIM_BT_LOOK_UP };
	const struct sim_cmd down = { .buttons = SIM_BT_LOOK_DOWN };
	const struct sim_cmd both = { .buttons = SIM_BT_LOOK_UP | SIM_BT_LOOK_DOWN };
	(void)state;
	/* the documented numbers (docs/game.md): the reach is 5/8, and held,
	 * the pitch goes from level to it in half a second: a step is 1/30 of
	 * the reach rounded down (the division loses under 1/65536 a step),
	 * so the half second's 30 steps come within 30/65536 of the top and
	 * the next tick stops on it */
	assert_int_equal(G_PITCH_MAX, FX_ONE * 5 / 8);
	sim_init(&s, m, &normal);
	assert_int_equal(s.pl.pitch, 0);
	run(&s, &up, 3);
	assert_int_equal(s.pl.pitch, 3 * G_PITCH_STEP);
	run(&s, &idle, 10);                    /* released: it stays */
	assert_int_equal(s.pl.pitch, 3 * G_PITCH_STEP);
	run(&s, &up, SIM_TICRATE / 2 - 3 - 1);
	assert_true(s.pl.pitch < G_PITCH_MAX - FX_ONE / 100);
	sim_tick(&s, &up);                     /* the half second's last tick */
	assert_true(s.pl.pitch > G_PITCH_MAX - 30);
	assert_true(s.pl.pitch <= G_PITCH_MAX);
	sim_tick(&s, &up);
	assert_int_equal(s.pl.pitch, G_PITCH_MAX);
	run(&s, &up, 100);                     /* held on: it stays at the top */
	assert_int_equal(s.pl.pitch, G_PITCH_MAX);
	run(&s, &down, SIM_TICRATE - 1);
	assert_true(s.pl.pitch > -G_PITCH_MAX);
	run(&s, &down, 100);
	assert_int_equal(s.pl.pitch, -G_PITCH_MAX);
	sim_tick(&s, &both);
	assert_int_equal(s.pl.pitch, 0);
	run(&s, &down, 2);                     /* down from level: negative */
	assert_int_equal(s.pl.pitch, -2 * G_PITCH_STEP);
	map_free(m);
}

static void a_raised_pitch_hits_the_ledge_enemy_and_level_misses_it(void **state)
{
	struct map *m = ledge();
	struct sim s;
	(void)state;
	/* auto-aim off, level: the shot meets the riser (its lower part) */
	ledge_shot(&s, m, 1, 0);
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.shot_x, U(768));
	assert_int_equal(s.g.en[0].health, 30);
	/* five steps up (slope 0.104): into the grunt's body */
	ledge_shot(&s, m, 1, 5);
	assert_int_equal(s.g.shot, G_SHOT_ENEMY);
	assert_int_equal(s.g.en[0].health, 30 - G_SHOT_DAMAGE);
	assert_true(s.g.shot_z > U(96) && s.g.shot_z < U(152));
	/* eight (0.167): over its head, on to the far wall */
	ledge_shot(&s, m, 1, 8);
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.shot_x, U(1024));
	assert_int_equal(s.g.en[0].health, 30);
	map_free(m);
}

static void the_ledges_lower_wall_stops_a_shot_that_would_reach_the_body(void **state)
{
	struct map *m = ledge();
	struct sim s;
	(void)state;
	/* four steps (0.083): 94.3 high at the riser (top 96), though 103.7
	 * where it would enter the grunt, inside its body */
	ledge_shot(&s, m, 1, 4);
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.shot_x, U(768));
	assert_true(s.g.shot_z < U(96));
	assert_int_equal(s.g.en[0].health, 30);
	map_free(m);
}

static void auto_aim_hits_the_ledge_enemy_level(void **state)
{
	struct map *m = ledge();
	struct sim s;
	(void)state;
	ledge_shot(&s, m, 0, 0);
	assert_int_equal(s.g.shot, G_SHOT_ENEMY);
	assert_int_equal(s.g.en[0].health, 30 - G_SHOT_DAMAGE);
	/* at the middle of its body (124) where the line enters (752 out) */
	assert_true(s.g.shot_z >= U(123) && s.g.shot_z <= U(125));
	/* an enemy beyond auto-aim's reach (slope 5/8) is not aimed at: the
	 * grunt lifted to 600 (middle 587 high at 752: slope 0.73) */
	sim_init(&s, m, &normal);
	s.g.en[0].z = U(600);
	assert_int_equal(g_aim(&s, s.pl.angle), 0);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sight_crosses_an_open_room_but_not_a_pillar),
		cmocka_unit_test(sight_through_a_window_depends_on_the_heights),
		cmocka_unit_test(a_grunt_at_300_units_takes_two_shots),
		cmocka_unit_test(a_shot_past_the_radius_misses),
		cmocka_unit_test(the_nearest_enemy_on_the_ray_is_hit),
		cmocka_unit_test(a_wall_in_front_of_the_enemy_takes_the_shot),
		cmocka_unit_test(no_ammo_no_shot),
		cmocka_unit_test(a_grunt_in_range_does_five_damage_per_second),
		cmocka_unit_test(difficulty_scales_enemy_damage),
		cmocka_unit_test(a_brute_chases_into_melee_range_and_hits_harder),
		cmocka_unit_test(a_sentry_never_moves),
		cmocka_unit_test(a_chasing_enemy_slides_round_a_pillar_and_stays_out_of_walls),
		cmocka_unit_test(pickups_heal_and_give_ammo_only_when_useful),
		cmocka_unit_test(ammo_is_capped),
		cmocka_unit_test(the_pitch_moves_by_steps_within_its_range_and_both_centre),
		cmocka_unit_test(a_raised_pitch_hits_the_ledge_enemy_and_level_misses_it),
		cmocka_unit_test(the_ledges_lower_wall_stops_a_shot_that_would_reach_the_body),
		cmocka_unit_test(auto_aim_hits_the_ledge_enemy_level),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
