/*
 * r_main: render context, per-frame set-up, and the geometry every stage
 * shares: view transform, clipping to the visible region, projection.
 *
 * Projection: 90-degree horizontal field of view, focal length w/2 pixels,
 * square pixels. Screen x of a view-space point is w/2 + (w/2) * l / d; a
 * height H above the eye at depth d is (w/2) * H / d pixels above the
 * horizon, which sits at row centre h/2 + shear.
 *
 * Clipping finds plane crossings by bisection on exact integer midpoints
 * rather than by a multiply-divide: view-space values reach 2^33, so the
 * product in a one-step intersection would need 128 bits, while bisection
 * stays exact in int64 and costs ~36 cheap steps, only for the few segs that
 * cross the near plane or a screen edge. The point kept is always on the
 * visible side.
 */
#include "engine/r_main.h"

#include <assert.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/r_local.h"
#include "engine/tab.h"

enum { R_PLANE_NEAR, R_PLANE_LEFT, R_PLANE_RIGHT, R_PLANES };

/* >= 0 on the visible side of plane */
static int64_t r_plane_dist(int plane, const struct r_vpt *p)
{
	switch (plane) {
	case R_PLANE_NEAR:
		return p->d - R_NEAR;
	case R_PLANE_LEFT:
		return p->d + p->l;
	default:
		return p->d - p->l;
	}
}

/* The point of segment in-out nearest the plane on its visible side, to
 * within one unit (1/65536 map unit) per coordinate. in is visible, out not.
 * Midpoints are floor averages: no overflow, and strictly between the ends
 * while they are two or more apart, so each step halves the interval. */
static struct r_vpt r_bisect(int plane, struct r_vpt in, struct r_vpt out)
{
	for (;;) {
		int64_t dl = in.l - out.l, dd = in.d - out.d;
		struct r_vpt mid;

		if (dl >= -1 && dl <= 1 && dd >= -1 && dd <= 1)
			return in;
		mid.l = (in.l + out.l) >> 1;
		mid.d = (in.d + out.d) >> 1;
		if (r_plane_dist(plane, &mid) >= 0)
			in = mid;
		else
			out = mid;
	}
}

/* Removes the last unit of bisection rounding: floor averages keep every
 * earlier plane except that d + l or d - l may end 1 below zero. */
static void r_settle(struct r_vpt *p)
{
	if (p->d < R_NEAR)
		p->d = R_NEAR;
	if (p->l > p->d)
		p->l = p->d;
	if (p->l < -p->d)
		p->l = -p->d;
}

void r_to_view(const struct r_ctx *r, fx_t x, fx_t y, struct r_vpt *p)
{
	/* |dx|, |dy| < 2^31 (both clamped to MAP_COORD_MAX), products < 2^47 */
	int64_t dx = (int64_t)x - r->ex;
	int64_t dy = (int64_t)y - r->ey;

	p->d = (dx * r->vcos + dy * r->vsin) >> FX_SHIFT;
	p->l = (dx * r->vsin - dy * r->vcos) >> FX_SHIFT;
}

int r_clip_segment(struct r_vpt *a, struct r_vpt *b)
{
	for (int plane = 0; plane < R_PLANES; plane++) {
		int64_t fa = r_plane_dist(plane, a);
		int64_t fb = r_plane_dist(plane, b);

		if (fa < 0 && fb < 0)
			return 0;
		if (fa < 0)
			*a = r_bisect(plane, *b, *a);
		else if (fb < 0)
			*b = r_bisect(plane, *a, *b);
	}
	r_settle(a);
	r_settle(b);
	return 1;
}

/* One Sutherland-Hodgman pass; every edge adds at most two points. */
static int r_clip_poly_plane(int plane, const struct r_vpt *in, int n, struct r_vpt *out)
{
	int k = 0;

	for (int i = 0; i < n; i++) {
		const struct r_vpt *a = &in[i], *b = &in[(i + 1) % n];
		int va = r_plane_dist(plane, a) >= 0;
		int vb = r_plane_dist(plane, b) >= 0;

		if (va)
			out[k++] = *a;
		if (va && !vb)
			out[k++] = r_bisect(plane, *a, *b);
		else if (!va && vb)
			out[k++] = r_bisect(plane, *b, *a);
	}
	return k;
}

int r_clip_polygon(struct r_vpt *v, int n)
{
	struct r_vpt tmp[R_POLY_MAX];

	/* each pass at most doubles the count: 4 -> 8 -> 16 -> 32 */
	n = r_clip_poly_plane(R_PLANE_NEAR, v, n, tmp);
	n = r_clip_poly_plane(R_PLANE_LEFT, tmp, n, v);
	n = r_clip_poly_plane(R_PLANE_RIGHT, v, n, tmp);
	for (int i = 0; i < n; i++) {
		v[i] = tmp[i];
		r_settle(&v[i]);
	}
	return n;
}

int64_t r_project_x(const struct r_ctx *r, const struct r_vpt *p)
{
	/* |l| <= d < 2^33 and half = w * 2^15 <= 2^27: product < 2^60 */
	int64_t half = (int64_t)r->w << (FX_SHIFT - 1);

	return half + p->l * half / p->d;
}

int r_new(int w, int h, const struct pal *pal, struct r_ctx **out)
{
	struct r_ctx *r;

	*out = NULL;
	if (w < 1 || h < 1 || w > R_MAX_DIM || h > R_MAX_DIM || !pal)
		return -EINVAL;
	r = calloc(1, sizeof(*r));
	if (!r)
		return -ENOMEM;
	r->w = w;
	r->h = h;
	r->pal = pal;
	/* disjoint non-adjacent runs in w columns: at most (w + 1) / 2, plus the
	 * two sentinels and one being inserted */
	r->maxsolid = w / 2 + 4;
	r->ceilclip = malloc((size_t)w * sizeof(*r->ceilclip));
	r->floorclip = malloc((size_t)w * sizeof(*r->floorclip));
	r->solid = malloc((size_t)r->maxsolid * sizeof(*r->solid));
	r->rowv = malloc((size_t)h * sizeof(*r->rowv));
	if (!r->ceilclip || !r->floorclip || !r->solid || !r->rowv)
		goto fail;
	r->rowv_cy2 = INT32_MIN;
	/* fade = R_FADE_DIST * scale / focal with focal = w / 2 and scale16 =
	 * scale * 2^16: (scale16 * R_FADE_DIST * 2^17 / w) >> 32 */
	r->wall_kq = ((int64_t)R_FADE_DIST << 17) / w;
	*out = r;
	return 0;
fail:
	r_free(r);
	return -ENOMEM;
}

void r_free(struct r_ctx *r)
{
	if (!r)
		return;
	free(r->ceilclip);
	free(r->floorclip);
	free(r->solid);
	free(r->rowv);
	free(r);
}

static fx_t r_clamp_coord(fx_t v)
{
	if (v > MAP_COORD_MAX)
		return MAP_COORD_MAX;
	if (v < -MAP_COORD_MAX)
		return -MAP_COORD_MAX;
	return v;
}

static void r_setup_view(struct r_ctx *r, const struct r_view *v)
{
	int32_t shear = v->shear;

	r->ex = r_clamp_coord(v->x);
	r->ey = r_clamp_coord(v->y);
	r->ez = v->z;
	r->vcos = tab_cos(v->angle);
	r->vsin = tab_sin(v->angle);
	if (shear > r->h)
		shear = r->h;
	if (shear < -r->h)
		shear = -r->h;
	r->cy2 = r->h + 2 * shear;
	r->cy32 = (int64_t)r->cy2 * ((int64_t)1 << 31);
	if (r->cy2 != r->rowv_cy2) {
		for (int y = 0; y < r->h; y++) {
			int32_t dv = 2 * y + 1 - r->cy2;
			r->rowv[y] = dv < 0 ? -dv : dv;
		}
		r->rowv_cy2 = r->cy2;
	}
	for (int x = 0; x < r->w; x++) {
		r->ceilclip[x] = -1;
		r->floorclip[x] = (int16_t)r->h;
	}
	r_solid_reset(r);
}

void r_render(struct r_ctx *r, const struct map *m, const struct r_view *v,
	      struct r_frame *f)
{
	assert(r && m && v && f && f->px);
	assert(f->w == r->w && f->h == r->h && f->pitch >= f->w);
	memset(&r->st, 0, sizeof(r->st));
	r->map = m;
	r->px = f->px;
	r->pitch = f->pitch;
	r_setup_view(r, v);
	if (m->num_subsectors > 0)
		r_bsp_render(r);
	r_draw_finish(r);
	r->map = NULL;
	r->px = NULL;
}

void r_get_stats(const struct r_ctx *r, struct r_stats *st)
{
	*st = r->st;
}
