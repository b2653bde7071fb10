/* Tests for engine/core/le.h: little-endian integers in byte buffers. The
 * expected values are the bytes written out by hand (least significant
 * first), not the functions' own output. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/le.h"

static const uint8_t b[8] = { 0xfe, 0xff, 0x01, 0x80, 0x34, 0x12, 0x00, 0xa5 };

static void getters_read_least_significant_first(void **state)
{
	(void)state;
	assert_int_equal(le_get16(b), 0xfffe);
	assert_int_equal(le_get16(b + 2), 0x8001);
	assert_int_equal(le_get32(b), 0x8001fffeu);
	assert_int_equal(le_get32(b + 4), 0xa5001234u);
	assert_true(le_get64(b) == 0xa50012348001fffeull);
}

/* Two's complement by arithmetic: the top bit set is negative. */
static void signed_getters_take_the_top_bit_as_the_sign(void **state)
{
	static const uint8_t min16[2] = { 0x00, 0x80 }, max16[2] = { 0xff, 0x7f },
			     min32[4] = { 0, 0, 0, 0x80 }, max32[4] = { 0xff, 0xff, 0xff, 0x7f },
			     m1[4] = { 0xff, 0xff, 0xff, 0xff };
	(void)state;
	assert_int_equal(le_s16(b), -2);
	assert_int_equal(le_s16(b + 4), 0x1234);
	assert_int_equal(le_s16(min16), INT16_MIN);
	assert_int_equal(le_s16(max16), INT16_MAX);
	assert_int_equal(le_s32(b), -0x7ffe0002);
	assert_int_equal(le_s32(min32), INT32_MIN);
	assert_int_equal(le_s32(max32), INT32_MAX);
	assert_int_equal(le_s32(m1), -1);
}

static void putters_write_least_significant_first(void **state)
{
	uint8_t o[9];
	(void)state;
	memset(o, 0xcc, sizeof(o));
	le_put16(o, 0xfffe);
	assert_memory_equal(o, b, 2);
	assert_int_equal(o[2], 0xcc);                  /* nothing past the field */
	le_put32(o, 0x8001fffeu);
	assert_memory_equal(o, b, 4);
	assert_int_equal(o[4], 0xcc);
	le_put64(o, 0xa50012348001fffeull);
	assert_memory_equal(o, b, 8);
	assert_int_equal(o[8], 0xcc);
}

/* Widths known at run time: n bytes, nothing past them; 0 bytes is 0. */
static void variable_widths_take_n_bytes(void **state)
{
	uint8_t o[9];
	(void)state;
	assert_true(le_getn(b, 0) == 0);
	assert_true(le_getn(b, 1) == 0xfe);
	assert_true(le_getn(b, 3) == 0x01fffe);
	assert_true(le_getn(b, 5) == 0x348001fffeull);
	assert_true(le_getn(b, 8) == le_get64(b));
	memset(o, 0xcc, sizeof(o));
	le_putn(o, 0xa50012348001fffeull, 3);
	assert_memory_equal(o, b, 3);
	assert_int_equal(o[3], 0xcc);
	le_putn(o, 0xa50012348001fffeull, 8);
	assert_memory_equal(o, b, 8);
	assert_int_equal(o[8], 0xcc);
}

static void round_trips(void **state)
{
	uint8_t o[8];
	(void)state;
	for (uint32_t v = 0; v < 0x10000u; v += 7) {
		le_put16(o, (uint16_t)v);
		assert_int_equal(le_get16(o), v);
		le_put32(o, v * 0x10001u + 3);
		assert_int_equal(le_get32(o), v * 0x10001u + 3);
		le_put64(o, (uint64_t)v << 40 | v);
		assert_true(le_get64(o) == ((uint64_t)v << 40 | v));
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(getters_read_least_significant_first),
		cmocka_unit_test(signed_getters_take_the_top_bit_as_the_sign),
		cmocka_unit_test(putters_write_least_significant_first),
		cmocka_unit_test(variable_widths_take_n_bytes),
		cmocka_unit_test(round_trips),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
