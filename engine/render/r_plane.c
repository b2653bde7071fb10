/*
 * r_plane: floors and ceilings as visplanes (Doom's r_plane).
 *
 * While the walls are drawn, each seg marks, per column, the rows of its
 * subsector's floor and ceiling that lie between the clip arrays and the
 * wall's edges into a visplane: a key (height, flat, light; all sky
 * ceilings share one key) and per column the rows top..bot. A plane is
 * reused for the next seg with the same key unless that seg's columns
 * overlap columns it already has, in which case a new plane of the same key
 * starts (r_plane_check). Each frame pixel is marked into at most one plane,
 * since marking also shrinks the clip arrays.
 *
 * After the walls, each strip turns every plane's columns inside it into
 * horizontal spans (Doom's R_MakeSpans: a row's span starts where the
 * plane's column runs first include it and ends where they stop, or at the
 * strip's edges) and draws each span textured with the flat (Doom's
 * R_MapPlane): the row's depth is plane height * w / rowv (rowv = twice the
 * row centre's distance from the horizon, see r_local.h), the world
 * position at column 0's centre and the step per pixel follow from the view
 * direction, and the texel is the flat's, wrapped at 64 units, with Doom's
 * orientation (row = -y, column = x). Light is per row by depth. The sky is
 * drawn by columns instead: texture column from the column's view angle,
 * texel rows at a fixed scale around the horizon, full bright.
 *
 * Sky columns are recorded for the strips (r_strip.c); spans are drawn by
 * the strip's job as they are found (r_plane_strip). Lists grow as needed
 * and are kept between frames; when memory runs out a seg marks nothing
 * and its rows are filled black instead (counted in stats.degraded).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/render/r_local.h"

static unsigned r_plane_hash(fx_t height, uint16_t pic, int light)
{
	uint32_t k = (uint32_t)height * 2654435761u;

	k ^= (uint32_t)pic * 40503u + (uint32_t)light * 9973u;
	return (k ^ (k >> 16)) & (R_PLANE_HASH - 1);
}

void r_plane_clear(struct r_ctx *r)
{
	r->nplanes = 0;
	for (int i = 0; i < R_PLANE_HASH; i++)
		r->plane_hash[i] = -1;
	r->ceilplane = r->floorplane = -1;
}

/* A new plane of the key with no columns, first in its hash chain. */
static int r_plane_new(struct r_ctx *r, fx_t height, uint16_t pic, int light, int sky,
		       const struct lmap_grid *lg)
{
	int i = r->nplanes;
	size_t n = (size_t)r->w;
	struct r_plane *p;
	unsigned hk;

	if (i == r->maxplanes) {
		int cap = r->maxplanes;

		if (r_grow((void **)&r->planes, &cap, sizeof(*r->planes), i + 1) < 0)
			goto fail;
		for (int k = r->maxplanes; k < cap; k++)
			r->planes[k].top = r->planes[k].bot = NULL;
		r->maxplanes = cap;
	}
	p = &r->planes[i];
	if (!p->top) {
		p->top = malloc(n * sizeof(*p->top));
		p->bot = malloc(n * sizeof(*p->bot));
		if (!p->top || !p->bot) {
			free(p->top);
			free(p->bot);
			p->top = p->bot = NULL;
			goto fail;
		}
	}
	p->height = height;
	p->lg = lg;
	p->pic = pic;
	p->light = (uint8_t)light;
	p->sky = (uint8_t)sky;
	/* for surface ids; r_plane_check copies a key for the same subsector */
	p->sector = r->front;
	p->minx = r->w;
	p->maxx = -1;
	/* R_EMPTY in every column; bot is only read where top is set */
	memset(p->top, 0xff, n * sizeof(*p->top));
	hk = r_plane_hash(height, pic, light);
	p->next = r->plane_hash[hk];
	r->plane_hash[hk] = i;
	r->nplanes++;
	return i;
fail:
	r->st.degraded++;
	return -1;
}

int r_plane_find(struct r_ctx *r, fx_t height, uint16_t pic, int light,
		 const struct lmap_grid *lg)
{
	int sky = r_is_sky(r, pic);

	if (sky) {
		height = 0;
		light = 0;
		lg = NULL;
	}
	for (int i = r->plane_hash[r_plane_hash(height, pic, light)]; i >= 0;
	     i = r->planes[i].next) {
		const struct r_plane *p = &r->planes[i];

		/* a sector with a light map has planes of its own */
		if (p->height == height && p->pic == pic && p->light == light && p->lg == lg)
			return i;
	}
	return r_plane_new(r, height, pic, light, sky, lg);
}

int r_plane_check(struct r_ctx *r, int i, int x1, int x2)
{
	struct r_plane *p;
	int lo, hi, x;

	if (i < 0)
		return -1;
	p = &r->planes[i];
	/* columns both in p and in [x1, x2] */
	lo = x1 > p->minx ? x1 : p->minx;
	hi = x2 < p->maxx ? x2 : p->maxx;
	for (x = lo; x <= hi; x++)
		if (p->top[x] != R_EMPTY)
			break;
	if (x > hi) {
		if (x1 < p->minx)
			p->minx = x1;
		if (x2 > p->maxx)
			p->maxx = x2;
		return i;
	}
	i = r_plane_new(r, p->height, p->pic, p->light, p->sky, p->lg);
	if (i >= 0) {
		r->planes[i].minx = x1;
		r->planes[i].maxx = x2;
	}
	return i;
}

/* Fade factor of a plane dist (> 0) units from the eye: a row's fade is
 * (rowv[y] * q) >> 32 = R_FADE_DIST * |y + 0.5 - cy| / (dist * w / 2), i.e.
 * R_FADE_DIST / depth at that row. Capped at 32 per unit of rowv: any
 * row (rowv >= 1) then fades by >= R_FADE_MAX, as the exact value would. */
static int64_t r_plane_q(const struct r_ctx *r, int64_t dist)
{
	/* dist < 2^33, w <= 2^12: den < 2^45; R_FADE_DIST << 48 < 2^59 */
	int64_t q = ((int64_t)R_FADE_DIST << 48) / ((int64_t)r->w * dist);
	int64_t cap = (int64_t)32 << 32;

	return q > cap ? cap : q;
}

/* The set-up of row y for a plane hgt (16.16, > 0) from the eye: the
 * world position at column 0's centre and the step per pixel to the
 * right, 32.32 (Doom's R_MapPlane, with the row's distance from
 * r->yslope). Kept per strip while the plane height stays. */
static const struct r_rowc *r_row_setup(const struct r_ctx *r, struct r_strip *s, int64_t hgt,
					int y)
{
	struct r_rowc *c = &s->rowc[y];

	if (c->h != hgt || c->gen != s->rowgen) {
		/* hgt < 2^33, yslope <= w * 2^17 <= 2^29: product < 2^62 */
		int64_t d = (hgt * r->yslope[y]) >> 16;

		if (d > R_PLANE_DMAX)
			d = R_PLANE_DMAX;
		/* the point on the view axis at depth d, and one pixel's step
		 * to the right, 2d/w along (sin, -cos); |d * sin| <= 2^48 */
		c->h = hgt;
		c->gen = s->rowgen;
		c->sx = d * r->vsin * 2 / r->w;
		c->sy = -(d * r->vcos * 2 / r->w);
		/* column 0's centre is (1 - w) / 2 pixels right of the axis;
		 * the product is at most 2d in magnitude (see above) */
		c->px0 = (int64_t)r->ex * FX_ONE + d * r->vcos + (((int64_t)(1 - r->w) * c->sx) >> 1);
		c->py0 = (int64_t)r->ey * FX_ONE + d * r->vsin + (((int64_t)(1 - r->w) * c->sy) >> 1);
	}
	return c;
}

/* Row y, columns x1..x2 of plane p in strip s. Positions are 6.26 texels
 * (the 32.32 value's bits 6..37, i.e. modulo 64 units; flat rows run along
 * -y, as Doom's) and linear in the column modulo 2^32: column 0's value
 * plus x steps, so every span through a pixel gives it the same texel
 * wherever the span began. With a light map the span is lit in runs of
 * the R_LMAP_RUN-column blocks of the frame, each by the texel under its
 * block's middle column, again whatever the span's ends. */
static void r_map_span(const struct r_ctx *r, struct r_strip *s, const struct r_plane *p,
		       int y, int x1, int x2)
{
	const struct r_rowc *c = r_row_setup(r, s, p->hgt, y);
	uint32_t xs = (uint32_t)(c->sx >> 6), ys = (uint32_t)(-c->sy >> 6);
	uint32_t x0f = (uint32_t)(c->px0 >> 6), y0f = (uint32_t)(-c->py0 >> 6);
	/* rowv < 2^14, q <= 2^37 */
	int64_t fade = ((int64_t)r->rowv[y] * p->q) >> 32;
	int lvl = p->base - (fade > R_FADE_MAX ? R_FADE_MAX : (int)fade);
	struct r_span sp;

	if (lvl < 0)
		lvl = 0;
	sp.flat = p->flat;
	sp.xs = xs;
	sp.ys = ys;
	sp.y = (int16_t)y;
	sp.id = p->id;
	if (!p->lg) {
		sp.cm = r->cmap[lvl];
		sp.x1 = (int16_t)x1;
		sp.x2 = (int16_t)x2;
		sp.xf = x0f + (uint32_t)x1 * xs;
		sp.yf = y0f + (uint32_t)x1 * ys;
		r_draw_span(r, s, &sp);
		return;
	}
	for (int a = x1; a <= x2;) {
		int blk = a & ~(R_LMAP_RUN - 1), b = blk + R_LMAP_RUN - 1 < x2 ? blk + R_LMAP_RUN - 1 : x2;
		/* the block's middle column; m < 2^12, |step| <= 2^49 */
		int64_t m = blk + (R_LMAP_RUN - 1) / 2;
		int64_t mx = (c->px0 + m * c->sx) >> 16, my = (c->py0 + m * c->sy) >> 16;
		int l;

		mx = mx < -MAP_COORD_MAX ? -MAP_COORD_MAX : mx > MAP_COORD_MAX ? MAP_COORD_MAX : mx;
		my = my < -MAP_COORD_MAX ? -MAP_COORD_MAX : my > MAP_COORD_MAX ? MAP_COORD_MAX : my;
		l = lvl - lmap_grid_flat_at(p->lg, (fx_t)mx, (fx_t)my);
		sp.cm = r->cmap[l < 0 ? 0 : l];
		sp.x1 = (int16_t)a;
		sp.x2 = (int16_t)b;
		sp.xf = x0f + (uint32_t)a * xs;
		sp.yf = y0f + (uint32_t)a * ys;
		r_draw_span(r, s, &sp);
		a = b + 1;
	}
}

/* Closes row y's span of p at column x - 1; counted in s->nspans unless it
 * is the rest of a span that began left of the strip (it began at the
 * strip's first column, and the column before has the row too). */
static void r_close_span(const struct r_ctx *r, struct r_strip *s, const struct r_plane *p,
			 int y, int x)
{
	int x1 = s->spanstart[y];

	if (!(x1 == s->x0 && x1 > p->minx && p->top[x1 - 1] != R_EMPTY && p->top[x1 - 1] <= y &&
	      y <= p->bot[x1 - 1]))
		s->nspans++;
	r_map_span(r, s, p, y, x1, x - 1);
}

/* Doom's R_MakeSpans for the step from column x - 1 (rows t1..b1) to
 * column x (rows t2..b2): rows that end close their span at x - 1, rows
 * that begin open one at x. */
static void r_make_spans(const struct r_ctx *r, struct r_strip *s, const struct r_plane *p, int x,
			 int t1, int b1, int t2, int b2)
{
	uint16_t *start = s->spanstart;

	while (t1 < t2 && t1 <= b1) {
		r_close_span(r, s, p, t1, x);
		t1++;
	}
	while (b1 > b2 && b1 >= t1) {
		r_close_span(r, s, p, b1, x);
		b1--;
	}
	while (t2 < t1 && t2 <= b2) {
		start[t2] = (uint16_t)x;
		t2++;
	}
	while (b2 > b1 && b2 >= t2) {
		start[b2] = (uint16_t)x;
		b2--;
	}
}

void r_plane_strip(const struct r_ctx *r, struct r_strip *s)
{
	/* the rows' set-ups of earlier frames no longer count (a new view) */
	if (++s->rowgen == 0) {
		for (int y = 0; y < r->h; y++)
			s->rowc[y].gen = 0;
		s->rowgen = 1;
	}
	for (int i = 0; i < r->nplanes; i++) {
		const struct r_plane *p = &r->planes[i];
		int lo = p->minx > s->x0 ? p->minx : s->x0, hi = p->maxx < s->x1 ? p->maxx : s->x1;
		int tp = R_EMPTY, bp = 0;

		if (p->sky || lo > hi)
			continue;
		/* column lo - 1 counts as empty: a span open there is cut at
		 * the strip's edge and goes on at lo; one step past hi (empty)
		 * closes all */
		for (int x = lo; x <= hi + 1; x++) {
			int t = x <= hi ? p->top[x] : R_EMPTY;
			int b = t == R_EMPTY ? 0 : p->bot[x];

			r_make_spans(r, s, p, x, tp, bp, t, b);
			tp = t;
			bp = b;
		}
	}
}

void r_plane_prepare(struct r_ctx *r)
{
	for (int i = 0; i < r->nplanes; i++) {
		struct r_plane *p = &r->planes[i];

		if (p->sky || p->minx > p->maxx)
			continue;
		p->hgt = (int64_t)p->height - r->ez;
		if (p->hgt < 0)
			p->hgt = -p->hgt;
		p->flat = r_flat_px(r, p->pic);
		p->base = r_light_base(p->light);
		p->q = r_plane_q(r, p->hgt);
		/* only floors are below the eye, only ceilings above (r_bsp.c) */
		p->id = r_id(p->height < r->ez ? R_IDK_FLOOR : R_IDK_CEIL, p->sector);
	}
}

/* The sky in the plane's columns: texture column (view angle + column
 * angle) >> R_SKY_SHIFT wrapped at the texture's width (Doom's), texel row
 * R_SKY_MID at the horizon and R_SKY_COLS texels per frame width; rows
 * above the texture's top repeat its top texel. Full bright. */
static void r_plane_sky(struct r_ctx *r, const struct r_plane *p)
{
	const struct tex_pic *sky = r_wall_pic(r, (uint16_t)(r->tex->sky_tex > 0 ? r->tex->sky_tex : 0));
	const uint8_t *cm = r->cmap[0];
	int64_t step, hf;

	if (!sky) {
		r->st.missing++;
		sky = &r->fb_pic;
	}
	r->id = r_id(R_IDK_SKY, 0);
	hf = (int64_t)sky->h << 16;
	step = ((int64_t)R_SKY_COLS << 16) / r->w;
	for (int x = p->minx; x <= p->maxx; x++) {
		int y1 = p->top[x], y2, col;
		const uint8_t *src;
		int64_t v;

		if (y1 == R_EMPTY)
			continue;
		y2 = p->bot[x];
		col = (int)(((r->angle + r->xtoang[x]) >> R_SKY_SHIFT) % (uint32_t)sky->w);
		src = sky->px + (size_t)col * (size_t)sky->h;
		/* texel row at y1's centre: R_SKY_MID + (y1 + 0.5 - cy) * step */
		v = ((int64_t)R_SKY_MID << 16) + (((int64_t)(2 * y1 + 1 - r->cy2) * step) >> 1);
		if (v < 0) {
			/* rows y1 .. y1 + n - 1 are above the texture */
			int64_t n = (-v + step - 1) / step;
			int ye = n > y2 - y1 + 1 ? y2 : y1 + (int)n - 1;

			r_rec_fill(r, x, y1, ye, cm[src[0]]);
			v += n * step;
			y1 = ye + 1;
		}
		if (y1 <= y2)
			r_rec_col(r, x, y1, y2, src, sky->h, cm, (uint32_t)(v % hf),
				   (uint32_t)(step % hf));
	}
}

void r_plane_draw_sky(struct r_ctx *r)
{
	for (int i = 0; i < r->nplanes; i++) {
		struct r_plane *p = &r->planes[i];

		if (p->minx <= p->maxx && p->sky)
			r_plane_sky(r, p);
	}
}
