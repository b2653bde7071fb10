/*
 * pace: the tick clock (contract in pace.h).
 */
#include "app/pace.h"

#include <errno.h>
#include <poll.h>
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

/* Until deadline, calling w->ready whenever w->fd is readable. */
static void pace_poll_until(uint64_t deadline_ns, const struct pace_fd *w)
{
	struct pollfd pf = { .fd = w->fd, .events = POLLIN };

	for (;;) {
		uint64_t now = in_now_ns(), left;
		struct timespec ts;
		int rc;

		if (now >= deadline_ns)
			return;
		left = deadline_ns - now;
		ts.tv_sec = (time_t)(left / 1000000000u);
		ts.tv_nsec = (long)(left % 1000000000u);
		rc = ppoll(&pf, 1, &ts, NULL);
		if (rc < 0 && errno == EINTR && sig_stop())
			return;
		if (rc <= 0)
			continue;
		if (pf.revents & (POLLERR | POLLHUP | POLLNVAL)) {
			pace_sleep_until(deadline_ns);
			return;
		}
		w->ready(w->ctx);
	}
}

void pace_start(struct pace *p, uint64_t now)
{
	p->base = now;
}

uint64_t pace_due(const struct pace *p, uint32_t t)
{
	return p->base + PACE_TICK_NS(t);
}

uint64_t pace_wait(struct pace *p, uint32_t t, const struct pace_fd *w)
{
	uint64_t deadline = p->base + PACE_TICK_NS(t), now = in_now_ns(), dropped = 0;

	if (now > deadline + PACE_RESYNC_NS) {
		/* Far behind: do not fast-forward the game, start the clock
		 * again. */
		dropped = (now - deadline) / PACE_TICK_NS(1);
		p->base = now - PACE_TICK_NS(t);
	} else if (now < deadline) {
		if (w && w->fd >= 0)
			pace_poll_until(deadline, w);
		else
			pace_sleep_until(deadline);
	}
	return dropped;
}
