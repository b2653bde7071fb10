/* Tests for engine/map/map_wad.c: the two-room fixture read field by field, a
 * corpus of corrupted maps each naming map, lump and entry, BSP rebuild,
 * normalisations, layering, the hostile maps of issue 13 (a BSP that is a
 * DAG, heights the view cannot hold, lumps over the record limit, 40,000
 * map markers, the node builder's limit and stop), and every map of
 * Freedoom, with the work each loader needs far below its limit (skipped
 * loudly when the freedoom package is not installed). Fixtures:
 * wad_fixture.h, hostile_fixture.h. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <cmocka.h>

#include "app/ct.h"
#include "engine/core/lim.h"
#include "engine/map/lmap.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/nb.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"
#include "hostile_fixture.h"
#include "wad_fixture.h"

/* The fixture graphics plus map MAP01 changed by fix (NULL: as is), and E1M1
 * as is. */
struct mfx {
	uint8_t *img;
	struct wad *w;
	struct tex_set *t;
};

static struct mfx mfx_open(void (*fix)(struct wbuf *l))
{
	struct mfx f;
	struct wfix b;
	size_t len;
	char err[160];

	wf_init(&b);
	wfx_graphics(&b, 1);
	wfx_map(&b, "MAP01", fix);
	wfx_map(&b, "E1M1", NULL);
	f.img = wf_finish(&b, "IWAD", &len);
	assert_int_equal(wad_new(&f.w), 0);
	assert_int_equal(wad_add(f.w, f.img, len, "fix.wad", err, sizeof err), 0);
	assert_int_equal(tex_load_wad(f.w, &f.t, err, sizeof err), 0);
	return f;
}

static void mfx_close(struct mfx *f)
{
	tex_free(f->t);
	wad_free(f->w);
	free(f->img);
}

/* Loads MAP01 with fix applied; returns the result, err filled. */
static int load_fixed(void (*fix)(struct wbuf *l), char *err, size_t errlen)
{
	struct mfx f = mfx_open(fix);
	struct map *m = NULL;
	int r = map_load_wad(f.w, f.t, "MAP01", &m, err, errlen);

	if (r)
		assert_null(m);
	map_free(m);
	mfx_close(&f);
	return r;
}

/* Overwrites the 16-bit field at byte `at` of lump l. */
static void put16(struct wbuf *l, size_t at, int v)
{
	l->d[at] = (uint8_t)(v & 255);
	l->d[at + 1] = (uint8_t)((v >> 8) & 255);
}

enum { L_THINGS, L_LINEDEFS, L_SIDEDEFS, L_VERTEXES, L_SEGS, L_SSECTORS, L_NODES, L_SECTORS };

static void reads_every_field(void **state)
{
	struct mfx f = mfx_open(NULL);
	struct map *m;
	char err[160];

	(void)state;
	assert_int_equal(map_load_wad(f.w, f.t, "map01", &m, err, sizeof err), 0);
	assert_string_equal(m->name, "MAP01");
	assert_int_equal(m->num_vertices, 6);
	assert_int_equal(m->num_lines, 7);
	assert_int_equal(m->num_sides, 8);
	assert_int_equal(m->num_sectors, 2);
	assert_int_equal(m->num_things, 2);
	assert_int_equal(m->num_segs, 8);
	assert_int_equal(m->num_subsectors, 2);
	assert_int_equal(m->num_nodes, 1);
	for (int i = 0; i < 6; i++) {
		assert_int_equal(m->vertices[i].x, wfx_verts[i][0] * FX_ONE);
		assert_int_equal(m->vertices[i].y, wfx_verts[i][1] * FX_ONE);
	}
	/* sectors */
	assert_int_equal(m->sectors[0].floor_h, 0);
	assert_int_equal(m->sectors[0].ceil_h, 128 * FX_ONE);
	assert_int_equal(m->sectors[0].floor_tex, tex_find_flat(f.t, "FLOOR1"));
	assert_int_equal(m->sectors[0].ceil_tex, f.t->sky_flat);
	assert_int_equal(m->sectors[0].light, 160);
	assert_int_equal(m->sectors[1].floor_h, 16 * FX_ONE);
	assert_int_equal(m->sectors[1].ceil_h, 112 * FX_ONE);
	assert_int_equal(m->sectors[1].floor_tex, tex_find_flat(f.t, "NUKAGE1"));
	assert_int_equal(m->sectors[1].ceil_tex, f.t->fallback_flat);
	assert_int_equal(m->sectors[1].light, 255);
	assert_int_equal(m->sectors[1].special, 9);
	assert_int_equal(m->sectors[1].tag, 7);
	/* sides: "two" in lower case finds TWO; "-" is 0; NOTEX the fallback */
	assert_int_equal(m->sides[0].xoff, 8 * FX_ONE);
	assert_int_equal(m->sides[0].yoff, -4 * FX_ONE);
	assert_int_equal(m->sides[0].mid_tex, tex_find(f.t, "TWO"));
	assert_int_equal(m->sides[0].top_tex, 0);
	assert_int_equal(m->sides[2].top_tex, tex_find(f.t, "SOLID"));
	assert_int_equal(m->sides[2].mid_tex, 0);
	assert_int_equal(m->sides[3].top_tex, f.t->fallback_tex);
	assert_int_equal(m->sides[3].sector, 1);
	assert_int_equal(m->missing_textures, 2);
	/* lines */
	assert_int_equal(m->lines[2].v1, 2);
	assert_int_equal(m->lines[2].v2, 3);
	assert_int_equal(m->lines[2].flags, ML_TWOSIDED);
	assert_int_equal(m->lines[2].special, 1);
	assert_int_equal(m->lines[2].tag, 7);
	assert_int_equal(m->lines[2].side[0], 2);
	assert_int_equal(m->lines[2].side[1], 3);
	assert_int_equal(m->lines[0].side[1], MAP_NONE);
	assert_int_equal(m->lines[0].flags, ML_BLOCKING);
	/* things: 225 degrees is 5/8 of a turn */
	assert_int_equal(m->things[0].x, 64 * FX_ONE);
	assert_int_equal(m->things[0].angle, ANG90);
	assert_int_equal(m->things[0].type, 1);
	assert_int_equal(m->things[0].flags, 7);
	assert_int_equal(m->things[1].angle, 0xA0000000u);
	assert_int_equal(m->things[1].type, 3004);
	/* segs: BAM16 << 16, the back side of line 2 faces B */
	assert_int_equal(m->segs[0].angle, ANG90);
	assert_int_equal(m->segs[2].angle, ANG270);
	assert_int_equal(m->segs[4].line, 2);
	assert_int_equal(m->segs[4].side, 1);
	assert_int_equal(m->segs[4].front, 1);
	assert_int_equal(m->segs[4].back, 0);
	assert_int_equal(m->segs[3].back, MAP_NONE);
	assert_int_equal(m->subsectors[1].first_seg, 4);
	assert_int_equal(m->subsectors[1].sector, 1);
	/* the node: 0x8000 children become MAP_NF_SUBSECTOR, boxes in 16.16 */
	assert_int_equal(m->nodes[0].child[0], MAP_NF_SUBSECTOR | 1);
	assert_int_equal(m->nodes[0].child[1], MAP_NF_SUBSECTOR | 0);
	assert_int_equal(m->nodes[0].dy, 128 * FX_ONE);
	assert_int_equal(m->nodes[0].bbox[0][BOX_RIGHT], 256 * FX_ONE);
	assert_int_equal(m->nodes[0].bbox[1][BOX_LEFT], 0);
	/* point location through the file's BSP */
	assert_int_equal(map_point_sector(m, 64 * FX_ONE, 64 * FX_ONE), 0);
	assert_int_equal(map_point_sector(m, 192 * FX_ONE, 64 * FX_ONE), 1);
	map_free(m);
	mfx_close(&f);
}

static void bad_line_vertex(struct wbuf *l) { put16(&l[L_LINEDEFS], 3 * 14 + 2, 99); }
static void bad_line_side(struct wbuf *l) { put16(&l[L_LINEDEFS], 4 * 14 + 12, 0xFFFE); }
static void no_front_side(struct wbuf *l) { put16(&l[L_LINEDEFS], 5 * 14 + 10, 0xFFFF); }
static void zero_length(struct wbuf *l) { put16(&l[L_VERTEXES], 4 + 2, 0); }
static void far_vertex(struct wbuf *l) { put16(&l[L_VERTEXES], 5 * 4, 20000); }
static void bad_side_sector(struct wbuf *l) { put16(&l[L_SIDEDEFS], 5 * 30 + 28, 9); }
static void bad_seg_vertex(struct wbuf *l) { put16(&l[L_SEGS], 6 * 12 + 2, 6); }
static void bad_seg_line(struct wbuf *l) { put16(&l[L_SEGS], 1 * 12 + 6, 7); }
static void bad_seg_side(struct wbuf *l) { put16(&l[L_SEGS], 0 * 12 + 8, 1); }
static void bad_ssector(struct wbuf *l) { put16(&l[L_SSECTORS], 4, 60000); }
static void bad_child_ss(struct wbuf *l) { put16(&l[L_NODES], 24, 0x8005); }
static void bad_child_node(struct wbuf *l) { put16(&l[L_NODES], 26, 0x0000); }
static void empty_partition(struct wbuf *l) { put16(&l[L_NODES], 6, 0); }
static void odd_segs(struct wbuf *l) { wb_u8(&l[L_SEGS], 0); }
static void odd_sectors(struct wbuf *l) { l[L_SECTORS].n -= 3; }

static void corrupt_maps_name_map_lump_and_entry(void **state)
{
	static const struct {
		void (*fix)(struct wbuf *l);
		const char *msg;
	} cases[] = {
		{ bad_line_vertex, "fix.wad: MAP01: LINEDEFS entry 3: vertex 99 out of range (6 vertices)" },
		{ bad_line_side, "fix.wad: MAP01: LINEDEFS entry 4: sidedef 65534 out of range (8 sidedefs)" },
		{ no_front_side, "fix.wad: MAP01: LINEDEFS entry 5: no front sidedef" },
		{ zero_length, "fix.wad: MAP01: LINEDEFS entry 0: zero length" },
		{ far_vertex,
		  "fix.wad: MAP01: VERTEXES entry 5: coordinates out of range (+/-16384 units)" },
		{ bad_side_sector, "fix.wad: MAP01: SIDEDEFS entry 5: sector 9 out of range (2 sectors)" },
		{ bad_seg_vertex, "fix.wad: MAP01: SEGS entry 6: vertex 6 out of range (6 vertices)" },
		{ bad_seg_line, "fix.wad: MAP01: SEGS entry 1: linedef 7 out of range (7 linedefs)" },
		{ bad_seg_side, "fix.wad: MAP01: SEGS entry 0: direction 1: no such side of linedef 0" },
		{ bad_ssector, "fix.wad: MAP01: SSECTORS entry 1: segs 4+60000 out of range (8 segs)" },
		{ bad_child_ss,
		  "fix.wad: MAP01: NODES entry 0: right child subsector 5 out of range (2 subsectors)" },
		{ bad_child_node, "fix.wad: MAP01: NODES entry 0: left child node 0 is not listed before it" },
		{ empty_partition, "fix.wad: MAP01: NODES entry 0: empty partition line" },
		{ odd_segs, "fix.wad: MAP01: SEGS size 97 is not a multiple of 12" },
		{ odd_sectors, "fix.wad: MAP01: SECTORS size 49 is not a multiple of 26" },
	};
	char err[160];

	(void)state;
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		assert_int_equal(load_fixed(cases[i].fix, err, sizeof err), -EINVAL);
		assert_string_equal(err, cases[i].msg);
	}
}

/* Every lump of the map cut to every length: an error naming the file and MAP01 or a
 * map that passes map_finish, never a read past the lump (ASan build). */
static int cut_lump, cut_len;
static void cut(struct wbuf *l) { l[cut_lump].n = (size_t)cut_len; }

static void truncated_lumps_fail_cleanly(void **state)
{
	static const int sizes[8] = { 20, 98, 240, 24, 96, 8, 28, 52 };
	char err[160];

	(void)state;
	for (cut_lump = 0; cut_lump < 8; cut_lump++) {
		for (cut_len = 0; cut_len < sizes[cut_lump]; cut_len++) {
			int r = load_fixed(cut, err, sizeof err);
			assert_true(r == 0 || r == -EINVAL);
			if (r)
				assert_memory_equal(err, "fix.wad: MAP01: ", 16);
		}
	}
}

static void no_bsp(struct wbuf *l) { l[L_SEGS].n = l[L_SSECTORS].n = l[L_NODES].n = 0; }
static void xnod(struct wbuf *l) { memcpy(l[L_NODES].d, "XNOD", 4); }

static void maps_without_nodes_get_built_ones(void **state)
{
	void (*fixes[2])(struct wbuf *) = { no_bsp, xnod };

	(void)state;
	for (int k = 0; k < 2; k++) {
		struct mfx f = mfx_open(fixes[k]);
		struct map *m;
		char err[160];

		assert_int_equal(map_load_wad(f.w, f.t, "MAP01", &m, err, sizeof err), 0);
		assert_true(m->num_nodes >= 1);
		assert_true(m->num_segs >= 8);
		assert_int_equal(map_point_sector(m, 64 * FX_ONE, 64 * FX_ONE), 0);
		assert_int_equal(map_point_sector(m, 192 * FX_ONE, 100 * FX_ONE), 1);
		map_free(m);
		mfx_close(&f);
	}
}

static void low_ceiling(struct wbuf *l) { put16(&l[L_SECTORS], 26 + 2, 8); }
static void flags_lie(struct wbuf *l)
{
	put16(&l[L_LINEDEFS], 2 * 14 + 4, 0);      /* two sides, no flag */
	put16(&l[L_LINEDEFS], 0 * 14 + 4, 5);      /* one side, flag set */
}
static void far_thing(struct wbuf *l) { put16(&l[L_THINGS], 2, 24608); }

static void doom_quirks_are_normalised(void **state)
{
	struct mfx f;
	struct map *m;
	char err[160];

	(void)state;
	f = mfx_open(low_ceiling);
	assert_int_equal(map_load_wad(f.w, f.t, "MAP01", &m, err, sizeof err), 0);
	assert_int_equal(m->sectors[1].ceil_h, 8 * FX_ONE);
	assert_int_equal(m->sectors[1].floor_h, 8 * FX_ONE);
	map_free(m);
	mfx_close(&f);
	f = mfx_open(flags_lie);
	assert_int_equal(map_load_wad(f.w, f.t, "MAP01", &m, err, sizeof err), 0);
	assert_int_equal(m->lines[2].flags, ML_TWOSIDED);
	assert_int_equal(m->lines[0].flags, ML_BLOCKING);
	map_free(m);
	mfx_close(&f);
	f = mfx_open(far_thing);
	assert_int_equal(map_load_wad(f.w, f.t, "MAP01", &m, err, sizeof err), 0);
	assert_int_equal(m->num_things, 1);
	assert_int_equal(m->things[0].type, 3004);
	map_free(m);
	mfx_close(&f);
}

static void names_lists_and_missing_maps(void **state)
{
	struct mfx f = mfx_open(NULL);
	struct map *m;
	char err[160], names[4][9];

	(void)state;
	assert_int_equal(map_list_wad(f.w, names, 4), 2);
	assert_string_equal(names[0], "MAP01");
	assert_string_equal(names[1], "E1M1");
	assert_int_equal(map_list_wad(f.w, names, 1), 2);
	assert_int_equal(map_load_wad(f.w, f.t, "e1m1", &m, err, sizeof err), 0);
	assert_string_equal(m->name, "E1M1");
	map_free(m);
	assert_int_equal(map_load_wad(f.w, f.t, "MAP02", &m, err, sizeof err), -ENOENT);
	assert_null(m);
	assert_string_equal(err, "no map MAP02 (maps: MAP01 E1M1)");
	/* THINGS is a lump, not a map */
	assert_int_equal(map_load_wad(f.w, f.t, "THINGS", &m, err, sizeof err), -ENOENT);
	assert_int_equal(map_load_wad(f.w, f.t, "MAP01XXXX", &m, err, sizeof err), -ENOENT);
	mfx_close(&f);
}

static void brighter(struct wbuf *l) { put16(&l[L_SECTORS], 20, 99); }

static void pwad_overrides_a_map(void **state)
{
	struct mfx f = mfx_open(NULL);
	struct wfix b;
	struct map *m;
	uint8_t *pw;
	size_t len;
	char err[160], names[4][9];

	(void)state;
	wf_init(&b);
	wfx_map(&b, "MAP01", brighter);
	pw = wf_finish(&b, "PWAD", &len);
	assert_int_equal(wad_add(f.w, pw, len, "p.wad", err, sizeof err), 0);
	assert_int_equal(map_load_wad(f.w, f.t, "MAP01", &m, err, sizeof err), 0);
	assert_int_equal(m->sectors[0].light, 99);
	map_free(m);
	assert_int_equal(map_list_wad(f.w, names, 4), 2);
	mfx_close(&f);
	free(pw);
}

static void other_formats_and_missing_lumps_are_refused(void **state)
{
	struct wfix b;
	struct wad *w;
	struct tex_set *t;
	struct map *m;
	uint8_t *img;
	size_t len;
	char err[160];

	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	wf_init(&b);
	wf_lump(&b, "MAP01", NULL, 0);
	wf_lump(&b, "TEXTMAP", "namespace=\"doom\";", 17);
	wfx_map(&b, "MAP02", NULL);
	wf_lump(&b, "BEHAVIOR", "x", 1);
	wf_lump(&b, "MAP03", NULL, 0);
	wf_lump(&b, "THINGS", NULL, 0);
	wf_lump(&b, "LINEDEFS", NULL, 0);
	img = wf_finish(&b, "PWAD", &len);
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "o.wad", err, sizeof err), 0);
	assert_int_equal(map_load_wad(w, t, "MAP01", &m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "o.wad: MAP01: UDMF map (TEXTMAP) not supported");
	assert_int_equal(map_load_wad(w, t, "MAP02", &m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "o.wad: MAP02: Hexen-format map (BEHAVIOR lump) not supported");
	assert_int_equal(map_load_wad(w, t, "MAP03", &m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "o.wad: MAP03: no SIDEDEFS lump");
	wad_free(w);
	free(img);
	tex_free(t);
}

/* ---- writing ------------------------------------------------------------ */

/* Every built-in level, its texture numbers moved into the built-in set,
 * written as a PWAD and read back: the same level, and the same BSP from
 * the node builder. */
static void builtin_levels_round_trip_through_a_wad(void **state)
{
	struct tex_set *t;

	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	for (int i = 0; i < lvl_builtin_count(); i++) {
		struct map *m, *back;
		uint8_t *img;
		size_t len;
		struct wad *w;
		char err[160];
		const char *name = "MAP07";
		const struct map *maps[1];

		assert_int_equal(lvl_builtin(i, &m), 0);
		for (uint32_t k = 0; k < m->num_sides; k++) {
			struct map_side *s = &m->sides[k];
			s->top_tex = s->top_tex ? (uint16_t)(1 + s->top_tex % (t->num_textures - 2)) : 0;
			s->mid_tex = s->mid_tex ? (uint16_t)(1 + s->mid_tex % (t->num_textures - 2)) : 0;
			s->bot_tex = s->bot_tex ? (uint16_t)(1 + s->bot_tex % (t->num_textures - 2)) : 0;
		}
		for (uint32_t k = 0; k < m->num_sectors; k++) {
			m->sectors[k].floor_tex = (uint16_t)(m->sectors[k].floor_tex % (t->num_flats - 1));
			m->sectors[k].ceil_tex = (uint16_t)(m->sectors[k].ceil_tex % (t->num_flats - 1));
		}
		maps[0] = m;
		assert_int_equal(map_wad_write(maps, &name, 1, t, &img, &len, err, sizeof err), 0);
		assert_int_equal(wad_new(&w), 0);
		assert_int_equal(wad_add(w, img, len, "rt.wad", err, sizeof err), 0);
		if (map_load_wad(w, t, "MAP07", &back, err, sizeof err))
			fail_msg("level %d: %s", i, err);
		assert_int_equal(back->missing_textures, 0);
		assert_int_equal(back->num_sectors, m->num_sectors);
		assert_int_equal(back->num_sides, m->num_sides);
		assert_int_equal(back->num_lines, m->num_lines);
		assert_int_equal(back->num_things, m->num_things);
		assert_memory_equal(back->sectors, m->sectors, m->num_sectors * sizeof *m->sectors);
		assert_memory_equal(back->sides, m->sides, m->num_sides * sizeof *m->sides);
		assert_memory_equal(back->lines, m->lines, m->num_lines * sizeof *m->lines);
		for (uint32_t k = 0; k < m->num_things; k++) {
			uint32_t d = back->things[k].angle - m->things[k].angle;
			assert_int_equal(back->things[k].x, m->things[k].x);
			assert_int_equal(back->things[k].y, m->things[k].y);
			assert_int_equal(back->things[k].type, m->things[k].type);
			assert_int_equal(back->things[k].flags, m->things[k].flags);
			/* whole degrees: within a degree, 2^32 / 360 */
			assert_true(d < 11930465u || d > 0u - 11930465u);
		}
		for (uint32_t k = 0; k < back->num_vertices && k < m->num_vertices; k++)
			assert_memory_equal(&back->vertices[k], &m->vertices[k], sizeof m->vertices[k]);
		assert_int_equal(back->num_nodes, m->num_nodes);
		assert_int_equal(back->num_subsectors, m->num_subsectors);
		map_free(back);
		wad_free(w);
		free(img);
		/* a half-unit vertex cannot be written */
		m->vertices[m->lines[0].v1].x += FX_HALF;
		assert_int_equal(map_wad_write(maps, &name, 1, t, &img, &len, err, sizeof err),
				 -EINVAL);
		assert_null(img);
		assert_string_equal(err, "MAP07: vertex 0: not whole units within int16");
		map_free(m);
	}
	tex_free(t);
}

/* ---- Freedoom ------------------------------------------------------------ */

/* The file at path, or NULL (ct_read_file, app/ct.h). */
static uint8_t *slurp(const char *path, size_t *len)
{
	uint8_t *d = NULL;

	return ct_read_file(path, &d, len) == 0 ? d : NULL;
}

/* For each sector with an area, some seg of it whose midpoint, nudged 1/16
 * unit to its front (right) side, locates back into that sector. A sector
 * of zero area (E3M6 has one: two lines back to back) has no inside. The
 * area is the shoelace sum over the line sides facing the sector. */
static uint32_t unreachable_sectors(const struct map *m)
{
	uint8_t *ok = calloc(m->num_sectors, 1), *used = calloc(m->num_sectors, 1);
	int64_t *area = calloc(m->num_sectors, sizeof *area);
	uint32_t bad = 0;

	assert_non_null(ok);
	assert_non_null(used);
	assert_non_null(area);
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		int64_t x1 = m->vertices[l->v1].x / FX_ONE, y1 = m->vertices[l->v1].y / FX_ONE;
		int64_t x2 = m->vertices[l->v2].x / FX_ONE, y2 = m->vertices[l->v2].y / FX_ONE;

		area[m->sides[l->side[0]].sector] += x1 * y2 - x2 * y1;
		if (l->side[1] != MAP_NONE)
			area[m->sides[l->side[1]].sector] -= x1 * y2 - x2 * y1;
	}
	for (uint32_t i = 0; i < m->num_sides; i++)
		used[m->sides[i].sector] = area[m->sides[i].sector] != 0;
	free(area);
	for (uint32_t i = 0; i < m->num_segs; i++) {
		const struct map_seg *s = &m->segs[i];
		const struct map_vertex *a = &m->vertices[s->v1], *b = &m->vertices[s->v2];
		fx_t dx = b->x - a->x, dy = b->y - a->y;
		fx_t x = a->x + dx / 2 + (dy > 0 ? FX_ONE / 16 : dy < 0 ? -FX_ONE / 16 : 0);
		fx_t y = a->y + dy / 2 + (dx > 0 ? -FX_ONE / 16 : dx < 0 ? FX_ONE / 16 : 0);

		if (map_point_sector(m, x, y) == s->front)
			ok[s->front] = 1;
	}
	for (uint32_t i = 0; i < m->num_sectors; i++)
		bad += used[i] && !ok[i];
	free(ok);
	free(used);
	return bad;
}

/* The light maps of every light of m, counted through hook; fails when
 * they come near a limit. */
static void light_up(const struct map *m, const struct lim_stop *hook, const char *path,
		     const char *name)
{
	int n = lmap_lights_from_map(m, LMAP_DECOR, NULL, 0);
	struct lmap_light *l = calloc((size_t)n + 1, sizeof *l);
	struct lmap *lm;
	char err[200];

	assert_non_null(l);
	if (n > LMAP_MAX_LIGHTS / 8)
		fail_msg("%s %s: %d lights, within 8 times LMAP_MAX_LIGHTS", path, name, n);
	lmap_lights_from_map(m, LMAP_DECOR, l, n);
	if (lmap_new_lim(m, l, n, hook, &lm, err, sizeof err))
		fail_msg("%s %s: %s", path, name, err);
	if (*hook->steps > LMAP_MAX_STEPS / 8)
		fail_msg("%s %s: the light maps take %llu steps, within 8 times LMAP_MAX_STEPS",
			 path, name, (unsigned long long)*hook->steps);
	lmap_free(lm);
	free(l);
}

static void check_freedoom(const char *path, const char *first, const char *last, int count)
{
	size_t len = 0;
	uint8_t *d = slurp(path, &len);
	struct wad *w;
	struct tex_set *t;
	char err[256], names[64][9];
	clock_t t0 = clock();
	uint64_t steps = 0, most[3] = { 0, 0, 0 };
	struct lim_stop hook = { NULL, NULL, &steps };
	int n;

	if (!d) {
		print_message("SKIPPED: %s is not installed (Debian package freedoom; "
			      "scripts/setup.sh installs it)\n", path);
		skip();
	}
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, d, len, path, err, sizeof err), 0);
	assert_int_equal(tex_load_wad_lim(w, &hook, &t, err, sizeof err), 0);
	/* the limits are far above what Freedoom needs (issue 13 item 8) */
	if (steps > TEX_MAX_STEPS / 8)
		fail_msg("%s: the textures take %llu steps, within 8 times TEX_MAX_STEPS", path,
			 (unsigned long long)steps);
	most[0] = steps;
	assert_int_equal(t->missing, 0);
	assert_true(t->num_textures > 100);
	assert_true(t->num_flats > 100);
	assert_true(t->sky_flat >= 0);
	assert_int_equal(t->sky_tex, tex_find(t, "SKY1"));
	/* Doom's sky rule, on map names (E1M1..E4M9, MAP01..MAP32) */
	for (int k = 0; k < 3; k++) {
		static const char *const maps[2][3] = { { "E2M1", "E4M9", "E1M5" },
						       { "MAP12", "MAP32", "MAP11" } };
		static const char *const skies[2][3] = { { "SKY2", "SKY4", "SKY1" },
							 { "SKY2", "SKY3", "SKY1" } };
		int doom2 = count == 32;

		assert_true(tex_find(t, skies[doom2][k]) > 0);
		tex_pick_sky(t, maps[doom2][k]);
		assert_int_equal(t->sky_tex, tex_find(t, skies[doom2][k]));
	}
	tex_pick_sky(t, "ARENA1");
	assert_int_equal(t->sky_tex, tex_find(t, "SKY1"));
	n = map_list_wad(w, names, 64);
	assert_int_equal(n, count);
	assert_string_equal(names[0], first);
	assert_string_equal(names[n - 1], last);
	for (int i = 0; i < n; i++) {
		struct map *m;
		int starts = 0;

		if (map_load_wad(w, t, names[i], &m, err, sizeof err))
			fail_msg("%s: %s", path, err);
		assert_true(m->num_sectors > 10 && m->num_lines > 100 && m->num_things > 10);
		assert_true(m->num_nodes > 0 && m->num_subsectors == m->num_nodes + 1);
		assert_int_equal(m->missing_textures, 0);
		for (uint32_t k = 0; k < m->num_things; k++)
			starts += m->things[k].type == 1;
		assert_true(starts >= 1);
		/* each thing's sector, found once by map_finish for the
		 * renderer's decorations, is where point location puts it */
		assert_non_null(m->thing_sec);
		for (uint32_t k = 0; k < m->num_things; k++)
			if (m->thing_sec[k] != map_point_sector(m, m->things[k].x, m->things[k].y))
				fail_msg("%s %s: thing %u: sector %u, point location %u", path,
					 names[i], k, m->thing_sec[k],
					 map_point_sector(m, m->things[k].x, m->things[k].y));
		if (unreachable_sectors(m))
			fail_msg("%s %s: %u sectors not found by point location", path, names[i],
				 unreachable_sectors(m));
		/* the node builder and the light maps on it, counted */
		steps = 0;
		if (nb_build(m, &hook, err, sizeof err))
			fail_msg("%s %s: %s", path, names[i], err);
		if (steps > NB_MAX_STEPS / 8)
			fail_msg("%s %s: rebuilding the BSP takes %llu steps, within 8 times "
				 "NB_MAX_STEPS", path, names[i], (unsigned long long)steps);
		most[1] = steps > most[1] ? steps : most[1];
		steps = 0;
		light_up(m, &hook, path, names[i]);
		most[2] = steps > most[2] ? steps : most[2];
		map_free(m);
	}
	print_message("%s: most steps: textures %llu, node builder %llu, light maps %llu\n", path,
		      (unsigned long long)most[0], (unsigned long long)most[1],
		      (unsigned long long)most[2]);
	print_message("%s: palette, %d textures, %d flats, %d sprites and %d maps in %ld ms\n",
		      path, t->num_textures, t->num_flats, t->num_sprites, n,
		      (long)((clock() - t0) * 1000 / CLOCKS_PER_SEC));
	tex_free(t);
	wad_free(w);
	free(d);
}

/* Loads MAP01 of the hostile image img (freed here) as "hostile.wad" with
 * stop hook `stop` (may be NULL); returns map_load_wad_lim's result, *out
 * the map or NULL. */
static int hostile_load(uint8_t *img, size_t len, const struct lim_stop *stop, struct map **out,
			char *err, size_t errlen)
{
	struct wad *w;
	struct tex_set *t;
	int r;

	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "hostile.wad", err, errlen), 0);
	assert_int_equal(tex_load_wad(w, &t, err, errlen), 0);
	r = map_load_wad_lim(w, t, "MAP01", stop, out, err, errlen);
	if (r)
		assert_null(*out);
	tex_free(t);
	wad_free(w);
	free(img);
	return r;
}

/* Issue 13 item 7: 1,200 nodes, each with both children the node before
 * it, are 2^1200 paths for a walk: the loader refuses the DAG (it used to
 * load, and the renderer then never finished a frame). One node is a
 * tree and loads. */
static void bsp_dag_is_refused(void **state)
{
	struct map *m;
	char err[200];
	size_t len;
	uint8_t *img;

	(void)state;
	img = hf_dag(1200, &len);
	assert_int_equal(hostile_load(img, len, NULL, &m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "hostile.wad: MAP01: node 1199: child[1] node 1198 is reached a second "
				 "time: the BSP is not a tree");
	img = hf_dag(1, &len);
	assert_int_equal(hostile_load(img, len, NULL, &m, err, sizeof err), 0);
	assert_int_equal(m->num_nodes, 1);
	map_free(m);
}

/* Issue 13 item 9: a floor above 32,726 makes the eye height (floor + 41)
 * overflow 16.16; heights beyond MAP_HEIGHT_MAX are refused, naming the
 * lump and entry. The bound itself loads. */
static void heights_the_view_cannot_hold_are_refused(void **state)
{
	struct map *m;
	char err[200];
	size_t len;
	uint8_t *img;

	(void)state;
	img = hf_heights(32730, 32760, &len);
	assert_int_equal(hostile_load(img, len, NULL, &m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "hostile.wad: MAP01: SECTORS entry 0: floor 32730 out of range (+/-16383 "
				 "units: the view's fixed point holds no more)");
	img = hf_heights(-16384, 0, &len);
	assert_int_equal(hostile_load(img, len, NULL, &m, err, sizeof err), -EINVAL);
	assert_non_null(strstr(err, "SECTORS entry 0: floor -16384 out of range"));
	img = hf_heights(0, 16384, &len);
	assert_int_equal(hostile_load(img, len, NULL, &m, err, sizeof err), -EINVAL);
	assert_non_null(strstr(err, "SECTORS entry 0: ceiling 16384 out of range"));
	img = hf_heights(-16383, 16383, &len);
	assert_int_equal(hostile_load(img, len, NULL, &m, err, sizeof err), 0);
	assert_true(m->sectors[0].floor_h == -MAP_HEIGHT_MAX && m->sectors[0].ceil_h == MAP_HEIGHT_MAX);
	map_free(m);
}

static void many_things(struct wbuf *l)
{
	l[L_THINGS].n = 0;
	for (int i = 0; i < MW_MAX_RECORDS + 1; i++) {
		wb_16(&l[L_THINGS], 64);
		wb_16(&l[L_THINGS], 64);
		wb_16(&l[L_THINGS], 0);
		wb_16(&l[L_THINGS], 1);
		wb_16(&l[L_THINGS], 7);
	}
}

/* A lump holding more records than 16-bit indices reach is refused with
 * the file, map, lump and limit. */
static void lumps_over_the_record_limit_are_refused(void **state)
{
	char err[200];

	(void)state;
	assert_int_equal(load_fixed(many_things, err, sizeof err), -E2BIG);
	assert_string_equal(err, "fix.wad: MAP01: THINGS: 65537 entries, more than the limit of "
				 "65536 (MW_MAX_RECORDS)");
}

/* 40,000 markers more (distinct names), plus repeated names: each name is
 * listed once, at its first marker, in lump order. The listing sorts the
 * markers (it compared each with every lump before it: 8.7 s here). */
static void forty_thousand_markers_are_listed_once_each(void **state)
{
	char names[4][9], err[200];
	size_t len;
	uint8_t *img = hf_markers(40000, &len);
	struct wad *w;
	struct wfix f;
	uint8_t *img2;
	size_t len2;

	(void)state;
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "markers.wad", err, sizeof err), 0);
	assert_int_equal(map_list_wad(w, names, 4), 40001);
	assert_string_equal(names[0], "MAP01");
	assert_string_equal(names[1], "M0000000");
	assert_string_equal(names[3], "M0000002");
	/* a second file repeating two names and adding one: listed once each,
	 * the new one last */
	wf_init(&f);
	wf_lump(&f, "M0000001", NULL, 0);
	wf_lump(&f, "THINGS", NULL, 0);
	wf_lump(&f, "ZZZ", NULL, 0);
	wf_lump(&f, "THINGS", NULL, 0);
	wf_lump(&f, "MAP01", NULL, 0);
	wf_lump(&f, "THINGS", NULL, 0);
	img2 = wf_finish(&f, "PWAD", &len2);
	assert_int_equal(wad_add(w, img2, len2, "more.wad", err, sizeof err), 0);
	assert_int_equal(map_list_wad(w, names, 1), 40002);
	assert_string_equal(names[0], "MAP01");
	wad_free(w);
	free(img);
	free(img2);
}

/* Issue 13 item 8: 2,004 lines that all cross each other took the node
 * builder 57 s and 180 MB. It now stops at NB_MAX_STEPS (the stop hook,
 * called every LIM_POLL steps, shows how far it went), naming the file,
 * map and limit; and a stop hook that says stop ends it at its next poll. */
static void crossing_lines_stop_at_the_node_builders_limit(void **state)
{
	struct hf_polls count = { 0, UINT64_MAX }, halt = { 0, 3 };
	uint64_t steps = 0;
	struct lim_stop hook = { hf_poll, &count, &steps }, stop = { hf_poll, &halt, NULL };
	struct map *m;
	char err[200];
	size_t len;
	uint8_t *img;

	(void)state;
	img = hf_crossing(2004, &len);
	assert_int_equal(hostile_load(img, len, &hook, &m, err, sizeof err), -E2BIG);
	assert_string_equal(err, "hostile.wad: MAP01: NODES (built here): node builder: 2008 "
				 "lines need more than 268435456 steps (limit NB_MAX_STEPS)");
	/* it went to the limit and one chunk past it, no further */
	assert_true(steps > NB_MAX_STEPS && steps < NB_MAX_STEPS + 10 * 1000 * 1000);
	assert_true(count.polls >= 1 && count.polls <= NB_MAX_STEPS / LIM_POLL + 1);
	img = hf_crossing(2004, &len);
	assert_int_equal(hostile_load(img, len, &stop, &m, err, sizeof err), -ECANCELED);
	assert_string_equal(err, "hostile.wad: MAP01: NODES (built here): node builder: stopped");
	assert_int_equal(halt.polls, 3);
	/* a few crossing lines build */
	img = hf_crossing(40, &len);
	assert_int_equal(hostile_load(img, len, NULL, &m, err, sizeof err), 0);
	assert_true(m->num_segs > 2 * 44);
	map_free(m);
}

static void freedoom1_every_map_loads(void **state)
{
	(void)state;
	check_freedoom("/usr/share/games/doom/freedoom1.wad", "E1M1", "E4M9", 36);
}

static void freedoom2_every_map_loads(void **state)
{
	(void)state;
	check_freedoom("/usr/share/games/doom/freedoom2.wad", "MAP01", "MAP32", 32);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(reads_every_field),
		cmocka_unit_test(corrupt_maps_name_map_lump_and_entry),
		cmocka_unit_test(truncated_lumps_fail_cleanly),
		cmocka_unit_test(maps_without_nodes_get_built_ones),
		cmocka_unit_test(doom_quirks_are_normalised),
		cmocka_unit_test(names_lists_and_missing_maps),
		cmocka_unit_test(pwad_overrides_a_map),
		cmocka_unit_test(other_formats_and_missing_lumps_are_refused),
		cmocka_unit_test(builtin_levels_round_trip_through_a_wad),
		cmocka_unit_test(bsp_dag_is_refused),
		cmocka_unit_test(heights_the_view_cannot_hold_are_refused),
		cmocka_unit_test(lumps_over_the_record_limit_are_refused),
		cmocka_unit_test(forty_thousand_markers_are_listed_once_each),
		cmocka_unit_test(crossing_lines_stop_at_the_node_builders_limit),
		cmocka_unit_test(freedoom1_every_map_loads),
		cmocka_unit_test(freedoom2_every_map_loads),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
