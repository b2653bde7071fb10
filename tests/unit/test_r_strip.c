/*
 * Tests for engine/render/r_strip.c: the frame does not depend on how it is cut
 * into strips and bands, nor on how many threads draw the strips.
 *
 * The reference is one strip as wide as the frame with one band as tall as
 * it, drawn on the calling thread: every recorded run and span is then
 * drawn whole, in the order the walk recorded them, which is the single
 * pass the renderer made before it had strips. Every other layout (the
 * default, narrow strips with short bands, strips that leave a narrower
 * last one) and pools of 2 and 3 threads must give the same bytes and the
 * same counters, over many seeded views of the built-in levels and of
 * Freedoom maps, with sprites (given to r_render, or from beside the walk
 * with r_beside_sprites) and with the maps' light maps (which light the
 * flats' spans in blocks of columns, so a span cut at a strip edge must
 * still be lit as the whole one is).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include <errno.h>

#include "app/ct.h"
#include "app/pool.h"
#include "engine/map/lmap.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"
#include "engine/map/wad.h"
#include "engine/render/r_game.h"
#include "engine/render/r_local.h"
#include "engine/render/r_main.h"

static uint32_t lcg(uint32_t *s)
{
	*s = *s * 1664525u + 1013904223u;
	return *s >> 8;
}

/* A seeded view of map m: a point between two vertices plus up to 64
 * units (inside a sector or outside every one), 8 to 87 units above the
 * floor there, any angle, shear -100..100. */
static struct r_view seeded_view(const struct map *m, uint32_t *seed)
{
	struct r_view v = { 0 };
	const struct map_vertex *a = &m->vertices[lcg(seed) % m->num_vertices];
	const struct map_vertex *b = &m->vertices[lcg(seed) % m->num_vertices];

	v.x = a->x / 2 + b->x / 2 + (fx_t)(lcg(seed) % 64) * FX_ONE;
	v.y = a->y / 2 + b->y / 2 + (fx_t)(lcg(seed) % 64) * FX_ONE;
	v.z = m->sectors[map_point_sector(m, v.x, v.y)].floor_h + (fx_t)(8 + lcg(seed) % 80) * FX_ONE;
	v.angle = lcg(seed) * 2654435761u;
	v.shear = (int32_t)(lcg(seed) % 201) - 100;
	return v;
}

/* One way of drawing: a context with a strip layout, and a pool or none. */
struct way {
	struct r_ctx *r;
	struct pool *pool;
	uint8_t *px;
	struct r_frame f;
	struct r_stats st;
	const char *name;
	uint8_t *snap;                  /* each strip's columns when r_set_strip_done's call came */
	int *done;                      /* calls that covered each column */
	_Atomic int beside;             /* r_set_beside_walk calls returned this frame */
	_Atomic int early;              /* strip-done calls that came before one had */
	/* the odd ways give the frame's sprites from beside the walk
	 * (r_beside_sprites) and r_render none */
	int via_beside;
	const struct r_sprite *spr;
	int nspr;
};

/* r_set_beside_walk: gives the sprites when the way does, counts its
 * returns. */
static void way_beside(void *arg)
{
	struct way *w = arg;

	if (w->via_beside)
		r_beside_sprites(w->r, w->spr, w->nspr);
	w->beside++;
}

/* r_set_strip_done: copies the strip's columns as they are now. */
static void way_strip_done(void *arg, int x0, int x1)
{
	struct way *w = arg;

	if (w->beside != 1)
		w->early++;
	for (int y = 0; y < w->f.h; y++)
		memcpy(w->snap + (size_t)y * (size_t)w->f.w + (size_t)x0,
		       w->px + (size_t)y * (size_t)w->f.pitch + (size_t)x0, (size_t)(x1 - x0));
	for (int x = x0; x < x1; x++)
		w->done[x]++;
}

enum { WAYS = 6 };

/* 0: the reference (one strip, one band, no pool); 1: defaults (one strip,
 * bands); 2: 64-column strips, 8-row bands, 2 threads; 3: defaults for 3
 * threads; 4: 64-column strips, 1-row bands, 2 threads; 5: 64-column
 * strips on 2 threads in two batches (a pool that cannot wait for a job).
 * Ways 2 to 4 draw in one batch whose jobs wait (r_par.wait). */
static void ways_open(struct way *w, int width, int height)
{
	static const char *names[WAYS] = { "reference", "default", "64x8, 2 threads",
					   "default, 3 threads", "64x1, 2 threads",
					   "64 wide, 2 threads, two batches" };

	for (int i = 0; i < WAYS; i++) {
		struct r_par par;

		memset(&w[i], 0, sizeof(w[i]));
		w[i].name = names[i];
		w[i].via_beside = i & 1;
		assert_int_equal(r_new(width, height, &w[i].r), 0);
		w[i].px = malloc((size_t)width * (size_t)height);
		assert_non_null(w[i].px);
		w[i].f = (struct r_frame){ w[i].px, width, height, width, NULL };
		w[i].snap = malloc((size_t)width * (size_t)height);
		w[i].done = calloc((size_t)width, sizeof(*w[i].done));
		assert_non_null(w[i].snap);
		assert_non_null(w[i].done);
		r_set_strip_done(w[i].r, way_strip_done, &w[i]);
		r_set_beside_walk(w[i].r, way_beside, &w[i]);
		if (i >= 2) {
			assert_int_equal(pool_new(i == 3 ? 3 : 2, &w[i].pool), 0);
			pool_r_par(w[i].pool, &par);
			if (i == 5)
				par.wait = NULL;
			assert_int_equal(r_set_par(w[i].r, &par), 0);
		}
		if (i == 0)
			assert_int_equal(r_strip_layout(w[i].r, 12, 12), 0);
		if (i == 2)
			assert_int_equal(r_strip_layout(w[i].r, 6, 3), 0);
		if (i == 4)
			assert_int_equal(r_strip_layout(w[i].r, 6, 0), 0);
		if (i == 5)
			assert_int_equal(r_strip_layout(w[i].r, 6, R_BAND_SHIFT), 0);
	}
	assert_int_equal(w[0].r->nstrips, 1);
	assert_int_equal(w[0].r->nbands, 1);
}

/* The light map of m's light things and lit decorations (as the daemon
 * makes it, app/ct.c), set on every way in place of the last map's; NULL
 * (and none set) when m has no lights. */
static struct lmap *ways_lmap(struct way *w, const struct map *m)
{
	int n = lmap_lights_from_map(m, LMAP_DECOR, NULL, 0);
	struct lmap *lm = NULL;

	if (n > 0) {
		struct lmap_light *lights = calloc((size_t)n, sizeof(*lights));

		assert_non_null(lights);
		lmap_lights_from_map(m, LMAP_DECOR, lights, n);
		assert_int_equal(lmap_new(m, lights, n, &lm), 0);
		free(lights);
	}
	for (int i = 0; i < WAYS; i++)
		r_set_lmap(w[i].r, lm);
	return lm;
}

/* Whether the light map changes the reference's frame of v (drawn again
 * without it): the views do show lit flats. */
static int ways_lit(struct way *w, const struct map *m, const struct tex_set *t,
		    const struct r_view *v, const struct lmap *lm)
{
	size_t bytes = (size_t)w[0].f.w * (size_t)w[0].f.h;
	uint8_t *lit = malloc(bytes);
	int differs;

	assert_non_null(lit);
	memcpy(lit, w[0].px, bytes);
	r_set_lmap(w[0].r, NULL);
	r_render(w[0].r, m, t, v, w[0].spr, w[0].nspr, &w[0].f);
	r_set_lmap(w[0].r, lm);
	differs = memcmp(lit, w[0].px, bytes) != 0;
	free(lit);
	return differs;
}

static void ways_close(struct way *w)
{
	for (int i = 0; i < WAYS; i++) {
		r_free(w[i].r);
		pool_free(w[i].pool);
		free(w[i].px);
		free(w[i].snap);
		free(w[i].done);
	}
}

/* Renders v with every way; all must match the reference byte for byte
 * and counter for counter. Returns the reference's stats. */
static struct r_stats ways_render(struct way *w, const struct map *m, const struct tex_set *t,
				  const struct r_view *v, const struct r_sprite *spr, int nspr,
				  const char *what, int n)
{
	size_t bytes = (size_t)w[0].f.w * (size_t)w[0].f.h;

	for (int i = 0; i < WAYS; i++) {
		memset(w[i].px, 0x5a + i, bytes);
		memset(w[i].done, 0, (size_t)w[i].f.w * sizeof(*w[i].done));
		w[i].beside = 0;
		w[i].early = 0;
		w[i].spr = spr;
		w[i].nspr = nspr;
		if (w[i].via_beside)
			r_render(w[i].r, m, t, v, NULL, 0, &w[i].f);
		else
			r_render(w[i].r, m, t, v, spr, nspr, &w[i].f);
		r_get_stats(w[i].r, &w[i].st);
		/* r_set_beside_walk: once a frame, returned before the first
		 * strip-done call */
		if (w[i].beside != 1 || w[i].early != 0)
			fail_msg("%s, view %d, way %s: %d beside-the-walk calls, %d strip-done "
				 "calls before it returned", what, n, w[i].name, (int)w[i].beside,
				 (int)w[i].early);
		/* r_set_strip_done: once per column, and the columns were final
		 * when it came (the HUD is drawn there then, app/view.c) */
		for (int x = 0; x < w[i].f.w; x++)
			if (w[i].done[x] != 1)
				fail_msg("%s, %s %d, way %s: column %d in %d strip-done calls", what,
					 "view", n, w[i].name, x, w[i].done[x]);
		if (memcmp(w[i].snap, w[i].px, bytes) != 0)
			fail_msg("%s, view %d, way %s: a strip's columns changed after its "
				 "strip-done call", what, n, w[i].name);
	}
	for (int i = 1; i < WAYS; i++) {
		if (memcmp(w[0].px, w[i].px, bytes) != 0) {
			size_t k = 0;

			while (w[0].px[k] == w[i].px[k])
				k++;
			fail_msg("%s view %d %dx%d: %s differs from the reference at (%zu, %zu)",
				 what, n, w[0].f.w, w[0].f.h, w[i].name, k % (size_t)w[0].f.w,
				 k / (size_t)w[0].f.w);
		}
		if (memcmp(&w[0].st, &w[i].st, sizeof(w[0].st)) != 0)
			fail_msg("%s view %d: %s counters differ (written %u/%u masked %u/%u "
				 "spans %u/%u)", what, n, w[i].name, w[0].st.pixels_written,
				 w[i].st.pixels_written, w[0].st.pixels_masked,
				 w[i].st.pixels_masked, w[0].st.spans, w[i].st.spans);
	}
	assert_int_equal(w[0].st.pixels_written, (uint32_t)bytes);
	return w[0].st;
}

static void fake_run(void *pool, int n, void (*job)(void *arg, int i), void *arg)
{
	(void)pool;
	(void)n;
	(void)job;
	(void)arg;
}

/* Without a pool one strip covers the frame; with a pool of t threads the
 * strips are contiguous, start on 64-column boundaries, all but the last
 * are a power of two of 64 or more columns wide, and there are at most 4t
 * of them (at least 2 once the frame is 8t * 64 columns wide). */
static void layout_cuts_whole_cache_lines_per_thread(void **state)
{
	static const int widths[] = { 1, 63, 64, 65, 320, 333, 1280, 1920, 2047, 4096 };
	(void)state;

	for (size_t i = 0; i < sizeof(widths) / sizeof(widths[0]); i++) {
		for (int t = 1; t <= 4; t++) {
			struct r_par par = { fake_run, NULL, t, NULL, NULL, NULL, 0 };
			struct r_ctx *r;
			int w = widths[i], covered = 0;

			assert_int_equal(r_new(w, 50, &r), 0);
			assert_int_equal(r->nstrips, 1);
			assert_int_equal(r_set_par(r, &par), 0);
			if (t == 1)
				assert_int_equal(r->nstrips, 1);
			assert_true(r->nstrips >= 1 && r->nstrips <= R_STRIPS_PER_THREAD * t);
			if (t > 1 && w >= 8 * t * R_STRIP_MIN)
				assert_true(r->nstrips >= 2);
			for (int k = 0; k < r->nstrips; k++) {
				const struct r_strip *s = &r->strips[k];
				int sw = s->x1 - s->x0 + 1;

				assert_int_equal(s->x0, covered);
				assert_int_equal(s->x0 % R_STRIP_MIN, 0);
				assert_true(sw >= 1);
				if (k < r->nstrips - 1)
					assert_true(sw >= R_STRIP_MIN && (sw & (sw - 1)) == 0);
				covered = s->x1 + 1;
			}
			assert_int_equal(covered, w);
			assert_int_equal(r->nbands, (50 + (1 << R_BAND_SHIFT) - 1) >> R_BAND_SHIFT);
			/* back to one strip without the pool */
			assert_int_equal(r_set_par(r, NULL), 0);
			assert_int_equal(r->nstrips, 1);
			r_free(r);
		}
	}
}

/* A stand-in pool that runs every job in index order on this thread. */
static void run_in_order(void *pool, int n, void (*job)(void *arg, int i), void *arg)
{
	(void)pool;
	for (int i = 0; i < n; i++)
		job(arg, i);
}

/* Half h (0: the column runs' batch, 1: the rest's) of r's next orders is
 * a permutation of the strips with cost falling, ties by position. */
static void check_order(const struct r_ctx *r, int h)
{
	const int32_t *o = r->strip_order + h * r->nstrips;
	uint32_t seen = 0;

	for (int k = 0; k < r->nstrips; k++) {
		assert_true(o[k] >= 0 && o[k] < r->nstrips && !(seen & (1u << o[k])));
		seen |= 1u << o[k];
		if (k > 0) {
			const struct r_strip *a = &r->strips[o[k - 1]], *b = &r->strips[o[k]];
			uint64_t ca = h ? a->cost_rest : a->cost_cols;
			uint64_t cb = h ? b->cost_rest : b->cost_cols;

			assert_true(ca > cb || (ca == cb && o[k - 1] < o[k]));
		}
	}
}

/* Each batch hands its strips out costliest first by its own cost: without
 * a clock, the first batch by the pixels the column runs wrote, the second
 * by the spans', sprites' and black fill's. Over the views, the two orders
 * differ (a strip of sky is cheap first and dear after, one of near wall
 * the reverse), so one order for both would fail here. */
static void each_batch_orders_strips_by_its_own_cost(void **state)
{
	struct r_par par = { run_in_order, NULL, 2, NULL, NULL, NULL, 0 };
	struct tex_set *t;
	struct r_ctx *r;
	uint8_t *px = malloc(2048 * 200);
	struct r_frame f = { px, 2048, 200, 2048, NULL };
	uint32_t seed = 4242;
	int differ = 0;
	(void)state;

	assert_non_null(px);
	assert_int_equal(r_pal_set_new(&t), 0);
	assert_int_equal(r_new(2048, 200, &r), 0);
	assert_int_equal(r_set_par(r, &par), 0);
	assert_true(r->nstrips >= 4 && r->nstrips <= 32);
	for (int lv = 0; lv < lvl_builtin_count(); lv++) {
		struct map *m;

		assert_int_equal(lvl_builtin(lv, &m), 0);
		for (int n = 0; n < 20; n++) {
			struct r_view v = seeded_view(m, &seed);

			r_render(r, m, t, &v, NULL, 0, &f);
			for (int i = 0; i < r->nstrips; i++) {
				const struct r_strip *s = &r->strips[i];

				assert_true(s->cost_cols == (uint64_t)s->written - s->empty);
				assert_true(s->cost_rest == (uint64_t)s->spanned + s->masked + s->empty);
			}
			check_order(r, 0);
			check_order(r, 1);
			for (int k = 0; k < r->nstrips; k++)
				assert_int_equal(r->strip_order[2 * r->nstrips + r->strip_order[k]], k);
			differ += memcmp(r->strip_order, r->strip_order + r->nstrips,
					 (size_t)r->nstrips * sizeof(*r->strip_order)) != 0;
		}
		map_free(m);
	}
	assert_true(differ > 0);
	r_free(r);
	r_pal_set_free(t);
	free(px);
}

/* A pool_run that counts its batches. */
static int batches;

static void counting_run(void *pool, int n, void (*job)(void *arg, int i), void *arg)
{
	batches++;
	pool_run(pool, n, job, arg);
}

/* r_set_beside_walk for the batch test: counts its calls. */
static void count_beside(void *arg)
{
	(*(int *)arg)++;
}

/* A frame's strips are one batch on a pool that can wait for a job, two
 * on one that cannot; the frames are the same (the ways below compare
 * them on many views). Work beside the walk adds one batch, the walk and
 * it, and is called once. */
static void strips_are_one_batch_when_the_pool_can_wait(void **state)
{
	struct tex_set *t;
	struct map *m;
	struct pool *p;
	struct r_par par;
	struct r_ctx *r;
	uint8_t *px = malloc(1024 * 200);
	struct r_frame f = { px, 1024, 200, 1024, NULL };
	struct r_view v;
	uint32_t seed = 99;
	(void)state;

	assert_non_null(px);
	assert_int_equal(r_pal_set_new(&t), 0);
	assert_int_equal(lvl_builtin(0, &m), 0);
	v = seeded_view(m, &seed);
	assert_int_equal(pool_new(2, &p), 0);
	assert_int_equal(r_new(1024, 200, &r), 0);
	for (int k = 0; k < 4; k++) {
		int can = k & 1, beside = k >> 1, calls = 0;

		pool_r_par(p, &par);
		par.run = counting_run;
		if (!can)
			par.wait = NULL;
		assert_int_equal(r_set_par(r, &par), 0);
		assert_true(r->nstrips > 1);
		r_set_beside_walk(r, beside ? count_beside : NULL, &calls);
		batches = 0;
		r_render(r, m, t, &v, NULL, 0, &f);
		assert_int_equal(batches, (can ? 1 : 2) + beside);
		assert_int_equal(calls, beside);
	}
	r_free(r);
	pool_free(p);
	map_free(m);
	r_pal_set_free(t);
	free(px);
}

/* Views of every built-in level: seeded points of the map's box (some
 * outside every sector), angles and shears, at two sizes. */
static void builtin_levels_same_frame_every_way(void **state)
{
	static const int sizes[][2] = { { 320, 240 }, { 333, 199 } };
	struct tex_set *t;
	uint32_t seed = 777;
	int lit = 0;
	(void)state;

	assert_int_equal(r_pal_set_new(&t), 0);
	for (size_t z = 0; z < 2; z++) {
		struct way w[WAYS];

		ways_open(w, sizes[z][0], sizes[z][1]);
		for (int lv = 0; lv < lvl_builtin_count(); lv++) {
			struct map *m;
			struct lmap *lm;

			assert_int_equal(lvl_builtin(lv, &m), 0);
			lm = ways_lmap(w, m);
			for (int n = 0; n < 60; n++) {
				struct r_view v = seeded_view(m, &seed);

				ways_render(w, m, t, &v, NULL, 0, "built-in", n);
				if (lm && n < 8)
					lit += ways_lit(w, m, t, &v, lm);
			}
			lmap_free(lm);
			map_free(m);
		}
		ways_close(w);
	}
	/* some views showed flats the light maps lit */
	assert_true(lit > 0);
	r_pal_set_free(t);
}

/* The file at path, or NULL when it does not exist (ct_read_file,
 * app/ct.h); any other failure fails the test. */
static uint8_t *slurp(const char *path, size_t *len)
{
	uint8_t *d = NULL;
	int rc = ct_read_file(path, &d, len);

	if (rc == -ENOENT)
		return NULL;
	assert_int_equal(rc, 0);
	return d;
}

/* Freedoom maps E1M1..E1M4 with their things as sprites: the player start
 * and seeded views from near things (where sprites, masked middles and
 * their clipping are), at 320x200 and 1280x720. */
static void freedoom_maps_same_frame_every_way(void **state)
{
	static const char *maps[] = { "E1M1", "E1M2", "E1M3", "E1M4" };
	static const int sizes[][2] = { { 320, 200 }, { 1280, 720 } };
	const char *path = "/usr/share/games/doom/freedoom1.wad";
	char err[256] = "";
	uint32_t seed = 99;
	struct tex_set *t;
	struct wad *wd;
	uint8_t *data;
	size_t len = 0;
	uint32_t masked = 0;
	int lit = 0;
	(void)state;

	data = slurp(path, &len);
	if (!data)
		skip();
	assert_int_equal(wad_new(&wd), 0);
	assert_int_equal(wad_add(wd, data, len, path, err, sizeof(err)), 0);
	assert_int_equal(tex_load_wad(wd, &t, err, sizeof(err)), 0);
	for (size_t z = 0; z < 2; z++) {
		struct way w[WAYS];

		ways_open(w, sizes[z][0], sizes[z][1]);
		for (size_t i = 0; i < sizeof(maps) / sizeof(maps[0]); i++) {
			struct map *m;
			struct r_sprite *spr;
			struct lmap *lm;
			int nspr;

			assert_int_equal(map_load_wad(wd, t, maps[i], &m, err, sizeof(err)), 0);
			lm = ways_lmap(w, m);
			spr = calloc(m->num_things + 1, sizeof(*spr));
			assert_non_null(spr);
			nspr = r_map_sprites(m, t, spr);
			for (int n = 0; n < (z == 0 ? 40 : 12); n++) {
				const struct map_thing *th = &m->things[lcg(&seed) % m->num_things];
				struct r_view v = { 0 };
				struct r_stats st;

				v.x = th->x + (fx_t)((int32_t)(lcg(&seed) % 257) - 128) * FX_ONE;
				v.y = th->y + (fx_t)((int32_t)(lcg(&seed) % 257) - 128) * FX_ONE;
				v.z = m->sectors[map_point_sector(m, v.x, v.y)].floor_h + 41 * FX_ONE;
				v.angle = lcg(&seed) * 2654435761u;
				v.shear = (int32_t)(lcg(&seed) % 81) - 40;
				st = ways_render(w, m, t, &v, spr, nspr, maps[i], n);
				masked += st.pixels_masked;
				if (lm && n < 8)
					lit += ways_lit(w, m, t, &v, lm);
			}
			free(spr);
			lmap_free(lm);
			map_free(m);
		}
		ways_close(w);
	}
	/* the views did show sprites or masked middles, and lit flats */
	assert_true(masked > 0);
	assert_true(lit > 0);
	tex_free(t);
	wad_free(wd);
	free(data);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(layout_cuts_whole_cache_lines_per_thread),
		cmocka_unit_test(each_batch_orders_strips_by_its_own_cost),
		cmocka_unit_test(strips_are_one_batch_when_the_pool_can_wait),
		cmocka_unit_test(builtin_levels_same_frame_every_way),
		cmocka_unit_test(freedoom_maps_same_frame_every_way),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
