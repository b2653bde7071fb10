/*
 * prof: autoconfiguration profiles, default bindings for known encoders
 * and pads (the .ini files of config/profiles/), so a known device works
 * without a bindings file.
 *
 * Profile file (INI, read by config/cini.c):
 *   [profile]
 *   name = DragonRise Zero Delay encoder     # shown in logs and `arcaded devices`
 *   match = 0079:0006, 0079:0011            # VID:PID list (hex); VVVV:* any product;
 *                                           # "any": every device of the backend
 *   match_name = *Generic*Joystick*         # glob over the device's name (no case)
 *   backend = hid                           # hid | evdev | any (default any)
 *   hid = split=none, deadzone=200          # HID decoder options (input/in_hid.h terms)
 *   [bindings]
 *   fire = BTN_TRIGGER_HAPPY1               # as [keyboard] in bindings files
 * A profile needs a match or a match_name. In [bindings], actions not
 * listed are unbound.
 *
 * Matching (prof_match): among the profiles of the device's backend (or
 * backend any), the one that matches best: VID:PID and name glob (best),
 * then VID:PID alone (a profile with a match_name must match it), then
 * name glob alone, then "any"; on a tie the profile loaded first. Files
 * are loaded in byte order of their names; load a directory that should
 * win on ties (the cabinet's /etc) first.
 *
 * Errors name file:line, like the bindings: an unknown key, a bad VID:PID,
 * a bad action or key name (that action stays unbound), another section.
 * A profile left without any match is dropped with a message at line 0.
 */
#ifndef ARCADED_CONFIG_PROF_H
#define ARCADED_CONFIG_PROF_H

#include <stddef.h>
#include <stdint.h>

#include "config/bind.h"
#include "config/cfg.h"
#include "input/in.h"

#define PROF_MAX 64
#define PROF_IDS 8

struct prof {
	char file[64];               /* base name of its file */
	char name[64];
	int nids;
	uint16_t vid[PROF_IDS];
	int32_t pid[PROF_IDS];       /* -1: any product of that vendor */
	int any;                     /* match = any */
	char name_glob[64];          /* "": none */
	char backend[8];             /* "hid", "evdev", or "" for any */
	char hid[128];               /* HID decoder options, "" none */
	int key[ACT_COUNT][BIND_MAX];
};

struct prof_set {
	int n;
	struct prof p[PROF_MAX];
};

void prof_init(struct prof_set *s);

/* Adds the profile in text (len bytes) named name (its base name is the
 * profile's file) to s. Returns the number of problems reported through
 * fn (may be NULL); a profile without a match, or one beyond PROF_MAX, is
 * not added. */
int prof_load_text(struct prof_set *s, const char *text, size_t len, const char *name,
		   cfg_err_fn fn, void *user);

/* Adds every *.ini file of dir, in byte order of the names. Returns the
 * number of problems, or -errno when dir cannot be read (-ENOENT is not
 * reported through fn). */
int prof_load_dir(struct prof_set *s, const char *dir, cfg_err_fn fn, void *user);

/* The best profile for device id (rules above) opened by backend ("hid",
 * "evdev", ...), or NULL. */
const struct prof *prof_match(const struct prof_set *s, const char *backend,
			      const struct in_ident *id);

/* Gives device id the bindings of p unless b already has a section for it
 * (the user's bindings win): a section named by its VID:PID, or by its
 * port when it has no VID:PID. 1 when added, 0 when the device already had
 * one, -EINVAL (no identity) or -ENOSPC (no section left). */
int prof_bind(const struct prof *p, struct bind_table *b, const struct in_ident *id);

#endif
