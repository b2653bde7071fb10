/*
 * g_combat: the player's hitscan shots (every pellet of the held weapon,
 * g_weapon.c) and pickups.
 *
 * The shot is exact integer geometry in the plan: which lines it crosses
 * comes from g_segs_cross (g_sight.c), the ray against enemy circles by
 * projection and an integer square root. In height it is a slope from the
 * eye (vertical aim, g_game.h G_PITCH_*): it hits an enemy only when its
 * height where it enters the enemy's circle lies between the enemy's feet
 * and its top (G_BODY_HEIGHT), and a two-sided line stops it when its
 * height where it crosses lies outside the line's opening (the wall's
 * upper or lower part). The slope is the pitch's, or with auto-aim the one
 * to the middle of the nearest enemy the shot can reach (g_aim).
 */
#include <stddef.h>

#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_BONUS_TICKS 10
#define G_PICKUP_RADIUS (20 * FX_ONE)

/* The shot's line in space: from the eye (x, y, z) along (cx, cy) (unit
 * direction, 16.16) rising slope units per unit. */
struct g_line3 {
	fx_t x, y, z;
	int64_t cx, cy;
	fx_t slope;
};

/* Its height at horizontal distance d. */
static fx_t g_line3_z(const struct g_line3 *r, int64_t d)
{
	return (fx_t)(r->z + ((d * r->slope) >> FX_SHIFT));
}

/*
 * The nearest line that stops the shot within horizontal distance len,
 * as that distance (len when none): one-sided and ML_BLOCKING lines, and
 * two-sided lines whose opening (now) the slope's height where it crosses
 * lies outside. Which lines it crosses is exact; the crossing's distance
 * is rounded down to the unit's 1/65536, which only places the puff and
 * the height compared (a shot grazing an opening's edge within that may
 * go either way, the same way on every build).
 */
static int64_t g_wall_along(const struct sim *s, const struct g_line3 *r, int64_t len)
{
	const struct map *m = s->map;
	int64_t dx = (len * r->cx) >> FX_SHIFT, dy = (len * r->cy) >> FX_SHIFT;
	int64_t ex = r->x + dx, ey = r->y + dy;
	int64_t lox = r->x < ex ? r->x : ex, hix = r->x > ex ? r->x : ex;
	int64_t loy = r->y < ey ? r->y : ey, hiy = r->y > ey ? r->y : ey;
	int64_t best = len;

	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		int64_t wx, wy, den, num, d;
		fx_t floor, ceil, t, z;
		if ((a->x < lox && b->x < lox) || (a->x > hix && b->x > hix) ||
		    (a->y < loy && b->y < loy) || (a->y > hiy && b->y > hiy) ||
		    !g_segs_cross(r->x, r->y, ex, ey, a, b))
			continue;
		wx = (int64_t)b->x - a->x;
		wy = (int64_t)b->y - a->y;
		den = dx * wy - dy * wx;
		num = ((int64_t)a->x - r->x) * wy - ((int64_t)a->y - r->y) * wx;
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
			if (t > FX_ONE)
				t = FX_ONE;
		}
		d = (len * t) >> FX_SHIFT;
		if (d >= best)
			continue;
		z = g_line3_z(r, d);
		if (g_opening(s, l, &floor, &ceil) == 0 && ceil > floor && z >= floor && z <= ceil)
			continue;              /* through the opening */
		best = d;
	}
	return best;
}

/* The living enemies whose circles the shot's line enters within range,
 * nearest first (ties by number): their numbers in cand, the horizontal
 * distances where the line enters in entry. Returns how many. */
static int g_ray_enemies(const struct sim *s, const struct g_line3 *r, fx_t *entry, uint8_t *cand)
{
	const struct g_game *g = &s->g;
	int64_t range = G_SHOT_RANGE;
	int n = 0;

	for (int i = 0; i < g->num_enemies; i++) {
		const struct g_enemy *e = &g->en[i];
		int64_t rad = g_kinds[e->kind].radius, vx = (int64_t)e->x - r->x,
			vy = (int64_t)e->y - r->y, proj, perp, in;
		if (e->state == G_E_DEAD || vx > range + rad || vx < -range - rad ||
		    vy > range + rad || vy < -range - rad)
			continue;
		proj = (vx * r->cx + vy * r->cy) >> FX_SHIFT;
		perp = (vx * r->cy - vy * r->cx) >> FX_SHIFT;
		if (proj <= 0 || perp >= rad || perp <= -rad)
			continue;
		in = proj - fx_isqrt64((uint64_t)(rad * rad - perp * perp));
		if (in > range)
			continue;
		entry[n] = (fx_t)(in < 0 ? 0 : in);
		cand[n++] = (uint8_t)i;
	}
	/* insertion sort: nearest first */
	for (int k = 1; k < n; k++) {
		fx_t te = entry[k];
		uint8_t tc = cand[k];
		int j = k;
		while (j > 0 && (entry[j - 1] > te || (entry[j - 1] == te && cand[j - 1] > tc))) {
			entry[j] = entry[j - 1];
			cand[j] = cand[j - 1];
			j--;
		}
		entry[j] = te;
		cand[j] = tc;
	}
	return n;
}

fx_t g_aim(const struct sim *s, ang_t a)
{
	const struct sim_player *p = &s->pl;
	struct g_line3 r = { p->x, p->y, p->viewz, tab_cos(a), tab_sin(a), p->pitch };
	fx_t entry[G_MAX_ENEMIES];
	uint8_t cand[G_MAX_ENEMIES];
	int n;

	if (s->set.free_aim)
		return p->pitch;
	n = g_ray_enemies(s, &r, entry, cand);
	for (int k = 0; k < n; k++) {
		/* the middle of its body where the line enters its circle, else
		 * (an edge or a sill hides that) near its top, then near its feet */
		static const fx_t at[] = { G_BODY_HEIGHT / 2, G_BODY_HEIGHT - 8 * FX_ONE, 8 * FX_ONE };
		const struct g_enemy *e = &s->g.en[cand[k]];
		int64_t d = entry[k] < FX_ONE ? FX_ONE : entry[k];
		for (size_t h = 0; h < sizeof(at) / sizeof(at[0]); h++) {
			int64_t rise = (int64_t)e->z + at[h] - p->viewz;
			fx_t slope;
			if (rise >= (((int64_t)G_AUTOAIM_MAX * d) >> FX_SHIFT) ||
			    rise <= -(((int64_t)G_AUTOAIM_MAX * d) >> FX_SHIFT))
				continue;      /* out of the aim's reach */
			slope = (fx_t)(rise * FX_ONE / d);  /* a multiply: rise may be negative */
			r.slope = slope;
			if (g_wall_along(s, &r, d) == d)
				return slope;
		}
	}
	return p->pitch;
}

/* One ray of a shot from the player's eye along angle a rising by slope:
 * it hurts the nearest living enemy whose circle it enters within range at
 * a height between the enemy's feet and top, before any wall stops it,
 * else it ends on the nearest wall or at its range. Sets *x, *y, *z to
 * where it ended and returns enum g_shot. The lines it reached get their
 * gun specials. */
static int g_trace(const struct sim *s, ang_t a, fx_t slope, fx_t *x, fx_t *y, fx_t *z, int *who)
{
	const struct sim_player *p = &s->pl;
	struct g_line3 r = { p->x, p->y, p->viewz, tab_cos(a), tab_sin(a), slope };
	int64_t range = G_SHOT_RANGE, wall = g_wall_along(s, &r, range);
	fx_t entry[G_MAX_ENEMIES];
	uint8_t cand[G_MAX_ENEMIES];
	int n = g_ray_enemies(s, &r, entry, cand);

	for (int k = 0; k < n && entry[k] < wall; k++) {
		const struct g_enemy *e = &s->g.en[cand[k]];
		fx_t hz = g_line3_z(&r, entry[k]);
		if (hz < e->z || hz > e->z + G_BODY_HEIGHT)
			continue;              /* over its head or under its feet */
		*x = (fx_t)(p->x + ((entry[k] * r.cx) >> FX_SHIFT));
		*y = (fx_t)(p->y + ((entry[k] * r.cy) >> FX_SHIFT));
		*z = hz;
		*who = cand[k];
		return G_SHOT_ENEMY;
	}
	*x = (fx_t)(p->x + ((wall * r.cx) >> FX_SHIFT));
	*y = (fx_t)(p->y + ((wall * r.cy) >> FX_SHIFT));
	*z = g_line3_z(&r, wall);
	*who = -1;
	return wall < range ? G_SHOT_WALL : G_SHOT_MISS;
}

/* g_trace, then its effects: the lines reached get their gun specials,
 * the enemy hit takes dmg. */
static int g_ray(struct sim *s, ang_t a, fx_t slope, int dmg, fx_t *x, fx_t *y, fx_t *z)
{
	int who, r = g_trace(s, a, slope, x, y, z, &who);

	g_shoot_lines(s, s->pl.x, s->pl.y, *x, *y);
	if (who >= 0)
		g_hurt_enemy(s, who, dmg);
	return r;
}

int g_shot_reaches(const struct sim *s, int i)
{
	const struct g_enemy *e = &s->g.en[i];
	ang_t a = tab_atan2(e->y - s->pl.y, e->x - s->pl.x);
	fx_t x, y, z;
	int who;

	return g_trace(s, a, g_aim(s, a), &x, &y, &z, &who) == G_SHOT_ENEMY && who == i;
}

void g_fire(struct sim *s)
{
	struct g_game *g = &s->g;
	struct sim_player *p = &s->pl;
	const struct g_weapon_info *w = &g_weapons[p->weapon < G_WEAPONS ? p->weapon : 0];
	int half = w->pellets / 2, hit = 0;
	fx_t slope = g_aim(s, p->angle);

	p->ammo = (uint16_t)(p->ammo - w->ammo);
	p->refire = w->refire;
	g->shot_t = 0;
	g_noise(s);
	g_sound_play(s, w->sfx, G_SRC_WEAPON);
	/* the pellets from left to right, all at the centre's slope; the HUD
	 * and the puff show the first that hit an enemy, else the middle one */
	for (int k = 0; k < w->pellets; k++) {
		ang_t a = p->angle + (ang_t)((int64_t)(half - k) * w->step);
		fx_t x, y, z;
		int r = g_ray(s, a, slope, w->damage, &x, &y, &z);
		if ((r == G_SHOT_ENEMY && !hit) || (k == half && !hit)) {
			g->shot = (uint8_t)r;
			/* a miss ends at the full range, which near the
			 * edge of a map may lie past the coordinate range */
			g->shot_x = g_clamp(x, MAP_COORD_MAX);
			g->shot_y = g_clamp(y, MAP_COORD_MAX);
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
