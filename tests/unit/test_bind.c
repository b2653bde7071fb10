/*
 * bind: default bindings, the bindings file and its errors, lookups. Key
 * codes are checked against the kernel's own constants
 * (linux/input-event-codes.h), not against libevdev's name table.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <linux/input-event-codes.h>

#include "config/bind.h"
#include "config/cini.h"

struct errs {
	char text[4096];
	size_t n;
	int count;
};

static void on_err(void *user, const char *file, int line, const char *msg)
{
	struct errs *e = user;
	int w = snprintf(e->text + e->n, sizeof(e->text) - e->n, "%s:%d: %s\n", file, line, msg);

	assert_true(w > 0 && (size_t)w < sizeof(e->text) - e->n);
	e->n += (size_t)w;
	e->count++;
}

static int load(struct bind_table *b, const char *text, struct errs *e)
{
	memset(e, 0, sizeof(*e));
	return bind_load_text(b, text, strlen(text), "b.ini", on_err, e);
}

/* Asserts that action a is bound to exactly the keys given, in order. */
static void expect_keys(const struct bind_table *b, int a, int k0, int k1)
{
	assert_int_equal(b->key[a][0], k0);
	assert_int_equal(b->key[a][1], k1);
	for (int i = 2; i < BIND_MAX; i++)
		assert_int_equal(b->key[a][i], -1);
}

static void test_defaults_bind_the_documented_keys(void **state)
{
	struct bind_table b;

	(void)state;
	bind_defaults(&b);
	expect_keys(&b, ACT_FORWARD, KEY_UP, KEY_W);
	expect_keys(&b, ACT_BACK, KEY_DOWN, KEY_S);
	expect_keys(&b, ACT_TURN_LEFT, KEY_LEFT, -1);
	expect_keys(&b, ACT_TURN_RIGHT, KEY_RIGHT, -1);
	expect_keys(&b, ACT_STRAFE_LEFT, KEY_A, KEY_COMMA);
	expect_keys(&b, ACT_STRAFE_RIGHT, KEY_D, KEY_DOT);
	expect_keys(&b, ACT_FIRE, KEY_LEFTCTRL, KEY_SPACE);
	expect_keys(&b, ACT_USE, KEY_E, -1);
	expect_keys(&b, ACT_START, KEY_1, KEY_ENTER);
	expect_keys(&b, ACT_COIN, KEY_5, -1);
	expect_keys(&b, ACT_SERVICE, KEY_9, KEY_F2);
	expect_keys(&b, ACT_WEAPON, KEY_Z, KEY_TAB);
	expect_keys(&b, ACT_LOOK_UP, KEY_PAGEUP, -1);
	expect_keys(&b, ACT_LOOK_DOWN, KEY_PAGEDOWN, -1);
}

static void test_file_replaces_a_whole_action_list(void **state)
{
	struct bind_table b;
	struct errs e;

	(void)state;
	bind_defaults(&b);
	assert_int_equal(load(&b, "# cabinet\n[keyboard]\nfire = x, BTN_SOUTH  # button 1\n"
				  "Forward = KEY_I\nuse =\nstart = 1, 1, key_1, enter\n",
			      &e),
			 0);
	expect_keys(&b, ACT_FIRE, KEY_X, BTN_SOUTH);
	expect_keys(&b, ACT_FORWARD, KEY_I, -1);
	expect_keys(&b, ACT_USE, -1, -1);
	/* The same key named three ways counts once. */
	expect_keys(&b, ACT_START, KEY_1, KEY_ENTER);
	/* Untouched actions keep their defaults. */
	expect_keys(&b, ACT_BACK, KEY_DOWN, KEY_S);
}

static void test_errors_name_file_line_and_keep_the_binding(void **state)
{
	static const char in[] = "[keyboard]\n"                          /* 1 */
				 "jump = space\n"                        /* 2 */
				 "fire = x, nosuchkey\n"                 /* 3 */
				 "coin = a, b, c, d, e\n"                /* 4 */
				 "use = e,,f\n"                          /* 5 */
				 "garbage line\n"                        /* 6 */
				 "[joystick]\n"                          /* 7 */
				 "back = BTN_SOUTH\n"                    /* 8: ignored */
				 "[keyboard]\n"                          /* 9 */
				 "service = f1\n";                       /* 10 */
	static const char want[] = "b.ini:2: unknown action 'jump'\n"
				   "b.ini:3: fire: unknown key name 'nosuchkey'\n"
				   "b.ini:4: coin: too many keys (at most 4)\n"
				   "b.ini:5: use: empty key name in list\n"
				   "b.ini:6: line is neither [section] nor key = value\n"
				   "b.ini:7: unknown section [joystick] (only [keyboard] and "
				   "[device \"ID\"])\n";
	struct bind_table b;
	struct errs e;

	(void)state;
	bind_defaults(&b);
	assert_int_equal(load(&b, in, &e), 6);
	assert_string_equal(e.text, want);
	expect_keys(&b, ACT_FIRE, KEY_LEFTCTRL, KEY_SPACE);
	expect_keys(&b, ACT_COIN, KEY_5, -1);
	expect_keys(&b, ACT_USE, KEY_E, -1);
	expect_keys(&b, ACT_BACK, KEY_DOWN, KEY_S);
	/* The line after the errors still applies. */
	expect_keys(&b, ACT_SERVICE, KEY_F1, -1);
}

static void test_four_keys_fit(void **state)
{
	struct bind_table b;
	struct errs e;

	(void)state;
	bind_defaults(&b);
	assert_int_equal(load(&b, "[keyboard]\ncoin = 5, 6, 7, 8\n", &e), 0);
	assert_int_equal(b.key[ACT_COIN][0], KEY_5);
	assert_int_equal(b.key[ACT_COIN][1], KEY_6);
	assert_int_equal(b.key[ACT_COIN][2], KEY_7);
	assert_int_equal(b.key[ACT_COIN][3], KEY_8);
}

static void test_lookup_returns_every_action_of_a_key(void **state)
{
	struct bind_table b;
	struct errs e;
	int acts[ACT_COUNT];

	(void)state;
	bind_defaults(&b);
	assert_int_equal(bind_lookup(&b, KEY_SPACE, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_FIRE);
	assert_int_equal(bind_lookup(&b, KEY_W, acts, ACT_COIN), 1);
	assert_int_equal(acts[0], ACT_FORWARD);
	assert_int_equal(bind_lookup(&b, KEY_P, acts, ACT_COUNT), 0);
	/* a key of both players: each player's action (the command reads the
	 * one up's) */
	assert_int_equal(bind_lookup(&b, KEY_A, acts, ACT_COUNT), 2);
	assert_int_equal(acts[0], ACT_STRAFE_LEFT);
	assert_int_equal(acts[1], ACT_P2_FIRE);
	assert_int_equal(bind_lookup(&b, KEY_2, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_START2);
	assert_int_equal(bind_lookup(&b, -1, acts, ACT_COUNT), 0);

	assert_int_equal(load(&b, "[keyboard]\nuse = space\nstart = space, 1\n", &e), 0);
	assert_int_equal(bind_lookup(&b, KEY_SPACE, acts, ACT_COUNT), 3);
	assert_int_equal(acts[0], ACT_FIRE);
	assert_int_equal(acts[1], ACT_USE);
	assert_int_equal(acts[2], ACT_START);
	/* max limits what is stored. */
	assert_int_equal(bind_lookup(&b, KEY_SPACE, acts, 2), 2);
	assert_int_equal(bind_lookup(&b, KEY_SPACE, acts, 0), 0);
}

static void test_load_file_missing_silent_present_applied(void **state)
{
	char dir[] = "/tmp/test_bind.XXXXXX";
	char path[64], want[128];
	struct bind_table b;
	struct errs e;
	int fd;

	(void)state;
	assert_non_null(mkdtemp(dir));
	bind_defaults(&b);
	memset(&e, 0, sizeof(e));
	snprintf(path, sizeof(path), "%s/bindings.ini", dir);
	assert_int_equal(bind_load(&b, path, on_err, &e), -ENOENT);
	assert_int_equal(e.count, 0);

	fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, "[keyboard]\r\ncoin = c\r\nfire = ?\r\n", 32), 32);
	close(fd);
	assert_int_equal(bind_load(&b, path, on_err, &e), 1);
	snprintf(want, sizeof(want), "%s:3: fire: unknown key name '?'\n", path);
	assert_string_equal(e.text, want);
	expect_keys(&b, ACT_COIN, KEY_C, -1);
	unlink(path);
	rmdir(dir);
}

/* config/bindings.ini (installed to /etc/arcaded) writes out exactly the
 * built-in defaults. Run from the repository root, as make does. */
static void test_shipped_bindings_ini_equals_defaults(void **state)
{
	struct bind_table b, d;
	struct errs e;
	int n;

	(void)state;
	bind_defaults(&d);
	memset(&b, 0x7f, sizeof(b));
	for (int a = 0; a < ACT_COUNT; a++)
		for (int i = 0; i < BIND_MAX; i++)
			b.key[a][i] = -1;
	b.ndev = 0;
	memset(&e, 0, sizeof(e));
	n = bind_load(&b, "config/bindings.ini", on_err, &e);
	if (n == -ENOENT)
		fail_msg("config/bindings.ini: not found (run from the repository root)");
	assert_int_equal(n, 0);
	assert_memory_equal(b.key, d.key, sizeof(b.key));
	assert_int_equal(b.ndev, 0);
}

static void test_random_bytes_never_crash(void **state)
{
	uint32_t seed = 7;
	char buf[300];
	struct bind_table b;
	struct errs e;
	int n;

	(void)state;
	for (int round = 0; round < 3000; round++) {
		size_t len = (size_t)(round % (int)sizeof(buf));

		for (size_t i = 0; i < len; i++) {
			static const char alpha[] = "[keyboard]\n=,fire  use ab1\0";

			seed = seed * 1103515245u + 12345u;
			buf[i] = alpha[(seed >> 16) % (sizeof(alpha) - 1)];
		}
		bind_defaults(&b);
		memset(&e, 0, sizeof(e));
		n = bind_load_text(&b, buf, len, "r", on_err, &e);
		assert_int_equal(n, e.count);
		for (int a = 0; a < ACT_COUNT; a++)
			for (int i = 0; i < BIND_MAX; i++)
				assert_true(b.key[a][i] == -1 ||
					    (b.key[a][i] > 0 && b.key[a][i] < KEY_MAX));
	}
}

static struct in_ident ident(const char *port, uint16_t vid, uint16_t pid)
{
	struct in_ident id;

	memset(&id, 0, sizeof(id));
	snprintf(id.port, sizeof(id.port), "%s", port);
	id.vid = vid;
	id.pid = pid;
	return id;
}

/* The one action code triggers on device id, or -1 for none. */
static int act_of(const struct bind_table *b, const struct in_ident *id, int code)
{
	int acts[ACT_COUNT];
	int n = bind_lookup_dev(b, id, code, acts, ACT_COUNT);

	assert_true(n <= 1);
	return n ? acts[0] : -1;
}

static void test_device_sections_bind_by_port_then_vid_pid(void **state)
{
	static const char in[] = "[device \"usb-1-1.2\"]\n"
				 "fire = BTN_TRIGGER_HAPPY1\n"
				 "[device USB-1-1.3]\n"
				 "fire = BTN_TRIGGER_HAPPY2\n"
				 "[device \"0079:0006\"]\n"
				 "fire = BTN_TRIGGER_HAPPY3\n"
				 "start = BTN_TRIGGER_HAPPY10\n";
	struct in_ident p2 = ident("1-1.2", 0x0079, 0x0006), p3 = ident("1-1.3", 0x0079, 0x0006);
	struct in_ident p4 = ident("1-4", 0x0079, 0x0006), kb = ident("1-5", 0x046d, 0xc31c);
	struct bind_table b;
	struct errs e;

	(void)state;
	bind_defaults(&b);
	assert_int_equal(load(&b, in, &e), 0);
	assert_int_equal(b.ndev, 3);
	assert_string_equal(b.dev[1].id, "usb-1-1.3");
	/* two identical encoders keep their own bindings by port */
	assert_int_equal(act_of(&b, &p2, BTN_TRIGGER_HAPPY1), ACT_FIRE);
	assert_int_equal(act_of(&b, &p2, BTN_TRIGGER_HAPPY2), -1);
	assert_int_equal(act_of(&b, &p3, BTN_TRIGGER_HAPPY2), ACT_FIRE);
	/* a third one on another port falls back to its VID:PID */
	assert_int_equal(act_of(&b, &p4, BTN_TRIGGER_HAPPY3), ACT_FIRE);
	assert_int_equal(act_of(&b, &p4, BTN_TRIGGER_HAPPY10), ACT_START);
	/* a device section starts empty: [keyboard] does not apply to it */
	assert_int_equal(act_of(&b, &p2, KEY_LEFTCTRL), -1);
	assert_int_equal(act_of(&b, &p2, BTN_TRIGGER_HAPPY10), -1);
	/* no section: [keyboard], as plain bind_lookup for every device */
	assert_int_equal(act_of(&b, &kb, KEY_LEFTCTRL), ACT_FIRE);
	assert_int_equal(act_of(&b, NULL, KEY_5), ACT_COIN);
	assert_null(bind_find_device(&b, &kb));
	assert_ptr_equal(bind_find_device(&b, &p3), &b.dev[1]);
	{
		int acts[ACT_COUNT];

		assert_int_equal(bind_lookup(&b, BTN_TRIGGER_HAPPY1, acts, ACT_COUNT), 0);
	}
}

static void test_device_sections_layer_action_by_action(void **state)
{
	struct in_ident p = ident("", 0x16c0, 0x05e1);
	struct bind_table b;
	struct errs e;

	(void)state;
	bind_defaults(&b);
	assert_int_equal(load(&b, "[device 16C0:05E1]\nfire = BTN_TRIGGER_HAPPY1\n"
				  "use = BTN_TRIGGER_HAPPY2\n", &e), 0);
	assert_int_equal(load(&b, "[device \"16c0:05e1\"]\nuse = BTN_TRIGGER_HAPPY3\n", &e), 0);
	assert_int_equal(b.ndev, 1);
	assert_string_equal(b.dev[0].id, "16c0:05e1");
	assert_int_equal(act_of(&b, &p, BTN_TRIGGER_HAPPY1), ACT_FIRE);
	assert_int_equal(act_of(&b, &p, BTN_TRIGGER_HAPPY2), -1);
	assert_int_equal(act_of(&b, &p, BTN_TRIGGER_HAPPY3), ACT_USE);
}

static void test_device_section_errors(void **state)
{
	static const char in[] = "[device \"usb-1-x\"]\n"      /* 1 */
				 "fire = BTN_TRIGGER_HAPPY1\n"    /* 2: ignored */
				 "[device \"\"]\n"                /* 3 */
				 "[device 079:0006]\n"            /* 4 */
				 "[devices]\n"                    /* 5 */
				 "[device \"0079:0006\"]\n"       /* 6 */
				 "fire = nosuchkey\n";            /* 7 */
	static const char want[] =
		"b.ini:1: bad device id 'usb-1-x' (usb-PORT or VVVV:PPPP)\n"
		"b.ini:3: bad device id '' (usb-PORT or VVVV:PPPP)\n"
		"b.ini:4: bad device id '079:0006' (usb-PORT or VVVV:PPPP)\n"
		"b.ini:5: unknown section [devices] (only [keyboard] and [device \"ID\"])\n"
		"b.ini:7: fire: unknown key name 'nosuchkey'\n";
	char many[2048];
	size_t n = 0;
	struct bind_table b;
	struct errs e;

	(void)state;
	bind_defaults(&b);
	assert_int_equal(load(&b, in, &e), 5);
	assert_string_equal(e.text, want);
	assert_int_equal(b.ndev, 1);
	for (int i = 0; i <= BIND_DEVICES; i++)
		n += (size_t)snprintf(many + n, sizeof(many) - n, "[device usb-1-%d]\nfire = x\n",
				      i + 1);
	bind_defaults(&b);
	assert_int_equal(load(&b, many, &e), 1);
	assert_string_equal(e.text, "b.ini:33: too many device sections (at most 16)\n");
	assert_int_equal(b.ndev, BIND_DEVICES);
}

static void test_set_device_replaces_a_section(void **state)
{
	int key[ACT_COUNT][BIND_MAX];
	struct in_ident p = ident("2-1", 0xd209, 0x0410);
	struct bind_table b;
	char id[BIND_ID_MAX];

	(void)state;
	bind_defaults(&b);
	memset(key, 0xff, sizeof(key));
	key[ACT_START][0] = KEY_1;
	assert_int_equal(bind_set_device(&b, "D209:0410", key), 0);
	assert_int_equal(act_of(&b, &p, KEY_1), ACT_START);
	key[ACT_START][0] = KEY_2;
	assert_int_equal(bind_set_device(&b, "d209:0410", key), 0);
	assert_int_equal(b.ndev, 1);
	assert_int_equal(act_of(&b, &p, KEY_1), -1);
	assert_int_equal(act_of(&b, &p, KEY_2), ACT_START);
	assert_int_equal(bind_set_device(&b, "usb-", key), -EINVAL);
	assert_int_equal(bind_set_device(&b, "usb-1-2.", key), -EINVAL);
	for (int i = 1; i < BIND_DEVICES; i++) {
		snprintf(id, sizeof(id), "usb-9-%d", i);
		assert_int_equal(bind_set_device(&b, id, key), 0);
	}
	assert_int_equal(bind_set_device(&b, "usb-9-99", key), -ENOSPC);
	assert_int_equal(bind_device_id("usb-1-1.2.3", id), 0);
	assert_string_equal(id, "usb-1-1.2.3");
	assert_int_equal(bind_device_id("0079:000G", id), -EINVAL);
}

static void test_codes_by_number(void **state)
{
	int keys[BIND_MAX];
	char why[128];

	(void)state;
	assert_int_equal(bind_parse_keys("0x54, 0X2C0, 0x02fe, 0x1", keys, why, sizeof(why)), 0);
	assert_int_equal(keys[0], 84);
	assert_int_equal(keys[1], BTN_TRIGGER_HAPPY1);
	assert_int_equal(keys[2], KEY_MAX - 1);
	assert_int_equal(keys[3], KEY_ESC);
	/* the same code by name and by number counts once */
	assert_int_equal(bind_parse_keys("esc, 0x0001", keys, why, sizeof(why)), 0);
	assert_int_equal(keys[0], KEY_ESC);
	assert_int_equal(keys[1], -1);
	static const char *const bad[] = { "0x0", "0x0000", "0x2ff", "0xffff", "0x10000", "0x",
					   "0xg1", "x54", "0x-1", "0x 1" };
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		char want[64];

		snprintf(want, sizeof(want), "unknown key name '%s'", bad[i]);
		assert_int_equal(bind_parse_keys(bad[i], keys, why, sizeof(why)), -EINVAL);
		assert_string_equal(why, want);
	}
}

/* Whether a and b bind the same: [keyboard], then the sections in order. */
static void expect_same_table(const struct bind_table *a, const struct bind_table *b)
{
	assert_memory_equal(a->key, b->key, sizeof(a->key));
	assert_int_equal(a->ndev, b->ndev);
	for (int d = 0; d < a->ndev; d++) {
		assert_string_equal(a->dev[d].id, b->dev[d].id);
		assert_memory_equal(a->dev[d].key, b->dev[d].key, sizeof(a->dev[d].key));
	}
}

/* Every action unbound, no sections; other bytes garbage. */
static void blank_table(struct bind_table *b)
{
	memset(b, 0x5a, sizeof(*b));
	for (int a = 0; a < ACT_COUNT; a++)
		for (int i = 0; i < BIND_MAX; i++)
			b->key[a][i] = -1;
	b->ndev = 0;
}

static void test_format_writes_every_action_of_every_section(void **state)
{
	/* Written out by hand from the defaults table of docs/config.md. */
	static const char want[] =
		"# arcaded key bindings: every action of [keyboard] and of each device\n"
		"[keyboard]\n"
		"forward = KEY_UP, KEY_W\n"
		"back = KEY_DOWN, KEY_S\n"
		"turn_left = KEY_LEFT\n"
		"turn_right = KEY_RIGHT\n"
		"strafe_left = KEY_A, KEY_COMMA\n"
		"strafe_right = KEY_D, KEY_DOT\n"
		"fire = KEY_LEFTCTRL, KEY_SPACE\n"
		"use = KEY_E\n"
		"start = KEY_1, KEY_ENTER\n"
		"coin = KEY_5\n"
		"service = KEY_9, KEY_F2\n"
		"weapon = KEY_Z, KEY_TAB\n"
		"look_up = KEY_PAGEUP\n"
		"look_down = KEY_PAGEDOWN\n"
		"start2 = KEY_2\n"
		"p2_forward = KEY_R\n"
		"p2_back = KEY_F\n"
		"p2_turn_left = KEY_D\n"
		"p2_turn_right = KEY_G\n"
		"p2_strafe_left =\n"
		"p2_strafe_right =\n"
		"p2_fire = KEY_A\n"
		"p2_use = KEY_S\n"
		"p2_weapon = KEY_Q\n"
		"\n"
		"[device \"usb-1-1.2\"]\n"
		"forward = BTN_DPAD_UP\n"
		"back =\n"
		"turn_left =\n"
		"turn_right =\n"
		"strafe_left =\n"
		"strafe_right =\n"
		"fire = BTN_TRIGGER_HAPPY1, 0x0054, 0x02fe\n"
		"use =\n"
		"start =\n"
		"coin =\n"
		"service =\n"
		"weapon =\n"
		"look_up =\n"
		"look_down =\n"
		"start2 =\n"
		"p2_forward =\n"
		"p2_back =\n"
		"p2_turn_left =\n"
		"p2_turn_right =\n"
		"p2_strafe_left =\n"
		"p2_strafe_right =\n"
		"p2_fire =\n"
		"p2_use =\n"
		"p2_weapon =\n";
	int key[ACT_COUNT][BIND_MAX];
	struct bind_table b, back;
	char buf[2048];
	struct errs e;
	size_t n;

	(void)state;
	bind_defaults(&b);
	memset(key, 0xff, sizeof(key));
	key[ACT_FORWARD][0] = BTN_DPAD_UP;
	key[ACT_FIRE][0] = BTN_TRIGGER_HAPPY1;
	key[ACT_FIRE][1] = 84;          /* between KEY_KPDOT (83) and KEY_ZENKAKUHANKAKU (85) */
	key[ACT_FIRE][2] = KEY_MAX - 1;        /* unnamed too */
	assert_int_equal(bind_set_device(&b, "usb-1-1.2", key), 0);
	n = bind_format(&b, buf, sizeof(buf));
	assert_int_equal(n, strlen(want));
	assert_string_equal(buf, want);
	/* read back over a table that binds nothing, and over the defaults */
	blank_table(&back);
	assert_int_equal(load(&back, buf, &e), 0);
	expect_same_table(&back, &b);
	bind_defaults(&back);
	assert_int_equal(load(&back, buf, &e), 0);
	expect_same_table(&back, &b);
}

static void test_format_cut_short_like_snprintf(void **state)
{
	struct bind_table b;
	char full[1024], cut[40];
	size_t n;

	(void)state;
	bind_defaults(&b);
	n = bind_format(&b, full, sizeof(full));
	assert_true(n > sizeof(cut) && n < sizeof(full));
	assert_int_equal(strlen(full), n);
	assert_int_equal(bind_format(&b, NULL, 0), n);
	memset(cut, 'z', sizeof(cut));
	assert_int_equal(bind_format(&b, cut, sizeof(cut)), n);
	assert_int_equal(strlen(cut), sizeof(cut) - 1);
	assert_memory_equal(cut, full, sizeof(cut) - 1);
}

/* Random tables of every shape (codes 1..KEY_MAX-1, named or not, lists
 * of 0 to 4, up to 16 sections of both id forms) read back equal. */
static void test_format_round_trips_random_tables(void **state)
{
	uint32_t seed = 12345;
	static char buf[64 * 1024];
	struct bind_table b, back;
	struct errs e;

#define RND() (seed = seed * 1103515245u + 12345u, seed >> 8)
	(void)state;
	for (int round = 0; round < 500; round++) {
		int (*sec)[BIND_MAX];

		blank_table(&b);
		b.ndev = (int)(RND() % (BIND_DEVICES + 1));
		for (int d = -1; d < b.ndev; d++) {
			if (d >= 0) {
				if (RND() % 2)
					snprintf(b.dev[d].id, BIND_ID_MAX, "usb-%d-%d.%d", d + 1,
						 (int)(RND() % 9) + 1, round);
				else
					snprintf(b.dev[d].id, BIND_ID_MAX, "%04x:%04x",
						 (unsigned)d, (unsigned)(RND() & 0xffff));
			}
			sec = d < 0 ? b.key : b.dev[d].key;
			for (int a = 0; a < ACT_COUNT; a++) {
				int k = (int)(RND() % (BIND_MAX + 1));

				for (int i = 0; i < BIND_MAX; i++)
					sec[a][i] = -1;
				for (int i = 0; i < k; i++) {
					/* half from the top, where names are few */
					int code = RND() % 2 ? (int)(RND() % (KEY_MAX - 1)) + 1
							     : KEY_MAX - 1 - (int)(RND() % 32);
					int dup = 0;

					for (int j = 0; j < i; j++)
						dup |= sec[a][j] == code;
					if (!dup)
						sec[a][i] = code;
				}
				/* compact: free slots last, as parsed lists are */
				for (int i = 0, w = 0; i < BIND_MAX; i++) {
					int c = sec[a][i];

					sec[a][i] = -1;
					if (c >= 0)
						sec[a][w++] = c;
				}
			}
		}
		assert_true(bind_format(&b, buf, sizeof(buf)) < sizeof(buf));
		blank_table(&back);
		assert_int_equal(load(&back, buf, &e), 0);
		expect_same_table(&back, &b);
	}
#undef RND
}

/* One entry, as bindings files and profiles apply it: a good one replaces
 * the action's keys, an empty one unbinds it, an unknown action or a bad
 * list is reported at its line and changes nothing. */
static void test_set_entry_applies_or_reports(void **state)
{
	struct errs e = { .n = 0 };
	struct cini_errs err = { .file = "p.ini", .fn = on_err, .user = &e };
	struct bind_table b;
	int before[ACT_COUNT][BIND_MAX];
	(void)state;
	bind_defaults(&b);
	bind_set_entry(b.key, &err, 3, "fire", "z, x");
	assert_int_equal(b.key[ACT_FIRE][0], KEY_Z);
	assert_int_equal(b.key[ACT_FIRE][1], KEY_X);
	assert_int_equal(b.key[ACT_FIRE][2], -1);
	bind_set_entry(b.key, &err, 4, "use", "");
	assert_int_equal(b.key[ACT_USE][0], -1);
	assert_int_equal(err.count, 0);
	memcpy(before, b.key, sizeof(before));
	bind_set_entry(b.key, &err, 5, "jump", "space");
	bind_set_entry(b.key, &err, 6, "fire", "nosuchkey");
	assert_int_equal(err.count, 2);
	assert_int_equal(e.count, 2);
	assert_memory_equal(before, b.key, sizeof(before));
	assert_string_equal(e.text, "p.ini:5: unknown action 'jump'\n"
				    "p.ini:6: fire: unknown key name 'nosuchkey'\n");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_defaults_bind_the_documented_keys),
		cmocka_unit_test(test_file_replaces_a_whole_action_list),
		cmocka_unit_test(test_errors_name_file_line_and_keep_the_binding),
		cmocka_unit_test(test_four_keys_fit),
		cmocka_unit_test(test_lookup_returns_every_action_of_a_key),
		cmocka_unit_test(test_load_file_missing_silent_present_applied),
		cmocka_unit_test(test_shipped_bindings_ini_equals_defaults),
		cmocka_unit_test(test_random_bytes_never_crash),
		cmocka_unit_test(test_device_sections_bind_by_port_then_vid_pid),
		cmocka_unit_test(test_device_sections_layer_action_by_action),
		cmocka_unit_test(test_device_section_errors),
		cmocka_unit_test(test_set_device_replaces_a_section),
		cmocka_unit_test(test_codes_by_number),
		cmocka_unit_test(test_format_writes_every_action_of_every_section),
		cmocka_unit_test(test_format_cut_short_like_snprintf),
		cmocka_unit_test(test_format_round_trips_random_tables),
		cmocka_unit_test(test_set_entry_applies_or_reports),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
