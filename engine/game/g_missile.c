/*
 * g_missile: the thrower's missiles (g_game.h struct g_missile), real
 * moving objects of the sim.
 *
 * Thrown from G_MISSILE_LAUNCH above the thrower's feet towards where the
 * player stands at the throw, at G_MISSILE_SPEED along the straight line,
 * climbing or falling as the player's feet are above or below the
 * thrower's (Doom's slope: level between bodies on one floor); it does not
 * steer, so a player who moves away after the throw is missed. Each tick a
 * flying missile moves by its momentum and explodes where it was when the
 * new place would touch the player (damage, fixed at the throw), touch a
 * wall that stops it (g_wall_touch, the walls of g_move.c with the
 * missile's radius and height and no step), lie outside its sector's
 * floor and ceiling, or reach the edge of the coordinate range (g_in_range:
 * only past a broken map's lines). Its step (5.83 units) is less than its
 * radius, so it cannot pass through a wall between two ticks. Missiles
 * pass through enemies (no infighting). The throw and the explosion are
 * sound events.
 */
#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"

int g_missiles_flying(const struct sim *s)
{
	int n = 0;

	for (int i = 0; i < s->g.num_missiles; i++)
		n += s->g.ms[i].boom == 0;
	return n;
}

void g_missile_throw(struct sim *s, int i, fx_t damage)
{
	const struct g_enemy *e = &s->g.en[i];
	struct g_missile *m;
	int64_t dx = (int64_t)s->pl.x - e->x, dy = (int64_t)s->pl.y - e->y, dz, dist;
	ang_t a;

	g_cry(s, i, G_CRY_ATTACK);
	if (s->g.num_missiles >= G_MAX_MISSILES)
		return;
	m = &s->g.ms[s->g.num_missiles++];
	*m = (struct g_missile){ 0 };
	a = tab_atan2((fx_t)dy, (fx_t)dx);
	m->x = e->x;
	m->y = e->y;
	m->z = e->z + G_MISSILE_LAUNCH;
	m->momx = fx_mul(G_MISSILE_SPEED, tab_cos(a));
	m->momy = fx_mul(G_MISSILE_SPEED, tab_sin(a));
	/* Doom's slope: the player's feet over the thrower's, so on one floor
	 * it flies level at G_MISSILE_LAUNCH, chest-high on the player */
	dz = (int64_t)s->pl.z - e->z;
	dist = fx_len((fx_t)dx, (fx_t)dy);
	if (dist < G_MISSILE_SPEED)
		dist = G_MISSILE_SPEED;
	m->momz = (fx_t)(dz * G_MISSILE_SPEED / dist);
	m->damage = damage;
	m->owner = (uint8_t)i;
}

/* Whether a missile at (x, y, z) touches the player's body. */
static int g_hits_player(const struct sim *s, fx_t x, fx_t y, fx_t z)
{
	int64_t dx = (int64_t)x - s->pl.x, dy = (int64_t)y - s->pl.y;
	int64_t r = (int64_t)G_MISSILE_RADIUS + SIM_PLAYER_RADIUS;

	if (s->g.phase != G_PH_PLAY || dx <= -r || dx >= r || dy <= -r || dy >= r)
		return 0;
	return dx * dx + dy * dy < r * r && (int64_t)z < (int64_t)s->pl.z + SIM_PLAYER_HEIGHT &&
	       (int64_t)z + G_MISSILE_HEIGHT > s->pl.z;
}

static void g_explode(struct sim *s, struct g_missile *m, int how)
{
	m->boom = G_MISSILE_BOOM;
	m->momx = m->momy = m->momz = 0;
	s->g.mend = (uint8_t)how;
	g_sound_start(s, SFX_WALLHIT, m->x, m->y, G_SRC_NONE);
}

static void g_missile_fly(struct sim *s, struct g_missile *m)
{
	fx_t x = m->x + m->momx, y = m->y + m->momy, z = m->z + m->momz;
	const struct g_sector *sec;

	if (g_hits_player(s, x, y, z)) {
		g_explode(s, m, G_MEND_PLAYER);
		g_hurt_player(s, m->damage);
		return;
	}
	if (!g_in_range(x, y, G_MISSILE_RADIUS) ||
	    g_wall_touch(s, x, y, G_MISSILE_RADIUS, z, G_MISSILE_HEIGHT)) {
		g_explode(s, m, G_MEND_WALL);
		return;
	}
	sec = &s->w.sec[map_point_sector(s->map, x, y)];
	if ((int64_t)z < sec->floor_h || (int64_t)z + G_MISSILE_HEIGHT > sec->ceil_h) {
		g_explode(s, m, G_MEND_PLANE);
		return;
	}
	m->x = x;
	m->y = y;
	m->z = z;
}

void g_missiles_tick(struct sim *s)
{
	struct g_game *g = &s->g;
	int n = 0;

	for (int i = 0; i < g->num_missiles; i++) {
		struct g_missile *m = &g->ms[i];
		if (m->boom == 0)
			g_missile_fly(s, m);
		else if (--m->boom == 0)
			continue;              /* gone: not kept */
		g->ms[n++] = *m;
	}
	for (int i = n; i < g->num_missiles; i++)
		g->ms[i] = (struct g_missile){ 0 };
	g->num_missiles = (uint8_t)n;
}
