/*
 * bind: which controls trigger which actions.
 *
 * File format (INI, read by config/cini.c):
 *   [keyboard]
 *   forward = up, w          # key names as in_key_from_name accepts
 *   fire = leftctrl, space
 *   use =                    # empty: the action has no key
 * An action may name up to BIND_MAX keys; a line replaces that action's
 * whole list. A bad key name or action, too many keys, another section or
 * a malformed line gives file:line and a reason through the callback, and
 * the action concerned keeps the binding it had. One key may trigger
 * several actions.
 */
#ifndef ARCADED_CONFIG_BIND_H
#define ARCADED_CONFIG_BIND_H

#include "config/cfg.h"
#include "input/act.h"

#define BIND_MAX 4

struct bind_table {
	int key[ACT_COUNT][BIND_MAX];    /* key codes, -1 for unused slots */
};

/* Built-in defaults: forward up/w, back down/s, turn left/right arrows,
 * strafe a/comma and d/dot, fire leftctrl/space, use e, start 1/enter,
 * coin 5, service 9/F2 (1/5/9 as in MAME). */
void bind_defaults(struct bind_table *b);

/* Applies bindings text (len bytes, need not be NUL-terminated) named name
 * in messages on top of b. Returns the number of problems reported through
 * fn (which may be NULL). */
int bind_load_text(struct bind_table *b, const char *text, size_t len, const char *name,
		   cfg_err_fn fn, void *user);

/* Applies a bindings file on top of b. Returns the number of problems
 * reported (>= 0) or -errno when the file cannot be read (-ENOENT is not
 * reported through fn, other errors are, with line 0). */
int bind_load(struct bind_table *b, const char *path, cfg_err_fn fn, void *user);

/* Stores in acts up to max actions bound to key code; returns how many. */
int bind_lookup(const struct bind_table *b, int code, int *acts, int max);

#endif
