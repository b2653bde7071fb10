/*
 * hidsys: the hidraw devices as sysfs lists them, for in_hid's
 * auto-detection and `arcaded devices`: read from sysfs directly, each read
 * allowed to fail (a device unplugged during the scan is left out).
 */
#ifndef ARCADED_INPUT_HIDSYS_H
#define ARCADED_INPUT_HIDSYS_H

#include <stddef.h>

#include "input/in_hid.h"

/* The hidraw devices under SYSROOT/class/hidraw (sysroot "/sys"; a test
 * gives its own tree), in node number order: node "/dev/hidrawN"; vid and
 * pid from the HID device's uevent (HID_ID); serial HID_UNIQ; name the USB
 * device's "manufacturer product" strings, else HID_NAME; iface the USB
 * interface number, else -1. port, fields and why are left empty. 0 with
 * *out (malloc'd, *count may be 0; no hidraw directory is no devices), or
 * -errno. */
int hidsys_scan(const char *sysroot, struct in_hid_info **out, size_t *count);

#endif
