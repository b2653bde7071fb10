/*
 * demo: the attract demo (app/demo.c). On the first built-in level it is
 * the recorded game (levels/demo.scr): played through demo_tick under a
 * main sim held on the DEMO page, it scores, kills every enemy and clears
 * the stage with the spread gun in hand, by the recorded rules whatever the cabinet's settings (a
 * cabinet set to BRUTAL with one life plays the same demo, tick for tick,
 * as one at the factory settings); on other content (the grid map) it is
 * the walk about. Independent reasons for the numbers: ARENA1 has four
 * enemies (levels/arena1.txt, "Three grunts ... a sentry"), and a clear
 * is phase G_PH_CLEAR with no enemy alive.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "app/ct.h"
#include "app/demo.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"

/* A main sim on its DEMO page, as attract mode has it when the demo
 * starts (mode_t 0), with the cabinet's settings set. */
static void on_demo_page(struct sim *m, const struct ct *ct, const struct sim_settings *set)
{
	sim_init_stages(m, (const struct map *const *)ct->maps, ct->nmaps, set, NULL, NULL);
	m->mode = SIM_ATTRACT;
	m->page = SIM_PAGE_DEMO;
	m->mode_t = 0;
}

/* Plays the demo for n ticks; the first tick the stage showed cleared
 * (UINT32_MAX: never), and the kills and the score then. */
static uint32_t play(struct demo *d, struct sim *m, uint32_t n, uint32_t *kills, uint32_t *score,
		     uint8_t *weapon)
{
	uint32_t clear_t = UINT32_MAX;

	*kills = *score = 0;
	for (uint32_t t = 0; t < n; t++) {
		demo_tick(d, m);
		m->mode_t++;
		assert_non_null(demo_under(d, m));
		if (clear_t == UINT32_MAX && d->sim.g.phase == G_PH_CLEAR && d->sim.g.alive == 0) {
			clear_t = t;
			*kills = d->sim.g.kills;
			*score = d->sim.g.score;
			*weapon = d->sim.pl.weapon;
		}
	}
	return clear_t;
}

static void the_demo_game_clears_the_first_level(void **state)
{
	struct ct_spec spec = { .level = 1 };
	struct sim_settings set = { 0 };
	struct ct *ct = calloc(1, sizeof(*ct));
	struct sim *m = calloc(1, sizeof(*m));
	struct demo *d = calloc(1, sizeof(*d)), *d2 = calloc(1, sizeof(*d2));
	uint32_t kills, score, clear_t, kills2, score2;
	uint8_t weapon = G_W_PISTOL, weapon2 = G_W_PISTOL;
	char err[256];
	int diff;

	(void)state;
	assert_non_null(ct);
	assert_non_null(m);
	assert_non_null(d);
	assert_non_null(d2);
	assert_int_equal(ct_load(ct, &spec, err, sizeof(err)), 0);
	assert_string_equal(ct->maps[0]->name, "ARENA1");
	assert_true(demo_game_matches(ct->maps[0], &diff));
	assert_int_equal(demo_init(d, ct, err, sizeof(err)), 0);
	assert_int_equal(d->game, 1);

	set.difficulty = 1;
	on_demo_page(m, ct, &set);
	clear_t = play(d, m, SIM_DEMO_TICKS, &kills, &score, &weapon);
	assert_true(clear_t < SIM_DEMO_TICKS);
	assert_int_equal(kills, 4);
	assert_true(score > 0);
	/* the spread gun at the stairs' foot (levels/arena1.txt) is taken */
	assert_int_equal(weapon, G_W_SPREAD);

	/* another cabinet: BRUTAL, one life, no stage clock; the same game */
	assert_int_equal(demo_init(d2, ct, err, sizeof(err)), 0);
	set.difficulty = 3;
	set.lives = 1;
	set.stage_time = 255;
	on_demo_page(m, ct, &set);
	assert_int_equal(play(d2, m, SIM_DEMO_TICKS, &kills2, &score2, &weapon2), clear_t);
	assert_int_equal(weapon2, weapon);
	assert_int_equal(kills2, kills);
	assert_int_equal(score2, score);
	assert_int_equal(sim_hash(&d2->sim), sim_hash(&d->sim));

	demo_free(d);
	demo_free(d2);
	ct_free(ct);
	free(ct);
	free(m);
	free(d);
	free(d2);
}

static void other_content_gets_the_walk_about(void **state)
{
	struct ct_spec spec = { .grid = "builtin" };
	struct ct *ct = calloc(1, sizeof(*ct));
	struct demo *d = calloc(1, sizeof(*d));
	char err[256];
	int diff;

	(void)state;
	assert_non_null(ct);
	assert_non_null(d);
	assert_int_equal(ct_load(ct, &spec, err, sizeof(err)), 0);
	assert_false(demo_game_matches(ct->maps[0], &diff));
	assert_int_equal(demo_init(d, ct, err, sizeof(err)), 0);
	assert_int_equal(d->game, 0);
	assert_int_equal(d->len, 1800);
	demo_free(d);
	ct_free(ct);
	free(ct);
	free(d);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_demo_game_clears_the_first_level),
		cmocka_unit_test(other_content_gets_the_walk_about),
	};

	return cmocka_run_group_tests_name("demo", tests, NULL, NULL);
}
