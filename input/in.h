/*
 * in: input devices. Every backend is one file (in_evdev.c, in_tty.c, ...)
 * implementing struct in_backend; backends deliver raw events, which the
 * bindings (config/bind.h) turn into actions.
 *
 * Control codes for keys are the Linux input event codes (KEY_*): a stable
 * kernel ABI, so a terminal key and an evdev key bind the same way. Only
 * backend files include Linux headers; in_keys.c names the codes.
 */
#ifndef ARCADED_INPUT_IN_H
#define ARCADED_INPUT_IN_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "input/gpo.h"

enum in_type {
	IN_KEY = 1,              /* code: KEY_* / BTN_*; value 1 press, 0 release */
	IN_ABS = 3,              /* code: ABS_*; value: axis position */
};

struct in_event {
	uint64_t time_ns;        /* CLOCK_MONOTONIC time the kernel stamped the event */
	uint16_t type;           /* enum in_type */
	uint16_t code;
	int32_t value;
};

struct in_dev;

/* Who a device is, for per-device bindings (config/bind.h): two identical
 * encoders differ by the USB port they are plugged into. */
struct in_ident {
	char port[32];           /* USB port path ("1-1.2"); "" when not on USB */
	uint16_t vid, pid;       /* 0 when unknown */
	char name[128];          /* product name, "" when unknown */
};

struct in_backend {
	const char *name;
	/* Opens the device at path (NULL: auto-detect). 0 or -errno with a
	 * reason in why; -ENODEV when nothing suitable exists. */
	int (*open)(const char *path, struct in_dev **out, char *why, size_t whylen);
	/* File descriptor to poll for readability, or -1. */
	int (*fd)(struct in_dev *d);
	/* Non-blocking: stores up to max events, returns how many (0: none),
	 * or -ENODEV when the device went away (the caller releases every
	 * control of it and may reopen later). */
	int (*read)(struct in_dev *d, struct in_event *ev, int max);
	/* NULL-safe; releases grabs and restores what open changed. */
	void (*close)(struct in_dev *d);
	/* Human-readable name ("AT Translated Set 2 keyboard (/dev/input/event3)"). */
	const char *(*describe)(struct in_dev *d);
	/* Optional (NULL: the backend cannot tell): fills id. */
	void (*ident)(struct in_dev *d, struct in_ident *id);

	/* The entries below are optional: a backend without the feature
	 * leaves them NULL (0). The app uses no backend in any other way. */

	/* Applies a profile's decoder options (config/prof.h, "hid =": terms
	 * as input/in_hid.h lists them) to d, right after open. 0 or -errno
	 * with the reason in why (d keeps what it had). */
	int (*configure)(struct in_dev *d, const char *terms, char *why, size_t whylen);
	/* Drives d's output lines (coin meter, lamps) for the game's state s
	 * at time now_ns (not decreasing); called once per tick. 0, or
	 * -ENODEV when the device went away (the caller drops it as after a
	 * read's -ENODEV). */
	int (*outputs)(struct in_dev *d, const struct gpo_state *s, uint64_t now_ns);
	/* Where this backend's device nodes appear: a directory and a name
	 * prefix ("/dev/hidraw"). A node created, changed (udev granting
	 * access) or removed there is a hotplug notice (hp.h): closed slots
	 * retry at once instead of at their next periodic rescan. */
	const char *node;
	/* `arcaded devices`: prints to out a heading line, then every device
	 * of this kind with what a bindings section names it by; profile(u,
	 * id) names the autoconfig profile that would configure a device
	 * (NULL: none). 0, or -errno when the listing failed (the heading
	 * says so). */
	int (*list)(FILE *out, const char *(*profile)(void *u, const struct in_ident *id),
		    void *u);
	/* Which control codes the bindings use, for auto-detection: an
	 * auto-detecting open takes only a device with a code for which
	 * fn(u, id, code) is nonzero (id: that device's ident), so a device
	 * nothing binds is left alone. Called once before the first open;
	 * fn is asked again at every later auto-detection, so bindings the
	 * wizard changed count. fn NULL: every code counts. */
	void (*set_bound)(int (*fn)(void *u, const struct in_ident *id, int code), void *u);
	unsigned flags;          /* IN_* below */
};

/* in_backend.flags. */
enum {
	/* "auto" takes keyboards for itself (evdev grabs them): not done
	 * while the display reads the keyboard (dp_backend.input), where it
	 * would take the developer's own keyboard from every window. */
	IN_AUTO_TAKES_KEYBOARD = 1,
	/* Its controls are not keys the default bindings cover (a HID pad's
	 * BTN_TRIGGER_HAPPYn, BTN_DPAD_*): a device no bindings section and no
	 * profile but the generic guess names is of no use until bound, so on
	 * a first boot it starts the input wizard. */
	IN_NEEDS_BINDINGS = 2,
};

/* in_evdev: keyboards and encoders through libevdev (input/in_evdev.h);
 * in_hid: HID devices through hidapi (input/in_hid.h); in_gpio: switches
 * and coin lines on GPIO through libgpiod (input/in_gpio.h). */
extern const struct in_backend in_evdev, in_tty, in_hid, in_gpio;

/* Key code by name: "KEY_UP", "up", "w", "space", "enter", "BTN_SOUTH", ...
 * (case-insensitive; a bare letter or digit is that key). -1 if unknown. */
int in_key_from_name(const char *name);
/* Canonical name ("KEY_UP") of a code, or NULL. */
const char *in_key_name(int code);

/* The USB port path ("1-1.2") of the device whose sysfs directory (or a
 * link to it) is dir, after dropping `up` trailing path components: the
 * port when the last remaining component is a USB interface directory
 * ("1-1.2:1.0") or that component's parent is one (a HID device under its
 * interface); port is "" otherwise (uinput, Bluetooth behind a dongle:
 * the dongle's port is not the pad's). 0 or -errno (dir unresolvable,
 * -ENAMETOOLONG). in_sysfs.c. */
int in_usb_port(const char *dir, int up, char *port, size_t len);

/* Appends printf output to the NUL-terminated text in buf (len bytes in
 * all), cutting it to fit; nothing when buf is full. The backends' reasons
 * ("why") and descriptions are built with it. */
void in_say(char *buf, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* CLOCK_MONOTONIC now, ns (for backends whose source has no timestamp). */
uint64_t in_now_ns(void);

#endif
