/*
 * gpo: coin meter pulses and the start lamp; rules in gpo.h.
 */
#include "input/gpo.h"

void gpo_init(struct gpo *g, uint64_t on_ns, uint64_t gap_ns, uint64_t blink_ns)
{
	g->on_ns = on_ns ? on_ns : GPO_METER_ON_NS;
	g->gap_ns = gap_ns ? gap_ns : GPO_METER_GAP_NS;
	g->blink_ns = blink_ns ? blink_ns : GPO_BLINK_NS;
	g->phase_end_ns = 0;
	g->queued = 0;
	g->coins_seen = 0;
	g->based = 0;
	g->meter_on = 0;
}

void gpo_update(struct gpo *g, const struct gpo_state *s, uint64_t now, int *meter,
		int *lamp_start)
{
	if (g->based && s->coins_total > g->coins_seen) {
		uint32_t add = s->coins_total - g->coins_seen;

		g->queued = add > UINT32_MAX - g->queued ? UINT32_MAX : g->queued + add;
	}
	g->coins_seen = s->coins_total;
	g->based = 1;
	if (now >= g->phase_end_ns) {
		if (g->meter_on) {
			g->meter_on = 0;
			g->phase_end_ns = now + g->gap_ns;
		} else if (g->queued) {
			g->queued--;
			g->meter_on = 1;
			g->phase_end_ns = now + g->on_ns;
		}
	}
	*meter = g->meter_on;
	*lamp_start = s->credits > 0 && !s->playing && (now / g->blink_ns) % 2 == 0;
}

uint32_t gpo_queued(const struct gpo *g)
{
	return g->queued;
}
