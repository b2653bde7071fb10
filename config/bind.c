/*
 * bind: the [keyboard] section of a bindings file maps each action to up to
 * BIND_MAX key names; [device "ID"] sections do the same for one device.
 * Read with cini (config/cini.h); every problem names file:line and the
 * action it concerns keeps what it had.
 */
#include "config/bind.h"

#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "config/cini.h"
#include "engine/core/num.h"
#include "input/in.h"
#include "input/txt.h"

/* Defaults: arrows and WASD (A/D strafe, arrows turn), the 1/5/9 start,
 * coin and service keys of MAME's defaults, F2 as a second service key, Z
 * (MAME's player 1 button 5) and Tab to change weapons. Player 2: MAME's
 * 2 start and player 2 keys (R F D G move and turn, A fires, S uses, Q
 * changes weapons), as a keyboard encoder types them; some are player 1's
 * WASD too, which is harmless: the command reads only the actions of the
 * player whose turn it is (app/cmd.h). */
static const struct {
	int act;
	const char *keys[BIND_MAX];
} bind_builtin[] = {
	{ ACT_FORWARD, { "KEY_UP", "KEY_W" } },
	{ ACT_BACK, { "KEY_DOWN", "KEY_S" } },
	{ ACT_TURN_LEFT, { "KEY_LEFT" } },
	{ ACT_TURN_RIGHT, { "KEY_RIGHT" } },
	{ ACT_STRAFE_LEFT, { "KEY_A", "KEY_COMMA" } },
	{ ACT_STRAFE_RIGHT, { "KEY_D", "KEY_DOT" } },
	{ ACT_FIRE, { "KEY_LEFTCTRL", "KEY_SPACE" } },
	{ ACT_USE, { "KEY_E" } },
	{ ACT_START, { "KEY_1", "KEY_ENTER" } },
	{ ACT_COIN, { "KEY_5" } },
	{ ACT_SERVICE, { "KEY_9", "KEY_F2" } },
	{ ACT_WEAPON, { "KEY_Z", "KEY_TAB" } },
	{ ACT_LOOK_UP, { "KEY_PAGEUP" } },
	{ ACT_LOOK_DOWN, { "KEY_PAGEDOWN" } },
	{ ACT_START2, { "KEY_2" } },
	{ ACT_P2_FORWARD, { "KEY_R" } },
	{ ACT_P2_BACK, { "KEY_F" } },
	{ ACT_P2_TURN_LEFT, { "KEY_D" } },
	{ ACT_P2_TURN_RIGHT, { "KEY_G" } },
	{ ACT_P2_FIRE, { "KEY_A" } },
	{ ACT_P2_USE, { "KEY_S" } },
	{ ACT_P2_WEAPON, { "KEY_Q" } },
};

void bind_defaults(struct bind_table *b)
{
	b->ndev = 0;
	memset(b->dev, 0, sizeof(b->dev));
	for (int a = 0; a < ACT_COUNT; a++)
		for (int i = 0; i < BIND_MAX; i++)
			b->key[a][i] = -1;
	for (size_t i = 0; i < sizeof(bind_builtin) / sizeof(bind_builtin[0]); i++) {
		for (int k = 0; k < BIND_MAX && bind_builtin[i].keys[k]; k++) {
			int code = in_key_from_name(bind_builtin[i].keys[k]);

			/* The names above are fixed kernel names; libevdev knows them. */
			b->key[bind_builtin[i].act][k] = code;
		}
	}
}

struct bind_ctx {
	struct bind_table *b;
	int (*cur)[BIND_MAX];            /* the section being read: [keyboard] or a device's */
	struct cini_errs err;
	bool section_ok;
};

/* "0x" or "0X" and 1 to 4 hex digits, BIND_CODE_MIN..BIND_CODE_MAX: a
 * code by number (for codes libevdev has no name for). The code, or -1. */
static int bind_numeric_key(const char *name)
{
	size_t n = strlen(name);
	int code = 0;

	if (n < 3 || n > 6 || name[0] != '0' || (name[1] != 'x' && name[1] != 'X'))
		return -1;
	for (size_t i = 2; i < n; i++) {
		int d = num_hex(name[i]);

		if (d < 0)
			return -1;
		code = code * 16 + d;
	}
	return code >= BIND_CODE_MIN && code <= BIND_CODE_MAX ? code : -1;
}

int bind_parse_keys(const char *value, int keys[BIND_MAX], char *why, size_t whylen)
{
	const char *p = value;
	int n = 0;

	for (int i = 0; i < BIND_MAX; i++)
		keys[i] = -1;
	while (*p) {
		const char *e = strchr(p, ',');
		const char *b = p;
		char name[64];
		size_t len;
		int code, dup = 0;

		if (!e)
			e = p + strlen(p);
		p = *e ? e + 1 : e;
		while (b < e && (*b == ' ' || *b == '\t'))
			b++;
		len = (size_t)(e - b);
		while (len && (b[len - 1] == ' ' || b[len - 1] == '\t'))
			len--;
		if (len == 0) {
			snprintf(why, whylen, "empty key name in list");
			return -EINVAL;
		}
		if (len >= sizeof(name)) {
			snprintf(why, whylen, "unknown key name '%.*s...'", 40, b);
			return -EINVAL;
		}
		memcpy(name, b, len);
		name[len] = '\0';
		code = bind_numeric_key(name);
		if (code < 0)
			code = in_key_from_name(name);
		if (code < 0) {
			snprintf(why, whylen, "unknown key name '%s'", name);
			return -EINVAL;
		}
		for (int i = 0; i < n; i++)
			dup |= keys[i] == code;
		if (dup)
			continue;
		if (n == BIND_MAX) {
			snprintf(why, whylen, "too many keys (at most %d)", BIND_MAX);
			return -EINVAL;
		}
		keys[n++] = code;
	}
	return 0;
}

void bind_set_entry(int key[ACT_COUNT][BIND_MAX], struct cini_errs *err, int line,
		    const char *action, const char *value)
{
	int keys[BIND_MAX];
	int a = act_from_name(action);
	char why[128];

	if (a < 0) {
		cini_report(err, line, "unknown action '%s'", action);
		return;
	}
	if (bind_parse_keys(value, keys, why, sizeof(why)) < 0) {
		cini_report(err, line, "%s: %s", action, why);
		return;
	}
	memcpy(key[a], keys, sizeof(keys));
}

static bool port_path(const char *p)
{
	size_t n = strspn(p, "0123456789");

	if (n == 0 || p[n] != '-')
		return false;
	p += n + 1;
	for (;;) {
		n = strspn(p, "0123456789");
		if (n == 0)
			return false;
		p += n;
		if (*p == '\0')
			return true;
		if (*p != '.')
			return false;
		p++;
	}
}

int bind_device_id(const char *id, char *out)
{
	size_t n = strlen(id);

	if (strncasecmp(id, "usb-", 4) == 0) {
		if (n >= BIND_ID_MAX || !port_path(id + 4))
			return -EINVAL;
		memcpy(out, "usb-", 4);
		memcpy(out + 4, id + 4, n - 3);
		return 0;
	}
	if (n != 9 || id[4] != ':')
		return -EINVAL;
	for (size_t i = 0; i < 9; i++) {
		char c = id[i];

		if (i == 4) {
			out[i] = ':';
			continue;
		}
		if (c >= 'A' && c <= 'F')
			c = (char)(c - 'A' + 'a');
		if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')))
			return -EINVAL;
		out[i] = c;
	}
	out[9] = '\0';
	return 0;
}

static struct bind_dev *find_id(struct bind_table *b, const char *id)
{
	for (int i = 0; i < b->ndev; i++)
		if (strcmp(b->dev[i].id, id) == 0)
			return &b->dev[i];
	return NULL;
}

/* The section for normalised id, created with every action unbound. */
static struct bind_dev *device_section(struct bind_table *b, const char *id)
{
	struct bind_dev *d = find_id(b, id);

	if (d)
		return d;
	if (b->ndev == BIND_DEVICES)
		return NULL;
	d = &b->dev[b->ndev++];
	snprintf(d->id, sizeof(d->id), "%s", id);
	for (int a = 0; a < ACT_COUNT; a++)
		for (int i = 0; i < BIND_MAX; i++)
			d->key[a][i] = -1;
	return d;
}

int bind_set_device(struct bind_table *b, const char *id, const int key[ACT_COUNT][BIND_MAX])
{
	char norm[BIND_ID_MAX];
	struct bind_dev *d;

	if (bind_device_id(id, norm) < 0)
		return -EINVAL;
	d = device_section(b, norm);
	if (!d)
		return -ENOSPC;
	memcpy(d->key, key, sizeof(d->key));
	return 0;
}

/* "device ID" or "device \"ID\"" (cini has trimmed the ends). */
static void device_header(struct bind_ctx *x, int line, const char *section)
{
	char id[CINI_NAME_MAX], norm[BIND_ID_MAX];
	const char *p = section + 6;
	size_t n;
	struct bind_dev *d;

	x->section_ok = false;
	p += strspn(p, " \t");
	n = strlen(p);
	if (n >= 2 && p[0] == '"' && p[n - 1] == '"') {
		p++;
		n -= 2;
	}
	memcpy(id, p, n);
	id[n] = '\0';
	if (bind_device_id(id, norm) < 0) {
		cini_report(&x->err, line, "bad device id '%s' (usb-PORT or VVVV:PPPP)", id);
		return;
	}
	d = device_section(x->b, norm);
	if (!d) {
		cini_report(&x->err, line, "too many device sections (at most %d)", BIND_DEVICES);
		return;
	}
	x->cur = d->key;
	x->section_ok = true;
}

static void bind_ev(void *user, const struct cini_ev *ev)
{
	struct bind_ctx *x = user;

	switch (ev->kind) {
	case CINI_ERROR:
		cini_report(&x->err, ev->line, "%s", ev->msg);
		break;
	case CINI_SECTION:
		x->section_ok = strcmp(ev->section, "keyboard") == 0;
		x->cur = x->b->key;
		if (strncmp(ev->section, "device", 6) == 0 &&
		    (ev->section[6] == ' ' || ev->section[6] == '\t'))
			device_header(x, ev->line, ev->section);
		else if (!x->section_ok)
			cini_report(&x->err, ev->line,
				    "unknown section [%s] (only [keyboard] and [device \"ID\"])",
				    ev->section);
		break;
	case CINI_ENTRY:
		if (ev->section[0] == '\0')
			cini_report(&x->err, ev->line, "key '%s' is outside [keyboard]", ev->key);
		else if (x->section_ok)
			bind_set_entry(x->cur, &x->err, ev->line, ev->key, ev->value);
		break;
	}
}

int bind_load_text(struct bind_table *b, const char *text, size_t len, const char *name,
		   cfg_err_fn fn, void *user)
{
	struct bind_ctx x = { .b = b, .cur = b->key,
			      .err = { .file = name, .fn = fn, .user = user } };

	cini_parse(text, len, bind_ev, &x);
	return x.err.count;
}

static int bind_load_any(void *b, const char *text, size_t len, const char *name, cfg_err_fn fn,
			 void *user)
{
	return bind_load_text(b, text, len, name, fn, user);
}

int bind_load(struct bind_table *b, const char *path, cfg_err_fn fn, void *user)
{
	return cini_load_file(path, bind_load_any, b, fn, user);
}

/* Up to max actions bound to code in one section's table. */
static int bind_lookup_in(const int key[ACT_COUNT][BIND_MAX], int code, int *acts, int max)
{
	int n = 0;

	if (code < 0)
		return 0;
	for (int a = 0; a < ACT_COUNT && n < max; a++) {
		for (int i = 0; i < BIND_MAX; i++) {
			if (key[a][i] == code) {
				acts[n++] = a;
				break;
			}
		}
	}
	return n;
}

int bind_lookup(const struct bind_table *b, int code, int *acts, int max)
{
	return bind_lookup_in(b->key, code, acts, max);
}

const struct bind_dev *bind_find_device(const struct bind_table *b, const struct in_ident *id)
{
	char want[BIND_ID_MAX];

	if (!id)
		return NULL;
	if (id->port[0] && snprintf(want, sizeof(want), "usb-%s", id->port) < (int)sizeof(want)) {
		for (int i = 0; i < b->ndev; i++)
			if (strcmp(b->dev[i].id, want) == 0)
				return &b->dev[i];
	}
	if (id->vid || id->pid) {
		snprintf(want, sizeof(want), "%04x:%04x", id->vid, id->pid);
		for (int i = 0; i < b->ndev; i++)
			if (strcmp(b->dev[i].id, want) == 0)
				return &b->dev[i];
	}
	return NULL;
}

int bind_lookup_dev(const struct bind_table *b, const struct in_ident *id, int code, int *acts,
		    int max)
{
	const struct bind_dev *d = bind_find_device(b, id);

	return bind_lookup_in(d ? d->key : b->key, code, acts, max);
}

static void bind_put_section(struct txt *o, const int key[ACT_COUNT][BIND_MAX])
{
	for (int a = 0; a < ACT_COUNT; a++) {
		int first = 1;

		txt_put(o, "%s =", act_name(a));
		for (int i = 0; i < BIND_MAX; i++) {
			int code = key[a][i];
			const char *name = in_key_name(code);

			if (code < BIND_CODE_MIN || code > BIND_CODE_MAX)
				continue;
			if (name)
				txt_put(o, "%s %s", first ? "" : ",", name);
			else
				txt_put(o, "%s 0x%04x", first ? "" : ",", (unsigned)code);
			first = 0;
		}
		txt_put(o, "\n");
	}
}

size_t bind_format(const struct bind_table *b, char *buf, size_t len)
{
	struct txt o = { .buf = buf, .len = len };

	if (buf && len)
		buf[0] = '\0';
	txt_put(&o, "# arcaded key bindings: every action of [keyboard] and of each device\n");
	txt_put(&o, "[keyboard]\n");
	bind_put_section(&o, b->key);
	for (int d = 0; d < b->ndev; d++) {
		txt_put(&o, "\n[device \"%s\"]\n", b->dev[d].id);
		bind_put_section(&o, b->dev[d].key);
	}
	return o.n;
}
