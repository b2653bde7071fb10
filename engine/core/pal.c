/*
 * pal: the built-in palette and its light tables.
 *
 * Every ramp is drawn through three key colours: a pale tint (shade 0), the
 * pure hue (shade PAL_KEY_SHADE) and a dark end (shade 15), with integer
 * linear interpolation between them. The grey ramp runs from white to
 * near-black and the last ramp is a dark neutral ramp ending at pure black
 * (index 255). The grey keys make exact steps of 16 (255, 239, ... 15) and
 * the dark ones steps of 4 (60, 56, ... 0, never a grey value). All 256
 * colours are distinct, so colormap 0 is the identity.
 *
 * Colormap l scales each colour by (PAL_LIGHTS - l) / PAL_LIGHTS, rounded,
 * and maps it to the nearest palette entry by squared RGB distance, ties to
 * the lowest index: plain integer arithmetic, identical everywhere.
 */
#include "engine/core/pal.h"

#include <stdint.h>

#define PAL_KEY_SHADE 4

/* tint (shade 0), pure hue (shade PAL_KEY_SHADE), dark end (shade 15) */
static const uint8_t pal_keys[PAL_RAMPS][3][3] = {
	[PAL_GREY] = { { 255, 255, 255 }, { 191, 191, 191 }, { 15, 15, 15 } },
	[PAL_RED] = { { 255, 176, 176 }, { 224, 32, 32 }, { 32, 0, 0 } },
	[PAL_ORANGE] = { { 255, 208, 160 }, { 240, 128, 32 }, { 40, 16, 0 } },
	[PAL_YELLOW] = { { 255, 255, 176 }, { 240, 224, 40 }, { 40, 36, 0 } },
	[PAL_OLIVE] = { { 224, 224, 160 }, { 144, 144, 48 }, { 24, 24, 4 } },
	[PAL_GREEN] = { { 176, 255, 176 }, { 40, 192, 40 }, { 0, 28, 0 } },
	[PAL_TEAL] = { { 160, 240, 208 }, { 32, 160, 128 }, { 0, 24, 20 } },
	[PAL_CYAN] = { { 192, 255, 255 }, { 32, 208, 224 }, { 0, 28, 32 } },
	[PAL_SKY] = { { 200, 228, 255 }, { 96, 160, 240 }, { 8, 20, 40 } },
	[PAL_BLUE] = { { 176, 176, 255 }, { 40, 56, 224 }, { 0, 0, 36 } },
	[PAL_PURPLE] = { { 224, 176, 255 }, { 136, 48, 208 }, { 20, 0, 32 } },
	[PAL_PINK] = { { 255, 192, 232 }, { 232, 80, 168 }, { 36, 8, 24 } },
	[PAL_BROWN] = { { 224, 176, 128 }, { 144, 88, 40 }, { 24, 12, 4 } },
	[PAL_TAN] = { { 248, 232, 200 }, { 200, 168, 120 }, { 36, 28, 16 } },
	[PAL_SLATE] = { { 200, 208, 224 }, { 104, 120, 144 }, { 12, 16, 20 } },
	[PAL_BLACKRAMP] = { { 60, 60, 60 }, { 44, 44, 44 }, { 0, 0, 0 } },
};

/* a + (b - a) * num / den, rounded to nearest (num <= den, all small) */
static uint8_t pal_lerp(int a, int b, int num, int den)
{
	int v = a * den + (b - a) * num;

	return (uint8_t)((v + den / 2) / den);
}

static void pal_ramps(struct pal *p)
{
	for (int r = 0; r < PAL_RAMPS; r++) {
		for (int s = 0; s < PAL_SHADES; s++) {
			uint8_t *c = p->rgb[PAL_RGB(r, s)];

			for (int k = 0; k < 3; k++) {
				if (s <= PAL_KEY_SHADE)
					c[k] = pal_lerp(pal_keys[r][0][k], pal_keys[r][1][k], s,
							PAL_KEY_SHADE);
				else
					c[k] = pal_lerp(pal_keys[r][1][k], pal_keys[r][2][k],
							s - PAL_KEY_SHADE,
							PAL_SHADES - 1 - PAL_KEY_SHADE);
			}
		}
	}
}

uint8_t pal_nearest(const struct pal *p, int r, int g, int b)
{
	int32_t best = INT32_MAX;
	int besti = 0;

	for (int i = 0; i < 256; i++) {
		int32_t dr = p->rgb[i][0] - r;
		int32_t dg = p->rgb[i][1] - g;
		int32_t db = p->rgb[i][2] - b;
		int32_t d = dr * dr + dg * dg + db * db;

		if (d < best) {
			best = d;
			besti = i;
			if (d == 0)
				break;
		}
	}
	return (uint8_t)besti;
}

/* The palette's indices ordered by red, equal reds by index (a counting
 * sort), for the colormaps' 8,192 nearest-colour searches. */
struct pal_by_red {
	uint8_t idx[256];
	uint8_t red[256];
	uint16_t from[257];            /* first position of each red value */
};

static void pal_sort_red(const struct pal *p, struct pal_by_red *o)
{
	uint16_t at[256] = { 0 };

	for (int i = 0; i < 256; i++)
		at[p->rgb[i][0]]++;
	o->from[0] = 0;
	for (int v = 0; v < 256; v++)
		o->from[v + 1] = (uint16_t)(o->from[v] + at[v]);
	for (int v = 0; v < 256; v++)
		at[v] = o->from[v];
	for (int i = 0; i < 256; i++) {
		int k = at[p->rgb[i][0]]++;
		o->idx[k] = (uint8_t)i;
		o->red[k] = p->rgb[i][0];
	}
}

/* pal_nearest's answer (ties to the lowest index) from the entries in red
 * order, walking up and down from r: an entry whose red difference alone
 * squared exceeds the best distance so far is farther than the answer, and
 * so is every entry past it. About 20 tests a search instead of 256. */
static uint8_t pal_nearest_by_red(const struct pal *p, const struct pal_by_red *o, int r, int g,
				  int b)
{
	int32_t best = INT32_MAX;
	int besti = 256, start = o->from[r];

	for (int dir = 0; dir < 2; dir++) {
		for (int k = dir ? start - 1 : start; k >= 0 && k < 256; k += dir ? -1 : 1) {
			int i = o->idx[k];
			int32_t dr = o->red[k] - r;
			int32_t dg = p->rgb[i][1] - g;
			int32_t db = p->rgb[i][2] - b;
			int32_t d;

			if (dr * dr > best)
				break;
			d = dr * dr + dg * dg + db * db;
			if (d < best || (d == best && i < besti)) {
				best = d;
				besti = i;
			}
		}
	}
	return (uint8_t)besti;
}

void pal_make_colormaps(struct pal *p)
{
	struct pal_by_red o;

	pal_sort_red(p, &o);
	for (int l = 0; l < PAL_LIGHTS; l++) {
		int f = PAL_LIGHTS - l;

		for (int i = 0; i < 256; i++) {
			int r = (p->rgb[i][0] * f + PAL_LIGHTS / 2) / PAL_LIGHTS;
			int g = (p->rgb[i][1] * f + PAL_LIGHTS / 2) / PAL_LIGHTS;
			int b = (p->rgb[i][2] * f + PAL_LIGHTS / 2) / PAL_LIGHTS;

			p->cmap[l][i] = pal_nearest_by_red(p, &o, r, g, b);
		}
	}
}

void pal_builtin(struct pal *p)
{
	pal_ramps(p);
	pal_make_colormaps(p);
}
