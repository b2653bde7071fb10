/*
 * in_keys: key names to kernel codes and back. Expected codes come from
 * the kernel's linux/input-event-codes.h, independent of libevdev's table.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include <linux/input-event-codes.h>

#include "input/in.h"

static void test_full_names_any_case(void **state)
{
	(void)state;
	assert_int_equal(in_key_from_name("KEY_UP"), KEY_UP);
	assert_int_equal(in_key_from_name("key_up"), KEY_UP);
	assert_int_equal(in_key_from_name("Key_LeftCtrl"), KEY_LEFTCTRL);
	assert_int_equal(in_key_from_name("KEY_F12"), KEY_F12);
}

static void test_short_names_letters_and_digits(void **state)
{
	(void)state;
	assert_int_equal(in_key_from_name("up"), KEY_UP);
	assert_int_equal(in_key_from_name("DOWN"), KEY_DOWN);
	assert_int_equal(in_key_from_name("leftctrl"), KEY_LEFTCTRL);
	assert_int_equal(in_key_from_name("w"), KEY_W);
	assert_int_equal(in_key_from_name("W"), KEY_W);
	assert_int_equal(in_key_from_name("5"), KEY_5);
	assert_int_equal(in_key_from_name("0"), KEY_0);
	assert_int_equal(in_key_from_name("comma"), KEY_COMMA);
	assert_int_equal(in_key_from_name("f2"), KEY_F2);
}

static void test_aliases(void **state)
{
	(void)state;
	assert_int_equal(in_key_from_name("space"), KEY_SPACE);
	assert_int_equal(in_key_from_name("enter"), KEY_ENTER);
	assert_int_equal(in_key_from_name("Return"), KEY_ENTER);
	assert_int_equal(in_key_from_name("esc"), KEY_ESC);
	assert_int_equal(in_key_from_name("escape"), KEY_ESC);
	assert_int_equal(in_key_from_name("ctrl"), KEY_LEFTCTRL);
	assert_int_equal(in_key_from_name("alt"), KEY_LEFTALT);
	assert_int_equal(in_key_from_name("shift"), KEY_LEFTSHIFT);
	assert_int_equal(in_key_from_name("tab"), KEY_TAB);
	assert_int_equal(in_key_from_name("backspace"), KEY_BACKSPACE);
}

static void test_buttons(void **state)
{
	(void)state;
	assert_int_equal(in_key_from_name("BTN_SOUTH"), BTN_SOUTH);
	assert_int_equal(in_key_from_name("btn_a"), BTN_A);
	assert_int_equal(in_key_from_name("BTN_TRIGGER"), BTN_TRIGGER);
	assert_int_equal(in_key_from_name("BTN_0"), BTN_0);
}

static void test_unknown_names(void **state)
{
	char longname[200];

	(void)state;
	memset(longname, 'a', sizeof(longname) - 1);
	longname[sizeof(longname) - 1] = '\0';
	assert_int_equal(in_key_from_name(NULL), -1);
	assert_int_equal(in_key_from_name(""), -1);
	assert_int_equal(in_key_from_name("nosuchkey"), -1);
	assert_int_equal(in_key_from_name("KEY_"), -1);
	assert_int_equal(in_key_from_name("KEY_UP "), -1);
	assert_int_equal(in_key_from_name("up down"), -1);
	assert_int_equal(in_key_from_name("KEY_UP\n"), -1);
	assert_int_equal(in_key_from_name("key-up"), -1);
	assert_int_equal(in_key_from_name(longname), -1);
	/* In libevdev's table, but not keys. */
	assert_int_equal(in_key_from_name("KEY_RESERVED"), -1);
	assert_int_equal(in_key_from_name("KEY_MAX"), -1);
	assert_int_equal(in_key_from_name("reserved"), -1);
}

static void test_names_of_codes(void **state)
{
	(void)state;
	assert_string_equal(in_key_name(KEY_UP), "KEY_UP");
	assert_string_equal(in_key_name(KEY_ESC), "KEY_ESC");
	assert_string_equal(in_key_name(KEY_5), "KEY_5");
	assert_string_equal(in_key_name(BTN_SOUTH), "BTN_SOUTH");
	assert_null(in_key_name(KEY_RESERVED));
	assert_null(in_key_name(KEY_MAX));
	assert_null(in_key_name(KEY_MAX + 1));
	assert_null(in_key_name(-1));
}

static void test_every_named_code_round_trips(void **state)
{
	int named = 0;

	(void)state;
	for (int code = 1; code < KEY_MAX; code++) {
		const char *n = in_key_name(code);

		if (!n)
			continue;
		named++;
		assert_int_equal(in_key_from_name(n), code);
	}
	/* Letters, digits, F-keys, arrows and pad buttons at least. */
	assert_true(named > 300);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_full_names_any_case),
		cmocka_unit_test(test_short_names_letters_and_digits),
		cmocka_unit_test(test_aliases),
		cmocka_unit_test(test_buttons),
		cmocka_unit_test(test_unknown_names),
		cmocka_unit_test(test_names_of_codes),
		cmocka_unit_test(test_every_named_code_round_trips),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
