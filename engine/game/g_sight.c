/*
 * g_sight: line of sight and which walls stop a line, for the enemies'
 * sight and the player's shot.
 *
 * Exact integer geometry on the map's lines: segment crossings by the signs
 * of 64-bit cross products (coordinates are bounded by MAP_COORD_MAX, so
 * every product fits).
 */
#include "engine/game/g_local.h"
#include "engine/map/map.h"

static int g_sign(int64_t v)
{
	return (v > 0) - (v < 0);
}

/* Sign of the cross product (b - a) x (c - a). */
static int g_orient(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t cx, int64_t cy)
{
	return g_sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
}

/* Whether c lies within the bounding box of a-b (for collinear points). */
static int g_between(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t cx, int64_t cy)
{
	return (cx >= (ax < bx ? ax : bx)) && (cx <= (ax > bx ? ax : bx)) &&
	       (cy >= (ay < by ? ay : by)) && (cy <= (ay > by ? ay : by));
}

int g_segs_cross(int64_t p1x, int64_t p1y, int64_t p2x, int64_t p2y, const struct map_vertex *q1,
		   const struct map_vertex *q2)
{
	int o1 = g_orient(p1x, p1y, p2x, p2y, q1->x, q1->y);
	int o2 = g_orient(p1x, p1y, p2x, p2y, q2->x, q2->y);
	int o3 = g_orient(q1->x, q1->y, q2->x, q2->y, p1x, p1y);
	int o4 = g_orient(q1->x, q1->y, q2->x, q2->y, p2x, p2y);

	if (o1 * o2 < 0 && o3 * o4 < 0)
		return 1;
	if (o1 == 0 && g_between(p1x, p1y, p2x, p2y, q1->x, q1->y))
		return 1;
	if (o2 == 0 && g_between(p1x, p1y, p2x, p2y, q2->x, q2->y))
		return 1;
	if (o3 == 0 && g_between(q1->x, q1->y, q2->x, q2->y, p1x, p1y))
		return 1;
	if (o4 == 0 && g_between(q1->x, q1->y, q2->x, q2->y, p2x, p2y))
		return 1;
	return 0;
}

/* Whether line l stops sight or a shot between heights z1 and z2. */
static int g_opaque(const struct sim *s, const struct map_line *l, fx_t z1, fx_t z2)
{
	fx_t floor, ceil;

	if (g_opening(s, l, &floor, &ceil) < 0 || ceil <= floor)
		return 1;
	return (z1 < floor && z2 < floor) || (z1 > ceil && z2 > ceil);
}

/* Whether line l's bounding box misses the box of the segment. */
static int g_box_misses(const struct map_vertex *a, const struct map_vertex *b, int64_t lox,
			int64_t hix, int64_t loy, int64_t hiy)
{
	return (a->x < lox && b->x < lox) || (a->x > hix && b->x > hix) ||
	       (a->y < loy && b->y < loy) || (a->y > hiy && b->y > hiy);
}

int g_line_stops(const struct sim *s, const struct map_line *l, int64_t x1, int64_t y1, fx_t z1,
		 int64_t x2, int64_t y2, fx_t z2)
{
	const struct map *m = s->map;
	const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
	int64_t lox = x1 < x2 ? x1 : x2, hix = x1 > x2 ? x1 : x2;
	int64_t loy = y1 < y2 ? y1 : y2, hiy = y1 > y2 ? y1 : y2;

	return !g_box_misses(a, b, lox, hix, loy, hiy) && g_opaque(s, l, z1, z2) &&
	       g_segs_cross(x1, y1, x2, y2, a, b);
}

int g_sight(const struct sim *s, fx_t x1, fx_t y1, fx_t z1, fx_t x2, fx_t y2, fx_t z2)
{
	const struct map *m = s->map;

	for (uint32_t i = 0; i < m->num_lines; i++)
		if (g_line_stops(s, &m->lines[i], x1, y1, z1, x2, y2, z2))
			return 0;
	return 1;
}
