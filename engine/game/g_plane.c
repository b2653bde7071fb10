/*
 * g_plane: a floor or ceiling moving among the bodies (Doom's T_MovePlane
 * and P_ChangeSector).
 *
 * A body (the player, a living enemy) is in a sector's way when its centre
 * is in it or its circle overlaps one of the sector's lines. It fits when
 * the space between the higher of its own sector's floor and the moving
 * sector's floor and the lower of the two ceilings is at least
 * G_BODY_HEIGHT. Bodies stand on their own sector's floor (sim.h: no
 * falling), so a body in the moving sector rides its floor at once.
 * Corpses and pickups never stop a plane.
 */
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_CRUSH_DAMAGE 10

/* Whether the circle (x, y, r) overlaps line l (exact enough: in 1/16
 * units, so every product fits 64 bits). */
static int g_circle_on_line(const struct map *m, const struct map_line *l, fx_t x, fx_t y, fx_t r)
{
	const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
	int64_t lox = a->x < b->x ? a->x : b->x, hix = a->x > b->x ? a->x : b->x;
	int64_t loy = a->y < b->y ? a->y : b->y, hiy = a->y > b->y ? a->y : b->y;
	int64_t dx, dy, px, py, t, len2, cx, cy, rr, d2;

	if (x <= lox - r || x >= hix + r || y <= loy - r || y >= hiy + r)
		return 0;
	dx = ((int64_t)b->x - a->x) >> 12;
	dy = ((int64_t)b->y - a->y) >> 12;
	px = ((int64_t)x - a->x) >> 12;
	py = ((int64_t)y - a->y) >> 12;
	len2 = dx * dx + dy * dy;
	t = px * dx + py * dy;
	if (t <= 0 || len2 == 0) {
		cx = px;
		cy = py;
	} else if (t >= len2) {
		cx = px - dx;
		cy = py - dy;
	} else {
		/* distance to the line: cross / len, compared squared */
		int64_t c = dx * py - dy * px;
		rr = (int64_t)r >> 12;
		/* c^2 / len2 < rr^2, with c up to 2^38: c / len compared as
		 * c * c < rr * rr * len2 would overflow; divide first */
		return (c < 0 ? -c : c) / (fx_isqrt64((uint64_t)len2) + 1) < rr;
	}
	rr = (int64_t)r >> 12;
	d2 = cx * cx + cy * cy;
	return d2 < rr * rr;
}

/* Whether a body at (x, y) of radius r whose centre is in sector `centre`
 * is in the way of sector sec. */
static int g_touches(const struct sim *s, fx_t x, fx_t y, fx_t r, uint32_t centre, uint32_t sec)
{
	uint32_t n;
	const uint32_t *l;

	if (centre == sec)
		return 1;
	l = map_sector_lines(s->map, sec, &n);
	for (uint32_t k = 0; k < n; k++)
		if (g_circle_on_line(s->map, &s->map->lines[l[k]], x, y, r))
			return 1;
	return 0;
}

/* Whether a body in sector `centre` touching sec fits between the two
 * sectors' planes. */
static int g_fits(const struct sim *s, uint32_t centre, uint32_t sec)
{
	const struct g_sector *a = &s->w.sec[centre], *b = &s->w.sec[sec];
	int64_t floor = a->floor_h > b->floor_h ? a->floor_h : b->floor_h;
	int64_t ceil = a->ceil_h < b->ceil_h ? a->ceil_h : b->ceil_h;

	return ceil - floor >= G_BODY_HEIGHT;
}

/* Doom's P_ChangeSector: the bodies in sec's way ride its floor; returns
 * 1 when one of them does not fit (crushing it when crush, on every
 * fourth tic). */
static int g_change(struct sim *s, uint32_t sec, int crush)
{
	int nofit = 0, hurt = crush && g_dtic_now(s) && (g_dtic(s) & 3) == 0;
	struct sim_player *p = &s->pl;

	if (s->mode == SIM_PLAY && (s->g.phase == G_PH_PLAY || s->g.phase == G_PH_CLEAR)) {
		if (g_touches(s, p->x, p->y, SIM_PLAYER_RADIUS, p->sector, sec)) {
			if (p->sector == sec) {
				fx_t dz = s->w.sec[sec].floor_h - p->z;
				p->z += dz;
				p->viewz += dz;
			}
			if (!g_fits(s, p->sector, sec)) {
				nofit = 1;
				if (hurt)
					g_hurt_player(s, G_CRUSH_DAMAGE * FX_ONE);
			}
		}
	}
	for (int i = 0; i < s->g.num_enemies; i++) {
		struct g_enemy *e = &s->g.en[i];
		if (e->state == G_E_DEAD ||
		    !g_touches(s, e->x, e->y, g_kinds[e->kind].radius, e->sector, sec))
			continue;
		/* a flyer is lifted only when the floor reaches it */
		if (e->sector == sec && (!g_kinds[e->kind].fly || e->z < s->w.sec[sec].floor_h))
			e->z = s->w.sec[sec].floor_h;
		if (!g_fits(s, e->sector, sec)) {
			nofit = 1;
			if (hurt)
				g_hurt_enemy(s, i, G_CRUSH_DAMAGE);
		}
	}
	return nofit;
}

int g_plane_move(struct sim *s, uint32_t sec, fx_t speed, fx_t dest, int crush, int ceiling,
		 int dir)
{
	struct g_sector *g = &s->w.sec[sec];
	fx_t *h = ceiling ? &g->ceil_h : &g->floor_h;
	fx_t last = *h;
	int64_t next = (int64_t)*h + (dir < 0 ? -(int64_t)speed : speed);

	dest = g_clamp(dest, MAP_HEIGHT_MAX);

	/* Doom's rule: the last step goes exactly to dest; a body in the way
	 * there puts the plane back, but the move still counts as done */
	if ((dir < 0 && next < dest) || (dir > 0 && next > dest)) {
		*h = dest;
		if (g_change(s, sec, crush)) {
			*h = last;
			g_change(s, sec, crush);
		}
		return G_RES_PASTDEST;
	}
	*h = (fx_t)next;
	if (!g_change(s, sec, crush))
		return G_RES_OK;
	/* a body does not fit: a crushing plane goes on (down) unless it is
	 * a floor going down or a ceiling going up, which never crush */
	if (ceiling && dir > 0)
		return G_RES_OK;
	if (crush && ((ceiling && dir < 0) || (!ceiling && dir > 0)))
		return G_RES_CRUSHED;
	*h = last;
	g_change(s, sec, crush);
	return G_RES_CRUSHED;
}
