/*
 * g_floor: moving floors, stairs and the donut (Doom's p_floor.c and
 * EV_DoDonut). A floor moves a unit a Doom tic (turbo ones four), to a
 * height found from its neighbours when it starts (enum g_floor); some take
 * a neighbour's flat and special. Stairs raise the tagged sector by a step
 * and then, one by one, the sectors behind its front-facing two-sided
 * lines that have the same flat, each a step higher.
 */
#include <stdint.h>

#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_FLOOR_SPEED G_PER_TICK(FX_ONE)

/* The destination of floor type `type` in sector sec (and what the
 * "change" types end with, in *tex and *special). */
static fx_t g_floor_dest(struct sim *s, uint32_t sec, int type, uint16_t *tex, uint16_t *special)
{
	const struct map *m = s->map;
	struct g_sector *g = &s->w.sec[sec];
	fx_t d;

	switch (type) {
	case G_FLOOR_LOWER:
		return g_highest_floor_around(s, sec);
	case G_FLOOR_LOWEST:
		return g_lowest_floor_around(s, sec);
	case G_FLOOR_TURBO_LOWER:
		d = g_highest_floor_around(s, sec);
		return d != g->floor_h ? d + 8 * FX_ONE : d;
	case G_FLOOR_RAISE:
	case G_FLOOR_RAISE_CRUSH:
		d = g_lowest_ceil_around(s, sec);
		if (d > g->ceil_h)
			d = g->ceil_h;
		return type == G_FLOOR_RAISE_CRUSH ? d - 8 * FX_ONE : d;
	case G_FLOOR_RAISE_NEAREST:
	case G_FLOOR_RAISE_TURBO:
		return g_next_floor_above(s, sec, g->floor_h);
	case G_FLOOR_RAISE24:
	case G_FLOOR_RAISE24_CHANGE:
		return g->floor_h + 24 * FX_ONE;
	case G_FLOOR_RAISE512:
		return g->floor_h + 512 * FX_ONE;
	case G_FLOOR_RAISE_TEXTURE: {
		/* the shortest lower texture on either side of its two-sided
		 * lines ("no texture" does not count) */
		uint32_t n, best = UINT32_MAX;
		const uint32_t *l = map_sector_lines(m, sec, &n);
		for (uint32_t k = 0; k < n; k++) {
			const struct map_line *ln = &m->lines[l[k]];
			if (ln->side[1] == MAP_NONE)
				continue;
			for (int sd = 0; sd < 2; sd++) {
				uint16_t t = m->sides[ln->side[sd]].bot_tex;
				uint32_t h = !t ? UINT32_MAX : t < m->num_tex_h ? m->tex_h[t] : 64;
				if (h < best)
					best = h;
			}
		}
		return best == UINT32_MAX ? g->floor_h
					  : g_clamp((int64_t)g->floor_h + (int64_t)best * FX_ONE,
						    MAP_HEIGHT_MAX);
	}
	case G_FLOOR_LOWER_CHANGE:
	default: {
		uint32_t n;
		const uint32_t *l = map_sector_lines(m, sec, &n);
		d = g_lowest_floor_around(s, sec);
		*tex = g->floor_tex;
		*special = g->special;
		/* the flat and special of the first neighbour at that height */
		for (uint32_t k = 0; k < n; k++) {
			uint32_t o = g_other_sector(m, &m->lines[l[k]], sec);
			if (o != MAP_NONE && s->w.sec[o].floor_h == d) {
				*tex = s->w.sec[o].floor_tex;
				*special = s->w.sec[o].special;
				break;
			}
		}
		return d;
	}
	}
}

int g_floor_tagged(struct sim *s, const struct map_line *l, int type)
{
	int sec = -1, rtn = 0;

	while ((sec = g_tagged(s, l->tag, sec)) >= 0) {
		struct g_mover *f;
		uint16_t tex = 0, special = 0;
		int down = type == G_FLOOR_LOWER || type == G_FLOOR_LOWEST ||
			   type == G_FLOOR_TURBO_LOWER || type == G_FLOOR_LOWER_CHANGE;

		if (g_mover_of(s, (uint32_t)sec))
			continue;
		f = g_mover_new(s, (uint32_t)sec, G_MV_FLOOR, type);
		if (!f)
			continue;
		rtn = 1;
		f->low = g_floor_dest(s, (uint32_t)sec, type, &tex, &special);
		f->tex = tex;
		f->newspecial = special;
		f->dir = down ? G_DIR_DOWN : G_DIR_UP;
		f->crush = type == G_FLOOR_RAISE_CRUSH;
		f->speed = type == G_FLOOR_TURBO_LOWER || type == G_FLOOR_RAISE_TURBO
				   ? 4 * G_FLOOR_SPEED : G_FLOOR_SPEED;
		if (type == G_FLOOR_RAISE24_CHANGE) {
			/* takes the flat and special of the line's front sector now */
			const struct g_sector *front = &s->w.sec[s->map->sides[l->side[0]].sector];
			s->w.sec[sec].floor_tex = front->floor_tex;
			s->w.sec[sec].special = front->special;
		}
	}
	return rtn;
}

/* A floor mover of sector sec to height h (the stairs' and donut's). */
static struct g_mover *g_floor_to(struct sim *s, uint32_t sec, int type, int dir, fx_t speed,
				  fx_t h)
{
	struct g_mover *f = g_mover_new(s, sec, G_MV_FLOOR, type);

	if (f) {
		f->dir = (int8_t)dir;
		f->speed = speed;
		f->low = h;
	}
	return f;
}

int g_stairs(struct sim *s, const struct map_line *l, int turbo)
{
	const struct map *m = s->map;
	fx_t speed = turbo ? 4 * G_FLOOR_SPEED : G_FLOOR_SPEED / 4;
	fx_t step = (turbo ? 16 : 8) * FX_ONE;
	int sec = -1, rtn = 0;

	while ((sec = g_tagged(s, l->tag, sec)) >= 0) {
		struct g_mover *f;
		uint16_t tex;
		fx_t h;
		int ok;

		if (g_mover_of(s, (uint32_t)sec))
			continue;
		h = g_clamp((int64_t)s->w.sec[sec].floor_h + step, MAP_HEIGHT_MAX);
		f = g_floor_to(s, (uint32_t)sec, G_FLOOR_STAIR, G_DIR_UP, speed, h);
		if (!f)
			continue;
		rtn = 1;
		f->crush = 1;
		tex = s->w.sec[sec].floor_tex;
		/* the next step: behind a two-sided line whose front faces this
		 * step, with the same flat; a busy sector still counts a step
		 * (Doom's order) but is not raised. The search for more tagged
		 * sectors then goes on from the last step, as in Doom. */
		do {
			uint32_t n;
			const uint32_t *ls = map_sector_lines(m, (uint32_t)sec, &n);
			ok = 0;
			for (uint32_t k = 0; k < n; k++) {
				const struct map_line *ln = &m->lines[ls[k]];
				uint32_t t;
				if (ln->side[1] == MAP_NONE || m->sides[ln->side[0]].sector != (uint32_t)sec)
					continue;
				t = m->sides[ln->side[1]].sector;
				if (s->w.sec[t].floor_tex != tex)
					continue;
				h = g_clamp((int64_t)h + step, MAP_HEIGHT_MAX);
				if (g_mover_of(s, t))
					continue;
				f = g_floor_to(s, t, G_FLOOR_STAIR, G_DIR_UP, speed, h);
				if (!f)
					continue;
				f->crush = 1;
				sec = (int)t;
				ok = 1;
				break;
			}
		} while (ok);
	}
	return rtn;
}

int g_donut(struct sim *s, const struct map_line *l)
{
	const struct map *m = s->map;
	int sec = -1, rtn = 0;

	while ((sec = g_tagged(s, l->tag, sec)) >= 0) {
		uint32_t n, n2, s2;
		const uint32_t *ls, *l2;

		if (g_mover_of(s, (uint32_t)sec))
			continue;
		rtn = 1;
		ls = map_sector_lines(m, (uint32_t)sec, &n);
		if (n == 0)
			break;
		s2 = g_other_sector(m, &m->lines[ls[0]], (uint32_t)sec);
		if (s2 == MAP_NONE)
			break;
		l2 = map_sector_lines(m, s2, &n2);
		for (uint32_t k = 0; k < n2; k++) {
			const struct map_line *ln = &m->lines[l2[k]];
			uint32_t s3;
			struct g_mover *f;
			if (ln->side[1] == MAP_NONE)
				continue;
			s3 = m->sides[ln->side[1]].sector;
			if (s3 == (uint32_t)sec)
				continue;
			/* the ring rises to the outside's floor and takes its flat;
			 * the pillar sinks to it */
			f = g_floor_to(s, s2, G_FLOOR_DONUT_RAISE, G_DIR_UP, G_FLOOR_SPEED / 2,
				       s->w.sec[s3].floor_h);
			if (f)
				f->tex = s->w.sec[s3].floor_tex;
			g_floor_to(s, (uint32_t)sec, G_FLOOR_LOWER, G_DIR_DOWN, G_FLOOR_SPEED / 2,
				   s->w.sec[s3].floor_h);
			break;
		}
	}
	return rtn;
}

int g_floor_tick(struct sim *s, struct g_mover *f)
{
	struct g_sector *g = &s->w.sec[f->sector];
	int res = g_plane_move(s, f->sector, f->speed, f->low, f->crush, 0, f->dir);

	if (g_dtic_now(s) && (g_dtic(s) & 7) == 0)
		g_event(s, G_EV_PLANE_MOVE, f->sector);
	if (res != G_RES_PASTDEST)
		return 0;
	if ((f->dir == G_DIR_UP && f->type == G_FLOOR_DONUT_RAISE) ||
	    (f->dir == G_DIR_DOWN && f->type == G_FLOOR_LOWER_CHANGE)) {
		g->special = f->newspecial;
		g->floor_tex = f->tex;
	}
	g_event(s, G_EV_PLAT_STOP, f->sector);
	g_mover_remove(s, f);
	return 1;
}
