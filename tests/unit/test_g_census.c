/* Tests for engine/game/g_census.c: the special types a map uses, counted,
 * and whether the game plays each. Expected values from the map built here
 * and docs/specials.md: line 1 (DR door) and sector 9 (secret) are played;
 * line 24576 (Boom's generalized floor, 0x6000) and sector 256 (Boom's
 * friction bit) are not. */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_world.h"
#include "engine/map/map.h"
#include "g_fixture.h"

/* A room whose four walls have specials w[0..3] and its sector sec. */
static struct map *room(const uint16_t w[4], uint16_t sec)
{
	struct map *m = gf_room(256, 256, NULL, 0, NULL, 0);

	assert_non_null(m);
	for (int i = 0; i < 4; i++)
		m->lines[i].special = w[i];
	m->sectors[0].special = sec;
	return m;
}

static void counts_each_type_and_says_what_is_played(void **state)
{
	static const uint16_t w[4] = { 24576, 1, 0, 24576 };
	struct g_spec_use u[8];
	struct map *m = room(w, 256);
	int n;

	(void)state;
	n = g_census(m, u, 8);
	assert_int_equal(n, 3);
	/* lines first, by type; the wall without a special is left out */
	assert_int_equal(u[0].sector, 0);
	assert_int_equal(u[0].type, 1);
	assert_int_equal(u[0].count, 1);
	assert_int_equal(u[0].played, 1);
	assert_int_equal(u[1].sector, 0);
	assert_int_equal(u[1].type, 24576);
	assert_int_equal(u[1].count, 2);
	assert_int_equal(u[1].played, 0);
	assert_int_equal(u[2].sector, 1);
	assert_int_equal(u[2].type, 256);
	assert_int_equal(u[2].count, 1);
	assert_int_equal(u[2].played, 0);
	m->sectors[0].special = 9;
	n = g_census(m, u, 8);
	assert_int_equal(n, 3);
	assert_int_equal(u[2].type, 9);
	assert_int_equal(u[2].played, 1);
	map_free(m);
}

static void no_specials_is_an_empty_census(void **state)
{
	static const uint16_t w[4] = { 0, 0, 0, 0 };
	struct g_spec_use u[1];
	struct map *m = room(w, 0);

	(void)state;
	assert_int_equal(g_census(m, u, 0), 0);
	map_free(m);
}

static void more_types_than_room_is_e2big(void **state)
{
	static const uint16_t w[4] = { 1, 2, 3, 1 };
	struct g_spec_use u[3];
	struct map *m = room(w, 0);

	(void)state;
	assert_int_equal(g_census(m, u, 2), -E2BIG);
	assert_int_equal(g_census(m, u, 3), 3);
	assert_int_equal(u[0].count, 2);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(counts_each_type_and_says_what_is_played),
		cmocka_unit_test(no_specials_is_an_empty_census),
		cmocka_unit_test(more_types_than_room_is_e2big),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
