/* Tests for app/lat.c: timing statistics. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "app/lat.h"

static struct lat_series s;

static void empty_series_reports_no_samples(void **state)
{
	char buf[128];
	(void)state;
	lat_reset(&s);
	assert_int_equal(lat_percentile(&s, 50), 0);
	lat_format(&s, "x", buf, sizeof(buf));
	assert_string_equal(buf, "x: no samples");
}

static void percentiles_use_nearest_rank(void **state)
{
	(void)state;
	lat_reset(&s);
	/* 1..100 ms added in reverse: p50 is the 50th smallest, p99 the 99th */
	for (int i = 100; i >= 1; i--)
		lat_add_ns(&s, (uint64_t)i * 1000000u);
	assert_int_equal(lat_percentile(&s, 50), 50000);
	assert_int_equal(lat_percentile(&s, 99), 99000);
	assert_int_equal(lat_percentile(&s, 100), 100000);
	assert_int_equal(lat_percentile(&s, 0), 1000);
	assert_int_equal(s.max_us, 100000);
}

static void ring_keeps_only_recent_samples_but_max_is_all_time(void **state)
{
	(void)state;
	lat_reset(&s);
	lat_add_ns(&s, 900000000u); /* 900 ms, then pushed out of the ring */
	for (int i = 0; i < LAT_SAMPLES; i++)
		lat_add_ns(&s, 2000000u);
	assert_int_equal(lat_percentile(&s, 100), 2000);
	assert_int_equal(s.max_us, 900000);
	assert_int_equal(s.count, LAT_SAMPLES + 1);
}

static void format_prints_milliseconds(void **state)
{
	char buf[160];
	(void)state;
	lat_reset(&s);
	lat_add_ns(&s, 1250000u);
	lat_format(&s, "frame", buf, sizeof(buf));
	assert_string_equal(buf, "frame p50 1.25 ms p99 1.25 ms max 1.25 ms (n 1)");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(empty_series_reports_no_samples),
		cmocka_unit_test(percentiles_use_nearest_rank),
		cmocka_unit_test(ring_keeps_only_recent_samples_but_max_is_all_time),
		cmocka_unit_test(format_prints_milliseconds),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
