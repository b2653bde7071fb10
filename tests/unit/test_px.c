/* Tests for display/px.c: formats, conversion table, layout, blit.
 *
 * Expected values are hand-computed constants (table entries, scale
 * factors, offsets) or come from the rotation formulas applied per source
 * pixel, independently of px_layout_init's offset tables:
 *   rotate 0:   (rx, ry) = (sx, sy)
 *   rotate 90:  (rx, ry) = (H - 1 - sy, sx)      top row -> right column
 *   rotate 180: (rx, ry) = (W - 1 - sx, H - 1 - sy)
 *   rotate 270: (rx, ry) = (sy, W - 1 - sx)      top row -> left column
 * with the scaled pixel at (dst_x + k*rx + i, dst_y + k*ry + j).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "display/px.h"

#define SENTINEL 0xA5
#define PAD 24

/* ---- formats and table -------------------------------------------------- */

struct colour_case {
	uint8_t rgb[3];
	uint32_t want;
};

static void check_table(const char *name, int bytes, const struct colour_case *c, int n)
{
	uint8_t pal[256][3];
	struct px_format f;
	struct px_table *t = malloc(sizeof(*t));
	int i;

	assert_non_null(t);
	memset(pal, 0, sizeof(pal));
	for (i = 0; i < n; i++)
		memcpy(pal[i + 1], c[i].rgb, 3);
	assert_int_equal(px_format_by_name(name, &f), 0);
	assert_int_equal(px_format_check(&f), 0);
	assert_string_equal(px_format_name(&f), name);
	px_table_build(t, &f, pal);
	assert_int_equal(t->bytes, bytes);
	assert_int_equal(t->v[0], 0);
	for (i = 0; i < n; i++)
		assert_int_equal(t->v[i + 1], c[i].want);
	free(t);
}

static void table_rgb565_pure_and_grey(void **state)
{
	/* grey 128: 5 bits 128*31/255 = 15.56 -> 16, 6 bits 128*63/255 = 31.6 -> 32 */
	static const struct colour_case c[] = {
		{ { 255, 0, 0 }, 0xF800 }, { { 0, 255, 0 }, 0x07E0 }, { { 0, 0, 255 }, 0x001F },
		{ { 255, 255, 255 }, 0xFFFF }, { { 128, 128, 128 }, 0x8410 },
		/* rounding edge: 5*31/255 = 0.61 -> 1, 4*31/255 = 0.49 -> 0 */
		{ { 5, 0, 0 }, 0x0800 }, { { 4, 0, 0 }, 0x0000 },
	};
	(void)state;
	check_table("rgb565", 2, c, (int)(sizeof(c) / sizeof(c[0])));
}

static void table_bgr565_pure_and_grey(void **state)
{
	static const struct colour_case c[] = {
		{ { 255, 0, 0 }, 0x001F }, { { 0, 255, 0 }, 0x07E0 }, { { 0, 0, 255 }, 0xF800 },
		{ { 255, 255, 255 }, 0xFFFF }, { { 128, 128, 128 }, 0x8410 },
	};
	(void)state;
	check_table("bgr565", 2, c, (int)(sizeof(c) / sizeof(c[0])));
}

static void table_xrgb8888_pure_and_grey(void **state)
{
	static const struct colour_case c[] = {
		{ { 255, 0, 0 }, 0x00FF0000 }, { { 0, 255, 0 }, 0x0000FF00 },
		{ { 0, 0, 255 }, 0x000000FF }, { { 255, 255, 255 }, 0x00FFFFFF },
		{ { 128, 128, 128 }, 0x00808080 }, { { 1, 2, 3 }, 0x00010203 },
	};
	(void)state;
	check_table("xrgb8888", 4, c, (int)(sizeof(c) / sizeof(c[0])));
}

static void table_xbgr8888_pure_and_grey(void **state)
{
	static const struct colour_case c[] = {
		{ { 255, 0, 0 }, 0x000000FF }, { { 0, 255, 0 }, 0x0000FF00 },
		{ { 0, 0, 255 }, 0x00FF0000 }, { { 255, 255, 255 }, 0x00FFFFFF },
		{ { 128, 128, 128 }, 0x00808080 }, { { 1, 2, 3 }, 0x00030201 },
	};
	(void)state;
	check_table("xbgr8888", 4, c, (int)(sizeof(c) / sizeof(c[0])));
}

static void table_rgb888_pure_and_grey(void **state)
{
	static const struct colour_case c[] = {
		{ { 255, 0, 0 }, 0xFF0000 }, { { 0, 255, 0 }, 0x00FF00 }, { { 0, 0, 255 }, 0x0000FF },
		{ { 255, 255, 255 }, 0xFFFFFF }, { { 128, 128, 128 }, 0x808080 },
	};
	(void)state;
	check_table("rgb888", 3, c, (int)(sizeof(c) / sizeof(c[0])));
}

static void table_custom_format_rgb555(void **state)
{
	/* xrgb1555: r 10/5 g 5/5 b 0/5; grey 128 -> 16 in each field */
	struct px_format f = { 16, 10, 5, 5, 5, 0, 5 };
	uint8_t pal[256][3];
	struct px_table t;
	(void)state;
	memset(pal, 0, sizeof(pal));
	pal[1][0] = 255;
	pal[2][0] = pal[2][1] = pal[2][2] = 128;
	assert_int_equal(px_format_check(&f), 0);
	assert_string_equal(px_format_name(&f), "custom");
	px_table_build(&t, &f, pal);
	assert_int_equal(t.v[1], 0x7C00);
	assert_int_equal(t.v[2], (16 << 10) | (16 << 5) | 16);
}

static void format_unknown_name_is_einval(void **state)
{
	struct px_format f;
	(void)state;
	assert_int_equal(px_format_by_name("rgb332", &f), -EINVAL);
	assert_int_equal(px_format_by_name(NULL, &f), -EINVAL);
}

static void format_check_rejects_bad_fields(void **state)
{
	struct px_format ok = { 32, 16, 8, 8, 8, 0, 8 }, f;
	(void)state;
	f = ok;
	f.bpp = 8;
	assert_int_equal(px_format_check(&f), -EINVAL);
	f = ok;
	f.r_len = 9;
	assert_int_equal(px_format_check(&f), -EINVAL);
	f = ok;
	f.g_len = 0;
	assert_int_equal(px_format_check(&f), -EINVAL);
	f = ok;
	f.r_off = 12;   /* overlaps green at 8..15 */
	assert_int_equal(px_format_check(&f), -EINVAL);
	f = ok;
	f.bpp = 16;     /* red at 16..23 lies outside 16 bits */
	assert_int_equal(px_format_check(&f), -EINVAL);
	f = ok;
	f.b_off = -1;
	assert_int_equal(px_format_check(&f), -EINVAL);
	assert_int_equal(px_format_check(&ok), 0);
}

/* ---- layout ------------------------------------------------------------- */

static struct px_layout *layout(int pw, int ph, int rot, int fill, int sw, int sh)
{
	struct px_layout *l = calloc(1, sizeof(*l));

	assert_non_null(l);
	l->panel_w = pw;
	l->panel_h = ph;
	l->rotate = rot;
	l->fill = fill;
	l->src_w = sw;
	l->src_h = sh;
	return l;
}

static void check_rect(int pw, int ph, int rot, int fill, int sw, int sh, int k, int x, int y,
		       int w, int h)
{
	struct px_layout *l = layout(pw, ph, rot, fill, sw, sh);

	assert_int_equal(px_layout_init(l), 0);
	assert_int_equal(l->scale, k);
	assert_int_equal(l->dst_x, x);
	assert_int_equal(l->dst_y, y);
	assert_int_equal(l->dst_w, w);
	assert_int_equal(l->dst_h, h);
	free(l);
}

static void layout_integer_scale_and_centring(void **state)
{
	(void)state;
	/* 1280/320 = 4, 720/240 = 3 -> 3: 960x720 at ((1280-960)/2, 0) */
	check_rect(1280, 720, 0, 0, 320, 240, 3, 160, 0, 960, 720);
	/* 1920/320 = 6, 1080/240 = 4 -> 4: 1280x960 at (320, 60) */
	check_rect(1920, 1080, 0, 0, 320, 240, 4, 320, 60, 1280, 960);
	/* 1024/320 = 3, 600/240 = 2 -> 2: 640x480 at (192, 60) */
	check_rect(1024, 600, 0, 0, 320, 240, 2, 192, 60, 640, 480);
	check_rect(320, 240, 0, 0, 320, 240, 1, 0, 0, 320, 240);
	/* odd spare pixel goes right/bottom: 4x3 in 9x7 -> k 2, 8x6 at (0, 0) */
	check_rect(9, 7, 0, 0, 4, 3, 2, 0, 0, 8, 6);
	/* 180 keeps the frame's orientation for sizing */
	check_rect(1280, 720, 180, 0, 320, 240, 3, 160, 0, 960, 720);
}

static void layout_rotation_swaps_panel_for_fitting(void **state)
{
	(void)state;
	/* portrait cabinet 768x1366, frame 320x240 turned: 240 wide, 320 high;
	 * 768/240 = 3, 1366/320 = 4 -> 3: 720x960 at (24, 203) */
	check_rect(768, 1366, 90, 0, 320, 240, 3, 24, 203, 720, 960);
	check_rect(768, 1366, 270, 0, 320, 240, 3, 24, 203, 720, 960);
	/* landscape panel, rotated frame: 1920/240 = 8, 1080/320 = 3 -> 3:
	 * 720x960 at (600, 60) */
	check_rect(1920, 1080, 90, 0, 320, 240, 3, 600, 60, 720, 960);
}

static void layout_fill_covers_panel(void **state)
{
	(void)state;
	check_rect(1280, 720, 0, 1, 320, 240, 0, 0, 0, 1280, 720);
	check_rect(768, 1366, 90, 1, 320, 240, 0, 0, 0, 768, 1366);
}

static void layout_larger_frame_downscales_keeping_aspect(void **state)
{
	(void)state;
	/* 320x240 on 160x100: height-limited, 100 high, 320*100/240 = 133 wide */
	check_rect(160, 100, 0, 0, 320, 240, 0, 13, 0, 133, 100);
	/* 320x240 on 200x400: width-limited, 200 wide, 240*200/320 = 150 high */
	check_rect(200, 400, 0, 0, 320, 240, 0, 0, 125, 200, 150);
	/* fits in width only (300x1000 frame, 320x240 panel): 72x240 */
	check_rect(320, 240, 0, 0, 300, 1000, 0, 124, 0, 72, 240);
}

static void layout_bad_input_is_einval(void **state)
{
	struct px_layout *l = layout(640, 480, 45, 0, 320, 240);
	(void)state;
	assert_int_equal(px_layout_init(l), -EINVAL);
	l->rotate = 0;
	l->src_w = 0;
	assert_int_equal(px_layout_init(l), -EINVAL);
	l->src_w = 320;
	l->panel_w = PX_MAX_DIM + 1;
	assert_int_equal(px_layout_init(l), -EINVAL);
	l->panel_w = 640;
	l->src_pitch = 319;
	assert_int_equal(px_layout_init(l), -EINVAL);
	l->src_pitch = 400;
	assert_int_equal(px_layout_init(l), 0);
	free(l);
}

/* ---- blit --------------------------------------------------------------- */

#define SW 4
#define SH 3
#define SPITCH 7   /* frame rows padded; the pad holds index 200 */

/* Frame 4x3, every pixel its own index 1..12; pad bytes index 200. */
static void make_frame(uint8_t *src)
{
	int x, y;

	memset(src, 200, SPITCH * SH);
	for (y = 0; y < SH; y++)
		for (x = 0; x < SW; x++)
			src[y * SPITCH + x] = (uint8_t)(1 + y * SW + x);
}

/* A table with a distinct non-zero value per index in every byte width. */
static void make_table(struct px_table *t, int bytes)
{
	int i;

	t->bytes = bytes;
	for (i = 0; i < 256; i++)
		t->v[i] = 0x00C0B000u | (uint32_t)i;
	t->v[200] = 0x00DEAD00u;   /* must never appear */
}

static uint32_t read_px(const uint8_t *p, int bytes)
{
	uint32_t v = 0;
	uint16_t h;

	if (bytes == 4)
		memcpy(&v, p, 4);
	else if (bytes == 2) {
		memcpy(&h, p, 2);
		v = h;
	} else {
		v = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16;
	}
	return v;
}

/* Rotated-frame position of source pixel (sx, sy). */
static void rot_pos(int rot, int sx, int sy, int *rx, int *ry)
{
	switch (rot) {
	case 0: *rx = sx; *ry = sy; break;
	case 90: *rx = SH - 1 - sy; *ry = sx; break;
	case 180: *rx = SW - 1 - sx; *ry = SH - 1 - sy; break;
	default: *rx = sy; *ry = SW - 1 - sx; break;
	}
}

/* Blits the 4x3 frame into a pw x ph panel of the given bytes per pixel
 * and rotation with line_length pw*bytes + PAD, and checks: the integer
 * factor k and origin (x0, y0) given by hand; every pixel against the
 * expected image built from the rotation formulas (0 outside); padding and
 * the line after the panel still SENTINEL. */
static void check_blit(int bytes, int rot, int pw, int ph, int k, int x0, int y0)
{
	size_t ll = (size_t)pw * (size_t)bytes + PAD;
	struct px_layout *l = layout(pw, ph, rot, 0, SW, SH);
	uint32_t *want = calloc((size_t)pw * (size_t)ph, sizeof(*want));
	uint8_t *dst = malloc(ll * (size_t)(ph + 1));
	uint8_t src[SPITCH * SH];
	struct px_table t;
	uint32_t mask = bytes == 4 ? 0xFFFFFFFFu : bytes == 3 ? 0xFFFFFFu : 0xFFFFu;
	int sx, sy, i, j, x, y;
	size_t b;

	assert_non_null(want);
	assert_non_null(dst);
	make_frame(src);
	make_table(&t, bytes);
	l->src_pitch = SPITCH;
	assert_int_equal(px_layout_init(l), 0);
	assert_int_equal(l->scale, k);
	assert_int_equal(l->dst_x, x0);
	assert_int_equal(l->dst_y, y0);

	for (sy = 0; sy < SH; sy++) {
		for (sx = 0; sx < SW; sx++) {
			int rx, ry;

			rot_pos(rot, sx, sy, &rx, &ry);
			for (j = 0; j < k; j++)
				for (i = 0; i < k; i++)
					want[(size_t)(y0 + k * ry + j) * pw + x0 + k * rx + i] =
						t.v[1 + sy * SW + sx] & mask;
		}
	}

	memset(dst, SENTINEL, ll * (size_t)(ph + 1));
	px_blit(l, &t, src, dst, ll);
	for (y = 0; y < ph; y++) {
		for (x = 0; x < pw; x++) {
			uint32_t got = read_px(dst + (size_t)y * ll + (size_t)x * bytes, bytes);

			if (got != want[(size_t)y * pw + x])
				fail_msg("bpp %d rot %d panel %dx%d: pixel (%d,%d) is %#x, want %#x",
					 bytes * 8, rot, pw, ph, x, y, got, want[(size_t)y * pw + x]);
		}
		for (b = (size_t)pw * bytes; b < ll; b++)
			if (dst[(size_t)y * ll + b] != SENTINEL)
				fail_msg("bpp %d rot %d: padding byte %zu of line %d written",
					 bytes * 8, rot, b, y);
	}
	for (b = 0; b < ll; b++)
		assert_int_equal(dst[(size_t)ph * ll + b], SENTINEL);
	free(dst);
	free(want);
	free(l);
}

/* 11x11 panel, k 2: unrotated 8x6 at (1, 2), quarter-turned 6x8 at
 * (2, 1): a bar on every side. */
static void blit_rotations(int bytes)
{
	check_blit(bytes, 0, 11, 11, 2, 1, 2);
	check_blit(bytes, 90, 11, 11, 2, 2, 1);
	check_blit(bytes, 180, 11, 11, 2, 1, 2);
	check_blit(bytes, 270, 11, 11, 2, 2, 1);
}

static void blit_16bpp_padded_all_rotations(void **state)
{
	(void)state;
	blit_rotations(2);
}

static void blit_24bpp_padded_all_rotations(void **state)
{
	(void)state;
	blit_rotations(3);
}

static void blit_32bpp_padded_all_rotations(void **state)
{
	(void)state;
	blit_rotations(4);
}

static void blit_scale_1_and_3(void **state)
{
	int bytes;
	(void)state;
	for (bytes = 2; bytes <= 4; bytes++) {
		/* exact fit, no bars */
		check_blit(bytes, 0, 4, 3, 1, 0, 0);
		check_blit(bytes, 90, 3, 4, 1, 0, 0);
		/* 14/4 = 3, 13/3 = 4 -> 3: 12x9 at (1, 2) */
		check_blit(bytes, 0, 14, 13, 3, 1, 2);
		check_blit(bytes, 180, 14, 13, 3, 1, 2);
		/* turned 3x4: 14/3 = 4, 13/4 = 3 -> 3: 9x12 at (2, 0) */
		check_blit(bytes, 270, 14, 13, 3, 2, 0);
	}
}

/* The scale-1 32-bit rows (streaming stores where SSE2 is there): rows of
 * every width 1..40 written at every byte offset 0..15 from a 16-byte
 * boundary (the store loop starts only on one, and a pitch that is not a
 * multiple of 4 never reaches one) show each frame pixel's table value,
 * and the bytes before and after the row are untouched. */
static void blit_scale_1_rows_any_alignment(void **state)
{
	enum { MAXW = 40, GUARD = 32 };
	uint8_t src[MAXW];
	_Alignas(16) uint8_t buf[GUARD + MAXW * 4 + GUARD];
	struct px_table t;
	(void)state;

	make_table(&t, 4);
	for (int i = 0; i < MAXW; i++)
		src[i] = (uint8_t)(17 + 5 * i);
	for (int w = 1; w <= MAXW; w++) {
		for (int off = 0; off < 16; off++) {
			struct px_layout *l = layout(w, 1, 0, 0, w, 1);
			uint8_t *d = buf + GUARD + off;

			assert_int_equal(px_layout_init(l), 0);
			assert_int_equal(l->scale, 1);
			memset(buf, SENTINEL, sizeof(buf));
			px_blit(l, &t, src, d, (size_t)w * 4);
			for (int x = 0; x < w; x++) {
				uint32_t got = read_px(d + 4 * x, 4);

				if (got != t.v[src[x]])
					fail_msg("width %d offset %d: pixel %d is %#x, want %#x", w,
						 off, x, got, t.v[src[x]]);
			}
			for (size_t b = 0; b < sizeof(buf); b++)
				if ((b < GUARD + (size_t)off || b >= GUARD + (size_t)off + 4 * (size_t)w) &&
				    buf[b] != SENTINEL)
					fail_msg("width %d offset %d: byte %zu outside the row written",
						 w, off, b);
			free(l);
		}
	}
}

/* Fill: each corner of the panel shows the frame corner the rotation puts
 * there, and nothing is black. */
static void blit_fill_maps_corners_to_corners(void **state)
{
	static const int rots[] = { 0, 90, 180, 270 };
	uint8_t src[SPITCH * SH];
	struct px_table t;
	int r;
	(void)state;
	make_frame(src);
	make_table(&t, 4);
	for (r = 0; r < 4; r++) {
		int rot = rots[r], quarter = rot == 90 || rot == 270;
		int pw = quarter ? 7 : 10, ph = quarter ? 10 : 7;
		size_t ll = (size_t)pw * 4 + PAD;
		struct px_layout *l = layout(pw, ph, rot, 1, SW, SH);
		uint8_t *dst = malloc(ll * (size_t)ph);
		/* source corners TL, TR, BL, BR and their panel corners */
		static const int sc[4][2] = { { 0, 0 }, { SW - 1, 0 }, { 0, SH - 1 },
					      { SW - 1, SH - 1 } };
		int c, x, y;

		assert_non_null(dst);
		l->src_pitch = SPITCH;
		assert_int_equal(px_layout_init(l), 0);
		memset(dst, SENTINEL, ll * (size_t)ph);
		px_blit(l, &t, src, dst, ll);
		for (c = 0; c < 4; c++) {
			int rx, ry, px, py;

			rot_pos(rot, sc[c][0], sc[c][1], &rx, &ry);
			/* rotated frame is (quarter ? 3x4 : 4x3); its corner
			 * (rx, ry) is on the panel's corner */
			px = rx == 0 ? 0 : pw - 1;
			py = ry == 0 ? 0 : ph - 1;
			assert_int_equal(read_px(dst + (size_t)py * ll + (size_t)px * 4, 4),
					 t.v[1 + sc[c][1] * SW + sc[c][0]]);
		}
		for (y = 0; y < ph; y++)
			for (x = 0; x < pw; x++) {
				uint32_t v = read_px(dst + (size_t)y * ll + (size_t)x * 4, 4);

				assert_true(v >= t.v[1] && v <= t.v[12]);
			}
		free(dst);
		free(l);
	}
}

/* A larger-than-panel frame is shown whole: corners land on the rectangle's
 * corners, bars stay black. */
static void blit_downscale_shows_whole_frame(void **state)
{
	uint8_t src[SPITCH * SH];
	struct px_layout *l = layout(3, 3, 0, 0, SW, SH);
	size_t ll = 3 * 4 + PAD;
	uint8_t dst[(3 * 4 + PAD) * 3];
	struct px_table t;
	int x;
	(void)state;
	make_frame(src);
	make_table(&t, 4);
	l->src_pitch = SPITCH;
	/* 4x3 in 3x3: width-limited, 3 wide, 3*3/4 = 2 high, at (0, 0) */
	assert_int_equal(px_layout_init(l), 0);
	assert_int_equal(l->dst_w, 3);
	assert_int_equal(l->dst_h, 2);
	assert_int_equal(l->dst_y, 0);
	px_blit(l, &t, src, dst, ll);
	assert_int_equal(read_px(dst, 4), t.v[1]);                 /* frame (0,0) */
	assert_int_equal(read_px(dst + 2 * 4, 4), t.v[4]);         /* frame (3,0) */
	assert_int_equal(read_px(dst + ll, 4), t.v[9]);            /* frame (0,2) */
	assert_int_equal(read_px(dst + ll + 2 * 4, 4), t.v[12]);   /* frame (3,2) */
	for (x = 0; x < 3; x++)
		assert_int_equal(read_px(dst + 2 * ll + (size_t)x * 4, 4), 0);
	free(l);
}

static void panel_draw_follows_frame_size_and_refuses_bad(void **state)
{
	struct px_panel *p = malloc(sizeof(*p));
	struct px_format f;
	uint8_t pal[256][3];
	uint8_t src[8 * 6];
	uint8_t mem[16 * 12 * 4];
	size_t i;
	(void)state;
	assert_non_null(p);
	memset(pal, 0, sizeof(pal));
	pal[7][0] = 255;
	memset(src, 7, sizeof(src));
	assert_int_equal(px_format_by_name("xrgb8888", &f), 0);
	assert_int_equal(px_panel_init(p, &f, 16, 12, 16 * 4, 0, 0, 4, 3), 0);
	assert_int_equal(p->layout.scale, 4);
	px_panel_palette(p, pal);
	/* an 8x6 frame instead: k 2, whole panel red */
	assert_int_equal(px_panel_draw(p, mem, src, 8, 6, 8), 0);
	assert_int_equal(p->layout.scale, 2);
	for (i = 0; i < 16 * 12; i++)
		assert_int_equal(read_px(mem + 4 * i, 4), 0x00FF0000);
	/* refused: nothing written, layout kept */
	memset(mem, SENTINEL, sizeof(mem));
	assert_int_equal(px_panel_draw(p, mem, src, 8, 6, 7), -EINVAL);
	assert_int_equal(px_panel_draw(p, mem, src, 0, 6, 8), -EINVAL);
	assert_int_equal(p->layout.src_w, 8);
	for (i = 0; i < sizeof(mem); i++)
		assert_int_equal(mem[i], SENTINEL);
	/* line length shorter than the panel's pixels */
	assert_int_equal(px_panel_init(p, &f, 16, 12, 16 * 4 - 1, 0, 0, 4, 3), -EINVAL);
	free(p);
}

/* A stand-in pool: runs the jobs one after the other, last first, so a
 * range that read a line of another range would see it unwritten. */
static int fake_jobs;

static void fake_run(void *pool, int n, void (*job)(void *arg, int i), void *arg)
{
	(void)pool;
	fake_jobs = n;
	for (int i = n - 1; i >= 0; i--)
		job(arg, i);
}

/* Row ranges in any order, and a parallel panel draw, write exactly what
 * one pass writes: every rotation, integer and fill, letterbox rows above
 * and below, repeated source lines, and line padding left alone. */
static void row_ranges_write_what_one_pass_writes(void **state)
{
	struct px_layout *l = malloc(sizeof(*l));
	struct px_panel *p = malloc(sizeof(*p));
	struct px_table t;
	struct px_format f;
	struct px_par par = { fake_run, NULL, 2 };
	uint8_t src[SPITCH * SH];
	enum { PW = 23, PH = 70, LL = PW * 4 + 8 };
	static uint8_t a[PH * LL], b[PH * LL];
	static const int cuts[][2] = { { 0, 5 }, { 5, 6 }, { 6, 40 }, { 40, 70 } };
	(void)state;

	assert_non_null(l);
	assert_non_null(p);
	make_frame(src);
	make_table(&t, 4);
	for (int rot = 0; rot < 360; rot += 90)
		for (int fill = 0; fill < 2; fill++) {
			memset(l, 0, sizeof(*l));
			l->panel_w = PW;
			l->panel_h = PH;
			l->rotate = rot;
			l->fill = fill;
			l->src_w = SW;
			l->src_h = SH;
			l->src_pitch = SPITCH;
			assert_int_equal(px_layout_init(l), 0);
			memset(a, SENTINEL, sizeof(a));
			memset(b, SENTINEL, sizeof(b));
			px_blit(l, &t, src, a, LL);
			for (int k = 3; k >= 0; k--)
				px_blit_rows(l, &t, src, b, LL, cuts[k][0], cuts[k][1]);
			assert_memory_equal(a, b, sizeof(a));
		}
	/* the panel through a pool: 2 threads, PX_JOBS_PER_THREAD ranges each */
	assert_int_equal(px_format_by_name("xrgb8888", &f), 0);
	assert_int_equal(px_panel_init(p, &f, PW, PH, LL, 90, 0, SW, SH), 0);
	p->table = t;
	memset(a, SENTINEL, sizeof(a));
	memset(b, SENTINEL, sizeof(b));
	assert_int_equal(px_panel_draw(p, a, src, SW, SH, SPITCH), 0);
	px_panel_set_par(p, &par);
	fake_jobs = 0;
	assert_int_equal(px_panel_draw(p, b, src, SW, SH, SPITCH), 0);
	assert_int_equal(fake_jobs, 2 * PX_JOBS_PER_THREAD);
	assert_memory_equal(a, b, sizeof(a));
	/* one thread is no pool */
	par.threads = 1;
	px_panel_set_par(p, &par);
	fake_jobs = 0;
	assert_int_equal(px_panel_draw(p, b, src, SW, SH, SPITCH), 0);
	assert_int_equal(fake_jobs, 0);
	/* a tall panel: ranges of PX_ROWS_PER_JOB rows, more than
	 * PX_JOBS_PER_THREAD a thread, still the one pass's bytes */
	{
		enum { TW = 8, TH = 10 * PX_ROWS_PER_JOB + 5, TLL = TW * 4 };
		static uint8_t ta[TH * TLL], tb[TH * TLL];

		assert_int_equal(px_panel_init(p, &f, TW, TH, TLL, 0, 1, SW, SH), 0);
		p->table = t;
		memset(ta, SENTINEL, sizeof(ta));
		memset(tb, SENTINEL, sizeof(tb));
		assert_int_equal(px_panel_draw(p, ta, src, SW, SH, SPITCH), 0);
		par.threads = 2;
		px_panel_set_par(p, &par);
		fake_jobs = 0;
		assert_int_equal(px_panel_draw(p, tb, src, SW, SH, SPITCH), 0);
		assert_int_equal(fake_jobs, 10);
		assert_memory_equal(ta, tb, sizeof(ta));
	}
	free(l);
	free(p);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(table_rgb565_pure_and_grey),
		cmocka_unit_test(table_bgr565_pure_and_grey),
		cmocka_unit_test(table_xrgb8888_pure_and_grey),
		cmocka_unit_test(table_xbgr8888_pure_and_grey),
		cmocka_unit_test(table_rgb888_pure_and_grey),
		cmocka_unit_test(table_custom_format_rgb555),
		cmocka_unit_test(format_unknown_name_is_einval),
		cmocka_unit_test(format_check_rejects_bad_fields),
		cmocka_unit_test(layout_integer_scale_and_centring),
		cmocka_unit_test(layout_rotation_swaps_panel_for_fitting),
		cmocka_unit_test(layout_fill_covers_panel),
		cmocka_unit_test(layout_larger_frame_downscales_keeping_aspect),
		cmocka_unit_test(layout_bad_input_is_einval),
		cmocka_unit_test(blit_16bpp_padded_all_rotations),
		cmocka_unit_test(blit_24bpp_padded_all_rotations),
		cmocka_unit_test(blit_32bpp_padded_all_rotations),
		cmocka_unit_test(blit_scale_1_and_3),
		cmocka_unit_test(blit_scale_1_rows_any_alignment),
		cmocka_unit_test(blit_fill_maps_corners_to_corners),
		cmocka_unit_test(blit_downscale_shows_whole_frame),
		cmocka_unit_test(panel_draw_follows_frame_size_and_refuses_bad),
		cmocka_unit_test(row_ranges_write_what_one_pass_writes),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
