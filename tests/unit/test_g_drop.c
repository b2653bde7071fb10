/* Tests for engine/game/g_drop.c: a dying soldier leaves its drop, a new
 * pickup where it died, taken as any other with half a placed one's ammo;
 * kinds without a drop leave nothing; no drop when the pickups are full. */
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

static const struct sim_settings normal = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
static const struct sim_cmd idle_cmd = { 0 };

/* Doom's soldiers' drops: the zombieman's clip, the shotgun guy's shotgun,
 * the chaingunner's chaingun; the imp, demon and lost soul drop nothing. */
static void the_soldiers_drop_what_they_carry(void **state)
{
	(void)state;
	assert_int_equal(g_drop_type(3004), 2007);
	assert_int_equal(g_drop_type(84), 2007);
	assert_int_equal(g_drop_type(9), 2001);
	assert_int_equal(g_drop_type(65), 2002);
	assert_int_equal(g_drop_type(3001), 0);
	assert_int_equal(g_drop_type(3002), 0);
	assert_int_equal(g_drop_type(3006), 0);
}

/* A zombieman killed at (900, 300) leaves a clip there (on the floor, not
 * counted among the map's items) holding half a placed clip's 10 rounds;
 * the player walking onto it takes the 5. A demon killed beside it leaves
 * nothing. */
static void a_killed_grunt_drops_a_clip_that_is_taken(void **state)
{
	static const struct gf_thing t[] = { { 900, 300, ANG180, 3004, G_TF_AMBUSH },
					     { 900, 100, ANG180, 3002, G_TF_AMBUSH } };
	struct map *m = gf_arena(t, 2, NULL, 0);
	struct sim s;
	struct g_thing_info clip;
	const struct g_pickup *p;
	int before, items;
	uint16_t ammo;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	g_thing_info(2007, &clip);
	before = s.g.num_pickups;
	items = s.w.items_total;
	g_hurt_enemy(&s, 1, 1000);              /* the demon */
	assert_int_equal(s.g.en[1].state, G_E_DEAD);
	assert_int_equal(s.g.num_pickups, before);
	g_hurt_enemy(&s, 0, 1000);              /* the grunt */
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	assert_int_equal(s.g.num_pickups, before + 1);
	p = &s.g.pk[before];
	assert_int_equal(p->type, 2007);
	assert_int_equal(p->kind, G_P_AMMO);
	assert_int_equal(p->x, fx_from_int(900));
	assert_int_equal(p->y, fx_from_int(300));
	assert_int_equal(p->z, 0);
	assert_int_equal(p->amount, clip.amount / 2);
	assert_int_equal(p->amount, 5);
	assert_false(p->taken);
	assert_int_equal(s.w.items_total, items);
	/* taken as any pickup: the player stands on it */
	ammo = s.pl.ammo;
	s.pl.x = fx_from_int(900);
	s.pl.y = fx_from_int(300);
	s.pl.sector = 0;
	sim_tick(&s, &idle_cmd);
	assert_true(s.g.pk[before].taken);
	assert_int_equal(s.pl.ammo, ammo + 5);
	map_free(m);
}

/* With every pickup slot used, a death drops nothing (and breaks nothing). */
static void no_drop_when_the_pickups_are_full(void **state)
{
	static const struct gf_thing t[] = { { 900, 300, ANG180, 3004, G_TF_AMBUSH } };
	struct map *m = gf_arena(t, 1, NULL, 0);
	struct sim s;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	s.g.num_pickups = G_MAX_PICKUPS;
	g_hurt_enemy(&s, 0, 1000);
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	assert_int_equal(s.g.num_pickups, G_MAX_PICKUPS);
	assert_int_equal(g_drop(&s, 0), -1);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_soldiers_drop_what_they_carry),
		cmocka_unit_test(a_killed_grunt_drops_a_clip_that_is_taken),
		cmocka_unit_test(no_drop_when_the_pickups_are_full),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
