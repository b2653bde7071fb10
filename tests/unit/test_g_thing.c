/* Tests for engine/game/g_thing.c: Doom thing types as enemy kinds, pickups,
 * lights and decorations, with th.h's sprites. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_game.h"
#include "engine/game/g_world.h"
#include "engine/map/th.h"

static int kind_of(uint16_t type)
{
	struct g_thing_info ti;
	g_thing_info(type, &ti);
	assert_int_equal(ti.cls, G_C_ENEMY);
	return ti.kind;
}

static void monsters_map_to_the_four_kinds(void **state)
{
	(void)state;
	assert_int_equal(kind_of(3004), G_GRUNT);   /* zombieman */
	assert_int_equal(kind_of(9), G_GRUNT);      /* shotgun guy */
	assert_int_equal(kind_of(65), G_GRUNT);     /* chaingunner */
	assert_int_equal(kind_of(3001), G_THROWER); /* imp: fireballs */
	assert_int_equal(kind_of(3002), G_BRUTE);   /* demon */
	assert_int_equal(kind_of(3003), G_BRUTE);   /* baron */
	assert_int_equal(kind_of(3005), G_SENTRY);  /* cacodemon */
	assert_int_equal(kind_of(16), G_SENTRY);    /* cyberdemon */
}

/* Every monster th.h knows is an enemy here, except Keen (a hanging
 * target) and the boss brain's parts; every enemy's sprite is th's. */
static void every_th_monster_is_an_enemy_with_its_sprite(void **state)
{
	int n = 0;
	(void)state;
	for (int i = 0; i < th_count(); i++) {
		const struct th_info *th = th_at(i);
		struct g_thing_info ti;
		g_thing_info(th->type, &ti);
		if (!(th->flags & TH_MONSTER))
			continue;
		if (th->type == 72 || th->type == 88 || th->type == 89)
			continue;
		if (ti.cls != G_C_ENEMY)
			fail_msg("monster type %u (%s) is not an enemy", th->type, th->name);
		assert_string_equal(ti.sprite, th->sprite);
		assert_true(ti.death1 >= ti.death0 && ti.death1 < 26);
		n++;
	}
	assert_int_equal(n, 18);
}

static void pickups_give_health_or_ammo(void **state)
{
	struct g_thing_info ti;
	(void)state;
	g_thing_info(2012, &ti);                    /* medikit */
	assert_int_equal(ti.cls, G_C_PICKUP);
	assert_int_equal(ti.kind, G_P_HEALTH);
	assert_int_equal(ti.amount, 25);
	assert_string_equal(ti.sprite, "MEDI");
	g_thing_info(2011, &ti);                    /* stimpack */
	assert_int_equal(ti.amount, 10);
	g_thing_info(2007, &ti);                    /* clip */
	assert_int_equal(ti.kind, G_P_AMMO);
	assert_int_equal(ti.amount, 10);
	/* Doom's weapons give one of the game's (docs/game.md's table) */
	g_thing_info(2001, &ti);                    /* shotgun: the spread gun */
	assert_int_equal(ti.cls, G_C_PICKUP);
	assert_int_equal(ti.kind, G_P_WEAPON);
	assert_int_equal(ti.weapon, G_W_SPREAD);
	assert_int_equal(ti.amount, 20);
	g_thing_info(82, &ti);                      /* super shotgun */
	assert_int_equal(ti.kind, G_P_WEAPON);
	assert_int_equal(ti.weapon, G_W_SPREAD);
	g_thing_info(2002, &ti);                    /* chaingun: the rapid gun */
	assert_int_equal(ti.kind, G_P_WEAPON);
	assert_int_equal(ti.weapon, G_W_RAPID);
	g_thing_info(2004, &ti);                    /* plasma rifle */
	assert_int_equal(ti.weapon, G_W_RAPID);
	g_thing_info(2003, &ti);                    /* rocket launcher */
	assert_int_equal(ti.weapon, G_W_SPREAD);
	assert_int_equal(ti.amount, 10);
	g_thing_info(2006, &ti);                    /* BFG9000 */
	assert_int_equal(ti.weapon, G_W_SPREAD);
}

static void lights_decorations_and_the_rest(void **state)
{
	struct g_thing_info ti;
	(void)state;
	g_thing_info(2028, &ti);                    /* floor lamp */
	assert_int_equal(ti.cls, G_C_LIGHT);
	assert_int_equal(ti.bright, 1);
	assert_string_equal(ti.sprite, "COLU");
	g_thing_info(TH_LIGHT_FIRST + 100, &ti);     /* arcaded's light: no sprite */
	assert_int_equal(ti.cls, G_C_LIGHT);
	assert_string_equal(ti.sprite, "");
	g_thing_info(2035, &ti);                    /* barrel */
	assert_int_equal(ti.cls, G_C_DECOR);
	g_thing_info(18, &ti);                      /* dead zombieman: frame L */
	assert_int_equal(ti.cls, G_C_DECOR);
	assert_int_equal(ti.stand, 'L' - 'A');
	g_thing_info(1, &ti);
	assert_int_equal(ti.cls, G_C_PLAYER);
	g_thing_info(5, &ti);                       /* blue keycard: opens blue doors */
	assert_int_equal(ti.cls, G_C_PICKUP);
	assert_int_equal(ti.kind, G_P_KEY);
	assert_int_equal(ti.amount, G_KEY_BLUE);
	assert_int_equal(ti.counted, 0);
	g_thing_info(38, &ti);                      /* red skull key */
	assert_int_equal(ti.kind, G_P_KEY);
	assert_int_equal(ti.amount, G_KEY_RED_SKULL);
	g_thing_info(2018, &ti);                    /* green armour: health here */
	assert_int_equal(ti.kind, G_P_HEALTH);
	assert_int_equal(ti.amount, 25);
	g_thing_info(2026, &ti);                    /* computer map: only counted */
	assert_int_equal(ti.kind, G_P_ITEM);
	assert_int_equal(ti.counted, 1);
	g_thing_info(11, &ti);                      /* deathmatch start */
	assert_int_equal(ti.cls, G_C_NONE);
	g_thing_info(12345, &ti);                   /* unknown */
	assert_int_equal(ti.cls, G_C_NONE);
}

static void skill_bits_select_difficulties(void **state)
{
	(void)state;
	assert_true(g_thing_at_difficulty(1, 0));
	assert_false(g_thing_at_difficulty(1, 1));
	assert_true(g_thing_at_difficulty(2, 1));
	assert_false(g_thing_at_difficulty(2, 2));
	assert_true(g_thing_at_difficulty(4, 2));
	assert_true(g_thing_at_difficulty(4, 3));
	assert_false(g_thing_at_difficulty(4, 0));
	assert_true(g_thing_at_difficulty(0, 3));   /* no bits: every skill */
	assert_true(g_thing_at_difficulty(8, 1));   /* ambush bit only: every skill */
	/* multiplayer-only things never appear (one player at a time) */
	assert_false(g_thing_at_difficulty(7 | G_TF_MULTI, 1));
	assert_false(g_thing_at_difficulty(G_TF_MULTI, 0));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(monsters_map_to_the_four_kinds),
		cmocka_unit_test(every_th_monster_is_an_enemy_with_its_sprite),
		cmocka_unit_test(pickups_give_health_or_ammo),
		cmocka_unit_test(lights_decorations_and_the_rest),
		cmocka_unit_test(skill_bits_select_difficulties),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
