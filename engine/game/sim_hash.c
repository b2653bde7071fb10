/*
 * sim_hash: the state of struct sim, field by field, for three uses that
 * must never disagree: the per-tick hash (sim_hash), the snapshot
 * (sim_snapshot) and its restore (sim_restore).
 *
 * One walk (sim_walk) visits every field of struct sim and its nested
 * structs in declaration order, each as an explicit little-endian integer
 * (never struct bytes, which carry padding), with an op: hash it, count
 * it, write it or read it back. A field added to the walk is hashed, saved
 * and restored by construction; a field missing from it is none of them,
 * which the tests catch (test_sim_hash.c: a restored sim is byte-identical
 * to the original).
 *
 * The hash (unchanged since before snapshots existed, so recorded state
 * hashes stay valid): FNV-1a of the stages' sim_stages_hash, the current
 * map's content hash, then every field. Enemy and pickup slots past the
 * counts are not state (spawning overwrites them) and are not hashed; the
 * snapshot still carries them, so a restore gives back the very bytes.
 *
 * The snapshot: the same fields in the same order and sizes, except that
 * the current map is one byte (its index in the stages) instead of its
 * 8-byte content hash. Its size is fixed (every slot is written).
 * sim_restore reads into a copy, checks every value the rules index or
 * enumerate by (the walk's limits, each next to its field), and only then
 * replaces the caller's state.
 */
#include "engine/game/sim.h"

#include <assert.h>
#include <errno.h>
#include <string.h>

#include "engine/core/hash.h"
#include "engine/map/map.h"

enum sim_op { SIM_OP_HASH, SIM_OP_SIZE, SIM_OP_WRITE, SIM_OP_READ };

struct sim_walk {
	enum sim_op op;
	uint64_t h;                    /* HASH: the hash so far */
	size_t n;                      /* SIZE, WRITE, READ: bytes so far */
	uint8_t *out;                  /* WRITE */
	const uint8_t *in;             /* READ: sim_snapshot_size() bytes */
	int spare;                     /* the fields are a spare slot: not hashed, not checked */
	int bad;                       /* READ: a value out of range */
};

/* No limit on a field's value. */
#define SW_ANY UINT64_MAX

/* Visits an unsigned value of `bytes` bytes (little-endian): hashes,
 * counts or writes v, or reads one and returns it (else returns v). */
static uint64_t sw_num(struct sim_walk *w, uint64_t v, int bytes)
{
	uint8_t b[8];

	switch (w->op) {
	case SIM_OP_HASH:
		if (w->spare)
			return v;
		for (int i = 0; i < bytes; i++)
			b[i] = (uint8_t)(v >> (8 * i));
		w->h = hash_bytes(w->h, b, (size_t)bytes);
		return v;
	case SIM_OP_SIZE:
		break;
	case SIM_OP_WRITE:
		for (int i = 0; i < bytes; i++)
			w->out[w->n + (size_t)i] = (uint8_t)(v >> (8 * i));
		break;
	case SIM_OP_READ:
	default:
		v = 0;
		for (int i = 0; i < bytes; i++)
			v |= (uint64_t)w->in[w->n + (size_t)i] << (8 * i);
		break;
	}
	w->n += (size_t)bytes;
	return v;
}

/* An unsigned field: READ stores the value read, and marks the walk bad
 * when it is above max (not in a spare slot). */
static uint64_t sw_read_max(struct sim_walk *w, uint64_t v, int bytes, uint64_t max)
{
	v = sw_num(w, v, bytes);
	if (w->op == SIM_OP_READ && !w->spare && v > max)
		w->bad = 1;
	return v;
}

static void sw_u8(struct sim_walk *w, uint8_t *p, uint64_t max)
{
	uint64_t v = sw_read_max(w, *p, 1, max);

	if (w->op == SIM_OP_READ)
		*p = (uint8_t)v;
}

static void sw_u16(struct sim_walk *w, uint16_t *p, uint64_t max)
{
	uint64_t v = sw_read_max(w, *p, 2, max);

	if (w->op == SIM_OP_READ)
		*p = (uint16_t)v;
}

static void sw_u32(struct sim_walk *w, uint32_t *p, uint64_t max)
{
	uint64_t v = sw_read_max(w, *p, 4, max);

	if (w->op == SIM_OP_READ)
		*p = (uint32_t)v;
}

static void sw_u64(struct sim_walk *w, uint64_t *p)
{
	uint64_t v = sw_num(w, *p, 8);

	if (w->op == SIM_OP_READ)
		*p = v;
}

/* Signed fields travel as their two's complement bytes; reading converts
 * back by arithmetic (no implementation-defined conversion). READ marks
 * the walk bad outside lo..hi. */
static int64_t sw_signed(struct sim_walk *w, int64_t v, int bytes, int64_t lo, int64_t hi)
{
	uint64_t top = (uint64_t)1 << (8 * bytes - 1);
	uint64_t u = sw_num(w, (uint64_t)v & (top * 2 - 1), bytes);

	if (w->op != SIM_OP_READ)
		return v;
	v = u < top ? (int64_t)u : (int64_t)u - (int64_t)(top * 2);
	if (!w->spare && (v < lo || v > hi))
		w->bad = 1;
	return v;
}

static void sw_i8(struct sim_walk *w, int8_t *p, int lo, int hi)
{
	int64_t v = sw_signed(w, *p, 1, lo, hi);

	if (w->op == SIM_OP_READ)
		*p = (int8_t)v;
}

static void sw_i16(struct sim_walk *w, int16_t *p)
{
	int64_t v = sw_signed(w, *p, 2, INT16_MIN, INT16_MAX);

	if (w->op == SIM_OP_READ)
		*p = (int16_t)v;
}

static void sw_i32(struct sim_walk *w, int32_t *p, int32_t lo, int32_t hi)
{
	int64_t v = sw_signed(w, *p, 4, lo, hi);

	if (w->op == SIM_OP_READ)
		*p = (int32_t)v;
}

/* A position or height: within the map's coordinate range, so the rules'
 * arithmetic on it cannot overflow. */
static void sw_coord(struct sim_walk *w, fx_t *p)
{
	sw_i32(w, p, -MAP_COORD_MAX, MAP_COORD_MAX);
}

/* A sector index of the current map. */
static void sw_sector(struct sim_walk *w, const struct sim *s, uint32_t *p)
{
	sw_u32(w, p, s->map ? (uint64_t)s->map->num_sectors - 1 : 0);
}

static void sw_bytes(struct sim_walk *w, uint8_t *p, int n, uint64_t max)
{
	for (int i = 0; i < n; i++)
		sw_u8(w, &p[i], max);
}

/* The stage maps (borrowed, not saved): the hash and the snapshot hold
 * their sim_stages_hash; a restore must be on the same maps. */
static void sw_stages(struct sim_walk *w, const struct sim *s)
{
	uint64_t h = sim_stages_hash(s->stages, s->num_stages);

	if (sw_num(w, h, 8) != h)
		w->bad = 1;
}

/* The current map: its content hash in the hash, its index in the stages
 * in the snapshot. */
static void sw_map(struct sim_walk *w, struct sim *s)
{
	uint8_t i = 0;

	switch (w->op) {
	case SIM_OP_HASH:
		w->h = hash_u64(w->h, s->map ? s->map->content_hash : 0);
		return;
	case SIM_OP_WRITE:
		while (i < s->num_stages && s->stages[i] != s->map)
			i++;
		/* sim_init_stages and every stage change set map to a stage */
		assert(i < s->num_stages);
		break;
	case SIM_OP_SIZE:
	case SIM_OP_READ:
	default:
		break;
	}
	i = (uint8_t)sw_num(w, i, 1);
	if (w->op != SIM_OP_READ)
		return;
	if (i < s->num_stages)
		s->map = s->stages[i];
	else
		w->bad = 1;
}

/* num_stages comes from the caller's sim_init_stages: READ only checks it. */
static void sw_num_stages(struct sim_walk *w, const struct sim *s)
{
	if (sw_num(w, s->num_stages, 1) != s->num_stages)
		w->bad = 1;
}

static void sw_settings(struct sim_walk *w, struct sim_settings *t)
{
	sw_u8(w, &t->coins_per_credit, SW_ANY);
	sw_u8(w, &t->freeplay, SW_ANY);
	sw_u8(w, &t->start_in_play, SW_ANY);
	sw_u8(w, &t->difficulty, SW_ANY);
	sw_u8(w, &t->lives, SW_ANY);
}

static void sw_cmd(struct sim_walk *w, struct sim_cmd *c)
{
	sw_i8(w, &c->forward, INT8_MIN, INT8_MAX);
	sw_i8(w, &c->side, INT8_MIN, INT8_MAX);
	sw_i16(w, &c->turn);
	sw_u8(w, &c->buttons, SW_ANY);
	sw_u8(w, &c->coins, SW_ANY);
}

static void sw_player(struct sim_walk *w, const struct sim *s, struct sim_player *p)
{
	sw_coord(w, &p->x);
	sw_coord(w, &p->y);
	sw_coord(w, &p->z);
	sw_coord(w, &p->viewz);
	sw_i32(w, &p->momx, INT32_MIN, INT32_MAX);
	sw_i32(w, &p->momy, INT32_MIN, INT32_MAX);
	sw_u32(w, &p->angle, SW_ANY);
	sw_sector(w, s, &p->sector);
	sw_i32(w, &p->health, 0, G_HEALTH_MAX * FX_ONE);
	sw_u16(w, &p->ammo, SW_ANY);
	sw_u16(w, &p->refire, SW_ANY);
	sw_u16(w, &p->hurt, SW_ANY);
	sw_u16(w, &p->bonus, SW_ANY);
}

static void sw_enemy(struct sim_walk *w, const struct sim *s, struct g_enemy *e)
{
	sw_coord(w, &e->x);
	sw_coord(w, &e->y);
	sw_coord(w, &e->z);
	sw_u32(w, &e->angle, SW_ANY);
	sw_sector(w, s, &e->sector);
	sw_coord(w, &e->sx);
	sw_coord(w, &e->sy);
	sw_u32(w, &e->sangle, SW_ANY);
	sw_u16(w, &e->type, SW_ANY);
	sw_u8(w, &e->kind, G_KINDS - 1);
	sw_u8(w, &e->state, G_E_DEAD);
	sw_i16(w, &e->health);
	sw_u16(w, &e->timer, SW_ANY);
	sw_u16(w, &e->anim, SW_ANY);
	sw_u32(w, &e->wander, SW_ANY);
	sw_u8(w, &e->stuck, SW_ANY);
	sw_u8(w, &e->flash, SW_ANY);
}

static void sw_pickup(struct sim_walk *w, struct g_pickup *p)
{
	sw_coord(w, &p->x);
	sw_coord(w, &p->y);
	sw_coord(w, &p->z);
	sw_u16(w, &p->type, SW_ANY);
	sw_u8(w, &p->kind, G_P_AMMO);
	sw_u8(w, &p->taken, 1);
	sw_u16(w, &p->amount, SW_ANY);
}

static void sw_game(struct sim_walk *w, const struct sim *s, struct g_game *g)
{
	sw_u32(w, &g->score, SW_ANY);
	sw_u8(w, &g->lives, SW_ANY);
	sw_u8(w, &g->continues, SW_ANY);
	sw_u8(w, &g->stage, (uint64_t)s->num_stages - 1);
	sw_u8(w, &g->loop, SW_ANY);
	sw_u8(w, &g->phase, G_PH_CLEAR);
	sw_u16(w, &g->phase_t, SW_ANY);
	sw_u32(w, &g->stage_t, SW_ANY);
	sw_u32(w, &g->kills, SW_ANY);
	sw_u16(w, &g->num_enemies, G_MAX_ENEMIES);
	sw_u16(w, &g->num_pickups, G_MAX_PICKUPS);
	sw_u16(w, &g->alive, g->num_enemies);
	for (int i = 0; i < G_MAX_ENEMIES; i++) {
		w->spare = i >= g->num_enemies;
		sw_enemy(w, s, &g->en[i]);
	}
	for (int i = 0; i < G_MAX_PICKUPS; i++) {
		w->spare = i >= g->num_pickups;
		sw_pickup(w, &g->pk[i]);
	}
	w->spare = 0;
	sw_coord(w, &g->shot_x);
	sw_coord(w, &g->shot_y);
	sw_coord(w, &g->shot_z);
	sw_u8(w, &g->shot, G_SHOT_MISS);
	sw_u16(w, &g->shot_t, SW_ANY);
}

static void sw_scores(struct sim_walk *w, struct g_scores *t)
{
	for (int i = 0; i < G_SCORES; i++) {
		sw_bytes(w, (uint8_t *)t->e[i].name, G_NAME_LEN, SW_ANY);
		sw_u32(w, &t->e[i].score, SW_ANY);
		sw_u8(w, &t->e[i].stage, SW_ANY);
	}
}

static void sw_books(struct sim_walk *w, struct g_books *b)
{
	sw_u32(w, &b->coins, SW_ANY);
	sw_u32(w, &b->plays, SW_ANY);
	sw_u64(w, &b->play_ticks);
	sw_u64(w, &b->on_ticks);
}

static void sw_menu(struct sim_walk *w, struct menu *m)
{
	/* the cursor is an item of MAIN or of SETTINGS */
	int items = MENU_ITEMS, settings = MENU_SETTINGS_COUNT;
	int cursors = items > settings ? items : settings;

	sw_u8(w, &m->page, MENU_PAGES - 1);
	sw_u8(w, &m->cursor, (uint64_t)cursors - 1);
	sw_u8(w, &m->main_cursor, MENU_ITEMS - 1);
	sw_u8(w, &m->display, MENU_D_COUNT - 1);
	sw_u8(w, &m->confirm, MENU_ITEMS - 1);
	sw_u8(w, &m->yes, 1);
	sw_u8(w, &m->res, MENU_RES_COUNT);
	sw_u8(w, &m->done, MENU_ITEMS - 1);
	sw_u16(w, &m->done_t, SW_ANY);
	sw_u32(w, &m->coins_seen, SW_ANY);
	sw_u32(w, &m->t, SW_ANY);
}

/* Every field of s, in declaration order. Only READ writes to s (a copy
 * owned by sim_restore); the other ops only read, so the const casts of
 * sim_hash and sim_snapshot are sound. A limit that names an earlier field
 * (alive <= num_enemies, the letter position in INITIALS) sees the value
 * already read. */
static void sim_walk(struct sim_walk *w, struct sim *s)
{
	uint32_t mode = (uint32_t)s->mode;
	int initials;

	sw_stages(w, s);
	sw_map(w, s);
	sw_num_stages(w, s);
	sw_settings(w, &s->set);
	sw_u32(w, &s->tick, SW_ANY);
	sw_u32(w, &mode, SIM_MODE_COUNT - 1);
	if (w->op == SIM_OP_READ)
		s->mode = mode < SIM_MODE_COUNT ? (enum sim_mode)mode : SIM_ATTRACT;
	initials = s->mode == SIM_INITIALS;
	sw_u8(w, &s->page, SIM_PAGE_COUNT - 1);
	sw_u32(w, &s->mode_t, SW_ANY);
	sw_u32(w, &s->credits, SW_ANY);
	sw_u32(w, &s->coin_rem, SW_ANY);
	sw_u32(w, &s->coins_total, SW_ANY);
	sw_u32(w, &s->plays, SW_ANY);
	sw_u8(w, &s->prev_buttons, SW_ANY);
	sw_u8(w, &s->prev_nav, SW_ANY);
	sw_u16(w, &s->nav_t, SW_ANY);
	sw_cmd(w, &s->cmd);
	sw_u32(w, &s->rng, SW_ANY);
	sw_player(w, s, &s->pl);
	sw_game(w, s, &s->g);
	sw_u16(w, &s->countdown, SW_ANY);
	/* a letter is being chosen in INITIALS; after the third, ini_pos stays 3 */
	sw_u8(w, &s->ini_pos, initials ? G_NAME_LEN - 1 : G_NAME_LEN);
	sw_bytes(w, s->ini, G_NAME_LEN, G_ALPHABET_LEN - 1);
	sw_i8(w, &s->ini_rank, initials ? 0 : -1, G_SCORES - 1);
	sw_i8(w, &s->new_rank, -1, G_SCORES - 1);
	sw_scores(w, &s->scores);
	sw_books(w, &s->books);
	sw_u32(w, &s->set_gen, SW_ANY);
	sw_u32(w, &s->scores_gen, SW_ANY);
	sw_u32(w, &s->books_gen, SW_ANY);
	sw_menu(w, &s->menu);
}

uint64_t sim_hash(const struct sim *s)
{
	struct sim_walk w = { .op = SIM_OP_HASH, .h = HASH_INIT };

	sim_walk(&w, (struct sim *)s);
	return w.h;
}

size_t sim_snapshot_size(void)
{
	struct sim_walk w = { .op = SIM_OP_SIZE };
	struct sim z;

	memset(&z, 0, sizeof(z));
	sim_walk(&w, &z);
	return w.n;
}

void sim_snapshot(const struct sim *s, uint8_t *out)
{
	struct sim_walk w = { .op = SIM_OP_WRITE, .out = out };

	sim_walk(&w, (struct sim *)s);
}

int sim_restore(struct sim *s, const uint8_t *buf, size_t len)
{
	struct sim_walk w = { .op = SIM_OP_READ, .in = buf };
	struct sim t;

	if (len != sim_snapshot_size())
		return -EINVAL;
	t = *s;
	sim_walk(&w, &t);
	if (w.bad)
		return -EINVAL;
	*s = t;
	return 0;
}
