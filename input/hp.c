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
#define HP_DIR_MAX 128

/* What a watched directory reports. IN_MASK_ADD: a directory watched for
 * two reasons (/dev holds /dev/fb* and is the parent of a missing
 * /dev/dri) keeps both masks. */
#define HP_DIR_MASK (IN_CREATE | IN_ATTRIB | IN_DELETE | IN_MOVED_TO | IN_MOVED_FROM | \
		     IN_ONLYDIR | IN_MASK_ADD)
#define HP_PARENT_MASK (IN_CREATE | IN_MOVED_TO | IN_ONLYDIR | IN_MASK_ADD)

struct hp {
	int fd;                          /* inotify, -1 when not in use */
	struct {
		int wd;                  /* its directory's watch (pending: the parent's), -1 none */
		int pending;             /* the directory does not exist yet */
		char dir[HP_DIR_MAX];
		char prefix[HP_PREFIX_MAX];
	} node[HP_MAX_NODES];
	int nnodes;
	libusb_context *usb;             /* NULL when libusb is not in use */
	libusb_hotplug_callback_handle cb;
	int usb_failed;                  /* libusb was asked for and did not start */
	int inotify_failed;              /* inotify or a directory could not be watched */
	int seen;                        /* enum hp_what bits gathered by callbacks */
	struct hp_notice notice[HP_MAX_NOTICES];
	int nnotices;
	char sources[256];
};

static struct hp_notice *hp_note(struct hp *h, unsigned what)
{
	struct hp_notice *n;

	if (h->nnotices == HP_MAX_NOTICES)
		return NULL;
	n = &h->notice[h->nnotices++];
	memset(n, 0, sizeof(*n));
	n->what = what;
	n->time_ns = in_now_ns();
	return n;
}

/* libusb calls this from inside libusb_handle_events (hp_poll). */
static int LIBUSB_CALL hp_usb_cb(libusb_context *ctx, libusb_device *dev,
				 libusb_hotplug_event ev, void *user)
{
	struct hp *h = user;
	unsigned what = ev == LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED ? HP_USB_ARRIVED : HP_USB_LEFT;
	struct hp_notice *n = hp_note(h, what);

	(void)ctx;
	h->seen |= (int)what;
	if (n) {
		struct libusb_device_descriptor d;
		uint8_t ports[8];
		int np = libusb_get_port_numbers(dev, ports, (int)sizeof(ports));

		/* the descriptor is cached by libusb (read from sysfs): no I/O
		 * on the device, allowed in a callback */
		if (libusb_get_device_descriptor(dev, &d) == 0) {
			n->vid = d.idVendor;
			n->pid = d.idProduct;
		}
		in_say(n->name, sizeof(n->name), "%u", libusb_get_bus_number(dev));
		for (int i = 0; i < np; i++)
			in_say(n->name, sizeof(n->name), "%c%u", i ? '.' : '-', ports[i]);
	}
	return 0;  /* stay registered */
}

static void hp_open_usb(struct hp *h)
{
	int rc;

	if (!libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG)) {
		in_say(h->sources, sizeof(h->sources), "%slibusb: no hotplug support in this libusb", h->sources[0] ? "; " : "");
		h->usb_failed = 1;
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
		h->usb_failed = 1;
		return;
	}
	in_say(h->sources, sizeof(h->sources), "%slibusb hotplug", h->sources[0] ? "; " : "");
}

/* Watches the directory of node k; when it does not exist, its parent for
 * its creation. */
static void hp_add_watch(struct hp *h, int k)
{
	char *dir = h->node[k].dir, *slash = strrchr(dir, '/');

	h->node[k].wd = inotify_add_watch(h->fd, dir, HP_DIR_MASK);
	if (h->node[k].wd >= 0) {
		in_say(h->sources, sizeof(h->sources), " %s", dir);
		return;
	}
	if (errno == ENOENT && slash && slash != dir) {
		*slash = '\0';
		h->node[k].wd = inotify_add_watch(h->fd, dir, HP_PARENT_MASK);
		*slash = '/';
		if (h->node[k].wd >= 0) {
			h->node[k].pending = 1;
			in_say(h->sources, sizeof(h->sources), " (%s: not there yet)", dir);
			return;
		}
		errno = ENOENT;
	}
	h->inotify_failed = 1;
	in_say(h->sources, sizeof(h->sources), " (%s: %s)", dir, strerror(errno));
}

/* Keeps pattern nodes[i] (DIR/PREFIX) and watches DIR, once per directory.
 * 0, or -EINVAL for a pattern that is not DIR/PREFIX. */
static int hp_watch(struct hp *h, const char *const *nodes, int i, char *why, size_t whylen)
{
	const char *slash = strrchr(nodes[i], '/');
	int k = h->nnodes;

	if (!slash || slash == nodes[i] || !slash[1] || strlen(slash + 1) >= HP_PREFIX_MAX ||
	    (size_t)(slash - nodes[i]) >= HP_DIR_MAX) {
		snprintf(why, whylen, "%s: not a directory and a node name prefix", nodes[i]);
		return -EINVAL;
	}
	snprintf(h->node[k].dir, sizeof(h->node[k].dir), "%.*s", (int)(slash - nodes[i]), nodes[i]);
	snprintf(h->node[k].prefix, sizeof(h->node[k].prefix), "%s", slash + 1);
	h->node[k].wd = -1;
	h->nnodes++;
	for (int j = 0; j < k; j++)
		if (strcmp(h->node[j].dir, h->node[k].dir) == 0) {
			/* the same directory */
			h->node[k].wd = h->node[j].wd;
			h->node[k].pending = h->node[j].pending;
			return 0;
		}
	if (h->fd >= 0)
		hp_add_watch(h, k);
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
		if (h->fd < 0) {
			in_say(h->sources, sizeof(h->sources), "inotify: %s", strerror(errno));
			h->inotify_failed = 1;
		} else {
			in_say(h->sources, sizeof(h->sources), "inotify");
		}
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

/* A directory that was waited for appeared (name in the parent watched
 * by wd): watch it now. 1 when name was one. */
static int hp_arrived_dir(struct hp *h, int wd, const char *name)
{
	int found = 0;

	for (int k = 0; k < h->nnodes; k++) {
		const char *slash = strrchr(h->node[k].dir, '/');

		if (!h->node[k].pending || h->node[k].wd != wd || !slash || strcmp(slash + 1, name) != 0)
			continue;
		if (!found) {
			struct hp_notice *n = hp_note(h, HP_NODE);

			if (n) {
				snprintf(n->name, sizeof(n->name), "%.63s", h->node[k].dir);
				snprintf(n->how, sizeof(n->how), "created");
			}
			/* the parent's watch stays (other nodes may use it);
			 * the directory gets its own, shared by its patterns */
			h->node[k].wd = inotify_add_watch(h->fd, h->node[k].dir, HP_DIR_MASK);
			for (int j = k + 1; j < h->nnodes; j++)
				if (strcmp(h->node[j].dir, h->node[k].dir) == 0) {
					h->node[j].wd = h->node[k].wd;
					h->node[j].pending = 0;
				}
		}
		h->node[k].pending = 0;
		found = 1;
	}
	return found;
}

/* Whether name in the directory watched by wd is a node a pattern wants;
 * only those count: /dev sees ttys, ptys and others come and go, which
 * must not cost a rescan. */
static int hp_wanted(const struct hp *h, int wd, const char *name)
{
	for (int i = 0; i < h->nnodes; i++)
		if (!h->node[i].pending && h->node[i].wd == wd &&
		    strncmp(name, h->node[i].prefix, strlen(h->node[i].prefix)) == 0)
			return i;
	return -1;
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
			int k;

			off += (ssize_t)sizeof(*e) + e->len;
			if (e->mask & IN_Q_OVERFLOW) {
				what |= HP_NODE;   /* lost some: rescan anyway */
				continue;
			}
			if (!e->len)
				continue;
			if ((e->mask & (IN_CREATE | IN_MOVED_TO)) && (e->mask & IN_ISDIR) &&
			    hp_arrived_dir(h, e->wd, e->name)) {
				what |= HP_NODE;
				continue;
			}
			k = hp_wanted(h, e->wd, e->name);
			if (k >= 0) {
				struct hp_notice *nt = hp_note(h, HP_NODE);

				what |= HP_NODE;
				if (nt) {
					in_say(nt->name, sizeof(nt->name), "%s/%s", h->node[k].dir,
					       e->name);
					snprintf(nt->how, sizeof(nt->how), "%s",
						 e->mask & (IN_CREATE | IN_MOVED_TO) ? "created" :
						 e->mask & IN_ATTRIB ? "changed" : "removed");
				}
			}
		}
	}
	return what;
}

int hp_poll(struct hp *h)
{
	int what = 0;

	if (!h)
		return 0;
	h->nnotices = 0;
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

int hp_notices(const struct hp *h, const struct hp_notice **out)
{
	*out = h ? h->notice : NULL;
	return h ? h->nnotices : 0;
}

int hp_fd(const struct hp *h)
{
	return h ? h->fd : -1;
}

const char *hp_sources(const struct hp *h)
{
	return h ? h->sources : "";
}

int hp_complete(const struct hp *h)
{
	return h && !h->usb_failed && !h->inotify_failed;
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
