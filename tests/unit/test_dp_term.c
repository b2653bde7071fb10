/* Tests for display/dp_term.c, on a pseudo-terminal standing in for
 * stdin/stdout: terminal mode set and restored, the escape sequences sent,
 * half-block cells, sending only changed cells, the frame-rate limit, a
 * resize, and the emergency restore.
 *
 * While the pty replaces fds 0 and 1 nothing may be printed, so each test
 * collects what it needs, puts the fds back, then asserts.
 *
 * Geometry by hand: an 8x5 terminal leaves 8x4 cells (last line: status)
 * = 8x8 half-block pixels; an 8x8 frame fills it exactly at origin (0, 0).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "display/dp.h"

#define HALF "\xe2\x96\x80"
#define RED_ON_BLUE "\033[38;2;255;0;0;48;2;0;0;255m"

struct pty {
	int master, slave, saved0, saved1;
	struct termios orig;
};

static void pty_attach(struct pty *p, int cols, int rows)
{
	struct winsize ws = { .ws_row = (unsigned short)rows, .ws_col = (unsigned short)cols };

	assert_int_equal(openpty(&p->master, &p->slave, NULL, NULL, &ws), 0);
	assert_int_equal(tcgetattr(p->slave, &p->orig), 0);
	fcntl(p->master, F_SETFL, O_NONBLOCK);
	fflush(stdout);
	p->saved0 = dup(0);
	p->saved1 = dup(1);
	assert_true(p->saved0 >= 0 && p->saved1 >= 0);
	dup2(p->slave, 0);
	dup2(p->slave, 1);
}

static void pty_detach(struct pty *p)
{
	dup2(p->saved0, 0);
	dup2(p->saved1, 1);
	close(p->saved0);
	close(p->saved1);
}

static void pty_free(struct pty *p)
{
	close(p->master);
	close(p->slave);
}

/* Everything the terminal received so far (waits until it has been quiet
 * for quiet_ms). */
static char *drain_for(struct pty *p, size_t *len, int quiet_ms)
{
	size_t cap = 1 << 16, n = 0;
	char *buf = malloc(cap + 1);
	struct pollfd pf = { .fd = p->master, .events = POLLIN };

	while (buf && poll(&pf, 1, quiet_ms) > 0) {
		ssize_t r = read(p->master, buf + n, cap - n);

		if (r <= 0)
			break;
		n += (size_t)r;
	}
	if (buf)
		buf[n] = '\0';
	*len = n;
	return buf;
}

static char *drain(struct pty *p, size_t *len)
{
	return drain_for(p, len, 100);
}

static int count(const char *hay, const char *needle)
{
	int c = 0;

	while ((hay = strstr(hay, needle)) != NULL) {
		c++;
		hay += strlen(needle);
	}
	return c;
}

static void sleep_ms(int ms)
{
	struct timespec ts = { 0, ms * 1000000L };

	nanosleep(&ts, NULL);
}

static uint64_t now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000 + (uint64_t)ts.tv_nsec / 1000000;
}

static struct dp_config config(void)
{
	struct dp_config c;

	memset(&c, 0, sizeof(c));
	c.backend = "term";
	c.render_w = 8;
	c.render_h = 8;
	return c;
}

/* Palette: 1 red, 2 blue, 3 green. Frame: even rows red, odd rows blue, so
 * every cell is red over blue. */
static void make(uint8_t pal[256][3], uint8_t px[64])
{
	int i;

	memset(pal, 0, 256 * 3);
	pal[1][0] = 255;
	pal[2][2] = 255;
	pal[3][1] = 255;
	for (i = 0; i < 64; i++)
		px[i] = (i / 8) % 2 ? 2 : 1;
}

static void open_needs_terminal_on_stdout(void **state)
{
	struct dp_config c = config();
	struct dp *d = (struct dp *)1;
	char why[128];
	int saved = dup(1), null = open("/dev/null", O_WRONLY | O_CLOEXEC), rc;
	(void)state;

	fflush(stdout);
	dup2(null, 1);
	rc = dp_term.open(&c, &d, why, sizeof(why));
	dup2(saved, 1);
	close(saved);
	close(null);
	assert_int_equal(rc, -ENOTTY);
	assert_null(d);
	assert_string_equal(why, "stdout is not a terminal");
}

static void open_sets_mode_and_close_restores_it(void **state)
{
	struct dp_config c = config();
	struct termios during, after;
	struct pty p;
	struct dp *d = NULL;
	char why[128], *opened, *closed;
	size_t n1, n2;
	int rc;
	(void)state;

	pty_attach(&p, 8, 5);
	rc = dp_term.open(&c, &d, why, sizeof(why));
	tcgetattr(p.slave, &during);
	opened = drain(&p, &n1);
	dp_term.close(d);
	tcgetattr(p.slave, &after);
	closed = drain(&p, &n2);
	pty_detach(&p);

	assert_int_equal(rc, 0);
	assert_non_null(opened);
	assert_non_null(closed);
	/* raw-ish: no canonical mode, no echo, signals kept, reads never wait */
	assert_true(p.orig.c_lflag & ICANON);
	assert_false(during.c_lflag & ICANON);
	assert_false(during.c_lflag & ECHO);
	assert_true(during.c_lflag & ISIG);
	assert_int_equal(during.c_cc[VMIN], 0);
	assert_int_equal(during.c_cc[VTIME], 0);
	/* alternate screen, cursor hidden; then both undone */
	assert_non_null(strstr(opened, "\033[?1049h"));
	assert_non_null(strstr(opened, "\033[?25l"));
	assert_non_null(strstr(closed, "\033[?25h"));
	assert_non_null(strstr(closed, "\033[?1049l"));
	assert_int_equal(after.c_lflag, p.orig.c_lflag);
	assert_int_equal(after.c_iflag, p.orig.c_iflag);
	assert_memory_equal(after.c_cc, p.orig.c_cc, sizeof(after.c_cc));
	free(opened);
	free(closed);
	pty_free(&p);
}

static void present_sends_half_blocks_then_only_changes(void **state)
{
	struct dp_config c = config();
	uint8_t pal[256][3], px[64];
	struct pty p;
	struct dp *d = NULL;
	char why[128], *first, *same, *changed, *soon;
	size_t n1, n2, n3, n4;
	uint64_t t0, t1;
	int rc0, rc1, rc2, rc3, rc4;
	(void)state;

	make(pal, px);
	pty_attach(&p, 8, 5);
	rc0 = dp_term.open(&c, &d, why, sizeof(why));
	free(drain(&p, &n1));
	dp_term.set_palette(d, pal);
	rc1 = dp_term.present(d, px, 8, 8, 8);
	first = drain(&p, &n1);
	sleep_ms(40);
	rc2 = dp_term.present(d, px, 8, 8, 8);
	same = drain(&p, &n2);
	sleep_ms(40);
	px[2 * 8 + 3] = 3;   /* pixel (3, 2): top half of cell (3, 1) */
	rc3 = dp_term.present(d, px, 8, 8, 8);
	t0 = now_ms();
	px[0] = 3;
	rc4 = dp_term.present(d, px, 8, 8, 8);
	t1 = now_ms();
	changed = drain(&p, &n3);
	dp_term.close(d);
	soon = drain(&p, &n4);
	pty_detach(&p);

	assert_int_equal(rc0, 0);
	assert_int_equal(rc1, 0);
	assert_int_equal(rc2, 0);
	assert_int_equal(rc3, 0);
	assert_int_equal(rc4, 0);
	/* every one of the 8x4 cells, one colour change for all of them */
	assert_int_equal(count(first, HALF), 32);
	assert_int_equal(count(first, RED_ON_BLUE), 1);
	assert_int_equal(count(first, "\033[38;2;"), 1);
	/* status line cut to 8 columns: "arcaded " and not the dash after it */
	assert_non_null(strstr(first, "\033[5;1Harcaded "));
	assert_null(strstr(first, "arcaded \xe2"));
	/* unchanged frame: nothing at all */
	assert_int_equal(n2, 0);
	/* one cell: moved to row 2 column 4, green over (still) blue */
	assert_int_equal(count(changed, HALF), 1);
	assert_non_null(strstr(changed, "\033[2;4H\033[38;2;0;255;0m" HALF));
	assert_null(strstr(changed, "48;2;"));
	/* the present right after came within the 30 fps limit: skipped
	 * (checked only if it really came within 25 ms) */
	if (t1 - t0 < 25)
		assert_null(strstr(changed, "\033[1;1H"));
	free(first);
	free(same);
	free(changed);
	free(soon);
	pty_free(&p);
}

/* 10x5 terminal: 10x4 cells; the 8x8 frame (8 <= 10 wide) keeps 8x4 cells
 * centred at column (10 - 8) / 2 = 1, i.e. "\033[1;2H" for its first. */
static void resize_redraws_everything(void **state)
{
	struct dp_config c = config();
	struct winsize ws = { .ws_row = 5, .ws_col = 10 };
	uint8_t pal[256][3], px[64];
	struct pty p;
	struct dp *d = NULL;
	char why[128], *out;
	size_t n;
	int rc;
	(void)state;

	make(pal, px);
	pty_attach(&p, 8, 5);
	rc = dp_term.open(&c, &d, why, sizeof(why));
	dp_term.set_palette(d, pal);
	dp_term.present(d, px, 8, 8, 8);
	free(drain(&p, &n));
	ioctl(p.master, TIOCSWINSZ, &ws);
	sleep_ms(40);
	dp_term.present(d, px, 8, 8, 8);
	out = drain(&p, &n);
	dp_term.close(d);
	free(drain(&p, &n));
	pty_detach(&p);

	assert_int_equal(rc, 0);
	assert_non_null(strstr(out, "\033[2J"));
	assert_non_null(strstr(out, "\033[1;2H" RED_ON_BLUE HALF));
	assert_int_equal(count(out, HALF), 32);
	assert_non_null(strstr(out, "arcaded \xe2\x80\x94 "));   /* 10 columns */
	free(out);
	pty_free(&p);
}

/* A frame bigger than the terminal takes at once (200x60: 11800 cells,
 * each with new colours, some 400 KiB) stays pending and reaches the
 * terminal whole over the following presents (which send what is pending
 * whatever the frame rate), never blocking. */
static void output_the_terminal_cannot_take_yet_is_sent_later(void **state)
{
	struct dp_config c = config();
	uint8_t pal[256][3], *px = malloc(200 * 118);
	struct pty p;
	struct dp *d = NULL;
	char why[128], *all = malloc(1 << 20), *got;
	size_t total = 0, n, first = 0;
	int i, done = 0, halves = 0, rc, x, y;
	(void)state;

	assert_non_null(px);
	assert_non_null(all);
	/* even rows use indices 0..127 (red ramp), odd rows 128..255 (green):
	 * top and bottom of every cell differ, so every cell is a half block */
	for (i = 0; i < 256; i++) {
		pal[i][0] = i < 128 ? (uint8_t)(2 * i + 1) : 0;
		pal[i][1] = i < 128 ? 0 : (uint8_t)(2 * (i - 128) + 1);
		pal[i][2] = 0;
	}
	for (y = 0; y < 118; y++)
		for (x = 0; x < 200; x++)
			px[y * 200 + x] = (uint8_t)((x * 37 + y * 11) % 128 + (y % 2) * 128);
	c.render_w = 200;
	c.render_h = 118;
	pty_attach(&p, 200, 60);
	rc = dp_term.open(&c, &d, why, sizeof(why));
	free(drain(&p, &n));
	dp_term.set_palette(d, pal);
	dp_term.present(d, px, 200, 118, 200);
	for (i = 0; i < 4000 && !done; i++) {
		got = drain_for(&p, &n, i == 0 ? 100 : 5);
		if (i == 0)
			first = n;
		if (got && total + n < (1 << 20)) {
			/* count the glyphs of the new bytes (one may straddle) */
			size_t from = total > 2 ? total - 2 : 0;

			memcpy(all + total, got, n);
			total += n;
			all[total] = '\0';
			halves += count(all + from, HALF);
		}
		free(got);
		done = halves >= 200 * 59;
		dp_term.present(d, px, 200, 118, 200);
	}
	/* nothing more comes once it is all there */
	sleep_ms(40);
	dp_term.present(d, px, 200, 118, 200);
	got = drain(&p, &n);
	if (got && total + n < (1 << 20)) {
		memcpy(all + total, got, n);
		total += n;
	}
	free(got);
	all[total] = '\0';
	dp_term.close(d);
	free(drain(&p, &n));
	pty_detach(&p);

	assert_int_equal(rc, 0);
	assert_true(first < total);   /* it did not all go in one write */
	assert_int_equal(count(all, HALF), 200 * 59);
	assert_int_equal(count(all, "\033[2J"), 1);
	free(all);
	free(px);
	pty_free(&p);
}

static void emergency_restore_undoes_mode_and_screen(void **state)
{
	struct dp_config c = config();
	struct termios after;
	struct pty p;
	struct dp *d = NULL;
	char why[128], *out;
	size_t n;
	int rc;
	(void)state;

	pty_attach(&p, 8, 5);
	rc = dp_term.open(&c, &d, why, sizeof(why));
	free(drain(&p, &n));
	dp_emergency_restore();
	tcgetattr(p.slave, &after);
	out = drain(&p, &n);
	dp_term.close(d);
	free(drain(&p, &n));
	pty_detach(&p);

	assert_int_equal(rc, 0);
	assert_non_null(strstr(out, "\033[?25h"));
	assert_non_null(strstr(out, "\033[?1049l"));
	assert_int_equal(after.c_lflag, p.orig.c_lflag);
	free(out);
	pty_free(&p);
}

static void auto_picks_term_on_a_terminal(void **state)
{
	struct dp_config c = config();
	const struct dp_backend *be = NULL;
	struct pty p;
	struct dp *d = NULL;
	char why[256], *out;
	size_t n;
	int rc;
	(void)state;

	c.backend = "auto";
	c.card = "/nonexistent/card0"; /* no KMS either, whatever this machine has */
	c.device = "/nonexistent/fb0";
	pty_attach(&p, 8, 5);
	rc = dp_open(&c, &be, &d, why, sizeof(why));
	if (be)
		be->close(d);
	out = drain(&p, &n);
	pty_detach(&p);

	assert_int_equal(rc, 0);
	assert_ptr_equal(be, &dp_term);
	assert_string_equal(why, "kms: /nonexistent/card0: No such file or directory; "
			    "fbdev: /nonexistent/fb0: No such file or directory");
	free(out);
	pty_free(&p);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(open_needs_terminal_on_stdout),
		cmocka_unit_test(open_sets_mode_and_close_restores_it),
		cmocka_unit_test(present_sends_half_blocks_then_only_changes),
		cmocka_unit_test(resize_redraws_everything),
		cmocka_unit_test(output_the_terminal_cannot_take_yet_is_sent_later),
		cmocka_unit_test(emergency_restore_undoes_mode_and_screen),
		cmocka_unit_test(auto_picks_term_on_a_terminal),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
