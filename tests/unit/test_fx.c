/* Tests for engine/core/fx.h: 16.16 arithmetic, rounding, saturation, sqrt. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "engine/core/fx.h"

static void mul_is_exact_for_both_signs(void **state)
{
	(void)state;
	/* 2.5 * 3 = 7.5 */
	assert_int_equal(fx_mul(5 * FX_HALF, 3 * FX_ONE), 15 * FX_HALF);
	assert_int_equal(fx_mul(-5 * FX_HALF, 3 * FX_ONE), -15 * FX_HALF);
	assert_int_equal(fx_mul(5 * FX_HALF, -3 * FX_ONE), -15 * FX_HALF);
	assert_int_equal(fx_mul(-5 * FX_HALF, -3 * FX_ONE), 15 * FX_HALF);
}

static void mul_rounds_towards_minus_infinity(void **state)
{
	(void)state;
	/* 1/65536 * 0.5 = 1/131072: floor gives 0 and -1 */
	assert_int_equal(fx_mul(1, FX_HALF), 0);
	assert_int_equal(fx_mul(-1, FX_HALF), -1);
	/* 3/65536 * 0.5 = 1.5/65536 */
	assert_int_equal(fx_mul(3, FX_HALF), 1);
	assert_int_equal(fx_mul(-3, FX_HALF), -2);
}

static void div_is_exact_and_truncates_towards_zero(void **state)
{
	(void)state;
	assert_int_equal(fx_div(15 * FX_HALF, 5 * FX_HALF), 3 * FX_ONE);
	assert_int_equal(fx_div(-15 * FX_HALF, 5 * FX_HALF), -3 * FX_ONE);
	/* 1/3 = 21845.33/65536 */
	assert_int_equal(fx_div(FX_ONE, 3 * FX_ONE), 21845);
	assert_int_equal(fx_div(-FX_ONE, 3 * FX_ONE), -21845);
	assert_int_equal(fx_div(FX_ONE, -3 * FX_ONE), -21845);
	assert_int_equal(fx_div(1, 3 * FX_ONE), 0);
	assert_int_equal(fx_div(-1, 3 * FX_ONE), 0);
}

static void div_saturates_on_overflow(void **state)
{
	(void)state;
	assert_int_equal(fx_div(FX_MAX, FX_HALF), FX_MAX);
	assert_int_equal(fx_div(FX_MIN, FX_HALF), FX_MIN);
	assert_int_equal(fx_div(FX_MIN, -FX_HALF), FX_MAX);
	/* -32768.0 / -1.0 = +32768.0 does not fit */
	assert_int_equal(fx_div(FX_MIN, -FX_ONE), FX_MAX);
	assert_int_equal(fx_div(FX_MIN, FX_ONE), FX_MIN);
}

static void div_by_zero_saturates_by_sign(void **state)
{
	(void)state;
	assert_int_equal(fx_div(5, 0), FX_MAX);
	assert_int_equal(fx_div(-5, 0), FX_MIN);
	assert_int_equal(fx_div(0, 0), FX_MAX);
}

static void int_conversion_floors(void **state)
{
	(void)state;
	assert_int_equal(fx_from_int(-3), -3 * 65536);
	assert_int_equal(fx_to_int(fx_from_int(-3)), -3);
	assert_int_equal(fx_to_int(-1), -1);
	assert_int_equal(fx_to_int(FX_ONE - 1), 0);
	assert_int_equal(fx_abs(-FX_ONE), FX_ONE);
}

static void isqrt_floors_at_edges(void **state)
{
	(void)state;
	assert_int_equal(fx_isqrt64(0), 0);
	assert_int_equal(fx_isqrt64(1), 1);
	assert_int_equal(fx_isqrt64(15), 3);
	assert_int_equal(fx_isqrt64(16), 4);
	assert_int_equal(fx_isqrt64(17), 4);
	assert_true(fx_isqrt64(UINT64_MAX) == 0xffffffffu);
	assert_true(fx_isqrt64(0xfffffffe00000001ull) == 0xffffffffu);     /* (2^32-1)^2 */
	assert_true(fx_isqrt64(0xfffffffe00000000ull) == 0xfffffffeu);
}

static void len_rounds_to_nearest(void **state)
{
	(void)state;
	assert_int_equal(fx_len(3 * FX_ONE, -4 * FX_ONE), 5 * FX_ONE);
	/* 65536 * sqrt(2) = 92681.9: 92682^2 is nearer 2 * 65536^2 than 92681^2 */
	assert_int_equal(fx_len(FX_ONE, FX_ONE), 92682);
	assert_int_equal(fx_len(0, -7), 7);
	assert_int_equal(fx_len(FX_MIN, FX_MIN), FX_MAX);
	assert_int_equal(fx_len(FX_MIN, 0), FX_MAX);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(mul_is_exact_for_both_signs),
		cmocka_unit_test(mul_rounds_towards_minus_infinity),
		cmocka_unit_test(div_is_exact_and_truncates_towards_zero),
		cmocka_unit_test(div_saturates_on_overflow),
		cmocka_unit_test(div_by_zero_saturates_by_sign),
		cmocka_unit_test(int_conversion_floors),
		cmocka_unit_test(isqrt_floors_at_edges),
		cmocka_unit_test(len_rounds_to_nearest),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
