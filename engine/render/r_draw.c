/*
 * r_draw: the inner loops, and the only code that writes frame pixels.
 *
 * Every function draws for one strip (r_strip.c) and writes only inside
 * its columns, so strips can be drawn by several threads at once. Callers
 * pass runs inside the frame (asserted) and texture positions that stay
 * inside the texture (stated per function in r_local.h), so the loops do
 * no clamping: per pixel a texel fetch, a colormap lookup, a store and an
 * add, no division, no floating point. Writes of the opaque pass (walls,
 * planes, sky, black fill) are counted in the strip's written, which the
 * tests compare with w * h; masked writes (sprites, masked middles) in its
 * masked.
 */
#include <assert.h>
#include <stddef.h>
#include <stdint.h>

#include "engine/render/r_local.h"

/* Surface ids of rows y1..y2 of column x (r_set_idbuf): kept out of the
 * pixel loops, which are the same with and without an id buffer. */
static void r_ids_col(const struct r_ctx *r, int x, int y1, int y2, uint32_t id)
{
	uint32_t *d = r->ids + (size_t)y1 * (size_t)r->w + (size_t)x;

	for (int y = y1; y <= y2; y++, d += r->w)
		*d = id;
}

/* Rows from p down, n of them, texel rows frac >> 16 & mask stepping by
 * step: a power-of-two height divides 2^16, so the 16.16 position wraps
 * by itself. Returns the position after the last row. */
static uint32_t r_col_pow2(uint8_t *p, size_t pitch, int n, const uint8_t *col,
			   const uint8_t *cm, uint32_t mask, uint32_t frac, uint32_t step)
{
	for (; n >= 4; n -= 4) {
		uint32_t f1 = frac + step, f2 = f1 + step, f3 = f2 + step;

		p[0] = cm[col[(frac >> 16) & mask]];
		p[pitch] = cm[col[(f1 >> 16) & mask]];
		p[2 * pitch] = cm[col[(f2 >> 16) & mask]];
		p[3 * pitch] = cm[col[(f3 >> 16) & mask]];
		frac = f3 + step;
		p += 4 * pitch;
	}
	for (; n > 0; n--) {
		*p = cm[col[(frac >> 16) & mask]];
		frac += step;
		p += pitch;
	}
	return frac;
}

/* The same for any height: the position is kept below hf = h << 16 by one
 * subtraction per row (step < hf). */
static uint32_t r_col_any(uint8_t *p, size_t pitch, int n, const uint8_t *col, const uint8_t *cm,
			  uint32_t hf, uint32_t frac, uint32_t step)
{
	for (; n > 0; n--) {
		*p = cm[col[frac >> 16]];
		p += pitch;
		frac += step;
		if (frac >= hf)
			frac -= hf;
	}
	return frac;
}

void r_draw_run(const struct r_ctx *r, struct r_strip *s, struct r_col *c, int y2)
{
	size_t pitch = (size_t)r->pitch;
	uint8_t *p;
	int n = y2 - c->y1 + 1;

	if (n <= 0)
		return;
	assert(c->x >= s->x0 && c->x <= s->x1 && c->y1 >= 0 && y2 <= c->y2 && y2 < r->h);
	p = r->px + (size_t)c->y1 * pitch + (size_t)c->x;
	s->written += (uint32_t)n;
	if (r->ids)
		r_ids_col(r, c->x, c->y1, y2, c->id);
	c->y1 = (int16_t)(y2 + 1);
	if (!c->src) {
		uint8_t v = c->colour;

		for (; n > 0; n--, p += pitch)
			*p = v;
		return;
	}
	/* a power-of-two height's position runs on modulo 2^32 between bands;
	 * any other stays below h << 16 */
	assert(c->h >= 1 && c->step < ((uint32_t)c->h << 16));
	if ((c->h & (c->h - 1)) == 0) {
		c->frac = r_col_pow2(p, pitch, n, c->src, c->cm, (uint32_t)c->h - 1, c->frac, c->step);
	} else {
		assert(c->frac < ((uint32_t)c->h << 16));
		c->frac = r_col_any(p, pitch, n, c->src, c->cm, (uint32_t)c->h << 16, c->frac,
				    c->step);
	}
}

void r_draw_span(const struct r_ctx *r, struct r_strip *s, const struct r_span *sp)
{
	const uint8_t *flat = sp->flat, *cm = sp->cm;
	uint32_t xf = sp->xf, yf = sp->yf, xs = sp->xs, ys = sp->ys;
	int x1 = sp->x1, x2 = sp->x2, n;
	uint8_t *p;

	assert(x1 >= s->x0 && x2 <= s->x1 && x1 <= x2);
	assert(sp->y >= 0 && sp->y < r->h && x1 >= 0 && x2 < r->w);
	p = r->px + (size_t)sp->y * (size_t)r->pitch + (size_t)x1;
	n = x2 - x1 + 1;
	s->spanned += (uint32_t)n;
	if (r->ids)
		for (int i = 0; i < n; i++)
			r->ids[(size_t)sp->y * (size_t)r->w + (size_t)(x1 + i)] = sp->id;
	/* texel (row yf >> 26, column xf >> 26) of the row-major 64x64 flat */
	for (; n >= 4; n -= 4) {
		uint32_t xf1 = xf + xs, yf1 = yf + ys;
		uint32_t xf2 = xf1 + xs, yf2 = yf1 + ys;
		uint32_t xf3 = xf2 + xs, yf3 = yf2 + ys;

		p[0] = cm[flat[((yf >> 20) & 0xfc0) | (xf >> 26)]];
		p[1] = cm[flat[((yf1 >> 20) & 0xfc0) | (xf1 >> 26)]];
		p[2] = cm[flat[((yf2 >> 20) & 0xfc0) | (xf2 >> 26)]];
		p[3] = cm[flat[((yf3 >> 20) & 0xfc0) | (xf3 >> 26)]];
		xf = xf3 + xs;
		yf = yf3 + ys;
		p += 4;
	}
	for (; n > 0; n--) {
		*p++ = cm[flat[((yf >> 20) & 0xfc0) | (xf >> 26)]];
		xf += xs;
		yf += ys;
	}
}

void r_draw_masked(const struct r_ctx *r, struct r_strip *s, int x, int y1, int y2,
		   const uint8_t *col, const uint8_t *op, const uint8_t *cm, uint32_t frac,
		   uint32_t step, uint32_t id)
{
	size_t pitch = (size_t)r->pitch;
	uint8_t *p;
	uint32_t n = 0;

	if (y2 < y1)
		return;
	assert(x >= s->x0 && x <= s->x1 && y1 >= 0 && y2 < r->h);
	p = r->px + (size_t)y1 * pitch + (size_t)x;
	if (r->ids) {
		uint32_t *d = r->ids + (size_t)y1 * (size_t)r->w + (size_t)x, f = frac;

		for (int y = y1; y <= y2; y++, d += r->w, f += step)
			if (!op || op[f >> 16])
				*d = id;
	}
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
	s->masked += n;
}

void r_draw_finish(const struct r_ctx *r, struct r_strip *s)
{
	size_t pitch = (size_t)r->pitch;

	for (int x = s->x0; x <= s->x1; x++) {
		int y1 = r->ceilclip[x] + 1, y2 = r->floorclip[x] - 1;
		uint8_t *p;

		if (y2 < y1)
			continue;
		p = r->px + (size_t)y1 * pitch + (size_t)x;
		for (int y = y1; y <= y2; y++, p += pitch)
			*p = r->black;
		s->written += (uint32_t)(y2 - y1 + 1);
		s->empty += (uint32_t)(y2 - y1 + 1);
		if (r->ids)
			r_ids_col(r, x, y1, y2, r_id(R_IDK_NONE, 0));
	}
}
