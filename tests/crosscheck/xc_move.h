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

/* From xcheck.c, shared by its random views and these: the squared
 * distance from (x, y) to line l, and whether (x, y) is clear of every
 * solid thing by a player's radius (1) or not (0). */
double xc_line_dist(const struct map *m, const struct map_line *l, double x, double y);
int xc_clear_of_things(const struct map *m, double x, double y);

#endif
