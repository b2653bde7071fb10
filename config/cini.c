/*
 * cini: see cini.h for the INI rules this reader accepts and why it is not
 * inih.
 */
#include "config/cini.h"

#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input/io.h"

static bool cini_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r';
}

/* Trims blanks from both ends of [*b, *e). */
static void cini_trim(const char **b, const char **e)
{
	while (*b < *e && cini_blank(**b))
		(*b)++;
	while (*e > *b && cini_blank((*e)[-1]))
		(*e)--;
}

/* Copies [b, e) into dst (size n) as a string; false if it does not fit. */
static bool cini_copy(char *dst, size_t n, const char *b, const char *e)
{
	size_t len = (size_t)(e - b);

	if (len >= n)
		return false;
	memcpy(dst, b, len);
	dst[len] = '\0';
	return true;
}

struct cini_state {
	cini_fn fn;
	void *user;
	int line;
	int errors;
	bool skip;               /* after a malformed [section]: drop its keys */
	char section[CINI_NAME_MAX];
	char key[CINI_NAME_MAX];
	char value[CINI_VALUE_MAX];
};

static void cini_error(struct cini_state *st, const char *msg)
{
	struct cini_ev ev = { .kind = CINI_ERROR, .line = st->line, .section = st->section,
			      .msg = msg };

	st->errors++;
	st->fn(st->user, &ev);
}

static void cini_section(struct cini_state *st, const char *b, const char *e)
{
	const char *close = memchr(b, ']', (size_t)(e - b));
	const char *nb = b + 1;
	const char *ne = close;
	struct cini_ev ev = { .kind = CINI_SECTION };

	/* Until a good header comes, keys belong to no section we can name. */
	st->skip = true;
	if (!close) {
		cini_error(st, "missing ] after section name");
		return;
	}
	if (close + 1 != e) {
		cini_error(st, "text after ] of section name");
		return;
	}
	cini_trim(&nb, &ne);
	if (nb == ne) {
		cini_error(st, "empty section name");
		return;
	}
	if (!cini_copy(st->section, sizeof(st->section), nb, ne)) {
		cini_error(st, "section name too long");
		return;
	}
	st->skip = false;
	ev.line = st->line;
	ev.section = st->section;
	st->fn(st->user, &ev);
}

static void cini_entry(struct cini_state *st, const char *b, const char *e)
{
	const char *eq = memchr(b, '=', (size_t)(e - b));
	const char *kb = b, *ke = eq, *vb, *ve = e;
	struct cini_ev ev = { .kind = CINI_ENTRY };

	if (!eq) {
		cini_error(st, "line is neither [section] nor key = value");
		return;
	}
	vb = eq + 1;
	cini_trim(&kb, &ke);
	cini_trim(&vb, &ve);
	if (kb == ke) {
		cini_error(st, "missing key before =");
		return;
	}
	if (!cini_copy(st->key, sizeof(st->key), kb, ke)) {
		cini_error(st, "key too long");
		return;
	}
	if (!cini_copy(st->value, sizeof(st->value), vb, ve)) {
		cini_error(st, "value too long");
		return;
	}
	if (st->skip)
		return;
	ev.line = st->line;
	ev.section = st->section;
	ev.key = st->key;
	ev.value = st->value;
	st->fn(st->user, &ev);
}

static void cini_line(struct cini_state *st, const char *b, const char *e)
{
	const char *p;

	if (memchr(b, '\0', (size_t)(e - b))) {
		cini_error(st, "line contains a NUL byte");
		return;
	}
	cini_trim(&b, &e);
	if (b == e || *b == ';' || *b == '#')
		return;
	/* An inline comment needs a blank before it, so "a;b" stays a value. */
	for (p = b + 1; p < e; p++) {
		if ((*p == ';' || *p == '#') && cini_blank(p[-1])) {
			e = p;
			break;
		}
	}
	cini_trim(&b, &e);
	if (*b == '[')
		cini_section(st, b, e);
	else
		cini_entry(st, b, e);
}

int cini_parse(const char *text, size_t len, cini_fn fn, void *user)
{
	struct cini_state st = { .fn = fn, .user = user };
	const char *p = text, *end = text + len;

	if (len >= 3 && memcmp(p, "\xef\xbb\xbf", 3) == 0)
		p += 3;
	while (p < end) {
		const char *nl = memchr(p, '\n', (size_t)(end - p));
		const char *le = nl ? nl : end;

		st.line++;
		cini_line(&st, p, le);
		p = nl ? nl + 1 : end;
	}
	return st.errors;
}

void cini_report(struct cini_errs *e, int line, const char *fmt, ...)
{
	char msg[CINI_VALUE_MAX + 128];
	va_list ap;

	e->count++;
	if (!e->fn)
		return;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	e->fn(e->user, e->file, line, msg);
}

int cini_read_file(const char *path, char **text, size_t *len)
{
	uint8_t *b;
	int ret = io_read_file(path, CINI_FILE_MAX, IO_REGULAR, &b, len);

	*text = (char *)b;
	return ret;
}

int cini_load_file(const char *path,
		   int (*load)(void *obj, const char *text, size_t len, const char *name,
			       cini_err_fn fn, void *user),
		   void *obj, cini_err_fn fn, void *user)
{
	char msg[160], *text;
	size_t len;
	int ret = cini_read_file(path, &text, &len);

	if (ret == -ENOENT)
		return ret;
	if (ret < 0) {
		if (ret == -EFBIG)
			snprintf(msg, sizeof(msg), "file is larger than %d bytes", CINI_FILE_MAX);
		else if (ret == -EINVAL)
			snprintf(msg, sizeof(msg), "not a regular file; ignored");
		else
			snprintf(msg, sizeof(msg), "cannot read: %s", strerror(-ret));
		if (fn)
			fn(user, path, 0, msg);
		return ret;
	}
	ret = load(obj, text, len, path, fn, user);
	free(text);
	return ret;
}
