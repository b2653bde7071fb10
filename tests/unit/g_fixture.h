/*
 * Test fixture for the game rules: a rectangular room (floor 0, ceiling
 * 128) with optional solid pillars and any things, finished with
 * map_finish. Shared by test_g_*.c, test_menu.c and test_hud.c. And
 * gf_restores: whether a state passes its own snapshot (test_sim.c,
 * test_sim_hash.c).
 */
#ifndef ARCADED_TESTS_G_FIXTURE_H
#define ARCADED_TESTS_G_FIXTURE_H

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/game/sim.h"
#include "engine/map/map.h"

struct gf_thing {
	int x, y;
	ang_t angle;
	uint16_t type, flags;
};

/* A pillar: the box x0..x1, y0..y1 (map units), solid. */
struct gf_box {
	int x0, y0, x1, y1;
};

/* Room 0..w x 0..h. The outline runs clockwise (room on the right), the
 * pillars counter-clockwise (room on the right again). NULL on failure. */
static inline struct map *gf_room(int w, int h, const struct gf_thing *th, int nth,
				  const struct gf_box *box, int nbox)
{
	struct map *m;
	uint32_t nv = 4 + 4 * (uint32_t)nbox, nl = nv, i;

	if (map_alloc(&m, nv, 1, nl, nl, (uint32_t)nth))
		return NULL;
	memcpy(m->name, "GFIX", 5);
	m->vertices[0] = (struct map_vertex){ 0, 0 };
	m->vertices[1] = (struct map_vertex){ 0, fx_from_int(h) };
	m->vertices[2] = (struct map_vertex){ fx_from_int(w), fx_from_int(h) };
	m->vertices[3] = (struct map_vertex){ fx_from_int(w), 0 };
	for (int b = 0; b < nbox; b++) {
		struct map_vertex *v = &m->vertices[4 + 4 * b];
		v[0] = (struct map_vertex){ fx_from_int(box[b].x0), fx_from_int(box[b].y0) };
		v[1] = (struct map_vertex){ fx_from_int(box[b].x1), fx_from_int(box[b].y0) };
		v[2] = (struct map_vertex){ fx_from_int(box[b].x1), fx_from_int(box[b].y1) };
		v[3] = (struct map_vertex){ fx_from_int(box[b].x0), fx_from_int(box[b].y1) };
	}
	m->sectors[0].floor_h = 0;
	m->sectors[0].ceil_h = fx_from_int(128);
	m->sectors[0].light = 160;
	for (i = 0; i < nl; i++) {
		uint32_t base = i / 4 * 4;
		m->lines[i].v1 = i;
		m->lines[i].v2 = base + (i + 1) % 4;
		m->lines[i].flags = ML_BLOCKING;
		m->lines[i].side[0] = i;
		m->lines[i].side[1] = MAP_NONE;
		m->sides[i].sector = 0;
		m->sides[i].mid_tex = 1;
	}
	for (int k = 0; k < nth; k++) {
		m->things[k].x = fx_from_int(th[k].x);
		m->things[k].y = fx_from_int(th[k].y);
		m->things[k].angle = th[k].angle;
		m->things[k].type = th[k].type;
		m->things[k].flags = th[k].flags;
	}
	if (map_finish(m, NULL, 0)) {
		map_free(m);
		return NULL;
	}
	return m;
}

/* The game tests' arena: gf_room 2048 x 512 with the player 1 start at
 * (128, 256) facing east, then the n things th (at most 7) and the boxes.
 * NULL on failure. */
static inline struct map *gf_arena(const struct gf_thing *th, int n, const struct gf_box *box,
				   int nbox)
{
	struct gf_thing all[8];

	if (n < 0 || n > 7)
		return NULL;
	all[0] = (struct gf_thing){ 128, 256, 0, 1, 0 };
	if (n > 0)
		memcpy(all + 1, th, (size_t)n * sizeof(*th));
	return gf_room(2048, 512, all, n + 1, box, nbox);
}

/* Snapshots a and restores the bytes into a new sim started on the one
 * stage map m with settings set (the snapshot brings its own): returns
 * sim_restore's result, 0 when the state passes its own range checks (what
 * a recording of the game needs), and the restored sim's hash in *hash
 * when hash is not NULL; -ENOMEM when the memory cannot be had. */
static inline int gf_restores(const struct sim *a, const struct map *m,
			      const struct sim_settings *set, uint64_t *hash)
{
	struct sim *b = malloc(sizeof(*b));
	uint8_t *buf = malloc(sim_snapshot_size());
	int rc = -ENOMEM;

	if (b && buf) {
		sim_snapshot(a, buf);
		sim_init(b, m, set);
		rc = sim_restore(b, buf, sim_snapshot_size());
		if (hash)
			*hash = sim_hash(b);
	}
	free(buf);
	free(b);
	return rc;
}

#endif
