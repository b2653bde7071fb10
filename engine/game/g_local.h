/*
 * g_local: what the sim's rule files (sim.c, g_*.c, menu.c) share inside
 * the engine. Not for the app: its interface is sim.h and g_game.h.
 */
#ifndef ARCADED_ENGINE_G_LOCAL_H
#define ARCADED_ENGINE_G_LOCAL_H

#include <stdint.h>

#include "engine/game/g_sound.h"
#include "engine/game/sim.h"

struct map;
struct map_line;

/* ---- g_move.c: bodies moving with the player's collision ------------- */

/* A body: a circle of `radius` on the floor at z. self: -1 for the player,
 * else the enemy index (bodies do not block themselves). */
struct g_body {
	fx_t x, y, z;
	fx_t momx, momy;               /* the move to make this tick */
	fx_t radius;
	int self;
};

/* The opening of line l, for bodies (g_blocks) and for sight and shots
 * (g_sight.c): 0 with its highest floor and lowest ceiling, or -1 when
 * nothing passes (one-sided or ML_BLOCKING). */
int g_opening(const struct map *m, const struct map_line *l, fx_t *floor, fx_t *ceil);

/* Whether line l stops a body whose feet are at z (sim.h's rule). */
int g_blocks(const struct map *m, const struct map_line *l, fx_t z);

/* Moves b by (momx, momy) in sub-steps of at most half its radius, pushed
 * out of walls (sliding), with Doom's x-only / y-only fallback; living
 * bodies other than b block it (a step that brings two bodies closer while
 * they overlap is refused). Afterwards momx/momy are limited to what was
 * really moved when something blocked (never reversed). Returns 1 if
 * anything blocked the move. z is not changed (the caller settles it). */
int g_move(struct sim *s, struct g_body *b);

/* Whether the circle (x, y, r) overlaps a living body other than self
 * more than it did at (ox, oy). */
int g_body_blocked(const struct sim *s, int self, fx_t ox, fx_t oy, fx_t x, fx_t y, fx_t r);

/* ---- g_enemy.c ------------------------------------------------------- */

/* Fills s->g.en and s->g.pk from the things of s->map that appear at the
 * sim's difficulty. */
void g_spawn_stage(struct sim *s);
/* Puts the living enemies back at their spawn points, idle (after the
 * player lost a life). */
void g_enemies_reset(struct sim *s);
/* One tick of every enemy. */
void g_enemies_tick(struct sim *s);
/* Damage per attack of kind k at the sim's difficulty and loop (16.16). */
fx_t g_enemy_damage(const struct sim *s, int kind);
/* Chase speed per tick of kind k at the sim's difficulty and loop. */
fx_t g_enemy_speed(const struct sim *s, int kind);
/* Takes dmg (16.16) off the player's health. */
void g_hurt_player(struct sim *s, fx_t dmg);

/* ---- g_sight.c ------------------------------------------------------- */

/* Whether line l stops the straight line from (x1, y1) at height z1 to
 * (x2, y2) at z2: the segments share a point (touching counts) and l is
 * one-sided, ML_BLOCKING, or two-sided with an opening that is closed or
 * lies wholly above or wholly below both heights. */
int g_line_stops(const struct map *m, const struct map_line *l, int64_t x1, int64_t y1, fx_t z1,
		 int64_t x2, int64_t y2, fx_t z2);

/* Whether the straight line from (x1, y1) at eye height z1 to (x2, y2)
 * at z2 crosses no wall: exact integer segment tests against one-sided and
 * ML_BLOCKING lines, and two-sided lines whose opening is closed or lies
 * wholly above or wholly below both heights. Touching a wall counts as
 * crossing it. */
int g_sight(const struct map *m, fx_t x1, fx_t y1, fx_t z1, fx_t x2, fx_t y2, fx_t z2);

/* ---- g_combat.c ------------------------------------------------------ */

/* The player's shot along the view centre (g_combat.c); called on a FIRE
 * level when refire allows and there is ammo. */
void g_fire(struct sim *s);
/* Damage to enemy i; kills give score. */
void g_hurt_enemy(struct sim *s, int i, int dmg);
/* Takes the pickups the player touches (when they are of use). */
void g_pickups_tick(struct sim *s);

/* ---- the sim's RNG ---------------------------------------------------- */

/* Steps the sim's xorshift32 and returns the new value. */
static inline uint32_t g_random(struct sim *s)
{
	s->rng ^= s->rng << 13;
	s->rng ^= s->rng >> 17;
	s->rng ^= s->rng << 5;
	return s->rng;
}

/* Settings with their defaults applied. */
static inline int g_difficulty(const struct sim *s)
{
	return s->set.difficulty > 3 ? 3 : s->set.difficulty;
}

static inline int g_lives_setting(const struct sim *s)
{
	return s->set.lives == 0 ? G_LIVES_DEFAULT : s->set.lives > 9 ? 9 : s->set.lives;
}

#endif
