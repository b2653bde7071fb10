/*
 * in_evdev: keys and axes from Linux input devices (/dev/input/eventN)
 * through libevdev. The backend is in_evdev (input/in.h); this header has
 * what else it offers: auto-detection over another directory, the rule it
 * applies, and the device list for `arcaded devices`.
 *
 * Auto-detection (open with a NULL path) takes a device the bindings
 * need: the first of DIR/event0, event1, ... (numeric order) that opens,
 * is not open in this process already (through another slot), and has at
 * least one key or button the bindings use for it (in_evdev.set_bound:
 * its own [device] section, else [keyboard]). So several auto-detecting
 * opens take several devices: a keyboard encoder (I-PAC style) next to a
 * PS/2 keyboard, a service keyboard, a second encoder. Devices whose keys
 * nothing binds (power and sleep buttons, lid switches, media keys, mice,
 * a pad whose buttons are bound through hidraw instead) are passed over.
 */
#ifndef ARCADED_INPUT_IN_EVDEV_H
#define ARCADED_INPUT_IN_EVDEV_H

#include <stddef.h>

#include "input/in.h"

struct libevdev;

/* in_evdev's auto-detection over DIR/event* instead of /dev/input/event*
 * (in_evdev.open with a NULL path is this with "/dev/input"); for tests.
 * 0, or -ENODEV with every device tried and why it was passed over in
 * why. */
int in_evdev_open_dir(const char *dir, struct in_dev **out, char *why, size_t whylen);

/* The keys and buttons of ev (a device identified as id) the bindings use
 * for it, by the function in_evdev.set_bound was given (none given: all
 * of them): their count; the first max codes go to codes (NULL: only the
 * count). A device is auto-detected when this is above 0. */
int in_evdev_bound_keys(const struct libevdev *ev, const struct in_ident *id, int *codes,
			int max);

/* One evdev device as `arcaded devices` lists it. */
struct in_evdev_info {
	char node[64];           /* /dev/input/eventN */
	int opened;              /* 0: could not be opened (why says why) */
	int nbound;              /* its keys the bindings use: auto-detection takes it if > 0 */
	int bound[8];            /* the first of them */
	struct in_ident id;
	char why[160];
};

/* Every DIR/event* (NULL: /dev/input), in number order, opened briefly to
 * read its name, ids, USB port and bound keys (never grabbed). *out is
 * malloc'd (free it). 0 or -errno when DIR cannot be listed. */
int in_evdev_list(const char *dir, struct in_evdev_info **out, size_t *count);

#endif
