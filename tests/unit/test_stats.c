/* Tests for app/stats.c: frames presented late (after the next tick was
 * due), present-to-flip times, and input latency waiting for a present. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "app/stats.h"

static struct stats st;

static void late_frames_are_those_ending_after_the_next_tick(void **state)
{
	static const char *const names[] = { "evdev" };
	(void)state;

	stats_init(&st, names, 1);
	stats_presented(&st, 100, 200, 300);   /* before the next tick */
	stats_presented(&st, 100, 300, 300);   /* exactly at it: still in its tick */
	stats_presented(&st, 100, 301, 300);   /* after it: late */
	stats_presented(&st, 100, 5000, 0);    /* not paced: never late */
	assert_int_equal(st.frames, 4);
	assert_int_equal(st.late, 1);
	assert_int_equal(st.frame_time.count, 4);
}

static void flips_go_into_their_own_series(void **state)
{
	(void)state;

	stats_init(&st, NULL, 0);
	stats_flip(&st, 1000000, 5000000);     /* 4 ms */
	stats_flip(&st, 2000000, 4000000);     /* 2 ms */
	stats_flip(&st, 9000000, 8000000);     /* clock skew: 0, never negative */
	assert_int_equal(st.flip.count, 3);
	assert_int_equal(lat_percentile(&st.flip, 100), 4000);
	assert_int_equal(lat_percentile(&st.flip, 50), 2000);
	assert_int_equal(lat_percentile(&st.flip, 1), 0);
	/* flips are not frames and carry no input latency */
	assert_int_equal(st.frames, 0);
	assert_int_equal(st.latency.count, 0);
}

static void input_waits_for_the_next_present(void **state)
{
	static const char *const names[] = { "evdev", "hid" };
	(void)state;

	stats_init(&st, names, 2);
	stats_input(&st, 1, 1000000);
	stats_input(&st, 1, 3000000);          /* a later event of the same frame */
	stats_presented(&st, 4000000, 6000000, 0);
	assert_int_equal(st.latency.count, 1);
	assert_int_equal(lat_percentile(&st.latency, 50), 5000);   /* from the first event */
	assert_int_equal(st.src[1].count, 1);
	assert_int_equal(st.src[0].count, 0);
	stats_presented(&st, 7000000, 8000000, 0);
	assert_int_equal(st.latency.count, 1);  /* nothing was waiting */
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(late_frames_are_those_ending_after_the_next_tick),
		cmocka_unit_test(flips_go_into_their_own_series),
		cmocka_unit_test(input_waits_for_the_next_present),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
