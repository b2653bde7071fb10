/* Tests for input/txt.c: printf-style text into a caller's buffer. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "input/txt.h"

static void set_formats_cuts_and_skips_an_absent_buffer(void **state)
{
	char b[8];
	(void)state;
	memset(b, 'x', sizeof(b));
	txt_set(b, sizeof(b), "%s %d", "ab", 12);
	assert_string_equal(b, "ab 12");
	txt_set(b, sizeof(b), "%s", "0123456789");      /* cut, terminated */
	assert_string_equal(b, "0123456");
	txt_set(b, sizeof(b), "new");                   /* replaces, not appends */
	assert_string_equal(b, "new");
	txt_set(NULL, 8, "ignored");
	txt_set(b, 0, "ignored");
	assert_string_equal(b, "new");
}

/* What fits is appended; n counts everything, so the caller learns the
 * size the whole text needs. */
static void put_appends_and_counts_past_the_end(void **state)
{
	char b[10];
	struct txt t = { .buf = b, .len = sizeof(b) };
	(void)state;
	memset(b, 'x', sizeof(b));
	txt_put(&t, "%s", "abc");
	txt_put(&t, "-%d", 42);
	assert_string_equal(b, "abc-42");
	assert_int_equal(t.n, 6);
	txt_put(&t, "%s", "0123456789");
	assert_int_equal(t.n, 16);
	assert_string_equal(b, "abc-42012");          /* the first len - 1 bytes */
	txt_put(&t, "more");
	assert_int_equal(t.n, 20);
	assert_string_equal(b, "abc-42012");
}

static void put_without_a_buffer_only_measures(void **state)
{
	struct txt t = { 0 };
	(void)state;
	txt_put(&t, "%s=%d\n", "key", 123);
	txt_put(&t, "%s", "");
	assert_int_equal(t.n, 8);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(set_formats_cuts_and_skips_an_absent_buffer),
		cmocka_unit_test(put_appends_and_counts_past_the_end),
		cmocka_unit_test(put_without_a_buffer_only_measures),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
