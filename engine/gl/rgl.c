/*
 * rgl: the OSMesa renderer's context, GL state, textures, passes and the
 * per-pixel resolve. The only file of the project that includes OSMesa or
 * GL headers.
 *
 * Fixed-function GL 1.3 on llvmpipe, no shaders. Textures hold palette
 * indices: each texel is (index, 255, 255, opaque ? 255 : 0), a wall
 * texture or sprite uploaded column-major as it is decoded (GL's s runs
 * down a picture column, t across columns), a flat row-major; GL_NEAREST,
 * so a pixel shows exactly one texel, chosen at its centre as the software
 * renderer chooses it. Vertex colours are flat-shaded bytes.
 *
 * Colour pass: texture modulated by the vertex colour (255, colormap level,
 * mode, 255) writes (index, level, mode, alpha); masked middles and sprites
 * pass the alpha test only where opaque. The resolve then makes each frame
 * byte on the CPU: cmap[level - fade][index] with Doom's fade
 * min(24, 1280 / depth) from the pixel's depth (every lit surface of the
 * software renderer fades by the depth of the point it shows), the sky by
 * the software renderer's formula for that column and row, black where
 * nothing was drawn. Id pass (with an id buffer): the same triangles with
 * the vertex colour replaced by the surface id's 24 packed bits (texture
 * alpha kept for the alpha test), read back into ids.
 *
 * Each pass draws the world (planes, decals with a depth offset, walls,
 * masked middles), then, with the depth buffer cleared in the sprites'
 * box, the masked middles' depth and the sprites and meshes one by one in
 * the software renderer's order (a painter's algorithm), each masked
 * through the stencil buffer by the silhouettes Doom would clip it with
 * (rgl_sprites). Between the two, the world's depth gives per column the
 * farthest depth shown, from which the silhouettes' columns and the
 * sprites' sectors are found (rgl_reach).
 *
 * Projection: eye-relative positions (x east, y north, z up) go to view
 * space l = x sin - y cos (right), d = x cos + y sin (depth), H = z; clip
 * x = l, y = (w/h) H - (2 shear / h) d, w = d: NDC x = l / d puts a point at
 * column w/2 + (w/2) l / d, and NDC y = (w/h) H / d - 2 shear / h at row
 * h/2 + shear - (w/2) H / d (focal w/2 both ways, square pixels), the
 * software renderer's projection. Near plane 1/4 unit, as R_NEAR.
 */
#include "engine/gl/rgl.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/gl.h>
#include <GL/osmesa.h>

#include "engine/core/pal.h"
#include "engine/core/tab.h"
#include "engine/gl/rgl_local.h"
#include "engine/render/r_id.h"

_Static_assert(sizeof(GLuint) == sizeof(uint32_t), "GLuint is 32 bits");

/* Far plane: beyond any two points of a map (MAP_COORD_MAX each way). */
#define RGL_FAR 65536.0

static void rgl_msg(char *err, size_t errlen, const char *what)
{
	if (err && errlen)
		snprintf(err, errlen, "%s", what);
}

static int rgl_current(const struct rgl_ctx *g)
{
	return OSMesaMakeCurrent((OSMesaContext)g->osm, g->buf, GL_UNSIGNED_BYTE, g->w, g->h) ? 0 :
									       -EIO;
}

int rgl_new(int w, int h, struct rgl_ctx **out, char *err, size_t errlen)
{
	struct rgl_ctx *g;
	const GLubyte *name;

	*out = NULL;
	if (w < 1 || h < 1 || w > 4096 || h > 4096) {
		rgl_msg(err, errlen, "frame size out of range");
		return -EINVAL;
	}
	g = calloc(1, sizeof(*g));
	if (!g)
		return -ENOMEM;
	g->w = w;
	g->h = h;
	g->buf = malloc((size_t)w * (size_t)h * 4);
	g->depth = malloc((size_t)w * (size_t)h * sizeof(*g->depth));
	g->xtoang = malloc((size_t)w * sizeof(*g->xtoang));
	g->colmax = malloc((size_t)w * sizeof(*g->colmax));
	if (!g->buf || !g->depth || !g->xtoang || !g->colmax)
		goto nomem;
	/* the ray through column x's centre, as r_new computes it */
	for (int x = 0; x < w; x++)
		g->xtoang[x] = tab_atan2((fx_t)((w - 2 * x - 1) * 4096), (fx_t)(w * 4096));
	g->osm = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
	if (!g->osm) {
		rgl_msg(err, errlen, "OSMesaCreateContextExt failed");
		rgl_free(g);
		return -EIO;
	}
	if (rgl_current(g) < 0) {
		rgl_msg(err, errlen, "OSMesaMakeCurrent failed");
		rgl_free(g);
		return -EIO;
	}
	name = glGetString(GL_RENDERER);
	snprintf(g->name, sizeof(g->name), "%s", name ? (const char *)name : "?");
	glViewport(0, 0, w, h);
	glEnable(GL_DEPTH_TEST);
	glDepthFunc(GL_LESS);
	glShadeModel(GL_FLAT);
	glDisable(GL_DITHER);
	glDisable(GL_BLEND);
	glDisable(GL_CULL_FACE);       /* on only for meshes (rgl_sprites) */
	glFrontFace(GL_CCW);           /* OBJ faces turn counter-clockwise */
	glCullFace(GL_BACK);
	glDisable(GL_LIGHTING);
	glAlphaFunc(GL_GREATER, 0.5f);
	glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	glMatrixMode(GL_MODELVIEW);
	glLoadIdentity();
	glEnableClientState(GL_VERTEX_ARRAY);
	glEnableClientState(GL_TEXTURE_COORD_ARRAY);
	glEnableClientState(GL_COLOR_ARRAY);
	*out = g;
	return 0;
nomem:
	rgl_free(g);
	return -ENOMEM;
}

static void rgl_drop_textures(struct rgl_ctx *g)
{
	if (g->osm && rgl_current(g) == 0) {
		for (int i = 0; i < g->n_wall; i++)
			if (g->gl_wall[i])
				glDeleteTextures(1, &g->gl_wall[i]);
		for (int i = 0; i < g->n_flat; i++)
			if (g->gl_flat[i])
				glDeleteTextures(1, &g->gl_flat[i]);
		for (int i = 0; i < g->n_spr; i++)
			if (g->gl_spr[i])
				glDeleteTextures(1, &g->gl_spr[i]);
		if (g->gl_fbwall)
			glDeleteTextures(1, &g->gl_fbwall);
		if (g->gl_fbflat)
			glDeleteTextures(1, &g->gl_fbflat);
	}
	free(g->gl_wall);
	free(g->gl_flat);
	free(g->gl_spr);
	g->gl_wall = g->gl_flat = g->gl_spr = NULL;
	g->n_wall = g->n_flat = g->n_spr = 0;
	g->gl_fbwall = g->gl_fbflat = 0;
	g->tex = NULL;
	g->st.textures = 0;
}

void rgl_flush(struct rgl_ctx *g)
{
	rgl_drop_textures(g);
	free(g->poff);
	free(g->sec_ss);
	free(g->sec_first);
	free(g->ss_box);
	g->ss_box = NULL;
	g->poff = NULL;
	g->sec_ss = g->sec_first = NULL;
	g->map = NULL;
	g->npv = 0;
}

void rgl_free(struct rgl_ctx *g)
{
	if (!g)
		return;
	rgl_flush(g);
	if (g->osm) {
		if (OSMesaGetCurrentContext() == (OSMesaContext)g->osm)
			OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
		OSMesaDestroyContext((OSMesaContext)g->osm);
	}
	free(g->pv);
	free(g->pieces);
	free(g->vtx);
	free(g->items);
	free(g->idx);
	free(g->buf);
	free(g->depth);
	free(g->xtoang);
	free(g->colmax);
	free(g->sils);
	free(g->sec_seen);
	free(g->spr_sec);
	free(g->sprs);
	free(g->runs);
	free(g->sidx);
	free(g->sord);
	free(g->silv);
	free(g);
}

void rgl_set_idbuf(struct rgl_ctx *g, uint32_t *ids)
{
	g->ids = ids;
}

void rgl_get_stats(const struct rgl_ctx *g, struct rgl_stats *st)
{
	*st = g->st;
}

const char *rgl_name(const struct rgl_ctx *g)
{
	return g->name;
}

/* ---- textures --------------------------------------------------------- */

/* The fallback checker's colours (r_main.c's: the palette's nearest magenta
 * and black, 8-texel squares), for the texture set's palette. */
static void rgl_fb_pixels(const struct rgl_ctx *g, uint8_t *px)
{
	for (int x = 0; x < RGL_FB_SIZE; x++)
		for (int y = 0; y < RGL_FB_SIZE; y++)
			px[x * RGL_FB_SIZE + y] = ((x ^ y) & 8) ? g->fb_lo : g->fb_hi;
}

/* A GL texture of n columns of len texels (column-major px, GL image rows
 * = columns), opaque mask op or NULL. 0 when GL has no room. */
static GLuint rgl_upload(const uint8_t *px, const uint8_t *op, int len, int n)
{
	size_t count = (size_t)len * (size_t)n;
	uint8_t *rgba = malloc(count * 4);
	GLuint name = 0;

	if (!rgba)
		return 0;
	for (size_t i = 0; i < count; i++) {
		rgba[4 * i] = px[i];
		rgba[4 * i + 1] = 255;
		rgba[4 * i + 2] = 255;
		rgba[4 * i + 3] = op && !op[i] ? 0 : 255;
	}
	glGenTextures(1, &name);
	glBindTexture(GL_TEXTURE_2D, name);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
	glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
	glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, len, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
	free(rgba);
	return name;
}

/* Makes the caches fit texture set t (dropping another set's). 0 or
 * -ENOMEM. */
static int rgl_tex_set(struct rgl_ctx *g, const struct tex_set *t)
{
	if (g->tex == t && g->n_wall == t->num_textures && g->n_flat == t->num_flats &&
	    g->n_spr == t->num_sprpics)
		return 0;
	rgl_drop_textures(g);
	g->gl_wall = calloc((size_t)t->num_textures + 1, sizeof(*g->gl_wall));
	g->gl_flat = calloc((size_t)t->num_flats + 1, sizeof(*g->gl_flat));
	g->gl_spr = calloc((size_t)t->num_sprpics + 1, sizeof(*g->gl_spr));
	if (!g->gl_wall || !g->gl_flat || !g->gl_spr) {
		rgl_drop_textures(g);
		return -ENOMEM;
	}
	g->n_wall = t->num_textures;
	g->n_flat = t->num_flats;
	g->n_spr = t->num_sprpics;
	g->fb_hi = pal_nearest(&t->pal, 255, 0, 255);
	g->fb_lo = pal_nearest(&t->pal, 0, 0, 0);
	g->tex = t;
	return 0;
}

/* The GL texture of texref, made on first use (0 if GL has no room). */
static GLuint rgl_texture(struct rgl_ctx *g, uint32_t ref)
{
	const struct tex_set *t = g->tex;
	uint32_t i = ref & 0x0fffffffu;
	GLuint *slot;
	uint8_t fb[RGL_FB_SIZE * RGL_FB_SIZE];

	switch (ref >> 28) {
	case RGL_TEX_WALL:
		slot = &g->gl_wall[i];
		if (!*slot)
			*slot = rgl_upload(t->textures[i].px, t->textures[i].opaque,
					   t->textures[i].h, t->textures[i].w);
		break;
	case RGL_TEX_FLAT:
		slot = &g->gl_flat[i];
		if (!*slot)
			*slot = rgl_upload(t->flats[i].px, NULL, TEX_FLAT_SIZE, TEX_FLAT_SIZE);
		break;
	case RGL_TEX_SPRITE:
		slot = &g->gl_spr[i];
		if (!*slot)
			*slot = rgl_upload(t->sprpics[i].px, t->sprpics[i].opaque,
					   t->sprpics[i].h, t->sprpics[i].w);
		break;
	case RGL_TEX_FBWALL:
	case RGL_TEX_FBFLAT:
		/* the checker is symmetric: the same pixels either way */
		slot = (ref >> 28) == RGL_TEX_FBWALL ? &g->gl_fbwall : &g->gl_fbflat;
		if (!*slot) {
			rgl_fb_pixels(g, fb);
			*slot = rgl_upload(fb, NULL, RGL_FB_SIZE, RGL_FB_SIZE);
		}
		break;
	default:
		return 0;
	}
	return *slot;
}

/* ---- passes ----------------------------------------------------------- */

static int rgl_item_cmp(const void *a, const void *b)
{
	const struct rgl_item *x = a, *y = b;

	if (x->key != y->key)
		return x->key < y->key ? -1 : 1;
	return x->first < y->first ? -1 : x->first > y->first;
}

/* Sorts the items by pass and texture, merging their vertices into runs of
 * indices (items[] then holds one run per key, first/count into idx).
 * 0 or -ENOMEM. */
static int rgl_batch(struct rgl_ctx *g)
{
	int n = 0, runs = 0;

	if (g->nvtx > g->maxidx) {
		uint32_t *ni = realloc(g->idx, (size_t)g->nvtx * sizeof(*ni));

		if (!ni)
			return -ENOMEM;
		g->idx = ni;
		g->maxidx = g->nvtx;
	}
	qsort(g->items, (size_t)g->nitems, sizeof(*g->items), rgl_item_cmp);
	for (int i = 0; i < g->nitems; i++) {
		struct rgl_item it = g->items[i];

		if (runs == 0 || g->items[runs - 1].key != it.key) {
			g->items[runs].key = it.key;
			g->items[runs].tex = it.tex;
			g->items[runs].first = n;
			g->items[runs].count = 0;
			runs++;
		}
		for (int k = 0; k < it.count; k++)
			g->idx[n++] = (uint32_t)(it.first + k);
		g->items[runs - 1].count += it.count;
	}
	g->nitems = runs;
	return 0;
}

/* Projection times view rotation, column-major, for eye-relative
 * positions (see the top of this file). */
static void rgl_matrix(const struct rgl_ctx *g, double *mat, int with_view)
{
	double s = g->vsin / 65536.0, c = g->vcos / 65536.0;
	double n = RGL_NEAR, f = RGL_FAR;
	double a = -(f + n) / (f - n), b = -2 * f * n / (f - n);
	double ar = (double)g->w / g->h, sh = 2.0 * g->shear / g->h;
	/* view: (x, y, z) -> x_e = s x - c y, y_e = z, z_e = -(c x + s y) */
	double view[3][3] = { { s, -c, 0 }, { 0, 0, 1 }, { -c, -s, 0 } };
	static const double ident[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
	/* projection rows applied to (x_e, y_e, z_e, 1) */
	double proj[4][4] = { { 1, 0, 0, 0 }, { 0, ar, sh, 0 }, { 0, 0, a, b }, { 0, 0, -1, 0 } };

	for (int row = 0; row < 4; row++) {
		for (int col = 0; col < 3; col++) {
			double v = 0;

			for (int k = 0; k < 3; k++)
				v += proj[row][k] * (with_view ? view[k][col] : ident[k][col]);
			mat[col * 4 + row] = v;
		}
		mat[12 + row] = proj[row][3];
	}
}

/* One run, textured unless only depth or ids are written and the run is
 * not alpha-tested. */
static void rgl_item_draw(struct rgl_ctx *g, const struct rgl_item *it, int plain)
{
	uint32_t ref = it->tex;
	int pass = (int)(it->key >> 32);
	int alpha = pass == RGL_MASKED || pass == RGL_MDECAL || pass == RGL_SPRITE;
	GLuint name = 0;

	if (ref && (!plain || alpha))
		name = rgl_texture(g, ref);
	if (name) {
		glEnable(GL_TEXTURE_2D);
		glBindTexture(GL_TEXTURE_2D, name);
		glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, alpha ? GL_CLAMP_TO_EDGE : GL_REPEAT);
		glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T,
				pass == RGL_SPRITE ? GL_CLAMP_TO_EDGE : GL_REPEAT);
	} else {
		glDisable(GL_TEXTURE_2D);
	}
	if (alpha && name)
		glEnable(GL_ALPHA_TEST);
	else
		glDisable(GL_ALPHA_TEST);
	glDrawElements(GL_TRIANGLES, it->count, GL_UNSIGNED_INT, &g->idx[it->first]);
	g->st.draws++;
}

/* The runs of the passes in the mask (1 << enum rgl_pass). */
static void rgl_runs(struct rgl_ctx *g, unsigned mask, int plain)
{
	for (int i = 0; i < g->nitems; i++)
		if (mask & (1u << (int)(g->items[i].key >> 32)))
			rgl_item_draw(g, &g->items[i], plain);
}

/* View depth of a depth-buffer value (window z in [0, 1]). */
static double rgl_view_depth(float z)
{
	const double n = RGL_NEAR, f = RGL_FAR;

	return 2.0 * f * n / ((f + n) - (2.0 * z - 1.0) * (f - n));
}

/* What a pass writes: the frame's colour channels or surface ids. */
enum rgl_out { RGL_OUT_COLOUR, RGL_OUT_IDS };

/* The world (everything but sprites) into a cleared colour and depth
 * buffer. */
static void rgl_world(struct rgl_ctx *g, enum rgl_out out)
{
	const struct rgl_vtx *v = g->vtx;
	GLsizei stride = (GLsizei)sizeof(*v);

	if (out != RGL_OUT_COLOUR) {
		glClearColor(0, 0, 0, 0);
		glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
		glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_REPLACE);
		glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PRIMARY_COLOR);
		glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, GL_SRC_COLOR);
		glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
		glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);
		glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_ALPHA);
	} else {
		glClearColor(0, 0, RGL_MODE_NONE / 255.0f, 0);
		glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
	}
	glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
	if (g->nvtx == 0)
		return;
	glVertexPointer(3, GL_FLOAT, stride, &v->x);
	glTexCoordPointer(4, GL_FLOAT, stride, &v->s);
	glColorPointer(4, GL_UNSIGNED_BYTE, stride, out == RGL_OUT_COLOUR ? v->c : v->id);
	rgl_runs(g, 1u << RGL_PLANE, out != RGL_OUT_COLOUR);
	/* decals lie on a floor: drawn nearer by a depth offset */
	glEnable(GL_POLYGON_OFFSET_FILL);
	glPolygonOffset(-1.0f, -4.0f);
	rgl_runs(g, 1u << RGL_DECAL, out != RGL_OUT_COLOUR);
	glDisable(GL_POLYGON_OFFSET_FILL);
	rgl_runs(g, (1u << RGL_WALL) | (1u << RGL_MASKED), out != RGL_OUT_COLOUR);
	glEnable(GL_POLYGON_OFFSET_FILL);
	rgl_runs(g, 1u << RGL_MDECAL, out != RGL_OUT_COLOUR);
	glDisable(GL_POLYGON_OFFSET_FILL);
}

/* The software renderer's drawing order of sprites and meshes (r_things.c):
 * by the scale at their centre, smaller (farther) first, ties in the
 * list's order. */
static int rgl_sord_cmp(const void *a, const void *b)
{
	const struct rgl_sord *x = a, *y = b;

	if (x->scale != y->scale)
		return x->scale < y->scale ? -1 : 1;
	return x->k < y->k ? -1 : x->k > y->k;
}

/* The depth buffer in window box (x0, y0)-(x1, y1) back to the masked
 * middles alone (after a mesh wrote its own). */
static void rgl_depth_reset(struct rgl_ctx *g, int x0, int y0, int x1, int y1)
{
	if (x1 <= x0 || y1 <= y0)
		return;
	glScissor(x0, y0, x1 - x0, y1 - y0);
	glDepthMask(GL_TRUE);          /* glClear honours the mask */
	glClear(GL_DEPTH_BUFFER_BIT);
	glDisable(GL_STENCIL_TEST);
	glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
	rgl_runs(g, 1u << RGL_MASKED, 1);
	glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	glEnable(GL_STENCIL_TEST);
}

/* The sprites and meshes over the world, with the depth buffer cleared in
 * their box and holding only the masked middles, in the software
 * renderer's order (farthest centre first: a painter's algorithm, as
 * Doom's): each is clipped, through the stencil buffer, by the silhouettes
 * Doom's R_DrawSprite would take as in front of it (not by the walls
 * themselves: where a silhouette is missing, e.g. a zero-height sector's
 * walls, a sprite shows through, as in Doom), and by the masked middles'
 * depth, never by another sprite's: billboards write no depth, and a mesh's
 * depth (which sorts its own triangles) is put back to the masked middles'
 * in its box after it is drawn. Only those standing in a sector the walk
 * would reach are drawn. */
static void rgl_sprites(struct rgl_ctx *g, const struct map *m, enum rgl_out out)
{
	const struct rgl_vtx *v = g->vtx;
	GLsizei stride = (GLsizei)sizeof(*v);
	int x0 = g->sbox[0] < 0 ? 0 : g->sbox[0], y0 = g->sbox[1] < 0 ? 0 : g->sbox[1];
	int x1 = g->sbox[2] > g->w ? g->w : g->sbox[2], y1 = g->sbox[3] > g->h ? g->h : g->sbox[3];
	int nord = 0;

	if (g->nvtx == 0 || g->st.sprites == 0 || x1 <= x0 || y1 <= y0)
		return;
	for (int i = 0; i < g->nitems; i++) {
		uint32_t k = (uint32_t)g->items[i].key;

		if ((g->items[i].key >> 32) != RGL_SPRITE || g->sec_seen[g->spr_sec[k]] != 1 ||
		    g->sprs[k].x1 < g->sprs[k].x0 || nord >= g->maxsord)
			continue;
		g->sord[nord].scale = g->sprs[k].scale;
		g->sord[nord].k = k;
		g->sord[nord].item = i;
		nord++;
	}
	qsort(g->sord, (size_t)nord, sizeof(*g->sord), rgl_sord_cmp);
	glEnable(GL_SCISSOR_TEST);
	glScissor(x0, y0, x1 - x0, y1 - y0);
	glClear(GL_DEPTH_BUFFER_BIT);
	glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
	rgl_runs(g, 1u << RGL_MASKED, 1);
	glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
	glDepthFunc(GL_LEQUAL);
	glEnable(GL_STENCIL_TEST);
	for (int o = 0; o < nord; o++) {
		const struct rgl_item *it = &g->items[g->sord[o].item];
		uint32_t k = g->sord[o].k;
		const struct rgl_sprrec *sp = &g->sprs[k];
		int n, sx0 = sp->x0 > x0 ? sp->x0 : x0, sx1 = sp->x1 + 1 < x1 ? sp->x1 + 1 : x1;

		if (sx1 <= sx0)
			continue;
		n = rgl_geo_sprite_sils(g, m, (int)k, g->sidx);
		glStencilFunc(GL_ALWAYS, 0, 1);
		glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
		if (n > 0) {
			/* the silhouettes in front of it, in its columns */
			glScissor(sx0, y0, sx1 - sx0, y1 - y0);
			glClear(GL_STENCIL_BUFFER_BIT);
			glStencilFunc(GL_ALWAYS, 1, 1);
			glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
			glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
			glDisable(GL_DEPTH_TEST);
			glDisable(GL_TEXTURE_2D);
			glDisable(GL_ALPHA_TEST);
			glVertexPointer(3, GL_FLOAT, stride, &g->silv->x);
			glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, g->sidx);
			glVertexPointer(3, GL_FLOAT, stride, &v->x);
			glEnable(GL_DEPTH_TEST);
			glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
			glStencilFunc(GL_EQUAL, 0, 1);
			glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
			glScissor(x0, y0, x1 - x0, y1 - y0);
		}
		/* a billboard is built in view space, a mesh in the world; a
		 * mesh's faces turned away are not drawn (r_mesh.c skips them) */
		glMatrixMode(GL_PROJECTION);
		glLoadMatrixd(sp->mesh ? g->mat_world : g->mat_view);
		glDepthMask(sp->mesh ? GL_TRUE : GL_FALSE);
		if (sp->mesh)
			glEnable(GL_CULL_FACE);
		rgl_item_draw(g, it, out != RGL_OUT_COLOUR);
		glDisable(GL_CULL_FACE);
		glLoadMatrixd(g->mat_world);
		glMatrixMode(GL_MODELVIEW);
		if (sp->mesh) {
			int by0 = sp->y0 > y0 ? sp->y0 : y0, by1 = sp->y1 < y1 ? sp->y1 : y1;

			rgl_depth_reset(g, sx0, by0, sx1, by1);
			glScissor(x0, y0, x1 - x0, y1 - y0);
		}
	}
	glDepthMask(GL_TRUE);
	glDisable(GL_STENCIL_TEST);
	glDepthFunc(GL_LESS);
	glDisable(GL_SCISSOR_TEST);
}

/* Room in sidx for every silhouette vertex. 0 or -ENOMEM. */
static int rgl_grow_sidx(struct rgl_ctx *g)
{
	uint32_t *n = realloc(g->sidx, (size_t)g->nsilv * sizeof(*n));

	if (!n)
		return -ENOMEM;
	g->sidx = n;
	g->maxsidx = g->nsilv;
	return 0;
}

/* After the world's colour pass, from its depth: the silhouettes of the
 * columns segs reach, and which sprites' sectors the walk would reach. */
static void rgl_reach(struct rgl_ctx *g, const struct map *m)
{
	g->nsilv = 0;
	g->nruns = 0;
	if (g->st.sprites == 0)
		return;
	/* the farthest depth over pairs of rows: a single pixel where the
	 * rasterizer leaves a crack between a wall and a floor does not count */
	for (int x = 0; x < g->w; x++) {
		float zmax = 0, above = 1;

		for (int y = 0; y < g->h; y++) {
			float z = g->depth[(size_t)y * (size_t)g->w + (size_t)x];
			float pair = z < above ? z : above;

			zmax = pair > zmax ? pair : zmax;
			above = z;
		}
		g->colmax[x] = (float)rgl_view_depth(zmax);
	}
	if (rgl_geo_sils(g, g->colmax) < 0 || (g->nsilv > g->maxsidx && rgl_grow_sidx(g) < 0))
		g->nsilv = g->nruns = 0;
	memset(g->sec_seen, 0, m->num_sectors);
	for (int i = 0; i < g->nitems; i++) {
		uint32_t sec;

		if ((g->items[i].key >> 32) != RGL_SPRITE)
			continue;
		sec = g->spr_sec[(uint32_t)g->items[i].key];
		if (sec < m->num_sectors && !g->sec_seen[sec])
			g->sec_seen[sec] = rgl_geo_reached(g, sec, g->colmax) ? 1 : 2;
	}
}

/* ---- resolve ---------------------------------------------------------- */

/* The software renderer's sky texel at column x, row y (r_plane.c). */
static uint8_t rgl_sky(const struct rgl_ctx *g, const struct tex_pic *sky, const uint8_t *cm,
		       int x, int y, int cy2)
{
	int64_t step = ((int64_t)RGL_SKY_COLS << 16) / g->w, hf = (int64_t)sky->h << 16;
	int col = (int)(((g->angle + g->xtoang[x]) >> RGL_SKY_SHIFT) % (uint32_t)sky->w);
	const uint8_t *src = sky->px + (size_t)col * (size_t)sky->h;
	int64_t v = ((int64_t)RGL_SKY_MID << 16) + (((int64_t)(2 * y + 1 - cy2) * step) >> 1);

	return cm[src[v < 0 ? 0 : (v % hf) >> 16]];
}

static void rgl_resolve(struct rgl_ctx *g, const struct tex_set *t, struct r_frame *f)
{
	struct tex_pic fbpic = { .w = RGL_FB_SIZE, .h = RGL_FB_SIZE };
	uint8_t fb[RGL_FB_SIZE * RGL_FB_SIZE];
	const struct tex_pic *sky;
	int idx, isfb, cy2 = g->h + 2 * g->shear;

	sky = rgl_wall_pic(t, (uint16_t)(t->sky_tex > 0 ? t->sky_tex : 0), &idx, &isfb);
	if (!sky) {
		rgl_fb_pixels(g, fb);
		fbpic.px = fb;
		sky = &fbpic;
	}
	for (int y = 0; y < g->h; y++) {
		const uint8_t *src = g->buf + (size_t)(g->h - 1 - y) * (size_t)g->w * 4;
		const float *dz = g->depth + (size_t)(g->h - 1 - y) * (size_t)g->w;
		uint8_t *dst = f->px + (size_t)y * (size_t)f->pitch;

		for (int x = 0; x < g->w; x++, src += 4) {
			double d;
			int lvl, fade;

			switch (src[2]) {
			case RGL_MODE_LIT:
				d = rgl_view_depth(dz[x]);
				fade = d * RGL_FADE_MAX >= RGL_FADE_DIST ? (int)(RGL_FADE_DIST / d) :
									   RGL_FADE_MAX;
				lvl = src[1] - fade;
				lvl = lvl < 0 ? 0 : lvl > PAL_LIGHTS - 1 ? PAL_LIGHTS - 1 : lvl;
				dst[x] = t->pal.cmap[lvl][src[0]];
				break;
			case RGL_MODE_SKY:
				dst[x] = rgl_sky(g, sky, t->pal.cmap[0], x, y, cy2);
				break;
			case RGL_MODE_RAW:
				dst[x] = src[0];
				break;
			case RGL_MODE_FIXED:
				dst[x] = t->pal.cmap[src[1] < PAL_LIGHTS ? src[1] : PAL_LIGHTS - 1][src[0]];
				break;
			default:
				dst[x] = g->black;
				break;
			}
		}
	}
}

static void rgl_read_ids(const struct rgl_ctx *g)
{
	for (int y = 0; y < g->h; y++) {
		const uint8_t *src = g->buf + (size_t)(g->h - 1 - y) * (size_t)g->w * 4;
		uint32_t *dst = g->ids + (size_t)y * (size_t)g->w;

		for (int x = 0; x < g->w; x++, src += 4) {
			uint32_t packed = src[0] | ((uint32_t)src[1] << 8) | ((uint32_t)src[2] << 16);

			dst[x] = r_id((enum r_id_kind)(packed >> 20), packed & 0xfffffu);
		}
	}
}

void rgl_render(struct rgl_ctx *g, const struct map *m, const struct tex_set *t,
		const struct r_view *v, const struct r_sprite *spr, int nspr, struct r_frame *f)
{
	int shear = v->shear;

	memset(&g->st, 0, sizeof(g->st));
	g->ex = v->x > MAP_COORD_MAX ? MAP_COORD_MAX : v->x < -MAP_COORD_MAX ? -MAP_COORD_MAX : v->x;
	g->ey = v->y > MAP_COORD_MAX ? MAP_COORD_MAX : v->y < -MAP_COORD_MAX ? -MAP_COORD_MAX : v->y;
	g->ez = v->z;
	g->angle = v->angle;
	g->vcos = tab_cos(v->angle);
	g->vsin = tab_sin(v->angle);
	g->shear = shear > g->h ? g->h : shear < -g->h ? -g->h : shear;
	g->black = pal_nearest(&t->pal, 0, 0, 0);
	if (rgl_current(g) < 0 || rgl_tex_set(g, t) < 0 ||
	    ((g->map != m || g->map_hash != m->content_hash || g->map_nss != m->num_subsectors) &&
	     rgl_geo_polys(g, m) < 0) ||
	    rgl_geo_build(g, m, t, spr, nspr) < 0 || rgl_batch(g) < 0) {
		/* out of memory: a black frame (and no surfaces) */
		for (int y = 0; y < f->h; y++)
			memset(f->px + (size_t)y * (size_t)f->pitch, g->black, (size_t)f->w);
		if (g->ids)
			memset(g->ids, 0, (size_t)g->w * (size_t)g->h * sizeof(*g->ids));
		g->st.missing++;
		return;
	}
	rgl_matrix(g, g->mat_world, 1);
	rgl_matrix(g, g->mat_view, 0);
	glMatrixMode(GL_PROJECTION);
	glLoadMatrixd(g->mat_world);
	glMatrixMode(GL_MODELVIEW);
	rgl_world(g, RGL_OUT_COLOUR);
	glReadPixels(0, 0, g->w, g->h, GL_DEPTH_COMPONENT, GL_FLOAT, g->depth);
	rgl_reach(g, m);
	rgl_sprites(g, m, RGL_OUT_COLOUR);
	glFinish();
	rgl_resolve(g, t, f);
	if (g->ids) {
		rgl_world(g, RGL_OUT_IDS);
		rgl_sprites(g, m, RGL_OUT_IDS);
		glFinish();
		rgl_read_ids(g);
	}
	for (int i = 0; i < g->n_wall; i++)
		g->st.textures += g->gl_wall[i] != 0;
	for (int i = 0; i < g->n_flat; i++)
		g->st.textures += g->gl_flat[i] != 0;
	for (int i = 0; i < g->n_spr; i++)
		g->st.textures += g->gl_spr[i] != 0;
}
