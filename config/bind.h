/*
 * bind: which controls trigger which actions.
 *
 * File format (INI, read by config/cini.c):
 *   [keyboard]
 *   forward = up, w          # key names as in_key_from_name accepts,
 *   coin = 0x2c0             # or codes by number (see BIND_CODE_MIN)
 *   fire = leftctrl, space
 *   use =                    # empty: the action has no key
 *   [device "usb-1-1.2"]     # one device, by USB port path
 *   fire = BTN_TRIGGER_HAPPY1
 *   [device "0079:0006"]     # every device with this VID:PID (hex)
 *   start = BTN_TRIGGER_HAPPY10
 * An action may name up to BIND_MAX keys; a line replaces that action's
 * whole list. A bad key name or action, too many keys, another section or
 * a malformed line gives file:line and a reason through the callback, and
 * the action concerned keeps the binding it had. One key may trigger
 * several actions.
 *
 * Device sections: a device with a section of its own uses that section's
 * bindings and not [keyboard]'s; its port path section wins over its
 * VID:PID section (two identical encoders on two ports keep their own
 * bindings, whichever enumerates first). A device section starts with
 * every action unbound the first time it appears; later lines and files
 * change it action by action like [keyboard]. Devices without a section
 * (and every device when the app calls plain bind_lookup) use [keyboard].
 * Ids are "usb-" and a USB port path (bus-port[.port...], as sysfs names
 * it and `arcaded devices` prints it) or VID:PID as 4 hex digits each;
 * the quotes are optional. At most BIND_DEVICES device sections.
 */
#ifndef ARCADED_CONFIG_BIND_H
#define ARCADED_CONFIG_BIND_H

#include "config/cfg.h"
#include "input/act.h"
#include "input/in.h"

struct cini_errs;

#define BIND_MAX 4
#define BIND_DEVICES 16
#define BIND_ID_MAX 40

struct bind_dev {
	char id[BIND_ID_MAX];            /* "usb-1-1.2" or "0079:0006" (lower-case hex) */
	int key[ACT_COUNT][BIND_MAX];
};

struct bind_table {
	int key[ACT_COUNT][BIND_MAX];    /* [keyboard]: key codes, -1 for unused slots */
	int ndev;
	struct bind_dev dev[BIND_DEVICES];
};

/* Codes a bindings file can name: the kernel's key codes, KEY_RESERVED
 * (0) and KEY_MAX (0x2ff) excluded as in_key_name excludes them. Key
 * names (in_key_name) cover most; any code of this range may also be
 * written as "0x" and 1..4 hex digits ("0x2c0", "0x02e8"), which is how
 * bind_format writes the codes libevdev has no name for. */
#define BIND_CODE_MIN 1
#define BIND_CODE_MAX 0x2fe

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

/* Stores in acts up to max actions bound to key code in [keyboard];
 * returns how many. */
int bind_lookup(const struct bind_table *b, int code, int *acts, int max);

/* The section for device id (its port path first, then its VID:PID), or
 * NULL when it has none (it uses [keyboard]). id may be NULL. */
const struct bind_dev *bind_find_device(const struct bind_table *b, const struct in_ident *id);

/* bind_lookup for a control of device id: its own section's bindings if it
 * has one, else [keyboard]'s. */
int bind_lookup_dev(const struct bind_table *b, const struct in_ident *id, int code, int *acts,
		    int max);

/* Parses a list of key names ("up, w"; empty: none) into keys (BIND_MAX
 * slots, -1 filled; a name given twice counts once). A name is one
 * in_key_from_name knows or a code by number ("0x2c0", BIND_CODE_MIN..
 * BIND_CODE_MAX). 0, or -EINVAL with the reason in why ("unknown key
 * name 'x'", "empty key name in list", "too many keys (at most 4)"). */
int bind_parse_keys(const char *value, int keys[BIND_MAX], char *why, size_t whylen);

/* One "action = name, name, ..." entry into key (an empty value unbinds
 * the action), for bindings files and profiles alike: an unknown action or
 * a bad list is counted and reported through err at line (config/cini.h)
 * and leaves key as it was. */
void bind_set_entry(int key[ACT_COUNT][BIND_MAX], struct cini_errs *err, int line,
		    const char *action, const char *value);

/* Writes b as bindings text that bind_load_text reads back to the same
 * table: a comment line, [keyboard], then [device "ID"] for every device
 * section in table order; every action of every section on its own line
 * ("fire = KEY_LEFTCTRL, KEY_SPACE", "use =" for none), so loading the
 * text replaces each section whole whatever it is loaded over. Keys by
 * in_key_name, codes without a name as "0x" and 4 hex digits; slots
 * holding -1 (or any code outside BIND_CODE_MIN..BIND_CODE_MAX, which no
 * file can name) are left out. "The same table" means: each list in
 * order, its free slots last and no code twice, as bind_load_text makes
 * lists. Like snprintf: writes at most len bytes including a terminating
 * NUL (buf may be NULL when len is 0) and returns the length of the whole
 * text, so a return >= len means it was cut. */
size_t bind_format(const struct bind_table *b, char *buf, size_t len);

/* Normalises a device section id ("USB-1-1.2", "0079:0006") into out
 * (BIND_ID_MAX bytes). 0, or -EINVAL when it is neither form. */
int bind_device_id(const char *id, char *out);

/* Sets device section id (normalised as above) to key, replacing the
 * whole section. 0, -EINVAL (bad id) or -ENOSPC (BIND_DEVICES sections). */
int bind_set_device(struct bind_table *b, const char *id, const int key[ACT_COUNT][BIND_MAX]);

#endif
