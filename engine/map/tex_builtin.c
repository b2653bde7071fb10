/*
 * tex_builtin: the project's own texture set, made by integer code so the
 * game needs no WAD: pal_builtin's palette, wall textures, flats, a sky and
 * sprites (tex_bspr.c). Every pixel comes from integer hashing and patterns of
 * the coordinates (tiling: every noise lattice wraps at the picture size),
 * so the set is identical on every build.
 *
 * Names are Doom-style. The sprites use Doom's sprite names (tex_bspr.c
 * lists them) so that the thing table (th.h) finds pictures for the thing
 * types the game uses in a map drawn with this set.
 *
 * Numbering (what the built-in levels' texture numbers mean, map.h): the
 * order of the tables below, the same on every call and every build.
 */
#include "engine/map/tex.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/map/tex_local.h"
#include "engine/map/tex_paint.h"

/* The tables name each picture's maker by kind (no function pointers, so
 * they stay read-only data); tb_make_* dispatch. */
enum tb_kind {
	TB_BRICK, TB_METAL, TB_STONE, TB_TECH, TB_WOOD, TB_DOOR, TB_GRATE, TB_MARBLE, TB_SKY,
	TB_FLOOR, TB_NOISY, TB_CEIL, TB_WATER, TB_SKYFLAT,
};

struct tb_tex {
	char name[9];
	int16_t w, h;
	uint8_t kind;
};

struct tb_flat {
	char name[9];
	uint8_t kind;
	int16_t arg;
};

/* Value noise 0..255 on a lattice of `cell` pixels that wraps every
 * `period` pixels (a multiple of cell), bilinear between lattice points. */
static int tb_noise(int x, int y, int cell, int period, uint32_t seed)
{
	int n = period / cell;
	int cx = x / cell, cy = y / cell, fx = x % cell, fy = y % cell;
	int x0 = cx % n, x1 = (cx + 1) % n, y0 = cy % n, y1 = (cy + 1) % n;
	int a = (int)(tp_hash((uint32_t)x0, (uint32_t)y0, seed) & 255);
	int b = (int)(tp_hash((uint32_t)x1, (uint32_t)y0, seed) & 255);
	int c = (int)(tp_hash((uint32_t)x0, (uint32_t)y1, seed) & 255);
	int d = (int)(tp_hash((uint32_t)x1, (uint32_t)y1, seed) & 255);
	int top = a * (cell - fx) + b * fx, bot = c * (cell - fx) + d * fx;

	return (top * (cell - fy) + bot * fy) / (cell * cell);
}

/* ---- wall textures ---------------------------------------------------- */

static void tb_brick(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int row = y / 16, sx = (x + (row & 1) * 16) % p->w;
			int id = row * 2 + sx / 32;
			int shade = 5 + (int)(tp_hash((uint32_t)id, 1, 11) % 3) +
				    (int)(tp_hash((uint32_t)x, (uint32_t)y, 12) % 3) - 1;

			if (y % 16 == 15 || sx % 32 == 31)
				tp_set(p, x, y, tp_c(PAL_GREY, 9 + (int)(tp_hash((uint32_t)x, (uint32_t)y, 13) % 2)));
			else
				tp_set(p, x, y, tp_c(PAL_RED, y % 16 == 0 ? shade - 2 : shade + 1));
		}
	}
}

static void tb_metal(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int px = x % 32, py = y % 32;
			int shade = 5 + tb_noise(x, y, 8, 64, 21) / 100;
			int rx = px < 16 ? px - 4 : px - 27, ry = py < 16 ? py - 4 : py - 27;

			if (px == 0 || py == 0)
				shade = 11;
			else if (px == 1 || py == 1)
				shade = 2;
			else if (rx * rx + ry * ry <= 2)
				shade = rx + ry < 0 ? 1 : 9;
			tp_set(p, x, y, tp_c(PAL_SLATE, shade));
		}
	}
}

/* Stone blocks: a wrapped Voronoi pattern, one point per 16x16 cell. */
static void tb_stone(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int d1 = 1 << 30, d2 = 1 << 30, id = 0;

			for (int j = -1; j <= 1; j++) {
				for (int i = -1; i <= 1; i++) {
					int cx = ((x / 16 + i) + 4) % 4, cy = ((y / 16 + j) + 4) % 4;
					uint32_t h = tp_hash((uint32_t)cx, (uint32_t)cy, 31);
					int ox = (x / 16 + i) * 16 + 2 + (int)(h % 12);
					int oy = (y / 16 + j) * 16 + 2 + (int)((h >> 8) % 12);
					int d = (x - ox) * (x - ox) + (y - oy) * (y - oy);

					if (d < d1) {
						d2 = d1;
						d1 = d;
						id = cx + 4 * cy;
					} else if (d < d2) {
						d2 = d;
					}
				}
			}
			if (d2 - d1 < 24)
				tp_set(p, x, y, tp_c(PAL_GREY, 12));
			else
				tp_set(p, x, y, tp_c(PAL_GREY, 6 + (int)(tp_hash((uint32_t)id, 0, 32) % 3) +
						     (int)(tp_hash((uint32_t)x, (uint32_t)y, 33) % 2)));
		}
	}
}

static void tb_tech(struct tex_pic *p)
{
	static const int lights[4] = { PAL_RED, PAL_YELLOW, PAL_GREEN, PAL_CYAN };

	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int shade = 8 + (int)(tp_hash((uint32_t)x, (uint32_t)y, 41) % 2);
			uint8_t c;

			if (x % 16 == 0)
				shade = 12;
			if (y % 32 == 0)
				shade = 3;
			c = tp_c(PAL_TEAL, shade);
			if (x >= 12 && x < 52 && y >= 40 && y < 80) {
				c = tp_c(PAL_BLACKRAMP, 13);
				if (y % 4 == 0 && (int)(tp_hash((uint32_t)y, 0, 42) % 32) > x - 12)
					c = tp_c(PAL_CYAN, 3);
			}
			if (y >= 10 && y < 14 && x % 8 >= 2 && x % 8 < 6)
				c = tp_c(lights[(x / 8) % 4], 1);
			tp_set(p, x, y, c);
		}
	}
}

static void tb_wood(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int plank = x / 16;
			int grain = tb_noise(x * 4, y, 16, 256, 51 + (uint32_t)plank) / 64;
			int shade = 4 + (int)(tp_hash((uint32_t)plank, 0, 52) % 3) + grain;

			if (x % 16 == 15 || (y + plank * 23) % 64 == 0)
				shade = 12;
			tp_set(p, x, y, tp_c(PAL_BROWN, shade));
		}
	}
}

static void tb_door(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int shade = 6 + tb_noise(x, y, 8, 64, 61) / 128;
			uint8_t c;

			if (x < 4 || x >= p->w - 4 || y < 4)
				shade = 10;
			if (y % 32 == 31 || x == p->w / 2)
				shade = 12;
			c = tp_c(PAL_SLATE, shade);
			if (y >= p->h - 16 && x >= 4 && x < p->w - 4)
				c = ((x + y) / 8) & 1 ? tp_c(PAL_YELLOW, 3) : tp_c(PAL_BLACKRAMP, 12);
			tp_set(p, x, y, c);
		}
	}
}

/* A grate: a frame and bars, transparent between them (a masked texture
 * for windows and fences). */
static void tb_grate(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++)
		for (int x = 0; x < p->w; x++)
			if (x < 4 || x >= p->w - 4 || y < 4 || y >= p->h - 4 || x % 16 < 2)
				tp_set(p, x, y, tp_c(PAL_GREY, 9 - (x % 16 == 0 || x < 2 || y < 2)));
}

static void tb_marble(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int n = tb_noise(x, y, 16, 64, 71) + tb_noise(x, y, 4, 64, 72) / 4;
			int vein = (n + x * 2 + y) % 64;

			tp_set(p, x, y, vein < 4 ? tp_c(PAL_RED, 8) : tp_c(PAL_TAN, 2 + n / 64));
		}
	}
}

/* The sky: blue fading to pale towards the horizon (the bottom), with
 * clouds of two noise octaves that wrap around the 256 columns. */
static void tb_sky(struct tex_pic *p)
{
	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int n = tb_noise(x, y * 2, 32, 256, 81) + tb_noise(x, y * 2, 8, 256, 82) / 2;
			int cloud = n - 250 + y / 4;
			uint8_t c = tp_c(PAL_SKY, 6 - y * 6 / p->h);

			if (cloud > 24)
				c = tp_c(PAL_GREY, 1 + (int)(tp_hash((uint32_t)x, (uint32_t)y, 83) % 2));
			else if (cloud > 0)
				c = tp_c(PAL_SLATE, 1);
			tp_set(p, x, y, c);
		}
	}
}

/* ---- flats -------------------------------------------------------------- */

static void tb_fset(struct tex_flat *f, int x, int y, uint8_t c)
{
	f->px[y * TEX_FLAT_SIZE + x] = c;
}

static void tb_floor(struct tex_flat *f, int arg)
{
	(void)arg;
	for (int y = 0; y < TEX_FLAT_SIZE; y++)
		for (int x = 0; x < TEX_FLAT_SIZE; x++)
			tb_fset(f, x, y, x % 32 == 0 || y % 32 == 0
				? tp_c(PAL_GREY, 11)
				: tp_c(PAL_TAN, 4 + ((x / 32 + y / 32) & 1) * 2 +
						(int)(tp_hash((uint32_t)x, (uint32_t)y, 91) % 2)));
}

/* Noise of one ramp: ramp, base shade and spread packed in arg. */
static void tb_noisy(struct tex_flat *f, int arg)
{
	int ramp = arg & 15, base = (arg >> 4) & 15, spread = (arg >> 8) & 15;

	for (int y = 0; y < TEX_FLAT_SIZE; y++)
		for (int x = 0; x < TEX_FLAT_SIZE; x++)
			tb_fset(f, x, y, tp_c(ramp, base + tb_noise(x, y, 8, 64, (uint32_t)arg) *
						      spread / 256 +
						      (int)(tp_hash((uint32_t)x, (uint32_t)y,
								    (uint32_t)arg) % 2)));
}

#define TB_NOISE_ARG(ramp, base, spread) ((ramp) | (base) << 4 | (spread) << 8)

static void tb_ceil(struct tex_flat *f, int arg)
{
	for (int y = 0; y < TEX_FLAT_SIZE; y++) {
		for (int x = 0; x < TEX_FLAT_SIZE; x++) {
			int cx = x % 32 - 16, cy = y % 32 - 16;
			int shade = 7;

			if (x % 32 == 0 || y % 32 == 0)
				shade = 11;
			/* a light panel: a pale glowing disc in each square */
			if (arg && cx * cx + cy * cy < 40) {
				tb_fset(f, x, y, tp_c(PAL_YELLOW, (cx * cx + cy * cy) / 20));
				continue;
			}
			tb_fset(f, x, y, tp_c(PAL_GREY, shade));
		}
	}
}

/* Water, frame arg of 4: ripples that move one quarter of their period per
 * frame. */
static void tb_water(struct tex_flat *f, int arg)
{
	for (int y = 0; y < TEX_FLAT_SIZE; y++)
		for (int x = 0; x < TEX_FLAT_SIZE; x++) {
			int n = tb_noise((x + arg * 16) % 64, y, 16, 64, 101) +
				tb_noise(x, (y + 64 - arg * 16) % 64, 16, 64, 102);

			tb_fset(f, x, y, tp_c(PAL_BLUE, 4 + n / 64));
		}
}

static void tb_skyflat(struct tex_flat *f, int arg)
{
	(void)arg;
	memset(f->px, tp_c(PAL_SKY, 3), sizeof f->px);
}

static const struct tb_tex tb_textures[] = {
	{ "AR_BRICK", 64, 64, TB_BRICK },   { "AR_METAL", 64, 64, TB_METAL },
	{ "AR_STONE", 64, 64, TB_STONE },   { "AR_TECH", 64, 128, TB_TECH },
	{ "AR_WOOD", 64, 64, TB_WOOD },     { "AR_DOOR", 64, 128, TB_DOOR },
	{ "AR_GRATE", 64, 64, TB_GRATE },   { "AR_MARBL", 64, 128, TB_MARBLE },
	{ "SKY1", 256, 128, TB_SKY },
};

static const struct tb_flat tb_flats[] = {
	{ "AR_FLOOR", TB_FLOOR, 0 },
	{ "AR_GRASS", TB_NOISY, TB_NOISE_ARG(PAL_GREEN, 5, 4) },
	{ "AR_DIRT", TB_NOISY, TB_NOISE_ARG(PAL_BROWN, 5, 4) },
	{ "AR_SLATE", TB_NOISY, TB_NOISE_ARG(PAL_SLATE, 5, 3) },
	{ "AR_CEIL", TB_CEIL, 0 },
	{ "AR_LIGHT", TB_CEIL, 1 },
	{ "AR_WAT1", TB_WATER, 0 },
	{ "AR_WAT2", TB_WATER, 1 },
	{ "AR_WAT3", TB_WATER, 2 },
	{ "AR_WAT4", TB_WATER, 3 },
	{ "F_SKY1", TB_SKYFLAT, 0 },
};

static void tb_make_pic(struct tex_pic *p, int kind)
{
	switch (kind) {
	case TB_BRICK: tb_brick(p); break;
	case TB_METAL: tb_metal(p); break;
	case TB_STONE: tb_stone(p); break;
	case TB_TECH: tb_tech(p); break;
	case TB_WOOD: tb_wood(p); break;
	case TB_DOOR: tb_door(p); break;
	case TB_GRATE: tb_grate(p); break;
	case TB_MARBLE: tb_marble(p); break;
	case TB_SKY: tb_sky(p); break;
	default: break;
	}
}

static void tb_make_flat(struct tex_flat *f, int kind, int arg)
{
	switch (kind) {
	case TB_FLOOR: tb_floor(f, arg); break;
	case TB_NOISY: tb_noisy(f, arg); break;
	case TB_CEIL: tb_ceil(f, arg); break;
	case TB_WATER: tb_water(f, arg); break;
	default: tb_skyflat(f, arg); break;
	}
}

#define TB_N(a) ((int)(sizeof(a) / sizeof((a)[0])))

int tex_builtin(struct tex_set **out)
{
	struct tex_set *t;
	uint64_t budget = TEX_BUDGET;
	uint8_t ca = PAL_RGB(PAL_PINK, 3), cb = PAL_BLACK;
	int r, nt = TB_N(tb_textures) + 2, nf = TB_N(tb_flats) + 1, ns = tex_bspr_count() + 1;

	*out = NULL;
	r = tex_set_alloc(&t, nt, nf, ns);
	if (r)
		return r;
	pal_builtin(&t->pal);
	r = tex_pic_new(&t->textures[0], "-", 1, 1, &budget);
	for (int i = 0; !r && i < TB_N(tb_textures); i++) {
		struct tex_pic *p = &t->textures[i + 1];

		r = tex_pic_new(p, tb_textures[i].name, tb_textures[i].w, tb_textures[i].h, &budget);
		if (!r) {
			tb_make_pic(p, tb_textures[i].kind);
			tex_pic_seal(p);
		}
	}
	t->fallback_tex = nt - 1;
	if (!r)
		r = tex_pic_checker(&t->textures[nt - 1], "", TEX_CHECKER_SIDE, TEX_CHECKER_SIDE, ca,
				    cb);
	for (int i = 0; i < TB_N(tb_flats); i++) {
		tex_name(t->flats[i].name, tb_flats[i].name);
		tb_make_flat(&t->flats[i], tb_flats[i].kind, tb_flats[i].arg);
	}
	t->fallback_flat = nf - 1;
	tex_flat_checker(&t->flats[nf - 1], "", ca, cb);
	if (!r)
		r = tex_pic_checker(&t->sprpics[0], "", 8, 8, ca, cb);
	if (!r)
		r = tex_bspr_make(&t->sprpics[1], &budget);
	if (!r)
		r = tex_set_finish(t, NULL);
	if (r) {
		tex_free(t);
		return r < 0 && r != -ENOMEM ? -ENOMEM : r;
	}
	*out = t;
	return 0;
}
