/*
 * Tests of the daemon's log (app/say.c): each line carries the sd-daemon
 * prefix of its priority when stderr is the journal's stream, and none on
 * anything else, so `journalctl -p warning` shows warnings and errors only.
 * stderr is pointed at a file of the test's own; "the journal's stream" is
 * that file, named in JOURNAL_STREAM as systemd names its socket.
 */
#include <inttypes.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "app/say.h"

struct cap {
	char path[64];
	int saved;               /* the test runner's stderr */
};

static int cap_setup(void **state)
{
	struct cap *c = calloc(1, sizeof(*c));
	int fd;

	if (!c)
		return -1;
	snprintf(c->path, sizeof(c->path), "/tmp/test_say.XXXXXX");
	fd = mkstemp(c->path);
	if (fd < 0)
		return -1;
	fflush(stderr);
	c->saved = dup(2);
	if (c->saved < 0 || dup2(fd, 2) < 0)
		return -1;
	close(fd);
	*state = c;
	return 0;
}

static int cap_teardown(void **state)
{
	struct cap *c = *state;

	fflush(stderr);
	dup2(c->saved, 2);
	close(c->saved);
	unlink(c->path);
	unsetenv("JOURNAL_STREAM");
	say_open();
	free(c);
	return 0;
}

/* JOURNAL_STREAM names stderr (journal 1) or not (0); then say_open. */
static void as_journal(int journal)
{
	struct stat st;
	char env[64];

	assert_int_equal(fstat(2, &st), 0);
	snprintf(env, sizeof(env), "%ju:%ju", (uintmax_t)st.st_dev,
		 (uintmax_t)st.st_ino + (journal ? 0 : 1));
	setenv("JOURNAL_STREAM", env, 1);
	say_open();
}

/* Everything written to stderr so far. */
static void captured(const struct cap *c, char *buf, size_t len)
{
	FILE *f;
	size_t n;

	fflush(stderr);
	f = fopen(c->path, "r");
	assert_non_null(f);
	n = fread(buf, 1, len - 1, f);
	buf[n] = '\0';
	fclose(f);
}

static void log_one_of_each(void)
{
	say("display: %s", "fbdev");
	say_warn("input %s: missing", "gpio");
	say_err("%s: not saved", "books");
	say_cfg(NULL, "a.ini", 3, "unknown key");
	say_cfg(NULL, "b.ini", 0, "cannot read");
}

static void test_journal_lines_carry_priorities(void **state)
{
	char buf[1024];

	as_journal(1);
	log_one_of_each();
	captured(*state, buf, sizeof(buf));
	assert_string_equal(buf, "<6>arcaded: display: fbdev\n"
				 "<4>arcaded: input gpio: missing\n"
				 "<3>arcaded: books: not saved\n"
				 "<4>arcaded: a.ini:3: unknown key\n"
				 "<4>arcaded: b.ini: cannot read\n");
}

static void test_no_prefix_elsewhere(void **state)
{
	char buf[1024];
	const char *want = "arcaded: display: fbdev\n"
			   "arcaded: input gpio: missing\n"
			   "arcaded: books: not saved\n"
			   "arcaded: a.ini:3: unknown key\n"
			   "arcaded: b.ini: cannot read\n";

	/* another stream than the one JOURNAL_STREAM names (a child's
	 * redirected stderr inherits the variable) */
	as_journal(0);
	log_one_of_each();
	captured(*state, buf, sizeof(buf));
	assert_string_equal(buf, want);
	/* no JOURNAL_STREAM at all (a terminal, a test) */
	assert_int_equal(ftruncate(2, 0), 0);
	assert_int_equal(lseek(2, 0, SEEK_SET), 0);
	unsetenv("JOURNAL_STREAM");
	say_open();
	log_one_of_each();
	captured(*state, buf, sizeof(buf));
	assert_string_equal(buf, want);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_journal_lines_carry_priorities, cap_setup,
						cap_teardown),
		cmocka_unit_test_setup_teardown(test_no_prefix_elsewhere, cap_setup, cap_teardown),
	};

	return cmocka_run_group_tests_name("say", tests, NULL, NULL);
}
