/*
 * in_hid: HID devices (USB encoders, pads) through hidapi's hidraw backend.
 * The backend is in_hid (input/in.h); this header has what else it
 * offers: the device spec parser, the sysfs lookups and the device list
 * for `arcaded devices`.
 *
 * Device spec (the path given to in_hid.open), "hid:" then comma-separated
 * terms, all of which must match; the first match in /dev/hidrawN number
 * order is opened:
 *   VVVV:PPPP        vendor and product id, hex ("hid:0079:0006")
 *   port=PATH        USB port path as sysfs names it ("hid:port=1-1.2"):
 *                    bus 1, root port 1, hub port 2; stays the same across
 *                    reboots and replugs into the same socket
 *   serial=TEXT      the USB serial number string
 *   /dev/hidrawN     that node (also node=/dev/hidrawN)
 *   if=N             USB interface number (encoders with a keyboard and a
 *                    joystick interface)
 * and decoder options (input/hidr.h):
 *   split=auto|none|usage, deadzone=N, press=N, release=N (per mille),
 *   p2_button=N (first button of player 2), p2_x=AXIS, p2_y=AXIS (AXIS: x
 *   y z rx ry rz slider dial wheel).
 * A NULL path, "hid" or "hid:" with no device term auto-detects: the first
 * device whose descriptor has a joystick or gamepad application collection
 * with buttons, axes or a hat (keyboards are left to evdev).
 * A node this process already has open (through another in_dev) is passed
 * over by every open, so several auto-detecting opens take several pads.
 *
 * Reading: hidapi 0.13 gives no file descriptor (fd returns -1). Each open
 * device has a reader thread blocked in hid_read_timeout that stamps every
 * report with in_now_ns() as it arrives (hidraw has no timestamps, so this
 * is the closest to the kernel's time) and queues up to 64 reports; the
 * app calls read every tick, which decodes the queued reports (at most 256
 * per call) by hidr into changes with their arrival times. A full queue
 * makes the thread wait (the kernel buffers meanwhile): no report is
 * dropped. A failed read (the device was unplugged) is -ENODEV once the
 * reports before it are delivered; close stops and joins the thread
 * (within 50 ms).
 * Codes: BTN_TRIGGER_HAPPY*, BTN_DPAD_*, KEY_* and ABS_* as hidr.h
 * says.
 *
 * The report descriptor comes from sysfs, SYSFS/class/hidraw/hidrawN/
 * device/report_descriptor (hidapi 0.13 has no hid_get_report_descriptor),
 * and the port path from where SYSFS/class/hidraw/hidrawN/device resolves
 * to: the HID device's parent, when it is a USB interface directory
 * ("1-1.2:1.0"), less its ":config.interface" suffix; "" otherwise
 * (Bluetooth, uhid, I2C).
 */
#ifndef ARCADED_INPUT_IN_HID_H
#define ARCADED_INPUT_IN_HID_H

#include <stddef.h>
#include <stdint.h>

#include "input/hidr.h"

struct in_hid_spec {
	int vid, pid;            /* -1: any */
	char port[32];           /* "": any */
	char serial[64];         /* "": any */
	char node[64];           /* "": any */
	int iface;               /* -1: any */
	struct hidr_opts opts;
};

/* Parses spec s (NULL: auto-detect). 0, or -EINVAL with the reason in why. */
int in_hid_parse_spec(const char *s, struct in_hid_spec *out, char *why, size_t whylen);

/* Whether out names a device (any term but the decoder options). */
int in_hid_spec_names_device(const struct in_hid_spec *s);

/* Rebuilds the decoder of d (opened by in_hid) with the decoder options in
 * terms (split, deadzone, press, release, p2_button, p2_x, p2_y, as in a
 * spec; device terms are refused) on top of those it was opened with: how
 * a profile's "hid =" options (config/prof.h) are applied once the device
 * is known (it is in_hid.configure). The decoder starts over with every control released and
 * undelivered events are dropped: call it right after open. 0, -EINVAL
 * with the reason in why, or -ENOMEM (d keeps its old decoder). */
int in_hid_configure(struct in_dev *d, const char *terms, char *why, size_t whylen);

/* USB port path of hidraw node ("/dev/hidraw3" or "hidraw3") under sysfs
 * root sysroot ("/sys"): 0 with port "" when the device is not on USB, or
 * -errno when the node has no sysfs entry. */
int in_hid_port(const char *sysroot, const char *node, char *port, size_t len);

/* Reads the report descriptor of node under sysroot into a new buffer
 * (free()); 0 or -errno (-EFBIG above HIDD_MAX_DESC bytes). */
int in_hid_read_desc(const char *sysroot, const char *node, uint8_t **buf, size_t *len);

struct in_hid_info {
	char node[64];           /* /dev/hidrawN */
	uint16_t vid, pid;
	int iface;               /* -1 when not USB */
	char port[32];
	char name[128];          /* manufacturer and product strings */
	char serial[64];
	char *fields;            /* hidd_describe of its descriptor (malloc'd), or NULL */
	char why[160];           /* why fields is NULL */
};

/* Lists every hidraw device sysfs lists (input/hidsys.h), in node number order, with its
 * decoded fields. 0 (*n may be 0) or -ENOMEM. */
int in_hid_list(struct in_hid_info **out, size_t *n);

/* NULL-safe. */
void in_hid_list_free(struct in_hid_info *l, size_t n);

#endif
