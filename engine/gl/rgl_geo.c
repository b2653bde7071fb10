/*
 * rgl_geo: the world as triangles for the OSMesa renderer.
 *
 * Floors and ceilings: each subsector's convex polygon, made once per map
 * the way GL node builders make them: a box larger than any map is cut by
 * the partition line of every node on the path from the root (keeping the
 * subsector's side), then by the line of each of the subsector's segs
 * (keeping its front). Vanilla nodes store partitions and split vertices
 * rounded to whole units, so neighbouring polygons can overlap or leave
 * slivers a fraction of a unit wide: "slime trails", a few pixels at most.
 *
 * Walls: one quad per seg part, in the seg's own plane, with the software
 * renderer's rules (engine/render/r_seg.c): drawn only when the eye is strictly on
 * the seg's front side (the same exact integer test), texture u = seg offset
 * + side x offset + distance along the seg, texel row = (height of texel
 * row 0) - height, pegging per ML_DONTPEGTOP / ML_DONTPEGBOTTOM. Two sky
 * ceilings: no upper wall, a sky quad down to the lower ceiling instead. A
 * missing upper or lower texture shows the back sector's ceiling or floor
 * as the software renderer's visplanes do (Doom's "flat bleeding"): a quad
 * in the wall's place textured with that flat by projective texture
 * coordinates (s/q, t/q is where the pixel's ray meets the plane). Masked
 * middles: one quad, the texture's height from its pegged top, clipped to
 * the opening. A seg whose front floor is not below the eye (or ceiling not
 * above it) gets a black skirt below that floor (above that ceiling): the
 * rows the software renderer fills black for a plane seen from behind.
 *
 * Sprites: a quad parallel to the view plane at the thing's depth, from
 * its left offset to its width, top at z + top offset, the rotation and
 * mirroring Doom picks (the software renderer's formula and tables).
 *
 * Meshes: the built-in mesh's triangles in the world, turned and placed
 * in the software renderer's integer steps (rgl_mesh).
 *
 * Positions are relative to the eye, so that floats keep their precision
 * where the depth buffer needs it. Everything a frame needs is rebuilt
 * each frame (sector heights move), except the polygons' x and y.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/tab.h"
#include "engine/gl/rgl_local.h"
#include "engine/map/mesh_builtin.h"
#include "engine/render/r_id.h"
#include "engine/render/r_main.h"

#define RGL_BOX (MAP_COORD_MAX / 65536.0 * 2.0)

static double rgl_fx(fx_t v)
{
	return v / 65536.0;
}

int rgl_light_base(int light)
{
	int base;

	light = light < 0 ? 0 : light > 255 ? 255 : light;
	base = 4 * (15 - (light >> 4));
	return base > PAL_LIGHTS - 1 ? PAL_LIGHTS - 1 : base;
}

const struct tex_pic *rgl_wall_pic(const struct tex_set *t, uint16_t num, int *index, int *fb)
{
	int n = tex_wall_index(t, num);

	*fb = n < 0;
	*index = n > 0 ? n : 0;
	return n > 0 ? &t->textures[n] : NULL;
}

/* ---- subsector polygons ---------------------------------------------- */

/* Keeps the part of polygon in[0..n-1] (x, y pairs) on one side of the
 * line through (px, py) along (dx, dy): the right side (cross <= 0) when
 * right, else the left. Points within a millionth of a unit of the line
 * count as on it. Returns the new count (<= RGL_POLY_MAX). */
static int rgl_clip(const double *in, int n, double *out, double px, double py, double dx,
		    double dy, int right)
{
	double len = sqrt(dx * dx + dy * dy);
	double dist[RGL_POLY_MAX];
	int k = 0;

	if (len <= 0)
		return 0;
	for (int i = 0; i < n; i++) {
		double c = (dx * (in[2 * i + 1] - py) - dy * (in[2 * i] - px)) / len;

		dist[i] = right ? -c : c;      /* >= 0: kept */
		if (dist[i] > -1e-6 && dist[i] < 1e-6)
			dist[i] = 0;
	}
	for (int i = 0; i < n && k < RGL_POLY_MAX - 1; i++) {
		int j = (i + 1) % n;

		if (dist[i] >= 0) {
			out[2 * k] = in[2 * i];
			out[2 * k + 1] = in[2 * i + 1];
			k++;
		}
		if ((dist[i] > 0 && dist[j] < 0) || (dist[i] < 0 && dist[j] > 0)) {
			double f = dist[i] / (dist[i] - dist[j]);

			out[2 * k] = in[2 * i] + f * (in[2 * j] - in[2 * i]);
			out[2 * k + 1] = in[2 * i + 1] + f * (in[2 * j + 1] - in[2 * i + 1]);
			k++;
		}
	}
	return k;
}

static int rgl_poly_store(struct rgl_ctx *g, uint32_t ss, const double *p, int n)
{
	/* a point is two doubles */
	if (r_grow((void **)&g->pv, &g->maxpv, 2 * sizeof(*g->pv), g->npv + n) < 0)
		return -ENOMEM;
	memcpy(&g->pv[2 * g->npv], p, (size_t)n * 2 * sizeof(*p));
	g->poff[ss] = g->npv;
	g->poff[g->map_nss + ss] = n;
	g->npv += n;
	return 0;
}

static int rgl_poly_subsector(struct rgl_ctx *g, const struct map *m, uint32_t i, double *p,
			      int n, double *tmp)
{
	const struct map_subsector *ss;

	if (i >= m->num_subsectors)
		return 0;
	ss = &m->subsectors[i];
	for (uint32_t k = 0; k < ss->num_segs && n >= 3; k++) {
		const struct map_seg *sg;
		const struct map_vertex *a, *b;

		if (ss->first_seg + k >= m->num_segs)
			break;
		sg = &m->segs[ss->first_seg + k];
		/* a two-sided seg lies on a partition line already (its sides
		 * are in different subsectors): cutting by its rounded ends
		 * again would only open slivers between neighbours */
		if (sg->v1 >= m->num_vertices || sg->v2 >= m->num_vertices || sg->back != MAP_NONE)
			continue;
		a = &m->vertices[sg->v1];
		b = &m->vertices[sg->v2];
		n = rgl_clip(p, n, tmp, rgl_fx(a->x), rgl_fx(a->y), rgl_fx(b->x) - rgl_fx(a->x),
			     rgl_fx(b->y) - rgl_fx(a->y), 1);
		memcpy(p, tmp, (size_t)n * 2 * sizeof(*p));
	}
	return n >= 3 ? rgl_poly_store(g, i, p, n) : 0;
}

/* The node (or subsector) child with polygon p[0..n-1]; limit as in
 * r_bsp.c (children are listed before parents). */
static int rgl_poly_node(struct rgl_ctx *g, const struct map *m, uint32_t child, uint32_t limit,
			 const double *p, int n)
{
	double *a = malloc(3 * RGL_POLY_MAX * 2 * sizeof(*a));
	int rc = 0;

	if (!a)
		return -ENOMEM;
	if (child & MAP_NF_SUBSECTOR) {
		memcpy(a, p, (size_t)n * 2 * sizeof(*p));
		rc = rgl_poly_subsector(g, m, child & ~MAP_NF_SUBSECTOR, a, n,
					a + 2 * RGL_POLY_MAX);
	} else if (child < limit) {
		const struct map_node *nd = &m->nodes[child];

		/* a subsector's box is the one its parent keeps for it */
		for (int side = 0; side < 2; side++) {
			uint32_t c = nd->child[side];

			if ((c & MAP_NF_SUBSECTOR) && (c & ~MAP_NF_SUBSECTOR) < g->map_nss) {
				double *b = &g->ss_box[4 * (c & ~MAP_NF_SUBSECTOR)];

				b[0] = rgl_fx(nd->bbox[side][BOX_LEFT]);
				b[1] = rgl_fx(nd->bbox[side][BOX_BOTTOM]);
				b[2] = rgl_fx(nd->bbox[side][BOX_RIGHT]);
				b[3] = rgl_fx(nd->bbox[side][BOX_TOP]);
			}
		}
		for (int side = 0; side < 2 && rc == 0; side++) {
			int k = rgl_clip(p, n, a, rgl_fx(nd->x), rgl_fx(nd->y), rgl_fx(nd->dx),
					 rgl_fx(nd->dy), side == 0);

			if (k >= 3)
				rc = rgl_poly_node(g, m, nd->child[side], child, a, k);
		}
	}
	free(a);
	return rc;
}

int rgl_geo_polys(struct rgl_ctx *g, const struct map *m)
{
	double box[8] = { -RGL_BOX, -RGL_BOX, -RGL_BOX, RGL_BOX,
			  RGL_BOX, RGL_BOX, RGL_BOX, -RGL_BOX };

	free(g->poff);
	free(g->sec_ss);
	free(g->sec_first);
	free(g->ss_box);
	g->ss_box = malloc(((size_t)m->num_subsectors + 1) * 4 * sizeof(*g->ss_box));
	g->poff = calloc((size_t)m->num_subsectors * 2 + 1, sizeof(*g->poff));
	g->sec_ss = malloc(((size_t)m->num_subsectors + 1) * sizeof(*g->sec_ss));
	g->sec_first = calloc((size_t)m->num_sectors + 2, sizeof(*g->sec_first));
	g->map = NULL;
	g->npv = 0;
	if (!g->poff || !g->sec_ss || !g->sec_first || !g->ss_box)
		return -ENOMEM;
	/* a map without nodes: its one subsector is seen from anywhere */
	for (uint32_t i = 0; i < 4 * (m->num_subsectors + 1); i++)
		g->ss_box[i] = (i % 4) < 2 ? -RGL_BOX : RGL_BOX;
	g->map_nss = m->num_subsectors;
	g->map_nsecs = m->num_sectors;
	/* a counting sort of the subsectors by sector */
	for (uint32_t i = 0; i < m->num_subsectors; i++)
		if (m->subsectors[i].sector < m->num_sectors)
			g->sec_first[m->subsectors[i].sector + 2]++;
	for (uint32_t i = 0; i < m->num_sectors; i++)
		g->sec_first[i + 2] += g->sec_first[i + 1];
	for (uint32_t i = 0; i < m->num_subsectors; i++)
		if (m->subsectors[i].sector < m->num_sectors)
			g->sec_ss[g->sec_first[m->subsectors[i].sector + 1]++] = i;
	if (m->num_nodes == 0) {
		double a[4 * RGL_POLY_MAX];

		memcpy(a, box, sizeof(box));
		if (m->num_subsectors > 0 &&
		    rgl_poly_subsector(g, m, 0, a, 4, a + 2 * RGL_POLY_MAX) < 0)
			return -ENOMEM;
	} else if (rgl_poly_node(g, m, m->num_nodes - 1, m->num_nodes, box, 4) < 0) {
		return -ENOMEM;
	}
	g->map = m;
	g->map_hash = m->content_hash;
	return 0;
}

/* ---- triangles -------------------------------------------------------- */

/* What every vertex of a surface shares. */
struct rgl_surf {
	uint64_t key;
	uint32_t tex;
	uint8_t c[4];
	uint8_t id[4];
};

/* Room for n more vertices in an item of surface s; returns them, or
 * NULL. */
static struct rgl_vtx *rgl_push(struct rgl_ctx *g, const struct rgl_surf *s, int n)
{
	uint64_t key = s->key;

	struct rgl_item *it;

	if (r_grow((void **)&g->vtx, &g->maxvtx, sizeof(*g->vtx), g->nvtx + n) < 0)
		return NULL;
	it = g->nitems ? &g->items[g->nitems - 1] : NULL;
	if (!it || it->key != key || it->first + it->count != g->nvtx) {
		if (r_grow((void **)&g->items, &g->maxitems, sizeof(*g->items), g->nitems + 1) < 0)
			return NULL;
		it = &g->items[g->nitems++];
		it->key = key;
		it->tex = s->tex;
		it->first = g->nvtx;
		it->count = 0;
	}
	it->count += n;
	g->nvtx += n;
	g->st.triangles += (uint32_t)n / 3;
	return &g->vtx[g->nvtx - n];
}

static void rgl_surf(struct rgl_surf *s, enum rgl_pass pass, uint32_t texref, int index,
		     int level, enum rgl_mode mode, uint32_t id)
{
	/* 24 bits of id survive the colour buffer: kind, then 20 of index */
	uint32_t packed = ((uint32_t)r_id_kind(id) << 20) | (r_id_index(id) & 0xfffffu);

	s->key = ((uint64_t)pass << 32) | texref;
	s->tex = texref;
	s->c[0] = (uint8_t)index;
	s->c[1] = (uint8_t)level;
	s->c[2] = (uint8_t)mode;
	s->c[3] = 255;
	s->id[0] = (uint8_t)packed;
	s->id[1] = (uint8_t)(packed >> 8);
	s->id[2] = (uint8_t)(packed >> 16);
	s->id[3] = 255;
}

static void rgl_set(struct rgl_vtx *v, const struct rgl_surf *s, double x, double y, double z,
		    double ts, double tt, double tq)
{
	v->x = (float)x;
	v->y = (float)y;
	v->z = (float)z;
	v->s = (float)ts;
	v->t = (float)tt;
	v->r = 0;
	v->q = (float)tq;
	memcpy(v->c, s->c, 4);
	memcpy(v->id, s->id, 4);
}

/* A seg's line in eye-relative coordinates and its texture u range. */
struct rgl_line {
	double ax, ay, bx, by;          /* ends, relative to the eye */
	double u0, len;                 /* u at a, seg length */
};

/* Corners of a wall quad, top a, top b, bottom b, bottom a, as two
 * triangles. tc: (s, t, q) per corner. */
static int rgl_quad(struct rgl_ctx *g, const struct rgl_surf *s, const struct rgl_line *l,
		    double zb, double zt, const double tc[4][3])
{
	struct rgl_vtx *v = rgl_push(g, s, 6);
	static const int tri[6] = { 0, 1, 2, 0, 2, 3 };

	if (!v)
		return -ENOMEM;
	for (int i = 0; i < 6; i++) {
		int k = tri[i];
		double x = k == 0 || k == 3 ? l->ax : l->bx;
		double y = k == 0 || k == 3 ? l->ay : l->by;

		rgl_set(&v[i], s, x, y, k < 2 ? zt : zb, tc[k][0], tc[k][1], tc[k][2]);
	}
	g->st.walls++;
	return 0;
}

/* A textured wall part between heights zb < zt (relative to the eye);
 * texel row 0 at tm above the eye. */
static int rgl_wall_part(struct rgl_ctx *g, const struct rgl_surf *s, const struct rgl_line *l,
			 double zb, double zt, double tm, const struct tex_pic *p)
{
	double tc[4][3];
	double sh = p ? p->h : RGL_FB_SIZE, sw = p ? p->w : RGL_FB_SIZE;

	if (zt <= zb)
		return 0;
	/* GL's s runs down a picture column (v / h), t across columns (u / w) */
	tc[0][0] = tc[1][0] = (tm - zt) / sh;
	tc[2][0] = tc[3][0] = (tm - zb) / sh;
	tc[0][1] = tc[3][1] = l->u0 / sw;
	tc[1][1] = tc[2][1] = (l->u0 + l->len) / sw;
	for (int i = 0; i < 4; i++)
		tc[i][2] = 1;
	return rgl_quad(g, s, l, zb, zt, tc);
}

/* An untextured quad (sky, black). */
static int rgl_flat_quad(struct rgl_ctx *g, const struct rgl_surf *s, const struct rgl_line *l,
			 double zb, double zt)
{
	static const double tc[4][3] = { { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 } };

	return zt > zb ? rgl_quad(g, s, l, zb, zt, tc) : 0;
}

/* The texref of flat num now, and whether it is the sky. */
static uint32_t rgl_flat_ref(struct rgl_ctx *g, const struct tex_set *t, uint16_t num)
{
	int n = num;

	if (t->flat_xlat && n < t->num_flats)
		n = t->flat_xlat[n];
	if (n >= t->num_flats || !t->flats) {
		g->st.missing++;
		return RGL_TEXREF(RGL_TEX_FBFLAT, 0);
	}
	return RGL_TEXREF(RGL_TEX_FLAT, n);
}

static int rgl_is_sky(const struct tex_set *t, uint16_t num)
{
	return t->sky_flat >= 0 && num == t->sky_flat;
}

/* The back sector's plane seen in place of a missing upper (ceil) or lower
 * wall part: the flat projected from the plane at height hp above the eye
 * (homogeneous coordinates: at a point P of the quad, q = P.z and
 * (s, t) * q = the world position where the ray through P meets the plane,
 * divided by 64), or the sky. */
static int rgl_bleed(struct rgl_ctx *g, const struct tex_set *t, const struct map_sector *bs,
		     uint32_t bsec, int ceil, const struct rgl_line *l, double zb, double zt)
{
	uint16_t pic = ceil ? bs->ceil_tex : bs->floor_tex;
	double hp = rgl_fx(ceil ? bs->ceil_h : bs->floor_h) - rgl_fx(g->ez);
	double ex = rgl_fx(g->ex), ey = rgl_fx(g->ey), tc[4][3];
	struct rgl_surf s;

	if (zt <= zb || rgl_is_sky(t, pic))
		return 0;
	/* the software renderer has no plane there when it is seen from
	 * behind */
	if (ceil ? hp <= 0 : hp >= 0)
		return 0;
	rgl_surf(&s, RGL_PLANE, rgl_flat_ref(g, t, pic), 255, rgl_light_base(bs->light),
		 RGL_MODE_LIT, r_id(ceil ? R_IDK_CEIL : R_IDK_FLOOR, bsec));
	for (int k = 0; k < 4; k++) {
		double px = k == 0 || k == 3 ? l->ax : l->bx;
		double py = k == 0 || k == 3 ? l->ay : l->by;
		double pz = k < 2 ? zt : zb;

		/* world x = ex + px * hp / pz */
		tc[k][0] = (ex * pz + px * hp) / 64.0;
		tc[k][1] = -(ey * pz + py * hp) / 64.0;
		tc[k][2] = pz;
	}
	return rgl_quad(g, &s, l, zb, zt, tc);
}

/* 0 when the points (x y pairs, less ox, oy: relative to the eye) all lie
 * outside one side of the 90-degree view frustum (behind the near plane, or
 * beyond its left or right plane): nothing standing on them can show. */
static int rgl_in_view(const struct rgl_ctx *g, const double *p, int n, double ox, double oy)
{
	double c = rgl_fx(g->vcos), s = rgl_fx(g->vsin);
	int behind = 1, left = 1, right = 1;

	for (int i = 0; i < n; i++) {
		double x = p[2 * i] - ox, y = p[2 * i + 1] - oy;
		double d = x * c + y * s, l = x * s - y * c;

		behind &= d < RGL_NEAR;
		left &= l < -d;
		right &= l > d;
	}
	return !(behind || left || right);
}

/* 1 when a two-sided seg without a middle texture separates sectors that
 * look the same: the software renderer skips it (r_seg_invisible). */
static int rgl_seg_invisible(const struct map *m, const struct map_seg *sg)
{
	const struct map_sector *f = &m->sectors[sg->front], *b;

	if (sg->back == MAP_NONE)
		return 0;
	b = &m->sectors[sg->back];
	return f->ceil_h == b->ceil_h && f->floor_h == b->floor_h && f->ceil_tex == b->ceil_tex &&
	       f->floor_tex == b->floor_tex && f->light == b->light &&
	       m->sides[m->lines[sg->line].side[sg->side]].mid_tex == 0;
}

/* 1 when the eye is strictly on the seg's front side (r_seg_front). */
static int rgl_seg_front(const struct map *m, const struct map_seg *sg, fx_t x, fx_t y)
{
	const struct map_vertex *a = &m->vertices[sg->v1], *b = &m->vertices[sg->v2];
	int64_t cross = ((int64_t)b->x - a->x) * ((int64_t)y - a->y) -
			((int64_t)b->y - a->y) * ((int64_t)x - a->x);

	return cross < 0;
}

/* Removes from every piece the part inside the cone from the eye (the
 * origin) through a and b. */
static void rgl_cut_cone(struct rgl_pieces *ps, double ax, double ay, double bx, double by)
{
	/* inside: on b's side of ray a and on a's side of ray b */
	int a_right = ax * by - ay * bx < 0;
	double tmp[2 * RGL_POLY_MAX];
	int count = ps->count;

	for (int i = 0; i < count; i++) {
		int n = ps->n[i], k, j = ps->count;
		double in[2 * RGL_POLY_MAX];

		/* untouched unless the cone and the piece overlap; none is cut
		 * once there is no room for another piece */
		k = rgl_clip(ps->p[i], n, tmp, 0, 0, ax, ay, a_right);
		if (k < 3 || rgl_clip(tmp, k, in, 0, 0, bx, by, !a_right) < 3 || j == RGL_PIECES)
			continue;
		/* the part outside ray a stays in place; the part inside it,
		 * outside ray b, becomes a new piece */
		ps->n[j] = rgl_clip(tmp, k, ps->p[j], 0, 0, bx, by, a_right);
		if (ps->n[j] >= 3)
			ps->count++;
		k = rgl_clip(ps->p[i], n, tmp, 0, 0, ax, ay, !a_right);
		memcpy(ps->p[i], tmp, (size_t)k * 2 * sizeof(*tmp));
		ps->n[i] = k;
	}
}

/* A masked middle's texture as a decal shows it: the wall's mapping seen
 * through each point of the decal's plane (rgl_decal). */
struct rgl_dmap {
	const struct rgl_line *l;       /* the seg */
	double tm;                      /* texel row 0's height above the eye */
	double th, tw;                  /* the texture's height and width */
};

/* Texture coordinates at P = (px, py, pz) (relative to the eye) of a
 * decal showing dm's wall: the ray through P meets the wall's line at
 * Q = P / k; the wall's (s, t) at Q, times k, and q = k, so that GL's
 * interpolation over the decal gives the wall's own perspective mapping. */
static void rgl_dmap_at(const struct rgl_dmap *dm, double px, double py, double pz, double *tc)
{
	const struct rgl_line *l = dm->l;
	double dx = l->bx - l->ax, dy = l->by - l->ay;
	double den = dx * py - dy * px, lam, qx, qy, u;

	lam = den != 0 ? (dx * l->ay - dy * l->ax) / den : 1;
	qx = lam * px;
	qy = lam * py;
	u = l->u0 + ((qx - l->ax) * dx + (qy - l->ay) * dy) / (l->len > 0 ? l->len : 1);
	tc[2] = lam != 0 ? 1 / lam : 1;
	tc[0] = (dm->tm - lam * pz) / dm->th * tc[2];
	tc[1] = u / dm->tw * tc[2];
}

/* Doom's planes drawn past a seg's edge, as a decal on the front floor (or
 * ceiling) plane at height pz above the eye: the software renderer marks
 * or draws the rows between the seg's edge at height pz and its edge at
 * height ez (further from the horizon), and in the columns the seg reaches
 * those rows cover the front plane too. On the plane that is the part of
 * the front sector between the seg and the seg scaled towards the eye by
 * pz / ez, less the columns of one-sided segs in front of it, cut by each
 * of the sector's subsector polygons. s: the decal's surface; dm: the
 * masked texture it shows, or NULL (then untextured, e.g. the sky). */
static int rgl_decal(struct rgl_ctx *g, const struct map *m, const struct map_seg *sg,
		     const struct rgl_line *l, double pz, double ez, const struct rgl_surf *s,
		     const struct rgl_dmap *dm)
{
	struct rgl_pieces *ps;
	double k = pz / ez, ex = rgl_fx(g->ex), ey = rgl_fx(g->ey);
	double sax = rgl_fx(m->vertices[sg->v1].x), say = rgl_fx(m->vertices[sg->v1].y);
	double sdx = rgl_fx(m->vertices[sg->v2].x) - sax, sdy = rgl_fx(m->vertices[sg->v2].y) - say;
	double tmp[2 * RGL_POLY_MAX];
	uint32_t sec = sg->front;

	if (sec >= g->map_nsecs)
		return 0;
	if (!g->pieces && !(g->pieces = malloc(sizeof(*g->pieces))))
		return -ENOMEM;
	ps = g->pieces;
	ps->count = 1;
	ps->n[0] = 4;
	{
		const double q[8] = { l->ax, l->ay, k * l->ax, k * l->ay,
				      k * l->bx, k * l->by, l->bx, l->by };

		memcpy(ps->p[0], q, sizeof(q));
	}
	for (uint32_t i = 0; i < m->num_segs && ps->count > 0; i++) {
		const struct map_seg *w = &m->segs[i];
		const struct map_vertex *a, *b;
		double c1, c2;

		if (w == sg || w->back != MAP_NONE || w->v1 >= m->num_vertices ||
		    w->v2 >= m->num_vertices || !rgl_seg_front(m, w, g->ex, g->ey))
			continue;
		a = &m->vertices[w->v1];
		b = &m->vertices[w->v2];
		/* in front of the seg: both ends on the eye's side of its line */
		c1 = sdx * (rgl_fx(a->y) - say) - sdy * (rgl_fx(a->x) - sax);
		c2 = sdx * (rgl_fx(b->y) - say) - sdy * (rgl_fx(b->x) - sax);
		if (c1 < 0 && c2 < 0)
			rgl_cut_cone(ps, rgl_fx(a->x) - ex, rgl_fx(a->y) - ey, rgl_fx(b->x) - ex,
				     rgl_fx(b->y) - ey);
	}
	for (int pc = 0; pc < ps->count; pc++) {
		for (uint32_t j = g->sec_first[sec]; j < g->sec_first[sec + 1]; j++) {
			uint32_t ss = g->sec_ss[j];
			const double *p = &g->pv[2 * g->poff[ss]];
			int np = g->poff[g->map_nss + ss], n = ps->n[pc];
			double a[2 * RGL_POLY_MAX];
			struct rgl_vtx *v;

			if (np < 3 || n < 3)
				continue;
			memcpy(a, ps->p[pc], (size_t)n * 2 * sizeof(*a));
			/* subsector polygons run clockwise: inside is on the right */
			for (int e = 0; e < np && n >= 3; e++) {
				int f = (e + 1) % np;

				n = rgl_clip(a, n, tmp, p[2 * e] - ex, p[2 * e + 1] - ey,
					     p[2 * f] - p[2 * e], p[2 * f + 1] - p[2 * e + 1], 1);
				memcpy(a, tmp, (size_t)n * 2 * sizeof(*a));
			}
			if (n < 3)
				continue;
			v = rgl_push(g, s, 3 * (n - 2));
			if (!v)
				return -ENOMEM;
			for (int t = 1; t + 1 < n; t++) {
				const int tri[3] = { 0, t, t + 1 };

				for (int q = 0; q < 3; q++) {
					double tc[3] = { 0, 0, 1 };
					double x = a[2 * tri[q]], y = a[2 * tri[q] + 1];

					if (dm)
						rgl_dmap_at(dm, x, y, pz, tc);
					rgl_set(v++, s, x, y, pz, tc[0], tc[1], tc[2]);
				}
			}
		}
	}
	return 0;
}

/* A textured wall part (upper, middle or lower) of seg l: drawn in the
 * world and hiding sprites. tm: texel row 0's height above the eye. 0 or
 * -ENOMEM; nothing when the part is empty. */
static int rgl_part(struct rgl_ctx *g, const struct rgl_line *l, const struct tex_pic *p, int idx,
		    int fb, int base, uint32_t id, double zb, double zt, double tm)
{
	struct rgl_surf s;

	g->st.missing += (uint32_t)fb;
	rgl_surf(&s, RGL_WALL, fb ? RGL_TEXREF(RGL_TEX_FBWALL, 0) : RGL_TEXREF(RGL_TEX_WALL, idx),
		 255, base, RGL_MODE_LIT, id);
	return rgl_wall_part(g, &s, l, zb, zt, tm, p);
}

/* Sprite clipping (r_things.c, Doom's silhouettes): a sprite behind a seg
 * is hidden below the seg's bottom clip and above its top clip, as the
 * software renderer saved them after drawing the seg: from height zb down
 * and from zt up (a one-sided wall or a closed door: the whole column).
 * Kept here and made into quads once the world's depth shows in which
 * columns the seg is reached (rgl_geo_sils). */
static int rgl_sil(struct rgl_ctx *g, const struct rgl_line *l, uint32_t seg, int bottom,
		   double zb, double bsil, int top, double zt, double tsil)
{
	struct rgl_sil *sl;

	if (!bottom && !top)
		return 0;
	if (r_grow((void **)&g->sils, &g->maxsils, sizeof(*g->sils), g->nsils + 1) < 0)
		return -ENOMEM;
	sl = &g->sils[g->nsils++];
	sl->ax = l->ax;
	sl->ay = l->ay;
	sl->bx = l->bx;
	sl->by = l->by;
	sl->zb = bottom ? zb : -RGL_SKIRT;
	sl->zt = top ? zt : RGL_SKIRT;
	sl->bsil = bsil;
	sl->tsil = tsil;
	sl->seg = seg;
	return 0;
}

/* Room for n more silhouette vertices, or NULL. */
static struct rgl_vtx *rgl_sil_push(struct rgl_ctx *g, int n)
{
	if (r_grow((void **)&g->silv, &g->maxsilv, sizeof(*g->silv), g->nsilv + n) < 0)
		return NULL;
	g->nsilv += n;
	return &g->silv[g->nsilv - n];
}

/* Quads of silhouette sl between screen x positions x0 < x1 (pixels from
 * the left edge): the part of the seg whose rays those are; the run of
 * columns x0 .. x1 - 1 they apply to. */
static int rgl_sil_quads(struct rgl_ctx *g, int sil, int x0, int x1)
{
	const struct rgl_sil *sl = &g->sils[sil];
	struct rgl_silrun *run;
	double c = rgl_fx(g->vcos), s = rgl_fx(g->vsin), half = g->w / 2.0;
	double ad = sl->ax * c + sl->ay * s, al = sl->ax * s - sl->ay * c;
	double bd = sl->bx * c + sl->by * s, bl = sl->bx * s - sl->by * c;
	double t[2], px[2], py[2], dk[2];
	struct rgl_surf sf;

	/* the ray l = X d (X = x / half - 1) meets a + t (b - a) at
	 * t = (X ad - al) / ((bl - al) - X (bd - ad)) */
	if (r_grow((void **)&g->runs, &g->maxruns, sizeof(*g->runs), g->nruns + 1) < 0)
		return -ENOMEM;
	run = &g->runs[g->nruns++];
	run->sil = sil;
	run->x0 = x0;
	run->x1 = x1 - 1;
	run->first = g->nsilv;
	run->nbottom = run->ntop = 0;
	for (int k = 0; k < 2; k++) {
		double X = (k ? x1 : x0) / half - 1, den = (bl - al) - X * (bd - ad);

		t[k] = den != 0 ? (X * ad - al) / den : 0;
		t[k] = t[k] < 0 ? 0 : t[k] > 1 ? 1 : t[k];
		px[k] = sl->ax + t[k] * (sl->bx - sl->ax);
		py[k] = sl->ay + t[k] * (sl->by - sl->ay);
		dk[k] = px[k] * c + py[k] * s;
	}
	run->dmin = dk[0] < dk[1] ? dk[0] : dk[1];
	run->dmax = dk[0] < dk[1] ? dk[1] : dk[0];
	rgl_surf(&sf, RGL_SIL, 0, 0, 0, RGL_MODE_NONE, 0);
	for (int part = 0; part < 2; part++) {
		double lo = part ? sl->zt : -RGL_SKIRT, hi = part ? RGL_SKIRT : sl->zb;
		static const int tri[6] = { 0, 1, 2, 0, 2, 3 };
		struct rgl_vtx *v;

		if (part ? sl->zt >= RGL_SKIRT : sl->zb <= -RGL_SKIRT)
			continue;
		v = rgl_sil_push(g, 6);
		if (!v)
			return -ENOMEM;
		if (part)
			run->ntop = 6;
		else
			run->nbottom = 6;
		for (int i = 0; i < 6; i++) {
			int k = tri[i], e = k == 1 || k == 2;

			rgl_set(&v[i], &sf, px[e], py[e], k < 2 ? hi : lo, 0, 0, 1);
		}
	}
	return 0;
}

int rgl_geo_sils(struct rgl_ctx *g, const float *colmax)
{
	double c = rgl_fx(g->vcos), s = rgl_fx(g->vsin), half = g->w / 2.0;

	g->nsilv = 0;
	g->nruns = 0;
	for (int i = 0; i < g->nsils; i++) {
		const struct rgl_sil *sl = &g->sils[i];
		double ad = sl->ax * c + sl->ay * s, al = sl->ax * s - sl->ay * c;
		double bd = sl->bx * c + sl->by * s, bl = sl->bx * s - sl->by * c;
		double sa, sb;
		int xa, xb, run = -1;

		/* the seg's columns, after the near plane */
		if (ad < RGL_NEAR && bd < RGL_NEAR)
			continue;
		if (ad < RGL_NEAR || bd < RGL_NEAR) {
			double f = (RGL_NEAR - ad) / (bd - ad);

			if (ad < RGL_NEAR) {
				al += f * (bl - al);
				ad = RGL_NEAR;
			} else {
				bl = al + f * (bl - al);
				bd = RGL_NEAR;
			}
		}
		sa = half + half * al / ad;
		sb = half + half * bl / bd;
		if (sa > sb) {
			double tmp = sa;

			sa = sb;
			sb = tmp;
		}
		xa = (int)floor(sa - 0.5);
		xb = (int)ceil(sb - 0.5);
		xa = xa < 0 ? 0 : xa;
		xb = xb > g->w - 1 ? g->w - 1 : xb;
		/* reached: somewhere in the column nothing nearer hides the
		 * seg's line (the software renderer keeps a drawseg only for the
		 * columns a seg reaches) */
		for (int x = xa; x <= xb + 1; x++) {
			int reached = 0;

			if (x <= xb) {
				double X = (2.0 * x + 1) / g->w - 1, den = (bl - al) - X * (bd - ad);
				double t = den != 0 ? (X * ad - al) / den : -1, d;

				if (t >= -0.01 && t <= 1.01) {
					d = ad + t * (bd - ad);
					reached = d <= colmax[x] * 1.0005 + 0.05;
				}
			}
			if (reached && run < 0)
				run = x;
			if (!reached && run >= 0) {
				if (rgl_sil_quads(g, i, run, x) < 0)
					return -ENOMEM;
				run = -1;
			}
		}
	}
	return 0;
}

int rgl_geo_sprite_sils(struct rgl_ctx *g, const struct map *m, int i, uint32_t *idx)
{
	const struct rgl_sprrec *sp = &g->sprs[i];
	int n = 0;

	for (int k = 0; k < g->nruns; k++) {
		const struct rgl_silrun *r = &g->runs[k];
		const struct rgl_sil *sl = &g->sils[r->sil];

		if (r->x1 < sp->x0 || r->x0 > sp->x1)
			continue;
		/* behind the sprite (R_DrawSprite): its nearest point farther,
		 * or its farthest point farther and the sprite on its front */
		if (r->dmin > sp->d || (r->dmax > sp->d && sl->seg < m->num_segs &&
					rgl_seg_front(m, &m->segs[sl->seg], sp->gx, sp->gy)))
			continue;
		if (r->nbottom && sp->gz < sl->bsil)
			for (int v = 0; v < r->nbottom; v++)
				idx[n++] = (uint32_t)(r->first + v);
		if (r->ntop && sp->gzt > sl->tsil)
			for (int v = 0; v < r->ntop; v++)
				idx[n++] = (uint32_t)(r->first + r->nbottom + v);
	}
	return n;
}

/* 1 when the convex polygon p[0..n-1] (world x y pairs) has, in some
 * column of its projection widened by one each side, a point no farther
 * than colmax there. */
static int rgl_poly_reached(const struct rgl_ctx *g, const double *p, int n, const float *colmax)
{
	double c = rgl_fx(g->vcos), s = rgl_fx(g->vsin), ex = rgl_fx(g->ex), ey = rgl_fx(g->ey);
	double half = g->w / 2.0, in[2 * RGL_POLY_MAX], out[2 * RGL_POLY_MAX], lo = 1e30, hi = -1e30;
	int k = 0;

	/* to view space (l, d), then the part in front of the near plane */
	for (int i = 0; i < n && i < RGL_POLY_MAX; i++) {
		double x = p[2 * i] - ex, y = p[2 * i + 1] - ey;

		in[2 * i] = x * s - y * c;
		in[2 * i + 1] = x * c + y * s;
	}
	n = n < RGL_POLY_MAX ? n : RGL_POLY_MAX;
	/* keep d >= near: the line l = 0... d = near, along +l */
	k = rgl_clip(in, n, out, 0, RGL_NEAR, 1, 0, 0);
	if (k < 3)
		return 0;
	for (int i = 0; i < k; i++) {
		double sx = half + half * out[2 * i] / out[2 * i + 1];

		lo = sx < lo ? sx : lo;
		hi = sx > hi ? sx : hi;
	}
	for (int x = (int)floor(lo - 0.5) - 1 < 0 ? 0 : (int)floor(lo - 0.5) - 1;
	     x < g->w && x <= (int)ceil(hi - 0.5) + 1; x++) {
		/* the margin columns test the polygon's nearest edge column */
		double cx = x + 0.5 < lo ? lo : x + 0.5 > hi ? hi : x + 0.5;
		double X = cx / half - 1;

		/* the nearest point of the polygon on the column's ray l = X d:
		 * where an edge crosses it */
		for (int i = 0; i < k; i++) {
			int j = (i + 1) % k;
			double fa = out[2 * i] - X * out[2 * i + 1], fb = out[2 * j] - X * out[2 * j + 1];

			if ((fa <= 0 && fb >= 0) || (fa >= 0 && fb <= 0)) {
				double t = fa != fb ? fa / (fa - fb) : 0;
				double d = out[2 * i + 1] + t * (out[2 * j + 1] - out[2 * i + 1]);

				if (d <= colmax[x] * 1.0005 + 0.05)
					return 1;
			}
		}
	}
	return 0;
}

int rgl_geo_reached(struct rgl_ctx *g, uint32_t sec, const float *colmax)
{
	if (sec >= g->map_nsecs)
		return 0;
	/* the walk tests the bounding box its parent node keeps for a
	 * subsector (r_bsp.c), not the subsector's polygon */
	for (uint32_t k = g->sec_first[sec]; k < g->sec_first[sec + 1]; k++) {
		const double *b = &g->ss_box[4 * g->sec_ss[k]];
		const double box[8] = { b[0], b[1], b[0], b[3], b[2], b[3], b[2], b[1] };

		if (rgl_poly_reached(g, box, 4, colmax))
			return 1;
	}
	return 0;
}

static int rgl_seg(struct rgl_ctx *g, const struct map *m, const struct tex_set *t, uint32_t i)
{
	const struct map_seg *sg = &m->segs[i];
	const struct map_line *ln;
	const struct map_side *sd;
	const struct map_sector *fs, *bs;
	const struct tex_pic *p, *mid;
	struct rgl_line l;
	struct rgl_surf s;
	double ff, fc, bf, bc, hfc, hb, ht, bsil, tsil, ez = rgl_fx(g->ez), yoff;
	uint32_t lside;
	int light, base, idx, fb, midx, mfb, sky_f, sky_c, bottom, top, markc, markf;

	if (sg->v1 >= m->num_vertices || sg->v2 >= m->num_vertices || sg->line >= m->num_lines ||
	    sg->side > 1 || sg->front >= m->num_sectors ||
	    (sg->back != MAP_NONE && sg->back >= m->num_sectors))
		return 0;
	ln = &m->lines[sg->line];
	if (ln->side[sg->side] >= m->num_sides || ln->v1 >= m->num_vertices ||
	    ln->v2 >= m->num_vertices || !rgl_seg_front(m, sg, g->ex, g->ey) ||
	    rgl_seg_invisible(m, sg))
		return 0;
	sd = &m->sides[ln->side[sg->side]];
	fs = &m->sectors[sg->front];
	bs = sg->back == MAP_NONE ? NULL : &m->sectors[sg->back];
	lside = sg->line * 2 + sg->side;
	yoff = rgl_fx(sd->yoff);
	l.ax = rgl_fx(m->vertices[sg->v1].x) - rgl_fx(g->ex);
	l.ay = rgl_fx(m->vertices[sg->v1].y) - rgl_fx(g->ey);
	l.bx = rgl_fx(m->vertices[sg->v2].x) - rgl_fx(g->ex);
	l.by = rgl_fx(m->vertices[sg->v2].y) - rgl_fx(g->ey);
	{
		const double ends[4] = { l.ax, l.ay, l.bx, l.by };

		if (!rgl_in_view(g, ends, 2, 0, 0))
			return 0;
	}
	l.u0 = rgl_fx(sg->offset) + rgl_fx(sd->xoff);
	l.len = rgl_fx(fx_len(m->vertices[sg->v2].x - m->vertices[sg->v1].x,
			      m->vertices[sg->v2].y - m->vertices[sg->v1].y));
	light = fs->light;
	if (m->vertices[ln->v1].y == m->vertices[ln->v2].y)
		light += RGL_CONTRAST;
	else if (m->vertices[ln->v1].x == m->vertices[ln->v2].x)
		light -= RGL_CONTRAST;
	base = rgl_light_base(light);
	ff = rgl_fx(fs->floor_h) - ez;
	fc = rgl_fx(fs->ceil_h) - ez;
	bf = bs ? rgl_fx(bs->floor_h) - ez : 0;
	bc = bs ? rgl_fx(bs->ceil_h) - ez : 0;
	sky_f = rgl_is_sky(t, fs->floor_tex);
	sky_c = rgl_is_sky(t, fs->ceil_tex);
	/* between two sky ceilings the sky comes down to the lower one */
	hfc = bs && sky_c && rgl_is_sky(t, bs->ceil_tex) ? bc : fc;
	/* Doom: a two-sided seg marks no floor (ceiling) rows when the back
	 * plane has the front's height, flat and light: the segs behind do */
	markc = markf = 1;
	if (bs && bs->ceil_h > fs->floor_h && bs->floor_h < fs->ceil_h) {
		markc = hfc != bc || bs->ceil_tex != fs->ceil_tex || bs->light != fs->light;
		markf = bf != ff || bs->floor_tex != fs->floor_tex || bs->light != fs->light;
	}

	/* The planes as the software renderer marks them from this seg: a sky
	 * ceiling is the rows above the seg's ceiling edge (a sky floor: below
	 * its floor edge): the sky "wall" from there up; a plane seen from
	 * behind fills those rows black: a black skirt. */
	if (sky_c && markc) {
		rgl_surf(&s, RGL_PLANE, 0, 0, 0, RGL_MODE_SKY, r_id(R_IDK_SKY, 0));
		if (rgl_flat_quad(g, &s, &l, hfc, RGL_SKIRT) < 0)
			return -ENOMEM;
		/* Doom's sky over a floor: below the front floor, the sky
		 * comes down past it */
		rgl_surf(&s, RGL_DECAL, 0, 0, 0, RGL_MODE_SKY, r_id(R_IDK_SKY, 0));
		if (hfc < ff && ff < 0 && !sky_f &&
		    rgl_decal(g, m, sg, &l, ff, hfc, &s, NULL) < 0)
			return -ENOMEM;
	} else if (!sky_c && fs->ceil_h <= g->ez) {
		rgl_surf(&s, RGL_PLANE, 0, g->black, 0, RGL_MODE_RAW, r_id(R_IDK_BACK, sg->front));
		if (rgl_flat_quad(g, &s, &l, fc, fc + RGL_SKIRT) < 0)
			return -ENOMEM;
	}
	if (fs->floor_h >= g->ez) {
		rgl_surf(&s, RGL_PLANE, 0, g->black, 0, RGL_MODE_RAW, r_id(R_IDK_BACK, sg->front));
		if (rgl_flat_quad(g, &s, &l, ff - RGL_SKIRT, ff) < 0)
			return -ENOMEM;
	} else if (sky_f && markf) {
		rgl_surf(&s, RGL_PLANE, 0, 0, 0, RGL_MODE_SKY, r_id(R_IDK_SKY, 0));
		if (rgl_flat_quad(g, &s, &l, ff - RGL_SKIRT, ff) < 0)
			return -ENOMEM;
	}

	if (!bs) {
		p = rgl_wall_pic(t, sd->mid_tex, &idx, &fb);
		if (rgl_sil(g, &l, i, 1, RGL_SKIRT, RGL_SKIRT, 0, 0, -RGL_SKIRT) < 0)
			return -ENOMEM;
		if (!p && !fb) {
			rgl_surf(&s, RGL_WALL, 0, g->black, 0, RGL_MODE_RAW, r_id(R_IDK_MIDDLE, lside));
			return rgl_flat_quad(g, &s, &l, ff, fc);
		}
		return rgl_part(g, &l, p, idx, fb, base, r_id(R_IDK_MIDDLE, lside), ff, fc,
				((ln->flags & ML_DONTPEGBOTTOM) ? ff + (p ? p->h : RGL_FB_SIZE) : fc) +
				yoff);
	}

	/* upper part down to the back ceiling, lower part up to the back floor,
	 * inside the front's floor and (sky-lowered) ceiling */
	ht = hfc;
	hb = ff;
	if (bc < hfc) {
		double zb = bc > ff ? bc : ff;

		p = rgl_wall_pic(t, sd->top_tex, &idx, &fb);
		if (p || fb) {
			if (rgl_part(g, &l, p, idx, fb, base, r_id(R_IDK_UPPER, lside), zb, hfc,
				     ((ln->flags & ML_DONTPEGTOP) ?
				      hfc : bc + (p ? p->h : RGL_FB_SIZE)) + yoff) < 0)
				return -ENOMEM;
			ht = zb;
		} else if (!rgl_is_sky(t, bs->ceil_tex) &&
			   rgl_bleed(g, t, bs, sg->back, 1, &l, zb, hfc) < 0) {
			return -ENOMEM;
		}
	}
	if (bf > ff) {
		double zt = bf < hfc ? bf : hfc;

		p = rgl_wall_pic(t, sd->bot_tex, &idx, &fb);
		if (p || fb) {
			if (rgl_part(g, &l, p, idx, fb, base, r_id(R_IDK_LOWER, lside), ff, zt,
				     ((ln->flags & ML_DONTPEGBOTTOM) ? hfc : bf) + yoff) < 0)
				return -ENOMEM;
			hb = zt;
		} else if (rgl_bleed(g, t, bs, sg->back, 0, &l, ff, zt) < 0) {
			return -ENOMEM;
		}
	}

	/* silhouettes (r_seg.c r_dseg_sil): a closed door hides the whole
	 * column; the bottom clips where the front floor is higher (sprites
	 * standing at or above it exempt) or the back floor above the eye, the
	 * top where the front ceiling is lower (sprites at or below it exempt)
	 * or the back ceiling below the eye; a masked middle clips both */
	mid = rgl_wall_pic(t, sd->mid_tex, &midx, &mfb);
	bsil = RGL_SKIRT;
	tsil = -RGL_SKIRT;
	if (bs->ceil_h <= fs->floor_h || bs->floor_h >= fs->ceil_h) {
		bottom = 1;
		hb = RGL_SKIRT;
		top = 0;
	} else {
		bottom = fs->floor_h > bs->floor_h || bs->floor_h > g->ez;
		if (fs->floor_h > bs->floor_h)
			bsil = ff;
		top = fs->ceil_h < bs->ceil_h || bs->ceil_h < g->ez;
		if (fs->ceil_h < bs->ceil_h)
			tsil = fc;
		if (mid || mfb) {
			if (!bottom)
				bsil = RGL_SKIRT;
			if (!top)
				tsil = -RGL_SKIRT;
			bottom = top = 1;
		}
	}
	if (rgl_sil(g, &l, i, bottom, hb, bsil, top, ht, tsil) < 0)
		return -ENOMEM;

	if (mid || mfb) {
		/* Doom: hung from the lower ceiling, or standing on the higher
		 * floor when lower-unpegged; drawn once, inside the opening */
		double h = mid ? mid->h : RGL_FB_SIZE;
		double lo = ff > bf ? ff : bf, hi = fc < bc ? fc : bc;
		double tm = ((ln->flags & ML_DONTPEGBOTTOM) ? lo + h : hi) + yoff;
		struct rgl_dmap dm = { &l, tm, h, mid ? mid->w : RGL_FB_SIZE };
		uint32_t ref = mfb ? RGL_TEXREF(RGL_TEX_FBWALL, 0) : RGL_TEXREF(RGL_TEX_WALL, midx);

		g->st.missing += (uint32_t)mfb;
		rgl_surf(&s, RGL_MASKED, ref, 255, base, RGL_MODE_LIT, r_id(R_IDK_MASKED, lside));
		if (rgl_wall_part(g, &s, &l, tm - h > lo ? tm - h : lo, tm < hi ? tm : hi, tm, mid) < 0)
			return -ENOMEM;
		/* where the seg marks no floor (ceiling) rows, the software
		 * renderer's clip there is what was drawn before: the texture
		 * hanging below the floor (above the ceiling) shows over the
		 * front plane, as a decal on it */
		rgl_surf(&s, RGL_MDECAL, ref, 255, base, RGL_MODE_LIT, r_id(R_IDK_MASKED, lside));
		if (!markf && tm - h < lo && lo < 0 && rgl_decal(g, m, sg, &l, lo, tm - h, &s, &dm) < 0)
			return -ENOMEM;
		if (!markc && tm > hi && hi > 0 && rgl_decal(g, m, sg, &l, hi, tm, &s, &dm) < 0)
			return -ENOMEM;
	}
	return 0;
}

/* Floor and ceiling of subsector i, when seen from their visible side
 * (r_bsp.c); sky planes are drawn by their segs (rgl_seg). */
static int rgl_planes(struct rgl_ctx *g, const struct map *m, const struct tex_set *t, uint32_t i)
{
	const struct map_subsector *ss = &m->subsectors[i];
	const struct map_sector *sec;
	const double *p = &g->pv[2 * g->poff[i]];
	int n = g->poff[g->map_nss + i];
	double ex = rgl_fx(g->ex), ey = rgl_fx(g->ey);

	if (n < 3 || ss->sector >= m->num_sectors || !rgl_in_view(g, p, n, ex, ey))
		return 0;
	sec = &m->sectors[ss->sector];
	for (int c = 0; c < 2; c++) {
		fx_t hgt = c ? sec->ceil_h : sec->floor_h;
		uint16_t pic = c ? sec->ceil_tex : sec->floor_tex;
		double z = rgl_fx(hgt) - rgl_fx(g->ez);
		struct rgl_surf s;
		struct rgl_vtx *v;

		if (rgl_is_sky(t, pic) || (c ? hgt <= g->ez : hgt >= g->ez))
			continue;
		rgl_surf(&s, RGL_PLANE, rgl_flat_ref(g, t, pic), 255, rgl_light_base(sec->light),
			 RGL_MODE_LIT, r_id(c ? R_IDK_CEIL : R_IDK_FLOOR, ss->sector));
		v = rgl_push(g, &s, 3 * (n - 2));
		if (!v)
			return -ENOMEM;
		for (int k = 1; k + 1 < n; k++) {
			const int tri[3] = { 0, k, k + 1 };

			for (int j = 0; j < 3; j++) {
				double x = p[2 * tri[j]], y = p[2 * tri[j] + 1];

				rgl_set(v++, &s, x - ex, y - ey, z, x / 64.0, -y / 64.0, 1);
			}
		}
		g->st.planes++;
	}
	return 0;
}

static fx_t rgl_clamp(fx_t v)
{
	return v > MAP_COORD_MAX ? MAP_COORD_MAX : v < -MAP_COORD_MAX ? -MAP_COORD_MAX : v;
}

/* A sprite's or mesh's light level, as r_things.c gives it: its sector's
 * light faded by its scale (w/2) / d (scale: 16.16 of that, shifted as
 * r_scale_level takes it), in r_scale_level's integer steps; 0 when full
 * bright. */
static int rgl_spr_level(const struct rgl_ctx *g, const struct map *m, uint32_t sec,
			 int64_t scale, int fullbright)
{
	int64_t fade;
	int level;

	if (fullbright)
		return 0;
	fade = ((scale >> 16) * (((int64_t)RGL_FADE_DIST << 17) / g->w)) >> 32;
	level = rgl_light_base(m->sectors[sec].light) -
		(fade > RGL_FADE_MAX ? RGL_FADE_MAX : (int)fade);
	return level < 0 ? 0 : level;
}

/* Sprite i as a billboard (r_things.c's projection and rotation). */
static int rgl_sprite(struct rgl_ctx *g, const struct map *m, const struct tex_set *t,
		      const struct r_sprite *sp, int i)
{
	fx_t gx = rgl_clamp(sp->x), gy = rgl_clamp(sp->y);
	int64_t dx = (int64_t)gx - g->ex, dy = (int64_t)gy - g->ey;
	int64_t d = (dx * g->vcos + dy * g->vsin) >> FX_SHIFT;
	int64_t l = (dx * g->vsin - dy * g->vcos) >> FX_SHIFT;
	int64_t scale;
	const struct tex_pic *pic;
	int level, pi, flip;
	double x0, x1, zt, zb, t0, t1;
	struct rgl_surf s;
	struct rgl_vtx *v;
	uint32_t sec;

	if (d < RGL_SPR_NEAR || l > 4 * d || l < -4 * d)
		return 0;
	pi = tex_sprite_pic(t, sp->sprite, sp->frame, tab_atan2(gy - g->ey, gx - g->ex) - sp->angle,
			    &flip);
	if (pi < 0) {
		g->st.missing++;
		return 0;
	}
	pic = &t->sprpics[pi];
	sec = map_point_sector(m, gx, gy);
	g->spr_sec[i] = sec;
	scale = ((int64_t)g->w << 47) / d;
	level = rgl_spr_level(g, m, sec, scale, sp->flags & R_SPR_FULLBRIGHT);
	rgl_surf(&s, RGL_SPRITE, RGL_TEXREF(RGL_TEX_SPRITE, pi), 255, level, RGL_MODE_FIXED,
		 r_id(R_IDK_SPRITE, (uint32_t)i));
	/* drawn in the list's order: at equal depth the later one shows, as
	 * the software renderer breaks ties */
	s.key = ((uint64_t)RGL_SPRITE << 32) | (uint32_t)i;
	/* in view space (l right, H up, -d: the sprite pass's matrix), so
	 * that every corner has exactly the depth d and sprites at the same
	 * depth tie exactly (then the later one shows) */
	x0 = ((double)l / 65536.0) - pic->left;
	x1 = x0 + pic->w;
	zt = rgl_fx(sp->z) + pic->top - rgl_fx(g->ez);
	zb = zt - pic->h;
	/* its screen box (GL window coordinates, y up); none: not drawn */
	{
		double dd = (double)d / 65536.0, f = g->w / 2.0;
		double cy = g->h / 2.0 - g->shear;   /* the horizon, from the bottom */
		int bx0 = (int)floor(f + f * x0 / dd), bx1 = (int)ceil(f + f * x1 / dd);
		int by0 = (int)floor(cy + f * zb / dd), by1 = (int)ceil(cy + f * zt / dd);

		if (bx1 <= 0 || bx0 >= g->w || by1 <= 0 || by0 >= g->h)
			return 0;
		g->sprs[i].x0 = bx0;
		g->sprs[i].x1 = bx1 - 1;
		g->sprs[i].d = dd;
		g->sprs[i].gz = rgl_fx(sp->z) - rgl_fx(g->ez);
		g->sprs[i].gzt = zt;
		g->sprs[i].gx = gx;
		g->sprs[i].gy = gy;
		g->sprs[i].scale = scale;
		g->sbox[0] = bx0 < g->sbox[0] ? bx0 : g->sbox[0];
		g->sbox[1] = by0 < g->sbox[1] ? by0 : g->sbox[1];
		g->sbox[2] = bx1 > g->sbox[2] ? bx1 : g->sbox[2];
		g->sbox[3] = by1 > g->sbox[3] ? by1 : g->sbox[3];
	}
	t0 = flip ? 1 : 0;
	t1 = 1 - t0;
	v = rgl_push(g, &s, 6);
	if (!v)
		return -ENOMEM;
	{
		const double cx[4] = { x0, x1, x1, x0 };
		const double cy[4] = { zt, zt, zb, zb };
		const double cz[4] = { -((double)d / 65536.0), -((double)d / 65536.0), -((double)d / 65536.0),
				       -((double)d / 65536.0) };
		const double cs[4] = { 0, 0, 1, 1 };
		const double ct[4] = { t0, t1, t1, t0 };
		static const int tri[6] = { 0, 1, 2, 0, 2, 3 };

		for (int k = 0; k < 6; k++)
			rgl_set(&v[k], &s, cx[tri[k]], cy[tri[k]], cz[tri[k]], cs[tri[k]],
				ct[tri[k]], 1);
	}
	g->st.sprites++;
	return 0;
}

/* The software renderer's mesh light (r_mesh.c): towards (-2, 3, 6) / 7,
 * up to RGL_MESH_SHADE colormap levels darker as a face turns away. */
#define RGL_MESH_LX (-2.0)
#define RGL_MESH_LY 3.0
#define RGL_MESH_LZ 6.0
#define RGL_MESH_SHADE 12

/* Sprite i, a built-in mesh, as its own triangles in the world (eye
 * relative, the world pass's matrix), facing outward (the sprite pass
 * culls those turned away, as r_mesh.c skips them): rotated by the
 * sprite's angle about its vertical axis with the same tables and the same
 * integer steps to each vertex's map position as the software renderer
 * (r_mesh.c), so that both draw one shape. Drawn under the same rule
 * (whole or not at all: the cylinder of 3/2 its radius in front, beside
 * and above and below the eye within four times its nearest depth) and
 * clipped as a sprite (its record: the cylinder's screen box, the depth
 * of its centre, its lowest and highest points). The id is the sprite's. */
static int rgl_mesh(struct rgl_ctx *g, const struct map *m, const struct r_sprite *sp, int i)
{
	fx_t gx = rgl_clamp(sp->x), gy = rgl_clamp(sp->y);
	int64_t dx = (int64_t)sp->x - g->ex, dy = (int64_t)sp->y - g->ey;
	int64_t d = (dx * g->vcos + dy * g->vsin) >> FX_SHIFT;
	int64_t l = (dx * g->vsin - dy * g->vcos) >> FX_SHIFT;
	int64_t rr, dmin, zlo, zhi, scale;
	fx_t c = tab_cos(sp->angle), sn = tab_sin(sp->angle);
	double f = g->w / 2.0, cy = g->h / 2.0 - g->shear, xmin = 1e30, xmax = -1e30;
	double ymin = 1e30, ymax = -1e30;
	struct mesh me;
	struct rgl_surf s;
	struct rgl_vtx *v;
	uint32_t sec;
	int base;

	if (sp->mp) {
		me = *sp->mp;
	} else if (mesh_builtin_get(sp->mesh, &me) < 0) {
		g->st.missing++;
		return 0;
	}
	rr = (int64_t)me.radius * 3 / 2 + FX_ONE;
	dmin = d - rr;
	zlo = (int64_t)sp->z + me.zmin - g->ez;
	zhi = (int64_t)sp->z + me.zmax - g->ez;
	if (dmin < RGL_SPR_NEAR || (l < 0 ? -l : l) + rr > 4 * dmin ||
	    (zlo < 0 ? -zlo : zlo) > 4 * dmin || (zhi < 0 ? -zhi : zhi) > 4 * dmin)
		return 0;
	/* the screen box of the cylinder's corners (window coordinates, y up) */
	for (int k = 0; k < 4; k++) {
		double dd = (double)(k & 1 ? d + rr : dmin) / 65536.0;
		double sx = f + f * ((double)(l + (k & 2 ? rr : -rr)) / 65536.0) / dd;
		double sy = cy + f * ((double)(k & 2 ? zhi : zlo) / 65536.0) / dd;

		xmin = sx < xmin ? sx : xmin;
		xmax = sx > xmax ? sx : xmax;
		ymin = sy < ymin ? sy : ymin;
		ymax = sy > ymax ? sy : ymax;
	}
	if (xmax < 0 || xmin >= g->w || ymax < 0 || ymin >= g->h)
		return 0;
	sec = map_point_sector(m, gx, gy);
	g->spr_sec[i] = sec;
	scale = ((int64_t)g->w << 47) / d;      /* d > 0: dmin >= RGL_SPR_NEAR above */
	base = rgl_spr_level(g, m, sec, scale, sp->flags & R_SPR_FULLBRIGHT);
	g->sprs[i].x0 = (int)floor(xmin);
	g->sprs[i].x1 = (int)floor(xmax);
	g->sprs[i].d = (double)d / 65536.0;
	g->sprs[i].gz = (double)zlo / 65536.0;
	g->sprs[i].gzt = (double)zhi / 65536.0;
	g->sprs[i].gx = gx;
	g->sprs[i].gy = gy;
	g->sprs[i].mesh = 1;
	g->sprs[i].scale = scale;
	g->sprs[i].y0 = (int)floor(ymin);
	g->sprs[i].y1 = (int)ceil(ymax) + 1;
	g->sbox[0] = (int)floor(xmin) < g->sbox[0] ? (int)floor(xmin) : g->sbox[0];
	g->sbox[1] = (int)floor(ymin) < g->sbox[1] ? (int)floor(ymin) : g->sbox[1];
	g->sbox[2] = (int)ceil(xmax) + 1 > g->sbox[2] ? (int)ceil(xmax) + 1 : g->sbox[2];
	g->sbox[3] = (int)ceil(ymax) + 1 > g->sbox[3] ? (int)ceil(ymax) + 1 : g->sbox[3];
	for (uint32_t t = 0; t < me.nt; t++) {
		double p[3][3], ux, uy, uz, wx, wy, wz, nx, ny, nz, len, lam;
		int lvl;

		for (int k = 0; k < 3; k++) {
			const struct mesh_vert *mv = &me.v[me.t[t].v[k]];
			/* r_mesh.c's map position, in its integer steps */
			int64_t x = gx + (((int64_t)mv->x * c - (int64_t)mv->y * sn) >> FX_SHIFT);
			int64_t y = gy + (((int64_t)mv->x * sn + (int64_t)mv->y * c) >> FX_SHIFT);
			int64_t z = (int64_t)sp->z + mv->z;

			p[k][0] = (double)(x - g->ex) / 65536.0;
			p[k][1] = (double)(y - g->ey) / 65536.0;
			p[k][2] = (double)(z - g->ez) / 65536.0;
		}
		/* the outward normal (the file's order) against the light */
		ux = p[1][0] - p[0][0], uy = p[1][1] - p[0][1], uz = p[1][2] - p[0][2];
		wx = p[2][0] - p[0][0], wy = p[2][1] - p[0][1], wz = p[2][2] - p[0][2];
		nx = uy * wz - uz * wy;
		ny = uz * wx - ux * wz;
		nz = ux * wy - uy * wx;
		len = sqrt(nx * nx + ny * ny + nz * nz);
		lam = len > 0 ? (nx * RGL_MESH_LX + ny * RGL_MESH_LY + nz * RGL_MESH_LZ) / (7.0 * len) : 0;
		lam = lam < 0 ? 0 : lam > 1 ? 1 : lam;
		lvl = base + (int)((1.0 - lam) * RGL_MESH_SHADE);
		lvl = lvl > PAL_LIGHTS - 1 ? PAL_LIGHTS - 1 : lvl;
		rgl_surf(&s, RGL_SPRITE, RGL_TEXREF(RGL_TEX_NONE, 0), sp->colour, lvl, RGL_MODE_FIXED,
			 r_id(R_IDK_SPRITE, (uint32_t)i));
		s.key = ((uint64_t)RGL_SPRITE << 32) | (uint32_t)i;
		v = rgl_push(g, &s, 3);
		if (!v)
			return -ENOMEM;
		for (int k = 0; k < 3; k++)
			rgl_set(&v[k], &s, p[k][0], p[k][1], p[k][2], 0, 0, 1);
	}
	g->st.sprites++;
	g->st.meshes++;
	return 0;
}

int rgl_geo_build(struct rgl_ctx *g, const struct map *m, const struct tex_set *t,
		  const struct r_sprite *spr, int nspr)
{
	g->nvtx = 0;
	g->nitems = 0;
	g->nsils = 0;
	g->sbox[0] = g->sbox[1] = INT32_MAX;
	g->sbox[2] = g->sbox[3] = INT32_MIN;
	if (nspr > g->max_spr) {
		uint32_t *ns = realloc(g->spr_sec, (size_t)nspr * sizeof(*ns));
		struct rgl_sprrec *nr;
		struct rgl_sord *no;

		if (!ns)
			return -ENOMEM;
		g->spr_sec = ns;
		nr = realloc(g->sprs, (size_t)nspr * sizeof(*nr));
		if (!nr)
			return -ENOMEM;
		g->sprs = nr;
		no = realloc(g->sord, (size_t)nspr * sizeof(*no));
		if (!no)
			return -ENOMEM;
		g->sord = no;
		g->maxsord = nspr;
		g->max_spr = nspr;
	}
	for (int i = 0; i < nspr; i++) {
		g->sprs[i].x0 = 0;
		g->sprs[i].x1 = -1;
		g->sprs[i].mesh = 0;
	}
	if ((int)m->num_sectors > g->max_seen) {
		uint8_t *ns = realloc(g->sec_seen, m->num_sectors);

		if (!ns)
			return -ENOMEM;
		g->sec_seen = ns;
		g->max_seen = (int)m->num_sectors;
	}
	for (uint32_t i = 0; i < m->num_segs; i++)
		if (rgl_seg(g, m, t, i) < 0)
			return -ENOMEM;
	for (uint32_t i = 0; i < m->num_subsectors && i < g->map_nss; i++)
		if (rgl_planes(g, m, t, i) < 0)
			return -ENOMEM;
	for (int i = 0; i < nspr; i++)
		if ((spr[i].mesh ? rgl_mesh(g, m, &spr[i], i) : rgl_sprite(g, m, t, &spr[i], i)) < 0)
			return -ENOMEM;
	return 0;
}
