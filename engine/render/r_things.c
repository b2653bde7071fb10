/*
 * r_things: sprites and masked middle textures (Doom's r_things and
 * R_RenderMaskedSegRange), drawn after the opaque pass, back to front.
 *
 * Projection (Doom's R_ProjectSprite): only sprites standing in a sector
 * the BSP walk reached this frame are drawn (Doom adds the things of each
 * sector it reaches; a thing behind a closed door is never considered, so
 * silhouettes need not hide it). A sprite at depth below R_SPR_NEAR, or
 * more than four times its depth to the side, is skipped. The rotation
 * is Doom's: the angle from the eye to the thing minus the thing's facing,
 * in eighths of a turn centred on each direction (rotation 0 = facing the
 * viewer), and the frame says which picture and whether mirrored. The
 * picture's left offset puts its left edge at x - left (not mirrored by a
 * flip, as in Doom), its top offset puts its top at z + top. Its columns
 * are those whose centre lies within its projected width; texture column u
 * = (column centre - left edge) * depth / focal, one texel per map unit.
 * Light: the sector under the thing's position, faded by scale like a wall
 * (no fake contrast), or colormap 0 when full bright.
 *
 * Drawing (Doom's R_DrawMasked): sprites sorted by scale, farthest first
 * (ties: the caller's order). For each sprite, the drawsegs that overlap it
 * are walked nearest first: a drawseg behind the sprite (its largest scale
 * is smaller, or its smallest is and the sprite is on its front side) only
 * draws its masked middle in those columns now; one in front clips the
 * sprite with its saved clip arrays where its silhouette can hide the
 * sprite (bottom: unless the sprite is entirely above the silhouette
 * height; top: unless entirely below). Then the sprite's columns are drawn
 * between those clips, opaque texels only. Last, every masked middle not
 * yet drawn, farthest drawseg first. A masked middle is drawn once, between
 * the clips saved after its seg, not tiled vertically, lit like its wall.
 */
#include <stdint.h>
#include <stdlib.h>

#include "engine/core/tab.h"
#include "engine/render/r_local.h"

static fx_t r_clamp(fx_t v)
{
	return v > MAP_COORD_MAX ? MAP_COORD_MAX : v < -MAP_COORD_MAX ? -MAP_COORD_MAX : v;
}

/* Rows y1..y2 of column x, restricted to those where the picture column
 * (h texels, texel row 0 at height tm above the eye, iscale 16.16 texels
 * per pixel) exists: no wrapping. */
static void r_masked_col(const struct r_ctx *r, struct r_strip *s, int x, int y1, int y2,
			 const uint8_t *col, const uint8_t *op, int h, int64_t tm, int64_t iscale,
			 const uint8_t *cm, uint32_t id)
{
	int64_t hf = (int64_t)h << 16, v, last;

	if (y1 < 0)
		y1 = 0;
	if (y2 > r->h - 1)
		y2 = r->h - 1;
	if (y2 < y1)
		return;
	/* texel row at y1's centre; rows step by iscale exactly as drawn */
	v = tm + (((int64_t)(2 * y1 + 1 - r->cy2) * iscale) >> 1);
	if (v < 0) {
		int64_t n = (-v + iscale - 1) / iscale;

		if (n > y2 - y1)
			return;
		y1 += (int)n;
		v += n * iscale;
	}
	if (v >= hf)
		return;
	last = y1 + (hf - 1 - v) / iscale;
	if (last < y2)
		y2 = (int)last;
	/* more than one row only when iscale < hf < 2^31 */
	r_draw_masked(r, s, x, y1, y2, col, op, cm, (uint32_t)v,
		      (uint32_t)(y2 > y1 ? iscale : 0), id);
}

/* Clip value of a drawseg reference at column x; def for R_CLIP_ALL. */
static int r_clip_at(const struct r_ctx *r, const struct r_dseg *ds, int32_t ref, int x, int all)
{
	return ref == R_CLIP_ALL ? all : r->open[ref + x - ds->x1];
}

/* Doom's R_RenderMaskedSegRange: the masked middle of ds in columns
 * x1..x2 not yet drawn, within strip s. */
static void r_masked_range(struct r_ctx *r, struct r_strip *st, struct r_dseg *ds, int x1, int x2)
{
	const struct tex_pic *p = ds->mid;
	const struct map_seg *sg = &r->map->segs[ds->seg];
	uint32_t id = r_id(R_IDK_MASKED, sg->line * 2 + sg->side);

	if (x1 < st->x0)
		x1 = st->x0;
	if (x2 > st->x1)
		x2 = st->x1;
	for (int x = x1; x <= x2; x++) {
		int16_t *mc = &r->open[ds->maskcol + x - ds->x1];
		int64_t s = ds->s0 + ds->step * (x - ds->sx);
		size_t off;

		if (*mc == R_MASK_DONE)
			continue;
		s = s < ds->smin ? ds->smin : s > ds->smax ? ds->smax : s;
		off = (size_t)*mc * (size_t)p->h;
		r_masked_col(r, st, x, r_clip_at(r, ds, ds->topclip, x, r->h) + 1,
			     r_clip_at(r, ds, ds->botclip, x, -1) - 1, p->px + off,
			     p->opaque ? p->opaque + off : NULL, p->h, ds->mid_tmid,
			     ((int64_t)1 << 48) / s, r->cmap[r_scale_level(r, ds->light_base, s)], id);
		*mc = R_MASK_DONE;
	}
}

static int r_vis_cmp(const void *a, const void *b)
{
	const struct r_vis *va = a, *vb = b;

	if (va->scale != vb->scale)
		return va->scale < vb->scale ? -1 : 1;
	return va->order < vb->order ? -1 : va->order > vb->order;
}

void r_things_project(struct r_ctx *r, const struct r_sprite *spr, int nspr)
{
	const struct tex_set *t = r->tex;
	int64_t half = (int64_t)r->w << (FX_SHIFT - 1);

	for (int i = 0; i < nspr; i++) {
		const struct r_sprite *sp = &spr[i];
		fx_t gx = r_clamp(sp->x), gy = r_clamp(sp->y);
		const struct tex_pic *pic;
		struct r_vis *vs;
		struct r_vpt p;
		int64_t ll, sxl, sxr;
		uint32_t sec;
		int x1, x2, pi, flip;

		if (sp->mesh) {
			struct r_vis mv = { 0 };
			int rc;

			mv.gx = gx;
			mv.gy = gy;
			rc = r_mesh_project(r, sp, &mv);
			if (rc < 0)
				r->st.missing++;
			if (rc != 0)
				continue;
			sec = map_point_sector(r->map, gx, gy);
			if (r->seen_ok && r->sec_seen[sec] != r->frame_no)
				continue;
			if (r->nvis == r->maxvis &&
			    r_grow((void **)&r->vis, &r->maxvis, sizeof(*r->vis), r->nvis + 1) < 0) {
				r->st.degraded++;
				break;
			}
			mv.order = i;
			mv.lvl = (sp->flags & R_SPR_FULLBRIGHT) ? 0 :
				 r_scale_level(r, r_light_base(r->map->sectors[sec].light), mv.scale);
			r->vis[r->nvis++] = mv;
			continue;
		}
		r_to_view(r, gx, gy, &p);
		if (p.d < R_SPR_NEAR || p.l > 4 * p.d || p.l < -4 * p.d)
			continue;
		sec = map_point_sector(r->map, gx, gy);
		if (r->seen_ok && r->sec_seen[sec] != r->frame_no)
			continue;
		/* coordinates within MAP_COORD_MAX: differences fit fx_t */
		pi = tex_sprite_pic(t, sp->sprite, sp->frame,
				    tab_atan2(gy - r->ey, gx - r->ex) - sp->angle, &flip);
		if (pi < 0) {
			r->st.missing++;
			continue;
		}
		pic = &t->sprpics[pi];
		/* |l| <= 4d < 2^34, offsets < 2^31: |ll| < 2^35, half <= 2^27 */
		ll = p.l - (int64_t)pic->left * FX_ONE;
		sxl = half + ll * half / p.d;
		sxr = half + (ll + (int64_t)pic->w * FX_ONE) * half / p.d;
		x1 = r_col_at(sxl);
		x2 = r_col_at(sxr) - 1;
		if (x1 < 0)
			x1 = 0;
		if (x2 > r->w - 1)
			x2 = r->w - 1;
		if (x1 > x2)
			continue;
		if (r->nvis == r->maxvis &&
		    r_grow((void **)&r->vis, &r->maxvis, sizeof(*r->vis), r->nvis + 1) < 0) {
			r->st.degraded++;
			break;
		}
		vs = &r->vis[r->nvis++];
		vs->x1 = x1;
		vs->x2 = x2;
		vs->scale = ((int64_t)r->w << 47) / p.d;
		vs->gx = gx;
		vs->gy = gy;
		vs->gz = sp->z;
		vs->gzt = (int64_t)sp->z + (int64_t)pic->top * FX_ONE;
		vs->tmid = vs->gzt - r->ez;
		vs->sxl = sxl;
		vs->iscale = p.d * 2 / r->w;
		vs->pic = pic;
		vs->flip = flip;
		vs->order = i;
		vs->mesh = 0;
		vs->mp = NULL;
		vs->lvl = (sp->flags & R_SPR_FULLBRIGHT) ? 0 :
			  r_scale_level(r, r_light_base(r->map->sectors[sec].light), vs->scale);
	}
	if (r->nvis > 1)
		qsort(r->vis, (size_t)r->nvis, sizeof(*r->vis), r_vis_cmp);
}

/* Doom's R_DrawSprite, in columns vx1..vx2 (the sprite's inside strip
 * s). */
static void r_draw_vis(struct r_ctx *r, struct r_strip *s, const struct r_vis *vs, int vx1,
		       int vx2)
{
	int16_t *ct = r->cliptop, *cb = r->clipbot;
	const struct tex_pic *p = vs->pic;
	const uint8_t *cm = r->cmap[vs->lvl];

	for (int x = vx1; x <= vx2; x++)
		ct[x] = cb[x] = -2;
	for (int i = r->ndsegs - 1; i >= 0; i--) {
		struct r_dseg *ds = &r->dsegs[i];
		int x1, x2, sil;

		if (ds->x1 > vx2 || ds->x2 < vx1 || (!ds->sil && ds->maskcol == R_CLIP_NONE))
			continue;
		x1 = ds->x1 > vx1 ? ds->x1 : vx1;
		x2 = ds->x2 < vx2 ? ds->x2 : vx2;
		if (ds->hi < vs->scale ||
		    (ds->lo < vs->scale && r_seg_front(r->map, &r->map->segs[ds->seg], vs->gx, vs->gy))) {
			/* behind the sprite */
			if (ds->maskcol != R_CLIP_NONE)
				r_masked_range(r, s, ds, x1, x2);
			continue;
		}
		sil = ds->sil;
		if (vs->gz >= ds->bsil)
			sil &= ~R_SIL_BOTTOM;
		if (vs->gzt <= ds->tsil)
			sil &= ~R_SIL_TOP;
		if ((sil & R_SIL_BOTTOM) && ds->botclip != R_CLIP_NONE)
			for (int x = x1; x <= x2; x++)
				if (cb[x] == -2)
					cb[x] = (int16_t)r_clip_at(r, ds, ds->botclip, x, -1);
		if ((sil & R_SIL_TOP) && ds->topclip != R_CLIP_NONE)
			for (int x = x1; x <= x2; x++)
				if (ct[x] == -2)
					ct[x] = (int16_t)r_clip_at(r, ds, ds->topclip, x, r->h);
	}
	for (int x = vx1; x <= vx2; x++) {
		if (cb[x] == -2)
			cb[x] = (int16_t)r->h;
		if (ct[x] == -2)
			ct[x] = -1;
	}
	if (vs->mesh) {
		r_mesh_draw(r, s, vs, vx1, vx2, ct, cb);
		return;
	}
	for (int x = vx1; x <= vx2; x++) {
		/* (column centre - left edge) < 2^31 and u within the picture:
		 * the product is below 2^47 */
		int64_t u = (((int64_t)x * FX_ONE + FX_HALF - vs->sxl) * vs->iscale) >> 32;
		size_t off;

		if (u < 0)
			u = 0;
		if (u > p->w - 1)
			u = p->w - 1;
		if (vs->flip)
			u = p->w - 1 - u;
		off = (size_t)u * (size_t)p->h;
		r_masked_col(r, s, x, ct[x] + 1, cb[x] - 1,
			     p->px + off, p->opaque ? p->opaque + off : NULL, p->h, vs->tmid,
			     vs->iscale, cm, r_id(R_IDK_SPRITE, (uint32_t)vs->order));
	}
}

void r_things_draw(struct r_ctx *r, struct r_strip *s)
{
	for (int i = 0; i < r->nvis; i++) {
		const struct r_vis *vs = &r->vis[i];
		int x1 = vs->x1 > s->x0 ? vs->x1 : s->x0, x2 = vs->x2 < s->x1 ? vs->x2 : s->x1;

		if (x1 <= x2)
			r_draw_vis(r, s, vs, x1, x2);
	}
	for (int i = r->ndsegs - 1; i >= 0; i--) {
		struct r_dseg *ds = &r->dsegs[i];

		if (ds->maskcol != R_CLIP_NONE && ds->x1 <= s->x1 && ds->x2 >= s->x0)
			r_masked_range(r, s, ds, ds->x1, ds->x2);
	}
}
