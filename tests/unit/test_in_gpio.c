/*
 * Tests of the GPIO backend (input/in_gpio.c): the device spec parser and
 * opens that cannot succeed here. Reading real lines needs a gpiochip
 * (gpio-sim in the VM tests); the debounce, coin and output timing behind
 * it are tested in test_deb and test_gpo. Expected key codes are MAME's
 * default layout as the kernel names it.
 */
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>
#include <linux/input-event-codes.h>

#include "input/in_gpio.h"

#define MS(x) ((uint64_t)(x) * 1000000u)

static void test_spec_with_chip_roles_and_outputs(void **state)
{
	struct in_gpio_spec s;
	char why[200];

	(void)state;
	assert_int_equal(in_gpio_parse_spec("gpio:gpiochip0:5=coin,6=start,7=p1_fire;meter=12;"
					    "lamp_start=13",
					    &s, why, sizeof(why)),
			 0);
	assert_string_equal(s.chip, "gpiochip0");
	assert_int_equal(s.nin, 3);
	assert_int_equal(s.in[0].offset, 5);
	assert_int_equal(s.in[0].code, KEY_5);
	assert_int_equal(s.in[0].coin, 1);
	assert_int_equal(s.in[1].code, KEY_1);
	assert_int_equal(s.in[1].coin, 0);
	assert_int_equal(s.in[2].code, KEY_LEFTCTRL);
	assert_int_equal(s.meter.offset, 12);
	assert_int_equal(s.lamp_start.offset, 13);
	/* defaults */
	assert_int_equal(s.active_low, 1);
	assert_int_equal(s.bias, IN_GPIO_BIAS_PULL_UP);
	assert_int_equal(s.out_active_low, 0);
	assert_true(s.holdoff_ns == MS(5));
	assert_true(s.coin_min_ns == MS(10) && s.coin_max_ns == MS(250));
	assert_true(s.meter_ns == MS(50) && s.blink_ns == MS(250));
}

static void test_spec_by_line_name_keys_and_options(void **state)
{
	struct in_gpio_spec s;
	char why[200];

	(void)state;
	assert_int_equal(in_gpio_parse_spec(" COIN1 = coin2 , P1-UP=p1_up,START_1=KEY_E,x.9=space ;"
					    " active=high; bias=pull-down; out_active=low;"
					    "holdoff_ms=8;coin_min_ms=20;coin_max_ms=120;"
					    "meter_ms=80;blink_ms=400;meter=METER",
					    &s, why, sizeof(why)),
			 0);
	assert_string_equal(s.chip, "");
	assert_int_equal(s.nin, 4);
	assert_string_equal(s.in[0].name, "COIN1");
	assert_int_equal(s.in[0].offset, -1);
	assert_int_equal(s.in[0].code, KEY_6);
	assert_int_equal(s.in[0].coin, 1);
	assert_string_equal(s.in[1].name, "P1-UP");
	assert_int_equal(s.in[1].code, KEY_UP);
	assert_int_equal(s.in[2].code, KEY_E);
	assert_string_equal(s.in[3].name, "x.9");
	assert_int_equal(s.in[3].code, KEY_SPACE);
	assert_string_equal(s.meter.name, "METER");
	assert_int_equal(s.active_low, 0);
	assert_int_equal(s.bias, IN_GPIO_BIAS_PULL_DOWN);
	assert_int_equal(s.out_active_low, 1);
	assert_true(s.holdoff_ns == MS(8));
	assert_true(s.coin_min_ns == MS(20) && s.coin_max_ns == MS(120));
	assert_true(s.meter_ns == MS(80) && s.blink_ns == MS(400));
	/* every role of the MAME layout */
	assert_int_equal(in_gpio_parse_spec("gpio:c:1=p2_up,2=p2_down,3=p2_left,4=p2_right,"
					    "5=p2_button1,6=p2_button4,7=p1_button6,8=service,"
					    "9=test,10=tilt,11=start2",
					    &s, why, sizeof(why)),
			 0);
	assert_int_equal(s.in[0].code, KEY_R);
	assert_int_equal(s.in[1].code, KEY_F);
	assert_int_equal(s.in[2].code, KEY_D);
	assert_int_equal(s.in[3].code, KEY_G);
	assert_int_equal(s.in[4].code, KEY_A);
	assert_int_equal(s.in[5].code, KEY_W);
	assert_int_equal(s.in[6].code, KEY_X);
	assert_int_equal(s.in[7].code, KEY_9);
	assert_int_equal(s.in[8].code, KEY_F2);
	assert_int_equal(s.in[9].code, KEY_T);
	assert_int_equal(s.in[10].code, KEY_2);
}

static void test_spec_errors(void **state)
{
	static const struct { const char *spec, *why; } bad[] = {
		{ NULL, "a GPIO device needs a spec (gpio:CHIP:LINE=ROLE,...)" },
		{ "gpio:", "a GPIO device needs a spec (gpio:CHIP:LINE=ROLE,...)" },
		{ "gpio:gpiochip0:", "no lines in GPIO spec" },
		{ "gpio:5=coin", "line offset 5 needs a chip (gpio:CHIP:...)" },
		{ "gpio:COIN=coin;lamp_start=3", "line offset 3 needs a chip (gpio:CHIP:...)" },
		{ "gpio:c:5=jump", "unknown role or key 'jump'" },
		{ "gpio:c:5", "bad line '5' (LINE=ROLE with LINE an offset or a name)" },
		{ "gpio:c:a b=coin", "bad line 'a b=coin' (LINE=ROLE with LINE an offset or a name)" },
		{ "gpio:c:99999=coin", "bad line '99999=coin' (LINE=ROLE with LINE an offset or a name)" },
		{ "gpio:c:5=coin,5=start", "line '5' given twice" },
		{ "gpio:c:5=coin;meter=5", "an output line is also used for something else" },
		{ "gpio:c:5=coin;meter=6;lamp_start=6", "an output line is also used for something else" },
		{ "gpio:c:5=coin;colour=red", "bad option 'colour=red'" },
		{ "gpio:c:5=coin;holdoff_ms=0", "bad option 'holdoff_ms=0'" },
		{ "gpio:c:5=coin;bias=strong", "bad option 'bias=strong'" },
		{ "gpio:c:5=coin;active=yes", "bad option 'active=yes'" },
		{ "gpio:c:5=coin;meter", "bad option 'meter'" },
		{ "gpio:c:5=coin;coin_min_ms=300", "coin_min_ms above coin_max_ms" },
		{ ":5=coin", "bad chip ''" },
	};
	struct in_gpio_spec s;
	char why[200];

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		assert_int_equal(in_gpio_parse_spec(bad[i].spec, &s, why, sizeof(why)), -EINVAL);
		assert_string_equal(why, bad[i].why);
	}
}

static void test_spec_line_limit(void **state)
{
	char spec[1024] = "gpio:c:";
	struct in_gpio_spec s;
	char why[200];
	size_t n = strlen(spec);

	(void)state;
	for (int i = 0; i < IN_GPIO_MAX_LINES; i++)
		n += (size_t)snprintf(spec + n, sizeof(spec) - n, "%s%d=start", i ? "," : "", i);
	assert_int_equal(in_gpio_parse_spec(spec, &s, why, sizeof(why)), 0);
	assert_int_equal(s.nin, IN_GPIO_MAX_LINES);
	snprintf(spec + n, sizeof(spec) - n, ",99=start");
	assert_int_equal(in_gpio_parse_spec(spec, &s, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "more than 32 input lines");
}

static void test_open_missing_chip_says_why(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	struct gpo_state st = { 0 };
	char why[256];

	(void)state;
	assert_int_equal(in_gpio.open("gpio:/nonexistent/gpiochip99:5=coin", &d, why, sizeof(why)),
			 -ENODEV);
	assert_null(d);
	assert_string_equal(why, "/nonexistent/gpiochip99: No such file or directory");
	assert_int_equal(in_gpio.open("gpio:c:5=jump", &d, why, sizeof(why)), -EINVAL);
	assert_int_equal(in_gpio_update(NULL, &st, 0), -EINVAL);
	in_gpio.close(NULL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_spec_with_chip_roles_and_outputs),
		cmocka_unit_test(test_spec_by_line_name_keys_and_options),
		cmocka_unit_test(test_spec_errors),
		cmocka_unit_test(test_spec_line_limit),
		cmocka_unit_test(test_open_missing_chip_says_why),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
