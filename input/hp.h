/*
 * hp: hotplug notices. Tells the main loop, without blocking, that input
 * devices may have appeared or gone, so a closed input slot retries its
 * open at once instead of at its next periodic rescan.
 *
 * Two sources:
 *   - inotify on the directories where input backends' device nodes
 *     appear (in_backend.node: /dev/hidraw, /dev/gpiochip,
 *     /dev/input/event): devtmpfs creates and removes the nodes as
 *     the kernel adds and removes devices, and udev changes their owner
 *     and mode right after (IN_ATTRIB), which is when the service's user
 *     can open them. Works inside the hardened unit (no network, AF_UNIX
 *     only) and without udevd.
 *   - libusb hotplug callbacks (USB devices arriving and leaving), where
 *     libusb can run them: Debian's libusb watches udev's netlink
 *     messages, which a unit with PrivateNetwork= and
 *     RestrictAddressFamilies=AF_UNIX never receives, so there libusb's
 *     set-up fails and hp says so in hp_sources; inotify still works.
 *
 * Ownership: hp_open returns a handle the caller frees with hp_close
 * (NULL-safe). One thread uses a handle.
 */
#ifndef ARCADED_INPUT_HP_H
#define ARCADED_INPUT_HP_H

#include <stddef.h>

/* What hp_poll saw since the last call (a bit mask). */
enum hp_what {
	HP_NODE = 1,             /* a watched device node appeared, changed or went */
	HP_USB_ARRIVED = 2,      /* libusb: a USB device arrived */
	HP_USB_LEFT = 4,         /* libusb: a USB device left */
};

/* Watch sources (hp_open's flags). */
#define HP_INOTIFY 1u
#define HP_LIBUSB 2u

#define HP_MAX_NODES 8

struct hp;

/* Watches the nodes named by the n patterns nodes[i], each a directory
 * and a name prefix ("/dev/hidraw": nodes hidraw* of /dev; at most
 * HP_MAX_NODES, directories watched once each in the order they first
 * appear), and, with HP_LIBUSB, USB arrivals and departures. A source
 * that cannot be set up is left out and named in hp_sources with its
 * reason; -ENODEV (why says why) only when no source works at all. */
int hp_open(const char *const *nodes, int n, unsigned flags, struct hp **out, char *why,
	    size_t whylen);

/* Non-blocking: drains pending notices; their enum hp_what bits, 0 none. */
int hp_poll(struct hp *h);

/* A file descriptor that becomes readable when hp_poll has something to
 * report (the inotify one), or -1. */
int hp_fd(const struct hp *h);

/* "inotify /dev /dev/input; libusb hotplug" or with a source's failure
 * ("libusb: not available: ..."), for the log. */
const char *hp_sources(const struct hp *h);

void hp_close(struct hp *h);

#endif
