/*
 * Tests of the service-manager notifications (systemd/svc.c) against a
 * notify socket of the test's own: what systemd would receive, the
 * watchdog interval from the environment, and no-ops outside systemd.
 */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cmocka.h>

#include "systemd/svc.h"

struct notify {
	char dir[64];
	char path[128];
	int fd;
};

static int sock_setup(void **state)
{
	struct notify *n = calloc(1, sizeof(*n));
	struct sockaddr_un a = { .sun_family = AF_UNIX };

	if (!n)
		return -1;
	snprintf(n->dir, sizeof(n->dir), "/tmp/test_svc.XXXXXX");
	if (!mkdtemp(n->dir))
		return -1;
	snprintf(n->path, sizeof(n->path), "%s/notify", n->dir);
	n->fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	if (n->fd < 0)
		return -1;
	if (snprintf(a.sun_path, sizeof(a.sun_path), "%s", n->path) >= (int)sizeof(a.sun_path))
		return -1;
	if (bind(n->fd, (struct sockaddr *)&a, sizeof(a)) != 0)
		return -1;
	setenv("NOTIFY_SOCKET", n->path, 1);
	*state = n;
	return 0;
}

static int sock_teardown(void **state)
{
	struct notify *n = *state;

	unsetenv("NOTIFY_SOCKET");
	unsetenv("WATCHDOG_USEC");
	unsetenv("WATCHDOG_PID");
	close(n->fd);
	unlink(n->path);
	rmdir(n->dir);
	free(n);
	return 0;
}

/* The next datagram, NUL-terminated; fails if none is waiting. */
static void receive(struct notify *n, char *buf, size_t len)
{
	ssize_t got = recv(n->fd, buf, len - 1, MSG_DONTWAIT);

	assert_true(got >= 0);
	buf[got] = '\0';
}

/* 1 if text has line as one of its newline-separated lines. */
static int has_line(const char *text, const char *line)
{
	size_t l = strlen(line);

	for (const char *p = text; p; p = strchr(p, '\n'), p = p ? p + 1 : NULL)
		if (strncmp(p, line, l) == 0 && (p[l] == '\n' || p[l] == '\0'))
			return 1;
	return 0;
}

static void test_ready_sends_ready_and_status(void **state)
{
	struct notify *n = *state;
	char msg[512];

	assert_true(svc_ready() > 0);
	receive(n, msg, sizeof(msg));
	assert_true(has_line(msg, "READY=1"));
	assert_true(has_line(msg, "STATUS=running"));
}

static void test_watchdog_ping_sends_watchdog(void **state)
{
	struct notify *n = *state;
	char msg[512];

	assert_true(svc_watchdog_ping() > 0);
	receive(n, msg, sizeof(msg));
	assert_string_equal(msg, "WATCHDOG=1");
}

static void test_stopping_sends_stopping(void **state)
{
	struct notify *n = *state;
	char msg[512];

	assert_true(svc_stopping() > 0);
	receive(n, msg, sizeof(msg));
	assert_string_equal(msg, "STOPPING=1");
}

static void test_status_is_formatted_on_one_line(void **state)
{
	struct notify *n = *state;
	char msg[512];

	assert_true(svc_status("tick %d of %s", 42, "play") > 0);
	receive(n, msg, sizeof(msg));
	assert_string_equal(msg, "STATUS=tick 42 of play");

	/* A newline in the text must not smuggle in READY=1. */
	assert_true(svc_status("bad\nREADY=%d", 1) > 0);
	receive(n, msg, sizeof(msg));
	assert_string_equal(msg, "STATUS=bad READY=1");
	assert_false(has_line(msg, "READY=1"));
}

static void test_watchdog_interval_is_half_of_usec(void **state)
{
	char pid[32];

	(void)state;
	snprintf(pid, sizeof(pid), "%ld", (long)getpid());
	setenv("WATCHDOG_USEC", "4000000", 1);
	setenv("WATCHDOG_PID", pid, 1);
	/* 4 s watchdog: ping every 2 s. */
	assert_int_equal(svc_watchdog_interval_ns(), 2000000000u);

	/* Meant for another process: not ours to ping. */
	snprintf(pid, sizeof(pid), "%ld", (long)getpid() + 1);
	setenv("WATCHDOG_PID", pid, 1);
	assert_int_equal(svc_watchdog_interval_ns(), 0);

	unsetenv("WATCHDOG_PID");
	unsetenv("WATCHDOG_USEC");
	assert_int_equal(svc_watchdog_interval_ns(), 0);
}

static void test_no_notify_socket_is_a_noop(void **state)
{
	struct notify *n = *state;
	char buf[64];

	unsetenv("NOTIFY_SOCKET");
	assert_int_equal(svc_ready(), 0);
	assert_int_equal(svc_watchdog_ping(), 0);
	assert_int_equal(svc_stopping(), 0);
	assert_int_equal(svc_status("x"), 0);
	/* Nothing reached the socket. */
	assert_int_equal(recv(n->fd, buf, sizeof(buf), MSG_DONTWAIT), -1);
	assert_int_equal(errno, EAGAIN);
	setenv("NOTIFY_SOCKET", n->path, 1);
}

static void test_unreachable_socket_is_an_error(void **state)
{
	struct notify *n = *state;
	char gone[192];

	snprintf(gone, sizeof(gone), "%s/absent", n->dir);
	setenv("NOTIFY_SOCKET", gone, 1);
	assert_true(svc_watchdog_ping() < 0);
	setenv("NOTIFY_SOCKET", n->path, 1);
}

/* JOURNAL_STREAM names the device and inode of the stream systemd gave
 * the service: only that fd is the journal. */
static void test_journal_fd_matches_only_journal_stream(void **state)
{
	char path[] = "/tmp/test_svc_journal.XXXXXX", env[64];
	int fd = mkstemp(path), other = open("/dev/null", O_WRONLY | O_CLOEXEC);
	struct stat st;

	(void)state;
	assert_true(fd >= 0);
	assert_true(other >= 0);
	assert_int_equal(fstat(fd, &st), 0);
	unsetenv("JOURNAL_STREAM");
	assert_int_equal(svc_journal_fd(fd), 0);
	snprintf(env, sizeof(env), "%ju:%ju", (uintmax_t)st.st_dev, (uintmax_t)st.st_ino);
	setenv("JOURNAL_STREAM", env, 1);
	assert_int_equal(svc_journal_fd(fd), 1);
	assert_int_equal(svc_journal_fd(other), 0);
	/* the same device, another inode; a malformed value */
	snprintf(env, sizeof(env), "%ju:%ju", (uintmax_t)st.st_dev, (uintmax_t)st.st_ino + 1);
	setenv("JOURNAL_STREAM", env, 1);
	assert_int_equal(svc_journal_fd(fd), 0);
	snprintf(env, sizeof(env), "%ju:%ju:", (uintmax_t)st.st_dev, (uintmax_t)st.st_ino);
	setenv("JOURNAL_STREAM", env, 1);
	assert_int_equal(svc_journal_fd(fd), 0);
	setenv("JOURNAL_STREAM", "x", 1);
	assert_int_equal(svc_journal_fd(fd), 0);
	assert_int_equal(svc_journal_fd(-1), 0);
	snprintf(env, sizeof(env), "%ju:%ju", (uintmax_t)st.st_dev, (uintmax_t)st.st_ino);
	setenv("JOURNAL_STREAM", env, 1);
	assert_int_equal(svc_journal_fd(-1), -EBADF);
	unsetenv("JOURNAL_STREAM");
	close(other);
	close(fd);
	unlink(path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_ready_sends_ready_and_status, sock_setup,
						sock_teardown),
		cmocka_unit_test_setup_teardown(test_watchdog_ping_sends_watchdog, sock_setup,
						sock_teardown),
		cmocka_unit_test_setup_teardown(test_stopping_sends_stopping, sock_setup,
						sock_teardown),
		cmocka_unit_test_setup_teardown(test_status_is_formatted_on_one_line, sock_setup,
						sock_teardown),
		cmocka_unit_test_setup_teardown(test_watchdog_interval_is_half_of_usec, sock_setup,
						sock_teardown),
		cmocka_unit_test_setup_teardown(test_no_notify_socket_is_a_noop, sock_setup,
						sock_teardown),
		cmocka_unit_test(test_journal_fd_matches_only_journal_stream),
		cmocka_unit_test_setup_teardown(test_unreachable_socket_is_an_error, sock_setup,
						sock_teardown),
	};

	return cmocka_run_group_tests_name("svc", tests, NULL, NULL);
}
