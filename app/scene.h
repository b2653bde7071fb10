/*
 * scene: what the cabinet shows. Owns the frame (8-bit palette indices at
 * the render size), the software renderer and its worker threads, the
 * OSMesa renderer plugin when --renderer gl asks for it (app/glr.h), the
 * view that draws the game into the frame (app/view.h), and the display
 * (display/dp.h, reached only through its table) that shows it. The render
 * size follows the service menu's choice.
 *
 * A cabinet's display may be missing at start (a nomodeset kernel, a slow
 * DRM driver, a node the service may not open yet): then the null display
 * stands in (the game runs, nothing is shown), the reason is kept, and the
 * display is opened again on a notice from where display nodes appear
 * (dp_backend.node, through input/hp.h) or every SCENE_RETRY_NS, until it
 * opens. Headless runs (scripts, replays) never wait: a display that does
 * not open stops them.
 */
#ifndef ARCADED_APP_SCENE_H
#define ARCADED_APP_SCENE_H

#include <stdint.h>

#include "display/dp.h"

#include "app/glr.h"
#include "app/view.h"
#include "config/cfg.h"
#include "display/px.h"
#include "engine/render/r_main.h"

struct ct;
struct hp;
struct dp;
struct dp_backend;
struct dp_flip;
struct pool;
struct sim;
struct wiz;
struct pick;

struct scene {
	const struct cfg *cfg;
	const struct ct *ct;       /* borrowed: stages, textures, palette */
	struct view view;
	struct r_ctx *r;
	struct pool *pool;         /* render worker threads, NULL: one thread */
	struct r_par par;
	struct px_par ppar;        /* the same pool for the display's present */
	int use_gl;                /* --renderer gl */
	struct glr glr;
	struct rgl_ctx *gl;
	struct r_frame frame;
	uint8_t res;               /* the service menu's render size in effect */
	const struct dp_backend *dpb;
	struct dp *dp;
	int present_errors;
	/* The display is missing: the null display stands in (see above). */
	int waiting;
	char missing[1200];        /* why, as the log and the status say it */
	struct hp *hp;             /* display node notices while waiting, NULL none */
	uint64_t retry_ns;         /* the next periodic try */
	uint64_t shown;            /* frames presented on the display asked for */
	int event_errors;          /* the display's event entry failed (flips) */
};

#define SCENE_RETRY_NS 1000000000ull

/* What scene_poll_display found. */
enum scene_poll {
	SCENE_SAME,                /* nothing new */
	SCENE_STILL_MISSING,       /* still none, for another reason (missing says it) */
	SCENE_ACQUIRED,            /* the display opened: frames are shown from now on */
};

/* Prepares s for the content ct with configuration c (rotation, render
 * threads, the service menu's sizes) at render size w x h; gl: draw the
 * world with the OSMesa plugin. 0 or -errno (logged). */
int scene_init(struct scene *s, const struct cfg *c, const struct ct *ct, int gl, int w, int h);

/* (Re)makes the frame and the renderer at w x h. 0 or -errno (logged);
 * the old ones stay on failure. */
int scene_resize(struct scene *s, int w, int h);

/* Opens the configured display (headless: unless one is named, the file
 * framebuffer when configured, else none) for the frame's size, with the
 * content's palette. Not headless, a display that does not open (the
 * one named, or with "auto" any but the null display) is waited for:
 * waiting is set, missing says why (both logged), and 0 is returned.
 * 0 or -errno (logged). */
int scene_open_display(struct scene *s, int headless);

/* Once per tick while waiting (else SCENE_SAME at once): on a display
 * node notice, or when SCENE_RETRY_NS passed since the last try (now_ns:
 * CLOCK_MONOTONIC), tries the configured display again. Logged. */
enum scene_poll scene_poll_display(struct scene *s, uint64_t now_ns);

/* Once per tick: the service menu changed the render size, the frame
 * follows. */
void scene_follow_menu(struct scene *s, const struct sim *sim);

/* Draws the frame (the wizard's screen when wiz is not NULL, else the
 * service menu's app page when pick is not NULL (app/pick.h), else sim,
 * over the attract demo's under when not NULL) and presents it; a
 * successful present on the display asked for (not a stand-in) counts in
 * shown. 0 or the present's -errno (the first failure is logged). */
int scene_show(struct scene *s, const struct sim *sim, const struct sim *under,
	       const struct wiz *wiz, const struct pick *pick);

/* The display's fd to watch between ticks (dp_backend.wait_fd), -1 none. */
int scene_wait_fd(struct scene *s);

/* Serves the display's fd (dp_backend.event) without blocking: up to max
 * page flips completed since the last call into done; their count (0
 * for a display without events; an error is logged once and counts 0). */
int scene_flips(struct scene *s, struct dp_flip *done, int max);

/* The display's counters (dp_backend.status) or NULL. */
const char *scene_status(struct scene *s);

/* Closes the display (the console back in text mode, the terminal
 * restored); NULL-safe state. */
void scene_close_display(struct scene *s);

/* Frees everything else. */
void scene_free(struct scene *s);

#endif
