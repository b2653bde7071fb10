/*
 * r_draw: the inner loops, and the only code that writes frame pixels.
 *
 * Callers pass runs inside the frame (asserted); every write is counted in
 * stats.pixels_written, which the tests compare with w * h.
 */
#include <assert.h>
#include <stdint.h>

#include "engine/r_local.h"

void r_draw_fill(struct r_ctx *r, int x, int y1, int y2, uint8_t colour)
{
	uint8_t *p;
	int pitch = r->pitch;

	if (y2 < y1)
		return;
	assert(x >= 0 && x < r->w && y1 >= 0 && y2 < r->h);
	p = r->px + (size_t)y1 * (size_t)pitch + (size_t)x;
	for (int y = y1; y <= y2; y++, p += pitch)
		*p = colour;
	r->st.pixels_written += (uint32_t)(y2 - y1 + 1);
}

void r_draw_plane(struct r_ctx *r, int x, int y1, int y2, uint8_t tex, int base, int64_t q)
{
	const uint8_t(*cmap)[256] = r->pal->cmap;
	const int32_t *rowv = r->rowv;
	uint8_t *p;
	int pitch = r->pitch;

	if (y2 < y1)
		return;
	assert(x >= 0 && x < r->w && y1 >= 0 && y2 < r->h);
	p = r->px + (size_t)y1 * (size_t)pitch + (size_t)x;
	for (int y = y1; y <= y2; y++, p += pitch) {
		/* rowv < 2^15, q <= 2^37 */
		int64_t fade = ((int64_t)rowv[y] * q) >> 32;
		int lvl = base - (fade > R_FADE_MAX ? R_FADE_MAX : (int)fade);

		*p = cmap[lvl < 0 ? 0 : lvl][tex];
	}
	r->st.pixels_written += (uint32_t)(y2 - y1 + 1);
}

void r_draw_finish(struct r_ctx *r)
{
	for (int x = 0; x < r->w; x++) {
		int y1 = r->ceilclip[x] + 1, y2 = r->floorclip[x] - 1;

		if (y2 >= y1) {
			r_draw_fill(r, x, y1, y2, PAL_BLACK);
			r->st.pixels_empty += (uint32_t)(y2 - y1 + 1);
		}
	}
}
