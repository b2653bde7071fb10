/*
 * g_tele: teleporters (Doom's EV_Teleport). Crossing a teleport line from
 * its front moves the body to the teleport destination thing (type 14,
 * present at the game's difficulty) in the first tagged sector that has
 * one, facing the destination's angle, its momentum gone. The player is
 * held still for Doom's 18 tics and kills the enemies standing there (a
 * telefrag); an enemy does not teleport onto another body.
 */
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_TELE_DEST 14                 /* Doom's teleport destination thing */
#define G_TELE_FREEZE G_TICS(18)
#define G_TELEFRAG 10000

/* The destination thing in the sectors tagged `tag`, or -1. */
static int g_tele_dest(const struct sim *s, uint16_t tag)
{
	const struct map *m = s->map;
	int sec = -1;

	while ((sec = g_tagged(s, tag, sec)) >= 0)
		for (uint32_t i = 0; i < m->num_things; i++) {
			const struct map_thing *t = &m->things[i];
			if (t->type == G_TELE_DEST && g_thing_at_difficulty(t->flags, g_difficulty(s)) &&
			    map_point_sector(m, t->x, t->y) == (uint32_t)sec)
				return (int)i;
		}
	return -1;
}

/* Whether the boxes of two bodies overlap (Doom's test: the sum of the
 * radii along each axis). */
static int g_boxes_meet(fx_t x1, fx_t y1, fx_t r1, fx_t x2, fx_t y2, fx_t r2)
{
	int64_t d = (int64_t)r1 + r2, dx = (int64_t)x1 - x2, dy = (int64_t)y1 - y2;

	return dx < d && dx > -d && dy < d && dy > -d;
}

int g_teleport(struct sim *s, const struct map_line *l, int side, int who)
{
	const struct map_thing *t;
	int d;

	if (side == 1)
		return 0;
	d = g_tele_dest(s, l->tag);
	if (d < 0)
		return 0;
	t = &s->map->things[d];
	if (who == G_WHO_PLAYER) {
		struct sim_player *p = &s->pl;
		for (int i = 0; i < s->g.num_enemies; i++) {
			const struct g_enemy *e = &s->g.en[i];
			if (e->state != G_E_DEAD &&
			    g_boxes_meet(t->x, t->y, SIM_PLAYER_RADIUS, e->x, e->y, g_kinds[e->kind].radius))
				g_hurt_enemy(s, i, G_TELEFRAG);
		}
		p->x = t->x;
		p->y = t->y;
		p->angle = t->angle;
		p->momx = p->momy = 0;
		p->sector = map_point_sector(s->map, p->x, p->y);
		p->z = s->w.sec[p->sector].floor_h;
		p->viewz = p->z + SIM_VIEW_HEIGHT;
		p->freeze = G_TELE_FREEZE;
	} else {
		struct g_enemy *e = &s->g.en[who];
		fx_t r = g_kinds[e->kind].radius;
		if (s->g.phase == G_PH_PLAY &&
		    g_boxes_meet(t->x, t->y, r, s->pl.x, s->pl.y, SIM_PLAYER_RADIUS))
			return 0;
		for (int i = 0; i < s->g.num_enemies; i++) {
			const struct g_enemy *o = &s->g.en[i];
			if (i != who && o->state != G_E_DEAD &&
			    g_boxes_meet(t->x, t->y, r, o->x, o->y, g_kinds[o->kind].radius))
				return 0;
		}
		e->x = t->x;
		e->y = t->y;
		e->angle = t->angle;
		e->stuck = 0;
		e->sector = map_point_sector(s->map, e->x, e->y);
		e->z = s->w.sec[e->sector].floor_h;
	}
	g_event(s, G_EV_TELEPORT, map_point_sector(s->map, t->x, t->y));
	return 1;
}
