/*
 * xc_mesh: the cross-check's mesh views (docs/crosscheck.md): each thing
 * the game draws as a built-in mesh (keys, the floor lamp) seen from
 * around it, turned as at a tick of its own. Test code (floating point).
 */
#ifndef XC_MESH_H
#define XC_MESH_H

#include <stdint.h>

#include "engine/map/map.h"
#include "engine/render/r_main.h"

struct xcx_view {
	struct r_view v;
	int sprite;                    /* the mesh's index in the sprite list */
	uint32_t tick;                 /* the tick whose turn the meshes show */
};

/* The mesh views of map m whose things are spr[0..nspr-1] (r_map_things):
 * for every mesh, up to XCX_PER_MESH points around it (alternately 96 and
 * 160 units out, 45 degrees apart, off the axes) from which xcm_eye allows
 * a look at it, eye 41 above the floor, looking at its axis, no shear,
 * each with its own tick. Writes at most max into out and returns how
 * many there are (may exceed max). */
int xcx_views(const struct map *m, const struct r_sprite *spr, int nspr, struct xcx_view *out,
	      int max);

#define XCX_PER_MESH 8

#endif
