/*
 * r_bsp: front-to-back BSP traversal and the solid-column list.
 *
 * From the root, each node sends the walk first into the child on the
 * eye's side, then into the other child only if that child's bounding box
 * reaches a column that is not yet fully occluded. Each subsector reached
 * looks up the visplanes of its sector's floor and ceiling, then its segs
 * go to r_seg_add in order, so every wall drawn is nearer than anything
 * drawn later in the same pixel. The walk stops once every column is
 * occluded.
 *
 * The solid list is Doom's solidsegs: sorted, disjoint, non-adjacent runs of
 * occluded columns with one sentinel run left of column 0 and one right of
 * column w - 1. Adjacent runs merge, so "the whole screen is solid" is "one
 * run is left".
 */
#include <assert.h>
#include <stdint.h>
#include <string.h>

#include "engine/map/map.h"
#include "engine/render/r_local.h"

#define R_SENTINEL 0x40000000

void r_solid_reset(struct r_ctx *r)
{
	r->solid[0].first = -R_SENTINEL;
	r->solid[0].last = -1;
	r->solid[1].first = r->w;
	r->solid[1].last = R_SENTINEL;
	r->nsolid = 2;
}

void r_solid_add(struct r_ctx *r, int x1, int x2)
{
	struct r_range *s = r->solid;
	int i = 0, j;

	assert(x1 >= 0 && x2 < r->w && x1 <= x2);
	/* first run touching [x1, x2] or after it; the right sentinel ends the
	 * scan */
	while (s[i].last < x1 - 1)
		i++;
	if (s[i].first > x2 + 1) {
		/* a new run before run i */
		assert(r->nsolid < r->maxsolid);
		memmove(&s[i + 1], &s[i], (size_t)(r->nsolid - i) * sizeof(*s));
		s[i].first = x1;
		s[i].last = x2;
		r->nsolid++;
		return;
	}
	/* merge runs i..j, all touching [x1, x2] */
	j = i;
	while (j + 1 < r->nsolid && s[j + 1].first <= x2 + 1)
		j++;
	if (x1 < s[i].first)
		s[i].first = x1;
	s[i].last = s[j].last > x2 ? s[j].last : x2;
	if (j > i) {
		memmove(&s[i + 1], &s[j + 1], (size_t)(r->nsolid - j - 1) * sizeof(*s));
		r->nsolid -= j - i;
	}
}

int r_solid_covers(const struct r_ctx *r, int x1, int x2)
{
	const struct r_range *s = r->solid;
	int i = 0;

	while (s[i].last < x1)
		i++;
	return s[i].first <= x1 && s[i].last >= x2;
}

/* 1 when some part of the bounding box bb that lies in the view (clipped to
 * the near plane and the frustum) projects onto a column not yet occluded;
 * conservative by one column on each side. The eye inside the box always
 * sees it. */
static int r_bbox_visible(struct r_ctx *r, const fx_t *bb)
{
	struct r_vpt v[R_POLY_MAX];
	int64_t lo, hi;
	int n, x1, x2;

	if (r->ex >= bb[BOX_LEFT] && r->ex <= bb[BOX_RIGHT] &&
	    r->ey >= bb[BOX_BOTTOM] && r->ey <= bb[BOX_TOP])
		return 1;
	r_to_view(r, bb[BOX_LEFT], bb[BOX_TOP], &v[0]);
	r_to_view(r, bb[BOX_RIGHT], bb[BOX_TOP], &v[1]);
	r_to_view(r, bb[BOX_RIGHT], bb[BOX_BOTTOM], &v[2]);
	r_to_view(r, bb[BOX_LEFT], bb[BOX_BOTTOM], &v[3]);
	n = r_clip_polygon(v, 4);
	if (n == 0)
		return 0;
	lo = hi = r_project_x(r, &v[0]);
	for (int i = 1; i < n; i++) {
		int64_t sx = r_project_x(r, &v[i]);
		if (sx < lo)
			lo = sx;
		if (sx > hi)
			hi = sx;
	}
	/* one column of margin on each side: the test only has to be
	 * conservative */
	x1 = (int)(lo >> FX_SHIFT) - 1;
	x2 = (int)(hi >> FX_SHIFT) + 1;
	if (x1 < 0)
		x1 = 0;
	if (x2 > r->w - 1)
		x2 = r->w - 1;
	return !r_solid_covers(r, x1, x2);
}

static void r_subsector(struct r_ctx *r, uint32_t i)
{
	const struct map *m = r->map;
	const struct map_subsector *ss;
	const struct map_sector *sec;
	uint32_t end;

	if (i >= m->num_subsectors)
		return;
	ss = &m->subsectors[i];
	r->st.subsectors++;
	end = ss->first_seg + ss->num_segs;
	if (ss->first_seg > m->num_segs || end > m->num_segs || end < ss->first_seg ||
	    ss->sector >= m->num_sectors)
		return;
	/* the subsector's planes, when seen from their visible side (the sky
	 * always is); its segs add columns to them */
	r->front = ss->sector;
	if (r->seen_ok)
		r->sec_seen[ss->sector] = r->frame_no;
	sec = &m->sectors[ss->sector];
	r->floorplane = sec->floor_h < r->ez ?
		r_plane_find(r, sec->floor_h, sec->floor_tex, sec->light,
			     lmap_flat_grid(r->lm, ss->sector, 0)) : -1;
	r->ceilplane = sec->ceil_h > r->ez || r_is_sky(r, sec->ceil_tex) ?
		r_plane_find(r, sec->ceil_h, sec->ceil_tex, sec->light,
			     lmap_flat_grid(r->lm, ss->sector, 1)) : -1;
	for (uint32_t k = ss->first_seg; k < end && r->nsolid > 1; k++)
		r_seg_add(r, &m->segs[k]);
}

/* child: a node index or MAP_NF_SUBSECTOR | subsector. limit: the parent's
 * index; map_finish lists children before parents, and refusing any other
 * child keeps the walk finite on any data. Depth is the tree's height. */
static void r_node(struct r_ctx *r, uint32_t child, uint32_t limit)
{
	const struct map_node *nd;
	int side;

	if (r->nsolid == 1)
		return;
	if (child & MAP_NF_SUBSECTOR) {
		r_subsector(r, child & ~MAP_NF_SUBSECTOR);
		return;
	}
	if (child >= limit)
		return;
	nd = &r->map->nodes[child];
	r->st.nodes++;
	side = map_point_on_side(r->ex, r->ey, nd);
	r_node(r, nd->child[side], child);
	if (r->nsolid > 1 && r_bbox_visible(r, nd->bbox[side ^ 1]))
		r_node(r, nd->child[side ^ 1], child);
}

void r_bsp_render(struct r_ctx *r)
{
	const struct map *m = r->map;

	/* Doom's convention: a map without nodes is subsector 0 */
	if (m->num_nodes == 0)
		r_subsector(r, 0);
	else
		r_node(r, m->num_nodes - 1, m->num_nodes);
}
