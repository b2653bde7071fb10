/*
 * gpo: what the cabinet's output lines should show, tick by tick. Pure:
 * the GPIO backend (in_gpio.c) drives real lines from it.
 *
 * Coin meter: an electromechanical counter advances once per pulse on its
 * coil. Each coin the game accepted queues one pulse: on_ns energised, then
 * at least gap_ns off before the next (defaults 50 ms and 50 ms; meters
 * need about 20-50 ms each way). Levels change only when gpo_update is
 * called, so at 60 Hz a 50 ms pulse lasts 50-67 ms. Coins arriving faster
 * than the meter can count wait in the queue; none is lost.
 *
 * Start lamp: blinks (half_ns on, half_ns off, default 250 ms each, phase
 * from the clock) while credits are available and no game is being
 * played; off otherwise.
 */
#ifndef ARCADED_INPUT_GPO_H
#define ARCADED_INPUT_GPO_H

#include <stdint.h>

#define GPO_METER_ON_NS 50000000ull
#define GPO_METER_GAP_NS 50000000ull
#define GPO_BLINK_NS 250000000ull

/* What the game says each tick. coins_total counts every coin accepted
 * since the game started (it only grows; a decrease is taken as a restart
 * of the count and queues nothing). */
struct gpo_state {
	uint32_t coins_total;
	uint32_t credits;
	int playing;
};

struct gpo {
	uint64_t on_ns, gap_ns, blink_ns;
	uint64_t phase_end_ns;    /* the meter's current pulse or gap ends here */
	uint32_t queued;          /* pulses still to give */
	uint32_t coins_seen;
	uint8_t based;            /* coins_seen holds a total */
	uint8_t meter_on;
};

/* 0 for any time: its default. */
void gpo_init(struct gpo *g, uint64_t on_ns, uint64_t gap_ns, uint64_t blink_ns);

/* Takes the game's state at time now (not decreasing between calls) and
 * gives the levels the lines should have (1: energised/lit). */
void gpo_update(struct gpo *g, const struct gpo_state *s, uint64_t now, int *meter,
		int *lamp_start);

/* Pulses queued and not yet started. */
uint32_t gpo_queued(const struct gpo *g);

#endif
