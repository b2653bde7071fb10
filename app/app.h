/*
 * app: one run of the daemon. One process, one loop at a fixed 60 Hz tick
 * (app/loop.h has its steps and their order): read input as late as
 * possible before the tick, build the tick's command, run the sim, render,
 * present; measure frame time and input-to-present latency; notify
 * systemd. The same loop runs headless and as fast as it can for scripts
 * and replays. app_run sets up the modules of app/ (docs/architecture.md),
 * runs the loop and tears down.
 */
#ifndef ARCADED_APP_APP_H
#define ARCADED_APP_APP_H

#include <stdint.h>
#include <stdio.h>

#include "app/ct.h"
#include "config/cfg.h"

struct app_opts {
	const char *script;      /* drive with this script, headless, fast */
	const char *record;      /* write the commands of every tick here */
	const char *replay;      /* take the commands from this recording */
	const char *screenshot;  /* PNG of the last frame, written at exit */
	const char *bindings;    /* extra bindings file (after the config layers) */
	const char *config_dir;  /* /etc/arcaded: every *.ini, in name order */
	uint32_t ticks;          /* stop after this many ticks (0: no limit) */
	int fast;                /* do not wait for the tick clock */
	int realtime;            /* a script or replay follows the tick clock too */
	int no_render;           /* replay without rendering (state hashes only) */
	int quiet;               /* replay without printing per-tick hashes */
	int verify;              /* replay: compare with the recording's stored hashes */
	int size_w, size_h;      /* --size: render size over config and recording */
	int gl;                  /* --renderer gl: draw the world with OSMesa */
	FILE *out;               /* hashes, snapshots and summaries (stdout) */
	struct ct_spec content;  /* what to play on (level set from the config) */
	struct cfgerr *errs;     /* the configuration's errors, for the screen (NULL none);
				  * a [game] wad that fails to load is added */
};

/* Exit codes of app_run. */
enum { APP_OK = 0, APP_EXPECT_FAILED = 1, APP_SETUP_FAILED = 2,
       APP_RELOAD = 3 };              /* the service menu changed the content or the screen:
				       * read the configuration again and run again (app/op.h) */

/* Runs the daemon or a headless script/replay with configuration c until
 * the end of the script/recording, the tick limit, or SIGINT/SIGTERM.
 * Logs to stderr. Returns an APP_* code. */
int app_run(const struct cfg *c, const struct app_opts *o);

#endif
