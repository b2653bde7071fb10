/* Tests for engine/map/lvl_builtin.c: the built-in levels are maps of the
 * project's own, loaded from the compiled-in PWAD (levels/arena*.txt,
 * engine/map/lvl_wad.c) with tex_builtin's texture names; and as game stages
 * every one has one start, enemies and pickups that stand clear of the
 * walls, and the stages grow harder in order. */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <limits.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/lvl_wad.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"

/* Whether a circle of radius r at (x, y) overlaps a wall that blocks a
 * body standing at z there (same rule as movement). Exact: squared
 * distances to each segment in 64-bit integer arithmetic. */
static int overlaps_wall(const struct sim *sm, fx_t x, fx_t y, fx_t z, fx_t r)
{
	const struct map *m = sm->map;

	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		int64_t dx = (int64_t)b->x - a->x, dy = (int64_t)b->y - a->y;
		int64_t px = (int64_t)x - a->x, py = (int64_t)y - a->y;
		int64_t t = px * dx + py * dy, len2 = dx * dx + dy * dy;
		int64_t qx, qy;
		if (!g_blocks(sm, l, z))
			continue;
		if (t <= 0) {
			qx = px;
			qy = py;
		} else if (t >= len2) {
			qx = (int64_t)x - b->x;
			qy = (int64_t)y - b->y;
		} else {
			/* distance to the line: |cross| / len < r */
			int64_t cross = dx * py - dy * px;
			int64_t len = fx_len((fx_t)dx, (fx_t)dy);
			if ((cross < 0 ? -cross : cross) < (int64_t)r * len)
				return 1;
			continue;
		}
		if (qx * qx + qy * qy < (int64_t)r * r)
			return 1;
	}
	return 0;
}

static void every_stage_is_playable(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
	(void)state;
	assert_true(lvl_builtin_count() >= 3);
	for (int i = 0; i < lvl_builtin_count(); i++) {
		struct map *m;
		struct sim s;
		int starts = 0;
		assert_int_equal(lvl_builtin(i, &m), 0);
		for (uint32_t k = 0; k < m->num_things; k++)
			starts += m->things[k].type == 1;
		assert_int_equal(starts, 1);
		sim_init(&s, m, &set);
		assert_true(s.g.num_enemies >= 4);
		assert_true(s.g.num_pickups >= 3);
		assert_false(overlaps_wall(&s, s.pl.x, s.pl.y, s.pl.z, SIM_PLAYER_RADIUS));
		for (int k = 0; k < s.g.num_enemies; k++) {
			const struct g_enemy *e = &s.g.en[k];
			if (overlaps_wall(&s, e->x, e->y, e->z, g_kinds[e->kind].radius))
				fail_msg("level %d enemy %d at (%d, %d) is in a wall", i, k,
					 e->x >> 16, e->y >> 16);
		}
		for (int k = 0; k < s.g.num_pickups; k++) {
			const struct g_pickup *p = &s.g.pk[k];
			if (overlaps_wall(&s, p->x, p->y, p->z, SIM_PLAYER_RADIUS))
				fail_msg("level %d pickup %d at (%d, %d) cannot be reached", i, k,
					 p->x >> 16, p->y >> 16);
		}
		map_free(m);
	}
}

/* The total health of the enemies, and their damage per second, grow
 * from stage to stage; hard adds enemies on every stage after the first. */
static void stages_grow_harder(void **state)
{
	int64_t prev_hp = 0, prev_dps = 0;
	(void)state;
	for (int i = 0; i < lvl_builtin_count(); i++) {
		static const struct sim_settings normal = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 }, hard = { 1, 0, 1, 2, 3, 100, 1, 0, 0, 0 };
		struct map *m;
		struct sim s, h;
		int64_t hp = 0, dps = 0;
		assert_int_equal(lvl_builtin(i, &m), 0);
		sim_init(&s, m, &normal);
		sim_init(&h, m, &hard);
		for (int k = 0; k < s.g.num_enemies; k++) {
			const struct g_kind_info *ki = &g_kinds[s.g.en[k].kind];
			hp += ki->health;
			dps += (int64_t)ki->damage * SIM_TICRATE * 100 / ki->period;
		}
		assert_true(hp > prev_hp);
		assert_true(dps > prev_dps);
		if (i > 0)
			assert_true(h.g.num_enemies > s.g.num_enemies);
		prev_hp = hp;
		prev_dps = dps;
		map_free(m);
	}
}

/* The compiled-in PWAD holds ARENA1..8 in play order, and lvl_builtin
 * gives exactly what loading that WAD's map with tex_builtin's set gives. */
static void levels_are_the_compiled_in_wad(void **state)
{
	static const char *const want[] = { "ARENA1", "ARENA2", "ARENA3", "ARENA4",
					    "ARENA5", "ARENA6", "ARENA7", "ARENA8" };
	char names[16][9], err[160];
	struct tex_set *t;
	struct wad *w;
	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, lvl_wad, lvl_wad_len, "lvl_wad", err, sizeof err), 0);
	assert_int_equal(memcmp(lvl_wad, "PWAD", 4), 0);
	assert_int_equal(map_list_wad(w, names, 16), 8);
	assert_int_equal(lvl_builtin_count(), 8);
	for (int i = 0; i < 8; i++) {
		struct map *a, *b;
		assert_string_equal(names[i], want[i]);
		assert_int_equal(lvl_builtin(i, &a), 0);
		assert_int_equal(map_load_wad(w, t, want[i], &b, err, sizeof err), 0);
		assert_string_equal(a->name, want[i]);
		assert_true(a->content_hash == b->content_hash);
		assert_int_equal(a->num_nodes, b->num_nodes);
		assert_int_equal(a->missing_textures, 0);
		map_free(a);
		map_free(b);
	}
	wad_free(w);
	tex_free(t);
}

/* One set made by the caller serves every level (what the app does): each
 * level is the one lvl_builtin makes against a set of its own, texture
 * numbers included (content_hash covers sides and sectors); an index out
 * of range is -EINVAL with no map. */
static void one_set_serves_every_level(void **state)
{
	struct tex_set *t;
	struct map *m = (struct map *)&m;
	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	for (int i = 0; i < lvl_builtin_count(); i++) {
		struct map *a, *b;
		assert_int_equal(lvl_builtin_for(i, t, &a), 0);
		assert_int_equal(lvl_builtin(i, &b), 0);
		assert_string_equal(a->name, b->name);
		assert_true(a->content_hash == b->content_hash);
		assert_int_equal(a->num_nodes, b->num_nodes);
		assert_int_equal(a->missing_textures, 0);
		map_free(a);
		map_free(b);
	}
	assert_int_equal(lvl_builtin_for(-1, t, &m), -EINVAL);
	assert_null(m);
	m = (struct map *)&m;
	assert_int_equal(lvl_builtin_for(lvl_builtin_count(), t, &m), -EINVAL);
	assert_null(m);
	tex_free(t);
}

static const struct map_sector *sector_at(const struct map *m, int x, int y)
{
	return &m->sectors[map_point_sector(m, fx_from_int(x), fx_from_int(y))];
}

/* Every side and sector names a real texture of tex_builtin's set (none is
 * the fallback checker); one-sided walls have a middle texture, portals
 * none but ARENA1's window grate. The names the level files give are
 * where they should be: ARENA1's hall floor is AR_FLOOR with AR_STONE
 * walls, its yard and dais are open to the sky, ARENA2's west arm is
 * water (animated), the step risers are AR_METAL. */
static void levels_are_textured_by_name(void **state)
{
	struct tex_set *t;
	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	for (int i = 0; i < lvl_builtin_count(); i++) {
		struct map *m;
		int grates = 0;
		assert_int_equal(lvl_builtin(i, &m), 0);
		for (uint32_t k = 0; k < m->num_lines; k++) {
			const struct map_line *l = &m->lines[k];
			for (int sd = 0; sd < 2 && l->side[sd] != MAP_NONE; sd++) {
				const struct map_side *s = &m->sides[l->side[sd]];
				const uint16_t tx[3] = { s->top_tex, s->mid_tex, s->bot_tex };
				for (int p = 0; p < 3; p++)
					assert_true(tx[p] < t->num_textures && tx[p] != t->fallback_tex);
				if (l->side[1] == MAP_NONE) {
					assert_int_not_equal(s->mid_tex, 0);
				} else {
					assert_int_not_equal(s->top_tex, 0);
					assert_int_not_equal(s->bot_tex, 0);
					grates += s->mid_tex != 0;
					if (s->mid_tex)
						assert_int_equal(s->mid_tex, tex_find(t, "AR_GRATE"));
				}
			}
		}
		/* two sides for each grated line (levels/arena*.txt, `mid
		 * AR_GRATE`): ARENA1 and ARENA4 one line each; ARENA5 and ARENA8
		 * a window grated on both faces (two lines); ARENA7 two such */
		static const int want_grates[] = { 2, 0, 0, 2, 4, 0, 8, 4 };
		assert_int_equal(grates, want_grates[i]);
		for (uint32_t k = 0; k < m->num_sectors; k++) {
			assert_true(m->sectors[k].floor_tex < t->num_flats - 1);
			assert_true(m->sectors[k].ceil_tex < t->num_flats - 1);
		}
		if (i == 0) {
			const struct map_sector *hall = sector_at(m, 96, 192);
			const struct map_sector *yard = sector_at(m, 700, 900);
			const struct map_sector *dais = sector_at(m, 864, 512);
			uint32_t riser = m->lines[2].side[0];   /* hall to step 1 */
			assert_int_equal(hall->floor_tex, tex_find_flat(t, "AR_FLOOR"));
			assert_int_equal(m->sides[m->lines[0].side[0]].mid_tex, tex_find(t, "AR_STONE"));
			assert_int_equal(yard->ceil_tex, t->sky_flat);
			assert_int_equal(dais->ceil_tex, t->sky_flat);
			assert_int_equal(m->sides[riser].bot_tex, tex_find(t, "AR_METAL"));
		} else if (i == 1) {
			assert_int_equal(sector_at(m, 64, 512)->floor_tex, tex_find_flat(t, "AR_WAT1"));
		}
		map_free(m);
	}
	tex_free(t);
}

/* Which sectors a player can walk to from the start, on the sector graph:
 * through two-sided lines where the step up is at most SIM_MAX_STEP (any
 * drop) and the opening at least the player's height. A door's sector (the
 * back of a manual door line, specials 1, 31, 117, 118) counts with its ceiling
 * opened to its lowest neighbour's less 4 (Doom's rule); a lift (a sector
 * tagged by a lift line, specials 10, 62, 88, 120..123) counts at every
 * height from its lowest neighbour's floor to its own. A rule of the
 * test, independent of the sim's movement code: it reads only the map. */
#define REACH_MAX 64

static int is_door_special(int sp)
{
	return sp == 1 || sp == 31 || sp == 117 || sp == 118;
}

static int is_lift_special(int sp)
{
	return sp == 10 || sp == 62 || sp == 88 || (sp >= 120 && sp <= 123);
}

/* The lowest ceiling (ceil 1) or floor (0) of the sectors next to sector
 * sec across two-sided lines, or from if none is lower. */
static fx_t lowest_neighbour(const struct map *m, uint32_t sec, int ceil, fx_t from)
{
	fx_t v = from;

	for (uint32_t j = 0; j < m->num_lines; j++) {
		const struct map_line *o = &m->lines[j];
		if (o->side[1] == MAP_NONE)
			continue;
		for (int sd = 0; sd < 2; sd++) {
			uint32_t a = m->sides[o->side[sd]].sector;
			uint32_t b = m->sides[o->side[!sd]].sector;
			fx_t h = ceil ? m->sectors[b].ceil_h : m->sectors[b].floor_h;
			if (a == sec && b != sec && h < v)
				v = h;
		}
	}
	return v;
}

static void reachable_sectors(const struct map *m, uint32_t start, uint8_t *reach)
{
	fx_t lo[REACH_MAX], hi[REACH_MAX], ceil[REACH_MAX];
	uint32_t n = m->num_sectors;
	int changed = 1;
	assert_true(n <= REACH_MAX);
	for (uint32_t s = 0; s < n; s++) {
		lo[s] = hi[s] = m->sectors[s].floor_h;
		ceil[s] = m->sectors[s].ceil_h;
		reach[s] = s == start;
	}
	for (uint32_t k = 0; k < m->num_lines; k++) {
		const struct map_line *l = &m->lines[k];
		if (l->side[1] == MAP_NONE)
			continue;
		uint32_t back = m->sides[l->side[1]].sector;
		if (is_door_special(l->special))
			ceil[back] = lowest_neighbour(m, back, 1, INT32_MAX) - 4 * FX_ONE;
		if (is_lift_special(l->special))
			for (uint32_t s = 0; s < n; s++)
				if (m->sectors[s].tag == l->tag)
					lo[s] = lowest_neighbour(m, s, 0, lo[s]);
	}
	while (changed) {
		changed = 0;
		for (uint32_t k = 0; k < m->num_lines; k++) {
			const struct map_line *l = &m->lines[k];
			if (l->side[1] == MAP_NONE)
				continue;
			for (int sd = 0; sd < 2; sd++) {
				uint32_t a = m->sides[l->side[sd]].sector;
				uint32_t b = m->sides[l->side[!sd]].sector;
				fx_t c = ceil[a] < ceil[b] ? ceil[a] : ceil[b];
				/* b's lowest floor against a's highest: the best step */
				fx_t f = lo[b] > hi[a] ? lo[b] : hi[a];
				if (!reach[a] || reach[b] || lo[b] - hi[a] > SIM_MAX_STEP ||
				    c - f < SIM_PLAYER_HEIGHT)
					continue;
				reach[b] = 1;
				changed = 1;
			}
		}
	}
}

/* Every stage can be finished: stages 4..8 have an exit switch (special
 * 11) whose front sector the player can walk to from the start, and a
 * weapon pickup; stages 1..3 end when their enemies are dead. Every
 * pickup lies in a sector the player can reach. */
static void every_stage_can_be_finished(void **state)
{
	static const struct sim_settings set = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
	(void)state;
	assert_int_equal(lvl_builtin_count(), 8);
	for (int i = 0; i < lvl_builtin_count(); i++) {
		struct map *m;
		struct sim s;
		uint8_t reach[REACH_MAX];
		int exits = 0, weapons = 0;
		assert_int_equal(lvl_builtin(i, &m), 0);
		sim_init(&s, m, &set);
		reachable_sectors(m, map_point_sector(m, s.pl.x, s.pl.y), reach);
		for (uint32_t k = 0; k < m->num_lines; k++) {
			const struct map_line *l = &m->lines[k];
			if (l->special != 11)
				continue;
			exits++;
			assert_int_equal(l->side[1], MAP_NONE);   /* a wall switch */
			if (!reach[m->sides[l->side[0]].sector])
				fail_msg("level %d: the exit switch (line %u) cannot be reached", i, k);
		}
		assert_int_equal(exits, i >= 3);
		assert_int_equal(s.w.has_exit, i >= 3);
		for (int k = 0; k < s.g.num_pickups; k++) {
			const struct g_pickup *p = &s.g.pk[k];
			weapons += p->kind == G_P_WEAPON;
			if (!reach[map_point_sector(m, p->x, p->y)])
				fail_msg("level %d: pickup %d (type %d) at (%d, %d) cannot be reached", i,
					 k, p->type, p->x >> 16, p->y >> 16);
		}
		if (i >= 3)
			assert_true(weapons >= 1);
		map_free(m);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(levels_are_the_compiled_in_wad),
		cmocka_unit_test(one_set_serves_every_level),
		cmocka_unit_test(levels_are_textured_by_name),
		cmocka_unit_test(every_stage_is_playable),
		cmocka_unit_test(stages_grow_harder),
		cmocka_unit_test(every_stage_can_be_finished),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
