/* Tests for engine/game/menu.c: navigating the service menu with the game's
 * commands, changing settings, resets with confirmation. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/menu.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "g_fixture.h"

static const struct sim_cmd none = { 0 };

/* One press of a control: a tick with it, a tick without. */
static void press(struct sim *s, struct sim_cmd c)
{
	sim_tick(s, &c);
	sim_tick(s, &none);
}

#define UP ((struct sim_cmd){ .forward = 127 })
#define DOWN ((struct sim_cmd){ .forward = -127 })
#define LEFT ((struct sim_cmd){ .turn = 384 })
#define RIGHT ((struct sim_cmd){ .turn = -384 })
#define FIRE ((struct sim_cmd){ .buttons = SIM_BT_FIRE })
#define SERVICE ((struct sim_cmd){ .buttons = SIM_BT_SERVICE })

static struct map *m_room;

static int setup(void **state)
{
	static const struct gf_thing t[] = { { 100, 100, 0, 1, 0 } };
	(void)state;
	m_room = gf_room(512, 512, t, 1, NULL, 0);
	return m_room ? 0 : -1;
}

static int teardown(void **state)
{
	(void)state;
	map_free(m_room);
	return 0;
}

static void in_menu(struct sim *s, const struct sim_settings *set)
{
	sim_init(s, m_room, set);
	press(s, SERVICE);
	assert_int_equal(s->mode, SIM_SERVICE);
	assert_int_equal(s->menu.page, MENU_MAIN);
	assert_int_equal(s->menu.cursor, MENU_I_INPUT);
}

static const struct sim_settings base = { 1, 0, 0, 1, 3, 100, 1, 0, 0, 0 };

static void the_cursor_moves_and_wraps_and_pages_open_and_close(void **state)
{
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	press(&s, DOWN);
	assert_int_equal(s.menu.cursor, MENU_I_DISPLAY);
	press(&s, UP);
	press(&s, UP);                         /* wraps to the last item */
	assert_int_equal(s.menu.cursor, MENU_I_EXIT);
	press(&s, DOWN);
	assert_int_equal(s.menu.cursor, MENU_I_INPUT);
	for (int i = 0; i < MENU_I_BOOKS; i++)
		press(&s, DOWN);
	press(&s, FIRE);
	assert_int_equal(s.menu.page, MENU_BOOKS);
	press(&s, SERVICE);                    /* back, cursor kept */
	assert_int_equal(s.menu.page, MENU_MAIN);
	assert_int_equal(s.menu.cursor, MENU_I_BOOKS);
	assert_int_equal(s.mode, SIM_SERVICE);
	press(&s, SERVICE);                    /* and out */
	assert_int_equal(s.mode, SIM_ATTRACT);
}

static void a_held_direction_repeats(void **state)
{
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	/* held 21 ticks: the press, then one repeat at 20 ticks held */
	for (int i = 0; i < 21; i++)
		sim_tick(&s, &DOWN);
	assert_int_equal(s.menu.cursor, 2);
	for (int i = 0; i < 6; i++)              /* every 6 ticks after that */
		sim_tick(&s, &DOWN);
	assert_int_equal(s.menu.cursor, 3);
}

static void the_input_test_shows_commands_and_counts_coins(void **state)
{
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	press(&s, FIRE);
	assert_int_equal(s.menu.page, MENU_INPUT);
	press(&s, (struct sim_cmd){ .coins = 2 });
	press(&s, (struct sim_cmd){ .coins = 1 });
	assert_int_equal(s.menu.coins_seen, 3);
	/* directions and fire do not navigate here */
	press(&s, DOWN);
	press(&s, FIRE);
	assert_int_equal(s.menu.page, MENU_INPUT);
	sim_tick(&s, &(struct sim_cmd){ .forward = 127, .buttons = SIM_BT_USE });
	assert_int_equal(s.cmd.forward, 127);
	assert_int_equal(s.cmd.buttons, SIM_BT_USE);
	press(&s, SERVICE);
	assert_int_equal(s.menu.page, MENU_MAIN);
}

static void the_display_test_steps_through_its_screens(void **state)
{
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	press(&s, DOWN);
	press(&s, FIRE);
	assert_int_equal(s.menu.page, MENU_DISPLAY);
	assert_int_equal(s.menu.display, MENU_D_BARS);
	press(&s, FIRE);
	assert_int_equal(s.menu.display, MENU_D_GRID);
	press(&s, FIRE);
	assert_int_equal(s.menu.display, MENU_D_ORIENT);
	press(&s, FIRE);
	assert_int_equal(s.menu.display, MENU_D_BARS);
}

static void settings_change_with_left_and_right(void **state)
{
	struct sim s;
	int w, h;
	(void)state;
	in_menu(&s, &base);
	for (int i = 0; i < MENU_I_SETTINGS; i++)
		press(&s, DOWN);
	press(&s, FIRE);
	assert_int_equal(s.menu.page, MENU_SETTINGS);
	assert_int_equal(s.menu.cursor, MENU_S_DIFFICULTY);
	press(&s, RIGHT);
	assert_int_equal(s.set.difficulty, 2);
	press(&s, RIGHT);
	press(&s, RIGHT);                      /* 3 wraps to 0 */
	assert_int_equal(s.set.difficulty, 0);
	press(&s, DOWN);
	press(&s, LEFT);
	assert_int_equal(s.set.lives, 2);
	press(&s, LEFT);
	press(&s, LEFT);                       /* 1 wraps to 9 */
	assert_int_equal(s.set.lives, 9);
	press(&s, DOWN);
	press(&s, FIRE);                       /* fire steps forward too */
	assert_int_equal(s.set.coins_per_credit, 2);
	press(&s, DOWN);
	press(&s, RIGHT);
	assert_int_equal(s.set.freeplay, 1);
	assert_int_equal(s.set_gen, 3 + 3 + 1 + 1);   /* one per change */
	press(&s, DOWN);
	press(&s, LEFT);                       /* volume in steps of 5 */
	assert_int_equal(s.set.volume, 95);
	press(&s, RIGHT);
	press(&s, RIGHT);                      /* 100 stays 100: never a jump to silent */
	assert_int_equal(s.set.volume, 100);
	press(&s, DOWN);
	press(&s, RIGHT);                      /* attract sound: on, then 1 cycle in 2 */
	assert_int_equal(s.set.attract_sound, 2);
	press(&s, LEFT);
	press(&s, LEFT);
	assert_int_equal(s.set.attract_sound, 0);
	press(&s, LEFT);                       /* off wraps to 1 cycle in 9 */
	assert_int_equal(s.set.attract_sound, 9);
	assert_int_equal(s.set_gen, 8 + 3 + 4);
	press(&s, DOWN);
	press(&s, RIGHT);                      /* stage clock: 0 means the default 5 minutes */
	assert_int_equal(s.set.stage_time, G_STAGE_TIME_DEFAULT + 1);
	press(&s, LEFT);
	press(&s, LEFT);
	assert_int_equal(s.set.stage_time, G_STAGE_TIME_DEFAULT - 1);
	for (int i = 0; i < G_STAGE_TIME_DEFAULT - 1; i++)
		press(&s, LEFT);               /* down to OFF, under 1 minute */
	assert_int_equal(s.set.stage_time, G_STAGE_TIME_OFF);
	press(&s, LEFT);                       /* and round to the longest */
	assert_int_equal(s.set.stage_time, G_STAGE_TIME_MAX);
	press(&s, DOWN);
	press(&s, RIGHT);                      /* idle player: lose a life, end the game, off */
	assert_int_equal(s.set.idle_out, G_IDLE_END);
	press(&s, RIGHT);
	assert_int_equal(s.set.idle_out, G_IDLE_OFF);
	press(&s, RIGHT);                      /* wraps */
	assert_int_equal(s.set.idle_out, G_IDLE_LIFE);
	assert_int_equal(s.set_gen, 15 + 3 + G_STAGE_TIME_DEFAULT + 3);
	press(&s, DOWN);
	press(&s, RIGHT);                      /* auto-aim: on (the default) to off and back */
	assert_int_equal(s.set.free_aim, 1);
	press(&s, LEFT);
	assert_int_equal(s.set.free_aim, 0);
	press(&s, RIGHT);
	assert_int_equal(s.set.free_aim, 1);
	assert_int_equal(s.set_gen, 21 + G_STAGE_TIME_DEFAULT + 3);
	press(&s, DOWN);
	press(&s, RIGHT);
	assert_int_equal(s.menu.res, 1);
	menu_res_size(s.menu.res, &w, &h);
	assert_int_equal(w, 320);
	assert_int_equal(h, 240);
	press(&s, LEFT);
	press(&s, LEFT);                       /* 0 (as configured) wraps to the last */
	assert_int_equal(s.menu.res, MENU_RES_COUNT);
	assert_int_equal(s.set_gen, 29);       /* the size is not a game setting */
	press(&s, DOWN);
	press(&s, DOWN);
	press(&s, FIRE);                       /* BACK */
	assert_int_equal(s.menu.page, MENU_MAIN);
	/* the new settings rule the next game: free play, 9 lives */
	press(&s, SERVICE);
	press(&s, (struct sim_cmd){ .buttons = SIM_BT_START });
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(s.g.lives, 9);
	assert_int_equal(s.credits, 0);
}

static void factory_defaults_restore_every_setting(void **state)
{
	static const struct sim_settings odd = { 7, 1, 0, 3, 9, 30, 0, 17, G_IDLE_OFF, 1 };
	struct sim s;
	(void)state;
	in_menu(&s, &odd);
	for (int i = 0; i < MENU_I_SETTINGS; i++)
		press(&s, DOWN);
	press(&s, FIRE);
	for (int i = 0; i < MENU_S_RES; i++)
		press(&s, DOWN);
	press(&s, RIGHT);                      /* a render size choice */
	assert_int_equal(s.menu.res, 1);
	press(&s, DOWN);
	assert_int_equal(s.menu.cursor, MENU_S_DEFAULTS);
	press(&s, LEFT);                       /* left/right do nothing here */
	assert_int_equal(s.set.lives, 9);
	press(&s, FIRE);
	assert_int_equal(s.set.coins_per_credit, 1);
	assert_int_equal(s.set.freeplay, 0);
	assert_int_equal(s.set.difficulty, 1);
	assert_int_equal(s.set.lives, 3);
	assert_int_equal(s.set.volume, 80);
	assert_int_equal(s.set.attract_sound, 1);
	assert_int_equal(s.set.stage_time, G_STAGE_TIME_DEFAULT);
	assert_int_equal(s.set.idle_out, G_IDLE_LIFE);
	assert_int_equal(s.set.free_aim, 0);
	assert_int_equal(s.menu.res, 0);
	assert_int_equal(s.set_gen, 1);
	assert_int_equal(s.menu.page, MENU_SETTINGS);
}

static void resets_need_a_yes(void **state)
{
	struct g_books books = { 5, 6, 7, 8 };
	const struct map *mp = m_room;
	struct sim s;
	(void)state;
	sim_init_stages(&s, &mp, 1, &base, NULL, &books);
	s.scores.e[0].score = 99999;
	press(&s, SERVICE);
	for (int i = 0; i < MENU_I_RESET_SCORES; i++)
		press(&s, DOWN);
	press(&s, FIRE);
	assert_int_equal(s.menu.page, MENU_CONFIRM);
	assert_int_equal(s.menu.yes, 0);
	press(&s, FIRE);                       /* NO */
	assert_int_equal(s.menu.page, MENU_MAIN);
	assert_int_equal(s.scores.e[0].score, 99999);
	press(&s, FIRE);
	press(&s, RIGHT);                      /* YES */
	assert_int_equal(s.menu.yes, 1);
	press(&s, FIRE);
	assert_int_equal(s.scores.e[0].score, 10000);
	assert_int_equal(s.scores_gen, 1);
	assert_int_equal(s.menu.done, MENU_I_RESET_SCORES);
	assert_int_equal(s.books.coins, 5);
	press(&s, DOWN);                       /* reset bookkeeping */
	press(&s, FIRE);
	press(&s, LEFT);
	sim_tick(&s, &FIRE);                   /* the tick of the reset */
	assert_int_equal(s.books.coins, 0);
	assert_int_equal(s.books.plays, 0);
	assert_true(s.books.play_ticks == 0);
	assert_true(s.books.on_ticks == 0);
}

static void the_exit_item_leaves(void **state)
{
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	press(&s, UP);
	assert_int_equal(s.menu.cursor, MENU_I_EXIT);
	press(&s, FIRE);
	assert_int_equal(s.mode, SIM_ATTRACT);
}

/* DEVICES and LATENCY (just under RESET BOOKKEEPING) open their pages,
 * which hold no state of their own (their text is the app's): FIRE or
 * SERVICE goes back to MAIN with the cursor on the item, and the menu is
 * as it was before the visit (but for its clock and MAIN's cursor). */
static void the_diagnostics_pages_open_and_go_back(void **state)
{
	static const uint8_t item[2] = { MENU_I_DEVICES, MENU_I_LATENCY };
	static const uint8_t page[2] = { MENU_DEVICES, MENU_LATENCY };
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	assert_int_equal(MENU_I_RESET_BOOKS + 1, MENU_I_DEVICES);
	for (int k = 0; k < 2; k++) {
		for (int back = 0; back < 2; back++) {
			struct menu before;
			while (s.menu.cursor != item[k])
				press(&s, DOWN);
			before = s.menu;
			press(&s, FIRE);
			assert_int_equal(s.menu.page, page[k]);
			assert_int_equal(s.mode, SIM_SERVICE);
			press(&s, DOWN);               /* moves nothing */
			assert_int_equal(s.menu.page, page[k]);
			assert_int_equal(s.menu.main_cursor, item[k]);
			press(&s, back ? SERVICE : FIRE);
			assert_int_equal(s.mode, SIM_SERVICE);
			assert_int_equal(s.menu.page, MENU_MAIN);
			assert_int_equal(s.menu.cursor, item[k]);
			/* only the menu's clock moved, and MAIN's cursor is kept */
			before.t = s.menu.t;
			before.main_cursor = item[k];
			assert_memory_equal(&before, &s.menu, sizeof(before));
		}
	}
}

/* CONFIGURE INPUTS (just above EXIT): the page says so for exactly the
 * tick of the choice, then MAIN is back with the cursor on the item,
 * whatever that next tick's commands are (a SERVICE press does not leave);
 * only a new press of fire asks again. */
static void configure_inputs_is_a_one_tick_request(void **state)
{
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	press(&s, UP);                         /* wraps to EXIT */
	press(&s, UP);
	assert_int_equal(s.menu.cursor, MENU_I_WIZARD);
	assert_int_equal(MENU_I_WIZARD + 1, MENU_I_EXIT);
	sim_tick(&s, &FIRE);
	assert_int_equal(s.menu.page, MENU_WIZARD);
	assert_int_equal(s.mode, SIM_SERVICE);
	sim_tick(&s, &FIRE);                   /* held: no new choice */
	assert_int_equal(s.menu.page, MENU_MAIN);
	assert_int_equal(s.menu.cursor, MENU_I_WIZARD);
	sim_tick(&s, &FIRE);
	assert_int_equal(s.menu.page, MENU_MAIN);
	sim_tick(&s, &none);
	sim_tick(&s, &FIRE);                   /* pressed again: a new request */
	assert_int_equal(s.menu.page, MENU_WIZARD);
	sim_tick(&s, &SERVICE);                /* the request's tick swallows it */
	assert_int_equal(s.menu.page, MENU_MAIN);
	assert_int_equal(s.menu.cursor, MENU_I_WIZARD);
	assert_int_equal(s.mode, SIM_SERVICE);
	sim_tick(&s, &none);
	/* and the menu goes on as before */
	press(&s, DOWN);
	assert_int_equal(s.menu.cursor, MENU_I_EXIT);
	press(&s, FIRE);
	assert_int_equal(s.mode, SIM_ATTRACT);
}

/* CONTENT PACK, SCREEN and CONFIG ERRORS (between LATENCY and CONFIGURE
 * INPUTS, so that the items a recorded session reaches by counting moves
 * down keep their places): each is a one-tick request to the app, like
 * CONFIGURE INPUTS: its page for the tick of FIRE, then MAIN with the
 * cursor on the item; the menu is as before but for its clock. */
static void the_app_pages_are_one_tick_requests(void **state)
{
	static const uint8_t item[3] = { MENU_I_CONTENT, MENU_I_SCREEN, MENU_I_CONFIG };
	static const uint8_t page[3] = { MENU_CONTENT, MENU_SCREEN, MENU_CONFIG };
	struct sim s;
	(void)state;
	in_menu(&s, &base);
	assert_int_equal(MENU_I_LATENCY + 1, MENU_I_CONTENT);
	assert_int_equal(MENU_I_CONFIG + 1, MENU_I_WIZARD);
	assert_true(MENU_LATENCY < MENU_CONTENT && MENU_CONFIG + 1 == MENU_PAGES);
	for (int k = 0; k < 3; k++) {
		struct menu before;
		while (s.menu.cursor != item[k])
			press(&s, DOWN);
		before = s.menu;
		sim_tick(&s, &FIRE);
		assert_int_equal(s.menu.page, page[k]);
		assert_int_equal(s.mode, SIM_SERVICE);
		sim_tick(&s, &FIRE);               /* held: no new request */
		assert_int_equal(s.menu.page, MENU_MAIN);
		assert_int_equal(s.menu.cursor, item[k]);
		sim_tick(&s, &none);
		before.t = s.menu.t;
		before.main_cursor = item[k];
		assert_memory_equal(&before, &s.menu, sizeof(before));
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_cursor_moves_and_wraps_and_pages_open_and_close),
		cmocka_unit_test(a_held_direction_repeats),
		cmocka_unit_test(the_input_test_shows_commands_and_counts_coins),
		cmocka_unit_test(the_display_test_steps_through_its_screens),
		cmocka_unit_test(settings_change_with_left_and_right),
		cmocka_unit_test(factory_defaults_restore_every_setting),
		cmocka_unit_test(resets_need_a_yes),
		cmocka_unit_test(the_exit_item_leaves),
		cmocka_unit_test(configure_inputs_is_a_one_tick_request),
		cmocka_unit_test(the_diagnostics_pages_open_and_go_back),
		cmocka_unit_test(the_app_pages_are_one_tick_requests),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
