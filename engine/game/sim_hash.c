/*
 * sim_hash: the state of struct sim, field by field, for uses that must
 * never disagree: the per-tick hash (sim_hash), the snapshot (sim_snapshot)
 * and its restore (sim_restore), the snapshot's size, and the list of
 * fields the tests and tools read (sim_visit).
 *
 * One walk visits every field of struct sim and its nested structs in
 * declaration order, each as an explicit little-endian integer (never
 * struct bytes, which carry padding), with an op: hash it, count it, write
 * it, read it back, or report it. The walk of each struct is generated from
 * the struct's field list (engine/game/sim_table.h: SW_STRUCT below), the
 * same list that declares its members: a field is hashed, saved, restored,
 * checked and listed by construction. A member declared outside the list
 * stops the build (SW_CHECK).
 *
 * The hash (unchanged since before snapshots existed, so recorded state
 * hashes stay valid): FNV-1a of the stages' sim_stages_hash, the current
 * map's content hash, then every field. Slots of an array past its count
 * (enemies, pickups) are not state (spawning overwrites them) and are not
 * hashed; the snapshot still carries them, so a restore gives back the very
 * bytes.
 *
 * The snapshot: the same fields in the same order and sizes, except that
 * the current map is one byte (its index in the stages) instead of its
 * 8-byte content hash. Its size is fixed (every slot is written).
 * sim_restore reads into a copy, checks every value against its limit in
 * the list, and only then replaces the caller's state.
 */
#include "engine/game/sim.h"

#include <assert.h>
#include <errno.h>
#include <string.h>

#include "engine/core/hash.h"
#include "engine/core/le.h"
#include "engine/map/map.h"

enum sim_op { SIM_OP_HASH, SIM_OP_SIZE, SIM_OP_WRITE, SIM_OP_READ, SIM_OP_VISIT };

struct sim_walk {
	enum sim_op op;
	uint64_t h;                    /* HASH: the hash so far */
	size_t n;                      /* SIZE, WRITE, READ, VISIT: snapshot bytes so far */
	uint8_t *out;                  /* WRITE */
	const uint8_t *in;             /* READ: sim_snapshot_size() bytes */
	int spare;                     /* the fields are a spare slot: not hashed, not checked */
	int bad;                       /* READ: a value out of range */
	const char *base;              /* VISIT: the struct sim walked */
	const char *owner;             /* VISIT: the struct being walked */
	sim_visit_fn *fn;              /* VISIT */
	void *ctx;
};

/* Visits an unsigned value of `bytes` bytes (little-endian): hashes,
 * counts or writes v, or reads one and returns it (else returns v). */
static uint64_t sw_num(struct sim_walk *w, uint64_t v, int bytes)
{
	uint8_t b[8];

	switch (w->op) {
	case SIM_OP_HASH:
		if (w->spare)
			return v;
		le_putn(b, v, bytes);
		w->h = hash_bytes(w->h, b, (size_t)bytes);
		return v;
	case SIM_OP_SIZE:
	case SIM_OP_VISIT:
		break;
	case SIM_OP_WRITE:
		le_putn(w->out + w->n, v, bytes);
		break;
	case SIM_OP_READ:
	default:
		v = le_getn(w->in + w->n, bytes);
		break;
	}
	w->n += (size_t)bytes;
	return v;
}

/* The signed value of `bytes` (1..4) bytes of two's complement, by
 * arithmetic (no implementation-defined conversion). */
static int64_t sw_sext(uint64_t u, int bytes)
{
	uint64_t top = (uint64_t)1 << (8 * bytes - 1);

	return u < top ? (int64_t)u : (int64_t)u - (int64_t)(top * 2);
}

/* Whether u (`bytes` bytes; signed: two's complement) is in lo..hi; for an
 * unsigned field hi INT64_MAX means no upper limit (64-bit fields). */
static int sw_in(uint64_t u, int bytes, int sgn, int64_t lo, int64_t hi)
{
	if (sgn) {
		int64_t v = sw_sext(u, bytes);

		return v >= lo && v <= hi;
	}
	if (hi < 0 || (lo > 0 && u < (uint64_t)lo))
		return 0;
	return hi == INT64_MAX || u <= (uint64_t)hi;
}

/* One integer field: `size` bytes in memory at addr, `bytes` in the hash
 * and the snapshot, its value u (two's complement when sgn). Hashes,
 * counts or writes it, or reads one (returned, else u is) and marks the
 * walk bad when it is outside lo..hi (not in a spare slot), or reports it. */
static uint64_t sw_int(struct sim_walk *w, const void *addr, size_t size, uint64_t u, int bytes,
		       int sgn, const char *name, int index, int64_t lo, int64_t hi)
{
	uint64_t top = (uint64_t)1 << (8 * bytes - 1);
	size_t at = w->n;

	u = sw_num(w, u & (top * 2 - 1), bytes);
	if (w->op == SIM_OP_READ && !w->spare && !sw_in(u, bytes, sgn, lo, hi))
		w->bad = 1;
	if (w->op == SIM_OP_VISIT) {
		struct sim_vfield f = {
			.tag = w->owner, .name = name, .index = index,
			.off = (size_t)((const char *)addr - w->base), .size = size, .at = at,
			.bytes = (uint8_t)bytes, .sgn = (uint8_t)sgn, .spare = (uint8_t)w->spare,
			.lo = lo, .hi = hi,
		};
		w->fn(w->ctx, &f);
	}
	return u;
}

/* The walk of each integer type a list may name (sw_<type>), storing the
 * value read back. */
#define SW_UNSIGNED(type, bytes)                                                                 \
	static void sw_##type(struct sim_walk *w, type *p, const char *name, int index, int64_t lo, \
			      int64_t hi)                                                        \
	{                                                                                        \
		uint64_t u = sw_int(w, p, sizeof(*p), *p, bytes, 0, name, index, lo, hi);        \
		if (w->op == SIM_OP_READ)                                                        \
			*p = (type)u;                                                            \
	}
#define SW_SIGNED(type, bytes)                                                                   \
	static void sw_##type(struct sim_walk *w, type *p, const char *name, int index, int64_t lo, \
			      int64_t hi)                                                        \
	{                                                                                        \
		uint64_t u = sw_int(w, p, sizeof(*p), (uint64_t)*p, bytes, 1, name, index, lo, hi); \
		if (w->op == SIM_OP_READ)                                                        \
			*p = (type)sw_sext(u, bytes);                                            \
	}
SW_UNSIGNED(uint8_t, 1)
SW_UNSIGNED(uint16_t, 2)
SW_UNSIGNED(uint32_t, 4)
SW_UNSIGNED(uint64_t, 8)
SW_SIGNED(int8_t, 1)
SW_SIGNED(int16_t, 2)
SW_SIGNED(int32_t, 4)
#define sw_fx_t sw_int32_t
#define sw_ang_t sw_uint32_t

/* A char (initials) travels as its byte: stored through unsigned char, so
 * a signed char needs no conversion. */
static void sw_char(struct sim_walk *w, char *p, const char *name, int index, int64_t lo,
		    int64_t hi)
{
	unsigned char *b = (unsigned char *)p;
	uint64_t u = sw_int(w, p, 1, *b, 1, 0, name, index, lo, hi);

	if (w->op == SIM_OP_READ)
		*b = (unsigned char)u;
}

/* An enum travels as 4 bytes; a restore takes a value out of range as 0
 * (and refuses the snapshot anyway, by the limit). */
static uint32_t sw_enum(struct sim_walk *w, const void *addr, size_t size, uint32_t v,
			const char *name, uint32_t count)
{
	return (uint32_t)sw_int(w, addr, size, v, 4, 0, name, 0, 0, (int64_t)count - 1);
}

/* SIM_SECTOR's limit: a sector index of the current map. */
static int64_t sw_sector_max(const struct sim *s)
{
	return s->map ? (int64_t)s->map->num_sectors - 1 : 0;
}

/* The stage maps (borrowed, not saved): the hash and the snapshot hold
 * their sim_stages_hash; a restore must be on the same maps. */
static void sw_stages(struct sim_walk *w, struct sim *s)
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
	case SIM_OP_VISIT:
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

/* ---- the walks generated from the lists ------------------------------
 *
 * SW_FIELD turns one list entry into its walk, in a function where w is
 * the walk, s the whole sim and p the struct walked. An array's spare
 * slots are spare together with everything inside them; a slot of a spare
 * slot stays spare. The walk functions are called by their name in
 * parentheses, so a type without one (a struct without a list, a type the
 * walk does not know) is an undeclared name, an error with every
 * compiler's flags, never an implicit declaration.
 */
#define SW_FIELD(kind, ...) SW_##kind(__VA_ARGS__)
#define SW_VAL(type, name, limit) (sw_##type)(w, &p->name, #name, 0, SIM_LO limit, SIM_HI limit);
#define SW_ARR(type, name, n, used, limit)                                                      \
	{                                                                                       \
		int up_ = w->spare;                                                             \
		for (int i_ = 0; i_ < (n); i_++) {                                              \
			w->spare = up_ || i_ >= (int64_t)(used);                                       \
			if (w->spare && w->op == SIM_OP_HASH)                                   \
				break;         /* the rest is spare: nothing to hash */         \
			(sw_##type)(w, &p->name[i_], #name, i_, SIM_LO limit, SIM_HI limit);    \
		}                                                                               \
		w->spare = up_;                                                                 \
	}
#define SW_ENUM(type, name, count)                                                              \
	{                                                                                       \
		uint32_t e_ = sw_enum(w, &p->name, sizeof(p->name), (uint32_t)p->name, #name,  \
				      (uint32_t)(count));                                       \
		if (w->op == SIM_OP_READ)                                                       \
			p->name = e_ < (uint32_t)(count) ? (type)e_ : (type)0;                  \
	}
#define SW_SUB(tag, name) (sw_struct_##tag)(w, s, &p->name);
#define SW_SUBS(tag, name, n, used)                                                             \
	{                                                                                       \
		int up_ = w->spare;                                                             \
		for (int i_ = 0; i_ < (n); i_++) {                                              \
			w->spare = up_ || i_ >= (int64_t)(used);                                       \
			if (w->spare && w->op == SIM_OP_HASH)                                   \
				break;         /* the rest is spare: nothing to hash */         \
			(sw_struct_##tag)(w, s, &p->name[i_]);                                  \
		}                                                                               \
		w->spare = up_;                                                                 \
	}
#define SW_FN(type, name, fn) fn(w, s);
#define SW_FNS(type, name, n, fn) fn(w, s);

/* The missing-field check: a compound literal of the struct initialised
 * from its list alone, one initialiser a field, in order. A member the
 * list does not declare (written into the struct by hand) is left without
 * an initialiser, which -Wmissing-field-initializers reports; it is made an
 * error here whatever the build's flags. ({0} for an aggregate is the
 * universal zero initialiser, which the warning accepts; its inner braces
 * are left out, which -Wmissing-braces would report.) */
#define SW_ZERO(kind, ...) SW_ZERO_##kind
#define SW_ZERO_VAL 0,
#define SW_ZERO_ARR {0},
#define SW_ZERO_ENUM 0,
#define SW_ZERO_SUB {0},
#define SW_ZERO_SUBS {0},
#define SW_ZERO_FN 0,
#define SW_ZERO_FNS {0},
#define SW_CHECK(tag, LIST)                                                                     \
	_Pragma("GCC diagnostic push")                                                          \
	_Pragma("GCC diagnostic error \"-Wmissing-field-initializers\"")                        \
	_Pragma("GCC diagnostic ignored \"-Wmissing-braces\"")                                  \
	_Static_assert(sizeof((struct tag){ LIST(SW_ZERO) }) == sizeof(struct tag),             \
		       "struct " #tag ": every member comes from " #LIST);                      \
	_Pragma("GCC diagnostic pop")

/* The walk of struct tag, from its list (and the check that the list is
 * all of it). A struct named in a SUB or SUBS entry needs its line here,
 * before the struct that holds it. */
#define SW_STRUCT(tag, LIST)                                                                    \
	SW_CHECK(tag, LIST)                                                                     \
	static void sw_struct_##tag(struct sim_walk *w, struct sim *s, struct tag *p)           \
	{                                                                                       \
		const char *up = w->owner;                                                      \
		(void)s;                                                                        \
		w->owner = #tag;                                                                \
		LIST(SW_FIELD)                                                                  \
		w->owner = up;                                                                  \
	}

SW_STRUCT(sim_settings, SIM_SETTINGS_FIELDS)
SW_STRUCT(sim_cmd, SIM_CMD_FIELDS)
SW_STRUCT(sim_player, SIM_PLAYER_FIELDS)
SW_STRUCT(g_enemy, G_ENEMY_FIELDS)
SW_STRUCT(g_pickup, G_PICKUP_FIELDS)
SW_STRUCT(g_missile, G_MISSILE_FIELDS)
SW_STRUCT(g_game, G_GAME_FIELDS)
SW_STRUCT(g_seat, G_SEAT_FIELDS)
SW_STRUCT(g_sector, G_SECTOR_FIELDS)
SW_STRUCT(g_mover, G_MOVER_FIELDS)
SW_STRUCT(g_button, G_BUTTON_FIELDS)
SW_STRUCT(g_world, G_WORLD_FIELDS)
SW_STRUCT(g_entry, G_ENTRY_FIELDS)
SW_STRUCT(g_scores, G_SCORES_FIELDS)
SW_STRUCT(g_books, G_BOOKS_FIELDS)
SW_STRUCT(g_schan, G_SCHAN_FIELDS)
SW_STRUCT(g_sound, G_SOUND_FIELDS)
SW_STRUCT(menu, MENU_FIELDS)
SW_STRUCT(sim, SIM_FIELDS)

/* Every field of s, in declaration order. Only READ writes to s (a copy
 * owned by sim_restore); the other ops only read, so the const casts of
 * sim_hash, sim_snapshot and sim_visit are sound. A limit that names an
 * earlier field (alive <= num_enemies, the letter position in INITIALS)
 * sees the value already read. */
static void sim_walk(struct sim_walk *w, struct sim *s)
{
	w->base = (const char *)s;
	sw_struct_sim(w, s, s);
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

void sim_visit(const struct sim *s, sim_visit_fn *fn, void *ctx)
{
	struct sim_walk w = { .op = SIM_OP_VISIT, .fn = fn, .ctx = ctx };

	sim_walk(&w, (struct sim *)s);
}
