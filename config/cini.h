/*
 * cini: the small INI reader shared by cfg and bind.
 *
 * Why not inih: Debian 12 ships inih r55 built without INI_HANDLER_LINENO,
 * so its handler never learns the line number; it reports only the first
 * malformed line (as a return value, not through the handler), never shows
 * a section that has no keys, splits lines longer than 200 bytes into
 * separate "lines", and treats an indented line as a continuation of the
 * previous value. arcaded must name file:line for every problem and go on,
 * so it parses the few INI rules it uses itself:
 *
 *   - one entry per line; lines end at '\n' ("\r\n" works too);
 *   - a line whose first non-blank character is ';' or '#' is a comment;
 *   - ';' or '#' preceded by a blank starts a comment anywhere else;
 *   - "[name]" starts a section (blanks inside the brackets are trimmed);
 *   - "key = value": blanks around key and value are trimmed; the value may
 *     be empty; there are no quotes, escapes or continuation lines;
 *   - a UTF-8 byte order mark before the first line is skipped.
 * Anything else (including a NUL byte, an over-long key or value, text
 * after "]") is reported as an error for that line and parsing goes on.
 */
#ifndef ARCADED_CONFIG_CINI_H
#define ARCADED_CONFIG_CINI_H

#include <stddef.h>

#define CINI_NAME_MAX 64       /* section and key: at most 63 bytes */
#define CINI_VALUE_MAX 1024    /* value: at most 1023 bytes */
#define CINI_FILE_MAX (1 << 20) /* cini_read_file refuses larger files */

enum cini_kind {
	CINI_SECTION,          /* section set; key and value are NULL */
	CINI_ENTRY,            /* key = value inside section ("" before any [section]) */
	CINI_ERROR,            /* malformed line; msg says why */
};

struct cini_ev {
	enum cini_kind kind;
	int line;              /* 1-based */
	const char *section;
	const char *key;
	const char *value;
	const char *msg;
};

/* Called once per section header, entry and malformed line, in file order.
 * Every string is valid only during the call. */
typedef void (*cini_fn)(void *user, const struct cini_ev *ev);

/* Parses len bytes of text (need not be NUL-terminated; may hold any bytes).
 * Returns the number of CINI_ERROR events. Never fails otherwise. */
int cini_parse(const char *text, size_t len, cini_fn fn, void *user);

/* Reads a whole file (input/io.h's io_read_file) into a malloc'd,
 * NUL-terminated buffer that the caller frees. 0, or -errno with *text
 * NULL: -EFBIG above CINI_FILE_MAX bytes, -EISDIR for a directory,
 * -EINVAL for anything else that is not a regular file (a FIFO, a device:
 * refused without blocking, IO_REGULAR). */
int cini_read_file(const char *path, char **text, size_t *len);

/* Reports a problem: file, line (0: none), message (cfg_err_fn's shape). */
typedef void (*cini_err_fn)(void *user, const char *file, int line, const char *msg);

/* Where the problems of one file (or one --set) go while settings,
 * bindings or a profile are read from it: counted, and passed to fn (when
 * not NULL) with the file's name. The loaders (cfg, bind, prof) report
 * through this one function; it is here because all of them read INI text
 * with cini and report in cini_err_fn's shape. */
struct cini_errs {
	const char *file;
	cini_err_fn fn;
	void *user;
	int count;             /* problems so far */
};

/* Counts a problem and passes it to e->fn, formatted as printf does (cut
 * at CINI_VALUE_MAX + 127 bytes, room for a whole value). line 0: the file
 * as a whole. */
void cini_report(struct cini_errs *e, int line, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

/* Reads path and hands its text to load(obj, text, len, path, fn, user),
 * returning what load returns. A missing file is -ENOENT, not reported; a
 * file that cannot be read, or is larger than CINI_FILE_MAX, is reported
 * through fn (line 0) and returns -errno. Shared by settings and
 * bindings. */
int cini_load_file(const char *path,
		   int (*load)(void *obj, const char *text, size_t len, const char *name,
			       cini_err_fn fn, void *user),
		   void *obj, cini_err_fn fn, void *user);

#endif
