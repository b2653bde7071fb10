/*
 * g_move: circles moving on the map with wall sliding, for the player and
 * the enemies alike (the same code, so a chasing enemy obeys exactly the
 * player's collision), in exact 16.16 integer arithmetic.
 */
#include <stddef.h>

#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_PUSH_ITERS 4
#define G_PUSH_MARGIN 2                /* fx units left between a body and a wall */

int g_opening(const struct sim *s, const struct map_line *l, fx_t *floor, fx_t *ceil)
{
	const struct map *m = s->map;
	const struct g_sector *f, *b;

	if (l->side[1] == MAP_NONE || (l->flags & ML_BLOCKING))
		return -1;
	f = &s->w.sec[m->sides[l->side[0]].sector];
	b = &s->w.sec[m->sides[l->side[1]].sector];
	*floor = f->floor_h > b->floor_h ? f->floor_h : b->floor_h;
	*ceil = f->ceil_h < b->ceil_h ? f->ceil_h : b->ceil_h;
	return 0;
}

/* Whether line l stops a body with its feet at z, `height` tall, that
 * climbs steps up to `step`: g_blocks with the player's numbers, the
 * missiles' (g_wall_touch) with their own. */
static int g_stops(const struct sim *s, const struct map_line *l, fx_t z, fx_t height, fx_t step)
{
	fx_t fl, cl;
	int64_t floor, ceil;

	if (g_opening(s, l, &fl, &cl) < 0)
		return 1;
	floor = fl;
	ceil = cl;
	return floor - z > step || ceil - floor < height || ceil - z < height;
}

int g_blocks(const struct sim *s, const struct map_line *l, fx_t z)
{
	return g_stops(s, l, z, SIM_PLAYER_HEIGHT, SIM_MAX_STEP);
}

/* |n / d| rounded up, for d > 0: pushes round away from the wall. */
static int64_t g_div_up(int64_t n, int64_t d)
{
	return n >= 0 ? (n + d - 1) / d : -((-n + d - 1) / d);
}

/* Pushes (*x, *y) radially away from point (ax, ay) to radius r (plus
 * margin) if closer; (fdx, fdy) is the way out if it is exactly on it.
 * Returns whether it was closer. */
static int g_push_point(fx_t *x, fx_t *y, fx_t r, fx_t ax, fx_t ay, int64_t fdx, int64_t fdy,
			int apply)
{
	int64_t vx = (int64_t)*x - ax, vy = (int64_t)*y - ay;
	int64_t out = (int64_t)r + G_PUSH_MARGIN;
	int64_t d;

	if (vx <= -r || vx >= r || vy <= -r || vy >= r || vx * vx + vy * vy >= (int64_t)r * r)
		return 0;
	if (!apply)
		return 1;
	if (vx == 0 && vy == 0) {
		vx = fdx;
		vy = fdy;
	}
	d = fx_len((fx_t)vx, (fx_t)vy);
	*x = (fx_t)(ax + g_div_up(vx * out, d));
	*y = (fx_t)(ay + g_div_up(vy * out, d));
	return 1;
}

/*
 * Whether the circle (*x, *y, r) overlaps segment a-b; with apply, moves it
 * out to r + margin: along the segment's normal when the nearest point is
 * inside the segment (which is what makes bodies slide along walls),
 * radially from an end point otherwise. A centre exactly on the line goes
 * to the front (right) side.
 */
static int g_push(fx_t *x, fx_t *y, fx_t r, const struct map_vertex *a,
		  const struct map_vertex *b, int apply)
{
	int64_t dx = (int64_t)b->x - a->x, dy = (int64_t)b->y - a->y;
	int64_t px = (int64_t)*x - a->x, py = (int64_t)*y - a->y;
	int64_t t = px * dx + py * dy, len2 = dx * dx + dy * dy;
	int64_t cross, mag, len, need;

	if (t <= 0)
		return g_push_point(x, y, r, a->x, a->y, -dx, -dy, apply);
	if (t >= len2)
		return g_push_point(x, y, r, b->x, b->y, dx, dy, apply);
	len = fx_len((fx_t)dx, (fx_t)dy);
	cross = dx * py - dy * px;     /* > 0: left of a->b */
	mag = cross < 0 ? -cross : cross;
	if (mag >= r * len)
		return 0;
	if (!apply)
		return 1;
	/* left normal (-dy, dx) / len; the centre moves by (r - dist) along it */
	need = r + G_PUSH_MARGIN - mag / len;
	if (cross <= 0)
		need = -need;
	*x = (fx_t)(*x + g_div_up(-dy * need, len));
	*y = (fx_t)(*y + g_div_up(dx * need, len));
	return 1;
}

/* Whether the circle (*x, *y, r) overlaps a wall that stops a body at z,
 * `height` tall, climbing `step` (g_stops); with apply, pushes it out of
 * each such wall in turn (g_push). Lines are tested only when their
 * bounding box, grown by the radius, contains the centre. */
static int g_walls(const struct sim *s, fx_t r, fx_t z, fx_t height, fx_t step, fx_t *x, fx_t *y,
		   int apply)
{
	const struct map *m = s->map;
	int hit = 0;

	for (uint32_t i = 0; i < m->num_lines && !(hit && !apply); i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		int64_t lo, hi;
		lo = (a->x < b->x ? a->x : b->x) - (int64_t)r;
		hi = (a->x > b->x ? a->x : b->x) + (int64_t)r;
		if (*x <= lo || *x >= hi)
			continue;
		lo = (a->y < b->y ? a->y : b->y) - (int64_t)r;
		hi = (a->y > b->y ? a->y : b->y) + (int64_t)r;
		if (*y <= lo || *y >= hi)
			continue;
		if (g_stops(s, l, z, height, step) && g_push(x, y, r, a, b, apply))
			hit = 1;
	}
	return hit;
}

int g_wall_touch(const struct sim *s, fx_t x, fx_t y, fx_t r, fx_t z, fx_t height)
{
	return g_walls(s, r, z, height, 0, &x, &y, 0);
}

/* Pushes the circle at (*x, *y) out of every wall it overlaps. Returns 1 if
 * it then fits and moved no more than a radius per axis from (ox, oy) (so a
 * push can never carry it through a wall), else 0. */
static int g_fit(const struct sim *s, fx_t r, fx_t z, fx_t ox, fx_t oy, fx_t *x, fx_t *y)
{
	for (int iter = 0; iter <= G_PUSH_ITERS; iter++) {
		int apply = iter < G_PUSH_ITERS;
		if (!g_walls(s, r, z, SIM_PLAYER_HEIGHT, SIM_MAX_STEP, x, y, apply))
			break;
		if (!apply)
			return 0;
	}
	return (int64_t)*x - ox <= r && ox - (int64_t)*x <= r && (int64_t)*y - oy <= r &&
	       oy - (int64_t)*y <= r;
}

static uint64_t g_dist2(int64_t dx, int64_t dy)
{
	return (uint64_t)(dx * dx) + (uint64_t)(dy * dy);
}

/* One body against a circle (bx, by, br): blocked if the new position
 * overlaps it and is closer than the old one. */
static int g_one_blocks(fx_t bx, fx_t by, fx_t br, fx_t ox, fx_t oy, fx_t x, fx_t y, fx_t r)
{
	uint64_t reach = (uint64_t)((int64_t)br + r);
	uint64_t dn = g_dist2((int64_t)x - bx, (int64_t)y - by);

	if (dn >= reach * reach)
		return 0;
	return dn < g_dist2((int64_t)ox - bx, (int64_t)oy - by);
}

int g_body_blocked(const struct sim *s, int self, fx_t ox, fx_t oy, fx_t x, fx_t y, fx_t r)
{
	const struct g_game *g = &s->g;

	if (self >= 0 &&
	    g_one_blocks(s->pl.x, s->pl.y, SIM_PLAYER_RADIUS, ox, oy, x, y, r))
		return 1;
	for (int i = 0; i < g->num_enemies; i++) {
		const struct g_enemy *e = &g->en[i];
		if (i == self || e->state == G_E_DEAD)
			continue;
		if (g_one_blocks(e->x, e->y, g_kinds[e->kind].radius, ox, oy, x, y, r))
			return 1;
	}
	return 0;
}

/* The edge of the coordinate range as a wall (g_in_range): whether the
 * move from (ox, oy) to (x, y) takes a body of radius r past the edge, or
 * further past it. A body placed within r of the edge (a teleport
 * destination there) may still move inwards. */
static int g_past_edge(fx_t ox, fx_t oy, fx_t x, fx_t y, fx_t r)
{
	int64_t lim = (int64_t)MAP_COORD_MAX - r;

	return (x > lim && x > ox) || (x < -lim && x < ox) || (y > lim && y > oy) ||
	       (y < -lim && y < oy);
}

/* Tries to move the body by (dx, dy); updates its position on success. */
static int g_try(struct sim *s, struct g_body *b, fx_t dx, fx_t dy)
{
	fx_t x = b->x + dx, y = b->y + dy;

	if (g_past_edge(b->x, b->y, x, y, b->radius))
		return 0;
	if (!g_fit(s, b->radius, b->z, b->x, b->y, &x, &y) ||
	    g_past_edge(b->x, b->y, x, y, b->radius))
		return 0;
	if (g_body_blocked(s, b->self, b->x, b->y, x, y, b->radius))
		return 0;
	b->x = x;
	b->y = y;
	return 1;
}

/* Momentum after a blocked move: no more than what was actually moved, and
 * never reversed. */
static fx_t g_limit(fx_t mom, fx_t moved)
{
	if ((mom > 0 && moved <= 0) || (mom < 0 && moved >= 0))
		return 0;
	return fx_abs(moved) < fx_abs(mom) ? moved : mom;
}

int g_move(struct sim *s, struct g_body *b)
{
	int64_t mx = b->momx, my = b->momy;
	int64_t ax = mx < 0 ? -mx : mx, ay = my < 0 ? -my : my;
	int64_t n = (ax > ay ? ax : ay) / (b->radius / 2) + 1, i;
	fx_t x0 = b->x, y0 = b->y;
	int blocked = 0;

	for (i = 0; i < n; i++) {
		fx_t dx = (fx_t)(mx * (i + 1) / n - mx * i / n);
		fx_t dy = (fx_t)(my * (i + 1) / n - my * i / n);
		fx_t want_x = b->x + dx, want_y = b->y + dy;
		if (g_try(s, b, dx, dy)) {
			if (b->x != want_x || b->y != want_y)
				blocked = 1;
			continue;
		}
		blocked = 1;
		if (dx && g_try(s, b, dx, 0))
			continue;
		if (dy && g_try(s, b, 0, dy))
			continue;
		break;
	}
	if (blocked) {
		b->momx = g_limit(b->momx, b->x - x0);
		b->momy = g_limit(b->momy, b->y - y0);
	}
	return blocked;
}
