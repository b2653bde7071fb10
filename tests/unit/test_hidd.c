/*
 * Tests of the HID report descriptor parser (input/hidd.c).
 *
 * The expected layouts were decoded by hand from the fixture bytes (item
 * by item, HID 1.11 section 6.2.2); the report lengths are the ones the
 * fixtures' source README lists. Malformed descriptors are built here byte
 * by byte; each must be refused with the offset of the item at fault.
 */
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "input/hidd.h"
#include "tests/unit/hid_fixture.h"

#define U(p, i) HIDD_USAGE(p, i)

static struct hidd_desc *parse_ok(const uint8_t *b, size_t n)
{
	struct hidd_desc *d = NULL;
	char err[200];
	int rc = hidd_parse(b, n, &d, err, sizeof(err));

	if (rc != 0)
		fprintf(stderr, "parse failed: %d %s\n", rc, err);
	assert_int_equal(rc, 0);
	assert_non_null(d);
	return d;
}

static struct hidd_desc *parse_fixture(const char *name)
{
	static uint8_t b[4096];
	long n = fix_desc(name, b, sizeof(b));

	assert_true(n > 0);
	return parse_ok(b, (size_t)n);
}

/* Parses b expecting error rc with exactly message want. */
static void parse_fails(const uint8_t *b, size_t n, int rc, const char *want)
{
	struct hidd_desc *d = (struct hidd_desc *)1;
	char err[200];

	assert_int_equal(hidd_parse(b, n, &d, err, sizeof(err)), rc);
	assert_null(d);
	assert_string_equal(err, want);
}

static void expect_field(const struct hidd_field *f, uint8_t id, uint32_t bit, uint16_t size,
			 uint16_t count, int kind, int64_t lmin, int64_t lmax)
{
	assert_int_equal(f->report_id, id);
	assert_int_equal(f->bit, bit);
	assert_int_equal(f->size, size);
	assert_int_equal(f->count, count);
	assert_int_equal(f->kind, kind);
	assert_true(f->lmin == lmin);
	assert_true(f->lmax == lmax);
}

static void test_every_fixture_parses_with_the_listed_report_lengths(void **state)
{
	(void)state;
	for (size_t i = 0; i < FIX_NDESC; i++) {
		static uint8_t b[4096];
		long n = fix_desc(fix_descs[i].name, b, sizeof(b));
		struct hidd_desc *d;
		size_t nin = 0;

		assert_int_equal(n, fix_descs[i].bytes);
		d = parse_ok(b, (size_t)n);
		for (int k = 0; k < 7 && fix_descs[i].in[k].len; k++, nin++)
			assert_int_equal(hidd_report_len(d, (uint8_t)fix_descs[i].in[k].id),
					 fix_descs[i].in[k].len);
		assert_int_equal(d->nreport, nin);
		assert_true(d->nfield > 0);
		hidd_free(d);
	}
}

static void test_buzz_has_two_axes_twenty_buttons_and_vendor_bits(void **state)
{
	struct hidd_desc *d = parse_fixture("054C_1000_buzz-4p");

	(void)state;
	assert_int_equal(d->nfield, 3);
	assert_int_equal(d->has_ids, 0);
	assert_int_equal(d->napp, 1);
	assert_int_equal(d->ncoll, 3);
	/* 75 08 95 02 15 00 26 ff 00 ... 09 30 09 31 81 02 */
	expect_field(&d->field[0], 0, 0, 8, 2, HIDD_AXIS, 0, 255);
	assert_int_equal(hidd_usage(d, &d->field[0], 0), U(1, 0x30));
	assert_int_equal(hidd_usage(d, &d->field[0], 1), U(1, 0x31));
	assert_int_equal(d->field[0].app, 0);
	assert_int_equal(d->field[0].app_usage, U(1, HIDD_GD_JOYSTICK));
	/* 75 01 95 14 25 01 05 09 19 01 29 14 81 02 */
	expect_field(&d->field[1], 0, 16, 1, 20, HIDD_BUTTON, 0, 1);
	assert_int_equal(hidd_usage(d, &d->field[1], 0), U(9, 1));
	assert_int_equal(hidd_usage(d, &d->field[1], 19), U(9, 20));
	assert_int_equal(d->field[1].flags, HIDD_F_VAR);
	/* 06 00 ff 75 01 95 04 25 01 09 01 81 02 */
	expect_field(&d->field[2], 0, 36, 1, 4, HIDD_VENDOR, 0, 1);
	assert_int_equal(hidd_usage(d, &d->field[2], 3), U(0xff00, 1));
	assert_int_equal(hidd_report_len(d, 0), 5);
	hidd_free(d);
}

static void test_dualshock3_report_1_layout(void **state)
{
	struct hidd_desc *d = parse_fixture("054C_0268_dualshock3-usb");

	(void)state;
	assert_int_equal(d->has_ids, 1);
	assert_int_equal(d->nreport, 1);   /* ids 2, 0xee, 0xef are features only */
	assert_int_equal(d->nfield, 5);
	assert_int_equal(d->ncoll, 6);
	/* 85 01 75 08 95 01 15 00 26 ff 00 81 03: one constant byte */
	expect_field(&d->field[0], 1, 0, 8, 1, HIDD_PAD, 0, 255);
	assert_int_equal(d->field[0].flags, HIDD_F_CONST | HIDD_F_VAR);
	/* 75 01 95 13 ... 05 09 19 01 29 13 81 02 */
	expect_field(&d->field[1], 1, 8, 1, 19, HIDD_BUTTON, 0, 1);
	assert_int_equal(hidd_usage(d, &d->field[1], 18), U(9, 19));
	/* 75 01 95 0d 06 00 ff 81 03 */
	expect_field(&d->field[2], 1, 27, 1, 13, HIDD_PAD, 0, 1);
	/* in a Physical collection: 75 08 95 04 ... 09 30 09 31 09 32 09 35 81 02 */
	expect_field(&d->field[3], 1, 40, 8, 4, HIDD_AXIS, 0, 255);
	assert_int_equal(hidd_usage(d, &d->field[3], 2), U(1, 0x32));
	assert_int_equal(hidd_usage(d, &d->field[3], 3), U(1, 0x35));
	assert_int_equal(d->field[3].app, 0);
	assert_int_equal(d->field[3].coll, 2);   /* app 0, logical 1, physical 2 */
	/* 05 01 75 08 95 27 09 01 81 02: 39 bytes of Pointer usages */
	expect_field(&d->field[4], 1, 72, 8, 39, HIDD_OTHER, 0, 255);
	assert_int_equal(hidd_report_len(d, 1), 49);
	assert_int_equal(hidd_report_len(d, 2), 0);
	hidd_free(d);
}

static void test_boot_keyboard_has_modifier_bits_and_a_six_key_array(void **state)
{
	struct hidd_desc *d = parse_fixture("0458_4018_genius-imperator-keyboard");

	(void)state;
	assert_int_equal(d->nfield, 3);
	/* 05 07 19 e0 29 e7 15 00 25 01 75 01 95 08 81 02 */
	expect_field(&d->field[0], 0, 0, 1, 8, HIDD_KEY, 0, 1);
	assert_int_equal(hidd_usage(d, &d->field[0], 0), U(7, 0xe0));
	assert_int_equal(hidd_usage(d, &d->field[0], 7), U(7, 0xe7));
	/* 95 01 75 08 81 01 */
	expect_field(&d->field[1], 0, 8, 8, 1, HIDD_PAD, 0, 1);
	/* 95 06 75 08 26 ff 00 05 07 19 00 29 fe 81 00 */
	expect_field(&d->field[2], 0, 16, 8, 6, HIDD_KEY_ARRAY, 0, 255);
	assert_int_equal(d->field[2].flags, 0);
	assert_int_equal(hidd_usage(d, &d->field[2], 0xc0), U(7, 0xc0));
	assert_int_equal(hidd_usage(d, &d->field[2], 0xfe), U(7, 0xfe));
	assert_int_equal(hidd_usage(d, &d->field[2], 0xff), 0);   /* past 29 fe */
	assert_int_equal(hidd_report_len(d, 0), 8);
	hidd_free(d);
}

static void test_xbox_bt_four_byte_maximum_triggers_and_null_hat(void **state)
{
	struct hidd_desc *d = parse_fixture("045E_02FD_xbox-one-s-bt");
	const struct hidd_field *f = d->field;

	(void)state;
	/* 15 00 27 ff ff 00 00 95 02 75 10 81 02 */
	expect_field(&f[0], 1, 0, 16, 2, HIDD_AXIS, 0, 65535);
	expect_field(&f[1], 1, 32, 16, 2, HIDD_AXIS, 0, 65535);
	/* 05 02 09 c5 15 00 26 ff 03 95 01 75 0a 81 02, then 6 padding bits */
	expect_field(&f[2], 1, 64, 10, 1, HIDD_AXIS, 0, 1023);
	assert_int_equal(hidd_usage(d, &f[2], 0), U(2, 0xc5));
	expect_field(&f[3], 1, 74, 6, 1, HIDD_PAD, 0, 0);
	expect_field(&f[4], 1, 80, 10, 1, HIDD_AXIS, 0, 1023);
	/* 09 39 15 01 25 08 ... 75 04 95 01 81 42 */
	expect_field(&f[6], 1, 96, 4, 1, HIDD_HAT, 1, 8);
	assert_int_equal(f[6].flags, HIDD_F_VAR | HIDD_F_NULL);
	assert_int_equal(f[0].app_usage, U(1, HIDD_GD_GAMEPAD));
	hidd_free(d);
}

static void test_zero_width_constant_padding_is_skipped(void **state)
{
	/* Saitek: 95 01 75 00 81 03 at offset 60, between 12 buttons and the
	 * hat: the hat starts right after the buttons. */
	struct hidd_desc *d = parse_fixture("06A3_FF0D_saitek-ff-gamepad");
	int hat = -1;

	(void)state;
	for (size_t i = 0; i < d->nfield; i++)
		if (d->field[i].kind == HIDD_HAT)
			hat = (int)i;
	assert_true(hat > 0);
	expect_field(&d->field[hat - 1], 1, 32, 1, 12, HIDD_BUTTON, 0, 1);
	expect_field(&d->field[hat], 1, 44, 4, 1, HIDD_HAT, 0, 7);
	hidd_free(d);
}

static void test_trailing_nul_is_ignored(void **state)
{
	struct hidd_desc *a = parse_fixture("045E_02E0_gamesir-nova-lite-2-bt");
	struct hidd_desc *b = parse_fixture("quirks/045E_02E0_gulikit-es-pro-bt-trailing-nul");

	(void)state;
	/* the same 306 bytes plus 0x00: the same fields */
	assert_int_equal(a->ignored, 0);
	assert_int_equal(b->ignored, 1);
	assert_int_equal(a->nfield, b->nfield);
	assert_memory_equal(a->field, b->field, a->nfield * sizeof(*a->field));
	hidd_free(a);
	hidd_free(b);
}

static void test_icade_keyboard_report_and_its_other_collections(void **state)
{
	struct hidd_desc *d = parse_fixture("quirks/15E4_0132_ion-icade-bt");

	(void)state;
	assert_int_equal(d->ignored, 1);
	assert_int_equal(d->napp, 6);
	expect_field(&d->field[0], 1, 0, 1, 8, HIDD_KEY, 0, 1);
	expect_field(&d->field[2], 1, 16, 8, 6, HIDD_KEY_ARRAY, 0, 255);
	assert_int_equal(hidd_usage(d, &d->field[2], 0xff), U(7, 0xff));
	assert_int_equal(d->field[2].app_usage, U(1, HIDD_GD_KEYBOARD));
	hidd_free(d);
}

static void test_logical_range_is_signed_only_below_zero(void **state)
{
	static const uint8_t b[] = {
		0x05, 0x01, 0x09, 0x04, 0xa1, 0x01, 0x75, 0x08, 0x95, 0x01,
		0x15, 0x81, 0x25, 0x7f, 0x09, 0x30, 0x81, 0x02,             /* -127..127 */
		0x15, 0x00, 0x25, 0xff, 0x09, 0x31, 0x81, 0x02,             /* 0..255 */
		0x75, 0x10, 0x16, 0x00, 0x80, 0x26, 0xff, 0x7f, 0x09, 0x32, 0x81, 0x02,
		0x75, 0x20, 0x17, 0x00, 0x00, 0x00, 0x80, 0x27, 0xff, 0xff, 0xff, 0x7f,
		0x09, 0x33, 0x81, 0x02,                                     /* int32 */
		0x15, 0x00, 0x27, 0xff, 0xff, 0xff, 0xff, 0x09, 0x34, 0x81, 0x02,
		0x15, 0xff, 0x25, 0xff, 0x75, 0x08, 0x09, 0x35, 0x81, 0x02, /* -1..-1 */
		0xc0,
	};
	struct hidd_desc *d = parse_ok(b, sizeof(b));

	(void)state;
	assert_int_equal(d->nfield, 6);
	expect_field(&d->field[0], 0, 0, 8, 1, HIDD_AXIS, -127, 127);
	expect_field(&d->field[1], 0, 8, 8, 1, HIDD_AXIS, 0, 255);
	expect_field(&d->field[2], 0, 16, 16, 1, HIDD_AXIS, -32768, 32767);
	expect_field(&d->field[3], 0, 32, 32, 1, HIDD_AXIS, INT32_MIN, INT32_MAX);
	expect_field(&d->field[4], 0, 64, 32, 1, HIDD_AXIS, 0, 4294967295);
	expect_field(&d->field[5], 0, 96, 8, 1, HIDD_AXIS, -1, -1);
	assert_int_equal(hidd_report_len(d, 0), 13);
	hidd_free(d);
}

static void test_extended_usages_keep_their_own_page(void **state)
{
	static const uint8_t b[] = {
		0x05, 0x09, 0xa1, 0x01, 0x75, 0x08, 0x95, 0x01, 0x26, 0xff, 0x00,
		0x0b, 0x30, 0x00, 0x01, 0x00, 0x81, 0x02,       /* usage 0001:0030 (X) */
		0x05, 0x01, 0x75, 0x01, 0x95, 0x04, 0x25, 0x01,
		0x1b, 0x01, 0x00, 0x09, 0x00, 0x2b, 0x04, 0x00, 0x09, 0x00,
		0x81, 0x02,                                     /* Button 1..4 */
		0xc0,
	};
	struct hidd_desc *d = parse_ok(b, sizeof(b));

	(void)state;
	assert_int_equal(d->nfield, 2);
	expect_field(&d->field[0], 0, 0, 8, 1, HIDD_AXIS, 0, 255);
	assert_int_equal(hidd_usage(d, &d->field[0], 0), U(1, 0x30));
	expect_field(&d->field[1], 0, 8, 1, 4, HIDD_BUTTON, 0, 1);
	assert_int_equal(hidd_usage(d, &d->field[1], 3), U(9, 4));
	/* an application collection outside any page: usage 0 */
	assert_int_equal(d->field[0].app_usage, 0);
	hidd_free(d);
}

static void test_short_usage_takes_the_page_in_effect_when_declared(void **state)
{
	/* Button 1, then the page changes, then X: one item, two kinds. */
	static const uint8_t b[] = {
		0x05, 0x09, 0x09, 0x01, 0x05, 0x01, 0x09, 0x30, 0x75, 0x08, 0x95, 0x03,
		0x26, 0xff, 0x00, 0x81, 0x02,
	};
	struct hidd_desc *d = parse_ok(b, sizeof(b));

	(void)state;
	assert_int_equal(d->nfield, 2);
	expect_field(&d->field[0], 0, 0, 8, 1, HIDD_BUTTON, 0, 255);
	/* the third element repeats the last usage, X */
	expect_field(&d->field[1], 0, 8, 8, 2, HIDD_AXIS, 0, 255);
	assert_int_equal(hidd_usage(d, &d->field[1], 0), U(1, 0x30));
	assert_int_equal(hidd_usage(d, &d->field[1], 1), U(1, 0x30));
	assert_int_equal(d->field[0].app, HIDD_NO_APP);
	hidd_free(d);
}

static void test_push_and_pop_restore_the_globals(void **state)
{
	static const uint8_t b[] = {
		0x05, 0x01, 0x75, 0x08, 0x95, 0x02, 0x26, 0xff, 0x00, 0x85, 0x07,
		0xa4,                                           /* push */
		0x05, 0x09, 0x75, 0x01, 0x95, 0x10, 0x25, 0x01, 0x85, 0x08,
		0xb4,                                           /* pop */
		0x09, 0x30, 0x09, 0x31, 0x81, 0x02,
	};
	struct hidd_desc *d = parse_ok(b, sizeof(b));

	(void)state;
	assert_int_equal(d->nfield, 1);
	expect_field(&d->field[0], 7, 0, 8, 2, HIDD_AXIS, 0, 255);
	assert_int_equal(d->has_ids, 1);
	assert_int_equal(hidd_report_len(d, 7), 3);
	assert_int_equal(hidd_report_len(d, 8), 0);
	hidd_free(d);
}

static void test_delimited_set_counts_its_first_usage(void **state)
{
	static const uint8_t b[] = {
		0x05, 0x01, 0xa9, 0x01, 0x09, 0x30, 0x09, 0x31, 0xa9, 0x00,
		0x09, 0x32, 0x75, 0x08, 0x95, 0x02, 0x26, 0xff, 0x00, 0x81, 0x02,
	};
	struct hidd_desc *d = parse_ok(b, sizeof(b));

	(void)state;
	assert_int_equal(hidd_usage(d, &d->field[0], 0), U(1, 0x30));
	assert_int_equal(hidd_usage(d, &d->field[0], 1), U(1, 0x32));
	hidd_free(d);
}

static void test_long_items_are_skipped(void **state)
{
	static uint8_t b[4096];
	long n = fix_desc("054C_1000_buzz-4p", b + 5, sizeof(b) - 5);
	struct hidd_desc *d;

	(void)state;
	b[0] = 0xfe;   /* long item, 2 data bytes, tag 0x10 */
	b[1] = 0x02;
	b[2] = 0x10;
	b[3] = 0xaa;
	b[4] = 0xbb;
	d = parse_ok(b, (size_t)n + 5);
	assert_int_equal(d->nfield, 3);
	expect_field(&d->field[1], 0, 16, 1, 20, HIDD_BUTTON, 0, 1);
	hidd_free(d);
}

static void test_truncated_items_are_refused_with_their_offset(void **state)
{
	static uint8_t b[4096];
	static const uint8_t long_cut[] = { 0xfe, 0x05, 0x10, 0xaa };
	static const uint8_t long_head[] = { 0x05, 0x01, 0xfe, 0x05 };
	long n = fix_desc("054C_0268_dualshock3-usb", b, sizeof(b));

	(void)state;
	assert_int_equal(n, 148);
	/* offset 16 is 26 ff 00 (Logical Maximum 255): cut after ff */
	parse_fails(b, 18, -EINVAL, "offset 16: item 0x26 needs 2 data bytes, 1 left");
	parse_fails(b, 17, -EINVAL, "offset 16: item 0x26 needs 2 data bytes, 0 left");
	parse_fails(long_cut, sizeof(long_cut), -EINVAL,
		    "offset 0: long item needs 5 data bytes, 1 left");
	parse_fails(long_head, sizeof(long_head), -EINVAL, "offset 2: long item truncated");
}

static void test_every_prefix_of_every_fixture_parses_or_names_an_offset(void **state)
{
	(void)state;
	for (size_t i = 0; i < FIX_NDESC; i++) {
		static uint8_t b[4096];
		long n = fix_desc(fix_descs[i].name, b, sizeof(b));

		for (long k = 0; k < n; k++) {
			struct hidd_desc *d = NULL;
			char err[200] = "";
			int rc = hidd_parse(b, (size_t)k, &d, err, sizeof(err));

			if (rc == 0) {
				hidd_free(d);
				continue;
			}
			assert_null(d);
			assert_int_equal(strncmp(err, "offset ", 7), 0);
		}
	}
}

static void test_unbalanced_collections_are_refused(void **state)
{
	static uint8_t b[4096];
	long n = fix_desc("054C_1000_buzz-4p", b, sizeof(b) - 1);
	static const uint8_t lone_end[] = { 0x05, 0x01, 0xc0 };

	(void)state;
	assert_int_equal(n, 78);
	b[78] = 0xc0;
	parse_fails(b, 79, -EINVAL, "offset 78: end collection without an open collection");
	parse_fails(b, 77, -EINVAL, "offset 77: 1 collection(s) left open at the end");
	parse_fails(lone_end, sizeof(lone_end), -EINVAL,
		    "offset 2: end collection without an open collection");
}

static void test_size_and_count_limits_are_refused(void **state)
{
	static const uint8_t size0[] = { 0x05, 0x09, 0x19, 0x01, 0x29, 0x08, 0x75, 0x00,
					 0x95, 0x08, 0x81, 0x02 };
	static const uint8_t size257[] = { 0x76, 0x01, 0x01, 0x95, 0x01, 0x81, 0x02 };
	static const uint8_t size_huge[] = { 0x77, 0xff, 0xff, 0xff, 0x7f, 0x95, 0x01, 0xb1, 0x02 };
	static const uint8_t count_big[] = { 0x75, 0x01, 0x96, 0x01, 0x30, 0x91, 0x02 };
	static const uint8_t too_long[] = { 0x76, 0x00, 0x01, 0x96, 0x00, 0x30, 0x81, 0x02 };
	static const uint8_t id0[] = { 0x85, 0x00 };
	static const uint8_t id256[] = { 0x86, 0x00, 0x01 };
	static const uint8_t range[] = { 0x05, 0x09, 0x19, 0x05, 0x29, 0x01 };

	(void)state;
	parse_fails(size0, sizeof(size0), -EINVAL, "offset 10: input item with report size 0");
	parse_fails(size257, sizeof(size257), -E2BIG, "offset 5: report size 257 above 256 bits");
	parse_fails(size_huge, sizeof(size_huge), -E2BIG,
		    "offset 7: report size 2147483647 above 256 bits");
	parse_fails(count_big, sizeof(count_big), -E2BIG, "offset 5: report count 12289 above 12288");
	/* 256 bits x 12288 = 393216 bytes */
	parse_fails(too_long, sizeof(too_long), -E2BIG,
		    "offset 6: input report 0 longer than 4096 bytes");
	parse_fails(id0, sizeof(id0), -EINVAL, "offset 0: report id 0 (must be 1..255)");
	parse_fails(id256, sizeof(id256), -EINVAL, "offset 0: report id 256 (must be 1..255)");
	parse_fails(range, sizeof(range), -EINVAL,
		    "offset 4: usage minimum 0x00090005 above usage maximum 0x00090001");
}

static void test_ten_thousand_pushes_pops_or_collections_are_refused(void **state)
{
	static uint8_t b[20000];

	(void)state;
	memset(b, 0xa4, 10000);
	parse_fails(b, 10000, -E2BIG, "offset 16: push nested deeper than 16");
	memset(b, 0xb4, 10000);
	parse_fails(b, 10000, -EINVAL, "offset 0: pop with nothing pushed");
	for (int i = 0; i < 10000; i++) {
		b[2 * i] = 0xa1;
		b[2 * i + 1] = 0x01;
	}
	parse_fails(b, 20000, -E2BIG, "offset 128: collections nested deeper than 64");
}

static void test_fields_and_spans_are_bounded(void **state)
{
	/* 1025 one-bit input items: one field each */
	static uint8_t b[8192];
	size_t n = 0;
	char want[64];

	(void)state;
	b[n++] = 0x75;
	b[n++] = 0x01;
	b[n++] = 0x95;
	b[n++] = 0x01;
	for (int i = 0; i < 1025; i++) {
		b[n++] = 0x81;
		b[n++] = 0x02;
	}
	snprintf(want, sizeof(want), "offset %d: more than 1024 input fields", 4 + 2 * 1024);
	parse_fails(b, n, -E2BIG, want);
}

static uint32_t rnd(uint32_t *x)
{
	*x = *x * 1103515245u + 12345u;
	return *x >> 16;
}

/* Random descriptor bytes: every other round plain random bytes (which
 * rarely parse), else a usage page, report size and count, then a random
 * run of well-formed short items (usages, logical ranges, report sizes,
 * counts and ids, inputs, outputs, balanced collections) with small
 * values, one byte of it replaced one time in four, so that many parse
 * and have fields. Returns the length. */
static size_t random_descriptor(uint8_t *b, size_t max, int round, uint32_t *x)
{
	static const uint8_t tags[] = { 0x04, 0x08, 0x08, 0x14, 0x24, 0x74, 0x94, 0x84, 0x80,
					0x80, 0x80, 0xA0, 0xC0, 0x18, 0x28, 0x90 };
	size_t n = 0;
	int depth = 0;

	if (round % 2) {
		n = (size_t)(round % (int)max);
		for (size_t i = 0; i < n; i++)
			b[i] = (uint8_t)rnd(x);
		return n;
	}
	/* a usage page, a report size and count to start from */
	b[n++] = 0x05; b[n++] = 0x09;
	b[n++] = 0x75; b[n++] = (uint8_t)(1 + rnd(x) % 8);
	b[n++] = 0x95; b[n++] = (uint8_t)(1 + rnd(x) % 8);
	for (int items = (int)(rnd(x) % 40) + 1; items > 0 && n + 3 + (size_t)depth <= max; items--) {
		uint8_t tag = tags[rnd(x) % sizeof tags];
		uint32_t r = rnd(x);
		uint32_t v = tag == 0x74 ? 1 + r % 16 : tag == 0x94 ? 1 + r % 8
			   : tag == 0x84 ? 1 + r % 3 : tag == 0xA0 ? r % 3 : r % 256;

		if (tag == 0xC0) {
			if (depth > 0) {
				b[n++] = tag;      /* End Collection has no data */
				depth--;
			}
			continue;
		}
		depth += tag == 0xA0;
		if (r % 4 == 0 && tag != 0xA0) {
			b[n++] = (uint8_t)(tag | 2);
			b[n++] = (uint8_t)v;
			b[n++] = (uint8_t)(v >> 8);
		} else {
			b[n++] = (uint8_t)(tag | 1);
			b[n++] = (uint8_t)v;
		}
	}
	while (depth-- > 0)
		b[n++] = 0xC0;
	if (n && rnd(x) % 4 == 0) {
		size_t at = rnd(x) % n;

		b[at] = (uint8_t)rnd(x);
	}
	return n;
}

/* 20,000 random descriptors (random_descriptor). Each parse either fails with
 * a message at an offset inside the descriptor ("offset N: ...", N < the
 * length; N == the length only for what is found missing at the end), or
 * succeeds with every field inside its report: a report of that id exists,
 * the field's last bit lies within the report's bits, the report's length
 * is its bits rounded up to bytes (plus the id byte), and the field's
 * usages lie inside the usage table. A fair share must parse with fields,
 * or the invariant is not exercised. */
static void test_random_bytes_fail_at_an_offset_or_fit_their_reports(void **state)
{
	static uint8_t b[512];
	uint32_t x = 12345;
	int with_fields = 0, failed = 0;

	(void)state;
	for (int round = 0; round < 20000; round++) {
		size_t n = random_descriptor(b, sizeof b, round, &x);
		struct hidd_desc *d;
		char err[100] = "";
		int r;

		r = hidd_parse(b, n, &d, err, sizeof(err));
		if (r != 0) {
			long off = -1;

			assert_true(r == -EINVAL || r == -E2BIG);
			if (sscanf(err, "offset %ld:", &off) != 1 || off < 0 || (size_t)off > n ||
			    ((size_t)off == n && !strstr(err, "at the end")))
				fail_msg("round %d, %zu bytes: \"%s\" is not at an offset inside the "
					 "descriptor", round, n, err);
			failed++;
			continue;
		}
		with_fields += d->nfield > 0;
		for (size_t i = 0; i < d->nfield; i++) {
			const struct hidd_field *f = &d->field[i];
			size_t k;

			for (k = 0; k < d->nreport; k++)
				if (d->report[k].id == f->report_id)
					break;
			if (k == d->nreport)
				fail_msg("round %d: field %zu is in report %u, which the descriptor "
					 "does not have", round, i, f->report_id);
			if ((uint64_t)f->bit + (uint64_t)f->size * f->count > d->report[k].bits)
				fail_msg("round %d: field %zu (bits %u + %u x %u) runs past report %u "
					 "(%u bits)", round, i, f->bit, f->size, f->count, f->report_id,
					 d->report[k].bits);
			assert_int_equal(hidd_report_len(d, f->report_id),
					 (d->report[k].bits + 7) / 8 + (d->has_ids ? 1 : 0));
			assert_true((uint64_t)f->span0 + f->nspan <= d->nspan);
			for (uint32_t u = 0; u < f->count && u < 4; u++)
				(void)hidd_usage(d, f, u);
		}
		hidd_free(d);
	}
	print_message("random descriptors: %d refused at an offset, %d parsed with fields\n",
		      failed, with_fields);
	assert_true(with_fields >= 1000);
}

static void test_describe_lists_each_field(void **state)
{
	struct hidd_desc *d = parse_fixture("054C_1000_buzz-4p");
	char buf[1024], small[16];
	size_t need = hidd_describe(d, buf, sizeof(buf));

	(void)state;
	assert_int_equal(need, strlen(buf));
	assert_non_null(strstr(buf, "report 0 bit 0: axis 2x8 bit, 0..255, app 0: X-Y\n"));
	assert_non_null(strstr(buf, "report 0 bit 16: button 20x1 bit, 0..1, app 0: "
				    "Button1-Button20\n"));
	assert_non_null(strstr(buf, "report 0 bit 36: vendor 4x1 bit, 0..1, app 0: ff00:0001\n"));
	assert_int_equal(hidd_describe(d, small, sizeof(small)), need);
	assert_int_equal(strlen(small), sizeof(small) - 1);
	hidd_free(d);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_fixture_parses_with_the_listed_report_lengths),
		cmocka_unit_test(test_buzz_has_two_axes_twenty_buttons_and_vendor_bits),
		cmocka_unit_test(test_dualshock3_report_1_layout),
		cmocka_unit_test(test_boot_keyboard_has_modifier_bits_and_a_six_key_array),
		cmocka_unit_test(test_xbox_bt_four_byte_maximum_triggers_and_null_hat),
		cmocka_unit_test(test_zero_width_constant_padding_is_skipped),
		cmocka_unit_test(test_trailing_nul_is_ignored),
		cmocka_unit_test(test_icade_keyboard_report_and_its_other_collections),
		cmocka_unit_test(test_logical_range_is_signed_only_below_zero),
		cmocka_unit_test(test_extended_usages_keep_their_own_page),
		cmocka_unit_test(test_short_usage_takes_the_page_in_effect_when_declared),
		cmocka_unit_test(test_push_and_pop_restore_the_globals),
		cmocka_unit_test(test_delimited_set_counts_its_first_usage),
		cmocka_unit_test(test_long_items_are_skipped),
		cmocka_unit_test(test_truncated_items_are_refused_with_their_offset),
		cmocka_unit_test(test_every_prefix_of_every_fixture_parses_or_names_an_offset),
		cmocka_unit_test(test_unbalanced_collections_are_refused),
		cmocka_unit_test(test_size_and_count_limits_are_refused),
		cmocka_unit_test(test_ten_thousand_pushes_pops_or_collections_are_refused),
		cmocka_unit_test(test_fields_and_spans_are_bounded),
		cmocka_unit_test(test_random_bytes_fail_at_an_offset_or_fit_their_reports),
		cmocka_unit_test(test_describe_lists_each_field),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
