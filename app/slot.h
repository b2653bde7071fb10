/*
 * slot: the input slots. A slot is one device the configuration asks for
 * (a path, a spec, or "auto"), of one input backend, reached only through
 * the backend's table (input/in.h). A slot whose device is missing or went
 * away stays, closed, and retries its open every SLOT_REOPEN_NS, or at
 * once on a hotplug notice (input/hp.h) from the directories where the
 * slots' backends have their nodes (in_backend.node).
 *
 * Each slot keeps which controls are down, so repeats and resyncs do not
 * count twice, and so a device that goes away (read or outputs -ENODEV)
 * has every control it held released before it is closed: nothing stays
 * pressed. What a control does is not the slot's business: the hooks get
 * the changes (app/ctl.c binds them to actions).
 *
 * The registry (slot_kinds) is the one list of the input backends that
 * exist, with the setting that names each one's devices. It is the only
 * place in app/ that names a backend.
 */
#ifndef ARCADED_APP_SLOT_H
#define ARCADED_APP_SLOT_H

#include <stdint.h>

#include "config/cfg.h"
#include "input/in.h"

#define SLOT_MAX 16                /* slots in all */
#define SLOT_KINDS 8               /* backends in the registry, at most */
#define SLOT_KEYS 1024             /* key codes tracked per device (KEY_CNT is 768) */
#define SLOT_REOPEN_NS 1000000000ull

struct dp_backend;
struct hp;

/* One input backend of the registry and what names its devices. */
struct slot_kind {
	const struct in_backend *be;
	/* The setting (input.<name>): "none", "auto" (with autos), or its
	 * devices; NULL: it has none, and opens only with a display whose
	 * keys it reads (dp_backend.input). */
	const char *devices;
	int autos;                 /* slots "auto" opens; 0: "auto" is not special */
	int whole;                 /* devices is one device, not a blank-separated list */
};

struct slot {
	const struct in_backend *be;
	int kind;                  /* its registry entry (statistics by source) */
	struct in_dev *dev;        /* NULL: closed, retried at retry_ns */
	const char *path;          /* what to (re)open; NULL: auto-detect */
	char spec[CFG_PATH_MAX];   /* the path's storage */
	struct in_ident id;        /* who the open device is (per-device bindings) */
	uint64_t retry_ns;
	uint8_t down[SLOT_KEYS / 8];
};

/* What the slots tell their user (ctx is slot_init's). */
struct slot_hooks {
	/* s opened (at the start or again); s->id says who it is. */
	void (*opened)(void *ctx, struct slot *s);
	/* Control code of s went down (1) or up (0) at time_ns (the kernel's
	 * stamp where the backend has one). */
	void (*key)(void *ctx, struct slot *s, int code, int down, uint64_t time_ns);
	/* s went away while code was down: release it. */
	void (*released)(void *ctx, struct slot *s, int code);
	/* s went away; its controls are released, it closes next. */
	void (*gone)(void *ctx, struct slot *s);
	/* Whether control code of the device id is bound (does something):
	 * what auto-detection looks for (in_backend.set_bound). NULL: every
	 * code counts. */
	int (*bound)(void *ctx, const struct in_ident *id, int code);
};

struct slot_set {
	struct slot s[SLOT_MAX];
	int n;
	struct hp *hp;             /* hotplug notices, NULL: periodic retries only */
	const struct slot_kind *kinds;   /* slot_open's registry, NULL before */
	int nkinds;
	int log_nodes;             /* log every device node notice too (input.log) */
	const struct slot_hooks *h;
	void *ctx;
	uint64_t (*now)(void);     /* the clock of retries: in_now_ns */
};

/* The registry: fills out[0..SLOT_KINDS) with every input backend, in the
 * order their slots open (and their latency is summarised), with c's
 * settings (c NULL: none). Returns how many. */
int slot_kinds(const struct cfg *c, struct slot_kind *out);

/* An empty set whose changes go to h with ctx. */
void slot_init(struct slot_set *set, const struct slot_hooks *h, void *ctx);

/* Opens the slots that kinds[0..n) name: per kind its devices setting
 * ("none": no slot; "auto": autos slots, retried quietly when more than
 * one; otherwise one slot per device), and the kind whose backend reads
 * the keys of display (dp_backend.input; display may be NULL). First
 * every backend that auto-detects by the bindings (in_backend.set_bound)
 * is told the bound hook. Then starts the hotplug notices of the slots'
 * backends. Everything is logged; a device that does not open keeps its
 * slot. kinds must stay valid until slot_close. */
void slot_open(struct slot_set *set, const struct slot_kind *kinds, int n,
	       const struct dp_backend *display);

/* Adds a slot of kind (kinds[kind]) for path (NULL: auto-detect; copied)
 * and opens it: -ENOSPC when the set is full, else 0 (also when the
 * device did not open: the slot retries). quiet: a failed open is not
 * logged. */
int slot_add(struct slot_set *set, const struct slot_kind *kinds, int kind, const char *path,
	     int quiet);

/* Once per tick, before the command is built: closed slots whose time
 * has come (all of them after a hotplug notice) retry their open, and
 * every open device is read, its key changes going to the hooks. USB
 * devices arriving and leaving (libusb) are logged, and with log_nodes
 * every device node notice. */
void slot_read(struct slot_set *set);

/* s's device went away: releases every control it held (hooks), closes
 * it, and schedules its reopen. */
void slot_drop(struct slot_set *set, struct slot *s);

/* Closes every device and the hotplug notices. */
void slot_close(struct slot_set *set);

#endif
