/*
 * map: allocation, validation, content hash and BSP point location of the
 * level model.
 */
#include "engine/map/map.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/hash.h"
#include "engine/core/msg.h"
#include "engine/map/nb.h"

/* Starts err with "<what> <index>: " and returns -EINVAL, for the messages
 * that name the bad entry. */
static int map_bad(char *err, size_t errlen, const char *what, uint32_t i)
{
	if (err && errlen)
		err[0] = '\0';
	msg_cat(err, errlen, what);
	msg_cat(err, errlen, " ");
	msg_int(err, errlen, i);
	msg_cat(err, errlen, ": ");
	return -EINVAL;
}

/* "<field> <value> out of range (<count> <things>)" */
static int map_range(char *err, size_t errlen, const char *field, uint32_t v, uint32_t count,
		     const char *things)
{
	msg_cat(err, errlen, field);
	msg_cat(err, errlen, " ");
	msg_int(err, errlen, v);
	msg_cat(err, errlen, " out of range (");
	msg_int(err, errlen, count);
	msg_cat(err, errlen, " ");
	msg_cat(err, errlen, things);
	msg_cat(err, errlen, ")");
	return -EINVAL;
}

static int map_in_range(int64_t x, int64_t y)
{
	return x >= -MAP_COORD_MAX && x <= MAP_COORD_MAX && y >= -MAP_COORD_MAX &&
	       y <= MAP_COORD_MAX;
}

int map_alloc(struct map **out, uint32_t vertices, uint32_t sectors, uint32_t sides,
	      uint32_t lines, uint32_t things)
{
	struct map *m = calloc(1, sizeof *m);

	*out = NULL;
	if (!m)
		return -ENOMEM;
	/* calloc(n ? n : 1) so that an empty array is still a valid pointer */
	m->vertices = calloc(vertices ? vertices : 1, sizeof *m->vertices);
	m->sectors = calloc(sectors ? sectors : 1, sizeof *m->sectors);
	m->sides = calloc(sides ? sides : 1, sizeof *m->sides);
	m->lines = calloc(lines ? lines : 1, sizeof *m->lines);
	m->things = calloc(things ? things : 1, sizeof *m->things);
	if (!m->vertices || !m->sectors || !m->sides || !m->lines || !m->things)
		goto fail;
	m->num_vertices = vertices;
	m->num_sectors = sectors;
	m->num_sides = sides;
	m->num_lines = lines;
	m->num_things = things;
	*out = m;
	return 0;
fail:
	map_free(m);
	return -ENOMEM;
}

void map_free(struct map *m)
{
	if (!m)
		return;
	free(m->vertices);
	free(m->sectors);
	free(m->sides);
	free(m->lines);
	free(m->segs);
	free(m->subsectors);
	free(m->nodes);
	free(m->things);
	free(m->sec_first);
	free(m->sec_lines);
	free(m->thing_sec);
	free(m->spec_lines);
	free(m->tex_h);
	free(m);
}

static int map_check_level(const struct map *m, char *err, size_t errlen)
{
	uint32_t i;

	if (m->num_sectors == 0 || m->num_lines == 0) {
		msg_cat(err, errlen, "map has no sectors or no lines");
		return -EINVAL;
	}
	for (i = 0; i < m->num_vertices; i++) {
		const struct map_vertex *v = &m->vertices[i];
		if (!map_in_range(v->x, v->y)) {
			map_bad(err, errlen, "vertex", i);
			msg_cat(err, errlen, "coordinates out of range (+/-16384 units)");
			return -EINVAL;
		}
	}
	for (i = 0; i < m->num_sectors; i++) {
		const struct map_sector *s = &m->sectors[i];
		if (s->floor_h < -MAP_HEIGHT_MAX || s->floor_h > MAP_HEIGHT_MAX ||
		    s->ceil_h < -MAP_HEIGHT_MAX || s->ceil_h > MAP_HEIGHT_MAX) {
			map_bad(err, errlen, "sector", i);
			msg_cat(err, errlen, "floor ");
			msg_fx(err, errlen, s->floor_h);
			msg_cat(err, errlen, " or ceiling ");
			msg_fx(err, errlen, s->ceil_h);
			msg_cat(err, errlen, " out of range (+/-16383 units)");
			return -EINVAL;
		}
		if (s->ceil_h < s->floor_h) {
			map_bad(err, errlen, "sector", i);
			msg_cat(err, errlen, "ceiling ");
			msg_fx(err, errlen, s->ceil_h);
			msg_cat(err, errlen, " below floor ");
			msg_fx(err, errlen, s->floor_h);
			return -EINVAL;
		}
	}
	for (i = 0; i < m->num_sides; i++) {
		if (m->sides[i].sector >= m->num_sectors) {
			map_bad(err, errlen, "side", i);
			return map_range(err, errlen, "sector", m->sides[i].sector, m->num_sectors,
					 "sectors");
		}
	}
	for (i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		int two = (l->flags & ML_TWOSIDED) != 0;
		if (l->v1 >= m->num_vertices) {
			map_bad(err, errlen, "line", i);
			return map_range(err, errlen, "v1", l->v1, m->num_vertices, "vertices");
		}
		if (l->v2 >= m->num_vertices) {
			map_bad(err, errlen, "line", i);
			return map_range(err, errlen, "v2", l->v2, m->num_vertices, "vertices");
		}
		if (m->vertices[l->v1].x == m->vertices[l->v2].x &&
		    m->vertices[l->v1].y == m->vertices[l->v2].y) {
			map_bad(err, errlen, "line", i);
			msg_cat(err, errlen, "zero length");
			return -EINVAL;
		}
		if (l->side[0] >= m->num_sides) {
			map_bad(err, errlen, "line", i);
			return map_range(err, errlen, "side[0]", l->side[0], m->num_sides, "sides");
		}
		if (l->side[1] != MAP_NONE && l->side[1] >= m->num_sides) {
			map_bad(err, errlen, "line", i);
			return map_range(err, errlen, "side[1]", l->side[1], m->num_sides, "sides");
		}
		if (two != (l->side[1] != MAP_NONE)) {
			map_bad(err, errlen, "line", i);
			msg_cat(err, errlen, two ? "two-sided flag set but no side[1]"
						 : "side[1] present but two-sided flag not set");
			return -EINVAL;
		}
	}
	for (i = 0; i < m->num_things; i++) {
		if (!map_in_range(m->things[i].x, m->things[i].y)) {
			map_bad(err, errlen, "thing", i);
			msg_cat(err, errlen, "position out of range (+/-16384 units)");
			return -EINVAL;
		}
	}
	return 0;
}

/* The sector a seg's side faces, and the one behind it. */
static uint32_t map_side_sector(const struct map *m, const struct map_line *l, unsigned side)
{
	return l->side[side] == MAP_NONE ? MAP_NONE : m->sides[l->side[side]].sector;
}

static int map_check_segs(const struct map *m, char *err, size_t errlen)
{
	uint32_t i;

	for (i = 0; i < m->num_segs; i++) {
		const struct map_seg *s = &m->segs[i];
		const struct map_line *l;
		if (s->v1 >= m->num_vertices || s->v2 >= m->num_vertices) {
			map_bad(err, errlen, "seg", i);
			return map_range(err, errlen, "vertex", s->v1 >= m->num_vertices ? s->v1 : s->v2,
					 m->num_vertices, "vertices");
		}
		if (s->line >= m->num_lines) {
			map_bad(err, errlen, "seg", i);
			return map_range(err, errlen, "line", s->line, m->num_lines, "lines");
		}
		l = &m->lines[s->line];
		if (s->side > 1 || l->side[s->side] == MAP_NONE) {
			map_bad(err, errlen, "seg", i);
			msg_cat(err, errlen, "side of a line that has none");
			return -EINVAL;
		}
		if (s->front != map_side_sector(m, l, s->side) ||
		    s->back != map_side_sector(m, l, s->side ^ 1u)) {
			map_bad(err, errlen, "seg", i);
			msg_cat(err, errlen, "front/back sectors differ from its line's sides");
			return -EINVAL;
		}
	}
	return 0;
}

/* The nodes reached from the root must form a tree: a node or subsector
 * reached twice makes every walk that visits both parents' sides
 * exponential in the number of such nodes (a 66 KB file held 2^1200
 * paths). One walk with an explicit stack, each child checked when first
 * reached; children come before parents (checked above), so it ends.
 * Nodes no path reaches are left alone. */
static int map_check_tree(const struct map *m, char *err, size_t errlen)
{
	uint8_t *seen;
	uint32_t *stack, top = 0;
	int r = 0;

	if (m->num_nodes == 0)
		return 0;
	seen = calloc((size_t)m->num_nodes + m->num_subsectors, 1);
	stack = malloc((size_t)m->num_nodes * sizeof *stack);
	if (!seen || !stack) {
		free(seen);
		free(stack);
		return -ENOMEM;
	}
	stack[top++] = m->num_nodes - 1;
	seen[m->num_nodes - 1] = 1;
	while (top && !r) {
		uint32_t n = stack[--top];

		for (int c = 0; c < 2 && !r; c++) {
			uint32_t ch = m->nodes[n].child[c];
			int sub = (ch & MAP_NF_SUBSECTOR) != 0;
			size_t k = sub ? (size_t)m->num_nodes + (ch & ~MAP_NF_SUBSECTOR) : ch;

			if (seen[k]) {
				map_bad(err, errlen, "node", n);
				msg_cat(err, errlen, c ? "child[1] " : "child[0] ");
				msg_cat(err, errlen, sub ? "subsector " : "node ");
				msg_int(err, errlen, ch & ~MAP_NF_SUBSECTOR);
				msg_cat(err, errlen, " is reached a second time: the BSP is not a tree");
				r = -EINVAL;
				break;
			}
			seen[k] = 1;
			if (!sub)
				stack[top++] = ch;
		}
	}
	free(seen);
	free(stack);
	return r;
}

static int map_check_bsp(const struct map *m, char *err, size_t errlen)
{
	uint32_t i;
	int r = map_check_segs(m, err, errlen);

	if (r)
		return r;
	if (m->num_subsectors == 0 || (m->num_nodes == 0 && m->num_subsectors != 1)) {
		msg_cat(err, errlen, "BSP: a map needs nodes, or no nodes and exactly one subsector");
		return -EINVAL;
	}
	for (i = 0; i < m->num_subsectors; i++) {
		const struct map_subsector *ss = &m->subsectors[i];
		if (ss->num_segs == 0 ||
		    (uint64_t)ss->first_seg + ss->num_segs > m->num_segs) {
			map_bad(err, errlen, "subsector", i);
			msg_cat(err, errlen, "segs out of range");
			return -EINVAL;
		}
		if (ss->sector >= m->num_sectors) {
			map_bad(err, errlen, "subsector", i);
			return map_range(err, errlen, "sector", ss->sector, m->num_sectors, "sectors");
		}
	}
	for (i = 0; i < m->num_nodes; i++) {
		const struct map_node *n = &m->nodes[i];
		if (!map_in_range(n->x, n->y) ||
		    !map_in_range((int64_t)n->x + n->dx, (int64_t)n->y + n->dy) ||
		    (n->dx == 0 && n->dy == 0)) {
			map_bad(err, errlen, "node", i);
			msg_cat(err, errlen, "partition line empty or out of range");
			return -EINVAL;
		}
		for (int c = 0; c < 2; c++) {
			uint32_t ch = n->child[c];
			int bad = (ch & MAP_NF_SUBSECTOR) ? (ch & ~MAP_NF_SUBSECTOR) >= m->num_subsectors
							  : ch >= i;
			if (bad) {
				map_bad(err, errlen, "node", i);
				msg_cat(err, errlen, c ? "child[1] " : "child[0] ");
				msg_int(err, errlen, ch & ~MAP_NF_SUBSECTOR);
				msg_cat(err, errlen, (ch & MAP_NF_SUBSECTOR)
					? " is not a subsector"
					: " is not a node listed before it (children come first)");
				return -EINVAL;
			}
		}
	}
	return map_check_tree(m, err, errlen);
}

/* FNV-1a over the level as given: counts, then every field of every vertex,
 * sector, side, line and thing, in that order. Not the name, not the BSP
 * (derived data). Computed before the node builder appends split vertices. */
static uint64_t map_content_hash(const struct map *m)
{
	uint64_t h = HASH_INIT;
	uint32_t i;

	h = hash_u32(h, m->num_vertices);
	h = hash_u32(h, m->num_sectors);
	h = hash_u32(h, m->num_sides);
	h = hash_u32(h, m->num_lines);
	h = hash_u32(h, m->num_things);
	for (i = 0; i < m->num_vertices; i++) {
		h = hash_i32(h, m->vertices[i].x);
		h = hash_i32(h, m->vertices[i].y);
	}
	for (i = 0; i < m->num_sectors; i++) {
		const struct map_sector *s = &m->sectors[i];
		h = hash_i32(h, s->floor_h);
		h = hash_i32(h, s->ceil_h);
		h = hash_u16(h, s->floor_tex);
		h = hash_u16(h, s->ceil_tex);
		h = hash_u8(h, s->light);
		h = hash_u16(h, s->special);
		h = hash_u16(h, s->tag);
	}
	for (i = 0; i < m->num_sides; i++) {
		const struct map_side *s = &m->sides[i];
		h = hash_i32(h, s->xoff);
		h = hash_i32(h, s->yoff);
		h = hash_u16(h, s->top_tex);
		h = hash_u16(h, s->mid_tex);
		h = hash_u16(h, s->bot_tex);
		h = hash_u32(h, s->sector);
	}
	for (i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		h = hash_u32(h, l->v1);
		h = hash_u32(h, l->v2);
		h = hash_u16(h, l->flags);
		h = hash_u16(h, l->special);
		h = hash_u16(h, l->tag);
		h = hash_u32(h, l->side[0]);
		h = hash_u32(h, l->side[1]);
	}
	for (i = 0; i < m->num_things; i++) {
		const struct map_thing *t = &m->things[i];
		h = hash_i32(h, t->x);
		h = hash_i32(h, t->y);
		h = hash_u32(h, t->angle);
		h = hash_u16(h, t->type);
		h = hash_u16(h, t->flags);
	}
	return h;
}

/* Each sector's bordering lines (map.h: sec_first, sec_lines), counted
 * then filled in line order. 0 or -ENOMEM. */
static int map_sector_index(struct map *m)
{
	uint32_t *first, *lines, *spec, i, total = 0, nspec = 0;

	free(m->sec_first);
	free(m->sec_lines);
	free(m->spec_lines);
	m->sec_first = m->sec_lines = m->spec_lines = NULL;
	m->num_spec_lines = 0;
	first = calloc((size_t)m->num_sectors + 1, sizeof(*first));
	if (!first)
		return -ENOMEM;
	for (i = 0; i < m->num_lines; i++) {
		uint32_t a = map_side_sector(m, &m->lines[i], 0);
		uint32_t b = map_side_sector(m, &m->lines[i], 1);
		first[a + 1]++;
		if (b != MAP_NONE && b != a)
			first[b + 1]++;
	}
	for (i = 0; i < m->num_sectors; i++) {
		total += first[i + 1];
		first[i + 1] = total;
	}
	lines = calloc(total ? total : 1, sizeof(*lines));
	if (!lines) {
		free(first);
		return -ENOMEM;
	}
	/* first[s] counts up while sector s is filled, then is put back */
	for (i = 0; i < m->num_lines; i++) {
		uint32_t a = map_side_sector(m, &m->lines[i], 0);
		uint32_t b = map_side_sector(m, &m->lines[i], 1);
		lines[first[a]++] = i;
		if (b != MAP_NONE && b != a)
			lines[first[b]++] = i;
	}
	for (i = m->num_sectors; i > 0; i--)
		first[i] = first[i - 1];
	first[0] = 0;
	for (i = 0; i < m->num_lines; i++)
		nspec += m->lines[i].special != 0;
	spec = calloc(nspec ? nspec : 1, sizeof(*spec));
	if (!spec) {
		free(first);
		free(lines);
		return -ENOMEM;
	}
	for (i = 0, nspec = 0; i < m->num_lines; i++)
		if (m->lines[i].special)
			spec[nspec++] = i;
	m->sec_first = first;
	m->sec_lines = lines;
	m->spec_lines = spec;
	m->num_spec_lines = nspec;
	return 0;
}

/* thing_sec: each thing's sector, by the BSP (checked by then). 0 or
 * -ENOMEM. */
static int map_thing_sectors(struct map *m)
{
	free(m->thing_sec);
	m->num_thing_sec = 0;
	m->thing_sec = malloc(((size_t)m->num_things + 1) * sizeof(*m->thing_sec));
	if (!m->thing_sec)
		return -ENOMEM;
	for (uint32_t i = 0; i < m->num_things; i++)
		m->thing_sec[i] = map_point_sector(m, m->things[i].x, m->things[i].y);
	m->num_thing_sec = m->num_things;
	return 0;
}

int map_finish(struct map *m, char *err, size_t errlen)
{
	return map_finish_lim(m, NULL, err, errlen);
}

int map_finish_lim(struct map *m, const struct lim_stop *stop, char *err, size_t errlen)
{
	int r;

	if (err && errlen)
		err[0] = '\0';
	r = map_check_level(m, err, errlen);
	if (r)
		return r;
	m->content_hash = map_content_hash(m);
	if (m->num_nodes == 0 && m->num_subsectors == 0) {
		r = nb_build(m, stop, err, errlen);
		if (r)
			return r;
	}
	r = map_check_bsp(m, err, errlen);
	if (r == 0 && (map_sector_index(m) < 0 || map_thing_sectors(m) < 0)) {
		msg_cat(err, errlen, "out of memory");
		r = -ENOMEM;
	}
	return r;
}

static fx_t map_clamp(fx_t v)
{
	return v < -MAP_COORD_MAX ? -MAP_COORD_MAX : v > MAP_COORD_MAX ? MAP_COORD_MAX : v;
}

int map_point_on_side(fx_t x, fx_t y, const struct map_node *n)
{
	/* |x - n->x| < 2^31 and |dx| < 2^31 (map_finish), so each product is
	 * below 2^62 and the difference below 2^63. */
	int64_t px = (int64_t)map_clamp(x) - n->x;
	int64_t py = (int64_t)map_clamp(y) - n->y;
	int64_t c = (int64_t)n->dx * py - (int64_t)n->dy * px;

	return c > 0;
}

uint32_t map_point_subsector(const struct map *m, fx_t x, fx_t y)
{
	uint32_t n;

	if (m->num_nodes == 0)
		return 0;
	/* children are listed before their parents (map_finish checks), so the
	 * walk ends */
	n = m->num_nodes - 1;
	for (;;) {
		const struct map_node *nd = &m->nodes[n];
		uint32_t c = nd->child[map_point_on_side(x, y, nd)];
		if (c & MAP_NF_SUBSECTOR)
			return c & ~MAP_NF_SUBSECTOR;
		n = c;
	}
}
