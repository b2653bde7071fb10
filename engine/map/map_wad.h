/*
 * map_wad: Doom-format maps from a layered WAD set.
 *
 * A map is the marker lump (E1M1, MAP01, ...) followed by THINGS, LINEDEFS,
 * SIDEDEFS, VERTEXES, SEGS, SSECTORS, NODES, SECTORS (REJECT, BLOCKMAP
 * optional). Every count, offset and index is validated; an error names the
 * map, the lump and the entry ("E1M1: LINEDEFS entry 17: sidedef 900 out of
 * range (512 sidedefs)"). Texture and flat names are resolved against the
 * texture set; an unknown name becomes the fallback (tex_set.fallback_tex
 * or fallback_flat) and is counted in map.missing_textures; "-" or an empty
 * name is texture 0. A map whose SEGS or SSECTORS are empty, whose NODES are
 * empty with more than one subsector, or whose NODES are in ZDoom's
 * extended formats (XNOD, ZNOD, XGLN, ...) gets its BSP from the node
 * builder; BSP lumps in Doom's format are used as they are, and any bad
 * entry in them is an error. REJECT and BLOCKMAP are not read.
 *
 * Normalised as Doom behaves, not refused: a linedef's two-sided flag is
 * set exactly when it has a back sidedef; a sector whose ceiling is below
 * its floor gets its floor lowered to the ceiling; a thing beyond
 * MAP_COORD_MAX is left out. Sky ceilings keep their flat (tex_set.sky_flat
 * tells the renderer). Hexen-format and UDMF maps are refused (-EINVAL).
 */
#ifndef ARCADED_ENGINE_MAP_WAD_H
#define ARCADED_ENGINE_MAP_WAD_H

#include <stddef.h>
#include <stdint.h>

struct lim_stop;
struct map;
struct tex_set;
struct wad;

/* Records a map lump may hold (THINGS ... SECTORS): Doom's 16-bit indices
 * reach no further, and Freedoom's largest lump holds a few ten thousand. */
#define MW_MAX_RECORDS 65536

/* Loads map `name` (case-insensitive). 0, -ENOENT (no such map: err
 * lists the maps there are), -EINVAL (err says what is wrong), -E2BIG (a
 * limit: MW_MAX_RECORDS, or the node builder's, nb.h; err names the file,
 * map, lump and limit), -ECANCELED (stop said so, while the node builder
 * ran; stop may be NULL, lim.h) or -ENOMEM. The map is the caller's
 * (map_free) and owns all its data: the WADs may be freed after loading.
 * map_load_wad is map_load_wad_lim without a stop hook. */
int map_load_wad_lim(const struct wad *w, const struct tex_set *t, const char *name,
		     const struct lim_stop *stop, struct map **out, char *err, size_t errlen);
int map_load_wad(const struct wad *w, const struct tex_set *t, const char *name,
		 struct map **out, char *err, size_t errlen);

/* Stores up to max map names found in w (in lump order, each once) into
 * names; returns how many there are in all, or -ENOMEM. O(n log n) in the
 * number of markers. */
int map_list_wad(const struct wad *w, char (*names)[9], int max);

/* Writes n maps (names[i], up to 8 chars, e.g. "MAP01") into one new PWAD
 * in Doom's format, texture and flat numbers written as the names they have
 * in t. Only the vertices the lines use are written (a node builder's split
 * points are not) and SEGS, SSECTORS and NODES are empty, so the loader
 * builds the BSP again (the same one: nb_build is deterministic); REJECT
 * and BLOCKMAP are empty. Every coordinate, height and offset must be whole
 * units within int16, every index below 65535, every texture and flat in t:
 * else -EINVAL (err names the map and entry). *out is the caller's (free);
 * 0, -EINVAL or -ENOMEM. */
int map_wad_write(const struct map *const *maps, const char *const *names, int n,
		  const struct tex_set *t, uint8_t **out, size_t *len, char *err, size_t errlen);

#endif
