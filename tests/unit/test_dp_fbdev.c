/* Tests for display/dp_fbdev.c: what can be checked without a framebuffer
 * device (the refusals and their reasons). The present path itself is
 * px_panel_draw, tested through the file framebuffer (test_dp_file.c) and
 * px (test_px.c). A real /dev/fb0, when the machine has one and we may
 * open it, is opened read-only here just to say so: writing it would
 * disturb the console of whoever runs the tests. */
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
#include <unistd.h>

#include "display/dp.h"

static struct dp_config config(const char *device)
{
	struct dp_config c;

	memset(&c, 0, sizeof(c));
	c.backend = "fbdev";
	c.device = device;
	c.tty = "";
	c.render_w = 320;
	c.render_h = 240;
	return c;
}

static void missing_device_is_enoent_naming_it(void **state)
{
	struct dp_config c = config("/nonexistent/fb7");
	struct dp *d = (struct dp *)1;
	char why[256];
	(void)state;

	assert_int_equal(dp_fbdev.open(&c, &d, why, sizeof(why)), -ENOENT);
	assert_null(d);
	assert_string_equal(why, "/nonexistent/fb7: No such file or directory");
}

/* A regular file opens but answers no framebuffer ioctl. */
static void non_framebuffer_is_refused_at_screen_info(void **state)
{
	char path[] = "/tmp/test_dp_fbdev.XXXXXX";
	int fd = mkstemp(path);
	struct dp_config c = config(path);
	struct dp *d = (struct dp *)1;
	char why[256];
	(void)state;

	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(dp_fbdev.open(&c, &d, why, sizeof(why)), -ENOTTY);
	assert_null(d);
	assert_non_null(strstr(why, path));
	assert_non_null(strstr(why, "screen info"));
	unlink(path);
}

static void default_device_is_dev_fb0(void **state)
{
	struct dp_config c = config(NULL);
	struct dp *d = NULL;
	char why[256];
	int fd;
	(void)state;

	fd = open("/dev/fb0", O_RDONLY | O_CLOEXEC);
	if (fd >= 0) {
		const char *dev = getenv("ARCADED_TEST_DEVICES");

		close(fd);
		if (!dev || strcmp(dev, "1") != 0) {
			printf("  (skipped: /dev/fb0 exists here; ARCADED_TEST_DEVICES=1 lets it open it)\n");
			skip();
		}
		/* a machine given to the tests (the VM): the default is that one */
		assert_int_equal(dp_fbdev.open(&c, &d, why, sizeof(why)), 0);
		assert_non_null(d);
		assert_non_null(strstr(dp_fbdev.describe(d), "/dev/fb0"));
		dp_fbdev.close(d);
		return;
	}
	assert_true(dp_fbdev.open(&c, &d, why, sizeof(why)) < 0);
	assert_null(d);
	assert_true(strncmp(why, "/dev/fb0: ", 10) == 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(missing_device_is_enoent_naming_it),
		cmocka_unit_test(non_framebuffer_is_refused_at_screen_info),
		cmocka_unit_test(default_device_is_dev_fb0),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
