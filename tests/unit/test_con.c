/* Tests for display/con.c. Without a console: the refusals and that
 * nothing is held. With /dev/tty0 and ARCADED_TEST_DEVICES=1 (the VM tests
 * set it and run these as root, where nothing may skip; elsewhere the
 * console of whoever runs the tests is left alone): graphics mode and
 * keyboard off while held, the VT signals become requests, and leaving
 * puts text mode and the keyboard back, as read through the console's own
 * ioctls. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "display/con.h"

static void empty_tty_is_left_alone(void **state)
{
	char note[160];
	(void)state;

	assert_int_equal(con_enter("", 1, note, sizeof(note)), 0);
	assert_string_equal(note, "console left alone");
	assert_int_equal(con_vt_requests(), 0);
	assert_int_equal(con_vt_release(), -EBADF);
	assert_int_equal(con_vt_acquire(), -EBADF);
	con_leave();      /* not held: nothing to do */
	con_emergency();
}

static void missing_tty_is_left_alone_with_its_reason(void **state)
{
	char note[160];
	(void)state;

	assert_int_equal(con_enter("/nonexistent/tty9", 0, note, sizeof(note)), 0);
	assert_string_equal(note, "console /nonexistent/tty9: No such file or directory "
				  "(left alone)");
}

/* A regular file answers no console ioctl. */
static void non_console_is_left_alone(void **state)
{
	char path[] = "/tmp/test_con.XXXXXX", note[160];
	int fd = mkstemp(path);
	(void)state;

	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(con_enter(path, 0, note, sizeof(note)), 0);
	assert_non_null(strstr(note, "(left alone)"));
	assert_int_equal(con_vt_requests(), 0);
	unlink(path);
}

/* The console's display mode, keyboard mode and VT mode, from a fd of its
 * own; 0 or -1 when it cannot be read. */
static int modes(int *kd, int *kb, int *vt)
{
	struct vt_mode m;
	int fd = open("/dev/tty0", O_RDWR | O_NOCTTY | O_CLOEXEC), rc = 0;

	if (fd < 0)
		return -1;
	if (ioctl(fd, KDGETMODE, kd) < 0 || ioctl(fd, KDGKBMODE, kb) < 0 ||
	    ioctl(fd, VT_GETMODE, &m) < 0)
		rc = -1;
	*vt = m.mode;
	close(fd);
	return rc;
}

static void console_is_taken_and_given_back(void **state)
{
	char note[160];
	int kd0, kb0, vt0, kd, kb, vt;
	(void)state;

	if (!getenv("ARCADED_TEST_DEVICES")) {
		printf("  (skipped: ARCADED_TEST_DEVICES=1 lets it take this machine's console)\n");
		skip();
	}
	if (modes(&kd0, &kb0, &vt0) < 0) {
		printf("  (skipped: no /dev/tty0 console here)\n");
		skip();
	}
	if (con_enter("/dev/tty0", 1, note, sizeof(note)) != 1) {
		printf("  (skipped: %s)\n", note);
		skip();
	}
	printf("  %s\n", note);
	assert_string_equal(note, "console /dev/tty0 graphics, keyboard off, VT switching by "
				  "signals");
	assert_int_equal(modes(&kd, &kb, &vt), 0);
	assert_int_equal(kd, KD_GRAPHICS);
	assert_int_equal(kb, K_OFF);
	assert_int_equal(vt, VT_PROCESS);
	/* a second display finds it held */
	assert_int_equal(con_enter("/dev/tty0", 0, note, sizeof(note)), 0);
	assert_string_equal(note, "console left alone (held by another display)");
	/* the kernel's signals, as it sends them on a switch away and back */
	assert_int_equal(con_vt_requests(), 0);
	raise(SIGRTMIN + 2);
	assert_int_equal(con_vt_requests(), CON_VT_RELEASE);
	assert_int_equal(con_vt_requests(), 0);
	raise(SIGRTMIN + 3);
	raise(SIGRTMIN + 2);
	assert_int_equal(con_vt_requests(), CON_VT_RELEASE | CON_VT_ACQUIRE);
	con_leave();
	assert_int_equal(modes(&kd, &kb, &vt), 0);
	assert_int_equal(kd, kd0 == KD_GRAPHICS ? KD_TEXT : kd0);
	assert_int_equal(kb, kb0 == K_OFF ? K_UNICODE : kb0);
	assert_int_equal(vt, VT_AUTO);
	assert_int_equal(con_vt_requests(), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(empty_tty_is_left_alone),
		cmocka_unit_test(missing_tty_is_left_alone_with_its_reason),
		cmocka_unit_test(non_console_is_left_alone),
		cmocka_unit_test(console_is_taken_and_given_back),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
