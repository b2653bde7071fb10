/*
 * map_wad: Doom (vanilla) binary map lumps into struct map.
 *
 * Records (little-endian):
 *   THINGS 10: x, y, angle (degrees), type, flags
 *   LINEDEFS 14: v1, v2, flags, special, tag, front sidedef, back sidedef
 *   SIDEDEFS 30: xoff, yoff, upper[8], lower[8], middle[8], sector
 *   VERTEXES 4: x, y
 *   SEGS 12: v1, v2, angle (BAM >> 16), linedef, direction, offset
 *   SSECTORS 4: seg count, first seg
 *   NODES 28: x, y, dx, dy, right bbox[4], left bbox[4], right, left child
 *   SECTORS 26: floor, ceiling, floor flat[8], ceiling flat[8], light,
 *               special, tag
 * Indices are unsigned 16-bit (0xFFFF: no sidedef); a node child with bit
 * 0x8000 is a subsector. Every index is checked here, with the lump and
 * entry in the message, before map_finish checks the model again.
 *
 * Two things Doom accepts are normalised rather than refused, both as Doom
 * itself behaves: a linedef's two-sided flag follows whether it has a back
 * sidedef (Doom's renderer and collision look at the back sector, not the
 * flag), and a sector whose ceiling is below its floor (closed lifts and
 * doors in Freedoom) gets its floor lowered to its ceiling: Doom draws the
 * neighbours' upper texture down to that ceiling first, so the walls look
 * the same. A thing beyond MAP_COORD_MAX (outside any loadable map) is
 * left out.
 *
 * Bounds (issue 13 item 8): a lump the loader reads holds at most
 * MW_MAX_RECORDS records (Doom's 16-bit indices reach no further), heights
 * stay within MAP_HEIGHT_MAX, and the node builder has its own limits
 * (nb.h). A limit's message names the file as well as the map and lump.
 */
#include "engine/map/map_wad.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/le.h"
#include "engine/core/lim.h"
#include "engine/core/msg.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"

enum {
	MW_THINGS, MW_LINEDEFS, MW_SIDEDEFS, MW_VERTEXES, MW_SEGS, MW_SSECTORS, MW_NODES,
	MW_SECTORS, MW_REJECT, MW_BLOCKMAP, MW_BEHAVIOR, MW_LUMPS
};

static const char mw_names[MW_LUMPS][9] = {
	"THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS", "NODES",
	"SECTORS", "REJECT", "BLOCKMAP", "BEHAVIOR",
};

static const size_t mw_size[MW_LUMPS] = { 10, 14, 30, 4, 12, 4, 28, 26, 1, 1, 1 };

struct mw {
	const char *map;               /* upper-case name, for messages */
	const char *file;              /* the file of the marker, for messages */
	const struct lim_stop *stop;   /* passed to the node builder */
	const uint8_t *p[MW_LUMPS];
	uint32_t n[MW_LUMPS];          /* records */
	int have[MW_LUMPS];
	const struct tex_set *t;
	struct map *m;
	char *err;
	size_t errlen;
};

/* Index of the map lump (0..MW_LUMPS-1) called name, or -1. */
static int mw_lump(const char *name)
{
	for (int k = 0; k < MW_LUMPS; k++)
		if (strcmp(name, mw_names[k]) == 0)
			return k;
	return -1;
}

/* A map marker: a lump followed, in the same file, by THINGS (Doom and
 * Hexen format) or TEXTMAP (UDMF, refused later with a message). */
static int mw_is_marker(const struct wad *w, int i)
{
	const char *next = wad_name(w, i + 1);

	return i + 1 < wad_count(w) && wad_file(w, i) == wad_file(w, i + 1) &&
	       (strcmp(next, "THINGS") == 0 || strcmp(next, "TEXTMAP") == 0);
}

static void mw_start(struct mw *c)
{
	if (c->err && c->errlen)
		c->err[0] = '\0';
	msg_cat(c->err, c->errlen, c->map);
	msg_cat(c->err, c->errlen, ": ");
}

/* "<file>: <map>: ", for the limits' messages */
static void mw_start_file(struct mw *c)
{
	if (c->err && c->errlen)
		c->err[0] = '\0';
	msg_cat(c->err, c->errlen, c->file);
	msg_cat(c->err, c->errlen, ": ");
	msg_cat(c->err, c->errlen, c->map);
	msg_cat(c->err, c->errlen, ": ");
}

/* "<map>: <LUMP> entry <i>: " */
static void mw_entry(struct mw *c, int lump, uint32_t i)
{
	mw_start(c);
	msg_cat(c->err, c->errlen, mw_names[lump]);
	msg_cat(c->err, c->errlen, " entry ");
	msg_int(c->err, c->errlen, i);
	msg_cat(c->err, c->errlen, ": ");
}

/* "<map>: <LUMP> entry <i>: <field> <v> out of range (<count> <what>)" */
static int mw_range(struct mw *c, int lump, uint32_t i, const char *field, uint32_t v,
		    uint32_t count, const char *what)
{
	mw_entry(c, lump, i);
	msg_cat(c->err, c->errlen, field);
	msg_cat(c->err, c->errlen, " ");
	msg_int(c->err, c->errlen, v);
	msg_cat(c->err, c->errlen, " out of range (");
	msg_int(c->err, c->errlen, count);
	msg_cat(c->err, c->errlen, " ");
	msg_cat(c->err, c->errlen, what);
	msg_cat(c->err, c->errlen, ")");
	return -EINVAL;
}

/* Collects the lumps after the marker at index i, up to the first lump
 * that is not a map lump. */
static int mw_collect(struct mw *c, const struct wad *w, int i)
{
	for (int k = i + 1; k < wad_count(w) && wad_file(w, k) == wad_file(w, i); k++) {
		int l = mw_lump(wad_name(w, k));
		size_t len;
		const uint8_t *d = wad_data(w, k, &len);

		if (l < 0)
			break;
		if (c->have[l])
			continue;
		if (len % mw_size[l]) {
			mw_start(c);
			msg_cat(c->err, c->errlen, mw_names[l]);
			msg_cat(c->err, c->errlen, " size ");
			msg_int(c->err, c->errlen, (int64_t)len);
			msg_cat(c->err, c->errlen, " is not a multiple of ");
			msg_int(c->err, c->errlen, (int64_t)mw_size[l]);
			return -EINVAL;
		}
		if (l < MW_REJECT && len / mw_size[l] > MW_MAX_RECORDS) {
			mw_start_file(c);
			msg_cat(c->err, c->errlen, mw_names[l]);
			msg_cat(c->err, c->errlen, ": ");
			msg_int(c->err, c->errlen, (int64_t)(len / mw_size[l]));
			msg_cat(c->err, c->errlen, " entries, more than the limit of ");
			msg_int(c->err, c->errlen, MW_MAX_RECORDS);
			msg_cat(c->err, c->errlen, " (MW_MAX_RECORDS)");
			return -E2BIG;
		}
		c->have[l] = 1;
		c->p[l] = d;
		c->n[l] = (uint32_t)(len / mw_size[l]);
	}
	if (c->have[MW_BEHAVIOR]) {
		mw_start(c);
		msg_cat(c->err, c->errlen, "Hexen-format map (BEHAVIOR lump) not supported");
		return -EINVAL;
	}
	for (int l = MW_THINGS; l <= MW_SECTORS; l++) {
		if (l == MW_SEGS || l == MW_SSECTORS || l == MW_NODES || c->have[l])
			continue;
		mw_start(c);
		msg_cat(c->err, c->errlen, "no ");
		msg_cat(c->err, c->errlen, mw_names[l]);
		msg_cat(c->err, c->errlen, " lump");
		return -EINVAL;
	}
	return 0;
}

/* An 8-byte name field as a NUL-terminated string. */
static void mw_name8(char out[9], const uint8_t *p)
{
	memcpy(out, p, 8);
	out[8] = '\0';
}

static uint16_t mw_tex(struct mw *c, const uint8_t *p)
{
	char name[9];
	int i;

	mw_name8(name, p);
	if (name[0] == '\0' || strcmp(name, "-") == 0)
		return 0;
	i = tex_find(c->t, name);
	if (i < 0) {
		c->m->missing_textures++;
		return (uint16_t)c->t->fallback_tex;
	}
	return (uint16_t)i;
}

static uint16_t mw_flat(struct mw *c, const uint8_t *p)
{
	char name[9];
	int i;

	mw_name8(name, p);
	i = tex_find_flat(c->t, name);
	if (i < 0) {
		c->m->missing_textures++;
		return (uint16_t)c->t->fallback_flat;
	}
	return (uint16_t)i;
}

static int mw_vertices(struct mw *c)
{
	for (uint32_t i = 0; i < c->n[MW_VERTEXES]; i++) {
		const uint8_t *r = c->p[MW_VERTEXES] + 4 * (size_t)i;
		fx_t x = fx_from_int(le_s16(r)), y = fx_from_int(le_s16(r + 2));

		if (x < -MAP_COORD_MAX || x > MAP_COORD_MAX || y < -MAP_COORD_MAX ||
		    y > MAP_COORD_MAX) {
			mw_entry(c, MW_VERTEXES, i);
			msg_cat(c->err, c->errlen, "coordinates out of range (+/-16384 units)");
			return -EINVAL;
		}
		c->m->vertices[i].x = x;
		c->m->vertices[i].y = y;
	}
	return 0;
}

static int mw_sectors(struct mw *c)
{
	for (uint32_t i = 0; i < c->n[MW_SECTORS]; i++) {
		const uint8_t *r = c->p[MW_SECTORS] + 26 * (size_t)i;
		struct map_sector *s = &c->m->sectors[i];
		int light = le_s16(r + 20);

		s->floor_h = fx_from_int(le_s16(r));
		s->ceil_h = fx_from_int(le_s16(r + 2));
		for (int k = 0; k < 2; k++) {
			fx_t h = k ? s->ceil_h : s->floor_h;

			if (h < -MAP_HEIGHT_MAX || h > MAP_HEIGHT_MAX) {
				mw_entry(c, MW_SECTORS, i);
				msg_cat(c->err, c->errlen, k ? "ceiling " : "floor ");
				msg_int(c->err, c->errlen, fx_to_int(h));
				msg_cat(c->err, c->errlen,
					" out of range (+/-16383 units: the view's fixed point holds no more)");
				return -EINVAL;
			}
		}
		if (s->ceil_h < s->floor_h)
			s->floor_h = s->ceil_h;
		s->floor_tex = mw_flat(c, r + 4);
		s->ceil_tex = mw_flat(c, r + 12);
		s->light = (uint8_t)(light < 0 ? 0 : light > 255 ? 255 : light);
		s->special = le_get16(r + 22);
		s->tag = le_get16(r + 24);
	}
	return 0;
}

static int mw_sides(struct mw *c)
{
	for (uint32_t i = 0; i < c->n[MW_SIDEDEFS]; i++) {
		const uint8_t *r = c->p[MW_SIDEDEFS] + 30 * (size_t)i;
		struct map_side *s = &c->m->sides[i];

		s->xoff = fx_from_int(le_s16(r));
		s->yoff = fx_from_int(le_s16(r + 2));
		s->top_tex = mw_tex(c, r + 4);
		s->bot_tex = mw_tex(c, r + 12);
		s->mid_tex = mw_tex(c, r + 20);
		s->sector = le_get16(r + 28);
		if (s->sector >= c->n[MW_SECTORS])
			return mw_range(c, MW_SIDEDEFS, i, "sector", s->sector, c->n[MW_SECTORS],
					"sectors");
	}
	return 0;
}

static int mw_lines(struct mw *c)
{
	const struct map_vertex *v = c->m->vertices;

	for (uint32_t i = 0; i < c->n[MW_LINEDEFS]; i++) {
		const uint8_t *r = c->p[MW_LINEDEFS] + 14 * (size_t)i;
		struct map_line *l = &c->m->lines[i];
		uint16_t s0 = le_get16(r + 10), s1 = le_get16(r + 12);

		l->v1 = le_get16(r);
		l->v2 = le_get16(r + 2);
		l->flags = le_get16(r + 4);
		l->special = le_get16(r + 6);
		l->tag = le_get16(r + 8);
		if (l->v1 >= c->n[MW_VERTEXES])
			return mw_range(c, MW_LINEDEFS, i, "vertex", l->v1, c->n[MW_VERTEXES],
					"vertices");
		if (l->v2 >= c->n[MW_VERTEXES])
			return mw_range(c, MW_LINEDEFS, i, "vertex", l->v2, c->n[MW_VERTEXES],
					"vertices");
		if (v[l->v1].x == v[l->v2].x && v[l->v1].y == v[l->v2].y) {
			mw_entry(c, MW_LINEDEFS, i);
			msg_cat(c->err, c->errlen, "zero length");
			return -EINVAL;
		}
		if (s0 == 0xFFFF) {
			mw_entry(c, MW_LINEDEFS, i);
			msg_cat(c->err, c->errlen, "no front sidedef");
			return -EINVAL;
		}
		if (s0 >= c->n[MW_SIDEDEFS])
			return mw_range(c, MW_LINEDEFS, i, "sidedef", s0, c->n[MW_SIDEDEFS],
					"sidedefs");
		if (s1 != 0xFFFF && s1 >= c->n[MW_SIDEDEFS])
			return mw_range(c, MW_LINEDEFS, i, "sidedef", s1, c->n[MW_SIDEDEFS],
					"sidedefs");
		l->side[0] = s0;
		l->side[1] = s1 == 0xFFFF ? MAP_NONE : s1;
		if (s1 == 0xFFFF)
			l->flags &= (uint16_t)~ML_TWOSIDED;
		else
			l->flags |= ML_TWOSIDED;
	}
	return 0;
}

/* A thing farther out than MAP_COORD_MAX is outside every map that loads
 * (Freedoom's E3M7 has one at y 24608) and is left out. */
static int mw_thing_in_range(const uint8_t *r)
{
	int64_t x = fx_from_int(le_s16(r)), y = fx_from_int(le_s16(r + 2));

	return x >= -MAP_COORD_MAX && x <= MAP_COORD_MAX && y >= -MAP_COORD_MAX &&
	       y <= MAP_COORD_MAX;
}

static uint32_t mw_num_things(const struct mw *c)
{
	uint32_t n = 0;

	for (uint32_t i = 0; i < c->n[MW_THINGS]; i++)
		n += (uint32_t)mw_thing_in_range(c->p[MW_THINGS] + 10 * (size_t)i);
	return n;
}

static void mw_things(struct mw *c)
{
	uint32_t n = 0;

	for (uint32_t i = 0; i < c->n[MW_THINGS]; i++) {
		const uint8_t *r = c->p[MW_THINGS] + 10 * (size_t)i;
		struct map_thing *t = &c->m->things[n];
		int deg = le_s16(r + 4) % 360;

		if (!mw_thing_in_range(r))
			continue;
		n++;
		if (deg < 0)
			deg += 360;
		t->x = fx_from_int(le_s16(r));
		t->y = fx_from_int(le_s16(r + 2));
		/* degrees to binary angle, rounded down: 90 -> ANG90 exactly */
		t->angle = (ang_t)(((uint64_t)deg << 32) / 360);
		t->type = le_get16(r + 6);
		t->flags = le_get16(r + 8);
	}
}

/* The BSP lumps are used when all are there in Doom's format; otherwise
 * (saved without nodes, or ZDoom's extended nodes) the node builder makes
 * the BSP. A single subsector without nodes is a valid Doom BSP. */
static int mw_has_bsp(const struct mw *c)
{
	if (!c->n[MW_SEGS] || !c->n[MW_SSECTORS])
		return 0;
	if (!c->n[MW_NODES])
		return c->n[MW_SSECTORS] == 1;
	return memcmp(c->p[MW_NODES], "XNOD", 4) != 0 && memcmp(c->p[MW_NODES], "ZNOD", 4) != 0 &&
	       memcmp(c->p[MW_NODES], "XGL", 3) != 0 && memcmp(c->p[MW_NODES], "ZGL", 3) != 0;
}

static int mw_segs(struct mw *c)
{
	struct map *m = c->m;

	for (uint32_t i = 0; i < m->num_segs; i++) {
		const uint8_t *r = c->p[MW_SEGS] + 12 * (size_t)i;
		struct map_seg *s = &m->segs[i];
		const struct map_line *l;
		uint16_t dir = le_get16(r + 8);

		s->v1 = le_get16(r);
		s->v2 = le_get16(r + 2);
		s->angle = (ang_t)le_get16(r + 4) << 16;
		s->line = le_get16(r + 6);
		s->offset = fx_from_int(le_s16(r + 10));
		if (s->v1 >= m->num_vertices)
			return mw_range(c, MW_SEGS, i, "vertex", s->v1, m->num_vertices, "vertices");
		if (s->v2 >= m->num_vertices)
			return mw_range(c, MW_SEGS, i, "vertex", s->v2, m->num_vertices, "vertices");
		if (s->line >= m->num_lines)
			return mw_range(c, MW_SEGS, i, "linedef", s->line, m->num_lines, "linedefs");
		l = &m->lines[s->line];
		if (dir > 1 || l->side[dir] == MAP_NONE) {
			mw_entry(c, MW_SEGS, i);
			msg_cat(c->err, c->errlen, "direction ");
			msg_int(c->err, c->errlen, dir);
			msg_cat(c->err, c->errlen, ": no such side of linedef ");
			msg_int(c->err, c->errlen, s->line);
			return -EINVAL;
		}
		s->side = (uint8_t)dir;
		s->front = m->sides[l->side[dir]].sector;
		s->back = l->side[dir ^ 1] == MAP_NONE ? MAP_NONE : m->sides[l->side[dir ^ 1]].sector;
	}
	return 0;
}

static int mw_subsectors(struct mw *c)
{
	struct map *m = c->m;

	for (uint32_t i = 0; i < m->num_subsectors; i++) {
		const uint8_t *r = c->p[MW_SSECTORS] + 4 * (size_t)i;
		struct map_subsector *ss = &m->subsectors[i];

		ss->num_segs = le_get16(r);
		ss->first_seg = le_get16(r + 2);
		if (ss->num_segs == 0 || ss->first_seg + ss->num_segs > m->num_segs) {
			mw_entry(c, MW_SSECTORS, i);
			msg_cat(c->err, c->errlen, "segs ");
			msg_int(c->err, c->errlen, ss->first_seg);
			msg_cat(c->err, c->errlen, "+");
			msg_int(c->err, c->errlen, ss->num_segs);
			msg_cat(c->err, c->errlen, " out of range (");
			msg_int(c->err, c->errlen, m->num_segs);
			msg_cat(c->err, c->errlen, " segs)");
			return -EINVAL;
		}
		ss->sector = m->segs[ss->first_seg].front;
	}
	return 0;
}

static int mw_nodes(struct mw *c)
{
	struct map *m = c->m;

	for (uint32_t i = 0; i < m->num_nodes; i++) {
		const uint8_t *r = c->p[MW_NODES] + 28 * (size_t)i;
		struct map_node *n = &m->nodes[i];

		n->x = fx_from_int(le_s16(r));
		n->y = fx_from_int(le_s16(r + 2));
		n->dx = fx_from_int(le_s16(r + 4));
		n->dy = fx_from_int(le_s16(r + 6));
		if (n->dx == 0 && n->dy == 0) {
			mw_entry(c, MW_NODES, i);
			msg_cat(c->err, c->errlen, "empty partition line");
			return -EINVAL;
		}
		for (int k = 0; k < 2; k++)
			for (int b = 0; b < 4; b++)
				n->bbox[k][b] = fx_from_int(le_s16(r + 8 + 8 * k + 2 * b));
		for (int k = 0; k < 2; k++) {
			uint16_t ch = le_get16(r + 24 + 2 * k);
			uint32_t idx = ch & 0x7FFFu;

			if (ch & 0x8000u) {
				if (idx >= m->num_subsectors)
					return mw_range(c, MW_NODES, i, k ? "left child subsector"
									  : "right child subsector",
							idx, m->num_subsectors, "subsectors");
				n->child[k] = MAP_NF_SUBSECTOR | idx;
			} else {
				if (idx >= i) {
					mw_entry(c, MW_NODES, i);
					msg_cat(c->err, c->errlen, k ? "left child node " : "right child node ");
					msg_int(c->err, c->errlen, idx);
					msg_cat(c->err, c->errlen, " is not listed before it");
					return -EINVAL;
				}
				n->child[k] = idx;
			}
		}
	}
	return 0;
}

static int mw_bsp(struct mw *c)
{
	struct map *m = c->m;
	int r;

	if (!mw_has_bsp(c))
		return 0;
	m->segs = calloc(c->n[MW_SEGS], sizeof *m->segs);
	m->subsectors = calloc(c->n[MW_SSECTORS], sizeof *m->subsectors);
	m->nodes = calloc(c->n[MW_NODES] ? c->n[MW_NODES] : 1, sizeof *m->nodes);
	if (!m->segs || !m->subsectors || !m->nodes)
		return -ENOMEM;
	m->num_segs = c->n[MW_SEGS];
	m->num_subsectors = c->n[MW_SSECTORS];
	m->num_nodes = c->n[MW_NODES];
	r = mw_segs(c);
	if (!r)
		r = mw_subsectors(c);
	if (!r)
		r = mw_nodes(c);
	return r;
}

static int mw_build(struct mw *c)
{
	int r = map_alloc(&c->m, c->n[MW_VERTEXES], c->n[MW_SECTORS], c->n[MW_SIDEDEFS],
			  c->n[MW_LINEDEFS], mw_num_things(c));

	if (r)
		return r;
	memcpy(c->m->name, c->map, strlen(c->map) + 1);
	r = mw_vertices(c);
	if (!r)
		r = mw_sectors(c);
	if (r)
		return r;
	r = mw_sides(c);
	if (!r)
		r = mw_lines(c);
	if (r)
		return r;
	mw_things(c);
	r = mw_bsp(c);
	if (r)
		return r;
	/* map_finish names entries by its own words ("line 3"); the map name
	 * goes in front, and the file too for the node builder's limits and
	 * stop. No BSP lumps (or ones in another format) are why it ran. */
	r = map_finish_lim(c->m, c->stop, c->err, c->errlen);
	if (r && r != -ENOMEM && c->err && c->errlen) {
		char tail[256] = "";

		msg_cat(tail, sizeof tail, c->err);
		if (r == -EINVAL) {
			mw_start(c);
		} else {
			mw_start_file(c);
			msg_cat(c->err, c->errlen, "NODES (built here): ");
		}
		msg_cat(c->err, c->errlen, tail);
	}
	return r;
}

/* "no map X (maps: A B C)" */
static int mw_no_map(const struct wad *w, const char *name, char *err, size_t errlen)
{
	char names[64][9];
	int n = map_list_wad(w, names, 64);

	if (n < 0)
		n = 0;
	if (err && errlen)
		err[0] = '\0';
	msg_cat(err, errlen, "no map ");
	msg_cat(err, errlen, name);
	msg_cat(err, errlen, n ? " (maps:" : " (no maps)");
	for (int i = 0; i < n && i < 64; i++) {
		msg_cat(err, errlen, " ");
		msg_cat(err, errlen, names[i]);
	}
	if (n > 64)
		msg_cat(err, errlen, " ...");
	if (n)
		msg_cat(err, errlen, ")");
	return -ENOENT;
}

int map_load_wad(const struct wad *w, const struct tex_set *t, const char *name,
		 struct map **out, char *err, size_t errlen)
{
	return map_load_wad_lim(w, t, name, NULL, out, err, errlen);
}

int map_load_wad_lim(const struct wad *w, const struct tex_set *t, const char *name,
		     const struct lim_stop *stop, struct map **out, char *err, size_t errlen)
{
	struct mw c;
	char key[9];
	int i, r;

	*out = NULL;
	memset(&c, 0, sizeof c);
	memset(key, 0, sizeof key);
	for (size_t k = 0; k < 8 && name[k]; k++)
		key[k] = (name[k] >= 'a' && name[k] <= 'z') ? (char)(name[k] - 'a' + 'A') : name[k];
	for (i = wad_count(w) - 1; i >= 0; i--)
		if (strlen(name) <= 8 && strcmp(wad_name(w, i), key) == 0 && mw_is_marker(w, i))
			break;
	if (i < 0)
		return mw_no_map(w, name, err, errlen);
	c.map = key;
	c.file = wad_file(w, i);
	c.stop = stop;
	c.t = t;
	c.err = err;
	c.errlen = errlen;
	if (strcmp(wad_name(w, i + 1), "TEXTMAP") == 0) {
		mw_start(&c);
		msg_cat(err, errlen, "UDMF map (TEXTMAP) not supported");
		return -EINVAL;
	}
	r = mw_collect(&c, w, i);
	if (!r)
		r = mw_build(&c);
	if (r) {
		map_free(c.m);
		return r;
	}
	*out = c.m;
	return 0;
}

/* A map marker for the listing: its name and lump index. */
struct mw_mark {
	const char *name;
	int lump;
};

static int mw_mark_cmp(const void *pa, const void *pb)
{
	const struct mw_mark *a = pa, *b = pb;
	int c = strcmp(a->name, b->name);

	return c ? c : (a->lump > b->lump) - (a->lump < b->lump);
}

/* Sorting the markers by name, then lump, finds each name's first marker
 * in O(n log n): comparing every marker with every lump before it took
 * 8.7 s for 40,000 markers. */
int map_list_wad(const struct wad *w, char (*names)[9], int max)
{
	int count = wad_count(w), nm = 0, n = 0;
	struct mw_mark *mk;
	uint8_t *first;

	for (int i = 0; i < count; i++)
		nm += mw_is_marker(w, i);
	mk = malloc((nm > 0 ? (size_t)nm : 1) * sizeof *mk);
	first = calloc(count > 0 ? (size_t)count : 1, 1);
	if (!mk || !first) {
		free(mk);
		free(first);
		return -ENOMEM;
	}
	nm = 0;
	for (int i = 0; i < count; i++)
		if (mw_is_marker(w, i))
			mk[nm++] = (struct mw_mark){ wad_name(w, i), i };
	qsort(mk, (size_t)nm, sizeof *mk, mw_mark_cmp);
	for (int j = 0; j < nm; j++)
		if (j == 0 || strcmp(mk[j].name, mk[j - 1].name) != 0)
			first[mk[j].lump] = 1;
	for (int i = 0; i < count; i++) {
		if (!first[i])
			continue;
		if (n < max)
			memcpy(names[n], wad_name(w, i), 9);
		n++;
	}
	free(mk);
	free(first);
	return n;
}
