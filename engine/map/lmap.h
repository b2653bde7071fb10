/*
 * lmap: shadowed light maps of point lights, computed once at load.
 *
 * Beyond Doom (the seed thesis): point lights placed in a map brighten
 * walls, floors and ceilings with distance, and walls block them. For every
 * line side and every sector floor and ceiling that some light can reach,
 * lmap_new computes a grid of texels (LMAP_TEXEL = 16 map units square;
 * doubled for a surface until it has at most LMAP_GRID_MAX texels, and for
 * every surface until all have at most LMAP_TEXELS_MAX, so memory stays
 * bounded; see lmap_grid.shift). A texel's value is a
 * colormap-level boost 0..PAL_LIGHTS-1: the drawers use level
 * max(0, level - boost) (docs/lights.md).
 *
 * Light of one light at a texel sample point at 3D distance d (both in
 * 1/16 map units, d = floor(sqrt(dx^2 + dy^2 + dz^2))), radius R and
 * intensity I (light units, the scale of sector light: 16 units = 4
 * colormap levels):
 *     c = d < R ? floor(I * (R - d)^2 / R^2) : 0
 * if the straight segment from the light to the point is clear, else 0.
 * A texel's boost = min(PAL_LIGHTS - 1, (sum of c over the lights) / 4).
 * The segment is blocked by a one-sided line it crosses or touches, and by
 * a two-sided line where, at the crossing, it passes below the higher floor
 * or above the lower ceiling of the two sectors (the 3D opening); two-sided
 * lines between sectors of equal floor and ceiling never block.
 *
 * Sample points: a flat texel's centre at the plane's height; a wall
 * texel's centre, moved 1 map unit off the wall into the side's sector.
 * When the centre is blocked, the four points a quarter texel from it
 * diagonally are tried in order (-,-), (+,-), (-,+), (+,+) and the first
 * clear one gives the value (no black seams where a texel's centre lies
 * behind a wall it only touches).
 *
 * Only the surfaces a light can reach get a grid: a floor below the light,
 * a ceiling above it, a side whose front faces it, within its radius.
 * Everything else samples as 0. Heights are those at load: surfaces that
 * move later sample their nearest texel (clamped).
 *
 * Integer-exact and deterministic: the same map and lights give the same
 * bytes (lmap_hash) on every compiler and CPU.
 */
#ifndef ARCADED_ENGINE_LMAP_H
#define ARCADED_ENGINE_LMAP_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"

struct lim_stop;
struct map;
struct map_thing;

#define LMAP_TEXEL_SHIFT 4             /* 16 map units */
#define LMAP_TEXEL (1 << LMAP_TEXEL_SHIFT)
#define LMAP_GRID_MAX 65536            /* texels per surface before coarsening */
#define LMAP_TEXELS_MAX (16u << 20)    /* texels in all before coarsening all */
#define LMAP_RADIUS_MAX 2048           /* map units */

/* Limits on one lmap_new (issue 13 item 8): 30,000 lights took 60 s
 * without them. A step is one test of whether a light reaches a surface,
 * one blockmap cell filled or crossed by a ray, one line tested against a
 * ray, and a texel's own work counts 8 (its five distances): about 10 ns
 * a step both on Freedoom and on the hostile maps, so the limit is about
 * 2 s. Freedoom's most lit maps: freedoom2 MAP28 has 116 lights (35 times
 * fewer than LMAP_MAX_LIGHTS), MAP18 takes the most steps, 15.7 million
 * (13 times fewer than LMAP_MAX_STEPS). LMAP_MAX_CELL_LINES bounds the
 * blockmap's lists (long lines over a big map cross many cells; 16 MB at
 * the limit). */
#define LMAP_MAX_LIGHTS 4096
#define LMAP_MAX_STEPS ((uint64_t)200 << 20)
#define LMAP_MAX_CELL_LINES (1u << 22)

/* Lights come from map things (lmap_lights_from_map): arcaded's light
 * thing (th.h: types TH_LIGHT_FIRST..TH_LIGHT_LAST encode radius 64..512,
 * intensity 32..255 and a colour; the colour is not used here, the boost
 * is brightness only), placed half way between the floor and the ceiling
 * of the sector it is in. */

struct lmap_light {
	fx_t x, y, z;                  /* 16.16 map units */
	int32_t intensity;             /* light units, 1..1024 */
	int32_t radius;                /* map units, 1..LMAP_RADIUS_MAX */
};

/* Flags of lmap_lights_from_map. */
#define LMAP_DECOR 1u   /* also Doom's light-giving decorations (th.h
			 * TH_DECOR with TH_LIGHT: lamps, candles,
			 * torches, burning barrels) as lights */

/* Collects the point lights of finished map m from its things (arcaded
 * light things, plus Doom decorations with LMAP_DECOR; docs/lights.md has
 * the table), in thing order, storing at most max into out (may be NULL
 * when max is 0). Returns how many there are in all. */
int lmap_lights_from_map(const struct map *m, unsigned flags, struct lmap_light *out, int max);

/* One surface's texels. Flats: row-major, t[row * w + col], texel (col,
 * row) covers map x in [x0 + col * T, x0 + (col + 1) * T) and y likewise
 * from y0, T = 1 << shift map units. Walls: column-major, t[col * h + row],
 * u (distance along the side from its start, map units) from x0 = 0 and
 * height z from y0 = the front sector's floor at load, upwards. */
struct lmap_grid {
	const uint8_t *t;
	int32_t x0, y0;                /* integer map units */
	int32_t w, h;                  /* texels, both >= 1 */
	int32_t shift;                 /* texel size 1 << shift map units */
};

struct lmap;

/* Computes the light maps of finished map m (borrowed only during the
 * call) for n lights (n 0 gives an empty, valid lmap). Returns 0, -EINVAL
 * (a light with intensity or radius out of range, n < 0), -E2BIG (more
 * than LMAP_MAX_LIGHTS lights, LMAP_MAX_STEPS steps or
 * LMAP_MAX_CELL_LINES blockmap entries; err says which and the limit),
 * -ECANCELED (stop said so; stop may be NULL, lim.h) or -ENOMEM. err may
 * be NULL. Owned by the caller: lmap_free. lmap_new is lmap_new_lim
 * without a stop hook or message. */
int lmap_new_lim(const struct map *m, const struct lmap_light *lights, int n,
		 const struct lim_stop *stop, struct lmap **out, char *err, size_t errlen);
int lmap_new(const struct map *m, const struct lmap_light *lights, int n, struct lmap **out);

/* NULL-safe. */
void lmap_free(struct lmap *lm);

/* The grid of a sector's floor (ceiling 0) or ceiling (ceiling 1), or of
 * side `side` (0 front, 1 back) of a line; NULL when no light reaches it
 * or the index is out of range. Valid until lmap_free. */
const struct lmap_grid *lmap_flat_grid(const struct lmap *lm, uint32_t sector, int ceiling);
const struct lmap_grid *lmap_wall_grid(const struct lmap *lm, uint32_t line, int side);

/* Texel value of a flat grid at map point (x, y) (16.16), the nearest
 * texel for points outside the grid. */
static inline int lmap_grid_flat_at(const struct lmap_grid *g, fx_t x, fx_t y)
{
	int32_t c = (fx_to_int(x) - g->x0) >> g->shift;
	int32_t r = (fx_to_int(y) - g->y0) >> g->shift;

	c = c < 0 ? 0 : c >= g->w ? g->w - 1 : c;
	r = r < 0 ? 0 : r >= g->h ? g->h - 1 : r;
	return g->t[(size_t)r * (size_t)g->w + (size_t)c];
}

/* The column of a wall grid at u (16.16 map units from the side's start),
 * h texels from the bottom up: the column drawer indexes it with
 * lmap_column_at. Clamped to the grid. */
static inline const uint8_t *lmap_grid_column(const struct lmap_grid *g, fx_t u)
{
	int32_t c = fx_to_int(u) >> g->shift;

	c = c < 0 ? 0 : c >= g->w ? g->w - 1 : c;
	return g->t + (size_t)c * (size_t)g->h;
}

/* Texel of column col (from lmap_grid_column of g) at height z (16.16). */
static inline int lmap_column_at(const struct lmap_grid *g, const uint8_t *col, fx_t z)
{
	int32_t r = (fx_to_int(z) - g->y0) >> g->shift;

	r = r < 0 ? 0 : r >= g->h ? g->h - 1 : r;
	return col[r];
}

/* Boost at a point of a floor/ceiling, or of a wall side at (u, z); 0 for
 * surfaces without a grid. The per-pixel convenience forms of the above. */
int lmap_flat(const struct lmap *lm, uint32_t sector, int ceiling, fx_t x, fx_t y);
int lmap_wall(const struct lmap *lm, uint32_t line, int side, fx_t u, fx_t z);

/* Figures of a built lmap. */
struct lmap_stats {
	uint32_t lights;               /* lights used */
	uint32_t grids;                /* surfaces with a grid */
	uint64_t texels;               /* texels over all grids */
	uint64_t rays;                 /* light-to-point visibility tests */
	size_t bytes;                  /* heap held by the lmap */
};

void lmap_get_stats(const struct lmap *lm, struct lmap_stats *st);

/* FNV-1a of every grid's position, size and texels, in sector then side
 * order: equal for equal light maps. */
uint64_t lmap_hash(const struct lmap *lm);

#endif
