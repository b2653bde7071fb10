/*
 * slot: input slots with fake backends (a fake stands in for a device only
 * here, in a unit test). A device that goes away has every control it held
 * released before it is closed, and is opened again after SLOT_REOPEN_NS,
 * or at once on a hotplug notice from where its backend's nodes appear; a
 * device missing at the start keeps its slot and is retried; repeats do
 * not count twice; the settings open the slots they name; a display that
 * reads keys (a fake terminal) opens its input backend and keeps
 * auto-detection off the keyboard. The clock is the test's.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <fcntl.h>
#include <unistd.h>

#include "display/dp.h"
#include "slot_fixture.h"

#define MS 1000000ull

static const struct slot_kind one_fake[] = { { &fake_be, "fake0", 0, 1 } };

/* ---- tests ------------------------------------------------------------- */

static void a_device_that_goes_away_has_what_it_held_released(void **state)
{
	(void)state;
	assert_int_equal(slot_add(&set, one_fake, 0, "fake0", 0), 0);
	assert_string_equal(seen, "opened 1209:1 ");
	fake_key(30, 1);
	fake_key(31, 1);
	fake_key(40, 1);
	fake_key(30, 0);
	slot_read(&set);
	assert_string_equal(seen, "opened 1209:1 key 30 1 key 31 1 key 40 1 key 30 0 ");
	seen[0] = '\0';
	fk.gone = 1;
	slot_read(&set);
	/* 31 and 40 were down, 30 was not: only they are released, then the
	 * device is gone and closed */
	assert_string_equal(seen, "released 31 released 40 gone ");
	assert_int_equal(fk.closes, 1);
	assert_null(set.s[0].dev);
	/* back again, nothing is down: a release reads as new */
	clock_ns += SLOT_REOPEN_NS;
	seen[0] = '\0';
	fake_key(31, 0);
	slot_read(&set);
	assert_string_equal(seen, "opened 1209:2 ");
}

static void a_dropped_device_is_reopened_after_the_retry_time(void **state)
{
	(void)state;
	slot_add(&set, one_fake, 0, "fake0", 0);
	fk.gone = 1;
	slot_read(&set);
	assert_int_equal(fk.closes, 1);
	clock_ns += SLOT_REOPEN_NS - 1;
	slot_read(&set);
	assert_int_equal(fk.open_calls, 1);    /* not yet */
	assert_null(set.s[0].dev);
	clock_ns += 1;
	seen[0] = '\0';
	slot_read(&set);
	assert_int_equal(fk.open_calls, 2);
	assert_non_null(set.s[0].dev);
	assert_string_equal(fk.last_path, "fake0");   /* the same spec */
	assert_string_equal(seen, "opened 1209:2 ");
	/* and it is read again */
	fake_key(44, 1);
	slot_read(&set);
	assert_string_equal(seen, "opened 1209:2 key 44 1 ");
}

static void a_device_missing_at_the_start_keeps_its_slot(void **state)
{
	(void)state;
	fk.fail = 2;
	assert_int_equal(slot_add(&set, one_fake, 0, NULL, 1), 0);
	assert_int_equal(set.n, 1);
	assert_null(set.s[0].dev);
	assert_string_equal(fk.last_path, "(auto)");
	slot_read(&set);
	assert_int_equal(fk.open_calls, 1);
	clock_ns += SLOT_REOPEN_NS;
	slot_read(&set);                       /* fails again */
	assert_int_equal(fk.open_calls, 2);
	assert_null(set.s[0].dev);
	clock_ns += SLOT_REOPEN_NS;
	slot_read(&set);
	assert_int_equal(fk.open_calls, 3);
	assert_non_null(set.s[0].dev);
	assert_string_equal(seen, "opened 1209:1 ");
}

static void repeats_and_releases_of_keys_up_are_not_passed_on(void **state)
{
	(void)state;
	slot_add(&set, one_fake, 0, "fake0", 0);
	seen[0] = '\0';
	fake_key(5, 1);
	fake_key(5, 2);                 /* autorepeat */
	fake_key(5, 1);
	fake_key(6, 0);                 /* never pressed */
	fake_key(5, 0);
	fake_key(5, 0);
	fake_key(SLOT_KEYS, 1);         /* beyond what is tracked */
	slot_read(&set);
	assert_string_equal(seen, "key 5 1 key 5 0 ");
}

static void a_hotplug_notice_retries_at_once(void **state)
{
	char dir[64] = "/tmp/test_slot.XXXXXX", node[96], p[128];
	/* static: the set outlives the test when an assertion fails */
	static struct in_backend be;
	struct slot_kind k[] = { { &be, "fake0", 0, 1 } };
	int fd;

	(void)state;
	be = fake_be;
	assert_non_null(mkdtemp(dir));
	snprintf(node, sizeof(node), "%s/fakedev", dir);
	be.node = node;
	slot_open(&set, k, 1, NULL);
	assert_int_equal(set.n, 1);
	assert_non_null(set.hp);
	fk.gone = 1;
	slot_read(&set);
	assert_null(set.s[0].dev);
	/* long before the retry time, the device's node appears */
	clock_ns += 10 * MS;
	snprintf(p, sizeof(p), "%s/fakedev3", dir);
	fd = open(p, O_WRONLY | O_CREAT | O_CLOEXEC, 0600);
	assert_true(fd >= 0);
	close(fd);
	slot_read(&set);
	assert_int_equal(fk.open_calls, 2);
	assert_non_null(set.s[0].dev);
	slot_close(&set);          /* before be goes out of scope */
	unlink(p);
	rmdir(dir);
}

static void settings_open_the_slots_they_name(void **state)
{
	static struct in_backend a, b, c, d;
	struct slot_kind k[] = {
		{ &a, "none", 1, 1 },
		{ &b, "auto", 3, 0 },
		{ &c, "x\ty  z", 0, 0 },
		{ &d, "p q", 0, 1 },
	};

	(void)state;
	a = b = c = d = fake_be;
	a.name = "a";
	b.name = "b";
	c.name = "c";
	d.name = "d";
	fk.fail = 1;               /* the first auto slot finds nothing yet */
	slot_open(&set, k, 4, NULL);
	assert_int_equal(set.n, 7);
	for (int i = 0; i < 3; i++) {
		assert_ptr_equal(set.s[i].be, &b);
		assert_int_equal(set.s[i].kind, 1);
		assert_null(set.s[i].path);
	}
	assert_null(set.s[0].dev);               /* kept, retried */
	assert_non_null(set.s[1].dev);
	assert_string_equal(set.s[3].path, "x");
	assert_string_equal(set.s[4].path, "y");
	assert_string_equal(set.s[5].path, "z");
	assert_int_equal(set.s[5].kind, 2);
	/* one device, blanks and all */
	assert_string_equal(set.s[6].path, "p q");
	assert_int_equal(set.s[6].kind, 3);
	slot_close(&set);
	/* more devices than slots are left out */
	slot_init(&set, &fake_hooks, NULL);
	k[2].devices = "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20";
	slot_open(&set, &k[2], 1, NULL);
	assert_int_equal(set.n, SLOT_MAX);
	assert_string_equal(set.s[SLOT_MAX - 1].path, "16");
	/* "auto" is a device name to a backend without auto slots */
	slot_close(&set);
	slot_init(&set, &fake_hooks, NULL);
	k[2].devices = "auto";
	slot_open(&set, &k[2], 1, NULL);
	assert_int_equal(set.n, 1);
	assert_string_equal(set.s[0].path, "auto");
	slot_close(&set);
}

static void a_display_that_reads_keys_opens_them_and_spares_the_keyboard(void **state)
{
	static struct in_backend kbd, keys;
	const struct dp_backend term = { .name = "faketerm", .input = "fakekeys" };
	const struct dp_backend plain = { .name = "fakepanel" };
	struct slot_kind k[] = {
		{ &kbd, "auto", 1, 1 },
		{ &keys, NULL, 0, 1 },
	};

	(void)state;
	kbd = keys = fake_be;
	kbd.name = "fakekbd";
	kbd.flags = IN_AUTO_TAKES_KEYBOARD;
	keys.name = "fakekeys";
	slot_open(&set, k, 2, &term);
	assert_int_equal(set.n, 1);
	assert_ptr_equal(set.s[0].be, &keys);
	assert_null(set.s[0].path);
	slot_close(&set);
	/* a display without keys: the keyboard, and no terminal input */
	slot_init(&set, &fake_hooks, NULL);
	slot_open(&set, k, 2, &plain);
	assert_int_equal(set.n, 1);
	assert_ptr_equal(set.s[0].be, &kbd);
	slot_close(&set);
	/* a keyboard named in the settings is opened with the terminal */
	slot_init(&set, &fake_hooks, NULL);
	k[0].devices = "/dev/input/event7";
	slot_open(&set, k, 2, &term);
	assert_int_equal(set.n, 2);
	assert_ptr_equal(set.s[0].be, &kbd);
	assert_ptr_equal(set.s[1].be, &keys);
	slot_close(&set);
}

/* What a backend that auto-detects by the bindings was told. */
static int (*told_fn)(void *u, const struct in_ident *id, int code);
static void *told_u;
static int told_calls;

static void fake_set_bound(int (*fn)(void *u, const struct in_ident *id, int code), void *u)
{
	told_fn = fn;
	told_u = u;
	told_calls++;
}

static void auto_detection_asks_the_bindings(void **state)
{
	static struct in_backend kbd, plain;
	struct slot_kind k[] = {
		{ &kbd, "auto", 4, 1 },
		{ &plain, "auto", 2, 0 },
	};
	struct slot_hooks no_bound = fake_hooks;
	struct in_ident id = { .vid = 1, .pid = 1 };

	(void)state;
	kbd = plain = fake_be;
	kbd.name = "fakekbd";
	kbd.set_bound = fake_set_bound;
	plain.name = "fakeplain";
	told_calls = 0;
	slot_open(&set, k, 2, NULL);
	/* told before its slots opened: every auto slot its own device */
	assert_int_equal(told_calls, 1);
	assert_int_equal(set.n, 6);
	for (int i = 0; i < 4; i++)
		assert_int_equal(set.s[i].dev->n, i + 1);
	/* the function it was given asks the slots' bound hook */
	assert_non_null(told_fn);
	assert_int_equal(told_fn(told_u, &id, 2), 1);    /* KEY_1 */
	assert_int_equal(told_fn(told_u, &id, 3), 0);
	/* and the backend forgets it when the slots close */
	slot_close(&set);
	assert_int_equal(told_calls, 2);
	assert_null(told_fn);
	assert_null(told_u);
	/* hooks without a bound hook: every code counts (NULL) */
	no_bound.bound = NULL;
	slot_init(&set, &no_bound, NULL);
	slot_open(&set, k, 1, NULL);
	assert_int_equal(told_calls, 3);
	assert_null(told_fn);
	slot_close(&set);
}

static void the_registry_has_every_backend_once(void **state)
{
	struct slot_kind k[SLOT_KINDS];
	struct cfg c;
	int n;

	(void)state;
	cfg_defaults(&c);
	n = slot_kinds(&c, k);
	assert_true(n >= 4 && n <= SLOT_KINDS);
	for (int i = 0; i < n; i++) {
		assert_non_null(k[i].be->open);
		for (int j = 0; j < i; j++)
			assert_string_not_equal(k[i].be->name, k[j].be->name);
	}
	/* the backend that auto-detects keyboards takes several (a PS/2
	 * keyboard does not keep an encoder out), by the bindings */
	for (int i = 0; i < n; i++)
		if (k[i].be->flags & IN_AUTO_TAKES_KEYBOARD) {
			assert_true(k[i].autos > 1);
			assert_non_null(k[i].be->set_bound);
		}
	/* the terminal preview's keys are a registered backend */
	int found = 0;
	for (int i = 0; i < n; i++)
		found += dp_term.input && strcmp(k[i].be->name, dp_term.input) == 0 && !k[i].devices;
	assert_int_equal(found, 1);
}

int main(void)
{
#define T(name) cmocka_unit_test_setup_teardown(name, fake_setup, fake_teardown)
	const struct CMUnitTest tests[] = {
		T(a_device_that_goes_away_has_what_it_held_released),
		T(a_dropped_device_is_reopened_after_the_retry_time),
		T(a_device_missing_at_the_start_keeps_its_slot),
		T(repeats_and_releases_of_keys_up_are_not_passed_on),
		T(a_hotplug_notice_retries_at_once),
		T(settings_open_the_slots_they_name),
		T(a_display_that_reads_keys_opens_them_and_spares_the_keyboard),
		T(auto_detection_asks_the_bindings),
		cmocka_unit_test(the_registry_has_every_backend_once),
	};

#undef T
	return cmocka_run_group_tests(tests, NULL, NULL);
}
