/*
 * g_local: what the sim's rule files (sim.c, g_*.c, menu.c) share inside
 * the engine. Not for the app: its interface is sim.h and g_game.h.
 */
#ifndef ARCADED_ENGINE_G_LOCAL_H
#define ARCADED_ENGINE_G_LOCAL_H

#include <stdint.h>

#include "engine/game/g_sound.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"

/* ---- g_move.c: bodies moving with the player's collision ------------- */

/* A body: a circle of `radius` on the floor at z. self: -1 for the player,
 * else the enemy index (bodies do not block themselves). */
struct g_body {
	fx_t x, y, z;
	fx_t momx, momy;               /* the move to make this tick */
	fx_t radius;
	int self;
};

/* The opening of line l of the current map with its sectors' heights now
 * (s->w), for bodies (g_blocks) and for sight and shots (g_sight.c): 0
 * with its highest floor and lowest ceiling, or -1 when nothing passes
 * (one-sided or ML_BLOCKING). */
int g_opening(const struct sim *s, const struct map_line *l, fx_t *floor, fx_t *ceil);

/* Whether line l stops a body whose feet are at z (sim.h's rule). */
int g_blocks(const struct sim *s, const struct map_line *l, fx_t z);

/* Whether the circle (x, y, r) of a body with its bottom at z, `height`
 * tall, that climbs no step (a missile), overlaps a line that stops it:
 * one-sided, ML_BLOCKING, or two-sided with an opening whose floor is above
 * z or whose ceiling is below z + height. */
int g_wall_touch(const struct sim *s, fx_t x, fx_t y, fx_t r, fx_t z, fx_t height);

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
/* One tick of every enemy (in play; in other phases only a dead flyer
 * falls) and of the missiles (in play). */
void g_enemies_tick(struct sim *s);
/* The player's shot is heard: idle enemies that are not deaf (ambush) in
 * the sectors the sound reaches wake. */
void g_noise(struct sim *s);
/* Damage per attack of kind k at the sim's difficulty and loop (16.16). */
fx_t g_enemy_damage(const struct sim *s, int kind);
/* Chase speed per tick of kind k at the sim's difficulty and loop. */
fx_t g_enemy_speed(const struct sim *s, int kind);

/* ---- g_missile.c ----------------------------------------------------- */

/* Enemy i throws a missile at the player (its attack sound) that does
 * damage (16.16) where it hits. No missile when all G_MAX_MISSILES are in
 * use. */
void g_missile_throw(struct sim *s, int i, fx_t damage);
/* One tick of every missile: flying ones move and may explode, exploding
 * ones count down and are removed. */
void g_missiles_tick(struct sim *s);
/* Flying missiles (not those exploding). */
int g_missiles_flying(const struct sim *s);

/* ---- g_hurt.c: damage ----------------------------------------------- */

/* Takes dmg (16.16) off the player's health (in phase PLAY only); at 0 the
 * player dies (phase DEAD). */
void g_hurt_player(struct sim *s, fx_t dmg);
/* Damage to enemy i; kills give score (and its drop, g_drop). A hit may
 * make it flinch (PAIN) or wake it. */
void g_hurt_enemy(struct sim *s, int i, int dmg);

/* ---- g_drop.c: what a dying enemy drops ----------------------------- */

/* The Doom thing type an enemy of Doom type `enemy` drops, 0 none. */
uint16_t g_drop_type(uint16_t enemy);
/* Enemy i's drop, a new pickup where it stands: its index in s->g.pk, or
 * -1 when it drops nothing or the pickups are full. */
int g_drop(struct sim *s, int i);

/* Enemy i's cry (G_CRY_*), where it stands; its next cry cuts this one. */
enum { G_CRY_SIGHT, G_CRY_ATTACK, G_CRY_PAIN, G_CRY_DEATH, G_CRY_WINDUP, G_CRIES };
void g_cry(struct sim *s, int i, int cry);

/* ---- g_sight.c ------------------------------------------------------- */

/* Whether line l stops the straight line from (x1, y1) at height z1 to
 * (x2, y2) at z2: the segments share a point (touching counts) and l is
 * one-sided, ML_BLOCKING, or two-sided with an opening (now) that is closed
 * or lies wholly above or wholly below both heights. */
int g_line_stops(const struct sim *s, const struct map_line *l, int64_t x1, int64_t y1, fx_t z1,
		 int64_t x2, int64_t y2, fx_t z2);

/* Whether the closed segments (p1x, p1y)-(p2x, p2y) and q1-q2 share a
 * point (exact). */
int g_segs_cross(int64_t p1x, int64_t p1y, int64_t p2x, int64_t p2y, const struct map_vertex *q1,
		 const struct map_vertex *q2);

/* Whether the straight line from (x1, y1) at eye height z1 to (x2, y2)
 * at z2 crosses no wall: exact integer segment tests against one-sided and
 * ML_BLOCKING lines, and two-sided lines whose opening is closed or lies
 * wholly above or wholly below both heights. Touching a wall counts as
 * crossing it. */
int g_sight(const struct sim *s, fx_t x1, fx_t y1, fx_t z1, fx_t x2, fx_t y2, fx_t z2);

/* ---- g_combat.c ------------------------------------------------------ */

/* The player's shot with the held weapon: its pellets fanned about the
 * view centre (g_combat.c); called on a FIRE level when g_weapon_can_fire. */
void g_fire(struct sim *s);
/* The slope a shot along angle a takes from the eye (g_combat.c): with
 * auto-aim (set.free_aim 0) the one to the middle of the nearest enemy in
 * its line that it can reach within G_AUTOAIM_MAX, else the pitch's. */
fx_t g_aim(const struct sim *s, ang_t a);
/* Whether a shot now, along the line to enemy i's centre with the slope
 * g_aim gives, would hit enemy i (for test tools that pick targets). */
int g_shot_reaches(const struct sim *s, int i);
/* Takes the pickups the player touches (when they are of use). */
void g_pickups_tick(struct sim *s);

/* ---- g_weapon.c ------------------------------------------------------ */

/* Whether the held weapon may fire now: refire run out and at least its
 * ammo per shot. */
int g_weapon_can_fire(const struct sim *s);
/* The weapon-change press: the next weapon the player owns after the one
 * held, in enum g_weapon order, wrapping (the same one when it is the only
 * one owned). */
void g_weapon_next(struct sim *s);
/* A weapon pickup: weapon w with ammo (capped at G_AMMO_MAX). Returns 0
 * when it is of no use (owned already, ammo full), else gives it, and a
 * weapon not owned before is taken in hand. */
int g_weapon_give(struct sim *s, int w, int ammo);
/* The pistol only, in hand: a new game and every life (an arcade death
 * drops what the player found). */
void g_weapon_reset(struct sim *s);

/* ---- g_world.c: what every special shares ---------------------------- */

/* Events of the specials, for the sound seam. */
enum g_ev {
	G_EV_DOOR_OPEN, G_EV_DOOR_CLOSE, G_EV_BLAZE_OPEN, G_EV_BLAZE_CLOSE,
	G_EV_PLANE_MOVE,               /* a floor or ceiling moving (every 8 tics) */
	G_EV_PLAT_START, G_EV_PLAT_STOP,
	G_EV_SWITCH, G_EV_SWITCH_EXIT, /* a switch or button pressed, or popping back */
	G_EV_NOWAY,                    /* USE on a wall with nothing to use */
	G_EV_LOCKED,                   /* a locked door or switch refused */
	G_EV_TELEPORT, G_EV_SECRET, G_EV_ITEM, G_EV_KEY
};

/* Where the specials' events happen (doors opening and closing, lifts
 * starting and stopping, switches, teleports, secrets), at a sector of the
 * current map (MAP_NONE: the player). The one place a sound module hooks
 * in; it changes no state. */
void g_event(struct sim *s, enum g_ev ev, uint32_t sector);

/* The sector on line l's other side from sec (MAP_NONE: one-sided). */
uint32_t g_other_sector(const struct map *m, const struct map_line *l, uint32_t sec);
/* Doom's searches over a sector's neighbours (its two-sided lines), with
 * the heights now: the lowest floor (sec's own if lower), the highest floor
 * (at least -500), the lowest floor above h (h when none), the lowest
 * ceiling (FX_MAX when none), the highest ceiling (at least 0); the light
 * furthest from start towards dark (brightest 0) or bright. */
fx_t g_lowest_floor_around(const struct sim *s, uint32_t sec);
fx_t g_highest_floor_around(const struct sim *s, uint32_t sec);
fx_t g_next_floor_above(const struct sim *s, uint32_t sec, fx_t h);
fx_t g_lowest_ceil_around(const struct sim *s, uint32_t sec);
fx_t g_highest_ceil_around(const struct sim *s, uint32_t sec);
int g_light_around(const struct sim *s, uint32_t sec, int start, int brightest);
/* The first sector after index `after` (-1: from the start) whose tag is
 * tag, or -1. */
int g_tagged(const struct sim *s, uint16_t tag, int after);
/* The mover of sector sec, or NULL. */
struct g_mover *g_mover_of(struct sim *s, uint32_t sec);
/* A new mover of sector sec (zeroed but for sector, kind, type), or NULL
 * when the sector has one or the list is full. */
struct g_mover *g_mover_new(struct sim *s, uint32_t sec, int kind, int type);
/* Removes m from the list, keeping the others' order. */
void g_mover_remove(struct sim *s, struct g_mover *m);
/* Sets or clears a line's bit in w.used or w.switched (g_world_bit reads
 * it). */
void g_line_set(uint32_t *bits, uint32_t line, int on);
/* The stage's Doom tic (35 Hz) and whether one began this tick. */
uint32_t g_dtic(const struct sim *s);
int g_dtic_now(const struct sim *s);
/* Shows message msg (enum g_msg) on the HUD. */
void g_message(struct sim *s, int msg);

/* ---- g_plane.c: moving floors and ceilings among the bodies ---------- */

enum g_res { G_RES_OK, G_RES_CRUSHED, G_RES_PASTDEST };

/* Body heights for fitting under ceilings. */
#define G_BODY_HEIGHT (56 * FX_ONE)

/* Doom's T_MovePlane: moves sector sec's floor (ceiling 0) or ceiling
 * (ceiling 1) by speed towards dest in direction dir (-1, 1). A body that
 * would no longer fit stops the move (the plane goes back; G_RES_CRUSHED)
 * unless crush (then it is crushed: 10 damage every 4 tics, and the move
 * goes on; also G_RES_CRUSHED); reaching dest is G_RES_PASTDEST. Bodies
 * standing in sec ride its floor. A dest beyond +/-MAP_HEIGHT_MAX counts as
 * the limit: no plane leaves the range the loader holds maps to, which the
 * eye height and the renderer's height differences are sized for (map.h;
 * Doom lets a raise by 512 go past its own int16 heights). */
int g_plane_move(struct sim *s, uint32_t sec, fx_t speed, fx_t dest, int crush, int ceiling,
		 int dir);

/* v held to +/-lim, for values summed in 64 bits so that the sum itself
 * cannot overflow fx_t: heights against MAP_HEIGHT_MAX (stairs add a step
 * per sector, a texture raise a texture's height), points against
 * MAP_COORD_MAX (a shot's end at its full range). */
static inline fx_t g_clamp(int64_t v, fx_t lim)
{
	return v > lim ? lim : v < -(int64_t)lim ? -lim : (fx_t)v;
}

/* Whether (x, y) with a body of radius r around it lies within the
 * coordinate range (+/-MAP_COORD_MAX) that every map's vertices and things
 * keep to. A body goes past a map's lines into open space only on a broken
 * map (a teleport destination outside it); the edge of the range then
 * stops it as a wall would (g_move.c; a missile explodes there), since the
 * sim's positions, their snapshot checks and their arithmetic end there. */
static inline int g_in_range(int64_t x, int64_t y, int64_t r)
{
	return x >= -MAP_COORD_MAX + r && x <= MAP_COORD_MAX - r && y >= -MAP_COORD_MAX + r &&
	       y <= MAP_COORD_MAX - r;
}

/* ---- the movers: g_door.c, g_floor.c, g_ceil.c (with platforms) ------- */

/* Who triggers: G_WHO_PLAYER, or an enemy's index (>= 0). */
#define G_WHO_PLAYER (-1)

/* Doom's EV_DoDoor on the sectors tagged like line l: 1 if one started. */
int g_door_tagged(struct sim *s, const struct map_line *l, int type);
/* Doom's EV_VerticalDoor: the door behind line `line` (its back sector),
 * used by who; keys checked (a message when one is missing). 1 when a
 * door started or turned. */
int g_door_manual(struct sim *s, uint32_t line, int who);
/* The locked switches' doors (Doom's EV_DoLockedDoor): 1 if one started. */
int g_door_locked(struct sim *s, uint32_t line, int type, int who);
/* Sector specials 10 and 14 at the stage start. */
void g_door_spawn(struct sim *s, uint32_t sec, int raise5);
/* One tick of door m; 1 when it finished (removed). */
int g_door_tick(struct sim *s, struct g_mover *m);

int g_floor_tagged(struct sim *s, const struct map_line *l, int type);
int g_stairs(struct sim *s, const struct map_line *l, int turbo);
int g_donut(struct sim *s, const struct map_line *l);
int g_floor_tick(struct sim *s, struct g_mover *m);

int g_ceil_tagged(struct sim *s, const struct map_line *l, int type);
int g_ceil_stop(struct sim *s, uint16_t tag);
int g_ceil_tick(struct sim *s, struct g_mover *m);
/* Doom's EV_DoPlat (amount: raise-and-change's height in units), with the
 * line's front sector giving the new flat. */
int g_plat_tagged(struct sim *s, const struct map_line *l, int type, int amount);
void g_plat_stop(struct sim *s, uint16_t tag);
int g_plat_tick(struct sim *s, struct g_mover *m);

/* ---- g_light.c ------------------------------------------------------- */

/* Starts light effect `lfx` (enum g_lfx) in sector sec; sync: strobes all
 * start together. */
void g_light_spawn(struct sim *s, uint32_t sec, int lfx, int sync);
/* The light of the sectors tagged `tag`: to `level`, or (level < 0) to
 * their brightest (-1) or darkest (-2) neighbour. */
void g_light_set(struct sim *s, uint16_t tag, int level);
/* Line 17: slow strobes in the tagged sectors that have no mover. */
void g_light_strobe_tagged(struct sim *s, uint16_t tag);
/* One Doom tic of every light effect. */
void g_lights_tic(struct sim *s);

/* ---- g_tele.c -------------------------------------------------------- */

/* Doom's EV_Teleport over line l crossed from side `side` by who: to the
 * teleport destination thing in the tagged sector, facing its angle. 1 if
 * who moved. */
int g_teleport(struct sim *s, const struct map_line *l, int side, int who);

/* ---- g_line.c: the line specials and their triggers ------------------ */

/* A body moved from (ox, oy) to (nx, ny) with radius r: the walk-over
 * specials of the lines it crossed (players all, enemies Doom's few). */
void g_cross(struct sim *s, int who, fx_t ox, fx_t oy, fx_t nx, fx_t ny, fx_t r);
/* The player pressed USE: the first line within 64 units in front. */
void g_use(struct sim *s);
/* Enemy i bumped into walls at (x, y): it opens the manual doors there. */
void g_enemy_bump(struct sim *s, int i, fx_t x, fx_t y);
/* The player's shot from (x1, y1) to (x2, y2) (where it stopped): the
 * gun-triggered specials of the lines it reached. */
void g_shoot_lines(struct sim *s, fx_t x1, fx_t y1, fx_t x2, fx_t y2);
/* One tick of the buttons popping back. */
void g_buttons_tick(struct sim *s);

/* ---- g_spec.c: the stage's specials ----------------------------------- */

/* The stage's world from its map (sectors, lines, counts), its sector
 * specials started (lights, timed doors, secrets). */
void g_spec_start(struct sim *s);
/* One tick of the specials in play: movers, lights, buttons, the player's
 * sector (damage, secrets, the exit floor), messages. */
void g_spec_tick(struct sim *s);
/* ---- g_exit.c: leaving the map ---------------------------------------- */

/* The map is left (exit lines, sector 11): the intermission begins. */
void g_exit(struct sim *s, int secret);
/* Doom's next map after the current one: the stage index (which may be
 * 0 again after the last). */
int g_next_stage(const struct sim *s, int secret);

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

/* ---- g_pace: the stage clock, hurry up, the idle player ---------------- */

/* The stage clock's full length in ticks (set.stage_time); 0 when off. */
uint32_t g_pace_full(const struct sim *s);

/* A stage or a life begins: the clock full, the idle count zero. */
void g_pace_start(struct sim *s);

/* One tick of phase PLAY, after the player's move and before the enemies:
 * counts cmd's input, runs the clock; the clock's last G_HURRY_TICKS wake
 * every enemy; its end, or a player gone (set.idle_out), kills the player. */
void g_pace_tick(struct sim *s, const struct sim_cmd *cmd);

/* 1 in the clock's last G_HURRY_TICKS of phase PLAY (never when off). */
int g_pace_hurry(const struct sim *s);

/* A stage was cleared or its exit taken: scores the whole seconds left. */
void g_pace_bonus(struct sim *s);

/* The player dies now (phase PLAY only), for the reason why (enum g_why). */
void g_player_dies(struct sim *s, int why);

/* ---- sim_input: the command's coins, credits and directions (sim.c) ---- */

/* cmd's coins: coins_total, books and coin_rem count them, each
 * coins_per_credit of them make a credit (with its sounds). */
void sim_coins(struct sim *s, uint8_t coins);

/* Spends n credits (a credit a player) for a start or continue, nothing in
 * free play; 0 if there are fewer. */
int sim_pay(struct sim *s, uint32_t n);

/* This tick's menu and initials directions (MENU_NAV_*): new ones, and
 * held ones every SIM_NAV_REPEAT ticks after SIM_NAV_DELAY. */
uint8_t sim_nav(struct sim *s, const struct sim_cmd *c);

/* ---- g_turn: two players alternating ----------------------------------- */

/* A new game of `players` (1 or 2), after g and the player were set for
 * player 1 at stage 0: player 1 is up; player 2 waits with the same
 * start (full lives, stage 1, the pistol and G_AMMO_START). With two, the
 * "PLAYER 1" page comes first. */
void g_turn_begin(struct sim *s, int players);

/* The player up lost a life and plays on (lives left, or a continue
 * taken), with their health, ammo and weapons set for the next life: when
 * the other player is still in the game, the two change places (g, pl and
 * wait; g.stage is the new player's) and 1 is returned: the caller (sim.c)
 * then starts that stage behind the "PLAYER n" page. 0: the player up goes
 * on. */
int g_turn_pass(struct sim *s);

/* The game of the player up is over (no continue, initials done): when
 * the other player is still in the game, the two change places as in
 * g_turn_pass, the finished player marked out, and 1 is returned; else 0
 * (the game is over). */
int g_turn_over(struct sim *s);

#endif
