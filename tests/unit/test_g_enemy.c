/* Tests for engine/game/g_enemy.c: waking by hearing (g_noise, the
 * player's shot): idle enemies in the sectors the sound reaches wake
 * unless deaf (the map's ambush flag); a closed sector stops the sound. */
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

static const struct sim_settings normal = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
static const struct sim_cmd fire = { .buttons = SIM_BT_FIRE };

/* In one room, behind a pillar (out of sight) and 1800 units away: the
 * shot wakes the grunt that can hear, not the deaf one beside it. */
static void a_shot_wakes_the_hearing_not_the_deaf(void **state)
{
	static const struct gf_box pillar = { 1000, 0, 1100, 480 };
	static const struct gf_thing t[] = { { 1900, 100, 0, 3004, 0 },
					     { 1900, 300, 0, 3004, G_TF_AMBUSH } };
	struct map *m = gf_arena(t, 2, &pillar, 1);
	struct sim s;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.en[0].state, G_E_IDLE);
	assert_int_equal(s.g.en[1].state, G_E_IDLE);
	assert_false(g_sight(&s, s.pl.x, s.pl.y, s.pl.viewz, s.g.en[0].x, s.g.en[0].y,
			     s.g.en[0].z + g_kinds[G_GRUNT].eye));
	sim_tick(&s, &fire);                    /* the shot hits the pillar */
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.en[0].state, G_E_CHASE);
	assert_int_equal(s.g.en[1].state, G_E_IDLE);
	map_free(m);
}

/* ARENA2: four arms round the court. With the north arm shut (its ceiling
 * down on its floor, as a closed door), the player's shot in the south arm
 * wakes the enemies of the other arms, and none in the north. */
static void a_closed_sector_stops_the_sound(void **state)
{
	struct map *m;
	struct sim s;
	int north = 0, woke = 0;
	(void)state;
	assert_int_equal(lvl_builtin(1, &m), 0);
	sim_init(&s, m, &normal);
	s.w.sec[3].ceil_h = s.w.sec[3].floor_h;    /* NORTH, the 4th sector */
	for (int i = 0; i < s.g.num_enemies; i++)
		assert_int_equal(s.g.en[i].state, G_E_IDLE);
	g_noise(&s);
	for (int i = 0; i < s.g.num_enemies; i++) {
		const struct g_enemy *e = &s.g.en[i];
		if (e->sector == 3) {
			north++;
			assert_int_equal(e->state, G_E_IDLE);
		} else {
			woke++;
			assert_int_equal(e->state, G_E_CHASE);
		}
	}
	assert_int_equal(north, 3);             /* 2 grunts and the thrower */
	assert_true(woke >= 4);
	/* open again: the north hears too */
	s.w.sec[3].ceil_h = s.w.sec[3].floor_h + 128 * FX_ONE;
	g_noise(&s);
	for (int i = 0; i < s.g.num_enemies; i++)
		assert_int_equal(s.g.en[i].state, G_E_CHASE);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_shot_wakes_the_hearing_not_the_deaf),
		cmocka_unit_test(a_closed_sector_stops_the_sound),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
