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

#define HP_PREFIX_MAX 32

struct hp {
	int fd;                          /* inotify, -1 when not in use */
	struct {
		int wd;                  /* its directory's watch, -1 none */
		char prefix[HP_PREFIX_MAX];
	} node[HP_MAX_NODES];
	int nnodes;
	libusb_context *usb;             /* NULL when libusb is not in use */
	libusb_hotplug_callback_handle cb;
	int seen;                        /* enum hp_what bits gathered by callbacks */
	char sources[256];
};

/* Only the nodes input backends open, each in its own directory; /dev
 * sees ttys, ptys and others come and go, which must not cost a rescan. */
static int hp_wanted(const struct hp *h, int wd, const char *name)
{
	for (int i = 0; i < h->nnodes; i++)
		if (h->node[i].wd == wd &&
		    strncmp(name, h->node[i].prefix, strlen(h->node[i].prefix)) == 0)
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

/* Watches the directory of nodes[i] (once per directory) and keeps its
 * prefix. 0, or -EINVAL for a pattern that is not DIR/PREFIX. */
static int hp_watch(struct hp *h, const char *const *nodes, int i, char *why, size_t whylen)
{
	const char *slash = strrchr(nodes[i], '/');
	char dir[256];
	int k = h->nnodes;

	if (!slash || slash == nodes[i] || !slash[1] || strlen(slash + 1) >= HP_PREFIX_MAX ||
	    (size_t)(slash - nodes[i]) >= sizeof(dir)) {
		snprintf(why, whylen, "%s: not a directory and a node name prefix", nodes[i]);
		return -EINVAL;
	}
	snprintf(dir, sizeof(dir), "%.*s", (int)(slash - nodes[i]), nodes[i]);
	snprintf(h->node[k].prefix, sizeof(h->node[k].prefix), "%s", slash + 1);
	h->node[k].wd = -1;
	h->nnodes++;
	for (int j = 0; j < k; j++)
		if (strncmp(nodes[j], nodes[i], (size_t)(slash - nodes[i]) + 1) == 0 &&
		    strchr(nodes[j] + (slash - nodes[i]) + 1, '/') == NULL) {
			h->node[k].wd = h->node[j].wd;   /* the same directory */
			return 0;
		}
	if (h->fd < 0)
		return 0;
	h->node[k].wd = inotify_add_watch(h->fd, dir, IN_CREATE | IN_ATTRIB | IN_DELETE |
					  IN_MOVED_TO | IN_MOVED_FROM | IN_ONLYDIR);
	if (h->node[k].wd < 0)
		in_say(h->sources, sizeof(h->sources), " (%s: %s)", dir, strerror(errno));
	else
		in_say(h->sources, sizeof(h->sources), " %s", dir);
	return 0;
}

int hp_open(const char *const *nodes, int n, unsigned flags, struct hp **out, char *why,
	    size_t whylen)
{
	struct hp *h;
	int watched = 0;

	*out = NULL;
	if (n < 0 || n > HP_MAX_NODES) {
		snprintf(why, whylen, "%d node patterns (at most %d)", n, HP_MAX_NODES);
		return -EINVAL;
	}
	h = calloc(1, sizeof(*h));
	if (!h)
		return -ENOMEM;
	h->fd = -1;
	if (flags & HP_INOTIFY) {
		h->fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
		if (h->fd < 0)
			in_say(h->sources, sizeof(h->sources), "inotify: %s", strerror(errno));
		else
			in_say(h->sources, sizeof(h->sources), "inotify");
	}
	for (int i = 0; i < n; i++) {
		int rc = hp_watch(h, nodes, i, why, whylen);
		if (rc < 0) {
			if (h->fd >= 0)
				close(h->fd);
			free(h);
			return rc;
		}
		watched += h->node[i].wd >= 0;
	}
	if (h->fd >= 0 && !watched) {
		close(h->fd);
		h->fd = -1;
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
			else if (e->len && hp_wanted(h, e->wd, e->name))
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
