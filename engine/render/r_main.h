/*
 * r_main: the software renderer's public interface.
 *
 * Doom lineage: BSP front-to-back traversal, solid-segment clipping,
 * textured wall columns with per-column upper/lower clip, floors and
 * ceilings as visplanes drawn in horizontal spans, the sky, masked middle
 * textures and sprites drawn back to front and clipped against the walls'
 * silhouettes, light through colormaps with distance fade. Integer-exact:
 * the same map, textures, view, sprites and size give the same frame bytes
 * on every compiler and CPU.
 *
 * A render context owns all per-resolution buffers and the growable lists
 * a frame needs (visplanes, drawsegs, clip openings, sprites); they grow
 * as a frame needs them and are kept for the next frame, so there is no
 * fixed limit a map can overflow. Several contexts may coexist.
 * The frame is row-major 8-bit palette indices.
 *
 * Threads: a frame is drawn in two phases, the BSP walk on one thread
 * (the calling one, or any of the pool's when there is work to do beside
 * it: r_set_beside_walk), then strips of columns that a worker pool may
 * draw at once (r_set_par). The engine starts no thread itself: the pool is the
 * caller's. The frame's bytes do not depend on the pool or its size.
 */
#ifndef ARCADED_ENGINE_R_MAIN_H
#define ARCADED_ENGINE_R_MAIN_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/render/r_id.h"

struct lmap;
struct map;
struct mesh;
struct tex_set;
struct v_list;

struct r_view {
	fx_t x, y, z;                  /* eye position; z is eye height */
	ang_t angle;                   /* view direction */
	int32_t shear;                 /* vertical look: the horizon moves down
					* by shear pixels (clamped to +/-h) */
};

/* A thing to draw. The picture is frame `frame` of sprite `sprite` in the
 * texture set, at the rotation Doom picks from the angle between the
 * viewer's line of sight and the thing's facing. Lit by the light of the
 * sector under (x, y) with distance fade, or full bright. */
struct r_sprite {
	fx_t x, y;                     /* map position */
	fx_t z;                        /* the thing's feet (Doom's thing z, usually
					* its sector's floor): the picture's top is
					* z + its top offset */
	ang_t angle;                   /* the thing's facing */
	uint16_t sprite;               /* index into tex_set.sprites */
	uint16_t frame;                /* 0 = frame A */
	uint8_t flags;                 /* R_SPR_* */
	/* A built-in mesh (engine/map/mesh_builtin.h) drawn instead of the
	 * picture when not 0 (r_mesh.c): rotated by angle about its vertical
	 * axis, standing at z, in palette colour `colour` lit by the sector
	 * light and a Lambert term, clipped by the walls as a sprite is. */
	uint8_t mesh;
	uint8_t colour;
	/* A mesh loaded at run time (struct mesh_set, engine/map/mesh.h),
	 * drawn as the built-in ones are; mesh is then R_MESH_LOADED.
	 * Borrowed: it outlives the frame. NULL otherwise. */
	const struct mesh *mp;
};

#define R_MESH_LOADED 255              /* r_sprite.mesh of a loaded mesh (mp) */

#define R_SPR_FULLBRIGHT 0x01          /* colormap 0, no fade (Doom's FF_FULLBRIGHT) */

struct r_frame {
	uint8_t *px;                   /* w*h indices, row stride `pitch` bytes */
	int w, h, pitch;
	/* NULL to draw; else the 2D calls of engine/ui/v_video.h append
	 * themselves to this list instead of drawing (the renderer never
	 * looks at it) */
	struct v_list *rec;
};

/* Counters of the last frame, for tests and benchmarks. */
struct r_stats {
	uint32_t nodes, subsectors, segs, columns;
	uint32_t pixels_written;       /* walls, planes, sky and the black fill:
					* each pixel of the frame exactly once */
	uint32_t pixels_empty;         /* of those, pixels no surface covered
					* (PAL_BLACK): 0 inside a closed map */
	uint32_t pixels_masked;        /* drawn over that by masked middle
					* textures and sprites */
	uint32_t planes, spans;        /* visplanes used; spans: their row runs drawn
					* (a light map's blocks and strip edges cut
					* none into more) */
	uint32_t drawsegs, openings;   /* wall ranges kept for the masked pass,
					* clip entries they saved */
	uint32_t sprites;              /* sprites projected (on screen) */
	uint32_t missing;              /* surfaces drawn with the fallback checker
					* (texture, flat or sprite number out of
					* range, or an unusable picture) */
	uint32_t degraded;             /* lists that could not grow (out of memory):
					* the frame is still whole, with plain black
					* planes or unclipped sprites there */
};

struct r_ctx;

/* New context for frames of w x h (1..4096 each). Returns 0, -EINVAL or
 * -ENOMEM. Owned by the caller: r_free. */
int r_new(int w, int h, struct r_ctx **out);

/* NULL-safe. */
void r_free(struct r_ctx *r);

/* Grows the array *p of *cap elements of size elem to hold at least need
 * (doubling from *cap, or from 16). 0, or -ENOMEM with *p and *cap
 * unchanged. The growth of the renderers' arrays (the OSMesa renderer's
 * too). */
int r_grow(void **p, int *cap, size_t elem, int need);

/* Draws map m with texture set t from view v into f (f->w, f->h must
 * equal the context's), then the nspr sprites of spr (NULL when nspr is
 * 0), or those the work beside the walk gives (r_beside_sprites). m, t and
 * spr are only read during the call. Map texture numbers
 * index t->textures and t->flats through t->tex_xlat / t->flat_xlat (when
 * not NULL); the palette and colormaps are t->pal. Every pixel of f is
 * written. Never fails on a finished map: data it cannot use draws as the
 * fallback checker (counted in stats.missing). */
void r_render(struct r_ctx *r, const struct map *m, const struct tex_set *t,
	      const struct r_view *v, const struct r_sprite *spr, int nspr, struct r_frame *f);

/* A pool of threads to draw strips on, provided by the caller (the engine
 * has no threads of its own; app/pool.h makes one).
 * run(pool, n, job, arg) calls job(arg, i) exactly once for every i in
 * 0..n-1, any number at a time on any threads (the caller's included), and
 * returns when every call has returned; calls for different i touch
 * disjoint memory, and run's return must make their writes visible to the
 * caller (a full barrier). */
struct r_par {
	void (*run)(void *pool, int n, void (*job)(void *arg, int i), void *arg);
	void *pool;
	int threads;                   /* how many jobs the pool runs at once */
	/* Optional: a monotonic clock in ns, any thread; the strips' measured
	 * cost orders the next frame's jobs. NULL: their pixel counts do. */
	uint64_t (*now)(void);
	/* Optional: a batch comes soon (r_render calls it before its serial
	 * walk), so workers asleep can be running again by then. Any time
	 * between batches; NULL: nothing to do. */
	void (*warm)(void *pool);
	/* Optional: from inside a job of the running batch, returns once job
	 * i of that batch has returned (its writes visible); i is below the
	 * calling job's own index (handed out before it: running or done)
	 * and below wait_jobs. With it the strips are one batch instead of
	 * two (r_strip.c). NULL: two batches. */
	void (*wait)(void *pool, int i);
	int wait_jobs;
};

/* Draws the next frames' strips through par (copied; the pool must outlive
 * its use), or on the calling thread when par is NULL or has fewer than
 * two threads (the default). With a pool the frame is cut into about four
 * strips per thread (the jobs balance between threads); without, into one
 * (no cost for cutting spans). Frames are identical either way. 0, or
 * -ENOMEM with the context drawing as before. */
int r_set_par(struct r_ctx *r, const struct r_par *par);

/* Point-light maps (lmap.h) for the next frames, NULL for none (the
 * default): borrowed, must be made for the map r_render draws and outlive
 * its use. A texel's boost subtracts from the colormap level of walls,
 * floors and ceilings (not the sky, masked middles or sprites). */
void r_set_lmap(struct r_ctx *r, const struct lmap *lm);

/* Work to do on each strip's columns once they are final, for the next
 * frames (NULL: none, the default): r_render calls fn(arg, x0, x1) once
 * per strip, on the thread that drew the strip, as soon as frame columns
 * x0 <= x < x1 hold their final pixels (nothing of r_render writes there
 * afterwards); the calls' ranges cut the frame's columns, and calls for
 * different strips may run at once. Why: what goes over the view (the
 * HUD, engine/ui/v_video.h v_replay) is then drawn by the threads that
 * drew the view, on columns still in their caches, instead of by one
 * thread after them all. Its time counts in the strip's measured cost, so
 * the balance of the strips allows for it. */
void r_set_strip_done(struct r_ctx *r, void (*fn)(void *arg, int x0, int x1), void *arg);

/* Work that needs nothing of the walk, for the next frames (NULL: none, the
 * default): r_render calls fn(arg) once, and it has returned before the
 * first strip_done call. With a pool (r_set_par) it runs on one thread
 * while another walks the BSP, else before the walk; so fn may run on any
 * of the pool's threads at the same time as the walk, and must not touch
 * the context, the map, the textures or the frame but to read them. Why:
 * the walk is serial, the pool's other threads wait through it, and what
 * goes over the view (the HUD recorded as v_ calls, engine/ui/v_video.h)
 * can be made in that time instead of before it. */
void r_set_beside_walk(struct r_ctx *r, void (*fn)(void *arg), void *arg);

/* From inside the beside-the-walk function only (the one exception to its
 * read-only rule): the frame's sprites are the n of spr instead of the
 * ones r_render was given, read as those are (after fn has returned, until
 * r_render returns). Why: the sprite list (r_game_sprites) needs nothing
 * of the walk either, and making it before r_render kept the pool's other
 * threads waiting as long. */
void r_beside_sprites(struct r_ctx *r, const struct r_sprite *spr, int n);

/* Surface-id buffer (engine/render/r_id.h) for the next frames, NULL for none
 * (the default): borrowed, w*h entries, row stride w. r_render then writes,
 * with every pixel it writes to the frame, the id of the surface drawn
 * there (the last writer's: a sprite or masked texel over a wall gives the
 * sprite's or the masked texture's). The frame's bytes are the same with
 * and without it; without it the only cost is one test per run drawn. */
void r_set_idbuf(struct r_ctx *r, uint32_t *ids);

/* Counters of the last r_render. */
void r_get_stats(const struct r_ctx *r, struct r_stats *st);

/* The palette-colour texture set, for maps whose texture numbers are
 * palette indices (map.h "Textures": the built-in levels as written so
 * far): pal_builtin's palette; wall texture i (1..255) and flat i (0..255)
 * are the solid colour i; no sky, no sprites. Drawn with it, such a map
 * looks exactly as it did before textures existed. 0 or -ENOMEM. Owned by
 * the caller: r_pal_set_free (not tex_free). */
int r_pal_set_new(struct tex_set **out);

/* NULL-safe. */
void r_pal_set_free(struct tex_set *t);

#endif
