/*
 * xc_move: the cross-check's mover views (docs/crosscheck.md): door
 * sectors half open and lift sectors mid-travel, as Doom's movers leave
 * them in play, each seen from in front. Test code (floating point).
 */
#ifndef XC_MOVE_H
#define XC_MOVE_H

#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/map/map.h"
#include "engine/render/r_main.h"

struct xcm_view {
	struct r_view v;
	uint32_t sector;               /* the mover's sector */
	char kind;                     /* 'd' door (ceiling moved), 'l' lift (floor moved) */
	int quarter;                   /* 1..3: how far along its travel, in quarters */
	fx_t floor_h, ceil_h;          /* the sector's heights for this view */
};

/* The mover views of map m into out (at most max), in line and sector
 * order; returns how many there are (may exceed max: only max are
 * written). */
int xcm_views(const struct map *m, struct xcm_view *out, int max);

/* The eye's sector when (x, y) is a good place to look at (mx, my) from,
 * else MAP_NONE: in a sector other than mover (MAP_NONE: any) at least 56
 * units tall, at least 1 unit from every line and 16 from one-sided ones,
 * clear of things, no one-sided line between the two points. Shared with
 * the mesh views (xc_mesh.c). */
uint32_t xcm_eye(const struct map *m, uint32_t mover, double x, double y, double mx, double my);

/* From xcheck.c, shared by its random views and these: the squared
 * distance from (x, y) to line l, and whether (x, y) is clear of every
 * solid thing by a player's radius (1) or not (0). */
double xc_line_dist(const struct map *m, const struct map_line *l, double x, double y);
int xc_clear_of_things(const struct map *m, double x, double y);

#endif
