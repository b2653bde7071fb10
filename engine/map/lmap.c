/*
 * lmap: shadowed point-light maps (lmap.h, docs/lights.md).
 *
 * Geometry runs in "sub units" of 1/16 map unit (16.16 >> 12): map
 * coordinates stay below 2^18 in magnitude, so differences fit 2^19,
 * cross products 2^39, and the crossing-height test of a two-sided line
 * (a height difference times a cross product) 2^60: every test is exact
 * int64 arithmetic.
 *
 * Visibility uses a blockmap of 128-unit cells listing the lines that can
 * block (one-sided lines and two-sided lines whose sectors differ in floor
 * or ceiling); a ray visits the cells of its bounding box that its line
 * passes through, and each line once (a per-line stamp).
 *
 * Bounded (lmap.h): at most LMAP_MAX_LIGHTS lights; every reach test,
 * blockmap cell filled or visited and line tested is a step of one count
 * (LMAP_MAX_STEPS), which also polls the caller's stop hook. A ray charges
 * its steps when it ends (one ray is at most the cells of its box times
 * the lines in them).
 */
#include "engine/map/lmap.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/hash.h"
#include "engine/core/lim.h"
#include "engine/core/msg.h"
#include "engine/core/pal.h"
#include "engine/map/map.h"
#include "engine/map/th.h"

#define LMAP_SUB(v) ((int64_t)(v) >> 12)        /* 16.16 to 1/16 units */
#define LMAP_CELL_SHIFT 11                      /* 128 units in sub units */
#define LMAP_SHIFT_MAX 12                       /* coarsest texel: 4096 units */

struct lmap {
	uint32_t num_sectors, num_lines;
	/* per surface, flats [2 * sector + ceiling] then walls [2 * sectors +
	 * 2 * line + side]: index into grids, or MAP_NONE */
	uint32_t *idx;
	struct lmap_grid *grids;
	uint32_t ngrids;
	uint8_t *pool;
	struct lmap_stats st;
};

/* Build state. */
struct lmap_b {
	const struct map *m;
	int64_t bx0, by0;                       /* blockmap origin, sub units */
	int32_t bw, bh;
	uint32_t *cstart;                       /* bw * bh + 1 offsets into clines */
	uint32_t *clines;
	uint32_t *stamp, cur;
	int64_t *lo, *hi;                       /* per line: opening, sub units;
						 * lo > hi for one-sided */
	uint64_t rays;
	uint64_t steps;                         /* taken by a ray, not yet charged */
	struct lim lim;                         /* LMAP_MAX_STEPS, the stop hook */
};

/* Doom's light-giving decorations (th.h TH_DECOR | TH_LIGHT): intensity,
 * radius and the flame's height above the floor, judged from their
 * sprites; others of that kind get LMAP_DECOR_DEFAULT. */
static const int32_t lmap_doom_decor[][4] = {
	/* type, intensity, radius, height */
	{ 34, 64, 128, 16 },                    /* candle */
	{ 35, 128, 192, 56 },                   /* candelabra */
	{ 44, 160, 256, 64 },                   /* tall blue firestick */
	{ 45, 160, 256, 64 },                   /* tall green firestick */
	{ 46, 160, 256, 64 },                   /* tall red firestick */
	{ 55, 128, 192, 40 },                   /* short blue firestick */
	{ 56, 128, 192, 40 },                   /* short green firestick */
	{ 57, 128, 192, 40 },                   /* short red firestick */
	{ 70, 128, 192, 32 },                   /* burning barrel */
	{ 85, 192, 320, 72 },                   /* tall techno lamp */
	{ 86, 160, 256, 52 },                   /* short techno lamp */
	{ 2028, 160, 256, 44 },                 /* floor lamp */
};
static const int32_t lmap_decor_default[3] = { 96, 160, 24 };

/* Intensity, radius and height of thing type `type` as a light, or 0. */
static int lmap_thing_light(uint16_t type, unsigned flags, int32_t *inten, int32_t *rad,
			    int32_t *above)
{
	const struct th_info *ti;
	struct th_light tl;

	if (th_light(type, &tl)) {
		*inten = tl.intensity;
		*rad = tl.radius;
		*above = -1;                    /* half way up */
		return 1;
	}
	ti = th_find(type);
	if (!(flags & LMAP_DECOR) || !ti || (ti->flags & (TH_DECOR | TH_LIGHT)) != (TH_DECOR | TH_LIGHT))
		return 0;
	*inten = lmap_decor_default[0];
	*rad = lmap_decor_default[1];
	*above = lmap_decor_default[2];
	for (size_t k = 0; k < sizeof lmap_doom_decor / sizeof lmap_doom_decor[0]; k++)
		if (lmap_doom_decor[k][0] == type) {
			*inten = lmap_doom_decor[k][1];
			*rad = lmap_doom_decor[k][2];
			*above = lmap_doom_decor[k][3];
		}
	return 1;
}

int lmap_lights_from_map(const struct map *m, unsigned flags, struct lmap_light *out, int max)
{
	int n = 0;

	for (uint32_t i = 0; i < m->num_things; i++) {
		const struct map_thing *t = &m->things[i];
		const struct map_sector *s;
		int32_t inten, rad, above;

		if (!lmap_thing_light(t->type, flags, &inten, &rad, &above))
			continue;
		if (n < max) {
			s = &m->sectors[map_point_sector(m, t->x, t->y)];
			out[n].x = t->x;
			out[n].y = t->y;
			/* (floor + ceil) / 2 without overflow; decorations at their
			 * flame, not above the ceiling */
			out[n].z = above < 0 ? s->floor_h + (fx_t)(((int64_t)s->ceil_h - s->floor_h) / 2)
					     : (fx_t)((int64_t)s->floor_h + fx_from_int(above) < s->ceil_h
							      ? s->floor_h + fx_from_int(above)
							      : s->ceil_h);
			out[n].intensity = inten;
			out[n].radius = rad;
		}
		n++;
	}
	return n;
}

static int64_t lmap_orient(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t cx, int64_t cy)
{
	return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

static int lmap_sign(int64_t v)
{
	return (v > 0) - (v < 0);
}

/* 1 when segment a-b (sub units) may touch the cell rectangle [x0, x1] x
 * [y0, y1]: not all four corners strictly on one side of its line. */
static int lmap_seg_cell(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t x0, int64_t y0,
			 int64_t x1, int64_t y1)
{
	int s1 = lmap_sign(lmap_orient(ax, ay, bx, by, x0, y0));
	int s2 = lmap_sign(lmap_orient(ax, ay, bx, by, x1, y0));
	int s3 = lmap_sign(lmap_orient(ax, ay, bx, by, x0, y1));
	int s4 = lmap_sign(lmap_orient(ax, ay, bx, by, x1, y1));

	return !(s1 == s2 && s2 == s3 && s3 == s4 && s1 != 0);
}

static int32_t lmap_cell_clamp(int64_t v, int32_t n)
{
	return v < 0 ? 0 : v >= n ? n - 1 : (int32_t)v;
}

/* Blocking lines, their openings, and the blockmap. */
static int lmap_blockmap(struct lmap_b *b)
{
	const struct map *m = b->m;
	int64_t x1 = 0, y1 = 0;
	size_t cells, total = 0;
	uint32_t *fill;

	b->lo = malloc((m->num_lines ? m->num_lines : 1) * sizeof *b->lo);
	b->hi = malloc((m->num_lines ? m->num_lines : 1) * sizeof *b->hi);
	b->stamp = calloc(m->num_lines ? m->num_lines : 1, sizeof *b->stamp);
	if (!b->lo || !b->hi || !b->stamp)
		return -ENOMEM;
	for (uint32_t i = 0; i < m->num_vertices; i++) {
		int64_t x = LMAP_SUB(m->vertices[i].x), y = LMAP_SUB(m->vertices[i].y);
		if (i == 0 || x < b->bx0)
			b->bx0 = x;
		if (i == 0 || y < b->by0)
			b->by0 = y;
		if (i == 0 || x > x1)
			x1 = x;
		if (i == 0 || y > y1)
			y1 = y;
	}
	b->bw = (int32_t)((x1 - b->bx0) >> LMAP_CELL_SHIFT) + 1;
	b->bh = (int32_t)((y1 - b->by0) >> LMAP_CELL_SHIFT) + 1;
	cells = (size_t)b->bw * (size_t)b->bh;
	b->cstart = calloc(cells + 1, sizeof *b->cstart);
	fill = calloc(cells + 1, sizeof *fill);
	if (!b->cstart || !fill) {
		free(fill);
		return -ENOMEM;
	}
	/* two passes: count, then fill */
	for (int pass = 0; pass < 2; pass++) {
		for (uint32_t i = 0; i < m->num_lines; i++) {
			const struct map_line *l = &m->lines[i];
			const struct map_vertex *va = &m->vertices[l->v1], *vb = &m->vertices[l->v2];
			int64_t ax = LMAP_SUB(va->x), ay = LMAP_SUB(va->y);
			int64_t bx = LMAP_SUB(vb->x), by = LMAP_SUB(vb->y);
			int32_t cx0, cx1, cy0, cy1;

			if (pass == 0) {
				b->lo[i] = 1;
				b->hi[i] = 0;
				if (l->side[1] != MAP_NONE) {
					const struct map_sector *f = &m->sectors[m->sides[l->side[0]].sector];
					const struct map_sector *k = &m->sectors[m->sides[l->side[1]].sector];
					b->lo[i] = LMAP_SUB(f->floor_h > k->floor_h ? f->floor_h : k->floor_h);
					b->hi[i] = LMAP_SUB(f->ceil_h < k->ceil_h ? f->ceil_h : k->ceil_h);
					if (f->floor_h == k->floor_h && f->ceil_h == k->ceil_h)
						continue;      /* never blocks */
				}
			} else if (l->side[1] != MAP_NONE) {
				const struct map_sector *f = &m->sectors[m->sides[l->side[0]].sector];
				const struct map_sector *k = &m->sectors[m->sides[l->side[1]].sector];
				if (f->floor_h == k->floor_h && f->ceil_h == k->ceil_h)
					continue;
			}
			cx0 = (int32_t)(((ax < bx ? ax : bx) - b->bx0) >> LMAP_CELL_SHIFT);
			cx1 = (int32_t)(((ax < bx ? bx : ax) - b->bx0) >> LMAP_CELL_SHIFT);
			cy0 = (int32_t)(((ay < by ? ay : by) - b->by0) >> LMAP_CELL_SHIFT);
			cy1 = (int32_t)(((ay < by ? by : ay) - b->by0) >> LMAP_CELL_SHIFT);
			/* the cells of the line's box: long diagonals over a big
			 * map are many */
			if (lim_take(&b->lim, (uint64_t)(cx1 - cx0 + 1) * (uint64_t)(cy1 - cy0 + 1))) {
				free(fill);
				return b->lim.err;
			}
			for (int32_t cy = cy0; cy <= cy1; cy++)
				for (int32_t cx = cx0; cx <= cx1; cx++) {
					int64_t x0 = b->bx0 + ((int64_t)cx << LMAP_CELL_SHIFT);
					int64_t y0 = b->by0 + ((int64_t)cy << LMAP_CELL_SHIFT);
					size_t c = (size_t)cy * (size_t)b->bw + (size_t)cx;
					if (!lmap_seg_cell(ax, ay, bx, by, x0, y0,
							   x0 + (1 << LMAP_CELL_SHIFT),
							   y0 + (1 << LMAP_CELL_SHIFT)))
						continue;
					if (pass == 0)
						b->cstart[c + 1]++;
					else
						b->clines[b->cstart[c] + fill[c]++] = i;
				}
		}
		if (pass == 0) {
			for (size_t c = 0; c < cells; c++)
				b->cstart[c + 1] += b->cstart[c];
			total = b->cstart[cells];
			if (total > LMAP_MAX_CELL_LINES) {
				free(fill);
				return -E2BIG;
			}
			b->clines = malloc((total ? total : 1) * sizeof *b->clines);
			if (!b->clines) {
				free(fill);
				return -ENOMEM;
			}
		}
	}
	free(fill);
	return 0;
}

/* 1 when line i blocks the segment from L to P (sub units, with heights). */
static int lmap_blocks(const struct lmap_b *b, uint32_t i, const int64_t L[3], const int64_t P[3])
{
	const struct map *m = b->m;
	const struct map_line *l = &m->lines[i];
	int64_t ax = LMAP_SUB(m->vertices[l->v1].x), ay = LMAP_SUB(m->vertices[l->v1].y);
	int64_t bx = LMAP_SUB(m->vertices[l->v2].x), by = LMAP_SUB(m->vertices[l->v2].y);
	int64_t o1 = lmap_orient(ax, ay, bx, by, L[0], L[1]);
	int64_t o2 = lmap_orient(ax, ay, bx, by, P[0], P[1]);
	int64_t o3, o4, d, zl, zh;

	/* the ray's ends strictly on opposite sides of the line ... */
	if (o1 == 0 || o2 == 0 || (o1 < 0) == (o2 < 0))
		return 0;
	/* ... and the wall's ends not strictly on one side of the ray (a ray
	 * through a vertex is blocked: no light slips between two walls) */
	o3 = lmap_sign(lmap_orient(L[0], L[1], P[0], P[1], ax, ay));
	o4 = lmap_sign(lmap_orient(L[0], L[1], P[0], P[1], bx, by));
	if (o3 != 0 && o3 == o4)
		return 0;
	if (b->lo[i] > b->hi[i])
		return 1;
	/* crossing at t = o1 / (o1 - o2) in (0, 1); its height
	 * L.z + (P.z - L.z) t against the opening [lo, hi], exactly:
	 * z < lo  <=>  (L.z - lo) d + (P.z - L.z) o1 < 0 with d = o1 - o2 > 0 */
	d = o1 - o2;
	if (d < 0) {
		d = -d;
		o1 = -o1;
	}
	zl = (L[2] - b->lo[i]) * d + (P[2] - L[2]) * o1;
	zh = (L[2] - b->hi[i]) * d + (P[2] - L[2]) * o1;
	return zl < 0 || zh > 0;
}

/* 1 when nothing blocks the segment from L to P. */
static int lmap_clear(struct lmap_b *b, const int64_t L[3], const int64_t P[3])
{
	int32_t cx0, cx1, cy0, cy1;
	int64_t xa = L[0] < P[0] ? L[0] : P[0], xb = L[0] < P[0] ? P[0] : L[0];
	int64_t ya = L[1] < P[1] ? L[1] : P[1], yb = L[1] < P[1] ? P[1] : L[1];

	b->rays++;
	if (++b->cur == 0) {
		memset(b->stamp, 0, (b->m->num_lines ? b->m->num_lines : 1) * sizeof *b->stamp);
		b->cur = 1;
	}
	cx0 = lmap_cell_clamp((xa - b->bx0) >> LMAP_CELL_SHIFT, b->bw);
	cx1 = lmap_cell_clamp((xb - b->bx0) >> LMAP_CELL_SHIFT, b->bw);
	cy0 = lmap_cell_clamp((ya - b->by0) >> LMAP_CELL_SHIFT, b->bh);
	cy1 = lmap_cell_clamp((yb - b->by0) >> LMAP_CELL_SHIFT, b->bh);
	for (int32_t cy = cy0; cy <= cy1; cy++)
		for (int32_t cx = cx0; cx <= cx1; cx++) {
			int64_t x0 = b->bx0 + ((int64_t)cx << LMAP_CELL_SHIFT);
			int64_t y0 = b->by0 + ((int64_t)cy << LMAP_CELL_SHIFT);
			size_t c = (size_t)cy * (size_t)b->bw + (size_t)cx;
			b->steps++;
			if (b->cstart[c] == b->cstart[c + 1] ||
			    !lmap_seg_cell(L[0], L[1], P[0], P[1], x0, y0, x0 + (1 << LMAP_CELL_SHIFT),
					   y0 + (1 << LMAP_CELL_SHIFT)))
				continue;
			for (uint32_t k = b->cstart[c]; k < b->cstart[c + 1]; k++) {
				uint32_t i = b->clines[k];
				b->steps++;
				if (b->stamp[i] == b->cur)
					continue;
				b->stamp[i] = b->cur;
				if (lmap_blocks(b, i, L, P))
					return 0;
			}
		}
	return 1;
}

/* Light units of light li at distance d (sub units). */
static int64_t lmap_falloff(const struct lmap_light *li, int64_t d)
{
	int64_t r = (int64_t)li->radius * 16;

	if (d >= r)
		return 0;
	return (int64_t)li->intensity * (r - d) * (r - d) / (r * r);
}

/* Square of the distance from L to P (sub units); the distance itself is
 * its integer square root, floor(sqrt(s)). */
static uint64_t lmap_dist2(const int64_t L[3], const int64_t P[3])
{
	int64_t dx = P[0] - L[0], dy = P[1] - L[1], dz = P[2] - L[2];

	return (uint64_t)(dx * dx) + (uint64_t)(dy * dy) + (uint64_t)(dz * dz);
}

/* Light of li at the texel whose centre is P[0] (and quarter points
 * P[1..4]): the first clear point's falloff. Distances are compared as
 * squares (floor(sqrt(s)) >= k exactly when s >= k * k, k >= 0): the
 * square root, most of this function's time when each point took one, is
 * taken only for the point whose falloff is returned. */
static int64_t lmap_texel(struct lmap_b *b, const struct lmap_light *li, const int64_t L[3],
			  int64_t P[5][3], int64_t t)
{
	int64_t r = (int64_t)li->radius * 16;       /* > 0: lmap_new_lim checks radius */
	uint64_t s[5], r2 = (uint64_t)(r * r), rt = (uint64_t)(r + t);
	int any = 0;

	/* the quarter points lie within t of the centre */
	s[0] = lmap_dist2(L, P[0]);
	if (s[0] >= rt * rt)
		return 0;
	for (int k = 0; k < 5; k++) {
		s[k] = lmap_dist2(L, P[k]);
		any |= s[k] < r2;
	}
	if (!any)
		return 0;
	for (int k = 0; k < 5; k++)
		if (lmap_clear(b, L, P[k]))
			return s[k] < r2 ? lmap_falloff(li, (int64_t)fx_isqrt64(s[k])) : 0;
	return 0;
}

/* The quarter points around P[0]: offsets q along axes (ux, uy, uz) and
 * (vx, vy, vz) scaled by q. */
static void lmap_quarters(int64_t P[5][3], const int64_t U[3], const int64_t V[3])
{
	static const int su[4] = { -1, 1, -1, 1 }, sv[4] = { -1, -1, 1, 1 };

	for (int k = 0; k < 4; k++)
		for (int a = 0; a < 3; a++)
			P[k + 1][a] = P[0][a] + su[k] * U[a] + sv[k] * V[a];
}

/* Centre, in sub units, of the part of texel index i (size 1 << shift
 * units) that lies inside [0, extent) sub units. */
static int64_t lmap_centre(int32_t i, int32_t shift, int64_t extent)
{
	int64_t a = ((int64_t)i << shift) * 16, e = a + ((int64_t)16 << shift);

	if (e > extent)
		e = extent;
	return (a + e) / 2;
}

struct lmap_acc {
	uint16_t *v;                            /* per texel, light units */
};

static void lmap_add(uint16_t *a, int64_t c)
{
	int64_t s = (int64_t)*a + c;

	*a = (uint16_t)(s > 65535 ? 65535 : s);
}

/* Bounding boxes of sectors (sub units), from their sides' lines. */
static void lmap_sector_boxes(const struct map *m, int64_t (*box)[4])
{
	for (uint32_t s = 0; s < m->num_sectors; s++) {
		box[s][0] = box[s][1] = INT64_MAX;
		box[s][2] = box[s][3] = INT64_MIN;
	}
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		for (int sd = 0; sd < 2; sd++) {
			uint32_t s;
			if (l->side[sd] == MAP_NONE)
				continue;
			s = m->sides[l->side[sd]].sector;
			for (int v = 0; v < 2; v++) {
				const struct map_vertex *p = &m->vertices[v ? l->v2 : l->v1];
				int64_t x = LMAP_SUB(p->x), y = LMAP_SUB(p->y);
				box[s][0] = x < box[s][0] ? x : box[s][0];
				box[s][1] = y < box[s][1] ? y : box[s][1];
				box[s][2] = x > box[s][2] ? x : box[s][2];
				box[s][3] = y > box[s][3] ? y : box[s][3];
			}
		}
	}
}

/* 1 when the light's radius reaches the box (sub units). */
static int lmap_reach_box(const int64_t L[3], int64_t r, int64_t x0, int64_t y0, int64_t x1,
			  int64_t y1)
{
	int64_t dx = L[0] < x0 ? x0 - L[0] : L[0] > x1 ? L[0] - x1 : 0;
	int64_t dy = L[1] < y0 ? y0 - L[1] : L[1] > y1 ? L[1] - y1 : 0;

	return dx < r && dy < r && dx * dx + dy * dy < r * r;
}

static void lmap_light_sub(const struct lmap_light *li, int64_t L[3])
{
	L[0] = LMAP_SUB(li->x);
	L[1] = LMAP_SUB(li->y);
	L[2] = LMAP_SUB(li->z);
}

/* Whether light li reaches the floor (c 0) / ceiling (c 1) of sector s. */
static int lmap_reach_flat(const struct map *m, const int64_t (*box)[4], uint32_t s, int c,
			   const struct lmap_light *li)
{
	const struct map_sector *sec = &m->sectors[s];
	int64_t L[3];

	if (box[s][0] > box[s][2] || sec->floor_h >= sec->ceil_h)
		return 0;
	lmap_light_sub(li, L);
	if (c ? L[2] >= LMAP_SUB(sec->ceil_h) : L[2] <= LMAP_SUB(sec->floor_h))
		return 0;
	return lmap_reach_box(L, (int64_t)li->radius * 16, box[s][0], box[s][1], box[s][2],
			      box[s][3]);
}

/* Side sd of line i: its start and end (sub units), front sector. */
static void lmap_side_ends(const struct map *m, uint32_t i, int sd, int64_t S[2], int64_t E[2])
{
	const struct map_line *l = &m->lines[i];
	const struct map_vertex *a = &m->vertices[sd ? l->v2 : l->v1];
	const struct map_vertex *e = &m->vertices[sd ? l->v1 : l->v2];

	S[0] = LMAP_SUB(a->x);
	S[1] = LMAP_SUB(a->y);
	E[0] = LMAP_SUB(e->x);
	E[1] = LMAP_SUB(e->y);
}

static int lmap_reach_wall(const struct map *m, uint32_t i, int sd, const struct lmap_light *li)
{
	const struct map_line *l = &m->lines[i];
	const struct map_sector *f;
	int64_t S[2], E[2], L[3];

	if (l->side[sd] == MAP_NONE)
		return 0;
	f = &m->sectors[m->sides[l->side[sd]].sector];
	if (f->floor_h >= f->ceil_h)
		return 0;
	lmap_side_ends(m, i, sd, S, E);
	if (S[0] == E[0] && S[1] == E[1])
		return 0;              /* shorter than 1/16 unit: no texels */
	lmap_light_sub(li, L);
	/* the front is to the right of start -> end: cross < 0 */
	if (lmap_orient(S[0], S[1], E[0], E[1], L[0], L[1]) >= 0)
		return 0;
	return lmap_reach_box(L, (int64_t)li->radius * 16, S[0] < E[0] ? S[0] : E[0],
			      S[1] < E[1] ? S[1] : E[1], S[0] < E[0] ? E[0] : S[0],
			      S[1] < E[1] ? E[1] : S[1]);
}

static int32_t lmap_cells(int64_t extent_sub, int32_t shift)
{
	int64_t t = (int64_t)16 << shift;
	int64_t n = (extent_sub + t - 1) / t;

	return n < 1 ? 1 : (int32_t)n;
}

/* Sizes a grid over [0, ex) x [0, ey) sub units: the finest shift from
 * min_shift keeping it within LMAP_GRID_MAX texels. */
static void lmap_size(struct lmap_grid *g, int64_t ex, int64_t ey, int32_t min_shift)
{
	g->shift = min_shift;
	for (;;) {
		g->w = lmap_cells(ex, g->shift);
		g->h = lmap_cells(ey, g->shift);
		if ((int64_t)g->w * g->h <= LMAP_GRID_MAX || g->shift >= LMAP_SHIFT_MAX)
			return;
		g->shift++;
	}
}

static int64_t lmap_side_len(const struct map *m, uint32_t i)
{
	int64_t S[2], E[2];

	lmap_side_ends(m, i, 0, S, E);
	return (int64_t)fx_isqrt64((uint64_t)((E[0] - S[0]) * (E[0] - S[0])) +
				   (uint64_t)((E[1] - S[1]) * (E[1] - S[1])));
}

/* A texel's own work, in steps: five distances (integer square roots)
 * and the quarter points cost about as much as eight line tests; counting
 * them 1 let a map whose texels mostly lie beyond its lights' reach run
 * three times longer per step than Freedoom's maps. */
#define LMAP_TEXEL_STEPS 8

/* Charges a texel (and the steps of its rays) to b->lim: 0 or its error. */
static int lmap_charge(struct lmap_b *b)
{
	int r = lim_take(&b->lim, LMAP_TEXEL_STEPS + b->steps);

	b->steps = 0;
	return r;
}

/* Adds light li to flat grid g of sector s (c: ceiling). 0 or b->lim's
 * error. */
static int lmap_light_flat(struct lmap_b *b, const struct lmap_light *li, const struct lmap_grid *g,
			    uint16_t *acc, const int64_t *box, int64_t z)
{
	int64_t L[3], r = (int64_t)li->radius * 16, t = (int64_t)16 << g->shift;
	int64_t ox = (int64_t)g->x0 * 16, oy = (int64_t)g->y0 * 16;
	int64_t ex = box[2] - ox, ey = box[3] - oy;
	int64_t U[3] = { t / 4, 0, 0 }, V[3] = { 0, t / 4, 0 };
	int32_t c0, c1, r0, r1;

	lmap_light_sub(li, L);
	c0 = lmap_cell_clamp((L[0] - r - ox) / t, g->w);
	c1 = lmap_cell_clamp((L[0] + r - ox) / t, g->w);
	r0 = lmap_cell_clamp((L[1] - r - oy) / t, g->h);
	r1 = lmap_cell_clamp((L[1] + r - oy) / t, g->h);
	for (int32_t row = r0; row <= r1; row++)
		for (int32_t col = c0; col <= c1; col++) {
			int64_t P[5][3];
			P[0][0] = ox + lmap_centre(col, g->shift, ex);
			P[0][1] = oy + lmap_centre(row, g->shift, ey);
			P[0][2] = z;
			lmap_quarters(P, U, V);
			lmap_add(&acc[(size_t)row * (size_t)g->w + (size_t)col], lmap_texel(b, li, L, P, t));
			if (lmap_charge(b))
				return b->lim.err;
		}
	return 0;
}

/* Adds light li to wall grid g of side sd of line i. 0 or b->lim's error. */
static int lmap_light_wall(struct lmap_b *b, const struct lmap_light *li, const struct lmap_grid *g,
			    uint16_t *acc, uint32_t i, int sd, int64_t len, int64_t zf, int64_t zc)
{
	int64_t S[2], E[2], L[3], t = (int64_t)16 << g->shift;
	int64_t dx, dy, U[3], V[3] = { 0, 0, t / 4 };

	lmap_side_ends(b->m, i, sd, S, E);
	lmap_light_sub(li, L);
	dx = E[0] - S[0];
	dy = E[1] - S[1];
	U[0] = dx * (t / 4) / len;
	U[1] = dy * (t / 4) / len;
	U[2] = 0;
	for (int32_t col = 0; col < g->w; col++) {
		int64_t u = lmap_centre(col, g->shift, len);
		/* along the side, then 1 unit (16 sub) to its right, the front */
		int64_t px = S[0] + (dx * u + dy * 16) / len;
		int64_t py = S[1] + (dy * u - dx * 16) / len;
		for (int32_t row = 0; row < g->h; row++) {
			int64_t P[5][3];
			P[0][0] = px;
			P[0][1] = py;
			P[0][2] = zf + lmap_centre(row, g->shift, zc - zf);
			lmap_quarters(P, U, V);
			lmap_add(&acc[(size_t)col * (size_t)g->h + (size_t)row], lmap_texel(b, li, L, P, t));
			if (lmap_charge(b))
				return b->lim.err;
		}
	}
	return 0;
}

static void lmap_b_free(struct lmap_b *b)
{
	free(b->cstart);
	free(b->clines);
	free(b->stamp);
	free(b->lo);
	free(b->hi);
}

/* The grid of surface g (flats first, then walls), or NULL. */
static struct lmap_grid *lmap_surface(const struct lmap *lm, uint32_t g)
{
	return lm->idx[g] == MAP_NONE ? NULL : &lm->grids[lm->idx[g]];
}

/* Which surfaces some light reaches, their grids' sizes, and the pool:
 * grids take consecutive pool ranges in surface order. */
static int lmap_layout(struct lmap *lm, const struct map *m, const int64_t (*box)[4],
		       const struct lmap_light *lights, int n, struct lim *lim)
{
	size_t off = 0;
	uint32_t nf = 2 * m->num_sectors, nw = 2 * m->num_lines;

	for (uint32_t g = 0; g < nf + nw; g++) {
		int hit = 0, k;
		for (k = 0; k < n && !hit; k++)
			hit = g < nf ? lmap_reach_flat(m, box, g / 2, (int)(g & 1), &lights[k])
				     : lmap_reach_wall(m, (g - nf) / 2, (int)((g - nf) & 1), &lights[k]);
		if (lim_take(lim, 1 + (uint64_t)k))
			return lim->err;
		lm->idx[g] = hit ? lm->ngrids++ : MAP_NONE;
	}
	lm->grids = calloc(lm->ngrids ? lm->ngrids : 1, sizeof *lm->grids);
	if (!lm->grids)
		return -ENOMEM;
	/* the finest texels that keep the whole within LMAP_TEXELS_MAX */
	for (int32_t min_shift = LMAP_TEXEL_SHIFT;; min_shift++) {
		off = 0;
		for (uint32_t g = 0; g < nf + nw; g++) {
			struct lmap_grid *gr = lmap_surface(lm, g);
			if (!gr)
				continue;
			if (g < nf) {
				const int64_t *bx = box[g / 2];
				gr->x0 = (int32_t)(bx[0] >> 4);
				gr->y0 = (int32_t)(bx[1] >> 4);
				lmap_size(gr, bx[2] - (int64_t)gr->x0 * 16,
					  bx[3] - (int64_t)gr->y0 * 16, min_shift);
			} else {
				uint32_t i = (g - nf) / 2;
				const struct map_sector *f =
					&m->sectors[m->sides[m->lines[i].side[(g - nf) & 1]].sector];
				gr->x0 = 0;
				gr->y0 = fx_to_int(f->floor_h);
				lmap_size(gr, lmap_side_len(m, i),
					  LMAP_SUB(f->ceil_h) - LMAP_SUB(f->floor_h), min_shift);
			}
			off += (size_t)gr->w * (size_t)gr->h;
		}
		if (off <= LMAP_TEXELS_MAX || min_shift >= LMAP_SHIFT_MAX)
			break;
	}
	lm->st.grids = lm->ngrids;
	lm->st.texels = off;
	lm->pool = malloc(off ? off : 1);
	if (!lm->pool)
		return -ENOMEM;
	off = 0;
	for (uint32_t k = 0; k < lm->ngrids; k++) {
		lm->grids[k].t = lm->pool + off;
		off += (size_t)lm->grids[k].w * (size_t)lm->grids[k].h;
	}
	return 0;
}

static int lmap_check_lights(const struct lmap_light *lights, int n)
{
	if (n < 0 || (n > 0 && !lights))
		return -EINVAL;
	for (int k = 0; k < n; k++) {
		const struct lmap_light *li = &lights[k];
		if (li->intensity < 1 || li->intensity > 1024 || li->radius < 1 ||
		    li->radius > LMAP_RADIUS_MAX || li->x < -MAP_COORD_MAX || li->x > MAP_COORD_MAX ||
		    li->y < -MAP_COORD_MAX || li->y > MAP_COORD_MAX)
			return -EINVAL;
	}
	return 0;
}

int lmap_new(const struct map *m, const struct lmap_light *lights, int n, struct lmap **out)
{
	return lmap_new_lim(m, lights, n, NULL, out, NULL, 0);
}

/* err = "<what>" for lmap_new_lim's limits and stop. */
static int lmap_fail(int r, const struct lim *l, int n, char *err, size_t errlen)
{
	if (!err || !errlen || (r != -E2BIG && r != -ECANCELED))
		return r;
	err[0] = '\0';
	if (r == -ECANCELED) {
		msg_cat(err, errlen, "light maps: stopped");
	} else if (n > LMAP_MAX_LIGHTS) {
		msg_int(err, errlen, n);
		msg_cat(err, errlen, " lights, more than the limit of ");
		msg_int(err, errlen, LMAP_MAX_LIGHTS);
		msg_cat(err, errlen, " (LMAP_MAX_LIGHTS)");
	} else if (l->err == -E2BIG) {
		msg_cat(err, errlen, "light maps need more than ");
		msg_int(err, errlen, (int64_t)LMAP_MAX_STEPS);
		msg_cat(err, errlen, " steps (limit LMAP_MAX_STEPS)");
	} else {
		msg_cat(err, errlen, "light maps: the blocking lines fill more than ");
		msg_int(err, errlen, LMAP_MAX_CELL_LINES);
		msg_cat(err, errlen, " blockmap entries (limit LMAP_MAX_CELL_LINES)");
	}
	return r;
}

int lmap_new_lim(const struct map *m, const struct lmap_light *lights, int n,
		 const struct lim_stop *stop, struct lmap **out, char *err, size_t errlen)
{
	struct lmap_b b;
	struct lmap *lm;
	int64_t (*box)[4] = NULL;
	uint16_t *acc = NULL;
	uint32_t nf, nw;
	int r = lmap_check_lights(lights, n);

	*out = NULL;
	if (err && errlen)
		err[0] = '\0';
	if (r)
		return r;
	memset(&b, 0, sizeof b);
	lim_init(&b.lim, stop, LMAP_MAX_STEPS);
	if (n > LMAP_MAX_LIGHTS)
		return lmap_fail(-E2BIG, &b.lim, n, err, errlen);
	b.m = m;
	lm = calloc(1, sizeof *lm);
	if (!lm)
		return -ENOMEM;
	nf = 2 * m->num_sectors;
	nw = 2 * m->num_lines;
	lm->num_sectors = m->num_sectors;
	lm->num_lines = m->num_lines;
	lm->idx = malloc((nf + nw ? nf + nw : 1) * sizeof *lm->idx);
	box = malloc((m->num_sectors ? m->num_sectors : 1) * sizeof *box);
	r = -ENOMEM;
	if (!lm->idx || !box)
		goto fail;
	lmap_sector_boxes(m, box);
	r = lmap_layout(lm, m, (const int64_t(*)[4])box, lights, n, &b.lim);
	if (r)
		goto fail;
	r = -ENOMEM;
	acc = calloc(lm->st.texels ? lm->st.texels : 1, sizeof *acc);
	if (!acc)
		goto fail;
	r = lmap_blockmap(&b);
	if (r)
		goto fail;
	for (int k = 0; k < n && !r; k++) {
		const struct lmap_light *li = &lights[k];
		r = lim_take(&b.lim, (uint64_t)nf + nw);
		for (uint32_t s = 0; s < m->num_sectors && !r; s++)
			for (int c = 0; c < 2 && !r; c++) {
				const struct lmap_grid *g = lmap_surface(lm, 2 * s + (uint32_t)c);
				if (!g || !lmap_reach_flat(m, (const int64_t(*)[4])box, s, c, li))
					continue;
				r = lmap_light_flat(&b, li, g, acc + (g->t - lm->pool), box[s],
						    LMAP_SUB(c ? m->sectors[s].ceil_h : m->sectors[s].floor_h));
			}
		for (uint32_t i = 0; i < m->num_lines && !r; i++)
			for (int sd = 0; sd < 2 && !r; sd++) {
				const struct lmap_grid *g = lmap_surface(lm, nf + 2 * i + (uint32_t)sd);
				const struct map_sector *f;
				if (!g || !lmap_reach_wall(m, i, sd, li))
					continue;
				f = &m->sectors[m->sides[m->lines[i].side[sd]].sector];
				r = lmap_light_wall(&b, li, g, acc + (g->t - lm->pool), i, sd,
						    lmap_side_len(m, i), LMAP_SUB(f->floor_h),
						    LMAP_SUB(f->ceil_h));
			}
	}
	if (r)
		goto fail;
	for (uint64_t t = 0; t < lm->st.texels; t++) {
		uint32_t v = acc[t] >> 2;
		lm->pool[t] = (uint8_t)(v > PAL_LIGHTS - 1 ? PAL_LIGHTS - 1 : v);
	}
	lm->st.lights = (uint32_t)n;
	lm->st.rays = b.rays;
	lm->st.bytes = sizeof *lm + (nf + nw) * sizeof *lm->idx +
		       lm->ngrids * sizeof *lm->grids + (size_t)lm->st.texels;
	free(acc);
	free(box);
	lmap_b_free(&b);
	*out = lm;
	return 0;
fail:
	free(acc);
	free(box);
	lmap_b_free(&b);
	lmap_free(lm);
	return lmap_fail(r, &b.lim, n, err, errlen);
}

void lmap_free(struct lmap *lm)
{
	if (!lm)
		return;
	free(lm->idx);
	free(lm->grids);
	free(lm->pool);
	free(lm);
}

const struct lmap_grid *lmap_flat_grid(const struct lmap *lm, uint32_t sector, int ceiling)
{
	const struct lmap_grid *g;

	if (!lm || sector >= lm->num_sectors)
		return NULL;
	g = lmap_surface(lm, 2 * sector + (ceiling ? 1u : 0u));
	return g;
}

const struct lmap_grid *lmap_wall_grid(const struct lmap *lm, uint32_t line, int side)
{
	const struct lmap_grid *g;

	if (!lm || line >= lm->num_lines)
		return NULL;
	g = lmap_surface(lm, 2 * lm->num_sectors + 2 * line + (side ? 1u : 0u));
	return g;
}

int lmap_flat(const struct lmap *lm, uint32_t sector, int ceiling, fx_t x, fx_t y)
{
	const struct lmap_grid *g = lmap_flat_grid(lm, sector, ceiling);

	return g ? lmap_grid_flat_at(g, x, y) : 0;
}

int lmap_wall(const struct lmap *lm, uint32_t line, int side, fx_t u, fx_t z)
{
	const struct lmap_grid *g = lmap_wall_grid(lm, line, side);

	return g ? lmap_column_at(g, lmap_grid_column(g, u), z) : 0;
}

void lmap_get_stats(const struct lmap *lm, struct lmap_stats *st)
{
	*st = lm->st;
}

static uint64_t lmap_hash_grid(uint64_t h, const struct lmap_grid *g)
{
	h = hash_u8(h, g != NULL);
	if (!g)
		return h;
	h = hash_i32(h, g->x0);
	h = hash_i32(h, g->y0);
	h = hash_i32(h, g->w);
	h = hash_i32(h, g->h);
	h = hash_i32(h, g->shift);
	return hash_bytes(h, g->t, (size_t)g->w * (size_t)g->h);
}

uint64_t lmap_hash(const struct lmap *lm)
{
	uint64_t h = HASH_INIT;

	h = hash_u32(h, lm->num_sectors);
	h = hash_u32(h, lm->num_lines);
	for (uint32_t g = 0; g < 2 * lm->num_sectors + 2 * lm->num_lines; g++)
		h = lmap_hash_grid(h, lmap_surface(lm, g));
	return h;
}
