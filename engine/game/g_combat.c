/*
 * g_combat: the player's hitscan shots (every pellet of the held weapon,
 * g_weapon.c) and pickups.
 *
 * The shot is exact integer geometry: which walls stop it comes from
 * g_line_stops (g_sight.c), the ray against enemy circles by projection and
 * an integer square root.
 */
#include <stddef.h>

#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_BONUS_TICKS 10
#define G_PICKUP_RADIUS (20 * FX_ONE)

/*
 * The nearest wall along the ray from (px, py) by (dx, dy) (the whole
 * range), as a fraction t of the ray in 16.16 (FX_ONE when none). The
 * fraction only places the puff, so its rounding does not matter; which
 * walls block is decided exactly.
 */
static fx_t g_wall_along(const struct sim *s, fx_t px, fx_t py, fx_t pz, int64_t dx, int64_t dy)
{
	const struct map *m = s->map;
	int64_t ex = px + dx, ey = py + dy;
	fx_t best = FX_ONE;

	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		int64_t wx, wy, den, num;
		fx_t t;
		if (!g_line_stops(s, l, px, py, pz, ex, ey, pz))
			continue;
		wx = (int64_t)b->x - a->x;
		wy = (int64_t)b->y - a->y;
		den = dx * wy - dy * wx;
		num = ((int64_t)a->x - px) * wy - ((int64_t)a->y - py) * wx;
		if (den < 0) {
			den = -den;
			num = -num;
		}
		if (den == 0 || num <= 0) {
			t = 0;                 /* collinear or touching at the start */
		} else {
			while (den >= ((int64_t)1 << 46)) {
				den >>= 1;
				num >>= 1;
			}
			t = (fx_t)(num * FX_ONE / (den ? den : 1));
		}
		if (t < best)
			best = t;
	}
	return best;
}

/* One ray of a shot from the player's eye along angle a: it hurts the
 * nearest living enemy whose circle it enters within range and that no
 * wall hides by dmg, else it ends on the nearest wall or at its range.
 * Sets *x, *y, *z to where it ended and returns enum g_shot. The lines it
 * reached get their gun specials. */
static int g_ray(struct sim *s, ang_t a, int dmg, fx_t *x, fx_t *y, fx_t *z)
{
	struct g_game *g = &s->g;
	const struct sim_player *p = &s->pl;
	int64_t cx = tab_cos(a), cy = tab_sin(a);
	int64_t range = G_SHOT_RANGE;
	fx_t entry[G_MAX_ENEMIES];
	uint8_t cand[G_MAX_ENEMIES];
	int n = 0;

	/* every living enemy whose circle the ray enters within range */
	for (int i = 0; i < g->num_enemies; i++) {
		const struct g_enemy *e = &g->en[i];
		int64_t r = g_kinds[e->kind].radius, vx = (int64_t)e->x - p->x,
			vy = (int64_t)e->y - p->y, proj, perp, in;
		if (e->state == G_E_DEAD || vx > range + r || vx < -range - r || vy > range + r ||
		    vy < -range - r)
			continue;
		proj = (vx * cx + vy * cy) >> FX_SHIFT;
		perp = (vx * cy - vy * cx) >> FX_SHIFT;
		if (proj <= 0 || perp >= r || perp <= -r)
			continue;
		in = proj - fx_isqrt64((uint64_t)(r * r - perp * perp));
		if (in > range)
			continue;
		entry[n] = (fx_t)(in < 0 ? 0 : in);
		cand[n++] = (uint8_t)i;
	}
	/* nearest first: the first one no wall hides is hit */
	while (n > 0) {
		int best = 0;
		for (int k = 1; k < n; k++)
			if (entry[k] < entry[best] || (entry[k] == entry[best] && cand[k] < cand[best]))
				best = k;
		const struct g_enemy *e = &g->en[cand[best]];
		fx_t hx = (fx_t)(p->x + ((entry[best] * cx) >> FX_SHIFT));
		fx_t hy = (fx_t)(p->y + ((entry[best] * cy) >> FX_SHIFT));
		fx_t hz = e->z + g_kinds[e->kind].eye;
		if (g_sight(s, p->x, p->y, p->viewz, hx, hy, hz)) {
			*x = hx;
			*y = hy;
			*z = hz;
			g_shoot_lines(s, p->x, p->y, hx, hy);
			g_hurt_enemy(s, cand[best], dmg);
			return G_SHOT_ENEMY;
		}
		entry[best] = entry[n - 1];
		cand[best] = cand[n - 1];
		n--;
	}
	{
		int64_t dx = (range * cx) >> FX_SHIFT, dy = (range * cy) >> FX_SHIFT;
		fx_t t = g_wall_along(s, p->x, p->y, p->viewz, dx, dy);
		*x = (fx_t)(p->x + ((dx * t) >> FX_SHIFT));
		*y = (fx_t)(p->y + ((dy * t) >> FX_SHIFT));
		*z = p->viewz;
		g_shoot_lines(s, p->x, p->y, *x, *y);
		return t < FX_ONE ? G_SHOT_WALL : G_SHOT_MISS;
	}
}

void g_fire(struct sim *s)
{
	struct g_game *g = &s->g;
	struct sim_player *p = &s->pl;
	const struct g_weapon_info *w = &g_weapons[p->weapon < G_WEAPONS ? p->weapon : 0];
	int half = w->pellets / 2, hit = 0;

	p->ammo = (uint16_t)(p->ammo - w->ammo);
	p->refire = w->refire;
	g->shot_t = 0;
	g_noise(s);
	g_sound_play(s, w->sfx, G_SRC_WEAPON);
	/* the pellets from left to right; the HUD and the puff show the first
	 * that hit an enemy, else the middle one */
	for (int k = 0; k < w->pellets; k++) {
		ang_t a = p->angle + (ang_t)((int64_t)(half - k) * w->step);
		fx_t x, y, z;
		int r = g_ray(s, a, w->damage, &x, &y, &z);
		if ((r == G_SHOT_ENEMY && !hit) || (k == half && !hit)) {
			g->shot = (uint8_t)r;
			g->shot_x = x;
			g->shot_y = y;
			g->shot_z = z;
			hit = r == G_SHOT_ENEMY;
		}
	}
	if (g->shot == G_SHOT_WALL)
		g_sound_start(s, SFX_WALLHIT, g->shot_x, g->shot_y, G_SRC_PUFF);
}

void g_pickups_tick(struct sim *s)
{
	struct g_game *g = &s->g;
	struct sim_player *p = &s->pl;
	int64_t reach = SIM_PLAYER_RADIUS + G_PICKUP_RADIUS;

	for (int i = 0; i < g->num_pickups; i++) {
		struct g_pickup *k = &g->pk[i];
		int64_t dx = (int64_t)k->x - p->x, dy = (int64_t)k->y - p->y;
		struct g_thing_info ti;
		if (k->taken || dx >= reach || dx <= -reach || dy >= reach || dy <= -reach ||
		    dx * dx + dy * dy >= reach * reach)
			continue;
		g_thing_info(k->type, &ti);
		switch (k->kind) {
		case G_P_HEALTH: {
			int64_t h = p->health + (int64_t)k->amount * FX_ONE;
			/* Doom's counted items (bonuses, spheres) are always taken */
			if (p->health >= G_HEALTH_MAX * FX_ONE && !ti.counted)
				continue;
			p->health = (fx_t)(h > G_HEALTH_MAX * FX_ONE ? G_HEALTH_MAX * FX_ONE : h);
			break;
		}
		case G_P_AMMO: {
			uint32_t a = (uint32_t)p->ammo + k->amount;
			if (p->ammo >= G_AMMO_MAX)
				continue;
			p->ammo = (uint16_t)(a > G_AMMO_MAX ? G_AMMO_MAX : a);
			break;
		}
		case G_P_WEAPON:
			if (!g_weapon_give(s, ti.weapon, k->amount))
				continue;
			break;
		case G_P_KEY:
			s->w.keys = (uint8_t)(s->w.keys | (k->amount & 0x3f));
			g_message(s, G_MSG_KEY);
			g_event(s, G_EV_KEY, MAP_NONE);
			break;
		case G_P_SUIT:
			s->w.suit = k->amount;
			break;
		default:
			break;
		}
		if (ti.counted && s->w.items < UINT16_MAX)
			s->w.items++;
		if (k->kind != G_P_KEY)
			g_event(s, G_EV_ITEM, MAP_NONE);
		k->taken = 1;
		p->bonus = G_BONUS_TICKS;
		g_sound_play(s, SFX_PICKUP, G_SRC_ITEM);
	}
}
