/*
 * wad_fixture: tiny WAD images made in memory for the tests of wad, tex and
 * map_wad (and written to tests/data/wad/ and the fuzz seed corpus by
 * tests/data/wad/mkfixtures.c). Every value is chosen by hand so the tests
 * can state the expected pixels and fields independently.
 *
 * Functions are static inline so a test that uses a few draws no warning.
 */
#ifndef ARCADED_TESTS_WAD_FIXTURE_H
#define ARCADED_TESTS_WAD_FIXTURE_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* A growing byte buffer; allocation failure aborts (test code). */
struct wbuf {
	uint8_t *d;
	size_t n, cap;
};

static inline void wb_bytes(struct wbuf *b, const void *p, size_t n)
{
	if (b->n + n > b->cap) {
		b->cap = (b->n + n) * 2 + 64;
		b->d = realloc(b->d, b->cap);
		if (!b->d)
			abort();
	}
	if (n)
		memcpy(b->d + b->n, p, n);
	b->n += n;
}

static inline void wb_u8(struct wbuf *b, int v)
{
	uint8_t c = (uint8_t)v;
	wb_bytes(b, &c, 1);
}

static inline void wb_16(struct wbuf *b, int v)
{
	wb_u8(b, v & 255);
	wb_u8(b, (v >> 8) & 255);
}

static inline void wb_32(struct wbuf *b, int64_t v)
{
	wb_16(b, (int)(v & 0xffff));
	wb_16(b, (int)((v >> 16) & 0xffff));
}

/* An 8-byte name field, NUL-padded. */
static inline void wb_name(struct wbuf *b, const char *s)
{
	char n[8] = { 0 };
	for (int i = 0; i < 8 && s[i]; i++)
		n[i] = s[i];
	wb_bytes(b, n, 8);
}

static inline void wb_put32(struct wbuf *b, size_t at, int64_t v)
{
	for (int i = 0; i < 4; i++)
		b->d[at + (size_t)i] = (uint8_t)((uint64_t)v >> (8 * i));
}

/* A WAD being built: lumps appended to data, directory kept aside. */
struct wfix {
	struct wbuf data;
	struct wbuf dir;
	int n;
};

static inline void wf_init(struct wfix *f)
{
	memset(f, 0, sizeof *f);
	wb_bytes(&f->data, "PWAD\0\0\0\0\0\0\0\0", 12);
}

static inline void wf_lump(struct wfix *f, const char *name, const void *p, size_t len)
{
	wb_32(&f->dir, (int64_t)f->data.n);
	wb_32(&f->dir, (int64_t)len);
	wb_name(&f->dir, name);
	wb_bytes(&f->data, p, len);
	f->n++;
}

static inline void wf_lumpb(struct wfix *f, const char *name, struct wbuf *b)
{
	wf_lump(f, name, b->d, b->n);
	free(b->d);
	memset(b, 0, sizeof *b);
}

/* Appends the directory and fills the header; returns the image (the
 * caller frees it) and its size. */
static inline uint8_t *wf_finish(struct wfix *f, const char *magic, size_t *len)
{
	size_t dir = f->data.n;

	wb_bytes(&f->data, f->dir.d, f->dir.n);
	memcpy(f->data.d, magic, 4);
	wb_put32(&f->data, 4, f->n);
	wb_put32(&f->data, 8, (int64_t)dir);
	free(f->dir.d);
	*len = f->data.n;
	return f->data.d;
}

/* ---- the graphics fixture ------------------------------------------------
 * PLAYPAL: 2 palettes; palette 0 colour i = (i, 255 - i, 7 * i mod 256),
 *   palette 1 all zeros (must not be read).
 * COLORMAP: 34 maps; map l, entry i = (i + l) mod 256.
 * Patches (Doom pictures):
 *   PAT1 4x4 solid, pixel (x, y) = 16 + 4x + y, one post per column.
 *   PAT2 3x6, column x: rows 0-1 = 100 + 10x + y, rows 2-3 a hole,
 *     rows 4-5 = 100 + 10x + y (two posts).
 *   PAT3 1x300 tall patch: row 0 = 1, row 254 = 2, row 264 = 3 (its third
 *     post has topdelta 10 <= 254, so it continues at 254 + 10).
 * PNAMES: PAT1, PAT2, PAT3, NOSUCH (no lump).
 * TEXTURE1:
 *   TWO 8x8: PAT1 at (0,0), PAT2 at (6,4): PAT2's column 2 falls past the
 *     right edge and its rows 4-5 past the bottom; masked (holes).
 *   SOLID 4x4: PAT1 at (0,0): fully opaque.
 *   NEG 4x4: PAT1 at (-2,-1): pixel (0,0) = PAT1 (2,1).
 *   TALL 1x300: PAT3.
 *   MISSP 8x8: patch index 9 (PNAMES has 4): fallback.
 *   NOLUMP 16x8: patch NOSUCH: fallback.
 *   NUKAGE? no: textures BFALL1..BFALL2 (4x4 PAT1) form no animation
 *   (Doom's is BFALL1..BFALL4): only whole ranges animate.
 * Flats: F_START, FLOOR1 (pixel (x, y) = (3x + 5y) mod 256), NUKAGE1..3
 *   (all 1, 2, 3), a 100-byte lump "SHORT" (skipped), F_SKY1 (all 7), F_END.
 * Sprites: S_START, TROOA1, TROOA2A8, TROOA3A7, TROOA4A6, TROOA5, TROOB0,
 *   TROOD1 (frame C missing), S_END; each 2x3, every pixel = its index in
 *   that list + 200, left offset 1 + index, top offset 10 + index.
 */
static inline void wfx_patch_solid(struct wbuf *b, int w, int h, int base)
{
	wb_16(b, w);
	wb_16(b, h);
	wb_16(b, 0);
	wb_16(b, 0);
	for (int x = 0; x < w; x++)
		wb_32(b, 8 + 4 * w + x * (h + 5));
	for (int x = 0; x < w; x++) {
		wb_u8(b, 0);
		wb_u8(b, h);
		wb_u8(b, 0);
		for (int y = 0; y < h; y++)
			wb_u8(b, base + 4 * x + y);
		wb_u8(b, 0);
		wb_u8(b, 0xFF);
	}
}

static inline void wfx_pat2(struct wbuf *b)
{
	wb_16(b, 3);
	wb_16(b, 6);
	wb_16(b, 0);
	wb_16(b, 0);
	for (int x = 0; x < 3; x++)
		wb_32(b, 8 + 12 + x * 13);
	for (int x = 0; x < 3; x++) {
		for (int post = 0; post < 2; post++) {
			int top = post * 4;
			wb_u8(b, top);
			wb_u8(b, 2);
			wb_u8(b, 0);
			wb_u8(b, 100 + 10 * x + top);
			wb_u8(b, 100 + 10 * x + top + 1);
			wb_u8(b, 0);
		}
		wb_u8(b, 0xFF);
	}
}

static inline void wfx_pat3(struct wbuf *b)
{
	wb_16(b, 1);
	wb_16(b, 300);
	wb_16(b, 0);
	wb_16(b, 0);
	wb_32(b, 12);
	const int posts[3][2] = { { 0, 1 }, { 254, 2 }, { 10, 3 } };
	for (int i = 0; i < 3; i++) {
		wb_u8(b, posts[i][0]);
		wb_u8(b, 1);
		wb_u8(b, 0);
		wb_u8(b, posts[i][1]);
		wb_u8(b, 0);
	}
	wb_u8(b, 0xFF);
}

/* A TEXTURE1 entry with n patches {x, y, index}. */
static inline void wfx_texdef(struct wbuf *b, const char *name, int w, int h, int n,
			      const int (*p)[3])
{
	wb_name(b, name);
	wb_32(b, 0);
	wb_16(b, w);
	wb_16(b, h);
	wb_32(b, 0);
	wb_16(b, n);
	for (int i = 0; i < n; i++) {
		wb_16(b, p[i][0]);
		wb_16(b, p[i][1]);
		wb_16(b, p[i][2]);
		wb_16(b, 1);
		wb_16(b, 0);
	}
}

static inline void wfx_texture1(struct wbuf *b)
{
	static const int two[2][3] = { { 0, 0, 0 }, { 6, 4, 1 } };
	static const int solid[1][3] = { { 0, 0, 0 } };
	static const int neg[1][3] = { { -2, -1, 0 } };
	static const int tall[1][3] = { { 0, 0, 2 } };
	static const int missp[1][3] = { { 0, 0, 9 } };
	static const int nolump[1][3] = { { 0, 0, 3 } };
	struct wbuf defs = { 0 };
	size_t ofs[8];
	int n = 0;

	ofs[n++] = defs.n;
	wfx_texdef(&defs, "TWO", 8, 8, 2, two);
	ofs[n++] = defs.n;
	wfx_texdef(&defs, "SOLID", 4, 4, 1, solid);
	ofs[n++] = defs.n;
	wfx_texdef(&defs, "NEG", 4, 4, 1, neg);
	ofs[n++] = defs.n;
	wfx_texdef(&defs, "TALL", 1, 300, 1, tall);
	ofs[n++] = defs.n;
	wfx_texdef(&defs, "MISSP", 8, 8, 1, missp);
	ofs[n++] = defs.n;
	wfx_texdef(&defs, "NOLUMP", 16, 8, 1, nolump);
	ofs[n++] = defs.n;
	wfx_texdef(&defs, "BFALL1", 4, 4, 1, solid);
	ofs[n++] = defs.n;
	wfx_texdef(&defs, "BFALL2", 4, 4, 1, solid);
	wb_32(b, n);
	for (int i = 0; i < n; i++)
		wb_32(b, 4 + 4 * n + (int64_t)ofs[i]);
	wb_bytes(b, defs.d, defs.n);
	free(defs.d);
}

static const char *const wfx_sprite_names[] = {
	"TROOA1", "TROOA2A8", "TROOA3A7", "TROOA4A6", "TROOA5", "TROOB0", "TROOD1",
};
#define WFX_NSPRITES 7

static inline void wfx_sprite(struct wbuf *b, int i)
{
	wb_16(b, 2);
	wb_16(b, 3);
	wb_16(b, 1 + i);
	wb_16(b, 10 + i);
	wb_32(b, 16);
	wb_32(b, 16 + 8);
	for (int x = 0; x < 2; x++) {
		wb_u8(b, 0);
		wb_u8(b, 3);
		wb_u8(b, 0);
		for (int y = 0; y < 3; y++)
			wb_u8(b, 200 + i);
		wb_u8(b, 0);
		wb_u8(b, 0xFF);
	}
}

/* The graphics lumps into f; with_colormap 0 leaves COLORMAP out. */
static inline void wfx_graphics(struct wfix *f, int with_colormap)
{
	struct wbuf b = { 0 };
	uint8_t flat[4096];

	for (int p = 0; p < 2; p++)
		for (int i = 0; i < 256; i++) {
			wb_u8(&b, p ? 0 : i);
			wb_u8(&b, p ? 0 : 255 - i);
			wb_u8(&b, p ? 0 : (7 * i) & 255);
		}
	wf_lumpb(f, "PLAYPAL", &b);
	if (with_colormap) {
		for (int l = 0; l < 34; l++)
			for (int i = 0; i < 256; i++)
				wb_u8(&b, (i + l) & 255);
		wf_lumpb(f, "COLORMAP", &b);
	}
	wb_32(&b, 4);
	wb_name(&b, "PAT1");
	wb_name(&b, "pat2");
	wb_name(&b, "PAT3");
	wb_name(&b, "NOSUCH");
	wf_lumpb(f, "PNAMES", &b);
	wfx_texture1(&b);
	wf_lumpb(f, "TEXTURE1", &b);
	wfx_patch_solid(&b, 4, 4, 16);
	wf_lumpb(f, "PAT1", &b);
	wfx_pat2(&b);
	wf_lumpb(f, "PAT2", &b);
	wfx_pat3(&b);
	wf_lumpb(f, "PAT3", &b);
	wf_lump(f, "F_START", NULL, 0);
	for (int y = 0; y < 64; y++)
		for (int x = 0; x < 64; x++)
			flat[y * 64 + x] = (uint8_t)((3 * x + 5 * y) & 255);
	wf_lump(f, "FLOOR1", flat, sizeof flat);
	for (int k = 1; k <= 3; k++) {
		char name[9] = "NUKAGE0";
		name[6] = (char)('0' + k);
		memset(flat, k, sizeof flat);
		wf_lump(f, name, flat, sizeof flat);
	}
	wf_lump(f, "SHORT", flat, 100);
	memset(flat, 7, sizeof flat);
	wf_lump(f, "F_SKY1", flat, sizeof flat);
	wf_lump(f, "F_END", NULL, 0);
	wf_lump(f, "S_START", NULL, 0);
	for (int i = 0; i < WFX_NSPRITES; i++) {
		wfx_sprite(&b, i);
		wf_lumpb(f, wfx_sprite_names[i], &b);
	}
	wf_lump(f, "S_END", NULL, 0);
}

/* ---- the map fixture -----------------------------------------------------
 * Two rooms side by side, A x 0..128 and B x 128..256, y 0..128, a portal at
 * x = 128. Vertices 0 (0,0) 1 (0,128) 2 (128,128) 3 (128,0) 4 (256,128)
 * 5 (256,0). Lines (front on the right of v1 -> v2):
 *   0: 0-1 A   1: 1-2 A   2: 2-3 A|B (sides 2 and 3)   3: 3-0 A
 *   4: 2-4 B   5: 4-5 B   6: 5-3 B
 * Sidedefs 0 L0, 1 L1, 2 L2 front, 3 L2 back, 4 L3, 5 L4, 6 L5, 7 L6; side
 * 0 has x offset 8, y offset -4 and middle texture TWO; side 2 upper SOLID,
 * lower "-" ; side 3 upper "NOTEX" (unknown), middle TWO.
 * Sectors: A floor 0 ceil 128, FLOOR1 / F_SKY1, light 160; B floor 16
 * ceil 112, NUKAGE1 / NOFLAT (unknown), light 300 (clamped to 255),
 * special 9, tag 7.
 * BSP: segs 0-3 for A (L0, L1, L2 front, L3), 4-7 for B (L2 back as 3->2,
 * L4, L5, L6); subsectors (4 segs from 0) and (4 from 4); one node x 128,
 * y 0, dx 0, dy 128: its right (east) child subsector 1, left subsector 0.
 * Things: player 1 at (64, 64) angle 90; type 3004 at (192, 64) angle 225.
 */
static const int wfx_verts[6][2] = {
	{ 0, 0 }, { 0, 128 }, { 128, 128 }, { 128, 0 }, { 256, 128 }, { 256, 0 },
};

static inline void wfx_map_lumps(struct wbuf *l /* [8] */)
{
	static const int lines[7][4] = {
		/* v1, v2, front side, back side */
		{ 0, 1, 0, -1 }, { 1, 2, 1, -1 }, { 2, 3, 2, 3 }, { 3, 0, 4, -1 },
		{ 2, 4, 5, -1 }, { 4, 5, 6, -1 }, { 5, 3, 7, -1 },
	};
	static const int side_sector[8] = { 0, 0, 0, 1, 0, 1, 1, 1 };
	static const int segs[8][5] = {
		/* v1, v2, angle, line, dir */
		{ 0, 1, 0x4000, 0, 0 }, { 1, 2, 0, 1, 0 }, { 2, 3, 0xC000, 2, 0 },
		{ 3, 0, 0x8000, 3, 0 }, { 3, 2, 0x4000, 2, 1 }, { 2, 4, 0, 4, 0 },
		{ 4, 5, 0xC000, 5, 0 }, { 5, 3, 0x8000, 6, 0 },
	};
	/* THINGS */
	wb_16(&l[0], 64); wb_16(&l[0], 64); wb_16(&l[0], 90); wb_16(&l[0], 1); wb_16(&l[0], 7);
	wb_16(&l[0], 192); wb_16(&l[0], 64); wb_16(&l[0], 225); wb_16(&l[0], 3004); wb_16(&l[0], 7);
	/* LINEDEFS */
	for (int i = 0; i < 7; i++) {
		wb_16(&l[1], lines[i][0]);
		wb_16(&l[1], lines[i][1]);
		wb_16(&l[1], lines[i][3] < 0 ? 1 : 4);
		wb_16(&l[1], i == 2 ? 1 : 0);
		wb_16(&l[1], i == 2 ? 7 : 0);
		wb_16(&l[1], lines[i][2]);
		wb_16(&l[1], lines[i][3] < 0 ? 0xFFFF : lines[i][3]);
	}
	/* SIDEDEFS */
	for (int i = 0; i < 8; i++) {
		wb_16(&l[2], i == 0 ? 8 : 0);
		wb_16(&l[2], i == 0 ? -4 : 0);
		wb_name(&l[2], i == 2 ? "SOLID" : i == 3 ? "NOTEX" : "-");
		wb_name(&l[2], "-");
		wb_name(&l[2], i == 0 || i == 3 ? "two" : i == 2 ? "-" : "SOLID");
		wb_16(&l[2], side_sector[i]);
	}
	/* VERTEXES */
	for (int i = 0; i < 6; i++) {
		wb_16(&l[3], wfx_verts[i][0]);
		wb_16(&l[3], wfx_verts[i][1]);
	}
	/* SEGS */
	for (int i = 0; i < 8; i++) {
		wb_16(&l[4], segs[i][0]);
		wb_16(&l[4], segs[i][1]);
		wb_16(&l[4], segs[i][2]);
		wb_16(&l[4], segs[i][3]);
		wb_16(&l[4], segs[i][4]);
		wb_16(&l[4], 0);
	}
	/* SSECTORS */
	wb_16(&l[5], 4); wb_16(&l[5], 0);
	wb_16(&l[5], 4); wb_16(&l[5], 4);
	/* NODES: partition, right bbox (B), left bbox (A), children */
	wb_16(&l[6], 128); wb_16(&l[6], 0); wb_16(&l[6], 0); wb_16(&l[6], 128);
	wb_16(&l[6], 128); wb_16(&l[6], 0); wb_16(&l[6], 128); wb_16(&l[6], 256);
	wb_16(&l[6], 128); wb_16(&l[6], 0); wb_16(&l[6], 0); wb_16(&l[6], 128);
	wb_16(&l[6], 0x8001); wb_16(&l[6], 0x8000);
	/* SECTORS */
	wb_16(&l[7], 0); wb_16(&l[7], 128); wb_name(&l[7], "FLOOR1"); wb_name(&l[7], "F_SKY1");
	wb_16(&l[7], 160); wb_16(&l[7], 0); wb_16(&l[7], 0);
	wb_16(&l[7], 16); wb_16(&l[7], 112); wb_name(&l[7], "NUKAGE1"); wb_name(&l[7], "NOFLAT");
	wb_16(&l[7], 300); wb_16(&l[7], 9); wb_16(&l[7], 7);
}

static const char *const wfx_map_names[8] = {
	"THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES", "SECTORS",
};

/* Adds map `name` to f; fix(l) may change the lumps first (corruption
 * tests), NULL for the good map. REJECT and BLOCKMAP are empty. */
static inline void wfx_map(struct wfix *f, const char *name, void (*fix)(struct wbuf *l))
{
	struct wbuf l[8];

	memset(l, 0, sizeof l);
	wfx_map_lumps(l);
	if (fix)
		fix(l);
	wf_lump(f, name, NULL, 0);
	for (int i = 0; i < 8; i++) {
		wf_lump(f, wfx_map_names[i], l[i].d, l[i].n);
		free(l[i].d);
	}
	wf_lump(f, "REJECT", NULL, 0);
	wf_lump(f, "BLOCKMAP", NULL, 0);
}

/* The whole fixture IWAD: graphics and maps MAP01 (good) and E1M1 (the
 * same). */
static inline uint8_t *wfx_iwad(size_t *len)
{
	struct wfix f;

	wf_init(&f);
	wfx_graphics(&f, 1);
	wfx_map(&f, "MAP01", NULL);
	wfx_map(&f, "E1M1", NULL);
	return wf_finish(&f, "IWAD", len);
}

static inline void wfx_no_bsp(struct wbuf *l)
{
	l[4].n = l[5].n = l[6].n = 0;
}

/* A PWAD with MAP01 but no BSP lumps' contents (the node builder's case). */
static inline uint8_t *wfx_nonodes(size_t *len)
{
	struct wfix f;

	wf_init(&f);
	wfx_map(&f, "MAP01", wfx_no_bsp);
	return wf_finish(&f, "PWAD", len);
}

#endif
