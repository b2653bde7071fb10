/*
 * Tests of the terminal input backend (input/in_tty.c) on a pseudo-
 * terminal: bytes written to the master come out as keys, releases are
 * synthesized with no byte arriving, standard input keeps its flags, a
 * hang-up is -ENODEV. The decoding rules themselves are tested in
 * test_ttyk.c.
 */
#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>
#include <linux/input-event-codes.h>

#include "input/in.h"
#include "input/ttyk.h"

struct pty {
	int master;
	int slave;               /* kept open to hold the raw mode */
	char path[64];
};

static void pty_open(struct pty *p)
{
	struct termios t;

	p->master = posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC);
	assert_true(p->master >= 0);
	assert_int_equal(grantpt(p->master), 0);
	assert_int_equal(unlockpt(p->master), 0);
	assert_int_equal(ptsname_r(p->master, p->path, sizeof(p->path)), 0);
	p->slave = open(p->path, O_RDWR | O_NOCTTY | O_CLOEXEC);
	assert_true(p->slave >= 0);
	/* What dp_term does: raw, reads return at once. */
	assert_int_equal(tcgetattr(p->slave, &t), 0);
	cfmakeraw(&t);
	t.c_cc[VMIN] = 0;
	t.c_cc[VTIME] = 0;
	assert_int_equal(tcsetattr(p->slave, TCSANOW, &t), 0);
}

static void pty_close(struct pty *p)
{
	if (p->master >= 0)
		close(p->master);
	close(p->slave);
}

static void pty_type(struct pty *p, const char *s)
{
	assert_int_equal(write(p->master, s, strlen(s)), (ssize_t)strlen(s));
}

static void sleep_ms(int ms)
{
	struct timespec ts = { .tv_sec = ms / 1000, .tv_nsec = (long)(ms % 1000) * 1000000 };

	nanosleep(&ts, NULL);
}

/* Reads every few ms until n events came or timeout_ms passed. */
static int read_until(struct in_dev *d, struct in_event *ev, int n, int timeout_ms)
{
	int got = 0;

	for (int waited = 0; got < n && waited <= timeout_ms; waited += 5) {
		int r = in_tty.read(d, ev + got, n - got);

		assert_true(r >= 0);
		got += r;
		if (got < n)
			sleep_ms(5);
	}
	return got;
}

static void test_open_non_terminal_path_is_enotty(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	char why[128];

	(void)state;
	assert_int_equal(in_tty.open("/dev/null", &d, why, sizeof(why)), -ENOTTY);
	assert_null(d);
	assert_non_null(strstr(why, "/dev/null"));
	assert_int_equal(in_tty.open("/nonexistent/tty", &d, why, sizeof(why)), -ENOENT);
	assert_null(d);
}

static void test_open_stdin_not_a_terminal_is_enotty(void **state)
{
	struct in_dev *d = (struct in_dev *)1;
	char why[128];
	int saved = dup(0), null = open("/dev/null", O_RDONLY | O_CLOEXEC);

	(void)state;
	assert_true(saved >= 0 && null >= 0);
	assert_int_equal(dup2(null, 0), 0);
	assert_int_equal(in_tty.open(NULL, &d, why, sizeof(why)), -ENOTTY);
	assert_null(d);
	assert_true(why[0] != '\0');
	assert_int_equal(dup2(saved, 0), 0);
	close(saved);
	close(null);
}

static void test_arrow_press_then_synthesized_release(void **state)
{
	struct pty p;
	struct in_dev *d;
	struct in_event ev[4];
	char why[128];
	uint64_t t0, t1, t2;

	(void)state;
	pty_open(&p);
	assert_int_equal(in_tty.open(p.path, &d, why, sizeof(why)), 0);
	assert_non_null(strstr(in_tty.describe(d), p.path));
	assert_true(in_tty.fd(d) >= 0);
	assert_int_equal(in_tty.read(d, ev, 4), 0);

	t0 = in_now_ns();
	pty_type(&p, "\x1b[A");
	assert_int_equal(read_until(d, ev, 1, 1000), 1);
	t1 = in_now_ns();
	assert_int_equal(ev[0].type, IN_KEY);
	assert_int_equal(ev[0].code, KEY_UP);
	assert_int_equal(ev[0].value, 1);
	assert_true(ev[0].time_ns >= t0 && ev[0].time_ns <= t1);

	/* No more bytes: the release comes from the reads alone, one first
	 * hold-off after the press. */
	assert_int_equal(read_until(d, ev + 1, 1, 2000), 1);
	t2 = in_now_ns();
	assert_int_equal(ev[1].code, KEY_UP);
	assert_int_equal(ev[1].value, 0);
	assert_true(ev[1].time_ns - ev[0].time_ns >= TTYK_FIRST_HOLD_NS);
	assert_true(ev[1].time_ns <= t2);
	in_tty.close(d);
	pty_close(&p);
}

static void test_stdin_terminal_keeps_its_flags(void **state)
{
	struct pty p;
	struct in_dev *d;
	struct in_event ev[4];
	char why[128];
	int saved = dup(0), flags;

	(void)state;
	pty_open(&p);
	assert_true(saved >= 0);
	assert_int_equal(dup2(p.slave, 0), 0);
	flags = fcntl(0, F_GETFL);
	assert_int_equal(in_tty.open(NULL, &d, why, sizeof(why)), 0);
	assert_int_equal(in_tty.fd(d), 0);
	pty_type(&p, "x");
	assert_int_equal(read_until(d, ev, 1, 1000), 1);
	assert_int_equal(ev[0].code, KEY_X);
	/* O_NONBLOCK would be shared with stdout through the open file
	 * description: the backend must not have set it. */
	assert_int_equal(fcntl(0, F_GETFL), flags);
	in_tty.close(d);
	assert_true(fcntl(0, F_GETFD) >= 0);   /* fd 0 is not closed */
	assert_int_equal(dup2(saved, 0), 0);
	close(saved);
	pty_close(&p);
}

static void test_hangup_is_enodev(void **state)
{
	struct pty p;
	struct in_dev *d;
	struct in_event ev[4];
	char why[128];

	(void)state;
	pty_open(&p);
	assert_int_equal(in_tty.open(p.path, &d, why, sizeof(why)), 0);
	close(p.master);
	p.master = -1;
	assert_int_equal(in_tty.read(d, ev, 4), -ENODEV);
	in_tty.close(d);
	pty_close(&p);
}

static void test_close_null_is_safe(void **state)
{
	(void)state;
	in_tty.close(NULL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_open_non_terminal_path_is_enotty),
		cmocka_unit_test(test_open_stdin_not_a_terminal_is_enotty),
		cmocka_unit_test(test_arrow_press_then_synthesized_release),
		cmocka_unit_test(test_stdin_terminal_keeps_its_flags),
		cmocka_unit_test(test_hangup_is_enodev),
		cmocka_unit_test(test_close_null_is_safe),
	};

	return cmocka_run_group_tests_name("in_tty", tests, NULL, NULL);
}
