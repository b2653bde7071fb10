/*
 * act: action names, both ways.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "input/act.h"

static void test_names_are_the_documented_ones(void **state)
{
	(void)state;
	assert_string_equal(act_name(ACT_FORWARD), "forward");
	assert_string_equal(act_name(ACT_BACK), "back");
	assert_string_equal(act_name(ACT_TURN_LEFT), "turn_left");
	assert_string_equal(act_name(ACT_TURN_RIGHT), "turn_right");
	assert_string_equal(act_name(ACT_STRAFE_LEFT), "strafe_left");
	assert_string_equal(act_name(ACT_STRAFE_RIGHT), "strafe_right");
	assert_string_equal(act_name(ACT_FIRE), "fire");
	assert_string_equal(act_name(ACT_USE), "use");
	assert_string_equal(act_name(ACT_START), "start");
	assert_string_equal(act_name(ACT_COIN), "coin");
	assert_string_equal(act_name(ACT_SERVICE), "service");
	assert_string_equal(act_name(ACT_WEAPON), "weapon");
	assert_string_equal(act_name(ACT_LOOK_UP), "look_up");
	assert_string_equal(act_name(ACT_LOOK_DOWN), "look_down");
}

static void test_out_of_range_has_no_name(void **state)
{
	(void)state;
	assert_null(act_name(-1));
	assert_null(act_name(ACT_COUNT));
}

static void test_from_name_round_trips_and_ignores_case(void **state)
{
	(void)state;
	for (int a = 0; a < ACT_COUNT; a++)
		assert_int_equal(act_from_name(act_name(a)), a);
	assert_int_equal(act_from_name("TURN_Left"), ACT_TURN_LEFT);
	assert_int_equal(act_from_name("Coin"), ACT_COIN);
}

static void test_unknown_names_give_minus_one(void **state)
{
	(void)state;
	assert_int_equal(act_from_name("jump"), -1);
	assert_int_equal(act_from_name(""), -1);
	assert_int_equal(act_from_name("fire "), -1);
	assert_int_equal(act_from_name("turn left"), -1);
	assert_int_equal(act_from_name(NULL), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_names_are_the_documented_ones),
		cmocka_unit_test(test_out_of_range_has_no_name),
		cmocka_unit_test(test_from_name_round_trips_and_ignores_case),
		cmocka_unit_test(test_unknown_names_give_minus_one),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
