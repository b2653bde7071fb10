/* libFuzzer target: Doom's line and sector specials played on hostile maps
 * (engine/game/g_*.c), and the renderer drawing what they did to the map
 * (engine/render/r_game.c and the renderer over live heights).
 *
 * A level editor can put any special on any line, any tag on any sector and
 * any height the loader accepts; the map then loads, and what the specials
 * do with it happens only in play. Random bytes almost never make a map
 * that loads, so the input edits a real one: a built-in level's lumps in
 * the compiled-in PWAD (engine/map/lvl_wad.c).
 *
 * Input: a byte choosing the level; a count byte (mod 32), then that many
 * 6-byte edits (lump: THINGS, LINEDEFS or SECTORS; 2-byte entry; field;
 * 16-bit value) to the level's line flags, specials and tags, sector
 * heights, light, specials and tags, and thing positions, angles, types
 * and flags; the map must then load
 * (else the input is the loader's, which fuzz_wad covers). The rest are
 * 4-byte actions, at most FZ_ACTIONS: a tick with a command (moves, USE,
 * FIRE), a line crossed by the player or an enemy (walk triggers,
 * teleports), a line shot, the player standing in front of a line and
 * pressing USE (placed as a teleport places it: a hostile map's teleport
 * destination can be anywhere in the coordinate range), or FZ_WAIT ticks with no input so the
 * movers run their course.
 *
 * Oracles, under ASan and UBSan: every FZ_DRAW_EVERY ticks and at the end
 * the live map is drawn (a small frame); at the end the state must survive
 * its own snapshot: sim_restore, whose range checks are the state's
 * invariants, takes it back, and it snapshots again to the same bytes.
 * (The state is not hashed every tick: that walk of the whole state, which
 * the snapshot repeats at the end, took most of the time.) */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_wad.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"
#include "engine/render/r_game.h"
#include "engine/render/r_main.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

#define FZ_ACTIONS 96                   /* actions taken at most */
#define FZ_WAIT 70                      /* ticks of an idle action */
#define FZ_DRAW_EVERY 64                /* ticks between two frames drawn */
#define FZ_W 80
#define FZ_H 50

static struct tex_set *tex;             /* the built-in set the levels name */
static uint8_t *wadbuf;                 /* a copy of the built-in PWAD, edited */
static struct r_ctx *rc;
static uint8_t px[FZ_W * FZ_H];
static uint8_t *snap, *back;
static size_t snap_len;

static void fz_setup(void)
{
	if (tex_builtin(&tex) != 0 || r_new(FZ_W, FZ_H, &rc) != 0)
		abort();
	snap_len = sim_snapshot_size();
	wadbuf = malloc(lvl_wad_len);
	snap = malloc(snap_len);
	back = malloc(snap_len);
	if (!wadbuf || !snap || !back)
		abort();
}

static uint16_t fz_u16(const uint8_t *p)
{
	return (uint16_t)(p[0] | p[1] << 8);
}

/* One edit to the map's lumps in wadbuf: r[0] the lump, r[1..2] the entry,
 * r[3] the field, r[4..5] the value. Offsets are Doom's record layouts. */
static void fz_edit(const struct wad *w, int marker, const uint8_t *r)
{
	static const char *const lumps[3] = { "THINGS", "LINEDEFS", "SECTORS" };
	static const int size[3] = { 10, 14, 26 };
	/* the 16-bit fields an editor sets: things x, y, angle, type, flags;
	 * lines flags, special, tag; sectors floor, ceiling, light, special, tag */
	static const int fields[3][5] = {
		{ 0, 2, 4, 6, 8 }, { 4, 6, 8, 4, 6 }, { 0, 2, 20, 22, 24 },
	};
	int k = r[0] % 3, i = wad_find_from(w, lumps[k], marker);
	const uint8_t *p;
	size_t n, at;

	if (i < 0)
		return;
	p = wad_data(w, i, &n);
	if (n < (size_t)size[k])
		return;
	at = (size_t)(p - wadbuf) + (fz_u16(r + 1) % (n / (size_t)size[k])) * (size_t)size[k] +
	     (size_t)fields[k][r[3] % 5];
	wadbuf[at] = r[4];
	wadbuf[at + 1] = r[5];
}

/* A point d map units from line l's middle, in front (d > 0) or behind. */
static void fz_beside(const struct map *m, const struct map_line *l, int d, fx_t *x, fx_t *y)
{
	const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
	int64_t dx = ((int64_t)b->x - a->x) >> FX_SHIFT, dy = ((int64_t)b->y - a->y) >> FX_SHIFT;
	int64_t len = (int64_t)fx_isqrt64((uint64_t)(dx * dx + dy * dy)) + 1;

	/* the front is on the right of v1 -> v2: the normal (dy, -dx) */
	*x = (fx_t)(((int64_t)a->x + b->x) / 2 + dy * d * FX_ONE / len);
	*y = (fx_t)(((int64_t)a->y + b->y) / 2 - dx * d * FX_ONE / len);
}

static void fz_draw(const struct sim *s, struct r_live *live)
{
	struct r_frame f = { px, FZ_W, FZ_H, FZ_W, NULL };
	struct r_view v;
	const struct map *m = r_game_live(live, s, tex);

	tex_animate(tex, s->tick);
	r_game_view(s, FZ_W, &v);
	r_render(rc, m, tex, &v, NULL, 0, &f);
}

static void fz_tick(struct sim *s, const struct sim_cmd *c, struct r_live *live)
{
	sim_tick(s, c);
	if (s->tick % FZ_DRAW_EVERY == 0)
		fz_draw(s, live);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	static const struct sim_settings set = { .coins_per_credit = 1, .start_in_play = 1,
						 .lives = 3, .volume = 100 };
	static struct sim s, t;
	char names[8][9], err[256];
	struct wad *w = NULL;
	struct map *m = NULL;
	struct r_live live = { 0 };
	size_t i = 0;
	int n, marker, edits;

	if (!tex)
		fz_setup();
	if (len < 2)
		return 0;
	memcpy(wadbuf, lvl_wad, lvl_wad_len);
	if (wad_new(&w) != 0)
		return 0;
	if (wad_add(w, wadbuf, lvl_wad_len, "lvl.wad", err, sizeof err) != 0)
		abort();                /* the built-in PWAD always adds */
	n = map_list_wad(w, names, 8);
	if (n <= 0)
		abort();
	marker = wad_find(w, names[data[i] % (n < 8 ? n : 8)]);
	i++;
	for (edits = data[i++] % 32; edits > 0 && i + 6 <= len; edits--, i += 6)
		fz_edit(w, marker, data + i);
	if (map_load_wad(w, tex, wad_name(w, marker), &m, err, sizeof err) != 0)
		goto out;
	sim_init(&s, m, &set);
	for (int a = 0; a < FZ_ACTIONS && i + 4 <= len; a++, i += 4) {
		const uint8_t *r = data + i;
		const struct map_line *l = &m->lines[fz_u16(r + 1) % m->num_lines];
		struct sim_cmd c = { 0 };
		fx_t x1, y1, x2, y2;

		switch (r[0] % 6) {
		case 0: /* a tick with a command */
		case 1:
			c.forward = (int8_t)r[1];
			c.side = (int8_t)(r[2] & 0xf0);
			c.turn = (int16_t)((r[2] & 0x0f) << 10) - 0x2000;
			c.buttons = r[3] & (SIM_BT_FIRE | SIM_BT_USE | SIM_BT_WEAPON);
			fz_tick(&s, &c, &live);
			break;
		case 2: { /* crossed, by the player or a living enemy */
			int who = G_WHO_PLAYER;

			if (r[3] & 1 && s.g.num_enemies > 0) {
				who = (r[3] >> 1) % s.g.num_enemies;
				if (s.g.en[who].state == G_E_DEAD)
					who = G_WHO_PLAYER;
			}
			fz_beside(m, l, r[3] & 0x80 ? 8 : -8, &x1, &y1);
			fz_beside(m, l, r[3] & 0x80 ? -8 : 8, &x2, &y2);
			g_cross(&s, who, x1, y1, x2, y2, SIM_PLAYER_RADIUS);
			fz_tick(&s, &c, &live);
			break;
		}
		case 3: /* shot from in front */
			fz_beside(m, l, 48, &x1, &y1);
			fz_beside(m, l, -48, &x2, &y2);
			g_shoot_lines(&s, x1, y1, x2, y2);
			fz_tick(&s, &c, &live);
			break;
		case 4: /* USE in front of it, placed as a teleport places */
			if (s.g.phase != G_PH_PLAY)
				break;
			fz_beside(m, l, 20, &x1, &y1);
			fz_beside(m, l, 0, &x2, &y2);
			if (!g_in_range(x1, y1, 0))
				break;  /* a teleport destination is a thing: in range */
			s.pl.x = x1;
			s.pl.y = y1;
			s.pl.angle = tab_atan2(y2 - s.pl.y, x2 - s.pl.x);
			s.pl.momx = s.pl.momy = 0;
			s.pl.sector = map_point_sector(m, s.pl.x, s.pl.y);
			s.pl.z = s.w.sec[s.pl.sector].floor_h;
			s.pl.viewz = s.pl.z + SIM_VIEW_HEIGHT;
			c.buttons = SIM_BT_USE;
			fz_tick(&s, &c, &live);
			break;
		default: /* the movers run */
			for (int k = 0; k < FZ_WAIT; k++)
				fz_tick(&s, &c, &live);
			break;
		}
	}
	fz_draw(&s, &live);
	/* the state's invariants are the restore's range checks */
	sim_snapshot(&s, snap);
	sim_init(&t, m, &set);
	if (sim_restore(&t, snap, snap_len) != 0)
		abort();
	sim_snapshot(&t, back);
	if (memcmp(snap, back, snap_len) != 0)
		abort();
out:
	r_live_free(&live);
	map_free(m);
	wad_free(w);
	return 0;
}
