/*
 * Hand-built test maps for the renderer tests (no node builder): the maps'
 * BSP is written out by hand, so these tests do not depend on nb_build.
 * Included by tests/unit/test_r_*.c; static inline so that a test using
 * only some of them compiles warning-free.
 */
#ifndef ARCADED_TESTS_R_TESTMAP_H
#define ARCADED_TESTS_R_TESTMAP_H

#include <stdint.h>
#include <string.h>

#include "engine/map.h"
#include "engine/pal.h"

#define U(x) ((fx_t)((x) * FX_ONE))

/* Colours (palette indices) */
#define C_CEIL PAL_RGB(PAL_GREY, 2)
#define C_FLOOR PAL_RGB(PAL_BROWN, 6)
#define C_WEST PAL_RGB(PAL_RED, 4)
#define C_NORTH PAL_RGB(PAL_GREEN, 4)
#define C_EAST PAL_RGB(PAL_BLUE, 4)
#define C_SOUTH PAL_RGB(PAL_YELLOW, 4)

struct tmap {
	struct map m;
	struct map_vertex v[32];
	struct map_sector sec[4];
	struct map_side sd[32];
	struct map_line ln[32];
	struct map_seg sg[32];
	struct map_subsector ss[4];
	struct map_node nd[4];
};

static inline void t_init(struct tmap *t)
{
	memset(t, 0, sizeof(*t));
	t->m.vertices = t->v;
	t->m.sectors = t->sec;
	t->m.sides = t->sd;
	t->m.lines = t->ln;
	t->m.segs = t->sg;
	t->m.subsectors = t->ss;
	t->m.nodes = t->nd;
}

static inline uint32_t t_vertex(struct tmap *t, int x, int y)
{
	t->v[t->m.num_vertices].x = U(x);
	t->v[t->m.num_vertices].y = U(y);
	return t->m.num_vertices++;
}

static inline uint32_t t_sector(struct tmap *t, int floor, int ceil, int light)
{
	struct map_sector *s = &t->sec[t->m.num_sectors];
	s->floor_h = U(floor);
	s->ceil_h = U(ceil);
	s->floor_tex = C_FLOOR;
	s->ceil_tex = C_CEIL;
	s->light = (uint8_t)light;
	return t->m.num_sectors++;
}

/* A line v1 -> v2 (its front is on the right) with a seg for each side;
 * tex is the middle texture of a one-sided line, the upper and lower of a
 * two-sided one. The segs are appended in order; returns the line. */
static inline uint32_t t_line(struct tmap *t, uint32_t v1, uint32_t v2, uint32_t front, uint32_t back,
		       uint16_t tex)
{
	uint32_t li = t->m.num_lines++;
	struct map_line *l = &t->ln[li];

	l->v1 = v1;
	l->v2 = v2;
	l->side[0] = t->m.num_sides;
	l->side[1] = MAP_NONE;
	t->sd[t->m.num_sides].sector = front;
	if (back == MAP_NONE) {
		t->sd[t->m.num_sides++].mid_tex = tex;
	} else {
		t->sd[t->m.num_sides].top_tex = tex;
		t->sd[t->m.num_sides++].bot_tex = tex;
		l->flags = ML_TWOSIDED;
		l->side[1] = t->m.num_sides;
		t->sd[t->m.num_sides].sector = back;
		t->sd[t->m.num_sides].top_tex = tex;
		t->sd[t->m.num_sides++].bot_tex = tex;
	}
	return li;
}

/* Seg of side `side` of line li, facing sector `front`. */
static inline void t_seg(struct tmap *t, uint32_t li, int side)
{
	struct map_seg *s = &t->sg[t->m.num_segs++];
	const struct map_line *l = &t->ln[li];
	uint32_t other = l->side[side ^ 1];

	s->line = li;
	s->side = (uint8_t)side;
	s->v1 = side ? l->v2 : l->v1;
	s->v2 = side ? l->v1 : l->v2;
	s->front = t->sd[l->side[side]].sector;
	s->back = other == MAP_NONE ? MAP_NONE : t->sd[other].sector;
}

/* Square room [-128, 128]^2, floor 0, ceiling 128: one convex sector, no
 * nodes (Doom convention: the map is subsector 0). Walls listed clockwise
 * so that their front (right) side faces in. */
static inline void t_room(struct tmap *t, int light, int same_tex)
{
	uint32_t a, b, c, d, s;

	t_init(t);
	a = t_vertex(t, -128, -128);
	b = t_vertex(t, -128, 128);
	c = t_vertex(t, 128, 128);
	d = t_vertex(t, 128, -128);
	s = t_sector(t, 0, 128, light);
	t_seg(t, t_line(t, a, b, s, MAP_NONE, C_WEST), 0);
	t_seg(t, t_line(t, b, c, s, MAP_NONE, same_tex ? C_WEST : C_NORTH), 0);
	t_seg(t, t_line(t, c, d, s, MAP_NONE, same_tex ? C_WEST : C_EAST), 0);
	t_seg(t, t_line(t, d, a, s, MAP_NONE, same_tex ? C_WEST : C_SOUTH), 0);
	t->ss[0].first_seg = 0;
	t->ss[0].num_segs = 4;
	t->ss[0].sector = s;
	t->m.num_subsectors = 1;
}

/* Rooms A [-128,128]^2 (f0 c128), W [128,144]x[-32,32] (the window: sill
 * floor w_floor, lintel ceiling w_ceil) and B [144,400]x[-128,128] (f0
 * c128), all light 255. Window lines (A-W, W-B) are colour C_WIN, B's east
 * wall C_BEAST, every other wall C_WALL. Subsectors: 0 A, 1 W, 2 B. BSP:
 * root (node 1) splits at x = 144 going north (front, east: B), its back
 * child (node 0) at x = 128 (front W, back A). */
#define C_WIN PAL_RGB(PAL_PURPLE, 4)
#define C_BEAST PAL_RGB(PAL_ORANGE, 4)
#define C_WALL PAL_RGB(PAL_TAN, 4)

static inline void t_window(struct tmap *t, int w_floor, int w_ceil)
{
	const uint8_t c_win = C_WIN, c_beast = C_BEAST, c_wall = C_WALL;
	uint32_t a, w, b, la, lw;
	uint32_t p[12];

	t_init(t);
	a = t_sector(t, 0, 128, 255);
	w = t_sector(t, w_floor, w_ceil, 255);
	b = t_sector(t, 0, 128, 255);
	p[0] = t_vertex(t, -128, -128);
	p[1] = t_vertex(t, -128, 128);
	p[2] = t_vertex(t, 128, 128);
	p[3] = t_vertex(t, 128, 32);
	p[4] = t_vertex(t, 128, -32);
	p[5] = t_vertex(t, 128, -128);
	p[6] = t_vertex(t, 144, 32);
	p[7] = t_vertex(t, 144, -32);
	p[8] = t_vertex(t, 144, 128);
	p[9] = t_vertex(t, 400, 128);
	p[10] = t_vertex(t, 400, -128);
	p[11] = t_vertex(t, 144, -128);
	/* subsector 0: A */
	t_seg(t, t_line(t, p[0], p[1], a, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[1], p[2], a, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[2], p[3], a, MAP_NONE, c_wall), 0);
	la = t_line(t, p[3], p[4], a, w, c_win);
	t_seg(t, la, 0);
	t_seg(t, t_line(t, p[4], p[5], a, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[5], p[0], a, MAP_NONE, c_wall), 0);
	t->ss[0] = (struct map_subsector){ 0, 6, a };
	/* subsector 1: W */
	t_seg(t, t_line(t, p[3], p[6], w, MAP_NONE, c_wall), 0);
	lw = t_line(t, p[6], p[7], w, b, c_win);
	t_seg(t, lw, 0);
	t_seg(t, t_line(t, p[7], p[4], w, MAP_NONE, c_wall), 0);
	t_seg(t, la, 1);
	t->ss[1] = (struct map_subsector){ 6, 4, w };
	/* subsector 2: B */
	t_seg(t, t_line(t, p[6], p[8], b, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[8], p[9], b, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[9], p[10], b, MAP_NONE, c_beast), 0);
	t_seg(t, t_line(t, p[10], p[11], b, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[11], p[7], b, MAP_NONE, c_wall), 0);
	t_seg(t, lw, 1);
	t->ss[2] = (struct map_subsector){ 10, 6, b };
	t->m.num_subsectors = 3;
	t->nd[0] = (struct map_node){ U(128), 0, 0, U(1),
				     { { U(32), U(-32), U(128), U(144) },
				       { U(128), U(-128), U(-128), U(128) } },
				     { 1 | MAP_NF_SUBSECTOR, 0 | MAP_NF_SUBSECTOR } };
	t->nd[1] = (struct map_node){ U(144), 0, 0, U(1),
				     { { U(128), U(-128), U(144), U(400) },
				       { U(128), U(-128), U(-128), U(144) } },
				     { 2 | MAP_NF_SUBSECTOR, 0 } };
	t->m.num_nodes = 2;
}

#endif
