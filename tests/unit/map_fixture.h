/*
 * Test fixture: small maps from integer tables (map units), finished with
 * map_finish. Shared by the engine tests (test_map, test_nb, test_sim) and,
 * with fix_row, by the specials' tests (test_g_door, test_g_ceil,
 * test_g_line, test_g_floor, test_g_light, test_g_tele, test_g_spec).
 */
#ifndef ARCADED_TESTS_MAP_FIXTURE_H
#define ARCADED_TESTS_MAP_FIXTURE_H

#include <stdint.h>
#include <string.h>

#include "engine/map/map.h"

struct fix_sector {
	int floor, ceil, light;
};

/* A line from v1 to v2; front sector on the right; back -1: one-sided. */
struct fix_line {
	int v1, v2, front, back;
};

/* A thing besides the player 1 start (thing 0). */
struct fix_thing {
	int x, y;
	ang_t angle;
	uint16_t type, flags;
};

struct fix_map {
	const int (*v)[2];
	int nv;
	const struct fix_sector *s;
	int ns;
	const struct fix_line *l;
	int nl;
	int start_x, start_y;          /* player 1 start */
	ang_t start_angle;
};

#define FIX_N(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* Builds the map with the things th[0..nth) after the player start,
 * without finishing it. */
static inline struct map *fix_alloc_things(const struct fix_map *f, const struct fix_thing *th,
					   int nth)
{
	struct map *m;
	int i, nsides = 0, side = 0;

	for (i = 0; i < f->nl; i++)
		nsides += f->l[i].back >= 0 ? 2 : 1;
	if (map_alloc(&m, (uint32_t)f->nv, (uint32_t)f->ns, (uint32_t)nsides, (uint32_t)f->nl,
		      1 + (uint32_t)nth))
		return NULL;
	memcpy(m->name, "FIXTURE", 8);
	for (i = 0; i < f->nv; i++) {
		m->vertices[i].x = fx_from_int(f->v[i][0]);
		m->vertices[i].y = fx_from_int(f->v[i][1]);
	}
	for (i = 0; i < f->ns; i++) {
		m->sectors[i].floor_h = fx_from_int(f->s[i].floor);
		m->sectors[i].ceil_h = fx_from_int(f->s[i].ceil);
		m->sectors[i].light = (uint8_t)f->s[i].light;
		m->sectors[i].floor_tex = 1;
		m->sectors[i].ceil_tex = 2;
	}
	for (i = 0; i < f->nl; i++) {
		struct map_line *l = &m->lines[i];
		l->v1 = (uint32_t)f->l[i].v1;
		l->v2 = (uint32_t)f->l[i].v2;
		l->side[0] = (uint32_t)side;
		m->sides[side].sector = (uint32_t)f->l[i].front;
		m->sides[side++].mid_tex = 3;
		l->side[1] = MAP_NONE;
		l->flags = ML_BLOCKING;
		if (f->l[i].back >= 0) {
			l->flags = ML_TWOSIDED;
			l->side[1] = (uint32_t)side;
			m->sides[side++].sector = (uint32_t)f->l[i].back;
		}
	}
	m->things[0].x = fx_from_int(f->start_x);
	m->things[0].y = fx_from_int(f->start_y);
	m->things[0].angle = f->start_angle;
	m->things[0].type = 1;
	for (i = 0; i < nth; i++) {
		struct map_thing *t = &m->things[1 + i];
		t->x = fx_from_int(th[i].x);
		t->y = fx_from_int(th[i].y);
		t->angle = th[i].angle;
		t->type = th[i].type;
		t->flags = th[i].flags;
	}
	return m;
}

/* Builds the map without finishing it (tests may then break it). */
static inline struct map *fix_alloc(const struct fix_map *f)
{
	return fix_alloc_things(f, NULL, 0);
}

#define FIX_ROW_MAX 12

/* A row of n (at most FIX_ROW_MAX) rectangular sectors side by side along
 * x, all y 0..depth: sector i is width[i] wide and starts where sector i-1
 * ends (sector 0 at x = 0). Line 0 is sector 0's west wall; sector i's
 * north wall is line 3i+1, its east wall line 3i+2 (two-sided, front i and
 * back i+1, but for the last sector), its south wall line 3i+3. The player
 * starts at (sx, sy) facing a; th/nth: more things. Not finished (the
 * caller sets specials and tags, then map_finish). NULL on failure. */
static inline struct map *fix_row(const int *width, const struct fix_sector *s, int n,
				  int depth, int sx, int sy, ang_t a,
				  const struct fix_thing *th, int nth)
{
	int v[2 + 2 * FIX_ROW_MAX][2];
	struct fix_line l[1 + 3 * FIX_ROW_MAX];
	struct fix_map f = { (const int (*)[2])v, 2 + 2 * n, s, n, l, 1 + 3 * n, sx, sy, a };
	int x = 0;

	if (n < 1 || n > FIX_ROW_MAX)
		return NULL;
	v[0][0] = 0;
	v[0][1] = 0;
	v[1][0] = 0;
	v[1][1] = depth;
	l[0] = (struct fix_line){ 0, 1, 0, -1 };
	for (int i = 0; i < n; i++) {
		int nw = i ? 2 * i : 1, sw = i ? 2 * i + 1 : 0;   /* the west corners */
		x += width[i];
		v[2 + 2 * i][0] = x;          /* north-east corner */
		v[2 + 2 * i][1] = depth;
		v[3 + 2 * i][0] = x;          /* south-east corner */
		v[3 + 2 * i][1] = 0;
		l[3 * i + 1] = (struct fix_line){ nw, 2 * i + 2, i, -1 };
		l[3 * i + 2] = (struct fix_line){ 2 * i + 2, 2 * i + 3, i, i + 1 < n ? i + 1 : -1 };
		l[3 * i + 3] = (struct fix_line){ 2 * i + 3, sw, i, -1 };
	}
	return fix_alloc_things(&f, th, nth);
}

/* Builds and finishes the map; NULL if either fails (err says why). */
static inline struct map *fix_build(const struct fix_map *f, char *err, size_t errlen)
{
	struct map *m = fix_alloc(f);

	if (!m)
		return NULL;
	if (map_finish(m, err, errlen)) {
		map_free(m);
		return NULL;
	}
	return m;
}

#endif
