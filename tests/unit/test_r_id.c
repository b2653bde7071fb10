/*
 * Tests for surface ids (engine/render/r_id.h) in the software renderer
 * (r_set_idbuf): the packing, ids worked out by hand on the hand-built test
 * maps, ids counted against the renderer's own pixel counters, and frames
 * that are the same bytes with and without an id buffer.
 *
 * Geometry by hand: 320 wide, focal 160, horizon at row h/2; a height H
 * above the eye at depth D is at row h/2 - 160 H / D, a row is covered when
 * its centre lies in the span.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/map/map.h"
#include "engine/render/r_id.h"
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
#define H 200

struct frame {
	struct r_ctx *r;
	struct r_frame f;
	uint8_t px[W * H];
	uint32_t ids[W * H];
	struct r_stats st;
};

/* Renders with ids (ids != 0) or without; ids are pre-filled with a value
 * no surface has, so a pixel the renderer misses shows. */
static void render(struct frame *fr, const struct map *m, const struct r_view *v,
		   const struct r_sprite *spr, int n, int ids)
{
	if (!fr->r)
		assert_int_equal(r_new(W, H, &fr->r), 0);
	fr->f = (struct r_frame){ fr->px, W, H, W, NULL };
	memset(fr->px, 0xee, sizeof(fr->px));
	memset(fr->ids, 0xff, sizeof(fr->ids));
	r_set_idbuf(fr->r, ids ? fr->ids : NULL);
	r_render(fr->r, m, &tt->t, v, spr, n, &fr->f);
	r_get_stats(fr->r, &fr->st);
}

static void done(struct frame *fr)
{
	r_free(fr->r);
	fr->r = NULL;
}

static uint32_t id_at(const struct frame *fr, int x, int y)
{
	return fr->ids[y * W + x];
}

static uint32_t count_kind(const struct frame *fr, enum r_id_kind k)
{
	uint32_t n = 0;

	for (int i = 0; i < W * H; i++)
		n += r_id_kind(fr->ids[i]) == k;
	return n;
}

static void id_packs_kind_and_index(void **state)
{
	(void)state;
	for (int k = 0; k < R_IDK_COUNT; k++) {
		uint32_t id = r_id((enum r_id_kind)k, 123456);

		assert_int_equal(r_id_kind(id), k);
		assert_int_equal(r_id_index(id), 123456);
	}
	/* the index keeps 28 bits; the kind is untouched by a larger one */
	assert_int_equal(r_id_index(r_id(R_IDK_SPRITE, 0x1fffffffu)), 0x0fffffffu);
	assert_int_equal(r_id_kind(r_id(R_IDK_SPRITE, 0x1fffffffu)), R_IDK_SPRITE);
	assert_int_equal(r_id(R_IDK_NONE, 0), 0);
}

/* t_room (square room [-128, 128]^2, floor 0, ceiling 128), eye at the
 * centre z 64 facing east: the east wall (line 2 c-d, side 0: index 4) at
 * depth 128, scale 1.25. Its top is 64 above the eye: row 100 - 80 = 20,
 * its bottom row 180. Column 160: rows 0..19 ceiling, 20..179 wall, 180..199
 * floor; every pixel is one of the room's surfaces. */
static void room_ids_match_the_geometry(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_view v = { 0, 0, U(64), 0, 0 };
	(void)state;

	t_room(&t, 255, 0);
	render(&fr, &t.m, &v, NULL, 0, 1);
	for (int y = 0; y < H; y++) {
		uint32_t want = y < 20 ? r_id(R_IDK_CEIL, 0) :
				y < 180 ? r_id(R_IDK_MIDDLE, 4) : r_id(R_IDK_FLOOR, 0);

		assert_int_equal(id_at(&fr, 160, y), want);
	}
	for (int i = 0; i < W * H; i++) {
		enum r_id_kind k = r_id_kind(fr.ids[i]);

		assert_true(k == R_IDK_CEIL || k == R_IDK_FLOOR || k == R_IDK_MIDDLE);
		if (k == R_IDK_MIDDLE)
			assert_true(r_id_index(fr.ids[i]) % 2 == 0 && r_id_index(fr.ids[i]) < 8);
		else
			assert_int_equal(r_id_index(fr.ids[i]), 0);
	}
	/* the ceiling as the sky: the same rows, now sky */
	tt->t.sky_flat = C_CEIL;
	render(&fr, &t.m, &v, NULL, 0, 1);
	tt->t.sky_flat = -1;
	for (int y = 0; y < 20; y++)
		assert_int_equal(id_at(&fr, 160, y), r_id(R_IDK_SKY, 0));
	assert_int_equal(id_at(&fr, 160, 20), r_id(R_IDK_MIDDLE, 4));
	done(&fr);
}

/* A view from outside every wall (eye east of the room, facing away from
 * it) sees nothing: every pixel is the black fill, id 0, as many as the
 * renderer counts empty. */
static void empty_pixels_have_id_none(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_view v = { U(300), 0, U(64), 0, 0 };
	(void)state;

	t_room(&t, 255, 0);
	render(&fr, &t.m, &v, NULL, 0, 1);
	assert_int_equal(fr.st.pixels_empty, W * H);
	assert_int_equal(count_kind(&fr, R_IDK_NONE), W * H);
	for (int i = 0; i < W * H; i++)
		assert_int_equal(fr.ids[i], 0);
	done(&fr);
}

/* Sprites and masked middles write their id exactly where they write a
 * texel: with one sprite (or one masked texture) in view, the pixels with
 * that id number the renderer's masked writes. Sprite 0 at (64, 0) facing
 * the eye from (0, 0) z 41 spans columns 140..179 and, as in test_r_things
 * but with the horizon at row 100, heights 9..41 below the eye at scale
 * 2.5: 100 + 9 * 2.5 =
 * 122.5 .. 100 + 41 * 2.5 = 202.5, clipped to row 199). */
static void sprite_and_masked_ids_cover_their_texels(void **state)
{
	struct tmap t;
	static struct frame fr;
	struct r_view v = { 0, 0, U(41), 0, 0 };
	struct r_sprite s[2] = { { U(64), 0, 0, ANG180, 0, 0, 0, 0, 0, NULL }, { U(64), 0, 0, ANG180, 2, 0, 0, 0, 0, NULL } };
	(void)state;

	t_room(&t, 255, 0);
	render(&fr, &t.m, &v, s, 1, 1);
	assert_int_equal(count_kind(&fr, R_IDK_SPRITE), fr.st.pixels_masked);
	assert_int_equal(id_at(&fr, 160, 150), r_id(R_IDK_SPRITE, 0));
	/* (the top edge, 122.5, is exactly a row centre: rows either side) */
	assert_int_equal(id_at(&fr, 160, 121), r_id(R_IDK_MIDDLE, 4));
	assert_int_equal(id_at(&fr, 160, 123), r_id(R_IDK_SPRITE, 0));
	/* beside it the floor (the east wall ends at row 100 + 41 * 1.25 =
	 * 151.25) */
	assert_int_equal(id_at(&fr, 139, 170), r_id(R_IDK_FLOOR, 0));
	assert_int_equal(id_at(&fr, 140, 170), r_id(R_IDK_SPRITE, 0));
	assert_int_equal(id_at(&fr, 179, 170), r_id(R_IDK_SPRITE, 0));
	assert_int_equal(id_at(&fr, 180, 170), r_id(R_IDK_FLOOR, 0));
	/* two sprites at one place: the later one in the list shows where it
	 * is opaque (sprite 2: left half only), the earlier one elsewhere */
	render(&fr, &t.m, &v, s, 2, 1);
	assert_int_equal(id_at(&fr, 145, 150), r_id(R_IDK_SPRITE, 1));
	assert_int_equal(id_at(&fr, 175, 150), r_id(R_IDK_SPRITE, 0));

	/* t_window(0, 128) with TT_MASK on line 3's A side, seen from z 124
	 * (test_r_things): only masked texels carry the masked id */
	t_window(&t, 0, 128);
	t.sd[t.ln[3].side[0]].mid_tex = TT_MASK;
	v.z = U(124);
	render(&fr, &t.m, &v, NULL, 0, 1);
	assert_true(fr.st.pixels_masked > 0);
	assert_int_equal(count_kind(&fr, R_IDK_MASKED), fr.st.pixels_masked);
	for (int i = 0; i < W * H; i++)
		if (r_id_kind(fr.ids[i]) == R_IDK_MASKED)
			assert_int_equal(r_id_index(fr.ids[i]), 3 * 2 + 0);
	done(&fr);
}

/* The frame is the same bytes with and without ids, over views that draw
 * walls, planes, the sky, masked middles, sprites, and shear. */
static void ids_leave_the_frame_unchanged(void **state)
{
	struct tmap t;
	static struct frame a, b;
	struct r_sprite s[3] = { { U(200), 0, 0, 0, 0, 0, 0, 0, 0, NULL }, { U(64), U(32), 0, ANG90, 1, 0, 0, 0, 0, NULL },
				 { U(300), U(-40), 0, ANG180, 2, 0, R_SPR_FULLBRIGHT, 0, 0, NULL } };
	(void)state;

	t_window(&t, 24, 96);
	t.sd[t.ln[3].side[0]].mid_tex = TT_MASK;
	tt->t.sky_flat = C_CEIL;
	for (int k = 0; k < 24; k++) {
		struct r_view v = { U(-100 + 9 * k), U(-60 + 5 * k), U(41 + 3 * k),
				    (ang_t)k * (ANG45 / 3), (k % 5) * 17 - 34 };

		render(&a, &t.m, &v, s, 3, 0);
		render(&b, &t.m, &v, s, 3, 1);
		assert_memory_equal(a.px, b.px, sizeof(a.px));
		for (int i = 0; i < W * H; i++)
			assert_int_not_equal(b.ids[i], 0xffffffffu);
	}
	tt->t.sky_flat = -1;
	done(&a);
	done(&b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(id_packs_kind_and_index),
		cmocka_unit_test(room_ids_match_the_geometry),
		cmocka_unit_test(empty_pixels_have_id_none),
		cmocka_unit_test(sprite_and_masked_ids_cover_their_texels),
		cmocka_unit_test(ids_leave_the_frame_unchanged),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
