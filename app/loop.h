/*
 * loop: the main loop and the order of its steps. One tick (60 Hz; as
 * fast as possible for scripts and replays) runs these steps, in this
 * order; docs/architecture.md ("How a tick flows") says the same:
 *
 *   begin          a stop signal, the tick limit or the script's end stops
 *                  the loop here; SIGUSR1's summary; the injected hang
 *   wait           until the tick is due on the 60 Hz clock
 *   input          read the devices as late as possible (or apply the
 *                  script's steps): key changes to actions; a replay's
 *                  next tick instead (its end stops the loop here)
 *   command        the actions to the tick's sim_cmd, the one thing the sim
 *                  reads and a recording stores
 *   wizard         the input wizard's time
 *   flight_before  a START in attract may begin a game: keep its start
 *   sim            the game's tick, then the attract demo's
 *   sound          the tick's sounds mixed, hashed and written to the sound
 *                  output right away
 *   flight_after   the game's recording (begun, added to, ended)
 *   requests       what the service menu asked for: the wizard, a render size
 *   outputs        coin meter and lamps follow the game
 *   persist        settings, scores and books that changed
 *   present        render the frame and show it
 *   hashes         --record, --replay, --verify: the tick's hashes
 *   checks         a script's expects, snapshots and screenshots
 *   notify         READY=1 after the first frame; WATCHDOG=1
 * and once after the last tick:
 *   end            STOPPING=1
 *
 * The steps are hooks (struct loop_ops) the app fills in (app/app.c), so a
 * test can drive the loop with its own.
 */
#ifndef ARCADED_APP_LOOP_H
#define ARCADED_APP_LOOP_H

#include <stdint.h>

#include "input/rec.h"

/* What a tick's steps share. */
struct loop_tick {
	uint32_t t;                /* the tick's number, from 0 */
	struct rec_tick rt;        /* its command, and a replay's stored hashes; zero at begin */
};

/* A step: ctx is loop_run's. begin and input return 0 to stop the loop
 * (no further step of that tick runs), anything else to go on. */
typedef int loop_gate(void *ctx, struct loop_tick *k);
typedef void loop_step(void *ctx, struct loop_tick *k);

struct loop_ops {
	loop_gate *begin;
	loop_step *wait;
	loop_gate *input;
	loop_step *command;
	loop_step *wizard;
	loop_step *flight_before;
	loop_step *sim;
	loop_step *sound;
	loop_step *flight_after;
	loop_step *requests;
	loop_step *outputs;
	loop_step *persist;
	loop_step *present;
	loop_step *hashes;
	loop_step *checks;
	loop_step *notify;
	loop_step *end;
};

/* Runs ticks 0, 1, ... through the steps of ops, in the order above,
 * until begin or input stops it; then end. Returns the number of ticks
 * that ran whole (the one stopped does not count). */
uint32_t loop_run(const struct loop_ops *ops, void *ctx);

#endif
