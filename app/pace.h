/*
 * pace: the 60 Hz tick clock. Tick t is due at start + t * 10^9 / 60 ns
 * (CLOCK_MONOTONIC, computed from the start so it never drifts); waiting is
 * an absolute clock_nanosleep. Further behind than PACE_RESYNC_NS (a
 * suspended process, a debugger) the clock starts again rather than
 * fast-forwarding the game, and the ticks skipped are counted.
 */
#ifndef ARCADED_APP_PACE_H
#define ARCADED_APP_PACE_H

#include <stdint.h>

#define PACE_RESYNC_NS 250000000ull

struct pace {
	uint64_t base;             /* when tick 0 was due */
};

/* Tick 0 is due at now. */
void pace_start(struct pace *p, uint64_t now);

/* Sleeps until tick t is due (returns at once when it is). A stop signal
 * (app/sig.h) ends the sleep early. Returns the number of ticks dropped by
 * starting the clock again (0 normally). */
uint64_t pace_wait(struct pace *p, uint32_t t);

#endif
