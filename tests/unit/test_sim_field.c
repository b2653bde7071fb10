/* Tests for engine/game/sim_field.c: the sim's named values for scripts. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "g_fixture.h"

static void names_round_trip_and_unknown_names_are_refused(void **state)
{
	(void)state;
	assert_true(sim_field_count() >= 24);
	for (int i = 0; i < sim_field_count(); i++) {
		const char *n = sim_field_name(i);
		assert_non_null(n);
		assert_int_equal(sim_field_find(n), i);
	}
	assert_null(sim_field_name(sim_field_count()));
	assert_null(sim_field_name(-1));
	assert_int_equal(sim_field_find("hp"), -1);
	assert_int_equal(sim_field_find("Score"), -1);
	assert_int_equal(sim_field_kind(sim_field_find("x")), SIM_FK_FX);
	assert_int_equal(sim_field_kind(sim_field_find("angle")), SIM_FK_ANGLE);
	assert_int_equal(sim_field_kind(sim_field_find("mode")), SIM_FK_MODE);
	assert_int_equal(sim_field_kind(sim_field_find("page")), SIM_FK_PAGE);
	assert_int_equal(sim_field_kind(sim_field_find("score")), SIM_FK_INT);
}

static int64_t f(const struct sim *s, const char *name)
{
	int i = sim_field_find(name);
	assert_true(i >= 0);
	return sim_field_value(s, i);
}

static void values_read_the_state(void **state)
{
	static const struct gf_thing t[] = { { 100, 128, ANG90, 1, 0 }, { 400, 128, 0, 3004, 0 },
					      { 500, 128, 0, 3001, 0 } };
	static const struct sim_settings set = { 1, 0, 1, 2, 3, 100, 1, 0, 0, 0 };
	struct map *m = gf_room(1024, 256, t, 3, NULL, 0);
	struct sim s;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &set);
	assert_int_equal(f(&s, "x"), fx_from_int(100));
	assert_int_equal(f(&s, "angle"), 90);
	assert_int_equal(f(&s, "mode"), SIM_PLAY);
	assert_int_equal(f(&s, "lives"), 3);
	assert_int_equal(f(&s, "health"), 100);
	assert_int_equal(f(&s, "ammo"), G_AMMO_START);
	assert_int_equal(f(&s, "stage"), 1);
	assert_int_equal(f(&s, "enemies"), 2);
	assert_int_equal(f(&s, "difficulty"), 2);
	assert_int_equal(f(&s, "hiscore"), 10000);
	assert_int_equal(f(&s, "rank"), 0);
	s.pl.health = fx_from_int(41) + 1;     /* 41 and a bit shows as 42 */
	assert_int_equal(f(&s, "health"), 42);
	s.countdown = 541;                     /* 9 s and a tick: "10" on screen */
	assert_int_equal(f(&s, "countdown"), 10);
	s.countdown = 540;
	assert_int_equal(f(&s, "countdown"), 9);
	s.g.score = 1234;
	assert_int_equal(f(&s, "score"), 1234);
	s.new_rank = 2;
	assert_int_equal(f(&s, "rank"), 3);
	map_free(m);
}

static void page_names_round_trip(void **state)
{
	(void)state;
	assert_string_equal(sim_page_name(SIM_PAGE_TITLE), "title");
	assert_string_equal(sim_page_name(SIM_PAGE_SCORES), "scores");
	assert_string_equal(sim_page_name(SIM_PAGE_DEMO), "demo");
	assert_null(sim_page_name(SIM_PAGE_COUNT));
	assert_int_equal(sim_page_from_name("scores"), SIM_PAGE_SCORES);
	assert_int_equal(sim_page_from_name("Scores"), -1);
	assert_string_equal(sim_mode_name(SIM_GAMEOVER), "gameover");
	assert_int_equal(sim_mode_from_name("initials"), SIM_INITIALS);
	assert_int_equal(sim_mode_from_name("service"), SIM_SERVICE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(names_round_trip_and_unknown_names_are_refused),
		cmocka_unit_test(values_read_the_state),
		cmocka_unit_test(page_names_round_trip),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
