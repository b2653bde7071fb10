/*
 * pace: the 60 Hz tick clock. Tick t is due at start + t * 10^9 / 60 ns
 * (CLOCK_MONOTONIC, computed from the start so it never drifts); waiting is
 * an absolute clock_nanosleep. Further behind than PACE_RESYNC_NS (a
 * suspended process, a debugger) the clock starts again rather than
 * fast-forwarding the game, and the ticks skipped are counted.
 *
 * While it waits, the loop may also watch one file descriptor (a display
 * whose page flips complete between ticks: dp_backend.wait_fd); the sleep
 * is then a ppoll until the tick is due, calling back each time the fd is
 * readable.
 */
#ifndef ARCADED_APP_PACE_H
#define ARCADED_APP_PACE_H

#include <stdint.h>

#define PACE_RESYNC_NS 250000000ull

struct pace {
	uint64_t base;             /* when tick 0 was due */
};

/* What the wait also watches: fd (-1 none) readable calls ready(ctx),
 * which must take what made it readable. An fd that reports an error or
 * hang-up is not watched again during that wait. */
struct pace_fd {
	int fd;
	void (*ready)(void *ctx);
	void *ctx;
};

/* Tick 0 is due at now. */
void pace_start(struct pace *p, uint64_t now);

/* When tick t is due (CLOCK_MONOTONIC ns). */
uint64_t pace_due(const struct pace *p, uint32_t t);

/* Sleeps until tick t is due (returns at once when it is), serving w (NULL:
 * nothing to watch) meanwhile. A stop signal (app/sig.h) ends the sleep
 * early. Returns the number of ticks dropped by starting the clock again
 * (0 normally). */
uint64_t pace_wait(struct pace *p, uint32_t t, const struct pace_fd *w);

#endif
