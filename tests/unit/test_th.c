/* Tests for engine/map/th.c: Doom's thing types and arcaded's light thing. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "app/ct.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"
#include "engine/map/wad.h"

static void doom_types_by_number(void **state)
{
	const struct th_info *i;

	(void)state;
	/* values from Doom's mobjinfo, by hand */
	i = th_find(3004);
	assert_non_null(i);
	assert_string_equal(i->sprite, "POSS");
	assert_int_equal(i->radius, 20);
	assert_int_equal(i->height, 56);
	assert_true(i->flags & TH_MONSTER);
	assert_true(i->flags & TH_SOLID);
	i = th_find(16);
	assert_string_equal(i->sprite, "CYBR");
	assert_int_equal(i->height, 110);
	i = th_find(2035);
	assert_string_equal(i->sprite, "BAR1");
	assert_int_equal(i->radius, 10);
	assert_true(i->flags & TH_SOLID);
	assert_false(i->flags & TH_PICKUP);
	for (uint16_t p = 1; p <= 4; p++)
		assert_true(th_find(p)->flags & TH_PLAYER);
	assert_true(th_find(2028)->flags & TH_LIGHT);
	assert_true(th_find(13)->flags & TH_KEY);
	assert_true(th_find(2001)->flags & TH_WEAPON);
	assert_true(th_find(2048)->flags & TH_AMMO);
	assert_true(th_find(63)->flags & TH_HANGING);
	assert_false(th_find(63)->flags & TH_SOLID);
	assert_int_equal(th_find(18)->frame, 'L');
	assert_true(th_find(14)->flags & TH_INVISIBLE);
	assert_null(th_find(0));
	assert_null(th_find(2009));
	assert_null(th_find(32000));
	assert_null(th_find(TH_LIGHT_LAST + 1));
}

static void table_is_sorted_and_complete(void **state)
{
	static const uint16_t wanted[] = { 1, 2, 3, 4, 3004, 9, 3001, 3002, 58, 3005, 3003,
					   69, 16, 7, 65, 64, 66, 67, 68, 71, 84, 72, 2035,
					   2028, 85, 86, 44, 45, 46, 55, 56, 57, 43, 54, 5,
					   6, 13, 38, 39, 40, 2011, 2012, 2018, 2019, 2007 };

	(void)state;
	for (int i = 1; i < th_count(); i++)
		assert_true(th_at(i - 1)->type < th_at(i)->type);
	assert_null(th_at(th_count()));
	assert_null(th_at(-1));
	for (size_t k = 0; k < sizeof wanted / sizeof wanted[0]; k++)
		assert_non_null(th_find(wanted[k]));
}

static void light_things_encode_radius_intensity_colour(void **state)
{
	struct th_light l;

	(void)state;
	assert_int_equal(th_light(TH_LIGHT_FIRST, &l), 1);
	assert_int_equal(l.radius, 64);
	assert_int_equal(l.intensity, 32);
	assert_int_equal(l.rgb[0], 255);
	assert_int_equal(l.rgb[2], 255);
	/* 15248 = 15000 + 64*3 + 8*7 + 0: radius 256, full, white */
	assert_int_equal(th_light(15248, &l), 1);
	assert_int_equal(l.radius, 256);
	assert_int_equal(l.intensity, 255);
	/* 15000 + 64*7 + 8*3 + 1 = 15473: radius 512, 128, red */
	assert_int_equal(th_light(15473, &l), 1);
	assert_int_equal(l.radius, 512);
	assert_int_equal(l.intensity, 128);
	assert_true(l.rgb[0] > l.rgb[1] && l.rgb[0] > l.rgb[2]);
	l.radius = -1;
	assert_int_equal(th_light(3004, &l), 0);
	assert_int_equal(th_light(TH_LIGHT_LAST + 1, &l), 0);
	assert_int_equal(l.radius, -1);
	for (int r = 0; r < 8; r++)
		for (int i = 0; i < 8; i++)
			for (int c = 0; c < 8; c++) {
				uint16_t t = th_light_type(r, i, c);
				assert_int_equal(th_light(t, &l), 1);
				assert_int_equal(l.radius, 64 * (r + 1));
				assert_true(th_find(t)->flags & TH_LIGHT);
				assert_true(th_find(t)->flags & TH_INVISIBLE);
			}
	assert_int_equal(th_light_type(-3, 99, 0), th_light_type(0, 7, 0));
}

static void builtin_set_draws_its_thing_types(void **state)
{
	static const uint16_t types[] = { 2035, 2028, 3004, 2012, 9, 3001, 3002,
					  3005, 2011, 2007, 2048, 35, 46 };
	struct tex_set *t;

	(void)state;
	assert_int_equal(tex_builtin(&t), 0);
	for (size_t k = 0; k < sizeof types / sizeof types[0]; k++) {
		const struct th_info *i = th_find(types[k]);
		int s = tex_find_sprite(t, i->sprite);
		assert_true(s >= 0);
		assert_true(t->sprites[s].num_frames > i->frame - 'A');
	}
	tex_free(t);
}

/* The file at path, or NULL (ct_read_file, app/ct.h). */
static uint8_t *slurp(const char *path, size_t *len)
{
	uint8_t *d = NULL;

	return ct_read_file(path, &d, len) == 0 ? d : NULL;
}

/* Freedoom 2 (Doom II's set) has a picture for every table entry, and every
 * thing in its maps is in the table but 32000 (Doom Builder's camera). */
static void freedoom2_sprites_and_things_match_the_table(void **state)
{
	const char *path = "/usr/share/games/doom/freedoom2.wad";
	size_t len = 0;
	uint8_t *d = slurp(path, &len);
	struct wad *w;
	struct tex_set *t;
	char err[256], names[64][9];
	int n;

	(void)state;
	if (!d) {
		print_message("SKIPPED: %s is not installed (Debian package freedoom)\n", path);
		skip();
	}
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, d, len, path, err, sizeof err), 0);
	assert_int_equal(tex_load_wad(w, &t, err, sizeof err), 0);
	for (int i = 0; i < th_count(); i++) {
		const struct th_info *x = th_at(i);
		int s;

		if (x->flags & TH_INVISIBLE)
			continue;
		s = tex_find_sprite(t, x->sprite);
		if (s < 0 || t->sprites[s].num_frames <= x->frame - 'A' ||
		    t->sprites[s].frames[x->frame - 'A'].pic[0] == 0)
			fail_msg("type %d: no sprite %s frame %c", x->type, x->sprite, x->frame);
	}
	n = map_list_wad(w, names, 64);
	for (int i = 0; i < n; i++) {
		struct map *m;

		assert_int_equal(map_load_wad(w, t, names[i], &m, err, sizeof err), 0);
		for (uint32_t k = 0; k < m->num_things; k++)
			if (m->things[k].type != 32000 && !th_find(m->things[k].type))
				fail_msg("%s: thing %u type %d unknown", names[i], k, m->things[k].type);
		map_free(m);
	}
	tex_free(t);
	wad_free(w);
	free(d);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(doom_types_by_number),
		cmocka_unit_test(table_is_sorted_and_complete),
		cmocka_unit_test(light_things_encode_radius_intensity_colour),
		cmocka_unit_test(builtin_set_draws_its_thing_types),
		cmocka_unit_test(freedoom2_sprites_and_things_match_the_table),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
