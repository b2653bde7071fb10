/* Tests for display/shot.c: PNG screenshots, read back with libpng. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "display/shot.h"

#define W 5
#define H 4
#define PITCH 9

struct fixture {
	char dir[64];
	char path[96];
	char tmp[104];
};

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	if (!f)
		return -1;
	snprintf(f->dir, sizeof(f->dir), "/tmp/test_shot.XXXXXX");
	if (!mkdtemp(f->dir))
		return -1;
	snprintf(f->path, sizeof(f->path), "%s/shot.png", f->dir);
	snprintf(f->tmp, sizeof(f->tmp), "%s.tmp", f->path);
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fixture *f = *state;

	unlink(f->path);
	unlink(f->tmp);
	rmdir(f->dir);
	free(f);
	return 0;
}

/* Palette entry i is (i, 255 - i, 3i mod 256); the frame holds 7 + x + 11y,
 * padding bytes 0. */
static void make(uint8_t pal[256][3], uint8_t *px)
{
	int i, x, y;

	for (i = 0; i < 256; i++) {
		pal[i][0] = (uint8_t)i;
		pal[i][1] = (uint8_t)(255 - i);
		pal[i][2] = (uint8_t)(3 * i);
	}
	memset(px, 0, PITCH * H);
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++)
			px[y * PITCH + x] = (uint8_t)(7 + x + 11 * y);
}

/* Reads path as a PNG, checks it is W x H 8-bit RGB, returns the pixels. */
static uint8_t *read_png(const char *path)
{
	FILE *fp = fopen(path, "rb");
	png_structp png;
	png_infop info;
	uint8_t *rgb = malloc(W * H * 3);
	int y;

	assert_non_null(fp);
	assert_non_null(rgb);
	png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	assert_non_null(png);
	info = png_create_info_struct(png);
	assert_non_null(info);
	if (setjmp(png_jmpbuf(png)))
		fail_msg("libpng could not read %s", path);
	png_init_io(png, fp);
	png_read_info(png, info);
	assert_int_equal(png_get_image_width(png, info), W);
	assert_int_equal(png_get_image_height(png, info), H);
	assert_int_equal(png_get_bit_depth(png, info), 8);
	assert_int_equal(png_get_color_type(png, info), PNG_COLOR_TYPE_RGB);
	for (y = 0; y < H; y++)
		png_read_row(png, rgb + y * W * 3, NULL);
	png_read_end(png, NULL);
	png_destroy_read_struct(&png, &info, NULL);
	fclose(fp);
	return rgb;
}

static void png_round_trips_palette_colours(void **state)
{
	struct fixture *f = *state;
	uint8_t pal[256][3], px[PITCH * H], *rgb;
	struct stat st;
	int x, y;

	make(pal, px);
	assert_int_equal(shot_png(f->path, px, W, H, PITCH, pal), 0);
	rgb = read_png(f->path);
	for (y = 0; y < H; y++)
		for (x = 0; x < W; x++) {
			int i = 7 + x + 11 * y;
			const uint8_t *p = rgb + (y * W + x) * 3;

			assert_int_equal(p[0], i);
			assert_int_equal(p[1], 255 - i);
			assert_int_equal(p[2], (3 * i) & 0xff);
		}
	free(rgb);
	/* the temporary file was renamed away */
	assert_int_equal(stat(f->tmp, &st), -1);
	assert_int_equal(errno, ENOENT);
}

static void png_replaces_existing_file(void **state)
{
	struct fixture *f = *state;
	uint8_t pal[256][3], px[PITCH * H], *rgb;
	FILE *fp = fopen(f->path, "w");

	assert_non_null(fp);
	fputs("not a png", fp);
	fclose(fp);
	make(pal, px);
	assert_int_equal(shot_png(f->path, px, W, H, PITCH, pal), 0);
	rgb = read_png(f->path);
	assert_int_equal(rgb[0], 7);
	free(rgb);
}

/* A target that exists and is not a regular file is left alone: a symbolic
 * link stays a link (its target unchanged), a FIFO stays a FIFO (and the
 * call does not block on it), a directory stays; the call is -EEXIST and
 * shot_why names the kind. A .tmp name in the way is refused too. */
static void png_refuses_targets_that_are_not_regular_files(void **state)
{
	struct fixture *f = *state;
	uint8_t pal[256][3], px[PITCH * H];
	char target[160], why[160];
	struct stat st;
	FILE *fp;

	make(pal, px);
	snprintf(target, sizeof(target), "%s/target", f->dir);
	fp = fopen(target, "w");
	assert_non_null(fp);
	fputs("keep", fp);
	fclose(fp);
	assert_int_equal(symlink(target, f->path), 0);
	assert_int_equal(shot_png(f->path, px, W, H, PITCH, pal), -EEXIST);
	assert_int_equal(lstat(f->path, &st), 0);
	assert_true(S_ISLNK(st.st_mode));
	assert_int_equal(stat(target, &st), 0);
	assert_int_equal(st.st_size, 4);
	shot_why(f->path, -EEXIST, why, sizeof(why));
	assert_string_equal(why, "is a symbolic link, not a regular file: not replaced");
	assert_int_equal(unlink(f->path), 0);

	assert_int_equal(mkfifo(f->path, 0600), 0);
	alarm(5);
	assert_int_equal(shot_png(f->path, px, W, H, PITCH, pal), -EEXIST);
	alarm(0);
	assert_int_equal(lstat(f->path, &st), 0);
	assert_true(S_ISFIFO(st.st_mode));
	shot_why(f->path, -EEXIST, why, sizeof(why));
	assert_string_equal(why, "is a FIFO, not a regular file: not replaced");
	assert_int_equal(unlink(f->path), 0);

	/* nothing at path, but a FIFO at path.tmp */
	assert_int_equal(mkfifo(f->tmp, 0600), 0);
	alarm(5);
	assert_int_equal(shot_png(f->path, px, W, H, PITCH, pal), -EEXIST);
	alarm(0);
	assert_int_equal(lstat(f->path, &st), -1);
	shot_why(f->path, -EEXIST, why, sizeof(why));
	assert_non_null(strstr(why, ".tmp is a FIFO, not a regular file: not written"));
	assert_int_equal(unlink(f->tmp), 0);
	assert_int_equal(unlink(target), 0);

	/* other errors are strerror's words */
	shot_why(f->path, -ENOENT, why, sizeof(why));
	assert_string_equal(why, strerror(ENOENT));
}

static void png_errors_are_negative_errno(void **state)
{
	struct fixture *f = *state;
	uint8_t pal[256][3], px[PITCH * H];
	char missing[160];
	struct stat st;

	make(pal, px);
	snprintf(missing, sizeof(missing), "%s/no/dir/shot.png", f->dir);
	assert_int_equal(shot_png(missing, px, W, H, PITCH, pal), -ENOENT);
	assert_int_equal(shot_png(f->path, px, 0, H, PITCH, pal), -EINVAL);
	assert_int_equal(shot_png(f->path, px, W, H, W - 1, pal), -EINVAL);
	assert_int_equal(shot_png("", px, W, H, PITCH, pal), -EINVAL);
	assert_int_equal(stat(f->path, &st), -1);
}

/* libpng refuses a width over its default limit of 1,000,000 pixels:
 * that error arrives by longjmp and must come out as -EIO, leaving no
 * file behind. */
static void libpng_error_is_eio_and_leaves_no_file(void **state)
{
	struct fixture *f = *state;
	uint8_t pal[256][3], *px = calloc(1, 1000001);
	struct stat st;

	assert_non_null(px);
	memset(pal, 0, sizeof(pal));
	assert_int_equal(shot_png(f->path, px, 1000001, 1, 1000001, pal), -EIO);
	assert_int_equal(stat(f->path, &st), -1);
	assert_int_equal(stat(f->tmp, &st), -1);
	free(px);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(png_round_trips_palette_colours, setup, teardown),
		cmocka_unit_test_setup_teardown(png_replaces_existing_file, setup, teardown),
		cmocka_unit_test_setup_teardown(png_errors_are_negative_errno, setup, teardown),
		cmocka_unit_test_setup_teardown(png_refuses_targets_that_are_not_regular_files, setup,
						teardown),
		cmocka_unit_test_setup_teardown(libpng_error_is_eio_and_leaves_no_file, setup,
						teardown),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
