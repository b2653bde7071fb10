/*
 * scene: a display missing at start is waited for and taken when it
 * appears (app/scene.c). The display here is the file framebuffer in a
 * directory that does not exist yet (its open fails with ENOENT, as
 * fbdev's does before /dev/fb0 exists): the null display stands in,
 * nothing counts as shown, a retry before its time does nothing, and once
 * the directory exists the next retry takes the display, whose file then
 * holds the game's picture. A reason that changes is reported once; a
 * headless run never waits; "auto" waits when only the stand-in opened.
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
#include <sys/stat.h>
#include <unistd.h>

#include "app/ct.h"
#include "app/scene.h"
#include "engine/game/sim.h"

static char tmp[64], later[96], fb[128];
static struct ct ct;
static struct cfg cf;
static struct sim *sim;

static int setup(void **state)
{
	struct ct_spec spec = { .level = 1 };
	static const struct sim_settings set = { 1, 0, 0, 1, 3, 100, 1, 0, 0, 0 };
	char err[256];

	(void)state;
	snprintf(tmp, sizeof(tmp), "/tmp/test_scene.XXXXXX");
	if (!mkdtemp(tmp))
		return -1;
	snprintf(later, sizeof(later), "%s/later", tmp);
	snprintf(fb, sizeof(fb), "%s/fb", later);
	if (ct_load(&ct, &spec, err, sizeof(err)) < 0)
		return -1;
	sim = calloc(1, sizeof(*sim));
	if (!sim)
		return -1;
	sim_init(sim, ct.map, &set);
	return 0;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	free(sim);
	ct_free(&ct);
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmp);
	return system(cmd) == 0 ? 0 : -1;
}

/* The configuration: the file framebuffer at fb (its directory not made
 * yet), one thread. */
static void config(const char *backend)
{
	char cmd[128];

	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", later);
	assert_int_equal(system(cmd), 0);
	cfg_defaults(&cf);
	snprintf(cf.display.backend, sizeof(cf.display.backend), "%s", backend);
	snprintf(cf.display.file, sizeof(cf.display.file), "%s", fb);
	snprintf(cf.display.file_format, sizeof(cf.display.file_format), "xrgb8888");
	cf.display.file_width = 320;
	cf.display.file_height = 240;
	cf.game.render_threads = 1;
}

/* Distinct 32-bit values in the file framebuffer (0: no file). */
static int fb_values(void)
{
	static uint32_t px[320 * 240];
	uint32_t seen[8];
	int n = 0, fd = open(fb, O_RDONLY | O_CLOEXEC);
	ssize_t got;

	if (fd < 0)
		return 0;
	got = read(fd, px, sizeof(px));
	close(fd);
	assert_int_equal(got, (ssize_t)sizeof(px));
	for (size_t i = 0; i < sizeof(px) / sizeof(px[0]) && n < 8; i++) {
		int k = 0;
		while (k < n && seen[k] != px[i])
			k++;
		if (k == n)
			seen[n++] = px[i];
	}
	return n;
}

static void a_missing_display_is_waited_for_and_taken(void **state)
{
	struct scene s;
	uint64_t t = 5000000000ull;
	char why[sizeof(((struct scene *)0)->missing)];

	(void)state;
	config("file");
	memset(&s, 0, sizeof(s));
	assert_int_equal(scene_init(&s, &cf, &ct, 0, 160, 120), 0);
	/* the directory is missing: no error, a stand-in, the reason kept */
	assert_int_equal(scene_open_display(&s, 0), 0);
	assert_int_equal(s.waiting, 1);
	assert_non_null(strstr(s.missing, fb));
	assert_non_null(strstr(s.missing, strerror(ENOENT)));
	assert_true(s.dpb->flags & DP_SHOWS_NOTHING);
	assert_int_equal(scene_show(&s, sim, NULL, NULL, NULL), 0);
	assert_int_equal(s.shown, 0);                  /* nothing shown: no READY */
	/* still missing: the first try at once, then not before the retry time */
	snprintf(why, sizeof(why), "%s", s.missing);
	assert_int_equal(scene_poll_display(&s, t), SCENE_SAME);   /* same reason */
	assert_int_equal(mkdir(later, 0755), 0);
	assert_int_equal(scene_poll_display(&s, t + SCENE_RETRY_NS - 1), SCENE_SAME);
	assert_int_equal(s.waiting, 1);
	/* it is there now: taken at the next try, and shows the game */
	assert_int_equal(scene_poll_display(&s, t + SCENE_RETRY_NS), SCENE_ACQUIRED);
	assert_int_equal(s.waiting, 0);
	assert_null(s.hp);
	assert_false(s.dpb->flags & DP_SHOWS_NOTHING);
	assert_int_equal(fb_values(), 1);              /* cleared by its open */
	assert_int_equal(scene_show(&s, sim, NULL, NULL, NULL), 0);
	assert_int_equal(s.shown, 1);
	assert_true(fb_values() >= 4);                 /* a picture */
	assert_int_equal(scene_poll_display(&s, t + 10 * SCENE_RETRY_NS), SCENE_SAME);
	assert_string_equal(why, s.missing);           /* kept for the log */
	scene_free(&s);
}

static void a_new_reason_is_reported_once(void **state)
{
	struct scene s;
	uint64_t t = 5000000000ull;

	(void)state;
	config("file");
	/* a file where the directory should be: ENOTDIR, then ENOENT */
	assert_int_equal(close(open(later, O_WRONLY | O_CREAT | O_CLOEXEC, 0600)), 0);
	memset(&s, 0, sizeof(s));
	assert_int_equal(scene_init(&s, &cf, &ct, 0, 160, 120), 0);
	assert_int_equal(scene_open_display(&s, 0), 0);
	assert_non_null(strstr(s.missing, strerror(ENOTDIR)));
	assert_int_equal(unlink(later), 0);
	assert_int_equal(scene_poll_display(&s, t), SCENE_STILL_MISSING);
	assert_non_null(strstr(s.missing, strerror(ENOENT)));
	assert_int_equal(scene_poll_display(&s, t + SCENE_RETRY_NS), SCENE_SAME);
	assert_int_equal(s.waiting, 1);
	scene_free(&s);
}

static void headless_runs_do_not_wait(void **state)
{
	struct scene s;

	(void)state;
	config("file");
	memset(&s, 0, sizeof(s));
	assert_int_equal(scene_init(&s, &cf, &ct, 0, 160, 120), 0);
	assert_int_equal(scene_open_display(&s, 1), -ENOENT);
	assert_int_equal(s.waiting, 0);
	scene_free(&s);
}

/* "auto" with nothing but the stand-in: waits. The null display named in
 * the configuration: what was asked for, shown. */
static void auto_waits_and_a_named_null_display_does_not(void **state)
{
	struct scene s;
	int out = dup(1), null = open("/dev/null", O_WRONLY | O_CLOEXEC);

	(void)state;
	config("auto");
	cf.display.file[0] = '\0';
	snprintf(cf.display.device, sizeof(cf.display.device), "%s/fb0", later);
	/* stdout not a terminal, as under systemd: no terminal preview */
	assert_true(out >= 0 && null >= 0);
	assert_int_equal(dup2(null, 1), 1);
	memset(&s, 0, sizeof(s));
	assert_int_equal(scene_init(&s, &cf, &ct, 0, 160, 120), 0);
	assert_int_equal(scene_open_display(&s, 0), 0);
	assert_int_equal(dup2(out, 1), 1);
	close(out);
	close(null);
	assert_int_equal(s.waiting, 1);
	assert_non_null(strstr(s.missing, "fbdev"));
	assert_int_equal(scene_show(&s, sim, NULL, NULL, NULL), 0);
	assert_int_equal(s.shown, 0);
	scene_free(&s);

	config("null");
	memset(&s, 0, sizeof(s));
	assert_int_equal(scene_init(&s, &cf, &ct, 0, 160, 120), 0);
	assert_int_equal(scene_open_display(&s, 0), 0);
	assert_int_equal(s.waiting, 0);
	assert_int_equal(scene_show(&s, sim, NULL, NULL, NULL), 0);
	assert_int_equal(s.shown, 1);
	scene_free(&s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_missing_display_is_waited_for_and_taken),
		cmocka_unit_test(a_new_reason_is_reported_once),
		cmocka_unit_test(headless_runs_do_not_wait),
		cmocka_unit_test(auto_waits_and_a_named_null_display_does_not),
	};

	return cmocka_run_group_tests_name("scene", tests, setup, teardown);
}
