/*
 * r_local: the render context and the functions the renderer's stages share.
 * Internal to engine/r_*.c; nothing outside the renderer includes it.
 *
 * Stages (Doom's split): r_main.c sets up the view and owns the geometry
 * helpers (view transform, clipping, projection); r_bsp.c walks the BSP
 * front to back and keeps the solid-column list; r_seg.c turns one seg into
 * wall, ceiling and floor column runs; r_draw.c is the only code that writes
 * frame pixels.
 *
 * Number formats (all integer):
 *  - map and view-space coordinates: 16.16 map units, view space in int64;
 *  - screen x: 16.16 pixels (int64), 0 = left edge of column 0;
 *  - scale (pixels per map unit at a column, focal / depth): 32.32 in int64
 *    while stepping, 16.16 where it multiplies heights;
 *  - screen y of an edge: 32.32 pixels (int64), 0 = top edge of row 0.
 * Fill rule: a column or row is covered when its pixel centre (x + 0.5 or
 * y + 0.5) lies in [start, end) of the projected span.
 */
#ifndef ARCADED_ENGINE_R_LOCAL_H
#define ARCADED_ENGINE_R_LOCAL_H

#include <stdint.h>

#include "engine/fx.h"
#include "engine/map.h"
#include "engine/pal.h"
#include "engine/r_main.h"

#define R_MAX_DIM 4096

/* Near plane: nothing closer than this depth (map units, 16.16) is drawn.
 * The sim keeps the eye 16 units from solid walls, so it only shows when the
 * eye is within a quarter unit of a portal or outside the map. */
#define R_NEAR (FX_ONE / 4)

/* Distance fade, Doom's: a surface at depth z is R_FADE_DIST / z colormap
 * levels brighter than its sector's light alone gives, at most R_FADE_MAX. */
#define R_FADE_DIST 1280
#define R_FADE_MAX 24

/* Fake contrast: east-west walls one Doom light level (16 of 255) brighter,
 * north-south walls one darker. */
#define R_CONTRAST 16

/* A view-space point: l to the right of the view axis, d along it. */
struct r_vpt {
	int64_t l, d;
};

/* A run of fully occluded columns [first, last]. */
struct r_range {
	int first, last;
};

struct r_ctx {
	int w, h;
	const struct pal *pal;          /* borrowed */

	/* per column: rows [ceilclip + 1, floorclip - 1] are still unwritten;
	 * everything outside that interval has been written exactly once */
	int16_t *ceilclip, *floorclip;

	/* sorted, disjoint, non-adjacent occluded column runs, with sentinels
	 * below column 0 and past column w - 1 (Doom's solidsegs) */
	struct r_range *solid;
	int nsolid, maxsolid;

	/* per row: |2y + 1 - cy2|, twice the distance of the row's centre from
	 * the horizon; a plane's depth at row y is proportional to 1 / rowv[y] */
	int32_t *rowv;
	int rowv_cy2;                   /* the cy2 rowv was built for */

	int64_t wall_kq;                /* wall fade = (scale16 * wall_kq) >> 32 */

	/* the frame being drawn (valid during r_render only) */
	const struct map *map;
	uint8_t *px;
	int pitch;
	fx_t ex, ey, ez;                /* eye, x/y clamped to MAP_COORD_MAX */
	fx_t vcos, vsin;
	int cy2;                        /* twice the horizon row: h + 2 * shear */
	int64_t cy32;                   /* horizon, 32.32 pixels */
	struct r_stats st;
};

/* r_main.c: geometry */
void r_to_view(const struct r_ctx *r, fx_t x, fx_t y, struct r_vpt *p);
/* Clips the segment a-b to the visible region (depth >= R_NEAR, inside the
 * 90-degree frustum). Returns 0 when nothing is left. */
int r_clip_segment(struct r_vpt *a, struct r_vpt *b);
/* Clips the convex polygon v[0..n-1] (n <= 4) to the visible region in
 * place; v must have room for R_POLY_MAX points. Returns the new count. */
#define R_POLY_MAX 32
int r_clip_polygon(struct r_vpt *v, int n);
/* Screen x (16.16) of a clipped point: in [0, w * FX_ONE]. */
int64_t r_project_x(const struct r_ctx *r, const struct r_vpt *p);
/* First column whose centre is at or right of screen x sx (16.16). */
static inline int r_col_at(int64_t sx)
{
	return (int)((sx - FX_HALF + FX_ONE - 1) >> FX_SHIFT);
}

/* r_bsp.c: traversal and the solid-column list */
void r_bsp_render(struct r_ctx *r);
void r_solid_reset(struct r_ctx *r);
/* Marks columns [x1, x2] occluded. */
void r_solid_add(struct r_ctx *r, int x1, int x2);
/* 1 when every column of [x1, x2] is occluded. */
int r_solid_covers(const struct r_ctx *r, int x1, int x2);

/* r_seg.c: draws the parts of seg sg visible in columns not yet occluded,
 * then marks the columns it closed. */
void r_seg_add(struct r_ctx *r, const struct map_seg *sg);

/* r_draw.c: the only writers of frame pixels. Rows y1..y2 inclusive of
 * column x; nothing when y2 < y1. */
void r_draw_fill(struct r_ctx *r, int x, int y1, int y2, uint8_t colour);
/* A floor or ceiling run: palette index tex lit per row, level
 * base - min(R_FADE_MAX, (rowv[y] * q) >> 32), clamped at 0. */
void r_draw_plane(struct r_ctx *r, int x, int y1, int y2, uint8_t tex, int base, int64_t q);
/* Fills every still unwritten pixel with PAL_BLACK (counted as empty). */
void r_draw_finish(struct r_ctx *r);

#endif
