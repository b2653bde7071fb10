/*
 * r_mesh: 3D meshes (engine/map/mesh.h) as things, drawn in the masked
 * pass in the place of a sprite: projected with the sprites (sorted by the
 * scale at their centre) and clipped against the drawsegs exactly as a
 * sprite is (r_things.c makes the clip arrays); only their pixels are
 * made here.
 *
 * Projection: a mesh is rotated about its vertical axis by its thing's
 * angle and stands at the thing's position and z. It is drawn only whole:
 * when all of it (the cylinder of radius 3/2 r round its axis, which holds
 * every rotation of a mesh of radius r) lies at depth R_SPR_NEAR or more,
 * within four times its nearest depth to either side, and its lowest and
 * highest points within four times that depth above and below the eye;
 * otherwise it is skipped as a sprite too near or too far to the side is.
 * Those bounds keep every projected vertex within 2^14 pixels of the
 * screen, which the integer bounds below rely on. The screen box is the
 * box of the cylinder's corners.
 *
 * Rasterising (r_mesh_draw): per strip, into a scratch box of the mesh's
 * columns in the strip and its rows on screen: a colour and an inverse
 * depth per pixel (the small per-mesh depth buffer; 0: empty). Triangles
 * whose projected corners turn clockwise on screen face away and are
 * skipped (OBJ faces turn counter-clockwise seen from outside). A pixel is
 * covered when its centre lies inside the triangle (edges on the top or
 * left side included: each pixel of a closed surface once). Vertices are
 * 28.4 pixels; inverse depth 2^38 / depth (depth 16.16), interpolated
 * affinely on screen (1 / depth is affine in screen space) by the
 * triangle's edge functions: |edge| <= 2^37, inverse depth <= 2^20, the
 * weighted sum < 2^59. A nearer pixel (larger inverse depth) replaces a
 * farther one. Then the box's columns are drawn between the clip arrays
 * as a sprite's columns are (r_draw_masked), covered pixels only.
 *
 * Light: the colormap level of the thing's sector light with the distance
 * fade at its centre (as a sprite), plus R_MESH_SHADE levels times one
 * minus the Lambert term of the triangle's normal with a fixed light
 * direction, from above (MESH_LIGHT_*): faces turned from the light are
 * darker, and the shading turns with the mesh.
 */
#include <stdint.h>

#include "engine/core/tab.h"
#include "engine/map/mesh_builtin.h"
#include "engine/render/r_local.h"

/* The light's direction (towards the light), a unit vector times 7:
 * (-2, 3, 6) has length 7 exactly. */
#define R_MESH_LX (-2)
#define R_MESH_LY 3
#define R_MESH_LZ 6
#define R_MESH_LLEN 7

/* Colormap levels between a face lit head-on and one turned away. */
#define R_MESH_SHADE 12

/* A projected vertex: 28.4 pixels and inverse depth. */
struct r_mv {
	int64_t x, y, iz;
	int64_t wx, wy, wz;            /* world position, 16.16 */
};

int r_mesh_project(struct r_ctx *r, const struct r_sprite *sp, struct r_vis *vs)
{
	struct mesh m;
	struct r_vpt p;
	int64_t half = (int64_t)r->w << (FX_SHIFT - 1), rr, dmin, dmax, zlo, zhi;
	int64_t sx[4], sy[4], xmin, xmax, ymin, ymax, cy16 = (int64_t)r->cy2 * FX_HALF;

	if (sp->mp)
		m = *sp->mp;
	else if (mesh_builtin_get(sp->mesh, &m) < 0)
		return -1;
	r_to_view(r, sp->x, sp->y, &p);
	rr = (int64_t)m.radius * 3 / 2 + FX_ONE;
	dmin = p.d - rr;
	dmax = p.d + rr;
	zlo = (int64_t)sp->z + m.zmin - r->ez;
	zhi = (int64_t)sp->z + m.zmax - r->ez;
	if (dmin < R_SPR_NEAR || (p.l < 0 ? -p.l : p.l) + rr > 4 * dmin ||
	    (zlo < 0 ? -zlo : zlo) > 4 * dmin || (zhi < 0 ? -zhi : zhi) > 4 * dmin)
		return 1;
	for (int k = 0; k < 4; k++) {
		int64_t d = k & 1 ? dmax : dmin;

		sx[k] = half + (p.l + (k & 2 ? rr : -rr)) * half / d;
		sy[k] = cy16 - (k & 2 ? zhi : zlo) * half / d;
	}
	xmin = xmax = sx[0];
	ymin = ymax = sy[0];
	for (int k = 1; k < 4; k++) {
		xmin = sx[k] < xmin ? sx[k] : xmin;
		xmax = sx[k] > xmax ? sx[k] : xmax;
		ymin = sy[k] < ymin ? sy[k] : ymin;
		ymax = sy[k] > ymax ? sy[k] : ymax;
	}
	vs->x1 = (int)(xmin >> FX_SHIFT);
	vs->x2 = (int)(xmax >> FX_SHIFT);
	vs->y1 = (int)(ymin >> FX_SHIFT);
	vs->y2 = (int)(ymax >> FX_SHIFT);
	vs->x1 = vs->x1 < 0 ? 0 : vs->x1;
	vs->x2 = vs->x2 > r->w - 1 ? r->w - 1 : vs->x2;
	vs->y1 = vs->y1 < 0 ? 0 : vs->y1;
	vs->y2 = vs->y2 > r->h - 1 ? r->h - 1 : vs->y2;
	if (vs->x1 > vs->x2 || vs->y1 > vs->y2)
		return 1;
	vs->scale = ((int64_t)r->w << 47) / p.d;
	vs->gz = (int64_t)sp->z + m.zmin;
	vs->gzt = (int64_t)sp->z + m.zmax;
	vs->mesh = sp->mesh;
	vs->mp = sp->mp;
	vs->colour = sp->colour;
	vs->angle = sp->angle;
	vs->mz = sp->z;
	return 0;
}

/* Vertex i of m rotated by (c, s), at (gx, gy, gz), projected. */
static void r_mesh_vert(const struct r_ctx *r, const struct mesh_vert *v, fx_t c, fx_t s,
			const struct r_vis *vs, struct r_mv *o)
{
	int64_t half = (int64_t)r->w << (FX_SHIFT - 1), cy16 = (int64_t)r->cy2 * FX_HALF;
	int64_t dx, dy, d, l;

	o->wx = vs->gx + (((int64_t)v->x * c - (int64_t)v->y * s) >> FX_SHIFT);
	o->wy = vs->gy + (((int64_t)v->x * s + (int64_t)v->y * c) >> FX_SHIFT);
	o->wz = vs->mz + v->z;
	dx = o->wx - r->ex;
	dy = o->wy - r->ey;
	d = (dx * r->vcos + dy * r->vsin) >> FX_SHIFT;
	l = (dx * r->vsin - dy * r->vcos) >> FX_SHIFT;
	/* r_mesh_project checked d >= R_SPR_NEAR for the whole mesh */
	if (d < R_SPR_NEAR)
		d = R_SPR_NEAR;
	o->x = (half + l * half / d) >> 12;
	o->y = (cy16 - (o->wz - r->ez) * half / d) >> 12;
	o->iz = ((int64_t)1 << 38) / d;
}

/* Edge function of (ax, ay)-(bx, by) at (px, py): positive inside a
 * triangle turning clockwise on screen (y down). */
static int64_t r_edge(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
	return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/* Top or left edge of a triangle turning clockwise on screen (y down):
 * included on ties. */
static int r_topleft(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
	return (ay == by && bx > ax) || by < ay;
}

/* The colormap level of a triangle with corners a, b, c. */
static int r_mesh_level(const struct r_mv *a, const struct r_mv *b, const struct r_mv *c,
			int base)
{
	int64_t ux = (b->wx - a->wx) >> 8, uy = (b->wy - a->wy) >> 8, uz = (b->wz - a->wz) >> 8;
	int64_t vx = (c->wx - a->wx) >> 8, vy = (c->wy - a->wy) >> 8, vz = (c->wz - a->wz) >> 8;
	/* |u|, |v| components < 2^19 (mesh within 768 units): products < 2^38 */
	int64_t nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
	int64_t big = nx < 0 ? -nx : nx, len, dot, lam;
	int lvl;

	big = (ny < 0 ? -ny : ny) > big ? (ny < 0 ? -ny : ny) : big;
	big = (nz < 0 ? -nz : nz) > big ? (nz < 0 ? -nz : nz) : big;
	while (big >= ((int64_t)1 << 20)) {
		nx /= 2;
		ny /= 2;
		nz /= 2;
		big /= 2;
	}
	len = fx_isqrt64((uint64_t)(nx * nx + ny * ny + nz * nz));
	if (len == 0)
		return base + R_MESH_SHADE;
	dot = nx * R_MESH_LX + ny * R_MESH_LY + nz * R_MESH_LZ;
	lam = dot <= 0 ? 0 : dot * FX_ONE / (len * R_MESH_LLEN);
	lam = lam > FX_ONE ? FX_ONE : lam;
	lvl = base + (int)(((FX_ONE - lam) * R_MESH_SHADE) >> FX_SHIFT);
	return lvl > PAL_LIGHTS - 1 ? PAL_LIGHTS - 1 : lvl;
}

void r_mesh_draw(struct r_ctx *r, struct r_strip *s, const struct r_vis *vs, int vx1, int vx2,
		 const int16_t *ct, const int16_t *cb)
{
	struct mesh m;
	int bw = vx2 - vx1 + 1, bh = vs->y2 - vs->y1 + 1;
	fx_t c = tab_cos(vs->angle), sn = tab_sin(vs->angle);
	uint32_t id = r_id(R_IDK_SPRITE, (uint32_t)vs->order);
	uint8_t *mcol, *mop;

	if (vs->mp)
		m = *vs->mp;
	else if (mesh_builtin_get(vs->mesh, &m) < 0)
		return;
	if (bw <= 0 || bh <= 0)
		return;
	/* the box: colours, then covered flags (mbuf), inverse depths (mdep);
	 * kept by the strip for the next meshes and frames */
	if (r_grow((void **)&s->mbuf, &s->mbufcap, 1, 2 * bw * bh) < 0 ||
	    r_grow((void **)&s->mdep, &s->mdepcap, sizeof(*s->mdep), bw * bh) < 0) {
		s->degraded++;
		return;
	}
	mcol = s->mbuf;
	mop = s->mbuf + bw * bh;
	for (int i = 0; i < bw * bh; i++)
		s->mdep[i] = 0;
	for (uint32_t t = 0; t < m.nt; t++) {
		struct r_mv v[3];
		int64_t area, bx0, bx1, by0, by1;
		int x0, x1, y0, y1, lvl;
		int tl[3];
		uint8_t colour;

		for (int k = 0; k < 3; k++)
			r_mesh_vert(r, &m.v[m.t[t].v[k]], c, sn, vs, &v[k]);
		/* counter-clockwise as the viewer sees it is a negative area with
		 * y down; swapped, the triangle's edge functions are positive
		 * inside */
		area = r_edge(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
		if (area >= 0)
			continue;       /* facing away, or no area */
		area = -area;
		{
			struct r_mv tmp = v[1];

			v[1] = v[2];
			v[2] = tmp;
		}
		bx0 = v[0].x < v[1].x ? v[0].x : v[1].x;
		bx0 = v[2].x < bx0 ? v[2].x : bx0;
		bx1 = v[0].x > v[1].x ? v[0].x : v[1].x;
		bx1 = v[2].x > bx1 ? v[2].x : bx1;
		by0 = v[0].y < v[1].y ? v[0].y : v[1].y;
		by0 = v[2].y < by0 ? v[2].y : by0;
		by1 = v[0].y > v[1].y ? v[0].y : v[1].y;
		by1 = v[2].y > by1 ? v[2].y : by1;
		/* pixels whose centre (16 x + 8) lies within the bounds */
		x0 = (int)((bx0 - 8 + 15) >> 4);
		x1 = (int)((bx1 - 8) >> 4);
		y0 = (int)((by0 - 8 + 15) >> 4);
		y1 = (int)((by1 - 8) >> 4);
		x0 = x0 < vx1 ? vx1 : x0;
		x1 = x1 > vx2 ? vx2 : x1;
		y0 = y0 < vs->y1 ? vs->y1 : y0;
		y1 = y1 > vs->y2 ? vs->y2 : y1;
		if (x0 > x1 || y0 > y1)
			continue;
		for (int k = 0; k < 3; k++) {
			const struct r_mv *a = &v[(k + 1) % 3], *b = &v[(k + 2) % 3];

			tl[k] = r_topleft(a->x, a->y, b->x, b->y);
		}
		/* the file's order (before the swap): the outward normal */
		lvl = r_mesh_level(&v[0], &v[2], &v[1], vs->lvl);
		colour = r->cmap[lvl][vs->colour];
		for (int y = y0; y <= y1; y++) {
			int64_t py = 16 * (int64_t)y + 8;

			for (int x = x0; x <= x1; x++) {
				int64_t px = 16 * (int64_t)x + 8, e[3], iz;
				int in = 1;
				size_t o;

				for (int k = 0; k < 3 && in; k++) {
					const struct r_mv *a = &v[(k + 1) % 3], *b = &v[(k + 2) % 3];

					e[k] = r_edge(a->x, a->y, b->x, b->y, px, py);
					in = e[k] > 0 || (e[k] == 0 && tl[k]);
				}
				if (!in)
					continue;
				/* weights e[k] >= 0 summing to area: between the corners' */
				iz = (e[0] * v[0].iz + e[1] * v[1].iz + e[2] * v[2].iz) / area;
				iz = iz < 1 ? 1 : iz;
				o = (size_t)(x - vx1) * (size_t)bh + (size_t)(y - vs->y1);
				if ((uint32_t)iz > s->mdep[o]) {
					s->mdep[o] = (uint32_t)iz;
					mcol[o] = colour;
				}
			}
		}
	}
	for (int i = 0; i < bw * bh; i++)
		mop[i] = s->mdep[i] != 0;
	for (int x = vx1; x <= vx2; x++) {
		int ya = ct[x] + 1 > vs->y1 ? ct[x] + 1 : vs->y1;
		int yb = cb[x] - 1 < vs->y2 ? cb[x] - 1 : vs->y2;
		size_t off = (size_t)(x - vx1) * (size_t)bh;

		if (ya <= yb)
			r_draw_masked(r, s, x, ya, yb, mcol + off, mop + off, r->ident,
				      (uint32_t)(ya - vs->y1) << 16, (uint32_t)1 << 16, id);
	}
}
