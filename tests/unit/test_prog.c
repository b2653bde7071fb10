/* Tests for app/prog.c: a map's exit as the daemon logs it, on the tick the
 * exit is taken and on no other. The map: one room whose north wall (line
 * 1) is the exit switch (S1 11, or the secret exit 51), with an enemy
 * thing (a zombieman) and a health bonus far from the player, so the counts
 * the line gives are the map's: kills 0 of 1, items 0 of 1. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "app/prog.h"
#include "spec_fixture.h"

static struct map *exit_room(int special)
{
	static const int w[] = { 512 };
	static const struct fix_sector s[] = { { 0, 128, 160 } };
	/* a zombieman (3004) and a health bonus (2014), counted by Doom's rules */
	static const struct fix_thing th[] = { { 480, 480, 0, 3004, 7 }, { 400, 480, 0, 2014, 7 } };
	struct map *m = fix_row(w, s, 1, 512, 128, 480, 0x40000000u, th, 2);

	assert_non_null(m);
	m->lines[1].special = (uint16_t)special;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

static void the_exit_tick_gives_one_line(void **state)
{
	struct map *m = exit_room(11);
	struct sim s;
	char buf[256] = "untouched";
	(void)state;

	sim_init(&s, m, &spec_play);
	spec_run(&s, &spec_none, 119);
	assert_int_equal(prog_exit(&s, buf, sizeof(buf)), 0);
	assert_string_equal(buf, "untouched");
	/* the 120th tick: 2 s into the map. The score is stage 1's bonus
	 * (G_STAGE_BONUS) and the time bonus: the 5-minute clock ran on 119
	 * ticks (the exit comes before the clock in the tick), so 17881 are
	 * left, 299 seconds rounded up, 10 points each */
	sim_tick(&s, &spec_use_cmd);
	assert_int_equal(prog_exit(&s, buf, sizeof(buf)), 1);
	assert_string_equal(buf, "map FIXTURE: exit taken after 0:00:02 (120 ticks), kills 0 of 1, "
				 "items 0 of 1, secrets 0 of 0, score 3990; next FIXTURE");
	/* the intermission goes on: no second line */
	sim_tick(&s, &spec_none);
	assert_int_equal(prog_exit(&s, buf, sizeof(buf)), 0);
	map_free(m);
}

static void a_secret_exit_says_so(void **state)
{
	struct map *m = exit_room(51);
	struct sim s;
	char buf[256];
	(void)state;

	sim_init(&s, m, &spec_play);
	sim_tick(&s, &spec_use_cmd);
	assert_int_equal(prog_exit(&s, buf, sizeof(buf)), 1);
	assert_non_null(strstr(buf, "map FIXTURE: secret exit taken after 0:00:00 (1 ticks)"));
	map_free(m);
}

static void a_short_buffer_is_cut_and_terminated(void **state)
{
	struct map *m = exit_room(11);
	struct sim s;
	char buf[12];
	(void)state;

	sim_init(&s, m, &spec_play);
	sim_tick(&s, &spec_use_cmd);
	assert_int_equal(prog_exit(&s, buf, sizeof(buf)), 1);
	assert_string_equal(buf, "map FIXTURE");   /* 11 characters and the NUL */
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_exit_tick_gives_one_line),
		cmocka_unit_test(a_secret_exit_says_so),
		cmocka_unit_test(a_short_buffer_is_cut_and_terminated),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
