/*
 * Hand-built test maps and a hand-built texture set for the renderer tests
 * (no node builder, no WAD): the maps' BSP is written out by hand, so these
 * tests do not depend on nb_build, and the textures are synthetic so that a
 * pixel's colour says which texel it shows. Included by
 * tests/unit/test_r_*.c; static inline so that a test using only some of
 * them compiles warning-free.
 */
#ifndef ARCADED_TESTS_R_TESTMAP_H
#define ARCADED_TESTS_R_TESTMAP_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/pal.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"

#define U(x) ((fx_t)((x) * FX_ONE))

/* Colours (palette indices) */
#define C_CEIL PAL_RGB(PAL_GREY, 2)
#define C_FLOOR PAL_RGB(PAL_BROWN, 6)
#define C_WEST PAL_RGB(PAL_RED, 4)
#define C_NORTH PAL_RGB(PAL_GREEN, 4)
#define C_EAST PAL_RGB(PAL_BLUE, 4)
#define C_SOUTH PAL_RGB(PAL_YELLOW, 4)

struct tmap {
	struct map m;
	struct map_vertex v[32];
	struct map_sector sec[4];
	struct map_side sd[32];
	struct map_line ln[32];
	struct map_seg sg[32];
	struct map_subsector ss[4];
	struct map_node nd[4];
};

static inline void t_init(struct tmap *t)
{
	memset(t, 0, sizeof(*t));
	t->m.vertices = t->v;
	t->m.sectors = t->sec;
	t->m.sides = t->sd;
	t->m.lines = t->ln;
	t->m.segs = t->sg;
	t->m.subsectors = t->ss;
	t->m.nodes = t->nd;
}

static inline uint32_t t_vertex(struct tmap *t, int x, int y)
{
	t->v[t->m.num_vertices].x = U(x);
	t->v[t->m.num_vertices].y = U(y);
	return t->m.num_vertices++;
}

static inline uint32_t t_sector(struct tmap *t, int floor, int ceil, int light)
{
	struct map_sector *s = &t->sec[t->m.num_sectors];
	s->floor_h = U(floor);
	s->ceil_h = U(ceil);
	s->floor_tex = C_FLOOR;
	s->ceil_tex = C_CEIL;
	s->light = (uint8_t)light;
	return t->m.num_sectors++;
}

/* A line v1 -> v2 (its front is on the right) with a seg for each side;
 * tex is the middle texture of a one-sided line, the upper and lower of a
 * two-sided one. The segs are appended in order; returns the line. */
static inline uint32_t t_line(struct tmap *t, uint32_t v1, uint32_t v2, uint32_t front, uint32_t back,
		       uint16_t tex)
{
	uint32_t li = t->m.num_lines++;
	struct map_line *l = &t->ln[li];

	l->v1 = v1;
	l->v2 = v2;
	l->side[0] = t->m.num_sides;
	l->side[1] = MAP_NONE;
	t->sd[t->m.num_sides].sector = front;
	if (back == MAP_NONE) {
		t->sd[t->m.num_sides++].mid_tex = tex;
	} else {
		t->sd[t->m.num_sides].top_tex = tex;
		t->sd[t->m.num_sides++].bot_tex = tex;
		l->flags = ML_TWOSIDED;
		l->side[1] = t->m.num_sides;
		t->sd[t->m.num_sides].sector = back;
		t->sd[t->m.num_sides].top_tex = tex;
		t->sd[t->m.num_sides++].bot_tex = tex;
	}
	return li;
}

/* Seg of side `side` of line li, facing sector `front`. */
static inline void t_seg(struct tmap *t, uint32_t li, int side)
{
	struct map_seg *s = &t->sg[t->m.num_segs++];
	const struct map_line *l = &t->ln[li];
	uint32_t other = l->side[side ^ 1];

	s->line = li;
	s->side = (uint8_t)side;
	s->v1 = side ? l->v2 : l->v1;
	s->v2 = side ? l->v1 : l->v2;
	s->front = t->sd[l->side[side]].sector;
	s->back = other == MAP_NONE ? MAP_NONE : t->sd[other].sector;
}

/* Square room [-128, 128]^2, floor 0, ceiling 128: one convex sector, no
 * nodes (Doom convention: the map is subsector 0). Walls listed clockwise
 * so that their front (right) side faces in. */
static inline void t_room(struct tmap *t, int light, int same_tex)
{
	uint32_t a, b, c, d, s;

	t_init(t);
	a = t_vertex(t, -128, -128);
	b = t_vertex(t, -128, 128);
	c = t_vertex(t, 128, 128);
	d = t_vertex(t, 128, -128);
	s = t_sector(t, 0, 128, light);
	t_seg(t, t_line(t, a, b, s, MAP_NONE, C_WEST), 0);
	t_seg(t, t_line(t, b, c, s, MAP_NONE, same_tex ? C_WEST : C_NORTH), 0);
	t_seg(t, t_line(t, c, d, s, MAP_NONE, same_tex ? C_WEST : C_EAST), 0);
	t_seg(t, t_line(t, d, a, s, MAP_NONE, same_tex ? C_WEST : C_SOUTH), 0);
	t->ss[0].first_seg = 0;
	t->ss[0].num_segs = 4;
	t->ss[0].sector = s;
	t->m.num_subsectors = 1;
}

/* Rooms A [-128,128]^2 (f0 c128), W [128,144]x[-32,32] (the window: sill
 * floor w_floor, lintel ceiling w_ceil) and B [144,400]x[-128,128] (f0
 * c128), all light 255. Window lines (A-W, W-B) are colour C_WIN, B's east
 * wall C_BEAST, every other wall C_WALL. Subsectors: 0 A, 1 W, 2 B. BSP:
 * root (node 1) splits at x = 144 going north (front, east: B), its back
 * child (node 0) at x = 128 (front W, back A). */
#define C_WIN PAL_RGB(PAL_PURPLE, 4)
#define C_BEAST PAL_RGB(PAL_ORANGE, 4)
#define C_WALL PAL_RGB(PAL_TAN, 4)

static inline void t_window(struct tmap *t, int w_floor, int w_ceil)
{
	const uint8_t c_win = C_WIN, c_beast = C_BEAST, c_wall = C_WALL;
	uint32_t a, w, b, la, lw;
	uint32_t p[12];

	t_init(t);
	a = t_sector(t, 0, 128, 255);
	w = t_sector(t, w_floor, w_ceil, 255);
	b = t_sector(t, 0, 128, 255);
	p[0] = t_vertex(t, -128, -128);
	p[1] = t_vertex(t, -128, 128);
	p[2] = t_vertex(t, 128, 128);
	p[3] = t_vertex(t, 128, 32);
	p[4] = t_vertex(t, 128, -32);
	p[5] = t_vertex(t, 128, -128);
	p[6] = t_vertex(t, 144, 32);
	p[7] = t_vertex(t, 144, -32);
	p[8] = t_vertex(t, 144, 128);
	p[9] = t_vertex(t, 400, 128);
	p[10] = t_vertex(t, 400, -128);
	p[11] = t_vertex(t, 144, -128);
	/* subsector 0: A */
	t_seg(t, t_line(t, p[0], p[1], a, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[1], p[2], a, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[2], p[3], a, MAP_NONE, c_wall), 0);
	la = t_line(t, p[3], p[4], a, w, c_win);
	t_seg(t, la, 0);
	t_seg(t, t_line(t, p[4], p[5], a, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[5], p[0], a, MAP_NONE, c_wall), 0);
	t->ss[0] = (struct map_subsector){ 0, 6, a };
	/* subsector 1: W */
	t_seg(t, t_line(t, p[3], p[6], w, MAP_NONE, c_wall), 0);
	lw = t_line(t, p[6], p[7], w, b, c_win);
	t_seg(t, lw, 0);
	t_seg(t, t_line(t, p[7], p[4], w, MAP_NONE, c_wall), 0);
	t_seg(t, la, 1);
	t->ss[1] = (struct map_subsector){ 6, 4, w };
	/* subsector 2: B */
	t_seg(t, t_line(t, p[6], p[8], b, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[8], p[9], b, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[9], p[10], b, MAP_NONE, c_beast), 0);
	t_seg(t, t_line(t, p[10], p[11], b, MAP_NONE, c_wall), 0);
	t_seg(t, t_line(t, p[11], p[7], b, MAP_NONE, c_wall), 0);
	t_seg(t, lw, 1);
	t->ss[2] = (struct map_subsector){ 10, 6, b };
	t->m.num_subsectors = 3;
	t->nd[0] = (struct map_node){ U(128), 0, 0, U(1),
				     { { U(32), U(-32), U(128), U(144) },
				       { U(128), U(-128), U(-128), U(128) } },
				     { 1 | MAP_NF_SUBSECTOR, 0 | MAP_NF_SUBSECTOR } };
	t->nd[1] = (struct map_node){ U(144), 0, 0, U(1),
				     { { U(128), U(-128), U(144), U(400) },
				       { U(128), U(-128), U(-128), U(144) } },
				     { 2 | MAP_NF_SUBSECTOR, 0 } };
	t->m.num_nodes = 2;
}


/* ---- the test texture set ----
 *
 * Wall textures 1..255 and flats 0..255 are solid colours: number i is
 * palette index i (so maps written with palette indices, as the tests
 * above, draw those colours). Past them, textures and flats whose texels
 * encode their own coordinates, a masked texture, two skies and sprites:
 */
enum {
	TT_COLS = 256,     /* 64 x 64: texel (c, r) = c */
	TT_ROWS100,        /* 4 x 100 (height not a power of two): texel
			    * r in columns 0 and 2, 100 + r in 1 and 3 */
	TT_ROWS128,        /* 4 x 128: texel = r */
	TT_MASK,           /* 8 x 8, only columns 0..3 opaque: colour TT_MASK_C */
	TT_SKYCOLS,        /* 256 x 128: texel = c */
	TT_SKYROWS,        /* 256 x 128: texel = r */
	TT_WIDE3,          /* 3 x 1 (width not a power of two): 10, 20, 30 */
	TT_NUM_TEX
};
enum {
	TF_COLS = 256,     /* texel (x, y) = x */
	TF_ROWS,           /* texel (x, y) = y */
	TF_SKY,            /* the sky flat when a test sets sky_flat */
	TT_NUM_FLATS
};
#define TT_MASK_C PAL_RGB(PAL_PINK, 2)
/* Sprites: pictures 0..7 are 16 x 32 with texel (c, r) = 16 * k + c for
 * picture k, left offset 8, top offset 32 (standing on z, centred), fully
 * opaque; picture 8 is 16 x 32 with only columns 0..7 opaque, colour
 * TT_HOLE_C. Sprite 0 has one frame with picture k at rotation k; sprite 1
 * one frame mirrored as Doom's A1, A2A8, A3A7, A4A6, A5 (rotation 5..7 show
 * pictures 3..1 flipped); sprite 2 picture 8 at every rotation. */
#define TT_HOLE_C PAL_RGB(PAL_CYAN, 1)
#define TT_SPR_W 16
#define TT_SPR_H 32

struct ttex {
	struct tex_set t;
	uint8_t ident[256];
	struct tex_sprframe frames[3];
};

static inline uint8_t *tt_pic(struct tex_pic *p, const char *name, int w, int h)
{
	memset(p, 0, sizeof(*p));
	strncpy(p->name, name, sizeof(p->name) - 1);
	p->w = (int16_t)w;
	p->h = (int16_t)h;
	p->px = malloc((size_t)w * (size_t)h);
	assert_non_null(p->px);
	return p->px;
}

/* The set (heap, tt_free). Nothing animates: the translation tables are
 * the identity; sky_flat is -1 until a test sets it. */
static inline struct ttex *tt_new(void)
{
	struct ttex *x = calloc(1, sizeof(*x));
	struct tex_set *t;
	uint8_t *px;

	assert_non_null(x);
	t = &x->t;
	pal_builtin(&t->pal);
	for (int i = 0; i < 256; i++)
		x->ident[i] = (uint8_t)i;
	t->num_textures = TT_NUM_TEX;
	t->textures = calloc(TT_NUM_TEX, sizeof(*t->textures));
	assert_non_null(t->textures);
	strcpy(t->textures[0].name, "-");
	for (int i = 1; i < 256; i++) {
		t->textures[i].w = t->textures[i].h = 1;
		t->textures[i].px = &x->ident[i];
	}
	px = tt_pic(&t->textures[TT_COLS], "COLS", 64, 64);
	for (int c = 0; c < 64; c++)
		memset(px + c * 64, c, 64);
	px = tt_pic(&t->textures[TT_ROWS100], "ROWS100", 4, 100);
	for (int c = 0; c < 4; c++)
		for (int r = 0; r < 100; r++)
			px[c * 100 + r] = (uint8_t)(r + 100 * (c & 1));
	px = tt_pic(&t->textures[TT_ROWS128], "ROWS128", 4, 128);
	for (int c = 0; c < 4; c++)
		for (int r = 0; r < 128; r++)
			px[c * 128 + r] = (uint8_t)r;
	px = tt_pic(&t->textures[TT_MASK], "MASK", 8, 8);
	memset(px, TT_MASK_C, 64);
	t->textures[TT_MASK].opaque = calloc(64, 1);
	assert_non_null(t->textures[TT_MASK].opaque);
	memset(t->textures[TT_MASK].opaque, 1, 32);
	px = tt_pic(&t->textures[TT_SKYCOLS], "SKYCOLS", 256, 128);
	for (int c = 0; c < 256; c++)
		memset(px + c * 128, c, 128);
	px = tt_pic(&t->textures[TT_SKYROWS], "SKYROWS", 256, 128);
	for (int c = 0; c < 256; c++)
		for (int r = 0; r < 128; r++)
			px[c * 128 + r] = (uint8_t)r;
	px = tt_pic(&t->textures[TT_WIDE3], "WIDE3", 3, 1);
	px[0] = 10;
	px[1] = 20;
	px[2] = 30;

	t->num_flats = TT_NUM_FLATS;
	t->flats = calloc(TT_NUM_FLATS, sizeof(*t->flats));
	assert_non_null(t->flats);
	for (int i = 0; i < 256; i++)
		memset(t->flats[i].px, i, sizeof(t->flats[i].px));
	for (int y = 0; y < 64; y++)
		for (int xx = 0; xx < 64; xx++) {
			t->flats[TF_COLS].px[y * 64 + xx] = (uint8_t)xx;
			t->flats[TF_ROWS].px[y * 64 + xx] = (uint8_t)y;
		}
	t->sky_flat = -1;
	t->sky_tex = TT_SKYCOLS;

	t->num_sprpics = 9;
	t->sprpics = calloc(9, sizeof(*t->sprpics));
	assert_non_null(t->sprpics);
	for (int k = 0; k < 9; k++) {
		struct tex_pic *p = &t->sprpics[k];

		px = tt_pic(p, "SPR", TT_SPR_W, TT_SPR_H);
		p->left = TT_SPR_W / 2;
		p->top = TT_SPR_H;
		for (int c = 0; c < TT_SPR_W; c++)
			memset(px + c * TT_SPR_H, k < 8 ? 16 * k + c : TT_HOLE_C, TT_SPR_H);
	}
	t->sprpics[8].opaque = calloc(TT_SPR_W * TT_SPR_H, 1);
	assert_non_null(t->sprpics[8].opaque);
	memset(t->sprpics[8].opaque, 1, TT_SPR_W / 2 * TT_SPR_H);
	t->num_sprites = 3;
	t->sprites = calloc(3, sizeof(*t->sprites));
	assert_non_null(t->sprites);
	for (int k = 0; k < 8; k++) {
		static const uint8_t mirror[8] = { 0, 1, 2, 3, 4, 3, 2, 1 };

		x->frames[0].pic[k] = (uint16_t)k;
		x->frames[1].pic[k] = mirror[k];
		x->frames[1].flip[k] = k > 4;
		x->frames[2].pic[k] = 8;
	}
	for (int k = 0; k < 3; k++) {
		t->sprites[k].name[0] = 'T';
		t->sprites[k].num_frames = 1;
		t->sprites[k].frames = &x->frames[k];
	}

	t->tex_xlat = calloc(TT_NUM_TEX, sizeof(*t->tex_xlat));
	t->flat_xlat = calloc(TT_NUM_FLATS, sizeof(*t->flat_xlat));
	assert_non_null(t->tex_xlat);
	assert_non_null(t->flat_xlat);
	for (int i = 0; i < TT_NUM_TEX; i++)
		t->tex_xlat[i] = (uint16_t)i;
	for (int i = 0; i < TT_NUM_FLATS; i++)
		t->flat_xlat[i] = (uint16_t)i;
	return x;
}

static inline void tt_free(struct ttex *x)
{
	struct tex_set *t;

	if (!x)
		return;
	t = &x->t;
	for (int i = 256; i < TT_NUM_TEX; i++) {
		free(t->textures[i].px);
		free(t->textures[i].opaque);
	}
	for (int k = 0; k < t->num_sprpics; k++) {
		free(t->sprpics[k].px);
		free(t->sprpics[k].opaque);
	}
	free(t->textures);
	free(t->flats);
	free(t->sprpics);
	free(t->sprites);
	free(t->tex_xlat);
	free(t->flat_xlat);
	free(x);
}

#endif
