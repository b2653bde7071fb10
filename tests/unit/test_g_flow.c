/*
 * The whole arcade flow on the three built-in stages, played by a small
 * deterministic bot through the same path as the daemon (actions ->
 * cmd_build -> sim_tick): factory settings in the service menu, coin,
 * start, clear stage 1, lose every life on stage 2, continue, lose them
 * again, let the countdown run out, enter initials, see the new entry in
 * attract.
 *
 * The bot's actions are also the test script tests/script/game/flow.scr
 * (the daemon runs it in the script tests once the app plays the three
 * stages with the HUD): this test checks that the committed script is
 * exactly what the bot does, and replays the script through scr_parse and
 * the sim to check every game field it cannot check itself.
 *
 * The numbers the script expects are worked out here, not read from the
 * sim: the score at the clear of stage 1 is the kill values of the enemy
 * table (g_kinds) over the enemy things of stage 1's map plus the stage
 * bonus and the time bonus (the stage clock's whole seconds left, from the
 * clock's length and the stage's ticks), and its kills the count of those things; the score at initials
 * adds the kill values of the enemies seen dying on stage 2; the rank is
 * the place that score takes in the default high-score table. The sim
 * must agree with each (asserted), and the script states them. After an
 * intended change of the rules, write the script afresh with
 *   ARCADED_FLOW_SCRIPT=tests/script/game/flow.scr build/tests/test_g_flow
 * and look at the new numbers.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/cmd.h"
#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "input/act.h"
#include "input/scr.h"

#define FLOW_SCRIPT "tests/script/game/flow.scr"
#define MAX_TICKS 40000
#define MAX_LINES 4000

struct flow {
	struct map *maps[3];
	struct sim s;
	struct cmd_state cs;
	uint16_t held;                 /* actions held (bit per enum act) */
	char *lines[MAX_LINES];
	int nlines;
	/* what the flow saw, for the checks */
	uint32_t t_play, t_clear, t_stage2, t_over1, t_cont, t_over2, t_initials, t_attract;
	uint32_t score_clear, score_end;
	uint8_t was_dead[G_MAX_ENEMIES];   /* enemy i dead after the last tick */
	uint32_t dead_value, dead_count;   /* kill values and count of deaths seen */
};

static void say(struct flow *f, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void say(struct flow *f, const char *fmt, ...)
{
	char buf[128];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(buf, sizeof(buf), fmt, ap);
	va_end(ap);
	assert_true(f->nlines < MAX_LINES);
	f->lines[f->nlines] = strdup(buf);
	assert_non_null(f->lines[f->nlines]);
	f->nlines++;
}

/* One tick with the actions in `want` held (and the ones in `tap`
 * pressed for this tick only); the changes become script lines. */
static void step(struct flow *f, uint16_t want)
{
	struct sim_cmd c;

	for (int a = 0; a < ACT_COUNT; a++) {
		uint16_t bit = (uint16_t)(1u << a);
		if ((want & bit) && !(f->held & bit)) {
			say(f, "%u press %s", f->s.tick, act_name(a));
			cmd_action(&f->cs, a, 1);
		} else if (!(want & bit) && (f->held & bit)) {
			say(f, "%u release %s", f->s.tick, act_name(a));
			cmd_action(&f->cs, a, 0);
		}
	}
	f->held = want;
	cmd_build(&f->cs, &c);
	sim_tick(&f->s, &c);
	assert_true(f->s.tick < MAX_TICKS);
	/* deaths, from the enemies' states: their kill values by the table */
	for (int i = 0; i < f->s.g.num_enemies; i++) {
		int dead = f->s.g.en[i].state == G_E_DEAD;

		if (dead && !f->was_dead[i]) {
			f->dead_value += g_kinds[f->s.g.en[i].kind].score;
			f->dead_count++;
		}
		f->was_dead[i] = (uint8_t)dead;
	}
}

/* The enemies stage `m` starts with at difficulty d, and the sum of their
 * kill values in the enemy table: from the map's things, not from the sim. */
static void stage_enemies(const struct map *m, int d, uint32_t *count, uint32_t *value)
{
	*count = *value = 0;
	for (uint32_t i = 0; i < m->num_things; i++) {
		struct g_thing_info ti;

		g_thing_info(m->things[i].type, &ti);
		if (ti.cls != G_C_ENEMY || !g_thing_at_difficulty(m->things[i].flags, d))
			continue;
		(*count)++;
		*value += g_kinds[ti.kind].score;
	}
}

/* The 1-based place score takes in the default table: below every entry
 * with an equal or higher score (g_game.h). */
static int default_rank(uint32_t score)
{
	struct g_scores t;
	int r = 0;

	g_scores_default(&t);
	while (r < G_SCORES && t.e[r].score >= score)
		r++;
	return r + 1;
}


#define B(a) ((uint16_t)(1u << (a)))

static void idle(struct flow *f, int n)
{
	for (int i = 0; i < n; i++)
		step(f, 0);
}

/* Press for a tick, then a tick released. */
static void tap(struct flow *f, int a)
{
	step(f, B(a));
	step(f, 0);
}

static void expect(struct flow *f, const char *field, const char *op, const char *value)
{
	say(f, "%u expect %s %s %s", f->s.tick - 1, field, op, value);
}

static void expect_u(struct flow *f, const char *field, uint32_t v)
{
	char s[24];

	snprintf(s, sizeof s, "%u", v);
	expect(f, field, "==", s);
}

/* Signed difference of two angles. */
static int32_t ang_diff(ang_t to, ang_t from)
{
	return (int32_t)(to - from);
}

/* The nearest living enemy the player can see, or -1. */
static int target(const struct sim *s)
{
	int best = -1;
	uint64_t bd = UINT64_MAX;

	for (int i = 0; i < s->g.num_enemies; i++) {
		const struct g_enemy *e = &s->g.en[i];
		int64_t dx = (int64_t)e->x - s->pl.x, dy = (int64_t)e->y - s->pl.y;
		uint64_t d = (uint64_t)(dx * dx) + (uint64_t)(dy * dy);
		if (e->state == G_E_DEAD || d >= bd)
			continue;
		if (!g_sight(s, s->pl.x, s->pl.y, s->pl.viewz, e->x, e->y,
			     e->z + g_kinds[e->kind].eye))
			continue;
		best = i;
		bd = d;
	}
	return best;
}

/* Turn towards angle a; returns the actions and whether it is aimed
 * (within one turn step). */
static uint16_t turn_to(const struct sim *s, ang_t a, int *aimed)
{
	int32_t d = ang_diff(a, s->pl.angle);
	int32_t step_ang = CMD_TURN_SPEED * 65536;

	*aimed = d < step_ang / 2 && d > -step_ang / 2;
	if (*aimed)
		return 0;
	return d > 0 ? B(ACT_TURN_LEFT) : B(ACT_TURN_RIGHT);
}

/* Stage 1: through the hall and the doorway into the yard, shooting every
 * enemy in sight; when none is, walking the waypoints, then turning round
 * on the spot. */
static void clear_stage_1(struct flow *f)
{
	static const int wp[][2] = { { 560, 368 }, { 760, 368 }, { 780, 640 } };
	int w = 0;

	while (f->s.mode == SIM_PLAY && f->s.g.phase != G_PH_CLEAR) {
		const struct sim *s = &f->s;
		int t = target(s), aimed;
		uint16_t act;
		if (s->g.phase == G_PH_DEAD) {
			step(f, 0);
			continue;
		}
		if (t >= 0) {
			const struct g_enemy *e = &s->g.en[t];
			act = turn_to(s, tab_atan2(e->y - s->pl.y, e->x - s->pl.x), &aimed);
			if (aimed)
				act = B(ACT_FIRE);
		} else if (w < 3) {
			fx_t dx = fx_from_int(wp[w][0]) - s->pl.x, dy = fx_from_int(wp[w][1]) - s->pl.y;
			if (fx_abs(dx) < 24 * FX_ONE && fx_abs(dy) < 24 * FX_ONE) {
				w++;
				act = 0;
			} else {
				act = turn_to(s, tab_atan2(dy, dx), &aimed);
				if (aimed)
					act = B(ACT_FORWARD);
			}
		} else {
			act = B(ACT_TURN_LEFT);
		}
		step(f, act);
	}
}

/* Walks at the nearest living enemy without shooting until the game is
 * over (every life lost). */
static void lose_every_life(struct flow *f)
{
	while (f->s.mode == SIM_PLAY) {
		const struct sim *s = &f->s;
		int best = -1, aimed;
		uint64_t bd = UINT64_MAX;
		uint16_t act = 0;
		for (int i = 0; i < s->g.num_enemies; i++) {
			const struct g_enemy *e = &s->g.en[i];
			int64_t dx = (int64_t)e->x - s->pl.x, dy = (int64_t)e->y - s->pl.y;
			uint64_t d = (uint64_t)(dx * dx) + (uint64_t)(dy * dy);
			if (e->state != G_E_DEAD && d < bd) {
				bd = d;
				best = i;
			}
		}
		if (best >= 0 && s->g.phase == G_PH_PLAY) {
			const struct g_enemy *e = &s->g.en[best];
			act = turn_to(s, tab_atan2(e->y - s->pl.y, e->x - s->pl.x), &aimed);
			if (aimed)
				act = B(ACT_FORWARD);
		}
		step(f, act);
	}
}

static void play_flow(struct flow *f)
{
	static const struct sim_settings set = { 1, 0, 0, 0, 0, 100, 1, 0, 0, 0 };  /* what the app passes today */
	const struct map *mp[3];

	memset(f, 0, sizeof(*f));
	for (int i = 0; i < 3; i++) {
		assert_int_equal(lvl_builtin(i, &f->maps[i]), 0);
		mp[i] = f->maps[i];
	}
	sim_init_stages(&f->s, mp, 3, &set, NULL, NULL);
	cmd_reset(&f->cs);
	say(f, "# The whole arcade flow on the built-in stages, played by the bot of");
	say(f, "# tests/unit/test_g_flow.c (which writes this file and checks the game's");
	say(f, "# numbers on it): factory settings in the service menu, coin, start, clear");
	say(f, "# stage 1, lose every life on stage 2, continue, lose them again, the");
	say(f, "# countdown runs out, initials ACE, the new entry in attract.");
	say(f, "# expect-file: attract-scores.png");
	/* service menu: GAME SETTINGS, FACTORY DEFAULTS, back, out */
	idle(f, 2);
	tap(f, ACT_SERVICE);
	expect(f, "mode", "==", "service");
	for (int i = 0; i < MENU_I_SETTINGS; i++)
		tap(f, ACT_BACK);
	tap(f, ACT_FIRE);
	for (int i = 0; i < MENU_S_DEFAULTS; i++)
		tap(f, ACT_BACK);
	tap(f, ACT_FIRE);
	assert_int_equal(f->s.set.difficulty, MENU_DEFAULT_DIFFICULTY);
	tap(f, ACT_SERVICE);
	tap(f, ACT_SERVICE);
	expect(f, "mode", "==", "attract");
	/* coin-up and start */
	tap(f, ACT_COIN);
	expect(f, "credits", "==", "1");
	tap(f, ACT_START);
	expect(f, "mode", "==", "play");
	expect(f, "credits", "==", "0");
	f->t_play = f->s.tick;
	clear_stage_1(f);
	assert_int_equal(f->s.mode, SIM_PLAY);
	f->t_clear = f->s.tick;
	f->score_clear = f->s.g.score;
	expect(f, "enemies", "==", "0");
	{
		uint32_t n, v;

		stage_enemies(f->maps[0], f->s.set.difficulty, &n, &v);
		/* every one killed once: the table's values, the stage bonus
		 * and the time bonus: the whole seconds (rounded up) the stage
		 * clock had left, each tick of the stage having taken one */
		uint32_t tb = (G_STAGE_TIME_DEFAULT * 60 * SIM_TICRATE - f->s.g.stage_t +
			       SIM_TICRATE - 1) / SIM_TICRATE * G_TIME_BONUS;
		assert_int_equal(f->dead_count, n);
		assert_int_equal(f->s.g.time_bonus, tb);
		assert_int_equal(f->s.g.score, v + G_STAGE_BONUS * 1 + tb);
		expect_u(f, "score", v + G_STAGE_BONUS * 1 + tb);
		expect_u(f, "kills", n);
		f->dead_value = f->dead_count = 0;
	}
	idle(f, G_CLEAR_TICKS);
	assert_int_equal(f->s.g.stage, 1);
	f->t_stage2 = f->s.tick;
	expect(f, "mode", "==", "play");
	expect(f, "x", "==", "512");
	expect(f, "y", "==", "64");
	expect(f, "stage", "==", "2");
	{
		uint32_t n, v;

		stage_enemies(f->maps[1], f->s.set.difficulty, &n, &v);
		assert_int_equal(f->s.g.alive, n);
		expect_u(f, "enemies", n);
	}
	expect(f, "lives", "==", "3");
	lose_every_life(f);
	assert_int_equal(f->s.mode, SIM_GAMEOVER);
	f->t_over1 = f->s.tick;
	expect(f, "mode", "==", "gameover");
	expect(f, "lives", "==", "0");
	expect(f, "countdown", "==", "10");
	idle(f, 120);
	tap(f, ACT_COIN);
	tap(f, ACT_START);
	expect(f, "mode", "==", "play");
	expect(f, "coins", "==", "2");
	expect(f, "continues", "==", "1");
	expect(f, "lives", "==", "3");
	f->t_cont = f->s.tick;
	lose_every_life(f);
	f->t_over2 = f->s.tick;
	expect(f, "mode", "==", "gameover");
	while (f->s.mode == SIM_GAMEOVER)
		step(f, 0);
	assert_int_equal(f->s.mode, SIM_INITIALS);
	f->t_initials = f->s.tick;
	expect(f, "mode", "==", "initials");
	/* stage 2 gives no bonus: the clear's score and the kills since */
	assert_int_equal(f->s.g.score, f->score_clear + f->dead_value);
	expect_u(f, "score", f->score_clear + f->dead_value);
	/* A, then C (two steps on from A), then E (two on from C) */
	idle(f, 30);
	tap(f, ACT_FIRE);
	tap(f, ACT_FORWARD);
	tap(f, ACT_FORWARD);
	tap(f, ACT_FIRE);
	tap(f, ACT_TURN_RIGHT);
	tap(f, ACT_STRAFE_RIGHT);
	tap(f, ACT_FIRE);
	f->t_attract = f->s.tick;
	expect(f, "mode", "==", "attract");
	expect(f, "page", "==", "scores");
	assert_int_equal(f->s.new_rank + 1, default_rank(f->s.g.score));
	expect_u(f, "rank", (uint32_t)default_rank(f->s.g.score));
	expect(f, "hiscore", "==", "10000");
	say(f, "%u screenshot attract-scores.png", f->s.tick - 1);
	f->score_end = f->s.g.score;
	idle(f, 60);
	expect(f, "mode", "==", "attract");
	say(f, "%u end", f->s.tick - 1);
}

static void free_flow(struct flow *f)
{
	for (int i = 0; i < f->nlines; i++)
		free(f->lines[i]);
	for (int i = 0; i < 3; i++)
		map_free(f->maps[i]);
}

static char *script_text(const struct flow *f, size_t *len)
{
	size_t n = 0;
	char *t;

	for (int i = 0; i < f->nlines; i++)
		n += strlen(f->lines[i]) + 1;
	t = malloc(n + 1);
	assert_non_null(t);
	n = 0;
	for (int i = 0; i < f->nlines; i++) {
		size_t k = strlen(f->lines[i]);
		memcpy(t + n, f->lines[i], k);
		t[n + k] = '\n';
		n += k + 1;
	}
	t[n] = '\0';
	*len = n;
	return t;
}

/* The flow itself: every stage of it happens, in order. */
static void the_bot_plays_the_whole_flow(void **state)
{
	static struct flow f;
	(void)state;
	play_flow(&f);
	assert_true(f.t_play < f.t_clear && f.t_clear < f.t_stage2 && f.t_stage2 < f.t_over1 &&
		    f.t_over1 < f.t_cont && f.t_cont < f.t_over2 && f.t_over2 < f.t_initials &&
		    f.t_initials < f.t_attract);
	/* stage 1: every enemy killed, the clear bonus */
	assert_true(f.score_clear >= 100 * 3 + 200 + G_STAGE_BONUS);
	assert_int_equal(f.s.g.continues, 1);
	assert_int_equal(f.s.plays, 1);
	assert_int_equal(f.s.coins_total, 2);
	assert_int_equal(f.s.books.plays, 1);
	/* the new entry */
	assert_int_equal(f.s.mode, SIM_ATTRACT);
	assert_int_equal(f.s.page, SIM_PAGE_SCORES);
	assert_true(f.s.new_rank >= 0);
	assert_memory_equal(f.s.scores.e[f.s.new_rank].name, "ACE", 3);
	assert_int_equal(f.s.scores.e[f.s.new_rank].score, f.score_end);
	assert_int_equal(f.s.scores.e[f.s.new_rank].stage, 2);
	if (getenv("ARCADED_FLOW_SCRIPT")) {
		size_t len;
		char *t = script_text(&f, &len);
		FILE *fp = fopen(getenv("ARCADED_FLOW_SCRIPT"), "w");
		assert_non_null(fp);
		assert_int_equal(fwrite(t, 1, len, fp), len);
		assert_int_equal(fclose(fp), 0);
		free(t);
	}
	free_flow(&f);
}

/* The committed script is the bot's, and replaying it through the
 * script parser and cmd_build (the daemon's path) gives the same game. */
static void the_committed_script_is_the_flow(void **state)
{
	static struct flow f;
	struct scr *scr;
	char err[256];
	const struct map *mp[3];
	static const struct sim_settings set = { 1, 0, 0, 0, 0, 100, 1, 0, 0, 0 };
	struct cmd_state cs;
	struct sim s;
	size_t len, k = 0;
	char *t;
	int rc;
	(void)state;
	play_flow(&f);
	t = script_text(&f, &len);
	rc = scr_load(FLOW_SCRIPT, &scr, err, sizeof(err));
	if (rc != 0)
		fail_msg("%s (write it: ARCADED_FLOW_SCRIPT=%s)", err, FLOW_SCRIPT);
	{
		FILE *fp = fopen(FLOW_SCRIPT, "r");
		static char file[1 << 20];
		size_t n;
		assert_non_null(fp);
		n = fread(file, 1, sizeof(file), fp);
		fclose(fp);
		if (n != len || memcmp(file, t, len) != 0)
			fail_msg("%s is not what the bot plays now: regenerate it (see the top of "
				 "this file) after looking at why", FLOW_SCRIPT);
	}
	for (int i = 0; i < 3; i++)
		mp[i] = f.maps[i];
	sim_init_stages(&s, mp, 3, &set, NULL, NULL);
	cmd_reset(&cs);
	/* as the daemon does: inputs before the tick, checks after it */
	for (uint32_t tick = 0; tick <= scr->end_tick; tick++) {
		struct sim_cmd c;
		size_t k0 = k;
		for (; k < scr->n && scr->steps[k].tick == tick; k++)
			if (scr->steps[k].op == SCR_PRESS || scr->steps[k].op == SCR_RELEASE)
				cmd_action(&cs, scr->steps[k].action, scr->steps[k].op == SCR_PRESS);
		cmd_build(&cs, &c);
		sim_tick(&s, &c);
		for (size_t i = k0; i < k; i++) {
			const struct scr_step *st = &scr->steps[i];
			if (st->op == SCR_EXPECT &&
			    !scr_compare(sim_field_value(&s, (int)st->field), st->cmp, st->value))
				fail_msg("%s:%u: expect %s failed", FLOW_SCRIPT, st->line,
					 scr_field_name(st->field));
		}
	}
	assert_true(sim_hash(&s) == sim_hash(&f.s));
	scr_free(scr);
	free(t);
	free_flow(&f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_bot_plays_the_whole_flow),
		cmocka_unit_test(the_committed_script_is_the_flow),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
