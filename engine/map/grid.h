/*
 * grid: Wolfenstein-style ASCII tile maps imported into the level model.
 *
 * A grid map is text: a legend that defines tile characters, a line "map",
 * then rows of tile characters (the first row is the north edge). One tile
 * is GRID_TILE (64) map units square. The import turns every 4-connected
 * region of open tiles with the same surface (floor, ceiling, light, flats,
 * edge texture, special, tag) into one sector, puts a one-sided wall where
 * an open tile meets a wall tile, a two-sided line where two different open
 * regions meet (steps, windows, lintels), merges collinear edges of the same
 * kind into one line, places things at tile centres, and finishes the map
 * with map_finish (the node builder makes its BSP), so a grid map goes
 * through the same sim and renderer as any other. Syntax: docs/grid.md.
 *
 * Pure engine code: text in, map out, no I/O. Errors name the place:
 * "grid.txt:7:12: unknown tile 'x'".
 */
#ifndef ARCADED_ENGINE_GRID_H
#define ARCADED_ENGINE_GRID_H

#include <stddef.h>

struct lim_stop;
struct map;
struct tex_set;

#define GRID_TILE 64                   /* map units per tile */
#define GRID_MAX_DIM 255               /* rows and columns: keeps coordinates
					* inside MAP_COORD_MAX */

/* Texture and flat names to numbers, as the caller's texture set numbers
 * them (tex_find / tex_find_flat wrapped; map.h "Textures"). Each returns
 * the number (>= 0) or a negative value for an unknown name, which the
 * parser reports as an error at the name ("unknown texture 'FOO'"); a
 * caller that prefers Doom's fallback behaviour returns its fallback
 * number instead and counts. A token made only of digits is always taken
 * as a number and never looked up. Either pointer, or the whole struct, may
 * be NULL: then only numbers are accepted. */
struct grid_names {
	void *ctx;
	int (*wall)(void *ctx, const char *name);
	int (*flat)(void *ctx, const char *name);
};

/* Fills n to look names up in texture set t (tex_find, tex_find_flat;
 * borrowed: t must outlive the parse). An unknown name is an error. */
void grid_names_from_tex(struct grid_names *n, const struct tex_set *t);

/* Parses len bytes of text (need not be NUL-terminated) named `name` (for
 * messages, e.g. the file name) into a new finished map. names may be NULL.
 * Returns 0, -EINVAL with err holding "name:line:column: what is wrong"
 * (line and column 1-based; "name: ..." for whole-map errors such as a
 * missing player start), -E2BIG or -ECANCELED (the node builder's limits,
 * nb.h, and the stop hook, lim.h, which may be NULL) or -ENOMEM. err may
 * be NULL. The map is the caller's: map_free. grid_parse is
 * grid_parse_lim without a stop hook. */
int grid_parse_lim(const char *text, size_t len, const char *name, const struct grid_names *names,
		   const struct lim_stop *stop, struct map **out, char *err, size_t errlen);
int grid_parse(const char *text, size_t len, const char *name, const struct grid_names *names,
	       struct map **out, char *err, size_t errlen);

/* The built-in grid level's text (levels/grid1.txt is the same text) and
 * its length. Its textures and flats are names of the built-in set
 * (tex_builtin): parse it with grid_names_from_tex. */
const char *grid_builtin_text(size_t *len);

#endif
