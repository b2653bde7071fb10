/*
 * test_hidsys: the hidraw scan over a sysfs tree made here (the kernel's
 * layout: class/hidraw/hidrawN/device -> the HID device, inside its USB
 * interface, inside its USB device), including a device that vanished
 * between the directory listing and its uevent.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "input/hidsys.h"

static char root[64];

static void put(const char *rel, const char *text)
{
	char path[512], *slash;
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", root, rel);
	for (slash = strchr(path + strlen(root) + 1, '/'); slash; slash = strchr(slash + 1, '/')) {
		*slash = '\0';
		mkdir(path, 0755);
		*slash = '/';
	}
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
}

static void link_node(const char *node, const char *target)
{
	char dir[512], lnk[600], tgt[512];

	snprintf(dir, sizeof(dir), "%s/class/hidraw/%s", root, node);
	mkdir(dir, 0755);
	snprintf(lnk, sizeof(lnk), "%s/device", dir);
	snprintf(tgt, sizeof(tgt), "%s/%s", root, target);
	assert_int_equal(symlink(tgt, lnk), 0);
}

static int setup(void **state)
{
	(void)state;
	snprintf(root, sizeof(root), "/tmp/test_hidsys.XXXXXX");
	assert_non_null(mkdtemp(root));
	/* a USB encoder: strings from the USB device, interface 1 */
	put("devices/usb1/1-2/manufacturer", "Ultimarc\n");
	put("devices/usb1/1-2/product", "I-PAC 4\n");
	put("devices/usb1/1-2/1-2:1.1/bInterfaceNumber", "01\n");
	put("devices/usb1/1-2/1-2:1.1/0003:D209:0440.0007/uevent",
	    "DRIVER=hid-generic\nHID_ID=0003:0000D209:00000440\nHID_NAME=Ultimarc I-PAC 4\n"
	    "HID_PHYS=usb-0000:00:14.0-2/input1\nHID_UNIQ=\nMODALIAS=hid:b0003g0001v0000D209p00000440\n");
	put("class/hidraw/.keep", "");
	link_node("hidraw10", "devices/usb1/1-2/1-2:1.1/0003:D209:0440.0007");
	/* a Bluetooth pad: no USB strings, HID_NAME and the serial */
	put("devices/bt/0005:054C:05C4.0008/uevent",
	    "HID_ID=0005:0000054C:000005C4\nHID_NAME=Wireless Controller\nHID_UNIQ=a4:53:85:00:11:22\n");
	link_node("hidraw3", "devices/bt/0005:054C:05C4.0008");
	/* uhid claiming USB, with no USB device around it */
	put("devices/virtual/misc/uhid/0003:1209:0001.0009/uevent",
	    "HID_ID=0003:00001209:00000001\nHID_NAME=arcaded test pad\n");
	link_node("hidraw4", "devices/virtual/misc/uhid/0003:1209:0001.0009");
	/* unplugged between the listing and its uevent: the link dangles */
	link_node("hidraw5", "devices/gone/0003:1234:5678.000A");
	return 0;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", root);
	return system(cmd) == 0 ? 0 : -1;
}

static void scan_reads_every_device_and_leaves_out_the_gone(void **state)
{
	struct in_hid_info *l = NULL;
	size_t n = 99;

	(void)state;
	assert_int_equal(hidsys_scan(root, &l, &n), 0);
	assert_int_equal(n, 3);
	/* node number order: 3, 4, 10 (not the directory's order) */
	assert_string_equal(l[0].node, "/dev/hidraw3");
	assert_int_equal(l[0].vid, 0x054c);
	assert_int_equal(l[0].pid, 0x05c4);
	assert_int_equal(l[0].iface, -1);
	assert_string_equal(l[0].name, "Wireless Controller");
	assert_string_equal(l[0].serial, "a4:53:85:00:11:22");
	assert_string_equal(l[1].node, "/dev/hidraw4");
	assert_int_equal(l[1].vid, 0x1209);
	assert_int_equal(l[1].iface, -1);
	assert_string_equal(l[1].name, "arcaded test pad");
	assert_string_equal(l[2].node, "/dev/hidraw10");
	assert_int_equal(l[2].vid, 0xd209);
	assert_int_equal(l[2].pid, 0x0440);
	assert_int_equal(l[2].iface, 1);
	assert_string_equal(l[2].name, "Ultimarc I-PAC 4");
	assert_string_equal(l[2].serial, "");
	free(l);
}

static void no_hidraw_class_is_no_devices(void **state)
{
	struct in_hid_info *l = (struct in_hid_info *)1;
	size_t n = 99;

	(void)state;
	assert_int_equal(hidsys_scan("/nonexistent-sysfs", &l, &n), 0);
	assert_int_equal(n, 0);
	assert_null(l);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(scan_reads_every_device_and_leaves_out_the_gone),
		cmocka_unit_test(no_hidraw_class_is_no_devices),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
