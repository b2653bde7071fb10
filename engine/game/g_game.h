/*
 * g_game: the arcade game's rules and their state, part of the
 * deterministic sim (engine/game/sim.h holds these structs by value).
 *
 * Everything here is integer or 16.16 fixed point, driven only by the
 * per-tick commands; the sim's own RNG is the only randomness. The g_ files
 * split the rules by topic:
 *   g_thing.c   Doom thing types -> enemy kinds, pickups, lights
 *   g_enemy.c   enemy kinds, spawning from the map's things, chase, attack
 *   g_missile.c the thrower's missiles
 *   g_combat.c  line of sight, the player's hitscan shots, damage, pickups
 *   g_weapon.c  the weapons' table, the weapon change, weapon pickups
 *   g_score.c   the high-score table and bookkeeping (and their bytes)
 *   sim_field.c   named state values for test scripts
 *   r_game.c  the things to draw, for the renderer
 */
#ifndef ARCADED_ENGINE_G_GAME_H
#define ARCADED_ENGINE_G_GAME_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/game/sim_table.h"

#define G_MAX_ENEMIES 96
#define G_MAX_PICKUPS 96
#define G_MAX_MISSILES 32              /* thrown projectiles in flight or exploding */
#define G_MAX_STAGES 32                /* Doom II's 32 maps */
#define G_SCORES 10                    /* entries in the high-score table */
#define G_NAME_LEN 3                   /* initials */

/* Player limits. */
#define G_HEALTH_MAX 100
#define G_AMMO_START 50
#define G_AMMO_MAX 200
#define G_SHOT_RANGE (2048 * FX_ONE)   /* every weapon's hitscan reach */
#define G_LIVES_DEFAULT 3

/* Weapons (g_weapon.c): hitscan guns sharing the one ammo count. The
 * player owns a set of them (sim_player.weapons, a bit per enum g_weapon;
 * the pistol always) and holds one (sim_player.weapon). */
enum g_weapon { G_W_PISTOL, G_W_SPREAD, G_W_RAPID, G_WEAPONS };
#define G_W_BIT(w) (1u << (w))

struct g_weapon_info {
	char name[8];                  /* "PISTOL", for the HUD */
	uint8_t damage;                /* per pellet that hits */
	uint8_t pellets;               /* rays per shot, fanned about the view centre */
	uint8_t ammo;                  /* used per shot; fires only with this much */
	uint8_t refire;                /* ticks from one shot to the next */
	ang_t step;                    /* angle between neighbouring pellets */
	uint8_t sfx;                   /* enum sfx_id of the shot */
};

/* The table, indexed by enum g_weapon. */
extern const struct g_weapon_info g_weapons[G_WEAPONS];

/* The pistol's numbers, which other rules and the HUD name. */
#define G_SHOT_DAMAGE 15
#define G_REFIRE 12                    /* ticks between pistol shots: 5 per second */

/* Enemy kinds. Each has fixed numbers (g_kinds); difficulty and the
 * stage loop scale damage and speed (g_enemy.c). The thrower's attack is
 * a missile (g_missile.c) that does the damage where it lands; the
 * others' attacks hit at once, the grunt's after its G_GRUNT_WINDUP-tick
 * wind-up (0.4 s). The flyer flies, circles in and bites. */
enum g_kind { G_GRUNT, G_BRUTE, G_SENTRY, G_THROWER, G_FLYER, G_KINDS };

struct g_kind_info {
	char name[8];                  /* "grunt" */
	fx_t radius;                   /* body circle, map units */
	fx_t eye;                      /* sight height above its feet */
	int16_t health;
	fx_t speed;                    /* chase speed per tick at difficulty 1 */
	fx_t range;                    /* attack when the player's centre is this near */
	fx_t sight;                    /* wakes when it sees the player this near */
	uint8_t damage;                /* per attack at difficulty 1 */
	uint8_t period;                /* ticks between attacks */
	uint8_t reaction;              /* ticks from seeing in range to the first attack */
	uint16_t score;                /* for a kill */
	/* the attack's wind-up: the last `windup` ticks before each attack
	 * the enemy shows its aiming frame and its wind-up cry sounds (a
	 * telegraph); the attack needs line of sight until the end (0: none) */
	uint8_t windup;
	uint8_t fly;                   /* 1: flies (g_enemy.c: height, circling) */
};

/* The table, indexed by enum g_kind. */
extern const struct g_kind_info g_kinds[G_KINDS];

#define G_GRUNT_WINDUP 24              /* ticks: 0.4 s at 60 Hz */

/* The flyer (Doom's lost soul, 3006): it flies, climbing or sinking
 * G_FLY_CLIMB a tick towards G_FLY_ABOVE over the player's feet (within
 * its sector's floor and ceiling), spawns G_FLY_SPAWN over its floor, and
 * within G_FLY_ORBIT of the player circles in towards it, its heading
 * G_FLY_SLANT off the straight line (to the left for an even index, the
 * right for an odd one), until it is in bite range. Dead, it falls
 * G_FLY_FALL a tick to the floor. */
#define G_FLY_CLIMB (2 * FX_ONE)
#define G_FLY_ABOVE (16 * FX_ONE)
#define G_FLY_SPAWN (24 * FX_ONE)
#define G_FLY_ORBIT (192 * FX_ONE)
#define G_FLY_SLANT (ANG90 * 2 / 3)    /* 60 degrees */
#define G_FLY_FALL (4 * FX_ONE)

enum g_estate {
	G_E_IDLE,                      /* has not seen the player */
	G_E_CHASE,                     /* walking towards the player */
	G_E_ATTACK,                    /* in range with line of sight */
	G_E_PAIN,                      /* flinching after a hit */
	G_E_DEAD                       /* a corpse: not solid, not counted */
};

/* Its fields: engine/game/sim_table.h. */
#define G_ENEMY_FIELDS(X) \
	X(VAL, fx_t, x, SIM_COORD) \
	X(VAL, fx_t, y, SIM_COORD) \
	X(VAL, fx_t, z, SIM_COORD) \
	X(VAL, ang_t, angle, SIM_ANY)               /* facing, for sprites */ \
	X(VAL, uint32_t, sector, SIM_SECTOR) \
	X(VAL, fx_t, sx, SIM_COORD)                 /* spawn point (respawn after a death) */ \
	X(VAL, fx_t, sy, SIM_COORD) \
	X(VAL, ang_t, sangle, SIM_ANY) \
	/* the map thing's Doom type (sprite choice) */ \
	X(VAL, uint16_t, type, SIM_ANY) \
	X(VAL, uint8_t, kind, SIM_MAX(G_KINDS - 1)) /* enum g_kind */ \
	X(VAL, uint8_t, state, SIM_MAX(G_E_DEAD))   /* enum g_estate */ \
	X(VAL, int16_t, health, SIM_ANY) \
	X(VAL, uint16_t, timer, SIM_ANY)            /* attack countdown / pain ticks */ \
	X(VAL, uint16_t, anim, SIM_ANY)             /* ticks in the current state */ \
	X(VAL, ang_t, wander, SIM_ANY)              /* detour heading while stuck */ \
	X(VAL, uint8_t, stuck, SIM_ANY)             /* detour ticks left */ \
	X(VAL, uint8_t, flash, SIM_ANY)             /* ticks of the attack flash (sprites) */ \
	/* Doom's ambush (deaf) flag: wakes only on seeing the player */ \
	X(VAL, uint8_t, ambush, SIM_MAX(1))
struct g_enemy {
	G_ENEMY_FIELDS(SIM_MEMBER)
};

/* Missiles (g_missile.c): the thrower's fireballs, real moving objects.
 * A missile flies in a straight line at G_MISSILE_SPEED per tick (Doom's
 * imp ball, 10 units a 35 Hz tic, is 5.83 units a 60 Hz tick) and
 * explodes on the first of: a wall (one-sided, blocking, or two-sided
 * with an opening its G_MISSILE_HEIGHT does not fit in), the floor or
 * ceiling, the player (its damage). Exploding (boom > 0) it stays where it
 * stopped for G_MISSILE_BOOM ticks (the explosion's frames), harmless,
 * then is removed. */
#define G_MISSILE_SPEED ((fx_t)((int64_t)10 * 35 * FX_ONE / 60))
#define G_MISSILE_RADIUS (6 * FX_ONE)
#define G_MISSILE_HEIGHT (8 * FX_ONE)
#define G_MISSILE_LAUNCH (32 * FX_ONE)  /* launch height above the thrower's feet */
#define G_MISSILE_BOOM 18

/* How the last missile ended, for tests and the HUD. */
enum g_mend { G_MEND_NONE, G_MEND_WALL, G_MEND_PLANE, G_MEND_PLAYER };

#define G_MISSILE_FIELDS(X) \
	X(VAL, fx_t, x, SIM_COORD) \
	X(VAL, fx_t, y, SIM_COORD) \
	X(VAL, fx_t, z, SIM_COORD)                  /* its bottom */ \
	X(VAL, fx_t, momx, SIM_ANY)                 /* per tick */ \
	X(VAL, fx_t, momy, SIM_ANY) \
	X(VAL, fx_t, momz, SIM_ANY) \
	X(VAL, fx_t, damage, SIM_ANY)               /* 16.16, fixed at the throw */ \
	X(VAL, uint8_t, boom, SIM_MAX(G_MISSILE_BOOM))  /* explosion ticks left; 0 flying */ \
	X(VAL, uint8_t, owner, SIM_MAX(G_MAX_ENEMIES - 1))  /* the thrower's index */
struct g_missile {
	G_MISSILE_FIELDS(SIM_MEMBER)
};

/* Pickups: health (Doom's health items, armour and the health-giving
 * powerups), ammo, weapons (amount: the ammo it brings; the weapon is
 * g_thing_info's), keys (amount: the G_KEY_* bit), the
 * radiation suit (amount: ticks of protection from damaging floors), and
 * items the game has no use for but counts (Doom's computer map, light
 * visor, invisibility). */
enum g_pkind { G_P_HEALTH, G_P_AMMO, G_P_KEY, G_P_SUIT, G_P_ITEM, G_P_WEAPON, G_P_KINDS };

#define G_PICKUP_FIELDS(X) \
	X(VAL, fx_t, x, SIM_COORD) \
	X(VAL, fx_t, y, SIM_COORD) \
	X(VAL, fx_t, z, SIM_COORD) \
	X(VAL, uint16_t, type, SIM_ANY)             /* Doom thing type */ \
	X(VAL, uint8_t, kind, SIM_MAX(G_P_KINDS - 1))  /* enum g_pkind */ \
	X(VAL, uint8_t, taken, SIM_MAX(1)) \
	X(VAL, uint16_t, amount, SIM_ANY)
struct g_pickup {
	G_PICKUP_FIELDS(SIM_MEMBER)
};

/* Phases of a game in progress (mode PLAY). */
enum g_phase {
	G_PH_PLAY,                     /* fighting */
	G_PH_DEAD,                     /* the player died: G_DEAD_TICKS, then respawn or game over */
	G_PH_CLEAR,                    /* every enemy is dead: G_CLEAR_TICKS, then the next stage */
	G_PH_INTER,                    /* the map's exit was taken: the intermission page
					* (kills, items, secrets, time), then the next stage */
	G_PH_TURN                      /* two players: the "PLAYER n" page (G_TURN_TICKS)
					* before the player up starts their stage */
};

#define G_DEAD_TICKS 120
#define G_CLEAR_TICKS 150
#define G_INTER_TICKS 600              /* the intermission: 10 s, or FIRE/USE after 1 s */
#define G_INTER_MIN 60
#define G_TURN_TICKS 150               /* the "PLAYER n" page between turns: 2.5 s */
#define G_BANNER_TICKS 120             /* "STAGE n" shown after a stage starts */
#define G_CONTINUE_TICKS 600           /* 10 s continue countdown */
#define G_INITIALS_TICKS 1800          /* 30 s to enter initials */
#define G_STAGE_BONUS 1000             /* times the stage number, on clearing it */
#define G_EXTRA_LIFE_SCORE 20000       /* an extra life each time the score passes a multiple */

/* The stage clock (arcade pacing): each stage, and each life on it, gets
 * set.stage_time minutes; in its last G_HURRY_TICKS every enemy wakes and
 * runs faster ("HURRY UP"); at zero the player dies ("TIME UP"). Whole
 * seconds left at a clear or an exit score G_TIME_BONUS each. A player who
 * gives no input for G_IDLE_TICKS in play is gone (set.idle_out), warned
 * for the last G_IDLE_WARN of them. */
#define G_STAGE_TIME_DEFAULT 5         /* minutes, for set.stage_time 0 */
#define G_STAGE_TIME_MAX 30
/* set.stage_time: no clock (no hurry, no time up, no time bonus), for
 * free-play cabinets and tests that need a still screen */
#define G_STAGE_TIME_OFF 255
#define G_HURRY_TICKS 1800             /* 30 s */
#define G_HURRY_SPEED 50               /* points added to the enemies' speed percent */
#define G_IDLE_TICKS 1800              /* 30 s */
#define G_IDLE_WARN 600
#define G_TIME_BONUS 10

/* set.idle_out: what happens to a player who is gone. */
enum g_idle { G_IDLE_LIFE, G_IDLE_END, G_IDLE_OFF, G_IDLE_COUNT };

/* Vertical aim: the player's pitch is the slope of the line of sight
 * (height per unit of distance, 16.16; positive looks up). Each tick
 * LOOK_UP or LOOK_DOWN is held it moves G_PITCH_STEP, within
 * +/-G_PITCH_MAX (Doom's auto-aim reach, 100 of 160: about 32 degrees); both
 * held centre it. It stays where it was left and is level after a respawn
 * or a new stage. With auto-aim (set.free_aim 0) a shot whose line has an
 * enemy in it horizontally takes the slope that hits the nearest visible
 * one within G_AUTOAIM_MAX, else the pitch's slope (g_combat.c). */
#define G_PITCH_MAX (FX_ONE * 5 / 8)
#define G_PITCH_STEP (G_PITCH_MAX / 30)  /* the whole range in half a second */
#define G_AUTOAIM_MAX (FX_ONE * 5 / 8)
/* Every enemy's body is this tall above its feet, for shots (Doom's 56). */
#define G_BODY_HEIGHT (56 * FX_ONE)

/* Why the player died, for the banner. */
enum g_why { G_WHY_KILLED, G_WHY_TIME, G_WHY_IDLE };

/* What the last shot did, for the HUD and the puff sprite. */
enum g_shot { G_SHOT_NONE, G_SHOT_WALL, G_SHOT_ENEMY, G_SHOT_MISS };

#define G_GAME_FIELDS(X) \
	X(VAL, uint32_t, score, SIM_ANY) \
	X(VAL, uint8_t, lives, SIM_ANY)             /* left, including the current one */ \
	X(VAL, uint8_t, continues, SIM_ANY)         /* used in this game */ \
	X(VAL, uint8_t, stage, SIM_MAX(s->num_stages - 1))  /* index into the sim's stages */ \
	X(VAL, uint8_t, loop, SIM_ANY)              /* times every stage was cleared */ \
	X(VAL, uint8_t, phase, SIM_MAX(G_PH_TURN))  /* enum g_phase */ \
	X(VAL, uint16_t, phase_t, SIM_ANY)          /* ticks in the phase */ \
	X(VAL, uint32_t, stage_t, SIM_ANY)          /* ticks since the stage started */ \
	X(VAL, uint32_t, kills, SIM_ANY)            /* in this game */ \
	X(VAL, uint16_t, num_enemies, SIM_MAX(G_MAX_ENEMIES)) \
	X(VAL, uint16_t, num_pickups, SIM_MAX(G_MAX_PICKUPS)) \
	X(VAL, uint16_t, alive, SIM_MAX(p->num_enemies))  /* enemies not dead */ \
	X(SUBS, g_enemy, en, G_MAX_ENEMIES, p->num_enemies) \
	X(SUBS, g_pickup, pk, G_MAX_PICKUPS, p->num_pickups) \
	X(VAL, fx_t, shot_x, SIM_COORD)             /* where the last shot ended */ \
	X(VAL, fx_t, shot_y, SIM_COORD) \
	X(VAL, fx_t, shot_z, SIM_COORD) \
	X(VAL, uint8_t, shot, SIM_MAX(G_SHOT_MISS)) /* enum g_shot */ \
	X(VAL, uint16_t, shot_t, SIM_ANY)           /* ticks since the last shot (saturates) */ \
	X(VAL, uint32_t, clock, SIM_ANY)            /* stage clock: ticks left */ \
	X(VAL, uint16_t, idle_t, SIM_ANY)           /* ticks in play without input */ \
	X(VAL, uint8_t, why, SIM_MAX(G_WHY_IDLE))   /* enum g_why: the last death */ \
	X(VAL, uint32_t, time_bonus, SIM_ANY)       /* scored at the last clear or exit */ \
	X(VAL, uint8_t, num_missiles, SIM_MAX(G_MAX_MISSILES)) \
	X(SUBS, g_missile, ms, G_MAX_MISSILES, p->num_missiles) \
	X(VAL, uint8_t, mend, SIM_MAX(G_MEND_PLAYER))  /* enum g_mend: the last missile's end */
struct g_game {
	G_GAME_FIELDS(SIM_MEMBER)
};

/* Two players alternating (g_turn.c): what the player who waits for their
 * turn keeps. The player up has theirs in struct g_game and sim_player;
 * at each swap the two change places. The stage clock is not kept: every
 * turn begins with a new life, which gets a full clock (g_pace.c). */
#define G_SEAT_FIELDS(X) \
	X(VAL, uint32_t, score, SIM_ANY) \
	X(VAL, uint8_t, lives, SIM_ANY) \
	X(VAL, uint8_t, continues, SIM_ANY) \
	X(VAL, uint8_t, stage, SIM_MAX(s->num_stages - 1)) \
	X(VAL, uint8_t, loop, SIM_ANY) \
	X(VAL, uint32_t, kills, SIM_ANY) \
	X(VAL, uint16_t, ammo, SIM_ANY) \
	X(VAL, uint8_t, weapons, SIM_MAX(G_W_BIT(G_WEAPONS) - 1)) \
	X(VAL, uint8_t, weapon, SIM_MAX(G_WEAPONS - 1)) \
	/* 1: this player's game is over (no continue taken) */ \
	X(VAL, uint8_t, out, SIM_MAX(1))
struct g_seat {
	G_SEAT_FIELDS(SIM_MEMBER)
};

/* High-score table, best first; the sim gets it at init and changes it
 * when a score makes the table; the app stores it (g_scores_encode). */
#define G_ENTRY_FIELDS(X) \
	X(ARR, char, name, G_NAME_LEN, SIM_ALL, SIM_ANY)  /* G_ALPHABET letters, no NUL */ \
	X(VAL, uint32_t, score, SIM_ANY) \
	X(VAL, uint8_t, stage, SIM_ANY)             /* stage reached, 1-based */
struct g_entry {
	G_ENTRY_FIELDS(SIM_MEMBER)
};

#define G_SCORES_FIELDS(X) \
	X(SUBS, g_entry, e, G_SCORES, SIM_ALL)
struct g_scores {
	G_SCORES_FIELDS(SIM_MEMBER)
};

/* Bookkeeping totals, kept across boots by the app: the sim gets them at
 * init and counts on from there (deterministically); the service menu
 * shows and resets them. */
#define G_BOOKS_FIELDS(X) \
	X(VAL, uint32_t, coins, SIM_ANY)            /* coin pulses */ \
	X(VAL, uint32_t, plays, SIM_ANY)            /* games started (continues not counted) */ \
	X(VAL, uint64_t, play_ticks, SIM_ANY)       /* ticks in mode PLAY */ \
	X(VAL, uint64_t, on_ticks, SIM_ANY)         /* ticks the sim ran (power-on time) */
struct g_books {
	G_BOOKS_FIELDS(SIM_MEMBER)
};

/* Letters for initials, in the order the joystick steps through them. */
#define G_ALPHABET "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789. "
#define G_ALPHABET_LEN 38

/* The factory table: our own initials, 10000 down to 1000. */
void g_scores_default(struct g_scores *t);

/* Rank (0-based) a score would take, or -1 if it does not make the table.
 * A new score goes below equal ones already there; 0 never qualifies. */
int g_scores_rank(const struct g_scores *t, uint32_t score);

/* Inserts at rank (from g_scores_rank, >= 0), moving lower entries down
 * and dropping the last. */
void g_scores_insert(struct g_scores *t, int rank, const char name[G_NAME_LEN],
		     uint32_t score, uint8_t stage);

/* Byte encodings for the state directory: explicit little-endian fields,
 * a format byte first. decode validates everything (letters from
 * G_ALPHABET, scores in non-increasing order, stage 1..255) and returns 0,
 * or -EINVAL leaving *out unchanged. */
#define G_SCORES_BYTES (4 + G_SCORES * (G_NAME_LEN + 4 + 1))
#define G_BOOKS_BYTES (4 + 4 + 4 + 8 + 8)
void g_scores_encode(const struct g_scores *t, uint8_t out[G_SCORES_BYTES]);
int g_scores_decode(const uint8_t *buf, size_t len, struct g_scores *out);
void g_books_encode(const struct g_books *b, uint8_t out[G_BOOKS_BYTES]);
int g_books_decode(const uint8_t *buf, size_t len, struct g_books *out);

/* ---- map things ---------------------------------------------------- */

enum g_class { G_C_NONE, G_C_PLAYER, G_C_ENEMY, G_C_PICKUP, G_C_LIGHT, G_C_DECOR };

struct g_thing_info {
	uint8_t cls;                   /* enum g_class */
	uint8_t kind;                  /* enemy: enum g_kind; pickup: enum g_pkind */
	uint16_t amount;               /* pickup: health or ammo it gives, the key's bit,
					* the suit's ticks */
	uint8_t counted;               /* Doom counts it among the map's items */
	uint8_t weapon;                /* a G_P_WEAPON pickup: enum g_weapon it gives */
	char sprite[5];                /* Doom sprite name, e.g. "POSS" */
	uint8_t bright;                /* drawn full bright (lights) */
	uint8_t stand;                 /* standing frame (0 = 'A'), from th.h */
	uint8_t frames;                /* frames cycled from it while standing */
	/* enemies: Doom's frame letters (0 = 'A') of its attack, pain and
	 * death (first .. last, the last is the corpse) */
	uint8_t attack, pain, death0, death1;
};

/* What thing type `type` is in this game (G_C_NONE for types the game
 * ignores): the class, sprite and standing frame from th.h, enemy kinds,
 * pickup amounts and enemy frames from g_thing.c. See docs/game.md. */
void g_thing_info(uint16_t type, struct g_thing_info *out);

/* Whether a thing with Doom flags `flags` appears at difficulty d (0..3):
 * Doom's skill bits 1 (easy: d 0), 2 (normal: d 1), 4 (hard: d 2, 3).
 * Flags without any skill bit count as every skill (hand-made maps).
 * Things flagged multiplayer-only (16) never appear: the game has one
 * player at a time. */
int g_thing_at_difficulty(uint16_t flags, int d);

/* The enemies and pickups map m spawns at difficulty d, as g_spawn_stage
 * counts them; the game keeps the first G_MAX_ENEMIES and G_MAX_PICKUPS
 * in the map's order (the load warns of more: app/pspec.c). */
struct map;
void g_spawn_count(const struct map *m, int d, int *enemies, int *pickups);

/* Whether enemy e is in its attack's wind-up (g_kind_info.windup): the
 * renderer shows its aiming frame then (g_enemy.c). */
int g_enemy_winding(const struct g_enemy *e);

/* Doom's thing flags. */
#define G_TF_AMBUSH 0x0008
#define G_TF_MULTI 0x0010

#endif
