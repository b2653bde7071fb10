/*
 * diag: the text of the service menu's diagnostics pages (DEVICES and
 * LATENCY, engine/game/menu.h), and `arcaded devices`' listing that the
 * DEVICES page shows too. The text goes to the drawing in a struct
 * hud_diag (engine/ui/hud.h), never into the sim: devices and timings are
 * facts of this machine and this run, and must not change a hash.
 */
#ifndef ARCADED_APP_DIAG_H
#define ARCADED_APP_DIAG_H

#include <stdint.h>
#include <stdio.h>

#include "engine/ui/hud.h"

struct cfg;
struct ctl;
struct slot_set;
struct slot_kind;
struct stats;

/* `arcaded devices`: prints to out every device of every input backend
 * that can list them (HID devices with their decoded report fields, evdev
 * devices, GPIO chips and lines) with the profile that would configure it
 * (profiles of config_dir/profiles, then the installed ones; auto-detection
 * by the bindings a run with c, config_dir and bindings would use), then
 * every sound output's devices (ALSA's cards). 0 or -ENOMEM. */
int diag_list(FILE *out, const struct cfg *c, const char *config_dir, const char *bindings);

/* Empties d. */
void diag_clear(struct hud_diag *d);

/* Appends text as lines of d: one per '\n', each cut to what a line holds
 * (HUD_DIAG_COLS - 1), tabs as two blanks; the lines past HUD_DIAG_LINES
 * are dropped. */
void diag_add(struct hud_diag *d, const char *text);

/* The DEVICES page: "IN USE", then per input backend of kinds[0..nkinds)
 * that is configured (its setting is not "none") its setting and each of
 * its slots in set (the device node, who it is when open, else MISSING);
 * no slot at all (a script or replay opens none) says so. Then, when
 * found is not NULL, "FOUND" and found's lines (diag_list's output). */
void diag_devices(struct hud_diag *d, const struct slot_kind *kinds, int nkinds,
		  const struct slot_set *set, const char *found);

/* The LATENCY page: frame time and input-to-present latency overall and
 * per kind of source that gave input, p50 / p99 / max and the count, as
 * the SIGUSR1 summary has them (app/stats.h); a source without input yet
 * says NO INPUT YET. */
void diag_latency(struct hud_diag *d, const struct stats *st);

/* The input test's lines: the devices' last control changes, newest
 * first, each with the actions it triggers (struct ctl's raw), under a
 * heading; none yet (a script or replay reads no device) says so. */
void diag_raw(struct hud_diag *d, const struct ctl *c);

/* Where a run's diagnostics text comes from (all borrowed). */
struct diag_src {
	const struct cfg *cfg;
	const char *config_dir, *bindings;   /* for diag_list; may be NULL */
	int headless;                        /* a script or replay: no machine listing */
	const struct ctl *ctl;
	const struct stats *stats;
	const struct slot_kind *kinds;
	int nkinds;
	const struct slot_set *slots;
};

/* The text of the page on screen and when it was made. */
struct diag_view {
	struct hud_diag diag;
	int page;                  /* the page diag was made for, 0 none */
	uint32_t at;               /* the tick it was made */
	char *found;               /* DEVICES: `arcaded devices`' listing, NULL none */
};

#define DIAG_TICKS 30              /* DEVICES and LATENCY: made again this often */

/* The service menu's text from the app for this tick's frame, page being
 * the menu's page (0 when not in the menu) at tick t: DEVICES' and
 * LATENCY's made when the page opens, then again every DIAG_TICKS
 * (percentiles sort the kept samples: not every frame); INPUT TEST's raw
 * controls every tick; NULL on other pages. The machine's listing is made
 * once per opening, and not when src is headless (a script's or replay's
 * frames must not depend on the machine). While taping (recording or
 * replaying): NULL on every page, so they show the engine's own "NOTHING
 * TO SHOW" and a recording's frame hashes are the ones any replayer
 * computes, this machine's devices and timings aside (tests/xbuild
 * replays scripts through the engine alone). */
const struct hud_diag *diag_frame(struct diag_view *v, const struct diag_src *src, int page,
				  int taping, uint32_t t);

/* Frees what v holds. */
void diag_view_free(struct diag_view *v);

#endif
