/*
 * hp: hotplug notices. Tells the main loop, without blocking, that
 * devices may have appeared or gone, so a closed input slot (or a missing
 * display) retries its open at once instead of at its next periodic
 * rescan.
 *
 * Two sources:
 *   - inotify on the directories where the backends' device nodes
 *     appear (in_backend.node: /dev/hidraw, /dev/gpiochip,
 *     /dev/input/event; dp_backend.node: /dev/fb): devtmpfs creates and
 *     removes the nodes as the kernel adds and removes devices, and udev
 *     changes their owner and mode right after (IN_ATTRIB), which is when
 *     the service's user can open them. A directory that does not exist
 *     yet (/dev/dri before a DRM driver loads) is waited for in its
 *     parent: its creation is a notice, and from then on it is watched.
 *     Works without udevd and without any network socket.
 *   - libusb hotplug callbacks (USB devices arriving and leaving), where
 *     libusb can run them: Debian's libusb learns of devices from udev's
 *     netlink messages, so the process needs AF_NETLINK sockets and the
 *     host's network namespace (systemd/arcaded.service allows both, IP
 *     traffic stays denied); where libusb cannot start, hp says so in
 *     hp_sources and inotify still works.
 *
 * Every notice of the last hp_poll is also kept with its details
 * (hp_notices), for the log.
 *
 * Ownership: hp_open returns a handle the caller frees with hp_close
 * (NULL-safe). One thread uses a handle.
 */
#ifndef ARCADED_INPUT_HP_H
#define ARCADED_INPUT_HP_H

#include <stddef.h>
#include <stdint.h>

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
#define HP_MAX_NOTICES 32

/* One notice of the last hp_poll. */
struct hp_notice {
	unsigned what;           /* one enum hp_what bit */
	char name[64];           /* HP_NODE: the node ("/dev/hidraw0", "/dev/dri" for a
				  * directory that appeared); USB: the port path ("1-1.2") */
	char how[16];            /* HP_NODE: "created", "changed", "removed" */
	uint16_t vid, pid;       /* USB: the device's ids */
	uint64_t time_ns;        /* CLOCK_MONOTONIC when hp saw it (libusb: its callback) */
};

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

/* The notices the last hp_poll returned, in the order hp saw them (at
 * most HP_MAX_NOTICES; further ones still count in hp_poll's bits): their
 * count, *out pointing at them until the next hp_poll or hp_close. */
int hp_notices(const struct hp *h, const struct hp_notice **out);

/* A file descriptor that becomes readable when hp_poll has something to
 * report (the inotify one), or -1. */
int hp_fd(const struct hp *h);

/* "inotify /dev /dev/input; libusb hotplug" or with a source's failure
 * ("libusb: not available: ..."), for the log. */
const char *hp_sources(const struct hp *h);

/* Whether every source asked for works (hp_sources names no failure). */
int hp_complete(const struct hp *h);

void hp_close(struct hp *h);

#endif
