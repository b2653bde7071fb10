/*
 * Tests for engine/render/r_mesh.c: built-in meshes drawn as things. The
 * window map of r_testmap.h (room A, a window with a sill and a lintel,
 * room B behind), the eye in A at (0, 0) facing east, 320x240, focal 160,
 * horizon row 120. The lamp mesh (meshes/lamp.obj: base radius 10 on
 * 0..4, post radius 3 on 4..48, lantern radius 8 on 48..64, cap to 68) in
 * a cyan of the built-in palette: its pixels are the cyan ramp, lit by
 * light 255 (colormap 0 and the Lambert term's 0..12 levels darker).
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
#include "engine/map/mesh_builtin.h"
#include "engine/map/tex.h"
#include "engine/render/r_main.h"
#include "tests/unit/r_testmap.h"

#define W 320
#define H 240
#define C_MESH PAL_RGB(PAL_CYAN, 12)

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

struct frame {
	struct r_ctx *r;
	struct r_frame f;
	uint8_t px[W * H];
	struct r_stats st;
};

static void render(struct frame *fr, const struct map *m, int z, const struct r_sprite *spr, int n)
{
	struct r_view v = { 0, 0, U(z), 0, 0 };

	if (!fr->r)
		assert_int_equal(r_new(W, H, &fr->r), 0);
	fr->f = (struct r_frame){ fr->px, W, H, W, NULL };
	r_render(fr->r, m, &tt->t, &v, spr, n, &fr->f);
	r_get_stats(fr->r, &fr->st);
}

static int is_mesh(uint8_t c)
{
	return c / PAL_SHADES == PAL_CYAN;
}

static struct r_sprite lamp_at(int x, int y, ang_t a)
{
	struct r_sprite s = { U(x), U(y), 0, a, 0, 0, 0, MESH_B_LAMP, C_MESH, NULL };

	return s;
}

/* Rows covered in column x. */
static int mesh_rows(const struct frame *fr, int x, int *top, int *bot)
{
	int n = 0;

	*top = H;
	*bot = -1;
	for (int y = 0; y < H; y++)
		if (is_mesh(fr->px[y * W + x])) {
			n++;
			*top = y < *top ? y : *top;
			*bot = y;
		}
	return n;
}

/* In room A at depth 64 with the eye at 34 (octagons with flat sides
 * facing the axes: apothem 0.924 r). The highest pixel is the cap's near
 * top edge (z 68, 34 above the eye, depth 64 - 3.7): row 120 - 34 * 160 /
 * 60.3 = 29.8, the first row whose centre is below it 30 (29 or 31 allow
 * for the corners); the lowest the base's near bottom edge (z 0, depth
 * 64 - 9.24): row 120 + 34 * 160 / 54.76 = 219.3, row 219 the last whose
 * centre is above it. Nothing beyond the base's sides (lateral at most
 * 10 at depth 56 or more: 160 -/+ 28.6 columns). */
static void mesh_in_front_is_drawn_where_projected(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = lamp_at(64, 0, 0);
	int top, bot;

	(void)state;
	t_window(&t, 24, 96);
	render(&fr, &t.m, 34, &s, 1);
	assert_true(fr.st.pixels_masked > 0);
	{
		int n = mesh_rows(&fr, 160, &top, &bot);

		assert_int_equal(n, bot - top + 1);
	}
	assert_in_range(top, 29, 31);
	assert_in_range(bot, 218, 220);
	for (int x = 0; x < W; x++) {
		int n = mesh_rows(&fr, x, &top, &bot);

		if (x < 160 - 29 || x > 160 + 29)
			assert_int_equal(n, 0);
	}
	r_free(fr.r);
}

/* Behind the window in room B at depth 200, eye at 34: the sill (24) hides
 * what is below it: A's lower wall under the window reaches, at depth 128,
 * row 120 + 10 * 160 / 128 = 132.5; the lamp's rows there would go down to
 * 120 + 34 * 0.8 = 147. No mesh pixel at rows 133 and below, some above
 * (the cap's top, 34 above the eye: row 120 - 34 * 0.8 = 92.8; its near
 * edge a little higher). */
static void mesh_behind_a_window_is_clipped_by_the_sill(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = lamp_at(200, 0, 0);
	int top, bot;

	(void)state;
	t_window(&t, 24, 96);
	render(&fr, &t.m, 34, &s, 1);
	assert_true(mesh_rows(&fr, 160, &top, &bot) > 0);
	assert_in_range(top, 90, 95);
	for (int x = 140; x <= 180; x++)
		for (int y = 133; y < H; y++)
			assert_false(is_mesh(fr.px[y * W + x]));
	r_free(fr.r);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(mesh_in_front_is_drawn_where_projected),
		cmocka_unit_test(mesh_behind_a_window_is_clipped_by_the_sill),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
