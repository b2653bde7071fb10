/*
 * Test fixture: small maps from integer tables (map units), finished with
 * map_finish. Shared by the engine tests (test_map, test_nb, test_sim).
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

/* Builds the map without finishing it (tests may then break it). */
static inline struct map *fix_alloc(const struct fix_map *f)
{
	struct map *m;
	int i, nsides = 0, side = 0;

	for (i = 0; i < f->nl; i++)
		nsides += f->l[i].back >= 0 ? 2 : 1;
	if (map_alloc(&m, (uint32_t)f->nv, (uint32_t)f->ns, (uint32_t)nsides, (uint32_t)f->nl, 1))
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
	return m;
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
