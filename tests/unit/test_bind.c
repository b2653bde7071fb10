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
				   "b.ini:7: unknown section [joystick] (only [keyboard])\n";
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
	assert_int_equal(bind_lookup(&b, KEY_Q, acts, ACT_COUNT), 0);
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
	memset(&e, 0, sizeof(e));
	n = bind_load(&b, "config/bindings.ini", on_err, &e);
	if (n == -ENOENT)
		fail_msg("config/bindings.ini: not found (run from the repository root)");
	assert_int_equal(n, 0);
	assert_memory_equal(&b, &d, sizeof(b));
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
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
