/*
 * tab: the integer parts of table trigonometry (the tables themselves are in
 * the generated tab_data.c).
 */
#include "engine/core/tab.h"

#include <stdint.h>

/* tan of the angle as a tab_tantoangle index: num/den scaled to
 * [0, TAB_SLOPERANGE], rounded to nearest. Requires num <= den, den > 0;
 * num * 2048 < 2^43, so the 64-bit product is exact. */
static uint32_t tab_slope(uint64_t num, uint64_t den)
{
	return (uint32_t)((num * TAB_SLOPERANGE + den / 2) / den);
}

/*
 * Folds the vector into the first octant (0..45 degrees), looks the angle up
 * there and unfolds it. Doom's R_PointToAngle does the same with a 32-bit
 * SlopeDiv that loses precision for short vectors; here the division is
 * exact 64-bit, so the error is at most half a table step (about 0.014
 * degrees) for every vector. Axes and diagonals are exact: (+x, 0) is 0,
 * (0, +y) ANG90, (-x, 0) ANG180, (0, -y) ANG270, (d, d) ANG45.
 */
ang_t tab_atan2(fx_t dy, fx_t dx)
{
	uint64_t ax = dx < 0 ? (uint64_t)(-(int64_t)dx) : (uint64_t)dx;
	uint64_t ay = dy < 0 ? (uint64_t)(-(int64_t)dy) : (uint64_t)dy;
	ang_t a;

	if (ax == 0 && ay == 0)
		return 0;
	if (ax >= ay)
		a = tab_tantoangle[tab_slope(ay, ax)];
	else
		a = ANG90 - tab_tantoangle[tab_slope(ax, ay)];
	if (dx >= 0)
		return dy >= 0 ? a : 0u - a;
	return dy >= 0 ? ANG180 - a : ANG180 + a;
}
