/*
 * g_ceil: ceilings and crushers (Doom's p_ceilng.c) and platforms, lifts
 * among them (p_plats.c). Crushers go down to 8 above the floor and back
 * up forever, slowed to an eighth while they crush; a line stops them (in
 * stasis) and a crusher line starts them again. Lifts go down to the
 * lowest neighbouring floor, wait three seconds and come back up; a body
 * in the way of a lift going up sends it back down.
 */
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_CEIL_SPEED G_PER_TICK(FX_ONE)
#define G_PLAT_SPEED G_PER_TICK(FX_ONE)
#define G_PLAT_WAIT G_TICS(3 * 35)

int g_ceil_tagged(struct sim *s, const struct map_line *l, int type)
{
	int sec = -1, rtn = 0;

	/* crushers in stasis with this tag start again */
	if (type == G_CEIL_FAST_CRUSH_RAISE || type == G_CEIL_SILENT_CRUSH_RAISE ||
	    type == G_CEIL_CRUSH_RAISE)
		for (int i = 0; i < s->w.num_movers; i++) {
			struct g_mover *c = &s->w.mv[i];
			if (c->kind == G_MV_CEIL && c->tag == l->tag && c->dir == G_DIR_STASIS)
				c->dir = c->old;
		}
	while ((sec = g_tagged(s, l->tag, sec)) >= 0) {
		const struct g_sector *g = &s->w.sec[sec];
		struct g_mover *c;

		if (g_mover_of(s, (uint32_t)sec))
			continue;
		c = g_mover_new(s, (uint32_t)sec, G_MV_CEIL, type);
		if (!c)
			continue;
		rtn = 1;
		c->tag = s->map->sectors[sec].tag;
		c->speed = G_CEIL_SPEED;
		c->dir = G_DIR_DOWN;
		switch (type) {
		case G_CEIL_FAST_CRUSH_RAISE:
			c->speed = 2 * G_CEIL_SPEED;
			/* fall through */
		case G_CEIL_SILENT_CRUSH_RAISE:
		case G_CEIL_CRUSH_RAISE:
			c->crush = 1;
			c->high = g->ceil_h;
			c->low = g->floor_h + 8 * FX_ONE;
			break;
		case G_CEIL_LOWER_AND_CRUSH:
			c->low = g->floor_h + 8 * FX_ONE;
			break;
		case G_CEIL_LOWER_TO_FLOOR:
			c->low = g->floor_h;
			break;
		case G_CEIL_RAISE_TO_HIGHEST:
		default:
			c->high = g_highest_ceil_around(s, (uint32_t)sec);
			c->dir = G_DIR_UP;
			break;
		}
	}
	return rtn;
}

int g_ceil_stop(struct sim *s, uint16_t tag)
{
	int rtn = 0;

	for (int i = 0; i < s->w.num_movers; i++) {
		struct g_mover *c = &s->w.mv[i];
		if (c->kind == G_MV_CEIL && c->tag == tag && c->dir != G_DIR_STASIS) {
			c->old = c->dir;
			c->dir = G_DIR_STASIS;
			rtn = 1;
		}
	}
	return rtn;
}

int g_ceil_tick(struct sim *s, struct g_mover *c)
{
	int res, t = c->type;

	if (c->dir == G_DIR_STASIS)
		return 0;
	if (t != G_CEIL_SILENT_CRUSH_RAISE && g_dtic_now(s) && (g_dtic(s) & 7) == 0)
		g_event(s, G_EV_PLANE_MOVE, c->sector);
	if (c->dir == G_DIR_UP) {
		res = g_plane_move(s, c->sector, c->speed, c->high, 0, 1, G_DIR_UP);
		if (res != G_RES_PASTDEST)
			return 0;
		if (t == G_CEIL_RAISE_TO_HIGHEST) {
			g_mover_remove(s, c);
			return 1;
		}
		if (t == G_CEIL_SILENT_CRUSH_RAISE)
			g_event(s, G_EV_PLAT_STOP, c->sector);
		if (t == G_CEIL_SILENT_CRUSH_RAISE || t == G_CEIL_CRUSH_RAISE ||
		    t == G_CEIL_FAST_CRUSH_RAISE)
			c->dir = G_DIR_DOWN;
		return 0;
	}
	res = g_plane_move(s, c->sector, c->speed, c->low, c->crush, 1, G_DIR_DOWN);
	if (res == G_RES_PASTDEST) {
		switch (t) {
		case G_CEIL_SILENT_CRUSH_RAISE:
			g_event(s, G_EV_PLAT_STOP, c->sector);
			/* fall through */
		case G_CEIL_CRUSH_RAISE:
			c->speed = G_CEIL_SPEED;
			/* fall through */
		case G_CEIL_FAST_CRUSH_RAISE:
			c->dir = G_DIR_UP;
			return 0;
		case G_CEIL_LOWER_AND_CRUSH:
		case G_CEIL_LOWER_TO_FLOOR:
			g_mover_remove(s, c);
			return 1;
		default:
			return 0;
		}
	}
	if (res == G_RES_CRUSHED && (t == G_CEIL_SILENT_CRUSH_RAISE || t == G_CEIL_CRUSH_RAISE ||
				     t == G_CEIL_LOWER_AND_CRUSH))
		c->speed = G_CEIL_SPEED / 8;
	return 0;
}

int g_plat_tagged(struct sim *s, const struct map_line *l, int type, int amount)
{
	int sec = -1, rtn = 0;

	if (type == G_PLAT_PERPETUAL)
		for (int i = 0; i < s->w.num_movers; i++) {
			struct g_mover *p = &s->w.mv[i];
			if (p->kind == G_MV_PLAT && p->tag == l->tag && p->dir == G_DIR_STASIS)
				p->dir = p->old;
		}
	while ((sec = g_tagged(s, l->tag, sec)) >= 0) {
		struct g_sector *g = &s->w.sec[sec];
		struct g_mover *p;

		if (g_mover_of(s, (uint32_t)sec))
			continue;
		p = g_mover_new(s, (uint32_t)sec, G_MV_PLAT, type);
		if (!p)
			continue;
		rtn = 1;
		p->tag = l->tag;
		switch (type) {
		case G_PLAT_RAISE_NEAREST_CHANGE:
		case G_PLAT_RAISE_CHANGE:
			p->speed = G_PLAT_SPEED / 2;
			g->floor_tex = s->w.sec[s->map->sides[l->side[0]].sector].floor_tex;
			if (type == G_PLAT_RAISE_NEAREST_CHANGE) {
				p->high = g_next_floor_above(s, (uint32_t)sec, g->floor_h);
				g->special = 0;        /* no more damage, as in Doom */
			} else {
				p->high = g->floor_h + amount * FX_ONE;
			}
			p->dir = G_DIR_UP;
			g_event(s, G_EV_PLANE_MOVE, (uint32_t)sec);
			break;
		case G_PLAT_DWUS:
		case G_PLAT_BLAZE_DWUS:
			p->speed = (type == G_PLAT_DWUS ? 4 : 8) * G_PLAT_SPEED;
			p->low = g_lowest_floor_around(s, (uint32_t)sec);
			if (p->low > g->floor_h)
				p->low = g->floor_h;
			p->high = g->floor_h;
			p->wait = G_PLAT_WAIT;
			p->dir = G_DIR_DOWN;
			g_event(s, G_EV_PLAT_START, (uint32_t)sec);
			break;
		case G_PLAT_PERPETUAL:
		default:
			p->speed = G_PLAT_SPEED;
			p->low = g_lowest_floor_around(s, (uint32_t)sec);
			if (p->low > g->floor_h)
				p->low = g->floor_h;
			p->high = g_highest_floor_around(s, (uint32_t)sec);
			if (p->high < g->floor_h)
				p->high = g->floor_h;
			p->wait = G_PLAT_WAIT;
			p->dir = (g_random(s) & 1) ? G_DIR_DOWN : G_DIR_UP;
			g_event(s, G_EV_PLAT_START, (uint32_t)sec);
			break;
		}
	}
	return rtn;
}

void g_plat_stop(struct sim *s, uint16_t tag)
{
	for (int i = 0; i < s->w.num_movers; i++) {
		struct g_mover *p = &s->w.mv[i];
		if (p->kind == G_MV_PLAT && p->tag == tag && p->dir != G_DIR_STASIS) {
			p->old = p->dir;
			p->dir = G_DIR_STASIS;
		}
	}
}

int g_plat_tick(struct sim *s, struct g_mover *p)
{
	int res, t = p->type;

	switch (p->dir) {
	case G_DIR_UP:
		res = g_plane_move(s, p->sector, p->speed, p->high, p->crush, 0, G_DIR_UP);
		if ((t == G_PLAT_RAISE_CHANGE || t == G_PLAT_RAISE_NEAREST_CHANGE) && g_dtic_now(s) &&
		    (g_dtic(s) & 7) == 0)
			g_event(s, G_EV_PLANE_MOVE, p->sector);
		if (res == G_RES_CRUSHED && !p->crush) {
			/* something in the way: back down */
			p->count = p->wait;
			p->dir = G_DIR_DOWN;
			g_event(s, G_EV_PLAT_START, p->sector);
		} else if (res == G_RES_PASTDEST) {
			p->count = p->wait;
			p->dir = G_DIR_WAIT;
			g_event(s, G_EV_PLAT_STOP, p->sector);
			if (t != G_PLAT_PERPETUAL) {
				g_mover_remove(s, p);
				return 1;
			}
		}
		return 0;
	case G_DIR_DOWN:
		res = g_plane_move(s, p->sector, p->speed, p->low, 0, 0, G_DIR_DOWN);
		if (res == G_RES_PASTDEST) {
			p->count = p->wait;
			p->dir = G_DIR_WAIT;
			g_event(s, G_EV_PLAT_STOP, p->sector);
		}
		return 0;
	case G_DIR_WAIT:
		if (p->count > 0)
			p->count--;
		if (p->count == 0) {
			p->dir = s->w.sec[p->sector].floor_h == p->low ? G_DIR_UP : G_DIR_DOWN;
			g_event(s, G_EV_PLAT_START, p->sector);
		}
		return 0;
	default:
		return 0;
	}
}
