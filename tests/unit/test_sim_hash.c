/* Tests for engine/game/sim_hash.c: the state walk behind sim_hash, sim_snapshot,
 * sim_restore and sim_visit, generated from the field lists of
 * engine/game/sim_table.h. (That the hash values are unchanged is proven by
 * the golden recordings, tests/replay/run.sh and tests/xbuild/run.sh; that a
 * member outside the lists stops the build, by tests/check_state.sh.) */
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
#include "map_fixture.h"

/* Brutal, one life, no free play: games end soon. */
static const struct sim_settings set = { 1, 0, 0, 3, 1, 100, 1, 0, 0, 0 };
/* Other settings for the sim restored into: the snapshot brings its own. */
static const struct sim_settings other = { 4, 1, 0, 0, 9, 100, 1, 0, 0, 0 };

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
		/* the settings page: down three times, fire, change the lives */
		run(s, &service, 1);
		run(s, &nothing, 1);
		for (int i = 0; i < MENU_I_SETTINGS; i++) {
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
 * the rules store fields, never a struct with stray padding). A member
 * the walk did not restore would fail this (and the build refuses a member
 * outside the field lists: tests/check_state.sh). */
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

/* ---- the field list (sim_visit) -------------------------------------
 *
 * The tests below take their list of fields from sim_visit, which is
 * generated from the same lists as the struct members, the hash and the
 * snapshot (engine/game/sim_table.h): a field added to a list is checked
 * here without a line of test. */

struct flist {
	struct sim_vfield *f;
	int n, cap;
};

static void collect(void *ctx, const struct sim_vfield *f)
{
	struct flist *l = ctx;

	if (l->n == l->cap) {
		l->cap = l->cap ? 2 * l->cap : 1024;
		l->f = realloc(l->f, (size_t)l->cap * sizeof(*l->f));
		assert_non_null(l->f);
	}
	l->f[l->n++] = *f;
}

static struct flist fields_of(const struct sim *s)
{
	struct flist l = { 0 };

	sim_visit(s, collect, &l);
	assert_true(l.n > 0);
	return l;
}

/* The field at offset off of struct sim, or NULL. */
static const struct sim_vfield *field_at(const struct flist *l, size_t off)
{
	for (int i = 0; i < l->n; i++)
		if (l->f[i].off == off)
			return &l->f[i];
	return NULL;
}

/* The value of f in s (host order in memory), as the bits of its type. */
static uint64_t get_bits(const struct sim *s, const struct sim_vfield *f)
{
	const uint8_t *p = (const uint8_t *)s + f->off;
	uint8_t b8;
	uint16_t b16;
	uint32_t b32;
	uint64_t b64;

	switch (f->size) {
	case 1: memcpy(&b8, p, 1); return b8;
	case 2: memcpy(&b16, p, 2); return b16;
	case 4: memcpy(&b32, p, 4); return b32;
	default: memcpy(&b64, p, 8); return b64;
	}
}

static void set_bits(struct sim *s, const struct sim_vfield *f, uint64_t v)
{
	uint8_t *p = (uint8_t *)s + f->off;
	uint8_t b8 = (uint8_t)v;
	uint16_t b16 = (uint16_t)v;
	uint32_t b32 = (uint32_t)v;

	switch (f->size) {
	case 1: memcpy(p, &b8, 1); break;
	case 2: memcpy(p, &b16, 2); break;
	case 4: memcpy(p, &b32, 4); break;
	default: memcpy(p, &v, 8); break;
	}
}

/* Every field is listed once, in the order of memory and of the snapshot,
 * which it fills from the two map fields (the 8-byte stages hash and the
 * 1-byte map index) to the end: the snapshot size is the listed fields'
 * bytes. */
static void the_fields_are_listed_in_memory_and_snapshot_order(void **state)
{
	static const char *const tags[] = { "sim", "sim_settings", "sim_cmd", "sim_player",
					    "g_game", "g_enemy", "g_pickup", "g_entry",
					    "g_books", "menu" };
	struct stages st;
	struct sim *a = malloc(sizeof(*a));
	struct flist l;
	const struct sim_vfield *f;
	(void)state;
	assert_non_null(a);
	stages_load(&st);
	reach(a, &st, ST_PLAY);
	l = fields_of(a);
	assert_int_equal(l.f[0].at, 8 + 1);
	for (int i = 0; i < l.n; i++) {
		f = &l.f[i];
		assert_true(f->off + f->size <= sizeof(*a));
		assert_true(f->bytes >= 1 && f->bytes <= 8);
		/* only an enum differs: 4 bytes in the snapshot */
		if (f->size != f->bytes)
			assert_int_equal(f->bytes, 4);
		if (i == 0)
			continue;
		if (f->off < l.f[i - 1].off + l.f[i - 1].size)
			fail_msg("%s.%s (offset %zu) overlaps or precedes %s.%s", f->tag, f->name,
				 f->off, l.f[i - 1].tag, l.f[i - 1].name);
		assert_int_equal(f->at, l.f[i - 1].at + l.f[i - 1].bytes);
	}
	f = &l.f[l.n - 1];
	assert_int_equal(sim_snapshot_size(), f->at + f->bytes);
	for (size_t k = 0; k < sizeof(tags) / sizeof(tags[0]); k++) {
		int seen = 0;
		for (int i = 0; i < l.n; i++)
			seen |= strcmp(l.f[i].tag, tags[k]) == 0;
		if (!seen)
			fail_msg("no field of struct %s listed", tags[k]);
	}
	/* the names and offsets are the members' */
	f = field_at(&l, offsetof(struct sim, pl.x));
	assert_non_null(f);
	assert_string_equal(f->tag, "sim_player");
	assert_string_equal(f->name, "x");
	f = field_at(&l, offsetof(struct sim, ini[2]));
	assert_non_null(f);
	assert_string_equal(f->name, "ini");
	assert_int_equal(f->index, 2);
	assert_int_equal(f->hi, G_ALPHABET_LEN - 1);
	/* limits as the state is: alive at most the enemies */
	f = field_at(&l, offsetof(struct sim, g.alive));
	assert_non_null(f);
	assert_int_equal(f->hi, a->g.num_enemies);
	/* the first enemy slot past the count is spare, the last counted is not */
	assert_true(a->g.num_enemies > 0 && a->g.num_enemies < G_MAX_ENEMIES);
	f = field_at(&l, offsetof(struct sim, g.en) +
			     (size_t)a->g.num_enemies * sizeof(struct g_enemy));
	assert_non_null(f);
	assert_int_equal(f->spare, 1);
	f = field_at(&l, offsetof(struct sim, g.en) +
			     (size_t)(a->g.num_enemies - 1) * sizeof(struct g_enemy));
	assert_non_null(f);
	assert_int_equal(f->spare, 0);
	free(l.f);
	free(a);
	stages_free(&st);
}

/* f's lowest byte plus one (no carry into the next byte). */
static void bump(struct sim *u, const struct sim *a, const struct sim_vfield *f)
{
	uint64_t v = get_bits(a, f);

	set_bits(u, f, (v & ~(uint64_t)0xff) | ((v + 1) & 0xff));
}

/* Whether snapshot y is x with exactly the bytes at[0..count) one higher,
 * from byte `from` on. Leaves y as it was. */
static int only_bumped(const uint8_t *x, uint8_t *y, size_t n, size_t from, const size_t *at,
		       int count)
{
	int same;

	for (int i = 0; i < count; i++)
		y[at[i]] = (uint8_t)(y[at[i]] - 1);
	same = memcmp(x + from, y + from, n - from) == 0;
	for (int i = 0; i < count; i++)
		y[at[i]] = (uint8_t)(y[at[i]] + 1);
	return same;
}

/* The members (tag, name, index) of spare slots seen so far: the walk
 * passes the same name strings for every slot of an array. */
struct seen {
	const struct sim_vfield **f;
	int n, cap;
};

/* Whether f's member was seen; notes it if not. */
static int seen_before(struct seen *s, const struct sim_vfield *f)
{
	for (int i = s->n - 1; i >= 0; i--)
		if (s->f[i]->tag == f->tag && s->f[i]->name == f->name && s->f[i]->index == f->index)
			return 1;
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 256;
		s->f = realloc(s->f, (size_t)s->cap * sizeof(*s->f));
		assert_non_null(s->f);
	}
	s->f[s->n++] = f;
	return 0;
}

/* Whether field i is checked alone: every field of the state, and of the
 * spare slots (most of the list: 47,616 of 48,173 fields at the PLAY
 * start) each member's first (1,079 members there, most of them words of
 * the two line bit arrays), the last of each run of spare fields and
 * every 61st (spread over the slots). The slots of an array are walked
 * by the same code, and all spare fields at once are checked as well.
 * (Each field alone costs a walk of the whole list for the hash and one
 * for the snapshot: every field alone took 100 s of the gcc build and
 * five minutes under AddressSanitizer; these, about 2,300 a start, take
 * 4.4 s.) */
static int checked_alone(const struct flist *l, int i, struct seen *members)
{
	if (!l->f[i].spare)
		return 1;
	return !seen_before(members, &l->f[i]) || i % 61 == 0 || i + 1 == l->n ||
	       !l->f[i + 1].spare;
}

/* Each listed field, changed alone (its lowest byte plus one), changes the
 * hash unless it is in a spare slot, and changes exactly its own first
 * byte of the snapshot (little-endian, at its place); all spare fields
 * changed at once leave the hash as it was and change exactly their own
 * first bytes. Over every start. */
static void every_field_is_hashed_unless_spare_and_saved_in_place(void **state)
{
	struct stages st;
	struct sim *a = malloc(sizeof(*a)), *u = malloc(sizeof(*u));
	size_t n = sim_snapshot_size(), *at = NULL;
	uint8_t *x = malloc(n), *y = malloc(n);
	(void)state;
	assert_non_null(a);
	assert_non_null(u);
	assert_non_null(x);
	assert_non_null(y);
	stages_load(&st);
	for (int k = 0; k < ST_COUNT; k++) {
		struct flist l;
		struct seen members = { 0 };
		uint64_t h;
		int spare = 0, alone = 0;

		reach(a, &st, (enum start)k);
		l = fields_of(a);
		h = sim_hash(a);
		sim_snapshot(a, x);
		for (int i = 0; i < l.n; i++) {
			const struct sim_vfield *f = &l.f[i];

			spare += f->spare;
			if (!checked_alone(&l, i, &members))
				continue;
			alone++;
			*u = *a;
			bump(u, a, f);
			if ((sim_hash(u) != h) == f->spare)
				fail_msg("start %d: %s.%s[%d] (offset %zu, %s): the hash %s", k, f->tag,
					 f->name, f->index, f->off, f->spare ? "spare" : "state",
					 f->spare ? "changed" : "did not change");
			sim_snapshot(u, y);
			/* from the first listed field on (num_stages also feeds the
			 * stages hash before it) */
			if (!only_bumped(x, y, n, l.f[0].at, &f->at, 1)) {
				for (size_t j = l.f[0].at; j < n; j++) {
					int want = j == f->at ? (uint8_t)(x[j] + 1) : x[j];
					if (y[j] != want)
						fail_msg("start %d: %s.%s[%d] (snapshot byte %zu on): "
							 "byte %zu is %d, want %d", k, f->tag, f->name,
							 f->index, f->at, j, y[j], want);
				}
			}
		}
		/* every spare field at once */
		*u = *a;
		at = realloc(at, (size_t)spare * sizeof(*at) + 1);
		assert_non_null(at);
		for (int i = 0, j = 0; i < l.n; i++)
			if (l.f[i].spare) {
				bump(u, a, &l.f[i]);
				at[j++] = l.f[i].at;
			}
		if (sim_hash(u) != h)
			fail_msg("start %d: changing the %d spare fields changed the hash", k, spare);
		sim_snapshot(u, y);
		if (!only_bumped(x, y, n, l.f[0].at, at, spare))
			fail_msg("start %d: the %d spare fields changed other snapshot bytes than "
				 "their own", k, spare);
		/* the PLAY start has spare enemy and pickup slots, most of them
		 * not checked alone */
		if (k == ST_PLAY)
			assert_true(spare > 0 && alone < l.n / 4);
		free(members.f);
		free(l.f);
	}
	free(at);
	free(x);
	free(y);
	free(a);
	free(u);
	stages_free(&st);
}

/* The lowest and highest values of f's type. */
static void type_range(const struct sim_vfield *f, int64_t *min, int64_t *max)
{
	int bits = 8 * (int)f->bytes;

	if (f->sgn) {
		*min = -((int64_t)1 << (bits - 1));
		*max = ((int64_t)1 << (bits - 1)) - 1;
	} else {
		*min = 0;
		*max = bits >= 63 ? INT64_MAX : ((int64_t)1 << bits) - 1;
	}
}

/* Each listed limit is enforced: a field (not spare) set one past either
 * end of its range, where its type can hold that value, makes sim_restore
 * refuse the snapshot and leave the sim as it was. From the starts whose
 * limits differ (PLAY; INITIALS, where the letter and rank limits narrow;
 * SERVICE). */
static void every_listed_limit_is_enforced(void **state)
{
	static const enum start starts[] = { ST_PLAY, ST_INITIALS, ST_SERVICE };
	struct stages st;
	struct sim *a = malloc(sizeof(*a)), *u = malloc(sizeof(*u)), *b = malloc(sizeof(*b)),
		   *keep = malloc(sizeof(*keep));
	size_t n = sim_snapshot_size();
	uint8_t *buf = malloc(n);
	int cases = 0;
	(void)state;
	assert_non_null(a);
	assert_non_null(u);
	assert_non_null(b);
	assert_non_null(keep);
	assert_non_null(buf);
	stages_load(&st);
	for (size_t k = 0; k < sizeof(starts) / sizeof(starts[0]); k++) {
		struct flist l;

		reach(a, &st, starts[k]);
		l = fields_of(a);
		for (int i = 0; i < l.n; i++) {
			const struct sim_vfield *f = &l.f[i];
			int64_t min, max, out[2];
			int made = 0;

			if (f->spare)
				continue;
			type_range(f, &min, &max);
			out[0] = f->lo > min ? f->lo - 1 : 1;
			out[1] = f->hi < max ? f->hi + 1 : 0;
			for (int e = 0; e < 2; e++) {
				if (e == 0 ? !(f->lo > min) : !(f->hi < max))
					continue;
				*u = *a;
				set_bits(u, f, (uint64_t)out[e]);
				sim_snapshot(u, buf);
				fresh(b, &st);
				*keep = *b;
				if (sim_restore(b, buf, n) != -EINVAL)
					fail_msg("start %d: %s.%s[%d] = %lld (limit %lld..%lld) accepted",
						 (int)starts[k], f->tag, f->name, f->index,
						 (long long)out[e], (long long)f->lo, (long long)f->hi);
				assert_memory_equal(b, keep, sizeof(*b));
				made++;
			}
			cases += made;
		}
		free(l.f);
	}
	/* the lists hold limits (the contract's own cases are counted in
	 * out_of_range_values_are_refused) */
	assert_true(cases >= 33);
	free(buf);
	free(a);
	free(u);
	free(b);
	free(keep);
	stages_free(&st);
}

/* Snapshot encoding: little-endian fields at fixed offsets. */
static void the_snapshot_is_little_endian_fields_in_order(void **state)
{
	static const uint8_t settings[] = { 1, 0, 0, 3, 1, 100, 1, 0, 0, 0 },
			     tick[] = { 0x44, 0x33, 0x22, 0x11 },
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
	assert_memory_equal(b + 10, settings, 10);
	assert_memory_equal(b + 20, tick, 4);
	assert_memory_equal(b + 24, mode, 4);
	/* after page 28, attract_cycle 29..32 and mode_t 33..36 */
	assert_memory_equal(b + 37, credits, 4);
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
		case 7: a->g.phase = G_PH_TURN + 1; break;
		case 8: a->g.shot = G_SHOT_MISS + 1; break;
		case 9: a->g.en[0].kind = G_KINDS; break;
		case 10: a->g.en[0].state = G_E_DEAD + 1; break;
		case 11: a->g.en[a->g.num_enemies - 1].sector = a->map->num_sectors; break;
		case 12: a->g.pk[0].kind = G_P_KINDS; break;
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
		case 34: a->players = 3; break;
		case 35: a->up = 2; break;
		case 36: a->wait.stage = (uint8_t)st.n; break;
		case 37: a->wait.out = 2; break;
		case 38: a->w.sec[0].floor_h = MAP_HEIGHT_MAX + 1; break;
		case 39: a->w.sec[0].ceil_h = -MAP_HEIGHT_MAX - 1; break;
		default: break;
		}
		if (i > 39)
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
	assert_int_equal(cases, 39);
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

/* A map may have a floor at the height limit (MAP_HEIGHT_MAX: the loader
 * takes it), and the player standing there has the eye SIM_VIEW_HEIGHT
 * above it, past MAP_COORD_MAX: a state of the game, so its snapshot (what
 * the flight recorder keeps of every game) restores. */
static void the_eye_above_the_highest_floor_restores(void **state)
{
	static const struct fix_sector sec[] = { { 16383, 16383, 160 } };
	static const int w[] = { 256 };
	static const struct sim_settings play = { 1, 0, 1, 3, 1, 100, 1, 0, 0, 0 };
	struct map *m = fix_row(w, sec, 1, 128, 64, 64, 0, NULL, 0);
	struct sim *a = malloc(sizeof(*a));
	uint64_t h = 0;
	(void)state;
	assert_non_null(m);
	assert_non_null(a);
	assert_int_equal(map_finish(m, NULL, 0), 0);
	sim_init(a, m, &play);
	run(a, &(struct sim_cmd){ .forward = 50 }, 10);
	assert_int_equal(a->pl.viewz, MAP_HEIGHT_MAX + SIM_VIEW_HEIGHT);
	assert_int_equal(gf_restores(a, m, &set, &h), 0);
	assert_int_equal(h, sim_hash(a));
	free(a);
	map_free(m);
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
		cmocka_unit_test(the_fields_are_listed_in_memory_and_snapshot_order),
		cmocka_unit_test(every_field_is_hashed_unless_spare_and_saved_in_place),
		cmocka_unit_test(every_listed_limit_is_enforced),
		cmocka_unit_test(the_snapshot_is_little_endian_fields_in_order),
		cmocka_unit_test(a_restored_sim_is_byte_identical),
		cmocka_unit_test(a_restored_sim_follows_the_original_for_5000_ticks),
		cmocka_unit_test(every_state_of_a_long_session_restores),
		cmocka_unit_test(out_of_range_values_are_refused),
		cmocka_unit_test(the_eye_above_the_highest_floor_restores),
		cmocka_unit_test(damaged_snapshots_and_other_maps_are_refused),
		cmocka_unit_test(spare_slots_are_saved_but_not_hashed),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
