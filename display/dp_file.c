/*
 * dp_file: a framebuffer in a regular file. Geometry, stride and pixel
 * format come from the configuration; the file is mmapped MAP_SHARED and
 * drawn with the same px_panel path as fbdev, minus the ioctls. Tests and
 * headless script runs read the file (or the mapping) back.
 *
 * No msync per frame: a MAP_SHARED mapping is the file's page cache, so
 * read() and other mappings of the file see each present at once; only
 * durability across a crash of the machine would need msync, and a
 * framebuffer has no use for that.
 */
#include "display/dp.h"
#include "display/px.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

struct dp {
	int fd;
	uint8_t *mem;
	size_t len;
	struct px_panel panel;
	char desc[256];
};

static void file_close(struct dp *d);

static int file_open(const struct dp_config *cfg, struct dp **out, char *why, size_t whylen)
{
	struct px_format f;
	struct dp *d;
	size_t stride;
	int rc;

	*out = NULL;
	if (!cfg->file || !cfg->file[0]) {
		snprintf(why, whylen, "no file configured");
		return -EINVAL;
	}
	if (px_format_by_name(cfg->file_format, &f) < 0) {
		snprintf(why, whylen, "%s: unknown pixel format \"%s\"", cfg->file,
			 cfg->file_format ? cfg->file_format : "(none)");
		return -EINVAL;
	}
	if (cfg->file_w < 1 || cfg->file_h < 1 || cfg->file_w > PX_MAX_DIM ||
	    cfg->file_h > PX_MAX_DIM) {
		snprintf(why, whylen, "%s: bad geometry %dx%d", cfg->file, cfg->file_w,
			 cfg->file_h);
		return -EINVAL;
	}
	stride = cfg->file_stride ? (size_t)cfg->file_stride
				  : (size_t)cfg->file_w * (size_t)(f.bpp / 8);
	if (cfg->file_stride < 0 || stride < (size_t)cfg->file_w * (size_t)(f.bpp / 8)) {
		snprintf(why, whylen, "%s: stride %d is less than %d pixels of %d bytes",
			 cfg->file, cfg->file_stride, cfg->file_w, f.bpp / 8);
		return -EINVAL;
	}

	d = calloc(1, sizeof(*d));
	if (!d) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	d->fd = -1;
	d->mem = MAP_FAILED;
	rc = px_panel_init(&d->panel, &f, cfg->file_w, cfg->file_h, stride, cfg->rotate,
			   cfg->scale == DP_SCALE_FILL, cfg->render_w, cfg->render_h);
	if (rc < 0) {
		snprintf(why, whylen, "%s: bad rotation %d or render size %dx%d", cfg->file,
			 cfg->rotate, cfg->render_w, cfg->render_h);
		goto fail;
	}
	px_panel_set_par(&d->panel, cfg->par);
	d->len = stride * (size_t)cfg->file_h;
	d->fd = open(cfg->file, O_RDWR | O_CREAT | O_CLOEXEC, 0644);
	if (d->fd < 0) {
		rc = -errno;
		snprintf(why, whylen, "%s: %s", cfg->file, strerror(-rc));
		goto fail;
	}
	if (ftruncate(d->fd, (off_t)d->len) < 0) {
		rc = -errno;
		snprintf(why, whylen, "%s: ftruncate: %s", cfg->file, strerror(-rc));
		goto fail;
	}
	d->mem = mmap(NULL, d->len, PROT_READ | PROT_WRITE, MAP_SHARED, d->fd, 0);
	if (d->mem == MAP_FAILED) {
		rc = -errno;
		snprintf(why, whylen, "%s: mmap: %s", cfg->file, strerror(-rc));
		goto fail;
	}
	memset(d->mem, 0, d->len);
	snprintf(d->desc, sizeof(d->desc), "file %s %dx%d %s stride %zu rotate %d %s",
		 cfg->file, cfg->file_w, cfg->file_h, px_format_name(&f), stride, cfg->rotate,
		 cfg->scale == DP_SCALE_FILL ? "fill" : "integer");
	*out = d;
	return 0;
fail:
	file_close(d);
	return rc;
}

static void file_set_palette(struct dp *d, const uint8_t rgb[256][3])
{
	px_panel_palette(&d->panel, rgb);
}

static int file_present(struct dp *d, const uint8_t *px, int w, int h, int pitch)
{
	return px_panel_draw(&d->panel, d->mem, px, w, h, pitch);
}

static void file_close(struct dp *d)
{
	if (!d)
		return;
	if (d->mem != MAP_FAILED)
		munmap(d->mem, d->len);
	if (d->fd >= 0)
		close(d->fd);
	free(d);
}

static const char *file_describe(struct dp *d)
{
	return d->desc;
}

const struct dp_backend dp_file = {
	.name = "file",
	.open = file_open,
	.set_palette = file_set_palette,
	.present = file_present,
	.close = file_close,
	.describe = file_describe,
};
