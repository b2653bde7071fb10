/*
 * Tests of the terminal key decoder (input/ttyk.c): bytes and times
 * in, key presses and synthesized releases out. Expected key codes are the
 * kernel's KEY_* values; expected times follow from the hold-off rules in
 * ttyk.h (200 ms after a press, 150 ms after a repeat, 50 ms ESC
 * wait).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <linux/input-event-codes.h>

#include "engine/game/menu.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "g_fixture.h"
#include "input/ttyk.h"

#define MS(x) ((uint64_t)(x) * 1000000u)
#define T0 MS(1000)

struct out {
	struct in_event ev[256];
	int n;
};

static void drain(struct ttyk *k, struct out *o)
{
	o->n += ttyk_take(k, o->ev + o->n, (int)(sizeof(o->ev) / sizeof(o->ev[0])) - o->n);
}

/* Feeds len bytes at t, taking events whenever the queue fills. */
static void feedn(struct ttyk *k, const char *s, size_t len, uint64_t t, struct out *o)
{
	size_t off = 0;
	int stuck = 0;

	while (off < len) {
		size_t used = ttyk_feed(k, (const uint8_t *)s + off, len - off, t);

		off += used;
		drain(k, o);
		stuck = used == 0 ? stuck + 1 : 0;
		assert_true(stuck < 2);
	}
	drain(k, o);
}

static void feed(struct ttyk *k, const char *s, uint64_t t, struct out *o)
{
	feedn(k, s, strlen(s), t, o);
}

static void expire(struct ttyk *k, uint64_t t, struct out *o)
{
	ttyk_expire(k, t);
	drain(k, o);
}

static void assert_ev(const struct out *o, int i, int code, int value, uint64_t t)
{
	assert_true(i < o->n);
	assert_int_equal(o->ev[i].type, IN_KEY);
	assert_int_equal(o->ev[i].code, code);
	assert_int_equal(o->ev[i].value, value);
	assert_int_equal(o->ev[i].time_ns, t);
}

/* One byte or sequence in, exactly one press of code out. */
static void assert_single_press(const char *bytes, int code)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	ttyk_init(&k);
	feed(&k, bytes, T0, &o);
	assert_int_equal(o.n, 1);
	assert_ev(&o, 0, code, 1, T0);
}

static void test_letters_either_case_press_their_key(void **state)
{
	(void)state;
	assert_single_press("a", KEY_A);
	assert_single_press("A", KEY_A);
	assert_single_press("q", KEY_Q);
	assert_single_press("z", KEY_Z);
	assert_single_press("M", KEY_M);
}

static void test_digits_space_comma_dot(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "1 ,.0", T0, &o);
	assert_int_equal(o.n, 5);
	assert_ev(&o, 0, KEY_1, 1, T0);
	assert_ev(&o, 1, KEY_SPACE, 1, T0);
	assert_ev(&o, 2, KEY_COMMA, 1, T0);
	assert_ev(&o, 3, KEY_DOT, 1, T0);
	assert_ev(&o, 4, KEY_0, 1, T0);
}

static void test_enter_tab_backspace(void **state)
{
	(void)state;
	assert_single_press("\r", KEY_ENTER);
	assert_single_press("\n", KEY_ENTER);
	assert_single_press("\t", KEY_TAB);
	assert_single_press("\x7f", KEY_BACKSPACE);
}

static void test_arrows_csi_form(void **state)
{
	(void)state;
	assert_single_press("\x1b[A", KEY_UP);
	assert_single_press("\x1b[B", KEY_DOWN);
	assert_single_press("\x1b[C", KEY_RIGHT);
	assert_single_press("\x1b[D", KEY_LEFT);
}

static void test_arrows_ss3_form(void **state)
{
	(void)state;
	assert_single_press("\x1bOA", KEY_UP);
	assert_single_press("\x1bOB", KEY_DOWN);
	assert_single_press("\x1bOC", KEY_RIGHT);
	assert_single_press("\x1bOD", KEY_LEFT);
}

static void test_modified_arrow_is_the_arrow(void **state)
{
	(void)state;
	assert_single_press("\x1b[1;5A", KEY_UP);
	assert_single_press("\x1b[1;2D", KEY_LEFT);
}

static void test_function_keys_all_forms(void **state)
{
	(void)state;
	assert_single_press("\x1bOP", KEY_F1);
	assert_single_press("\x1bOS", KEY_F4);
	assert_single_press("\x1b[11~", KEY_F1);
	assert_single_press("\x1b[12~", KEY_F2);
	assert_single_press("\x1b[15~", KEY_F5);
	assert_single_press("\x1b[17~", KEY_F6);
	assert_single_press("\x1b[24~", KEY_F12);
	assert_single_press("\x1b[12;2~", KEY_F2);
	assert_single_press("\x1b[[A", KEY_F1);
	assert_single_press("\x1b[[E", KEY_F5);
	assert_single_press("\x1b[3~", KEY_DELETE);
	assert_single_press("\x1b[H", KEY_HOME);
}

static void test_sequence_split_across_reads(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "\x1b", T0, &o);
	expire(&k, T0 + MS(16), &o);        /* a tick passes: still waiting */
	feed(&k, "[", T0 + MS(20), &o);
	expire(&k, T0 + MS(33), &o);
	feed(&k, "A", T0 + MS(40), &o);
	assert_int_equal(o.n, 1);
	assert_ev(&o, 0, KEY_UP, 1, T0 + MS(40));

	/* Split inside the parameters of a tilde sequence. */
	ttyk_init(&k);
	o.n = 0;
	feed(&k, "\x1b[1", T0, &o);
	feed(&k, "2~", T0 + MS(10), &o);
	assert_int_equal(o.n, 1);
	assert_ev(&o, 0, KEY_F2, 1, T0 + MS(10));
}

static void test_lone_esc_becomes_esc_after_wait(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "\x1b", T0, &o);
	expire(&k, T0 + MS(49), &o);
	assert_int_equal(o.n, 0);
	expire(&k, T0 + MS(50), &o);
	assert_int_equal(o.n, 1);
	/* Stamped when its byte was read. */
	assert_ev(&o, 0, KEY_ESC, 1, T0);
}

static void test_esc_followed_by_sequence_in_one_read(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "\x1b\x1b[A", T0, &o);
	assert_int_equal(o.n, 2);
	assert_ev(&o, 0, KEY_ESC, 1, T0);
	assert_ev(&o, 1, KEY_UP, 1, T0);
}

static void test_unknown_sequences_consumed_entirely(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };
	char overlong[64];

	(void)state;
	ttyk_init(&k);
	/* Cursor position report, DEC private mode, unknown tilde code,
	 * unknown SS3 final, Alt+x, UTF-8 'e acute', Ctrl-A, then 'b'. */
	feed(&k, "\x1b[12;40R\x1b[?25h\x1b[99~\x1bOZ\x1bx\xc3\xa9\x01" "b", T0, &o);
	assert_int_equal(o.n, 1);
	assert_ev(&o, 0, KEY_B, 1, T0);

	/* A CSI longer than the sequence buffer is skipped up to its final
	 * byte; its digits must not turn into keys. */
	ttyk_init(&k);
	o.n = 0;
	memset(overlong, '7', sizeof(overlong));
	memcpy(overlong, "\x1b[", 2);
	overlong[sizeof(overlong) - 3] = 'A';
	overlong[sizeof(overlong) - 2] = 'c';
	overlong[sizeof(overlong) - 1] = '\0';
	feed(&k, overlong, T0, &o);
	assert_int_equal(o.n, 1);
	assert_ev(&o, 0, KEY_C, 1, T0);
}

static void test_broken_sequence_drops_and_keeps_the_byte(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	/* DEL cannot be inside a CSI: the sequence ends, DEL is Backspace. */
	feed(&k, "\x1b[1\x7f", T0, &o);
	assert_int_equal(o.n, 1);
	assert_ev(&o, 0, KEY_BACKSPACE, 1, T0);
}

static void test_stale_partial_sequence_is_dropped(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "\x1b[", T0, &o);
	expire(&k, T0 + MS(50), &o);
	assert_int_equal(o.n, 0);
	/* Too late to finish it: 'A' is now the letter. */
	feed(&k, "A", T0 + MS(60), &o);
	assert_int_equal(o.n, 1);
	assert_ev(&o, 0, KEY_A, 1, T0 + MS(60));
}

static void test_tap_released_after_first_hold(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "\x1b[A", T0, &o);
	assert_int_equal(ttyk_deadline(&k), T0 + MS(200));
	expire(&k, T0 + MS(199), &o);
	assert_int_equal(o.n, 1);
	expire(&k, T0 + MS(200), &o);
	assert_int_equal(o.n, 2);
	assert_ev(&o, 1, KEY_UP, 0, T0 + MS(200));
	assert_int_equal(ttyk_deadline(&k), 0);
}

static void test_held_key_repeats_then_released_after_repeat_hold(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "w", T0, &o);
	/* Initial autorepeat delay 180 ms (inside the first hold), then
	 * every 33 ms. */
	feed(&k, "w", T0 + MS(180), &o);
	feed(&k, "w", T0 + MS(213), &o);
	expire(&k, T0 + MS(240), &o);        /* past the first hold: repeats keep it */
	feed(&k, "w", T0 + MS(246), &o);
	assert_int_equal(o.n, 1);
	assert_int_equal(ttyk_deadline(&k), T0 + MS(246 + 150));
	expire(&k, T0 + MS(395), &o);
	assert_int_equal(o.n, 1);
	expire(&k, T0 + MS(396), &o);
	assert_int_equal(o.n, 2);
	assert_ev(&o, 0, KEY_W, 1, T0);
	assert_ev(&o, 1, KEY_W, 0, T0 + MS(396));
}

static void test_hold_with_long_repeat_delay_is_pressed_again(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	/* GNOME: the first repeat 500 ms after the press, then every 33 ms. */
	feed(&k, "w", T0, &o);
	expire(&k, T0 + MS(200), &o);        /* no repeat within the first hold: a tap */
	assert_int_equal(o.n, 2);
	assert_ev(&o, 1, KEY_W, 0, T0 + MS(200));
	feed(&k, "w", T0 + MS(500), &o);     /* the first repeat presses it again */
	feed(&k, "w", T0 + MS(533), &o);
	feed(&k, "w", T0 + MS(566), &o);
	assert_int_equal(o.n, 3);
	assert_ev(&o, 2, KEY_W, 1, T0 + MS(500));
	assert_int_equal(ttyk_deadline(&k), T0 + MS(566 + 150));
}

static void test_other_key_keeps_first_down_until_newest_released(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "\x1b[A", T0, &o);                   /* hold up */
	feed(&k, "\x1b[A", T0 + MS(180), &o);
	feed(&k, "\x1b[D", T0 + MS(200), &o);         /* tap left */
	expire(&k, T0 + MS(340), &o);                 /* up's own hold-off (330) passed */
	assert_int_equal(o.n, 2);
	assert_ev(&o, 0, KEY_UP, 1, T0);
	assert_ev(&o, 1, KEY_LEFT, 1, T0 + MS(200));
	expire(&k, T0 + MS(200 + 199), &o);
	assert_int_equal(o.n, 2);
	expire(&k, T0 + MS(200 + 200), &o);
	/* Both released, newest first. */
	assert_int_equal(o.n, 4);
	assert_ev(&o, 2, KEY_LEFT, 0, T0 + MS(400));
	assert_ev(&o, 3, KEY_UP, 0, T0 + MS(400));
}

static void test_older_held_key_again_becomes_newest(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "w", T0, &o);
	feed(&k, "a", T0 + MS(100), &o);
	feed(&k, "w", T0 + MS(200), &o);    /* no new press: W is down */
	assert_int_equal(o.n, 2);
	assert_int_equal(ttyk_deadline(&k), T0 + MS(400));
	expire(&k, T0 + MS(400), &o);
	assert_int_equal(o.n, 4);
	assert_ev(&o, 2, KEY_W, 0, T0 + MS(400));
	assert_ev(&o, 3, KEY_A, 0, T0 + MS(400));
}

static void test_late_read_releases_before_new_press(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };

	(void)state;
	ttyk_init(&k);
	feed(&k, "w", T0, &o);
	/* No expire call in between; the next byte comes after the hold-off. */
	feed(&k, "w", T0 + MS(700), &o);
	assert_int_equal(o.n, 3);
	assert_ev(&o, 0, KEY_W, 1, T0);
	assert_ev(&o, 1, KEY_W, 0, T0 + MS(700));
	assert_ev(&o, 2, KEY_W, 1, T0 + MS(700));
}

static void test_ninth_key_releases_oldest(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };
	static const int keys[9] = { KEY_A, KEY_B, KEY_C, KEY_D, KEY_E, KEY_F, KEY_G, KEY_H,
				     KEY_I };

	(void)state;
	ttyk_init(&k);
	feed(&k, "abcdefghi", T0, &o);
	assert_int_equal(o.n, 10);
	for (int i = 0; i < 8; i++)
		assert_ev(&o, i, keys[i], 1, T0);
	assert_ev(&o, 8, KEY_A, 0, T0);
	assert_ev(&o, 9, KEY_I, 1, T0);
}

static void test_long_paste_fills_queue_and_resumes(void **state)
{
	struct ttyk k;
	struct out o = { .n = 0 };
	char text[3 * 26 + 1];
	int down[KEY_MAX + 1] = { 0 };
	size_t used;

	(void)state;
	for (int i = 0; i < 3 * 26; i++)
		text[i] = (char)('a' + i % 26);
	text[3 * 26] = '\0';
	ttyk_init(&k);
	used = ttyk_feed(&k, (const uint8_t *)text, strlen(text), T0);
	/* 8 presses, then 2 events per byte: the 64-slot queue stops it early. */
	assert_true(used < strlen(text));
	assert_true(used > 8);
	drain(&k, &o);
	feed(&k, text + used, T0, &o);
	/* Every byte is a key not among the 8 held: 8 presses, then a
	 * release of the oldest and a press for each of the other 70. */
	assert_int_equal(o.n, 8 + 70 * 2);
	for (int i = 0; i < o.n; i++) {
		assert_int_not_equal(down[o.ev[i].code], o.ev[i].value);
		down[o.ev[i].code] = o.ev[i].value;
	}
}

/* ---- taps and holds as the service menu sees them ------------------------
 * The terminal preview's keys drive the same sim as a cabinet's: a held
 * direction repeats in the menu after some ticks (engine/game/sim.c). What
 * counts is the outcome: how often the cursor moves when the decoder's
 * events, sampled once per 60 Hz tick as the app does, are the sim's
 * commands. */

#define TICK_NS 16666667u

/* The times bytes of one key arrive, ms after T0, ending with -1. */
static int menu_moves(const int *arrive_ms, int ticks)
{
	static const struct gf_thing th[] = { { 100, 100, 0, 1, 0 } };
	static const struct sim_settings set = { 1, 0, 0, 1, 3, 100, 1, 0, 0, 0 };
	struct map *m = gf_room(512, 512, th, 1, NULL, 0);
	struct sim *s = calloc(1, sizeof(*s));
	struct ttyk k;
	struct out o;
	int down = 0, moves = 0, next = 0;
	uint8_t cursor;

	assert_non_null(m);
	assert_non_null(s);
	sim_init(s, m, &set);
	sim_tick(s, &(struct sim_cmd){ .buttons = SIM_BT_SERVICE });
	sim_tick(s, &(struct sim_cmd){ 0 });
	assert_int_equal(s->mode, SIM_SERVICE);
	cursor = s->menu.cursor;
	ttyk_init(&k);
	for (int t = 0; t < ticks; t++) {
		uint64_t now = T0 + (uint64_t)t * TICK_NS;
		struct sim_cmd c = { 0 };

		o.n = 0;
		/* the bytes that came since the last tick, read now */
		while (arrive_ms[next] >= 0 && T0 + MS(arrive_ms[next]) <= now) {
			feed(&k, "\x1b[B", now, &o);
			next++;
		}
		expire(&k, now, &o);
		for (int i = 0; i < o.n; i++)
			if (o.ev[i].code == KEY_DOWN)
				down = o.ev[i].value;
		c.forward = (int8_t)(down ? -127 : 0);
		sim_tick(s, &c);
		if (s->menu.cursor != cursor)
			moves++;
		cursor = s->menu.cursor;
	}
	free(s);
	map_free(m);
	return moves;
}

static void test_tap_moves_the_menu_cursor_once(void **state)
{
	static const int tap[] = { 0, -1 };
	static const int two_taps[] = { 0, 1000, -1 };

	(void)state;
	assert_int_equal(menu_moves(tap, 120), 1);
	assert_int_equal(menu_moves(two_taps, 180), 2);
}

static void test_held_key_still_repeats_in_the_menu(void **state)
{
	/* A terminal's autorepeat: the first repeat after 250 ms (the Linux
	 * console) or 500 ms (GNOME), then every 33 ms, for 1.5 s. */
	int console[64], gnome[64], n = 0;

	(void)state;
	console[n++] = 0;
	for (int t = 250; t <= 1500; t += 33)
		console[n++] = t;
	console[n] = -1;
	n = 0;
	gnome[n++] = 0;
	for (int t = 500; t <= 1500; t += 33)
		gnome[n++] = t;
	gnome[n] = -1;
	/* Held for 1.5 s, a direction moves the cursor several times. */
	assert_true(menu_moves(console, 150) >= 4);
	assert_true(menu_moves(gnome, 150) >= 4);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_letters_either_case_press_their_key),
		cmocka_unit_test(test_digits_space_comma_dot),
		cmocka_unit_test(test_enter_tab_backspace),
		cmocka_unit_test(test_arrows_csi_form),
		cmocka_unit_test(test_arrows_ss3_form),
		cmocka_unit_test(test_modified_arrow_is_the_arrow),
		cmocka_unit_test(test_function_keys_all_forms),
		cmocka_unit_test(test_sequence_split_across_reads),
		cmocka_unit_test(test_lone_esc_becomes_esc_after_wait),
		cmocka_unit_test(test_esc_followed_by_sequence_in_one_read),
		cmocka_unit_test(test_unknown_sequences_consumed_entirely),
		cmocka_unit_test(test_broken_sequence_drops_and_keeps_the_byte),
		cmocka_unit_test(test_stale_partial_sequence_is_dropped),
		cmocka_unit_test(test_tap_released_after_first_hold),
		cmocka_unit_test(test_held_key_repeats_then_released_after_repeat_hold),
		cmocka_unit_test(test_hold_with_long_repeat_delay_is_pressed_again),
		cmocka_unit_test(test_other_key_keeps_first_down_until_newest_released),
		cmocka_unit_test(test_older_held_key_again_becomes_newest),
		cmocka_unit_test(test_late_read_releases_before_new_press),
		cmocka_unit_test(test_ninth_key_releases_oldest),
		cmocka_unit_test(test_long_paste_fills_queue_and_resumes),
		cmocka_unit_test(test_tap_moves_the_menu_cursor_once),
		cmocka_unit_test(test_held_key_still_repeats_in_the_menu),
	};

	return cmocka_run_group_tests_name("ttyk", tests, NULL, NULL);
}
