/* Tests for display/dp.c: backend by name, the automatic choice and the
 * reasons it gives. stdout is pointed at /dev/null around each dp_open so
 * "stdout is not a terminal" holds whatever runs the tests. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include "display/dp.h"

#define NOFB "/nonexistent/fb0"
#define NOCARD "/nonexistent/card0"

struct fixture {
	char dir[64];
	char path[96];
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	if (!f)
		return -1;
	snprintf(f->dir, sizeof(f->dir), "/tmp/test_dp.XXXXXX");
	if (!mkdtemp(f->dir))
		return -1;
	snprintf(f->path, sizeof(f->path), "%s/fb", f->dir);
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fixture *f = *state;

	unlink(f->path);
	rmdir(f->dir);
	free(f);
	return 0;
}

static struct dp_config config(const char *backend, const char *file)
{
	struct dp_config c;

	memset(&c, 0, sizeof(c));
	c.backend = backend;
	c.card = NOCARD;
	c.device = NOFB;
	c.tty = "";
	c.file = file;
	c.file_w = 8;
	c.file_h = 6;
	c.file_format = "xrgb8888";
	c.render_w = 4;
	c.render_h = 3;
	return c;
}

/* dp_open with stdout on /dev/null. */
static int open_off_tty(const struct dp_config *c, const struct dp_backend **be,
			struct dp **d, char *why, size_t whylen)
{
	int saved = dup(1), null = open("/dev/null", O_WRONLY | O_CLOEXEC), rc;

	assert_true(saved >= 0 && null >= 0);
	fflush(stdout);
	assert_int_equal(dup2(null, 1), 1);
	rc = dp_open(c, be, d, why, whylen);
	assert_int_equal(dup2(saved, 1), 1);
	close(saved);
	close(null);
	return rc;
}

static void auto_without_fb_or_tty_picks_file(void **state)
{
	struct fixture *f = *state;
	struct dp_config c = config("auto", f->path);
	const struct dp_backend *be;
	struct dp *d;
	char why[512];

	assert_int_equal(open_off_tty(&c, &be, &d, why, sizeof(why)), 0);
	assert_ptr_equal(be, &dp_file);
	assert_non_null(d);
	assert_string_equal(why, "kms: " NOCARD ": No such file or directory; fbdev: " NOFB
				 ": No such file or directory; "
				 "term: stdout is not a terminal");
	be->close(d);
}

static void auto_without_file_picks_null(void **state)
{
	struct dp_config c = config(NULL, NULL);
	const struct dp_backend *be;
	struct dp *d;
	char why[512];
	uint8_t px[12] = { 0 };
	(void)state;

	assert_int_equal(open_off_tty(&c, &be, &d, why, sizeof(why)), 0);
	assert_ptr_equal(be, &dp_null);
	assert_string_equal(why, "kms: " NOCARD ": No such file or directory; fbdev: " NOFB
				 ": No such file or directory; "
				 "term: stdout is not a terminal; file: no file configured");
	assert_string_equal(be->describe(d), "null");
	assert_int_equal(be->present(d, px, 4, 3, 4), 0);
	assert_int_equal(be->present(d, px, 4, 3, 3), -EINVAL);
	be->close(d);
}

static void auto_skips_broken_file_with_its_reason(void **state)
{
	struct fixture *f = *state;
	struct dp_config c = config("auto", f->path);
	const struct dp_backend *be;
	struct dp *d;
	char why[512];

	c.file_format = "rgb332";
	assert_int_equal(open_off_tty(&c, &be, &d, why, sizeof(why)), 0);
	assert_ptr_equal(be, &dp_null);
	assert_non_null(strstr(why, "; file: "));
	assert_non_null(strstr(why, "rgb332"));
	be->close(d);
}

static void why_is_truncated_not_overrun(void **state)
{
	struct dp_config c = config("auto", NULL);
	const struct dp_backend *be;
	struct dp *d;
	char why[24];
	(void)state;

	memset(why, 'x', sizeof(why));
	assert_int_equal(open_off_tty(&c, &be, &d, why, 16), 0);
	assert_int_equal(strlen(why), 15);
	assert_int_equal(why[16], 'x');
	be->close(d);
}

static void named_backend_is_used_and_reports_its_own_error(void **state)
{
	struct dp_config c = config("null", NULL);
	const struct dp_backend *be;
	struct dp *d;
	char why[512];
	(void)state;

	assert_int_equal(open_off_tty(&c, &be, &d, why, sizeof(why)), 0);
	assert_ptr_equal(be, &dp_null);
	assert_string_equal(why, "");
	be->close(d);

	c = config("fbdev", NULL);
	assert_int_equal(open_off_tty(&c, &be, &d, why, sizeof(why)), -ENOENT);
	assert_null(be);
	assert_null(d);
	assert_string_equal(why, NOFB ": No such file or directory");

	c = config("term", NULL);
	assert_int_equal(open_off_tty(&c, &be, &d, why, sizeof(why)), -ENOTTY);
	assert_string_equal(why, "stdout is not a terminal");
}

static void unknown_backend_is_einval(void **state)
{
	struct dp_config c = config("sdl", NULL);
	const struct dp_backend *be;
	struct dp *d;
	char why[512];
	(void)state;

	assert_int_equal(open_off_tty(&c, &be, &d, why, sizeof(why)), -EINVAL);
	assert_null(be);
	assert_non_null(strstr(why, "\"sdl\""));
}

/* Open file descriptors of this process. */
static int open_fds(void)
{
	DIR *d = opendir("/proc/self/fd");
	struct dirent *e;
	int n = 0;

	assert_non_null(d);
	while ((e = readdir(d)))
		n += e->d_name[0] != '.';
	closedir(d);
	return n - 1;                  /* the directory's own fd */
}

/* With no display ever opened, the crash handler's restore and the
 * backends' close of NULL change nothing a user could see: no byte is
 * written to stdout or stderr (the terminal backend's restore writes an
 * escape sequence when it is active), no descriptor is opened or closed,
 * and the terminal's mode (when stdin is one) is unchanged. */
static void emergency_restore_without_display_is_harmless(void **state)
{
	char path[] = "/tmp/test_dp.XXXXXX";
	int fd = mkstemp(path), out = dup(1), err = dup(2), fds, tty;
	struct termios before, after;
	struct stat st;
	(void)state;
	assert_true(fd >= 0 && out >= 0 && err >= 0);
	unlink(path);
	tty = tcgetattr(0, &before) == 0;
	fflush(stdout);
	fflush(stderr);
	assert_true(dup2(fd, 1) == 1 && dup2(fd, 2) == 2);
	fds = open_fds();
	dp_emergency_restore();
	dp_emergency_restore();
	dp_null.close(NULL);
	dp_file.close(NULL);
	dp_fbdev.close(NULL);
	dp_term.close(NULL);
	assert_int_equal(open_fds(), fds);
	fflush(stdout);
	fflush(stderr);
	dup2(out, 1);
	dup2(err, 2);
	close(out);
	close(err);
	assert_int_equal(fstat(fd, &st), 0);
	close(fd);
	assert_int_equal(st.st_size, 0);
	if (tty) {
		assert_int_equal(tcgetattr(0, &after), 0);
		assert_memory_equal(&before, &after, sizeof before);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(auto_without_fb_or_tty_picks_file, setup, teardown),
		cmocka_unit_test(auto_without_file_picks_null),
		cmocka_unit_test_setup_teardown(auto_skips_broken_file_with_its_reason, setup,
						teardown),
		cmocka_unit_test(why_is_truncated_not_overrun),
		cmocka_unit_test(named_backend_is_used_and_reports_its_own_error),
		cmocka_unit_test(unknown_backend_is_einval),
		cmocka_unit_test(emergency_restore_without_display_is_harmless),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
