/*
 * Tests of the HID report decoder (input/hidr.c): the recorded reports
 * of real devices (tests/data/hid/) and hand-built descriptors for the
 * thresholds, hats, player splits and axis codes. Expected key codes are
 * the kernel's constants; expected calibrated values are worked out in the
 * comments from the rules in hidr.h (value = (v - centre) * 32767 /
 * (max - centre), truncated towards zero).
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

#include "input/hidr.h"
#include "tests/unit/hid_fixture.h"

#define MAXEV 1024
#define T0 1000000000ull

struct dev {
	struct hidd_desc *d;
	struct hidr *r;
	struct in_event ev[MAXEV];
	int n;
};

static void open_dev(struct dev *x, const uint8_t *b, size_t n, const struct hidr_opts *o)
{
	char err[200];

	memset(x, 0, sizeof(*x));
	assert_int_equal(hidd_parse(b, n, &x->d, err, sizeof(err)), 0);
	assert_int_equal(hidr_new(x->d, o, &x->r), 0);
	assert_true(hidr_max_events(x->r) <= MAXEV);
}

static void open_fixture(struct dev *x, const char *name)
{
	static uint8_t b[4096];
	long n = fix_desc(name, b, sizeof(b));

	assert_true(n > 0);
	open_dev(x, b, (size_t)n, NULL);
}

static void close_dev(struct dev *x)
{
	hidr_free(x->r);
	hidd_free(x->d);
}

/* Decodes one report; its events replace x->ev. */
static int feed(struct dev *x, const uint8_t *rep, size_t len, uint64_t t)
{
	x->n = hidr_decode(x->r, rep, len, t, x->ev, MAXEV);
	assert_true(x->n >= 0);
	return x->n;
}

static void expect_ev(const struct dev *x, int i, int type, int code, int value)
{
	assert_true(i < x->n);
	assert_int_equal(x->ev[i].type, type);
	assert_int_equal(x->ev[i].code, code);
	assert_int_equal(x->ev[i].value, value);
}

/* Decodes every report of a fixture, collecting the key events. */
struct keylog {
	int n;
	uint16_t code[256];
	int32_t value[256];
	int abs;
};

static void run_fixture(struct dev *x, const char *name, struct keylog *k)
{
	static struct fix_reports reps;

	memset(k, 0, sizeof(*k));
	assert_true(fix_reports(name, &reps) > 0);
	for (int i = 0; i < reps.n; i++) {
		feed(x, reps.b[i], reps.len[i], T0 + (uint64_t)i);
		for (int e = 0; e < x->n; e++) {
			assert_true(x->ev[e].time_ns == T0 + (uint64_t)i);
			if (x->ev[e].type == IN_ABS) {
				k->abs++;
				continue;
			}
			assert_true(k->n < 256);
			k->code[k->n] = x->ev[e].code;
			k->value[k->n] = x->ev[e].value;
			k->n++;
		}
	}
}

static void test_buzz_each_button_pressed_and_released_once(void **state)
{
	/* The bit set in bytes 2-4 of each recorded press, in order (low
	 * nibble of byte 4 is buttons 17-20): button 16 (byte 3 0x80), 17..20,
	 * 1..5 (byte 2), 11..15 (byte 3 0x04..0x40), 6..8, 9, 10, 16 again. */
	static const int order[] = { 16, 17, 18, 19, 20, 1, 2, 3, 4, 5, 11,
				     12, 13, 14, 15, 6, 7, 8, 9, 10, 16 };
	struct dev x;
	struct keylog k;

	(void)state;
	open_fixture(&x, "054C_1000_buzz-4p");
	run_fixture(&x, "054C_1000_buzz-4p", &k);
	assert_int_equal(k.n, 42);
	for (int i = 0; i < 21; i++) {
		assert_int_equal(k.code[2 * i], BTN_TRIGGER_HAPPY1 + order[i] - 1);
		assert_int_equal(k.value[2 * i], 1);
		assert_int_equal(k.code[2 * i + 1], BTN_TRIGGER_HAPPY1 + order[i] - 1);
		assert_int_equal(k.value[2 * i + 1], 0);
	}
	/* X and Y read 0 throughout: reported once at full deflection, but
	 * never armed, so no direction (checked above: only buttons). */
	assert_int_equal(k.abs, 2);
	close_dev(&x);
}

static void test_buzz_first_report_reports_its_stuck_axes(void **state)
{
	static const uint8_t rep[] = { 0x00, 0x00, 0x00, 0x00, 0xf0 };
	struct dev x;

	(void)state;
	open_fixture(&x, "054C_1000_buzz-4p");
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
	/* X = 0, centre 127: -(127 * 32767 / 127) */
	expect_ev(&x, 0, IN_ABS, ABS_X, -32767);
	expect_ev(&x, 1, IN_ABS, ABS_Y, -32767);
	assert_int_equal(feed(&x, rep, sizeof(rep), T0 + 1), 0);
	close_dev(&x);
}

static void test_genius_keyboard_codes(void **state)
{
	/* 0xc0..0xc5 (keypad E, F, XOR, ^, %, <) have no Linux key: they
	 * read as KEY_UNKNOWN, as in Linux; 0x65 (Application) is KEY_COMPOSE. */
	struct dev x;
	struct keylog k;

	(void)state;
	open_fixture(&x, "0458_4018_genius-imperator-keyboard");
	run_fixture(&x, "0458_4018_genius-imperator-keyboard", &k);
	assert_int_equal(k.n, 28);
	for (int i = 0; i < 14; i++) {
		int code = i < 12 ? KEY_UNKNOWN : KEY_COMPOSE;

		assert_int_equal(k.code[2 * i], code);
		assert_int_equal(k.value[2 * i], 1);
		assert_int_equal(k.code[2 * i + 1], code);
		assert_int_equal(k.value[2 * i + 1], 0);
	}
	assert_int_equal(k.abs, 0);
	close_dev(&x);
}

static void test_icade_letter_keys(void **state)
{
	/* press/release letter pairs of the 12 controls, as recorded */
	static const char letters[] = "weaqxzdcythrufjnimkpoglv";
	static const int key_of[26] = {
		KEY_A, KEY_B, KEY_C, KEY_D, KEY_E, KEY_F, KEY_G, KEY_H, KEY_I, KEY_J, KEY_K,
		KEY_L, KEY_M, KEY_N, KEY_O, KEY_P, KEY_Q, KEY_R, KEY_S, KEY_T, KEY_U, KEY_V,
		KEY_W, KEY_X, KEY_Y, KEY_Z,
	};
	struct dev x;
	struct keylog k;

	(void)state;
	open_fixture(&x, "quirks/15E4_0132_ion-icade-bt");
	run_fixture(&x, "quirks/15E4_0132_ion-icade-bt", &k);
	assert_int_equal(k.n, 48);
	for (int i = 0; i < 24; i++) {
		assert_int_equal(k.code[2 * i], key_of[letters[i] - 'a']);
		assert_int_equal(k.value[2 * i], 1);
		assert_int_equal(k.code[2 * i + 1], key_of[letters[i] - 'a']);
		assert_int_equal(k.value[2 * i + 1], 0);
	}
	close_dev(&x);
}

static void test_dualshock3_resting_reports_give_nothing(void **state)
{
	/* 299 reports, no button, sticks within 20 of centre: the largest,
	 * left Y 0x6f = 111, is -(16 * 32767 / 127) = -4128, inside the
	 * deadzone (150 per mille = 4915). */
	struct dev x;
	struct keylog k;

	(void)state;
	open_fixture(&x, "054C_0268_dualshock3-usb");
	run_fixture(&x, "054C_0268_dualshock3-usb", &k);
	assert_int_equal(k.n, 0);
	assert_int_equal(k.abs, 0);
	close_dev(&x);
}

/* The look axis on a real pad with a second stick: the DualShock 3's
 * report 1 has X, Y, Z, Rz in bytes 6..9 (with the id byte; 0..255, centre
 * 127 by default), Rz the right stick's vertical. Rz is the look axis:
 * pushed up (small values) it holds BTN_GEAR_UP, pulled down BTN_GEAR_DOWN,
 * through the digital thresholds: pressed at 500 per mille, i.e. 16383;
 * up at raw 63 is -(64 x 32767 / 127) = -16512 (pressed), at 64 -16254
 * (not); released under 350 per mille (11468): at raw 82, -11610, still
 * held, at 83, -11352, released. Its IN_ABS events stay. */
static void test_dualshock3_right_stick_vertical_looks_up_and_down(void **state)
{
	static struct fix_reports reps;
	struct hidr_opts o;
	struct dev x;
	uint8_t rep[49];

	(void)state;
	assert_true(fix_reports("054C_0268_dualshock3-usb", &reps) > 0);
	assert_int_equal(reps.len[0], sizeof(rep));
	memcpy(rep, reps.b[0], sizeof(rep));             /* the pad at rest, recorded */
	open_fixture(&x, "054C_0268_dualshock3-usb");
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 0);
	rep[9] = 64;                                     /* not far enough */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_RZ, -(63 * 32767 / 127));
	rep[9] = 63;
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_GEAR_UP, 1);
	expect_ev(&x, 1, IN_ABS, ABS_RZ, -(64 * 32767 / 127));
	rep[9] = 82;                                     /* hysteresis: still up */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_RZ, -(45 * 32767 / 127));
	rep[9] = 83;
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_GEAR_UP, 0);
	rep[9] = 255;                                    /* pulled down */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_GEAR_DOWN, 1);
	expect_ev(&x, 1, IN_ABS, ABS_RZ, 32767);
	rep[9] = reps.b[0][9];                           /* back to rest */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_GEAR_DOWN, 0);
	expect_ev(&x, 1, IN_ABS, ABS_RZ, 0);
	/* the left stick is still the d-pad, the right stick's X (Z) nothing */
	rep[8] = 0;
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_Z, -32767);
	rep[7] = 0;
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 1);
	close_dev(&x);

	/* look=none: Rz is an axis only; look=z: Z looks instead */
	hidr_default_opts(&o);
	o.look = HIDR_LOOK_NONE;
	{
		static uint8_t b[4096];
		long n = fix_desc("054C_0268_dualshock3-usb", b, sizeof(b));

		assert_true(n > 0);
		open_dev(&x, b, (size_t)n, &o);
		memcpy(rep, reps.b[0], sizeof(rep));
		assert_int_equal(feed(&x, rep, sizeof(rep), T0), 0);
		rep[9] = 0;
		assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
		expect_ev(&x, 0, IN_ABS, ABS_RZ, -32767);
		close_dev(&x);
		o.look = 0x32;
		open_dev(&x, b, (size_t)n, &o);
		memcpy(rep, reps.b[0], sizeof(rep));
		assert_int_equal(feed(&x, rep, sizeof(rep), T0), 0);
		rep[9] = 0;
		assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
		rep[8] = 255;
		assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
		expect_ev(&x, 0, IN_KEY, BTN_GEAR_DOWN, 1);
		expect_ev(&x, 1, IN_ABS, ABS_Z, 32767);
		close_dev(&x);
	}
}

/* A stick held off centre when the first report comes is no look: the
 * look axis, as X and Y, must be seen inside its deadzone once. */
static void test_a_look_axis_held_from_the_start_holds_nothing(void **state)
{
	static struct fix_reports reps;
	struct dev x;
	uint8_t rep[49];

	(void)state;
	assert_true(fix_reports("054C_0268_dualshock3-usb", &reps) > 0);
	memcpy(rep, reps.b[0], sizeof(rep));
	open_fixture(&x, "054C_0268_dualshock3-usb");
	rep[9] = 0;
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_RZ, -32767);
	rep[9] = reps.b[0][9];
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
	rep[9] = 0;
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_GEAR_UP, 1);
	close_dev(&x);
}

static void test_xbox_resting_triggers_and_centred_sticks_give_nothing(void **state)
{
	uint8_t rep[17] = { 0x01, 0x00, 0x80, 0x00, 0x80, 0x00, 0x80, 0x00, 0x80 };
	struct dev x;

	(void)state;
	open_fixture(&x, "045E_02FD_xbox-one-s-bt");
	/* triggers 0 (rest at the minimum), hat 0 (null: range 1..8) */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 0);
	rep[13] = 0x01;   /* hat 1: north */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 1);
	rep[11] = 0xff;   /* accelerator, bits 80..89: 0x3ff in bytes 11..12 */
	rep[12] = 0x03;
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_GAS, 32767);
	close_dev(&x);
}

/* Gamepad: X, Y (bytes 0, 1), hat (low nibble of byte 2, 0..7, null),
 * buttons 1..8 (byte 3). */
static const uint8_t pad_desc[] = {
	0x05, 0x01, 0x09, 0x05, 0xa1, 0x01,
	0x15, 0x00, 0x26, 0xff, 0x00, 0x75, 0x08, 0x95, 0x02, 0x09, 0x30, 0x09, 0x31, 0x81, 0x02,
	0x15, 0x00, 0x25, 0x07, 0x75, 0x04, 0x95, 0x01, 0x09, 0x39, 0x81, 0x42,
	0x75, 0x04, 0x95, 0x01, 0x81, 0x03,
	0x05, 0x09, 0x19, 0x01, 0x29, 0x08, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x08,
	0x81, 0x02,
	0xc0,
};

static int pad(struct dev *x, int px, int py, int hat, int buttons)
{
	uint8_t rep[4] = { (uint8_t)px, (uint8_t)py, (uint8_t)hat, (uint8_t)buttons };

	return feed(x, rep, sizeof(rep), T0);
}

static void test_identical_reports_give_nothing(void **state)
{
	struct dev x;

	(void)state;
	open_dev(&x, pad_desc, sizeof(pad_desc), NULL);
	assert_int_equal(pad(&x, 127, 127, 8, 0), 0);
	assert_int_equal(pad(&x, 127, 127, 8, 0x05), 2);
	expect_ev(&x, 0, IN_KEY, BTN_TRIGGER_HAPPY1, 1);
	expect_ev(&x, 1, IN_KEY, BTN_TRIGGER_HAPPY3, 1);
	assert_int_equal(pad(&x, 127, 127, 8, 0x05), 0);
	assert_int_equal(pad(&x, 127, 127, 8, 0x04), 1);
	expect_ev(&x, 0, IN_KEY, BTN_TRIGGER_HAPPY1, 0);
	close_dev(&x);
}

static void test_stick_thresholds_with_hysteresis(void **state)
{
	/* right of centre 127: n(v) = (v - 127) * 32767 / 128;
	 * press at 500 per mille = 16383, release below 350 = 11468,
	 * deadzone 150 = 4915. */
	struct dev x;

	(void)state;
	open_dev(&x, pad_desc, sizeof(pad_desc), NULL);
	assert_int_equal(pad(&x, 127, 127, 8, 0), 0);
	assert_int_equal(pad(&x, 190, 127, 8, 0), 1);      /* 16127: below press */
	expect_ev(&x, 0, IN_ABS, ABS_X, 16127);
	assert_int_equal(pad(&x, 191, 127, 8, 0), 2);      /* 16383: pressed */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_RIGHT, 1);
	expect_ev(&x, 1, IN_ABS, ABS_X, 16383);
	assert_int_equal(pad(&x, 172, 127, 8, 0), 1);      /* 11519: still held */
	expect_ev(&x, 0, IN_ABS, ABS_X, 11519);
	assert_int_equal(pad(&x, 171, 127, 8, 0), 2);      /* 11263: released */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_RIGHT, 0);
	expect_ev(&x, 1, IN_ABS, ABS_X, 11263);
	assert_int_equal(pad(&x, 146, 127, 8, 0), 1);      /* 4863: deadzone */
	expect_ev(&x, 0, IN_ABS, ABS_X, 0);
	assert_int_equal(pad(&x, 147, 127, 8, 0), 1);      /* 5119 */
	expect_ev(&x, 0, IN_ABS, ABS_X, 5119);
	/* left of centre: n(v) = -(127 - v) * 32767 / 127; up is Y below centre */
	assert_int_equal(pad(&x, 127, 64, 8, 0), 2);       /* -16254: not pressed */
	expect_ev(&x, 0, IN_ABS, ABS_X, 0);
	expect_ev(&x, 1, IN_ABS, ABS_Y, -16254);
	assert_int_equal(pad(&x, 127, 63, 8, 0), 2);       /* -16512: up */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 1);
	expect_ev(&x, 1, IN_ABS, ABS_Y, -16512);
	/* straight to the other side: up released, down pressed */
	assert_int_equal(pad(&x, 127, 255, 8, 0), 3);
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 0);
	expect_ev(&x, 1, IN_KEY, BTN_DPAD_DOWN, 1);
	expect_ev(&x, 2, IN_ABS, ABS_Y, 32767);
	close_dev(&x);
}

static void test_stick_held_at_plug_in_waits_for_centre(void **state)
{
	struct dev x;

	(void)state;
	open_dev(&x, pad_desc, sizeof(pad_desc), NULL);
	assert_int_equal(pad(&x, 0, 127, 8, 0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_X, -32767);
	assert_int_equal(pad(&x, 127, 127, 8, 0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_X, 0);
	assert_int_equal(pad(&x, 0, 127, 8, 0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_LEFT, 1);
	close_dev(&x);
}

static void test_hat_eight_ways_and_null(void **state)
{
	struct dev x;

	(void)state;
	open_dev(&x, pad_desc, sizeof(pad_desc), NULL);
	assert_int_equal(pad(&x, 127, 127, 1, 0), 2);       /* north-east */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 1);
	expect_ev(&x, 1, IN_KEY, BTN_DPAD_RIGHT, 1);
	assert_int_equal(pad(&x, 127, 127, 2, 0), 1);       /* east */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 0);
	assert_int_equal(pad(&x, 127, 127, 5, 0), 3);       /* south-west */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_RIGHT, 0);
	expect_ev(&x, 1, IN_KEY, BTN_DPAD_DOWN, 1);
	expect_ev(&x, 2, IN_KEY, BTN_DPAD_LEFT, 1);
	assert_int_equal(pad(&x, 127, 127, 8, 0), 2);       /* null: centred */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_DOWN, 0);
	expect_ev(&x, 1, IN_KEY, BTN_DPAD_LEFT, 0);
	close_dev(&x);
}

static void test_hat_four_ways(void **state)
{
	static const uint8_t desc[] = {
		0x05, 0x01, 0x09, 0x05, 0xa1, 0x01, 0x15, 0x00, 0x25, 0x03, 0x75, 0x08,
		0x95, 0x01, 0x09, 0x39, 0x81, 0x42, 0xc0,
	};
	static const int dir[4] = { BTN_DPAD_UP, BTN_DPAD_RIGHT, BTN_DPAD_DOWN, BTN_DPAD_LEFT };
	struct dev x;

	(void)state;
	open_dev(&x, desc, sizeof(desc), NULL);
	for (uint8_t v = 0; v < 4; v++) {
		assert_int_equal(feed(&x, &v, 1, T0), v == 0 ? 1 : 2);
		expect_ev(&x, v == 0 ? 0 : 1, IN_KEY, dir[v], 1);
	}
	close_dev(&x);
}

static void test_direction_held_by_hat_and_stick_is_released_by_the_last(void **state)
{
	struct dev x;

	(void)state;
	open_dev(&x, pad_desc, sizeof(pad_desc), NULL);
	assert_int_equal(pad(&x, 127, 127, 8, 0), 0);
	assert_int_equal(pad(&x, 127, 127, 0, 0), 1);      /* hat up */
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 1);
	assert_int_equal(pad(&x, 127, 0, 0, 0), 1);        /* and stick up: only the axis */
	expect_ev(&x, 0, IN_ABS, ABS_Y, -32767);
	assert_int_equal(pad(&x, 127, 0, 8, 0), 0);        /* hat released, stick holds */
	assert_int_equal(pad(&x, 127, 127, 8, 0), 2);
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 0);
	close_dev(&x);
}

static void test_two_joystick_collections_are_two_players(void **state)
{
	static const uint8_t desc[] = {
		0x05, 0x01, 0x09, 0x04, 0xa1, 0x01, 0x85, 0x01,
		0x15, 0x00, 0x26, 0xff, 0x00, 0x75, 0x08, 0x95, 0x02, 0x09, 0x30, 0x09, 0x31,
		0x81, 0x02, 0x05, 0x09, 0x19, 0x01, 0x29, 0x02, 0x25, 0x01, 0x75, 0x01, 0x95, 0x02,
		0x81, 0x02, 0x75, 0x06, 0x95, 0x01, 0x81, 0x03, 0xc0,
		0x05, 0x01, 0x09, 0x04, 0xa1, 0x01, 0x85, 0x02,
		0x15, 0x00, 0x26, 0xff, 0x00, 0x75, 0x08, 0x95, 0x02, 0x09, 0x30, 0x09, 0x31,
		0x81, 0x02, 0x05, 0x09, 0x19, 0x01, 0x29, 0x02, 0x25, 0x01, 0x75, 0x01, 0x95, 0x02,
		0x81, 0x02, 0x75, 0x06, 0x95, 0x01, 0x81, 0x03, 0xc0,
	};
	static const uint8_t p1_rest[] = { 1, 127, 127, 0 }, p2_rest[] = { 2, 127, 127, 0 };
	static const uint8_t p1[] = { 1, 127, 127, 1 }, p2[] = { 2, 255, 127, 3 };
	struct dev x;

	(void)state;
	open_dev(&x, desc, sizeof(desc), NULL);
	feed(&x, p1_rest, sizeof(p1_rest), T0);
	feed(&x, p2_rest, sizeof(p2_rest), T0);
	assert_int_equal(feed(&x, p1, sizeof(p1), T0), 1);
	expect_ev(&x, 0, IN_KEY, BTN_TRIGGER_HAPPY1, 1);
	assert_int_equal(feed(&x, p2, sizeof(p2), T0), 4);
	expect_ev(&x, 0, IN_KEY, BTN_TRIGGER_HAPPY21, 1);
	expect_ev(&x, 1, IN_KEY, BTN_TRIGGER_HAPPY22, 1);
	expect_ev(&x, 2, IN_KEY, BTN_TRIGGER_HAPPY40, 1);   /* player 2 right */
	expect_ev(&x, 3, IN_ABS, ABS_HAT0X, 32767);
	close_dev(&x);
}

static void test_usage_duplication_split_gives_player_two(void **state)
{
	static const uint8_t desc[] = {
		0x05, 0x01, 0x09, 0x04, 0xa1, 0x01,
		0x15, 0x00, 0x26, 0xff, 0x00, 0x75, 0x08, 0x95, 0x04,
		0x09, 0x30, 0x09, 0x31, 0x09, 0x30, 0x09, 0x31, 0x81, 0x02,
		0x05, 0x09, 0x09, 0x01, 0x09, 0x02, 0x09, 0x01, 0x09, 0x02, 0x25, 0x01,
		0x75, 0x01, 0x95, 0x04, 0x81, 0x02, 0x75, 0x04, 0x95, 0x01, 0x81, 0x03, 0xc0,
	};
	static const uint8_t rest[] = { 127, 127, 127, 127, 0 };
	static const uint8_t move[] = { 127, 127, 127, 0, 0x04 };
	struct hidr_opts o;
	struct dev x;

	(void)state;
	hidr_default_opts(&o);
	o.split = HIDR_SPLIT_USAGE;
	open_dev(&x, desc, sizeof(desc), &o);
	assert_int_equal(feed(&x, rest, sizeof(rest), T0), 0);
	/* third button bit is the second Button 1; fourth axis the second Y */
	assert_int_equal(feed(&x, move, sizeof(move), T0), 3);
	expect_ev(&x, 0, IN_KEY, BTN_TRIGGER_HAPPY21, 1);
	expect_ev(&x, 1, IN_KEY, BTN_TRIGGER_HAPPY37, 1);   /* player 2 up */
	expect_ev(&x, 2, IN_ABS, ABS_HAT0Y, -32767);
	close_dev(&x);
}

static void test_repeated_usages_without_split_take_the_next_axis_codes(void **state)
{
	/* The 101-byte descriptor of DragonRise 0079:0011 as Linux's hid-dr.c
	 * lists it: five bytes declared X, X, X, X, Y. */
	static const uint8_t desc[] = {
		0x05, 0x01, 0x09, 0x04, 0xa1, 0x01, 0xa1, 0x02, 0x75, 0x08, 0x95, 0x05, 0x15, 0x00,
		0x26, 0xff, 0x00, 0x35, 0x00, 0x46, 0xff, 0x00, 0x09, 0x30, 0x09, 0x30, 0x09, 0x30,
		0x09, 0x30, 0x09, 0x31, 0x81, 0x02, 0x75, 0x04, 0x95, 0x01, 0x25, 0x07, 0x46, 0x3b,
		0x01, 0x65, 0x14, 0x09, 0x00, 0x81, 0x42, 0x65, 0x00, 0x75, 0x01, 0x95, 0x0a, 0x25,
		0x01, 0x45, 0x01, 0x05, 0x09, 0x19, 0x01, 0x29, 0x0a, 0x81, 0x02, 0x06, 0x00, 0xff,
		0x75, 0x01, 0x95, 0x0a, 0x25, 0x01, 0x45, 0x01, 0x09, 0x01, 0x81, 0x02, 0xc0, 0xa1,
		0x02, 0x75, 0x08, 0x95, 0x04, 0x46, 0xff, 0x00, 0x26, 0xff, 0x00, 0x09, 0x02, 0x91,
		0x02, 0xc0, 0xc0,
	};
	uint8_t rep[8] = { 127, 127, 127, 127, 127, 0, 0, 0 };
	struct dev x;

	(void)state;
	assert_int_equal(sizeof(desc), 101);
	open_dev(&x, desc, sizeof(desc), NULL);
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 0);
	rep[0] = 255;
	rep[1] = 0;
	rep[2] = 0;
	rep[3] = 0;
	rep[4] = 0;
	rep[5] = 0x10;   /* button 1: bit 44 */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 8);
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_UP, 1);
	expect_ev(&x, 1, IN_KEY, BTN_DPAD_RIGHT, 1);
	expect_ev(&x, 2, IN_KEY, BTN_TRIGGER_HAPPY1, 1);
	expect_ev(&x, 3, IN_ABS, ABS_X, 32767);
	expect_ev(&x, 4, IN_ABS, ABS_Y, -32767);
	expect_ev(&x, 5, IN_ABS, ABS_Z, -32767);
	expect_ev(&x, 6, IN_ABS, ABS_RX, -32767);
	expect_ev(&x, 7, IN_ABS, ABS_RY, -32767);
	close_dev(&x);
}

static void test_second_player_axes_and_buttons_by_option(void **state)
{
	/* Xin-Mo style: X, Y, Z, Rx in -1..1 (the device sends -2 for -1),
	 * 20 buttons; player 2 is Z/Rx and buttons 11..20. */
	static const uint8_t desc[] = {
		0x05, 0x01, 0x09, 0x04, 0xa1, 0x01, 0x15, 0xff, 0x25, 0x01, 0x75, 0x08, 0x95, 0x04,
		0x09, 0x30, 0x09, 0x31, 0x09, 0x32, 0x09, 0x33, 0x81, 0x02,
		0x05, 0x09, 0x19, 0x01, 0x29, 0x14, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x14,
		0x81, 0x02, 0x75, 0x04, 0x95, 0x01, 0x81, 0x03, 0xc0,
	};
	uint8_t rep[7] = { 0 };
	struct hidr_opts o;
	struct dev x;

	(void)state;
	hidr_default_opts(&o);
	o.p2_x = 0x32;
	o.p2_y = 0x33;
	o.p2_first_button = 11;
	open_dev(&x, desc, sizeof(desc), &o);
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 0);
	rep[0] = 0xfe;              /* -2: below the range, clamped */
	rep[2] = 0x01;              /* player 2 X +1 */
	rep[5] = 0x02;              /* button 10: bit 41 */
	rep[6] = 0x04;              /* button 19: bit 50 -> player 2 button 9 */
	assert_int_equal(feed(&x, rep, sizeof(rep), T0), 6);
	expect_ev(&x, 0, IN_KEY, BTN_DPAD_LEFT, 1);
	expect_ev(&x, 1, IN_KEY, BTN_TRIGGER_HAPPY10, 1);
	expect_ev(&x, 2, IN_KEY, BTN_TRIGGER_HAPPY29, 1);
	expect_ev(&x, 3, IN_KEY, BTN_TRIGGER_HAPPY40, 1);
	expect_ev(&x, 4, IN_ABS, ABS_X, -32767);
	expect_ev(&x, 5, IN_ABS, ABS_HAT0X, 32767);
	close_dev(&x);
}

static const uint8_t two_kbd_desc[] = {
	0x05, 0x01, 0x09, 0x06, 0xa1, 0x01, 0x85, 0x01, 0x05, 0x07, 0x19, 0x00, 0x29, 0xff,
	0x15, 0x00, 0x26, 0xff, 0x00, 0x75, 0x08, 0x95, 0x02, 0x81, 0x00, 0xc0,
	0x05, 0x01, 0x09, 0x06, 0xa1, 0x01, 0x85, 0x02, 0x05, 0x07, 0x19, 0x00, 0x29, 0xff,
	0x15, 0x00, 0x26, 0xff, 0x00, 0x75, 0x08, 0x95, 0x02, 0x81, 0x00, 0xc0,
};

static void test_key_held_by_two_reports_is_released_by_the_last(void **state)
{
	static const uint8_t a1[] = { 1, 0x04, 0 }, a2[] = { 2, 0x04, 0 };
	static const uint8_t z1[] = { 1, 0, 0 }, z2[] = { 2, 0, 0 };
	struct dev x;

	(void)state;
	open_dev(&x, two_kbd_desc, sizeof(two_kbd_desc), NULL);
	assert_int_equal(feed(&x, a1, sizeof(a1), T0), 1);
	expect_ev(&x, 0, IN_KEY, KEY_A, 1);
	assert_int_equal(feed(&x, a2, sizeof(a2), T0), 0);
	assert_int_equal(feed(&x, z1, sizeof(z1), T0), 0);
	assert_int_equal(feed(&x, z2, sizeof(z2), T0), 1);
	expect_ev(&x, 0, IN_KEY, KEY_A, 0);
	close_dev(&x);
}

static void test_error_rollover_keeps_the_keys_as_they_were(void **state)
{
	static const uint8_t a[] = { 1, 0x04, 0 }, roll[] = { 1, 0x01, 0x01 };
	static const uint8_t b[] = { 1, 0x05, 0 };
	struct dev x;

	(void)state;
	open_dev(&x, two_kbd_desc, sizeof(two_kbd_desc), NULL);
	assert_int_equal(feed(&x, a, sizeof(a), T0), 1);
	assert_int_equal(feed(&x, roll, sizeof(roll), T0), 0);
	assert_int_equal(feed(&x, b, sizeof(b), T0), 2);
	expect_ev(&x, 0, IN_KEY, KEY_A, 0);
	expect_ev(&x, 1, IN_KEY, KEY_B, 1);
	close_dev(&x);
}

static void test_short_unknown_and_empty_reports(void **state)
{
	static const uint8_t unknown[] = { 3, 0x04, 0 }, short1[] = { 1, 0x04 };
	static const uint8_t a2[] = { 2, 0x04, 0x05 };
	struct in_event ev[4];
	struct dev x;

	(void)state;
	open_dev(&x, two_kbd_desc, sizeof(two_kbd_desc), NULL);
	assert_int_equal(hidr_decode(x.r, unknown, sizeof(unknown), T0, x.ev, MAXEV), -ENOENT);
	assert_int_equal(hidr_decode(x.r, unknown, 0, T0, x.ev, MAXEV), -EINVAL);
	assert_int_equal(hidr_decode(x.r, a2, sizeof(a2), T0, ev, 4), -ENOSPC);
	/* the missing second byte reads as 0 */
	assert_int_equal(feed(&x, short1, sizeof(short1), T0), 1);
	expect_ev(&x, 0, IN_KEY, KEY_A, 1);
	close_dev(&x);
}

static void test_calibration_moves_centre_and_ends(void **state)
{
	struct dev x;

	(void)state;
	open_dev(&x, pad_desc, sizeof(pad_desc), NULL);
	assert_int_equal(hidr_calibrate(x.r, ABS_X, 20, 100, 180), 0);
	assert_int_equal(hidr_calibrate(x.r, ABS_Z, 0, 1, 2), -ENOENT);
	assert_int_equal(hidr_calibrate(x.r, ABS_X, 5, 5, 5), -EINVAL);
	assert_int_equal(hidr_calibrate(x.r, ABS_X, 5, 9, 7), -EINVAL);
	assert_int_equal(pad(&x, 100, 127, 8, 0), 0);
	/* (140 - 100) * 32767 / 80 = 16383; 200 is past the maximum */
	assert_int_equal(pad(&x, 140, 127, 8, 0), 2);
	expect_ev(&x, 1, IN_ABS, ABS_X, 16383);
	assert_int_equal(pad(&x, 200, 127, 8, 0), 1);
	expect_ev(&x, 0, IN_ABS, ABS_X, 32767);
	close_dev(&x);
}

static void test_options_out_of_range_are_refused(void **state)
{
	struct hidd_desc *d;
	struct hidr *r = (struct hidr *)1;
	struct hidr_opts o;
	char err[100];

	(void)state;
	assert_int_equal(hidd_parse(pad_desc, sizeof(pad_desc), &d, err, sizeof(err)), 0);
	hidr_default_opts(&o);
	o.release = 600;
	assert_int_equal(hidr_new(d, &o, &r), -EINVAL);
	assert_null(r);
	hidr_default_opts(&o);
	o.deadzone = 1001;
	assert_int_equal(hidr_new(d, &o, &r), -EINVAL);
	hidr_default_opts(&o);
	o.split = 7;
	assert_int_equal(hidr_new(d, &o, &r), -EINVAL);
	hidd_free(d);
}

static void test_keyboard_usage_table(void **state)
{
	/* From the USB HID Usage Tables, Keyboard/Keypad page. */
	static const struct { uint32_t usage; int key; } t[] = {
		{ 0x04, KEY_A }, { 0x1d, KEY_Z }, { 0x1e, KEY_1 }, { 0x26, KEY_9 }, { 0x27, KEY_0 },
		{ 0x28, KEY_ENTER }, { 0x29, KEY_ESC }, { 0x2c, KEY_SPACE }, { 0x35, KEY_GRAVE },
		{ 0x39, KEY_CAPSLOCK }, { 0x3a, KEY_F1 }, { 0x44, KEY_F11 }, { 0x45, KEY_F12 },
		{ 0x4f, KEY_RIGHT }, { 0x50, KEY_LEFT }, { 0x51, KEY_DOWN }, { 0x52, KEY_UP },
		{ 0x58, KEY_KPENTER }, { 0x59, KEY_KP1 }, { 0x62, KEY_KP0 }, { 0x63, KEY_KPDOT },
		{ 0x68, KEY_F13 }, { 0x73, KEY_F24 }, { 0xe0, KEY_LEFTCTRL }, { 0xe1, KEY_LEFTSHIFT },
		{ 0xe2, KEY_LEFTALT }, { 0xe3, KEY_LEFTMETA }, { 0xe4, KEY_RIGHTCTRL },
		{ 0xe7, KEY_RIGHTMETA }, { 0x00, 0 }, { 0x01, 0 }, { 0x03, 0 },
		{ 0xc0, KEY_UNKNOWN }, { 0xe8, KEY_UNKNOWN }, { 0x1234, KEY_UNKNOWN },
	};

	(void)state;
	for (size_t i = 0; i < sizeof(t) / sizeof(t[0]); i++)
		assert_int_equal(hidr_key_code(t[i].usage), t[i].key);
}

static void test_describe_names_codes_and_players(void **state)
{
	char buf[4096];
	struct dev x;
	size_t need;

	(void)state;
	open_dev(&x, pad_desc, sizeof(pad_desc), NULL);
	need = hidr_describe(x.r, buf, sizeof(buf));
	assert_int_equal(need, strlen(buf));
	assert_non_null(strstr(buf, "report 0 bit 0: axis 0001:0030 -> abs 0, 0/127/255, "
				    "left/right p1\n"));
	assert_non_null(strstr(buf, "report 0 bit 16: hat -> directions p1\n"));
	assert_non_null(strstr(buf, "report 0 bit 31: 0009:0008 -> key 711 p1\n"));
	close_dev(&x);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_buzz_each_button_pressed_and_released_once),
		cmocka_unit_test(test_buzz_first_report_reports_its_stuck_axes),
		cmocka_unit_test(test_genius_keyboard_codes),
		cmocka_unit_test(test_icade_letter_keys),
		cmocka_unit_test(test_dualshock3_resting_reports_give_nothing),
		cmocka_unit_test(test_dualshock3_right_stick_vertical_looks_up_and_down),
		cmocka_unit_test(test_a_look_axis_held_from_the_start_holds_nothing),
		cmocka_unit_test(test_xbox_resting_triggers_and_centred_sticks_give_nothing),
		cmocka_unit_test(test_identical_reports_give_nothing),
		cmocka_unit_test(test_stick_thresholds_with_hysteresis),
		cmocka_unit_test(test_stick_held_at_plug_in_waits_for_centre),
		cmocka_unit_test(test_hat_eight_ways_and_null),
		cmocka_unit_test(test_hat_four_ways),
		cmocka_unit_test(test_direction_held_by_hat_and_stick_is_released_by_the_last),
		cmocka_unit_test(test_two_joystick_collections_are_two_players),
		cmocka_unit_test(test_usage_duplication_split_gives_player_two),
		cmocka_unit_test(test_repeated_usages_without_split_take_the_next_axis_codes),
		cmocka_unit_test(test_second_player_axes_and_buttons_by_option),
		cmocka_unit_test(test_key_held_by_two_reports_is_released_by_the_last),
		cmocka_unit_test(test_error_rollover_keeps_the_keys_as_they_were),
		cmocka_unit_test(test_short_unknown_and_empty_reports),
		cmocka_unit_test(test_calibration_moves_centre_and_ends),
		cmocka_unit_test(test_options_out_of_range_are_refused),
		cmocka_unit_test(test_keyboard_usage_table),
		cmocka_unit_test(test_describe_names_codes_and_players),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
