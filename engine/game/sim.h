/*
 * sim: the deterministic game simulation.
 *
 * The sim reads only one struct sim_cmd per tick (never a clock, never a
 * device), uses only fixed point and table trigonometry, and keeps all of
 * its state, including its RNG, in struct sim. Two sims fed the same
 * commands from the same start (maps, settings, high-score table,
 * bookkeeping) are bit-identical on every compiler, optimisation level and
 * CPU; sim_hash proves it tick by tick.
 *
 * struct sim is a plain value (no allocation): several can live in one
 * process (the app runs a second one for the attract demo). It borrows the
 * stage maps, which must outlive it.
 *
 * Modes (the arcade flow):
 *   ATTRACT   pages TITLE, SCORES, DEMO in a loop; coins make credits;
 *             START with a credit (or free play) starts a game
 *   PLAY      a game: stages of enemies; dying costs a life
 *   GAMEOVER  no lives left: CONTINUE countdown (10 s); START with a credit
 *             continues, fire speeds the countdown up
 *   INITIALS  the score made the high-score table: 3 letters
 *   SERVICE   the service menu (engine/game/menu.h); the SERVICE button enters
 *             it from every mode, abandoning a game in progress
 */
#ifndef ARCADED_ENGINE_SIM_H
#define ARCADED_ENGINE_SIM_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/game/g_game.h"
#include "engine/game/g_world.h"
#include "engine/game/g_sound.h"
#include "engine/game/menu.h"
#include "engine/game/sim_table.h"

struct map;
struct r_view;
struct snd_set;

#define SIM_TICRATE 60

/* Buttons: levels, sampled once per tick. The sim detects edges itself. */
#define SIM_BT_FIRE 0x01
#define SIM_BT_USE 0x02
#define SIM_BT_START 0x04
#define SIM_BT_SERVICE 0x08
/* weapon change: a press takes the next weapon the player owns */
#define SIM_BT_WEAPON 0x10
/* vertical aim, levels: held moves the pitch; both held centre it (g_game.h
 * G_PITCH_*) */
#define SIM_BT_LOOK_UP 0x20
#define SIM_BT_LOOK_DOWN 0x40
/* the 2P start: a two-player game (two credits), or a continue */
#define SIM_BT_START2 0x80

/* One tick of player input: exactly what a recording stores (6 bytes,
 * see input/rec.h). forward/side: -127..127 of full speed (positive is
 * forward / right). turn: change of view angle this tick in 1/65536 of a
 * turn, positive counter-clockwise (left). coins: coin pulses this tick. */
#define SIM_CMD_FIELDS(X) \
	X(VAL, int8_t, forward, SIM_ANY) \
	X(VAL, int8_t, side, SIM_ANY) \
	X(VAL, int16_t, turn, SIM_ANY) \
	X(VAL, uint8_t, buttons, SIM_ANY) \
	X(VAL, uint8_t, coins, SIM_ANY)
struct sim_cmd {
	SIM_CMD_FIELDS(SIM_MEMBER)
};

enum sim_mode {
	SIM_ATTRACT,   /* waiting for credits: title, scores, demo */
	SIM_PLAY,      /* a game in progress */
	SIM_GAMEOVER,  /* continue countdown */
	SIM_INITIALS,  /* entering initials for the high-score table */
	SIM_SERVICE,   /* the service menu */
	SIM_MODE_COUNT
};

/* Attract pages, in the order they cycle. */
enum sim_page { SIM_PAGE_TITLE, SIM_PAGE_SCORES, SIM_PAGE_DEMO, SIM_PAGE_COUNT };
#define SIM_TITLE_TICKS 480            /* 8 s */
#define SIM_SCORES_TICKS 480           /* 8 s */
#define SIM_DEMO_TICKS 1800            /* 30 s: the app replays its demo meanwhile */

/* Operator settings that change the game's rules; stored in recordings. */
#define SIM_SETTINGS_FIELDS(X) \
	X(VAL, uint8_t, coins_per_credit, SIM_ANY)  /* 1..9; 0 counts as 1 */ \
	X(VAL, uint8_t, freeplay, SIM_ANY)          /* 0/1: start needs no credit */ \
	/* 0/1: skip attract (development, make run) */ \
	X(VAL, uint8_t, start_in_play, SIM_ANY) \
	/* 0 easy, 1 normal, 2 hard, 3 brutal; above 3 counts as 3 */ \
	X(VAL, uint8_t, difficulty, SIM_ANY) \
	X(VAL, uint8_t, lives, SIM_ANY)             /* 1..9; 0 counts as G_LIVES_DEFAULT */ \
	/* master volume, percent 0..100 (0 silent; above 100 counts as 100) */ \
	X(VAL, uint8_t, volume, SIM_ANY) \
	/* attract mode's sound: 0 off, 1 on, N (2..9) once every N cycles (g_sound.h) */ \
	X(VAL, uint8_t, attract_sound, SIM_ANY) \
	/* the stage clock in minutes, 1..G_STAGE_TIME_MAX; 0 counts as \
	 * G_STAGE_TIME_DEFAULT, G_STAGE_TIME_OFF is none, other values above \
	 * the maximum count as the maximum (g_game.h) */ \
	X(VAL, uint8_t, stage_time, SIM_ANY) \
	/* a player gone idle: enum g_idle; above counts as G_IDLE_OFF */ \
	X(VAL, uint8_t, idle_out, SIM_ANY) \
	/* 0: vertical auto-aim (the default), 1: shots follow the pitch only \
	 * (config game.autoaim off) */ \
	X(VAL, uint8_t, free_aim, SIM_ANY)
struct sim_settings {
	SIM_SETTINGS_FIELDS(SIM_MEMBER)
};

#define SIM_PLAYER_FIELDS(X) \
	X(VAL, fx_t, x, SIM_COORD)                  /* position on the map */ \
	X(VAL, fx_t, y, SIM_COORD) \
	/* feet height (follows the floor, steps up) */ \
	X(VAL, fx_t, z, SIM_COORD) \
	/* eye height: up to SIM_VIEW_HEIGHT above the highest floor */ \
	X(VAL, fx_t, viewz, SIM_RANGE(-MAP_COORD_MAX, MAP_HEIGHT_MAX + SIM_VIEW_HEIGHT)) \
	X(VAL, fx_t, momx, SIM_ANY)                 /* momentum per tick */ \
	X(VAL, fx_t, momy, SIM_ANY) \
	X(VAL, ang_t, angle, SIM_ANY)               /* view direction */ \
	/* vertical aim: the slope of the line of sight, 16.16 (G_PITCH_*) */ \
	X(VAL, fx_t, pitch, SIM_RANGE(-G_PITCH_MAX, G_PITCH_MAX)) \
	X(VAL, uint32_t, sector, SIM_SECTOR)        /* sector under (x, y) */ \
	/* 16.16; dead at 0 or below */ \
	X(VAL, fx_t, health, SIM_RANGE(0, G_HEALTH_MAX * FX_ONE)) \
	X(VAL, uint16_t, ammo, SIM_ANY) \
	X(VAL, uint16_t, refire, SIM_ANY)           /* ticks until the next shot may fire */ \
	/* the weapons owned, a bit per enum g_weapon (G_W_BIT; the pistol's always) */ \
	X(VAL, uint8_t, weapons, SIM_MAX(G_W_BIT(G_WEAPONS) - 1)) \
	X(VAL, uint8_t, weapon, SIM_MAX(G_WEAPONS - 1))  /* enum g_weapon: the one held */ \
	X(VAL, uint16_t, hurt, SIM_ANY)             /* ticks left of the damage flash */ \
	X(VAL, uint16_t, bonus, SIM_ANY)            /* ticks left of the pickup flash */ \
	/* ticks the player is held still (after a teleport) */ \
	X(VAL, uint16_t, freeze, SIM_ANY)
struct sim_player {
	SIM_PLAYER_FIELDS(SIM_MEMBER)
};

/* The whole state. The current map is one of the stages (its index in the
 * snapshot). num_stages comes from sim_init_stages: a restore only checks
 * it. */
#define SIM_FIELDS(X) \
	X(FNS, const struct map *, stages, G_MAX_STAGES, sw_stages)  /* borrowed */ \
	X(FN, const struct map *, map, sw_map)      /* the current stage's map (borrowed) */ \
	X(VAL, uint8_t, num_stages, SIM_RANGE(p->num_stages, p->num_stages)) \
	X(SUB, sim_settings, set) \
	X(VAL, uint32_t, tick, SIM_ANY)             /* ticks simulated since sim_init */ \
	X(ENUM, enum sim_mode, mode, SIM_MODE_COUNT) \
	X(VAL, uint8_t, page, SIM_MAX(SIM_PAGE_COUNT - 1))  /* ATTRACT: enum sim_page */ \
	/* attract cycles begun (TITLE pages shown) since sim_init, for attract_sound */ \
	X(VAL, uint32_t, attract_cycle, SIM_ANY) \
	/* ticks since the mode (or attract page) began */ \
	X(VAL, uint32_t, mode_t, SIM_ANY) \
	X(VAL, uint32_t, credits, SIM_ANY)          /* whole credits available */ \
	X(VAL, uint32_t, coin_rem, SIM_ANY)         /* coins towards the next credit */ \
	X(VAL, uint32_t, coins_total, SIM_ANY)      /* coins inserted since sim_init */ \
	X(VAL, uint32_t, plays, SIM_ANY)            /* games started since sim_init */ \
	X(VAL, uint8_t, prev_buttons, SIM_ANY)      /* for edge detection */ \
	X(VAL, uint8_t, prev_nav, SIM_ANY)          /* directions held last tick (MENU_NAV_*) */ \
	/* ticks the current directions have been held */ \
	X(VAL, uint16_t, nav_t, SIM_ANY) \
	X(SUB, sim_cmd, cmd)                        /* this tick's command (input test) */ \
	X(VAL, uint32_t, rng, SIM_ANY)              /* the sim's own RNG state */ \
	X(SUB, sim_player, pl) \
	X(SUB, g_game, g) \
	/* players in the game: 1, or 2 alternating (0 before the first game) */ \
	X(VAL, uint8_t, players, SIM_MAX(2)) \
	/* whose turn it is: 0 player 1, 1 player 2 (the app reads player 2's \
	 * controls for the command while it is 1) */ \
	X(VAL, uint8_t, up, SIM_MAX(1)) \
	X(SUB, g_seat, wait)                        /* the player waiting for their turn */ \
	X(SUB, g_world, w)                          /* the current map as the game changed it */ \
	X(SUB, g_sound, snd)                        /* the sounds playing (g_sound.h) */ \
	X(VAL, uint16_t, countdown, SIM_ANY)        /* GAMEOVER: ticks left to continue */ \
	/* INITIALS: the letter being chosen, 0..2; after the third it stays 3 */ \
	X(VAL, uint8_t, ini_pos, SIM_MAX(s->mode == SIM_INITIALS ? G_NAME_LEN - 1 : G_NAME_LEN)) \
	/* INITIALS: indices into G_ALPHABET */ \
	X(ARR, uint8_t, ini, G_NAME_LEN, SIM_ALL, SIM_MAX(G_ALPHABET_LEN - 1)) \
	/* INITIALS: the rank the score takes */ \
	X(VAL, int8_t, ini_rank, SIM_RANGE(s->mode == SIM_INITIALS ? 0 : -1, G_SCORES - 1)) \
	/* the last entry made (highlighted in attract), -1 none */ \
	X(VAL, int8_t, new_rank, SIM_RANGE(-1, G_SCORES - 1)) \
	X(SUB, g_scores, scores) \
	X(SUB, g_books, books) \
	/* bumped when the menu changes set (app: persist) */ \
	X(VAL, uint32_t, set_gen, SIM_ANY) \
	X(VAL, uint32_t, scores_gen, SIM_ANY)       /* bumped when scores change */ \
	X(VAL, uint32_t, books_gen, SIM_ANY)        /* bumped on coins, plays and resets */ \
	X(SUB, menu, menu)
struct sim {
	SIM_FIELDS(SIM_MEMBER)
};

/* Player dimensions and movement limits, map units (16.16). */
#define SIM_PLAYER_RADIUS (16 * FX_ONE)
#define SIM_PLAYER_HEIGHT (56 * FX_ONE)
#define SIM_VIEW_HEIGHT (41 * FX_ONE)
#define SIM_MAX_STEP (24 * FX_ONE)

/* Starts a sim on n stage maps (1..G_MAX_STAGES, borrowed, played in
 * order and then again from the first, one loop harder), with the
 * high-score table `scores` (NULL: g_scores_default) and bookkeeping
 * totals `books` (NULL: zero), both copied. Mode ATTRACT on page TITLE,
 * unless set->start_in_play, which starts a game at once without counting
 * it in plays. The player stands at stage 0's player 1 start (thing type
 * 1) or, without one, 32 units in front of the middle of the first line
 * whose front side faces sector 0, facing along it. */
void sim_init_stages(struct sim *s, const struct map *const *maps, int n,
		     const struct sim_settings *set, const struct g_scores *scores,
		     const struct g_books *books);

/* The lengths of the sounds of set (snd_ticks, engine/sound/snd.h) for the
 * sim's channels, which play each sound that many ticks. sim_init_stages
 * takes those of the built-in set; the app gives the set it loaded (a
 * WAD's sounds differ) before the first tick. A snapshot carries them. */
void sim_set_sounds(struct sim *s, const struct snd_set *set);

/* sim_init_stages with the one map m, the default table and zero books. */
void sim_init(struct sim *s, const struct map *m, const struct sim_settings *set);

/* Advances one tick with cmd.
 *
 * Every mode: cmd->coins add to coins_total, books.coins and coin_rem,
 * each coins_per_credit of them making a credit; a SERVICE press (edge)
 * enters the service menu. ATTRACT: the pages cycle (TITLE, SCORES, DEMO);
 * a START press with a credit or freeplay consumes a credit (not in
 * freeplay), counts a play, and starts a game at stage 0; otherwise the
 * camera turns in place (a turn in 32 s) and movement is ignored.
 *
 * PLAY: turn adds cmd->turn/65536 of a turn; forward/side thrust along the
 * view (Doom's momentum and friction; full forward settles at about 8 units
 * per tick); the player, a circle of SIM_PLAYER_RADIUS, moves in sub-steps
 * of half a radius, pushed out of walls so it slides along them, with
 * Doom's x-only / y-only fallback, and does not walk into living enemies.
 * Walls are one-sided and ML_BLOCKING lines, and portals whose higher
 * floor is more than SIM_MAX_STEP above the feet or whose opening is lower
 * than SIM_PLAYER_HEIGHT. z is the floor of the sector under the centre:
 * steps up and drops down are immediate. A WEAPON press takes the next
 * weapon owned (g_weapon.c), FIRE shoots the one held (g_combat.c), enemies
 * act (g_enemy.c), pickups are taken; health at 0 starts the death phase
 * (G_DEAD_TICKS), then a life is lost: the player respawns at the stage
 * start (enemies back at their spawn points, unalerted) or, with no life
 * left, GAMEOVER. When every enemy of the stage is dead: G_STAGE_BONUS
 * times the stage number, G_CLEAR_TICKS, then the next stage (health
 * carried over, ammo topped up to at least G_AMMO_START).
 *
 * GAMEOVER: G_CONTINUE_TICKS countdown (a FIRE press takes a second off);
 * START with a credit (or freeplay) continues: full lives, health and at
 * least G_AMMO_START ammo, at the current stage's start, score kept. At 0:
 * INITIALS if the score makes the table, else ATTRACT (TITLE).
 *
 * INITIALS: forward/turn right/strafe right step the current letter
 * forwards through G_ALPHABET, back/turn left/strafe left backwards (held:
 * repeating), FIRE confirms it; after the third letter (or when
 * G_INITIALS_TICKS run out, taking the letters shown) the entry goes into
 * the table and the sim shows it on the attract SCORES page.
 *
 * SERVICE: menu_tick (engine/game/menu.h); leaving returns to ATTRACT (TITLE).
 *
 * The RNG (xorshift32) steps once per tick, and wherever the rules draw. */
void sim_tick(struct sim *s, const struct sim_cmd *cmd);

/* Hash of the whole sim state (every field, explicit encoding): FNV-1a of
 * every stage map's content_hash, the current map's, and every field of
 * struct sim and its nested structs in order (the lists of
 * engine/game/sim_table.h), integers as little-endian bytes; slots of an
 * array past its count are left out. */
uint64_t sim_hash(const struct sim *s);

/* Snapshots: the whole state as bytes, so a recording can start in the
 * middle of a cabinet's run (the flight recorder records each game from
 * its first tick, with credits, attract timers, RNG, high-score table and
 * bookkeeping as they were). The same walk over the fields as sim_hash
 * (sim_hash.c, generated from the lists of sim_table.h) writes and reads
 * them, so whatever is hashed is saved and restored: every field of struct
 * sim and its nested structs, little-endian, including the enemy and
 * pickup slots past the counts. The borrowed maps are not saved: the
 * snapshot holds sim_stages_hash of the stages and the index of the current
 * map among them.
 *
 * sim_snapshot_size: the snapshot's size in bytes (fixed for a build; it
 * changes only when struct sim does, which also changes REC_ENGINE_VERSION).
 * sim_snapshot: writes sim_snapshot_size() bytes of s to out.
 * sim_restore: the caller first runs sim_init_stages on the same stage
 * maps, in the same order (settings, tables and books are restored from
 * the snapshot, so the ones given there do not matter), then restores buf.
 * Returns 0 and s becomes the state snapshotted: fed the same commands it
 * gives the same hashes as the original did; or -EINVAL with s unchanged
 * when len is not sim_snapshot_size(), the stages differ (hash or count),
 * or a value is out of its range (the limits in the lists): the current
 * map index, mode, page, stage, phase, shot, enemy kinds and states, pickup
 * kinds, counts beyond G_MAX_ENEMIES / G_MAX_PICKUPS or alive beyond the
 * enemies, a sector index beyond the current map's, a position beyond
 * MAP_COORD_MAX, a sector's floor or ceiling beyond MAP_HEIGHT_MAX, health
 * outside 0..G_HEALTH_MAX, initials letters and ranks, menu page, cursor
 * and choices. */
size_t sim_snapshot_size(void);
void sim_snapshot(const struct sim *s, uint8_t *out);
int sim_restore(struct sim *s, const uint8_t *buf, size_t len);

/* One integer field of the state, as sim_visit reports it. */
struct sim_vfield {
	const char *tag;               /* the struct that declares it: "sim_player" */
	const char *name;              /* its name there: "x" */
	int index;                     /* the element of an array field, else 0 */
	size_t off;                    /* its offset in struct sim */
	size_t size;                   /* its bytes in memory (sizeof) */
	size_t at;                     /* its offset in the snapshot */
	uint8_t bytes;                 /* its bytes in the snapshot and the hash, little-endian */
	uint8_t sgn;                   /* signed (two's complement) */
	uint8_t spare;                 /* in a slot past its array's count: not hashed or checked */
	int64_t lo, hi;                /* what sim_restore accepts, with s as it is now (the
					  limit may name other fields); unsigned with hi
					  INT64_MAX: no upper limit */
};
typedef void sim_visit_fn(void *ctx, const struct sim_vfield *f);

/* Calls fn for every integer field of s in the order of the hash and the
 * snapshot (which is also the order in memory): the field list that the
 * tests check field by field and tools can name. The two borrowed map
 * fields (stages, map), which are walked by their own rules, are not
 * reported. fn must not change s. */
void sim_visit(const struct sim *s, sim_visit_fn *fn, void *ctx);

/* Hash of the stage maps' content hashes, in order: what a recording's map
 * hash should be when a game has several stages (one stage: FNV-1a of its
 * content hash). */
uint64_t sim_stages_hash(const struct map *const *maps, int n);

/* "attract", "play", "gameover", "initials", "service"; NULL for an
 * unknown mode. */
const char *sim_mode_name(enum sim_mode m);
/* Mode by name, or -1. */
int sim_mode_from_name(const char *name);

/* Named values of the state, for test scripts and tools: the built-in
 * fields of input/scr.h plus the game's (see sim_field.c and docs/game.md).
 * The kind says how a script writes the value. */
enum sim_fkind { SIM_FK_INT, SIM_FK_FX, SIM_FK_ANGLE, SIM_FK_MODE, SIM_FK_PAGE };
int sim_field_count(void);
const char *sim_field_name(int i);          /* NULL out of range */
enum sim_fkind sim_field_kind(int i);
int sim_field_find(const char *name);        /* index or -1 */
/* Value of field i: 16.16 for FX, whole degrees 0..359 for ANGLE, the
 * enum for MODE and PAGE, else the integer. */
int64_t sim_field_value(const struct sim *s, int i);
/* "title", "scores", "demo"; NULL for an unknown page. */
const char *sim_page_name(int page);
int sim_page_from_name(const char *name);

#endif
