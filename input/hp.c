/*
 * hp: hotplug notices from inotify and libusb (contract in hp.h).
 */
#include "input/hp.h"
#include "input/in.h"

#include <errno.h>
#include <fcntl.h>
#include <libusb.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/inotify.h>
#include <unistd.h>

#define HP_MAX_DIRS 4

struct hp {
	int fd;                          /* inotify, -1 when not in use */
	libusb_context *usb;             /* NULL when libusb is not in use */
	libusb_hotplug_callback_handle cb;
	int seen;                        /* enum hp_what bits gathered by callbacks */
	char sources[256];
};

/* Only the nodes input backends open; /dev sees ttys, ptys and others come
 * and go, which must not cost a rescan. */
static int hp_wanted(const char *name)
{
	static const char *const prefix[] = { "hidraw", "gpiochip", "event" };

	for (size_t i = 0; i < sizeof(prefix) / sizeof(prefix[0]); i++)
		if (strncmp(name, prefix[i], strlen(prefix[i])) == 0)
			return 1;
	return 0;
}

/* libusb calls this from inside libusb_handle_events (hp_poll). */
static int LIBUSB_CALL hp_usb_cb(libusb_context *ctx, libusb_device *dev,
				 libusb_hotplug_event ev, void *user)
{
	struct hp *h = user;

	(void)ctx;
	(void)dev;
	h->seen |= ev == LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED ? HP_USB_ARRIVED : HP_USB_LEFT;
	return 0;  /* stay registered */
}

static void hp_open_usb(struct hp *h)
{
	int rc;

	if (!libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
		in_say(h->sources, sizeof(h->sources), "%slibusb: no hotplug support in this libusb", h->sources[0] ? "; " : "");
		return;
	}
	rc = libusb_init(&h->usb);
	if (rc == 0)
		rc = libusb_hotplug_register_callback(
			h->usb, LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED | LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT, 0,
			LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY, LIBUSB_HOTPLUG_MATCH_ANY,
			hp_usb_cb, h, &h->cb);
	if (rc != 0) {
		in_say(h->sources, sizeof(h->sources), "%slibusb: not available: %s", h->sources[0] ? "; " : "",
			libusb_strerror(rc));
		if (h->usb)
			libusb_exit(h->usb);
		h->usb = NULL;
		return;
	}
	in_say(h->sources, sizeof(h->sources), "%slibusb hotplug", h->sources[0] ? "; " : "");
}

int hp_open(const char *const *dirs, int ndirs, unsigned flags, struct hp **out, char *why,
	    size_t whylen)
{
	static const char *const def[] = { "/dev", "/dev/input" };
	struct hp *h;
	int watched = 0;

	*out = NULL;
	if (!dirs) {
		dirs = def;
		ndirs = 2;
	}
	if (ndirs < 0 || ndirs > HP_MAX_DIRS) {
		snprintf(why, whylen, "%d directories (at most %d)", ndirs, HP_MAX_DIRS);
		return -EINVAL;
	}
	h = calloc(1, sizeof(*h));
	if (!h)
		return -ENOMEM;
	h->fd = -1;
	if (flags & HP_INOTIFY) {
		h->fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
		if (h->fd < 0) {
			in_say(h->sources, sizeof(h->sources), "inotify: %s", strerror(errno));
		} else {
			in_say(h->sources, sizeof(h->sources), "inotify");
			for (int i = 0; i < ndirs; i++) {
				if (inotify_add_watch(h->fd, dirs[i], IN_CREATE | IN_ATTRIB | IN_DELETE |
						      IN_MOVED_TO | IN_MOVED_FROM | IN_ONLYDIR) < 0) {
					in_say(h->sources, sizeof(h->sources), " (%s: %s)", dirs[i], strerror(errno));
					continue;
				}
				in_say(h->sources, sizeof(h->sources), " %s", dirs[i]);
				watched++;
			}
			if (!watched) {
				close(h->fd);
				h->fd = -1;
			}
		}
	}
	if (flags & HP_LIBUSB)
		hp_open_usb(h);
	if (h->fd < 0 && !h->usb) {
		snprintf(why, whylen, "no hotplug source: %s", h->sources[0] ? h->sources : "none asked for");
		free(h);
		return -ENODEV;
	}
	*out = h;
	return 0;
}

static int hp_drain(struct hp *h)
{
	/* Aligned for struct inotify_event, as inotify(7) asks. */
	char buf[4096] __attribute__((aligned(__alignof__(struct inotify_event))));
	int what = 0;

	for (;;) {
		ssize_t n = read(h->fd, buf, sizeof(buf));
		if (n <= 0)
			break;   /* EAGAIN: drained; errors leave the fd to the next call */
		for (ssize_t off = 0; off + (ssize_t)sizeof(struct inotify_event) <= n;) {
			const struct inotify_event *e = (const void *)(buf + off);
			if (e->mask & IN_Q_OVERFLOW)
				what |= HP_NODE;   /* lost some: rescan anyway */
			else if (e->len && hp_wanted(e->name))
				what |= HP_NODE;
			off += (ssize_t)sizeof(*e) + e->len;
		}
	}
	return what;
}

int hp_poll(struct hp *h)
{
	int what = 0;

	if (!h)
		return 0;
	if (h->fd >= 0)
		what |= hp_drain(h);
	if (h->usb) {
		struct timeval zero = { 0, 0 };
		libusb_handle_events_timeout_completed(h->usb, &zero, NULL);
		what |= h->seen;
		h->seen = 0;
	}
	return what;
}

int hp_fd(const struct hp *h)
{
	return h ? h->fd : -1;
}

const char *hp_sources(const struct hp *h)
{
	return h ? h->sources : "";
}

void hp_close(struct hp *h)
{
	if (!h)
		return;
	if (h->usb) {
		libusb_hotplug_deregister_callback(h->usb, h->cb);
		libusb_exit(h->usb);
	}
	if (h->fd >= 0)
		close(h->fd);
	free(h);
}
