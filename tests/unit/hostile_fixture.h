/*
 * hostile_fixture: generators of the hostile WADs of issue 13 (items 7-9),
 * shared by the unit tests of the loaders (test_map.c, test_map_wad.c,
 * test_tex.c, test_nb.c, test_lmap.c, test_wad.c) and by the tool that
 * writes them as files for the daemon's test (tests/hostile/mkhostile.c).
 *
 * Every image is a standalone IWAD: the fixture graphics of wad_fixture.h
 * (palette, colormaps, a few patches and flats) plus one or more maps
 * built here. Sizes are parameters, so a unit test can make a small case
 * (to check a rule) or the full-size one from the issue (to check that a
 * limit stops it).
 *
 * The room: a square of side 2 * HF_HALF units centred on the origin, one
 * sector (floor 0, ceiling 128 unless asked otherwise), four one-sided
 * walls, the player start at the centre facing east. Maps without BSP
 * lumps (empty SEGS, SSECTORS, NODES) get theirs from the node builder.
 */
#ifndef ARCADED_TESTS_HOSTILE_FIXTURE_H
#define ARCADED_TESTS_HOSTILE_FIXTURE_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "wad_fixture.h"

#define HF_HALF 8192

/* The fn of a stop hook (engine/core/lim.h: struct lim_stop) that counts
 * its calls and says stop at call stop_at (UINT64_MAX: never). With the
 * hook's steps counter, how the tests see a loader's work without timing
 * it. */
struct hf_polls {
	uint64_t polls, stop_at;
};

static inline int hf_poll(void *ctx)
{
	struct hf_polls *p = ctx;

	return ++p->polls >= p->stop_at;
}

/* A map in the making: the eight lumps of wfx_map_names' order. */
struct hf_map {
	struct wbuf l[8];
	int nverts, nsides, nlines, nsectors;
};

static inline int hf_vertex(struct hf_map *m, int x, int y)
{
	wb_16(&m->l[3], x);
	wb_16(&m->l[3], y);
	return m->nverts++;
}

static inline int hf_side(struct hf_map *m, int sector)
{
	wb_16(&m->l[2], 0);
	wb_16(&m->l[2], 0);
	wb_name(&m->l[2], "-");
	wb_name(&m->l[2], "-");
	wb_name(&m->l[2], "SOLID");
	wb_16(&m->l[2], sector);
	return m->nsides++;
}

/* A line v1 -> v2 with a front side in sector front and, when back >= 0,
 * a back side in sector back (two-sided). */
static inline void hf_line(struct hf_map *m, int v1, int v2, int front, int back)
{
	int s0 = hf_side(m, front), s1 = back >= 0 ? hf_side(m, back) : 0xFFFF;

	wb_16(&m->l[1], v1);
	wb_16(&m->l[1], v2);
	wb_16(&m->l[1], back >= 0 ? 4 : 1);
	wb_16(&m->l[1], 0);
	wb_16(&m->l[1], 0);
	wb_16(&m->l[1], s0);
	wb_16(&m->l[1], s1);
	m->nlines++;
}

static inline void hf_sector(struct hf_map *m, int floor, int ceil)
{
	wb_16(&m->l[7], floor);
	wb_16(&m->l[7], ceil);
	wb_name(&m->l[7], "FLOOR1");
	wb_name(&m->l[7], "FLOOR1");
	wb_16(&m->l[7], 160);
	wb_16(&m->l[7], 0);
	wb_16(&m->l[7], 0);
	m->nsectors++;
}

static inline void hf_thing(struct hf_map *m, int x, int y, int angle, int type)
{
	wb_16(&m->l[0], x);
	wb_16(&m->l[0], y);
	wb_16(&m->l[0], angle);
	wb_16(&m->l[0], type);
	wb_16(&m->l[0], 7);
}

/* The room around the origin: sector 0, vertices 0..3 (south-west,
 * north-west, north-east, south-east), walls 0..3 facing in, player 1 at
 * the centre. */
static inline void hf_room(struct hf_map *m, int half, int floor, int ceil)
{
	memset(m, 0, sizeof *m);
	hf_sector(m, floor, ceil);
	hf_vertex(m, -half, -half);
	hf_vertex(m, -half, half);
	hf_vertex(m, half, half);
	hf_vertex(m, half, -half);
	for (int i = 0; i < 4; i++)
		hf_line(m, i, (i + 1) % 4, 0, -1);
	hf_thing(m, 0, 0, 0, 1);
}

/* Adds map `name` to f (REJECT and BLOCKMAP empty) and frees m's lumps. */
static inline void hf_add(struct wfix *f, const char *name, struct hf_map *m)
{
	wf_lump(f, name, NULL, 0);
	for (int i = 0; i < 8; i++) {
		wf_lump(f, wfx_map_names[i], m->l[i].d, m->l[i].n);
		free(m->l[i].d);
	}
	wf_lump(f, "REJECT", NULL, 0);
	wf_lump(f, "BLOCKMAP", NULL, 0);
	memset(m, 0, sizeof *m);
}

/* The fixture graphics and one map MAP01; returns the IWAD image. */
static inline uint8_t *hf_iwad(struct hf_map *m, size_t *len)
{
	struct wfix f;

	wf_init(&f);
	wfx_graphics(&f, 1);
	hf_add(&f, "MAP01", m);
	return wf_finish(&f, "IWAD", len);
}

/* Item 7. MAP01 is the room with a BSP whose NODES are a chain in which
 * every node but the first has both children equal to the node before it
 * (node 0's children are subsectors 0 and 1): a DAG, not a tree. A walk
 * of it visits node 0 2^(nodes-1) times. Each node's partition is the
 * line x = 0 and both of its boxes are the whole room, so nothing is
 * culled. The subsectors hold only the west and the north wall, which the
 * player, at the centre facing east, does not see: the screen never
 * fills, so a renderer's walk is not cut short. nodes 1 is a valid tree
 * (node 0 only). */
static inline uint8_t *hf_dag(int nodes, size_t *len)
{
	static const int seg_ang[4] = { 0x4000, 0, 0xC000, 0x8000 };
	struct hf_map m;

	hf_room(&m, 512, 0, 128);
	for (int i = 0; i < 4; i++) {
		wb_16(&m.l[4], i);
		wb_16(&m.l[4], (i + 1) % 4);
		wb_16(&m.l[4], seg_ang[i]);
		wb_16(&m.l[4], i);
		wb_16(&m.l[4], 0);
		wb_16(&m.l[4], 0);
	}
	wb_16(&m.l[5], 1);                  /* subsector 0: the west wall */
	wb_16(&m.l[5], 0);
	wb_16(&m.l[5], 1);                  /* subsector 1: the north wall */
	wb_16(&m.l[5], 1);
	for (int i = 0; i < nodes; i++) {
		int child = i == 0 ? 0x8000 : i - 1;

		wb_16(&m.l[6], 0);
		wb_16(&m.l[6], -512);
		wb_16(&m.l[6], 0);
		wb_16(&m.l[6], 1024);
		for (int k = 0; k < 2; k++) {
			wb_16(&m.l[6], 512);        /* top, bottom, left, right */
			wb_16(&m.l[6], -512);
			wb_16(&m.l[6], -512);
			wb_16(&m.l[6], 512);
		}
		wb_16(&m.l[6], child);
		wb_16(&m.l[6], i == 0 ? 0x8001 : child);
	}
	return hf_iwad(&m, len);
}

/* Item 8, texture composition. PNAMES names one patch "TALLP", 4,096
 * columns wide, all of whose column offsets point at the same column of
 * `posts` one-pixel posts (each continuing the one before, DeePsea style,
 * so all land in row 0). TEXTURE1 (replacing the fixture's) holds one
 * texture, "SOLID" (4,096 x 128), made of `patches` copies of TALLP at
 * (0, 0): composing it walks patches x 4,096 x posts posts. MAP01 is the
 * small room, whose walls show SOLID (hf_side): a loader that composes
 * only what its maps show must compose it. */
static inline uint8_t *hf_tall_texture(int patches, int posts, size_t *len)
{
	struct wfix f;
	struct wbuf b = { 0 }, defs = { 0 };
	struct hf_map m;
	const int w = 4096;

	wf_init(&f);
	wfx_graphics(&f, 1);
	/* the fixture's PNAMES and TEXTURE1 are replaced: later lumps win */
	wb_32(&b, 5);
	wb_name(&b, "PAT1");
	wb_name(&b, "pat2");
	wb_name(&b, "PAT3");
	wb_name(&b, "NOSUCH");
	wb_name(&b, "TALLP");
	wf_lumpb(&f, "PNAMES", &b);
	wb_32(&b, 1);
	wb_32(&b, 8);
	wb_name(&defs, "SOLID");
	wb_32(&defs, 0);
	wb_16(&defs, w);
	wb_16(&defs, 128);
	wb_32(&defs, 0);
	wb_16(&defs, patches);
	for (int i = 0; i < patches; i++) {
		wb_16(&defs, 0);
		wb_16(&defs, 0);
		wb_16(&defs, 4);
		wb_16(&defs, 1);
		wb_16(&defs, 0);
	}
	wb_bytes(&b, defs.d, defs.n);
	free(defs.d);
	wf_lumpb(&f, "TEXTURE1", &b);
	wb_16(&b, w);
	wb_16(&b, 128);
	wb_16(&b, 0);
	wb_16(&b, 0);
	for (int x = 0; x < w; x++)
		wb_32(&b, 8 + 4 * w);
	for (int p = 0; p < posts; p++) {
		wb_u8(&b, 0);
		wb_u8(&b, 1);
		wb_u8(&b, 0);
		wb_u8(&b, 1 + (p & 127));
		wb_u8(&b, 0);
	}
	wb_u8(&b, 0xFF);
	wf_lumpb(&f, "TALLP", &b);
	hf_room(&m, 512, 0, 128);
	hf_add(&f, "MAP01", &m);
	return wf_finish(&f, "IWAD", len);
}

/* Item 8, node builder. MAP01 is a room of side 2 * HF_HALF with `lines`
 * two-sided lines (sector 0 on both sides) in two families: the first half
 * runs from its west part to its east part, line i from (-W, a_i) to
 * (W, b_i) with a_i rising and b_i falling in i, the other half likewise
 * from south to north. Every two lines cross (within a family the order
 * reverses; across, each spans the room), and no three at one point (the
 * i % 3 term), so the builder's splits grow as lines^2. No BSP lumps.
 * Up to 32,000 lines keep every coordinate within int16. */
static inline uint8_t *hf_crossing(int lines, size_t *len)
{
	struct hf_map m;
	const int w = HF_HALF - 64, span = 2 * HF_HALF - 512;
	int fam[2] = { lines - lines / 2, lines / 2 };

	hf_room(&m, HF_HALF, 0, 128);
	for (int f = 0; f < 2; f++) {
		int step = fam[f] > 1 ? span / fam[f] : 1;

		for (int i = 0; i < fam[f]; i++) {
			int a = -HF_HALF + 256 + step * i;
			int b = HF_HALF - 256 - step * i - (i % 3);
			int v1 = f ? hf_vertex(&m, a, -w) : hf_vertex(&m, -w, a);
			int v2 = f ? hf_vertex(&m, b, w) : hf_vertex(&m, w, b);

			hf_line(&m, v1, v2, 0, 0);
		}
	}
	return hf_iwad(&m, len);
}

/* Item 8, light maps. MAP01 is a room of side 2 * HF_HALF holding `lights`
 * arcaded light things of the largest radius (512) and full intensity, on
 * a grid over the room. No BSP lumps. */
static inline uint8_t *hf_lights(int lights, size_t *len)
{
	struct hf_map m;
	int side = 1;

	while (side * side < lights)
		side++;
	hf_room(&m, HF_HALF, 0, 128);
	for (int i = 0; i < lights; i++) {
		int x = -HF_HALF + 64 + (2 * HF_HALF - 128) * (i % side) / side;
		int y = -HF_HALF + 64 + (2 * HF_HALF - 128) * (i / side) / side;

		hf_thing(&m, x, y, 0, 15000 + 64 * 7 + 8 * 7);
	}
	return hf_iwad(&m, len);
}

/* Item 8, light maps that take long: hf_lights' room and lights, plus
 * `lines` parallel north-south two-sided lines across it between sector 0
 * and sector 1 (floor 8: a step, so each line can block light), every
 * (2 * HF_HALF - 256) / lines units. Every light's rays cross many of them. */
static inline uint8_t *hf_lit_lines(int lights, int lines, size_t *len)
{
	struct hf_map m;
	int side = 1, step = (2 * HF_HALF - 256) / (lines > 0 ? lines : 1);

	while (side * side < lights)
		side++;
	hf_room(&m, HF_HALF, 0, 128);
	hf_sector(&m, 8, 128);
	for (int i = 0; i < lines; i++) {
		int x = -HF_HALF + 128 + step * i + step / 2;
		int v1 = hf_vertex(&m, x, -HF_HALF + 64), v2 = hf_vertex(&m, x, HF_HALF - 64);

		hf_line(&m, v1, v2, 0, 1);
	}
	for (int i = 0; i < lights; i++) {
		int x = -HF_HALF + 64 + (2 * HF_HALF - 128) * (i % side) / side;
		int y = -HF_HALF + 64 + (2 * HF_HALF - 128) * (i / side) / side;

		hf_thing(&m, x, y, 0, 15000 + 64 * 7 + 8 * 7);
	}
	return hf_iwad(&m, len);
}

/* Item 8, map listing. MAP01 (the small room) and then `markers` more map
 * markers "Mnnnnnn" (distinct names), each followed only by an empty
 * THINGS lump: each is a map marker to the listing (map_list_wad). */
static inline uint8_t *hf_markers(int markers, size_t *len)
{
	struct wfix f;
	struct hf_map m;

	wf_init(&f);
	wfx_graphics(&f, 1);
	hf_room(&m, 512, 0, 128);
	hf_add(&f, "MAP01", &m);
	for (int i = 0; i < markers; i++) {
		char name[9] = "M0000000";

		for (int k = 7, v = i; k > 0; k--, v /= 10)
			name[k] = (char)('0' + v % 10);
		wf_lump(&f, name, NULL, 0);
		wf_lump(&f, "THINGS", NULL, 0);
	}
	return wf_finish(&f, "IWAD", len);
}

/* Item 9. MAP01 is the small room with its floor at `floor` and ceiling at
 * `ceil` (Doom's int16 heights), the player start at its centre. */
static inline uint8_t *hf_heights(int floor, int ceil, size_t *len)
{
	struct hf_map m;

	hf_room(&m, 512, floor, ceil);
	return hf_iwad(&m, len);
}

/* Issue 15 item 7, specials the game does not play (--print-specials and
 * the load-time note). MAP01 is the small room (sector 0, walls 0..3) and
 * a second room east of it (sector 1, walls 4..7). Line specials: walls
 * 0, 1 and 4 have 24576 (0x6000, a Boom generalized floor: not vanilla,
 * not played), wall 2 has 1 (DR door, played); sector specials: sector 0
 * has 256 (Boom's friction bit: not played), sector 1 has 9 (secret,
 * played). The census is thus line 1 x1, line 24576 x3, sector 9 x1,
 * sector 256 x1. */
static inline void hf_set16(struct wbuf *b, size_t at, int v)
{
	b->d[at] = (uint8_t)(v & 0xff);
	b->d[at + 1] = (uint8_t)((v >> 8) & 0xff);
}

static inline uint8_t *hf_specials(size_t *len)
{
	static const int wall[8] = { 24576, 24576, 1, 0, 24576, 0, 0, 0 };
	struct hf_map m;
	int v;

	hf_room(&m, 512, 0, 128);
	hf_sector(&m, 0, 128);
	v = hf_vertex(&m, 1024, -256);
	hf_vertex(&m, 1024, 256);
	hf_vertex(&m, 1536, 256);
	hf_vertex(&m, 1536, -256);
	for (int i = 0; i < 4; i++)
		hf_line(&m, v + i, v + (i + 1) % 4, 1, -1);
	/* LINEDEFS entries are 14 bytes, the special at 6; SECTORS entries
	 * 26 bytes, the special at 22 */
	for (int i = 0; i < 8; i++)
		hf_set16(&m.l[1], (size_t)i * 14 + 6, wall[i]);
	hf_set16(&m.l[7], 22, 256);
	hf_set16(&m.l[7], 26 + 22, 9);
	return hf_iwad(&m, len);
}

#endif
