/* Tests for display/dp_kms.c. Without a KMS card: the refusals and their
 * reasons. With one this process may become DRM master of, and
 * ARCADED_TEST_DEVICES=1 (the VM tests set it and run these with the daemon
 * stopped, where nothing may skip; elsewhere the screen of whoever runs the
 * tests is left alone): frames reach
 * the screen by page flips, never a flip while one is pending (the
 * kernel's own EBUSY refusals are counted by the backend), the scanned-out
 * buffer holds the frame, the mode comes from the configuration, and a
 * card whose master is someone else is refused. Expected pixels are
 * computed here from the palette and the integer scale, not by px.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include "display/dp.h"

#define FW 320
#define FH 240

/* What a device case holds, released by teardown even when an assertion
 * ended the case (a display left open would keep DRM master and fail every
 * case after it). */
static struct dp *held;
static int held_fd = -1;

static int teardown(void **state)
{
	(void)state;
	if (held)
		dp_kms.close(held);
	held = NULL;
	if (held_fd >= 0)
		close(held_fd);
	held_fd = -1;
	return 0;
}

static struct dp_config config(const char *card)
{
	struct dp_config c;

	memset(&c, 0, sizeof(c));
	c.backend = "kms";
	c.card = card;
	c.tty = "";
	c.render_w = FW;
	c.render_h = FH;
	return c;
}

/* The first /dev/dri/cardN with a connected connector, or NULL. */
static const char *find_card(void)
{
	static char path[32];

	for (int i = 0; i < 16; i++) {
		drmModeRes *r;
		int fd, ok = 0;

		snprintf(path, sizeof(path), "/dev/dri/card%d", i);
		fd = open(path, O_RDWR | O_CLOEXEC);
		if (fd < 0)
			continue;
		r = drmModeGetResources(fd);
		for (int k = 0; r && k < r->count_connectors && !ok; k++) {
			drmModeConnector *c = drmModeGetConnector(fd, r->connectors[k]);

			ok = c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0;
			drmModeFreeConnector(c);
		}
		drmModeFreeResources(r);
		close(fd);
		if (ok)
			return path;
	}
	return NULL;
}

/* The card for the device cases, or skip (loudly). */
static const char *card_or_skip(void)
{
	const char *p;

	if (!getenv("ARCADED_TEST_DEVICES")) {
		printf("  (skipped: ARCADED_TEST_DEVICES=1 lets it take this machine's screen)\n");
		skip();
	}
	p = find_card();
	if (!p) {
		printf("  (skipped: no KMS card with a connected connector here)\n");
		skip();
	}
	return p;
}

static void missing_card_is_enoent_naming_it(void **state)
{
	struct dp_config c = config("/nonexistent/card7");
	struct dp *d = (struct dp *)1;
	char why[256];
	(void)state;

	assert_int_equal(dp_kms.open(&c, &d, why, sizeof(why)), -ENOENT);
	assert_null(d);
	assert_string_equal(why, "/nonexistent/card7: No such file or directory");
}

/* A regular file opens but answers no KMS ioctl. */
static void non_kms_file_is_refused(void **state)
{
	char path[] = "/tmp/test_dp_kms.XXXXXX";
	int fd = mkstemp(path);
	struct dp_config c = config(path);
	struct dp *d = (struct dp *)1;
	char why[256];
	(void)state;

	assert_true(fd >= 0);
	close(fd);
	assert_true(dp_kms.open(&c, &d, why, sizeof(why)) < 0);
	assert_null(d);
	assert_non_null(strstr(why, path));
	assert_non_null(strstr(why, "not a KMS device"));
	unlink(path);
}

static void four_buffers_are_refused(void **state)
{
	struct dp_config c = config("/nonexistent/card7");
	struct dp *d = (struct dp *)1;
	char why[256];
	(void)state;

	c.buffers = 4;
	assert_int_equal(dp_kms.open(&c, &d, why, sizeof(why)), -EINVAL);
	assert_null(d);
	assert_string_equal(why, "display.buffers 4: 2 or 3");
}

/* ---- with a card -------------------------------------------------------- */

static uint8_t pal[256][3];

static void make_palette(void)
{
	for (int i = 0; i < 256; i++) {
		pal[i][0] = (uint8_t)i;
		pal[i][1] = (uint8_t)(255 - i);
		pal[i][2] = (uint8_t)(i / 2);
	}
}

/* Frame k: index (x + y + k) & 255. */
static void make_frame(uint8_t *px, int k)
{
	for (int y = 0; y < FH; y++)
		for (int x = 0; x < FW; x++)
			px[y * FW + x] = (uint8_t)((x + y + k) & 255);
}

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* The number after key in the status line ("%llu flips issued"). */
static unsigned long long count_of(const char *status, const char *key)
{
	const char *p = strstr(status, key);

	assert_non_null(p);
	while (p > status && p[-1] == ' ')
		p--;
	while (p > status && p[-1] >= '0' && p[-1] <= '9')
		p--;
	return strtoull(p, NULL, 10);
}

/* n frames as fast as they come, serving the fd between them as the loop
 * does; every completed flip reported has shown >= presented. */
static void run_frames(struct dp *d, int n, int *flips_seen)
{
	static uint8_t px[FW * FH];
	struct dp_flip done[16];

	for (int k = 0; k < n; k++) {
		struct pollfd p = { .fd = dp_kms.wait_fd(d), .events = POLLIN };
		int m;

		make_frame(px, k);
		assert_int_equal(dp_kms.present(d, px, FW, FH, FW), 0);
		poll(&p, 1, 0);
		m = dp_kms.event(d, done, 16);
		assert_true(m >= 0);
		for (int i = 0; i < m; i++)
			assert_true(done[i].shown_ns >= done[i].presented_ns);
		*flips_seen += m;
	}
}

static void flips_never_while_pending(int buffers)
{
	struct dp_config c = config(card_or_skip());
	struct dp *d = NULL;
	char why[512];
	const char *st;
	unsigned long long flips, completed, busy, replaced, waits, setcrtc, overdue;
	int seen = 0, n = 200;
	uint64_t t;

	c.buffers = buffers;
	make_palette();
	assert_int_equal(dp_kms.open(&c, &d, why, sizeof(why)), 0);
	held = d;
	dp_kms.set_palette(d, pal);
	printf("  %s\n", dp_kms.describe(d));
	run_frames(d, n, &seen);
	/* let the last flip land */
	t = now_ns();
	while (now_ns() - t < 200000000u) {
		struct dp_flip done[16];
		struct pollfd p = { .fd = dp_kms.wait_fd(d), .events = POLLIN };

		if (poll(&p, 1, 20) == 1)
			seen += dp_kms.event(d, done, 16);
	}
	st = dp_kms.status(d);
	printf("  %d buffers: %s\n", buffers, st);
	flips = count_of(st, " flips issued");
	completed = count_of(st, " completed");
	busy = count_of(st, " refused as busy");
	replaced = count_of(st, " frames replaced");
	waits = count_of(st, " waits for a flip");
	setcrtc = count_of(st, " mode sets for frames");
	overdue = count_of(st, " overdue");
	assert_int_equal(busy, 0);
	assert_int_equal(overdue, 0);
	assert_int_equal(setcrtc, 0);
	assert_true(flips >= 1);
	assert_int_equal(completed, flips);
	assert_int_equal((unsigned long long)seen, completed);
	/* every frame was flipped or replaced by a newer one before its flip */
	assert_int_equal(flips + replaced, (unsigned long long)n);
	if (buffers == 2)
		assert_int_equal(replaced, 0);  /* no room to queue: it waits */
	else
		assert_int_equal(waits, 0);     /* always a free buffer */
	dp_kms.close(d);
	held = NULL;
}

static void two_buffers_flip_never_while_pending(void **state)
{
	(void)state;
	flips_never_while_pending(2);
}

static void three_buffers_flip_never_while_pending(void **state)
{
	(void)state;
	flips_never_while_pending(3);
}

/* The framebuffer the CRTC scans out, mapped through our own fd (root
 * gets handles of other clients' framebuffers). */
static void screen_holds_the_frame(void **state)
{
	struct dp_config c = config(card_or_skip());
	static uint8_t px[FW * FH];
	struct dp *d = NULL;
	char why[512];
	drmModeRes *res;
	drmModeCrtc *crtc = NULL;
	drmModeFB *fb;
	struct drm_mode_map_dumb md = { 0 };
	uint32_t *mem;
	int fd, k, ox, oy, bad = 0;
	uint64_t t;
	(void)state;

	make_palette();
	assert_int_equal(dp_kms.open(&c, &d, why, sizeof(why)), 0);
	held = d;
	dp_kms.set_palette(d, pal);
	make_frame(px, 7);
	assert_int_equal(dp_kms.present(d, px, FW, FH, FW), 0);
	t = now_ns();
	while (now_ns() - t < 300000000u) {
		struct dp_flip done[4];
		struct pollfd p = { .fd = dp_kms.wait_fd(d), .events = POLLIN };

		if (poll(&p, 1, 20) == 1)
			dp_kms.event(d, done, 4);
	}
	fd = held_fd = open(c.card, O_RDWR | O_CLOEXEC);
	assert_true(fd >= 0);
	res = drmModeGetResources(fd);
	assert_non_null(res);
	for (int i = 0; i < res->count_crtcs && !crtc; i++) {
		crtc = drmModeGetCrtc(fd, res->crtcs[i]);
		if (crtc && !crtc->buffer_id) {
			drmModeFreeCrtc(crtc);
			crtc = NULL;
		}
	}
	assert_non_null(crtc);
	fb = drmModeGetFB(fd, crtc->buffer_id);
	assert_non_null(fb);
	if (!fb->handle) {
		printf("  (skipped: no handle for the scanned-out framebuffer: not root)\n");
		skip();
	}
	assert_int_equal(fb->bpp, 32);
	md.handle = fb->handle;
	assert_int_equal(drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &md), 0);
	mem = mmap(NULL, (size_t)fb->pitch * fb->height, PROT_READ, MAP_SHARED, fd,
		   (off_t)md.offset);
	assert_true(mem != MAP_FAILED);
	/* integer scale k, centred (odd spare pixel right/bottom) */
	k = (int)(fb->width / FW < fb->height / FH ? fb->width / FW : fb->height / FH);
	assert_true(k >= 1);
	ox = ((int)fb->width - k * FW) / 2;
	oy = ((int)fb->height - k * FH) / 2;
	for (int y = 0; y < FH; y += 7)
		for (int x = 0; x < FW; x += 5) {
			uint8_t i = (uint8_t)((x + y + 7) & 255);
			uint32_t want = (uint32_t)pal[i][0] << 16 | (uint32_t)pal[i][1] << 8 |
					pal[i][2];
			uint32_t got = mem[(size_t)(oy + y * k + k / 2) * (fb->pitch / 4) +
					   (size_t)(ox + x * k + k / 2)];

			bad += (got & 0xffffff) != want;
		}
	if (ox > 0)
		bad += (mem[(size_t)(fb->height / 2) * (fb->pitch / 4)] & 0xffffff) != 0;
	printf("  screen %ux%u pitch %u, frame at %d,%d x%d: %d pixel(s) differ\n", fb->width,
	       fb->height, fb->pitch, ox, oy, k, bad);
	assert_int_equal(bad, 0);
	munmap(mem, (size_t)fb->pitch * fb->height);
	drmModeFreeFB(fb);
	drmModeFreeCrtc(crtc);
	drmModeFreeResources(res);
}

static void configured_mode_is_used_or_refused(void **state)
{
	struct dp_config c = config(card_or_skip());
	struct dp *d = NULL;
	char why[1024], want[32], size[40];
	drmModeRes *res;
	drmModeConnector *conn = NULL;
	int fd;
	(void)state;

	fd = open(c.card, O_RDWR | O_CLOEXEC);
	assert_true(fd >= 0);
	res = drmModeGetResources(fd);
	for (int i = 0; res && i < res->count_connectors && !conn; i++) {
		conn = drmModeGetConnector(fd, res->connectors[i]);
		if (conn && (conn->connection != DRM_MODE_CONNECTED || !conn->count_modes)) {
			drmModeFreeConnector(conn);
			conn = NULL;
		}
	}
	assert_non_null(conn);
	/* the last mode the connector lists, usually not the preferred one */
	snprintf(want, sizeof(want), "%ux%u", conn->modes[conn->count_modes - 1].hdisplay,
		 conn->modes[conn->count_modes - 1].vdisplay);
	snprintf(size, sizeof(size), " %s@", want);
	drmModeFreeConnector(conn);
	drmModeFreeResources(res);
	close(fd);

	c.mode = want;
	assert_int_equal(dp_kms.open(&c, &d, why, sizeof(why)), 0);
	held = d;
	printf("  display.mode %s: %s\n", want, dp_kms.describe(d));
	assert_non_null(strstr(dp_kms.describe(d), size));
	dp_kms.close(d);
	held = NULL;

	c.mode = "12345x7";
	assert_int_equal(dp_kms.open(&c, &d, why, sizeof(why)), -ENOENT);
	assert_null(d);
	assert_non_null(strstr(why, ": no mode 12345x7 (has "));
	assert_non_null(strstr(why, size + 1));
	c.mode = "1280by800";
	assert_int_equal(dp_kms.open(&c, &d, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "display.mode \"1280by800\": not WxH or WxH@Hz");
}

/* Another open file of the card is master first: the mode set is refused
 * and the reason says why. */
static void card_with_another_master_is_refused(void **state)
{
	struct dp_config c = config(card_or_skip());
	struct dp *d = (struct dp *)1;
	char why[512];
	int fd;
	(void)state;

	fd = held_fd = open(c.card, O_RDWR | O_CLOEXEC);
	assert_true(fd >= 0);
	if (drmSetMaster(fd) != 0) {
		printf("  (skipped: cannot become master of %s here)\n", c.card);
		skip();
	}
	assert_true(dp_kms.open(&c, &d, why, sizeof(why)) < 0);
	assert_null(d);
	printf("  %s\n", why);
	assert_non_null(strstr(why, "(another process is DRM master)"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(missing_card_is_enoent_naming_it),
		cmocka_unit_test(non_kms_file_is_refused),
		cmocka_unit_test(four_buffers_are_refused),
		cmocka_unit_test_teardown(two_buffers_flip_never_while_pending, teardown),
		cmocka_unit_test_teardown(three_buffers_flip_never_while_pending, teardown),
		cmocka_unit_test_teardown(screen_holds_the_frame, teardown),
		cmocka_unit_test_teardown(configured_mode_is_used_or_refused, teardown),
		cmocka_unit_test_teardown(card_with_another_master_is_refused, teardown),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
