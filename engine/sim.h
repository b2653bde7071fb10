/*
 * sim: the deterministic game simulation.
 *
 * The sim reads only one struct sim_cmd per tick (never a clock, never a
 * device), uses only fixed point and table trigonometry, and keeps all of
 * its state, including its RNG, in struct sim. Two sims fed the same
 * commands from the same start are bit-identical on every compiler,
 * optimisation level and CPU; sim_hash proves it tick by tick.
 *
 * struct sim is a plain value (no allocation): several can live in one
 * process. It borrows the map, which must outlive it.
 */
#ifndef ARCADED_ENGINE_SIM_H
#define ARCADED_ENGINE_SIM_H

#include <stdint.h>

#include "engine/fx.h"

struct map;
struct r_view;

#define SIM_TICRATE 60

/* Buttons: levels, sampled once per tick. The sim detects edges itself. */
#define SIM_BT_FIRE 0x01
#define SIM_BT_USE 0x02
#define SIM_BT_START 0x04
#define SIM_BT_SERVICE 0x08

/* One tick of player input: exactly what a recording stores (6 bytes,
 * see input/rec.h). forward/side: -127..127 of full speed (positive is
 * forward / right). turn: change of view angle this tick in 1/65536 of a
 * turn, positive counter-clockwise (left). coins: coin pulses this tick. */
struct sim_cmd {
	int8_t forward;
	int8_t side;
	int16_t turn;
	uint8_t buttons;
	uint8_t coins;
};

enum sim_mode {
	SIM_ATTRACT,   /* waiting for credits; the camera idles */
	SIM_PLAY,      /* a game in progress */
	SIM_MODE_COUNT
};

/* Operator settings that change the game's rules; stored in recordings. */
struct sim_settings {
	uint8_t coins_per_credit;      /* 1..9 */
	uint8_t freeplay;              /* 0/1: start needs no credit */
	uint8_t start_in_play;         /* 0/1: skip attract (development, make run) */
};

struct sim_player {
	fx_t x, y;                     /* position on the map */
	fx_t z;                        /* feet height (follows the floor, steps up) */
	fx_t viewz;                    /* eye height */
	fx_t momx, momy;               /* momentum per tick */
	ang_t angle;                   /* view direction */
	uint32_t sector;               /* sector under (x, y) */
};

struct sim {
	const struct map *map;         /* borrowed */
	struct sim_settings set;
	uint32_t tick;                 /* ticks simulated since sim_init */
	enum sim_mode mode;
	uint32_t credits;              /* whole credits available */
	uint32_t coin_rem;             /* coins towards the next credit */
	uint32_t coins_total;          /* coins inserted since sim_init */
	uint32_t plays;                /* games started */
	uint8_t prev_buttons;          /* for edge detection */
	uint32_t rng;                  /* the sim's own RNG state */
	struct sim_player pl;
};

/* Player dimensions and movement limits, map units (16.16). */
#define SIM_PLAYER_RADIUS (16 * FX_ONE)
#define SIM_PLAYER_HEIGHT (56 * FX_ONE)
#define SIM_VIEW_HEIGHT (41 * FX_ONE)
#define SIM_MAX_STEP (24 * FX_ONE)

/* Starts a sim on map m (borrowed): player at the map's player 1 start
 * (thing type 1) or, without one, 32 units in front of the middle of the
 * first line whose front side faces sector 0, facing along it; mode ATTRACT
 * unless set->start_in_play (which starts a game without counting it in
 * plays). coins_per_credit 0 counts as 1. */
void sim_init(struct sim *s, const struct map *m, const struct sim_settings *set);

/* Advances one tick with cmd.
 *
 * Every mode: cmd->coins add to coins_total and coin_rem, each
 * coins_per_credit of them making a credit. ATTRACT: a START press (edge)
 * with a credit or freeplay consumes a credit (not in freeplay), counts a
 * play, enters PLAY and puts the player at its start; otherwise the camera
 * turns in place by a constant step (a turn in 32 s) and movement is
 * ignored. PLAY: turn adds cmd->turn/65536 of a turn; forward/side thrust
 * along the view (Doom's momentum and friction; full forward settles at
 * about 8 units per tick); the player, a circle of SIM_PLAYER_RADIUS, moves
 * in sub-steps of half a radius, pushed out of walls so it slides along
 * them, with Doom's x-only / y-only fallback. Walls are one-sided and
 * ML_BLOCKING lines, and portals whose higher floor is more than
 * SIM_MAX_STEP above the player's z or whose opening is lower than
 * SIM_PLAYER_HEIGHT. z is the floor of the sector under the centre: steps up
 * and drops down are immediate (no falling yet). The RNG (xorshift32) steps
 * once per tick. */
void sim_tick(struct sim *s, const struct sim_cmd *cmd);

/* Hash of the whole sim state (every field, explicit encoding): FNV-1a of
 * the map's content_hash (0 without a map), the settings, tick, mode,
 * credits, coin_rem, coins_total, plays, prev_buttons, rng and every player
 * field, integers as little-endian bytes. */
uint64_t sim_hash(const struct sim *s);

/* The camera for the current tick. */
void sim_view(const struct sim *s, struct r_view *v);

/* "attract", "play"; NULL for an unknown mode. */
const char *sim_mode_name(enum sim_mode m);
/* Mode by name, or -1. */
int sim_mode_from_name(const char *name);

#endif
