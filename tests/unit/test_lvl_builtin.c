/* Tests for engine/lvl_builtin.c as game stages: every built-in level has
 * one start, enemies and pickups that stand clear of the walls, and the
 * stages grow harder in order. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/g_local.h"
#include "engine/map.h"
#include "engine/sim.h"

/* Whether a circle of radius r at (x, y) overlaps a wall that blocks a
 * body standing at z there (same rule as movement). Exact: squared
 * distances to each segment in 64-bit integer arithmetic. */
static int overlaps_wall(const struct map *m, fx_t x, fx_t y, fx_t z, fx_t r)
{
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		int64_t dx = (int64_t)b->x - a->x, dy = (int64_t)b->y - a->y;
		int64_t px = (int64_t)x - a->x, py = (int64_t)y - a->y;
		int64_t t = px * dx + py * dy, len2 = dx * dx + dy * dy;
		int64_t qx, qy;
		if (!g_blocks(m, l, z))
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
	static const struct sim_settings set = { 1, 0, 1, 1, 3 };
	(void)state;
	assert_true(map_builtin_count() >= 3);
	for (int i = 0; i < map_builtin_count(); i++) {
		struct map *m;
		struct sim s;
		int starts = 0;
		assert_int_equal(map_builtin(i, &m), 0);
		for (uint32_t k = 0; k < m->num_things; k++)
			starts += m->things[k].type == 1;
		assert_int_equal(starts, 1);
		sim_init(&s, m, &set);
		assert_true(s.g.num_enemies >= 4);
		assert_true(s.g.num_pickups >= 3);
		assert_false(overlaps_wall(m, s.pl.x, s.pl.y, s.pl.z, SIM_PLAYER_RADIUS));
		for (int k = 0; k < s.g.num_enemies; k++) {
			const struct g_enemy *e = &s.g.en[k];
			if (overlaps_wall(m, e->x, e->y, e->z, g_kinds[e->kind].radius))
				fail_msg("level %d enemy %d at (%d, %d) is in a wall", i, k,
					 e->x >> 16, e->y >> 16);
		}
		for (int k = 0; k < s.g.num_pickups; k++) {
			const struct g_pickup *p = &s.g.pk[k];
			if (overlaps_wall(m, p->x, p->y, p->z, SIM_PLAYER_RADIUS))
				fail_msg("level %d pickup %d at (%d, %d) cannot be reached", i, k,
					 p->x >> 16, p->y >> 16);
		}
		map_free(m);
	}
}

/* The total health of the enemies, and their damage per second, grow
 * from stage to stage; hard adds enemies on stages 2 and 3. */
static void stages_grow_harder(void **state)
{
	int64_t prev_hp = 0, prev_dps = 0;
	(void)state;
	for (int i = 0; i < 3; i++) {
		static const struct sim_settings normal = { 1, 0, 1, 1, 3 }, hard = { 1, 0, 1, 2, 3 };
		struct map *m;
		struct sim s, h;
		int64_t hp = 0, dps = 0;
		assert_int_equal(map_builtin(i, &m), 0);
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

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_stage_is_playable),
		cmocka_unit_test(stages_grow_harder),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
