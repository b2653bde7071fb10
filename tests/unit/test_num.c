/* Tests for engine/core/num.c: checked decimal numbers. */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/num.h"

static void decimal_numbers_with_a_sign_parse(void **state)
{
	int64_t v = 7;
	(void)state;
	assert_int_equal(num_parse("0", 0, 10, &v), 0);
	assert_int_equal(v, 0);
	assert_int_equal(num_parse("42", 0, 100, &v), 0);
	assert_int_equal(v, 42);
	assert_int_equal(num_parse("+42", 0, 100, &v), 0);
	assert_int_equal(v, 42);
	assert_int_equal(num_parse("-42", -100, 100, &v), 0);
	assert_int_equal(v, -42);
	assert_int_equal(num_parse("007", 0, 10, &v), 0);     /* decimal, not octal */
	assert_int_equal(v, 7);
	assert_int_equal(num_parse("9223372036854775807", INT64_MIN, INT64_MAX, &v), 0);
	assert_true(v == INT64_MAX);
	assert_int_equal(num_parse("-9223372036854775808", INT64_MIN, INT64_MAX, &v), 0);
	assert_true(v == INT64_MIN);
}

/* Anything but a sign and digits is not a number; *out is left alone. */
static void other_text_is_einval(void **state)
{
	static const char *const bad[] = { "", "+", "-", " 5", "5 ", "\t5", "5\n", "0x10",
					   "12a", "1.5", "1e3", "--5", "+-5", "five" };
	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		int64_t v = 7;
		if (num_parse(bad[i], INT64_MIN, INT64_MAX, &v) != -EINVAL)
			fail_msg("'%s' was taken", bad[i]);
		assert_int_equal(v, 7);
	}
}

/* The ends of the range are in; one past either end, or past int64, is
 * -ERANGE; *out is left alone. */
static void the_range_is_inclusive_and_checked(void **state)
{
	int64_t v = 7;
	(void)state;
	assert_int_equal(num_parse("1", 1, 1000, &v), 0);
	assert_int_equal(num_parse("1000", 1, 1000, &v), 0);
	assert_int_equal(v, 1000);
	v = 7;
	assert_int_equal(num_parse("0", 1, 1000, &v), -ERANGE);
	assert_int_equal(num_parse("1001", 1, 1000, &v), -ERANGE);
	assert_int_equal(num_parse("-1", 0, 4294967294, &v), -ERANGE);
	assert_int_equal(num_parse("4294967295", 0, 4294967294, &v), -ERANGE);
	assert_int_equal(num_parse("9223372036854775808", INT64_MIN, INT64_MAX, &v), -ERANGE);
	assert_int_equal(num_parse("-9223372036854775809", INT64_MIN, INT64_MAX, &v), -ERANGE);
	assert_int_equal(num_parse("99999999999999999999999", 0, 10, &v), -ERANGE);
	assert_int_equal(v, 7);
	/* text after a huge number is still not a number */
	assert_int_equal(num_parse("99999999999999999999999x", 0, 10, &v), -EINVAL);
}

/* Every byte value: the sixteen digits of each case give 0..15 (a-f and
 * A-F alike), every other byte -1. */
static void hex_digits_and_nothing_else(void **state)
{
	(void)state;
	for (int c = 0; c < 256; c++) {
		const char *lo = "0123456789abcdef", *up = "0123456789ABCDEF";
		const char *a = c ? strchr(lo, c) : NULL, *b = c ? strchr(up, c) : NULL;
		int want = a ? (int)(a - lo) : b ? (int)(b - up) : -1;

		if (num_hex(c) != want)
			fail_msg("byte %d: %d, want %d", c, num_hex(c), want);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(decimal_numbers_with_a_sign_parse),
		cmocka_unit_test(other_text_is_einval),
		cmocka_unit_test(the_range_is_inclusive_and_checked),
		cmocka_unit_test(hex_digits_and_nothing_else),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
