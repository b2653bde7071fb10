/*
 * Test fixture for the specials' tests (test_g_floor, test_g_ceil,
 * test_g_light, test_g_tele, test_g_spec): the sim in play, run for some
 * ticks, USE, and the walk-over of a line as the player's or an enemy's
 * move calls it. The maps come from fix_row (map_fixture.h).
 */
#ifndef ARCADED_TESTS_SPEC_FIXTURE_H
#define ARCADED_TESTS_SPEC_FIXTURE_H

#include <stdint.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "map_fixture.h"

/* One coin a credit, straight into play, easy, 100% volume, the default
 * stage clock, no idle-out (the specials' tests wait without input). */
static const struct sim_settings spec_play = { 1, 0, 1, 0, 0, 100, 1, 0, G_IDLE_OFF, 0 };
static const struct sim_cmd spec_none = { 0 };
static const struct sim_cmd spec_use_cmd = { .buttons = SIM_BT_USE };

static inline void spec_run(struct sim *s, const struct sim_cmd *c, int ticks)
{
	for (int i = 0; i < ticks; i++)
		sim_tick(s, c);
}

/* Body `who` (G_WHO_PLAYER or an enemy) crossing x = line_x at height y,
 * from west to east (east: 1) or back: the walk-over specials it meets, as
 * g_move's caller would run them. */
static inline void spec_cross(struct sim *s, int who, int line_x, int y, int east)
{
	fx_t a = fx_from_int(line_x - 4), b = fx_from_int(line_x + 4);

	if (east)
		g_cross(s, who, a, fx_from_int(y), b, fx_from_int(y), SIM_PLAYER_RADIUS);
	else
		g_cross(s, who, b, fx_from_int(y), a, fx_from_int(y), SIM_PLAYER_RADIUS);
}

/* Runs idle ticks until sector sec's floor (ceiling: its ceiling) is h
 * and no mover holds it, at most max ticks: how many it took, or -1. */
static inline int spec_ticks_to(struct sim *s, uint32_t sec, int ceiling, fx_t h, int max)
{
	for (int t = 1; t <= max; t++) {
		sim_tick(s, &spec_none);
		if ((ceiling ? s->w.sec[sec].ceil_h : s->w.sec[sec].floor_h) == h &&
		    !g_mover_of(s, sec))
			return t;
	}
	return -1;
}

#endif
