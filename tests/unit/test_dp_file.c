/* Tests for display/dp_file.c: the file framebuffer end to end (open,
 * palette, present, read the file back).
 *
 * The palette gives frame pixel (x, y) of the 4x3 test frame the colour
 * r = 33x, g = 65y, b = 255, all distinct, so every pixel's destination is
 * checked. Expected panel values by hand: xrgb8888 is the bytes themselves;
 * rgb565 rounds 33x * 31/255 = 4.01x -> 4x and 65y * 63/255 = 16.06y -> 16y,
 * blue 255 -> 31.
 */
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
#include <sys/stat.h>
#include <unistd.h>

#include "display/dp.h"

#define FW 4
#define FH 3

struct fixture {
	char dir[64];
	char path[96];
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	if (!f)
		return -1;
	snprintf(f->dir, sizeof(f->dir), "/tmp/test_dp_file.XXXXXX");
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

static void make_palette(uint8_t pal[256][3])
{
	int x, y;

	memset(pal, 0, 256 * 3);
	for (y = 0; y < FH; y++)
		for (x = 0; x < FW; x++) {
			uint8_t *c = pal[1 + y * FW + x];

			c[0] = (uint8_t)(33 * x);
			c[1] = (uint8_t)(65 * y);
			c[2] = 255;
		}
}

static void make_frame(uint8_t *px, int pitch)
{
	int x, y;

	memset(px, 0, (size_t)pitch * FH);
	for (y = 0; y < FH; y++)
		for (x = 0; x < FW; x++)
			px[y * pitch + x] = (uint8_t)(1 + y * FW + x);
}

static uint8_t *read_file(const char *path, size_t *len)
{
	struct stat st;
	uint8_t *buf;
	int fd = open(path, O_RDONLY | O_CLOEXEC);

	assert_true(fd >= 0);
	assert_int_equal(fstat(fd, &st), 0);
	*len = (size_t)st.st_size;
	buf = malloc(*len);
	assert_non_null(buf);
	assert_int_equal(pread(fd, buf, *len, 0), (ssize_t)*len);
	close(fd);
	return buf;
}

static struct dp_config file_config(const char *path, int w, int h, int stride,
				    const char *fmt, int rotate)
{
	struct dp_config c;

	memset(&c, 0, sizeof(c));
	c.backend = "file";
	c.file = path;
	c.file_w = w;
	c.file_h = h;
	c.file_stride = stride;
	c.file_format = fmt;
	c.rotate = rotate;
	c.scale = DP_SCALE_INTEGER;
	c.render_w = FW;
	c.render_h = FH;
	return c;
}

/* 12x8 xrgb8888 packed, unrotated: k = min(12/4, 8/3) = 2, 8x6 at (2, 1). */
static void xrgb8888_packed_present_lands_in_file(void **state)
{
	struct fixture *f = *state;
	struct dp_config c = file_config(f->path, 12, 8, 0, "xrgb8888", 0);
	uint8_t pal[256][3], frame[FW * FH];
	char why[256] = "";
	struct dp *d;
	uint8_t *buf;
	size_t len;
	int x, y;

	make_palette(pal);
	make_frame(frame, FW);
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), 0);
	assert_non_null(strstr(dp_file.describe(d), "xrgb8888"));
	assert_non_null(strstr(dp_file.describe(d), f->path));
	dp_file.set_palette(d, pal);
	assert_int_equal(dp_file.present(d, frame, FW, FH, FW), 0);
	buf = read_file(f->path, &len);
	assert_int_equal(len, 12 * 8 * 4);
	for (y = 0; y < 8; y++) {
		for (x = 0; x < 12; x++) {
			uint32_t got, want = 0;

			memcpy(&got, buf + (size_t)(y * 12 + x) * 4, 4);
			if (x >= 2 && x < 10 && y >= 1 && y < 7) {
				int sx = (x - 2) / 2, sy = (y - 1) / 2;

				want = (uint32_t)(33 * sx) << 16 | (uint32_t)(65 * sy) << 8 | 0xFF;
			}
			if (got != want)
				fail_msg("pixel (%d,%d) is %#x, want %#x", x, y, got, want);
		}
	}
	free(buf);
	dp_file.close(d);
}

/* 8x6 rgb565, stride 22 (6 padding bytes), rotated 90: the turned frame is
 * 3x4, k = min(8/3, 6/4) = 1, at (2, 1); frame (sx, sy) lands on
 * (2 + (2 - sy), 1 + sx). */
static void rgb565_padded_rotated_present_lands_in_file(void **state)
{
	struct fixture *f = *state;
	struct dp_config c = file_config(f->path, 8, 6, 22, "rgb565", 90);
	uint8_t pal[256][3], frame[8 * FH];
	uint16_t want[6][8];
	char why[256] = "";
	struct dp *d;
	uint8_t *buf;
	size_t len;
	int x, y;

	make_palette(pal);
	make_frame(frame, 8);           /* pitch 8: frame rows padded too */
	memset(want, 0, sizeof(want));
	for (y = 0; y < FH; y++)
		for (x = 0; x < FW; x++)
			want[1 + x][2 + (2 - y)] = (uint16_t)((4 * x) << 11 | (16 * y) << 5 | 31);

	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), 0);
	dp_file.set_palette(d, pal);
	assert_int_equal(dp_file.present(d, frame, FW, FH, 8), 0);
	buf = read_file(f->path, &len);
	assert_int_equal(len, 22 * 6);
	for (y = 0; y < 6; y++) {
		for (x = 0; x < 8; x++) {
			uint16_t got;

			memcpy(&got, buf + (size_t)y * 22 + (size_t)x * 2, 2);
			if (got != want[y][x])
				fail_msg("pixel (%d,%d) is %#x, want %#x", x, y, got, want[y][x]);
		}
		for (x = 16; x < 22; x++)
			assert_int_equal(buf[y * 22 + x], 0);
	}
	free(buf);
	dp_file.close(d);
}

static void open_resizes_and_clears_existing_file(void **state)
{
	struct fixture *f = *state;
	struct dp_config c = file_config(f->path, 4, 3, 0, "rgb888", 0);
	static const uint8_t junk[100] = { 1, 2, 3 };
	char why[256] = "";
	struct dp *d;
	uint8_t *buf;
	size_t len, i;
	int fd = open(f->path, O_WRONLY | O_CREAT | O_CLOEXEC, 0644);

	assert_true(fd >= 0);
	assert_int_equal(write(fd, junk, sizeof(junk)), (ssize_t)sizeof(junk));
	close(fd);
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), 0);
	buf = read_file(f->path, &len);
	assert_int_equal(len, 4 * 3 * 3);
	for (i = 0; i < len; i++)
		assert_int_equal(buf[i], 0);
	free(buf);
	dp_file.close(d);
}

static void bad_config_is_refused_with_reason(void **state)
{
	struct fixture *f = *state;
	struct dp_config c;
	char why[256];
	struct dp *d = (struct dp *)1;
	char missing[160];

	c = file_config(f->path, 8, 6, 0, "rgb332", 0);
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), -EINVAL);
	assert_null(d);
	assert_non_null(strstr(why, "rgb332"));

	c = file_config(f->path, 8, 6, 15, "rgb565", 0);   /* 8 * 2 = 16 > 15 */
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), -EINVAL);
	assert_non_null(strstr(why, "stride"));

	c = file_config(f->path, 0, 6, 0, "rgb565", 0);
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), -EINVAL);

	c = file_config(f->path, 8, 6, 0, "rgb565", 45);
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), -EINVAL);

	c = file_config(NULL, 8, 6, 0, "rgb565", 0);
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), -EINVAL);

	snprintf(missing, sizeof(missing), "%s/no/such/dir/fb", f->dir);
	c = file_config(missing, 8, 6, 0, "rgb565", 0);
	assert_int_equal(dp_file.open(&c, &d, why, sizeof(why)), -ENOENT);
	assert_non_null(strstr(why, missing));
	dp_file.close(NULL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(xrgb8888_packed_present_lands_in_file, setup,
						teardown),
		cmocka_unit_test_setup_teardown(rgb565_padded_rotated_present_lands_in_file, setup,
						teardown),
		cmocka_unit_test_setup_teardown(open_resizes_and_clears_existing_file, setup,
						teardown),
		cmocka_unit_test_setup_teardown(bad_config_is_refused_with_reason, setup, teardown),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
