/*
 * wiz: whole wizard runs fed by hand, each ending in a bindings table
 * worked out by hand from the rules of app/wiz.h (not from the output);
 * the page drawn at two sizes, its prompt found by its colour and counted
 * pixel by pixel against the font's glyph bits.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <linux/input-event-codes.h>

#include "app/wiz.h"
#include "config/bind.h"
#include "engine/core/pal.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud.h"
#include "engine/ui/v_video.h"

#define MS 1000000ull
#define S 1000000000ull
#define T0 (5 * S)                     /* any start time */

/* The steps in the order wiz.h gives. */
enum { UP, DOWN, LEFT, RIGHT, FIRE, USE, SLEFT, SRIGHT, START, COIN, SERVICE, WEAPON, LOOKUP,
       LOOKDOWN };

static struct in_ident ident(const char *port, uint16_t vid, uint16_t pid, const char *name)
{
	struct in_ident id;

	memset(&id, 0, sizeof(id));
	snprintf(id.port, sizeof(id.port), "%s", port);
	id.vid = vid;
	id.pid = pid;
	snprintf(id.name, sizeof(id.name), "%s", name);
	return id;
}

/* A short press: down at *t, up 100 ms later; *t moves on 200 ms. */
static void tap(struct wiz *w, const char *be, const struct in_ident *id, int code, uint64_t *t)
{
	wiz_event(w, be, id, code, 1, *t);
	assert_int_equal(wiz_tick(w, *t + 50 * MS), WIZ_RUNNING);
	wiz_event(w, be, id, code, 0, *t + 100 * MS);
	*t += 200 * MS;
}

/* A hold: down at *t, ticks up to 1.2 s, up at 1.3 s; *t moves on 1.5 s. */
static void hold(struct wiz *w, const char *be, const struct in_ident *id, int code, uint64_t *t)
{
	wiz_event(w, be, id, code, 1, *t);
	for (uint64_t d = 0; d <= 1200 * MS; d += 100 * MS)
		wiz_tick(w, *t + d);
	wiz_event(w, be, id, code, 0, *t + 1300 * MS);
	*t += 1500 * MS;
}

/* Every action of a section: one list each, in enum act order, ended by
 * -1 per action (at most BIND_MAX codes). */
static void expect_section(const int key[ACT_COUNT][BIND_MAX], const int want[ACT_COUNT][BIND_MAX])
{
	for (int a = 0; a < ACT_COUNT; a++)
		for (int i = 0; i < BIND_MAX; i++) {
			if (key[a][i] != want[a][i])
				fail_msg("action %s slot %d: %d, want %d", act_name(a), i, key[a][i],
					 want[a][i]);
		}
}

static const struct bind_dev *section(const struct bind_table *b, const char *id)
{
	for (int i = 0; i < b->ndev; i++)
		if (strcmp(b->dev[i].id, id) == 0)
			return &b->dev[i];
	fail_msg("no section %s", id);
	return NULL;
}

/* The defaults of docs/config.md, by hand. */
static void defaults_by_hand(int k[ACT_COUNT][BIND_MAX])
{
	memset(k, 0xff, sizeof(int) * ACT_COUNT * BIND_MAX);
	k[ACT_FORWARD][0] = KEY_UP, k[ACT_FORWARD][1] = KEY_W;
	k[ACT_BACK][0] = KEY_DOWN, k[ACT_BACK][1] = KEY_S;
	k[ACT_TURN_LEFT][0] = KEY_LEFT;
	k[ACT_TURN_RIGHT][0] = KEY_RIGHT;
	k[ACT_STRAFE_LEFT][0] = KEY_A, k[ACT_STRAFE_LEFT][1] = KEY_COMMA;
	k[ACT_STRAFE_RIGHT][0] = KEY_D, k[ACT_STRAFE_RIGHT][1] = KEY_DOT;
	k[ACT_FIRE][0] = KEY_LEFTCTRL, k[ACT_FIRE][1] = KEY_SPACE;
	k[ACT_USE][0] = KEY_E;
	k[ACT_START][0] = KEY_1, k[ACT_START][1] = KEY_ENTER;
	k[ACT_COIN][0] = KEY_5;
	k[ACT_SERVICE][0] = KEY_9, k[ACT_SERVICE][1] = KEY_F2;
	k[ACT_WEAPON][0] = KEY_Z, k[ACT_WEAPON][1] = KEY_TAB;
	k[ACT_LOOK_UP][0] = KEY_PAGEUP;
	k[ACT_LOOK_DOWN][0] = KEY_PAGEDOWN;
	/* player 2: MAME's 2 start and player 2 keys */
	k[ACT_START2][0] = KEY_2;
	k[ACT_P2_FORWARD][0] = KEY_R;
	k[ACT_P2_BACK][0] = KEY_F;
	k[ACT_P2_TURN_LEFT][0] = KEY_D;
	k[ACT_P2_TURN_RIGHT][0] = KEY_G;
	k[ACT_P2_FIRE][0] = KEY_A;
	k[ACT_P2_USE][0] = KEY_S;
	k[ACT_P2_WEAPON][0] = KEY_Q;
}

/* Sets action a of k to exactly the one code c (or none for -1). */
static void only(int k[ACT_COUNT][BIND_MAX], int a, int c)
{
	for (int i = 0; i < BIND_MAX; i++)
		k[a][i] = -1;
	k[a][0] = c;
}

/* Ends the summary with a short press (save). */
static void save(struct wiz *w, uint64_t *t)
{
	static const struct in_ident none;

	assert_int_equal(wiz_step(w), WIZ_STEPS);
	tap(w, "evdev", &none, KEY_ENTER, t);
	assert_int_equal(wiz_tick(w, *t), WIZ_DONE);
}

static void the_steps_are_in_stick_then_button_order(void **state)
{
	static const int want[WIZ_STEPS] = { ACT_FORWARD, ACT_BACK, ACT_TURN_LEFT, ACT_TURN_RIGHT,
					     ACT_FIRE, ACT_USE, ACT_STRAFE_LEFT, ACT_STRAFE_RIGHT,
					     ACT_START, ACT_COIN, ACT_SERVICE, ACT_WEAPON,
					     ACT_LOOK_UP, ACT_LOOK_DOWN };

	(void)state;
	for (int k = 0; k < WIZ_STEPS; k++)
		assert_int_equal(wiz_step_action(k), want[k]);
	assert_int_equal(wiz_step_action(-1), -1);
	assert_int_equal(wiz_step_action(WIZ_STEPS), -1);
}

/* A HID encoder on port 1-1 (no section yet): its section starts as a copy
 * of [keyboard]; the service step is skipped and keeps [keyboard]'s keys. */
static void a_hid_device_on_a_port_gets_its_own_section(void **state)
{
	struct in_ident hid = ident("1-1", 0x0079, 0x0006, "Generic USB Joystick");
	static const int codes[] = { BTN_DPAD_UP, BTN_DPAD_DOWN, BTN_DPAD_LEFT, BTN_DPAD_RIGHT,
				     BTN_TRIGGER_HAPPY1, BTN_TRIGGER_HAPPY2, BTN_TRIGGER_HAPPY5,
				     BTN_TRIGGER_HAPPY6, BTN_TRIGGER_HAPPY10, BTN_TRIGGER_HAPPY9 };
	int want[ACT_COUNT][BIND_MAX], kbd[ACT_COUNT][BIND_MAX], acts[ACT_COUNT];
	struct bind_table b, out, back;
	struct wiz w;
	uint64_t t = T0;
	char text[4096];
	struct wiz_ctl c;
	int step;

	(void)state;
	bind_defaults(&b);
	wiz_start(&w, &b, t);
	for (int k = UP; k <= COIN; k++) {
		assert_int_equal(wiz_step(&w), k);
		tap(&w, "hid", &hid, codes[k], &t);
		assert_int_equal(wiz_last_note(&w, &step, &c), WIZ_N_ASSIGNED);
		assert_int_equal(step, k);
		assert_int_equal(c.code, codes[k]);
		assert_string_equal(c.sec, "usb-1-1");
	}
	hold(&w, "hid", &hid, BTN_TRIGGER_HAPPY3, &t);
	assert_int_equal(wiz_last_note(&w, &step, NULL), WIZ_N_SKIPPED);
	assert_int_equal(step, SERVICE);
	hold(&w, "hid", &hid, BTN_TRIGGER_HAPPY3, &t);
	assert_int_equal(wiz_last_note(&w, &step, NULL), WIZ_N_SKIPPED);
	assert_int_equal(step, WEAPON);
	/* look up: a button (a second stick's up is the same: a code) */
	assert_int_equal(wiz_step(&w), LOOKUP);
	tap(&w, "hid", &hid, BTN_TRIGGER_HAPPY7, &t);
	assert_int_equal(wiz_last_note(&w, &step, &c), WIZ_N_ASSIGNED);
	assert_int_equal(step, LOOKUP);
	assert_int_equal(c.code, BTN_TRIGGER_HAPPY7);
	/* look down: skipped, as a pad with too few buttons does */
	hold(&w, "hid", &hid, BTN_TRIGGER_HAPPY3, &t);
	assert_int_equal(wiz_last_note(&w, &step, NULL), WIZ_N_SKIPPED);
	assert_int_equal(step, LOOKDOWN);
	save(&w, &t);
	assert_int_equal(wiz_result(&w, &out), 1);

	defaults_by_hand(kbd);
	expect_section((const int (*)[BIND_MAX])out.key, (const int (*)[BIND_MAX])kbd);
	assert_int_equal(out.ndev, 1);
	defaults_by_hand(want);
	only(want, ACT_FORWARD, BTN_DPAD_UP);
	only(want, ACT_BACK, BTN_DPAD_DOWN);
	only(want, ACT_TURN_LEFT, BTN_DPAD_LEFT);
	only(want, ACT_TURN_RIGHT, BTN_DPAD_RIGHT);
	only(want, ACT_FIRE, BTN_TRIGGER_HAPPY1);
	only(want, ACT_USE, BTN_TRIGGER_HAPPY2);
	only(want, ACT_STRAFE_LEFT, BTN_TRIGGER_HAPPY5);
	only(want, ACT_STRAFE_RIGHT, BTN_TRIGGER_HAPPY6);
	only(want, ACT_START, BTN_TRIGGER_HAPPY10);
	only(want, ACT_COIN, BTN_TRIGGER_HAPPY9);
	only(want, ACT_LOOK_UP, BTN_TRIGGER_HAPPY7);
	/* service, weapon and look down: skipped, keep KEY_9, KEY_F2, KEY_Z,
	 * KEY_TAB and KEY_PAGEDOWN from the copy of [keyboard] */
	expect_section((const int (*)[BIND_MAX])section(&out, "usb-1-1")->key,
		       (const int (*)[BIND_MAX])want);

	/* as the app saves and reloads it: the encoder's button 1 fires */
	assert_true(bind_format(&out, text, sizeof(text)) < sizeof(text));
	bind_defaults(&back);
	assert_int_equal(bind_load_text(&back, text, strlen(text), "bindings.ini", NULL, NULL), 0);
	assert_int_equal(bind_lookup_dev(&back, &hid, BTN_TRIGGER_HAPPY1, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_FIRE);
	assert_int_equal(bind_lookup_dev(&back, &hid, KEY_9, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_SERVICE);
	assert_int_equal(bind_lookup_dev(&back, &hid, BTN_TRIGGER_HAPPY7, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_LOOK_UP);
	assert_int_equal(bind_lookup_dev(&back, &hid, KEY_PAGEDOWN, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_LOOK_DOWN);
}

/* The 1 s boundary: 999,999,999 ns is a press, 1 s a skip, whether the
 * tick or the release sees it first; the release after a skip is ignored,
 * and so is every control held at the skip. */
static void holding_one_second_skips_and_keeps_the_old_binding(void **state)
{
	int want[ACT_COUNT][BIND_MAX];
	struct bind_table b, out;
	struct wiz w;
	uint64_t t = T0;

	(void)state;
	bind_defaults(&b);
	wiz_start(&w, &b, t);
	/* forward: KEY_I held, seen by the tick at exactly 1 s */
	wiz_event(&w, "evdev", NULL, KEY_I, 1, t);
	assert_int_equal(wiz_tick(&w, t + S - 1), WIZ_RUNNING);
	assert_int_equal(wiz_step(&w), UP);
	/* KEY_O pressed meanwhile: held at the skip, so spent too */
	wiz_event(&w, "evdev", NULL, KEY_O, 1, t + 500 * MS);
	assert_int_equal(wiz_tick(&w, t + S), WIZ_RUNNING);
	assert_int_equal(wiz_step(&w), DOWN);
	wiz_event(&w, "evdev", NULL, KEY_O, 0, t + S + 10 * MS);
	wiz_event(&w, "evdev", NULL, KEY_I, 0, t + S + 20 * MS);
	assert_int_equal(wiz_step(&w), DOWN);
	t += 2 * S;
	/* back: released at 999,999,999 ns: a press */
	wiz_event(&w, "evdev", NULL, KEY_K, 1, t);
	wiz_event(&w, "evdev", NULL, KEY_K, 0, t + S - 1);
	assert_int_equal(wiz_step(&w), LEFT);
	t += 2 * S;
	/* turn left: released at exactly 1 s with no tick between: a skip */
	wiz_event(&w, "evdev", NULL, KEY_J, 1, t);
	wiz_event(&w, "evdev", NULL, KEY_J, 0, t + S);
	assert_int_equal(wiz_step(&w), RIGHT);
	assert_int_equal(wiz_last_note(&w, NULL, NULL), WIZ_N_SKIPPED);
	t += 2 * S;
	/* the rest skipped */
	for (int k = RIGHT; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_L, &t);
	save(&w, &t);
	assert_int_equal(wiz_result(&w, &out), 1);
	defaults_by_hand(want);
	only(want, ACT_BACK, KEY_K);
	expect_section((const int (*)[BIND_MAX])out.key, (const int (*)[BIND_MAX])want);
	assert_int_equal(out.ndev, 0);
}

/* A control this run assigned is refused for another action (the step
 * waits, the note names the action it has); a control bound before the
 * run is taken from its old action when assigned to a new one. */
static void a_control_assigned_twice_is_refused(void **state)
{
	int want[ACT_COUNT][BIND_MAX];
	struct bind_table b, out;
	struct wiz_ctl c;
	struct wiz w;
	uint64_t t = T0;
	int step;

	(void)state;
	bind_defaults(&b);
	wiz_start(&w, &b, t);
	tap(&w, "evdev", NULL, KEY_I, &t);             /* forward = I */
	tap(&w, "evdev", NULL, KEY_I, &t);             /* back = I? refused */
	assert_int_equal(wiz_step(&w), DOWN);
	assert_int_equal(wiz_last_note(&w, &step, &c), WIZ_N_TAKEN);
	assert_int_equal(step, UP);
	assert_int_equal(c.code, KEY_I);
	tap(&w, "evdev", NULL, KEY_K, &t);             /* back = K */
	assert_int_equal(wiz_step(&w), LEFT);
	tap(&w, "evdev", NULL, KEY_K, &t);             /* refused again */
	assert_int_equal(wiz_last_note(&w, &step, NULL), WIZ_N_TAKEN);
	assert_int_equal(step, DOWN);
	tap(&w, "evdev", NULL, KEY_SPACE, &t);         /* turn left = SPACE, off fire */
	for (int k = RIGHT; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_L, &t);
	save(&w, &t);
	assert_int_equal(wiz_result(&w, &out), 1);
	defaults_by_hand(want);
	only(want, ACT_FORWARD, KEY_I);
	only(want, ACT_BACK, KEY_K);
	only(want, ACT_TURN_LEFT, KEY_SPACE);
	only(want, ACT_FIRE, KEY_LEFTCTRL);            /* was LEFTCTRL, SPACE */
	expect_section((const int (*)[BIND_MAX])out.key, (const int (*)[BIND_MAX])want);
}

/* No ident, an ident with neither port nor VID:PID (GPIO, the terminal):
 * [keyboard], no section made. */
static void a_keyboard_without_ident_binds_in_keyboard(void **state)
{
	struct in_ident gpio = ident("", 0, 0, "gpio gpiochip0");
	int want[ACT_COUNT][BIND_MAX];
	struct bind_table b, out;
	struct wiz w;
	uint64_t t = T0;

	(void)state;
	bind_defaults(&b);
	wiz_start(&w, &b, t);
	tap(&w, "evdev", NULL, KEY_W, &t);             /* forward = W (was UP, W) */
	tap(&w, "tty", NULL, KEY_S, &t);               /* back = S */
	tap(&w, NULL, NULL, KEY_A, &t);                /* turn left = A, off strafe left */
	tap(&w, "gpio", &gpio, KEY_D, &t);             /* turn right = D, off strafe right */
	for (int k = FIRE; k <= LOOKDOWN; k++)
		hold(&w, "gpio", &gpio, KEY_5, &t);
	save(&w, &t);
	assert_int_equal(wiz_result(&w, &out), 1);
	assert_int_equal(out.ndev, 0);
	defaults_by_hand(want);
	only(want, ACT_FORWARD, KEY_W);
	only(want, ACT_BACK, KEY_S);
	only(want, ACT_TURN_LEFT, KEY_A);
	only(want, ACT_TURN_RIGHT, KEY_D);
	only(want, ACT_STRAFE_LEFT, KEY_COMMA);
	only(want, ACT_STRAFE_RIGHT, KEY_DOT);
	/* the wizard takes a key off every other action: player 2's too */
	only(want, ACT_P2_USE, -1);
	only(want, ACT_P2_FIRE, -1);
	only(want, ACT_P2_TURN_LEFT, -1);
	expect_section((const int (*)[BIND_MAX])out.key, (const int (*)[BIND_MAX])want);
}

/* Two encoders in one run: A on port 1-1 whose VID:PID already has a
 * (profile's) section, B with a VID:PID and no port. A's new port section
 * starts from its VID:PID section, B's from [keyboard]; the same code on
 * two devices is two controls. */
static void two_devices_in_one_run_get_two_sections(void **state)
{
	struct in_ident a = ident("1-1", 0x0079, 0x0006, "DragonRise");
	struct in_ident bb = ident("", 0x16c0, 0x05e1, "Xin-Mo");
	int prof[ACT_COUNT][BIND_MAX], want_a[ACT_COUNT][BIND_MAX], want_b[ACT_COUNT][BIND_MAX];
	int kbd[ACT_COUNT][BIND_MAX];
	struct bind_table b, out;
	struct wiz w;
	uint64_t t = T0;

	(void)state;
	bind_defaults(&b);
	memset(prof, 0xff, sizeof(prof));
	prof[ACT_FIRE][0] = BTN_TRIGGER_HAPPY1;
	prof[ACT_START][0] = BTN_TRIGGER_HAPPY10;
	assert_int_equal(bind_set_device(&b, "0079:0006", (const int (*)[BIND_MAX])prof), 0);
	wiz_start(&w, &b, t);
	tap(&w, "hid", &a, BTN_DPAD_UP, &t);           /* A forward */
	tap(&w, "hid", &bb, BTN_DPAD_DOWN, &t);        /* B back */
	tap(&w, "hid", &a, BTN_DPAD_DOWN, &t);         /* A turn left: not B's control */
	assert_int_equal(wiz_last_note(&w, NULL, NULL), WIZ_N_ASSIGNED);
	tap(&w, "hid", &bb, BTN_DPAD_UP, &t);          /* B turn right */
	assert_int_equal(wiz_last_note(&w, NULL, NULL), WIZ_N_ASSIGNED);
	tap(&w, "hid", &a, BTN_TRIGGER_HAPPY3, &t);    /* A fire (replaces HAPPY1) */
	tap(&w, "hid", &a, BTN_TRIGGER_HAPPY10, &t);   /* A use: off A's start */
	for (int k = SLEFT; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_SPACE, &t);
	save(&w, &t);
	assert_int_equal(wiz_result(&w, &out), 1);

	defaults_by_hand(kbd);
	expect_section((const int (*)[BIND_MAX])out.key, (const int (*)[BIND_MAX])kbd);
	assert_int_equal(out.ndev, 3);
	assert_string_equal(out.dev[0].id, "0079:0006");
	expect_section((const int (*)[BIND_MAX])out.dev[0].key, (const int (*)[BIND_MAX])prof);
	assert_string_equal(out.dev[1].id, "usb-1-1");
	memset(want_a, 0xff, sizeof(want_a));
	only(want_a, ACT_FORWARD, BTN_DPAD_UP);
	only(want_a, ACT_TURN_LEFT, BTN_DPAD_DOWN);
	only(want_a, ACT_FIRE, BTN_TRIGGER_HAPPY3);
	only(want_a, ACT_USE, BTN_TRIGGER_HAPPY10);
	expect_section((const int (*)[BIND_MAX])out.dev[1].key, (const int (*)[BIND_MAX])want_a);
	assert_string_equal(out.dev[2].id, "16c0:05e1");
	defaults_by_hand(want_b);
	only(want_b, ACT_BACK, BTN_DPAD_DOWN);
	only(want_b, ACT_TURN_RIGHT, BTN_DPAD_UP);
	expect_section((const int (*)[BIND_MAX])out.dev[2].key, (const int (*)[BIND_MAX])want_b);
}

static void skipping_every_step_changes_nothing(void **state)
{
	struct bind_table b, out;
	struct wiz w;
	uint64_t t = T0;

	(void)state;
	bind_defaults(&b);
	wiz_start(&w, &b, t);
	for (int k = UP; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_ENTER, &t);
	save(&w, &t);
	assert_int_equal(wiz_result(&w, &out), 0);
	assert_memory_equal(out.key, b.key, sizeof(b.key));
	assert_int_equal(out.ndev, 0);
}

/* Ways a run ends: held 1 s on the summary discards, the summary saves by
 * itself after 10 s, 60 s without an event cancels, and so does
 * wiz_cancel; a cancelled run's result is the table it started from. */
static void the_summary_saves_or_discards_and_idle_cancels(void **state)
{
	struct bind_table b, out;
	struct wiz w;
	uint64_t t;

	(void)state;
	bind_defaults(&b);
	/* discard */
	t = T0;
	wiz_start(&w, &b, t);
	tap(&w, "evdev", NULL, KEY_I, &t);
	for (int k = DOWN; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_L, &t);
	assert_int_equal(wiz_step(&w), WIZ_STEPS);
	hold(&w, "evdev", NULL, KEY_L, &t);
	assert_int_equal(wiz_tick(&w, t), WIZ_CANCELLED);
	assert_int_equal(wiz_result(&w, &out), 0);
	assert_memory_equal(out.key, b.key, sizeof(b.key));
	/* events after the end change nothing */
	wiz_event(&w, "evdev", NULL, KEY_I, 1, t);
	wiz_event(&w, "evdev", NULL, KEY_I, 0, t + 100 * MS);
	assert_int_equal(wiz_tick(&w, t + 200 * MS), WIZ_CANCELLED);
	assert_int_equal(wiz_result(&w, &out), 0);

	/* the summary's own timeout saves */
	t = T0;
	wiz_start(&w, &b, t);
	tap(&w, "evdev", NULL, KEY_I, &t);
	for (int k = DOWN; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_L, &t);
	/* the last hold ended the steps at its 1 s tick, 500 ms before t */
	assert_int_equal(wiz_tick(&w, t - 500 * MS + WIZ_SUMMARY_NS - 1), WIZ_RUNNING);
	assert_int_equal(wiz_tick(&w, t - 500 * MS + WIZ_SUMMARY_NS), WIZ_DONE);
	assert_int_equal(wiz_result(&w, &out), 1);
	assert_int_equal(out.key[ACT_FORWARD][0], KEY_I);

	/* idle: 60 s from the last event */
	t = T0;
	wiz_start(&w, &b, t);
	tap(&w, "evdev", NULL, KEY_I, &t);             /* last event at t - 100 ms */
	assert_int_equal(wiz_tick(&w, t - 100 * MS + WIZ_IDLE_NS - 1), WIZ_RUNNING);
	assert_int_equal(wiz_tick(&w, t - 100 * MS + WIZ_IDLE_NS), WIZ_CANCELLED);
	assert_int_equal(wiz_result(&w, &out), 0);
	assert_int_equal(out.key[ACT_FORWARD][0], KEY_UP);

	/* the app's cancel */
	t = T0;
	wiz_start(&w, &b, t);
	tap(&w, "evdev", NULL, KEY_I, &t);
	wiz_cancel(&w);
	assert_int_equal(wiz_tick(&w, t), WIZ_CANCELLED);
	assert_int_equal(wiz_result(&w, &out), 0);
}

/* The FIRE that chose CONFIGURE INPUTS is down when the run starts: its
 * release is no answer. Repeats change nothing; a device that goes away
 * with a control down neither assigns nor skips with it. */
static void releases_of_earlier_presses_repeats_and_unplugs_are_ignored(void **state)
{
	struct in_ident hid = ident("1-2", 0x0079, 0x0006, "");
	struct bind_table b;
	struct wiz w;
	uint64_t t = T0;

	(void)state;
	bind_defaults(&b);
	wiz_start(&w, &b, t);
	wiz_event(&w, "evdev", NULL, KEY_LEFTCTRL, 0, t + 50 * MS);
	assert_int_equal(wiz_step(&w), UP);
	/* press, two repeats, release: one press of 300 ms */
	wiz_event(&w, "evdev", NULL, KEY_I, 1, t + 100 * MS);
	wiz_event(&w, "evdev", NULL, KEY_I, 1, t + 200 * MS);
	wiz_event(&w, "evdev", NULL, KEY_I, 1, t + 300 * MS);
	wiz_event(&w, "evdev", NULL, KEY_I, 0, t + 400 * MS);
	assert_int_equal(wiz_step(&w), DOWN);
	/* unplugged while held: forgotten, no skip after 1 s, no assignment */
	wiz_event(&w, "hid", &hid, BTN_SOUTH, 1, t + 500 * MS);
	wiz_drop(&w, &hid);
	assert_int_equal(wiz_tick(&w, t + 3 * S), WIZ_RUNNING);
	assert_int_equal(wiz_step(&w), DOWN);
	wiz_event(&w, "hid", &hid, BTN_SOUTH, 0, t + 3 * S);
	assert_int_equal(wiz_step(&w), DOWN);
	/* code 0 (KEY_RESERVED) is no control */
	wiz_event(&w, "hid", &hid, 0, 1, t + 4 * S);
	wiz_event(&w, "hid", &hid, 0, 0, t + 4 * S + 10 * MS);
	assert_int_equal(wiz_step(&w), DOWN);
	assert_int_equal(wiz_tick(&w, t + 5 * S), WIZ_RUNNING);
}

/* BIND_DEVICES sections already: a new device is refused with a note, the
 * step waits, a device that has a section still assigns. */
static void no_room_for_another_section_is_refused(void **state)
{
	struct in_ident fresh = ident("3-1", 0, 0, "");
	struct in_ident known = ident("9-1", 0, 0, "");
	int key[ACT_COUNT][BIND_MAX];
	struct bind_table b, out;
	struct wiz w;
	uint64_t t = T0;
	char id[BIND_ID_MAX];

	(void)state;
	bind_defaults(&b);
	memset(key, 0xff, sizeof(key));
	for (int i = 0; i < BIND_DEVICES; i++) {
		snprintf(id, sizeof(id), "usb-9-%d", i + 1);
		assert_int_equal(bind_set_device(&b, id, (const int (*)[BIND_MAX])key), 0);
	}
	wiz_start(&w, &b, t);
	tap(&w, "hid", &fresh, BTN_SOUTH, &t);
	assert_int_equal(wiz_last_note(&w, NULL, NULL), WIZ_N_FULL);
	assert_int_equal(wiz_step(&w), UP);
	tap(&w, "hid", &known, BTN_SOUTH, &t);
	assert_int_equal(wiz_last_note(&w, NULL, NULL), WIZ_N_ASSIGNED);
	assert_int_equal(wiz_step(&w), DOWN);
	for (int k = DOWN; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_L, &t);
	save(&w, &t);
	assert_int_equal(wiz_result(&w, &out), 1);
	assert_int_equal(out.ndev, BIND_DEVICES);
	assert_int_equal(section(&out, "usb-9-1")->key[ACT_FORWARD][0], BTN_SOUTH);
}

/* ---- drawing ---------------------------------------------------------- */

static int count(const struct r_frame *f, uint8_t c)
{
	int n = 0;

	for (int y = 0; y < f->h; y++)
		for (int x = 0; x < f->w; x++)
			n += f->px[y * f->pitch + x] == c;
	return n;
}

/* Pixels s draws at scale: its glyphs' set bits, scale x scale each. */
static int text_pixels(const char *s, int scale)
{
	int n = 0;

	for (; *s; s++)
		for (int y = 0; y < 8; y++)
			for (int x = 0; x < 8; x++)
				n += v_glyph_bit(*s, x, y);
	return n * scale * scale;
}

/* The prompt is drawn whole in yellow (the one yellow text) at the
 * largest scale up to 3 per 240 lines that fits the width less 4 text
 * pixels each side; notes show in their colours; any size is safe. */
static void the_page_draws_the_prompt_and_notes_at_any_size(void **state)
{
	static const struct {
		int w, h, step;
		const char *prompt;
		int scale;
	} cases[] = {
		/* 320x240: text scale 1; "P1 UP" 120 px at 3 fits 312 */
		{ 320, 240, UP, "P1 UP", 3 },
		/* "P1 STRAFE RIGHT" 15 chars: 360 px at 3 > 312, 240 at 2 */
		{ 320, 240, SRIGHT, "P1 STRAFE RIGHT", 2 },
		/* 1920x1080: text scale 4, prompt up to 12: 1440 px fits 1888 */
		{ 1920, 1080, SRIGHT, "P1 STRAFE RIGHT", 12 },
		{ 1920, 1080, COIN, "COIN", 12 },
		/* the last step: "P1 LOOK DOWN" 12 chars, 288 px at 3 fits 312 */
		{ 320, 240, LOOKDOWN, "P1 LOOK DOWN", 3 },
	};
	struct hud_colours c;
	struct bind_table b;
	struct pal pal;
	struct wiz w;

	(void)state;
	pal_builtin(&pal);
	hud_colours(&pal, &c);
	/* the prompt's colour is used by nothing else on the page */
	assert_true(c.yellow != c.white && c.yellow != c.grey && c.yellow != c.cyan &&
		    c.yellow != c.green && c.yellow != c.orange && c.yellow != c.red &&
		    c.yellow != c.dark && c.yellow != c.black);
	bind_defaults(&b);
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		struct r_frame f = { NULL, cases[i].w, cases[i].h, cases[i].w, NULL };
		uint64_t t = T0;

		f.px = malloc((size_t)f.w * (size_t)f.h);
		assert_non_null(f.px);
		wiz_start(&w, &b, t);
		for (int k = 0; k < cases[i].step; k++)
			tap(&w, "evdev", NULL, KEY_A + k, &t);
		assert_int_equal(wiz_step(&w), cases[i].step);
		wiz_draw(&w, &pal, &f);
		assert_int_equal(count(&f, c.yellow), text_pixels(cases[i].prompt, cases[i].scale));
		assert_true(count(&f, c.black) < f.w * f.h);
		if (cases[i].step > 0) {
			/* the note of the last assignment in green, a refusal in red */
			assert_true(count(&f, c.green) > 0);
			assert_int_equal(count(&f, c.red), 0);
			tap(&w, "evdev", NULL, KEY_A, &t);
			wiz_draw(&w, &pal, &f);
			assert_int_equal(wiz_last_note(&w, NULL, NULL), WIZ_N_TAKEN);
			assert_true(count(&f, c.red) > 0);
		}
		assert_int_equal(count(&f, c.orange), 0);
		/* a hold under way: the bar */
		wiz_event(&w, "evdev", NULL, KEY_Z, 1, t);
		wiz_tick(&w, t + 500 * MS);
		wiz_draw(&w, &pal, &f);
		assert_true(count(&f, c.orange) > 0);
		wiz_tick(&w, t + 2 * S);
		wiz_event(&w, "evdev", NULL, KEY_Z, 0, t + 2 * S);
		t += 3 * S;
		/* the summary: every step listed, no prompt */
		while (wiz_step(&w) < WIZ_STEPS)
			hold(&w, "evdev", NULL, KEY_Z, &t);
		wiz_draw(&w, &pal, &f);
		assert_int_equal(count(&f, c.yellow), 0);
		assert_true(count(&f, c.white) > 0);
		free(f.px);
	}
}

/* The summary: each assigned control in green with its section's letter
 * (the only green on the page), letters in order of first use. */
static void the_summary_lists_controls_with_section_letters(void **state)
{
	struct in_ident hid = ident("1-1", 0, 0, "pad");
	struct r_frame f = { NULL, 320, 240, 320, NULL };
	struct hud_colours c;
	struct bind_table b;
	struct pal pal;
	struct wiz w;
	uint64_t t = T0;

	(void)state;
	pal_builtin(&pal);
	hud_colours(&pal, &c);
	bind_defaults(&b);
	f.px = malloc((size_t)f.w * (size_t)f.h);
	assert_non_null(f.px);
	wiz_start(&w, &b, t);
	tap(&w, "evdev", NULL, KEY_I, &t);              /* [A] KEYBOARD */
	tap(&w, "hid", &hid, BTN_SOUTH, &t);            /* [B] USB-1-1 */
	tap(&w, "evdev", NULL, KEY_K, &t);              /* [A] again */
	for (int k = RIGHT; k <= LOOKDOWN; k++)
		hold(&w, "evdev", NULL, KEY_L, &t);
	wiz_draw(&w, &pal, &f);
	assert_int_equal(count(&f, c.green), text_pixels("KEY_I [A]", 1) +
						     text_pixels("BTN_SOUTH [B]", 1) +
						     text_pixels("KEY_K [A]", 1));
	assert_int_equal(count(&f, c.yellow), 0);
	free(f.px);
}

/* The summary at 320x240 (scale 1) lists all 14 steps' names in white,
 * 9 lines apart from line 36, so they end at 36 + 14 x 9 = 162, above the
 * legend and the white lines at the bottom (from 240 - 36 = 204): the
 * white pixels above 162 are exactly the 14 names' glyph bits, LOOK UP
 * and LOOK DOWN last; LOOK UP's control in green, LOOK DOWN KEPT. */
static void the_summary_fits_every_step_above_the_bottom_lines(void **state)
{
	static const char *const names[WIZ_STEPS] = {
		"FORWARD", "BACK", "TURN LEFT", "TURN RIGHT", "FIRE", "USE", "STRAFE LEFT",
		"STRAFE RIGHT", "START", "COIN", "SERVICE", "WEAPON", "LOOK UP", "LOOK DOWN",
	};
	struct r_frame f = { NULL, 320, 240, 320, NULL };
	struct hud_colours c;
	struct bind_table b;
	struct pal pal;
	struct wiz w;
	uint64_t t = T0;
	int white = 0, green = 0, want = 0;

	(void)state;
	pal_builtin(&pal);
	hud_colours(&pal, &c);
	bind_defaults(&b);
	f.px = malloc((size_t)f.w * (size_t)f.h);
	assert_non_null(f.px);
	wiz_start(&w, &b, t);
	for (int k = UP; k < LOOKUP; k++)
		hold(&w, "evdev", NULL, KEY_L, &t);
	tap(&w, "evdev", NULL, KEY_PAGEUP, &t);         /* LOOK UP = KEY_PAGEUP [A] */
	hold(&w, "evdev", NULL, KEY_L, &t);             /* LOOK DOWN kept */
	assert_int_equal(wiz_step(&w), WIZ_STEPS);
	wiz_draw(&w, &pal, &f);
	for (int y = 0; y < 162; y++)
		for (int x = 0; x < f.w; x++) {
			white += f.px[y * f.pitch + x] == c.white;
			green += f.px[y * f.pitch + x] == c.green;
		}
	for (int k = 0; k < WIZ_STEPS; k++)
		want += text_pixels(names[k], 1);
	assert_int_equal(white, want);
	assert_int_equal(green, text_pixels("KEY_PAGEUP [A]", 1));
	assert_int_equal(count(&f, c.green), green);
	free(f.px);
}

/* Frames smaller than the page: clipped, never written outside (ASan). */
static void tiny_frames_are_safe(void **state)
{
	static const int sizes[][2] = { { 1, 1 }, { 16, 8 }, { 64, 48 }, { 319, 239 } };
	struct bind_table b;
	struct pal pal;
	struct wiz w;

	(void)state;
	pal_builtin(&pal);
	bind_defaults(&b);
	for (size_t i = 0; i < sizeof(sizes) / sizeof(sizes[0]); i++) {
		struct r_frame f = { NULL, sizes[i][0], sizes[i][1], sizes[i][0], NULL };
		uint64_t t = T0;

		f.px = malloc((size_t)f.w * (size_t)f.h);
		assert_non_null(f.px);
		wiz_start(&w, &b, t);
		wiz_draw(&w, &pal, &f);
		for (int k = UP; k <= LOOKDOWN; k++)
			hold(&w, "evdev", NULL, KEY_Z, &t);
		wiz_draw(&w, &pal, &f);
		free(f.px);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_steps_are_in_stick_then_button_order),
		cmocka_unit_test(a_hid_device_on_a_port_gets_its_own_section),
		cmocka_unit_test(holding_one_second_skips_and_keeps_the_old_binding),
		cmocka_unit_test(a_control_assigned_twice_is_refused),
		cmocka_unit_test(a_keyboard_without_ident_binds_in_keyboard),
		cmocka_unit_test(two_devices_in_one_run_get_two_sections),
		cmocka_unit_test(skipping_every_step_changes_nothing),
		cmocka_unit_test(the_summary_saves_or_discards_and_idle_cancels),
		cmocka_unit_test(releases_of_earlier_presses_repeats_and_unplugs_are_ignored),
		cmocka_unit_test(no_room_for_another_section_is_refused),
		cmocka_unit_test(the_page_draws_the_prompt_and_notes_at_any_size),
		cmocka_unit_test(the_summary_lists_controls_with_section_letters),
		cmocka_unit_test(the_summary_fits_every_step_above_the_bottom_lines),
		cmocka_unit_test(tiny_frames_are_safe),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
