/*
 * rgl_local: the OSMesa renderer's context and what its two files share.
 * Internal to engine/gl/. rgl.c owns OSMesa, GL state, textures, the
 * passes and the per-pixel resolve (the only file including GL headers);
 * rgl_geo.c turns the map, view and sprites into triangles (the
 * subsectors' polygons, walls, sprites) with plain floating point.
 */
#ifndef ARCADED_ENGINE_GL_R_GL_LOCAL_H
#define ARCADED_ENGINE_GL_R_GL_LOCAL_H

#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/gl/rgl.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"

/* Mirrors of the software renderer's constants (engine/render/r_local.h), which
 * define the picture both renderers must draw. */
#define RGL_NEAR 0.25                   /* R_NEAR: near plane, map units */
#define RGL_FADE_DIST 1280              /* R_FADE_DIST */
#define RGL_FADE_MAX 24                 /* R_FADE_MAX */
#define RGL_CONTRAST 16                 /* R_CONTRAST */
#define RGL_SPR_NEAR (4 * FX_ONE)       /* R_SPR_NEAR */
#define RGL_SKY_SHIFT 22                /* R_SKY_SHIFT, R_SKY_MID, R_SKY_COLS */
#define RGL_SKY_MID 100
#define RGL_SKY_COLS 256
#define RGL_FB_SIZE 64                  /* R_FB_SIZE: the fallback checker */

/* What the colour pass writes in the blue channel: how the resolve turns
 * the red channel (a texel's palette index) into the frame's byte. */
enum rgl_mode {
	RGL_MODE_LIT,                   /* colormap green - fade(depth) */
	RGL_MODE_SKY,                   /* the sky texel of this pixel */
	RGL_MODE_RAW,                   /* the index itself (black fill) */
	RGL_MODE_FIXED,                 /* colormap green (sprites: their level
					 * is the same over the picture) */
	RGL_MODE_NONE = 255             /* nothing drawn: black */
};

/* A texture a triangle uses: kind in the top four bits, index below; 0 is
 * none (untextured). */
enum rgl_texkind {
	RGL_TEX_NONE,
	RGL_TEX_WALL,                   /* tex_set.textures[index] */
	RGL_TEX_FLAT,                   /* tex_set.flats[index] */
	RGL_TEX_SPRITE,                 /* tex_set.sprpics[index] */
	RGL_TEX_FBWALL,                 /* the fallback checker */
	RGL_TEX_FBFLAT
};
#define RGL_TEXREF(kind, index) (((uint32_t)(kind) << 28) | (uint32_t)(index))

/* Which passes draw a run of triangles (rgl.c): the world pass draws
 * planes, decals, walls and masked middles; then, with the depth buffer
 * cleared, the sprite pass draws silhouettes and masked middles into the
 * depth buffer only, and the sprites and meshes against it. Masked middles and
 * sprites are alpha-tested, their textures clamped vertically (sprites
 * both ways). */
enum rgl_pass {
	RGL_PLANE,                      /* floors, ceilings, sky, black fills */
	RGL_DECAL,                      /* sky drawn over a floor (polygon offset) */
	RGL_WALL,                       /* wall parts */
	RGL_MASKED,                     /* masked middle textures */
	RGL_MDECAL,                     /* masked textures over a plane (offset) */
	RGL_SIL,                        /* silhouettes: sprite clipping only */
	RGL_SPRITE                      /* sprites and meshes (one run each) */
};

/* A seg's silhouettes (rgl_geo_sils): ends relative to the eye, heights
 * of the bottom clip (-RGL_SKIRT: none) and top clip (RGL_SKIRT: none),
 * and Doom's exemptions: a sprite whose feet are at or above bsil ignores
 * the bottom clip, one whose top is at or below tsil the top clip (heights
 * above the eye; +/-RGL_SKIRT: never). */
struct rgl_sil {
	double ax, ay, bx, by;
	double zb, zt;
	double bsil, tsil;
	uint32_t seg;
};

/* A run of columns x0..x1 where a silhouette's seg is reached (Doom: a
 * drawseg), its nearest and farthest depth there, and its quads in silv
 * (bottom part, then top part; counts 0 when absent). */
struct rgl_silrun {
	int sil, x0, x1;
	double dmin, dmax;
	int first, nbottom, ntop;
};

/* A sprite as drawn: its columns, depth, position (the map's, for Doom's
 * side test), feet and top above the eye; x1 < x0 when not drawn. A mesh:
 * the columns of its screen box, the depth of its centre, its lowest and
 * highest points. */
struct rgl_sprrec {
	int x0, x1;
	double d, gz, gzt;
	fx_t gx, gy;
	int mesh;                       /* a mesh: triangles in the world (eye
					 * relative), culled when turned away */
	int y0, y1;                     /* a mesh: its screen box's rows (window
					 * coordinates, y up, y1 past the last) */
	int64_t scale;                  /* the software renderer's scale at its
					 * centre, (w << 47) / depth: the drawing
					 * order */
};

/* One entry of the sprites' drawing order (rgl_sprites). */
struct rgl_sord {
	int64_t scale;
	uint32_t k;                     /* index in the sprite list */
	int item;                       /* its run in items */
};

#define RGL_SKIRT 100000.0              /* "to the top (bottom) of the view" */

/* One vertex: position relative to the eye, texture coordinates (s, t, r,
 * q: q != 1 only for projected flats), colour-pass colour, id colour. */
struct rgl_vtx {
	float x, y, z;
	float s, t, r, q;
	uint8_t c[4];
	uint8_t id[4];
};

#define RGL_POLY_MAX 1024              /* points of a polygon being clipped */
#define RGL_PIECES 16

/* Convex pieces of a polygon being cut (x y pairs) and their counts. */
struct rgl_pieces {
	double p[RGL_PIECES][2 * RGL_POLY_MAX];
	int n[RGL_PIECES];
	int count;
};

/* A run of vertices (triangles) with one texture and pass. */
struct rgl_item {
	uint64_t key;                   /* the draw order: pass << 32 | texref
					 * (sprites: | their index in the list) */
	uint32_t tex;                   /* texref */
	int first, count;
};

struct rgl_ctx {
	int w, h;
	void *osm;                      /* OSMesaContext */
	uint8_t *buf;                   /* OSMesa's colour buffer, RGBA, w*h*4,
					 * bottom row first */
	float *depth;                   /* depth read back, w*h, bottom row first */
	uint32_t *ids;                  /* caller's id buffer or NULL */
	ang_t *xtoang;                  /* per column, as the software renderer's */
	char name[128];

	/* GL textures made from tex (0: not yet) */
	const struct tex_set *tex;
	uint32_t *gl_wall, *gl_flat, *gl_spr;
	int n_wall, n_flat, n_spr;
	uint32_t gl_fbwall, gl_fbflat;
	uint8_t fb_lo, fb_hi;           /* colours of the fallback checker */

	/* the subsectors' polygons of map (x, y pairs, poff[i]..poff[i+1]) */
	const struct map *map;
	uint64_t map_hash;
	uint32_t map_nss;
	double *pv;
	int *poff;
	int npv, maxpv;
	uint32_t *sec_ss;               /* subsectors by sector: sector i's are */
	uint32_t *sec_first;            /* sec_ss[sec_first[i] .. sec_first[i+1]) */
	uint32_t map_nsecs;
	double *ss_box;                 /* per subsector: its parent node's box
					 * for it, x0 y0 x1 y1 */
	struct rgl_pieces *pieces;      /* scratch of the sky decals, or NULL */

	/* this frame's triangles */
	struct rgl_vtx *vtx;
	int nvtx, maxvtx;
	struct rgl_item *items;
	int nitems, maxitems;
	uint32_t *idx;                  /* vertex indices in draw order */
	int maxidx;
	struct rgl_sil *sils;           /* this frame's silhouettes */
	int nsils, maxsils;
	struct rgl_vtx *silv;           /* their quads, in reached columns */
	int nsilv, maxsilv;
	struct rgl_silrun *runs;        /* the columns where they apply */
	int nruns, maxruns;
	struct rgl_sprrec *sprs;        /* per sprite in the list */
	struct rgl_sord *sord;          /* their drawing order, maxsord entries */
	int maxsord;
	uint32_t *sidx;                 /* scratch: silhouette vertex indices */
	int maxsidx;
	float *colmax;                  /* per column: the farthest view depth */

	/* this frame's view, as the software renderer sets it up */
	fx_t ex, ey, ez;
	ang_t angle;
	fx_t vcos, vsin;
	int shear;
	uint8_t black;
	double mat_world[16];           /* projection x view, for eye-relative
					 * positions; projection alone, for view
					 * space (sprites) */
	double mat_view[16];
	uint8_t *sec_seen;              /* per sector: 0 not yet known, 1 reached,
					 * 2 not reached (rgl_geo_reached) */
	uint32_t *spr_sec;              /* per sprite in the list: its sector */
	int max_seen, max_spr;
	int sbox[4];                    /* the sprites' screen box: x0, y0, x1, y1
					 * (GL window coordinates, y up) */

	struct rgl_stats st;
};

/* rgl_geo.c */
/* Makes the polygons of m's subsectors (kept until the map changes).
 * 0 or -ENOMEM. */
int rgl_geo_polys(struct rgl_ctx *g, const struct map *m);
/* This frame's triangles: g->vtx, g->items. 0 or -ENOMEM. */
int rgl_geo_build(struct rgl_ctx *g, const struct map *m, const struct tex_set *t,
		  const struct r_sprite *spr, int nspr);
/* The silhouettes' quads (g->silv) in the columns where their seg is
 * reached: where its depth is within colmax (the farthest view depth of
 * the world in that column). 0 or -ENOMEM. */
int rgl_geo_sils(struct rgl_ctx *g, const float *colmax);
/* The silhouette vertices (indices into silv, into idx: room for nsilv)
 * that clip sprite i as Doom's R_DrawSprite would: the runs over its
 * columns in front of it, less the parts it is exempt from. Returns their
 * count. */
int rgl_geo_sprite_sils(struct rgl_ctx *g, const struct map *m, int i, uint32_t *idx);
/* Whether sector sec is reached, as the software renderer's walk would:
 * some point of one of its subsectors' polygons lies, in some column, no
 * farther than colmax there (the world's farthest depth in that column). */
int rgl_geo_reached(struct rgl_ctx *g, uint32_t sec, const float *colmax);
/* Colormap level of a light level before fade (r_light_base's rule). */
int rgl_light_base(int light);
/* The picture wall texture num draws now (animation applied): NULL for 0,
 * NULL with *fb set for one the set cannot provide (the fallback). */
const struct tex_pic *rgl_wall_pic(const struct tex_set *t, uint16_t num, int *index, int *fb);

#endif
