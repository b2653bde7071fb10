/*
 * g_enemy: the enemy kinds, spawning them (and the pickups) from a stage
 * map's things, and their behaviour: wake on sight, chase, attack.
 *
 * An enemy wakes when it sees the player within its sight distance (idle
 * enemies look every 8 ticks, staggered by index), when it is shot, or
 * when it hears the player's shot (g_noise: Doom's sound flood through
 * open two-sided lines, stopped by closed doors and by a second
 * sound-blocking line) unless it is deaf (the map's ambush flag). Awake,
 * it attacks while the player's centre is within its range and in line of
 * sight: the first attack `reaction` ticks after it came into range, then
 * one every `period` ticks, each taking `damage` (scaled by difficulty).
 * A kind with a wind-up (the grunt: G_GRUNT_WINDUP ticks) telegraphs each
 * attack: its wind-up cry starts `windup` ticks before it, and the
 * renderer shows the aiming frame for those ticks (g_enemy_winding); the
 * player who leaves its range or sight before the end is not shot (the
 * grunt goes back to the chase and starts over, as Doom's zombieman
 * turns to its target and shoots only at the end of its aim frames).
 * Otherwise it walks straight at the player with the player's own
 * collision (g_move); when a wall stops it, it walks a random detour
 * (left or right of its heading) for 16..31 ticks. Sentries never move.
 * A thrower's attack is a missile (g_missile.c), moved after the enemies
 * each tick.
 */
#include <stddef.h>

#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_IDLE_LOOK 8                  /* idle enemies look every 8 ticks */
#define G_FLASH_TICKS 8

/* Per difficulty 0..3: percent of the kinds' damage and speed. Each loop
 * through all stages adds 25% damage and 10% speed (speed capped at 200%);
 * the stage clock's hurry up adds G_HURRY_SPEED% after the cap. */
static const uint8_t g_damage_pct[4] = { 50, 100, 150, 200 };
static const uint8_t g_speed_pct[4] = { 80, 100, 115, 130 };

fx_t g_enemy_damage(const struct sim *s, int kind)
{
	int64_t pct = g_damage_pct[g_difficulty(s)] + 25 * (int64_t)s->g.loop;

	return (fx_t)((int64_t)g_kinds[kind].damage * FX_ONE * pct / 100);
}

fx_t g_enemy_speed(const struct sim *s, int kind)
{
	int64_t pct = g_speed_pct[g_difficulty(s)] + 10 * (int64_t)s->g.loop;

	if (pct > 200)
		pct = 200;
	if (g_pace_hurry(s))
		pct += G_HURRY_SPEED;
	return (fx_t)((int64_t)g_kinds[kind].speed * pct / 100);
}

/* A flyer's height z kept within its sector's floor and ceiling. */
static fx_t g_fly_clamp(const struct sim *s, const struct g_enemy *e, int64_t z)
{
	const struct g_sector *sec = &s->w.sec[e->sector];
	int64_t hi = (int64_t)sec->ceil_h - G_BODY_HEIGHT;

	if (z > hi)
		z = hi;
	if (z < sec->floor_h)
		z = sec->floor_h;
	return (fx_t)z;
}

/* Its sector, and its feet on the floor (a flyer: within the sector). */
static void g_settle_enemy(const struct sim *s, struct g_enemy *e)
{
	e->sector = map_point_sector(s->map, e->x, e->y);
	if (g_kinds[e->kind].fly)
		e->z = g_fly_clamp(s, e, e->z);
	else
		e->z = s->w.sec[e->sector].floor_h;
}

/* At its spawn spot's height: a flyer G_FLY_SPAWN over the floor. */
static void g_place_enemy(const struct sim *s, struct g_enemy *e)
{
	g_settle_enemy(s, e);
	if (g_kinds[e->kind].fly)
		e->z = g_fly_clamp(s, e, (int64_t)s->w.sec[e->sector].floor_h + G_FLY_SPAWN);
}

/* A flyer climbs or sinks towards G_FLY_ABOVE over the player's feet. */
static void g_fly_height(const struct sim *s, struct g_enemy *e)
{
	int64_t want = (int64_t)s->pl.z + G_FLY_ABOVE, z = e->z;

	if (want > z + G_FLY_CLIMB)
		z += G_FLY_CLIMB;
	else if (want < z - G_FLY_CLIMB)
		z -= G_FLY_CLIMB;
	else
		z = want;
	e->z = g_fly_clamp(s, e, z);
}

void g_spawn_stage(struct sim *s)
{
	const struct map *m = s->map;
	struct g_game *g = &s->g;
	int d = g_difficulty(s);

	g->num_enemies = 0;
	g->num_pickups = 0;
	g->num_missiles = 0;
	g->mend = G_MEND_NONE;
	for (uint32_t i = 0; i < m->num_things; i++) {
		const struct map_thing *t = &m->things[i];
		struct g_thing_info ti;

		g_thing_info(t->type, &ti);
		if (!g_thing_at_difficulty(t->flags, d))
			continue;
		if (ti.cls == G_C_ENEMY && g->num_enemies < G_MAX_ENEMIES) {
			struct g_enemy *e = &g->en[g->num_enemies++];
			*e = (struct g_enemy){ 0 };
			e->x = e->sx = t->x;
			e->y = e->sy = t->y;
			e->angle = e->sangle = t->angle;
			e->type = t->type;
			e->kind = ti.kind;
			e->state = G_E_IDLE;
			e->health = g_kinds[ti.kind].health;
			e->ambush = (t->flags & G_TF_AMBUSH) != 0;
			g_place_enemy(s, e);
		} else if (ti.cls == G_C_PICKUP && g->num_pickups < G_MAX_PICKUPS) {
			struct g_pickup *p = &g->pk[g->num_pickups++];
			*p = (struct g_pickup){ 0 };
			p->x = t->x;
			p->y = t->y;
			p->z = s->w.sec[map_point_sector(m, t->x, t->y)].floor_h;
			p->type = t->type;
			p->kind = ti.kind;
			p->amount = ti.amount;
			s->w.items_total = (uint16_t)(s->w.items_total + ti.counted);
		}
	}
	g->alive = g->num_enemies;
}

void g_enemies_reset(struct sim *s)
{
	struct g_game *g = &s->g;

	/* the missiles of the last life are gone */
	for (int i = 0; i < g->num_missiles; i++)
		g->ms[i] = (struct g_missile){ 0 };
	g->num_missiles = 0;
	for (int i = 0; i < g->num_enemies; i++) {
		struct g_enemy *e = &g->en[i];
		if (e->state == G_E_DEAD)
			continue;
		e->x = e->sx;
		e->y = e->sy;
		e->angle = e->sangle;
		e->state = G_E_IDLE;
		e->timer = 0;
		e->anim = 0;
		e->stuck = 0;
		e->flash = 0;
		g_place_enemy(s, e);
	}
}

static uint64_t g_dist2(const struct sim *s, const struct g_enemy *e)
{
	int64_t dx = (int64_t)s->pl.x - e->x, dy = (int64_t)s->pl.y - e->y;

	return (uint64_t)(dx * dx) + (uint64_t)(dy * dy);
}

static int g_within(const struct sim *s, const struct g_enemy *e, fx_t dist)
{
	return g_dist2(s, e) <= (uint64_t)((int64_t)dist * dist);
}

static int g_sees(const struct sim *s, const struct g_enemy *e)
{
	return g_sight(s, e->x, e->y, e->z + g_kinds[e->kind].eye, s->pl.x, s->pl.y,
		       s->pl.viewz);
}

static void g_set_state(struct g_enemy *e, int st, uint16_t timer)
{
	e->state = (uint8_t)st;
	e->timer = timer;
	e->anim = 0;
}

/* Walks towards the player (or along the detour). */
static void g_chase(struct sim *s, int i)
{
	struct g_enemy *e = &s->g.en[i];
	fx_t speed = g_enemy_speed(s, e->kind);
	ang_t head = tab_atan2(s->pl.y - e->y, s->pl.x - e->x);
	struct g_body b;

	if (speed == 0)
		return;
	if (e->stuck) {
		head = e->wander;
		e->stuck--;
	} else if (g_kinds[e->kind].fly && g_within(s, e, G_FLY_ORBIT)) {
		/* circling in: the slant turns the straight line into a spiral */
		head += (i & 1) ? (ang_t)0 - G_FLY_SLANT : G_FLY_SLANT;
	}
	e->angle = head;
	b.x = e->x;
	b.y = e->y;
	b.z = e->z;
	b.momx = fx_mul(speed, tab_cos(head));
	b.momy = fx_mul(speed, tab_sin(head));
	b.radius = g_kinds[e->kind].radius;
	b.self = i;
	if (g_move(s, &b)) {
		int64_t mx = (int64_t)b.x - e->x, my = (int64_t)b.y - e->y;
		/* a door in the way: Doom's monsters open the plain ones */
		g_enemy_bump(s, i, b.x, b.y);
		/* less than half the intended step: take a detour */
		if ((uint64_t)(mx * mx + my * my) * 4 < (uint64_t)((int64_t)speed * speed)) {
			uint32_t r = g_random(s);
			e->wander = head + ((r & 1) ? ANG90 : (ang_t)0 - ANG90);
			e->stuck = (uint8_t)(16 + ((r >> 1) & 15));
		}
	}
	{
		fx_t ox = e->x, oy = e->y;
		e->x = b.x;
		e->y = b.y;
		g_settle_enemy(s, e);
		g_cross(s, i, ox, oy, e->x, e->y, b.radius);
	}
}

static void g_enemy_tick(struct sim *s, int i)
{
	struct g_enemy *e = &s->g.en[i];
	const struct g_kind_info *k = &g_kinds[e->kind];
	int in_range;

	if (e->anim < UINT16_MAX)
		e->anim++;
	if (e->flash)
		e->flash--;
	switch (e->state) {
	case G_E_IDLE:
		if ((s->tick + (uint32_t)i) % G_IDLE_LOOK == 0 && g_within(s, e, k->sight) &&
		    g_sees(s, e)) {
			g_set_state(e, G_E_CHASE, 0);
			g_cry(s, i, G_CRY_SIGHT);
		}
		return;
	case G_E_PAIN:
		if (e->timer)
			e->timer--;
		if (e->timer == 0)
			g_set_state(e, G_E_CHASE, 0);
		return;
	case G_E_DEAD:
		return;
	default:
		break;
	}
	if (k->fly)
		g_fly_height(s, e);
	in_range = g_within(s, e, k->range) && g_sees(s, e);
	if (!in_range) {
		if (e->state == G_E_ATTACK)
			g_set_state(e, G_E_CHASE, 0);
		g_chase(s, i);
		return;
	}
	e->angle = tab_atan2(s->pl.y - e->y, s->pl.x - e->x);
	if (e->state != G_E_ATTACK) {
		g_set_state(e, G_E_ATTACK, k->reaction);
		return;
	}
	if (e->timer)
		e->timer--;
	/* the wind-up: its cry as the last `windup` ticks start; the shot at
	 * their end only if the player is still in range and sight (above:
	 * breaking either sends the enemy back to the chase, no shot) */
	if (k->windup && e->timer == k->windup)
		g_cry(s, i, G_CRY_WINDUP);
	if (e->timer == 0) {
		e->timer = k->period;
		e->flash = G_FLASH_TICKS;
		if (e->kind == G_THROWER) {
			g_missile_throw(s, i, g_enemy_damage(s, e->kind));
			return;
		}
		g_cry(s, i, G_CRY_ATTACK);
		g_hurt_player(s, g_enemy_damage(s, e->kind));
	}
}

#define G_ML_SOUNDBLOCK 0x0040

/* Sectors sound reaches from sec over open two-sided lines: heard[] is 1
 * for those reached without crossing a sound-blocking line, 2 for those
 * behind one (sound crosses one, not two). */
static void g_flood(const struct sim *s, uint32_t start, uint8_t *heard, uint32_t *queue)
{
	const struct map *m = s->map;

	for (int pass = 1; pass <= 2; pass++) {
		uint32_t head = 0, tail = 0;
		if (pass == 1) {
			heard[start] = 1;
			queue[tail++] = start;
		} else {
			for (uint32_t i = 0; i < s->w.num_sectors; i++)
				if (heard[i] == 2)
					queue[tail++] = i;
		}
		while (head < tail) {
			uint32_t sec = queue[head++], n;
			const uint32_t *ls = map_sector_lines(m, sec, &n);
			for (uint32_t k = 0; k < n; k++) {
				const struct map_line *l = &m->lines[ls[k]];
				uint32_t o = g_other_sector(m, l, sec);
				const struct g_sector *a, *b;
				if (o == MAP_NONE || heard[o])
					continue;
				a = &s->w.sec[sec];
				b = &s->w.sec[o];
				if ((a->ceil_h < b->ceil_h ? a->ceil_h : b->ceil_h) -
				    (int64_t)(a->floor_h > b->floor_h ? a->floor_h : b->floor_h) <= 0)
					continue;      /* a closed door */
				if (l->flags & G_ML_SOUNDBLOCK) {
					if (pass == 1)
						heard[o] = 2;
					continue;
				}
				heard[o] = (uint8_t)pass;
				queue[tail++] = o;
			}
		}
	}
}

void g_noise(struct sim *s)
{
	uint8_t heard[G_MAX_SECTORS] = { 0 };
	uint32_t queue[G_MAX_SECTORS];

	g_flood(s, s->pl.sector, heard, queue);
	for (int i = 0; i < s->g.num_enemies; i++) {
		struct g_enemy *e = &s->g.en[i];
		if (e->state == G_E_IDLE && !e->ambush && heard[e->sector]) {
			g_set_state(e, G_E_CHASE, 0);
			g_cry(s, i, G_CRY_SIGHT);
		}
	}
}

/* A dead flyer falls to the floor, in every phase (the last kill's
 * corpse falls while the stage is cleared). */
static void g_fall(struct sim *s, struct g_enemy *e)
{
	fx_t floor = s->w.sec[e->sector].floor_h;

	if (e->state != G_E_DEAD || !g_kinds[e->kind].fly || e->z <= floor)
		return;
	e->z = e->z - G_FLY_FALL < floor ? floor : e->z - G_FLY_FALL;
}

void g_enemies_tick(struct sim *s)
{
	for (int i = 0; i < s->g.num_enemies; i++) {
		g_fall(s, &s->g.en[i]);
		if (s->g.phase == G_PH_PLAY)
			g_enemy_tick(s, i);
	}
	if (s->g.phase == G_PH_PLAY)
		g_missiles_tick(s);
}

int g_enemy_winding(const struct g_enemy *e)
{
	const struct g_kind_info *k = &g_kinds[e->kind % G_KINDS];

	return e->state == G_E_ATTACK && k->windup && e->timer > 0 && e->timer <= k->windup;
}
