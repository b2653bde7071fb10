/* Tests for engine/game/g_turn.c and the two-player flow in sim.c: the 2P
 * start and its two credits, the swap after a life lost (the other player
 * up with their own lives, stage, score, ammo and weapons; the first's
 * kept), a player whose game is over leaving the other to play on, a
 * continue passing the turn, and both players' scores entering the table.
 * The numbers come from the rules' constants (g_game.h) and the settings
 * given, not from a run. */
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

static const struct sim_cmd none = { 0 };

static void run(struct sim *s, const struct sim_cmd *c, int n)
{
	for (int i = 0; i < n; i++)
		sim_tick(s, c);
}

/* A press: down one tick, up the next. */
static void press(struct sim *s, uint8_t bt)
{
	struct sim_cmd c = { .buttons = bt };
	sim_tick(s, &c);
	sim_tick(s, &none);
}

static void coins(struct sim *s, int n)
{
	struct sim_cmd c = { .coins = (uint8_t)n };
	sim_tick(s, &c);
}

struct two {
	struct map *m[2];
	struct sim s;
};

/* Attract on two stages (gf_arena each), 3 lives, no clock, no idle rule. */
static void two_init(struct two *t)
{
	struct sim_settings set = { 1, 0, 0, 0, 3, 100, 1, G_STAGE_TIME_OFF, G_IDLE_OFF, 0 };
	t->m[0] = gf_arena(NULL, 0, NULL, 0);
	t->m[1] = gf_arena(NULL, 0, NULL, 0);
	assert_non_null(t->m[0]);
	assert_non_null(t->m[1]);
	sim_init_stages(&t->s, (const struct map *const *)t->m, 2, &set, NULL, NULL);
	assert_int_equal(t->s.mode, SIM_ATTRACT);
}

static void two_free(struct two *t)
{
	map_free(t->m[0]);
	map_free(t->m[1]);
}

/* Two coins, 2P start, past the "PLAYER 1" page: player 1 in play. */
static void two_start(struct two *t)
{
	two_init(t);
	coins(&t->s, 2);
	press(&t->s, SIM_BT_START2);
	assert_int_equal(t->s.mode, SIM_PLAY);
	assert_int_equal(t->s.players, 2);
	assert_int_equal(t->s.up, 0);
	assert_int_equal(t->s.g.phase, G_PH_TURN);
	run(&t->s, &none, G_TURN_TICKS);
	assert_int_equal(t->s.g.phase, G_PH_PLAY);
}

/* The player up dies now; the death's ticks run out. */
static void die(struct sim *s)
{
	g_player_dies(s, G_WHY_KILLED);
	assert_int_equal(s->g.phase, G_PH_DEAD);
	run(s, &none, G_DEAD_TICKS);
}

static void two_start_costs_two_credits(void **state)
{
	struct two t;
	(void)state;
	two_init(&t);
	coins(&t.s, 1);
	press(&t.s, SIM_BT_START2);
	/* one credit is not enough for two players */
	assert_int_equal(t.s.mode, SIM_ATTRACT);
	assert_int_equal(t.s.credits, 1);
	coins(&t.s, 2);
	press(&t.s, SIM_BT_START2);
	assert_int_equal(t.s.mode, SIM_PLAY);
	assert_int_equal(t.s.credits, 1);
	assert_int_equal(t.s.plays, 2);
	assert_int_equal(t.s.players, 2);
	/* both start alike: full lives, stage 1, no score */
	assert_int_equal(t.s.g.lives, 3);
	assert_int_equal(t.s.wait.lives, 3);
	assert_int_equal(t.s.wait.stage, 0);
	assert_int_equal(t.s.wait.score, 0);
	assert_int_equal(t.s.wait.out, 0);
	two_free(&t);
}

static void one_player_start_has_no_turns(void **state)
{
	struct two t;
	(void)state;
	two_init(&t);
	coins(&t.s, 2);
	press(&t.s, SIM_BT_START);
	assert_int_equal(t.s.players, 1);
	assert_int_equal(t.s.credits, 1);
	assert_int_equal(t.s.g.phase, G_PH_PLAY);
	die(&t.s);
	assert_int_equal(t.s.up, 0);
	assert_int_equal(t.s.g.phase, G_PH_PLAY);
	assert_int_equal(t.s.g.lives, 2);
	two_free(&t);
}

static void a_life_lost_passes_the_turn(void **state)
{
	struct two t;
	(void)state;
	two_start(&t);
	/* player 1 on the second stage with a score, ammo and a spread gun */
	t.s.g.stage = 1;              /* as if stage 1 were cleared */
	t.s.g.score = 1234;
	t.s.g.kills = 7;
	t.s.pl.ammo = 120;
	g_weapon_give(&t.s, G_W_SPREAD, 0);
	die(&t.s);
	/* player 2 up: the page, then their own stage 1 with full lives */
	assert_int_equal(t.s.up, 1);
	assert_int_equal(t.s.mode, SIM_PLAY);
	assert_int_equal(t.s.g.phase, G_PH_TURN);
	assert_int_equal(t.s.g.lives, 3);
	assert_int_equal(t.s.g.stage, 0);
	assert_int_equal(t.s.g.score, 0);
	assert_int_equal(t.s.g.kills, 0);
	assert_int_equal(t.s.pl.ammo, G_AMMO_START);
	assert_int_equal(t.s.pl.weapons, G_W_BIT(G_W_PISTOL));
	assert_int_equal(t.s.pl.health, G_HEALTH_MAX * FX_ONE);
	/* player 1 waits with what they had, one life fewer (a life lost
	 * takes the weapons, keeps the ammo: sim.h) */
	assert_int_equal(t.s.wait.score, 1234);
	assert_int_equal(t.s.wait.kills, 7);
	assert_int_equal(t.s.wait.lives, 2);
	assert_int_equal(t.s.wait.stage, 1);
	assert_int_equal(t.s.wait.ammo, 120);
	/* the page holds the stage still, then play */
	run(&t.s, &none, G_TURN_TICKS - 1);
	assert_int_equal(t.s.g.phase, G_PH_TURN);
	sim_tick(&t.s, &none);
	assert_int_equal(t.s.g.phase, G_PH_PLAY);
	assert_int_equal(t.s.g.stage_t, 0);
	/* player 2 scores and dies: player 1 is back on their stage */
	t.s.g.score = 500;
	die(&t.s);
	assert_int_equal(t.s.up, 0);
	assert_int_equal(t.s.g.phase, G_PH_TURN);
	assert_int_equal(t.s.g.stage, 1);
	assert_int_equal(t.s.map, t.m[1]);
	assert_int_equal(t.s.g.score, 1234);
	assert_int_equal(t.s.g.lives, 2);
	assert_int_equal(t.s.pl.ammo, 120);
	assert_int_equal(t.s.wait.score, 500);
	assert_int_equal(t.s.wait.lives, 2);
	two_free(&t);
}

static void the_other_plays_on_after_a_game_over(void **state)
{
	struct two t;
	(void)state;
	two_start(&t);
	t.s.g.lives = 1;
	die(&t.s);
	/* player 1's continue countdown; it runs out, no score to enter */
	assert_int_equal(t.s.mode, SIM_GAMEOVER);
	assert_int_equal(t.s.up, 0);
	run(&t.s, &none, G_CONTINUE_TICKS);
	assert_int_equal(t.s.mode, SIM_PLAY);
	assert_int_equal(t.s.up, 1);
	assert_int_equal(t.s.g.phase, G_PH_TURN);
	assert_int_equal(t.s.wait.out, 1);
	run(&t.s, &none, G_TURN_TICKS);
	/* player 2 loses lives and plays on alone */
	die(&t.s);
	assert_int_equal(t.s.up, 1);
	assert_int_equal(t.s.g.phase, G_PH_PLAY);
	assert_int_equal(t.s.g.lives, 2);
	die(&t.s);
	die(&t.s);
	assert_int_equal(t.s.mode, SIM_GAMEOVER);
	run(&t.s, &none, G_CONTINUE_TICKS);
	assert_int_equal(t.s.mode, SIM_ATTRACT);
	two_free(&t);
}

static void a_continue_passes_the_turn(void **state)
{
	struct two t;
	(void)state;
	two_start(&t);
	coins(&t.s, 1);
	t.s.g.lives = 1;
	t.s.g.score = 300;
	die(&t.s);
	assert_int_equal(t.s.mode, SIM_GAMEOVER);
	/* the 2P start continues too */
	press(&t.s, SIM_BT_START2);
	assert_int_equal(t.s.credits, 0);
	assert_int_equal(t.s.mode, SIM_PLAY);
	assert_int_equal(t.s.up, 1);
	assert_int_equal(t.s.wait.lives, 3);
	assert_int_equal(t.s.wait.continues, 1);
	assert_int_equal(t.s.wait.score, 300);
	assert_int_equal(t.s.wait.out, 0);
	two_free(&t);
}

/* Enters AAA: three FIRE presses. */
static void initials(struct sim *s)
{
	assert_int_equal(s->mode, SIM_INITIALS);
	for (int i = 0; i < G_NAME_LEN; i++)
		press(s, SIM_BT_FIRE);
}

static void both_players_enter_the_table(void **state)
{
	struct two t;
	struct g_scores def;
	(void)state;
	g_scores_default(&def);
	two_start(&t);
	/* scores above the factory table's best (which is def.e[0]) */
	t.s.g.score = def.e[0].score + 2000;
	t.s.g.lives = 1;
	die(&t.s);
	run(&t.s, &none, G_CONTINUE_TICKS);
	assert_int_equal(t.s.up, 0);
	initials(&t.s);
	assert_int_equal(t.s.scores.e[0].score, def.e[0].score + 2000);
	assert_int_equal(t.s.new_rank, 0);
	/* then player 2's turn, not attract */
	assert_int_equal(t.s.mode, SIM_PLAY);
	assert_int_equal(t.s.up, 1);
	run(&t.s, &none, G_TURN_TICKS);
	t.s.g.score = def.e[0].score + 1000;
	t.s.g.lives = 1;
	die(&t.s);
	run(&t.s, &none, G_CONTINUE_TICKS);
	assert_int_equal(t.s.up, 1);
	initials(&t.s);
	assert_int_equal(t.s.mode, SIM_ATTRACT);
	assert_int_equal(t.s.page, SIM_PAGE_SCORES);
	assert_int_equal(t.s.scores.e[0].score, def.e[0].score + 2000);
	assert_int_equal(t.s.scores.e[1].score, def.e[0].score + 1000);
	assert_int_equal(t.s.scores.e[2].score, def.e[0].score);
	assert_int_equal(t.s.new_rank, 1);
	two_free(&t);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(two_start_costs_two_credits),
		cmocka_unit_test(one_player_start_has_no_turns),
		cmocka_unit_test(a_life_lost_passes_the_turn),
		cmocka_unit_test(the_other_plays_on_after_a_game_over),
		cmocka_unit_test(a_continue_passes_the_turn),
		cmocka_unit_test(both_players_enter_the_table),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
