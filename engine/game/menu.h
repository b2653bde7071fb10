/*
 * menu: the operator's service menu, a deterministic state machine inside
 * the sim (struct sim holds a struct menu). It is driven by the same
 * per-tick commands as the game, so a service session is recorded and
 * replays like a game, and the scripts can test it.
 *
 * Why in the sim and not in the app: what the menu changes (settings, the
 * high-score table, bookkeeping) changes the game, and the sim's state hash
 * must cover every such change; driving it from the recorded commands keeps
 * one source of truth. The app only applies what the menu decided
 * (persisting settings, scores and bookkeeping, changing the render size).
 *
 * Navigation: forward/back (joystick up/down) move the cursor, turn or
 * strafe left/right change a value, fire selects, service goes back (to the
 * main page, and from there out of the menu). Held directions repeat.
 *
 * Pages:
 *   MAIN      the list of pages
 *   INPUT     input test: each control's state as the game receives it;
 *             under it the devices' last raw control changes with the
 *             actions they trigger (text from the app, as for DEVICES)
 *   DISPLAY   display test: colour bars, convergence grid, orientation
 *             (fire steps through them)
 *   SETTINGS  difficulty, lives, coins per credit, free play, master volume,
 *             attract sound, render size, factory defaults
 *   SOUND     sound test: up/down choose a sound of the set (or the left or
 *             right channel test: a tone on that side only), fire plays it
 *   BOOKS     bookkeeping: coins, plays, play time, average, uptime
 *   DEVICES   diagnostics: the input devices the daemon uses and the ones
 *             the machine has (what `arcaded devices` prints)
 *   LATENCY   diagnostics: input-to-present latency per kind of source
 *             (p50/p99) and frame time (what the SIGUSR1 summary prints)
 *   CONFIRM   reset of the high scores or the bookkeeping: NO / YES
 *   WIZARD    the operator chose CONFIGURE INPUTS: a request to the app,
 *             which runs the input configuration wizard (app/wiz.h) outside
 *             the sim. The page lasts exactly one tick: the next tick
 *             returns to MAIN with the cursor on the item, whatever the
 *             commands. The app looks at the state after every tick, sees
 *             page == MENU_WIZARD once per choice and starts the wizard; it
 *             never writes sim state. A page value rather than a new
 *             counter field: every field is hashed and snapshotted
 *             (sim_hash.c), so a new one would change every recorded hash.
 *   CONTENT   the operator chose CONTENT PACK: like WIZARD, a one-tick
 *             request; the app runs its content picker (app/pick.h: the
 *             WADs of the content directories, then a start map) outside
 *             the sim, applies and persists the choice.
 *   SCREEN    the operator chose SCREEN: a one-tick request; the app's
 *             page sets the display's rotation and scale (app/pick.h).
 *   CONFIG    the operator chose CONFIG ERRORS: a one-tick request; the
 *             app's page lists the configuration's errors (file:line and
 *             reason), and FIRE acknowledges them (app/pick.h).
 *             The WADs found, the display and the configuration's errors
 *             are facts of the machine, not of the game: they never enter
 *             the sim state. Only the page value (one tick) and the
 *             cursor do, as for WIZARD.
 *
 * DEVICES and LATENCY (and INPUT's raw control lines) show facts of the
 * machine and of the main loop, not of the game: they must not enter the
 * sim state, its hash or a recording (a replay on another machine gives
 * the same hashes). So only where the operator is (the page value, the
 * navigation) is sim state; the text is the app's (struct hud_diag in
 * engine/ui/hud.h, passed in the hud_env each frame), and the drawing
 * prints what it is given. On DEVICES and LATENCY, FIRE or SERVICE goes
 * back, like BOOKS. Their two items sit above CONFIGURE INPUTS, after
 * every item a recorded session reaches by counting moves down from the
 * top, and their page values after MENU_SOUND: no recorded hash changes.
 * CONTENT PACK, SCREEN and CONFIG ERRORS followed the same rule: their
 * items come after LATENCY, their page values after MENU_LATENCY.
 *
 * The MAIN page may also show one line of the app's (hud_env.notice): the
 * first configuration error not yet acknowledged.
 */
#ifndef ARCADED_ENGINE_MENU_H
#define ARCADED_ENGINE_MENU_H

#include <stdint.h>

#include "engine/game/sim_table.h"
#include "engine/sound/sfx.h"

struct sim;
struct r_frame;
struct hud_env;

enum menu_page { MENU_MAIN, MENU_INPUT, MENU_DISPLAY, MENU_SETTINGS, MENU_BOOKS, MENU_CONFIRM,
		 MENU_WIZARD, MENU_SOUND, MENU_DEVICES, MENU_LATENCY, MENU_CONTENT, MENU_SCREEN,
		 MENU_CONFIG, MENU_PAGES };

/* Items of the main page, in order. */
enum menu_item { MENU_I_INPUT, MENU_I_DISPLAY, MENU_I_SOUND, MENU_I_SETTINGS, MENU_I_BOOKS,
		 MENU_I_RESET_SCORES, MENU_I_RESET_BOOKS, MENU_I_DEVICES, MENU_I_LATENCY,
		 MENU_I_CONTENT, MENU_I_SCREEN, MENU_I_CONFIG, MENU_I_WIZARD, MENU_I_EXIT, MENU_ITEMS };

/* Items of the settings page. */
enum menu_setting { MENU_S_DIFFICULTY, MENU_S_LIVES, MENU_S_COINS, MENU_S_FREEPLAY,
		    MENU_S_VOLUME, MENU_S_ATTRACT_SOUND, MENU_S_STAGE_TIME, MENU_S_IDLE,
		    MENU_S_AUTOAIM,
		    MENU_S_RES, MENU_S_DEFAULTS, MENU_S_BACK, MENU_SETTINGS_COUNT };

/* The factory settings MENU_S_DEFAULTS restores: 1 coin per credit, no
 * free play, NORMAL difficulty, 3 lives, volume 80%, attract sound on,
 * a 5-minute stage clock (G_STAGE_TIME_DEFAULT), an idle player loses a
 * life, vertical auto-aim on, the configured render size. */
#define MENU_DEFAULT_DIFFICULTY 1
#define MENU_DEFAULT_VOLUME 80
#define MENU_DEFAULT_ATTRACT_SOUND 1
#define MENU_VOLUME_STEP 5             /* percent per press */
#define MENU_ATTRACT_SOUND_MAX 9       /* once every 9 cycles at most */

/* Sound test entries: each sound of sfx.h (entry i plays sound i + 1),
 * then the left and the right channel test. */
#define MENU_SOUND_LEFT (SFX_COUNT - 1)
#define MENU_SOUND_RIGHT (SFX_COUNT)
#define MENU_SOUNDS (SFX_COUNT + 1)

/* Display test screens, stepped by fire. */
enum menu_display { MENU_D_BARS, MENU_D_GRID, MENU_D_ORIENT, MENU_D_COUNT };

/* Render sizes the settings page offers (index 1..MENU_RES_COUNT; 0 means
 * "as configured", the size the cabinet booted with). */
#define MENU_RES_COUNT 6

/* Navigation bits (sim.c computes them per tick: edges and repeats). */
#define MENU_NAV_UP 0x01
#define MENU_NAV_DOWN 0x02
#define MENU_NAV_LEFT 0x04
#define MENU_NAV_RIGHT 0x08

/* The cursor is an item of MAIN or of SETTINGS: below the longer list's length. */
#define MENU_CURSORS ((int)MENU_ITEMS > (int)MENU_SETTINGS_COUNT ? (int)MENU_ITEMS \
			                                              : (int)MENU_SETTINGS_COUNT)

/* Its fields: engine/game/sim_table.h. */
#define MENU_FIELDS(X) \
	X(VAL, uint8_t, page, SIM_MAX(MENU_PAGES - 1))        /* enum menu_page */ \
	X(VAL, uint8_t, cursor, SIM_MAX(MENU_CURSORS - 1))    /* item on MAIN or SETTINGS */ \
	/* MAIN's cursor, kept while on a sub-page */ \
	X(VAL, uint8_t, main_cursor, SIM_MAX(MENU_ITEMS - 1)) \
	X(VAL, uint8_t, display, SIM_MAX(MENU_D_COUNT - 1))   /* enum menu_display */ \
	/* CONFIRM: MENU_I_RESET_SCORES or _BOOKS */ \
	X(VAL, uint8_t, confirm, SIM_MAX(MENU_ITEMS - 1)) \
	X(VAL, uint8_t, yes, SIM_MAX(1))                      /* CONFIRM: YES highlighted */ \
	/* render size choice: 0 as configured, 1..MENU_RES_COUNT */ \
	X(VAL, uint8_t, res, SIM_MAX(MENU_RES_COUNT)) \
	/* last reset done: MENU_I_RESET_*, 0 none */ \
	X(VAL, uint8_t, done, SIM_MAX(MENU_ITEMS - 1)) \
	X(VAL, uint16_t, done_t, SIM_ANY)         /* ticks the "done" note has shown */ \
	/* input test: coin pulses since the page opened */ \
	X(VAL, uint32_t, coins_seen, SIM_ANY) \
	X(VAL, uint8_t, snd, SIM_MAX(MENU_SOUNDS - 1))        /* sound test: the entry */ \
	X(VAL, uint32_t, t, SIM_ANY)              /* ticks since the menu was entered */
struct menu {
	MENU_FIELDS(SIM_MEMBER)
};

/* Opens the menu at the main page (res keeps its value). */
void menu_enter(struct menu *m);

/* One tick of the menu, with this tick's button presses (edges, SIM_BT_*)
 * and navigation bits (MENU_NAV_*); may change s->set, s->scores, s->books.
 * Returns 1 when the operator leaves the menu (the sim returns to attract),
 * else 0. */
int menu_tick(struct sim *s, uint8_t pressed, uint8_t nav);

/* Width and height of render size choice i (1..MENU_RES_COUNT); 0 and
 * other values give 0 x 0. */
void menu_res_size(int i, int *w, int *h);

/* Names for the screens: "EASY" "NORMAL" "HARD" "BRUTAL" for difficulty
 * 0..3 (NULL otherwise). */
const char *menu_difficulty_name(int d);

/* The sound test's entry i: "COIN DROP", "LEFT CHANNEL", "RIGHT CHANNEL"
 * ("" out of range). */
const char *menu_sound_name(int i);

/* Draws the menu page for s over the whole frame (menu_draw.c), with the
 * HUD's colours and font (engine/ui/hud.h); DEVICES, LATENCY and INPUT
 * print env->diag's lines (none when NULL). */
void menu_draw(const struct sim *s, const struct hud_env *env, struct r_frame *f);

#endif
