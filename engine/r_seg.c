/*
 * r_seg: one seg to wall, ceiling and floor column runs (Doom's r_segs).
 *
 * A seg facing the eye is transformed to view space, clipped to the near
 * plane and the frustum, and projected to the columns whose centres lie in
 * [sx1, sx2). Its scale (focal / depth) is linear in screen x, so it is
 * computed at the first column centre and stepped, in 32.32.
 *
 * In each column the rows still unwritten are [top, bot] =
 * [ceilclip + 1, floorclip - 1]. The front sector's ceiling edge and floor
 * edge split them into ceiling rows, a middle, and floor rows. A one-sided
 * seg fills the middle with its wall and closes the column. A two-sided seg
 * draws an upper part where the back ceiling is lower, a lower part where the
 * back floor is higher, and narrows [top, bot] to the opening left between
 * them; the column closes when the opening is empty. Every pixel is written
 * once: each run is a prefix or suffix of the unwritten interval.
 *
 * Lighting: walls by column (sector light with fake contrast, faded by
 * scale), ceilings and floors by row (sector light, faded by the row's
 * depth), both Doom's R_FADE_DIST / depth rule.
 */
#include <stdint.h>

#include "engine/map.h"
#include "engine/r_local.h"

/* A seg's projection and surfaces (Doom's rw_* globals, as one value). */
struct r_wall {
	int x1, x2;                     /* columns */
	int64_t s0, step;               /* 32.32 scale at x1's centre, per column */
	int64_t smin, smax;             /* the endpoints' scales: s stays inside */
	int64_t hfc, hff, hbc, hbf;     /* heights above the eye, 16.16 */
	int two_sided, upper, lower;
	uint8_t mid, top, bot;          /* wall colours (palette indices) */
	int wall_base;                  /* colormap level before fade, walls */
	int plane_base;                 /* colormap level before fade, planes */
	int ceil_vis, floor_vis;        /* the eye is below / above the plane */
	uint8_t ceil_tex, floor_tex;
	int64_t qceil, qfloor;          /* plane fade factors, see r_plane_q */
};

/* Palette index of a texture number; 0 (none) and numbers past the palette
 * draw PAL_BLACK. */
static uint8_t r_tex(uint16_t t)
{
	return t == 0 || t > 255 ? PAL_BLACK : (uint8_t)t;
}

/* Colormap level before distance fade for a light level 0..255. */
static int r_light_base(int light)
{
	if (light < 0)
		light = 0;
	if (light > 255)
		light = 255;
	/* Doom's: 16 light steps of 16, two colormaps apart, so a bright
	 * sector (208) starts 8 levels down and the distance fade brightens
	 * near surfaces from there; a dark one (<= 112) is black far away. */
	int base = 4 * (15 - (light >> 4));
	return base > PAL_LIGHTS - 1 ? PAL_LIGHTS - 1 : base;
}

/* Fade factor of a plane dist (> 0) units from the eye: a row's fade is
 * (rowv[y] * q) >> 32 = R_FADE_DIST * |y + 0.5 - cy| / (dist * w / 2), i.e.
 * R_FADE_DIST / depth at that row. Capped at 32 per unit of rowv: any
 * row (rowv >= 1) then fades by >= R_FADE_MAX, as the exact value would. */
static int64_t r_plane_q(const struct r_ctx *r, int64_t dist)
{
	/* dist < 2^33, w <= 2^12: den < 2^45; R_FADE_DIST << 48 < 2^59 */
	int64_t q = ((int64_t)R_FADE_DIST << 48) / ((int64_t)r->w * dist);
	int64_t cap = (int64_t)32 << 32;

	return q > cap ? cap : q;
}

/* First row whose centre is at or below the edge of height hrel (16.16
 * above the eye) at scale s16 (16.16), clamped to [lo, hi]. */
static int r_edge_row(const struct r_ctx *r, int64_t hrel, int64_t s16, int lo, int hi)
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

static void r_plane_run(struct r_ctx *r, const struct r_wall *w, int x, int y1, int y2,
			int ceiling)
{
	if (ceiling ? w->ceil_vis : w->floor_vis)
		r_draw_plane(r, x, y1, y2, ceiling ? w->ceil_tex : w->floor_tex, w->plane_base,
			     ceiling ? w->qceil : w->qfloor);
	else
		r_draw_fill(r, x, y1, y2, PAL_BLACK);
}

static void r_column(struct r_ctx *r, const struct r_wall *w, int x)
{
	const uint8_t(*cmap)[256] = r->pal->cmap;
	int64_t s = w->s0 + w->step * (x - w->x1);
	int64_t s16, fade;
	int top = r->ceilclip[x] + 1, bot = r->floorclip[x] - 1;
	int a, b, m, k, lvl;

	if (top > bot)
		return;
	if (s < w->smin)
		s = w->smin;
	if (s > w->smax)
		s = w->smax;
	s16 = s >> 16;
	fade = (s16 * r->wall_kq) >> 32;
	lvl = w->wall_base - (fade > R_FADE_MAX ? R_FADE_MAX : (int)fade);
	if (lvl < 0)
		lvl = 0;
	r->st.columns++;

	/* rows [top, a - 1] ceiling, [a, b] middle, [b + 1, bot] floor */
	a = r_edge_row(r, w->hfc, s16, top, bot + 1);
	b = r_edge_row(r, w->hff, s16, a, bot + 1) - 1;
	r_plane_run(r, w, x, top, a - 1, 1);
	r_plane_run(r, w, x, b + 1, bot, 0);
	if (!w->two_sided) {
		r_draw_fill(r, x, a, b, cmap[lvl][w->mid]);
		r->ceilclip[x] = (int16_t)r->h;
		r->floorclip[x] = -1;
		return;
	}
	/* upper part [a, m], lower part [k, b], opening [m + 1, k - 1] */
	m = a - 1;
	if (w->upper) {
		m = r_edge_row(r, w->hbc, s16, a, b + 1) - 1;
		r_draw_fill(r, x, a, m, cmap[lvl][w->top]);
	}
	k = b + 1;
	if (w->lower) {
		k = r_edge_row(r, w->hbf, s16, m + 1, b + 1);
		r_draw_fill(r, x, k, b, cmap[lvl][w->bot]);
	}
	r->ceilclip[x] = (int16_t)m;
	r->floorclip[x] = (int16_t)k;
}

/* Fills w with the seg's surfaces and light. */
static void r_wall_surfaces(const struct r_ctx *r, const struct map_seg *sg, struct r_wall *w)
{
	const struct map *m = r->map;
	const struct map_line *ln = &m->lines[sg->line];
	const struct map_side *sd = &m->sides[ln->side[sg->side]];
	const struct map_sector *fs = &m->sectors[sg->front];
	const struct map_vertex *v1 = &m->vertices[ln->v1], *v2 = &m->vertices[ln->v2];
	int light = fs->light;

	if (v1->y == v2->y)
		light += R_CONTRAST;
	else if (v1->x == v2->x)
		light -= R_CONTRAST;
	w->wall_base = r_light_base(light);
	w->plane_base = r_light_base(fs->light);
	w->hfc = (int64_t)fs->ceil_h - r->ez;
	w->hff = (int64_t)fs->floor_h - r->ez;
	w->ceil_vis = w->hfc > 0 && fs->ceil_tex != 0;
	w->floor_vis = w->hff < 0 && fs->floor_tex != 0;
	w->ceil_tex = r_tex(fs->ceil_tex);
	w->floor_tex = r_tex(fs->floor_tex);
	w->qceil = w->hfc > 0 ? r_plane_q(r, w->hfc) : 0;
	w->qfloor = w->hff < 0 ? r_plane_q(r, -w->hff) : 0;
	w->mid = r_tex(sd->mid_tex);
	w->two_sided = sg->back != MAP_NONE;
	w->upper = w->lower = 0;
	if (w->two_sided) {
		const struct map_sector *bs = &m->sectors[sg->back];

		w->hbc = (int64_t)bs->ceil_h - r->ez;
		w->hbf = (int64_t)bs->floor_h - r->ez;
		/* a missing upper or lower texture draws nothing: what lies
		 * behind shows, as in Doom */
		w->upper = bs->ceil_h < fs->ceil_h && sd->top_tex != 0;
		w->lower = bs->floor_h > fs->floor_h && sd->bot_tex != 0;
		w->top = r_tex(sd->top_tex);
		w->bot = r_tex(sd->bot_tex);
	}
}

/* 1 when the seg's indices are usable (map_finish guarantees it; checked so
 * that no data can make the renderer read out of bounds). */
static int r_seg_valid(const struct map *m, const struct map_seg *sg)
{
	const struct map_line *ln;

	if (sg->v1 >= m->num_vertices || sg->v2 >= m->num_vertices ||
	    sg->line >= m->num_lines || sg->side > 1 || sg->front >= m->num_sectors ||
	    (sg->back != MAP_NONE && sg->back >= m->num_sectors))
		return 0;
	ln = &m->lines[sg->line];
	return ln->side[sg->side] < m->num_sides && ln->v1 < m->num_vertices &&
	       ln->v2 < m->num_vertices;
}

/* A two-sided seg between sectors that look the same changes nothing: the
 * ceiling and floor beyond it are drawn, identically, by the segs behind. */
static int r_seg_invisible(const struct map *m, const struct map_seg *sg)
{
	const struct map_sector *f, *b;

	if (sg->back == MAP_NONE)
		return 0;
	f = &m->sectors[sg->front];
	b = &m->sectors[sg->back];
	return f->ceil_h == b->ceil_h && f->floor_h == b->floor_h &&
	       f->ceil_tex == b->ceil_tex && f->floor_tex == b->floor_tex &&
	       f->light == b->light;
}

/* Projects the seg; 0 when it covers no column. */
static int r_wall_project(const struct r_ctx *r, const struct map_seg *sg, struct r_wall *w)
{
	const struct map *m = r->map;
	const struct map_vertex *a = &m->vertices[sg->v1], *b = &m->vertices[sg->v2];
	struct r_vpt p1, p2;
	int64_t sx1, sx2, s1, s2, xc;
	/* front side is to the right of v1 -> v2: the eye must be strictly
	 * right, cross((b - a), (eye - a)) < 0. Differences < 2^31 (coordinates
	 * within MAP_COORD_MAX): exact in int64. */
	int64_t cross = ((int64_t)b->x - a->x) * ((int64_t)r->ey - a->y) -
			((int64_t)b->y - a->y) * ((int64_t)r->ex - a->x);

	if (cross >= 0)
		return 0;
	r_to_view(r, a->x, a->y, &p1);
	r_to_view(r, b->x, b->y, &p2);
	if (!r_clip_segment(&p1, &p2))
		return 0;
	sx1 = r_project_x(r, &p1);
	sx2 = r_project_x(r, &p2);
	if (sx1 >= sx2)
		return 0;
	w->x1 = r_col_at(sx1);
	w->x2 = r_col_at(sx2) - 1;
	if (w->x1 < 0)
		w->x1 = 0;
	if (w->x2 > r->w - 1)
		w->x2 = r->w - 1;
	if (w->x1 > w->x2)
		return 0;
	/* scale = (w / 2) / depth in 32.32: w * 2^47 / d, d >= R_NEAR = 2^14,
	 * so at most 2^45 */
	s1 = ((int64_t)r->w << 47) / p1.d;
	s2 = ((int64_t)r->w << 47) / p2.d;
	/* 1/depth is linear in screen x: per-column step (s2 - s1) / (sx2 - sx1)
	 * pixels; |s2 - s1| * 2^16 < 2^61 */
	w->step = (s2 - s1) * FX_ONE / (sx2 - sx1);
	xc = (int64_t)w->x1 * FX_ONE + FX_HALF;
	/* 0 <= xc - sx1 < sx2 - sx1, so |step * (xc - sx1)| <= |s2 - s1| * 2^16 */
	w->s0 = s1 + ((w->step * (xc - sx1)) >> FX_SHIFT);
	w->smin = s1 < s2 ? s1 : s2;
	w->smax = s1 < s2 ? s2 : s1;
	return 1;
}

void r_seg_add(struct r_ctx *r, const struct map_seg *sg)
{
	const struct map *m = r->map;
	const struct r_range *s = r->solid;
	struct r_wall w;
	int x, i, run;

	if (!r_seg_valid(m, sg) || r_seg_invisible(m, sg) || !r_wall_project(r, sg, &w))
		return;
	r->st.segs++;
	r_wall_surfaces(r, sg, &w);
	/* draw the columns of [x1, x2] not in a solid run */
	x = w.x1;
	i = 0;
	while (x <= w.x2) {
		int end;

		while (s[i].last < x)
			i++;
		if (s[i].first <= x) {
			x = s[i].last + 1;
			continue;
		}
		end = s[i].first - 1 < w.x2 ? s[i].first - 1 : w.x2;
		for (; x <= end; x++)
			r_column(r, &w, x);
	}
	/* then record the columns this seg closed (and any closed before) */
	run = -1;
	for (x = w.x1; x <= w.x2 + 1; x++) {
		int closed = x <= w.x2 && r->ceilclip[x] >= r->floorclip[x] - 1;

		if (closed && run < 0)
			run = x;
		else if (!closed && run >= 0) {
			r_solid_add(r, run, x - 1);
			run = -1;
		}
	}
}
