/*
 * Tests for the renderer (engine/render/r_main.c, r_bsp.c, r_seg.c, r_draw.c).
 *
 * Expected pixels come from the projection geometry worked by hand in the
 * comments: focal length w/2, horizon at row centre h/2, a height H above
 * the eye at depth D is at screen y = h/2 - H * (w/2) / D, and a row or
 * column is covered when its pixel centre lies in the span. Colours are
 * picked with light 255 and near walls so that the colormap is the identity
 * unless a test is about light.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include <stdio.h>

#include "engine/core/pal.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"
#include "engine/map/wad.h"
#include "engine/render/r_game.h"
#include "engine/render/r_local.h"
#include "engine/render/r_main.h"
#include "tests/unit/r_testmap.h"

static struct pal pal;
static struct ttex *tt;

/* ---- maps through map_alloc + map_finish (node builder) ---- */

struct bline {
	int v1, v2, front, back, tex;
};

static struct map *build(const int (*vx)[2], int nv, const int (*sx)[3], int ns,
			 const struct bline *bl, int nl)
{
	struct map *m;
	char err[160] = "";
	uint32_t nsides = 0, side = 0;

	for (int i = 0; i < nl; i++)
		nsides += bl[i].back >= 0 ? 2 : 1;
	assert_int_equal(map_alloc(&m, (uint32_t)nv, (uint32_t)ns, nsides, (uint32_t)nl, 0), 0);
	for (int i = 0; i < nv; i++) {
		m->vertices[i].x = U(vx[i][0]);
		m->vertices[i].y = U(vx[i][1]);
	}
	for (int i = 0; i < ns; i++) {
		m->sectors[i].floor_h = U(sx[i][0]);
		m->sectors[i].ceil_h = U(sx[i][1]);
		m->sectors[i].light = (uint8_t)sx[i][2];
		m->sectors[i].floor_tex = C_FLOOR;
		m->sectors[i].ceil_tex = C_CEIL;
	}
	for (int i = 0; i < nl; i++) {
		struct map_line *l = &m->lines[i];
		l->v1 = (uint32_t)bl[i].v1;
		l->v2 = (uint32_t)bl[i].v2;
		l->side[0] = side;
		l->side[1] = MAP_NONE;
		m->sides[side].sector = (uint32_t)bl[i].front;
		if (bl[i].back < 0) {
			l->flags = ML_BLOCKING;
			m->sides[side++].mid_tex = (uint16_t)bl[i].tex;
		} else {
			l->flags = ML_TWOSIDED;
			m->sides[side].top_tex = m->sides[side].bot_tex = (uint16_t)bl[i].tex;
			side++;
			l->side[1] = side;
			m->sides[side].sector = (uint32_t)bl[i].back;
			m->sides[side].top_tex = m->sides[side].bot_tex = (uint16_t)bl[i].tex;
			side++;
		}
	}
	assert_int_equal(map_finish(m, err, sizeof(err)), 0);
	return m;
}

/* ---- rendering helpers ---- */

struct shot {
	struct r_ctx *r;
	struct r_frame f;
	struct r_stats st;
};

static void shot_open(struct shot *s, int w, int h)
{
	memset(s, 0, sizeof(*s));
	assert_int_equal(r_new(w, h, &s->r), 0);
	s->f.w = w;
	s->f.h = h;
	s->f.pitch = w;
	s->f.rec = NULL;
	s->f.px = malloc((size_t)w * (size_t)h);
	assert_non_null(s->f.px);
}

static void shot_close(struct shot *s)
{
	r_free(s->r);
	free(s->f.px);
}

static void shot_take(struct shot *s, const struct map *m, int x, int y, int z, ang_t a)
{
	struct r_view v = { U(x), U(y), U(z), a, 0 };

	memset(s->f.px, 0xee, (size_t)s->f.w * (size_t)s->f.h);
	r_render(s->r, m, &tt->t, &v, NULL, 0, &s->f);
	r_get_stats(s->r, &s->st);
}

static uint8_t px(const struct shot *s, int x, int y)
{
	return s->f.px[(size_t)y * (size_t)s->f.pitch + (size_t)x];
}

/* Asserts rows y1..y2 of column x are colour c. */
static void assert_run(const struct shot *s, int x, int y1, int y2, uint8_t c)
{
	for (int y = y1; y <= y2; y++) {
		if (px(s, x, y) != c)
			fail_msg("column %d row %d: colour %d, expected %d (rows %d..%d)", x, y,
				 px(s, x, y), c, y1, y2);
	}
}

/* Renders the view twice over frames pre-filled with different bytes: equal
 * results prove every pixel was written; pixels_written == w * h then proves
 * none was written twice. */
static void assert_written_once(struct shot *s, const struct map *m, const struct r_view *v)
{
	size_t n = (size_t)s->f.w * (size_t)s->f.h;
	uint8_t *first = malloc(n);

	assert_non_null(first);
	memset(s->f.px, 0x11, n);
	r_render(s->r, m, &tt->t, v, NULL, 0, &s->f);
	memcpy(first, s->f.px, n);
	memset(s->f.px, 0x99, n);
	r_render(s->r, m, &tt->t, v, NULL, 0, &s->f);
	r_get_stats(s->r, &s->st);
	assert_memory_equal(first, s->f.px, n);
	assert_int_equal(s->st.pixels_written, n);
	free(first);
}

static int setup(void **state)
{
	(void)state;
	pal_builtin(&pal);
	tt = tt_new();
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	tt_free(tt);
	return 0;
}

/* ---- tests ---- */

/* ---- geometry (r_main.c internals, through engine/render/r_local.h) ---- */

/* A segment across the whole view at depth 100 is cut at the frustum
 * edges l = -d and l = d; the kept ends are inside, within 2 units of 1/65536
 * (bisection stops at one unit, rounding may add one). */
static void clip_cuts_a_segment_at_the_frustum_edges(void **state)
{
	struct r_vpt a = { U(-1000), U(100) }, b = { U(1000), U(100) };
	(void)state;
	assert_int_equal(r_clip_segment(&a, &b), 1);
	assert_int_equal(a.d, U(100));
	assert_int_equal(b.d, U(100));
	assert_true(a.l >= U(-100) && a.l <= U(-100) + 2);
	assert_true(b.l <= U(100) && b.l >= U(100) - 2);
}

/* Crossing the near plane: the behind end moves onto it (d >= R_NEAR, within
 * two units), on the original line (here l = 0 throughout). */
static void clip_moves_a_behind_end_onto_the_near_plane(void **state)
{
	struct r_vpt a = { 0, U(-10) }, b = { 0, U(10) };
	(void)state;
	assert_int_equal(r_clip_segment(&a, &b), 1);
	assert_int_equal(a.l, 0);
	assert_true(a.d >= R_NEAR && a.d <= R_NEAR + 2);
	assert_int_equal(b.d, U(10));
}

static void clip_rejects_segments_behind_or_beside_the_view(void **state)
{
	struct r_vpt a = { U(-5), U(-10) }, b = { U(5), U(-1) };
	struct r_vpt c = { U(-50), U(10) }, d = { U(-20), U(10) };
	struct r_vpt e = { U(20), U(10) }, f = { U(30), U(25) };
	(void)state;
	assert_int_equal(r_clip_segment(&a, &b), 0);
	assert_int_equal(r_clip_segment(&c, &d), 0);
	assert_int_equal(r_clip_segment(&e, &f), 0);
}

/* A box straddling the near plane and both frustum edges: every point left
 * is visible, and the clipped polygon still spans the whole view. */
static void polygon_clip_keeps_only_visible_points(void **state)
{
	struct r_ctx *r;
	struct r_vpt v[R_POLY_MAX] = { { U(-50), U(-5) }, { U(50), U(-5) }, { U(50), U(20) },
				       { U(-50), U(20) } };
	int64_t lo = INT64_MAX, hi = INT64_MIN;
	int n;
	(void)state;
	assert_int_equal(r_new(320, 240, &r), 0);
	n = r_clip_polygon(v, 4);
	assert_true(n >= 3);
	for (int i = 0; i < n; i++) {
		int64_t sx = r_project_x(r, &v[i]);
		assert_true(v[i].d >= R_NEAR);
		assert_true(v[i].l >= -v[i].d && v[i].l <= v[i].d);
		lo = sx < lo ? sx : lo;
		hi = sx > hi ? sx : hi;
	}
	assert_int_equal(lo, 0);
	assert_int_equal(hi, (int64_t)320 * FX_ONE);
	r_free(r);
}

/* Screen x = w/2 + (w/2) * l / d: the axis at the centre, the frustum edges
 * at the frame edges. */
static void projection_maps_the_frustum_onto_the_frame(void **state)
{
	struct r_ctx *r;
	struct r_vpt c = { 0, U(7) }, l = { U(-7), U(7) }, rt = { U(7), U(7) }, q = { U(3), U(12) };
	(void)state;
	assert_int_equal(r_new(320, 240, &r), 0);
	assert_int_equal(r_project_x(r, &c), (int64_t)160 * FX_ONE);
	assert_int_equal(r_project_x(r, &l), 0);
	assert_int_equal(r_project_x(r, &rt), (int64_t)320 * FX_ONE);
	/* 160 + 160 * 3 / 12 = 200 */
	assert_int_equal(r_project_x(r, &q), (int64_t)200 * FX_ONE);
	r_free(r);
}

/* ---- whole frames ---- */

static void new_rejects_bad_sizes_and_free_takes_null(void **state)
{
	struct r_ctx *r = (struct r_ctx *)1;
	(void)state;
	assert_int_equal(r_new(0, 10, &r), -EINVAL);
	assert_null(r);
	assert_int_equal(r_new(10, 0, &r), -EINVAL);
	assert_int_equal(r_new(4097, 10, &r), -EINVAL);
	assert_int_equal(r_new(10, 4097, &r), -EINVAL);
	assert_int_equal(r_new(4096, 4096, &r), 0);
	r_free(r);
	r_free(NULL);
}

/* Eye at the centre of the square room, z 41, facing east; 320x240: focal
 * 160, horizon 120. The east wall is perpendicular at depth 128 across the
 * whole 90-degree view (its ends project exactly onto the screen edges), so
 * every column is the same: top edge 120 - (128-41)*160/128 = 11.25 (first
 * wall row 11), bottom edge 120 + 41*160/128 = 171.25 (last wall row 170).
 * Light 255: the east wall (north-south, one level darker: base level 2) is
 * faded by 1280/128 = 10 levels to level 0, the planes are at level 0. */
static void closed_room_frame_is_ceiling_wall_floor_by_geometry(void **state)
{
	struct tmap t;
	struct shot s;
	(void)state;
	t_room(&t, 255, 0);
	shot_open(&s, 320, 240);
	shot_take(&s, &t.m, 0, 0, 41, 0);
	for (int x = 0; x < 320; x++) {
		assert_run(&s, x, 0, 10, C_CEIL);
		assert_run(&s, x, 11, 170, C_EAST);
		assert_run(&s, x, 171, 239, C_FLOOR);
	}
	assert_int_equal(s.st.pixels_written, 320 * 240);
	assert_int_equal(s.st.pixels_empty, 0);
	assert_int_equal(s.st.columns, 320);
	shot_close(&s);
}

/* The wall's span at the centre column is (ceil - z) * focal / D above and
 * z * focal / D below the horizon, for several sizes and depths (eye moved
 * along x; depth D = 128 - x). Expected edges in exact integer rationals:
 * top = h/2 - 87 * (w/2) / D, bottom = h/2 + 41 * (w/2) / D; the first wall
 * row is the first centre at or below top, within one pixel. */
static void wall_span_is_height_times_focal_over_depth(void **state)
{
	static const int sizes[][2] = { { 64, 48 }, { 160, 120 }, { 320, 240 }, { 200, 100 } };
	static const int xs[] = { 0, 40, 64, 100, -100 };
	struct tmap t;
	(void)state;
	t_room(&t, 255, 0);
	for (size_t i = 0; i < sizeof(sizes) / sizeof(sizes[0]); i++) {
		int w = sizes[i][0], h = sizes[i][1];
		struct shot s;

		shot_open(&s, w, h);
		for (size_t j = 0; j < sizeof(xs) / sizeof(xs[0]); j++) {
			int d = 128 - xs[j], cx = w / 2, first = -1, last = -1;
			/* top edge * 2d = h*d - 87*w; first row: ceil(edge - 1/2) */
			long top2 = (long)h * d - 87L * w, bot2 = (long)h * d + 41L * w;
			long want_first = (top2 - d + 2L * d - 1) / (2L * d);
			long want_last = (bot2 - d + 2L * d - 1) / (2L * d) - 1;

			if (top2 - d < 0)
				want_first = 0;
			if (want_last > h - 1)
				want_last = h - 1;
			shot_take(&s, &t.m, xs[j], 0, 41, 0);
			for (int y = 0; y < h; y++) {
				if (px(&s, cx, y) == C_EAST) {
					if (first < 0)
						first = y;
					last = y;
				}
			}
			assert_true(first >= 0);
			assert_true(labs(first - want_first) <= 1);
			assert_true(labs(last - want_last) <= 1);
			/* contiguous: ceiling above, floor below */
			assert_run(&s, cx, first, last, C_EAST);
			if (first > 0)
				assert_int_equal(px(&s, cx, first - 1), C_CEIL);
			if (last < h - 1)
				assert_int_equal(px(&s, cx, last + 1), C_FLOOR);
		}
		shot_close(&s);
	}
}

/* Light 128, 320x240, eye z 41 facing east. Base level (Doom's rule)
 * 4 * (15 - light/16). East wall: north-south, light 128 - 16 = 112, base
 * 4 * 8 = 32, clamped to 31; fade 1280/128 = 10: level 21. Planes: base
 * 4 * (15 - 8) = 28. Ceiling row 5: depth 87*160/(120-5.5) = 121.6, fade
 * 1280/121.6 = 10.5 -> 10: level 18. Floor rows (depth 41*160/(y+0.5-120)):
 * row 172 depth 124.95, fade 10.2 -> 10: level 18; row 180: 108.4, 11.8 ->
 * 11: level 17; row 200: 81.5, 15.7 -> 15: level 13; row 239: 54.9, 23.3 ->
 * 23: level 5. */
static void sector_light_and_distance_pick_the_colormap(void **state)
{
	struct tmap t;
	struct shot s;
	(void)state;
	t_room(&t, 128, 0);
	shot_open(&s, 320, 240);
	shot_take(&s, &t.m, 0, 0, 41, 0);
	assert_int_equal(px(&s, 160, 100), pal.cmap[21][C_EAST]);
	assert_int_equal(px(&s, 10, 100), pal.cmap[21][C_EAST]);
	assert_int_equal(px(&s, 160, 5), pal.cmap[18][C_CEIL]);
	assert_int_equal(px(&s, 160, 172), pal.cmap[18][C_FLOOR]);
	assert_int_equal(px(&s, 160, 180), pal.cmap[17][C_FLOOR]);
	assert_int_equal(px(&s, 160, 200), pal.cmap[13][C_FLOOR]);
	assert_int_equal(px(&s, 160, 239), pal.cmap[5][C_FLOOR]);
	/* the per-row light does not depend on the column */
	for (int x = 0; x < 320; x++)
		assert_int_equal(px(&s, x, 180), px(&s, 160, 180));
	shot_close(&s);
}

/* Facing north in the same dim room: the north wall runs east-west, light
 * 128 + 16 = 144, base 4 * (15 - 9) = 24, fade 10: level 14, brighter than
 * the west wall's 21 (light 112, base clamped to 31) at the same distance. */
static void fake_contrast_lights_east_west_walls_brighter(void **state)
{
	struct tmap t;
	struct shot s;
	(void)state;
	t_room(&t, 128, 0);
	shot_open(&s, 320, 240);
	shot_take(&s, &t.m, 0, 0, 41, ANG90);
	assert_int_equal(px(&s, 160, 100), pal.cmap[14][C_NORTH]);
	shot_take(&s, &t.m, 0, 0, 41, ANG180);
	assert_int_equal(px(&s, 160, 100), pal.cmap[21][C_WEST]);
	shot_close(&s);
}

/* The horizon moves down by shear: every edge moves by the same rows. */
static void shear_moves_the_horizon(void **state)
{
	struct tmap t;
	struct shot s;
	struct r_view v = { 0, 0, U(41), 0, 10 };
	(void)state;
	t_room(&t, 255, 0);
	shot_open(&s, 320, 240);
	memset(s.f.px, 0, 320 * 240);
	r_render(s.r, &t.m, &tt->t, &v, NULL, 0, &s.f);
	assert_run(&s, 100, 0, 20, C_CEIL);
	assert_run(&s, 100, 21, 180, C_EAST);
	assert_run(&s, 100, 181, 239, C_FLOOR);
	shot_close(&s);
}

/* Half a unit from the east wall, facing it: the wall (127.5 units above and
 * 41*320 below the horizon) covers the whole frame. */
static void near_wall_fills_the_frame(void **state)
{
	struct tmap t;
	struct shot s;
	struct r_view v = { U(128) - FX_HALF, 0, U(41), 0, 0 };
	(void)state;
	t_room(&t, 255, 0);
	shot_open(&s, 160, 120);
	r_render(s.r, &t.m, &tt->t, &v, NULL, 0, &s.f);
	for (int x = 0; x < 160; x++)
		assert_run(&s, x, 0, 119, C_EAST);
	shot_close(&s);
}

/* Frame rows wider than w: the bytes past each row's w are not touched. */
static void pitch_padding_is_left_alone(void **state)
{
	struct tmap t;
	struct r_ctx *r;
	struct r_view v = { 0, 0, U(41), ANG45, 0 };
	uint8_t buf[24 * 20];
	struct r_frame f = { buf, 16, 20, 24, NULL };
	(void)state;
	t_room(&t, 255, 0);
	memset(buf, 0x77, sizeof(buf));
	assert_int_equal(r_new(16, 20, &r), 0);
	r_render(r, &t.m, &tt->t, &v, NULL, 0, &f);
	for (int y = 0; y < 20; y++)
		for (int x = 16; x < 24; x++)
			assert_int_equal(buf[y * 24 + x], 0x77);
	r_free(r);
}

/* Rotating eye and view by 90 degrees about the centre of a room that is
 * symmetric under that rotation (all walls alike, light 255 so the fake
 * contrast fades out) gives the same frame. */
static void quarter_turns_in_a_symmetric_room_give_the_same_frame(void **state)
{
	static const int views[][3] = { { 0, 0, 0 }, { 30, -50, 12345 }, { -90, 70, 400000000 },
					{ 100, 100, 0x9abcdef0 } };
	struct tmap t;
	struct shot s;
	uint8_t *first = malloc(160 * 120);
	(void)state;
	t_room(&t, 255, 1);
	shot_open(&s, 160, 120);
	for (size_t i = 0; i < sizeof(views) / sizeof(views[0]); i++) {
		int x = views[i][0], y = views[i][1];
		ang_t a = (ang_t)views[i][2];

		shot_take(&s, &t.m, x, y, 41, a);
		memcpy(first, s.f.px, 160 * 120);
		for (int q = 1; q < 4; q++) {
			int nx = -y, ny = x;

			x = nx;
			y = ny;
			a += ANG90;
			shot_take(&s, &t.m, x, y, 41, a);
			assert_memory_equal(first, s.f.px, 160 * 120);
		}
	}
	free(first);
	shot_close(&s);
}

/* t_window(24, 96): rooms A [-128,128]^2 (f0 c128), W [128,144]x[-32,32]
 * (the window sill f24, lintel c96) and B [144,400]x[-128,128] (f0 c128),
 * all light 255, with a hand-made BSP. Eye (0,0) z 64 facing east,
 * 320x240, centre column 160 (scale 160/D):
 *  - window line, D 128 (1.25): A ceiling edge 120 - 64*1.25 = 40, lintel
 *    120 - 32*1.25 = 80, sill 120 + 40*1.25 = 170, A floor 200;
 *  - W's far side, D 144: lintel 120 - 32*160/144 = 84.4, sill 164.4;
 *  - B's east wall, D 400 (0.4): ceiling edge 94.4, floor edge 145.6.
 * So rows: 0-39 ceiling, 40-79 upper wall, 80-83 W ceiling, 84-93 B
 * ceiling, 94-145 B's east wall, 146-163 B floor, 164-169 W floor, 170-199
 * lower wall, 200-239 floor. */
static void window_shows_upper_and_lower_parts_and_the_room_behind(void **state)
{
	const uint8_t c_win = C_WIN, c_beast = C_BEAST, c_wall = C_WALL;
	struct tmap t;
	struct shot s;
	struct r_view v = { 0, 0, U(64), 0, 0 };
	(void)state;
	t_window(&t, 24, 96);
	shot_open(&s, 320, 240);
	r_render(s.r, &t.m, &tt->t, &v, NULL, 0, &s.f);
	assert_run(&s, 160, 0, 39, C_CEIL);
	assert_run(&s, 160, 40, 79, c_win);
	assert_run(&s, 160, 80, 93, C_CEIL);
	assert_run(&s, 160, 94, 145, c_beast);
	assert_run(&s, 160, 146, 169, C_FLOOR);
	assert_run(&s, 160, 170, 199, c_win);
	assert_run(&s, 160, 200, 239, C_FLOOR);
	/* the window spans lateral -32..32 at D 128: columns 120..199; beside
	 * it A's own east wall fills rows 40..199 */
	assert_run(&s, 119, 40, 199, c_wall);
	assert_run(&s, 200, 40, 199, c_wall);
	assert_run(&s, 120, 40, 79, c_win);
	assert_run(&s, 199, 170, 199, c_win);
	r_get_stats(s.r, &s.st);
	assert_int_equal(s.st.subsectors, 3);
	assert_written_once(&s, &t.m, &v);
	assert_int_equal(s.st.pixels_empty, 0);
	shot_close(&s);
}

/* Room [-256,256]^2 (light 255) with a void pillar x 64..96, y -16..16.
 * Eye (0,0) z 41 facing east, 320x240. The pillar's west face, D 64,
 * lateral -16..16, covers columns 160 +/- 16*160/64 = 120..199 and rows
 * from above the frame to 120 + 41*2.5 = 222.5 (last row 221). The east
 * wall (D 256) shows only beside it. */
static void pillar_hides_the_wall_behind_it(void **state)
{
	static const int vx[][2] = { { -256, -256 }, { -256, 256 }, { 256, 256 }, { 256, -256 },
				     { 64, -16 },   { 96, -16 },   { 96, 16 },   { 64, 16 } };
	static const int sx[][3] = { { 0, 128, 255 } };
	static const struct bline bl[] = {
		{ 0, 1, 0, -1, C_WEST }, { 1, 2, 0, -1, C_NORTH }, { 2, 3, 0, -1, C_EAST },
		{ 3, 0, 0, -1, C_SOUTH }, { 4, 5, 0, -1, C_WEST }, { 5, 6, 0, -1, C_WEST },
		{ 6, 7, 0, -1, C_WEST },  { 7, 4, 0, -1, C_WEST },
	};
	struct map *m = build(vx, 8, sx, 1, bl, 8);
	struct shot s;
	struct r_view v = { 0, 0, U(41), 0, 0 };
	(void)state;
	shot_open(&s, 320, 240);
	shot_take(&s, m, 0, 0, 41, 0);
	for (int x = 120; x <= 199; x++) {
		assert_run(&s, x, 0, 221, C_WEST);
		for (int y = 0; y < 240; y++)
			assert_int_not_equal(px(&s, x, y), C_EAST);
	}
	assert_run(&s, 160, 222, 239, C_FLOOR);
	/* east wall at D 256: rows 120 - 87*0.625 = 65.6 .. 120 + 25.6 = 145.6 */
	assert_run(&s, 100, 66, 145, C_EAST);
	assert_run(&s, 219, 66, 145, C_EAST);
	assert_int_equal(px(&s, 100, 65), C_CEIL);
	assert_int_equal(px(&s, 100, 146), C_FLOOR);
	assert_written_once(&s, m, &v);
	assert_int_equal(s.st.pixels_empty, 0);
	shot_close(&s);
	map_free(m);
}

/* An L-shaped room (non-convex: the node builder splits it) has no hole from
 * views all over it: no pixel is left to the black fill, and every pixel is
 * written once. */
static void l_shaped_room_has_no_holes(void **state)
{
	static const int vx[][2] = { { 0, 0 }, { 0, 512 }, { 256, 512 }, { 256, 256 }, { 512, 256 },
				     { 512, 0 } };
	static const int sx[][3] = { { 0, 128, 200 } };
	static const struct bline bl[] = {
		{ 0, 1, 0, -1, C_WEST },  { 1, 2, 0, -1, C_NORTH }, { 2, 3, 0, -1, C_EAST },
		{ 3, 4, 0, -1, C_NORTH }, { 4, 5, 0, -1, C_EAST },  { 5, 0, 0, -1, C_SOUTH },
	};
	static const int pos[][2] = { { 32, 32 }, { 128, 128 }, { 480, 32 }, { 32, 480 },
				      { 230, 280 }, { 250, 250 }, { 128, 400 }, { 400, 128 } };
	struct map *m = build(vx, 6, sx, 1, bl, 6);
	struct shot s;
	(void)state;
	assert_true(m->num_subsectors >= 2);
	shot_open(&s, 160, 120);
	for (size_t i = 0; i < sizeof(pos) / sizeof(pos[0]); i++) {
		for (int k = 0; k < 16; k++) {
			struct r_view v = { U(pos[i][0]), U(pos[i][1]), U(41),
					    (ang_t)k * (ANG90 / 4) + 1234567u, 0 };

			assert_written_once(&s, m, &v);
			assert_int_equal(s.st.pixels_empty, 0);
			for (int p = 0; p < 160 * 120; p++)
				assert_int_not_equal(s.f.px[p], PAL_BLACK);
		}
	}
	shot_close(&s);
	map_free(m);
}

/* Same map, view and size: identical bytes, from a second context and
 * after the first context drew another view in between. */
static void same_view_gives_identical_bytes(void **state)
{
	struct map *m;
	struct shot s1, s2;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	shot_open(&s1, 320, 240);
	shot_open(&s2, 320, 240);
	shot_take(&s1, m, 96, 192, 41, 0x12345678);
	shot_take(&s2, m, 96, 192, 41, 0x12345678);
	assert_memory_equal(s1.f.px, s2.f.px, 320 * 240);
	shot_take(&s1, m, 700, 300, 80, 0x9000000);
	shot_take(&s1, m, 96, 192, 41, 0x12345678);
	assert_memory_equal(s1.f.px, s2.f.px, 320 * 240);
	shot_close(&s1);
	shot_close(&s2);
	map_free(m);
}

/* Distance from (x, y) to the nearest line of m, in map units (squared, as
 * a double: the test's own geometry, independent of the renderer). */
static double nearest_line_sq(const struct map *m, double x, double y)
{
	double best = 1e300;

	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_vertex *a = &m->vertices[m->lines[i].v1];
		const struct map_vertex *b = &m->vertices[m->lines[i].v2];
		double ax = a->x / 65536.0, ay = a->y / 65536.0;
		double dx = b->x / 65536.0 - ax, dy = b->y / 65536.0 - ay;
		double t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);
		double ex, ey;

		t = t < 0 ? 0 : t > 1 ? 1 : t;
		ex = ax + t * dx - x;
		ey = ay + t * dy - y;
		if (ex * ex + ey * ey < best)
			best = ex * ex + ey * ey;
	}
	return best;
}

/* 1 when (x, y) is inside sector sec's polygon: the parity of crossings of
 * a ray towards +x with the lines that bound sec (one side in sec). */
static int in_sector(const struct map *m, uint32_t sec, double x, double y)
{
	int odd = 0;

	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		int f = m->sides[l->side[0]].sector == sec;
		int b = l->side[1] != MAP_NONE && m->sides[l->side[1]].sector == sec;
		double ax = m->vertices[l->v1].x / 65536.0, ay = m->vertices[l->v1].y / 65536.0;
		double bx = m->vertices[l->v2].x / 65536.0, by = m->vertices[l->v2].y / 65536.0;

		if (f == b)
			continue;
		if ((ay > y) != (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay))
			odd ^= 1;
	}
	return odd;
}

static uint32_t lcg(uint32_t *s)
{
	*s = *s * 1664525u + 1013904223u;
	return *s >> 8;
}

/* 500 seeded views of the built-in level: inside, outside, on vertices,
 * along axes, at odd heights, at extreme coordinates, across sizes 64x48 to
 * 320x240 (run under ASan/UBSan by the sanitizer build). Every pixel is
 * written once each time; views well inside a sector (between its floor and
 * ceiling, 1 unit from every line) leave no pixel to the black fill. */
static void builtin_level_500_views_write_every_pixel_once(void **state)
{
	static const int sizes[][2] = { { 64, 48 }, { 160, 120 }, { 320, 240 }, { 97, 61 } };
	struct map *m;
	struct shot s[4];
	uint32_t seed = 12345;
	int inside = 0;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	for (int i = 0; i < 4; i++)
		shot_open(&s[i], sizes[i][0], sizes[i][1]);
	for (int n = 0; n < 500; n++) {
		struct shot *sh = &s[n % 4];
		struct r_view v;
		uint32_t kind = lcg(&seed) % 8;

		v.x = (fx_t)((int32_t)(lcg(&seed) % (1400u << 8)) - (200 << 8)) * 256;
		v.y = (fx_t)((int32_t)(lcg(&seed) % (1400u << 8)) - (200 << 8)) * 256;
		v.z = (fx_t)((int32_t)(lcg(&seed) % (360u << 8)) - (60 << 8)) * 256;
		v.angle = lcg(&seed) * 2654435761u;
		v.shear = 0;
		if (kind == 0) {
			const struct map_vertex *vt = &m->vertices[lcg(&seed) % m->num_vertices];
			v.x = vt->x;
			v.y = vt->y;
		} else if (kind == 1) {
			v.angle = (lcg(&seed) % 4) * ANG90;
		} else if (kind == 2) {
			v.x = (lcg(&seed) & 1) ? FX_MAX : FX_MIN;
			v.y = (lcg(&seed) & 1) ? -MAP_COORD_MAX : MAP_COORD_MAX;
			v.z = (lcg(&seed) & 1) ? FX_MAX : FX_MIN;
		} else if (kind == 3) {
			v.shear = (int32_t)(lcg(&seed) % 1001) - 500;
		}
		assert_written_once(sh, m, &v);
		if (kind != 2) {
			uint32_t sec = map_point_sector(m, v.x, v.y);
			const struct map_sector *se = &m->sectors[sec];
			double x = v.x / 65536.0, y = v.y / 65536.0;

			if (in_sector(m, sec, x, y) && v.z > se->floor_h + FX_ONE &&
			    v.z < se->ceil_h - FX_ONE && nearest_line_sq(m, x, y) > 1.0) {
				inside++;
				if (sh->st.pixels_empty != 0)
					fail_msg("view %d (%d, %d, %d) angle %08x: %u empty pixels",
						 n, v.x >> 16, v.y >> 16, v.z >> 16, v.angle,
						 sh->st.pixels_empty);
			}
		}
	}
	assert_true(inside > 50);
	for (int i = 0; i < 4; i++)
		shot_close(&s[i]);
	map_free(m);
}

/* ---- real content: the project's texture set, Freedoom ---- */

/* A room textured by name from tex_builtin: AR_BRICK walls, AR_FLOOR floor,
 * the sky (F_SKY1) as ceiling, light 255. Facing east from the centre
 * (eye z 41): the east wall's column 160 at row 100 shows AR_BRICK's texel
 * (column floor(128.4) mod 64 = 0, row floor(87 - (120 - 100.5) * 0.8) =
 * 71 mod 64 = 7) through colormap 0 (north-south wall: light 239, base 4,
 * faded by 10); the floor pixel (200, 200) shows AR_FLOOR's texel at world
 * (81.49, -20.63): row 20, column 17 (test_r_plane's geometry); the top row
 * is the sky: SKY1's texel of column ((0 + xtoang) >> 22) mod 256 and row
 * 4 (test_r_plane), unlit. */
static void builtin_texture_set_draws_its_named_textures(void **state)
{
	struct tex_set *t;
	struct tmap m;
	struct shot s;
	const struct tex_pic *brick, *sky;
	int tb, tf, ts;
	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	tb = tex_find(t, "AR_BRICK");
	tf = tex_find_flat(t, "AR_FLOOR");
	ts = tex_find(t, "SKY1");
	assert_true(tb > 0 && tf >= 0 && ts > 0 && t->sky_flat >= 0);
	brick = &t->textures[tb];
	sky = &t->textures[ts];
	assert_int_equal(brick->w, 64);
	t_room(&m, 255, 1);
	for (int i = 0; i < 4; i++)
		m.sd[i].mid_tex = (uint16_t)tb;
	m.sec[0].floor_tex = (uint16_t)tf;
	m.sec[0].ceil_tex = (uint16_t)t->sky_flat;
	shot_open(&s, 320, 240);
	{
		struct r_view v = { 0, 0, U(41), 0, 0 };

		memset(s.f.px, 0xee, 320 * 240);
		r_render(s.r, &m.m, t, &v, NULL, 0, &s.f);
	}
	r_get_stats(s.r, &s.st);
	assert_int_equal(s.st.pixels_written, 320 * 240);
	assert_int_equal(s.st.missing, 0);
	assert_int_equal(px(&s, 160, 100), brick->px[0 * brick->h + 7]);
	assert_int_equal(px(&s, 200, 200), t->flats[tf].px[20 * 64 + 17]);
	/* column 100's ray is 10.6 degrees left: sky column 30.3 */
	assert_int_equal(px(&s, 100, 0), sky->px[30 * sky->h + 4]);
	shot_close(&s);
	tex_free(t);
}

struct fwad {
	uint8_t *data;
	struct wad *w;
	struct tex_set *t;
};

/* Loads a WAD file with its textures; 0, or -1 when the file is absent. */
static int fwad_open(const char *path, struct fwad *f)
{
	FILE *fp = fopen(path, "rbe");
	char err[256] = "";
	long n;

	memset(f, 0, sizeof(*f));
	if (!fp)
		return -1;
	assert_int_equal(fseek(fp, 0, SEEK_END), 0);
	n = ftell(fp);
	assert_true(n > 0);
	rewind(fp);
	f->data = malloc((size_t)n);
	assert_non_null(f->data);
	assert_int_equal(fread(f->data, 1, (size_t)n, fp), (size_t)n);
	fclose(fp);
	assert_int_equal(wad_new(&f->w), 0);
	assert_int_equal(wad_add(f->w, f->data, (size_t)n, path, err, sizeof(err)), 0);
	assert_int_equal(tex_load_wad(f->w, &f->t, err, sizeof(err)), 0);
	return 0;
}

static void fwad_close(struct fwad *f)
{
	tex_free(f->t);
	wad_free(f->w);
	free(f->data);
}

/* Every map of a Freedoom WAD, from its player 1 start and from 50 seeded
 * views (random points of the map's box, the eye 41 above the floor there,
 * random angle and shear; some outside every sector), with the map's
 * things as sprites, at 320x200 (run under ASan/UBSan by the sanitizer
 * build): every pixel written once, nothing degraded, no texture of the
 * set missing. From the start (inside the map) no pixel is left black;
 * a second context gives the same bytes. Returns the number of maps. */
static int freedoom_views(const char *path)
{
	struct fwad f;
	char names[64][9];
	struct shot s, s2;
	uint32_t seed = 4242;
	int nmaps;

	if (fwad_open(path, &f) < 0)
		return -1;
	nmaps = map_list_wad(f.w, names, 64);
	assert_true(nmaps > 0 && nmaps <= 64);
	shot_open(&s, 320, 200);
	shot_open(&s2, 320, 200);
	for (int i = 0; i < nmaps; i++) {
		struct map *m;
		struct r_sprite *spr;
		char err[256] = "";
		fx_t x0 = FX_MAX, x1 = FX_MIN, y0 = FX_MAX, y1 = FX_MIN;
		struct r_view v = { 0 };
		int nspr, start = 0;

		assert_int_equal(map_load_wad(f.w, f.t, names[i], &m, err, sizeof(err)), 0);
		spr = calloc(m->num_things + 1, sizeof(*spr));
		assert_non_null(spr);
		nspr = r_map_sprites(m, f.t, spr);
		for (uint32_t k = 0; k < m->num_vertices; k++) {
			const struct map_vertex *p = &m->vertices[k];

			x0 = p->x < x0 ? p->x : x0;
			x1 = p->x > x1 ? p->x : x1;
			y0 = p->y < y0 ? p->y : y0;
			y1 = p->y > y1 ? p->y : y1;
		}
		for (uint32_t k = 0; k < m->num_things; k++)
			if (m->things[k].type == 1) {
				v.x = m->things[k].x;
				v.y = m->things[k].y;
				v.angle = m->things[k].angle;
				start = 1;
			}
		assert_true(start);
		for (int n = 0; n <= 50; n++) {
			const struct map_sector *sec;

			if (n > 0) {
				v.x = x0 + (fx_t)((int64_t)lcg(&seed) * ((int64_t)x1 - x0) >> 24);
				v.y = y0 + (fx_t)((int64_t)lcg(&seed) * ((int64_t)y1 - y0) >> 24);
				v.angle = lcg(&seed) * 2654435761u;
				v.shear = (int32_t)(lcg(&seed) % 121) - 60;
			}
			sec = &m->sectors[map_point_sector(m, v.x, v.y)];
			v.z = sec->floor_h + 41 * FX_ONE;
			memset(s.f.px, 0x11, 320 * 200);
			r_render(s.r, m, f.t, &v, spr, nspr, &s.f);
			r_get_stats(s.r, &s.st);
			if (s.st.pixels_written != 320 * 200 || s.st.degraded || s.st.missing)
				fail_msg("%s %s view %d: written %u degraded %u missing %u", path,
					 names[i], n, s.st.pixels_written, s.st.degraded,
					 s.st.missing);
			if (n == 0) {
				if (s.st.pixels_empty != 0)
					fail_msg("%s %s start: %u empty pixels", path, names[i],
						 s.st.pixels_empty);
				memset(s2.f.px, 0x99, 320 * 200);
				r_render(s2.r, m, f.t, &v, spr, nspr, &s2.f);
				assert_memory_equal(s.f.px, s2.f.px, 320 * 200);
			}
		}
		free(spr);
		map_free(m);
	}
	shot_close(&s);
	shot_close(&s2);
	fwad_close(&f);
	return nmaps;
}

static void freedoom1_maps_render_whole_from_51_views_each(void **state)
{
	int n = freedoom_views("/usr/share/games/doom/freedoom1.wad");
	(void)state;
	if (n < 0)
		skip();
	assert_int_equal(n, 36);
}

static void freedoom2_maps_render_whole_from_51_views_each(void **state)
{
	int n = freedoom_views("/usr/share/games/doom/freedoom2.wad");
	(void)state;
	if (n < 0)
		skip();
	assert_int_equal(n, 32);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(new_rejects_bad_sizes_and_free_takes_null),
		cmocka_unit_test(clip_cuts_a_segment_at_the_frustum_edges),
		cmocka_unit_test(clip_moves_a_behind_end_onto_the_near_plane),
		cmocka_unit_test(clip_rejects_segments_behind_or_beside_the_view),
		cmocka_unit_test(polygon_clip_keeps_only_visible_points),
		cmocka_unit_test(projection_maps_the_frustum_onto_the_frame),
		cmocka_unit_test(closed_room_frame_is_ceiling_wall_floor_by_geometry),
		cmocka_unit_test(wall_span_is_height_times_focal_over_depth),
		cmocka_unit_test(sector_light_and_distance_pick_the_colormap),
		cmocka_unit_test(fake_contrast_lights_east_west_walls_brighter),
		cmocka_unit_test(shear_moves_the_horizon),
		cmocka_unit_test(near_wall_fills_the_frame),
		cmocka_unit_test(pitch_padding_is_left_alone),
		cmocka_unit_test(quarter_turns_in_a_symmetric_room_give_the_same_frame),
		cmocka_unit_test(window_shows_upper_and_lower_parts_and_the_room_behind),
		cmocka_unit_test(pillar_hides_the_wall_behind_it),
		cmocka_unit_test(l_shaped_room_has_no_holes),
		cmocka_unit_test(same_view_gives_identical_bytes),
		cmocka_unit_test(builtin_level_500_views_write_every_pixel_once),
		cmocka_unit_test(builtin_texture_set_draws_its_named_textures),
		cmocka_unit_test(freedoom1_maps_render_whole_from_51_views_each),
		cmocka_unit_test(freedoom2_maps_render_whole_from_51_views_each),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
