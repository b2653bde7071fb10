/*
 * cini: the INI reader behind cfg and bind. Every event is logged as text
 * ("3 S display", "4 E display.key=value", "5 X reason") and compared with
 * what the INI rules in cini.h say the input means.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "config/cini.h"

struct log {
	char text[65536];
	int errors;
	size_t n;
};

static void log_ev(void *user, const struct cini_ev *ev)
{
	struct log *l = user;
	size_t room = sizeof(l->text) - l->n;
	int w = 0;

	switch (ev->kind) {
	case CINI_SECTION:
		w = snprintf(l->text + l->n, room, "%d S %s\n", ev->line, ev->section);
		break;
	case CINI_ENTRY:
		w = snprintf(l->text + l->n, room, "%d E %s.%s=%s\n", ev->line, ev->section,
			     ev->key, ev->value);
		break;
	case CINI_ERROR:
		l->errors++;
		w = snprintf(l->text + l->n, room, "%d X %s\n", ev->line, ev->msg);
		break;
	}
	assert_true(w > 0 && (size_t)w < room);
	l->n += (size_t)w;
}

static int parse(const char *text, size_t len, struct log *l)
{
	memset(l, 0, sizeof(*l));
	return cini_parse(text, len, log_ev, l);
}

static void test_sections_entries_and_line_numbers(void **state)
{
	static const char in[] = "[a]\nk = v\n\n  [ b c ]  \nkey=value with spaces  \n";
	struct log l;

	(void)state;
	assert_int_equal(parse(in, sizeof(in) - 1, &l), 0);
	assert_string_equal(l.text, "1 S a\n2 E a.k=v\n4 S b c\n5 E b c.key=value with spaces\n");
}

static void test_comments_whole_line_and_inline(void **state)
{
	static const char in[] = "; c1\n# c2\n   ;c3\n[s] ; after section\n"
				 "a = 1 ; comment\nb = 2 # comment\nc = x;y#z\nd =  ;only comment\n";
	struct log l;

	(void)state;
	assert_int_equal(parse(in, sizeof(in) - 1, &l), 0);
	/* ';' or '#' count only after a blank: "x;y#z" is one value. */
	assert_string_equal(l.text, "4 S s\n5 E s.a=1\n6 E s.b=2\n7 E s.c=x;y#z\n8 E s.d=\n");
}

static void test_crlf_bom_and_no_final_newline(void **state)
{
	static const char in[] = "\xef\xbb\xbf[s]\r\nk = v\r\nlast=1";
	struct log l;

	(void)state;
	assert_int_equal(parse(in, sizeof(in) - 1, &l), 0);
	assert_string_equal(l.text, "1 S s\n2 E s.k=v\n3 E s.last=1\n");
}

static void test_entry_before_any_section_has_empty_section(void **state)
{
	static const char in[] = "k = v\n";
	struct log l;

	(void)state;
	assert_int_equal(parse(in, sizeof(in) - 1, &l), 0);
	assert_string_equal(l.text, "1 E .k=v\n");
}

static void test_malformed_lines_are_reported_and_parsing_goes_on(void **state)
{
	static const char in[] = "[s]\n"
				 "just words\n"          /* 2 */
				 "= v\n"                 /* 3 */
				 "[open\n"               /* 4 */
				 "k = dropped\n"         /* 5: after a bad header */
				 "[x] y\n"               /* 6 */
				 "[  ]\n"                /* 7 */
				 "[t]\n"                 /* 8 */
				 "ok = 1\n";             /* 9 */
	struct log l;

	(void)state;
	assert_int_equal(parse(in, sizeof(in) - 1, &l), 5);
	assert_string_equal(l.text, "1 S s\n"
				    "2 X line is neither [section] nor key = value\n"
				    "3 X missing key before =\n"
				    "4 X missing ] after section name\n"
				    "6 X text after ] of section name\n"
				    "7 X empty section name\n"
				    "8 S t\n"
				    "9 E t.ok=1\n");
}

static void test_nul_byte_is_an_error_on_its_line(void **state)
{
	static const char in[] = "[s]\na = 1\0hidden\nb = 2";
	struct log l;

	(void)state;
	assert_int_equal(parse(in, sizeof(in) - 1, &l), 1);
	assert_string_equal(l.text, "1 S s\n2 X line contains a NUL byte\n3 E s.b=2\n");
}

static void test_overlong_key_value_and_section(void **state)
{
	char want[84 + CINI_VALUE_MAX + 1];
	size_t big = 200000;
	char *in = malloc(big + 4 * CINI_VALUE_MAX);
	struct log l;
	size_t n = 0;

	(void)state;
	assert_non_null(in);
	n += (size_t)sprintf(in + n, "[s]\nv = ");
	memset(in + n, 'x', CINI_VALUE_MAX);       /* one byte over the limit */
	n += CINI_VALUE_MAX;
	in[n++] = '\n';
	memset(in + n, 'k', big);                   /* a 200 kB key */
	n += big;
	n += (size_t)sprintf(in + n, " = 1\n[");
	memset(in + n, 's', CINI_NAME_MAX);
	n += CINI_NAME_MAX;
	n += (size_t)sprintf(in + n, "]\nskipped = 1\n[t]\nfit = ");
	memset(in + n, 'y', CINI_VALUE_MAX - 1);   /* exactly at the limit */
	n += CINI_VALUE_MAX - 1;
	assert_int_equal(parse(in, n, &l), 3);
	/* Line 5 belongs to the bad section and is dropped. */
	memcpy(want, "1 S s\n2 X value too long\n3 X key too long\n4 X section name too long\n"
		     "6 S t\n7 E t.fit=", 84);
	memset(want + 84, 'y', CINI_VALUE_MAX - 1);
	strcpy(want + 84 + CINI_VALUE_MAX - 1, "\n");
	assert_string_equal(l.text, want);
	free(in);
}

static void test_random_bytes_never_crash(void **state)
{
	uint32_t seed = 12345;
	char buf[512];
	struct log l;

	(void)state;
	for (int round = 0; round < 2000; round++) {
		size_t len = (size_t)(round % (int)sizeof(buf));
		int errs;

		for (size_t i = 0; i < len; i++) {
			seed = seed * 1103515245u + 12345u;
			/* Mostly INI punctuation, so the parser's paths get exercised. */
			buf[i] = "[]=;# \t\r\nab\0"[(seed >> 16) % 13];
		}
		errs = parse(buf, len, &l);
		/* Every error returned was also reported, with its line. */
		assert_int_equal(errs, l.errors);
	}
}

static void test_read_file_errors_and_content(void **state)
{
	char dir[] = "/tmp/test_cini.XXXXXX";
	char path[64];
	char *text;
	size_t len;
	int fd;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/missing.ini", dir);
	assert_int_equal(cini_read_file(path, &text, &len), -ENOENT);
	assert_int_equal(cini_read_file(dir, &text, &len), -EISDIR);

	snprintf(path, sizeof(path), "%s/a.ini", dir);
	fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, "[s]\nk=v", 7), 7);
	close(fd);
	assert_int_equal(cini_read_file(path, &text, &len), 0);
	assert_int_equal(len, 7);
	assert_memory_equal(text, "[s]\nk=v", 7);
	free(text);

	/* One byte over the limit is refused. */
	assert_int_equal(truncate(path, CINI_FILE_MAX + 1), 0);
	assert_int_equal(cini_read_file(path, &text, &len), -EFBIG);
	assert_int_equal(truncate(path, CINI_FILE_MAX), 0);
	assert_int_equal(cini_read_file(path, &text, &len), 0);
	assert_int_equal(len, CINI_FILE_MAX);
	free(text);
	unlink(path);
	rmdir(dir);
}

/* ---- cini_report: the loaders' one error reporter ---------------------- */

struct said {
	char file[64], msg[CINI_VALUE_MAX + 256];
	int line, calls;
	void *user;
};

static void say(void *user, const char *file, int line, const char *msg)
{
	struct said *s = user;

	snprintf(s->file, sizeof(s->file), "%s", file);
	snprintf(s->msg, sizeof(s->msg), "%s", msg);
	s->line = line;
	s->user = user;
	s->calls++;
}

static void test_report_counts_formats_and_names_the_file(void **state)
{
	struct said s = { .calls = 0 };
	struct cini_errs e = { .file = "a.ini", .fn = say, .user = &s };
	(void)state;
	cini_report(&e, 7, "%s: %d out of range %d..%d", "lives", 12, 1, 9);
	assert_int_equal(e.count, 1);
	assert_int_equal(s.calls, 1);
	assert_ptr_equal(s.user, &s);
	assert_string_equal(s.file, "a.ini");
	assert_int_equal(s.line, 7);
	assert_string_equal(s.msg, "lives: 12 out of range 1..9");
	e.file = "b.ini";
	cini_report(&e, 0, "cannot read");
	assert_int_equal(e.count, 2);
	assert_string_equal(s.file, "b.ini");
	assert_int_equal(s.line, 0);
}

/* Without a function problems are only counted. */
static void test_report_without_a_function_counts(void **state)
{
	struct cini_errs e = { .file = "a.ini" };
	(void)state;
	cini_report(&e, 1, "x");
	cini_report(&e, 2, "y");
	assert_int_equal(e.count, 2);
}

/* A whole over-long value fits in the message; past that it is cut. */
static void test_report_holds_a_whole_value(void **state)
{
	static char v[CINI_VALUE_MAX], big[2 * CINI_VALUE_MAX];
	struct said s = { .calls = 0 };
	struct cini_errs e = { .file = "a.ini", .fn = say, .user = &s };
	(void)state;
	memset(v, 'v', sizeof(v) - 1);
	cini_report(&e, 3, "key: '%s' is not an integer", v);
	assert_int_equal(strlen(s.msg), strlen(v) + strlen("key: '' is not an integer"));
	memset(big, 'b', sizeof(big) - 1);
	cini_report(&e, 3, "%s", big);
	assert_int_equal(strlen(s.msg), CINI_VALUE_MAX + 127);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_sections_entries_and_line_numbers),
		cmocka_unit_test(test_comments_whole_line_and_inline),
		cmocka_unit_test(test_crlf_bom_and_no_final_newline),
		cmocka_unit_test(test_entry_before_any_section_has_empty_section),
		cmocka_unit_test(test_malformed_lines_are_reported_and_parsing_goes_on),
		cmocka_unit_test(test_nul_byte_is_an_error_on_its_line),
		cmocka_unit_test(test_overlong_key_value_and_section),
		cmocka_unit_test(test_random_bytes_never_crash),
		cmocka_unit_test(test_read_file_errors_and_content),
		cmocka_unit_test(test_report_counts_formats_and_names_the_file),
		cmocka_unit_test(test_report_without_a_function_counts),
		cmocka_unit_test(test_report_holds_a_whole_value),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
