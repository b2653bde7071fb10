/*
 * Tests of the output-line scheduler (input/gpo.c): coin meter pulses and
 * the start lamp, stepped at the 60 Hz tick the daemon calls it at.
 * Expected pulse counts and widths follow from gpo.h: a pulse starts at
 * the first tick at or after the end of the previous gap and lasts until
 * the first tick at or after on_ns later.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "input/gpo.h"

#define MS(x) ((uint64_t)(x) * 1000000u)
#define TICK 16666667ull

struct trace {
	int pulses;
	uint64_t min_on, max_on, min_off;
	uint64_t rise, fall;
	int level;
};

static void step(struct gpo *g, struct gpo_state *s, uint64_t t, struct trace *tr, int *lamp)
{
	int meter;

	gpo_update(g, s, t, &meter, lamp);
	if (meter && !tr->level) {
		tr->pulses++;
		if (tr->fall && t - tr->fall < tr->min_off)
			tr->min_off = t - tr->fall;
		tr->rise = t;
	} else if (!meter && tr->level) {
		uint64_t w = t - tr->rise;

		if (w < tr->min_on)
			tr->min_on = w;
		if (w > tr->max_on)
			tr->max_on = w;
		tr->fall = t;
	}
	tr->level = meter;
}

static void test_each_new_coin_gives_one_meter_pulse(void **state)
{
	struct gpo g;
	struct gpo_state s = { .coins_total = 3 };
	struct trace tr = { .min_on = UINT64_MAX, .min_off = UINT64_MAX };
	int lamp;

	(void)state;
	gpo_init(&g, 0, 0, 0);
	/* coins counted before the first update are history: no pulse */
	for (uint64_t t = MS(1000); t < MS(2000); t += TICK)
		step(&g, &s, t, &tr, &lamp);
	assert_int_equal(tr.pulses, 0);
	/* five coins at once (a quick burst), then one more later */
	s.coins_total = 8;
	for (uint64_t t = MS(2000); t < MS(3000); t += TICK)
		step(&g, &s, t, &tr, &lamp);
	s.coins_total = 9;
	for (uint64_t t = MS(3000); t < MS(4000); t += TICK)
		step(&g, &s, t, &tr, &lamp);
	assert_int_equal(tr.pulses, 6);
	assert_int_equal(gpo_queued(&g), 0);
	assert_int_equal(tr.level, 0);
	/* 50 ms at 60 Hz: 3 or 4 ticks energised, at least 3 ticks off */
	assert_true(tr.min_on >= MS(50) && tr.max_on <= MS(67));
	assert_true(tr.min_off >= MS(50));
}

static void test_count_restart_queues_nothing(void **state)
{
	struct gpo g;
	struct gpo_state s = { .coins_total = 10 };
	struct trace tr = { .min_on = UINT64_MAX, .min_off = UINT64_MAX };
	int lamp;

	(void)state;
	gpo_init(&g, MS(30), MS(30), 0);
	step(&g, &s, MS(0), &tr, &lamp);
	s.coins_total = 0;
	step(&g, &s, TICK, &tr, &lamp);
	s.coins_total = 1;
	for (uint64_t t = 2 * TICK; t < MS(500); t += TICK)
		step(&g, &s, t, &tr, &lamp);
	assert_int_equal(tr.pulses, 1);
}

static void test_start_lamp_blinks_only_with_credits_outside_play(void **state)
{
	struct gpo g;
	struct gpo_state s = { .coins_total = 0, .credits = 0 };
	int meter, lamp, on = 0, off = 0;

	(void)state;
	gpo_init(&g, 0, 0, 0);
	gpo_update(&g, &s, MS(100), &meter, &lamp);
	assert_int_equal(lamp, 0);
	s.credits = 1;
	/* 250 ms halves: on in [0, 250), off in [250, 500), from the clock */
	gpo_update(&g, &s, MS(1000), &meter, &lamp);
	assert_int_equal(lamp, 1);
	gpo_update(&g, &s, MS(1249), &meter, &lamp);
	assert_int_equal(lamp, 1);
	gpo_update(&g, &s, MS(1250), &meter, &lamp);
	assert_int_equal(lamp, 0);
	for (uint64_t t = MS(2000); t < MS(4000); t += TICK) {
		gpo_update(&g, &s, t, &meter, &lamp);
		on += lamp;
		off += !lamp;
	}
	assert_true(on > 50 && off > 50);
	s.playing = 1;
	gpo_update(&g, &s, MS(5000), &meter, &lamp);
	assert_int_equal(lamp, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_each_new_coin_gives_one_meter_pulse),
		cmocka_unit_test(test_count_restart_queues_nothing),
		cmocka_unit_test(test_start_lamp_blinks_only_with_credits_outside_play),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
