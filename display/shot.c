/*
 * shot: PNG screenshots (libpng). The image is written to "<path>.tmp",
 * fsynced and renamed over path, so a reader never sees half a file.
 * A path (or "<path>.tmp") that exists and is not a regular file is never
 * written or replaced: renaming over a device node, FIFO or symbolic link
 * would replace the node or link itself (run as root, /dev/full became a
 * PNG).
 *
 * libpng reports errors by longjmp; the setjmp and every libpng call stay
 * inside shot_write, and our error handler keeps libpng from printing.
 */
#include "display/shot.h"

#include <errno.h>
#include <fcntl.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static void shot_error(png_structp png, png_const_charp msg)
{
	(void)msg;
	png_longjmp(png, 1);
}

static void shot_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

/* Encodes the frame into f; 0 or -EIO (libpng error) / -ENOMEM. row is a
 * caller-owned buffer of 3*w bytes, so nothing needs freeing after a
 * longjmp except the libpng structures. */
static int shot_write(FILE *f, const uint8_t *px, int w, int h, int pitch,
		      const uint8_t rgb[256][3], png_bytep row)
{
	png_structp png;
	png_infop info;
	int y, x;

	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, shot_error, shot_warning);
	if (!png)
		return -ENOMEM;
	info = png_create_info_struct(png);
	if (!info) {
		png_destroy_write_struct(&png, NULL);
		return -ENOMEM;
	}
	/* Only png and info (set above, not changed below) are used after a
	 * longjmp, so no local needs to be volatile. */
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_write_struct(&png, &info);
		return -EIO;
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
		     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (y = 0; y < h; y++) {
		const uint8_t *s = px + (size_t)y * (size_t)pitch;

		for (x = 0; x < w; x++)
			memcpy(row + 3 * x, rgb[s[x]], 3);
		png_write_row(png, row);
	}
	png_write_end(png, info);
	png_destroy_write_struct(&png, &info);
	return 0;
}

/* What lstat says path is, when it is not a regular file. */
static const char *shot_kind(mode_t m)
{
	if (S_ISLNK(m))
		return "a symbolic link";
	if (S_ISFIFO(m))
		return "a FIFO";
	if (S_ISCHR(m) || S_ISBLK(m))
		return "a device node";
	if (S_ISDIR(m))
		return "a directory";
	if (S_ISSOCK(m))
		return "a socket";
	return "not a regular file";
}

const char *shot_target_kind(const char *path)
{
	struct stat sb;

	if (lstat(path, &sb) < 0 || S_ISREG(sb.st_mode))
		return NULL;
	return shot_kind(sb.st_mode);
}

void shot_why(const char *path, int rc, char *why, size_t whylen)
{
	const char *k = shot_target_kind(path);

	if (rc != -EEXIST) {
		snprintf(why, whylen, "%s", strerror(-rc));
	} else if (k) {
		snprintf(why, whylen, "is %s, not a regular file: not replaced", k);
	} else {
		/* the temporary name is in the way */
		size_t n = strlen(path);
		char *tmp = malloc(n + 5);

		if (tmp) {
			memcpy(tmp, path, n);
			memcpy(tmp + n, ".tmp", 5);
			k = shot_target_kind(tmp);
			free(tmp);
		}
		snprintf(why, whylen, "%s.tmp is %s, not a regular file: not written", path,
			 k ? k : "not a regular file");
	}
}

int shot_png(const char *path, const uint8_t *px, int w, int h, int pitch,
	     const uint8_t rgb[256][3])
{
	size_t n = strlen(path);
	char *tmp = NULL;
	png_bytep row = NULL;
	FILE *f = NULL;
	int fd = -1, rc;

	if (w < 1 || h < 1 || pitch < w || !n)
		return -EINVAL;
	tmp = malloc(n + 5);
	row = malloc((size_t)w * 3);
	if (!tmp || !row) {
		rc = -ENOMEM;
		goto out;
	}
	memcpy(tmp, path, n);
	memcpy(tmp + n, ".tmp", 5);
	if (shot_target_kind(path) || shot_target_kind(tmp)) {
		rc = -EEXIST;
		goto out;
	}
	/* O_NOFOLLOW, O_NONBLOCK: should one appear after the check, a link
	 * is not followed and a FIFO does not block the open */
	fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
	if (fd < 0) {
		rc = -errno;
		goto out;
	}
	f = fdopen(fd, "wb");
	if (!f) {
		rc = -errno;
		close(fd);
		goto fail;
	}
	rc = shot_write(f, px, w, h, pitch, rgb, row);
	if (rc == 0 && fflush(f) != 0)
		rc = -errno;
	if (rc == 0 && fsync(fileno(f)) < 0)
		rc = -errno;
	if (fclose(f) != 0 && rc == 0)
		rc = -errno;
	if (rc < 0)
		goto fail;
	if (rename(tmp, path) < 0) {
		rc = -errno;
		goto fail;
	}
	goto out;
fail:
	unlink(tmp);
out:
	free(row);
	free(tmp);
	return rc;
}
