/*
 * out: every open input device with outputs (in_backend.outputs) gets the
 * game's coins, credits and whether a game is being played, once per tick
 * at the slots' clock; devices without outputs and closed slots are left
 * alone; a device whose outputs went away is dropped with its controls
 * released, as after a read's -ENODEV. Fake backends (unit test only).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "app/out.h"
#include "engine/game/sim.h"
#include "slot_fixture.h"

static struct sim sim;

static const struct slot_kind kinds[] = { { &fake_lines, NULL, 0, 1 }, { &fake_be, NULL, 0, 1 } };

static void outputs_follow_the_game(void **state)
{
	(void)state;
	slot_add(&set, kinds, 1, NULL, 0);     /* no outputs: skipped */
	slot_add(&set, kinds, 0, NULL, 0);
	memset(&sim, 0, sizeof(sim));
	clock_ns = 777;
	sim.coins_total = 7;
	sim.credits = 3;
	sim.mode = SIM_ATTRACT;
	out_update(&set, &sim);
	assert_int_equal(fk.outputs_calls, 1);
	assert_int_equal(fk.got.coins_total, 7);
	assert_int_equal(fk.got.credits, 3);
	assert_int_equal(fk.got.playing, 0);
	assert_int_equal(fk.at, 777);
	/* playing: every mode but attract and the continue countdown */
	sim.mode = SIM_PLAY;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 1);
	sim.mode = SIM_GAMEOVER;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 0);
	sim.mode = SIM_INITIALS;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 1);
	assert_int_equal(fk.outputs_calls, 4);
}

static void a_device_whose_outputs_went_away_is_dropped(void **state)
{
	(void)state;
	slot_add(&set, kinds, 0, NULL, 0);
	memset(&sim, 0, sizeof(sim));
	fake_key(6, 1);            /* coin held */
	slot_read(&set);
	seen[0] = '\0';
	fk.outputs_rc = -ENODEV;
	out_update(&set, &sim);
	assert_string_equal(seen, "released 6 gone ");
	assert_int_equal(fk.closes, 1);
	assert_null(set.s[0].dev);
	/* closed: no outputs until it is back */
	out_update(&set, &sim);
	assert_int_equal(fk.outputs_calls, 1);
	/* another error is not a drop */
	fk.outputs_rc = -EIO;
	slot_close(&set);
	slot_init(&set, &fake_hooks, NULL);
	slot_add(&set, kinds, 0, NULL, 0);
	out_update(&set, &sim);
	assert_non_null(set.s[0].dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(outputs_follow_the_game, fake_setup, fake_teardown),
		cmocka_unit_test_setup_teardown(a_device_whose_outputs_went_away_is_dropped, fake_setup,
						fake_teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
