/* Tests for engine/map/map.c (validation, hash, point location) and
 * engine/map/lvl_builtin.c (the built-in levels). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/msg.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "map_fixture.h"

static const int two_v[][2] = {
	{ 0, 0 }, { 0, 128 }, { 128, 128 }, { 128, 0 }, { 256, 128 }, { 256, 0 },
};
static const struct fix_sector two_s[] = { { 0, 128, 160 }, { 16, 112, 200 } };
/* two rooms side by side, a portal at x = 128 */
static const struct fix_line two_l[] = {
	{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, 1 }, { 3, 0, 0, -1 },
	{ 2, 4, 1, -1 }, { 4, 5, 1, -1 }, { 5, 3, 1, -1 },
};
static const struct fix_map two = { two_v, 6, two_s, 2, two_l, 7, 64, 64, 0 };

/* map_finish on a copy of `two` broken by `breakit`; returns its result. */
static int finish_broken(void (*breakit)(struct map *), char *err, size_t errlen)
{
	struct map *m = fix_alloc(&two);
	int r;
	assert_non_null(m);
	breakit(m);
	r = map_finish(m, err, errlen);
	map_free(m);
	return r;
}

static void bad_v2(struct map *m) { m->lines[2].v2 = 9; }
static void bad_side_sector(struct map *m) { m->sides[1].sector = 5; }
static void low_ceiling(struct map *m) { m->sectors[1].ceil_h = -8 * FX_ONE - FX_HALF; }
static void zero_length(struct map *m) { m->vertices[4] = m->vertices[2]; }
static void bad_side1(struct map *m) { m->lines[2].side[1] = 40; }
static void no_back_side(struct map *m) { m->lines[2].side[1] = MAP_NONE; }
static void unflagged_back(struct map *m) { m->lines[2].flags = 0; }
static void far_vertex(struct map *m) { m->vertices[3].x = fx_from_int(20000); }

static void validation_names_the_bad_entry(void **state)
{
	char err[128];
	(void)state;
	assert_int_equal(finish_broken(bad_v2, err, sizeof err), -EINVAL);
	assert_string_equal(err, "line 2: v2 9 out of range (6 vertices)");
	assert_int_equal(finish_broken(bad_side_sector, err, sizeof err), -EINVAL);
	assert_string_equal(err, "side 1: sector 5 out of range (2 sectors)");
	assert_int_equal(finish_broken(low_ceiling, err, sizeof err), -EINVAL);
	assert_string_equal(err, "sector 1: ceiling -8.5 below floor 16");
	assert_int_equal(finish_broken(zero_length, err, sizeof err), -EINVAL);
	assert_string_equal(err, "line 4: zero length");
	assert_int_equal(finish_broken(bad_side1, err, sizeof err), -EINVAL);
	assert_string_equal(err, "line 2: side[1] 40 out of range (8 sides)");
	assert_int_equal(finish_broken(no_back_side, err, sizeof err), -EINVAL);
	assert_string_equal(err, "line 2: two-sided flag set but no side[1]");
	assert_int_equal(finish_broken(unflagged_back, err, sizeof err), -EINVAL);
	assert_string_equal(err, "line 2: side[1] present but two-sided flag not set");
	assert_int_equal(finish_broken(far_vertex, err, sizeof err), -EINVAL);
	assert_string_equal(err, "vertex 3: coordinates out of range (+/-16384 units)");
}

static void error_message_truncates_safely(void **state)
{
	char err[8];
	(void)state;
	assert_int_equal(finish_broken(bad_v2, err, sizeof err), -EINVAL);
	assert_string_equal(err, "line 2:");
	assert_int_equal(finish_broken(bad_v2, NULL, 0), -EINVAL);
}

static void bad_bsp_is_refused(void **state)
{
	struct map *m = fix_alloc(&two);
	char err[128];
	(void)state;
	assert_non_null(m);
	/* a hand-made BSP: one node whose child points at itself */
	m->segs = calloc(1, sizeof *m->segs);
	m->subsectors = calloc(2, sizeof *m->subsectors);
	m->nodes = calloc(1, sizeof *m->nodes);
	assert_true(m->segs && m->subsectors && m->nodes);
	m->num_segs = m->num_subsectors = m->num_nodes = 1;
	m->segs[0] = (struct map_seg){ .v1 = 0, .v2 = 1, .line = 0, .side = 0, .front = 0,
				       .back = MAP_NONE };
	m->subsectors[0] = (struct map_subsector){ 0, 1, 0 };
	m->nodes[0] = (struct map_node){ .dx = FX_ONE, .child = { 0, MAP_NF_SUBSECTOR } };
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "node 0: child[0] 0 is not a node listed before it "
				 "(children come first)");
	m->nodes[0].child[0] = MAP_NF_SUBSECTOR | 3;
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "node 0: child[0] 3 is not a subsector");
	m->nodes[0].child[0] = MAP_NF_SUBSECTOR;
	m->subsectors[0].num_segs = 2;
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "subsector 0: segs out of range");
	m->subsectors[0].num_segs = 1;
	m->segs[0].v2 = 77;
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "seg 0: vertex 77 out of range (6 vertices)");
	m->segs[0].v2 = 1;
	m->segs[0].front = 1;
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "seg 0: front/back sectors differ from its line's sides");
	m->segs[0].front = 0;
	/* both children the same subsector: a walk reaches it twice */
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "node 0: child[1] subsector 0 is reached a second time: the BSP "
				 "is not a tree");
	m->subsectors[1] = m->subsectors[0];
	m->num_subsectors = 2;
	m->nodes[0].child[1] = MAP_NF_SUBSECTOR | 1;
	assert_int_equal(map_finish(m, err, sizeof err), 0);   /* given BSP is kept */
	assert_int_equal(m->num_nodes, 1);
	map_free(m);
}

/* Issue 13 item 7: nodes that share children make a walk exponential. The
 * first node or subsector reached twice from the root is named; a node no
 * path reaches is left alone. */
static void bsp_that_is_not_a_tree_is_refused(void **state)
{
	struct map *m = fix_build(&two, NULL, 0);
	char err[128];
	(void)state;
	assert_non_null(m);
	assert_int_equal(m->num_nodes, 1);
	/* nodes 0 (as built), 1 and 2 over it: 2 -> {1, 1} */
	m->nodes = realloc(m->nodes, 3 * sizeof *m->nodes);
	assert_non_null(m->nodes);
	m->nodes[1] = m->nodes[0];
	m->nodes[1].child[0] = 0;
	m->nodes[1].child[1] = 0;
	m->nodes[2] = m->nodes[0];
	m->nodes[2].child[0] = 1;
	m->nodes[2].child[1] = 1;
	m->num_nodes = 3;
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "node 2: child[1] node 1 is reached a second time: the BSP is "
				 "not a tree");
	/* 2 -> {1, 0}, 1 -> {0, 0}: node 0 reached from 1 and from 2 */
	m->nodes[2].child[1] = 0;
	assert_int_equal(map_finish(m, err, sizeof err), -EINVAL);
	assert_non_null(strstr(err, "node 0 is reached a second time"));
	/* 2 -> {0 as built}: node 1 is unreachable and harmless */
	m->nodes[2] = m->nodes[0];
	assert_int_equal(map_finish(m, err, sizeof err), 0);
	map_free(m);
}

static void far_floor(struct map *m) { m->sectors[1].floor_h = fx_from_int(-16384); }
static void far_ceiling(struct map *m) { m->sectors[0].ceil_h = fx_from_int(16384); }

/* Issue 13 item 9: heights beyond +/-16383 units are refused (the eye
 * height and the renderer's height differences must fit 16.16). */
static void heights_beyond_the_bound_are_refused(void **state)
{
	char err[128];
	(void)state;
	assert_int_equal(finish_broken(far_floor, err, sizeof err), -EINVAL);
	assert_string_equal(err, "sector 1: floor -16384 or ceiling 112 out of range (+/-16383 "
				 "units)");
	assert_int_equal(finish_broken(far_ceiling, err, sizeof err), -EINVAL);
	assert_string_equal(err, "sector 0: floor 0 or ceiling 16384 out of range (+/-16383 "
				 "units)");
}

static void content_hash_covers_geometry_not_name(void **state)
{
	struct map *a = fix_build(&two, NULL, 0), *b = fix_alloc(&two);
	uint64_t h;
	(void)state;
	assert_non_null(a);
	assert_non_null(b);
	h = a->content_hash;
	b->name[0] = 'X';
	assert_int_equal(map_finish(b, NULL, 0), 0);
	assert_true(b->content_hash == h);
	b->sectors[1].light++;
	b->num_nodes = b->num_subsectors = 0;
	assert_int_equal(map_finish(b, NULL, 0), 0);
	assert_true(b->content_hash != h);
	a->things[0].angle = ANG90;
	a->num_nodes = a->num_subsectors = 0;
	assert_int_equal(map_finish(a, NULL, 0), 0);
	assert_true(a->content_hash != h);
	map_free(a);
	map_free(b);
}

static void point_on_side_is_exact_with_ties_in_front(void **state)
{
	struct map_node east = { .x = 0, .y = 0, .dx = FX_ONE, .dy = 0 };
	struct map_node north = { .x = 0, .y = 0, .dx = 0, .dy = FX_ONE };
	struct map_node diag = { .x = 0, .y = 0, .dx = 3 * FX_ONE, .dy = 2 * FX_ONE };
	(void)state;
	assert_int_equal(map_point_on_side(0, -1, &east), 0);           /* right */
	assert_int_equal(map_point_on_side(0, 1, &east), 1);            /* left */
	assert_int_equal(map_point_on_side(5 * FX_ONE, 0, &east), 0);   /* on the line */
	assert_int_equal(map_point_on_side(-5 * FX_ONE, 0, &east), 0);
	assert_int_equal(map_point_on_side(1, 0, &north), 0);
	assert_int_equal(map_point_on_side(-1, 0, &north), 1);
	/* (3, 2) is on the line; one 1/65536 off either way is decided */
	assert_int_equal(map_point_on_side(3 * FX_ONE, 2 * FX_ONE, &diag), 0);
	assert_int_equal(map_point_on_side(3 * FX_ONE, 2 * FX_ONE + 1, &diag), 1);
	assert_int_equal(map_point_on_side(3 * FX_ONE, 2 * FX_ONE - 1, &diag), 0);
	/* far outside any map: clamped, no overflow */
	assert_int_equal(map_point_on_side(FX_MAX, FX_MIN, &diag), 0);
	assert_int_equal(map_point_on_side(FX_MIN, FX_MAX, &diag), 1);
}

static void builtin_levels_are_listed(void **state)
{
	struct map *m = (struct map *)1;
	(void)state;
	assert_true(lvl_builtin_count() >= 1);
	assert_int_equal(lvl_builtin(-1, &m), -EINVAL);
	assert_null(m);
	assert_int_equal(lvl_builtin(lvl_builtin_count(), &m), -EINVAL);
	assert_int_equal(lvl_builtin(0, &m), 0);
	assert_string_equal(m->name, "ARENA1");
	assert_true(m->num_nodes > 0);
	map_free(m);
	map_free(NULL);
}

/* Points read off ARENA1's plan and tables in levels/arena1.txt. */
static void builtin_points_land_in_their_sectors(void **state)
{
	static const struct { int x, y; uint32_t sector; } pts[] = {
		{ 96, 192, 0 },      /* hall, player start */
		{ 600, 40, 0 },      /* hall, south-east corner */
		{ 420, 600, 0 },     /* hall, the L's north arm next to the notch */
		{ 256, 300, 0 },     /* hall, just south of the pillar */
		{ 200, 656, 1 },     /* step 1 */
		{ 200, 688, 2 },     /* step 2 */
		{ 300, 720, 3 },     /* step 3 */
		{ 600, 1000, 4 },    /* gallery */
		{ 40, 750, 4 },
		{ 700, 900, 5 },     /* yard under the ledge */
		{ 1000, 10, 5 },
		{ 700, 500, 5 },     /* yard, west of the dais */
		{ 864, 512, 6 },     /* dais */
		{ 648, 368, 7 },     /* doorway */
		{ 648, 192, 8 },     /* window */
	};
	struct map *m;
	unsigned i;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	for (i = 0; i < sizeof pts / sizeof pts[0]; i++) {
		uint32_t s = map_point_sector(m, fx_from_int(pts[i].x), fx_from_int(pts[i].y));
		if (s != pts[i].sector)
			fail_msg("(%d, %d): sector %u, want %u", pts[i].x, pts[i].y, s, pts[i].sector);
	}
	map_free(m);
	/* map_finish's sector of each thing, on every built-in level: where
	 * point location puts it */
	for (int lv = 0; lv < lvl_builtin_count(); lv++) {
		assert_int_equal(lvl_builtin(lv, &m), 0);
		assert_non_null(m->thing_sec);
		for (i = 0; i < m->num_things; i++)
			assert_int_equal(m->thing_sec[i],
					 map_point_sector(m, m->things[i].x, m->things[i].y));
		map_free(m);
	}
}

static uint32_t side_sector(const struct map *m, const struct map_line *l, int side)
{
	return m->sides[l->side[side]].sector;
}

/* The level has what issue 2 asks for: steps, a window, a too-high ledge,
 * varied light and a player start. (The non-convex room is checked by
 * point location above: the hall's leaves surround the pillar and notch.) */
static void builtin_level_has_its_features(void **state)
{
	struct map *m;
	uint32_t i, steps = 0, windows = 0, ledges = 0, starts = 0;
	uint8_t lo = 255, hi = 0;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	for (i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_sector *f, *b;
		fx_t rise;
		if (l->side[1] == MAP_NONE)
			continue;
		f = &m->sectors[side_sector(m, l, 0)];
		b = &m->sectors[side_sector(m, l, 1)];
		rise = b->floor_h - f->floor_h;
		rise = rise < 0 ? -rise : rise;
		if (rise >= 8 * FX_ONE && rise <= 16 * FX_ONE)
			steps++;
		if (rise > 24 * FX_ONE)
			ledges++;
		if ((b->floor_h > f->floor_h && b->ceil_h < f->ceil_h) ||
		    (f->floor_h > b->floor_h && f->ceil_h < b->ceil_h))
			windows++;
	}
	for (i = 0; i < m->num_sectors; i++) {
		lo = m->sectors[i].light < lo ? m->sectors[i].light : lo;
		hi = m->sectors[i].light > hi ? m->sectors[i].light : hi;
	}
	for (i = 0; i < m->num_things; i++)
		starts += m->things[i].type == 1;
	assert_true(steps >= 3);
	assert_true(windows >= 1);
	assert_true(ledges >= 1);
	assert_true(hi - lo >= 64);
	assert_int_equal(starts, 1);
	map_free(m);
}

static void builtin_level_is_rebuilt_identically(void **state)
{
	struct map *a, *b;
	(void)state;
	assert_int_equal(lvl_builtin(0, &a), 0);
	assert_int_equal(lvl_builtin(0, &b), 0);
	assert_true(a->content_hash == b->content_hash);
	assert_int_equal(a->num_segs, b->num_segs);
	assert_int_equal(a->num_nodes, b->num_nodes);
	map_free(a);
	map_free(b);
}

static void map_without_nodes_has_one_subsector(void **state)
{
	static const int v[][2] = { { 0, 0 }, { 0, 64 }, { 64, 64 }, { 64, 0 } };
	static const struct fix_line l[] = {
		{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, -1 }, { 3, 0, 0, -1 },
	};
	static const struct fix_map f = { v, 4, two_s, 1, l, 4, 32, 32, 0 };
	struct map *m = fix_build(&f, NULL, 0);
	(void)state;
	assert_non_null(m);
	assert_int_equal(m->num_nodes, 0);
	assert_int_equal(map_point_subsector(m, 0, 0), 0);
	assert_int_equal(map_point_subsector(m, FX_MAX, FX_MIN), 0);
	map_free(m);
}

static void messages_format_numbers(void **state)
{
	char err[64] = "";
	(void)state;
	msg_int(err, sizeof err, INT64_MIN);
	assert_string_equal(err, "-9223372036854775808");
	err[0] = '\0';
	msg_fx(err, sizeof err, -FX_ONE - FX_ONE / 4);
	msg_cat(err, sizeof err, " ");
	msg_fx(err, sizeof err, 1);
	msg_cat(err, sizeof err, " ");
	msg_fx(err, sizeof err, FX_MIN);
	assert_string_equal(err, "-1.25 0.00001 -32768");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(validation_names_the_bad_entry),
		cmocka_unit_test(error_message_truncates_safely),
		cmocka_unit_test(bad_bsp_is_refused),
		cmocka_unit_test(bsp_that_is_not_a_tree_is_refused),
		cmocka_unit_test(heights_beyond_the_bound_are_refused),
		cmocka_unit_test(content_hash_covers_geometry_not_name),
		cmocka_unit_test(point_on_side_is_exact_with_ties_in_front),
		cmocka_unit_test(builtin_levels_are_listed),
		cmocka_unit_test(builtin_points_land_in_their_sectors),
		cmocka_unit_test(builtin_level_has_its_features),
		cmocka_unit_test(builtin_level_is_rebuilt_identically),
		cmocka_unit_test(map_without_nodes_has_one_subsector),
		cmocka_unit_test(messages_format_numbers),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
