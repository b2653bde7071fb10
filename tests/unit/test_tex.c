/* Tests for engine/map/tex*.c: palette and light maps, texture composition from
 * patches, flats, sprites and their rotations, animation, fallbacks,
 * layering, the built-in set, name lookup by index, and the work bound of
 * composing (issue 13 item 8). Fixture values: wad_fixture.h,
 * hostile_fixture.h. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/lim.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"
#include "hostile_fixture.h"
#include "wad_fixture.h"

struct fx {
	uint8_t *img;
	struct wad *w;
	struct tex_set *t;
};

static struct fx load_fixture(int with_colormap)
{
	struct fx f;
	struct wfix b;
	size_t len;
	char err[160];

	wf_init(&b);
	wfx_graphics(&b, with_colormap);
	f.img = wf_finish(&b, "IWAD", &len);
	assert_int_equal(wad_new(&f.w), 0);
	assert_int_equal(wad_add(f.w, f.img, len, "fix.wad", err, sizeof err), 0);
	assert_int_equal(tex_load_wad(f.w, &f.t, err, sizeof err), 0);
	return f;
}

static void unload(struct fx *f)
{
	tex_free(f->t);
	wad_free(f->w);
	free(f->img);
}

/* Pixel (x, y) of texture name, or -1 where it is transparent. */
static int px(const struct tex_set *t, const char *name, int x, int y)
{
	int i = tex_find(t, name);
	const struct tex_pic *p;
	size_t k;

	assert_true(i > 0);
	p = &t->textures[i];
	k = (size_t)x * (size_t)p->h + (size_t)y;
	if (p->opaque && !p->opaque[k])
		return -1;
	return p->px[k];
}

static void palette_and_colormaps_are_read_exactly(void **state)
{
	struct fx f = load_fixture(1);

	(void)state;
	for (int i = 0; i < 256; i++) {
		assert_int_equal(f.t->pal.rgb[i][0], i);
		assert_int_equal(f.t->pal.rgb[i][1], 255 - i);
		assert_int_equal(f.t->pal.rgb[i][2], (7 * i) & 255);
	}
	for (int l = 0; l < PAL_LIGHTS; l++)
		for (int i = 0; i < 256; i++)
			assert_int_equal(f.t->pal.cmap[l][i], (i + l) & 255);
	unload(&f);
}

static void missing_colormap_is_computed(void **state)
{
	struct fx f = load_fixture(0);

	(void)state;
	/* the fixture's 256 colours are distinct, so full light maps every
	 * colour to itself; the darkest map picks a colour at least as near to
	 * the colour at 1/32 brightness as black-most entry 0 (0, 255, 0) and
	 * the original colour are */
	for (int i = 0; i < 256; i++)
		assert_int_equal(f.t->pal.cmap[0][i], i);
	for (int i = 0; i < 256; i++) {
		const uint8_t *c = f.t->pal.rgb[i];
		int t[3], d[3] = { 0, 0, 0 };
		const uint8_t *cand[3] = { f.t->pal.rgb[f.t->pal.cmap[PAL_LIGHTS - 1][i]], c,
					   f.t->pal.rgb[0] };
		for (int k = 0; k < 3; k++)
			t[k] = (c[k] + 16) / 32;
		for (int j = 0; j < 3; j++)
			for (int k = 0; k < 3; k++)
				d[j] += (cand[j][k] - t[k]) * (cand[j][k] - t[k]);
		assert_true(d[0] <= d[1]);
		assert_true(d[0] <= d[2]);
	}
	unload(&f);
}

static void two_patch_texture_is_composed_and_clipped(void **state)
{
	struct fx f = load_fixture(1);
	const struct tex_pic *p;

	(void)state;
	assert_int_equal(tex_find(f.t, "TWO"), 1);
	p = &f.t->textures[1];
	assert_int_equal(p->w, 8);
	assert_int_equal(p->h, 8);
	/* PAT1 at (0,0): 16 + 4x + y */
	assert_int_equal(px(f.t, "TWO", 0, 0), 16);
	assert_int_equal(px(f.t, "TWO", 3, 2), 16 + 12 + 2);
	assert_int_equal(px(f.t, "TWO", 1, 3), 16 + 4 + 3);
	/* PAT2 at (6,4): its first post (rows 0-1) lands on rows 4-5 */
	assert_int_equal(px(f.t, "TWO", 6, 4), 100);
	assert_int_equal(px(f.t, "TWO", 6, 5), 101);
	assert_int_equal(px(f.t, "TWO", 7, 4), 110);
	assert_int_equal(px(f.t, "TWO", 7, 5), 111);
	/* its hole (rows 2-3) at rows 6-7; its second post (rows 4-5 -> 8-9)
	 * and its third column (x 8) are past the edges */
	assert_int_equal(px(f.t, "TWO", 6, 6), -1);
	assert_int_equal(px(f.t, "TWO", 7, 7), -1);
	/* nothing drawn at all */
	assert_int_equal(px(f.t, "TWO", 4, 0), -1);
	assert_int_equal(px(f.t, "TWO", 0, 4), -1);
	assert_non_null(p->opaque);
	unload(&f);
}

static void solid_negative_and_tall_textures(void **state)
{
	struct fx f = load_fixture(1);

	(void)state;
	assert_null(f.t->textures[tex_find(f.t, "SOLID")].opaque);
	/* NEG: PAT1 at (-2,-1), so (x, y) shows PAT1 (x + 2, y + 1) */
	assert_int_equal(px(f.t, "NEG", 0, 0), 16 + 8 + 1);
	assert_int_equal(px(f.t, "NEG", 1, 2), 16 + 12 + 3);
	assert_int_equal(px(f.t, "NEG", 2, 0), -1);
	assert_int_equal(px(f.t, "NEG", 0, 3), -1);
	/* TALL: posts at 0, 254, then 254 + 10 (relative topdelta) */
	assert_int_equal(f.t->textures[tex_find(f.t, "TALL")].h, 300);
	assert_int_equal(px(f.t, "TALL", 0, 0), 1);
	assert_int_equal(px(f.t, "TALL", 0, 254), 2);
	assert_int_equal(px(f.t, "TALL", 0, 264), 3);
	assert_int_equal(px(f.t, "TALL", 0, 10), -1);
	unload(&f);
}

static void missing_patches_become_counted_checkers(void **state)
{
	struct fx f = load_fixture(1);
	const struct tex_pic *a, *b;

	(void)state;
	a = &f.t->textures[tex_find(f.t, "MISSP")];
	b = &f.t->textures[tex_find(f.t, "NOLUMP")];
	/* the texture keeps its size so its neighbours stay aligned */
	assert_int_equal(a->w, 8);
	assert_int_equal(b->w, 16);
	assert_int_equal(b->h, 8);
	assert_null(b->opaque);
	/* a checker: two colours in 8-pixel squares */
	assert_int_not_equal(b->px[0], b->px[8 * 8]);
	assert_int_equal(b->px[0], b->px[7 * 8 + 7]);
	/* 2 textures + 15 sprite rotations (see sprites test) */
	assert_int_equal(f.t->missing, 2 + 15);
	unload(&f);
}

static void numbering_and_lookup(void **state)
{
	struct fx f = load_fixture(1);

	(void)state;
	/* 0 "-", 1..8 TEXTURE1 in order, 9 the fallback */
	assert_int_equal(f.t->num_textures, 10);
	assert_int_equal(tex_find(f.t, "-"), 0);
	assert_int_equal(tex_find(f.t, "two"), 1);
	assert_int_equal(tex_find(f.t, "BFALL2"), 8);
	assert_int_equal(tex_find(f.t, "NOPE"), -1);
	assert_int_equal(tex_find(f.t, ""), -1);
	assert_int_equal(tex_find(f.t, "TWOTWOTWO"), -1);
	assert_int_equal(f.t->fallback_tex, 9);
	assert_int_equal(f.t->textures[0].w, 1);
	assert_non_null(f.t->textures[0].opaque);
	assert_int_equal(f.t->textures[0].opaque[0], 0);
	/* no SKY1 in the fixture: the fallback */
	assert_int_equal(f.t->sky_tex, 9);
	unload(&f);
}

static void flats_are_read_exactly(void **state)
{
	struct fx f = load_fixture(1);
	int i;

	(void)state;
	/* FLOOR1, NUKAGE1..3, F_SKY1 (SHORT is not 4096 bytes), fallback */
	assert_int_equal(f.t->num_flats, 6);
	i = tex_find_flat(f.t, "floor1");
	assert_int_equal(i, 0);
	assert_int_equal(f.t->flats[i].px[0], 0);
	assert_int_equal(f.t->flats[i].px[10 * 64 + 7], (3 * 7 + 5 * 10) & 255);
	assert_int_equal(f.t->flats[i].px[63 * 64 + 63], (3 * 63 + 5 * 63) & 255);
	assert_int_equal(tex_find_flat(f.t, "SHORT"), -1);
	assert_int_equal(f.t->sky_flat, 4);
	assert_int_equal(f.t->flats[4].px[100], 7);
	assert_int_equal(f.t->fallback_flat, 5);
	unload(&f);
}

static void sprite_rotations_and_mirroring_follow_lump_names(void **state)
{
	struct fx f = load_fixture(1);
	const struct tex_sprite *s;
	const struct tex_sprframe *a;

	(void)state;
	assert_int_equal(f.t->num_sprites, 1);
	s = &f.t->sprites[tex_find_sprite(f.t, "troo")];
	/* frames A, B, C (no lumps), D */
	assert_int_equal(s->num_frames, 4);
	a = &s->frames[0];
	/* sprpics are 1.. in lump order: TROOA1 1, TROOA2A8 2, TROOA3A7 3,
	 * TROOA4A6 4, TROOA5 5, TROOB0 6, TROOD1 7 */
	static const int pic[8] = { 1, 2, 3, 4, 5, 4, 3, 2 };
	static const int flip[8] = { 0, 0, 0, 0, 0, 1, 1, 1 };
	for (int r = 0; r < 8; r++) {
		assert_int_equal(a->pic[r], pic[r]);
		assert_int_equal(a->flip[r], flip[r]);
	}
	for (int r = 0; r < 8; r++) {
		assert_int_equal(s->frames[1].pic[r], 6);
		assert_int_equal(s->frames[1].flip[r], 0);
		assert_int_equal(s->frames[2].pic[r], 0);
	}
	assert_int_equal(s->frames[3].pic[0], 7);
	assert_int_equal(s->frames[3].pic[1], 0);
	/* the pictures: 2x3, every pixel 200 + lump index, offsets 1 + i and
	 * 10 + i */
	assert_string_equal(f.t->sprpics[2].name, "TROOA2A8");
	assert_int_equal(f.t->sprpics[2].w, 2);
	assert_int_equal(f.t->sprpics[2].h, 3);
	assert_int_equal(f.t->sprpics[2].px[5], 201);
	assert_int_equal(f.t->sprpics[2].left, 2);
	assert_int_equal(f.t->sprpics[2].top, 11);
	assert_null(f.t->sprpics[2].opaque);
	assert_int_equal(tex_find_sprite(f.t, "POSS"), -1);
	assert_int_equal(tex_find_sprite(f.t, "TROOA"), -1);
	unload(&f);
}

/* The picture a thing shows: by the angle from the viewer to it minus its
 * facing (180 degrees: it faces the viewer, rotation 1; 0: its back,
 * rotation 5), mirrored where the lump names say; a frame without
 * pictures shows picture 0, the checker; none for an unknown frame or
 * sprite. */
static void the_sprite_picture_follows_the_view_angle(void **state)
{
	struct fx f = load_fixture(1);
	int s, flip = 7;

	(void)state;
	s = tex_find_sprite(f.t, "TROO");
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 0, ANG180, &flip), 1);
	assert_int_equal(flip, 0);
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 0, 0, &flip), 5);
	assert_int_equal(flip, 0);
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 0, ANG180 + ANG45, &flip), 2);
	assert_int_equal(flip, 0);
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 0, ANG180 - ANG45, &flip), 2);
	assert_int_equal(flip, 1);
	/* within half a rotation of 180 degrees it is still rotation 1 */
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 0, ANG180 + ANG45 / 2 - 1, &flip), 1);
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 1, 12345, &flip), 6);
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 2, ANG180, &flip), 0);
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s, 4, ANG180, &flip), -1);
	assert_int_equal(tex_sprite_pic(f.t, (unsigned)s + 1, 0, ANG180, &flip), -1);
	unload(&f);
}

static void animations_cycle_whole_ranges_only(void **state)
{
	struct fx f = load_fixture(1);

	(void)state;
	/* NUKAGE1..3 (flats 1..3) animate; BFALL1..2 lack Doom's BFALL4 */
	assert_int_equal(f.t->num_anims, 1);
	for (int i = 0; i < f.t->num_textures; i++)
		assert_int_equal(f.t->tex_xlat[i], i);
	tex_animate(f.t, 0);
	assert_int_equal(f.t->flat_xlat[1], 1);
	assert_int_equal(f.t->flat_xlat[3], 3);
	tex_animate(f.t, TEX_ANIM_TICKS - 1);
	assert_int_equal(f.t->flat_xlat[1], 1);
	tex_animate(f.t, TEX_ANIM_TICKS);
	assert_int_equal(f.t->flat_xlat[1], 2);
	assert_int_equal(f.t->flat_xlat[2], 3);
	assert_int_equal(f.t->flat_xlat[3], 1);
	tex_animate(f.t, 5 * TEX_ANIM_TICKS);
	assert_int_equal(f.t->flat_xlat[1], 3);
	assert_int_equal(f.t->flat_xlat[0], 0);
	assert_int_equal(f.t->flat_xlat[4], 4);
	unload(&f);
}

static void pwad_overrides_a_texture_and_a_flat(void **state)
{
	struct fx f = load_fixture(1);
	struct wfix b;
	struct wbuf l = { 0 };
	uint8_t *pw, flat[4096];
	size_t len;
	char err[160];
	struct tex_set *t;
	static const int one[1][3] = { { 0, 0, 0 } };

	(void)state;
	/* the PWAD's TEXTURE1 replaces the whole list; its FLOOR1 replaces the
	 * pixels of the IWAD's FLOOR1 in place */
	wf_init(&b);
	wb_32(&l, 1);
	wb_32(&l, 8);
	wfx_texdef(&l, "SOLID", 2, 2, 1, one);
	wf_lumpb(&b, "TEXTURE1", &l);
	wf_lump(&b, "FF_START", NULL, 0);
	memset(flat, 42, sizeof flat);
	wf_lump(&b, "FLOOR1", flat, sizeof flat);
	wf_lump(&b, "FF_END", NULL, 0);
	pw = wf_finish(&b, "PWAD", &len);
	assert_int_equal(wad_add(f.w, pw, len, "p.wad", err, sizeof err), 0);
	assert_int_equal(tex_load_wad(f.w, &t, err, sizeof err), 0);
	assert_int_equal(t->num_textures, 3);
	assert_int_equal(tex_find(t, "SOLID"), 1);
	assert_int_equal(tex_find(t, "TWO"), -1);
	assert_int_equal(t->textures[1].w, 2);
	assert_int_equal(t->textures[1].px[0], 16);
	assert_int_equal(tex_find_flat(t, "FLOOR1"), 0);
	assert_int_equal(t->flats[0].px[0], 42);
	assert_int_equal(t->num_flats, 6);
	tex_free(t);
	unload(&f);
	free(pw);
}

/* Deferred composition (tex_load_wad_names, tex_want_map, tex_compose):
 * the names and sizes are the full load's, no wall texture has pixels
 * until composed, and a composed one is the full load's exactly. */
static void deferred_set_composes_what_the_map_shows(void **state)
{
	struct fx f = load_fixture(1);
	struct tex_set *d;
	struct map m;
	struct map_side sides[2];
	struct tex_anim anim, *anims;
	uint8_t want[16] = { 0 };
	char err[160];
	int two, neg, missp, nanims;

	(void)state;
	assert_int_equal(tex_load_wad_names(f.w, NULL, &d, err, sizeof err), 0);
	assert_int_equal(d->num_textures, f.t->num_textures);
	assert_true(d->num_textures <= (int)sizeof want);
	for (int i = 1; i < d->num_textures - 1; i++) {
		assert_string_equal(d->textures[i].name, f.t->textures[i].name);
		assert_int_equal(d->textures[i].w, f.t->textures[i].w);
		assert_int_equal(d->textures[i].h, f.t->textures[i].h);
		assert_null(d->textures[i].px);
		assert_int_equal(tex_wall_index(d, (uint16_t)i), -1);
	}
	/* the fallback and texture 0 are there at once */
	assert_int_equal(tex_wall_index(d, (uint16_t)d->fallback_tex), d->fallback_tex);
	assert_int_equal(tex_wall_index(d, 0), 0);
	assert_int_equal(d->missing, 15);             /* sprite rotations only */

	/* a map whose sides show TWO (top), MISSP (bottom), an out-of-range
	 * number and nothing; BFALL1 is in an animation with BFALL2 */
	two = tex_find(d, "TWO");
	neg = tex_find(d, "NEG");
	missp = tex_find(d, "MISSP");
	memset(&m, 0, sizeof m);
	memset(sides, 0, sizeof sides);
	sides[0].top_tex = (uint16_t)two;
	sides[0].bot_tex = (uint16_t)missp;
	sides[1].mid_tex = (uint16_t)tex_find(d, "BFALL1");
	sides[1].top_tex = 999;
	m.sides = sides;
	m.num_sides = 2;
	anim.flat = 0;
	anim.first = (uint16_t)tex_find(d, "BFALL1");
	anim.count = 2;
	anims = d->anims;
	nanims = d->num_anims;
	d->anims = &anim;
	d->num_anims = 1;
	tex_want_map(d, &m, want);
	d->anims = anims;
	d->num_anims = nanims;
	for (int i = 0; i < d->num_textures; i++)
		assert_int_equal(want[i], i == two || i == missp || i == anim.first ||
						  i == anim.first + 1 || i == d->sky_tex);

	assert_int_equal(tex_compose(d, f.w, want, NULL, NULL, err, sizeof err), 0);
	assert_int_equal(tex_wall_index(d, (uint16_t)two), two);
	assert_memory_equal(d->textures[two].px, f.t->textures[two].px, 8 * 8);
	assert_memory_equal(d->textures[two].opaque, f.t->textures[two].opaque, 8 * 8);
	/* MISSP's patch is missing: the checker, counted as in a full load */
	assert_memory_equal(d->textures[missp].px, f.t->textures[missp].px, 8 * 8);
	assert_int_equal(d->missing, 15 + 1);
	/* not shown by the map: still without pixels */
	assert_null(d->textures[neg].px);
	assert_int_equal(tex_wall_index(d, (uint16_t)neg), -1);
	/* composing again changes nothing */
	assert_int_equal(tex_compose(d, f.w, want, NULL, NULL, err, sizeof err), 0);
	assert_int_equal(d->missing, 15 + 1);
	tex_free(d);
	unload(&f);
}

/* Deferred sprites: every picture has its name, size and offsets and no
 * pixels (the renderers' lookup says it cannot be drawn) until a wanted
 * sprite's pictures are decoded, exactly as a full load decodes them. */
static void deferred_sprites_are_decoded_when_wanted(void **state)
{
	struct fx f = load_fixture(1);
	struct tex_set *d;
	uint8_t want[16] = { 0 }, spr[16] = { 0 };
	char err[160];
	int flip, n = f.t->num_sprpics;

	(void)state;
	assert_int_equal(tex_load_wad_names(f.w, NULL, &d, err, sizeof err), 0);
	assert_int_equal(d->num_sprpics, n);
	assert_true(n <= (int)sizeof spr);
	for (int i = 1; i < n; i++) {
		assert_string_equal(d->sprpics[i].name, f.t->sprpics[i].name);
		assert_int_equal(d->sprpics[i].w, f.t->sprpics[i].w);
		assert_int_equal(d->sprpics[i].left, f.t->sprpics[i].left);
		assert_int_equal(d->sprpics[i].top, f.t->sprpics[i].top);
		assert_null(d->sprpics[i].px);
	}
	assert_int_equal(tex_sprite_pic(d, (unsigned)tex_find_sprite(d, "TROO"), 0, 0, &flip), -1);
	tex_want_sprite(d, "NONE", spr);
	for (int i = 0; i < n; i++)
		assert_int_equal(spr[i], 0);
	tex_want_sprite(d, "TROO", spr);
	/* TROOA1..A5, B0, D1 are pictures 1..7 (see the rotations test); the
	 * missing frame C points at picture 0 */
	for (int i = 1; i < n; i++)
		assert_int_equal(spr[i], 1);
	assert_int_equal(tex_compose(d, f.w, want, spr, NULL, err, sizeof err), 0);
	for (int i = 1; i < n; i++) {
		const struct tex_pic *a = &d->sprpics[i], *b = &f.t->sprpics[i];

		assert_non_null(a->px);
		assert_memory_equal(a->px, b->px, (size_t)a->w * (size_t)a->h);
		if (b->opaque)
			assert_memory_equal(a->opaque, b->opaque, (size_t)a->w * (size_t)a->h);
	}
	assert_int_equal(tex_sprite_pic(d, (unsigned)tex_find_sprite(d, "TROO"), 0, 0, &flip),
			 tex_sprite_pic(f.t, (unsigned)tex_find_sprite(f.t, "TROO"), 0, 0, &flip));
	tex_free(d);
	unload(&f);
}

/* tex_compose refuses WADs whose texture lists number other textures than
 * the set's (a PWAD's TEXTURE1 added after the set was loaded). */
static void deferred_set_refuses_other_lists(void **state)
{
	struct fx f = load_fixture(1);
	struct tex_set *d;
	struct wfix b;
	struct wbuf l = { 0 };
	uint8_t *pw, want[16];
	size_t len;
	char err[160];
	static const int one[1][3] = { { 0, 0, 0 } };

	(void)state;
	assert_int_equal(tex_load_wad_names(f.w, NULL, &d, err, sizeof err), 0);
	wf_init(&b);
	wb_32(&l, 1);
	wb_32(&l, 8);
	wfx_texdef(&l, "SOLID", 2, 2, 1, one);
	wf_lumpb(&b, "TEXTURE1", &l);
	pw = wf_finish(&b, "PWAD", &len);
	assert_int_equal(wad_add(f.w, pw, len, "p.wad", err, sizeof err), 0);
	memset(want, 1, sizeof want);
	assert_int_equal(tex_compose(d, f.w, want, NULL, NULL, err, sizeof err), -EINVAL);
	assert_non_null(strstr(err, "TEXTURE1"));
	assert_null(d->textures[1].px);
	tex_free(d);
	unload(&f);
	free(pw);
}

/* A graphics WAD whose lump `name` is replaced by n bytes. */
static int load_with(const char *name, size_t n, char *err, size_t errlen)
{
	struct fx f = load_fixture(1);
	struct wfix b;
	uint8_t *pw, zero[16] = { 0 };
	size_t len;
	struct tex_set *t = NULL;
	int r;

	wf_init(&b);
	wf_lump(&b, name, zero, n);
	pw = wf_finish(&b, "PWAD", &len);
	assert_int_equal(wad_add(f.w, pw, len, "p.wad", err, errlen), 0);
	r = tex_load_wad(f.w, &t, err, errlen);
	if (r)
		assert_null(t);
	tex_free(t);
	unload(&f);
	free(pw);
	return r;
}

static void bad_palette_and_lists_are_errors(void **state)
{
	char err[160];

	(void)state;
	assert_int_equal(load_with("PLAYPAL", 10, err, sizeof err), -EINVAL);
	assert_string_equal(err, "PLAYPAL: a palette needs 768 bytes, has 10");
	assert_int_equal(load_with("COLORMAP", 16, err, sizeof err), -EINVAL);
	assert_string_equal(err, "COLORMAP: 32 light maps need 8192 bytes, has 16");
	assert_int_equal(load_with("TEXTURE1", 2, err, sizeof err), -EINVAL);
	assert_string_equal(err, "TEXTURE1: no count: 2");
	/* count 0 in 16 bytes is fine: no textures */
	assert_int_equal(load_with("TEXTURE1", 16, err, sizeof err), 0);
	assert_int_equal(load_with("PNAMES", 3, err, sizeof err), -EINVAL);
}

static void no_playpal_is_an_error(void **state)
{
	struct wfix b;
	struct wad *w;
	struct tex_set *t;
	uint8_t *img;
	size_t len;
	char err[160];

	(void)state;
	wf_init(&b);
	wf_lump(&b, "JUNK", "x", 1);
	img = wf_finish(&b, "PWAD", &len);
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "j.wad", err, sizeof err), 0);
	assert_int_equal(tex_load_wad(w, &t, err, sizeof err), -EINVAL);
	assert_string_equal(err, "PLAYPAL: no palette in the WADs");
	wad_free(w);
	free(img);
}

/* Loads img (freed here) as "hostile.wad" with stop hook `stop`; returns
 * tex_load_wad_lim's result (the set is freed). */
static int load_hostile(uint8_t *img, size_t len, const struct lim_stop *stop, char *err,
			size_t errlen)
{
	struct wad *w;
	struct tex_set *t = NULL;
	int r;

	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "hostile.wad", err, errlen), 0);
	r = tex_load_wad_lim(w, stop, &t, err, errlen);
	if (r)
		assert_null(t);
	tex_free(t);
	wad_free(w);
	free(img);
	return r;
}

/* Issue 13 item 8: one texture of 2,000 patches whose 4,096 columns share
 * one column of 6,000 posts (5e10 posts to walk, 77 s and more) stops at
 * TEX_MAX_STEPS, naming the file, lump, entry and limit; the stop hook
 * ends it at its next poll; a small one composes. */
static void a_texture_past_the_step_limit_is_refused(void **state)
{
	struct hf_polls halt = { 0, 2 };
	uint64_t steps = 0;
	struct lim_stop count = { NULL, NULL, &steps }, stop = { hf_poll, &halt, NULL };
	size_t len;
	uint8_t *img;
	char err[200];

	(void)state;
	img = hf_tall_texture(2000, 6000, &len);
	assert_int_equal(load_hostile(img, len, &count, err, sizeof err), -E2BIG);
	assert_string_equal(err, "hostile.wad: TEXTURE1 entry 0 (SOLID): the textures need more "
				 "than 268435456 steps to compose (limit TEX_MAX_STEPS)");
	assert_true(steps > TEX_MAX_STEPS && steps < TEX_MAX_STEPS + 10000);
	img = hf_tall_texture(2000, 6000, &len);
	assert_int_equal(load_hostile(img, len, &stop, err, sizeof err), -ECANCELED);
	assert_string_equal(err, "hostile.wad: TEXTURE1 entry 0 (SOLID): stopped");
	assert_int_equal(halt.polls, 2);
	/* 2 patches of 10 one-pixel posts: per patch, a step per column (4,096)
	 * and per column 10 posts of 2 steps (the post and its pixel); the rest
	 * of the set (flats, sprites) takes a few hundred */
	steps = 0;
	img = hf_tall_texture(2, 10, &len);
	assert_int_equal(load_hostile(img, len, &count, err, sizeof err), 0);
	assert_true(steps >= 2 * (4096 + 4096 * 10 * 2) && steps < 2 * (4096 + 4096 * 10 * 2) + 5000);
}

/* Every sprite of t is found by its name, in either case, at its own
 * index (sprite names are unique); names that are no sprite's are not. */
static void sprites_found_by_name(const struct tex_set *t, int at_least)
{
	assert_non_null(t->spr_by_name);
	assert_true(t->num_sprites >= at_least);
	for (int i = 0; i < t->num_sprites; i++) {
		char lower[5];

		for (int k = 0; k < 5; k++)
			lower[k] = (char)(t->sprites[i].name[k] >= 'A' && t->sprites[i].name[k] <= 'Z'
						  ? t->sprites[i].name[k] - 'A' + 'a'
						  : t->sprites[i].name[k]);
		assert_int_equal(tex_find_sprite(t, t->sprites[i].name), i);
		assert_int_equal(tex_find_sprite(t, lower), i);
	}
	assert_int_equal(tex_find_sprite(t, ""), -1);
	assert_int_equal(tex_find_sprite(t, "ZZZZ"), -1);
	assert_int_equal(tex_find_sprite(t, "AAAA"), -1);
	/* a sprite's name and one more character is no sprite's */
	{
		char longer[6];

		memcpy(longer, t->sprites[0].name, 4);
		longer[4] = 'A';
		longer[5] = '\0';
		assert_int_equal(tex_find_sprite(t, longer), -1);
		longer[3] = '\0';
		assert_true(tex_find_sprite(t, longer) != 0);
	}
}

/* tex_find, tex_find_flat and tex_find_sprite go through a sorted index
 * once the set is finished: every name finds the first entry of that
 * name, as a scan would. */
static void lookup_by_index_agrees_with_a_scan(void **state)
{
	struct fx f = load_fixture(1);
	struct tex_set *t = f.t;
	(void)state;
	assert_non_null(t->tex_by_name);
	assert_non_null(t->flat_by_name);
	for (int i = 1; i < t->num_textures; i++) {
		int first = i;
		for (int k = 1; k < i; k++)
			if (memcmp(t->textures[k].name, t->textures[i].name, 9) == 0) {
				first = k;
				break;
			}
		if (t->textures[i].name[0])
			assert_int_equal(tex_find(t, t->textures[i].name), first);
	}
	for (int i = 0; i < t->num_flats; i++)
		if (t->flats[i].name[0])
			assert_int_equal(tex_find_flat(t, t->flats[i].name), i);
	assert_int_equal(tex_find(t, "nosuch"), -1);
	assert_int_equal(tex_find(t, "solid"), tex_find(t, "SOLID"));
	assert_int_equal(tex_find_flat(t, "ZZZZ"), -1);
	sprites_found_by_name(t, 1);
	unload(&f);
	/* the built-in set's sprites are added in no order of their names */
	assert_int_equal(tex_builtin(&t), 0);
	sprites_found_by_name(t, 8);
	tex_free(t);
}

static void builtin_set_is_complete_and_deterministic(void **state)
{
	struct tex_set *a, *b;
	struct pal p;
	static const char *const walls[] = { "AR_BRICK", "AR_METAL", "AR_STONE", "AR_TECH",
					     "AR_WOOD", "AR_DOOR", "AR_GRATE", "SKY1" };
	static const char *const flats[] = { "AR_FLOOR", "AR_GRASS", "AR_CEIL", "AR_WAT1",
					     "F_SKY1" };
	static const char *const sprites[] = { "BAR1", "COLU", "POSS", "MEDI", "SPOS", "TROO",
						 "SARG", "HEAD" };

	(void)state;
	assert_int_equal(tex_builtin(&a), 0);
	assert_int_equal(tex_builtin(&b), 0);
	pal_builtin(&p);
	assert_memory_equal(&a->pal, &p, sizeof p);
	for (size_t i = 0; i < sizeof walls / sizeof walls[0]; i++) {
		int k = tex_find(a, walls[i]);
		assert_true(k > 0);
		assert_int_not_equal(k, a->fallback_tex);
		assert_memory_equal(a->textures[k].px, b->textures[k].px,
				    (size_t)a->textures[k].w * (size_t)a->textures[k].h);
	}
	for (size_t i = 0; i < sizeof flats / sizeof flats[0]; i++)
		assert_true(tex_find_flat(a, flats[i]) >= 0);
	for (size_t i = 0; i < sizeof sprites / sizeof sprites[0]; i++) {
		const struct tex_sprite *s = &a->sprites[tex_find_sprite(a, sprites[i])];
		for (int r = 0; r < 8; r++)
			assert_int_not_equal(s->frames[0].pic[r], 0);
	}
	assert_int_equal(a->sky_tex, tex_find(a, "SKY1"));
	assert_int_equal(a->textures[a->sky_tex].w, 256);
	assert_int_equal(a->sky_flat, tex_find_flat(a, "F_SKY1"));
	assert_int_equal(a->missing, 0);
	/* the grate has holes (a masked texture), the brick has none */
	assert_non_null(a->textures[tex_find(a, "AR_GRATE")].opaque);
	assert_null(a->textures[tex_find(a, "AR_BRICK")].opaque);
	/* the enemy has 8 views from 5 pictures: 6..8 mirror 4..2 */
	const struct tex_sprframe *e = &a->sprites[tex_find_sprite(a, "POSS")].frames[0];
	assert_int_equal(e->pic[1], e->pic[7]);
	assert_int_equal(e->flip[7], 1);
	assert_int_not_equal(e->pic[0], e->pic[4]);
	/* the water flats animate */
	assert_int_equal(a->num_anims, 1);
	tex_animate(a, TEX_ANIM_TICKS);
	assert_int_equal(a->flat_xlat[tex_find_flat(a, "AR_WAT1")], tex_find_flat(a, "AR_WAT2"));
	tex_free(a);
	tex_free(b);
	tex_free(NULL);
}

/* The built-in set's one-view sprites: pickups, decorations, the shot's
 * puff and blood (4 frames each, as r_game.c shows them), and the HUD
 * pistol, whose every frame reaches the bottom of Doom's 320x168 view
 * (hud.c draws a picture's top left at (1 - left, 32 - top)) with the
 * recoil frames higher than the ready one. */
static void builtin_set_has_pickups_effects_and_the_pistol(void **state)
{
	static const struct { const char *name; int frames; } one[] = {
		{ "STIM", 1 }, { "CLIP", 1 }, { "AMMO", 1 }, { "CBRA", 1 }, { "TRED", 1 },
		{ "PUFF", 4 }, { "BLUD", 4 }, { "PISG", 5 }, { "PISF", 1 },
	};
	struct tex_set *t;
	int g, top_a = 0;

	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	for (size_t i = 0; i < sizeof one / sizeof one[0]; i++) {
		int k = tex_find_sprite(t, one[i].name);
		assert_true(k >= 0);
		assert_int_equal(t->sprites[k].num_frames, one[i].frames);
		for (int f = 0; f < one[i].frames; f++)
			for (int r = 0; r < 8; r++)
				assert_int_equal(t->sprites[k].frames[f].pic[r],
						 t->sprites[k].frames[f].pic[0]);
	}
	g = tex_find_sprite(t, "PISG");
	for (int f = 0; f < 5; f++) {
		const struct tex_pic *p = &t->sprpics[t->sprites[g].frames[f].pic[0]];
		assert_int_equal(32 - p->top + p->h, 168);
		if (f == 0)
			top_a = 32 - p->top;
		else
			assert_true(32 - p->top < top_a);
	}
	assert_int_equal(t->missing, 0);
	tex_free(t);
}

/* The opaque width of row y of picture p (from its first to its last
 * drawn pixel), 0 for an empty row. */
static int row_width(const struct tex_pic *p, int y)
{
	int first = -1, last = -1;

	for (int x = 0; x < p->w; x++)
		if (!p->opaque || p->opaque[(size_t)x * (size_t)p->h + (size_t)y]) {
			if (first < 0)
				first = x;
			last = x;
		}
	return first < 0 ? 0 : last - first + 1;
}

static const struct tex_pic *frame_pic(const struct tex_set *t, int sprite, int f)
{
	return &t->sprpics[t->sprites[sprite].frames[f].pic[0]];
}

/* The built-in brute (SARG) is a figure, not a block: seen from the front
 * its body is round (the rows across its chest and belly are not all one
 * width, as a box's are), and its walk, wind-up, aim, strike and pain
 * frames (A..H; C repeats A's pose) are each a picture of their own. */
static void builtin_brute_has_a_shape_and_a_frame_per_pose(void **state)
{
	static const int poses[] = { 0, 1, 3, 4, 5, 6, 7 };   /* A B D E F G H */
	struct tex_set *t;
	int k, lo = 1000, hi = 0;

	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	k = tex_find_sprite(t, "SARG");
	assert_true(k >= 0);
	assert_true(t->sprites[k].num_frames >= 14);
	for (int y = 22; y <= 34; y++) {
		int w = row_width(frame_pic(t, k, 0), y);

		lo = w < lo ? w : lo;
		hi = w > hi ? w : hi;
	}
	assert_true(hi - lo >= 3);
	for (size_t i = 0; i < sizeof poses / sizeof poses[0]; i++)
		for (size_t j = i + 1; j < sizeof poses / sizeof poses[0]; j++) {
			const struct tex_pic *a = frame_pic(t, k, poses[i]), *b = frame_pic(t, k, poses[j]);

			if (a->w == b->w && a->h == b->h &&
			    !memcmp(a->px, b->px, (size_t)a->w * (size_t)a->h) &&
			    !memcmp(a->opaque, b->opaque, (size_t)a->w * (size_t)a->h))
				fail_msg("SARG frames %c and %c are one picture", 'A' + poses[i],
					 'A' + poses[j]);
		}
	tex_free(t);
}

/* The soldiers' legs are limbs, not boxes: seen from the front the rows
 * from the hips to the ankles of the grunt (POSS) and the shotgun guy
 * (SPOS) are not all one width (the thighs are wider than the shins). */
static void builtin_soldiers_have_shaped_legs(void **state)
{
	static const char *const names[] = { "POSS", "SPOS" };
	struct tex_set *t;

	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
		const struct tex_pic *p = frame_pic(t, tex_find_sprite(t, names[i]), 0);
		int lo = 1000, hi = 0;

		for (int y = 43; y <= 52; y++) {
			int w = row_width(p, y);

			lo = w < lo ? w : lo;
			hi = w > hi ? w : hi;
		}
		if (hi - lo < 2)
			fail_msg("%s: legs %d..%d wide", names[i], lo, hi);
	}
	tex_free(t);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(palette_and_colormaps_are_read_exactly),
		cmocka_unit_test(missing_colormap_is_computed),
		cmocka_unit_test(two_patch_texture_is_composed_and_clipped),
		cmocka_unit_test(solid_negative_and_tall_textures),
		cmocka_unit_test(missing_patches_become_counted_checkers),
		cmocka_unit_test(numbering_and_lookup),
		cmocka_unit_test(flats_are_read_exactly),
		cmocka_unit_test(sprite_rotations_and_mirroring_follow_lump_names),
		cmocka_unit_test(the_sprite_picture_follows_the_view_angle),
		cmocka_unit_test(animations_cycle_whole_ranges_only),
		cmocka_unit_test(pwad_overrides_a_texture_and_a_flat),
		cmocka_unit_test(bad_palette_and_lists_are_errors),
		cmocka_unit_test(no_playpal_is_an_error),
		cmocka_unit_test(a_texture_past_the_step_limit_is_refused),
		cmocka_unit_test(deferred_set_composes_what_the_map_shows),
		cmocka_unit_test(deferred_set_refuses_other_lists),
		cmocka_unit_test(deferred_sprites_are_decoded_when_wanted),
		cmocka_unit_test(lookup_by_index_agrees_with_a_scan),
		cmocka_unit_test(builtin_set_is_complete_and_deterministic),
		cmocka_unit_test(builtin_set_has_pickups_effects_and_the_pistol),
		cmocka_unit_test(builtin_brute_has_a_shape_and_a_frame_per_pose),
		cmocka_unit_test(builtin_soldiers_have_shaped_legs),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
