/*
 * slot: the input slots and the registry of input backends (contract in
 * slot.h).
 */
#include "app/slot.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "app/say.h"
#include "display/dp.h"
#include "input/hp.h"

/* input.hid = auto opens this many pads: a 4-player cabinet. */
#define SLOT_HID_AUTO 4
/* input.evdev = auto opens this many devices with bound keys: keyboard
 * encoders, a PS/2 port's keyboard, a service keyboard. */
#define SLOT_EVDEV_AUTO 4

int slot_kinds(const struct cfg *c, struct slot_kind *out)
{
	/* Open order: the keyboard first, then the terminal's keys, pads,
	 * GPIO lines. */
	const struct slot_kind k[] = {
		{ &in_evdev, c ? c->input.evdev : NULL, SLOT_EVDEV_AUTO, 1 },
		{ &in_tty, NULL, 0, 1 },
		{ &in_hid, c ? c->input.hid : NULL, SLOT_HID_AUTO, 0 },
		{ &in_gpio, c ? c->input.gpio : NULL, 0, 0 },
	};
	_Static_assert(sizeof(k) / sizeof(k[0]) <= SLOT_KINDS, "SLOT_KINDS too small");

	memcpy(out, k, sizeof(k));
	return (int)(sizeof(k) / sizeof(k[0]));
}

void slot_init(struct slot_set *set, const struct slot_hooks *h, void *ctx)
{
	memset(set, 0, sizeof(*set));
	set->h = h;
	set->ctx = ctx;
	set->now = in_now_ns;
}

/* The device of s just opened: who it is, then the hook. */
static void slot_opened(struct slot_set *set, struct slot *s)
{
	memset(&s->id, 0, sizeof(s->id));
	if (s->be->ident)
		s->be->ident(s->dev, &s->id);
	set->h->opened(set->ctx, s);
}

int slot_add(struct slot_set *set, const struct slot_kind *kinds, int kind, const char *path,
	     int quiet)
{
	const struct in_backend *be = kinds[kind].be;
	char why[512] = "";
	struct slot *s;
	int rc;

	if (set->n >= SLOT_MAX)
		return -ENOSPC;
	s = &set->s[set->n++];
	memset(s, 0, sizeof(*s));
	s->be = be;
	s->kind = kind;
	if (path) {
		/* the slot keeps its own copy: it is reopened by it */
		snprintf(s->spec, sizeof(s->spec), "%s", path);
		path = s->path = s->spec;
	}
	rc = be->open(path, &s->dev, why, sizeof(why));
	if (rc < 0) {
		/* Not there yet (an encoder plugged in after boot, a named
		 * device that is unplugged): keep the slot and retry once a
		 * second. */
		if (!quiet)
			say_warn("input %s: %s; retrying as devices appear, and every second", be->name,
			    why[0] ? why : strerror(-rc));
		s->dev = NULL;
		s->retry_ns = set->now() + SLOT_REOPEN_NS;
		return 0;
	}
	say("input %s: %s", be->name, be->describe(s->dev));
	slot_opened(set, s);
	return 0;
}

/* One slot per device of a blank-separated list. */
static void slot_add_list(struct slot_set *set, const struct slot_kind *kinds, int kind,
			  const char *list)
{
	char buf[CFG_PATH_MAX], *save = NULL;

	snprintf(buf, sizeof(buf), "%s", list);
	for (char *tok = strtok_r(buf, " \t", &save); tok; tok = strtok_r(NULL, " \t", &save)) {
		if (set->n >= SLOT_MAX) {
			say_warn("input %s: more than %d devices; %s ignored", kinds[kind].be->name, SLOT_MAX,
			    tok);
			return;
		}
		slot_add(set, kinds, kind, tok, 0);
	}
}

/* Hotplug notices from where the slots' backends have their nodes. */
static void slot_watch(struct slot_set *set, const struct slot_kind *kinds, int n)
{
	const char *nodes[HP_MAX_NODES];
	char why[256];
	int nn = 0;

	for (int k = 0; k < n && nn < HP_MAX_NODES; k++)
		for (int i = 0; i < set->n; i++)
			if (set->s[i].kind == k && kinds[k].be->node) {
				nodes[nn++] = kinds[k].be->node;
				break;
			}
	if (hp_open(nodes, nn, HP_INOTIFY | HP_LIBUSB, &set->hp, why, sizeof(why)) < 0)
		say_warn("input hotplug: %s; devices are looked for every second", why);
	else if (!hp_complete(set->hp))
		say_warn("input hotplug: %s", hp_sources(set->hp));
	else
		say("input hotplug: %s", hp_sources(set->hp));
}

/* in_backend.set_bound's function: the hook, with the set's context. */
static int slot_bound(void *u, const struct in_ident *id, int code)
{
	const struct slot_set *set = u;

	return set->h->bound(set->ctx, id, code);
}

void slot_open(struct slot_set *set, const struct slot_kind *kinds, int n,
	       const struct dp_backend *display)
{
	const char *keys = display ? display->input : NULL;

	set->kinds = kinds;
	set->nkinds = n;
	for (int k = 0; k < n; k++)
		if (kinds[k].be->set_bound)
			kinds[k].be->set_bound(set->h->bound ? slot_bound : NULL, set);

	for (int k = 0; k < n; k++) {
		const struct slot_kind *kd = &kinds[k];
		const char *v = kd->devices;

		if (!v) {
			/* a display that reads the keys typed at it */
			if (keys && strcmp(keys, kd->be->name) == 0)
				slot_add(set, kinds, k, NULL, 0);
		} else if (strcmp(v, "none") == 0) {
			continue;
		} else if (kd->autos && strcmp(v, "auto") == 0) {
			/* Where the display reads the keyboard, taking it would
			 * take the developer's own keyboard away from every
			 * other window: only a device the configuration names
			 * is opened. Several auto slots (keyboards, pads) each
			 * take a device no other slot has; only the first says
			 * when it found none, the others are retried quietly:
			 * their devices may be plugged in later. */
			if (keys && (kd->be->flags & IN_AUTO_TAKES_KEYBOARD))
				say_warn("input %s: not auto-detected while the display (%s) reads the "
				    "keyboard (set input.%s)", kd->be->name, display->name, kd->be->name);
			else
				for (int i = 0; i < kd->autos; i++)
					slot_add(set, kinds, k, NULL, i > 0);
		} else if (kd->whole) {
			slot_add(set, kinds, k, v, 0);
		} else {
			slot_add_list(set, kinds, k, v);
		}
	}
	if (set->n == 0) {
		say_warn("no input device configured: the game runs, but nothing controls it");
		return;
	}
	slot_watch(set, kinds, n);
}

void slot_drop(struct slot_set *set, struct slot *s)
{
	for (int code = 0; code < SLOT_KEYS; code++)
		if (s->down[code / 8] & (1u << (code % 8)))
			set->h->released(set->ctx, s, code);
	memset(s->down, 0, sizeof(s->down));
	set->h->gone(set->ctx, s);
	say_warn("input %s: %s went away; its controls are released", s->be->name,
	    s->be->describe(s->dev));
	s->be->close(s->dev);
	s->dev = NULL;
	s->retry_ns = set->now() + SLOT_REOPEN_NS;
}

static void slot_key(struct slot_set *set, struct slot *s, const struct in_event *e)
{
	int down = e->value != 0;
	uint8_t bit;

	if (e->code >= SLOT_KEYS)
		return;
	bit = (uint8_t)(1u << (e->code % 8));
	/* Ignore a press of a key already down (and a release of one that is
	 * up): repeats and resyncs must not count twice. */
	if (!!(s->down[e->code / 8] & bit) == down)
		return;
	if (down)
		s->down[e->code / 8] |= bit;
	else
		s->down[e->code / 8] &= (uint8_t)~bit;
	set->h->key(set->ctx, s, e->code, down, e->time_ns);
}

/* What the last hotplug poll saw, for the log: USB arrivals and
 * departures always (an operator's view of what was plugged), node
 * notices with log_nodes. */
static void slot_log_notices(const struct slot_set *set)
{
	const struct hp_notice *n;
	int k = hp_notices(set->hp, &n);

	for (int i = 0; i < k; i++) {
		if (n[i].what == HP_USB_ARRIVED)
			say("input hotplug: libusb: USB device %04x:%04x arrived on port %s", n[i].vid,
			    n[i].pid, n[i].name);
		else if (n[i].what == HP_USB_LEFT)
			say("input hotplug: libusb: USB device %04x:%04x left port %s", n[i].vid,
			    n[i].pid, n[i].name);
		else if (set->log_nodes)
			say("input hotplug: inotify: %s %s", n[i].name, n[i].how);
	}
}

void slot_read(struct slot_set *set)
{
	struct in_event ev[64];
	uint64_t now = 0;

	/* A device node appeared or changed (udev grants access right after
	 * the kernel creates it), a USB device arrived: every closed slot
	 * tries now. */
	if (hp_poll(set->hp)) {
		slot_log_notices(set);
		for (int i = 0; i < set->n; i++)
			set->s[i].retry_ns = 0;
	}

	for (int i = 0; i < set->n; i++) {
		struct slot *s = &set->s[i];
		if (!s->dev) {
			if (!now)
				now = set->now();
			if (now < s->retry_ns)
				continue;
			char why[256];
			if (s->be->open(s->path, &s->dev, why, sizeof(why)) < 0) {
				s->dev = NULL;
				s->retry_ns = now + SLOT_REOPEN_NS;
				continue;
			}
			say("input %s: attached %s", s->be->name, s->be->describe(s->dev));
			slot_opened(set, s);
		}
		for (;;) {
			int n = s->be->read(s->dev, ev, (int)(sizeof(ev) / sizeof(ev[0])));
			if (n == -ENODEV) {
				slot_drop(set, s);
				break;
			}
			if (n <= 0)
				break;
			for (int k = 0; k < n; k++)
				if (ev[k].type == IN_KEY)
					slot_key(set, s, &ev[k]);
			if (n < (int)(sizeof(ev) / sizeof(ev[0])))
				break;
		}
	}
}

void slot_close(struct slot_set *set)
{
	hp_close(set->hp);
	set->hp = NULL;
	for (int i = 0; i < set->n; i++)
		if (set->s[i].dev)
			set->s[i].be->close(set->s[i].dev);
	set->n = 0;
	/* the backends keep no pointer to the set past its life */
	for (int k = 0; k < set->nkinds; k++)
		if (set->kinds[k].be->set_bound)
			set->kinds[k].be->set_bound(NULL, NULL);
	set->kinds = NULL;
	set->nkinds = 0;
}
