/*
 * pick: the app's service pages driven with the cabinet's controls, each
 * run ending in the choice pick.h describes, worked out by hand; and the
 * pages drawn (the cursor's row in the HUD's yellow, found on the frame).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/pick.h"
#include "engine/core/pal.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud.h"

/* Two packs: a PWAD with three maps, then an IWAD with two. */
static void two_packs(struct wads *w)
{
	memset(w, 0, sizeof(*w));
	w->n = 2;
	snprintf(w->pack[0].path, sizeof(w->pack[0].path), "/c/extra.wad");
	w->pack[0].iwad = 0;
	w->pack[0].nmaps = 3;
	strcpy(w->pack[0].maps[0], "MAP01");
	strcpy(w->pack[0].maps[1], "MAP02");
	strcpy(w->pack[0].maps[2], "MAP03");
	snprintf(w->pack[1].path, sizeof(w->pack[1].path), "/d/doom.wad");
	w->pack[1].iwad = 1;
	w->pack[1].nmaps = 2;
	strcpy(w->pack[1].maps[0], "E1M1");
	strcpy(w->pack[1].maps[1], "E1M2");
}

static void test_built_in_levels_is_the_first_row(void **state)
{
	static struct wads w;
	struct pick p;
	char wad[64], maps[64];

	(void)state;
	two_packs(&w);
	pick_content(&p, &w, "built-in level 1");
	assert_int_equal(pick_content_choice(&p, wad, sizeof(wad), maps, sizeof(maps)), -ENOENT);
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_CHOSEN);
	assert_int_equal(pick_content_choice(&p, wad, sizeof(wad), maps, sizeof(maps)), 0);
	assert_string_equal(wad, "");
	assert_string_equal(maps, "");
	/* ended: further keys change nothing */
	assert_int_equal(pick_keys(&p, PICK_K_DOWN | PICK_K_FIRE), PICK_CHOSEN);
}

static void test_an_iwad_from_its_second_map(void **state)
{
	static struct wads w;
	struct pick p;
	char wad[64], maps[64];

	(void)state;
	two_packs(&w);
	pick_content(&p, &w, NULL);
	/* rows: BUILT-IN, extra.wad, doom.wad, BACK; up from the top wraps to BACK */
	assert_int_equal(pick_keys(&p, PICK_K_UP), PICK_RUNNING);
	assert_int_equal(p.cursor, 3);
	pick_keys(&p, PICK_K_UP);             /* doom.wad */
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_RUNNING);
	assert_int_equal(p.maps, 1);
	/* rows: ALL MAPS, FROM E1M1, FROM E1M2, BACK */
	pick_keys(&p, PICK_K_DOWN);
	pick_keys(&p, PICK_K_DOWN);
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_CHOSEN);
	assert_int_equal(pick_content_choice(&p, wad, sizeof(wad), maps, sizeof(maps)), 0);
	assert_string_equal(wad, "/d/doom.wad");
	assert_string_equal(maps, "E1M2");
}

static void test_a_pwad_follows_the_first_iwad_and_all_maps_lists_them_all(void **state)
{
	static struct wads w;
	struct pick p;
	char wad[64], maps[64], small[12];

	(void)state;
	two_packs(&w);
	pick_content(&p, &w, NULL);
	pick_keys(&p, PICK_K_DOWN);           /* extra.wad */
	pick_keys(&p, PICK_K_FIRE);
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_CHOSEN);   /* ALL MAPS */
	assert_int_equal(pick_content_choice(&p, wad, sizeof(wad), maps, sizeof(maps)), 0);
	assert_string_equal(wad, "/d/doom.wad /c/extra.wad");
	assert_string_equal(maps, "MAP01 MAP02 MAP03");
	/* as many maps as fit: two of "MAP01 MAP02" (11 bytes and the NUL) */
	assert_int_equal(pick_content_choice(&p, wad, sizeof(wad), small, sizeof(small)), 0);
	assert_string_equal(small, "MAP01 MAP02");
	/* the paths must fit whole */
	assert_int_equal(pick_content_choice(&p, small, sizeof(small), maps, sizeof(maps)),
			 -ENAMETOOLONG);
}

/* freedoom1.wad has 36 maps; a run plays at most CT_MAX_STAGES (32):
 * the list stops there rather than have the load refuse it. */
static void test_all_maps_stops_at_the_stages_a_run_plays(void **state)
{
	static struct wads w;
	struct pick p;
	char wad[64], maps[256];
	int words = 0;

	(void)state;
	two_packs(&w);
	w.pack[1].nmaps = 36;
	for (int i = 0; i < 36; i++)
		snprintf(w.pack[1].maps[i], 9, "E%cM%c", '1' + i / 9, '1' + i % 9);
	pick_content(&p, &w, NULL);
	pick_keys(&p, PICK_K_DOWN);
	pick_keys(&p, PICK_K_DOWN);
	pick_keys(&p, PICK_K_FIRE);
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_CHOSEN);
	assert_int_equal(pick_content_choice(&p, wad, sizeof(wad), maps, sizeof(maps)), 0);
	for (char *s = maps; *s; s++)
		words += *s == ' ';
	assert_int_equal(words + 1, 32);
	assert_non_null(strstr(maps, "E4M5"));   /* the 32nd: 3 x 9 + 5 */
	assert_null(strstr(maps, "E4M6"));
}

static void test_service_goes_back_one_level_then_out(void **state)
{
	static struct wads w;
	struct pick p;

	(void)state;
	two_packs(&w);
	pick_content(&p, &w, NULL);
	pick_keys(&p, PICK_K_DOWN);
	pick_keys(&p, PICK_K_DOWN);           /* doom.wad */
	pick_keys(&p, PICK_K_FIRE);
	assert_int_equal(pick_keys(&p, PICK_K_SERVICE), PICK_RUNNING);
	assert_int_equal(p.maps, 0);
	assert_int_equal(p.cursor, 2);        /* back on doom.wad */
	/* BACK on the maps list does the same */
	pick_keys(&p, PICK_K_FIRE);
	pick_keys(&p, PICK_K_UP);             /* BACK */
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_RUNNING);
	assert_int_equal(p.maps, 0);
	assert_int_equal(pick_keys(&p, PICK_K_SERVICE), PICK_LEFT);
}

static void test_screen_steps_rotation_and_scale_then_applies(void **state)
{
	struct pick p;

	(void)state;
	pick_screen(&p, 270, 0);
	assert_int_equal(p.rotate, 270);
	pick_keys(&p, PICK_K_RIGHT);          /* 270 -> 0 */
	assert_int_equal(p.rotate, 0);
	pick_keys(&p, PICK_K_LEFT);           /* 0 -> 270 */
	pick_keys(&p, PICK_K_LEFT);           /* 270 -> 180 */
	assert_int_equal(p.rotate, 180);
	pick_keys(&p, PICK_K_FIRE);           /* FIRE steps on too: 180 -> 270 */
	assert_int_equal(p.rotate, 270);
	pick_keys(&p, PICK_K_DOWN);
	pick_keys(&p, PICK_K_FIRE);           /* scale */
	assert_int_equal(p.fill, 1);
	pick_keys(&p, PICK_K_DOWN);           /* APPLY */
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_CHOSEN);
	assert_int_equal(p.rotate, 270);
	assert_int_equal(p.fill, 1);
	/* a rotation the display does not take opens as 0 */
	pick_screen(&p, 45, 7);
	assert_int_equal(p.rotate, 0);
	assert_int_equal(p.fill, 1);
	pick_keys(&p, PICK_K_UP);             /* BACK */
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_LEFT);
}

static void test_config_acknowledges_only_when_there_are_errors(void **state)
{
	struct cfgerr e;
	struct pick p;

	(void)state;
	cfgerr_clear(&e);
	pick_config(&p, &e);
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_LEFT);   /* only BACK */
	cfgerr_keep(&e, "/etc/arcaded/a.ini", 3, "unknown key 'x'");
	pick_config(&p, &e);
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_CHOSEN); /* ACKNOWLEDGE */
	pick_config(&p, &e);
	pick_keys(&p, PICK_K_DOWN);
	assert_int_equal(pick_keys(&p, PICK_K_FIRE), PICK_LEFT);   /* BACK */
}

/* The rows drawn in the HUD's yellow: the cursor's, and nothing else. */
static void test_the_cursor_row_is_drawn_in_yellow(void **state)
{
	static struct wads w;
	static uint8_t px[320 * 240];
	struct r_frame f = { px, 320, 240, 320, NULL };
	struct hud_colours c;
	struct pal pal;
	struct pick p;
	int first = -1, last = -1;

	(void)state;
	pal_builtin(&pal);
	hud_colours(&pal, &c);
	two_packs(&w);
	pick_content(&p, &w, NULL);
	pick_keys(&p, PICK_K_DOWN);
	pick_keys(&p, PICK_K_DOWN);           /* row 2 of the list */
	pick_draw(&p, &pal, &f);
	for (int y = 0; y < f.h; y++)
		for (int x = 0; x < f.w; x++)
			if (px[y * f.w + x] == c.yellow) {
				if (first < 0)
					first = y;
				last = y;
			}
	/* the list starts at 36 (scale 1), 11 lines a row: row 2 at 58..65 */
	assert_int_equal(first, 58);
	assert_true(last <= 65);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_built_in_levels_is_the_first_row),
		cmocka_unit_test(test_an_iwad_from_its_second_map),
		cmocka_unit_test(test_a_pwad_follows_the_first_iwad_and_all_maps_lists_them_all),
		cmocka_unit_test(test_all_maps_stops_at_the_stages_a_run_plays),
		cmocka_unit_test(test_service_goes_back_one_level_then_out),
		cmocka_unit_test(test_screen_steps_rotation_and_scale_then_applies),
		cmocka_unit_test(test_config_acknowledges_only_when_there_are_errors),
		cmocka_unit_test(test_the_cursor_row_is_drawn_in_yellow),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
