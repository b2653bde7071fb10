/*
 * r_draw: the inner loops, and the only code that writes frame pixels.
 *
 * Callers pass runs inside the frame (asserted) and texture positions that
 * stay inside the texture (stated per function in r_local.h), so the loops
 * do no clamping: per pixel a texel fetch, a colormap lookup, a store and
 * an add. Writes of the opaque pass (walls, planes, sky, black fill) are
 * counted in stats.pixels_written, which the tests compare with w * h;
 * masked writes (sprites, masked middles) in stats.pixels_masked.
 */
#include <assert.h>
#include <stddef.h>
#include <stdint.h>

#include "engine/r_local.h"

void r_draw_fill(struct r_ctx *r, int x, int y1, int y2, uint8_t colour)
{
	uint8_t *p;
	size_t pitch = (size_t)r->pitch;

	if (y2 < y1)
		return;
	assert(x >= 0 && x < r->w && y1 >= 0 && y2 < r->h);
	p = r->px + (size_t)y1 * pitch + (size_t)x;
	for (int y = y1; y <= y2; y++, p += pitch)
		*p = colour;
	r->st.pixels_written += (uint32_t)(y2 - y1 + 1);
}

void r_draw_col(struct r_ctx *r, int x, int y1, int y2, const uint8_t *col, int h,
		const uint8_t *cm, uint32_t frac, uint32_t step)
{
	size_t pitch = (size_t)r->pitch;
	uint8_t *p;
	int n;

	if (y2 < y1)
		return;
	assert(x >= 0 && x < r->w && y1 >= 0 && y2 < r->h && h >= 1);
	assert(frac < ((uint32_t)h << 16) && step < ((uint32_t)h << 16));
	p = r->px + (size_t)y1 * pitch + (size_t)x;
	n = y2 - y1 + 1;
	r->st.pixels_written += (uint32_t)n;
	if ((h & (h - 1)) == 0) {
		/* h divides 2^16: the 16.16 position wraps by itself */
		uint32_t mask = (uint32_t)h - 1;

		for (; n >= 2; n -= 2) {
			p[0] = cm[col[(frac >> 16) & mask]];
			frac += step;
			p[pitch] = cm[col[(frac >> 16) & mask]];
			frac += step;
			p += 2 * pitch;
		}
		if (n)
			*p = cm[col[(frac >> 16) & mask]];
	} else {
		uint32_t hf = (uint32_t)h << 16;   /* < 2^31: no overflow below */

		while (n--) {
			*p = cm[col[frac >> 16]];
			p += pitch;
			frac += step;
			if (frac >= hf)
				frac -= hf;
		}
	}
}

void r_draw_masked(struct r_ctx *r, int x, int y1, int y2, const uint8_t *col,
		   const uint8_t *op, const uint8_t *cm, uint32_t frac, uint32_t step)
{
	size_t pitch = (size_t)r->pitch;
	uint8_t *p;
	uint32_t n = 0;

	if (y2 < y1)
		return;
	assert(x >= 0 && x < r->w && y1 >= 0 && y2 < r->h);
	p = r->px + (size_t)y1 * pitch + (size_t)x;
	if (!op) {
		for (int y = y1; y <= y2; y++, p += pitch, frac += step)
			*p = cm[col[frac >> 16]];
		n = (uint32_t)(y2 - y1 + 1);
	} else {
		for (int y = y1; y <= y2; y++, p += pitch, frac += step) {
			uint32_t v = frac >> 16;

			if (op[v]) {
				*p = cm[col[v]];
				n++;
			}
		}
	}
	r->st.pixels_masked += n;
}

void r_draw_span(struct r_ctx *r, int y, int x1, int x2, const uint8_t *flat,
		 const uint8_t *cm, uint32_t xf, uint32_t yf, uint32_t xs, uint32_t ys)
{
	uint8_t *p;
	int n;

	if (x2 < x1)
		return;
	assert(y >= 0 && y < r->h && x1 >= 0 && x2 < r->w);
	p = r->px + (size_t)y * (size_t)r->pitch + (size_t)x1;
	n = x2 - x1 + 1;
	r->st.pixels_written += (uint32_t)n;
	/* texel (row yf >> 26, column xf >> 26) of the row-major 64x64 flat */
	for (; n >= 2; n -= 2) {
		p[0] = cm[flat[((yf >> 20) & 0xfc0) | (xf >> 26)]];
		xf += xs;
		yf += ys;
		p[1] = cm[flat[((yf >> 20) & 0xfc0) | (xf >> 26)]];
		xf += xs;
		yf += ys;
		p += 2;
	}
	if (n)
		*p = cm[flat[((yf >> 20) & 0xfc0) | (xf >> 26)]];
}

void r_draw_finish(struct r_ctx *r)
{
	for (int x = 0; x < r->w; x++) {
		int y1 = r->ceilclip[x] + 1, y2 = r->floorclip[x] - 1;

		if (y2 >= y1) {
			r_draw_fill(r, x, y1, y2, r->black);
			r->st.pixels_empty += (uint32_t)(y2 - y1 + 1);
		}
	}
}
