/*
 * Tests for engine/render/r_plane.c: floors and ceilings as visplanes drawn in
 * spans (the flat texel under each pixel from the plane equations), the sky
 * (columns by view angle, rows around the horizon, no light), and lists
 * that grow without limit.
 *
 * Geometry by hand (doubles, the test's own): 320x240, focal 160, horizon
 * at row centre 120 + shear. A floor h units below the eye seen at row y is
 * at depth D = h * 160 / (y + 0.5 - 120); column x's centre is D * (2x + 1 -
 * 320) / 320 right of the view axis. Flats wrap at 64 units; Doom's
 * orientation: flat column = world x, flat row = -world y. TF_COLS' texel
 * is its column, TF_ROWS' its row; light 255 keeps colormap 0 (identity)
 * for planes. A texel within 1/50 of a boundary may be either neighbour.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/map/map.h"
#include "engine/map/tex.h"
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

#define W 320
#define H 240

struct frame {
	struct r_ctx *r;
	struct r_frame f;
	uint8_t px[W * H];
	struct r_stats st;
};

static void render_v(struct frame *fr, const struct map *m, const struct r_view *v)
{
	if (!fr->r)
		assert_int_equal(r_new(W, H, &fr->r), 0);
	fr->f = (struct r_frame){ fr->px, W, H, W, NULL };
	memset(fr->px, 0xee, sizeof(fr->px));
	r_render(fr->r, m, &tt->t, v, NULL, 0, &fr->f);
	r_get_stats(fr->r, &fr->st);
	assert_int_equal(fr->st.pixels_written, W * H);
}

static void render(struct frame *fr, const struct map *m, double x, double y, double z, ang_t a)
{
	struct r_view v = { (fx_t)(x * FX_ONE), (fx_t)(y * FX_ONE), (fx_t)(z * FX_ONE), a, 0 };

	render_v(fr, m, &v);
}

static void done(struct frame *fr)
{
	r_free(fr->r);
	fr->r = NULL;
}

static uint8_t at(const struct frame *fr, int x, int y)
{
	return fr->px[y * W + x];
}

/* floor(v) mod 64, or -1 when v is within 1/50 of a boundary. */
static int texel(double v)
{
	double k = floor(v), f = v - k;

	if (f < 0.02 || f > 0.98)
		return -1;
	return (int)(((long)k % 64 + 64) % 64);
}

/* World position of the plane point under pixel (x, y) for an eye at
 * (ex, ey) facing ang (radians), the plane dh units from the eye. */
static void plane_point(int x, int y, double ex, double ey, double ang, double dh, double *wx,
			double *wy)
{
	double d = dh * 160 / fabs(y + 0.5 - 120), l = d * (2 * x + 1 - W) / W;

	*wx = ex + d * cos(ang) + l * sin(ang);
	*wy = ey + d * sin(ang) - l * cos(ang);
}

/* Checks every pixel of rows y1..y2 against the flats' coordinate
 * texels; returns how many were checked. */
static int check_plane(struct tmap *t, uint16_t *flat, int y1, int y2, double ex, double ey,
		       double ez, double ang, ang_t a, double dh)
{
	static struct frame fc, fr;
	int n = 0;

	*flat = TF_COLS;
	render(&fc, &t->m, ex, ey, ez, a);
	*flat = TF_ROWS;
	render(&fr, &t->m, ex, ey, ez, a);
	for (int y = y1; y <= y2; y++)
		for (int x = 0; x < W; x += 3) {
			double wx, wy;
			int cx, cy;

			plane_point(x, y, ex, ey, ang, dh, &wx, &wy);
			/* only points inside the (convex) room: others are wall */
			if (fabs(wx) > 127 || fabs(wy) > 127)
				continue;
			cx = texel(wx);
			cy = texel(-wy);
			if (cx >= 0) {
				if (at(&fc, x, y) != cx)
					fail_msg("pixel (%d, %d): flat column %d, expected %d "
						 "(world x %.4f)", x, y, at(&fc, x, y), cx, wx);
				n++;
			}
			if (cy >= 0) {
				if (at(&fr, x, y) != cy)
					fail_msg("pixel (%d, %d): flat row %d, expected %d "
						 "(world y %.4f)", x, y, at(&fr, x, y), cy, wy);
				n++;
			}
		}
	done(&fc);
	done(&fr);
	return n;
}

/* The square room (floor 0, ceiling 128), eye z 41: floor rows 171..239
 * (test_r_main's geometry) at h = 41; facing east, north and at an odd
 * angle from an off-centre eye. */
static void floor_texel_follows_the_plane_equations(void **state)
{
	struct tmap t;
	(void)state;
	t_room(&t, 255, 0);
	assert_true(check_plane(&t, &t.sec[0].floor_tex, 180, 239, 0, 0, 41, 0, 0, 41) > 10000);
	assert_true(check_plane(&t, &t.sec[0].floor_tex, 180, 239, 0, 0, 41, M_PI / 2, ANG90,
				41) > 10000);
	/* 0x10000000 is 22.5 degrees */
	assert_true(check_plane(&t, &t.sec[0].floor_tex, 190, 239, 10.5, -20.25, 41, M_PI / 8,
				0x10000000u, 41) > 5000);
}

/* The ceiling 87 above the eye, rows 0..10 facing east. */
static void ceiling_texel_follows_the_plane_equations(void **state)
{
	struct tmap t;
	(void)state;
	t_room(&t, 255, 0);
	assert_true(check_plane(&t, &t.sec[0].ceil_tex, 0, 10, 0, 0, 41, 0, 0, 87) > 1000);
	assert_true(check_plane(&t, &t.sec[0].ceil_tex, 0, 10, 60, -10, 41, M_PI, ANG180, 87) >
		    800);
}

/* By hand: facing east from (0,0) z 41, pixel (200, 200): depth 41 * 160 /
 * 80.5 = 81.49, lateral 81.49 * 81 / 320 = 20.63 south: world (81.49,
 * -20.63): flat column 17, row 20. */
static void floor_texel_by_hand(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	t_room(&t, 255, 0);
	t.sec[0].floor_tex = TF_COLS;
	render(&fr, &t.m, 0, 0, 41, 0);
	assert_int_equal(at(&fr, 200, 200), 17);
	t.sec[0].floor_tex = TF_ROWS;
	render(&fr, &t.m, 0, 0, 41, 0);
	assert_int_equal(at(&fr, 200, 200), 20);
	done(&fr);
}

/* The room with a sky ceiling (and light 0: the sky ignores light).
 * TT_SKYCOLS' texel is its column: the pixel at the top of column x is
 * texture column ((view angle + atan((w - 2x - 1) / w)) / 2^22) mod 256
 * (angles in 2^32 per turn). */
static int sky_col(ang_t a, int x)
{
	double rel = atan2(W - 2 * x - 1, W) / (2 * M_PI) * 4294967296.0;
	double ang = fmod((double)a + rel + 4294967296.0, 4294967296.0);
	double c = ang / 4194304.0;
	double f = c - floor(c);

	/* the renderer's angles come from Doom's arctangent table (about
	 * 1/50 of a sky column off here) */
	if (f < 0.05 || f > 0.95)
		return -1;
	return (int)floor(c) % 256;
}

/* The room with a low sky ceiling (64, 23 above the eye): walls, at depth
 * 128 * cos 45 = 90.5 or more, end below row 78 in every view, so rows
 * 0..78 are sky. */
static void sky_room(struct tmap *t)
{
	t_room(t, 0, 0);
	t->sec[0].ceil_h = U(64);
	t->sec[0].ceil_tex = TF_SKY;
	tt->t.sky_flat = TF_SKY;
}

static void sky_columns_follow_the_view_angle(void **state)
{
	static const ang_t angles[] = { 0, ANG45, ANG90, 0x12345678u, 0xfedcba98u };
	struct tmap t;
	static struct frame fr;
	(void)state;
	sky_room(&t);
	tt->t.sky_tex = TT_SKYCOLS;
	for (size_t i = 0; i < sizeof(angles) / sizeof(angles[0]); i++) {
		render(&fr, &t.m, 0, 0, 41, angles[i]);
		for (int x = 0; x < W; x++) {
			int c = sky_col(angles[i], x);

			if (c >= 0 && at(&fr, x, 0) != c)
				fail_msg("angle %08x column %d: sky texel %d, expected %d", angles[i],
					 x, at(&fr, x, 0), c);
		}
	}
	/* four repeats per turn: a quarter turn shows the same sky; an
	 * eighth shifts it by half the texture (128 columns) */
	render(&fr, &t.m, 0, 0, 41, 0x01000000u);
	{
		uint8_t row[W];

		memcpy(row, fr.px, W);
		render(&fr, &t.m, 0, 0, 41, 0x01000000u + ANG90);
		assert_memory_equal(row, fr.px, W);
		render(&fr, &t.m, 0, 0, 41, 0x01000000u + ANG45);
		for (int x = 0; x < W; x++)
			assert_int_equal(fr.px[x], (row[x] + 128) % 256);
	}
	tt->t.sky_flat = -1;
	done(&fr);
}

/* TT_SKYROWS' texel is its row: texel row 100 at the horizon, 256 texels
 * per frame width (0.8 per pixel at w = 320): row y shows 100 + (y + 0.5 -
 * cy) * 0.8. Row 0: 4.4 -> 4; row 10: 12.4 -> 12. With the horizon 20 rows lower (shear
 * 20) row 0 would be -11.6, above the texture: its top texel (0) repeats;
 * row 20 shows 4.4 -> 4. */
static void sky_rows_sit_around_the_horizon_and_move_with_shear(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_view v = { 0, 0, U(41), 0, 20 };
	(void)state;
	sky_room(&t);
	tt->t.sky_tex = TT_SKYROWS;
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int x = 0; x < W; x++) {
		assert_int_equal(at(&fr, x, 0), 4);
		assert_int_equal(at(&fr, x, 10), 12);
	}
	render_v(&fr, &t.m, &v);
	for (int x = 0; x < W; x++) {
		for (int y = 0; y <= 12; y++)
			assert_int_equal(at(&fr, x, y), 0);
		assert_int_equal(at(&fr, x, 20), 4);
		assert_int_equal(at(&fr, x, 30), 12);
	}
	tt->t.sky_flat = -1;
	tt->t.sky_tex = TT_SKYCOLS;
	done(&fr);
}

/* Shear moves the planes with the horizon: the same view sheared by s rows
 * is the unsheared frame moved down by s rows (rows that scroll in at the
 * top aside), for floors, ceilings and walls alike. */
static void shear_moves_planes_by_whole_rows(void **state)
{
	static const int shears[] = { 1, 7, 33, -5, -40 };
	struct tmap t;
	static struct frame f0, fs;
	struct r_view v = { U(13), U(-27), U(41), 0x1234567u, 0 };
	(void)state;
	t_room(&t, 160, 0);
	t.sec[0].floor_tex = TF_COLS;
	t.sec[0].ceil_tex = TF_ROWS;
	render_v(&f0, &t.m, &v);
	for (size_t i = 0; i < sizeof(shears) / sizeof(shears[0]); i++) {
		int s = shears[i];

		v.shear = s;
		render_v(&fs, &t.m, &v);
		for (int y = 0; y < H; y++) {
			if (y + s < 0 || y + s >= H)
				continue;
			assert_memory_equal(&f0.px[y * W], &fs.px[(y + s) * W], W);
		}
	}
	done(&f0);
	done(&fs);
}

/* Growth: a corridor of 1500 strips 8 units deep along x, each its own
 * sector (own light, so its own floor and ceiling visplane key), and one
 * low ceiling strip in every ten (drawsegs with silhouettes). Seen along
 * the corridor at 640x480 every strip is in view: thousands of planes and
 * segs, no overflow, every pixel written once, nothing degraded. */
static void thousands_of_visible_planes_render_whole(void **state)
{
	enum { N = 1500 };
	struct map *m;
	char err[200] = "";
	struct r_ctx *r;
	uint8_t *px = malloc(640 * 480);
	struct r_frame f = { px, 640, 480, 640, NULL };
	struct r_view v = { U(-100), U(3), U(40), 0, 0 };
	struct r_stats st;
	uint32_t nl = 3 * N + 1, side = 0;
	(void)state;
	assert_non_null(px);
	/* vertices (8i, -64) and (8i, 64), i = 0..N */
	assert_int_equal(map_alloc(&m, 2 * (N + 1), N, 2 * nl, nl, 0), 0);
	for (int i = 0; i <= N; i++) {
		m->vertices[2 * i] = (struct map_vertex){ U(8 * i - 200), U(-64) };
		m->vertices[2 * i + 1] = (struct map_vertex){ U(8 * i - 200), U(64) };
	}
	for (int i = 0; i < N; i++) {
		m->sectors[i].floor_h = 0;
		m->sectors[i].ceil_h = U(i % 10 == 5 ? 96 : 128);
		m->sectors[i].floor_tex = (uint16_t)(i % 200);
		m->sectors[i].ceil_tex = (uint16_t)(i % 190 + 1);
		m->sectors[i].light = (uint8_t)(96 + i % 160);
	}
	for (uint32_t k = 0; k < nl; k++) {
		struct map_line *l = &m->lines[k];

		if (k < 2 * (uint32_t)N) {
			/* south wall of strip k/2 (west-going: its right, the
			 * front, is north), then its north wall (east-going) */
			int i = (int)k / 2;

			if (k % 2 == 0) {
				l->v1 = 2 * (uint32_t)i + 2;
				l->v2 = 2 * (uint32_t)i;
			} else {
				l->v1 = 2 * (uint32_t)i + 1;
				l->v2 = 2 * (uint32_t)i + 3;
			}
			l->flags = ML_BLOCKING;
			l->side[0] = side;
			l->side[1] = MAP_NONE;
			m->sides[side].sector = (uint32_t)i;
			m->sides[side++].mid_tex = (uint16_t)(TT_COLS);
		} else {
			/* cross line at x index j = k - 2N, north-going (its front,
			 * east, is strip j); j = 0 and N close the ends */
			uint32_t j = k - 2 * N;

			l->v1 = 2 * j;
			l->v2 = 2 * j + 1;
			l->side[0] = side;
			m->sides[side].sector = j < N ? j : N - 1;
			m->sides[side].top_tex = m->sides[side].bot_tex = TT_WIDE3;
			side++;
			if (j == 0 || j == N) {
				l->flags = ML_BLOCKING;
				l->side[1] = MAP_NONE;
				if (j == N) {
					l->v1 = 2 * j + 1;
					l->v2 = 2 * j;
				}
				m->sides[side - 1].mid_tex = TT_COLS;
			} else {
				l->flags = ML_TWOSIDED;
				l->side[1] = side;
				m->sides[side].sector = j - 1;
				m->sides[side].top_tex = m->sides[side].bot_tex = TT_WIDE3;
				side++;
			}
		}
	}
	m->num_sides = side;
	assert_int_equal(map_finish(m, err, sizeof(err)), 0);
	assert_int_equal(r_new(640, 480, &r), 0);
	v.x = U(-196);
	r_render(r, m, &tt->t, &v, NULL, 0, &f);
	r_get_stats(r, &st);
	assert_int_equal(st.pixels_written, 640 * 480);
	assert_int_equal(st.pixels_empty, 0);
	assert_int_equal(st.degraded, 0);
	assert_true(st.planes > 2000);
	assert_true(st.drawsegs > 100);
	assert_true(st.segs > 1000);
	/* again, with the lists already grown: the same frame */
	{
		uint8_t *first = malloc(640 * 480);

		assert_non_null(first);
		memcpy(first, px, 640 * 480);
		memset(px, 0x5a, 640 * 480);
		r_render(r, m, &tt->t, &v, NULL, 0, &f);
		assert_memory_equal(first, px, 640 * 480);
		free(first);
	}
	r_free(r);
	map_free(m);
	free(px);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(floor_texel_follows_the_plane_equations),
		cmocka_unit_test(ceiling_texel_follows_the_plane_equations),
		cmocka_unit_test(floor_texel_by_hand),
		cmocka_unit_test(sky_columns_follow_the_view_angle),
		cmocka_unit_test(sky_rows_sit_around_the_horizon_and_move_with_shear),
		cmocka_unit_test(shear_moves_planes_by_whole_rows),
		cmocka_unit_test(thousands_of_visible_planes_render_whole),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
