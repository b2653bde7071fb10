/* Tests for engine/core/tab.c and the generated tables (doubles as the second
 * method: tests may use libm, the engine may not). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <math.h>
#include <cmocka.h>

#include "engine/core/tab.h"

#define PI 3.14159265358979323846
/* Half a step of the slope table (0.5/2048 rad, atan' <= 1) in binary angle
 * units, plus the table's own rounding: tab_atan2's worst-case error. */
#define ATAN_TOLERANCE 166900

static void sin_and_cos_are_exact_at_quadrants(void **state)
{
	(void)state;
	assert_int_equal(tab_sin(0), 0);
	assert_int_equal(tab_sin(ANG90), FX_ONE);
	assert_int_equal(tab_sin(ANG180), 0);
	assert_int_equal(tab_sin(ANG270), -FX_ONE);
	assert_int_equal(tab_cos(0), FX_ONE);
	assert_int_equal(tab_cos(ANG90), 0);
	assert_int_equal(tab_cos(ANG180), -FX_ONE);
	assert_int_equal(tab_cos(ANG270), 0);
	/* the top of the range reads the repeated last quarter */
	assert_int_equal(tab_cos(0xffffffffu), tab_finesine[TAB_FINEANGLES / 4 - 1]);
}

static void sine_is_symmetric(void **state)
{
	int i;
	(void)state;
	for (i = 0; i < TAB_FINEANGLES; i++) {
		assert_int_equal(tab_finesine[i], -tab_finesine[(TAB_FINEANGLES - i) & TAB_FINEMASK]);
		assert_int_equal(tab_finesine[i],
				 tab_finesine[(TAB_FINEANGLES / 2 - i) & TAB_FINEMASK]);
	}
	for (i = TAB_FINEANGLES; i < TAB_FINEANGLES * 5 / 4; i++)
		assert_int_equal(tab_finesine[i], tab_finesine[i - TAB_FINEANGLES]);
}

static void sine_matches_libm(void **state)
{
	int i;
	(void)state;
	for (i = 0; i < TAB_FINEANGLES; i++) {
		double want = sin(i * 2.0 * PI / TAB_FINEANGLES) * 65536.0;
		assert_true(fabs(tab_finesine[i] - want) <= 0.5 + 1e-6);
	}
}

static void tangent_matches_libm_and_clamps(void **state)
{
	int i;
	(void)state;
	assert_int_equal(tab_finetangent[TAB_FINEANGLES / 4], 0);
	assert_int_equal(tab_finetangent[0], -2048 * FX_ONE);
	assert_int_equal(tab_finetangent[TAB_FINEANGLES / 4 + TAB_FINEANGLES / 8], FX_ONE);
	assert_int_equal(tab_finetangent[TAB_FINEANGLES / 4 - TAB_FINEANGLES / 8], -FX_ONE);
	for (i = 1; i < TAB_FINEANGLES / 2; i++) {
		double want = tan((i - TAB_FINEANGLES / 4) * 2.0 * PI / TAB_FINEANGLES) * 65536.0;
		assert_true(fabs(tab_finetangent[i] - want) <= 0.5 + 1e-6);
		if (i > 1)
			assert_true(tab_finetangent[i] > tab_finetangent[i - 1]);
	}
}

static void tantoangle_ends_and_grows(void **state)
{
	int i;
	(void)state;
	assert_int_equal(tab_tantoangle[0], 0);
	assert_int_equal(tab_tantoangle[TAB_SLOPERANGE], ANG45);
	for (i = 1; i <= TAB_SLOPERANGE; i++)
		assert_true(tab_tantoangle[i] > tab_tantoangle[i - 1]);
}

static void atan2_of_compass_directions_is_exact(void **state)
{
	static const fx_t mags[] = { 1, FX_ONE, 1000 * FX_ONE, FX_MAX };
	unsigned i;
	(void)state;
	for (i = 0; i < sizeof mags / sizeof mags[0]; i++) {
		fx_t d = mags[i];
		assert_int_equal(tab_atan2(0, d), 0);
		assert_int_equal(tab_atan2(d, d), ANG45);
		assert_int_equal(tab_atan2(d, 0), ANG90);
		assert_int_equal(tab_atan2(d, -d), ANG90 + ANG45);
		assert_int_equal(tab_atan2(0, -d), ANG180);
		assert_int_equal(tab_atan2(-d, -d), ANG180 + ANG45);
		assert_int_equal(tab_atan2(-d, 0), ANG270);
		assert_int_equal(tab_atan2(-d, d), ANG270 + ANG45);
	}
	assert_int_equal(tab_atan2(FX_MIN, 0), ANG270);
	assert_int_equal(tab_atan2(0, FX_MIN), ANG180);
	assert_int_equal(tab_atan2(FX_MIN, FX_MIN), ANG180 + ANG45);
	assert_int_equal(tab_atan2(0, 0), 0);
}

static int32_t angle_error(ang_t got, double dy, double dx)
{
	double a = atan2(dy, dx);
	ang_t want;
	if (a < 0)
		a += 2 * PI;
	want = (ang_t)(int64_t)llround(a / (2 * PI) * 4294967296.0);
	return (int32_t)(got - want);
}

static void atan2_of_random_vectors_is_within_table_precision(void **state)
{
	uint32_t rng = 12345;
	int i;
	(void)state;
	for (i = 0; i < 200000; i++) {
		int32_t dx, dy, err;
		int shift;
		rng = rng * 1664525u + 1013904223u;
		dx = (int32_t)rng;
		rng = rng * 1664525u + 1013904223u;
		dy = (int32_t)rng;
		rng = rng * 1664525u + 1013904223u;
		shift = (int)(rng >> 27);     /* short and long vectors alike */
		dx >>= shift;
		dy >>= shift;
		err = angle_error(tab_atan2(dy, dx), dy, dx);
		if (dx == 0 && dy == 0)
			continue;
		assert_true(err <= ATAN_TOLERANCE && err >= -ATAN_TOLERANCE);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sin_and_cos_are_exact_at_quadrants),
		cmocka_unit_test(sine_is_symmetric),
		cmocka_unit_test(sine_matches_libm),
		cmocka_unit_test(tangent_matches_libm_and_clamps),
		cmocka_unit_test(tantoangle_ends_and_grows),
		cmocka_unit_test(atan2_of_compass_directions_is_exact),
		cmocka_unit_test(atan2_of_random_vectors_is_within_table_precision),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
