/*
 * pal: the 256-colour palette and the light tables (colormaps).
 *
 * The renderer draws palette indices; light is a lookup through one of
 * PAL_LIGHTS colormaps (0 brightest .. PAL_LIGHTS-1 darkest), as in Doom.
 * The display converts indices to panel pixels with one 256-entry table.
 */
#ifndef ARCADED_ENGINE_PAL_H
#define ARCADED_ENGINE_PAL_H

#include <stdint.h>

#define PAL_LIGHTS 32

struct pal {
	uint8_t rgb[256][3];
	uint8_t cmap[PAL_LIGHTS][256];
};

/* Fills p with the project's built-in palette and its colormaps (computed
 * with integer nearest-colour search: deterministic). */
void pal_builtin(struct pal *p);

/* Fills p->cmap from p->rgb: colormap l scales each colour by
 * (PAL_LIGHTS - l) / PAL_LIGHTS, rounded, and maps it to the nearest
 * palette entry by squared RGB distance, ties to the lowest index. For a
 * palette loaded without light tables (a WAD without COLORMAP). */
void pal_make_colormaps(struct pal *p);

/* Index of the colour of p->rgb nearest to (r, g, b) by squared RGB
 * distance, ties to the lowest index. */
uint8_t pal_nearest(const struct pal *p, int r, int g, int b);

/* Layout of the built-in palette: 16 ramps of 16 shades. Index
 * PAL_RGB(ramp, shade) with shade 0 the brightest and 15 the darkest of
 * that hue. Index 0 (PAL_GREY ramp, shade 0) is white and index 15 is
 * near-black; index 255 is pure black, used for letterbox and clear. Built-in
 * content names its colours this way. */
enum pal_ramp {
	PAL_GREY, PAL_RED, PAL_ORANGE, PAL_YELLOW, PAL_OLIVE, PAL_GREEN, PAL_TEAL, PAL_CYAN,
	PAL_SKY, PAL_BLUE, PAL_PURPLE, PAL_PINK, PAL_BROWN, PAL_TAN, PAL_SLATE, PAL_BLACKRAMP,
	PAL_RAMPS
};
#define PAL_SHADES 16
#define PAL_RGB(ramp, shade) ((uint8_t)((ramp) * PAL_SHADES + (shade)))
#define PAL_BLACK 255

#endif
