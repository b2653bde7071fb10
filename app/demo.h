/*
 * demo: the attract mode's demo, a recording replayed through the engine.
 *
 * The recording is made at start from a built-in script (the same script
 * format the tests use, so it is readable and editable; its commands go
 * through cmd_build exactly as live input does): on the first built-in
 * level, the game levels/demo.scr, played by tests/replay/autopilot and
 * replayed with the rules it was played by (it scores, clears the stage
 * and uses the weapons); on other content, a walk about. When the main
 * sim's attract loop reaches its DEMO page, a second sim starts on the same
 * stages in play and is fed one recorded command per tick; the frame shows
 * that sim's world and HUD under the main sim's banner (INSERT COIN,
 * credits). Everything is driven by the main sim's ticks, so replays of the
 * cabinet reproduce the demo too. Daemon and replayer share this module.
 */
#ifndef ARCADED_APP_DEMO_H
#define ARCADED_APP_DEMO_H

#include <stdint.h>

#include "engine/game/sim.h"

struct ct;

struct demo {
	struct sim_cmd *cmds;    /* the recording: one command per tick */
	uint32_t len;
	struct sim sim;          /* the demo's own game */
	uint32_t t;              /* next command */
	int running;
	int game;                /* 1: the recorded game, 0: the walk about */
	int difficulty;          /* the recorded game's */
	const struct ct *ct;     /* borrowed: the stages */
};

struct map;

/* Whether the recorded demo game was played on map m (its name and
 * content hash); if so, *difficulty is the difficulty it was played at. */
int demo_game_matches(const struct map *m, int *difficulty);

/* Builds the demo recording for content ct. 0, -ENOMEM, or -EINVAL if the
 * built-in demo script does not parse (a programming error, reported in
 * err). */
int demo_init(struct demo *d, const struct ct *ct, char *err, size_t errlen);

/* After each tick of the main sim: starts the demo when the main sim
 * enters its DEMO page, advances it while the page shows, stops it after. */
void demo_tick(struct demo *d, const struct sim *main_sim);

/* The sim whose world is drawn under main_sim's page, or NULL. */
const struct sim *demo_under(const struct demo *d, const struct sim *main_sim);

void demo_free(struct demo *d);

#endif
