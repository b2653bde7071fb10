/*
 * tex_paint: the drawing helpers the built-in set's files share
 * (tex_builtin.c for walls and flats, tex_bspr.c for sprites); not for
 * other modules. Integer only: every picture is the same on every build.
 */
#ifndef ARCADED_ENGINE_TEX_PAINT_H
#define ARCADED_ENGINE_TEX_PAINT_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/pal.h"
#include "engine/map/tex.h"

/* A 32-bit hash of two coordinates and a seed (an avalanche mix). */
static inline uint32_t tp_hash(uint32_t a, uint32_t b, uint32_t seed)
{
	uint32_t h = a * 0x9E3779B1u ^ b * 0x85EBCA77u ^ seed * 0xC2B2AE3Du;

	h ^= h >> 15;
	h *= 0x2C1B3C6Du;
	h ^= h >> 12;
	h *= 0x297A2D39u;
	h ^= h >> 15;
	return h;
}

/* Palette index of a ramp's shade (pal.h), the shade clamped to the ramp. */
static inline uint8_t tp_c(int ramp, int shade)
{
	return PAL_RGB(ramp, shade < 0 ? 0 : shade > PAL_SHADES - 1 ? PAL_SHADES - 1 : shade);
}

/* Sets pixel (x, y) of p (column-major) and marks it opaque; outside p is
 * ignored, so shapes may run over the edges. */
static inline void tp_set(struct tex_pic *p, int x, int y, uint8_t c)
{
	if (x < 0 || y < 0 || x >= p->w || y >= p->h)
		return;
	p->px[(size_t)x * (size_t)p->h + (size_t)y] = c;
	if (p->opaque)
		p->opaque[(size_t)x * (size_t)p->h + (size_t)y] = 1;
}

static inline void tp_rect(struct tex_pic *p, int x0, int y0, int w, int h, uint8_t c)
{
	for (int y = y0; y < y0 + h; y++)
		for (int x = x0; x < x0 + w; x++)
			tp_set(p, x, y, c);
}

#endif
