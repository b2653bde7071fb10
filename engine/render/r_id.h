/*
 * r_id: surface ids, which surface a pixel of a frame shows. Both renderers
 * write them on request (r_set_idbuf for the software renderer, rgl_set_idbuf
 * for the OSMesa one in engine/gl/), so that their visibility can be compared
 * pixel by pixel (tests/crosscheck/, docs/crosscheck.md).
 *
 * An id is 32 bits: the kind in the top four bits, an index below (28 bits;
 * the OSMesa renderer carries 20 of them through its colour buffer, enough
 * for a million line sides). Id 0 is "no surface".
 */
#ifndef ARCADED_ENGINE_R_ID_H
#define ARCADED_ENGINE_R_ID_H

#include <stdint.h>

#define R_ID_KIND_SHIFT 28
#define R_ID_INDEX_MASK 0x0fffffffu

enum r_id_kind {
	R_IDK_NONE,             /* no surface: the black fill (id 0) */
	R_IDK_SKY,              /* the sky; index 0 */
	R_IDK_FLOOR,            /* index: a sector whose floor has the pixel's
				 * height, flat and light (the software renderer's
				 * visplanes merge sectors that look the same) */
	R_IDK_CEIL,             /* the same for ceilings */
	R_IDK_UPPER,            /* wall parts; index: line * 2 + side */
	R_IDK_MIDDLE,           /* a one-sided wall (drawn black without texture) */
	R_IDK_LOWER,
	R_IDK_MASKED,           /* a masked middle texture; line * 2 + side */
	R_IDK_SPRITE,           /* index in the caller's sprite list */
	R_IDK_BACK,             /* a floor or ceiling seen from behind, filled
				 * black; index: the sector */
	R_IDK_COUNT
};

static inline uint32_t r_id(enum r_id_kind kind, uint32_t index)
{
	return ((uint32_t)kind << R_ID_KIND_SHIFT) | (index & R_ID_INDEX_MASK);
}

static inline enum r_id_kind r_id_kind(uint32_t id)
{
	return (enum r_id_kind)(id >> R_ID_KIND_SHIFT);
}

static inline uint32_t r_id_index(uint32_t id)
{
	return id & R_ID_INDEX_MASK;
}

#endif
