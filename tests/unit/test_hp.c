/*
 * hp: hotplug notices. The inotify source is driven with plain files in a
 * temporary directory (inotify reports them as it reports devtmpfs nodes):
 * the names input backends open raise HP_NODE on creation, mode change and
 * removal, each only in its own directory, with a notice naming the node
 * and what happened; other names raise nothing; nothing pending reads 0 at
 * once; a directory that does not exist yet is watched for and then
 * watched.
 * libusb is real USB, tested in the VM (tests/vm/guest.sh): here only that
 * its absence or failure is named and never fatal.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "input/hp.h"

static char dir[64], sub[80];

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/test_hp.XXXXXX");
	if (!mkdtemp(dir))
		return -1;
	snprintf(sub, sizeof(sub), "%s/input", dir);
	return mkdir(sub, 0700);
}

static int teardown(void **state)
{
	char cmd[160];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void touch(const char *d, const char *name)
{
	char p[160];
	int fd;

	snprintf(p, sizeof(p), "%s/%s", d, name);
	fd = open(p, O_WRONLY | O_CREAT | O_CLOEXEC, 0600);
	assert_true(fd >= 0);
	close(fd);
}

static void path(char *p, size_t n, const char *d, const char *name)
{
	snprintf(p, n, "%s/%s", d, name);
}

/* The patterns of the three backends with nodes, in the temporary tree:
 * DIR/hidraw, DIR/gpiochip, DIR/input/event. */
static char pat[3][96];

static const char *const *patterns(void)
{
	static const char *p[3];

	snprintf(pat[0], sizeof(pat[0]), "%s/hidraw", dir);
	snprintf(pat[1], sizeof(pat[1]), "%s/gpiochip", dir);
	snprintf(pat[2], sizeof(pat[2]), "%s/event", sub);
	for (int i = 0; i < 3; i++)
		p[i] = pat[i];
	return p;
}

static struct hp *open_dirs(void)
{
	struct hp *h = NULL;
	char why[128] = "";

	assert_int_equal(hp_open(patterns(), 3, HP_INOTIFY, &h, why, sizeof(why)), 0);
	assert_non_null(h);
	assert_true(hp_fd(h) >= 0);
	return h;
}

static void nothing_pending_reads_zero(void **state)
{
	struct hp *h = open_dirs();

	(void)state;
	assert_int_equal(hp_poll(h), 0);
	assert_int_equal(hp_poll(h), 0);
	hp_close(h);
}

static void device_names_raise_node_notices(void **state)
{
	struct hp *h = open_dirs();
	char p[160];

	(void)state;
	touch(dir, "hidraw3");
	assert_int_equal(hp_poll(h), HP_NODE);
	assert_int_equal(hp_poll(h), 0);            /* drained */
	touch(sub, "event12");
	assert_int_equal(hp_poll(h), HP_NODE);
	touch(dir, "gpiochip1");
	assert_int_equal(hp_poll(h), HP_NODE);
	/* udev's change of owner and mode after the node appears */
	path(p, sizeof(p), dir, "hidraw3");
	assert_int_equal(chmod(p, 0660), 0);
	assert_int_equal(hp_poll(h), HP_NODE);
	/* and its removal */
	assert_int_equal(unlink(p), 0);
	assert_int_equal(hp_poll(h), HP_NODE);
	hp_close(h);
}

static void other_names_raise_nothing(void **state)
{
	struct hp *h = open_dirs();
	char p[160];

	(void)state;
	touch(dir, "tty7");
	touch(dir, "pts");
	touch(sub, "mouse0");
	touch(dir, "fb0");
	path(p, sizeof(p), dir, "tty7");
	assert_int_equal(chmod(p, 0666), 0);
	assert_int_equal(unlink(p), 0);
	assert_int_equal(hp_poll(h), 0);
	hp_close(h);
}

static void a_prefix_counts_only_in_its_own_directory(void **state)
{
	struct hp *h = open_dirs();
	char want[200];

	(void)state;
	/* each directory is watched once, in the order the patterns name it */
	snprintf(want, sizeof(want), "inotify %s %s", dir, sub);
	assert_string_equal(hp_sources(h), want);
	touch(dir, "event3");        /* an evdev name, but not in input/ */
	touch(sub, "hidraw3");       /* a hidraw name, but not in DIR */
	assert_int_equal(hp_poll(h), 0);
	touch(sub, "event3");
	assert_int_equal(hp_poll(h), HP_NODE);
	hp_close(h);
}

static void a_pattern_without_a_directory_is_refused(void **state)
{
	const char *bad[][1] = { { "hidraw" }, { "/dev/" }, { "/hidraw" } };
	struct hp *h = NULL;
	char why[256];

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		why[0] = '\0';
		assert_int_equal(hp_open(bad[i], 1, HP_INOTIFY, &h, why, sizeof(why)), -EINVAL);
		assert_null(h);
		assert_non_null(strstr(why, bad[i][0]));
	}
}

static void the_fd_wakes_a_poll(void **state)
{
	struct hp *h = open_dirs();
	struct pollfd pf = { .fd = hp_fd(h), .events = POLLIN };

	(void)state;
	assert_int_equal(poll(&pf, 1, 0), 0);
	touch(sub, "event0");
	assert_int_equal(poll(&pf, 1, 1000), 1);
	assert_int_equal(hp_poll(h), HP_NODE);
	assert_int_equal(poll(&pf, 1, 0), 0);
	hp_close(h);
}

static void many_notices_at_once_are_one_answer(void **state)
{
	struct hp *h = open_dirs();
	char name[32];

	(void)state;
	/* more than one read()'s buffer of events */
	for (int i = 0; i < 300; i++) {
		snprintf(name, sizeof(name), "hidraw%d", i);
		touch(dir, name);
	}
	assert_int_equal(hp_poll(h), HP_NODE);
	assert_int_equal(hp_poll(h), 0);
	hp_close(h);
}

static void missing_directories_are_named(void **state)
{
	const char *dirs[] = { "/nonexistent/hp-a/hidraw", "/nonexistent/hp-b/event" };
	const char *one[] = { "/nonexistent/hp-a/hidraw", patterns()[0] };
	struct hp *h = NULL;
	char why[256] = "";

	(void)state;
	assert_int_equal(hp_open(dirs, 2, HP_INOTIFY, &h, why, sizeof(why)), -ENODEV);
	assert_null(h);
	assert_non_null(strstr(why, "/nonexistent/hp-a"));
	assert_non_null(strstr(why, "/nonexistent/hp-b"));
	/* one directory of two is enough; the other is named */
	assert_int_equal(hp_open(one, 2, HP_INOTIFY, &h, why, sizeof(why)), 0);
	assert_non_null(strstr(hp_sources(h), "/nonexistent/hp-a"));
	assert_int_equal(hp_complete(h), 0);
	assert_non_null(strstr(hp_sources(h), dir));
	touch(dir, "hidraw0");
	assert_int_equal(hp_poll(h), HP_NODE);
	hp_close(h);
}

static void notices_say_which_node_and_what(void **state)
{
	struct hp *h = open_dirs();
	const struct hp_notice *n;
	char p[160], want[160];

	(void)state;
	touch(dir, "hidraw3");
	path(p, sizeof(p), dir, "hidraw3");
	assert_int_equal(chmod(p, 0660), 0);
	assert_int_equal(unlink(p), 0);
	touch(dir, "tty9");                 /* not wanted: no notice */
	assert_int_equal(hp_poll(h), HP_NODE);
	assert_int_equal(hp_notices(h, &n), 3);
	snprintf(want, sizeof(want), "%s/hidraw3", dir);
	for (int i = 0; i < 3; i++) {
		assert_int_equal(n[i].what, HP_NODE);
		assert_string_equal(n[i].name, want);
		assert_true(n[i].time_ns > 0);
	}
	assert_string_equal(n[0].how, "created");
	assert_string_equal(n[1].how, "changed");
	assert_string_equal(n[2].how, "removed");
	/* each poll starts afresh */
	assert_int_equal(hp_poll(h), 0);
	assert_int_equal(hp_notices(h, &n), 0);
	hp_close(h);
}

/* A DRM driver creates /dev/dri when it loads: a pattern whose directory
 * is missing is watched for in the parent, and from its creation on. */
static void a_directory_that_appears_later_is_watched(void **state)
{
	char later[128], fbpat[96], cardpat[160], p[200], want[200];
	const char *pats[2] = { fbpat, cardpat };
	const struct hp_notice *n;
	struct hp *h = NULL;
	char why[128] = "";

	(void)state;
	snprintf(later, sizeof(later), "%s/dri", dir);
	snprintf(fbpat, sizeof(fbpat), "%s/fb", dir);
	snprintf(cardpat, sizeof(cardpat), "%s/card", later);
	assert_int_equal(hp_open(pats, 2, HP_INOTIFY, &h, why, sizeof(why)), 0);
	snprintf(want, sizeof(want), "(%s: not there yet)", later);
	assert_non_null(strstr(hp_sources(h), want));
	assert_int_equal(hp_complete(h), 1);
	/* other directories and names in the parent: nothing */
	snprintf(p, sizeof(p), "%s/drx", dir);
	assert_int_equal(mkdir(p, 0700), 0);
	touch(dir, "card0");
	assert_int_equal(hp_poll(h), 0);
	/* the parent's own pattern keeps its changes (the masks add up) */
	touch(dir, "fb0");
	path(p, sizeof(p), dir, "fb0");
	assert_int_equal(chmod(p, 0660), 0);
	assert_int_equal(hp_poll(h), HP_NODE);
	assert_int_equal(hp_notices(h, &n), 2);
	assert_string_equal(n[1].how, "changed");
	/* the directory appears: a notice, and its nodes count from now on */
	assert_int_equal(mkdir(later, 0755), 0);
	assert_int_equal(hp_poll(h), HP_NODE);
	assert_int_equal(hp_notices(h, &n), 1);
	assert_string_equal(n[0].name, later);
	touch(later, "card0");
	assert_int_equal(hp_poll(h), HP_NODE);
	assert_int_equal(hp_notices(h, &n), 1);
	snprintf(want, sizeof(want), "%s/card0", later);
	assert_string_equal(n[0].name, want);
	touch(later, "renderD128");
	assert_int_equal(hp_poll(h), 0);
	hp_close(h);
}

static void libusb_is_optional(void **state)
{
	const char *const *dirs = patterns();
	struct hp *h = NULL;
	char why[256] = "";

	(void)state;
	/* With or without USB here, asking for libusb never fails the open
	 * while inotify works, and the sources say what libusb did. */
	assert_int_equal(hp_open(dirs, 1, HP_INOTIFY | HP_LIBUSB, &h, why, sizeof(why)), 0);
	assert_non_null(strstr(hp_sources(h), "libusb"));
	assert_int_equal(hp_poll(h) & HP_NODE, 0);
	hp_close(h);
	hp_close(NULL);
	assert_int_equal(hp_poll(NULL), 0);
	assert_int_equal(hp_fd(NULL), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(nothing_pending_reads_zero, setup, teardown),
		cmocka_unit_test_setup_teardown(device_names_raise_node_notices, setup, teardown),
		cmocka_unit_test_setup_teardown(other_names_raise_nothing, setup, teardown),
		cmocka_unit_test_setup_teardown(a_prefix_counts_only_in_its_own_directory, setup,
						teardown),
		cmocka_unit_test(a_pattern_without_a_directory_is_refused),
		cmocka_unit_test_setup_teardown(the_fd_wakes_a_poll, setup, teardown),
		cmocka_unit_test_setup_teardown(many_notices_at_once_are_one_answer, setup, teardown),
		cmocka_unit_test_setup_teardown(missing_directories_are_named, setup, teardown),
		cmocka_unit_test_setup_teardown(notices_say_which_node_and_what, setup, teardown),
		cmocka_unit_test_setup_teardown(a_directory_that_appears_later_is_watched, setup,
						teardown),
		cmocka_unit_test_setup_teardown(libusb_is_optional, setup, teardown),
	};

	return cmocka_run_group_tests_name("hp", tests, NULL, NULL);
}
