/*
 * prof: autoconfiguration profiles; file format and matching in prof.h.
 */
#include "config/prof.h"

#include <dirent.h>
#include <errno.h>
#include <fnmatch.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "config/cini.h"
#include "engine/core/num.h"

void prof_init(struct prof_set *s)
{
	s->n = 0;
}

struct prof_ctx {
	struct prof *p;
	struct cini_errs err;
	enum { SEC_NONE, SEC_PROFILE, SEC_BINDINGS, SEC_BAD } sec;
};

static int hex4(const char *s, size_t n)
{
	int v = 0;

	if (n != 4)
		return -1;
	for (size_t i = 0; i < n; i++) {
		int d = num_hex(s[i]);

		if (d < 0)
			return -1;
		v = v * 16 + d;
	}
	return v;
}

/* "0079:0006, d209:*" or "any" */
static void match_ids(struct prof_ctx *x, int line, const char *v)
{
	struct prof *p = x->p;
	char item[32];

	if (strcasecmp(v, "any") == 0) {
		p->any = 1;
		return;
	}
	while (*v) {
		size_t n = strcspn(v, ","), b = 0, e = n;
		const char *colon;
		int vid, pid;

		while (b < e && (v[b] == ' ' || v[b] == '\t'))
			b++;
		while (e > b && (v[e - 1] == ' ' || v[e - 1] == '\t'))
			e--;
		snprintf(item, sizeof(item), "%.*s", (int)(e - b), v + b);
		colon = strchr(item, ':');
		vid = colon ? hex4(item, (size_t)(colon - item)) : -1;
		pid = colon && strcmp(colon + 1, "*") == 0 ? -2 : colon ? hex4(colon + 1,
									     strlen(colon + 1))
								   : -1;
		if (vid < 0 || pid == -1 || e - b >= sizeof(item)) {
			cini_report(&x->err, line,
				    "match: '%s' is not VVVV:PPPP (hex), VVVV:* or any", item);
		} else if (p->nids == PROF_IDS) {
			cini_report(&x->err, line, "match: more than %d ids", PROF_IDS);
			return;
		} else {
			p->vid[p->nids] = (uint16_t)vid;
			p->pid[p->nids] = pid == -2 ? -1 : pid;
			p->nids++;
		}
		v += n;
		if (*v == ',')
			v++;
	}
}

static void copy_value(struct prof_ctx *x, int line, const char *key, const char *v, char *dst,
		       size_t len)
{
	if (strlen(v) >= len) {
		cini_report(&x->err, line, "%s: value too long (at most %zu bytes)", key, len - 1);
		return;
	}
	strcpy(dst, v);
}

static void profile_entry(struct prof_ctx *x, int line, const char *k, const char *v)
{
	struct prof *p = x->p;

	if (strcmp(k, "name") == 0) {
		copy_value(x, line, k, v, p->name, sizeof(p->name));
	} else if (strcmp(k, "match") == 0) {
		match_ids(x, line, v);
	} else if (strcmp(k, "match_name") == 0) {
		copy_value(x, line, k, v, p->name_glob, sizeof(p->name_glob));
	} else if (strcmp(k, "backend") == 0) {
		if (strcmp(v, "hid") == 0 || strcmp(v, "evdev") == 0 || strcmp(v, "gpio") == 0)
			strcpy(p->backend, v);
		else if (strcmp(v, "any") == 0)
			p->backend[0] = '\0';
		else
			cini_report(&x->err, line,
				    "backend: '%s' is not one of hid, evdev, gpio, any", v);
	} else if (strcmp(k, "hid") == 0) {
		copy_value(x, line, k, v, p->hid, sizeof(p->hid));
	} else {
		cini_report(&x->err, line, "unknown key '%s' in [profile]", k);
	}
}

static void prof_ev(void *user, const struct cini_ev *ev)
{
	struct prof_ctx *x = user;

	switch (ev->kind) {
	case CINI_ERROR:
		cini_report(&x->err, ev->line, "%s", ev->msg);
		break;
	case CINI_SECTION:
		if (strcmp(ev->section, "profile") == 0) {
			x->sec = SEC_PROFILE;
		} else if (strcmp(ev->section, "bindings") == 0) {
			x->sec = SEC_BINDINGS;
		} else {
			x->sec = SEC_BAD;
			cini_report(&x->err, ev->line,
				    "unknown section [%s] (only [profile] and [bindings])",
				    ev->section);
		}
		break;
	case CINI_ENTRY:
		if (x->sec == SEC_PROFILE)
			profile_entry(x, ev->line, ev->key, ev->value);
		else if (x->sec == SEC_BINDINGS)
			bind_set_entry(x->p->key, &x->err, ev->line, ev->key, ev->value);
		else if (x->sec == SEC_NONE)
			cini_report(&x->err, ev->line,
				    "key '%s' is outside [profile] and [bindings]", ev->key);
		break;
	}
}

int prof_load_text(struct prof_set *s, const char *text, size_t len, const char *name,
		   cfg_err_fn fn, void *user)
{
	struct prof_ctx x = { .err = { .file = name, .fn = fn, .user = user }, .sec = SEC_NONE };
	struct prof p;
	const char *base = strrchr(name, '/');

	memset(&p, 0, sizeof(p));
	for (int a = 0; a < ACT_COUNT; a++)
		for (int i = 0; i < BIND_MAX; i++)
			p.key[a][i] = -1;
	snprintf(p.file, sizeof(p.file), "%s", base ? base + 1 : name);
	x.p = &p;
	cini_parse(text, len, prof_ev, &x);
	if (p.nids == 0 && !p.any && !p.name_glob[0]) {
		cini_report(&x.err, 0, "no match or match_name: profile not used");
		return x.err.count;
	}
	if (s->n == PROF_MAX) {
		cini_report(&x.err, 0, "more than %d profiles: not used", PROF_MAX);
		return x.err.count;
	}
	if (!p.name[0])
		snprintf(p.name, sizeof(p.name), "%s", p.file);
	s->p[s->n++] = p;
	return x.err.count;
}

static int cmp_names(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

int prof_load_dir(struct prof_set *s, const char *dir, cfg_err_fn fn, void *user)
{
	DIR *dh = opendir(dir);
	struct dirent *de;
	char **names = NULL;
	size_t n = 0, cap = 0;
	int problems = 0, rc = 0;

	if (!dh) {
		rc = -errno;
		if (rc != -ENOENT && fn)
			fn(user, dir, 0, strerror(-rc));
		return rc;
	}
	while ((de = readdir(dh)) != NULL) {
		size_t len = strlen(de->d_name);

		if (de->d_name[0] == '.' || len < 5 || strcmp(de->d_name + len - 4, ".ini") != 0)
			continue;
		if (n == cap) {
			char **nn = realloc(names, (cap ? cap * 2 : 16) * sizeof(*names));

			if (!nn) {
				rc = -ENOMEM;
				break;
			}
			names = nn;
			cap = cap ? cap * 2 : 16;
		}
		names[n] = strdup(de->d_name);
		if (!names[n]) {
			rc = -ENOMEM;
			break;
		}
		n++;
	}
	closedir(dh);
	if (rc == 0 && n > 1)
		qsort(names, n, sizeof(*names), cmp_names);
	for (size_t i = 0; i < n && rc == 0; i++) {
		char path[CFG_PATH_MAX + 256];
		char *text;
		size_t len;
		int r;

		snprintf(path, sizeof(path), "%s/%s", dir, names[i]);
		r = cini_read_file(path, &text, &len);
		if (r < 0) {
			problems++;
			if (fn)
				fn(user, path, 0,
				   r == -EINVAL ? "not a regular file; ignored" : strerror(-r));
			continue;
		}
		problems += prof_load_text(s, text, len, path, fn, user);
		free(text);
	}
	for (size_t i = 0; i < n; i++)
		free(names[i]);
	free(names);
	return rc < 0 ? rc : problems;
}

static bool id_match(const struct prof *p, const struct in_ident *id)
{
	if (!id->vid && !id->pid)
		return false;
	for (int i = 0; i < p->nids; i++)
		if (p->vid[i] == id->vid && (p->pid[i] < 0 || p->pid[i] == id->pid))
			return true;
	return false;
}

/* 4: ids and name, 3: ids, 2: name only, 1: any; 0: no match. */
static int score(const struct prof *p, const char *backend, const struct in_ident *id)
{
	bool name = p->name_glob[0] && fnmatch(p->name_glob, id->name, FNM_CASEFOLD) == 0;

	if (p->backend[0] && (!backend || strcmp(p->backend, backend) != 0))
		return 0;
	if (p->nids && id_match(p, id))
		return p->name_glob[0] ? (name ? 4 : 0) : 3;
	if (!p->nids && name)
		return 2;
	return p->any && !p->nids && !p->name_glob[0] ? 1 : 0;
}

const struct prof *prof_match(const struct prof_set *s, const char *backend,
			      const struct in_ident *id)
{
	const struct prof *best = NULL;
	int best_score = 0;

	if (!id)
		return NULL;
	for (int i = 0; i < s->n; i++) {
		int sc = score(&s->p[i], backend, id);

		if (sc > best_score) {
			best = &s->p[i];
			best_score = sc;
		}
	}
	return best;
}

int prof_bind(const struct prof *p, struct bind_table *b, const struct in_ident *id)
{
	char name[BIND_ID_MAX];
	int rc;

	if (!id)
		return -EINVAL;
	if (bind_find_device(b, id))
		return 0;
	if (id->vid || id->pid)
		snprintf(name, sizeof(name), "%04x:%04x", id->vid, id->pid);
	else if (id->port[0] && strlen(id->port) + 4 < sizeof(name))
		snprintf(name, sizeof(name), "usb-%s", id->port);
	else
		return -EINVAL;
	rc = bind_set_device(b, name, p->key);
	return rc < 0 ? rc : 1;
}
