/* Tests for engine/core/pal.c: the built-in palette and its colormaps. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/pal.h"

static struct pal p;

static int setup(void **state)
{
	(void)state;
	pal_builtin(&p);
	return 0;
}

static int lum(const uint8_t *c)
{
	return c[0] + c[1] + c[2];
}

static void fixed_entries_are_white_near_black_and_black(void **state)
{
	(void)state;
	for (int k = 0; k < 3; k++) {
		assert_int_equal(p.rgb[0][k], 255);
		assert_int_equal(p.rgb[PAL_BLACK][k], 0);
		/* grey ramp steps of 16 from white: shade 15 is 255 - 240 */
		assert_int_equal(p.rgb[PAL_RGB(PAL_GREY, 15)][k], 15);
		assert_int_equal(p.rgb[PAL_RGB(PAL_GREY, 8)][k], 127);
	}
	assert_int_equal(PAL_RGB(PAL_BLACKRAMP, 15), PAL_BLACK);
}

static void all_colours_are_distinct(void **state)
{
	(void)state;
	for (int i = 0; i < 256; i++)
		for (int j = 0; j < i; j++)
			assert_false(memcmp(p.rgb[i], p.rgb[j], 3) == 0);
}

static void every_ramp_darkens_with_shade(void **state)
{
	(void)state;
	for (int r = 0; r < PAL_RAMPS; r++)
		for (int s = 1; s < PAL_SHADES; s++)
			assert_true(lum(p.rgb[PAL_RGB(r, s)]) < lum(p.rgb[PAL_RGB(r, s - 1)]));
}

static void colormap_zero_is_identity(void **state)
{
	(void)state;
	for (int i = 0; i < 256; i++)
		assert_int_equal(p.cmap[0][i], i);
}

static void half_light_maps_white_to_mid_grey(void **state)
{
	(void)state;
	/* level 16 scales by 16/32: 255 -> (255*16+16)/32 = 128; the grey ramp
	 * has 127 at shade 8, distance 3, and no other entry is that close */
	assert_int_equal(p.cmap[16][0], PAL_RGB(PAL_GREY, 8));
}

static void darkest_map_is_near_black_and_black_stays_black(void **state)
{
	(void)state;
	for (int i = 0; i < 256; i++) {
		/* scaled by 1/32: every channel <= 8, nearest entry <= 15 */
		for (int k = 0; k < 3; k++)
			assert_true(p.rgb[p.cmap[PAL_LIGHTS - 1][i]][k] <= 15);
	}
	for (int l = 0; l < PAL_LIGHTS; l++)
		assert_int_equal(p.cmap[l][PAL_BLACK], PAL_BLACK);
}

/* Second method: check the nearest-colour property directly instead of
 * re-running the search: no entry is strictly closer, and an equally close
 * entry never has a lower index. */
static void check_nearest_lowest_index(const struct pal *q)
{
	for (int l = 0; l < PAL_LIGHTS; l++) {
		int f = PAL_LIGHTS - l;
		for (int i = 0; i < 256; i++) {
			int want[3];
			int chosen = q->cmap[l][i];
			long dc = 0;

			for (int k = 0; k < 3; k++) {
				want[k] = (q->rgb[i][k] * f + PAL_LIGHTS / 2) / PAL_LIGHTS;
				dc += (long)(q->rgb[chosen][k] - want[k]) * (q->rgb[chosen][k] - want[k]);
			}
			for (int j = 0; j < 256; j++) {
				long d = 0;
				for (int k = 0; k < 3; k++)
					d += (long)(q->rgb[j][k] - want[k]) * (q->rgb[j][k] - want[k]);
				assert_false(d < dc);
				if (d == dc)
					assert_true(j >= chosen);
			}
		}
	}
}

static void colormaps_pick_the_nearest_lowest_index(void **state)
{
	(void)state;
	check_nearest_lowest_index(&p);
}

/* A WAD's palette without a COLORMAP gets its colormaps made too, and
 * Doom's palettes repeat colours: one with few distinct values per
 * channel (many exact ties and equal reds) still gets the nearest entry,
 * the lowest index of equals, the same as pal_nearest's answer. */
static void colormaps_of_a_palette_with_ties(void **state)
{
	static struct pal q;
	(void)state;
	for (int i = 0; i < 256; i++) {
		q.rgb[i][0] = (uint8_t)((i * 37) % 7 * 40);
		q.rgb[i][1] = (uint8_t)((i * 11) % 5 * 60);
		q.rgb[i][2] = (uint8_t)(i % 3 * 120);
	}
	pal_make_colormaps(&q);
	check_nearest_lowest_index(&q);
	for (int l = 0; l < PAL_LIGHTS; l++) {
		int f = PAL_LIGHTS - l;
		for (int i = 0; i < 256; i++)
			assert_int_equal(q.cmap[l][i],
					 pal_nearest(&q, (q.rgb[i][0] * f + PAL_LIGHTS / 2) / PAL_LIGHTS,
						     (q.rgb[i][1] * f + PAL_LIGHTS / 2) / PAL_LIGHTS,
						     (q.rgb[i][2] * f + PAL_LIGHTS / 2) / PAL_LIGHTS));
	}
}

static void colormaps_never_brighten(void **state)
{
	(void)state;
	/* a lit colour is never brighter than the unlit one */
	for (int l = 1; l < PAL_LIGHTS; l++)
		for (int i = 0; i < 256; i++)
			assert_true(lum(p.rgb[p.cmap[l][i]]) <= lum(p.rgb[i]));
}

static void builtin_is_deterministic(void **state)
{
	static struct pal q;
	(void)state;
	memset(&q, 0xa5, sizeof(q));
	pal_builtin(&q);
	assert_memory_equal(&p, &q, sizeof(p));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(fixed_entries_are_white_near_black_and_black),
		cmocka_unit_test(all_colours_are_distinct),
		cmocka_unit_test(every_ramp_darkens_with_shade),
		cmocka_unit_test(colormap_zero_is_identity),
		cmocka_unit_test(half_light_maps_white_to_mid_grey),
		cmocka_unit_test(darkest_map_is_near_black_and_black_stays_black),
		cmocka_unit_test(colormaps_pick_the_nearest_lowest_index),
		cmocka_unit_test(colormaps_of_a_palette_with_ties),
		cmocka_unit_test(colormaps_never_brighten),
		cmocka_unit_test(builtin_is_deterministic),
	};
	return cmocka_run_group_tests(tests, setup, NULL);
}
