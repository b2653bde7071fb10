/*
 * rgl: a second renderer of the same world on OSMesa (Mesa's software
 * OpenGL, llvmpipe), independent of the software renderer (r_main.h): the
 * oracle for its visibility (docs/crosscheck.md) and a yardstick for its
 * speed. engine/gl/ is the only place that includes OSMesa or GL headers and
 * the only engine code with floating point; nothing else in engine/ uses it.
 *
 * The world is drawn as polygons with a depth buffer: walls as textured
 * quads per seg (upper, middle, lower parts with Doom's pegging and offsets,
 * masked middles alpha-tested), floors and ceilings as the convex polygons
 * of the BSP's subsectors (each cut from a large box by its ancestors'
 * partition lines, then by its own one-sided segs, as GL node builders
 * do), sprites as billboards facing the view plane with Doom's
 * rotation choice, and the built-in meshes (r_sprite.mesh) as their own
 * triangles, rotated and lit as the software renderer's r_mesh.c does;
 * sprites and meshes in the software renderer's order. The projection is
 * the software renderer's exactly: 90 degree horizontal field of view,
 * focal length w/2, square pixels, horizon at row centre h/2 + shear, near
 * plane 1/4 unit. Light is the same: the
 * colour pass writes texel index, colormap level and a mode per pixel; the
 * CPU then looks each pixel up through the texture set's colormaps with
 * Doom's distance fade from the depth buffer, and draws the sky by the
 * software renderer's formula. The frame is the same kind as r_render's:
 * row-major 8-bit palette indices.
 *
 * Doom's rules it reproduces where they differ from the geometry
 * (docs/crosscheck.md lists them with how): back-face culling of walls,
 * floors drawn only from above and ceilings only from below, the sky as the
 * rows above each seg's ceiling edge (lowered between two sky ceilings),
 * planes seen from behind filled black, a missing upper or lower texture
 * showing the plane behind it, masked middles drawn once and showing over
 * planes their seg does not mark, sprites clipped by Doom's silhouettes
 * (not by walls) and drawn only in sectors Doom's walk would reach, and
 * sprites and meshes drawn over one another in Doom's order (a painter's
 * algorithm: farther centre first), not depth-tested against each other.
 * Point-light maps (r_set_lmap) are not drawn.
 *
 * Not deterministic across Mesa versions or thread counts in its edge
 * pixels; never used where frames are hashed.
 */
#ifndef ARCADED_ENGINE_GL_R_GL_H
#define ARCADED_ENGINE_GL_R_GL_H

#include <stddef.h>
#include <stdint.h>

#include "engine/render/r_main.h"

struct map;
struct tex_set;
struct rgl_ctx;

/* Counters of the last frame. */
struct rgl_stats {
	uint32_t walls, planes, sprites;   /* quads / polygons / sprites drawn
					    * (billboards and meshes) */
	uint32_t meshes;                   /* of the sprites, meshes */
	uint32_t triangles, draws;         /* sent to GL, draw calls (one pass) */
	uint32_t missing;                  /* surfaces drawn with the fallback
					    * checker, sprites skipped */
	uint32_t textures;                 /* GL textures made so far */
};

/* New context drawing frames of w x h (1..4096 each) into its own OSMesa
 * buffer (RGBA, 24-bit depth). 0, -EINVAL (size), -ENOMEM, or -EIO when
 * OSMesa cannot make a context (err says which call failed). Owned by the
 * caller: rgl_free. The context belongs to no thread: every call makes it
 * current on the calling thread, and calls on one context must not
 * overlap. llvmpipe's own threads follow LP_NUM_THREADS. */
int rgl_new(int w, int h, struct rgl_ctx **out, char *err, size_t errlen);

/* NULL-safe. */
void rgl_free(struct rgl_ctx *g);

/* Draws map m with texture set t from view v, then the nspr sprites of spr,
 * into f: the same calling shape and contract as r_render (f->w, f->h equal
 * the context's; every pixel written; data it cannot use draws as the
 * fallback checker or is skipped, counted in stats.missing). With an id
 * buffer set, a second pass writes every pixel's surface id.
 * The context keeps GL textures made from t and the floor polygons made
 * from m's BSP between frames, keyed by those pointers: call rgl_flush
 * before freeing either while the context lives on. */
void rgl_render(struct rgl_ctx *g, const struct map *m, const struct tex_set *t,
		const struct r_view *v, const struct r_sprite *spr, int nspr, struct r_frame *f);

/* Surface-id buffer (engine/render/r_id.h) for the next frames, NULL for none
 * (the default): borrowed, w*h entries, row stride w. */
void rgl_set_idbuf(struct rgl_ctx *g, uint32_t *ids);

/* Forgets the cached textures and polygons (see rgl_render). */
void rgl_flush(struct rgl_ctx *g);

/* Counters of the last rgl_render. */
void rgl_get_stats(const struct rgl_ctx *g, struct rgl_stats *st);

/* GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)". */
const char *rgl_name(const struct rgl_ctx *g);

#endif
