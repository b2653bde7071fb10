/*
 * cfg: layered settings. One table lists every key: its section, name,
 * type, limits and where it lives in struct cfg; loading, --set and
 * cfg_format all walk that table, so a key cannot be known to one and
 * missing from another.
 */
#include "config/cfg.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "config/cini.h"
#include "engine/core/num.h"
#include "engine/game/sim.h"
#include "input/txt.h"

enum cfg_type {
	CFG_T_INT,      /* int in min..max */
	CFG_T_BOOL,     /* int 0/1 from 0/1 yes/no true/false on/off */
	CFG_T_STR,      /* char[size], any text that fits */
	CFG_T_NAME,     /* char[size], one of names[] */
	CFG_T_INDEX,    /* int, index of the value in names[] */
	CFG_T_ONEOF,    /* int, one of ints[] */
	CFG_T_DEVICE,   /* char[size]: "auto", "none" or a path containing '/' */
};

struct cfg_key {
	const char *section;
	const char *key;
	enum cfg_type type;
	size_t off;
	size_t size;                 /* strings: the buffer size */
	int min, max;                /* CFG_T_INT */
	const char *const *names;    /* CFG_T_NAME, CFG_T_INDEX: NULL-terminated */
	const int *ints;             /* CFG_T_ONEOF */
	int nints;
};

static const char *const cfg_backends[] = { "auto", "kms", "fbdev", "file", "term", "null",
					    NULL };
static const char *const cfg_formats[] = { "rgb565", "bgr565", "xrgb8888", "xbgr8888", "rgb888",
					   NULL };
static const char *const cfg_scales[] = { "integer", "fill", NULL };
/* enum g_idle's order (engine/game/g_game.h) */
static const char *const cfg_idles[] = { "life", "end", "off", NULL };
static const int cfg_rotations[] = { 0, 90, 180, 270 };

#define CFG_STRKEY(sec, name, field, t)                                                      \
	{ .section = #sec, .key = #name, .type = (t), .off = offsetof(struct cfg, field),   \
	  .size = sizeof(((struct cfg *)0)->field) }
#define CFG_INTKEY(sec, name, field, lo, hi)                                                 \
	{ .section = #sec, .key = #name, .type = CFG_T_INT, .off = offsetof(struct cfg, field), \
	  .min = (lo), .max = (hi) }
#define CFG_BOOLKEY(sec, name, field)                                                        \
	{ .section = #sec, .key = #name, .type = CFG_T_BOOL, .off = offsetof(struct cfg, field) }

static const struct cfg_key cfg_keys[] = {
	{ .section = "display", .key = "backend", .type = CFG_T_NAME,
	  .off = offsetof(struct cfg, display.backend),
	  .size = sizeof(((struct cfg *)0)->display.backend), .names = cfg_backends },
	CFG_STRKEY(display, device, display.device, CFG_T_STR),
	CFG_STRKEY(display, card, display.card, CFG_T_STR),
	CFG_STRKEY(display, mode, display.mode, CFG_T_STR),
	CFG_INTKEY(display, buffers, display.buffers, 2, 3),
	CFG_STRKEY(display, tty, display.tty, CFG_T_STR),
	CFG_STRKEY(display, file, display.file, CFG_T_STR),
	CFG_INTKEY(display, file_width, display.file_width, 1, 16384),
	CFG_INTKEY(display, file_height, display.file_height, 1, 16384),
	CFG_INTKEY(display, file_stride, display.file_stride, 0, 65536),
	{ .section = "display", .key = "file_format", .type = CFG_T_NAME,
	  .off = offsetof(struct cfg, display.file_format),
	  .size = sizeof(((struct cfg *)0)->display.file_format), .names = cfg_formats },
	{ .section = "display", .key = "rotate", .type = CFG_T_ONEOF,
	  .off = offsetof(struct cfg, display.rotate), .ints = cfg_rotations, .nints = 4 },
	{ .section = "display", .key = "scale", .type = CFG_T_INDEX,
	  .off = offsetof(struct cfg, display.fill), .names = cfg_scales },
	CFG_INTKEY(game, render_width, game.render_width, 64, 4096),
	CFG_INTKEY(game, render_height, game.render_height, 48, 4096),
	CFG_INTKEY(game, render_threads, game.render_threads, 0, 64),
	CFG_INTKEY(game, coins_per_credit, game.coins_per_credit, 1, 9),
	CFG_BOOLKEY(game, freeplay, game.freeplay),
	CFG_BOOLKEY(game, start_in_play, game.start_in_play),
	CFG_INTKEY(game, level, game.level, 1, 99),
	CFG_INTKEY(game, difficulty, game.difficulty, 0, 3),
	CFG_INTKEY(game, lives, game.lives, 1, 9),
	CFG_INTKEY(game, volume, game.volume, 0, 100),
	CFG_INTKEY(game, attract_sound, game.attract_sound, 0, 9),
	CFG_INTKEY(game, stage_time, game.stage_time, 0, 30),
	{ .section = "game", .key = "idle_out", .type = CFG_T_INDEX,
	  .off = offsetof(struct cfg, game.idle_out), .names = cfg_idles },
	CFG_BOOLKEY(game, autoaim, game.autoaim),
	CFG_STRKEY(game, wad, game.wad, CFG_T_STR),
	CFG_STRKEY(game, maps, game.maps, CFG_T_STR),
	CFG_STRKEY(game, content_dirs, game.content_dirs, CFG_T_STR),
	CFG_STRKEY(game, meshes, game.meshes, CFG_T_STR),
	CFG_STRKEY(audio, output, audio.output, CFG_T_STR),
	CFG_STRKEY(audio, device, audio.device, CFG_T_STR),
	CFG_INTKEY(audio, rate, audio.rate, 8000, 192000),
	CFG_STRKEY(input, evdev, input.evdev, CFG_T_DEVICE),
	CFG_STRKEY(input, bindings, input.bindings, CFG_T_STR),
	CFG_STRKEY(input, hid, input.hid, CFG_T_STR),
	CFG_STRKEY(input, gpio, input.gpio, CFG_T_STR),
	CFG_BOOLKEY(input, log, input.log),
	CFG_STRKEY(paths, state_dir, paths.state_dir, CFG_T_STR),
	CFG_INTKEY(recorder, keep, recorder.keep, 0, 1000),
	CFG_INTKEY(recorder, max_mb, recorder.max_mb, 0, 1048576),
};

#define CFG_NKEYS (sizeof(cfg_keys) / sizeof(cfg_keys[0]))

/* Where problems go while one file or one --set is applied. */
struct cfg_ctx {
	struct cfg *c;
	struct cini_errs err;
	bool section_ok;         /* false inside an unknown [section] */
};

static void cfg_setstr(char *dst, size_t size, const char *s)
{
	snprintf(dst, size, "%s", s);
}

const char *cfg_idle_name(int idle)
{
	return cfg_idles[idle >= 0 && idle < G_IDLE_COUNT ? idle : G_IDLE_OFF];
}

void cfg_settings(const struct cfg *c, struct sim_settings *set)
{
	memset(set, 0, sizeof(*set));
	set->coins_per_credit = (uint8_t)c->game.coins_per_credit;
	set->freeplay = (uint8_t)c->game.freeplay;
	set->start_in_play = (uint8_t)c->game.start_in_play;
	set->difficulty = (uint8_t)c->game.difficulty;
	set->lives = (uint8_t)c->game.lives;
	set->volume = (uint8_t)c->game.volume;
	set->attract_sound = (uint8_t)c->game.attract_sound;
	/* the file's 0 is "no clock"; the sim's 0 is its default */
	set->stage_time = c->game.stage_time == 0 ? G_STAGE_TIME_OFF : (uint8_t)c->game.stage_time;
	set->idle_out = (uint8_t)c->game.idle_out;
	set->free_aim = (uint8_t)!c->game.autoaim;
}

void cfg_defaults(struct cfg *c)
{
	const char *sd = getenv("STATE_DIRECTORY");
	size_t sdlen = sd ? strcspn(sd, ":") : 0;

	memset(c, 0, sizeof(*c));
	cfg_setstr(c->display.backend, sizeof(c->display.backend), "auto");
	cfg_setstr(c->display.device, sizeof(c->display.device), "/dev/fb0");
	cfg_setstr(c->display.tty, sizeof(c->display.tty), "/dev/tty0");
	c->display.buffers = 3;
	c->display.file_width = 640;
	c->display.file_height = 480;
	cfg_setstr(c->display.file_format, sizeof(c->display.file_format), "xrgb8888");
	c->game.render_width = 320;
	c->game.render_height = 240;
	c->game.coins_per_credit = 1;
	c->game.level = 1;
	c->game.difficulty = 1;
	c->game.lives = 3;
	c->game.volume = 80;
	cfg_setstr(c->game.content_dirs, sizeof(c->game.content_dirs),
		   "/usr/share/games/doom /var/lib/arcaded/content");
	c->game.attract_sound = 1;
	c->game.stage_time = 5;
	c->game.autoaim = 1;
	cfg_setstr(c->audio.output, sizeof(c->audio.output), "auto");
	cfg_setstr(c->audio.device, sizeof(c->audio.device), "default");
	c->audio.rate = 48000;
	c->recorder.keep = 20;
	c->recorder.max_mb = 64;
	cfg_setstr(c->input.evdev, sizeof(c->input.evdev), "auto");
	cfg_setstr(c->input.hid, sizeof(c->input.hid), "auto");
	cfg_setstr(c->input.gpio, sizeof(c->input.gpio), "none");
	/* systemd's StateDirectory= may list several directories, colon-separated:
	 * arcaded's is the first. */
	if (sdlen > 0 && sdlen < sizeof(c->paths.state_dir)) {
		memcpy(c->paths.state_dir, sd, sdlen);
		c->paths.state_dir[sdlen] = '\0';
	} else {
		cfg_setstr(c->paths.state_dir, sizeof(c->paths.state_dir), "/var/lib/arcaded");
	}
}

static bool cfg_known_section(const char *s)
{
	for (size_t i = 0; i < CFG_NKEYS; i++)
		if (strcmp(cfg_keys[i].section, s) == 0)
			return true;
	return false;
}

static const struct cfg_key *cfg_find(const char *section, const char *key)
{
	for (size_t i = 0; i < CFG_NKEYS; i++)
		if (strcmp(cfg_keys[i].section, section) == 0 && strcmp(cfg_keys[i].key, key) == 0)
			return &cfg_keys[i];
	return NULL;
}

static int cfg_parse_bool(const char *v)
{
	static const char *const yes[] = { "1", "yes", "true", "on" };
	static const char *const no[] = { "0", "no", "false", "off" };

	for (size_t i = 0; i < 4; i++) {
		if (strcasecmp(v, yes[i]) == 0)
			return 1;
		if (strcasecmp(v, no[i]) == 0)
			return 0;
	}
	return -1;
}

/* "a, b, c" from a NULL-terminated list or an int list, for messages. */
static void cfg_list(const struct cfg_key *k, char *buf, size_t len)
{
	size_t n = 0;

	buf[0] = '\0';
	if (k->names) {
		for (int i = 0; k->names[i] && n < len; i++)
			n += (size_t)snprintf(buf + n, len - n, "%s%s", i ? ", " : "", k->names[i]);
	} else {
		for (int i = 0; i < k->nints && n < len; i++)
			n += (size_t)snprintf(buf + n, len - n, "%s%d", i ? ", " : "", k->ints[i]);
	}
}

static int cfg_name_index(const struct cfg_key *k, const char *v)
{
	for (int i = 0; k->names[i]; i++)
		if (strcasecmp(k->names[i], v) == 0)
			return i;
	return -1;
}

/* Applies one value; on any problem reports it and leaves the field alone. */
static void cfg_apply(struct cfg_ctx *x, int line, const struct cfg_key *k, const char *v)
{
	char *field = (char *)x->c + k->off;
	char list[128];
	int64_t l;
	int n, i, rc;

	switch (k->type) {
	case CFG_T_INT:
		rc = num_parse(v, k->min, k->max, &l);
		if (rc == -EINVAL) {
			cini_report(&x->err, line, "%s: '%s' is not an integer", k->key, v);
		} else if (rc < 0) {
			cini_report(&x->err, line, "%s: %s out of range %d..%d", k->key, v, k->min,
				    k->max);
		} else {
			n = (int)l;
			memcpy(field, &n, sizeof(n));
		}
		return;
	case CFG_T_BOOL:
		n = cfg_parse_bool(v);
		if (n < 0)
			cini_report(&x->err, line,
				    "%s: '%s' is not a boolean (yes/no, true/false, on/off, 1/0)",
				    k->key, v);
		else
			memcpy(field, &n, sizeof(n));
		return;
	case CFG_T_ONEOF:
		if (num_parse(v, INT_MIN, INT_MAX, &l) == 0) {
			n = (int)l;
			for (i = 0; i < k->nints; i++) {
				if (k->ints[i] == n) {
					memcpy(field, &n, sizeof(n));
					return;
				}
			}
		}
		cfg_list(k, list, sizeof(list));
		cini_report(&x->err, line, "%s: %s is not one of %s", k->key, v, list);
		return;
	case CFG_T_NAME:
	case CFG_T_INDEX:
		i = cfg_name_index(k, v);
		if (i < 0) {
			cfg_list(k, list, sizeof(list));
			cini_report(&x->err, line, "%s: '%s' is not one of %s", k->key, v, list);
		} else if (k->type == CFG_T_INDEX) {
			memcpy(field, &i, sizeof(i));
		} else {
			cfg_setstr(field, k->size, k->names[i]);
		}
		return;
	case CFG_T_DEVICE:
		if (strcmp(v, "auto") != 0 && strcmp(v, "none") != 0 && !strchr(v, '/')) {
			cini_report(&x->err, line, "%s: '%s' is not auto, none or a device path",
				    k->key, v);
			return;
		}
		break;
	case CFG_T_STR:
		break;
	}
	if (strlen(v) >= k->size) {
		cini_report(&x->err, line, "%s: value too long (at most %zu bytes)", k->key,
			    k->size - 1);
		return;
	}
	cfg_setstr(field, k->size, v);
}

static void cfg_entry(struct cfg_ctx *x, int line, const char *section, const char *key,
		      const char *value)
{
	const struct cfg_key *k = cfg_find(section, key);

	if (k)
		cfg_apply(x, line, k, value);
	else
		cini_report(&x->err, line, "unknown key '%s' in [%s]", key, section);
}

static void cfg_ev(void *user, const struct cini_ev *ev)
{
	struct cfg_ctx *x = user;

	switch (ev->kind) {
	case CINI_ERROR:
		cini_report(&x->err, ev->line, "%s", ev->msg);
		break;
	case CINI_SECTION:
		x->section_ok = cfg_known_section(ev->section);
		if (!x->section_ok)
			cini_report(&x->err, ev->line, "unknown section [%s]", ev->section);
		break;
	case CINI_ENTRY:
		/* Keys of an unknown section were covered by its one message. */
		if (ev->section[0] == '\0')
			cini_report(&x->err, ev->line, "key '%s' is outside any [section]",
				    ev->key);
		else if (x->section_ok)
			cfg_entry(x, ev->line, ev->section, ev->key, ev->value);
		break;
	}
}

int cfg_load_text(struct cfg *c, const char *text, size_t len, const char *name,
		  cfg_err_fn fn, void *user)
{
	struct cfg_ctx x = { .c = c, .err = { .file = name, .fn = fn, .user = user } };

	cini_parse(text, len, cfg_ev, &x);
	return x.err.count;
}

static int cfg_load_any(void *c, const char *text, size_t len, const char *name, cfg_err_fn fn,
			void *user)
{
	return cfg_load_text(c, text, len, name, fn, user);
}

int cfg_load_file(struct cfg *c, const char *path, cfg_err_fn fn, void *user)
{
	return cini_load_file(path, cfg_load_any, c, fn, user);
}

/* *.ini, not hidden, and not the bindings file that shares the directory
 * (bind_load reads it; its [keyboard] section is no setting). */
static bool cfg_is_ini(const char *name)
{
	size_t n = strlen(name);

	return name[0] != '.' && n > 4 && strcmp(name + n - 4, ".ini") == 0 &&
	       strcmp(name, CFG_BINDINGS_FILE) != 0;
}

static int cfg_cmp_names(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

int cfg_load_dir(struct cfg *c, const char *dir, cfg_err_fn fn, void *user)
{
	struct cfg_ctx x = { .c = c, .err = { .file = dir, .fn = fn, .user = user } };
	char **names = NULL;
	size_t n = 0, cap = 0;
	struct dirent *de;
	DIR *d;

	d = opendir(dir);
	if (!d) {
		if (errno != ENOENT)
			cini_report(&x.err, 0, "cannot read directory: %s", strerror(errno));
		return x.err.count;
	}
	while ((de = readdir(d))) {
		char **nn;

		if (!cfg_is_ini(de->d_name))
			continue;
		if (n == cap) {
			cap = cap ? cap * 2 : 8;
			nn = realloc(names, cap * sizeof(*names));
			if (!nn)
				goto nomem;
			names = nn;
		}
		names[n] = strdup(de->d_name);
		if (!names[n])
			goto nomem;
		n++;
	}
	closedir(d);
	d = NULL;
	/* Byte order, not the locale's: the same files load in the same order
	 * everywhere (as `LC_ALL=C ls`). */
	if (n)
		qsort(names, n, sizeof(*names), cfg_cmp_names);
	for (size_t i = 0; i < n; i++) {
		char path[PATH_MAX];
		int r;

		if ((size_t)snprintf(path, sizeof(path), "%s/%s", dir, names[i]) >= sizeof(path)) {
			x.err.file = names[i];
			cini_report(&x.err, 0, "path too long");
			continue;
		}
		r = cfg_load_file(c, path, fn, user);
		if (r > 0)
			x.err.count += r;
		else if (r < 0 && r != -ENOENT)
			x.err.count++;
	}
	goto out;
nomem:
	x.err.file = dir;
	cini_report(&x.err, 0, "out of memory");
out:
	if (d)
		closedir(d);
	for (size_t i = 0; i < n; i++)
		free(names[i]);
	free(names);
	return x.err.count;
}

/* Copies [b, e) trimmed of blanks into dst; false if it does not fit. */
static bool cfg_copy_trim(char *dst, size_t size, const char *b, const char *e)
{
	while (b < e && (*b == ' ' || *b == '\t'))
		b++;
	while (e > b && (e[-1] == ' ' || e[-1] == '\t'))
		e--;
	if ((size_t)(e - b) >= size)
		return false;
	memcpy(dst, b, (size_t)(e - b));
	dst[e - b] = '\0';
	return true;
}

int cfg_set(struct cfg *c, const char *assignment, cfg_err_fn fn, void *user)
{
	struct cfg_ctx x = { .c = c, .err = { .file = "--set", .fn = fn, .user = user } };
	const char *eq = strchr(assignment, '=');
	const char *dot = eq ? memchr(assignment, '.', (size_t)(eq - assignment)) : NULL;
	char section[CINI_NAME_MAX], key[CINI_NAME_MAX], value[CINI_VALUE_MAX];

	if (!dot) {
		cini_report(&x.err, 0, "expected section.key=value, got '%.200s'", assignment);
		return -EINVAL;
	}
	if (!cfg_copy_trim(section, sizeof(section), assignment, dot) ||
	    !cfg_copy_trim(key, sizeof(key), dot + 1, eq)) {
		cini_report(&x.err, 0, "name too long in '%.200s'", assignment);
		return -EINVAL;
	}
	if (!cfg_copy_trim(value, sizeof(value), eq + 1, eq + 1 + strlen(eq + 1))) {
		cini_report(&x.err, 0, "value too long");
		return -EINVAL;
	}
	if (!cfg_known_section(section))
		cini_report(&x.err, 0, "unknown section [%s]", section);
	else
		cfg_entry(&x, 0, section, key, value);
	return x.err.count ? -EINVAL : 0;
}

static const char *cfg_index_name(const struct cfg_key *k, int v)
{
	for (int i = 0; k->names[i]; i++)
		if (i == v)
			return k->names[i];
	return "?";
}

size_t cfg_format(const struct cfg *c, char *buf, size_t len)
{
	const char *section = NULL;
	struct txt t = { .buf = buf, .len = len };

	if (len)
		buf[0] = '\0';
	for (size_t i = 0; i < CFG_NKEYS; i++) {
		const struct cfg_key *k = &cfg_keys[i];
		const char *field = (const char *)c + k->off;
		int v;

		if (!section || strcmp(section, k->section) != 0) {
			txt_put(&t, "%s[%s]\n", section ? "\n" : "", k->section);
			section = k->section;
		}
		switch (k->type) {
		case CFG_T_STR:
		case CFG_T_NAME:
		case CFG_T_DEVICE:
			/* No blank after '=' for an empty value. */
			txt_put(&t, "%s =%s%s\n", k->key, field[0] ? " " : "", field);
			break;
		case CFG_T_BOOL:
			memcpy(&v, field, sizeof(v));
			txt_put(&t, "%s = %s\n", k->key, v ? "yes" : "no");
			break;
		case CFG_T_INDEX:
			memcpy(&v, field, sizeof(v));
			txt_put(&t, "%s = %s\n", k->key, cfg_index_name(k, v));
			break;
		case CFG_T_INT:
		case CFG_T_ONEOF:
			memcpy(&v, field, sizeof(v));
			txt_put(&t, "%s = %d\n", k->key, v);
			break;
		}
	}
	return t.n;
}
