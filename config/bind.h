/*
 * bind: which controls trigger which actions.
 *
 * File format (INI, read with inih):
 *   [keyboard]
 *   forward = up, w          # key names as in_key_from_name accepts
 *   fire = leftctrl, space
 * An action may name up to BIND_MAX keys. A bad key name or action gives
 * file:line and a reason through the callback, and that action keeps its
 * default binding.
 */
#ifndef ARCADED_CONFIG_BIND_H
#define ARCADED_CONFIG_BIND_H

#include "config/cfg.h"
#include "input/act.h"

#define BIND_MAX 4

struct bind_table {
	int key[ACT_COUNT][BIND_MAX];    /* key codes, -1 for unused slots */
};

/* Built-in defaults: arrows and WASD move (A/D strafe... see bind.c),
 * ctrl/space fire, 1 start, 5 coin, 9/F2 service, e use. */
void bind_defaults(struct bind_table *b);

/* Applies a bindings file on top of b. Returns the number of rejected
 * entries (>= 0) or -errno when the file cannot be read. */
int bind_load(struct bind_table *b, const char *path, cfg_err_fn fn, void *user);

/* Stores in acts up to max actions bound to key code; returns how many. */
int bind_lookup(const struct bind_table *b, int code, int *acts, int max);

#endif
