/*
 * g_kind: the enemy kinds' numbers (g_game.h struct g_kind_info). Data
 * only: every rule file reads it, and it calls nothing. A wind-up is
 * shorter than the kind's reaction and period (the countdowns it ends;
 * test_g_enemy checks).
 */
#include "engine/game/g_game.h"

const struct g_kind_info g_kinds[G_KINDS] = {
	[G_GRUNT] = { "grunt", 20 * FX_ONE, 40 * FX_ONE, 30, 2 * FX_ONE, 512 * FX_ONE,
		      1024 * FX_ONE, 5, 60, 30, 100, G_GRUNT_WINDUP, 0 },
	[G_BRUTE] = { "brute", 24 * FX_ONE, 44 * FX_ONE, 90, 7 * FX_HALF, 64 * FX_ONE,
		      1024 * FX_ONE, 10, 30, 15, 300, 0, 0 },
	[G_SENTRY] = { "sentry", 20 * FX_ONE, 44 * FX_ONE, 50, 0, 768 * FX_ONE,
		       1024 * FX_ONE, 12, 90, 45, 200, 0, 0 },
	/* damage: its missile's, where it lands (g_missile.c) */
	[G_THROWER] = { "thrower", 20 * FX_ONE, 40 * FX_ONE, 60, 2 * FX_ONE, 768 * FX_ONE,
			1024 * FX_ONE, 10, 100, 40, 150, 0, 0 },
	/* a bite, as the brute's, when it has circled in */
	[G_FLYER] = { "flyer", 16 * FX_ONE, 28 * FX_ONE, 40, 3 * FX_ONE, 64 * FX_ONE,
		      1024 * FX_ONE, 6, 40, 12, 250, 0, 1 },
};
