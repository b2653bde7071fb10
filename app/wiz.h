/*
 * wiz: the on-screen input configuration wizard ("PRESS P1 UP"). A pure
 * state machine: no I/O, no clock of its own (every call takes the time,
 * CLOCK_MONOTONIC ns, e.g. the event's kernel stamp or in_now_ns()), no
 * allocation. The app feeds it the raw key events of every open device
 * while it runs, ticks it, draws it instead of the game, and at the end
 * takes the bindings it made (wiz_result), to use them and to save them
 * (bind_format + st_write_plain as STATE_DIR/bindings.ini). docs/wizard.md.
 *
 * Steps, one per action, in this order (WIZ_STEPS):
 *   P1 UP (forward), P1 DOWN (back), P1 LEFT (turn_left), P1 RIGHT
 *   (turn_right), P1 FIRE, P1 USE, P1 STRAFE LEFT, P1 STRAFE RIGHT,
 *   P1 START, COIN, SERVICE, then the optional controls P1 WEAPON, P1
 *   LOOK UP, P1 LOOK DOWN (last: a cabinet with fewer buttons than
 *   actions skips them by holding, as any step).
 *
 * Rules of a step:
 *  - a control is assigned to the step's action on its RELEASE, when it
 *    was held less than WIZ_HOLD_NS (1 s) and pressed while the wizard ran
 *    (a release whose press came before wiz_start, like the FIRE that chose
 *    CONFIGURE INPUTS, is ignored);
 *  - a control held WIZ_HOLD_NS skips the step at that moment (wiz_tick or
 *    the release, whichever sees it first): the action keeps what it had.
 *    Every control held then is spent: its release is ignored;
 *  - a control already assigned in this run (same section, same code) is
 *    refused with a note naming its action, and the step waits;
 *  - a control is (section, code): the section is "usb-PORT" when the
 *    device's ident has a port, else "VVVV:PPPP" when it has a VID:PID,
 *    else [keyboard] (no ident, GPIO, the terminal). A device that gets a
 *    section of its own starts from its current effective bindings (its
 *    section found as bind_find_device finds it, else a copy of
 *    [keyboard]), so the actions it skips keep working; the assigned code
 *    replaces the action's list in that section and is removed from every
 *    other action of that section;
 *  - at most one control per action per run (each step takes one).
 *
 * After the last step a summary shows what each action got. A control
 * pressed there and released within WIZ_HOLD_NS saves (WIZ_DONE); held
 * WIZ_HOLD_NS it discards everything (WIZ_CANCELLED); with no press for
 * WIZ_SUMMARY_NS it saves. During the steps, WIZ_IDLE_NS without any event
 * cancels (a cabinet left in the wizard goes back to the game unchanged).
 * Skipping every step finishes with nothing changed (wiz_result returns
 * 0). The app may also end a run at any time with wiz_cancel.
 */
#ifndef ARCADED_APP_WIZ_H
#define ARCADED_APP_WIZ_H

#include <stdint.h>

#include "config/bind.h"
#include "input/in.h"

struct pal;
struct r_frame;

#define WIZ_STEPS 14
#define WIZ_HOLD_NS 1000000000ull       /* hold to skip (steps) or discard (summary) */
#define WIZ_IDLE_NS 60000000000ull      /* steps: no event for this long cancels */
#define WIZ_SUMMARY_NS 10000000000ull   /* summary: no press for this long saves */
#define WIZ_HELD_MAX 32                 /* controls tracked down at once (more: ignored) */
#define WIZ_LABEL_MAX 48

enum wiz_status {
	WIZ_RUNNING,
	WIZ_DONE,                       /* finished: wiz_result is the new table */
	WIZ_CANCELLED,                  /* nothing changed: wiz_result is the one given */
};

/* What the screen says about the last thing that happened. */
enum wiz_note {
	WIZ_N_NONE,
	WIZ_N_ASSIGNED,                 /* note_step got the control */
	WIZ_N_SKIPPED,                  /* note_step was skipped */
	WIZ_N_TAKEN,                    /* refused: the control is note_step's already */
	WIZ_N_FULL,                     /* refused: no room for another device section */
};

/* A control: a code in a bindings section ("" is [keyboard]). */
struct wiz_ctl {
	char sec[BIND_ID_MAX];
	int code;
};

/* The state. Embed it anywhere (no resources to free); the fields are
 * wiz.c's, read them only through the functions below. */
struct wiz {
	struct bind_table orig;         /* as given to wiz_start */
	struct bind_table cur;          /* with this run's assignments */
	uint8_t phase;                  /* steps, summary, ended */
	uint8_t status;                 /* enum wiz_status once ended */
	uint8_t step;                   /* 0..WIZ_STEPS-1 during the steps */
	uint64_t now;                   /* latest time seen (for drawing) */
	uint64_t idle_from;             /* last event during the steps */
	uint64_t summary_from;          /* the summary began */
	int nheld;
	struct {
		struct wiz_ctl c;
		uint64_t t0;            /* press time */
		uint8_t spent;          /* a skip (or the summary) took it: release ignored */
	} held[WIZ_HELD_MAX];
	struct {
		uint8_t state;          /* 0 pending, 1 assigned, 2 skipped */
		struct wiz_ctl c;
		char dev[WIZ_LABEL_MAX]; /* "hid DragonRise Generic USB Joystick" */
	} cap[WIZ_STEPS];
	uint8_t note;                   /* enum wiz_note */
	uint8_t note_step;
	struct wiz_ctl note_ctl;
	char note_dev[WIZ_LABEL_MAX];
};

/* Starts a run on a copy of cur (the bindings in effect, profiles'
 * sections included) at time now. */
void wiz_start(struct wiz *w, const struct bind_table *cur, uint64_t now);

/* One raw key event (IN_KEY) of any open device, in the order they came:
 * backend its backend's name ("hid", "evdev", ...; may be NULL), id the
 * device's ident (NULL when the backend has none), code the KEY_* / BTN_*
 * code, down 1 for a press (or a repeat: value 1 or 2) and 0 for a
 * release, now the event's time. Codes outside BIND_CODE_MIN..MAX are
 * ignored; so are events once the run has ended. */
void wiz_event(struct wiz *w, const char *backend, const struct in_ident *id, int code, int down,
	       uint64_t now);

/* A device went away (its backend read -ENODEV): the controls held in its
 * section are forgotten, neither assigned nor counted as held towards a
 * skip (other devices of the same section, e.g. two keyboards on
 * [keyboard], lose theirs too: a rare case, and the safe side). */
void wiz_drop(struct wiz *w, const struct in_ident *id);

/* Advances time to now (skips by holding, the timeouts) and returns the
 * status: WIZ_RUNNING until the run ends, then the same end status on
 * every call. */
enum wiz_status wiz_tick(struct wiz *w, uint64_t now);

/* Ends a running run as WIZ_CANCELLED (nothing changed). */
void wiz_cancel(struct wiz *w);

/* The table to use from now on: this run's assignments over the table
 * given to wiz_start once DONE, that table itself otherwise. Returns 1
 * when it differs from the table given (so there is something to save),
 * else 0. */
int wiz_result(const struct wiz *w, struct bind_table *out);

/* The action of step k (0..WIZ_STEPS-1, enum act), or -1. */
int wiz_step_action(int k);

/* The step being asked for (0..WIZ_STEPS-1), or WIZ_STEPS once the steps
 * are over. */
int wiz_step(const struct wiz *w);

/* The last thing that happened, for the screen and the app's log: the
 * note, and in *step (may be NULL) the step it concerns (for WIZ_N_TAKEN,
 * the step the control was assigned to) and in *ctl (may be NULL) the
 * control captured (not for WIZ_N_SKIPPED). */
enum wiz_note wiz_last_note(const struct wiz *w, int *step, struct wiz_ctl *ctl);

/* Draws the whole frame (any size; text scaled 1 per 240 lines as the
 * HUD's): the step's page (title, "STEP K OF 14", "PRESS" and the control
 * asked for, the action, the note about the last capture with its device
 * and control, a bar while a control is held towards a skip, the hint
 * "HOLD ANY BUTTON 1 S TO SKIP"), or the summary (each action with the
 * control it got and its section's letter, "[A] KEYBOARD  [B] USB-1-1.2"
 * below, "KEPT" for a skipped one; how to save or discard, the seconds
 * left). Lines are kept within the 39 characters a 4:3 frame holds (longer
 * ones are cut at the edge). The prompt ("P1 UP") is the only text in the
 * HUD's yellow, the summary's controls the only green. As of the last
 * wiz_event or wiz_tick; colours from pal (hud_colours). */
void wiz_draw(const struct wiz *w, const struct pal *pal, struct r_frame *f);

#endif
