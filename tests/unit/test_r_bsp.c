/*
 * Tests for engine/render/r_bsp.c: the solid-column list (through engine/render/r_local.h)
 * and the traversal's culling, seen in the frame statistics.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/pal.h"
#include "engine/map/map.h"
#include "engine/render/r_local.h"
#include "engine/render/r_main.h"
#include "tests/unit/r_testmap.h"

static struct ttex *tt;

static int setup(void **state)
{
	(void)state;
	tt = tt_new();
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	tt_free(tt);
	return 0;
}

static struct r_ctx *ctx(int w)
{
	struct r_ctx *r;

	assert_int_equal(r_new(w, 10, &r), 0);
	r_solid_reset(r);
	return r;
}

static void solid_runs_merge_when_touching_or_overlapping(void **state)
{
	struct r_ctx *r = ctx(100);
	(void)state;
	assert_int_equal(r->nsolid, 2);
	r_solid_add(r, 5, 9);
	r_solid_add(r, 20, 29);
	assert_int_equal(r->nsolid, 4);
	assert_false(r_solid_covers(r, 5, 29));
	assert_false(r_solid_covers(r, 10, 10));
	/* 10..19 touches both: one run 5..29 */
	r_solid_add(r, 10, 19);
	assert_int_equal(r->nsolid, 3);
	assert_int_equal(r->solid[1].first, 5);
	assert_int_equal(r->solid[1].last, 29);
	assert_true(r_solid_covers(r, 5, 29));
	assert_false(r_solid_covers(r, 4, 29));
	assert_false(r_solid_covers(r, 5, 30));
	/* overlapping from the left, inside, and spanning several runs */
	r_solid_add(r, 40, 50);
	r_solid_add(r, 60, 70);
	r_solid_add(r, 45, 46);
	assert_int_equal(r->nsolid, 5);
	r_solid_add(r, 28, 65);
	assert_int_equal(r->nsolid, 3);
	assert_int_equal(r->solid[1].first, 5);
	assert_int_equal(r->solid[1].last, 70);
	r_free(r);
}

static void solid_edges_merge_with_the_sentinels(void **state)
{
	struct r_ctx *r = ctx(100);
	(void)state;
	r_solid_add(r, 0, 10);
	assert_int_equal(r->nsolid, 2);
	assert_true(r_solid_covers(r, 0, 10));
	r_solid_add(r, 90, 99);
	assert_int_equal(r->nsolid, 2);
	r_solid_add(r, 11, 89);
	/* the whole screen: one run left, which the traversal treats as done */
	assert_int_equal(r->nsolid, 1);
	assert_true(r_solid_covers(r, 0, 99));
	r_free(r);
}

/* Every other column occluded, none touching an edge (which would merge
 * with a sentinel), is the most runs the list can hold: (w - 1) / 2 plus
 * the sentinels. Filling the gaps merges everything into one run. */
static void alternating_columns_fit_and_then_merge(void **state)
{
	static const int ws[] = { 1, 2, 3, 4, 5, 8, 9, 320, 4095, 4096 };
	(void)state;
	for (size_t i = 0; i < sizeof(ws) / sizeof(ws[0]); i++) {
		int w = ws[i];
		struct r_ctx *r = ctx(w);

		for (int x = 1; x <= w - 2; x += 2)
			r_solid_add(r, x, x);
		assert_int_equal(r->nsolid, 2 + (w - 1) / 2);
		assert_true(r->nsolid <= r->maxsolid);
		for (int x = 0; x < w; x++)
			r_solid_add(r, x, x);
		assert_int_equal(r->nsolid, 1);
		r_free(r);
	}
}

static void render_stats(const struct map *m, int x, int y, ang_t a, struct r_stats *st)
{
	struct r_ctx *r;
	struct r_view v = { U(x), U(y), U(64), a, 0 };
	uint8_t *px = malloc(160 * 120);
	struct r_frame f = { px, 160, 120, 160, NULL };

	assert_non_null(px);
	assert_int_equal(r_new(160, 120, &r), 0);
	r_render(r, m, &tt->t, &v, NULL, 0, &f);
	r_get_stats(r, st);
	assert_int_equal(st->pixels_written, 160 * 120);
	r_free(r);
	free(px);
}

/* t_window: A (subsector 0) west of x = 128, the window W (1), B (2) east of
 * x = 144. Facing east from A's centre all three are seen through the open
 * window; facing west, the boxes of W and B lie behind the eye, so the
 * walk never enters them. */
static void subsectors_behind_the_view_are_not_visited(void **state)
{
	struct tmap t;
	struct r_stats st;
	(void)state;
	t_window(&t, 24, 96);
	render_stats(&t.m, 0, 0, 0, &st);
	assert_int_equal(st.subsectors, 3);
	assert_int_equal(st.nodes, 2);
	render_stats(&t.m, 0, 0, ANG180, &st);
	assert_int_equal(st.subsectors, 1);
}

/* With the window closed (its floor meets its ceiling), A's east side is
 * solid in every column when facing east: every column is occluded after
 * A, so neither W nor B is visited. Facing north-east from near A's
 * south-west corner, W's and B's boxes are in the frustum but project only
 * onto columns A's east side has closed, so the solid list culls them. */
static void walk_stops_when_every_column_is_occluded(void **state)
{
	struct tmap t;
	struct r_stats st;
	(void)state;
	t_window(&t, 60, 60);
	render_stats(&t.m, 0, 0, 0, &st);
	assert_int_equal(st.subsectors, 1);
	assert_int_equal(st.pixels_empty, 0);
	render_stats(&t.m, -100, -100, ANG45, &st);
	assert_int_equal(st.subsectors, 1);
	assert_int_equal(st.pixels_empty, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(solid_runs_merge_when_touching_or_overlapping),
		cmocka_unit_test(solid_edges_merge_with_the_sentinels),
		cmocka_unit_test(alternating_columns_fit_and_then_merge),
		cmocka_unit_test(subsectors_behind_the_view_are_not_visited),
		cmocka_unit_test(walk_stops_when_every_column_is_occluded),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
