/*
 * pick: the service menu's pages that show facts of the machine and change
 * what the app owns, run by the app outside the sim (as the input wizard
 * is, app/wiz.h) when the menu asks for them (engine/game/menu.h: the
 * one-tick pages MENU_CONTENT, MENU_SCREEN, MENU_CONFIG):
 *
 *   CONTENT PACK   the packs: "BUILT-IN LEVELS", then each WAD the content
 *                  directories hold (app/wads.h), then BACK. FIRE on a WAD
 *                  lists where to start: "ALL MAPS" (from its first map),
 *                  or one of its maps (from that map on, in the WAD's
 *                  order), then BACK (to the packs). FIRE on a start, or on
 *                  BUILT-IN LEVELS, is the choice (PICK_CHOSEN).
 *   SCREEN         ROTATION 0/90/180/270 and SCALE INTEGER/FILL (left and
 *                  right, or FIRE, change the value), APPLY (PICK_CHOSEN),
 *                  BACK.
 *   CONFIG ERRORS  the configuration's errors (app/cfgerr.h), file:line and
 *                  reason, cut to the screen; ACKNOWLEDGE (PICK_CHOSEN) and
 *                  BACK, or only BACK when there are none.
 *
 * SERVICE goes back one level (from the top of a page: out of it,
 * PICK_LEFT), as on the sim's pages. A pure state machine: no I/O, no
 * clock, no allocation; the app feeds it the cabinet's controls as
 * PICK_K_* edges, draws it instead of the game, and applies the choice
 * (app/op.h).
 */
#ifndef ARCADED_APP_PICK_H
#define ARCADED_APP_PICK_H

#include <stddef.h>

#include "app/cfgerr.h"
#include "app/wads.h"

struct pal;
struct r_frame;

enum pick_page { PICK_CONTENT, PICK_SCREEN, PICK_CONFIG };

enum pick_status {
	PICK_RUNNING,
	PICK_CHOSEN,                /* the operator chose: the app applies it */
	PICK_LEFT,                  /* left without a choice */
};

/* The controls, as this tick's edges (or repeats). */
#define PICK_K_UP 0x01
#define PICK_K_DOWN 0x02
#define PICK_K_LEFT 0x04
#define PICK_K_RIGHT 0x08
#define PICK_K_FIRE 0x10
#define PICK_K_SERVICE 0x20

/* SCREEN's rows */
enum { PICK_S_ROTATE, PICK_S_SCALE, PICK_S_APPLY, PICK_S_BACK, PICK_S_COUNT };

struct pick {
	int page;                   /* enum pick_page */
	int status;                 /* enum pick_status */
	int maps;                   /* CONTENT: 1 on the pack's start list */
	int cursor;                 /* the row under the cursor */
	int pack;                   /* CONTENT: the WAD chosen or opened, -1 built-in */
	int start;                  /* CONTENT: 0 all maps, k from the pack's map k - 1 */
	int rotate, fill;           /* SCREEN: degrees, 1 fill / 0 integer */
	const struct wads *w;       /* borrowed: CONTENT's packs */
	const struct cfgerr *errs;  /* borrowed: CONFIG's errors */
	char now[80];               /* CONTENT: what plays now, as given */
};

/* Opens CONTENT on the packs of w (borrowed, must outlive the run). now
 * says what plays now (shown under the title, may be NULL). */
void pick_content(struct pick *p, const struct wads *w, const char *now);

/* Opens SCREEN at rotation rotate (0/90/180/270) and scale fill (0/1). */
void pick_screen(struct pick *p, int rotate, int fill);

/* Opens CONFIG ERRORS on e (borrowed). */
void pick_config(struct pick *p, const struct cfgerr *e);

/* One tick's controls (PICK_K_* bits). Returns the status: PICK_RUNNING
 * until a choice or a leaving, then the same on every call. */
enum pick_status pick_keys(struct pick *p, unsigned keys);

/* CONTENT's choice once PICK_CHOSEN: *wad the WAD files for [game] wad
 * (a PWAD follows the first IWAD found, which gives it its textures and
 * sounds), *maps for [game] maps (the start map and every map after it in
 * the pack's order, as many as fit in mlen and at most CT_MAX_STAGES, the
 * stages a run plays (app/ct.h); ALL MAPS: every map from the
 * first); both "" for the built-in levels. Returns 0, or -ENOENT when
 * there is no choice, -ENAMETOOLONG when the WADs' paths do not fit. */
int pick_content_choice(const struct pick *p, char *wad, size_t wlen, char *maps, size_t mlen);

/* Draws the page over the whole frame (any size, text scaled 1 per 240
 * lines as the HUD's), the cursor's row kept in view; colours from pal. */
void pick_draw(const struct pick *p, const struct pal *pal, struct r_frame *f);

#endif
