/*
 * r_local: the render context and the functions the renderer's stages share.
 * Internal to engine/render/r_*.c; nothing outside the renderer includes it.
 *
 * Stages (Doom's split): r_main.c sets up the view and owns the geometry
 * and texture helpers (view transform, clipping, projection, texture and
 * light lookup, list growth); r_bsp.c walks the BSP front to back and keeps
 * the solid-column list; r_seg.c turns one seg into wall columns, plane
 * marks and a drawseg; r_plane.c keeps the visplanes and draws them as
 * spans, strip by strip (and records the sky as columns); r_things.c
 * projects sprites and draws them and the masked middle textures back to
 * front; r_strip.c records what those stages draw and runs the drawing by
 * column strips; r_draw.c is the only code that writes frame pixels.
 *
 * A frame has two phases. The walk (one thread): BSP traversal, walls,
 * plane marks, sky, sprite projection; every column run it decides is
 * recorded (struct r_col), none drawn. Then the strips: disjoint ranges of
 * columns, each drawn by one job, in any order and on any thread (struct
 * r_par): its recorded column runs, the spans its columns of each visplane
 * make, the black fill, then sprites and masked middles clipped to it. A
 * pixel's value depends only on what was recorded for it and on its own
 * row and column (a flat's position is a function of the column, not of
 * where a span starts), never on which strip or thread drew it, so frames
 * are the same bytes whatever the number of threads.
 *
 * Number formats (all integer):
 *  - map and view-space coordinates: 16.16 map units, view space in int64;
 *  - screen x: 16.16 pixels (int64), 0 = left edge of column 0;
 *  - scale (pixels per map unit at a column, focal / depth): 32.32 in int64
 *    while stepping, 16.16 where it multiplies heights;
 *  - screen y of an edge: 32.32 pixels (int64), 0 = top edge of row 0;
 *  - texture coordinates: 16.16 texels (one texel per map unit), in uint32
 *    inside the column loops; flat coordinates 6.26 (position modulo 64
 *    units) inside the span loop.
 * Fill rule: a column or row is covered when its pixel centre (x + 0.5 or
 * y + 0.5) lies in [start, end) of the projected span; textures are
 * sampled at pixel centres.
 */
#ifndef ARCADED_ENGINE_R_LOCAL_H
#define ARCADED_ENGINE_R_LOCAL_H

#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/core/pal.h"
#include "engine/map/lmap.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/render/r_main.h"

#define R_MAX_DIM 4096

/* Near plane: nothing closer than this depth (map units, 16.16) is drawn.
 * The sim keeps the eye 16 units from solid walls, so it only shows when the
 * eye is within a quarter unit of a portal or outside the map. */
#define R_NEAR (FX_ONE / 4)

/* The frame's columns in blocks of this many (a power of two: r_plane.c
 * masks with it); a row of a lit floor or ceiling is lit by one light-map
 * texel per block. */
#define R_LMAP_RUN 16

/* Strips are R_STRIP_MIN columns wide or a power-of-two multiple of it: a
 * cache line (64 bytes) or more, so that two threads never write one line.
 * With a pool, about R_STRIPS_PER_THREAD strips per thread: enough for the
 * jobs to balance, few enough that cutting spans at strip edges costs
 * little (each cut is one more span set-up, and a row's set-up is made
 * once per strip); without, one strip. */
#define R_STRIP_MIN 64
#define R_STRIPS_PER_THREAD 4
/* A strip draws its column runs in bands of this many rows: one band of a
 * strip is a few KiB, so a wall column reuses the cache lines the column
 * before it loaded. */
#define R_BAND_SHIFT 7

/* Sprites nearer than this depth are not drawn (Doom's MINZ). */
#define R_SPR_NEAR (4 * FX_ONE)

/* Distance fade, Doom's: a surface at depth z is R_FADE_DIST / z colormap
 * levels brighter than its sector's light alone gives, at most R_FADE_MAX. */
#define R_FADE_DIST 1280
#define R_FADE_MAX 24

/* Fake contrast: east-west walls one Doom light level (16 of 255) brighter,
 * north-south walls one darker. */
#define R_CONTRAST 16

/* Planes deeper than this (16.16: 65536 map units, beyond any map) are
 * textured as if at this depth: keeps the span set-up inside int64. */
#define R_PLANE_DMAX ((int64_t)1 << 32)

/* The sky: Doom's 1024 texture columns per turn (a 256-wide sky repeats four
 * times), texel row R_SKY_MID at the horizon, R_SKY_COLS texels per screen
 * width vertically too (square texels, like the walls on square pixels). */
#define R_SKY_SHIFT 22
#define R_SKY_MID 100
#define R_SKY_COLS 256

/* Checker drawn for textures and flats the set cannot provide. */
#define R_FB_SIZE 64

#define R_PLANE_HASH 256
#define R_EMPTY 0xffffu                 /* visplane column with no rows */
#define R_MASK_DONE INT16_MAX           /* masked column already drawn */

/* Drawseg silhouettes (Doom's SIL_*): which edges clip sprites behind. */
#define R_SIL_BOTTOM 1
#define R_SIL_TOP 2
/* drawseg clip references besides an index into the openings */
#define R_CLIP_NONE (-1)                /* no saved clip */
#define R_CLIP_ALL (-2)                 /* the whole column is occluded */

/* A view-space point: l to the right of the view axis, d along it. */
struct r_vpt {
	int64_t l, d;
};

/* A run of fully occluded columns [first, last]. */
struct r_range {
	int first, last;
};

/* A visplane (Doom's visplane_t): the rows of one floor or ceiling (key:
 * height, flat, light; every sky ceiling is one key) per column, for
 * columns minx..maxx. top/bot hold w entries. */
struct r_plane {
	fx_t height;
	const struct lmap_grid *lg;    /* the sector's light map, or NULL */
	uint16_t pic;                   /* flat number as the sector stores it */
	uint8_t light, sky;
	uint32_t sector;                /* the sector it was made for (surface ids) */
	int minx, maxx;
	int next;                       /* hash chain (most recent first), -1 ends */
	uint16_t *top, *bot;            /* R_EMPTY: no rows in that column */
	/* what its spans share (r_plane_prepare, before the strips draw
	 * them): the flat's pixels, the height from the eye (16.16, > 0), the
	 * light before fade, the fade factor and the surface id */
	const uint8_t *flat;
	int64_t hgt, q;
	int base;
	uint32_t id;
};

/* A wall range kept for the masked pass (Doom's drawseg_t). Scales over
 * the range: clamp(s0 + step * (x - sx), smin, smax). Clip references are
 * indices into ctx.open such that column x is open[ref + x - x1], or
 * R_CLIP_NONE / R_CLIP_ALL. */
struct r_dseg {
	int x1, x2;
	uint32_t seg;                   /* for the sprite's side test */
	int sx;
	int64_t s0, step, smin, smax;
	int64_t lo, hi;                 /* smallest, largest scale over [x1, x2] */
	int sil;                        /* R_SIL_* */
	int64_t bsil, tsil;             /* world z: sprites entirely above bsil
					 * ignore the bottom silhouette, entirely
					 * below tsil the top one */
	int32_t topclip, botclip;
	int32_t maskcol;                /* texture column per x, or R_CLIP_NONE */
	const struct tex_pic *mid;      /* masked middle texture */
	int64_t mid_tmid;               /* its top, 16.16 above the eye */
	int light_base;                 /* colormap level before fade */
};

/* A projected sprite (Doom's vissprite_t). */
struct r_vis {
	int x1, x2;
	int64_t scale;                  /* 32.32 */
	fx_t gx, gy;
	int64_t gz, gzt;                /* world z of the picture's bottom, top */
	int64_t sxl;                    /* screen x of the left edge, 16.16 */
	int64_t iscale;                 /* texels per pixel, 16.16 */
	int64_t tmid;                   /* picture top, 16.16 above the eye */
	const struct tex_pic *pic;
	int flip;
	int lvl;                        /* colormap level */
	int order;                      /* index in the caller's list: ties */
	/* a mesh (r_mesh.c) instead of a picture: mesh number (0: a sprite),
	 * its rows y1..y2 on screen, colour, rotation and the thing's z */
	int mesh, y1, y2;
	const struct mesh *mp;         /* a loaded mesh (r_sprite.mp) or NULL */
	uint8_t colour;
	ang_t angle;
	fx_t mz;
};

/* A run of rows y1..y2 of column x recorded by the walk: a wall part or
 * the sky (texture column src of h texels, r_draw_col's frac and step,
 * through colormap cm), or a fill with colour when src is NULL. Drawing a
 * band of it advances y1 and frac. */
struct r_col {
	const uint8_t *src, *cm;
	uint32_t frac, step;
	int32_t h;
	int16_t x, y1, y2;
	uint8_t colour;
	uint32_t id;                    /* surface id (r_set_idbuf) */
};

/* A span of a flat: row y, columns x1..x2, the flat's 64x64 pixels,
 * colormap, and 6.26 positions at x1's centre plus steps. */
struct r_span {
	const uint8_t *flat, *cm;
	uint32_t xf, yf, xs, ys;
	int16_t y, x1, x2;
	uint32_t id;                    /* surface id (r_set_idbuf) */
};

/* A row's span set-up, kept while a strip draws its spans (Doom's
 * cachedheight): the plane height and the strip's frame (rowgen) it is
 * for, and the world position at column 0's centre and the step per
 * pixel, 32.32 (positions in world coordinates). */
struct r_rowc {
	int64_t h, px0, py0, sx, sy;
	uint32_t gen;
};

/* One strip: columns x0..x1, its recorded runs, scratch, and the pixel
 * counters of its drawing (summed into the frame's stats). Only the
 * job drawing the strip touches it during the strip phase. Each strip
 * starts a cache line of its own (the array is 64-byte aligned): two
 * threads updating the counters of neighbouring strips would otherwise
 * pass one line back and forth on every run. */
struct r_strip {
	_Alignas(64) int x0;
	int x1;
	struct r_col *cols;
	int ncols, maxcols;
	int32_t *order, *act, *next;    /* band scratch, maxcols entries each */
	int32_t *band;                  /* nbands + 1 counts */
	uint32_t written, spanned, empty, masked, degraded;
	uint32_t nspans;                /* spans begun in it (stats.spans) */
	/* its span scratch, h rows each: where each row's open span began,
	 * and the rows' set-ups */
	uint16_t *spanstart;
	struct r_rowc *rowc;
	uint32_t rowgen;                /* this frame's, never 0 (rowc[].gen 0: none) */
	/* a mesh's box (r_mesh.c): colours and covered flags, inverse depths */
	uint8_t *mbuf;
	uint32_t *mdep;
	int mbufcap, mdepcap;
	/* of the last frame, ns (r_par.now) or pixels: the column runs (first
	 * phase) and the rest (second phase), each phase ordered by its own */
	uint64_t cost_cols, cost_rest;
};

struct r_ctx {
	int w, h;

	/* the strips (r_strip.c), fixed per size; the shift turns a column
	 * into its strip */
	struct r_strip *strips;
	int nstrips, strip_shift, band_shift, nbands;
	struct r_par par;               /* run == NULL: strips drawn in turn */
	/* r_set_strip_done's */
	void (*strip_done)(void *arg, int x0, int x1);
	void *strip_done_arg;
	/* r_set_beside_walk's */
	void (*beside)(void *arg);
	void *beside_arg;
	/* 3 * nstrips: the strips costliest first for the first phase, then
	 * for the second, then each strip's place in the first (r_strip.c) */
	int32_t *strip_order;
	/* the frame's sprites, for the walk's rest (r_strip_draw_all):
	 * r_render's, or what the work beside the walk gave (r_beside_sprites) */
	const struct r_sprite *wspr;
	int wnspr, world;

	/* per column: rows [ceilclip + 1, floorclip - 1] are still unwritten;
	 * everything outside that interval has been written exactly once */
	int16_t *ceilclip, *floorclip;

	/* sorted, disjoint, non-adjacent occluded column runs, with sentinels
	 * below column 0 and past column w - 1 (Doom's solidsegs) */
	struct r_range *solid;
	int nsolid, maxsolid;

	/* per row: |2y + 1 - cy2|, twice the distance of the row's centre from
	 * the horizon; a plane's depth at row y is proportional to 1 / rowv[y];
	 * yslope[y] = w * 2^16 / rowv[y] (depth per unit of plane height) */
	int32_t *rowv;
	int64_t *yslope;
	int rowv_cy2;                   /* the cy2 rowv was built for */

	/* per column: angle of the ray through the column centre relative to
	 * the view direction (positive left), for the sky */
	ang_t *xtoang;

	int64_t wall_kq;                /* wall fade = (scale16 * wall_kq) >> 32 */

	/* visplanes: planes[0..nplanes-1] used this frame; the arrays of
	 * planes up to maxplanes are kept allocated */
	struct r_plane *planes;
	int nplanes, maxplanes;
	int plane_hash[R_PLANE_HASH];
	int ceilplane, floorplane;      /* of the subsector being drawn, -1 none */

	struct r_dseg *dsegs;
	int ndsegs, maxdsegs;
	int16_t *open;                  /* openings: saved clips, masked columns */
	int32_t nopen, maxopen;
	int16_t *cliptop, *clipbot;     /* a sprite's clip, per column */
	/* per sector: the frame number when the BSP walk last reached it;
	 * only sprites standing in a reached sector are drawn (Doom adds a
	 * sector's things when it reaches the sector) */
	uint32_t *sec_seen;
	int maxsecs;
	uint32_t frame_no;
	int seen_ok;                    /* sec_seen covers this map's sectors */

	/* fallback checker, magenta and black (the palette's nearest) */
	struct tex_pic fb_pic;
	uint8_t fb_px[R_FB_SIZE * R_FB_SIZE];
	uint8_t fb_flat[TEX_FLAT_SIZE * TEX_FLAT_SIZE];
	int fb_lo, fb_hi;               /* colours it is drawn in, -1 before use */

	/* the frame being drawn (valid during r_render only) */
	const struct map *map;
	const struct tex_set *tex;
	const uint8_t (*cmap)[256];     /* tex->pal.cmap */
	uint8_t black;                  /* the palette's nearest to black */
	uint8_t ident[256];             /* i -> i: the colormap of colours already lit */
	uint8_t *px;
	int pitch;
	fx_t ex, ey, ez;                /* eye, x/y clamped to MAP_COORD_MAX */
	ang_t angle;
	fx_t vcos, vsin;
	int cy2;                        /* twice the horizon row: h + 2 * shear */
	int64_t cy32;                   /* horizon, 32.32 pixels */
	uint32_t front;                 /* sector of the subsector being drawn */
	const struct lmap *lm;          /* point-light maps, NULL: none */
	uint32_t *ids;                  /* surface ids (r_set_idbuf), or NULL */
	uint32_t id;                    /* the walk's: what r_rec_* record */

	/* What the walk's rest (the planes' set-up, the sprites) writes while
	 * other threads draw column runs (r_strip.c): on cache lines of their
	 * own, the last of the context, so those threads' reads of the fields
	 * above (frame, pitch, strips, bands) never miss for its writes. The
	 * context is allocated 64-byte aligned (r_new). */
	_Alignas(64) struct r_vis *vis;
	int nvis, maxvis;
	struct r_stats st;
};

/* r_main.c: geometry */
void r_to_view(const struct r_ctx *r, fx_t x, fx_t y, struct r_vpt *p);
/* Clips the segment a-b to the visible region (depth >= R_NEAR, inside the
 * 90-degree frustum). Returns 0 when nothing is left. */
int r_clip_segment(struct r_vpt *a, struct r_vpt *b);
/* Clips the convex polygon v[0..n-1] (n <= 4) to the visible region in
 * place; v must have room for R_POLY_MAX points. Returns the new count. */
#define R_POLY_MAX 32
int r_clip_polygon(struct r_vpt *v, int n);
/* Screen x (16.16) of a clipped point: in [0, w * FX_ONE]. */
int64_t r_project_x(const struct r_ctx *r, const struct r_vpt *p);
/* First column whose centre is at or right of screen x sx (16.16). */
static inline int r_col_at(int64_t sx)
{
	return (int)((sx - FX_HALF + FX_ONE - 1) >> FX_SHIFT);
}
/* First row whose centre is at or below the edge of height hrel (16.16
 * above the eye) at scale s16 (16.16), clamped to [lo, hi]. */
int r_edge_row(const struct r_ctx *r, int64_t hrel, int64_t s16, int lo, int hi);

/* r_main.c: light and textures */
/* Colormap level before distance fade for a light level (clamped 0..255). */
int r_light_base(int light);
/* Level of a surface at scale s (32.32) with base level base. */
int r_scale_level(const struct r_ctx *r, int base, int64_t s);
/* The wall texture a side's number num draws now (animation applied):
 * NULL for 0 ("-", no texture), the fallback checker (counted) for a
 * number or picture the set cannot provide. */
const struct tex_pic *r_wall_pic(struct r_ctx *r, uint16_t num);
/* The 64x64 pixels of flat num now (animation applied), or the fallback. */
const uint8_t *r_flat_px(struct r_ctx *r, uint16_t num);
/* 1 when a sector's ceiling number num is the sky. */
int r_is_sky(const struct r_ctx *r, uint16_t num);
/* Reserves n entries of ctx.open; returns the index of the first or -1. */
int32_t r_open_alloc(struct r_ctx *r, int n);

/* r_bsp.c: traversal and the solid-column list */
void r_bsp_render(struct r_ctx *r);
void r_solid_reset(struct r_ctx *r);
/* Marks columns [x1, x2] occluded. */
void r_solid_add(struct r_ctx *r, int x1, int x2);
/* 1 when every column of [x1, x2] is occluded. */
int r_solid_covers(const struct r_ctx *r, int x1, int x2);

/* r_seg.c: draws the parts of seg sg visible in columns not yet occluded,
 * marks its planes, records its drawsegs, then marks the columns it
 * closed. */
void r_seg_add(struct r_ctx *r, const struct map_seg *sg);
/* 1 when the eye is on the front (right) side of seg sg's line, or (x, y)
 * when not the eye: the exact cross-product test. */
int r_seg_front(const struct map *m, const struct map_seg *sg, fx_t x, fx_t y);

/* r_plane.c: visplanes */
void r_plane_clear(struct r_ctx *r);
/* The visplane of key (height, pic, light) to add columns to, or -1 when
 * none could be allocated (degraded). */
int r_plane_find(struct r_ctx *r, fx_t height, uint16_t pic, int light,
		 const struct lmap_grid *lg);
/* Plane p, or a new plane of the same key when p already has rows in a
 * column of [x1, x2]; its column range then includes [x1, x2]. -1 when
 * p is -1 or none could be allocated. */
int r_plane_check(struct r_ctx *r, int p, int x1, int x2);
/* Records the sky planes, by columns (before the strips draw columns). */
void r_plane_draw_sky(struct r_ctx *r);
/* The other planes' span set-up (struct r_plane's flat .. id); may run
 * beside the column runs being drawn (r_strip.c), before any strip draws
 * spans. */
void r_plane_prepare(struct r_ctx *r);
/* Draws the spans of every plane but the sky in strip s's columns: each
 * row's run of a plane's columns there is one span (Doom's R_MakeSpans
 * and R_MapPlane). A texel's position depends only on the pixel's row and
 * column, so a span cut at a strip edge draws what the whole span would.
 * Writes only s's pixels and s. */
void r_plane_strip(const struct r_ctx *r, struct r_strip *s);

/* r_things.c: sprites and masked middle textures */
/* Projects the sprites and sorts them farthest first. */
void r_things_project(struct r_ctx *r, const struct r_sprite *spr, int nspr);
/* Draws the projected sprites and masked middles back to front, in strip
 * s's columns only. */
void r_things_draw(struct r_ctx *r, struct r_strip *s);

/* r_mesh.c: meshes drawn as things */
/* Fills the mesh fields of vs (and x1, x2, scale, gz, gzt) for sprite sp
 * with a mesh: 0, 1 when the mesh is not drawn (too near, too far to the
 * side or off the screen), -1 when sp->mesh is no built-in mesh and sp->mp
 * is NULL. */
int r_mesh_project(struct r_ctx *r, const struct r_sprite *sp, struct r_vis *vs);
/* Draws mesh vs in columns vx1..vx2 (inside strip s) between the clip
 * arrays ct (last row hidden above) and cb (first row hidden below). */
void r_mesh_draw(struct r_ctx *r, struct r_strip *s, const struct r_vis *vs, int vx1, int vx2,
		 const int16_t *ct, const int16_t *cb);

/* r_strip.c: recording by the walk and the strip phase. The r_rec_*
 * functions take what r_draw draws (same requirements); when a list cannot
 * grow they draw at once instead (counted in stats.degraded). */
/* (Re)makes the strips: 1 << strip_shift columns each (strip_shift >= 6),
 * bands of 1 << band_shift rows. r_set_par picks them (R_BAND_SHIFT);
 * tests pick others to show that the frame does not depend on them. 0, or
 * -ENOMEM with the strips as they were. */
int r_strip_layout(struct r_ctx *r, int strip_shift, int band_shift);
/* The strips (not the spans). */
void r_strip_free(struct r_ctx *r);
/* Empties the strips' lists for a new frame. */
void r_strip_reset(struct r_ctx *r);
/* Rows y1..y2 of column x from texture column col of h texels (h >= 1),
 * texel row frac >> 16 at row y1, frac + step at the next, wrapping at h;
 * requires frac, step < h << 16; through colormap cm. */
void r_rec_col(struct r_ctx *r, int x, int y1, int y2, const uint8_t *col, int h,
	       const uint8_t *cm, uint32_t frac, uint32_t step);
/* Rows y1..y2 of column x in one colour. Every r_rec_* records ctx.id as
 * the run's surface id. */
void r_rec_fill(struct r_ctx *r, int x, int y1, int y2, uint8_t colour);
/* Sets up the planes' spans and projects the frame's sprites (wspr,
 * wnspr: r_render's or r_beside_sprites') when world (the walk's rest),
 * draws every strip (through r->par when set, the walk's rest beside the
 * column runs) and adds their counters to the frame's stats. */
void r_strip_draw_all(struct r_ctx *r, int world);

/* r_draw.c: the only writers of frame pixels; s is the strip drawn, every
 * write stays inside its columns. With an id buffer each also writes the
 * surface id of every pixel it writes (the run's or span's, id for a masked
 * column, 0 for the black fill). */
/* Rows c->y1..y2 of run c (y2 <= c->y2); then c->y1 is y2 + 1 and c->frac
 * the position there. Counted in written. */
void r_draw_run(const struct r_ctx *r, struct r_strip *s, struct r_col *c, int y2);
/* Span sp, inside the strip's columns. Counted in spanned. */
void r_draw_span(const struct r_ctx *r, struct r_strip *s, const struct r_span *sp);
/* A masked column (sprites, masked middles): rows y1..y2 of column x (in
 * the strip) from picture column col, no wrapping, only texels whose op
 * entry is nonzero (op NULL: all); requires (frac + (y2 - y1) * step) >> 16
 * within the column. Counted in masked. */
void r_draw_masked(const struct r_ctx *r, struct r_strip *s, int x, int y1, int y2,
		   const uint8_t *col, const uint8_t *op, const uint8_t *cm, uint32_t frac,
		   uint32_t step, uint32_t id);
/* Fills every still unwritten pixel of the strip with black (counted in
 * written and empty). */
void r_draw_finish(const struct r_ctx *r, struct r_strip *s);

#endif
