/* Tests for app/diag.c: the text of the service menu's DEVICES and LATENCY
 * pages, made from the slots and the statistics. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#include "app/ctl.h"
#include "app/diag.h"
#include "app/slot.h"
#include "app/stats.h"

/* Index of the first line of d equal to text, -1 none. */
static int line_of(const struct hud_diag *d, const char *text)
{
	for (int i = 0; i < d->n; i++)
		if (strcmp(d->line[i], text) == 0)
			return i;
	return -1;
}

static void text_is_split_cut_and_bounded(void **state)
{
	static struct hud_diag d;
	char lng[200];
	(void)state;
	diag_clear(&d);
	diag_add(&d, "one\n\ttwo\n");
	assert_int_equal(d.n, 2);
	assert_string_equal(d.line[0], "one");
	assert_string_equal(d.line[1], "  two");
	memset(lng, 'x', sizeof(lng) - 1);
	lng[sizeof(lng) - 1] = '\0';
	diag_add(&d, lng);
	assert_int_equal(d.n, 3);
	assert_int_equal(strlen(d.line[2]), HUD_DIAG_COLS - 1);
	for (int i = 0; i < 2 * HUD_DIAG_LINES; i++)
		diag_add(&d, "more");
	assert_int_equal(d.n, HUD_DIAG_LINES);
}

static const struct in_backend be_ev = { .name = "evdev" };
static const struct in_backend be_gpio = { .name = "gpio" };
static const struct in_backend be_hid = { .name = "hid" };

/* Two configured kinds (evdev: a stick that is open and a pad that is
 * missing; hid "auto" with no slot) and one that is not (gpio "none"). */
static void devices_list_the_configured_slots(void **state)
{
	static struct hud_diag d;
	static struct slot_set set;
	const struct slot_kind kinds[3] = {
		{ &be_ev, "/dev/input/by-id/stick /dev/input/by-id/pad", 0, 0 },
		{ &be_gpio, "none", 0, 0 },
		{ &be_hid, "auto", 1, 0 },
	};
	int in_use, ev, hid;
	(void)state;
	memset(&set, 0, sizeof(set));
	set.n = 2;
	set.s[0].kind = 0;
	set.s[0].path = "/dev/input/by-id/stick";
	set.s[0].dev = (struct in_dev *)&set;          /* open: only tested for NULL */
	set.s[0].id.vid = 0xd209;
	set.s[0].id.pid = 0x0501;
	strcpy(set.s[0].id.name, "Ultimarc I-PAC");
	set.s[1].kind = 0;
	set.s[1].path = "/dev/input/by-id/pad";
	diag_devices(&d, kinds, 3, &set, "hid: 1 device\n  0001:0002 Pad\n");
	in_use = line_of(&d, "IN USE");
	ev = line_of(&d, "  evdev: /dev/input/by-id/stick /dev/input/by-id/pad");
	hid = line_of(&d, "  hid: auto");
	assert_int_equal(in_use, 0);
	assert_int_equal(ev, 1);
	assert_int_equal(line_of(&d, "    /dev/input/by-id/stick: Ultimarc I-PAC (d209:0501)"), 2);
	assert_int_equal(line_of(&d, "    /dev/input/by-id/pad: MISSING"), 3);
	assert_int_equal(hid, 4);
	assert_int_equal(line_of(&d, "    no device opened"), 5);
	assert_int_equal(line_of(&d, "  gpio: none"), -1);
	for (int i = 0; i < d.n; i++)
		assert_null(strstr(d.line[i], "gpio"));
	assert_int_equal(line_of(&d, "FOUND"), 6);
	assert_int_equal(line_of(&d, "hid: 1 device"), 7);
	assert_int_equal(line_of(&d, "  0001:0002 Pad"), 8);
	assert_int_equal(d.n, 9);
	diag_devices(&d, kinds, 3, &set, NULL);        /* no listing: no FOUND */
	assert_int_equal(line_of(&d, "FOUND"), -1);
	assert_int_equal(d.n, 6);
}

/* Frame time and input-to-present latency: nothing before input; after
 * one input of the script source at 1 ms shown by a present from 2 ms to
 * 4 ms, the frame took 2 ms and the input waited 3 ms. */
static void latency_lines_appear_after_input(void **state)
{
	static struct hud_diag d;
	static struct stats st;
	const char *names[2] = { "evdev", "script" };
	int ev, scr;
	(void)state;
	stats_init(&st, names, 2);
	diag_latency(&d, &st);
	assert_int_equal(line_of(&d, "FRAME TIME IN MS (RENDER + PRESENT)"), 0);
	assert_string_equal(d.line[1], "  NO INPUT YET");
	ev = line_of(&d, "INPUT TO PRESENT IN MS, evdev");
	scr = line_of(&d, "INPUT TO PRESENT IN MS, script");
	assert_true(ev > 0 && scr > ev);
	assert_string_equal(d.line[ev + 1], "  NO INPUT YET");
	assert_string_equal(d.line[scr + 1], "  NO INPUT YET");

	stats_input(&st, 1, 1000000);
	stats_presented(&st, 2000000, 4000000, 0);
	diag_latency(&d, &st);
	assert_string_equal(d.line[1], "  P50 2.00 P99 2.00 MAX 2.00 N 1");
	assert_string_equal(d.line[line_of(&d, "INPUT TO PRESENT IN MS, EVERY SOURCE") + 1],
			    "  P50 3.00 P99 3.00 MAX 3.00 N 1");
	assert_string_equal(d.line[ev + 1], "  NO INPUT YET");
	assert_string_equal(d.line[scr + 1], "  P50 3.00 P99 3.00 MAX 3.00 N 1");
	for (int i = 0; i < d.n; i++)
		assert_true(strlen(d.line[i]) <= 39);  /* the columns of a 320-wide frame */
}

/* The input test's lines: a heading, then the kept changes newest first;
 * only the last CTL_RAW once more were made. */
static void raw_controls_newest_first(void **state)
{
	static struct hud_diag d;
	static struct ctl c;
	(void)state;
	memset(&c, 0, sizeof(c));
	diag_raw(&d, &c);
	assert_int_equal(d.n, 2);
	assert_true(d.line[0][0] != ' ');
	assert_string_equal(d.line[1], "  NONE YET");
	for (unsigned i = 0; i < CTL_RAW + 2; i++) {
		snprintf(c.raw[c.raw_n % CTL_RAW], CTL_RAW_LEN, "change %u", i);
		c.raw_n++;
	}
	diag_raw(&d, &c);
	assert_int_equal(d.n, 1 + CTL_RAW);
	assert_string_equal(d.line[1], "  change 9");
	assert_string_equal(d.line[2], "  change 8");
	assert_string_equal(d.line[CTL_RAW], "  change 2");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(text_is_split_cut_and_bounded),
		cmocka_unit_test(devices_list_the_configured_slots),
		cmocka_unit_test(latency_lines_appear_after_input),
		cmocka_unit_test(raw_controls_newest_first),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
