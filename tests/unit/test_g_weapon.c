/* Tests for engine/game/g_weapon.c and the weapons' shots in g_combat.c:
 * the spread gun's fan of pellets, ammo and refire per weapon, weapon
 * pickups, the weapon-change press, and the pistol after a death. The
 * numbers expected are the rules of docs/game.md's weapons table, written
 * out here rather than read from g_weapons, so a changed table fails. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "g_fixture.h"

#define U(v) fx_from_int(v)

/* start_in_play, NORMAL, 3 lives */
static const struct sim_settings normal = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };

static const struct sim_cmd idle = { 0 };
static const struct sim_cmd fire = { .buttons = SIM_BT_FIRE };
static const struct sim_cmd change = { .buttons = SIM_BT_WEAPON };

/* gf_arena without pillars, which a test needs to have built. */
static struct map *arena(const struct gf_thing *th, int n)
{
	struct map *m = gf_arena(th, n, NULL, 0);

	assert_non_null(m);
	return m;
}

static void hold(struct sim *s, int w)
{
	s->pl.weapons = G_W_BIT(G_W_PISTOL) | G_W_BIT(G_W_SPREAD) | G_W_BIT(G_W_RAPID);
	s->pl.weapon = (uint8_t)w;
}

/* The game starts with the pistol only, in hand. */
static void a_game_starts_with_the_pistol_only(void **state)
{
	struct map *m = arena(NULL, 0);
	struct sim s;

	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.pl.weapons, G_W_BIT(G_W_PISTOL));
	assert_int_equal(s.pl.weapon, G_W_PISTOL);
	map_free(m);
}

/* Three grunts side by side 600 units ahead, 40 apart (touching): the
 * pistol's one ray hits the middle one only; the spread gun's seven
 * pellets, 1.25 degrees apart, reach all three. At 600 units a pellet at
 * angle a passes 600 sin a off the centre line: 0 and +-13.1 units hit the
 * middle grunt (3 pellets, 30 damage: dead), +-26.2 and +-39.2 units pass
 * within 20 of a side grunt's centre at 40 (2 pellets each, 20 damage). */
static void the_spread_reaches_enemies_side_by_side(void **state)
{
	static const struct gf_thing t[] = { { 728, 216, ANG180, 3004, 0 },
					     { 728, 256, ANG180, 3004, 0 },
					     { 728, 296, ANG180, 3004, 0 } };
	struct map *m = arena(t, 3);
	struct sim s;

	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.num_enemies, 3);
	sim_tick(&s, &fire);                   /* the pistol */
	assert_int_equal(s.g.en[0].health, 30);
	assert_int_equal(s.g.en[1].health, 30 - 15);
	assert_int_equal(s.g.en[2].health, 30);

	sim_init(&s, m, &normal);
	hold(&s, G_W_SPREAD);
	sim_tick(&s, &fire);
	assert_int_equal(s.g.shot, G_SHOT_ENEMY);
	assert_int_equal(s.g.en[1].state, G_E_DEAD);
	assert_int_equal(s.g.kills, 1);
	assert_int_equal(s.g.en[0].health, 30 - 2 * 10);
	assert_int_equal(s.g.en[2].health, 30 - 2 * 10);
	map_free(m);
}

/* A grunt 30 units off the centre line at 600: the pistol misses it (20
 * radius), the spread's pellets at 1.25, 2.5 and 3.75 degrees (13.1, 26.2,
 * 39.2 units off) pass within 20 of its centre: 3 pellets, a kill. */
static void a_spread_shot_kills_what_the_pistol_misses(void **state)
{
	static const struct gf_thing t[] = { { 728, 286, ANG180, 3004, 0 } };
	struct map *m = arena(t, 1);
	struct sim s;

	(void)state;
	sim_init(&s, m, &normal);
	sim_tick(&s, &fire);
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.en[0].health, 30);

	sim_init(&s, m, &normal);
	hold(&s, G_W_SPREAD);
	sim_tick(&s, &fire);
	assert_int_equal(s.g.shot, G_SHOT_ENEMY);
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	assert_int_equal(s.g.kills, 1);
	map_free(m);
}

/* FIRE held for 120 ticks: a shot at once and then one every refire
 * ticks, each spending the weapon's ammo: pistol 12 ticks and 1 ammo (10
 * shots), spread 42 and 3 (3 shots, 9 ammo), rapid 6 and 1 (20 shots). */
static void ammo_and_refire_per_weapon(void **state)
{
	static const struct {
		int w, used;
	} want[] = { { G_W_PISTOL, 10 }, { G_W_SPREAD, 9 }, { G_W_RAPID, 20 } };
	static const struct gf_thing t[] = { { 1900, 60, 0, 3004, 0 } };
	struct map *m = arena(t, 1);
	struct sim s;

	(void)state;
	for (size_t i = 0; i < sizeof(want) / sizeof(want[0]); i++) {
		sim_init(&s, m, &normal);
		hold(&s, want[i].w);
		for (int k = 0; k < 120; k++)
			sim_tick(&s, &fire);
		assert_int_equal(G_AMMO_START - s.pl.ammo, want[i].used);
	}
	/* the spread gun needs its 3: with 2 left it does not fire */
	sim_init(&s, m, &normal);
	hold(&s, G_W_SPREAD);
	s.pl.ammo = 2;
	sim_tick(&s, &fire);
	assert_int_equal(s.pl.ammo, 2);
	assert_int_equal(s.g.shot, G_SHOT_NONE);
	/* the pistol does with 1 */
	s.pl.weapon = G_W_PISTOL;
	sim_tick(&s, &fire);
	assert_int_equal(s.pl.ammo, 1);
	map_free(m);
}

/* The rapid gun does 10 a shot: a grunt (30) takes three. */
static void the_rapid_gun_does_ten_a_shot(void **state)
{
	static const struct gf_thing t[] = { { 428, 256, ANG180, 3004, 0 } };
	struct map *m = arena(t, 1);
	struct sim s;

	(void)state;
	sim_init(&s, m, &normal);
	hold(&s, G_W_RAPID);
	sim_tick(&s, &fire);
	assert_int_equal(s.g.en[0].health, 20);
	for (int k = 0; k < 6; k++)
		sim_tick(&s, &fire);
	assert_int_equal(s.g.en[0].health, 10);
	map_free(m);
}

/* A weapon pickup gives the weapon and its ammo and takes it in hand when
 * it is new; owned, it is only ammo (the weapon held stays), and with the
 * ammo full it stays on the floor. */
static void a_weapon_pickup_gives_and_switches(void **state)
{
	static const struct gf_thing t[] = { { 300, 256, 0, 2001, 0 },     /* shotgun */
					     { 600, 256, 0, 2001, 0 },     /* another */
					     { 900, 256, 0, 2002, 0 },     /* chaingun */
					     { 1200, 256, 0, 82, 0 } };    /* super shotgun */
	struct map *m = arena(t, 4);
	struct sim s;

	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.num_pickups, 4);
	s.pl.x = U(300);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.pk[0].taken, 1);
	assert_int_equal(s.pl.weapons, G_W_BIT(G_W_PISTOL) | G_W_BIT(G_W_SPREAD));
	assert_int_equal(s.pl.weapon, G_W_SPREAD);
	assert_int_equal(s.pl.ammo, G_AMMO_START + 20);
	/* owned already: ammo only, the pistol stays in hand */
	s.pl.weapon = G_W_PISTOL;
	s.pl.x = U(600);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.pk[1].taken, 1);
	assert_int_equal(s.pl.weapon, G_W_PISTOL);
	assert_int_equal(s.pl.ammo, G_AMMO_START + 40);
	/* the chaingun is new: the rapid gun, in hand */
	s.pl.x = U(900);
	sim_tick(&s, &idle);
	assert_int_equal(s.pl.weapon, G_W_RAPID);
	assert_int_equal(s.pl.weapons, 7);
	/* owned, ammo full: left where it lies */
	s.pl.ammo = G_AMMO_MAX;
	s.pl.x = U(1200);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.pk[3].taken, 0);
	assert_int_equal(s.pl.weapon, G_W_RAPID);
	map_free(m);
}

/* A press of the weapon button (an edge: holding it changes once) takes
 * the next weapon owned, skipping those not owned, and wraps. */
static void the_change_cycles_only_owned_weapons(void **state)
{
	struct map *m = arena(NULL, 0);
	struct sim s;

	(void)state;
	sim_init(&s, m, &normal);
	sim_tick(&s, &change);                 /* the pistol only: it stays */
	assert_int_equal(s.pl.weapon, G_W_PISTOL);
	sim_tick(&s, &idle);
	s.pl.weapons = G_W_BIT(G_W_PISTOL) | G_W_BIT(G_W_RAPID);
	for (int k = 0; k < 10; k++)           /* held: one change */
		sim_tick(&s, &change);
	assert_int_equal(s.pl.weapon, G_W_RAPID);
	sim_tick(&s, &idle);
	sim_tick(&s, &change);                 /* wraps past the spread gun */
	assert_int_equal(s.pl.weapon, G_W_PISTOL);
	sim_tick(&s, &idle);
	s.pl.weapons = 7;
	sim_tick(&s, &change);
	assert_int_equal(s.pl.weapon, G_W_SPREAD);
	sim_tick(&s, &idle);
	sim_tick(&s, &change);
	assert_int_equal(s.pl.weapon, G_W_RAPID);
	sim_tick(&s, &idle);
	sim_tick(&s, &change);
	assert_int_equal(s.pl.weapon, G_W_PISTOL);
	map_free(m);
}

/* A death drops the weapons found: the next life, and a continue after the
 * last, has the pistol only. */
static void a_death_drops_to_the_pistol(void **state)
{
	struct map *m = arena(NULL, 0);
	struct sim s;

	(void)state;
	sim_init(&s, m, &normal);
	hold(&s, G_W_RAPID);
	g_player_dies(&s, G_WHY_KILLED);
	for (int k = 0; k < G_DEAD_TICKS; k++)
		sim_tick(&s, &idle);
	assert_int_equal(s.g.lives, 2);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.pl.weapons, G_W_BIT(G_W_PISTOL));
	assert_int_equal(s.pl.weapon, G_W_PISTOL);
	/* the last life: game over, and a continue starts with the pistol */
	s.g.lives = 1;
	hold(&s, G_W_SPREAD);
	g_player_dies(&s, G_WHY_KILLED);
	for (int k = 0; k < G_DEAD_TICKS; k++)
		sim_tick(&s, &idle);
	assert_int_equal(s.mode, SIM_GAMEOVER);
	s.set.freeplay = 1;
	sim_tick(&s, &(struct sim_cmd){ .buttons = SIM_BT_START });
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.g.continues, 1);
	assert_int_equal(s.pl.weapons, G_W_BIT(G_W_PISTOL));
	assert_int_equal(s.pl.weapon, G_W_PISTOL);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_game_starts_with_the_pistol_only),
		cmocka_unit_test(the_spread_reaches_enemies_side_by_side),
		cmocka_unit_test(a_spread_shot_kills_what_the_pistol_misses),
		cmocka_unit_test(ammo_and_refire_per_weapon),
		cmocka_unit_test(the_rapid_gun_does_ten_a_shot),
		cmocka_unit_test(a_weapon_pickup_gives_and_switches),
		cmocka_unit_test(the_change_cycles_only_owned_weapons),
		cmocka_unit_test(a_death_drops_to_the_pistol),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
