/*
 * Tests of the HID backend (input/in_hid.c).
 *
 * Without devices: the device spec parser, the USB port path and report
 * descriptor lookups over a fake sysfs tree laid out like the kernel's,
 * and opens that match nothing. With /dev/uhid (the VM tests; skipped with
 * the reason printed elsewhere): a virtual HID device made from the Buzz
 * descriptor is found, its reports read as button events, and its removal
 * reads as -ENODEV.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>
#include <linux/input-event-codes.h>
#include <linux/uhid.h>

#include "input/in_hid.h"
#include "tests/unit/hid_fixture.h"

static char tmpdir[PATH_MAX];

static int make_tmpdir(void **state)
{
	(void)state;
	snprintf(tmpdir, sizeof(tmpdir), "/tmp/test_in_hid.XXXXXX");
	return mkdtemp(tmpdir) ? 0 : -1;
}

static int remove_tmpdir(void **state)
{
	char cmd[PATH_MAX + 16];

	(void)state;
	if (snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmpdir) >= (int)sizeof(cmd))
		return -1;
	return system(cmd) == 0 ? 0 : -1;
}

static void test_spec_terms(void **state)
{
	struct in_hid_spec s;
	char why[200];

	(void)state;
	assert_int_equal(in_hid_parse_spec("hid:1209:0001", &s, why, sizeof(why)), 0);
	assert_int_equal(s.vid, 0x1209);
	assert_int_equal(s.pid, 0x0001);
	assert_int_equal(s.iface, -1);
	assert_string_equal(s.port, "");
	assert_true(in_hid_spec_names_device(&s));
	assert_int_equal(in_hid_parse_spec("hid:port=1-1.2, if=0", &s, why, sizeof(why)), 0);
	assert_string_equal(s.port, "1-1.2");
	assert_int_equal(s.iface, 0);
	assert_int_equal(s.vid, -1);
	assert_int_equal(in_hid_parse_spec("hid:serial=AB12", &s, why, sizeof(why)), 0);
	assert_string_equal(s.serial, "AB12");
	assert_int_equal(in_hid_parse_spec("hid:/dev/hidraw3", &s, why, sizeof(why)), 0);
	assert_string_equal(s.node, "/dev/hidraw3");
	assert_int_equal(in_hid_parse_spec("0079:0006,split=none,deadzone=200,press=600,"
					   "release=400,p2_button=11,p2_x=z,p2_y=RX",
					   &s, why, sizeof(why)),
			 0);
	assert_int_equal(s.vid, 0x0079);
	assert_int_equal(s.opts.split, HIDR_SPLIT_NONE);
	assert_int_equal(s.opts.deadzone, 200);
	assert_int_equal(s.opts.press, 600);
	assert_int_equal(s.opts.release, 400);
	assert_int_equal(s.opts.p2_first_button, 11);
	assert_int_equal(s.opts.p2_x, 0x32);
	assert_int_equal(s.opts.p2_y, 0x33);
	/* the look axis: auto (0) unless named, or none */
	assert_int_equal(s.opts.look, 0);
	assert_int_equal(in_hid_parse_spec("hid:look=ry", &s, why, sizeof(why)), 0);
	assert_int_equal(s.opts.look, 0x34);
	assert_int_equal(in_hid_parse_spec("hid:look=none", &s, why, sizeof(why)), 0);
	assert_int_equal(s.opts.look, HIDR_LOOK_NONE);
	assert_int_equal(in_hid_parse_spec("hid:look=auto", &s, why, sizeof(why)), 0);
	assert_int_equal(s.opts.look, 0);
}

static void test_spec_auto_detect_forms(void **state)
{
	static const char *const forms[] = { "hid", "hid:", "split=usage" };
	struct in_hid_spec s;
	char why[200];

	(void)state;
	assert_int_equal(in_hid_parse_spec(NULL, &s, why, sizeof(why)), 0);
	assert_false(in_hid_spec_names_device(&s));
	assert_int_equal(s.opts.split, HIDR_SPLIT_AUTO);
	assert_int_equal(s.opts.deadzone, 150);
	for (size_t i = 0; i < sizeof(forms) / sizeof(forms[0]); i++) {
		assert_int_equal(in_hid_parse_spec(forms[i], &s, why, sizeof(why)), 0);
		assert_false(in_hid_spec_names_device(&s));
	}
	assert_int_equal(s.opts.split, HIDR_SPLIT_USAGE);
}

static void test_spec_errors_name_the_term(void **state)
{
	static const struct { const char *spec, *why; } bad[] = {
		{ "hid:12345:1", "bad term '12345:1' in HID device spec" },
		{ "hid:zz:01", "bad term 'zz:01' in HID device spec" },
		{ "hid:port=", "bad term 'port=' in HID device spec" },
		{ "hid:foo=1", "bad term 'foo=1' in HID device spec" },
		{ "hid:1209", "bad term '1209' in HID device spec" },
		{ "hid:deadzone=1001", "bad term 'deadzone=1001' in HID device spec" },
		{ "hid:if=x", "bad term 'if=x' in HID device spec" },
		{ "hid:p2_x=q", "bad term 'p2_x=q' in HID device spec" },
		{ "hid:look=up", "bad term 'look=up' in HID device spec" },
		{ "hid:split=both", "bad term 'split=both' in HID device spec" },
		{ "hid:press=300,release=400", "release (400) above press (300)" },
	};
	struct in_hid_spec s;
	char why[200];

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		assert_int_equal(in_hid_parse_spec(bad[i].spec, &s, why, sizeof(why)), -EINVAL);
		assert_string_equal(why, bad[i].why);
	}
}

/* Makes dir (and parents) under tmpdir. */
static void mkdirs(const char *rel)
{
	char path[PATH_MAX], *p;

	assert_true(snprintf(path, sizeof(path), "%s/%s", tmpdir, rel) < (int)sizeof(path));
	for (p = path + strlen(tmpdir) + 1; *p; p++) {
		if (*p == '/') {
			*p = '\0';
			mkdir(path, 0755);
			*p = '/';
		}
	}
	mkdir(path, 0755);
}

/* sysfs: class/hidraw/NODE/device -> devices/DEVPATH (a relative link, as
 * the kernel makes it). */
static void fake_hidraw(const char *sys, const char *node, const char *devpath)
{
	char rel[PATH_MAX], link[PATH_MAX];

	assert_true(snprintf(rel, sizeof(rel), "%s/%s", sys, devpath) < (int)sizeof(rel));
	mkdirs(rel);
	assert_true(snprintf(rel, sizeof(rel), "%s/class/hidraw/%s", sys, node) < (int)sizeof(rel));
	mkdirs(rel);
	assert_true(snprintf(link, sizeof(link), "%s/%s/device", tmpdir, rel) < (int)sizeof(link));
	assert_true(snprintf(rel, sizeof(rel), "../../../%s", devpath) < (int)sizeof(rel));
	assert_int_equal(symlink(rel, link), 0);
}

static void test_port_path_from_sysfs(void **state)
{
	char sys[PATH_MAX], port[32];

	(void)state;
	fake_hidraw("sys1", "hidraw3",
		    "devices/pci0000:00/0000:00:14.0/usb1/1-1/1-1.2/1-1.2:1.0/0003:1209:0001.0005");
	fake_hidraw("sys1", "hidraw4", "devices/pci0000:00/0000:00:14.0/usb3/3-4/3-4:1.1/"
				       "0003:0079:0006.0006");
	fake_hidraw("sys1", "hidraw5", "devices/pci0000:00/0000:00:14.0/usb1/1-3/1-3:1.0/"
				       "bluetooth/hci0/hci0:256/0005:045E:02FD.0007");
	fake_hidraw("sys1", "hidraw6", "devices/virtual/misc/uhid/0003:1209:0001.0008");
	assert_true(snprintf(sys, sizeof(sys), "%s/sys1", tmpdir) < (int)sizeof(sys));
	assert_int_equal(in_hid_port(sys, "/dev/hidraw3", port, sizeof(port)), 0);
	assert_string_equal(port, "1-1.2");
	assert_int_equal(in_hid_port(sys, "hidraw4", port, sizeof(port)), 0);
	assert_string_equal(port, "3-4");
	/* a Bluetooth pad behind a USB dongle: the dongle's port is no
	 * identity of the pad, and hci0:256 is no USB interface */
	assert_int_equal(in_hid_port(sys, "hidraw5", port, sizeof(port)), 0);
	assert_string_equal(port, "");
	assert_int_equal(in_hid_port(sys, "hidraw6", port, sizeof(port)), 0);
	assert_string_equal(port, "");
	assert_int_equal(in_hid_port(sys, "hidraw9", port, sizeof(port)), -ENOENT);
}

static void test_report_descriptor_from_sysfs(void **state)
{
	static uint8_t want[4096];
	long n = fix_desc("054C_1000_buzz-4p", want, sizeof(want));
	char sys[PATH_MAX], path[PATH_MAX];
	uint8_t *got;
	size_t len;
	FILE *f;

	(void)state;
	fake_hidraw("sys2", "hidraw0", "devices/virtual/misc/uhid/0003:1209:0001.0001");
	assert_true(snprintf(sys, sizeof(sys), "%s/sys2", tmpdir) < (int)sizeof(sys));
	assert_true(snprintf(path, sizeof(path), "%s/class/hidraw/hidraw0/device/report_descriptor",
			     sys) < (int)sizeof(path));
	f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(want, 1, (size_t)n, f), (size_t)n);
	fclose(f);
	assert_int_equal(in_hid_read_desc(sys, "/dev/hidraw0", &got, &len), 0);
	assert_int_equal(len, 78);
	assert_memory_equal(got, want, 78);
	free(got);
	f = fopen(path, "wb");
	assert_non_null(f);
	for (int i = 0; i <= HIDD_MAX_DESC; i++)
		fputc(0xc0, f);
	fclose(f);
	assert_int_equal(in_hid_read_desc(sys, "hidraw0", &got, &len), -EFBIG);
	assert_null(got);
	assert_int_equal(in_hid_read_desc(sys, "hidraw1", &got, &len), -ENOENT);
}

static void test_open_matching_nothing_says_why(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	char why[512];

	(void)state;
	assert_int_equal(in_hid.open("hid:0000:0000,serial=arcaded-no-such-device", &d, why,
				     sizeof(why)),
			 -ENODEV);
	assert_null(d);
	assert_non_null(strstr(why, "no HID device matches 'hid:0000:0000,serial="
				    "arcaded-no-such-device' ("));
	assert_int_equal(in_hid.open("hid:bogus", &d, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "bad term 'bogus' in HID device spec");
	in_hid.close(NULL);
	assert_int_equal(in_hid_configure(NULL, "split=none", why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "not a HID device");
}

static void test_list_gives_hidraw_nodes(void **state)
{
	struct in_hid_info *l;
	size_t n;

	(void)state;
	assert_int_equal(in_hid_list(&l, &n), 0);
	for (size_t i = 0; i < n; i++) {
		assert_int_equal(strncmp(l[i].node, "/dev/hidraw", 11), 0);
		assert_true(l[i].fields != NULL || l[i].why[0] != '\0');
	}
	in_hid_list_free(l, n);
	in_hid_list_free(NULL, 0);
}

/* ---- with /dev/uhid ---------------------------------------------------- */

static int uhid_send(int fd, const struct uhid_event *ev)
{
	return write(fd, ev, sizeof(*ev)) == (ssize_t)sizeof(*ev) ? 0 : -1;
}

static int uhid_input(int fd, const uint8_t *rep, size_t len)
{
	static struct uhid_event ev;

	memset(&ev, 0, sizeof(ev));
	ev.type = UHID_INPUT2;
	ev.u.input2.size = (uint16_t)len;
	memcpy(ev.u.input2.data, rep, len);
	return uhid_send(fd, &ev);
}

static void sleep_ms(int ms)
{
	struct timespec ts = { .tv_sec = 0, .tv_nsec = ms * 1000000L };

	nanosleep(&ts, NULL);
}

/* Reads d for up to 2 s until key code reaches value; returns its event's
 * time, 0 if it never came. */
static uint64_t wait_key(struct in_dev *d, int code, int value)
{
	struct in_event ev[64];

	for (int i = 0; i < 200; i++) {
		int n = in_hid.read(d, ev, 64);

		assert_true(n >= 0);
		for (int k = 0; k < n; k++)
			if (ev[k].type == IN_KEY && ev[k].code == code && ev[k].value == value)
				return ev[k].time_ns;
		sleep_ms(10);
	}
	return 0;
}

static void test_uhid_device_reports_buttons_and_unplug(void **state)
{
	static struct uhid_event ev;
	static const uint8_t press[] = { 0x7f, 0x7f, 0x01, 0x00, 0xf0 };
	static const uint8_t release[] = { 0x7f, 0x7f, 0x00, 0x00, 0xf0 };
	uint8_t desc[4096];
	long n = fix_desc("054C_1000_buzz-4p", desc, sizeof(desc));
	struct in_dev *d = NULL;
	struct in_ident id;
	struct in_event e[8];
	char why[512];
	uint64_t t0, t;
	int fd, rc = -ENODEV;

	(void)state;
	fd = open("/dev/uhid", O_RDWR | O_CLOEXEC);
	if (fd < 0) {
		printf("skipped: /dev/uhid: %s (the VM tests have it)\n", strerror(errno));
		skip();
	}
	memset(&ev, 0, sizeof(ev));
	ev.type = UHID_CREATE2;
	snprintf((char *)ev.u.create2.name, sizeof(ev.u.create2.name), "arcaded test buzz");
	ev.u.create2.rd_size = (uint16_t)n;
	ev.u.create2.bus = 0x03;          /* BUS_USB */
	ev.u.create2.vendor = 0x1209;
	ev.u.create2.product = 0x7e57;
	memcpy(ev.u.create2.rd_data, desc, (size_t)n);
	assert_int_equal(uhid_send(fd, &ev), 0);
	for (int i = 0; i < 200 && rc < 0; i++) {
		rc = in_hid.open("hid:1209:7e57", &d, why, sizeof(why));
		if (rc < 0)
			sleep_ms(10);
	}
	if (rc < 0)
		fprintf(stderr, "open: %s\n", why);
	assert_int_equal(rc, 0);
	in_hid.ident(d, &id);
	assert_int_equal(id.vid, 0x1209);
	assert_int_equal(id.pid, 0x7e57);
	assert_string_equal(id.port, "");
	assert_int_equal(in_hid.fd(d), -1);
	assert_int_equal(in_hid_configure(d, "port=1-1", why, sizeof(why)), -EINVAL);
	assert_int_equal(in_hid_configure(d, "split=none, deadzone=300", why, sizeof(why)), 0);
	t0 = in_now_ns();
	assert_int_equal(uhid_input(fd, press, sizeof(press)), 0);
	t = wait_key(d, BTN_TRIGGER_HAPPY1, 1);
	assert_true(t >= t0 && t <= in_now_ns());
	assert_int_equal(uhid_input(fd, release, sizeof(release)), 0);
	assert_true(wait_key(d, BTN_TRIGGER_HAPPY1, 0) != 0);
	memset(&ev, 0, sizeof(ev));
	ev.type = UHID_DESTROY;
	assert_int_equal(uhid_send(fd, &ev), 0);
	rc = 0;
	for (int i = 0; i < 200 && rc >= 0; i++) {
		rc = in_hid.read(d, e, 8);
		if (rc >= 0)
			sleep_ms(10);
	}
	assert_int_equal(rc, -ENODEV);
	in_hid.close(d);
	close(fd);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_spec_terms),
		cmocka_unit_test(test_spec_auto_detect_forms),
		cmocka_unit_test(test_spec_errors_name_the_term),
		cmocka_unit_test(test_port_path_from_sysfs),
		cmocka_unit_test(test_report_descriptor_from_sysfs),
		cmocka_unit_test(test_open_matching_nothing_says_why),
		cmocka_unit_test(test_list_gives_hidraw_nodes),
		cmocka_unit_test(test_uhid_device_reports_buttons_and_unplug),
	};

	return cmocka_run_group_tests(tests, make_tmpdir, remove_tmpdir);
}
