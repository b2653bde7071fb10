/*
 * r_seg: one seg to textured wall columns, plane marks and drawsegs (Doom's
 * r_segs).
 *
 * A seg facing the eye is transformed to view space, clipped to the near
 * plane and the frustum, and projected to the columns whose centres lie in
 * [sx1, sx2). Its scale (focal / depth) is linear in screen x, so it is
 * computed at the first column centre and stepped, in 32.32.
 *
 * In each column the rows still unwritten are [top, bot] =
 * [ceilclip + 1, floorclip - 1]. The front sector's ceiling edge and floor
 * edge split them into ceiling rows, a middle, and floor rows; the ceiling
 * and floor rows are marked into the subsector's visplanes (drawn later as
 * spans), or filled black when that plane is seen from behind. A one-sided
 * seg fills the middle with its texture and closes the column. A two-sided
 * seg draws an upper part where the back ceiling is lower, a lower part
 * where the back floor is higher, and narrows [top, bot] to the opening
 * left between them; the column closes when the opening is empty. As in
 * Doom, a two-sided seg whose back floor (ceiling) has the front's height,
 * flat and light marks no floor (ceiling) rows: the segs behind do, for the
 * same plane. Every pixel is written once: each run is a prefix or suffix
 * of the unwritten interval, which then shrinks.
 *
 * Texture mapping, Doom's rules:
 *  - horizontal: u = seg offset + side x offset + distance from the seg's
 *    first vertex to where the column's ray meets the seg's line. That
 *    fraction of the seg is num / den with num and den linear in the
 *    column (the ray-line intersection), so both are stepped exactly and
 *    one 64-bit division per column gives a perspective-correct u;
 *  - vertical: texel row = (height of texel row 0 above the eye) + (row
 *    centre below the horizon) / scale, one division per column for 1/scale,
 *    then stepped per row. Row 0 sits at the front ceiling for a one-sided
 *    wall, or at floor + texture height when lower-unpegged
 *    (ML_DONTPEGBOTTOM); an upper texture hangs from the back ceiling
 *    (its bottom there) unless upper-unpegged (ML_DONTPEGTOP: top at the
 *    front ceiling); a lower texture starts at the back floor unless
 *    lower-unpegged (then at the front ceiling); plus the side's y offset.
 *    Textures repeat vertically at any height (a correct modulo, not a
 *    power-of-two mask) and horizontally at any width.
 *  - between two sky ceilings the upper wall is not drawn: the sky plane
 *    reaches down to the back ceiling instead (Doom's outdoor hack).
 *
 * Lighting: walls by column (sector light with fake contrast, faded by
 * scale), Doom's R_FADE_DIST / depth rule.
 *
 * Each visible column range of a seg that sprites may need to be clipped
 * against (Doom's silhouettes), or that has a masked middle texture, is
 * kept as a drawseg with copies of the clip arrays after the seg, for
 * r_things.c.
 */
#include <stdint.h>
#include <string.h>

#include "engine/map/map.h"
#include "engine/render/r_local.h"

/* A seg's projection and surfaces (Doom's rw_* globals, as one value). */
struct r_wall {
	int x1, x2;                     /* columns */
	int64_t s0, step;               /* 32.32 scale at x1's centre, per column */
	int64_t smin, smax;             /* the endpoints' scales: s stays inside */
	int64_t hfc, hff, hbc, hbf;     /* heights above the eye, 16.16 */
	int two_sided, upper, lower;    /* upper/lower: the back ceiling is lower,
					 * the back floor higher */
	int markceil, markfloor;        /* this seg marks those plane rows */
	const struct tex_pic *mid, *top, *bot, *masked;   /* NULL: none */
	int64_t tm_mid, tm_top, tm_bot; /* texel row 0's height above the eye */
	int wall_base;                  /* colormap level before fade */
	int need_u;
	/* texture u: the ray of the column with X = 2x + 1 - w meets the seg
	 * at fraction (n0 + nx * X) / (d0 + dx * X) (0 at v1, 1 at v2), both
	 * shifted right by ushift so the denominator fits 31 bits */
	int64_t n0, nx, d0, dx;
	int ushift;
	int64_t u0;                     /* u at v1: offsets, 16.16 */
	int64_t xoff;                   /* the side's x offset, 16.16 */
	const struct lmap_grid *lg;     /* the side's light map, or NULL */
	uint64_t len;                   /* seg length, 16.16 */
	uint32_t lside;                 /* line * 2 + side: surface ids */
};

/* Texture column of integer u for a width w texture (any width). */
static int r_tex_col(int64_t u, int w)
{
	if ((w & (w - 1)) == 0)
		return (int)(u & (w - 1));
	u %= w;
	return (int)(u < 0 ? u + w : u);
}

/* Texture u (16.16 map units from the texture's left edge) at column x. */
static int64_t r_wall_u16(const struct r_ctx *r, const struct r_wall *w, int x)
{
	int64_t X = 2 * x + 1 - r->w;
	int64_t n = (w->n0 + w->nx * X) >> w->ushift;
	int64_t d = (w->d0 + w->dx * X) >> w->ushift;
	uint64_t t;

	/* t: 0..2^32; outside the seg (only by rounding at its ends) the
	 * nearer end */
	if (n <= 0)
		t = 0;
	else if (d <= 0 || n >= d)
		t = (uint64_t)1 << 32;
	else
		t = ((uint64_t)n << 32) / (uint64_t)d;  /* n < d < 2^31 */
	/* t <= 2^32, len < 2^31.5: product < 2^64 */
	return w->u0 + (int64_t)((t * w->len) >> 32);
}

/* Rows y1..y2 of column x from texture p's column col, texel row 0 at
 * height tm above the eye, iscale (16.16 map units per pixel). */
static void r_wall_part(struct r_ctx *r, int x, int y1, int y2, const struct tex_pic *p,
			int64_t u, int64_t tm, int64_t iscale, const uint8_t *cm)
{
	int64_t hf, v;

	if (y2 < y1)
		return;
	hf = (int64_t)p->h << 16;
	/* texel row at y1's centre; |2y + 1 - cy2| < 2^14, iscale < 2^35 */
	v = (tm + (((int64_t)(2 * y1 + 1 - r->cy2) * iscale) >> 1)) % hf;
	if (v < 0)
		v += hf;
	r_rec_col(r, x, y1, y2, p->px + (size_t)r_tex_col(u, p->w) * (size_t)p->h, p->h, cm,
		   (uint32_t)v, (uint32_t)(iscale % hf));
}

/* Rows y1..y2 of a wall part lit through light-map column lc of grid g
 * (lmap.h): texel row k covers heights [g->y0 + k T, g->y0 + (k + 1) T),
 * T = 1 << g->shift; each band of rows is drawn with colormap level
 * max(0, lvl - lc[k]). Bands go top down; row of a height: r_edge_row. */
static void r_wall_lit(struct r_ctx *r, int x, int y1, int y2, const struct tex_pic *p,
		       int64_t u, int64_t tm, int64_t iscale, int lvl, int64_t s16,
		       const struct lmap_grid *g, const uint8_t *lc)
{
	int y = y1;

	for (int k = g->h - 1; k >= 0 && y <= y2; k--) {
		/* first row at or below the band's bottom edge; the lowest band
		 * takes every row left */
		int end = k == 0 ? y2 + 1 :
			r_edge_row(r, ((int64_t)g->y0 + ((int64_t)k << g->shift)) * FX_ONE - r->ez,
				   s16, y, y2 + 1);
		int l = lvl - lc[k];

		if (end > y) {
			r_wall_part(r, x, y, end - 1, p, u, tm, iscale, r->cmap[l < 0 ? 0 : l]);
			y = end;
		}
	}
}

/* Plane rows y1..y2 of column x into visplane p, or black when there is
 * none (seen from behind, or out of memory). */
static void r_plane_rows(struct r_ctx *r, int p, int x, int y1, int y2)
{
	if (y2 < y1)
		return;
	if (p < 0) {
		r->id = r_id(R_IDK_BACK, r->front);
		r_rec_fill(r, x, y1, y2, r->black);
		return;
	}
	r->planes[p].top[x] = (uint16_t)y1;
	r->planes[p].bot[x] = (uint16_t)y2;
}

/* A wall part: lit by the light-map column lc when there is one. */
static void r_part(struct r_ctx *r, const struct r_wall *w, int x, int y1, int y2,
		   const struct tex_pic *p, int64_t u, int64_t tm, int64_t iscale, int lvl,
		   int64_t s16, const uint8_t *lc)
{
	if (lc)
		r_wall_lit(r, x, y1, y2, p, u, tm, iscale, lvl, s16, w->lg, lc);
	else
		r_wall_part(r, x, y1, y2, p, u, tm, iscale, r->cmap[lvl]);
}

/* Column x. mc: where to store its masked texture column, or NULL. */
static void r_column(struct r_ctx *r, const struct r_wall *w, int x, int16_t *mc)
{
	int64_t s = w->s0 + w->step * (x - w->x1);
	int64_t s16, iscale = 0, u = 0;
	int top = r->ceilclip[x] + 1, bot = r->floorclip[x] - 1;
	int a, b, m, k, newtop, newbot, markc, markf, lvl;
	const uint8_t *lc = NULL;

	if (top > bot) {
		if (mc)
			*mc = R_MASK_DONE;
		return;
	}
	if (s < w->smin)
		s = w->smin;
	if (s > w->smax)
		s = w->smax;
	s16 = s >> 16;
	lvl = r_scale_level(r, w->wall_base, s);
	r->st.columns++;
	if (w->need_u) {
		int64_t u16 = r_wall_u16(r, w, x);

		u = u16 >> FX_SHIFT;
		/* s >= 2^14 (depth < 2^33): iscale < 2^34 */
		iscale = ((int64_t)1 << 48) / s;
		/* light maps run along the side from its start, offsets aside */
		if (w->lg)
			lc = lmap_grid_column(w->lg, (fx_t)(u16 - w->xoff));
	}

	/* rows [top, a - 1] ceiling, [a, b] middle, [b + 1, bot] floor */
	a = r_edge_row(r, w->hfc, s16, top, bot + 1);
	b = r_edge_row(r, w->hff, s16, a, bot + 1) - 1;
	/* a plane seen from behind is black from the nearest seg on, marks or
	 * not */
	markc = w->markceil || r->ceilplane < 0;
	markf = w->markfloor || r->floorplane < 0;
	if (markc)
		r_plane_rows(r, r->ceilplane, x, top, a - 1);
	if (markf)
		r_plane_rows(r, r->floorplane, x, b + 1, bot);
	if (!w->two_sided) {
		r->id = r_id(R_IDK_MIDDLE, w->lside);
		if (w->mid)
			r_part(r, w, x, a, b, w->mid, u, w->tm_mid, iscale, lvl, s16, lc);
		else
			r_rec_fill(r, x, a, b, r->black);
		r->ceilclip[x] = (int16_t)r->h;
		r->floorclip[x] = -1;
		return;
	}
	/* upper part [a, m], lower part [k, b], opening between them */
	newtop = markc ? a - 1 : top - 1;
	newbot = markf ? b + 1 : bot + 1;
	m = a - 1;
	if (w->upper) {
		m = r_edge_row(r, w->hbc, s16, a, b + 1) - 1;
		if (w->top) {
			r->id = r_id(R_IDK_UPPER, w->lside);
			r_part(r, w, x, a, m, w->top, u, w->tm_top, iscale, lvl, s16, lc);
			newtop = m;
		}
	}
	k = b + 1;
	if (w->lower) {
		k = r_edge_row(r, w->hbf, s16, m + 1, b + 1);
		if (w->bot) {
			r->id = r_id(R_IDK_LOWER, w->lside);
			r_part(r, w, x, k, b, w->bot, u, w->tm_bot, iscale, lvl, s16, lc);
			newbot = k;
		}
	}
	r->ceilclip[x] = (int16_t)newtop;
	r->floorclip[x] = (int16_t)newbot;
	if (mc)
		*mc = (int16_t)r_tex_col(u, w->masked->w);
}

/* Fills w with the seg's textures, pegging, plane marks and light. */
static void r_wall_surfaces(struct r_ctx *r, const struct map_seg *sg, struct r_wall *w)
{
	const struct map *m = r->map;
	const struct map_line *ln = &m->lines[sg->line];
	const struct map_side *sd = &m->sides[ln->side[sg->side]];
	const struct map_sector *fs = &m->sectors[r->front];
	const struct map_vertex *v1 = &m->vertices[ln->v1], *v2 = &m->vertices[ln->v2];
	const struct map_sector *bs;
	int light = fs->light;

	if (v1->y == v2->y)
		light += R_CONTRAST;
	else if (v1->x == v2->x)
		light -= R_CONTRAST;
	w->wall_base = r_light_base(light);
	w->lg = lmap_wall_grid(r->lm, sg->line, sg->side);
	w->lside = sg->line * 2 + sg->side;
	w->xoff = sd->xoff;
	w->hfc = (int64_t)fs->ceil_h - r->ez;
	w->hff = (int64_t)fs->floor_h - r->ez;
	w->two_sided = sg->back != MAP_NONE;
	w->mid = w->top = w->bot = w->masked = NULL;
	w->upper = w->lower = 0;
	w->hbc = w->hbf = w->tm_mid = w->tm_top = w->tm_bot = 0;
	if (!w->two_sided) {
		w->markceil = w->markfloor = 1;
		w->mid = r_wall_pic(r, sd->mid_tex);
		if (w->mid)
			w->tm_mid = ((ln->flags & ML_DONTPEGBOTTOM) ?
				     (int64_t)fs->floor_h + (int64_t)w->mid->h * FX_ONE - r->ez :
				     w->hfc) + sd->yoff;
		w->need_u = w->mid != NULL;
		return;
	}
	bs = &m->sectors[sg->back];
	w->hbc = (int64_t)bs->ceil_h - r->ez;
	w->hbf = (int64_t)bs->floor_h - r->ez;
	/* outdoor areas: the sky comes down to the lower sky ceiling */
	if (r_is_sky(r, fs->ceil_tex) && r_is_sky(r, bs->ceil_tex))
		w->hfc = w->hbc;
	w->upper = w->hbc < w->hfc;
	w->lower = w->hbf > w->hff;
	w->markfloor = w->hbf != w->hff || bs->floor_tex != fs->floor_tex || bs->light != fs->light;
	w->markceil = w->hbc != w->hfc || bs->ceil_tex != fs->ceil_tex || bs->light != fs->light;
	if (bs->ceil_h <= fs->floor_h || bs->floor_h >= fs->ceil_h)
		w->markceil = w->markfloor = 1;   /* closed door */
	/* planes of sectors with light maps are their own (r_plane_find) */
	if (lmap_flat_grid(r->lm, r->front, 0) != lmap_flat_grid(r->lm, sg->back, 0))
		w->markfloor = 1;
	if (lmap_flat_grid(r->lm, r->front, 1) != lmap_flat_grid(r->lm, sg->back, 1))
		w->markceil = 1;
	/* a missing upper or lower texture draws nothing: what lies behind
	 * shows, as in Doom */
	if (w->upper && (w->top = r_wall_pic(r, sd->top_tex)) != NULL)
		w->tm_top = ((ln->flags & ML_DONTPEGTOP) ?
			     w->hfc : w->hbc + (int64_t)w->top->h * FX_ONE) + sd->yoff;
	if (w->lower && (w->bot = r_wall_pic(r, sd->bot_tex)) != NULL)
		w->tm_bot = ((ln->flags & ML_DONTPEGBOTTOM) ? w->hfc : w->hbf) + sd->yoff;
	w->masked = r_wall_pic(r, sd->mid_tex);
	w->need_u = w->top || w->bot || w->masked;
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

/* A two-sided seg without a middle texture between sectors that look the
 * same changes nothing: the ceiling and floor beyond it are drawn,
 * identically, by the segs behind (Doom's rule). */
static int r_seg_invisible(const struct r_ctx *r, const struct map_seg *sg)
{
	const struct map *m = r->map;
	const struct map_sector *f, *b;

	if (sg->back == MAP_NONE)
		return 0;
	f = &m->sectors[r->front];
	b = &m->sectors[sg->back];
	return f->ceil_h == b->ceil_h && f->floor_h == b->floor_h &&
	       f->ceil_tex == b->ceil_tex && f->floor_tex == b->floor_tex &&
	       f->light == b->light && m->sides[m->lines[sg->line].side[sg->side]].mid_tex == 0 &&
	       lmap_flat_grid(r->lm, r->front, 0) == lmap_flat_grid(r->lm, sg->back, 0) &&
	       lmap_flat_grid(r->lm, r->front, 1) == lmap_flat_grid(r->lm, sg->back, 1);
}

int r_seg_front(const struct map *m, const struct map_seg *sg, fx_t x, fx_t y)
{
	const struct map_vertex *a = &m->vertices[sg->v1], *b = &m->vertices[sg->v2];
	/* front is to the right of v1 -> v2: cross((b - a), (p - a)) < 0.
	 * Differences < 2^31 (coordinates within MAP_COORD_MAX): exact. */
	int64_t cross = ((int64_t)b->x - a->x) * ((int64_t)y - a->y) -
			((int64_t)b->y - a->y) * ((int64_t)x - a->x);

	return cross < 0;
}

/* Projects the seg; 0 when it covers no column. */
static int r_wall_project(const struct r_ctx *r, const struct map_seg *sg, struct r_wall *w)
{
	const struct map *m = r->map;
	const struct map_vertex *a = &m->vertices[sg->v1], *b = &m->vertices[sg->v2];
	struct r_vpt p1, p2, A, B;
	int64_t sx1, sx2, s1, s2, xc, e1, e2, dmax;
	int64_t X1, X2;

	if (!r_seg_front(m, sg, r->ex, r->ey))
		return 0;
	r_to_view(r, a->x, a->y, &A);
	r_to_view(r, b->x, b->y, &B);
	p1 = A;
	p2 = B;
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

	/* the ray (X, w) (X = 2x + 1 - w half-pixels right per w half-pixels
	 * of depth) meets A + t (B - A) at t = cross(A, ray) / cross(A - B,
	 * ray), cross(p, q) = p.l q.d - p.d q.l; |A|, |B| < 2^32 and
	 * |X| <= w <= 2^12: every term below 2^46 */
	w->n0 = A.l * r->w;
	w->nx = -A.d;
	w->d0 = (A.l - B.l) * r->w;
	w->dx = -(A.d - B.d);
	X1 = 2 * (int64_t)w->x1 + 1 - r->w;
	X2 = 2 * (int64_t)w->x2 + 1 - r->w;
	e1 = w->d0 + w->dx * X1;
	e2 = w->d0 + w->dx * X2;
	if (e1 + e2 < 0) {
		w->n0 = -w->n0;
		w->nx = -w->nx;
		w->d0 = -w->d0;
		w->dx = -w->dx;
	}
	e1 = e1 < 0 ? -e1 : e1;
	e2 = e2 < 0 ? -e2 : e2;
	dmax = e1 > e2 ? e1 : e2;
	w->ushift = 0;
	while ((dmax >> w->ushift) >= ((int64_t)1 << 31))
		w->ushift++;
	w->u0 = (int64_t)sg->offset + m->sides[m->lines[sg->line].side[sg->side]].xoff;
	w->len = (uint64_t)fx_len(b->x - a->x, b->y - a->y);
	return 1;
}

/* Doom's silhouettes of a two-sided seg: which of its edges hide sprites
 * behind it, and from which heights. */
static void r_dseg_sil(const struct r_ctx *r, const struct map_seg *sg, struct r_dseg *ds)
{
	const struct map *m = r->map;
	const struct map_sector *fs = &m->sectors[r->front];
	const struct map_sector *bs;

	ds->sil = 0;
	ds->bsil = INT64_MAX;
	ds->tsil = INT64_MIN;
	ds->topclip = ds->botclip = R_CLIP_NONE;
	if (sg->back == MAP_NONE) {
		ds->sil = R_SIL_BOTTOM | R_SIL_TOP;
		ds->topclip = ds->botclip = R_CLIP_ALL;
		return;
	}
	bs = &m->sectors[sg->back];
	if (fs->floor_h > bs->floor_h) {
		ds->sil = R_SIL_BOTTOM;
		ds->bsil = fs->floor_h;
	} else if (bs->floor_h > r->ez) {
		ds->sil = R_SIL_BOTTOM;
	}
	if (fs->ceil_h < bs->ceil_h) {
		ds->sil |= R_SIL_TOP;
		ds->tsil = fs->ceil_h;
	} else if (bs->ceil_h < r->ez) {
		ds->sil |= R_SIL_TOP;
	}
	if (bs->ceil_h <= fs->floor_h) {
		ds->botclip = R_CLIP_ALL;
		ds->bsil = INT64_MAX;
		ds->sil |= R_SIL_BOTTOM;
	}
	if (bs->floor_h >= fs->ceil_h) {
		ds->topclip = R_CLIP_ALL;
		ds->tsil = INT64_MIN;
		ds->sil |= R_SIL_TOP;
	}
}

/* Saves clip[x1..x2] in the openings; the reference, or R_CLIP_NONE when
 * out of memory. */
static int32_t r_save_clip(struct r_ctx *r, const int16_t *clip, int x1, int x2)
{
	int32_t at = r_open_alloc(r, x2 - x1 + 1);

	if (at < 0)
		return R_CLIP_NONE;
	memcpy(&r->open[at], &clip[x1], (size_t)(x2 - x1 + 1) * sizeof(*clip));
	return at;
}

/* Draws columns x1..x2 of the seg (none of them solid yet): Doom's
 * R_StoreWallRange. */
static void r_store_range(struct r_ctx *r, const struct map_seg *sg, const struct r_wall *w,
			  int x1, int x2)
{
	struct r_dseg ds;
	int keep;
	int16_t *mc = NULL;

	if (w->markceil)
		r->ceilplane = r_plane_check(r, r->ceilplane, x1, x2);
	if (w->markfloor)
		r->floorplane = r_plane_check(r, r->floorplane, x1, x2);
	r_dseg_sil(r, sg, &ds);
	keep = ds.sil || w->masked;
	ds.maskcol = R_CLIP_NONE;
	if (w->masked) {
		ds.maskcol = r_open_alloc(r, x2 - x1 + 1);
		if (ds.maskcol >= 0)
			mc = &r->open[ds.maskcol];
	}
	for (int x = x1; x <= x2; x++)
		r_column(r, w, x, mc ? &mc[x - x1] : NULL);
	if (!keep)
		return;
	if (r->ndsegs == r->maxdsegs &&
	    r_grow((void **)&r->dsegs, &r->maxdsegs, sizeof(*r->dsegs), r->ndsegs + 1) < 0) {
		/* sprites are not clipped by this range, its masked middle
		 * is not drawn */
		r->st.degraded++;
		return;
	}
	if (((ds.sil & R_SIL_TOP) || w->masked) && ds.topclip == R_CLIP_NONE)
		ds.topclip = r_save_clip(r, r->ceilclip, x1, x2);
	if (((ds.sil & R_SIL_BOTTOM) || w->masked) && ds.botclip == R_CLIP_NONE)
		ds.botclip = r_save_clip(r, r->floorclip, x1, x2);
	if (w->masked && (ds.topclip == R_CLIP_NONE || ds.botclip == R_CLIP_NONE))
		ds.maskcol = R_CLIP_NONE;
	if (w->masked && ds.maskcol != R_CLIP_NONE) {
		const struct map *m = r->map;
		const struct map_sector *fs = &m->sectors[r->front];
		const struct map_sector *bs = &m->sectors[sg->back];
		const struct map_side *sd = &m->sides[m->lines[sg->line].side[sg->side]];

		/* sprites behind it are clipped to the opening, as by both
		 * silhouettes */
		if (!(ds.sil & R_SIL_TOP))
			ds.tsil = INT64_MIN;
		if (!(ds.sil & R_SIL_BOTTOM))
			ds.bsil = INT64_MAX;
		ds.sil = R_SIL_BOTTOM | R_SIL_TOP;
		ds.mid = w->masked;
		/* Doom: hung from the lower ceiling, or standing on the
		 * higher floor when lower-unpegged */
		if (m->lines[sg->line].flags & ML_DONTPEGBOTTOM)
			ds.mid_tmid = (fs->floor_h > bs->floor_h ? (int64_t)fs->floor_h :
				       (int64_t)bs->floor_h) + (int64_t)w->masked->h * FX_ONE;
		else
			ds.mid_tmid = fs->ceil_h < bs->ceil_h ? fs->ceil_h : bs->ceil_h;
		ds.mid_tmid += sd->yoff - (int64_t)r->ez;
		ds.light_base = w->wall_base;
	}
	ds.x1 = x1;
	ds.x2 = x2;
	ds.seg = (uint32_t)(sg - r->map->segs);
	ds.sx = w->x1;
	ds.s0 = w->s0;
	ds.step = w->step;
	ds.smin = w->smin;
	ds.smax = w->smax;
	{
		int64_t a = w->s0 + w->step * (x1 - w->x1), b = w->s0 + w->step * (x2 - w->x1);

		a = a < w->smin ? w->smin : a > w->smax ? w->smax : a;
		b = b < w->smin ? w->smin : b > w->smax ? w->smax : b;
		ds.lo = a < b ? a : b;
		ds.hi = a < b ? b : a;
	}
	r->dsegs[r->ndsegs++] = ds;
}

void r_seg_add(struct r_ctx *r, const struct map_seg *sg)
{
	const struct r_range *s = r->solid;
	struct r_wall w;
	int x, i, run;

	if (!r_seg_valid(r->map, sg) || r_seg_invisible(r, sg) || !r_wall_project(r, sg, &w))
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
		r_store_range(r, sg, &w, x, end);
		x = end + 1;
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
