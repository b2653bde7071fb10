/*
 * au_alsa: the ALSA output through libasound2 itself: its "null" device
 * (part of alsa-lib: takes everything, plays nothing) opens with the
 * period and buffer this output asks for (5 and 20 ms) and is written
 * without blocking; a device that does not exist is "no sound card"
 * (-ENODEV with libasound's reason, nothing printed by the library); the
 * list of cards works with none. What a real card does (the stream,
 * underruns, latency) is tested in the VM through QEMU's Intel HDA card
 * (tests/vm, docs/vm.md).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "audio/au.h"

static void the_null_device_takes_a_tick_at_a_time(void **state)
{
	static int16_t frames[2 * 800];
	struct au_dev *d;
	struct au_status st;
	char why[256] = "";

	(void)state;
	assert_int_equal(au_alsa.open("null", 48000, &d, why, sizeof(why)), 0);
	assert_string_equal(au_alsa.describe(d),
			    "alsa null: 48000 Hz, period 240 frames (5.0 ms), buffer 960 frames "
			    "(20.0 ms)");
	/* the first write starts the stream after 960 - 800 frames of silence */
	assert_int_equal(au_alsa.write(d, frames, 800, &st), 0);
	assert_int_equal(st.delay, 160);
	assert_int_equal(st.underruns, 0);
	assert_int_equal(st.dropped, 0);
	for (int t = 0; t < 10; t++) {
		assert_int_equal(au_alsa.write(d, frames, 800, &st), 0);
		assert_true(st.delay >= 0);
	}
	au_alsa.close(d);
	au_alsa.close(NULL);
}

static void a_missing_card_is_no_sound_card(void **state)
{
	struct au_dev *d = NULL;
	char why[256] = "";

	(void)state;
	assert_int_equal(au_alsa.open("hw:77", 48000, &d, why, sizeof(why)), -ENODEV);
	assert_true(why[0] != '\0');
	assert_null(d);
}

static void the_list_says_what_it_finds(void **state)
{
	char buf[4096] = "";
	FILE *f = fmemopen(buf, sizeof(buf) - 1, "w");

	(void)state;
	assert_non_null(f);
	assert_int_equal(au_alsa.list(f), 0);
	fclose(f);
	/* a card's line, or the line that says there is none */
	assert_true(strncmp(buf, "sound: card ", 12) == 0 ||
		    strcmp(buf, "sound: no sound cards (the cabinet plays silent)\n") == 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_null_device_takes_a_tick_at_a_time),
		cmocka_unit_test(a_missing_card_is_no_sound_card),
		cmocka_unit_test(the_list_says_what_it_finds),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
