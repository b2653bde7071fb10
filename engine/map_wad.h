/*
 * map_wad: Doom-format maps from a layered WAD set.
 *
 * A map is the marker lump (E1M1, MAP01, ...) followed by THINGS, LINEDEFS,
 * SIDEDEFS, VERTEXES, SEGS, SSECTORS, NODES, SECTORS (REJECT, BLOCKMAP
 * optional). Every count, offset and index is validated; an error names the
 * map, the lump and the entry ("E1M1: LINEDEFS entry 17: sidedef 900 out of
 * range (512 sidedefs)"). Texture and flat names are resolved against the
 * texture set; an unknown name becomes the fallback and is counted. A map
 * without (valid) NODES/SEGS/SSECTORS gets its BSP from the node builder.
 */
#ifndef ARCADED_ENGINE_MAP_WAD_H
#define ARCADED_ENGINE_MAP_WAD_H

#include <stddef.h>

struct map;
struct tex_set;
struct wad;

/* Loads map `name` (case-insensitive). 0, -ENOENT (no such map: err
 * lists the maps there are), -EINVAL (err says what is wrong) or -ENOMEM.
 * The map is the caller's: map_free. */
int map_load_wad(const struct wad *w, const struct tex_set *t, const char *name,
		 struct map **out, char *err, size_t errlen);

/* Stores up to max map names found in w (in lump order, each once) into
 * names; returns how many there are in all. */
int map_list_wad(const struct wad *w, char (*names)[9], int max);

#endif
