/*
 * map: the level model shared by the sim and the renderer.
 *
 * Doom's model: sectors are areas with floor and ceiling heights, a light
 * level and flat "textures"; lines are walls between two vertices with one
 * or two sides; each side faces one sector. A two-sided line is a portal
 * whose upper and lower parts are drawn where the neighbouring sector's
 * ceiling is lower or its floor is higher (windows, steps). A sector's
 * polygon is the set of lines whose sides face it; it may be non-convex and
 * have holes.
 *
 * The BSP (segs, subsectors, nodes) is built by the project's node builder
 * (nb_build, map_finish) when a map has none, or taken from the map file.
 *
 * Textures: a texture number indexes the texture set the map is drawn with
 * (tex.h): side textures into tex_set.textures, 0 meaning "no texture"
 * (Doom's "-"); sector flats into tex_set.flats. A map loaded from a WAD
 * is numbered for the set it was loaded with (map_load_wad); the built-in
 * levels for tex_builtin's set (lvl_builtin below). Maps made in code with
 * palette indices as numbers are drawn with r_pal_set_new's set (r_main.h).
 *
 * Coordinates: x east, y north, map units in 16.16; angles counter-clockwise
 * from east (ANG90 = north).
 */
#ifndef ARCADED_ENGINE_MAP_H
#define ARCADED_ENGINE_MAP_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"

#define MAP_NONE UINT32_MAX           /* absent index (no back side, ...) */

/* Largest vertex and thing coordinate magnitude (16.16): just under 16384
 * map units (Doom levels and Freedoom stay well inside). Differences of two
 * coordinates then fit fx_t and cross products of differences fit int64, so
 * every geometric test is exact 64-bit arithmetic. map_finish enforces it. */
#define MAP_COORD_MAX ((fx_t)((1 << 30) - 1))

/* Largest floor and ceiling height magnitude: 16383 map units (Freedoom's
 * heights stay within -1072..1984). The difference of two heights plus the
 * view height (41) and a thing's height then fits fx_t, which the sim's
 * eye height (viewz = floor + 41) and the renderer's height differences
 * need; Doom's int16 heights go up to 32767 and would overflow them.
 * map_finish enforces it; grid maps have the same bound. */
#define MAP_HEIGHT_MAX (16383 * FX_ONE)
#define MAP_NF_SUBSECTOR 0x80000000u  /* node child flag: a subsector index */

/* Line flags, Doom values. */
#define ML_BLOCKING 0x0001
#define ML_BLOCKMONSTERS 0x0002
#define ML_TWOSIDED 0x0004
#define ML_DONTPEGTOP 0x0008
#define ML_DONTPEGBOTTOM 0x0010

/* Bounding box order, Doom's. */
enum { BOX_TOP, BOX_BOTTOM, BOX_LEFT, BOX_RIGHT };

struct lim_stop;

struct map_vertex {
	fx_t x, y;
};

struct map_sector {
	fx_t floor_h, ceil_h;
	uint16_t floor_tex, ceil_tex;  /* see "Textures" above */
	uint8_t light;                 /* 0 (dark) .. 255 (full bright) */
	uint16_t special, tag;
};

struct map_side {
	fx_t xoff, yoff;
	uint16_t top_tex, mid_tex, bot_tex;
	uint32_t sector;
};

struct map_line {
	uint32_t v1, v2;
	uint16_t flags, special, tag;
	uint32_t side[2];              /* side[0] right/front; side[1] MAP_NONE if one-sided */
};

/* A seg is the part of a line's side that lies in one subsector. */
struct map_seg {
	uint32_t v1, v2;               /* may be vertices made by the node builder */
	ang_t angle;                   /* direction v1 -> v2 */
	fx_t offset;                   /* distance from the line's start along the side */
	uint32_t line;
	uint8_t side;                  /* 0: front side of line, 1: back side */
	uint32_t front, back;          /* sectors; back MAP_NONE for one-sided */
};

/* A convex leaf of the BSP: a run of segs in map.segs. */
struct map_subsector {
	uint32_t first_seg, num_segs;
	uint32_t sector;
};

/* A partition line (x,y)+(dx,dy); child[0] is the right (front) side,
 * child[1] the left (back) side; bbox[i] bounds child[i]. A child with
 * MAP_NF_SUBSECTOR set is a subsector index. */
struct map_node {
	fx_t x, y, dx, dy;
	fx_t bbox[2][4];
	uint32_t child[2];
};

struct map_thing {
	fx_t x, y;
	ang_t angle;
	uint16_t type, flags;
};

struct map {
	char name[9];
	struct map_vertex *vertices;
	struct map_sector *sectors;
	struct map_side *sides;
	struct map_line *lines;
	struct map_seg *segs;
	struct map_subsector *subsectors;
	struct map_node *nodes;
	struct map_thing *things;
	uint32_t num_vertices, num_sectors, num_sides, num_lines;
	uint32_t num_segs, num_subsectors, num_nodes, num_things;
	uint64_t content_hash;         /* over the level geometry and things */
	uint32_t missing_textures;     /* texture/flat names a loader could not resolve
					* (drawn as the fallback; map_wad.h); 0 for maps
					* built in code. Not part of content_hash. */
	/* Derived by map_finish (not part of content_hash), for the game's
	 * sector specials: the lines bordering each sector, in line order, a
	 * line once even when both its sides face the sector. Sector i's
	 * lines are sec_lines[sec_first[i] .. sec_first[i + 1] - 1]. */
	uint32_t *sec_first;           /* num_sectors + 1 entries */
	uint32_t *sec_lines;
	uint32_t *spec_lines;          /* the lines with a special, in order */
	uint32_t num_spec_lines;
	/* Also by map_finish: the sector each thing stands in
	 * (map_point_sector of its position), so that what draws the
	 * decorations every frame need not descend the BSP for each. */
	uint32_t *thing_sec;           /* num_thing_sec entries: num_things when
					* map_finish ran */
	uint32_t num_thing_sec;
	/* Height in map units of every wall texture of the set the map was
	 * drawn with (tex_map_heights, tex.h), for the floors that rise by
	 * their lower texture's height; NULL when not given (64 is used). */
	uint16_t *tex_h;
	uint32_t num_tex_h;
};

/* Allocates an empty map with room for the given numbers of level objects
 * (BSP arrays are left empty). Returns 0 or -ENOMEM. The caller fills the
 * arrays, then calls map_finish. Owned by the caller: map_free. */
int map_alloc(struct map **out, uint32_t vertices, uint32_t sectors, uint32_t sides,
	      uint32_t lines, uint32_t things);

/* Validates every index and value (naming the first bad entry in err, e.g.
 * "line 12: side[1] 40 out of range (32 sides)"): at least one sector and
 * line; vertex and thing coordinates within MAP_COORD_MAX; floor and
 * ceiling heights within MAP_HEIGHT_MAX, no ceiling below its floor; side
 * sectors; line vertices, zero length, side indices, and ML_TWOSIDED set
 * exactly when side[1] exists. Then computes content_hash (see below),
 * builds the BSP with nb_build when the map has neither nodes nor
 * subsectors, and validates the BSP (seg vertices, lines, sides and
 * sectors; subsector seg ranges and sectors; node partitions, and children
 * that are subsectors or nodes listed before their parent, so the root is
 * the last node; no node or subsector reached twice from the root, so the
 * BSP is a tree and every walk of it is linear; no nodes means exactly one
 * subsector). err may be NULL. Returns 0, -EINVAL (err says why), -E2BIG
 * or -ECANCELED (the node builder's limits and stop hook: nb.h) or
 * -ENOMEM. stop (may be NULL) is polled by the node builder; map_finish
 * is map_finish_lim without one.
 *
 * Then fills the sector line lists (sec_first, sec_lines), the list of
 * lines with a special (spec_lines) and each thing's sector (thing_sec).
 *
 * content_hash: FNV-1a (hash.h) of the counts, then every field of every
 * vertex, sector, side, line and thing in that order, taken before the node
 * builder appends split vertices. Not the name, not the BSP. */
int map_finish_lim(struct map *m, const struct lim_stop *stop, char *err, size_t errlen);
int map_finish(struct map *m, char *err, size_t errlen);

/* The lines bordering sector `sec` of a finished map: *n of them from the
 * returned pointer (line indices, ascending). */
static inline const uint32_t *map_sector_lines(const struct map *m, uint32_t sec, uint32_t *n)
{
	*n = m->sec_first[sec + 1] - m->sec_first[sec];
	return m->sec_lines + m->sec_first[sec];
}

/* NULL-safe. Frees the map and all of its arrays. */
void map_free(struct map *m);

/* Subsector containing (x, y), by walking the BSP from the root (the last
 * node); a map without nodes has one subsector, 0 (Doom's convention).
 * Never fails on a finished map. */
uint32_t map_point_subsector(const struct map *m, fx_t x, fx_t y);

/* Sector containing (x, y). */
static inline uint32_t map_point_sector(const struct map *m, fx_t x, fx_t y)
{
	return m->subsectors[map_point_subsector(m, x, y)].sector;
}

/* Which side of node n the point is on: 0 front (right), 1 back (left).
 * Exact integer test, shared by the sim, the renderer and the node builder:
 * the sign of the 64-bit cross product dx*(y-n.y) - dy*(x-n.x); negative is
 * right (front), positive left (back), and a point exactly on the partition
 * line is on the FRONT side. The point is first clamped to +/-MAP_COORD_MAX
 * (only points outside every map can change side by that). */
int map_point_on_side(fx_t x, fx_t y, const struct map_node *n);

#endif
