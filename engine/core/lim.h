/*
 * lim: the work bound and the stop hook of a load (issue 13 item 8).
 *
 * Every loader and builder of outside data (WAD directory, textures, maps,
 * the node builder, light maps, grid maps) must end in bounded time and
 * memory, and must end early when the daemon is told to stop. Each one
 * counts its work in steps (one elementary test, post or pixel: a few
 * nanoseconds each) against a limit of its own, stated in its header and
 * chosen far above what any Freedoom map needs, and fails with -E2BIG and
 * a message naming the file, lump and limit when a file asks for more.
 *
 * The engine cannot see signals (no platform headers, no file-scope
 * state): the caller passes a struct lim_stop whose fn the loader calls
 * every LIM_POLL steps; a nonzero answer ends the load with -ECANCELED.
 * The app's fn reads its signal flag, so SIGTERM or SIGINT stops a load
 * within LIM_POLL steps (well under a millisecond).
 */
#ifndef ARCADED_ENGINE_LIM_H
#define ARCADED_ENGINE_LIM_H

#include <stdint.h>

/* Steps between two calls of the stop hook. */
#define LIM_POLL 4096u

/* The caller's stop hook: fn(ctx) returns nonzero when the load must stop
 * now (fn may be NULL: never). Called from the loading thread only; it
 * must not block. steps, when not NULL, receives every step any count
 * polling this hook takes: the work a load did, for figures and tests. */
struct lim_stop {
	int (*fn)(void *ctx);
	void *ctx;
	uint64_t *steps;
};

/* One loader's count, on the loader's stack. */
struct lim {
	const struct lim_stop *stop;   /* borrowed, may be NULL (never stops) */
	uint64_t used;                 /* steps taken so far */
	uint64_t max;                  /* the loader's limit */
	uint64_t poll;                 /* used at which to call stop next */
	int err;                       /* 0, or the error that ended the count */
};

/* Starts a count of at most max steps, polling stop (may be NULL). */
void lim_init(struct lim *l, const struct lim_stop *stop, uint64_t max);

/* Takes n more steps: 0 while within the limit, -E2BIG once used passes
 * max, -ECANCELED once the stop hook said stop (it is called when used
 * crosses a multiple of LIM_POLL). The first error sticks: later calls
 * return it again without counting. */
int lim_take(struct lim *l, uint64_t n);

/* The stop hook alone, for loops that take no counted steps of their own:
 * -ECANCELED when it says stop (sticky, as lim_take), else 0. */
int lim_check(struct lim *l);

#endif
