/*
 * Tests for engine/render/r_things.c: sprites (projection, rotation and mirroring,
 * light, occlusion by walls through drawseg silhouettes, back-to-front
 * order) and masked middle textures (holes show what is behind, drawn over
 * sprites behind them); shear moves all of it.
 *
 * Geometry by hand: 320x240, focal 160, horizon at row 120. A sprite at
 * depth D has scale 160 / D pixels per unit; the test pictures (r_testmap.h)
 * are 16 x 32 with left offset 8 and top offset 32, so a sprite standing on
 * z covers lateral -8..8 and heights z..z + 32; picture k's texel in column
 * c is 16k + c. Sprite 0 shows picture k at rotation k. Rows and columns
 * are covered when their centre lies in the projected span; checks keep a
 * pixel away from span edges.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
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

static void render_v(struct frame *fr, const struct map *m, const struct r_view *v,
		     const struct r_sprite *spr, int n)
{
	if (!fr->r)
		assert_int_equal(r_new(W, H, &fr->r), 0);
	fr->f = (struct r_frame){ fr->px, W, H, W, NULL };
	memset(fr->px, 0xee, sizeof(fr->px));
	r_render(fr->r, m, &tt->t, v, spr, n, &fr->f);
	r_get_stats(fr->r, &fr->st);
	assert_int_equal(fr->st.pixels_written, W * H);
}

static void render(struct frame *fr, const struct map *m, int z, const struct r_sprite *spr,
		   int n)
{
	struct r_view v = { 0, 0, U(z), 0, 0 };

	render_v(fr, m, &v, spr, n);
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

static struct r_sprite spr_at(int x, int y, int z, ang_t facing, int sprite)
{
	struct r_sprite s = { U(x), U(y), U(z), facing, (uint16_t)sprite, 0, 0, 0, 0, NULL };

	return s;
}

/* Sprite 0 at (64, 0) on the floor facing the eye (west, ANG180: rotation
 * 0) seen from (0, 0) z 41 facing east: depth 64, scale 2.5: columns
 * 160 +/- 20 (140..179), rows 120 + 9 * 2.5 = 142.5 .. 120 + 41 * 2.5 =
 * 222.5 (142..221); column x shows texel (x + 0.5 - 140) / 2.5. It covers
 * the east wall and the floor there; outside its box they show. */
static void sprite_projects_onto_its_box_with_its_texels(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = spr_at(64, 0, 0, ANG180, 0);
	(void)state;
	t_room(&t, 255, 0);
	render(&fr, &t.m, 41, &s, 1);
	for (int x = 141; x <= 178; x++) {
		int u = (int)((x + 0.5 - 140) / 2.5);
		double f = (x + 0.5 - 140) / 2.5 - u;

		if (f < 0.02 || f > 0.98)
			continue;
		for (int y = 144; y <= 220; y++)
			assert_int_equal(at(&fr, x, y), u);
	}
	assert_int_equal(at(&fr, 150, 180), 4);
	assert_int_equal(at(&fr, 138, 180), C_FLOOR);
	assert_int_equal(at(&fr, 181, 180), C_FLOOR);
	assert_int_equal(at(&fr, 160, 140), C_EAST);
	assert_int_equal(at(&fr, 160, 224), C_FLOOR);
	assert_int_equal(fr.st.sprites, 1);
	assert_true(fr.st.pixels_masked >= 38 * 77);
	done(&fr);
}

/* Rotation (Doom's): viewer-to-thing angle 0 here; a thing facing
 * ANG180 - k * ANG45 shows rotation k, picture k: the centre column (u =
 * 20.5 / 2.5 = 8.2) is 16k + 8. Half way between two facings the nearer
 * rotation wins: ANG180 - 22 degrees is still rotation 0, 23 degrees
 * rotation 1. */
static void rotation_follows_the_angle_between_viewer_and_facing(void **state)
{
	struct tmap t;
	static struct frame fr;
	(void)state;
	t_room(&t, 255, 0);
	for (int k = 0; k < 8; k++) {
		struct r_sprite s = spr_at(64, 0, 0, ANG180 - (ang_t)k * ANG45, 0);

		render(&fr, &t.m, 41, &s, 1);
		assert_int_equal(at(&fr, 160, 180), 16 * k + 8);
	}
	{
		struct r_sprite s = spr_at(64, 0, 0, ANG180 - (ANG45 / 45) * 22, 0);

		render(&fr, &t.m, 41, &s, 1);
		assert_int_equal(at(&fr, 160, 180), 8);
		s.angle = ANG180 - (ANG45 / 45) * 23;
		render(&fr, &t.m, 41, &s, 1);
		assert_int_equal(at(&fr, 160, 180), 24);
	}
	/* seen from the side: the eye north of the thing (viewer-to-thing
	 * angle 270 degrees) facing south; thing facing east (0): rotation
	 * (270 - 0 + 202.5) / 45 = 10.5 -> 2 (mod 8) */
	{
		struct r_sprite s = spr_at(0, -64, 0, 0, 0);
		struct r_view v = { 0, 0, U(41), ANG270, 0 };

		render_v(&fr, &t.m, &v, &s, 1);
		assert_int_equal(at(&fr, 160, 180), 16 * 2 + 8);
	}
	done(&fr);
}

/* Sprite 1 is mirrored as Doom's A2A8 pairs: rotation 7 shows picture 1
 * flipped, so column u shows texel 15 - u: at the centre 16 + 7, while
 * rotation 1 shows 16 + 8. */
static void mirrored_rotations_flip_the_picture(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = spr_at(64, 0, 0, ANG180 - 7 * ANG45, 1);
	(void)state;
	t_room(&t, 255, 0);
	render(&fr, &t.m, 41, &s, 1);
	assert_int_equal(at(&fr, 160, 180), 16 + 7);
	assert_int_equal(at(&fr, 142, 180), 16 + 15);
	assert_int_equal(at(&fr, 176, 180), 16 + 1);
	s.angle = ANG180 - ANG45;
	render(&fr, &t.m, 41, &s, 1);
	assert_int_equal(at(&fr, 160, 180), 16 + 8);
	assert_int_equal(at(&fr, 142, 180), 16 + 0);
	done(&fr);
}

/* Light: in a light-128 room the sprite (no fake contrast) has base level
 * 4 * (15 - 8) = 28, faded by 1280 / 64 = 20: level 8. Full bright:
 * colormap 0. Picture 8's right half is transparent: the wall shows. */
static void sprite_light_fades_with_distance_unless_full_bright(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = spr_at(64, 0, 0, ANG180, 0);
	(void)state;
	t_room(&t, 128, 0);
	render(&fr, &t.m, 41, &s, 1);
	assert_int_equal(at(&fr, 150, 180), tt->t.pal.cmap[8][4]);
	s.flags = R_SPR_FULLBRIGHT;
	render(&fr, &t.m, 41, &s, 1);
	assert_int_equal(at(&fr, 150, 180), 4);
	/* the holed picture: columns 140..159 opaque, 160..179 not */
	s = spr_at(64, 0, 0, ANG180, 2);
	render(&fr, &t.m, 41, &s, 1);
	{
		static struct frame ref;

		render(&ref, &t.m, 41, NULL, 0);
		for (int y = 144; y <= 220; y++) {
			assert_int_equal(at(&fr, 150, y), tt->t.pal.cmap[8][TT_HOLE_C]);
			assert_int_equal(at(&fr, 170, y), at(&ref, 170, y));
		}
		done(&ref);
	}
	done(&fr);
}

/* t_window(24, 96), eye (0,0) z 64 facing east. A sprite in room B at
 * (200, 0) on B's floor (depth 200, scale 0.8): columns 160 +/- 6.4
 * (154..165), rows 120 + 32 * 0.8 = 145.6 .. 120 + 64 * 0.8 = 171.2. The
 * window's sill is in front of its feet: the sill's top (the window's floor,
 * 40 below the eye from depth 128 to 144) covers rows 120 + 40 * 160 / 144
 * = 164.4 .. 169, A's lower wall rows 170 on. Rows 146..163 show the
 * sprite. Picture 4 (facing away, rotation 4) is colours 64..79. */
static int is_spr4(int c)
{
	return c >= 64 && c <= 79;
}

static void sprite_behind_a_window_is_clipped_by_the_sill_and_its_floor(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = spr_at(200, 0, 0, 0, 0);
	(void)state;
	t_window(&t, 24, 96);
	render(&fr, &t.m, 64, &s, 1);
	for (int x = 155; x <= 164; x++) {
		for (int y = 147; y <= 163; y++)
			assert_true(is_spr4(at(&fr, x, y)));
		for (int y = 165; y <= 169; y++)
			assert_int_equal(at(&fr, x, y), C_FLOOR);
		assert_int_equal(at(&fr, x, 170), C_WIN);
	}
	done(&fr);
}

/* The same sprite lifted to z 90 (top 122, bottom 90): rows 120 - 58 * 0.8 =
 * 73.6 .. 120 - 26 * 0.8 = 99.2. A's upper wall over the window (rows
 * 40..79) and the window's own ceiling (to 120 - 32 * 160 / 144 = 84.4 at
 * its far side) are in front of it: rows 74..83 are those, rows 84..98 the
 * sprite. */
static void sprite_behind_a_window_is_clipped_by_the_lintel(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = spr_at(200, 0, 90, 0, 0);
	(void)state;
	t_window(&t, 24, 96);
	render(&fr, &t.m, 64, &s, 1);
	for (int x = 155; x <= 164; x++) {
		for (int y = 74; y <= 83; y++)
			assert_false(is_spr4(at(&fr, x, y)));
		assert_int_equal(at(&fr, x, 79), C_WIN);
		assert_int_equal(at(&fr, x, 83), C_CEIL);
		for (int y = 84; y <= 98; y++)
			assert_true(is_spr4(at(&fr, x, y)));
	}
	done(&fr);
}

/* With the window closed (floor meets ceiling) the sprite behind A's east
 * wall is not drawn at all (the walk never reaches B; no silhouette of the
 * closed window would hide its lower part: the window's floor is below the
 * eye and above A's floor); in front of the wall it is. */
static void sprite_behind_a_solid_wall_is_hidden(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s[2] = { spr_at(200, 0, 0, 0, 0), spr_at(64, 0, 0, 0, 0) };
	(void)state;
	t_window(&t, 60, 60);
	render(&fr, &t.m, 64, s, 1);
	assert_int_equal(fr.st.pixels_masked, 0);
	for (int i = 0; i < W * H; i++)
		assert_false(is_spr4(fr.px[i]));
	render(&fr, &t.m, 64, &s[1], 1);
	assert_true(fr.st.pixels_masked > 0);
	/* depth 64 with the eye at 64: rows 120 + 32 * 2.5 = 200 down */
	assert_true(is_spr4(at(&fr, 160, 220)));
	done(&fr);
}

/* Two sprites, one in front of the other (depth 64: rotation 4, colours
 * 64..79; depth 100: rotation 0, colours 0..15): the nearer covers the
 * farther where they overlap, whatever the order of the list. */
static void nearer_sprites_cover_farther_ones_in_any_list_order(void **state)
{
	struct tmap t;
	static struct frame a, b;
	struct r_sprite s[2] = { spr_at(64, 0, 0, 0, 0), spr_at(100, 0, 0, ANG180, 0) };
	struct r_sprite rev[2] = { s[1], s[0] };
	(void)state;
	t_room(&t, 255, 0);
	render(&a, &t.m, 41, s, 2);
	render(&b, &t.m, 41, rev, 2);
	assert_memory_equal(a.px, b.px, sizeof(a.px));
	/* (160, 180): both cover it, the nearer shows; (160, 138): only the
	 * farther (rows 120 + 9 * 1.6 = 134.4 ..) */
	assert_true(is_spr4(at(&a, 160, 180)));
	assert_true(at(&a, 160, 138) <= 15);
	done(&a);
	done(&b);
}

/* t_window(0, 128): the window is a plain opening (all three rooms f0
 * c128). Its A-side gets the masked middle TT_MASK (8 x 8, columns 0..3
 * opaque TT_MASK_C, 4..7 transparent), pegged: top at the lower ceiling
 * 128, 4 above the eye (z 124), so rows 115..124 at depth 128 (scale
 * 1.25), once (masked middles do not tile). u = 32 + lateral; where u mod 8
 * < 4 the pixel is TT_MASK_C, elsewhere exactly what the frame without the
 * masked texture shows. */
static void masked_middle_shows_what_is_behind_through_its_holes(void **state)
{
	struct tmap t;
	static struct frame ref, fr;
	int opaque = 0, clear = 0;
	(void)state;
	t_window(&t, 0, 128);
	render(&ref, &t.m, 124, NULL, 0);
	t.sd[t.ln[3].side[0]].mid_tex = TT_MASK;
	render(&fr, &t.m, 124, NULL, 0);
	for (int x = 121; x <= 198; x++) {
		double u = 32 + 128.0 * (2 * x + 1 - W) / W;
		int k = (int)u;
		double f = u - k;

		if (f < 0.02 || f > 0.98)
			continue;
		for (int y = 116; y <= 123; y++) {
			if (k % 8 < 4) {
				assert_int_equal(at(&fr, x, y), TT_MASK_C);
				opaque++;
			} else {
				assert_int_equal(at(&fr, x, y), at(&ref, x, y));
				clear++;
			}
		}
		/* not tiled: above and below its 8 texels, what is behind */
		assert_int_equal(at(&fr, x, 112), at(&ref, x, 112));
		assert_int_equal(at(&fr, x, 127), at(&ref, x, 127));
	}
	assert_true(opaque > 200 && clear > 200);
	/* elsewhere the frames are identical */
	for (int y = 0; y < H; y++)
		if (y < 114 || y > 125)
			assert_memory_equal(&fr.px[y * W], &ref.px[y * W], W);
	done(&ref);
	done(&fr);
}

/* A sprite behind the masked middle (in B at (200, 0), z 110: rows 120 -
 * 18 * 0.8 = 105.6 .. 120 + 14 * 0.8 = 131.2, columns 154..165) is drawn
 * first and the masked texture over it: opaque texels cover the sprite,
 * holes show it. */
static void masked_middle_covers_a_sprite_behind_it(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = spr_at(200, 0, 110, 0, 0);
	(void)state;
	t_window(&t, 0, 128);
	t.sd[t.ln[3].side[0]].mid_tex = TT_MASK;
	render(&fr, &t.m, 124, &s, 1);
	for (int x = 155; x <= 164; x++) {
		double u = 32 + 128.0 * (2 * x + 1 - W) / W;
		int k = (int)u;
		double f = u - k;

		if (f < 0.02 || f > 0.98)
			continue;
		for (int y = 116; y <= 123; y++)
			assert_true(k % 8 < 4 ? at(&fr, x, y) == TT_MASK_C : is_spr4(at(&fr, x, y)));
		assert_true(is_spr4(at(&fr, x, 110)));
		assert_true(is_spr4(at(&fr, x, 128)));
	}
	done(&fr);
}

/* A sprite in front of the masked middle (in A at (100, 0), z 96: depth
 * 100, scale 1.6, rows 120 - 4 * 1.6 = 113.6 .. 120 + 28 * 1.6 = 164.8,
 * columns 160 +/- 12.8) covers it: the masked range behind the sprite is
 * drawn before the sprite. */
static void sprite_covers_a_masked_middle_behind_it(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_sprite s = spr_at(100, 0, 96, 0, 0);
	(void)state;
	t_window(&t, 0, 128);
	t.sd[t.ln[3].side[0]].mid_tex = TT_MASK;
	render(&fr, &t.m, 124, &s, 1);
	for (int x = 149; x <= 171; x++)
		for (int y = 115; y <= 124; y++)
			assert_true(is_spr4(at(&fr, x, y)));
	/* beside the sprite the masked middle is there */
	{
		int n = 0;

		for (int x = 121; x <= 146; x++)
			n += at(&fr, x, 120) == TT_MASK_C;
		assert_true(n > 8);
	}
	done(&fr);
}

/* Shear moves everything by whole rows: sky, walls, planes, a masked
 * middle and sprites, sheared by s, are the unsheared frame moved down by
 * s rows (rows scrolling in aside). */
static void shear_moves_everything_by_whole_rows(void **state)
{
	static const int shears[] = { 3, 17, -9, -30 };
	struct tmap t;
	static struct frame f0, fs;
	struct r_sprite s[3] = { spr_at(200, 0, 110, 0, 0), spr_at(90, 20, 0, ANG90, 1),
				 spr_at(300, -40, 0, 0x12345678u, 0) };
	struct r_view v = { U(-20), U(5), U(100), 0x0123456u, 0 };
	(void)state;
	t_window(&t, 0, 128);
	t.sd[t.ln[3].side[0]].mid_tex = TT_MASK;
	for (int i = 0; i < 3; i++) {
		t.sec[i].ceil_tex = TF_SKY;
		t.sec[i].floor_tex = TF_COLS;
	}
	tt->t.sky_flat = TF_SKY;
	render_v(&f0, &t.m, &v, s, 3);
	assert_true(f0.st.pixels_masked > 500);
	for (size_t i = 0; i < sizeof(shears) / sizeof(shears[0]); i++) {
		v.shear = shears[i];
		render_v(&fs, &t.m, &v, s, 3);
		for (int y = 0; y < H; y++)
			if (y + shears[i] >= 0 && y + shears[i] < H)
				assert_memory_equal(&f0.px[y * W], &fs.px[(y + shears[i]) * W], W);
	}
	tt->t.sky_flat = -1;
	done(&f0);
	done(&fs);
}

/* Sprite and frame numbers past the set are skipped and counted. */
static void unknown_sprites_are_skipped_and_counted(void **state)
{
	struct tmap t;
	static struct frame fr, ref;
	struct r_sprite s[2] = { spr_at(64, 0, 0, 0, 7), spr_at(64, 0, 0, 0, 0) };
	(void)state;
	s[1].frame = 3;
	t_room(&t, 255, 0);
	render(&fr, &t.m, 41, s, 2);
	render(&ref, &t.m, 41, NULL, 0);
	assert_int_equal(fr.st.missing, 2);
	assert_memory_equal(fr.px, ref.px, sizeof(fr.px));
	done(&fr);
	done(&ref);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sprite_projects_onto_its_box_with_its_texels),
		cmocka_unit_test(rotation_follows_the_angle_between_viewer_and_facing),
		cmocka_unit_test(mirrored_rotations_flip_the_picture),
		cmocka_unit_test(sprite_light_fades_with_distance_unless_full_bright),
		cmocka_unit_test(sprite_behind_a_window_is_clipped_by_the_sill_and_its_floor),
		cmocka_unit_test(sprite_behind_a_window_is_clipped_by_the_lintel),
		cmocka_unit_test(sprite_behind_a_solid_wall_is_hidden),
		cmocka_unit_test(nearer_sprites_cover_farther_ones_in_any_list_order),
		cmocka_unit_test(masked_middle_shows_what_is_behind_through_its_holes),
		cmocka_unit_test(masked_middle_covers_a_sprite_behind_it),
		cmocka_unit_test(sprite_covers_a_masked_middle_behind_it),
		cmocka_unit_test(shear_moves_everything_by_whole_rows),
		cmocka_unit_test(unknown_sprites_are_skipped_and_counted),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
