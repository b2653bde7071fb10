/*
 * op: the app's side of the service menu's CONTENT PACK, SCREEN and
 * CONFIG ERRORS items (engine/game/menu.h): when the menu shows one of
 * their one-tick request pages, op runs the page (app/pick.h) outside the
 * sim, takes the cabinet's controls from each tick's command while it
 * runs (the sim then gets a command with nothing but the coins), applies
 * and persists the operator's choice, and gives the frame the notice of a
 * configuration error not yet acknowledged (app/cfgerr.h).
 *
 * Where choices are kept: in the state directory, as state files whose
 * payload is INI text (config/st.h, power-cut safe, like settings.ini):
 * content.ini ([game] wad, maps) and screen.ini ([display] rotate, scale),
 * the layers main.c reads after settings.ini, so a choice made on screen
 * wins over /etc/arcaded after a restart; config-ack for the acknowledged
 * errors. Applying the content or the screen reloads the whole run
 * (op.reload: app_run returns APP_RELOAD and main.c reads the layers
 * again): the content is loaded anew (a WAD that fails falls back to the
 * built-in levels, and the error is shown as a configuration error), the
 * display is opened again with the new rotation and scale, and the game
 * starts again in attract.
 *
 * Not in a replay, not while recording (a recording's frames must be the
 * engine's own: tests/xbuild replays them through the engine alone): the
 * request is then logged and refused, and the menu stays on MAIN. In a
 * script run the pages run (the scripts test them), but nothing is kept
 * and nothing reloads: the choice is logged.
 */
#ifndef ARCADED_APP_OP_H
#define ARCADED_APP_OP_H

#include <stdint.h>

#include "app/cfgerr.h"
#include "app/pick.h"
#include "app/wads.h"
#include "config/cfg.h"

struct sim;
struct sim_cmd;
struct tape;

#define OP_CONTENT_FILE "content.ini"
#define OP_SCREEN_FILE "screen.ini"

struct op {
	const struct cfg *cfg;      /* borrowed */
	struct cfgerr *errs;        /* borrowed: the configuration's errors */
	const struct tape *tape;    /* borrowed: refused while it records or replays */
	int persist;                /* choices are kept in cfg's state directory */
	int on;                     /* a page runs: the controls are its */
	struct pick pick;
	struct wads wads;           /* CONTENT's packs, scanned when it opens */
	unsigned held;              /* the controls held last tick (PICK_K_*) */
	int held_ticks;             /* how long up or down has been held */
	unsigned swallow;           /* controls held when the page ended: the sim gets
				     * nothing until they are released (the FIRE that
				     * chose must not also choose on MAIN) */
	int acked;                  /* errs acknowledged */
	int reload;                 /* a choice was applied: the run starts again */
	char now[80];               /* what plays: shown by CONTENT */
};

/* Sets op up; what plays now is described by now (ct.what). errs may be
 * NULL (none). Reads whether errs were acknowledged (persist: from the
 * state directory). */
void op_init(struct op *o, const struct cfg *cfg, struct cfgerr *errs, const struct tape *tape,
	     int persist, const char *now);

/* After the sim's tick: starts the page the menu asks for, if any. */
void op_request(struct op *o, const struct sim *s);

/* Before the sim's tick, after the command was built: while a page runs,
 * its controls are taken from cmd (which keeps only its coins), and a
 * choice made is applied; after it ends, until every control held then is
 * released, too. */
void op_command(struct op *o, struct sim_cmd *cmd);

/* The notice for the frame (hud_env.notice): the first configuration
 * error while they are not acknowledged, else NULL; never while recording
 * or replaying. */
const char *op_notice(const struct op *o);

#endif
