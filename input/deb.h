/*
 * deb: software debounce for switches on GPIO lines, and coin pulse
 * counting. Pure state machines on (time, level) events: no I/O, no clock.
 * Times are CLOCK_MONOTONIC ns (the kernel's edge timestamps) and must not
 * decrease from one call to the next.
 *
 * Debounce ("report first, then ignore"): the first edge that changes the
 * reported level is reported at once, stamped with that edge's own time,
 * so debouncing adds no latency. Edges during the hold-off that follows
 * (default 5 ms; switch bounce lasts 1-5 ms) are bounce: they change
 * nothing but are remembered. When the hold-off is over and the line's
 * last known level differs from the reported one (the switch was tapped
 * for less than the hold-off, or its settling edge fell inside the
 * hold-off), deb_poll reports that level, stamped with the time of the
 * edge that set it; a new hold-off runs from that edge. The caller polls
 * at least once per tick.
 *
 * Consequences, by design: a noise spike on a line reads as a press of one
 * hold-off (use coin pulse limits, or a longer hold-off, on noisy wiring);
 * a real tap shorter than the hold-off reads as a press of one hold-off;
 * the kernel may merge edges, so two events with the same level are
 * handled (the second changes nothing).
 *
 * Coin pulses: a coin mechanism closes its switch for one pulse per coin
 * (typically 20-100 ms, 50 ms common). deb_coin debounces the line, then
 * measures each pulse from its debounced start to its debounced end, and
 * credits one coin at the end when the width is within [min, max]
 * (defaults 10 ms and 250 ms). Narrower pulses are noise (a spike reads as
 * one hold-off wide, below the minimum); wider ones are a jammed or
 * tampered switch (a coin held on a string). Both are counted as rejected.
 * The coin is credited at the end of its pulse, stamped with that time.
 */
#ifndef ARCADED_INPUT_DEB_H
#define ARCADED_INPUT_DEB_H

#include <stdint.h>

#define DEB_HOLDOFF_NS 5000000ull          /* 5 ms */
#define DEB_COIN_MIN_NS 10000000ull        /* 10 ms */
#define DEB_COIN_MAX_NS 250000000ull       /* 250 ms */

struct deb {
	uint64_t holdoff_ns;
	uint64_t until_ns;     /* edges before this are bounce */
	uint64_t raw_ns;       /* time of the last edge seen */
	uint8_t level;         /* the reported level */
	uint8_t raw;           /* the last edge's level */
};

/* A reported change: the line is now at level (1 active, 0 not) since
 * time_ns. */
struct deb_ev {
	uint64_t time_ns;
	int level;
};

/* Starts with level reported and no hold-off running (holdoff_ns 0: the
 * default). */
void deb_init(struct deb *d, uint64_t holdoff_ns, int level);

/* An edge: the line went to level (non-zero: active) at time t. Stores the
 * reported changes in out (room for 2) and returns how many: first what
 * deb_poll(d, t) would report (a change that settled before this edge and
 * was not polled yet), then this edge's own change, if any. */
int deb_edge(struct deb *d, uint64_t t, int level, struct deb_ev out[2]);

/* Time passes: returns 1 and fills out when the hold-off is over and the
 * line's last level differs from the reported one (see above), else 0. */
int deb_poll(struct deb *d, uint64_t now, struct deb_ev *out);

/* The line's level read directly at time now (for sources whose events
 * may merge or carry a stale level, like GPIO v1 edge events): it replaces
 * the last edge's level (keeping that edge's time when they agree, else
 * taking now), then acts as deb_poll. */
int deb_settle(struct deb *d, uint64_t now, int level, struct deb_ev *out);

/* The reported level. */
int deb_level(const struct deb *d);

struct deb_coin {
	struct deb d;
	uint64_t min_ns, max_ns;
	uint64_t start_ns;     /* debounced start of the pulse under way */
	uint32_t coins;        /* credited since init */
	uint32_t rejected;     /* pulses out of [min, max] */
};

/* holdoff_ns, min_ns, max_ns 0: the defaults. The line starts inactive. */
void deb_coin_init(struct deb_coin *c, uint64_t holdoff_ns, uint64_t min_ns, uint64_t max_ns);

/* An edge of the coin line. Returns 1 (and sets *credit_ns to the time of
 * the pulse's end) when it completes a pulse that counts as a coin, else
 * 0. */
int deb_coin_edge(struct deb_coin *c, uint64_t t, int level, uint64_t *credit_ns);

/* Time passes (once per tick at least); same return as deb_coin_edge. */
int deb_coin_poll(struct deb_coin *c, uint64_t now, uint64_t *credit_ns);

/* deb_settle for the coin line; same return as deb_coin_edge. */
int deb_coin_settle(struct deb_coin *c, uint64_t now, int level, uint64_t *credit_ns);

#endif
