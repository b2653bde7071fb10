/* Tests for engine/game/g_pace.c: the stage clock and its zero, the hurry
 * (every enemy woken, ambushers too, and faster), the idle player (a life,
 * the game, or nothing, by set.idle_out), the time bonus. The numbers come
 * from the rules' constants (g_game.h), not from a run. */
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

#define MIN (60 * SIM_TICRATE)

static const struct sim_cmd none = { 0 };
static const struct sim_cmd turn = { .turn = 16 };

static void run(struct sim *s, const struct sim_cmd *c, int n)
{
	for (int i = 0; i < n; i++)
		sim_tick(s, c);
}

/* Straight into play (easy, 3 lives) with a stage clock of `minutes` and
 * idle rule `idle`, in gf_arena with the things th. */
static struct map *start(struct sim *s, int minutes, int idle, const struct gf_thing *th, int n)
{
	struct sim_settings set = { 1, 0, 1, 0, 3, 100, 1, (uint8_t)minutes, (uint8_t)idle, 0 };
	struct map *m = gf_arena(th, n, NULL, 0);

	assert_non_null(m);
	sim_init(s, m, &set);
	assert_int_equal(s->mode, SIM_PLAY);
	return m;
}

static void the_clock_runs_out_and_the_life_with_it(void **state)
{
	struct sim s;
	struct map *m = start(&s, 1, G_IDLE_OFF, NULL, 0);
	(void)state;
	assert_int_equal(s.g.clock, 1 * MIN);
	run(&s, &none, MIN - 1);
	assert_int_equal(s.g.clock, 1);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.pl.health, G_HEALTH_MAX * FX_ONE);
	sim_tick(&s, &none);
	assert_int_equal(s.g.clock, 0);
	assert_int_equal(s.g.phase, G_PH_DEAD);
	assert_int_equal(s.g.why, G_WHY_TIME);
	assert_int_equal(s.pl.health, 0);
	/* the death's ticks, then a life fewer and the clock full again */
	run(&s, &none, G_DEAD_TICKS);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.g.lives, 2);
	assert_int_equal(s.g.clock, 1 * MIN);
	map_free(m);
}

static void the_clock_setting_has_a_default_and_a_ceiling(void **state)
{
	struct sim s;
	struct map *m = start(&s, 0, G_IDLE_OFF, NULL, 0);
	(void)state;
	assert_int_equal(s.g.clock, G_STAGE_TIME_DEFAULT * MIN);
	s.set.stage_time = 200;
	assert_int_equal(g_pace_full(&s), G_STAGE_TIME_MAX * MIN);
	map_free(m);
}

static void a_clock_turned_off_never_runs_out(void **state)
{
	static const struct gf_thing t[] = { { 1900, 60, 0, 3004, 0 } };
	struct sim s;
	struct map *m = start(&s, G_STAGE_TIME_OFF, G_IDLE_OFF, t, 1);
	(void)state;
	assert_int_equal(g_pace_full(&s), 0);
	run(&s, &none, G_STAGE_TIME_MAX * MIN + 1);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.g.lives, 3);
	assert_false(g_pace_hurry(&s));
	assert_int_equal(s.g.en[0].state, G_E_IDLE);     /* never woken by a hurry */
	g_pace_bonus(&s);
	assert_int_equal(s.g.time_bonus, 0);
	map_free(m);
}

static void the_hurry_wakes_everyone_and_speeds_them_up(void **state)
{
	/* a grunt behind the player (never seen) and a deaf one (ambush) */
	static const struct gf_thing t[] = { { 1900, 60, 0, 3004, 0 },
					     { 1900, 450, 0, 3004, G_TF_AMBUSH } };
	struct sim s;
	struct map *m = start(&s, 1, G_IDLE_OFF, t, 2);
	fx_t calm;
	(void)state;
	assert_int_equal(s.g.num_enemies, 2);
	calm = g_enemy_speed(&s, G_GRUNT);
	run(&s, &none, MIN - G_HURRY_TICKS - 1);
	assert_int_equal(s.g.en[0].state, G_E_IDLE);
	assert_int_equal(s.g.en[1].state, G_E_IDLE);
	assert_false(g_pace_hurry(&s));
	sim_tick(&s, &none);
	assert_int_equal(s.g.clock, G_HURRY_TICKS);
	assert_true(g_pace_hurry(&s));
	assert_int_equal(s.g.en[0].state, G_E_CHASE);
	assert_int_equal(s.g.en[1].state, G_E_CHASE);
	/* easy is 80% of the kind's speed; the hurry adds its points to that */
	assert_int_equal(calm, (fx_t)((int64_t)g_kinds[G_GRUNT].speed * 80 / 100));
	assert_int_equal(g_enemy_speed(&s, G_GRUNT),
			 (fx_t)((int64_t)g_kinds[G_GRUNT].speed * (80 + G_HURRY_SPEED) / 100));
	map_free(m);
}

static void a_player_gone_loses_a_life(void **state)
{
	struct sim s;
	struct map *m = start(&s, 5, G_IDLE_LIFE, NULL, 0);
	(void)state;
	run(&s, &none, G_IDLE_TICKS - 1);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	/* one tick of input starts the count again */
	sim_tick(&s, &turn);
	run(&s, &none, G_IDLE_TICKS - 1);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	sim_tick(&s, &none);
	assert_int_equal(s.g.phase, G_PH_DEAD);
	assert_int_equal(s.g.why, G_WHY_IDLE);
	run(&s, &none, G_DEAD_TICKS);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.g.lives, 2);
	assert_int_equal(s.g.idle_t, 0);
	map_free(m);
}

static void a_player_gone_ends_the_game_when_set(void **state)
{
	struct sim s;
	struct map *m = start(&s, 5, G_IDLE_END, NULL, 0);
	(void)state;
	run(&s, &none, G_IDLE_TICKS + G_DEAD_TICKS);
	assert_int_equal(s.mode, SIM_GAMEOVER);
	map_free(m);
}

static void idle_out_off_never_ends_a_life(void **state)
{
	struct sim s;
	struct map *m = start(&s, 5, G_IDLE_OFF, NULL, 0);
	(void)state;
	run(&s, &none, 3 * G_IDLE_TICKS);
	assert_int_equal(s.g.phase, G_PH_PLAY);
	assert_int_equal(s.g.lives, 3);
	map_free(m);
}

static void the_time_bonus_is_the_whole_seconds_left(void **state)
{
	static const struct gf_thing t[] = { { 428, 256, ANG180, 3004, 0 } };
	struct sim s;
	struct map *m = start(&s, 2, G_IDLE_OFF, t, 1);
	(void)state;
	run(&s, &turn, 61);                /* 2 minutes less 61 ticks: 118.98 s */
	assert_int_equal(s.g.clock, 2 * MIN - 61);
	g_pace_bonus(&s);
	assert_int_equal(s.g.time_bonus, 119 * G_TIME_BONUS);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_clock_runs_out_and_the_life_with_it),
		cmocka_unit_test(the_clock_setting_has_a_default_and_a_ceiling),
		cmocka_unit_test(a_clock_turned_off_never_runs_out),
		cmocka_unit_test(the_hurry_wakes_everyone_and_speeds_them_up),
		cmocka_unit_test(a_player_gone_loses_a_life),
		cmocka_unit_test(a_player_gone_ends_the_game_when_set),
		cmocka_unit_test(idle_out_off_never_ends_a_life),
		cmocka_unit_test(the_time_bonus_is_the_whole_seconds_left),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
