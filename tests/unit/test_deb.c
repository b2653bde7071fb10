/*
 * Tests of switch debounce and coin pulse counting (input/deb.c) against
 * bounce patterns written after what mechanical switches do: contacts
 * chatter for a few milliseconds at each make and break, at irregular
 * intervals. Every expected event and its time follows from the rules in
 * deb.h: the first edge reported at once with its own time, the rest of a
 * hold-off ignored, a settled level reported when the hold-off ends.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "input/deb.h"

#define US(x) ((uint64_t)(x) * 1000u)
#define MS(x) ((uint64_t)(x) * 1000000u)
#define T0 MS(1000)
#define TICK 16666667ull   /* 60 Hz */

/* A switch bouncing 8 times over 3 ms: 17 edges alternating from the new
 * level, the last one at 3.0 ms leaving the new level. */
static const uint32_t bounce_us[17] = { 0, 120, 310, 420, 700, 760, 1050, 1300, 1390,
					1700, 1850, 2100, 2250, 2500, 2620, 2900, 3000 };

struct log {
	struct deb_ev ev[64];
	int n;
};

static void edge(struct deb *d, uint64_t t, int level, struct log *l)
{
	struct deb_ev e[2];
	int n = deb_edge(d, t, level, e);

	for (int i = 0; i < n; i++) {
		assert_true(l->n < 64);
		l->ev[l->n++] = e[i];
	}
}

static void poll_until(struct deb *d, uint64_t from, uint64_t to, uint64_t step, struct log *l)
{
	for (uint64_t t = from; t <= to; t += step) {
		struct deb_ev e;

		if (deb_poll(d, t, &e)) {
			assert_true(l->n < 64);
			l->ev[l->n++] = e;
		}
	}
}

/* Feeds the bounce pattern for a change to level at t, polling every
 * 100 us while it runs (a read between bounces must not matter). */
static void bounce(struct deb *d, uint64_t t, int level, struct log *l)
{
	for (int k = 0; k < 17; k++) {
		poll_until(d, k ? t + US(bounce_us[k - 1]) : t, t + US(bounce_us[k]), US(100), l);
		edge(d, t + US(bounce_us[k]), (k % 2 == 0) ? level : !level, l);
	}
}

static void expect(const struct log *l, int i, uint64_t t, int level)
{
	assert_true(i < l->n);
	assert_true(l->ev[i].time_ns == t);
	assert_int_equal(l->ev[i].level, level);
}

static void test_bouncing_press_and_release_report_once_each_without_delay(void **state)
{
	struct deb d;
	struct log l = { .n = 0 };

	(void)state;
	deb_init(&d, 0, 0);
	bounce(&d, T0, 1, &l);
	poll_until(&d, T0 + MS(3), T0 + MS(200), US(500), &l);
	bounce(&d, T0 + MS(200), 0, &l);
	poll_until(&d, T0 + MS(203), T0 + MS(400), US(500), &l);
	assert_int_equal(l.n, 2);
	expect(&l, 0, T0, 1);               /* the first edge's own time */
	expect(&l, 1, T0 + MS(200), 0);
}

static void test_long_hold_polled_every_tick(void **state)
{
	struct deb d;
	struct log l = { .n = 0 };

	(void)state;
	deb_init(&d, 0, 0);
	bounce(&d, T0, 1, &l);
	poll_until(&d, T0 + MS(4), T0 + MS(10000), TICK, &l);
	assert_int_equal(deb_level(&d), 1);
	bounce(&d, T0 + MS(10000), 0, &l);
	poll_until(&d, T0 + MS(10004), T0 + MS(11000), TICK, &l);
	assert_int_equal(l.n, 2);
	expect(&l, 0, T0, 1);
	expect(&l, 1, T0 + MS(10000), 0);
}

static void test_tap_shorter_than_the_holdoff_is_released_at_its_end(void **state)
{
	struct deb d;
	struct log l = { .n = 0 };

	(void)state;
	deb_init(&d, 0, 0);
	edge(&d, T0, 1, &l);
	edge(&d, T0 + MS(2), 0, &l);
	poll_until(&d, T0 + MS(2), T0 + MS(4), US(100), &l);
	assert_int_equal(l.n, 1);
	poll_until(&d, T0 + MS(5), T0 + MS(5), 1, &l);
	assert_int_equal(l.n, 2);
	expect(&l, 0, T0, 1);
	expect(&l, 1, T0 + MS(2), 0);       /* stamped with the edge that set it */
}

static void test_settled_change_is_reported_before_the_next_edge(void **state)
{
	/* Press, a release inside the hold-off, no poll, a new press 50 ms
	 * later: release and press are both reported, in order. */
	struct deb d;
	struct log l = { .n = 0 };

	(void)state;
	deb_init(&d, 0, 0);
	edge(&d, T0, 1, &l);
	edge(&d, T0 + MS(3), 0, &l);
	edge(&d, T0 + MS(50), 1, &l);
	assert_int_equal(l.n, 3);
	expect(&l, 0, T0, 1);
	expect(&l, 1, T0 + MS(3), 0);
	expect(&l, 2, T0 + MS(50), 1);
}

static void test_repeated_level_changes_nothing(void **state)
{
	struct deb d;
	struct log l = { .n = 0 };

	(void)state;
	deb_init(&d, 0, 0);
	edge(&d, T0, 1, &l);
	edge(&d, T0 + MS(10), 1, &l);
	edge(&d, T0 + MS(20), 0, &l);
	edge(&d, T0 + MS(30), 0, &l);
	poll_until(&d, T0 + MS(30), T0 + MS(60), MS(1), &l);
	assert_int_equal(l.n, 2);
	expect(&l, 1, T0 + MS(20), 0);
}

static void test_holdoff_is_configurable(void **state)
{
	struct deb d;
	struct log l = { .n = 0 };

	(void)state;
	deb_init(&d, MS(20), 0);
	edge(&d, T0, 1, &l);
	edge(&d, T0 + MS(10), 0, &l);       /* inside 20 ms: bounce */
	edge(&d, T0 + MS(15), 1, &l);
	poll_until(&d, T0 + MS(15), T0 + MS(25), MS(1), &l);
	assert_int_equal(l.n, 1);
	edge(&d, T0 + MS(30), 0, &l);
	assert_int_equal(l.n, 2);
	expect(&l, 1, T0 + MS(30), 0);
	/* a start level of 1 is reported as is */
	deb_init(&d, 0, 1);
	assert_int_equal(deb_level(&d), 1);
}

static void test_settle_trusts_the_line_level_over_a_stale_event(void **state)
{
	/* The last edge event inside the hold-off says released, but the
	 * line reads pressed when the hold-off ends: nothing changes. */
	struct deb d;
	struct log l = { .n = 0 };
	struct deb_ev e;

	(void)state;
	deb_init(&d, 0, 0);
	edge(&d, T0, 1, &l);
	edge(&d, T0 + MS(1), 0, &l);
	assert_int_equal(deb_settle(&d, T0 + MS(5), 1, &e), 0);
	assert_int_equal(deb_level(&d), 1);
	/* released with an event that agrees: stamped with the event's time */
	edge(&d, T0 + MS(100), 0, &l);
	edge(&d, T0 + MS(101), 1, &l);
	edge(&d, T0 + MS(102), 0, &l);
	assert_int_equal(deb_settle(&d, T0 + MS(110), 0, &e), 0);   /* reported at 100 */
	assert_int_equal(l.n, 2);
	expect(&l, 1, T0 + MS(100), 0);
	/* a press whose event was lost: stamped with the time it was read */
	assert_int_equal(deb_settle(&d, T0 + MS(200), 1, &e), 1);
	assert_true(e.time_ns == T0 + MS(200) && e.level == 1);
	/* inside a hold-off the level read changes nothing yet */
	assert_int_equal(deb_settle(&d, T0 + MS(202), 0, &e), 0);
	assert_int_equal(deb_settle(&d, T0 + MS(205), 0, &e), 1);
	assert_true(e.time_ns == T0 + MS(202) && e.level == 0);
}

struct coins {
	int n;
	uint64_t t[8];
};

static void coin_edge(struct deb_coin *c, uint64_t t, int level, struct coins *k)
{
	uint64_t when;

	if (deb_coin_edge(c, t, level, &when)) {
		assert_true(k->n < 8);
		k->t[k->n++] = when;
	}
}

static void coin_poll(struct deb_coin *c, uint64_t from, uint64_t to, struct coins *k)
{
	for (uint64_t t = from; t <= to; t += US(500)) {
		uint64_t when;

		if (deb_coin_poll(c, t, &when)) {
			assert_true(k->n < 8);
			k->t[k->n++] = when;
		}
	}
}

/* A coin pulse of width w at t, bouncing at both ends. */
static void coin_pulse(struct deb_coin *c, uint64_t t, uint64_t w, struct coins *k)
{
	for (int e = 0; e < 2; e++) {
		uint64_t at = t + (e ? w : 0);

		for (int i = 0; i < 17; i++) {
			coin_poll(c, at + (i ? US(bounce_us[i - 1]) : 0), at + US(bounce_us[i]), k);
			coin_edge(c, at + US(bounce_us[i]), (i % 2 == 0) == (e == 0), k);
		}
		coin_poll(c, at + MS(3), at + (e ? MS(40) : w - US(500)), k);
	}
}

static void test_bouncing_50ms_coin_pulse_is_one_coin(void **state)
{
	struct deb_coin c;
	struct coins k = { .n = 0 };

	(void)state;
	deb_coin_init(&c, 0, 0, 0);
	coin_pulse(&c, T0, MS(50), &k);
	assert_int_equal(k.n, 1);
	assert_true(k.t[0] == T0 + MS(50));
	assert_int_equal(c.coins, 1);
	assert_int_equal(c.rejected, 0);
	/* a second coin 100 ms after the first */
	coin_pulse(&c, T0 + MS(100), MS(50), &k);
	assert_int_equal(k.n, 2);
	assert_true(k.t[1] == T0 + MS(150));
}

static void test_noise_spike_and_jam_are_rejected(void **state)
{
	struct deb_coin c;
	struct coins k = { .n = 0 };

	(void)state;
	deb_coin_init(&c, 0, 0, 0);
	/* 200 us spike: reads as a 0.2 ms pulse once the hold-off ends */
	coin_edge(&c, T0, 1, &k);
	coin_edge(&c, T0 + US(200), 0, &k);
	coin_poll(&c, T0 + US(200), T0 + MS(20), &k);
	/* 2 s jam */
	coin_edge(&c, T0 + MS(100), 1, &k);
	coin_poll(&c, T0 + MS(100), T0 + MS(2100), &k);
	coin_edge(&c, T0 + MS(2100), 0, &k);
	assert_int_equal(k.n, 0);
	assert_int_equal(c.coins, 0);
	assert_int_equal(c.rejected, 2);
}

static void test_pulse_width_limits_are_inclusive(void **state)
{
	struct deb_coin c;
	struct coins k = { .n = 0 };

	(void)state;
	deb_coin_init(&c, MS(1), MS(20), MS(40));
	coin_edge(&c, T0, 1, &k);
	coin_edge(&c, T0 + MS(20), 0, &k);                 /* = min */
	coin_edge(&c, T0 + MS(100), 1, &k);
	coin_edge(&c, T0 + MS(140), 0, &k);                /* = max */
	coin_edge(&c, T0 + MS(200), 1, &k);
	coin_edge(&c, T0 + MS(220) - 1, 0, &k);            /* 1 ns short */
	coin_edge(&c, T0 + MS(300), 1, &k);
	coin_edge(&c, T0 + MS(340) + 1, 0, &k);            /* 1 ns long */
	assert_int_equal(k.n, 2);
	assert_true(k.t[0] == T0 + MS(20));
	assert_true(k.t[1] == T0 + MS(140));
	assert_int_equal(c.rejected, 2);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_bouncing_press_and_release_report_once_each_without_delay),
		cmocka_unit_test(test_long_hold_polled_every_tick),
		cmocka_unit_test(test_tap_shorter_than_the_holdoff_is_released_at_its_end),
		cmocka_unit_test(test_settled_change_is_reported_before_the_next_edge),
		cmocka_unit_test(test_repeated_level_changes_nothing),
		cmocka_unit_test(test_holdoff_is_configurable),
		cmocka_unit_test(test_settle_trusts_the_line_level_over_a_stale_event),
		cmocka_unit_test(test_bouncing_50ms_coin_pulse_is_one_coin),
		cmocka_unit_test(test_noise_spike_and_jam_are_rejected),
		cmocka_unit_test(test_pulse_width_limits_are_inclusive),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
