/*
 * r_main: render context, per-frame set-up, and what every stage shares:
 * view transform, clipping to the visible region, projection, light levels,
 * texture lookup with its fallback, growth of the per-frame lists.
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
#include "engine/render/r_main.h"

#include <assert.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/pal.h"
#include "engine/core/tab.h"
#include "engine/render/r_local.h"

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

int r_edge_row(const struct r_ctx *r, int64_t hrel, int64_t s16, int lo, int hi)
{
	/* |hrel| < 2^33, s16 <= 2^29: product < 2^62 */
	int64_t y = r->cy32 - hrel * s16;
	int64_t row = (y + ((int64_t)1 << 31) - 1) >> 32;

	if (row < lo)
		return lo;
	if (row > hi)
		return hi;
	return (int)row;
}

int r_light_base(int light)
{
	int base;

	if (light < 0)
		light = 0;
	if (light > 255)
		light = 255;
	/* Doom's: 16 light steps of 16, two colormaps apart, so a bright
	 * sector (208) starts 8 levels down and the distance fade brightens
	 * near surfaces from there; a dark one (<= 112) is black far away. */
	base = 4 * (15 - (light >> 4));
	return base > PAL_LIGHTS - 1 ? PAL_LIGHTS - 1 : base;
}

int r_scale_level(const struct r_ctx *r, int base, int64_t s)
{
	/* s16 <= 2^29, wall_kq <= 1280 * 2^17: product < 2^60 */
	int64_t fade = ((s >> 16) * r->wall_kq) >> 32;
	int lvl = base - (fade > R_FADE_MAX ? R_FADE_MAX : (int)fade);

	return lvl < 0 ? 0 : lvl;
}

/* Paints the fallback checker (8x8 squares) in the palette's nearest
 * magenta and black, when those differ from the last frame's. */
static void r_fallback_colours(struct r_ctx *r)
{
	int hi = pal_nearest(&r->tex->pal, 255, 0, 255);
	int lo = r->black;

	if (hi == r->fb_hi && lo == r->fb_lo)
		return;
	r->fb_hi = hi;
	r->fb_lo = lo;
	for (int x = 0; x < R_FB_SIZE; x++)
		for (int y = 0; y < R_FB_SIZE; y++)
			r->fb_px[x * R_FB_SIZE + y] = (uint8_t)(((x ^ y) & 8) ? lo : hi);
	for (int y = 0; y < TEX_FLAT_SIZE; y++)
		for (int x = 0; x < TEX_FLAT_SIZE; x++)
			r->fb_flat[y * TEX_FLAT_SIZE + x] = (uint8_t)(((x ^ y) & 8) ? lo : hi);
}

const struct tex_pic *r_wall_pic(struct r_ctx *r, uint16_t num)
{
	int n = tex_wall_index(r->tex, num);

	if (n > 0)
		return &r->tex->textures[n];
	if (n == 0)
		return NULL;
	r->st.missing++;
	return &r->fb_pic;
}

const uint8_t *r_flat_px(struct r_ctx *r, uint16_t num)
{
	const struct tex_set *t = r->tex;
	int n = num;

	if (t->flat_xlat && n < t->num_flats)
		n = t->flat_xlat[n];
	if (n >= t->num_flats || !t->flats) {
		r->st.missing++;
		return r->fb_flat;
	}
	return t->flats[n].px;
}

int r_is_sky(const struct r_ctx *r, uint16_t num)
{
	return r->tex->sky_flat >= 0 && num == r->tex->sky_flat;
}

int r_grow(void **p, int *cap, size_t elem, int need)
{
	int64_t n = *cap > 0 ? *cap : 16;
	void *np;

	if (need <= *cap)
		return 0;
	while (n < need)
		n *= 2;
	if (n > INT32_MAX / 2 || (uint64_t)n > SIZE_MAX / elem)
		return -ENOMEM;
	np = realloc(*p, (size_t)n * elem);
	if (!np)
		return -ENOMEM;
	*p = np;
	*cap = (int)n;
	return 0;
}

int32_t r_open_alloc(struct r_ctx *r, int n)
{
	int cap = r->maxopen;
	int32_t at = r->nopen;

	if ((int64_t)at + n > INT32_MAX / 2 ||
	    r_grow((void **)&r->open, &cap, sizeof(*r->open), at + n) < 0) {
		r->st.degraded++;
		return -1;
	}
	r->maxopen = cap;
	r->nopen = at + n;
	r->st.openings += (uint32_t)n;
	return at;
}

int r_new(int w, int h, struct r_ctx **out)
{
	struct r_ctx *r;

	*out = NULL;
	if (w < 1 || h < 1 || w > R_MAX_DIM || h > R_MAX_DIM)
		return -EINVAL;
	/* sizeof is a multiple of the 64-byte alignment (r_local.h) */
	r = aligned_alloc(_Alignof(struct r_ctx), sizeof(*r));
	if (!r)
		return -ENOMEM;
	memset(r, 0, sizeof(*r));
	r->w = w;
	r->h = h;
	for (int i = 0; i < 256; i++)
		r->ident[i] = (uint8_t)i;
	/* disjoint non-adjacent runs in w columns: at most (w + 1) / 2, plus the
	 * two sentinels and one being inserted */
	r->maxsolid = w / 2 + 4;
	r->ceilclip = malloc((size_t)w * sizeof(*r->ceilclip));
	r->floorclip = malloc((size_t)w * sizeof(*r->floorclip));
	r->cliptop = malloc((size_t)w * sizeof(*r->cliptop));
	r->clipbot = malloc((size_t)w * sizeof(*r->clipbot));
	r->xtoang = malloc((size_t)w * sizeof(*r->xtoang));
	r->solid = malloc((size_t)r->maxsolid * sizeof(*r->solid));
	r->rowv = malloc((size_t)h * sizeof(*r->rowv));
	r->yslope = malloc((size_t)h * sizeof(*r->yslope));
	if (!r->ceilclip || !r->floorclip || !r->cliptop || !r->clipbot || !r->xtoang ||
	    !r->solid || !r->rowv || !r->yslope || r_set_par(r, NULL) < 0)
		goto fail;
	r->rowv_cy2 = INT32_MIN;
	/* fade = R_FADE_DIST * scale / focal with focal = w / 2 and scale16 =
	 * scale * 2^16: (scale16 * R_FADE_DIST * 2^17 / w) >> 32 */
	r->wall_kq = ((int64_t)R_FADE_DIST << 17) / w;
	/* the ray through column x's centre: lateral 2x + 1 - w (right) per
	 * depth w, i.e. an angle atan((w - 2x - 1) / w) to the left */
	for (int x = 0; x < w; x++)
		r->xtoang[x] = tab_atan2((fx_t)((w - 2 * x - 1) * 4096), (fx_t)(w * 4096));
	r->fb_pic.w = R_FB_SIZE;
	r->fb_pic.h = R_FB_SIZE;
	r->fb_pic.px = r->fb_px;
	memcpy(r->fb_pic.name, "-FALLBK", 8);
	r->fb_lo = r->fb_hi = -1;
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
	r_strip_free(r);
	for (int i = 0; i < r->maxplanes; i++) {
		free(r->planes[i].top);
		free(r->planes[i].bot);
	}
	free(r->planes);
	free(r->dsegs);
	free(r->open);
	free(r->vis);
	free(r->sec_seen);
	free(r->ceilclip);
	free(r->floorclip);
	free(r->cliptop);
	free(r->clipbot);
	free(r->xtoang);
	free(r->solid);
	free(r->rowv);
	free(r->yslope);
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
	r->angle = v->angle;
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
			/* a row on the horizon (odd h, no shear) counts as half a
			 * unit away: its planes are clamped to R_PLANE_DMAX */
			r->yslope[y] = ((int64_t)r->w << 16) * 2 / (r->rowv[y] ? 2 * r->rowv[y] : 1);
		}
		r->rowv_cy2 = r->cy2;
	}
	for (int x = 0; x < r->w; x++) {
		r->ceilclip[x] = -1;
		r->floorclip[x] = (int16_t)r->h;
	}
	r_solid_reset(r);
}

/* Makes sec_seen ready for m: a new frame number, the array grown to the
 * map's sectors (cleared when the number wraps or the array is new). */
static void r_sectors_reset(struct r_ctx *r, const struct map *m)
{
	int old = r->maxsecs;

	if (m->num_sectors > (uint32_t)INT32_MAX / 2 ||
	    r_grow((void **)&r->sec_seen, &r->maxsecs, sizeof(*r->sec_seen),
		   (int)m->num_sectors) < 0) {
		/* every sprite is then drawn, clipped only by drawsegs */
		r->seen_ok = 0;
		r->st.degraded++;
		return;
	}
	if (r->maxsecs > old)
		memset(&r->sec_seen[old], 0, (size_t)(r->maxsecs - old) * sizeof(*r->sec_seen));
	if (++r->frame_no == 0) {
		memset(r->sec_seen, 0, (size_t)r->maxsecs * sizeof(*r->sec_seen));
		r->frame_no = 1;
	}
	r->seen_ok = 1;
}

int r_set_par(struct r_ctx *r, const struct r_par *par)
{
	int threads = par && par->run ? par->threads : 1;
	int shift = 6;

	/* one strip on one thread; else strips of a power-of-two number of
	 * cache lines, about R_STRIPS_PER_THREAD per thread */
	if (threads < 2)
		threads = 1;
	while ((1 << shift) < r->w &&
	       ((r->w + (1 << shift) - 1) >> shift) > (threads > 1 ? R_STRIPS_PER_THREAD * threads : 1))
		shift++;
	if (shift != r->strip_shift && r_strip_layout(r, shift, R_BAND_SHIFT) < 0)
		return -ENOMEM;
	if (threads > 1)
		r->par = *par;
	else
		memset(&r->par, 0, sizeof(r->par));
	return 0;
}

void r_set_lmap(struct r_ctx *r, const struct lmap *lm)
{
	r->lm = lm;
}

void r_set_strip_done(struct r_ctx *r, void (*fn)(void *arg, int x0, int x1), void *arg)
{
	r->strip_done = fn;
	r->strip_done_arg = arg;
}

void r_set_beside_walk(struct r_ctx *r, void (*fn)(void *arg), void *arg)
{
	r->beside = fn;
	r->beside_arg = arg;
}

void r_beside_sprites(struct r_ctx *r, const struct r_sprite *spr, int n)
{
	assert(r && n >= 0 && (spr || n == 0));
	/* read only by the walk's rest, which starts after the batch that
	 * ran the caller returned */
	r->wspr = spr;
	r->wnspr = n;
}

/* The walk: every wall, sky and flat part recorded into the strips. */
static void r_walk(struct r_ctx *r)
{
	if (r->map->num_subsectors > 0) {
		r_bsp_render(r);
		r_plane_draw_sky(r);
	}
}

/* r_render's first batch: job 0 the walk, job 1 the work beside it. Jobs
 * are handed out in order, so the first thread to ask (the caller, when
 * the workers are slow to wake) takes the walk, usually the longer, and a
 * thread that comes later the shorter job; the walk may run on a worker. */
static void r_walk_job(void *arg, int i)
{
	struct r_ctx *r = arg;

	if (i == 0)
		r_walk(r);
	else
		r->beside(r->beside_arg);
}

void r_set_idbuf(struct r_ctx *r, uint32_t *ids)
{
	r->ids = ids;
}

void r_render(struct r_ctx *r, const struct map *m, const struct tex_set *t,
	      const struct r_view *v, const struct r_sprite *spr, int nspr, struct r_frame *f)
{
	assert(r && m && t && v && f && f->px && (spr || nspr == 0));
	assert(f->w == r->w && f->h == r->h && f->pitch >= f->w);
	/* the walk below is serial: the pool's workers wake during it */
	if (r->par.run && r->par.warm && r->nstrips > 1)
		r->par.warm(r->par.pool);
	memset(&r->st, 0, sizeof(r->st));
	r->map = m;
	r->tex = t;
	r->cmap = t->pal.cmap;
	r->black = pal_nearest(&t->pal, 0, 0, 0);
	r_fallback_colours(r);
	r->px = f->px;
	r->pitch = f->pitch;
	r_setup_view(r, v);
	r_plane_clear(r);
	r->ndsegs = 0;
	r->nopen = 0;
	r->nvis = 0;
	r_sectors_reset(r, m);
	r_strip_reset(r);
	/* the work beside the walk may replace them (r_beside_sprites) */
	r->wspr = spr;
	r->wnspr = nspr;
	/* the walk records, then the strips draw (r_strip.c) */
	if (r->beside && r->par.run && r->nstrips > 1) {
		r->par.run(r->par.pool, 2, r_walk_job, r);
	} else {
		if (r->beside)
			r->beside(r->beside_arg);
		r_walk(r);
	}
	r_strip_draw_all(r, m->num_subsectors > 0);
	r->st.planes = (uint32_t)r->nplanes;
	r->st.drawsegs = (uint32_t)r->ndsegs;
	r->st.sprites = (uint32_t)r->nvis;
	r->map = NULL;
	r->tex = NULL;
	r->cmap = NULL;
	r->px = NULL;
}

void r_get_stats(const struct r_ctx *r, struct r_stats *st)
{
	*st = r->st;
}
