/* Tests for engine/game/sim_hash.c: the state walk behind sim_hash, sim_snapshot
 * and sim_restore. (sim_hash's coverage of each field is tested in
 * test_sim.c; that its values are unchanged is proven by the golden
 * recordings, tests/replay/run.sh and tests/xbuild/run.sh.) */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "g_fixture.h"

/* Brutal, one life, no free play: games end soon. */
static const struct sim_settings set = { 1, 0, 0, 3, 1 };
/* Other settings for the sim restored into: the snapshot brings its own. */
static const struct sim_settings other = { 4, 1, 0, 0, 9 };

struct stages {
	struct map *m[G_MAX_STAGES];
	int n;
};

static void stages_load(struct stages *st)
{
	st->n = lvl_builtin_count();
	assert_true(st->n >= 1 && st->n <= G_MAX_STAGES);
	for (int i = 0; i < st->n; i++)
		assert_int_equal(lvl_builtin(i, &st->m[i]), 0);
}

static void stages_free(struct stages *st)
{
	for (int i = 0; i < st->n; i++)
		map_free(st->m[i]);
}

/* A table every score above 0 makes, so games end in INITIALS. */
static void low_table(struct g_scores *t)
{
	memset(t, 0, sizeof(*t));
	for (int i = 0; i < G_SCORES; i++)
		memcpy(t->e[i].name, "ZZZ", G_NAME_LEN);
}

static void session(struct sim *s, const struct stages *st)
{
	struct g_scores t;

	low_table(&t);
	sim_init_stages(s, (const struct map *const *)st->m, st->n, &set, &t, NULL);
}

/* A fresh sim on the same stages with other settings, tables and books. */
static void fresh(struct sim *s, const struct stages *st)
{
	struct g_books b = { 7, 7, 7, 7 };

	sim_init_stages(s, (const struct map *const *)st->m, st->n, &other, NULL, &b);
}

static uint32_t rnd(uint32_t *r)
{
	*r ^= *r << 13;
	*r ^= *r >> 17;
	*r ^= *r << 5;
	return *r;
}

/* Random play: movement and turning held for spans, fire often; now and
 * then a coin, START or (rarely) SERVICE, so every mode comes round. */
static struct sim_cmd random_cmd(uint32_t *r, struct sim_cmd *held)
{
	struct sim_cmd c;
	uint32_t v = rnd(r);

	if (v % 40 == 0) {
		held->forward = (int8_t)((int)(rnd(r) % 255) - 127);
		held->side = (int8_t)((int)(rnd(r) % 255) - 127);
		held->turn = (int16_t)((int)(rnd(r) % 1025) - 512);
	}
	c = *held;
	v = rnd(r);
	c.buttons = (uint8_t)((v % 4 == 0 ? SIM_BT_FIRE : 0) | (v % 997 == 1 ? SIM_BT_START : 0) |
			      (v % 7919 == 2 ? SIM_BT_SERVICE : 0));
	c.coins = (uint8_t)(v % 211 == 3);
	return c;
}

/* One tick of a session, sped up where random play is slow: START after
 * 300 ticks of attract, SERVICE (back, then out) after 600 in the menu;
 * in a fight, every 1000th tick a kill and every 3000th a death, by the
 * rules' own functions (what a hit does). */
static void session_tick(struct sim *s, struct sim_cmd c, int t)
{
	if (s->mode == SIM_ATTRACT && s->mode_t > 300 && t % 20 == 0)
		c.buttons |= SIM_BT_START;
	if (s->mode == SIM_SERVICE && s->menu.t > 600 && t % 20 == 0)
		c.buttons |= SIM_BT_SERVICE;
	sim_tick(s, &c);
	if (s->mode != SIM_PLAY || s->g.phase != G_PH_PLAY || t % 1000 != 999)
		return;
	for (int i = 0; i < s->g.num_enemies; i++) {
		if (s->g.en[i].state != G_E_DEAD) {
			g_hurt_enemy(s, i, 1000);
			break;
		}
	}
	if (t % 3000 == 2999)
		g_hurt_player(s, fx_from_int(1000));
}

static void run(struct sim *s, const struct sim_cmd *c, int ticks)
{
	for (int i = 0; i < ticks; i++)
		sim_tick(s, c);
}

static uint8_t *snap(const struct sim *s)
{
	uint8_t *b = malloc(sim_snapshot_size());

	assert_non_null(b);
	sim_snapshot(s, b);
	return b;
}

/* The states the tests start from, reached by play (and, to end a game
 * quickly, the rules' own damage functions). */
enum start { ST_ATTRACT, ST_PLAY, ST_GAMEOVER, ST_INITIALS, ST_SERVICE, ST_COUNT };

static void reach(struct sim *s, const struct stages *st, enum start which)
{
	static const struct sim_cmd nothing = { 0 }, coin = { .coins = 1 },
				    start = { .buttons = SIM_BT_START },
				    service = { .buttons = SIM_BT_SERVICE },
				    down = { .forward = -127 }, fire = { .buttons = SIM_BT_FIRE },
				    right = { .turn = -100 };
	struct sim_cmd held = { 0 };
	uint32_t r = 12345;

	session(s, st);
	run(s, &coin, 1);
	run(s, &nothing, 1);
	run(s, &coin, 1);
	run(s, &nothing, SIM_TITLE_TICKS + 100);       /* attract, page SCORES, 2 credits */
	assert_int_equal(s->mode, SIM_ATTRACT);
	assert_int_equal(s->page, SIM_PAGE_SCORES);
	assert_int_equal(s->credits, 2);
	if (which == ST_ATTRACT)
		return;
	run(s, &start, 1);
	run(s, &nothing, 1);
	for (int i = 0; i < 400; i++) {                 /* fight */
		struct sim_cmd c = random_cmd(&r, &held);
		c.buttons &= SIM_BT_FIRE;
		sim_tick(s, &c);
		if (s->g.phase == G_PH_DEAD)
			break;
	}
	if (which == ST_PLAY) {
		if (s->g.phase == G_PH_DEAD)
			fail_msg("died too soon for the PLAY start");
		return;
	}
	if (which == ST_SERVICE) {
		/* the settings page: down twice, fire, change the lives */
		run(s, &service, 1);
		run(s, &nothing, 1);
		for (int i = 0; i < 2; i++) {
			run(s, &down, 1);
			run(s, &nothing, 1);
		}
		run(s, &fire, 1);
		run(s, &nothing, 1);
		run(s, &down, 1);
		run(s, &nothing, 1);
		run(s, &right, 1);
		run(s, &nothing, 1);
		assert_int_equal(s->mode, SIM_SERVICE);
		assert_int_equal(s->menu.page, MENU_SETTINGS);
		return;
	}
	if (s->g.kills == 0)
		g_hurt_enemy(s, 0, 1000);              /* a score for the table */
	g_hurt_player(s, fx_from_int(1000));
	run(s, &nothing, G_DEAD_TICKS + 100);
	assert_int_equal(s->mode, SIM_GAMEOVER);
	if (which == ST_GAMEOVER)
		return;
	run(s, &nothing, G_CONTINUE_TICKS);
	assert_int_equal(s->mode, SIM_INITIALS);
	run(s, &down, 1);                               /* a letter, and the next */
	run(s, &fire, 1);
	run(s, &nothing, 1);
}

/* The restore of a snapshot is the very state: every byte of struct sim
 * (padding is zero in both: sim_init_stages clears the whole struct, and
 * the rules store fields, never a struct with stray padding). A field
 * added to struct sim but not to the walk fails this. */
static void a_restored_sim_is_byte_identical(void **state)
{
	struct stages st;
	(void)state;
	stages_load(&st);
	for (int k = 0; k < ST_COUNT; k++) {
		struct sim *a = malloc(sizeof(*a)), *b = malloc(sizeof(*b));
		uint8_t *buf;

		assert_non_null(a);
		assert_non_null(b);
		reach(a, &st, (enum start)k);
		buf = snap(a);
		fresh(b, &st);
		assert_int_equal(sim_restore(b, buf, sim_snapshot_size()), 0);
		if (memcmp(a, b, sizeof(*a)) != 0) {
			const uint8_t *x = (const uint8_t *)a, *y = (const uint8_t *)b;
			size_t i = 0;
			while (x[i] == y[i])
				i++;
			fail_msg("start %d: restored sim differs at byte %zu of %zu", k, i,
				 sizeof(*a));
		}
		assert_true(sim_hash(a) == sim_hash(b));
		free(buf);
		free(a);
		free(b);
	}
	stages_free(&st);
}

/* Restored at each start, both sims fed the same commands give the same
 * hash on each of 5000 ticks (through games, deaths, modes). */
static void a_restored_sim_follows_the_original_for_5000_ticks(void **state)
{
	static const enum sim_mode mode[ST_COUNT] = { SIM_ATTRACT, SIM_PLAY, SIM_GAMEOVER,
						      SIM_INITIALS, SIM_SERVICE };
	struct stages st;
	(void)state;
	stages_load(&st);
	for (int k = 0; k < ST_COUNT; k++) {
		struct sim *a = malloc(sizeof(*a)), *b = malloc(sizeof(*b));
		struct sim_cmd held = { 0 };
		uint32_t r = 777u + (uint32_t)k, modes = 0;
		uint8_t *buf;

		assert_non_null(a);
		assert_non_null(b);
		reach(a, &st, (enum start)k);
		assert_int_equal(a->mode, mode[k]);
		if (k == ST_PLAY)
			assert_true(a->g.num_enemies > 0 && a->g.alive > 0);
		buf = snap(a);
		fresh(b, &st);
		assert_true(sim_hash(a) != sim_hash(b));
		assert_int_equal(sim_restore(b, buf, sim_snapshot_size()), 0);
		assert_true(sim_hash(a) == sim_hash(b));
		for (int t = 0; t < 5000; t++) {
			struct sim_cmd c = random_cmd(&r, &held);
			session_tick(a, c, t);
			session_tick(b, c, t);
			if (sim_hash(a) != sim_hash(b))
				fail_msg("start %d: hashes differ %d ticks after the restore", k, t + 1);
			modes |= 1u << a->mode;
		}
		/* the commands took the sims through more than the start's mode */
		if (!(modes & ~(1u << mode[k])))
			fail_msg("start %d: stayed in mode %s", k, sim_mode_name(mode[k]));
		free(buf);
		free(a);
		free(b);
	}
	stages_free(&st);
}

/* Every state of a long random session snapshots, restores (into a fresh
 * sim) and snapshots again to the same bytes: the checks refuse no state
 * the rules can reach. */
static void every_state_of_a_long_session_restores(void **state)
{
	struct stages st;
	struct sim *a = malloc(sizeof(*a)), *b = malloc(sizeof(*b));
	size_t n = sim_snapshot_size();
	uint8_t *x = malloc(n), *y = malloc(n);
	struct sim_cmd held = { 0 };
	uint32_t r = 99, modes = 0, games = 0;
	(void)state;
	assert_non_null(a);
	assert_non_null(b);
	assert_non_null(x);
	assert_non_null(y);
	stages_load(&st);
	session(a, &st);
	for (int t = 0; t < 40000; t++) {
		struct sim_cmd c = random_cmd(&r, &held);
		uint32_t plays = a->plays;

		session_tick(a, c, t);
		games += a->plays != plays;
		modes |= 1u << a->mode;
		if (t % 5)
			continue;
		sim_snapshot(a, x);
		fresh(b, &st);
		if (sim_restore(b, x, n) != 0)
			fail_msg("tick %d (mode %s): a reachable state is refused", t,
				 sim_mode_name(a->mode));
		sim_snapshot(b, y);
		assert_memory_equal(x, y, n);
	}
	/* the session went through every mode, and several games */
	assert_int_equal(modes, (1u << SIM_MODE_COUNT) - 1);
	assert_true(games >= 3);
	free(x);
	free(y);
	free(a);
	free(b);
	stages_free(&st);
}

/* The size, counted by hand from the walk: stages hash 8, map index 1,
 * num_stages 1, settings 5, tick 4, mode 4, page 1, mode_t, credits,
 * coin_rem, coins_total, plays 4 each, prev_buttons 1, prev_nav 1, nav_t 2,
 * cmd 6, rng 4, player 44 (six 4-byte positions and momenta, angle,
 * sector, health 4 each, four 2-byte counters), game 25 + 96 enemies of 48
 * + 96 pickups of 18 + shot 15, countdown 2, ini_pos 1, ini 3, ranks 2,
 * scores 10 x 8, books 24, gens 12, menu 18. A change means the struct
 * changed: REC_ENGINE_VERSION must change with it. */
static void the_snapshot_size_is_every_field(void **state)
{
	size_t game = 25 + 96 * 48 + 96 * 18 + 15;
	size_t expect = 8 + 1 + 1 + 5 + 4 + 4 + 1 + 5 * 4 + 1 + 1 + 2 + 6 + 4 + 44 + game + 2 +
			1 + 3 + 2 + 80 + 24 + 12 + 18;
	(void)state;
	assert_int_equal(sim_snapshot_size(), expect);
	assert_int_equal(expect, 6620);
}

/* Snapshot encoding: little-endian fields at fixed offsets. */
static void the_snapshot_is_little_endian_fields_in_order(void **state)
{
	static const uint8_t settings[] = { 1, 0, 0, 3, 1 }, tick[] = { 0x44, 0x33, 0x22, 0x11 },
			     mode[] = { SIM_GAMEOVER, 0, 0, 0 }, credits[] = { 0x0d, 0x0c, 0x0b, 0x0a };
	struct stages st;
	struct sim s;
	uint8_t *b;
	uint64_t h;
	(void)state;
	stages_load(&st);
	session(&s, &st);
	s.tick = 0x11223344;
	s.mode = SIM_GAMEOVER;
	s.credits = 0x0a0b0c0d;
	b = snap(&s);
	h = sim_stages_hash((const struct map *const *)st.m, st.n);
	for (int i = 0; i < 8; i++)
		assert_int_equal(b[i], (uint8_t)(h >> (8 * i)));
	assert_int_equal(b[8], 0);                      /* attract shows stage 0 */
	assert_int_equal(b[9], st.n);
	assert_memory_equal(b + 10, settings, 5);
	assert_memory_equal(b + 15, tick, 4);
	assert_memory_equal(b + 19, mode, 4);
	assert_memory_equal(b + 28, credits, 4);       /* after page 23 and mode_t 24..27 */
	free(b);
	stages_free(&st);
}

/* Each change makes the state one the rules never reach; the restore
 * refuses it and leaves the sim as it was. */
static void out_of_range_values_are_refused(void **state)
{
	struct stages st;
	struct sim *a = malloc(sizeof(*a)), *b = malloc(sizeof(*b)), *keep = malloc(sizeof(*keep));
	size_t n = sim_snapshot_size();
	uint8_t *buf = malloc(n + 1);
	int cases = 0;
	(void)state;
	assert_non_null(a);
	assert_non_null(b);
	assert_non_null(keep);
	assert_non_null(buf);
	stages_load(&st);
	for (int i = 0;; i++) {
		reach(a, &st, ST_PLAY);
		switch (i) {
		case 0: break;                               /* unchanged: accepted */
		case 1: a->mode = SIM_MODE_COUNT; break;
		case 2: a->page = SIM_PAGE_COUNT; break;
		case 3: a->g.num_enemies = G_MAX_ENEMIES + 1; break;
		case 4: a->g.num_pickups = G_MAX_PICKUPS + 1; break;
		case 5: a->g.alive = (uint16_t)(a->g.num_enemies + 1); break;
		case 6: a->g.stage = (uint8_t)st.n; break;
		case 7: a->g.phase = G_PH_CLEAR + 1; break;
		case 8: a->g.shot = G_SHOT_MISS + 1; break;
		case 9: a->g.en[0].kind = G_KINDS; break;
		case 10: a->g.en[0].state = G_E_DEAD + 1; break;
		case 11: a->g.en[a->g.num_enemies - 1].sector = a->map->num_sectors; break;
		case 12: a->g.pk[0].kind = G_P_AMMO + 1; break;
		case 13: a->g.pk[0].taken = 2; break;
		case 14: a->pl.sector = a->map->num_sectors; break;
		case 15: a->pl.x = MAP_COORD_MAX + 1; break;
		case 16: a->g.en[0].sy = -MAP_COORD_MAX - 1; break;
		case 17: a->pl.health = -1; break;
		case 18: a->pl.health = G_HEALTH_MAX * FX_ONE + 1; break;
		case 19: a->ini_pos = G_NAME_LEN + 1; break;
		case 20: a->ini[2] = G_ALPHABET_LEN; break;
		case 21: a->ini_rank = G_SCORES; break;
		case 22: a->ini_rank = -2; break;
		case 23: a->new_rank = G_SCORES; break;
		case 24: a->mode = SIM_INITIALS; a->ini_pos = G_NAME_LEN; a->ini_rank = 0; break;
		case 25: a->mode = SIM_INITIALS; a->ini_pos = 0; a->ini_rank = -1; break;
		case 26: a->menu.page = MENU_PAGES; break;
		case 27: a->menu.cursor = MENU_ITEMS; break;
		case 28: a->menu.main_cursor = MENU_ITEMS; break;
		case 29: a->menu.display = MENU_D_COUNT; break;
		case 30: a->menu.confirm = MENU_ITEMS; break;
		case 31: a->menu.yes = 2; break;
		case 32: a->menu.res = MENU_RES_COUNT + 1; break;
		case 33: a->menu.done = MENU_ITEMS; break;
		default: break;
		}
		if (i > 33)
			break;
		sim_snapshot(a, buf);
		fresh(b, &st);
		*keep = *b;
		if (i == 0) {
			assert_int_equal(sim_restore(b, buf, n), 0);
			continue;
		}
		if (sim_restore(b, buf, n) != -EINVAL)
			fail_msg("case %d accepted", i);
		assert_memory_equal(b, keep, sizeof(*b));
		cases++;
	}
	assert_int_equal(cases, 33);
	/* in a spare slot (past the count) the same value is no state: accepted */
	reach(a, &st, ST_PLAY);
	a->g.en[a->g.num_enemies].kind = 200;
	a->g.pk[a->g.num_pickups].kind = 200;
	sim_snapshot(a, buf);
	fresh(b, &st);
	assert_int_equal(sim_restore(b, buf, n), 0);
	assert_int_equal(b->g.en[a->g.num_enemies].kind, 200);
	free(buf);
	free(a);
	free(b);
	free(keep);
	stages_free(&st);
}

/* Damaged bytes, a wrong length, other maps. */
static void damaged_snapshots_and_other_maps_are_refused(void **state)
{
	struct stages st;
	struct sim *a = malloc(sizeof(*a)), *b = malloc(sizeof(*b)), *keep = malloc(sizeof(*keep));
	size_t n = sim_snapshot_size();
	uint8_t *buf = malloc(n + 1);
	struct map *room;
	const struct map *one[1];
	(void)state;
	assert_non_null(a);
	assert_non_null(b);
	assert_non_null(keep);
	assert_non_null(buf);
	stages_load(&st);
	reach(a, &st, ST_PLAY);
	sim_snapshot(a, buf);
	buf[n] = 0;
	fresh(b, &st);
	*keep = *b;
	assert_int_equal(sim_restore(b, buf, n - 1), -EINVAL);
	assert_int_equal(sim_restore(b, buf, n + 1), -EINVAL);
	assert_int_equal(sim_restore(b, buf, 0), -EINVAL);
	buf[3] ^= 0x10;                                 /* the stages hash */
	assert_int_equal(sim_restore(b, buf, n), -EINVAL);
	buf[3] ^= 0x10;
	buf[8] = (uint8_t)st.n;                         /* the current map's index */
	assert_int_equal(sim_restore(b, buf, n), -EINVAL);
	buf[8] = 0;
	buf[9] = (uint8_t)(st.n + 1);                   /* the number of stages */
	assert_int_equal(sim_restore(b, buf, n), -EINVAL);
	buf[9] = (uint8_t)st.n;
	assert_memory_equal(b, keep, sizeof(*b));
	assert_int_equal(sim_restore(b, buf, n), 0);
	/* the same snapshot on other maps: one stage, a room */
	room = gf_room(512, 512, NULL, 0, NULL, 0);
	assert_non_null(room);
	one[0] = room;
	sim_init_stages(b, one, 1, &set, NULL, NULL);
	assert_int_equal(sim_restore(b, buf, n), -EINVAL);
	/* the stages in another order */
	if (st.n >= 2) {
		const struct map *rev[G_MAX_STAGES];
		for (int i = 0; i < st.n; i++)
			rev[i] = st.m[st.n - 1 - i];
		sim_init_stages(b, rev, st.n, &set, NULL, NULL);
		assert_int_equal(sim_restore(b, buf, n), -EINVAL);
	}
	map_free(room);
	free(buf);
	free(a);
	free(b);
	free(keep);
	stages_free(&st);
}

/* The hash skips spare slots, the snapshot keeps them: changing a spare
 * slot changes the snapshot, not the hash. */
static void spare_slots_are_saved_but_not_hashed(void **state)
{
	struct stages st;
	struct sim *a = malloc(sizeof(*a));
	size_t n = sim_snapshot_size();
	uint8_t *x = malloc(n), *y = malloc(n);
	uint64_t h;
	(void)state;
	assert_non_null(a);
	assert_non_null(x);
	assert_non_null(y);
	stages_load(&st);
	reach(a, &st, ST_PLAY);
	assert_true(a->g.num_enemies < G_MAX_ENEMIES);
	h = sim_hash(a);
	sim_snapshot(a, x);
	a->g.en[G_MAX_ENEMIES - 1].x += FX_ONE;
	sim_snapshot(a, y);
	assert_true(sim_hash(a) == h);
	assert_true(memcmp(x, y, n) != 0);
	a->g.en[0].x += FX_ONE;
	assert_true(sim_hash(a) != h);
	free(x);
	free(y);
	free(a);
	stages_free(&st);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_snapshot_size_is_every_field),
		cmocka_unit_test(the_snapshot_is_little_endian_fields_in_order),
		cmocka_unit_test(a_restored_sim_is_byte_identical),
		cmocka_unit_test(a_restored_sim_follows_the_original_for_5000_ticks),
		cmocka_unit_test(every_state_of_a_long_session_restores),
		cmocka_unit_test(out_of_range_values_are_refused),
		cmocka_unit_test(damaged_snapshots_and_other_maps_are_refused),
		cmocka_unit_test(spare_slots_are_saved_but_not_hashed),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
