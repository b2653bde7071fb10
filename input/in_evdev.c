/*
 * in_evdev: keys and axes from a Linux input device (/dev/input/eventN)
 * through libevdev (contract in in_evdev.h and in.h).
 *
 * Auto-detection (open with a NULL path) takes the first of
 * /dev/input/event0, event1, ... (numeric order) that opens, is not open
 * in this process already, and has a key or button the bindings use for
 * it (in_evdev_bound_keys); each auto slot so gets a device of its own.
 *
 * The device is grabbed (EVIOCGRAB) so its keys do not also reach the
 * console or another program; a failed grab is not fatal and shows in
 * describe. The kernel is asked to stamp events with CLOCK_MONOTONIC
 * (EVIOCSCLOCKID), the clock of in_now_ns; if it refuses, events are
 * stamped with in_now_ns at the read.
 */
#include "input/in_evdev.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <libevdev/libevdev.h>

#include "engine/core/num.h"

struct in_dev {
	struct libevdev *ev;
	int fd;
	dev_t rdev;              /* the node's device number: open in this process */
	int grab_err;            /* 0: grabbed; else the errno of the failed grab */
	int stamp_now;           /* the kernel keeps another clock: stamp at the read */
	int syncing;             /* draining the sync events after a SYN_DROPPED */
	struct in_ident id;      /* VID:PID, USB port, name: per-device bindings */
	char desc[320];
	struct in_dev *next;     /* evdev_open_devs */
};

/* What the bindings use (in_evdev.set_bound); NULL: every key counts. Set
 * from the main thread before the slots open. */
static int (*evdev_bound)(void *u, const struct in_ident *id, int code);
static void *evdev_bound_u;
/* The devices open in this process (taken over): auto-detection passes
 * over them, so two auto slots get two devices and never share one. Used
 * by the thread that opens and closes (the main loop's). */
static struct in_dev *evdev_open_devs;

static void evdev_set_bound(int (*fn)(void *u, const struct in_ident *id, int code), void *u)
{
	evdev_bound = fn;
	evdev_bound_u = u;
}

static int rdev_in_use(dev_t rdev)
{
	for (const struct in_dev *o = evdev_open_devs; o; o = o->next)
		if (o->rdev == rdev)
			return 1;
	return 0;
}

int in_evdev_bound_keys(const struct libevdev *ev, const struct in_ident *id, int *codes,
			int max)
{
	int n = 0;

	if (!libevdev_has_event_type(ev, EV_KEY))
		return 0;
	for (int c = 0; c <= KEY_MAX; c++) {
		if (!libevdev_has_event_code(ev, EV_KEY, (unsigned)c))
			continue;
		if (evdev_bound && !evdev_bound(evdev_bound_u, id, c))
			continue;
		if (codes && n < max)
			codes[n] = c;
		n++;
	}
	return n;
}

/* Opens path as an evdev device into a new d (not yet grabbed). On failure
 * returns -errno with "PATH: reason" appended to why. */
static int probe(const char *path, struct in_dev **out, char *why, size_t whylen)
{
	struct in_dev *d;
	int rc;

	d = calloc(1, sizeof(*d));
	if (!d) {
		in_say(why, whylen, "%s: out of memory", path);
		return -ENOMEM;
	}
	d->fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
	if (d->fd < 0) {
		rc = -errno;
		in_say(why, whylen, "%s: %s", path, strerror(-rc));
		goto fail;
	}
	{
		struct stat st;
		if (fstat(d->fd, &st) == 0)
			d->rdev = st.st_rdev;
	}
	rc = libevdev_new_from_fd(d->fd, &d->ev);
	if (rc < 0) {
		in_say(why, whylen, "%s: not an input event device (%s)", path, strerror(-rc));
		goto fail_fd;
	}
	*out = d;
	return 0;

fail_fd:
	close(d->fd);
fail:
	free(d);
	return rc;
}

static void evdev_close(struct in_dev *d)
{
	if (!d)
		return;
	for (struct in_dev **p = &evdev_open_devs; *p; p = &(*p)->next)
		if (*p == d) {
			*p = d->next;
			break;
		}
	if (d->ev) {
		if (d->grab_err == 0)
			libevdev_grab(d->ev, LIBEVDEV_UNGRAB);
		libevdev_free(d->ev);
	}
	close(d->fd);
	free(d);
}

/* Who the device is: its ids as the kernel reports them and, on USB, the
 * port it is plugged into (sysfs: class/input/eventN/device is the
 * inputN directory, under input/ of the HID device or USB interface). */
static void identify(struct in_dev *d, const char *path, const char *name)
{
	const char *base = strrchr(path, '/');
	char link[96];

	memset(&d->id, 0, sizeof(d->id));
	d->id.vid = (uint16_t)libevdev_get_id_vendor(d->ev);
	d->id.pid = (uint16_t)libevdev_get_id_product(d->ev);
	snprintf(d->id.name, sizeof(d->id.name), "%s", name ? name : "");
	base = base ? base + 1 : path;
	if (strncmp(base, "event", 5) == 0 &&
	    snprintf(link, sizeof(link), "/sys/class/input/%s/device", base) < (int)sizeof(link))
		in_usb_port(link, 2, d->id.port, sizeof(d->id.port));
}

static void evdev_ident(struct in_dev *d, struct in_ident *id)
{
	*id = d->id;
}

/* Grabs d (identified) and switches its clock; fills describe; counts it
 * as open in this process. */
static void take_over(struct in_dev *d, const char *path)
{
	const char *name = libevdev_get_name(d->ev);
	int rc;

	d->stamp_now = libevdev_set_clock_id(d->ev, CLOCK_MONOTONIC) != 0;
	rc = libevdev_grab(d->ev, LIBEVDEV_GRAB);
	d->grab_err = rc < 0 ? -rc : 0;
	snprintf(d->desc, sizeof(d->desc), "%s (%s)", name ? name : "unnamed", path);
	if (d->id.port[0])
		in_say(d->desc, sizeof(d->desc), ", %04x:%04x port %s", d->id.vid, d->id.pid,
		       d->id.port);
	if (d->grab_err)
		in_say(d->desc, sizeof(d->desc), ", not grabbed: %s", strerror(d->grab_err));
	if (d->stamp_now)
		in_say(d->desc, sizeof(d->desc), ", stamped at read");
	d->next = evdev_open_devs;
	evdev_open_devs = d;
}

static int cmp_uint(const void *a, const void *b)
{
	unsigned x = *(const unsigned *)a, y = *(const unsigned *)b;

	return (x > y) - (x < y);
}

/* Numbers N of the DIR/eventN entries, sorted; -errno on failure. */
static int list_events(const char *dir, unsigned **nums, size_t *count)
{
	DIR *dh;
	struct dirent *de;
	unsigned *v = NULL, *nv;
	size_t n = 0, cap = 0;

	dh = opendir(dir);
	if (!dh)
		return -errno;
	while ((de = readdir(dh)) != NULL) {
		const char *p = de->d_name;
		int64_t num;

		if (strncmp(p, "event", 5) != 0 || p[5] < '0' || p[5] > '9' ||
		    num_parse(p + 5, 0, 1000000, &num) < 0)
			continue;
		if (n == cap) {
			cap = cap ? cap * 2 : 16;
			nv = realloc(v, cap * sizeof(*v));
			if (!nv) {
				free(v);
				closedir(dh);
				return -ENOMEM;
			}
			v = nv;
		}
		v[n++] = (unsigned)num;
	}
	closedir(dh);
	if (n > 1)
		qsort(v, n, sizeof(*v), cmp_uint);
	*nums = v;
	*count = n;
	return 0;
}

int in_evdev_open_dir(const char *dir, struct in_dev **out, char *why, size_t whylen)
{
	unsigned *nums = NULL;
	size_t n = 0;
	char path[PATH_MAX];
	int rc;

	*out = NULL;
	if (whylen)
		why[0] = '\0';
	rc = list_events(dir, &nums, &n);
	if (rc < 0) {
		in_say(why, whylen, "%s: %s", dir, strerror(-rc));
		return rc == -ENOMEM ? rc : -ENODEV;
	}
	if (n == 0) {
		in_say(why, whylen, "no %s/event* devices", dir);
		free(nums);
		return -ENODEV;
	}
	in_say(why, whylen, "no device with a bound key among %s/event*: ", dir);
	for (size_t i = 0; i < n; i++) {
		struct in_dev *d;
		struct stat st;
		const char *name;

		snprintf(path, sizeof(path), "%s/event%u", dir, nums[i]);
		if (i > 0)
			in_say(why, whylen, "; ");
		if (stat(path, &st) == 0 && S_ISCHR(st.st_mode) && rdev_in_use(st.st_rdev)) {
			in_say(why, whylen, "%s: already open", path);
			continue;
		}
		if (probe(path, &d, why, whylen) < 0)
			continue;
		name = libevdev_get_name(d->ev);
		identify(d, path, name);
		if (in_evdev_bound_keys(d->ev, &d->id, NULL, 0) == 0) {
			in_say(why, whylen, "%s (%s): none of its keys is bound", path,
			       name ? name : "unnamed");
			evdev_close(d);
			continue;
		}
		take_over(d, path);
		free(nums);
		if (whylen)
			why[0] = '\0';
		*out = d;
		return 0;
	}
	free(nums);
	return -ENODEV;
}

int in_evdev_list(const char *dir, struct in_evdev_info **out, size_t *count)
{
	unsigned *nums = NULL;
	struct in_evdev_info *l;
	size_t n = 0;
	int rc;

	*out = NULL;
	*count = 0;
	rc = list_events(dir ? dir : "/dev/input", &nums, &n);
	if (rc < 0)
		return rc;
	l = calloc(n ? n : 1, sizeof(*l));
	if (!l) {
		free(nums);
		return -ENOMEM;
	}
	for (size_t i = 0; i < n; i++) {
		struct in_dev *d;
		char why[160] = "";

		snprintf(l[i].node, sizeof(l[i].node), "%s/event%u", dir ? dir : "/dev/input", nums[i]);
		if (probe(l[i].node, &d, why, sizeof(why)) < 0) {
			snprintf(l[i].why, sizeof(l[i].why), "%s", why);
			continue;
		}
		l[i].opened = 1;
		identify(d, l[i].node, libevdev_get_name(d->ev));
		l[i].id = d->id;
		l[i].nbound = in_evdev_bound_keys(d->ev, &d->id, l[i].bound,
						  (int)(sizeof(l[i].bound) / sizeof(l[i].bound[0])));
		evdev_close(d);   /* never grabbed */
	}
	free(nums);
	*out = l;
	*count = n;
	return 0;
}

static int evdev_open(const char *path, struct in_dev **out, char *why, size_t whylen)
{
	struct in_dev *d;
	int rc;

	if (!path)
		return in_evdev_open_dir("/dev/input", out, why, whylen);
	*out = NULL;
	if (whylen)
		why[0] = '\0';
	rc = probe(path, &d, why, whylen);
	if (rc < 0)
		return rc;
	identify(d, path, libevdev_get_name(d->ev));
	take_over(d, path);
	*out = d;
	return 0;
}

static int evdev_fd(struct in_dev *d)
{
	return d->fd;
}

static int evdev_read(struct in_dev *d, struct in_event *out, int max)
{
	struct input_event e;
	int n = 0, rc;

	while (n < max) {
		rc = libevdev_next_event(d->ev, d->syncing ? LIBEVDEV_READ_FLAG_SYNC
							     : LIBEVDEV_READ_FLAG_NORMAL, &e);
		if (rc == -EAGAIN) {
			if (!d->syncing)
				break;
			/* Sync done: back to the event stream. */
			d->syncing = 0;
			continue;
		}
		if (rc == -EINTR)
			break;
		if (rc < 0)
			return rc;   /* -ENODEV: unplugged */
		if (rc == LIBEVDEV_READ_STATUS_SYNC && !d->syncing) {
			/* This is the SYN_DROPPED itself: events were lost. The
			 * sync events that follow give the true state of every
			 * key and axis that changed meanwhile. */
			d->syncing = 1;
			continue;
		}
		if (e.type == EV_KEY) {
			/* 2 is autorepeat: the sim wants presses and releases. */
			if (e.value != 0 && e.value != 1)
				continue;
			out[n].type = IN_KEY;
		} else if (e.type == EV_ABS) {
			out[n].type = IN_ABS;
		} else {
			continue;
		}
		out[n].code = e.code;
		out[n].value = e.value;
		out[n].time_ns = d->stamp_now ? in_now_ns()
					      : (uint64_t)e.input_event_sec * 1000000000u +
						(uint64_t)e.input_event_usec * 1000u;
		n++;
	}
	return n;
}

static const char *evdev_describe(struct in_dev *d)
{
	return d->desc;
}

/* in_evdev.list: every event node, whether auto-detection takes it (the
 * bound keys it has), the bindings sections that name it and its
 * profile. */
static int evdev_list_out(FILE *out, const char *(*profile)(void *u, const struct in_ident *id),
			  void *u)
{
	struct in_evdev_info *ev = NULL;
	size_t n = 0;
	int rc = in_evdev_list(NULL, &ev, &n);

	fprintf(out, "evdev devices (/dev/input): %zu%s\n", n, rc < 0 ? " (listing failed)" : "");
	for (size_t i = 0; i < n; i++) {
		const struct in_ident *id = &ev[i].id;
		int shown = ev[i].nbound < 8 ? ev[i].nbound : 8;
		const char *p;

		if (!ev[i].opened) {
			fprintf(out, "  %s  not readable: %s\n", ev[i].node, ev[i].why);
			continue;
		}
		p = profile(u, id);
		fprintf(out, "  %s  %04x:%04x  \"%s\"  port %s\n    ", ev[i].node, id->vid, id->pid,
			id->name, id->port[0] ? id->port : "-");
		if (ev[i].nbound) {
			fprintf(out, "in use with input.evdev = auto: %d bound key(s):", ev[i].nbound);
			for (int k = 0; k < shown; k++) {
				const char *kn = in_key_name(ev[i].bound[k]);
				if (kn)
					fprintf(out, " %s", kn);
				else
					fprintf(out, " %d", ev[i].bound[k]);
			}
			fprintf(out, "%s\n", ev[i].nbound > shown ? " ..." : "");
		} else {
			fprintf(out, "not used by input.evdev = auto: none of its keys is bound\n");
		}
		fprintf(out, "    bindings section: ");
		if (id->port[0])
			fprintf(out, "[device \"usb-%s\"] or ", id->port);
		fprintf(out, "[device \"%04x:%04x\"], else [keyboard]; profile: %s\n", id->vid,
			id->pid, p ? p : "none");
	}
	free(ev);
	return rc;
}

const struct in_backend in_evdev = {
	.name = "evdev",
	.open = evdev_open,
	.fd = evdev_fd,
	.read = evdev_read,
	.close = evdev_close,
	.describe = evdev_describe,
	.ident = evdev_ident,
	.node = "/dev/input/event",
	.list = evdev_list_out,
	.set_bound = evdev_set_bound,
	.flags = IN_AUTO_TAKES_KEYBOARD,
};
