/*
 * bind: the [keyboard] section of a bindings file maps each action to up to
 * BIND_MAX key names. Read with cini (config/cini.h); every problem names
 * file:line and the action it concerns keeps what it had.
 */
#include "config/bind.h"

#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/cini.h"
#include "input/in.h"

/* Defaults: arrows and WASD (A/D strafe, arrows turn), the 1/5/9 start,
 * coin and service keys of MAME's defaults, F2 as a second service key. */
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
};

void bind_defaults(struct bind_table *b)
{
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
	const char *file;
	cfg_err_fn fn;
	void *user;
	int rejected;
	bool section_ok;
};

__attribute__((format(printf, 3, 4)))
static void bind_report(struct bind_ctx *x, int line, const char *fmt, ...)
{
	char msg[CINI_VALUE_MAX + 128];
	va_list ap;

	x->rejected++;
	if (!x->fn)
		return;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	x->fn(x->user, x->file, line, msg);
}

/* Parses "name, name, ..." into keys (BIND_MAX slots, -1 filled); a name
 * given twice counts once. An empty value unbinds the action. */
static void bind_entry(struct bind_ctx *x, int line, const char *action, const char *value)
{
	int keys[BIND_MAX], n = 0;
	int a = act_from_name(action);
	const char *p = value;

	if (a < 0) {
		bind_report(x, line, "unknown action '%s'", action);
		return;
	}
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
			bind_report(x, line, "%s: empty key name in list", action);
			return;
		}
		if (len >= sizeof(name)) {
			bind_report(x, line, "%s: unknown key name '%.*s...'", action, 40, b);
			return;
		}
		memcpy(name, b, len);
		name[len] = '\0';
		code = in_key_from_name(name);
		if (code < 0) {
			bind_report(x, line, "%s: unknown key name '%s'", action, name);
			return;
		}
		for (int i = 0; i < n; i++)
			dup |= keys[i] == code;
		if (dup)
			continue;
		if (n == BIND_MAX) {
			bind_report(x, line, "%s: too many keys (at most %d)", action, BIND_MAX);
			return;
		}
		keys[n++] = code;
	}
	memcpy(x->b->key[a], keys, sizeof(keys));
}

static void bind_ev(void *user, const struct cini_ev *ev)
{
	struct bind_ctx *x = user;

	switch (ev->kind) {
	case CINI_ERROR:
		bind_report(x, ev->line, "%s", ev->msg);
		break;
	case CINI_SECTION:
		x->section_ok = strcmp(ev->section, "keyboard") == 0;
		if (!x->section_ok)
			bind_report(x, ev->line, "unknown section [%s] (only [keyboard])",
				    ev->section);
		break;
	case CINI_ENTRY:
		if (ev->section[0] == '\0')
			bind_report(x, ev->line, "key '%s' is outside [keyboard]", ev->key);
		else if (x->section_ok)
			bind_entry(x, ev->line, ev->key, ev->value);
		break;
	}
}

int bind_load_text(struct bind_table *b, const char *text, size_t len, const char *name,
		   cfg_err_fn fn, void *user)
{
	struct bind_ctx x = { .b = b, .file = name, .fn = fn, .user = user };

	cini_parse(text, len, bind_ev, &x);
	return x.rejected;
}

int bind_load(struct bind_table *b, const char *path, cfg_err_fn fn, void *user)
{
	struct bind_ctx x = { .b = b, .file = path, .fn = fn, .user = user };
	char *text;
	size_t len;
	int ret;

	ret = cini_read_file(path, &text, &len);
	if (ret == -ENOENT)
		return ret;
	if (ret < 0) {
		if (ret == -EFBIG)
			bind_report(&x, 0, "file is larger than %d bytes", CINI_FILE_MAX);
		else
			bind_report(&x, 0, "cannot read: %s", strerror(-ret));
		return ret;
	}
	ret = bind_load_text(b, text, len, path, fn, user);
	free(text);
	return ret;
}

int bind_lookup(const struct bind_table *b, int code, int *acts, int max)
{
	int n = 0;

	if (code < 0)
		return 0;
	for (int a = 0; a < ACT_COUNT && n < max; a++) {
		for (int i = 0; i < BIND_MAX; i++) {
			if (b->key[a][i] == code) {
				acts[n++] = a;
				break;
			}
		}
	}
	return n;
}
