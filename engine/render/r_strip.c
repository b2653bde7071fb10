/*
 * r_strip: what the walk records, and the strip phase that draws it.
 *
 * The frame's columns are cut into strips (R_STRIP_MIN columns or a
 * power-of-two multiple: one strip without a pool, about
 * R_STRIPS_PER_THREAD per thread with one). The walk records each
 * column run (wall part, sky, fill) into the strip of its column. Then
 * each strip is one job: its column runs in bands of rows (every run that
 * reaches a band is drawn there before the next band starts, so the few
 * KiB of frame a band covers stay in the cache while the strip's columns
 * are drawn one after the other), the spans of the visplanes' rows in its
 * columns (r_plane_strip), the black fill of what is left, then sprites
 * and masked middles clipped to its columns. A flat's texel depends only
 * on the pixel's row and column, so a span cut by a strip edge draws what
 * the whole span would, and a run cut by a band edge resumes at the
 * position it stopped at: a strip draws the bytes a single pass over the
 * frame would.
 *
 * The jobs run through the caller's pool (struct r_par) or one after the
 * other. A list that cannot grow makes the walk draw that run at once: the
 * frame stays whole and the same (counted in stats.degraded).
 *
 * With a pool the strips are drawn in two phases, so that the rest of the
 * walk runs beside them rather than before: job 0 of the first sets up the
 * planes' spans (r_plane_prepare) and projects the sprites, while the
 * other jobs draw the strips' column runs (walls and sky, all recorded by
 * then); the second draws each strip's spans, black fill and sprites.
 * When the pool can wait for a job (r_par.wait) both phases are one batch
 * of 2n + 1 jobs, a strip's second-phase job waiting for job 0 and for its
 * own column job (both handed out before it), so a thread done with the
 * column runs goes on with the strips that are ready instead of waiting at
 * the end of a batch for the other thread's last strip; else they are two
 * batches. Runs, spans and the fill write disjoint pixels, so the order
 * changes no byte. While job 0 runs only its own fields change (the
 * planes' set-up, ctx.vis, ctx.st). (The spans were once recorded by job
 * 0 into lists the strips read: every span then crossed from one core's
 * cache to the other's, and recording them took 2.5 to 3.2 times as long
 * on two threads as on one for the same frames.)
 * Each phase hands its strips out costliest first by what each cost in
 * that phase the previous frame (the time the caller's clock measured,
 * r_par.now, else the pixels drawn there), so the last job to start is a
 * cheap one and the threads end together. The two orders differ: a strip
 * of sky costs little in the first phase and its floor much in the second.
 * (With one order by the sum, the first phase at 3840x2160 ended with one
 * thread idle 0.30 ms a frame on average, 0.25 ms with its own, as a
 * batch of its own.)
 */
#include <assert.h>
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/render/r_local.h"

static void r_strips_free(struct r_strip *st, int n)
{
	for (int i = 0; st && i < n; i++) {
		struct r_strip *s = &st[i];

		free(s->cols);
		free(s->order);
		free(s->act);
		free(s->next);
		free(s->band);
		free(s->spanstart);
		free(s->rowc);
		free(s->mbuf);
		free(s->mdep);
	}
	free(st);
}

int r_strip_layout(struct r_ctx *r, int strip_shift, int band_shift)
{
	int n = (r->w + (1 << strip_shift) - 1) >> strip_shift;
	int nbands = (r->h + (1 << band_shift) - 1) >> band_shift;
	/* sizeof is a multiple of the 64-byte alignment */
	struct r_strip *st = aligned_alloc(64, (size_t)n * sizeof(*st));
	int32_t *order = malloc(3 * (size_t)n * sizeof(*order));

	if (!st || !order) {
		free(st);
		free(order);
		return -ENOMEM;
	}
	memset(st, 0, (size_t)n * sizeof(*st));
	for (int i = 0; i < 3 * n; i++)
		order[i] = i % n;
	for (int i = 0; i < n; i++) {
		struct r_strip *s = &st[i];
		int x1;

		s->x0 = i << strip_shift;
		x1 = s->x0 + (1 << strip_shift) - 1;
		s->x1 = x1 < r->w - 1 ? x1 : r->w - 1;
		s->band = malloc((size_t)(nbands + 1) * sizeof(*s->band));
		s->spanstart = malloc((size_t)r->h * sizeof(*s->spanstart));
		s->rowc = calloc((size_t)r->h, sizeof(*s->rowc));
		if (!s->band || !s->spanstart || !s->rowc) {
			r_strips_free(st, n);
			free(order);
			return -ENOMEM;
		}
	}
	r_strip_free(r);
	r->strips = st;
	r->strip_order = order;
	r->nstrips = n;
	r->strip_shift = strip_shift;
	r->band_shift = band_shift;
	r->nbands = nbands;
	return 0;
}

void r_strip_free(struct r_ctx *r)
{
	r_strips_free(r->strips, r->nstrips);
	free(r->strip_order);
	r->strips = NULL;
	r->strip_order = NULL;
	r->nstrips = 0;
}

void r_strip_reset(struct r_ctx *r)
{
	for (int i = 0; i < r->nstrips; i++) {
		struct r_strip *s = &r->strips[i];

		s->ncols = 0;
		s->nspans = 0;
		s->written = s->spanned = s->empty = s->masked = s->degraded = 0;
	}
}

/* Grows s's full list of runs by at least one: the runs and their three
 * scratch arrays grow together. 0 or -1. */
static int r_strip_room(struct r_strip *s)
{
	int cap = s->maxcols, c = cap;

	if (r_grow((void **)&s->cols, &c, sizeof(*s->cols), cap + 1) < 0)
		return -1;
	c = cap;
	if (r_grow((void **)&s->order, &c, sizeof(*s->order), cap + 1) < 0)
		return -1;
	c = cap;
	if (r_grow((void **)&s->act, &c, sizeof(*s->act), cap + 1) < 0)
		return -1;
	c = cap;
	if (r_grow((void **)&s->next, &c, sizeof(*s->next), cap + 1) < 0)
		return -1;
	s->maxcols = c;
	return 0;
}

/* The slot for a new run in column x's strip, or NULL when the list cannot
 * grow (the caller then draws the run at once). */
static inline struct r_col *r_rec_slot(struct r_ctx *r, int x)
{
	struct r_strip *s = &r->strips[x >> r->strip_shift];

	if (s->ncols == s->maxcols && r_strip_room(s) < 0)
		return NULL;
	return &s->cols[s->ncols++];
}

/* Draws run c at once (out of memory for the lists). */
static void r_rec_now(struct r_ctx *r, struct r_col *c)
{
	r->st.degraded++;
	r_draw_run(r, &r->strips[c->x >> r->strip_shift], c, c->y2);
}

void r_rec_col(struct r_ctx *r, int x, int y1, int y2, const uint8_t *col, int h,
	       const uint8_t *cm, uint32_t frac, uint32_t step)
{
	struct r_col now, *c;

	if (y2 < y1)
		return;
	assert(h >= 1 && frac < ((uint32_t)h << 16) && step < ((uint32_t)h << 16));
	c = r_rec_slot(r, x);
	if (!c)
		c = &now;
	c->src = col;
	c->cm = cm;
	c->frac = frac;
	c->step = step;
	c->h = h;
	c->x = (int16_t)x;
	c->y1 = (int16_t)y1;
	c->y2 = (int16_t)y2;
	c->colour = 0;
	c->id = r->id;
	if (c == &now)
		r_rec_now(r, c);
}

void r_rec_fill(struct r_ctx *r, int x, int y1, int y2, uint8_t colour)
{
	struct r_col now, *c;

	if (y2 < y1)
		return;
	c = r_rec_slot(r, x);
	if (!c)
		c = &now;
	c->src = NULL;
	c->cm = NULL;
	c->frac = c->step = 0;
	c->h = 1;
	c->x = (int16_t)x;
	c->y1 = (int16_t)y1;
	c->y2 = (int16_t)y2;
	c->colour = colour;
	c->id = r->id;
	if (c == &now)
		r_rec_now(r, c);
}

/* The strip's column runs, band by band: runs are bucketed by the band
 * they start in (counting sort into order), and a run that goes on past a
 * band's last row is carried into the next band's active list. */
static void r_strip_cols(const struct r_ctx *r, struct r_strip *s)
{
	int32_t *cnt = s->band, *act = s->act, *next = s->next;
	int na = 0, start = 0;

	memset(cnt, 0, (size_t)(r->nbands + 1) * sizeof(*cnt));
	for (int i = 0; i < s->ncols; i++)
		cnt[(s->cols[i].y1 >> r->band_shift) + 1]++;
	for (int b = 0; b < r->nbands; b++)
		cnt[b + 1] += cnt[b];
	/* after this, cnt[b] is the end of band b's runs in order */
	for (int i = 0; i < s->ncols; i++)
		s->order[cnt[s->cols[i].y1 >> r->band_shift]++] = i;
	for (int b = 0; b < r->nbands; b++) {
		int yend = ((b + 1) << r->band_shift) - 1;
		int nn = 0;
		int32_t *t;

		if (yend > r->h - 1)
			yend = r->h - 1;
		for (int k = 0; k < na; k++) {
			struct r_col *c = &s->cols[act[k]];

			r_draw_run(r, s, c, c->y2 < yend ? c->y2 : yend);
			if (c->y2 > yend)
				next[nn++] = act[k];
		}
		for (int k = start; k < cnt[b]; k++) {
			struct r_col *c = &s->cols[s->order[k]];

			r_draw_run(r, s, c, c->y2 < yend ? c->y2 : yend);
			if (c->y2 > yend)
				next[nn++] = s->order[k];
		}
		start = cnt[b];
		t = act;
		act = next;
		next = t;
		na = nn;
	}
}

/* What strip s draws after its column runs; its columns are then final
 * (r_set_strip_done). */
static void r_strip_rest(struct r_ctx *r, struct r_strip *s)
{
	if (r->world)
		r_plane_strip(r, s);
	r_draw_finish(r, s);
	r_things_draw(r, s);
	if (r->strip_done)
		r->strip_done(r->strip_done_arg, s->x0, s->x1 + 1);
}

/* The walk's second half: the planes' span set-up, then the sprites. */
static void r_walk_rest(struct r_ctx *r)
{
	if (r->world) {
		r_plane_prepare(r);
		r_things_project(r, r->wspr, r->wnspr);
	}
}

/* One job without a pool: everything strip i shows. */
static void r_strip_job(void *arg, int i)
{
	struct r_ctx *r = arg;
	struct r_strip *s = &r->strips[i];

	r_strip_cols(r, s);
	r_strip_rest(r, s);
}

/* The caller's clock, or 0 without one. */
static uint64_t r_strip_now(const struct r_ctx *r)
{
	return r->par.now ? r->par.now() : 0;
}

/* First batch: job 0 the walk's rest, job i the column runs of the strip
 * i - 1 places down the costliest-first order. */
static void r_strip_job_cols(void *arg, int i)
{
	struct r_ctx *r = arg;
	struct r_strip *s;
	uint64_t t0;

	if (i == 0) {
		r_walk_rest(r);
		return;
	}
	s = &r->strips[r->strip_order[i - 1]];
	t0 = r_strip_now(r);
	r_strip_cols(r, s);
	s->cost_cols = r_strip_now(r) - t0;
}

/* Second phase, strip s: its spans, fill and sprites, timed. */
static void r_strip_rest_timed(struct r_ctx *r, struct r_strip *s)
{
	uint64_t t0 = r_strip_now(r);

	r_strip_rest(r, s);
	s->cost_rest = r_strip_now(r) - t0;
}

/* Second batch: the strip i places down the second order. */
static void r_strip_job_rest(void *arg, int i)
{
	struct r_ctx *r = arg;

	r_strip_rest_timed(r, &r->strips[r->strip_order[r->nstrips + i]]);
}

/* Both phases as one batch: jobs 0..n as the first batch's, then job
 * n + 1 + k the second phase of the strip k places down the second order,
 * once job 0 (the spans and sprites it draws) and the strip's own column
 * job (the walls its sprites go over) have returned. */
static void r_strip_job_one(void *arg, int i)
{
	struct r_ctx *r = arg;
	int s;

	if (i <= r->nstrips) {
		r_strip_job_cols(arg, i);
		return;
	}
	/* order[n + k] with k = i - n - 1 */
	s = r->strip_order[i - 1];
	r->par.wait(r->par.pool, 0);
	r->par.wait(r->par.pool, 1 + r->strip_order[2 * r->nstrips + s]);
	r_strip_rest_timed(r, &r->strips[s]);
}

/* What strip s cost in the first phase (rest 0) or the second (rest 1). */
static uint64_t r_strip_cost(const struct r_strip *s, int rest)
{
	return rest ? s->cost_rest : s->cost_cols;
}

/* The order of phase rest (0 or 1): the strips by what they cost in it
 * this frame, costliest first, ties by position; the pool hands jobs out
 * in index order. After the first phase's, strip_order[2n + s] is strip
 * s's place in it. */
static void r_strip_sort(struct r_ctx *r, int rest)
{
	int32_t *o = r->strip_order + (rest ? r->nstrips : 0);

	for (int i = 0; i < r->nstrips; i++) {
		uint64_t c = r_strip_cost(&r->strips[i], rest);
		int k = i;

		while (k > 0 && r_strip_cost(&r->strips[o[k - 1]], rest) < c) {
			o[k] = o[k - 1];
			k--;
		}
		o[k] = i;
	}
	if (!rest)
		for (int k = 0; k < r->nstrips; k++)
			r->strip_order[2 * r->nstrips + o[k]] = k;
}

void r_strip_draw_all(struct r_ctx *r, int world)
{
	r->world = world;
	if (r->par.run && r->nstrips > 1 && r->par.wait && 2 * r->nstrips + 1 <= r->par.wait_jobs) {
		r->par.run(r->par.pool, 2 * r->nstrips + 1, r_strip_job_one, r);
	} else if (r->par.run && r->nstrips > 1) {
		r->par.run(r->par.pool, r->nstrips + 1, r_strip_job_cols, r);
		r->par.run(r->par.pool, r->nstrips, r_strip_job_rest, r);
	} else {
		r_walk_rest(r);
		for (int i = 0; i < r->nstrips; i++)
			r_strip_job(r, i);
	}
	for (int i = 0; i < r->nstrips; i++) {
		const struct r_strip *s = &r->strips[i];

		r->st.pixels_written += s->written + s->spanned;
		r->st.pixels_empty += s->empty;
		r->st.pixels_masked += s->masked;
		r->st.degraded += s->degraded;
		r->st.spans += s->nspans;
	}
	/* the next frame's orders, from this frame's costs */
	if (r->par.run && r->nstrips > 1) {
		if (!r->par.now) {
			for (int i = 0; i < r->nstrips; i++) {
				struct r_strip *s = &r->strips[i];

				/* the black fill is drawn in the second batch */
				s->cost_cols = (uint64_t)s->written - s->empty;
				s->cost_rest = (uint64_t)s->spanned + s->masked + s->empty;
			}
		}
		r_strip_sort(r, 0);
		r_strip_sort(r, 1);
	}
}
