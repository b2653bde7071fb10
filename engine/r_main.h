/*
 * r_main: the software renderer's public interface.
 *
 * Doom lineage: BSP front-to-back traversal, solid-segment clipping, wall
 * columns with per-column upper/lower clip, floors and ceilings, light
 * through colormaps with distance fade. Integer-exact: the same map, view
 * and size give the same frame bytes on every compiler and CPU.
 *
 * A render context owns all per-resolution buffers; several may coexist.
 * The frame is row-major 8-bit palette indices.
 */
#ifndef ARCADED_ENGINE_R_MAIN_H
#define ARCADED_ENGINE_R_MAIN_H

#include <stdint.h>

#include "engine/fx.h"

struct map;
struct pal;

struct r_view {
	fx_t x, y, z;                  /* eye position; z is eye height */
	ang_t angle;                   /* view direction */
	int32_t shear;                 /* vertical look: the horizon moves down
					* by shear pixels (clamped to +/-h) */
};

struct r_frame {
	uint8_t *px;                   /* w*h indices, row stride `pitch` bytes */
	int w, h, pitch;
};

/* Counters of the last frame, for tests and benchmarks. */
struct r_stats {
	uint32_t nodes, subsectors, segs, columns;
	uint32_t pixels_written;       /* each pixel is written exactly once */
	uint32_t pixels_empty;         /* of those, pixels no surface covered
					* (PAL_BLACK): 0 inside a closed map */
};

struct r_ctx;

/* New context for frames of w x h (1..4096 each), using palette/colormaps
 * pal (borrowed, must outlive the context). Returns 0, -EINVAL or -ENOMEM. */
int r_new(int w, int h, const struct pal *pal, struct r_ctx **out);

/* NULL-safe. */
void r_free(struct r_ctx *r);

/* Draws map m from view v into f (f->w, f->h must equal the context's).
 * Every pixel of f is written. Never fails on a finished map. */
void r_render(struct r_ctx *r, const struct map *m, const struct r_view *v,
	      struct r_frame *f);

/* Counters of the last r_render. */
void r_get_stats(const struct r_ctx *r, struct r_stats *st);

#endif
