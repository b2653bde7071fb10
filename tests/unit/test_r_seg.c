/*
 * Tests for engine/render/r_seg.c: textured wall columns (horizontal mapping,
 * offsets, pegging, wrapping at any height and width), the sky rule between
 * two sky ceilings, animation translation.
 *
 * Expected texels come from the geometry worked by hand (in doubles, the
 * test's own arithmetic): 320x240, focal 160, horizon at row centre 120.
 * The ray through column x's centre meets a wall at depth D at lateral
 * D * (2x + 1 - 320) / 320 right of the view axis; a pixel row y's centre
 * is (120 - y - 0.5) / scale above the eye, scale = 160 / D. The test
 * textures (r_testmap.h) have texels that name their own column or row;
 * light 255 and near walls keep the colormap the identity. A texel whose
 * exact coordinate lies within 1/50 of a texel boundary may be either
 * neighbour (the renderer's fixed point rounds).
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

static void render(struct frame *fr, const struct map *m, double x, double y, double z, ang_t a)
{
	struct r_view v = { (fx_t)(x * FX_ONE), (fx_t)(y * FX_ONE), (fx_t)(z * FX_ONE), a, 0 };

	if (!fr->r)
		assert_int_equal(r_new(W, H, &fr->r), 0);
	fr->f = (struct r_frame){ fr->px, W, H, W, NULL };
	memset(fr->px, 0xee, sizeof(fr->px));
	r_render(fr->r, m, &tt->t, &v, NULL, 0, &fr->f);
	r_get_stats(fr->r, &fr->st);
	assert_int_equal(fr->st.pixels_written, W * H);
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

/* Asserts the pixel shows texel floor(v) mod n of a texture whose texel
 * colour is base + its index, allowing the neighbour when v is within 1/50
 * of an integer. */
static void assert_texel(const struct frame *fr, int x, int y, double v, int n, int base)
{
	int k = (int)floor(v), got = at(fr, x, y), want = base + ((k % n) + n) % n;
	double frac = v - k;

	if (got == want)
		return;
	if (frac < 0.02 && got == base + (((k - 1) % n) + n) % n)
		return;
	if (frac > 0.98 && got == base + (((k + 1) % n) + n) % n)
		return;
	fail_msg("pixel (%d, %d): colour %d, expected texel %d (coordinate %.4f)", x, y, got,
		 want - base, v);
}

/* Lateral offset (right of the view axis) of column x's ray at depth d. */
static double lateral(int x, double d)
{
	return d * (2 * x + 1 - W) / (double)W;
}

/* Height above the eye of row y's centre at depth d. */
static double height(int y, double d)
{
	return (H / 2.0 - y - 0.5) * d / (W / 2.0);
}

/* The square room (t_room) with its east wall (line 2, (128,128) ->
 * (128,-128), running south) textured tex. */
static void east_wall_room(struct tmap *t, uint16_t tex)
{
	t_room(t, 255, 0);
	t->sd[t->ln[2].side[0]].mid_tex = tex;
}

/* Eye (0,0) z 41 facing east: the east wall is at depth 128, its u (map
 * units from (128,128)) at column x is 128 + lateral, since lateral is
 * south. TT_COLS's texel in column c is c (64 wide). Rows 11..170 are wall
 * (test_r_main's geometry); every wall row of a column shows the same
 * column of the texture. */
static void wall_column_is_the_texel_under_the_ray(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	east_wall_room(&t, TT_COLS);
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int x = 0; x < W; x++) {
		assert_texel(&fr, x, 100, 128 + lateral(x, 128), 64, 0);
		for (int y = 11; y <= 170; y++)
			assert_int_equal(at(&fr, x, y), at(&fr, x, 100));
	}
	/* by hand: column 100's ray meets the wall 47.6 units north of its
	 * middle, u = 80.4: texel 16; column 250: u = 200.4, texel 8 */
	assert_int_equal(at(&fr, 100, 100), 16);
	assert_int_equal(at(&fr, 250, 100), 8);
	done(&fr);
}

/* Perspective: seen obliquely (eye (-64, 40) facing north-east), texels
 * are where the ray meets the wall, not evenly spread over the columns. */
static void wall_mapping_is_perspective_correct(void **state)
{
	struct tmap t;
	static struct frame fr;
	const double ex = -64, ey = 40, ang = M_PI / 4;
	int checked = 0;
	(void)state;
	east_wall_room(&t, TT_COLS);
	render(&fr, &t.m, ex, ey, 41, ANG45);
	for (int x = 0; x < W; x++) {
		/* ray direction: forward (cos, sin) plus lateral * right (sin, -cos) */
		double k = (2 * x + 1 - W) / (double)W;
		double dx = cos(ang) + k * sin(ang), dy = sin(ang) - k * cos(ang);
		double s = (128 - ex) / dx, wy = ey + s * dy;

		/* s is also the depth (the ray's forward component is 1); past
		 * 300 units the distance fade no longer brings the north-south
		 * wall's light to colormap 0 */
		if (wy > 128 || wy < -128 || s > 300)
			continue;
		assert_texel(&fr, x, 120, 128 - wy, 64, 0);
		checked++;
	}
	assert_true(checked > 100);
	done(&fr);
}

/* The side's x offset and the seg's offset add to u. */
static void x_offset_shifts_the_texture(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	east_wall_room(&t, TT_COLS);
	t.sd[t.ln[2].side[0]].xoff = U(10);
	t.sg[2].offset = U(3);
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int x = 0; x < W; x += 7)
		assert_texel(&fr, x, 100, 128 + lateral(x, 128) + 13, 64, 0);
	done(&fr);
}

/* A 3-wide texture (not a power of two) repeats every 3 units. */
static void texture_width_wraps_at_any_width(void **state)
{
	static const uint8_t cols[3] = { 10, 20, 30 };
	struct tmap t;
	static struct frame fr;
	(void)state;
	east_wall_room(&t, TT_WIDE3);
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int x = 0; x < W; x++) {
		double u = 128 + lateral(x, 128);
		int k = (int)floor(u), got = at(&fr, x, 100);

		if (u - k < 0.02 || u - k > 0.98)
			continue;
		assert_int_equal(got, cols[k % 3]);
	}
	done(&fr);
}

/* One-sided wall, pegged: texel row 0 at the ceiling (128, eye 41, so 87
 * above the eye); at depth 128 a row's texel is 87 - height. TT_ROWS100 is
 * 100 high: the texture repeats every 100 rows (row 136 shows texel 0, not
 * 100 as a power-of-two mask of 127 would give). Column 160 shows texture
 * column 0 (u = 128.4), whose texels are their row. */
static void one_sided_wall_hangs_from_the_ceiling_and_wraps_at_its_height(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	east_wall_room(&t, TT_ROWS100);
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int y = 11; y <= 170; y++)
		assert_texel(&fr, 160, y, 87 - height(y, 128), 100, 0);
	/* by hand: row 11 -> 0.2, row 135 -> 99.4, row 136 -> 100.2 = 0,
	 * row 170 -> 127.4 = 27 */
	assert_int_equal(at(&fr, 160, 11), 0);
	assert_int_equal(at(&fr, 160, 135), 99);
	assert_int_equal(at(&fr, 160, 136), 0);
	assert_int_equal(at(&fr, 160, 170), 27);
	/* a y offset of 250 starts the column at texel 250.2 = 50 */
	t.sd[t.ln[2].side[0]].yoff = U(250);
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int y = 11; y <= 170; y++)
		assert_texel(&fr, 160, y, 337 - height(y, 128), 100, 0);
	assert_int_equal(at(&fr, 160, 11), 50);
	done(&fr);
}

/* Lower-unpegged (ML_DONTPEGBOTTOM): the texture's bottom on the floor,
 * row 0 at floor + 100 (59 above the eye); the side's y offset moves the
 * texture up by that many texels (row 0 lower). */
static void lower_unpegged_one_sided_wall_stands_on_the_floor(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	east_wall_room(&t, TT_ROWS100);
	t.ln[2].flags |= ML_DONTPEGBOTTOM;
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int y = 11; y <= 170; y++)
		assert_texel(&fr, 160, y, 59 - height(y, 128), 100, 0);
	assert_int_equal(at(&fr, 160, 170), 99);
	t.sd[t.ln[2].side[0]].yoff = U(20);
	render(&fr, &t.m, 0, 0, 41, 0);
	for (int y = 11; y <= 170; y++)
		assert_texel(&fr, 160, y, 79 - height(y, 128), 100, 0);
	done(&fr);
}

/* t_window(24, 96), eye (0,0) z 64 facing east: A's side of the window
 * line (line 3) has an upper part rows 40..79 and a lower part rows
 * 170..199 at the centre column (depth 128). TT_ROWS128 texels name their
 * row. Doom's rules:
 *  - upper, pegged: the texture's bottom at the back (window) ceiling 96:
 *    row 0 at 96 + 128, 160 above the eye;
 *  - upper, ML_DONTPEGTOP: row 0 at the front ceiling 128 (64 above);
 *  - lower, pegged: row 0 at the back floor 24 (-40);
 *  - lower, ML_DONTPEGBOTTOM: row 0 at the front ceiling (64). */
static void window_pegging(uint16_t flags, double top0, double bot0)
{
	struct tmap t;
	static struct frame fr;
	struct map_side *sd;

	t_window(&t, 24, 96);
	sd = &t.sd[t.ln[3].side[0]];
	sd->top_tex = sd->bot_tex = TT_ROWS128;
	t.ln[3].flags |= flags;
	render(&fr, &t.m, 0, 0, 64, 0);
	for (int y = 40; y <= 79; y++)
		assert_texel(&fr, 160, y, top0 - height(y, 128), 128, 0);
	for (int y = 170; y <= 199; y++)
		assert_texel(&fr, 160, y, bot0 - height(y, 128), 128, 0);
	done(&fr);
}

static void upper_and_lower_textures_follow_dooms_pegging(void **state)
{
	(void)state;
	window_pegging(0, 160, -40);
}

static void unpegged_upper_and_lower_textures_start_at_the_front_ceiling(void **state)
{
	(void)state;
	window_pegging(ML_DONTPEGTOP | ML_DONTPEGBOTTOM, 64, 64);
}

/* By hand for the pegged case: the upper part's last row 79 shows texel
 * 160 - 40.5 * 0.8 = 127.6 -> 127 (the texture's bottom row at the window
 * top); the lower part's first row 170 shows -40 + 50.5 * 0.8 = 0.4 -> 0. */
static void pegged_window_texels_by_hand(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct map_side *sd;
	(void)state;
	t_window(&t, 24, 96);
	sd = &t.sd[t.ln[3].side[0]];
	sd->top_tex = sd->bot_tex = TT_ROWS128;
	render(&fr, &t.m, 0, 0, 64, 0);
	assert_int_equal(at(&fr, 160, 79), 127);
	assert_int_equal(at(&fr, 160, 40), 96);
	assert_int_equal(at(&fr, 160, 170), 0);
	assert_int_equal(at(&fr, 160, 199), 23);
	done(&fr);
}

/* Both ceilings sky (A and the window W lower than A): Doom draws no upper
 * wall there; the sky comes down to the window's ceiling edge. With B's
 * ceiling sky too, the centre column is sky from row 0 to B's far wall
 * (row 93), every such pixel one sky texel column. Without the sky the
 * upper wall (C_WIN) is there. */
static void no_upper_wall_between_two_sky_ceilings(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	t_window(&t, 24, 96);
	render(&fr, &t.m, 0, 0, 64, 0);
	assert_int_equal(at(&fr, 160, 60), C_WIN);
	for (int i = 0; i < 3; i++)
		t.sec[i].ceil_tex = TF_SKY;
	tt->t.sky_flat = TF_SKY;
	tt->t.sky_tex = TT_SKYCOLS;
	render(&fr, &t.m, 0, 0, 64, 0);
	tt->t.sky_flat = -1;
	for (int y = 0; y <= 93; y++)
		assert_int_equal(at(&fr, 160, y), at(&fr, 160, 0));
	assert_int_equal(at(&fr, 160, 94), C_BEAST);
	/* the upper wall is gone across the window: columns 120..199 */
	for (int x = 120; x <= 199; x++)
		assert_int_not_equal(at(&fr, x, 60), C_WIN);
	done(&fr);
}

/* An animated texture: tex_xlat sends TT_COLS to TT_WIDE3, so the wall
 * draws WIDE3's colours; flat_xlat likewise for flats. */
static void walls_and_flats_follow_the_animation_tables(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	east_wall_room(&t, TT_COLS);
	tt->t.tex_xlat[TT_COLS] = TT_WIDE3;
	tt->t.flat_xlat[C_FLOOR] = 77;
	render(&fr, &t.m, 0, 0, 41, 0);
	tt->t.tex_xlat[TT_COLS] = TT_COLS;
	tt->t.flat_xlat[C_FLOOR] = C_FLOOR;
	for (int x = 0; x < W; x++) {
		int c = at(&fr, x, 100);

		assert_true(c == 10 || c == 20 || c == 30);
		assert_int_equal(at(&fr, x, 239), 77);
	}
	done(&fr);
}

/* A texture number past the set, or a translation to one, draws the
 * fallback checker and is counted; the frame is still whole. */
static void unknown_texture_numbers_draw_the_fallback_and_count(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	east_wall_room(&t, 9999);
	t.sec[0].floor_tex = 9999;
	render(&fr, &t.m, 0, 0, 41, 0);
	assert_true(fr.st.missing >= 2);
	assert_int_equal(fr.st.pixels_empty, 0);
	/* two colours on the wall: the checker */
	{
		int a = at(&fr, 0, 100), n = 0;

		for (int x = 0; x < W; x++)
			n += at(&fr, x, 100) != a;
		assert_true(n > 0);
	}
	done(&fr);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(wall_column_is_the_texel_under_the_ray),
		cmocka_unit_test(wall_mapping_is_perspective_correct),
		cmocka_unit_test(x_offset_shifts_the_texture),
		cmocka_unit_test(texture_width_wraps_at_any_width),
		cmocka_unit_test(one_sided_wall_hangs_from_the_ceiling_and_wraps_at_its_height),
		cmocka_unit_test(lower_unpegged_one_sided_wall_stands_on_the_floor),
		cmocka_unit_test(upper_and_lower_textures_follow_dooms_pegging),
		cmocka_unit_test(unpegged_upper_and_lower_textures_start_at_the_front_ceiling),
		cmocka_unit_test(pegged_window_texels_by_hand),
		cmocka_unit_test(no_upper_wall_between_two_sky_ceilings),
		cmocka_unit_test(walls_and_flats_follow_the_animation_tables),
		cmocka_unit_test(unknown_texture_numbers_draw_the_fallback_and_count),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
