/* Tests for app/cmd.c: actions to per-tick commands. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "app/cmd.h"

static void idle_gives_zero_command(void **state)
{
	struct cmd_state s;
	struct sim_cmd c;
	(void)state;
	cmd_reset(&s);
	cmd_build(&s, &c);
	assert_int_equal(c.forward, 0);
	assert_int_equal(c.side, 0);
	assert_int_equal(c.turn, 0);
	assert_int_equal(c.buttons, 0);
	assert_int_equal(c.coins, 0);
}

static void held_actions_map_to_axes_and_buttons(void **state)
{
	struct cmd_state s;
	struct sim_cmd c;
	(void)state;
	cmd_reset(&s);
	cmd_action(&s, ACT_FORWARD, 1);
	cmd_action(&s, ACT_STRAFE_LEFT, 1);
	cmd_action(&s, ACT_TURN_RIGHT, 1);
	cmd_action(&s, ACT_FIRE, 1);
	cmd_build(&s, &c);
	assert_int_equal(c.forward, CMD_MOVE);
	assert_int_equal(c.side, -CMD_MOVE);
	assert_int_equal(c.turn, -CMD_TURN_SPEED);
	assert_int_equal(c.buttons, SIM_BT_FIRE);
	/* still held on the next tick */
	cmd_build(&s, &c);
	assert_int_equal(c.forward, CMD_MOVE);
	assert_int_equal(c.buttons, SIM_BT_FIRE);
}

static void opposite_actions_cancel(void **state)
{
	struct cmd_state s;
	struct sim_cmd c;
	(void)state;
	cmd_reset(&s);
	cmd_action(&s, ACT_FORWARD, 1);
	cmd_action(&s, ACT_BACK, 1);
	cmd_action(&s, ACT_TURN_LEFT, 1);
	cmd_action(&s, ACT_TURN_RIGHT, 1);
	cmd_build(&s, &c);
	assert_int_equal(c.forward, 0);
	assert_int_equal(c.turn, 0);
}

static void tap_within_one_tick_still_presses(void **state)
{
	struct cmd_state s;
	struct sim_cmd c;
	(void)state;
	cmd_reset(&s);
	cmd_action(&s, ACT_START, 1);
	cmd_action(&s, ACT_START, 0);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, SIM_BT_START);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, 0);
	/* the weapon change: its own bit, a tap is a press */
	cmd_action(&s, ACT_WEAPON, 1);
	cmd_action(&s, ACT_WEAPON, 0);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, SIM_BT_WEAPON);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, 0);
	/* the look buttons are levels, each its own bit */
	cmd_action(&s, ACT_LOOK_UP, 1);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, SIM_BT_LOOK_UP);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, SIM_BT_LOOK_UP);
	cmd_action(&s, ACT_LOOK_UP, 0);
	cmd_action(&s, ACT_LOOK_DOWN, 1);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, SIM_BT_LOOK_DOWN);
	cmd_action(&s, ACT_LOOK_DOWN, 0);
	cmd_build(&s, &c);
	assert_int_equal(c.buttons, 0);
}

static void each_coin_edge_counts_once(void **state)
{
	struct cmd_state s;
	struct sim_cmd c;
	(void)state;
	cmd_reset(&s);
	for (int i = 0; i < 3; i++) {
		cmd_action(&s, ACT_COIN, 1);
		cmd_action(&s, ACT_COIN, 0);
	}
	cmd_build(&s, &c);
	assert_int_equal(c.coins, 3);
	/* a coin held across ticks is one coin, not one per tick */
	cmd_action(&s, ACT_COIN, 1);
	cmd_build(&s, &c);
	assert_int_equal(c.coins, 1);
	cmd_build(&s, &c);
	assert_int_equal(c.coins, 0);
}

static void two_controls_hold_one_action_until_both_release(void **state)
{
	struct cmd_state s;
	struct sim_cmd c;
	(void)state;
	cmd_reset(&s);
	cmd_action(&s, ACT_FORWARD, 1);
	cmd_action(&s, ACT_FORWARD, 1);
	cmd_action(&s, ACT_FORWARD, 0);
	cmd_build(&s, &c);
	assert_int_equal(c.forward, CMD_MOVE);
	cmd_action(&s, ACT_FORWARD, 0);
	cmd_build(&s, &c);
	assert_int_equal(c.forward, 0);
	/* a stray release does not underflow into a held state */
	cmd_action(&s, ACT_FORWARD, 0);
	cmd_build(&s, &c);
	assert_int_equal(c.forward, 0);
}

static void out_of_range_action_is_ignored(void **state)
{
	struct cmd_state s;
	struct sim_cmd c;
	(void)state;
	cmd_reset(&s);
	cmd_action(&s, -1, 1);
	cmd_action(&s, ACT_COUNT, 1);
	cmd_build(&s, &c);
	assert_int_equal(c.forward | c.side | c.turn | c.buttons | c.coins, 0);
}

static void held_text_names_each_held_action(void **state)
{
	struct cmd_state s;
	char b[64], small[12];
	(void)state;
	cmd_reset(&s);
	assert_string_equal(cmd_held_text(&s, b, sizeof(b)), "none");
	/* a press that was released is not held, though its edge is pending */
	cmd_action(&s, ACT_USE, 1);
	cmd_action(&s, ACT_USE, 0);
	assert_string_equal(cmd_held_text(&s, b, sizeof(b)), "none");
	cmd_action(&s, ACT_TURN_LEFT, 1);
	cmd_action(&s, ACT_FIRE, 1);
	cmd_action(&s, ACT_FIRE, 1);
	/* in the actions' order, each with its count of controls */
	assert_string_equal(cmd_held_text(&s, b, sizeof(b)), "turn_left (1), fire (2)");
	assert_string_equal(cmd_held_text(&s, small, sizeof(small)), "turn_lef...");
	cmd_action(&s, ACT_TURN_LEFT, 0);
	cmd_action(&s, ACT_FIRE, 0);
	cmd_action(&s, ACT_FIRE, 0);
	assert_string_equal(cmd_held_text(&s, b, sizeof(b)), "none");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(idle_gives_zero_command),
		cmocka_unit_test(held_actions_map_to_axes_and_buttons),
		cmocka_unit_test(opposite_actions_cancel),
		cmocka_unit_test(tap_within_one_tick_still_presses),
		cmocka_unit_test(each_coin_edge_counts_once),
		cmocka_unit_test(two_controls_hold_one_action_until_both_release),
		cmocka_unit_test(out_of_range_action_is_ignored),
		cmocka_unit_test(held_text_names_each_held_action),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
