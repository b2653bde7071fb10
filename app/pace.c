/*
 * pace: the tick clock (contract in pace.h).
 */
#include "app/pace.h"

#include <errno.h>
#include <time.h>

#include "app/sig.h"
#include "engine/game/sim.h"
#include "input/in.h"

#define PACE_TICK_NS(t) ((uint64_t)(t) * 1000000000ull / SIM_TICRATE)

static void pace_sleep_until(uint64_t deadline_ns)
{
	struct timespec ts = {
		.tv_sec = (time_t)(deadline_ns / 1000000000u),
		.tv_nsec = (long)(deadline_ns % 1000000000u),
	};
	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR)
		if (sig_stop())
			break;
}

void pace_start(struct pace *p, uint64_t now)
{
	p->base = now;
}

uint64_t pace_wait(struct pace *p, uint32_t t)
{
	uint64_t deadline = p->base + PACE_TICK_NS(t), now = in_now_ns(), dropped = 0;

	if (now > deadline + PACE_RESYNC_NS) {
		/* Far behind: do not fast-forward the game, start the clock
		 * again. */
		dropped = (now - deadline) / PACE_TICK_NS(1);
		p->base = now - PACE_TICK_NS(t);
	} else if (now < deadline) {
		pace_sleep_until(deadline);
	}
	return dropped;
}
