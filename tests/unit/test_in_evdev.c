/*
 * Tests of the evdev input backend (input/in_evdev.c).
 *
 * Without a device: auto-detection over directories of non-devices, and
 * opens of files that are not input devices. With /dev/uinput (the VM
 * tests): real virtual keyboards and encoders built with libevdev's uinput
 * helpers: detection by bound keys (every such device, each once),
 * numeric order, grab, CLOCK_MONOTONIC stamps, autorepeat filtered, state
 * after SYN_DROPPED, unplug. Those tests are skipped, with the reason
 * printed, where /dev/uinput is missing. The detection rule itself is
 * tested on in-memory libevdev devices, which need no /dev/uinput.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <grp.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>
#include <libevdev/libevdev-uinput.h>
#include <libevdev/libevdev.h>

#include "input/in_evdev.h"

static char tmpdir[PATH_MAX];

static int test_bound(void *u, const struct in_ident *id, int code);

static int make_tmpdir(void **state)
{
	(void)state;
	in_evdev.set_bound(test_bound, NULL);
	snprintf(tmpdir, sizeof(tmpdir), "/tmp/test_in_evdev.XXXXXX");
	return mkdtemp(tmpdir) ? 0 : -1;
}

static int remove_tmpdir(void **state)
{
	char cmd[PATH_MAX + 16];

	(void)state;
	in_evdev.set_bound(NULL, NULL);
	if (snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmpdir) >= (int)sizeof(cmd))
		return -1;
	return system(cmd) == 0 ? 0 : -1;
}

/* A fresh empty directory under tmpdir. */
static void subdir(const char *name, char *out, size_t len)
{
	assert_true(snprintf(out, len, "%s/%s", tmpdir, name) < (int)len);
	assert_int_equal(mkdir(out, 0700), 0);
}

static void touch(const char *dir, const char *name)
{
	char path[PATH_MAX];
	int fd;

	assert_true(snprintf(path, sizeof(path), "%s/%s", dir, name) < (int)sizeof(path));
	fd = open(path, O_WRONLY | O_CREAT | O_CLOEXEC, 0600);
	assert_true(fd >= 0);
	close(fd);
}

static void test_autodetect_missing_dir_is_enodev_with_why(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	char why[256];

	(void)state;
	assert_int_equal(in_evdev_open_dir("/nonexistent/input", &d, why, sizeof(why)), -ENODEV);
	assert_null(d);
	assert_non_null(strstr(why, "/nonexistent/input"));
}

static void test_autodetect_empty_dir_is_enodev_with_why(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	char dir[PATH_MAX], why[256];

	(void)state;
	subdir("empty", dir, sizeof(dir));
	touch(dir, "mouse0");        /* not an eventN name */
	assert_int_equal(in_evdev_open_dir(dir, &d, why, sizeof(why)), -ENODEV);
	assert_null(d);
	assert_non_null(strstr(why, "event"));
}

static void test_autodetect_lists_non_devices_in_numeric_order(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	char dir[PATH_MAX], why[1024];
	const char *e2, *e10;

	(void)state;
	subdir("files", dir, sizeof(dir));
	touch(dir, "event10");
	touch(dir, "event2");
	touch(dir, "event1x");       /* not a number: ignored */
	assert_int_equal(in_evdev_open_dir(dir, &d, why, sizeof(why)), -ENODEV);
	assert_null(d);
	e2 = strstr(why, "/event2:");
	e10 = strstr(why, "/event10:");
	assert_non_null(e2);
	assert_non_null(e10);
	assert_true(e2 < e10);       /* 2 before 10, though "10" < "2" as text */
	assert_null(strstr(why, "event1x"));
	assert_non_null(strstr(why, "not an input event device"));
}

/* 0 if auto-detection over dir fails with -ENODEV and lists dir/event0 as
 * permission denied. */
static int unreadable_listed(const char *dir)
{
	struct in_dev *d = NULL;
	char why[1024];

	if (in_evdev_open_dir(dir, &d, why, sizeof(why)) != -ENODEV || d)
		return 1;
	return strstr(why, "/event0: ") && strstr(why, strerror(EACCES)) ? 0 : 1;
}

static void test_autodetect_lists_unreadable_devices(void **state)
{
	char dir[PATH_MAX], path[PATH_MAX];
	pid_t pid;
	int status;

	(void)state;
	subdir("locked", dir, sizeof(dir));
	touch(dir, "event0");
	assert_true(snprintf(path, sizeof(path), "%s/event0", dir) < (int)sizeof(path));
	assert_int_equal(chmod(path, 0), 0);
	if (geteuid() != 0) {
		assert_int_equal(unreadable_listed(dir), 0);
		return;
	}
	/* Root opens any file: look as an unprivileged user instead. */
	assert_int_equal(chmod(tmpdir, 0755), 0);
	assert_int_equal(chmod(dir, 0755), 0);
	pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		if (setgroups(0, NULL) != 0 || setgid(65534) != 0 || setuid(65534) != 0)
			_exit(2);
		_exit(unreadable_listed(dir));
	}
	assert_int_equal(waitpid(pid, &status, 0), pid);
	assert_true(WIFEXITED(status));
	assert_int_equal(WEXITSTATUS(status), 0);
}

static void test_open_non_evdev_file_fails_cleanly(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	char why[256];

	(void)state;
	assert_true(in_evdev.open("/dev/null", &d, why, sizeof(why)) < 0);
	assert_null(d);
	assert_non_null(strstr(why, "/dev/null"));
	assert_int_equal(in_evdev.open("/nonexistent/event0", &d, why, sizeof(why)), -ENOENT);
	assert_null(d);
}

static void test_autodetect_system_gives_device_or_enodev(void **state)
{
	struct in_dev *d = NULL;
	char why[1024];
	int rc;

	(void)state;
	rc = in_evdev.open(NULL, &d, why, sizeof(why));
	if (rc == 0) {
		assert_non_null(strstr(in_evdev.describe(d), "/dev/input/event"));
		in_evdev.close(d);
	} else {
		assert_int_equal(rc, -ENODEV);
		assert_null(d);
		assert_true(why[0] != '\0');
	}
}

static void test_close_null_is_safe(void **state)
{
	(void)state;
	in_evdev.close(NULL);
}

/* The bindings of these tests: the default keyboard's keys (arrows, W S A
 * D, ctrl, space, 1, 5, 9), and for the device 1209:00f0 only its
 * BTN_TRIGGER (a [device] section of its own replaces [keyboard]). */
static int test_bound(void *u, const struct in_ident *id, int code)
{
	static const int keys[] = { KEY_UP, KEY_DOWN, KEY_LEFT, KEY_RIGHT, KEY_W, KEY_S, KEY_A,
				    KEY_D, KEY_LEFTCTRL, KEY_SPACE, KEY_1, KEY_5, KEY_9 };

	(void)u;
	if (id->vid == 0x1209 && id->pid == 0x00f0)
		return code == BTN_TRIGGER;
	for (size_t i = 0; i < sizeof(keys) / sizeof(keys[0]); i++)
		if (keys[i] == code)
			return 1;
	return 0;
}

/* An in-memory device description with the given keys (0-terminated). */
static struct libevdev *described(const char *name, const unsigned *keys)
{
	struct libevdev *ev = libevdev_new();

	assert_non_null(ev);
	libevdev_set_name(ev, name);
	libevdev_enable_event_type(ev, EV_KEY);
	for (; *keys; keys++)
		libevdev_enable_event_code(ev, EV_KEY, *keys, NULL);
	return ev;
}

static void test_bound_keys_decide_auto_detection(void **state)
{
	static const unsigned encoder[] = { KEY_UP, KEY_DOWN, KEY_LEFT, KEY_RIGHT, KEY_LEFTCTRL,
					    KEY_LEFTALT, KEY_1, KEY_5, 0 };
	static const unsigned power[] = { KEY_POWER, 0 };
	static const unsigned mouse[] = { BTN_LEFT, BTN_RIGHT, 0 };
	static const unsigned media[] = { KEY_VOLUMEUP, KEY_VOLUMEDOWN, KEY_MUTE, 0 };
	static const unsigned pad[] = { BTN_TRIGGER, BTN_THUMB, 0 };
	unsigned keyboard[KEY_KPDOT - KEY_ESC + 2];
	struct in_ident any = { .vid = 1, .pid = 1 }, padid = { .vid = 0x1209, .pid = 0x00f0 };
	struct libevdev *ev;
	int codes[16];

	(void)state;
	for (unsigned c = KEY_ESC; c <= KEY_KPDOT; c++)
		keyboard[c - KEY_ESC] = c;
	keyboard[KEY_KPDOT - KEY_ESC + 1] = 0;

	/* ESC..KPDOT: of the bound keys W S A D, ctrl, space, 1, 5, 9 */
	ev = described("AT keyboard", keyboard);
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 9);
	libevdev_free(ev);
	/* an encoder: the arrows, ctrl, 1 and 5 are bound, alt is not */
	ev = described("encoder", encoder);
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 7);
	assert_int_equal(codes[0], KEY_1);     /* in code order */
	assert_int_equal(codes[2], KEY_LEFTCTRL);
	assert_int_equal(in_evdev_bound_keys(ev, &any, NULL, 0), 7);
	libevdev_free(ev);
	/* nothing binds these: passed over */
	ev = described("Power Button", power);
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 0);
	in_evdev.set_bound(NULL, NULL);     /* no bindings given: every key counts */
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 1);
	in_evdev.set_bound(test_bound, NULL);
	libevdev_free(ev);
	ev = described("mouse", mouse);
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 0);
	libevdev_free(ev);
	ev = described("Consumer Control", media);
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 0);
	libevdev_free(ev);
	/* a device's own section: the pad's BTN_TRIGGER counts for it only */
	ev = described("pad", pad);
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 0);
	assert_int_equal(in_evdev_bound_keys(ev, &padid, codes, 16), 1);
	assert_int_equal(codes[0], BTN_TRIGGER);
	libevdev_free(ev);
	/* no keys at all */
	ev = libevdev_new();
	assert_non_null(ev);
	assert_int_equal(in_evdev_bound_keys(ev, &any, codes, 16), 0);
	libevdev_free(ev);
}

/* uinput part. */

static void need_uinput(void)
{
	if (access("/dev/uinput", R_OK | W_OK) != 0) {
		print_message("SKIP: /dev/uinput is not usable here (%s); the uinput tests "
			      "run in the VM appliance tests\n", strerror(errno));
		skip();
	}
}

enum kind { KEYBOARD, ENCODER, ARROWS_ONLY, MOUSE, POWER };

/* A virtual device of the given kind; its node is uinput_devnode(). */
static struct libevdev_uinput *make_device(enum kind kind, const char *name)
{
	struct libevdev *ev = libevdev_new();
	struct libevdev_uinput *ui = NULL;
	const char *node;

	assert_non_null(ev);
	libevdev_set_name(ev, name);
	libevdev_set_id_bustype(ev, BUS_VIRTUAL);
	libevdev_enable_event_type(ev, EV_KEY);
	if (kind == KEYBOARD) {
		for (unsigned c = KEY_ESC; c <= KEY_KPDOT; c++)
			libevdev_enable_event_code(ev, EV_KEY, c, NULL);
	}
	if (kind == POWER)
		libevdev_enable_event_code(ev, EV_KEY, KEY_POWER, NULL);
	if (kind != MOUSE && kind != POWER) {
		libevdev_enable_event_code(ev, EV_KEY, KEY_UP, NULL);
		libevdev_enable_event_code(ev, EV_KEY, KEY_DOWN, NULL);
		libevdev_enable_event_code(ev, EV_KEY, KEY_LEFT, NULL);
		libevdev_enable_event_code(ev, EV_KEY, KEY_RIGHT, NULL);
	}
	if (kind == ENCODER) {
		libevdev_enable_event_code(ev, EV_KEY, KEY_LEFTCTRL, NULL);
		libevdev_enable_event_code(ev, EV_KEY, KEY_5, NULL);
	}
	if (kind == MOUSE) {
		libevdev_enable_event_code(ev, EV_KEY, BTN_LEFT, NULL);
		libevdev_enable_event_type(ev, EV_REL);
		libevdev_enable_event_code(ev, EV_REL, REL_X, NULL);
		libevdev_enable_event_code(ev, EV_REL, REL_Y, NULL);
	}
	assert_int_equal(libevdev_uinput_create_from_device(ev, LIBEVDEV_UINPUT_OPEN_MANAGED, &ui),
			 0);
	libevdev_free(ev);
	node = libevdev_uinput_get_devnode(ui);
	assert_non_null(node);
	/* devtmpfs makes the node at once; udev may still be setting its mode. */
	for (int i = 0; i < 100 && access(node, R_OK) != 0; i++) {
		struct timespec ts = { 0, 10000000 };

		nanosleep(&ts, NULL);
	}
	assert_int_equal(access(node, R_OK), 0);
	return ui;
}

static void emit(struct libevdev_uinput *ui, unsigned code, int value)
{
	assert_int_equal(libevdev_uinput_write_event(ui, EV_KEY, code, value), 0);
	assert_int_equal(libevdev_uinput_write_event(ui, EV_SYN, SYN_REPORT, 0), 0);
}

/* Reads until want events arrived or nothing came for 300 ms. Returns the
 * count, or a negative read result. */
static int read_events(struct in_dev *d, struct in_event *ev, int want)
{
	int got = 0;

	while (got < want) {
		struct pollfd p = { .fd = in_evdev.fd(d), .events = POLLIN };
		int r;

		if (poll(&p, 1, 300) <= 0)
			break;
		r = in_evdev.read(d, ev + got, want - got);
		if (r < 0)
			return r;
		got += r;
	}
	return got;
}

static void dir_link(const char *dir, const char *name, const char *target)
{
	char path[PATH_MAX];

	assert_true(snprintf(path, sizeof(path), "%s/%s", dir, name) < (int)sizeof(path));
	assert_int_equal(symlink(target, path), 0);
}

static void test_uinput_press_release_monotonic_no_repeat(void **state)
{
	struct libevdev_uinput *ui;
	struct in_dev *d;
	struct in_event ev[8];
	char why[256];
	uint64_t t0, t1;

	(void)state;
	need_uinput();
	ui = make_device(KEYBOARD, "arcaded test keyboard");
	assert_int_equal(in_evdev.open(libevdev_uinput_get_devnode(ui), &d, why, sizeof(why)), 0);
	assert_non_null(strstr(in_evdev.describe(d), "arcaded test keyboard"));
	assert_non_null(strstr(in_evdev.describe(d), libevdev_uinput_get_devnode(ui)));
	assert_null(strstr(in_evdev.describe(d), "not grabbed"));
	assert_null(strstr(in_evdev.describe(d), "stamped at read"));

	t0 = in_now_ns();
	emit(ui, KEY_UP, 1);
	emit(ui, KEY_UP, 2);
	emit(ui, KEY_UP, 2);
	emit(ui, KEY_UP, 0);
	assert_int_equal(read_events(d, ev, 8), 2);
	t1 = in_now_ns();
	assert_int_equal(ev[0].type, IN_KEY);
	assert_int_equal(ev[0].code, KEY_UP);
	assert_int_equal(ev[0].value, 1);
	assert_int_equal(ev[1].type, IN_KEY);
	assert_int_equal(ev[1].code, KEY_UP);
	assert_int_equal(ev[1].value, 0);
	/* Kernel stamps on CLOCK_MONOTONIC fall between our own readings of it
	 * (CLOCK_REALTIME stamps would be decades away). */
	assert_true(ev[0].time_ns >= t0 && ev[0].time_ns <= ev[1].time_ns);
	assert_true(ev[1].time_ns <= t1);
	in_evdev.close(d);
	libevdev_uinput_destroy(ui);
}

static void test_uinput_second_open_reports_not_grabbed(void **state)
{
	struct libevdev_uinput *ui;
	struct in_dev *a, *b;
	struct in_event ev[4];
	char why[256];

	(void)state;
	need_uinput();
	ui = make_device(KEYBOARD, "arcaded test grab");
	assert_int_equal(in_evdev.open(libevdev_uinput_get_devnode(ui), &a, why, sizeof(why)), 0);
	assert_int_equal(in_evdev.open(libevdev_uinput_get_devnode(ui), &b, why, sizeof(why)), 0);
	assert_non_null(strstr(in_evdev.describe(b), "not grabbed"));
	/* The grab holds: only the first open sees the key. */
	emit(ui, KEY_A, 1);
	assert_int_equal(read_events(a, ev, 1), 1);
	assert_int_equal(read_events(b, ev, 1), 0);
	in_evdev.close(b);
	in_evdev.close(a);
	libevdev_uinput_destroy(ui);
}

static void test_uinput_autodetect_skips_mouse_takes_keyboard(void **state)
{
	struct libevdev_uinput *mouse, *kbd;
	struct in_dev *d;
	char dir[PATH_MAX], why[1024];

	(void)state;
	need_uinput();
	mouse = make_device(MOUSE, "arcaded test mouse");
	kbd = make_device(KEYBOARD, "arcaded test keyboard");
	subdir("mouse_kbd", dir, sizeof(dir));
	dir_link(dir, "event0", libevdev_uinput_get_devnode(mouse));
	dir_link(dir, "event1", libevdev_uinput_get_devnode(kbd));
	assert_int_equal(in_evdev_open_dir(dir, &d, why, sizeof(why)), 0);
	assert_non_null(strstr(in_evdev.describe(d), "arcaded test keyboard"));
	in_evdev.close(d);
	libevdev_uinput_destroy(kbd);
	libevdev_uinput_destroy(mouse);
}

static void test_uinput_autodetect_numeric_order(void **state)
{
	struct libevdev_uinput *first, *second;
	struct in_dev *d;
	char dir[PATH_MAX], why[1024];

	(void)state;
	need_uinput();
	first = make_device(KEYBOARD, "arcaded test first");
	second = make_device(KEYBOARD, "arcaded test second");
	subdir("order", dir, sizeof(dir));
	dir_link(dir, "event2", libevdev_uinput_get_devnode(first));
	dir_link(dir, "event10", libevdev_uinput_get_devnode(second));
	assert_int_equal(in_evdev_open_dir(dir, &d, why, sizeof(why)), 0);
	assert_non_null(strstr(in_evdev.describe(d), "arcaded test first"));
	in_evdev.close(d);
	libevdev_uinput_destroy(second);
	libevdev_uinput_destroy(first);
}

/* A cabinet with a PS/2 keyboard and a keyboard encoder (and a power
 * button, and a mouse): auto-detection takes both keyboards, one per
 * open, never one twice, and leaves the rest; a closed device is taken
 * again. */
static void test_uinput_autodetect_takes_every_bound_device(void **state)
{
	struct libevdev_uinput *power, *kbd, *mouse, *encoder;
	struct in_dev *a, *b, *c = NULL;
	char dir[PATH_MAX], why[2048];

	(void)state;
	need_uinput();
	power = make_device(POWER, "arcaded test power");
	kbd = make_device(KEYBOARD, "arcaded test keyboard");
	mouse = make_device(MOUSE, "arcaded test mouse");
	encoder = make_device(ENCODER, "arcaded test encoder");
	subdir("cabinet", dir, sizeof(dir));
	dir_link(dir, "event0", libevdev_uinput_get_devnode(power));
	dir_link(dir, "event1", libevdev_uinput_get_devnode(kbd));
	dir_link(dir, "event2", libevdev_uinput_get_devnode(mouse));
	dir_link(dir, "event3", libevdev_uinput_get_devnode(encoder));
	assert_int_equal(in_evdev_open_dir(dir, &a, why, sizeof(why)), 0);
	assert_non_null(strstr(in_evdev.describe(a), "arcaded test keyboard"));
	assert_int_equal(in_evdev_open_dir(dir, &b, why, sizeof(why)), 0);
	assert_non_null(strstr(in_evdev.describe(b), "arcaded test encoder"));
	assert_int_equal(in_evdev_open_dir(dir, &c, why, sizeof(why)), -ENODEV);
	assert_null(c);
	assert_non_null(strstr(why, "/event0 (arcaded test power): none of its keys is bound"));
	assert_non_null(strstr(why, "/event1: already open"));
	assert_non_null(strstr(why, "/event2 (arcaded test mouse): none of its keys is bound"));
	assert_non_null(strstr(why, "/event3: already open"));
	/* both deliver */
	{
		struct in_event ev[4];

		emit(kbd, KEY_1, 1);
		emit(encoder, KEY_5, 1);
		assert_int_equal(read_events(a, ev, 1), 1);
		assert_int_equal(ev[0].code, KEY_1);
		assert_int_equal(read_events(b, ev, 1), 1);
		assert_int_equal(ev[0].code, KEY_5);
	}
	in_evdev.close(a);
	assert_int_equal(in_evdev_open_dir(dir, &c, why, sizeof(why)), 0);
	assert_non_null(strstr(in_evdev.describe(c), "arcaded test keyboard"));
	in_evdev.close(c);
	in_evdev.close(b);
	libevdev_uinput_destroy(encoder);
	libevdev_uinput_destroy(mouse);
	libevdev_uinput_destroy(kbd);
	libevdev_uinput_destroy(power);
}

static void test_uinput_state_true_after_dropped_events(void **state)
{
	struct libevdev_uinput *ui;
	struct in_dev *d;
	static struct in_event ev[2048];
	char why[256];
	int n, a = 0, b = 0;

	(void)state;
	need_uinput();
	ui = make_device(KEYBOARD, "arcaded test overflow");
	assert_int_equal(in_evdev.open(libevdev_uinput_get_devnode(ui), &d, why, sizeof(why)), 0);
	/* B goes down, then far more than the kernel's per-client buffer
	 * holds without a read: it drops the queue (B's press with it) and
	 * queues SYN_DROPPED. Only the resync can tell that B is down. */
	emit(ui, KEY_B, 1);
	for (int i = 0; i < 500; i++) {
		emit(ui, KEY_A, 1);
		emit(ui, KEY_A, 0);
	}
	n = read_events(d, ev, 2048);
	assert_true(n > 0);
	assert_true(n < 1 + 2 * 500);   /* events were lost: the test tests a resync */
	for (int i = 0; i < n; i++) {
		assert_true(ev[i].value == 0 || ev[i].value == 1);
		if (ev[i].code == KEY_A)
			a = ev[i].value;
		if (ev[i].code == KEY_B)
			b = ev[i].value;
	}
	/* Whatever was lost, the last word on each key is its true state. */
	assert_int_equal(a, 0);
	assert_int_equal(b, 1);
	in_evdev.close(d);
	libevdev_uinput_destroy(ui);
}

static void test_uinput_unplug_is_enodev(void **state)
{
	struct libevdev_uinput *ui;
	struct in_dev *d;
	struct in_event ev[4];
	char why[256];
	int r = 0;

	(void)state;
	need_uinput();
	ui = make_device(KEYBOARD, "arcaded test unplug");
	assert_int_equal(in_evdev.open(libevdev_uinput_get_devnode(ui), &d, why, sizeof(why)), 0);
	libevdev_uinput_destroy(ui);
	for (int i = 0; i < 100 && r >= 0; i++) {
		struct pollfd p = { .fd = in_evdev.fd(d), .events = POLLIN };

		poll(&p, 1, 10);
		r = in_evdev.read(d, ev, 4);
	}
	assert_int_equal(r, -ENODEV);
	in_evdev.close(d);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_autodetect_missing_dir_is_enodev_with_why),
		cmocka_unit_test(test_autodetect_empty_dir_is_enodev_with_why),
		cmocka_unit_test(test_autodetect_lists_non_devices_in_numeric_order),
		cmocka_unit_test(test_autodetect_lists_unreadable_devices),
		cmocka_unit_test(test_open_non_evdev_file_fails_cleanly),
		cmocka_unit_test(test_autodetect_system_gives_device_or_enodev),
		cmocka_unit_test(test_close_null_is_safe),
		cmocka_unit_test(test_bound_keys_decide_auto_detection),
		cmocka_unit_test(test_uinput_press_release_monotonic_no_repeat),
		cmocka_unit_test(test_uinput_second_open_reports_not_grabbed),
		cmocka_unit_test(test_uinput_autodetect_skips_mouse_takes_keyboard),
		cmocka_unit_test(test_uinput_autodetect_numeric_order),
		cmocka_unit_test(test_uinput_autodetect_takes_every_bound_device),
		cmocka_unit_test(test_uinput_state_true_after_dropped_events),
		cmocka_unit_test(test_uinput_unplug_is_enodev),
	};

	return cmocka_run_group_tests_name("in_evdev", tests, make_tmpdir, remove_tmpdir);
}
