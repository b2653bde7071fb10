/*
 * xc_move: the mover views of the cross-check (xc_move.h). Which sectors
 * move comes from the map's line specials by Doom's rules, independently
 * of the game's tables (engine/game/g_line.c):
 *   door sectors: the back sector of a manual door line (types 1, 26-28,
 *     31-34, 117, 118) and the sectors tagged by a line whose door special
 *     raises a ceiling (open or open-wait-close, plain, fast or locked);
 *     open height = the lowest neighbouring ceiling - 4 (Doom's
 *     P_FindLowestCeilingSurrounding - 4); the views put the ceiling a
 *     quarter, half and three quarters of the way from the floor up;
 *   lift sectors: the sectors tagged by a lift line (down-wait-up 10, 21,
 *     62, 88, fast 120-123, perpetual 53, 87); a lift travels between its
 *     floor and the lowest neighbouring floor (no higher than its own);
 *     the views put the floor a quarter, half and three quarters of the
 *     way down.
 * Viewpoints: for every two-sided line of a mover sector, points on the
 * line's other side, on its normal through the midpoint, 64 and 192
 * units out, looking at the midpoint; a point counts when it lies in a
 * sector (not the mover) at least 56 units tall, at least 1 unit from any
 * line and 16 from one-sided ones, not within a thing's radius plus 16,
 * and no one-sided line lies between it and the midpoint. Eye 41 above
 * the floor, no shear.
 */
#include <math.h>
#include <stdlib.h>

#include "tests/crosscheck/xc_move.h"

/* Viewpoints on the grid of a map's vertices (whole units, straight out
 * from an axis-aligned line) put plane and wall edges exactly on pixel
 * centres, where the two renderers break the tie differently and a whole
 * row differs (0.5% of a view): the points are moved this far out and
 * sideways, as a player rarely stands exactly on the grid. */
#define XCM_OFF 0.375

static const uint16_t xcm_manual[] = { 1, 26, 27, 28, 31, 32, 33, 34, 117, 118 };
static const uint16_t xcm_tagdoor[] = { 2,   4,   29,  46,  61,  63,  86,  90,
					99,  103, 105, 106, 108, 109, 111, 112,
					114, 115, 133, 134, 135, 136, 137 };
static const uint16_t xcm_lift[] = { 10, 21, 53, 62, 87, 88, 120, 121, 122, 123 };

static int xcm_in(uint16_t t, const uint16_t *set, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (set[i] == t)
			return 1;
	return 0;
}

#define XCM_IN(t, set) xcm_in((t), (set), sizeof(set) / sizeof((set)[0]))

static double xcm_x(const struct map *m, uint32_t v)
{
	return m->vertices[v].x / 65536.0;
}

static double xcm_y(const struct map *m, uint32_t v)
{
	return m->vertices[v].y / 65536.0;
}

static uint32_t xcm_sec(const struct map *m, uint32_t side)
{
	return side == MAP_NONE ? MAP_NONE : m->sides[side].sector;
}

/* 1 when segments (a, b) and (c, d) cross. */
static int xcm_cross(double ax, double ay, double bx, double by, double cx, double cy, double dx,
		     double dy)
{
	double d1 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
	double d2 = (bx - ax) * (dy - ay) - (by - ay) * (dx - ax);
	double d3 = (dx - cx) * (ay - cy) - (dy - cy) * (ax - cx);
	double d4 = (dx - cx) * (by - cy) - (dy - cy) * (bx - cx);

	return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

uint32_t xcm_eye(const struct map *m, uint32_t mover, double x, double y, double mx, double my)
{
	uint32_t s = map_point_sector(m, (fx_t)lround(x * 65536.0), (fx_t)lround(y * 65536.0));

	if (s >= m->num_sectors || s == mover ||
	    m->sectors[s].ceil_h - m->sectors[s].floor_h < 56 * FX_ONE)
		return MAP_NONE;
	if (!xc_clear_of_things(m, x, y))
		return MAP_NONE;
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		int solid = l->side[1] == MAP_NONE;
		double d2 = xc_line_dist(m, l, x, y);

		if (d2 < 1.0 || (solid && d2 < 16.0 * 16.0))
			return MAP_NONE;
		if (solid && xcm_cross(x, y, mx, my, xcm_x(m, l->v1), xcm_y(m, l->v1),
				       xcm_x(m, l->v2), xcm_y(m, l->v2)))
			return MAP_NONE;
	}
	return s;
}

/* Lowest ceiling (c) or floor of the sectors across s's two-sided lines,
 * or INT32_MAX when there is none. */
static fx_t xcm_lowest(const struct map *m, uint32_t s, int c)
{
	fx_t low = INT32_MAX;

	for (uint32_t k = m->sec_first[s]; k < m->sec_first[s + 1]; k++) {
		const struct map_line *l = &m->lines[m->sec_lines[k]];
		uint32_t a = xcm_sec(m, l->side[0]), b = xcm_sec(m, l->side[1]);
		uint32_t o = a == s ? b : a;
		fx_t h;

		if (b == MAP_NONE || o >= m->num_sectors)
			continue;
		h = c ? m->sectors[o].ceil_h : m->sectors[o].floor_h;
		low = h < low ? h : low;
	}
	return low;
}

/* Views of sector s with its heights at quarter k: every good viewpoint. */
static int xcm_sector(const struct map *m, uint32_t s, char kind, struct xcm_view *out, int max,
		      int n)
{
	const struct map_sector *sec = &m->sectors[s];
	fx_t from, to;

	if (kind == 'd') {
		from = sec->floor_h;
		to = xcm_lowest(m, s, 1);
		if (to == INT32_MAX)
			return n;
		to -= 4 * FX_ONE;
	} else {
		from = sec->floor_h;
		to = xcm_lowest(m, s, 0);
		if (to == INT32_MAX)
			return n;
	}
	if (kind == 'd' ? to <= from : to >= from)
		return n;
	for (uint32_t k = m->sec_first[s]; k < m->sec_first[s + 1]; k++) {
		const struct map_line *l = &m->lines[m->sec_lines[k]];
		uint32_t a = xcm_sec(m, l->side[0]), b = xcm_sec(m, l->side[1]);
		double ax = xcm_x(m, l->v1), ay = xcm_y(m, l->v1);
		double dx = xcm_x(m, l->v2) - ax, dy = xcm_y(m, l->v2) - ay;
		double len = sqrt(dx * dx + dy * dy), mx = ax + dx / 2, my = ay + dy / 2;
		/* the unit normal towards the side not facing s (front: right) */
		double sign = a == s ? -1.0 : 1.0, nx = sign * dy / len, ny = -sign * dx / len;

		if (b == MAP_NONE || a == b || len < 1)
			continue;
		for (int d = 64; d <= 192; d += 128) {
			/* off the map's grid by a fraction of a unit (XCM_OFF) */
			double x = mx + nx * (d + XCM_OFF) - ny * XCM_OFF;
			double y = my + ny * (d + XCM_OFF) + nx * XCM_OFF;
			uint32_t e = xcm_eye(m, s, x, y, mx, my);
			double ang = atan2(my - y, mx - x);

			if (e == MAP_NONE)
				continue;
			for (int q = 1; q <= 3; q++, n++) {
				struct xcm_view *o;

				if (n >= max)
					continue;
				o = &out[n];
				o->sector = s;
				o->kind = kind;
				o->quarter = q;
				o->floor_h = sec->floor_h;
				o->ceil_h = sec->ceil_h;
				if (kind == 'd')
					o->ceil_h = (fx_t)(from + (int64_t)(to - from) * q / 4);
				else
					o->floor_h = (fx_t)(from + (int64_t)(to - from) * q / 4);
				o->v.x = (fx_t)lround(x * 65536.0);
				o->v.y = (fx_t)lround(y * 65536.0);
				o->v.z = m->sectors[e].floor_h + 41 * FX_ONE;
				o->v.angle = (ang_t)(int64_t)llround(ang / (2 * M_PI) * 4294967296.0);
				o->v.shear = 0;
			}
		}
	}
	return n;
}

int xcm_views(const struct map *m, struct xcm_view *out, int max)
{
	uint8_t *what = calloc(m->num_sectors ? m->num_sectors : 1, 1);   /* 1 door, 2 lift */
	int n = 0;

	if (!what)
		return -1;
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		uint8_t bit = XCM_IN(l->special, xcm_tagdoor) ? 1 : XCM_IN(l->special, xcm_lift) ? 2 : 0;

		if (XCM_IN(l->special, xcm_manual)) {
			uint32_t b = xcm_sec(m, l->side[1]);

			if (b < m->num_sectors)
				what[b] |= 1;
		} else if (bit && l->tag) {
			for (uint32_t s = 0; s < m->num_sectors; s++)
				if (m->sectors[s].tag == l->tag)
					what[s] |= bit;
		}
	}
	for (uint32_t s = 0; s < m->num_sectors; s++) {
		if (what[s] & 1)
			n = xcm_sector(m, s, 'd', out, max, n);
		if (what[s] & 2)
			n = xcm_sector(m, s, 'l', out, max, n);
	}
	free(what);
	return n;
}
