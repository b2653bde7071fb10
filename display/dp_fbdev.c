/*
 * dp_fbdev: the Linux framebuffer (/dev/fb*).
 *
 * The pixel format comes from fb_var_screeninfo (bits per pixel and the
 * red/green/blue offsets and lengths), the line length from
 * fb_fix_screeninfo; the whole framebuffer memory is mmapped and frames
 * are drawn by px_panel_draw, the same path as the file framebuffer.
 *
 * Double buffering: when yres_virtual holds two pages and the driver pans,
 * a frame is drawn into the hidden page and FBIOPAN_DISPLAY shows it. The
 * first failing pan switches to single buffering (drawing into the shown
 * page) for good, and describe says so. Drivers apply a pan at the next
 * vertical blank or at once; we do not wait for vblank (FBIO_WAITFORVSYNC
 * is not universal and the main loop paces itself).
 *
 * Console: display/con.h (graphics mode, keyboard off; restored on close
 * and by dp_emergency_restore from a fatal signal handler). VT switches
 * are left to the kernel: fbdev has no master to hand over.
 */
#include "display/con.h"
#include "display/dp.h"
#include "display/px.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/fb.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

struct dp {
	int fd;
	uint8_t *mem;
	size_t maplen;
	struct fb_var_screeninfo var;   /* current (yoffset follows the pans) */
	uint32_t yoffset0;              /* shown at open; restored at close */
	size_t line_length;
	size_t xbytes;                  /* xoffset in bytes */
	int pages;                      /* 2 double-buffered, 1 single */
	int shown;                      /* page on screen (double) */
	int con;                        /* this display holds the console state */
	struct px_panel panel;
	char device[128];
	char con_note[160];             /* console outcome, for describe */
	char pan_note[96];              /* why single-buffered, for describe */
	char desc[512];
};

static void fbdev_close(struct dp *d);

static void fbdev_describe_update(struct dp *d)
{
	snprintf(d->desc, sizeof(d->desc), "fbdev %s %ux%u %s line %zu %s%s rotate %d %s; %s",
		 d->device, d->var.xres, d->var.yres, px_format_name(&d->panel.fmt),
		 d->line_length, d->pages == 2 ? "double-buffered" : "single-buffered",
		 d->pan_note, d->panel.layout.rotate, d->panel.layout.fill ? "fill" : "integer",
		 d->con_note);
}

/* The panel format from the screen info; 0 or -EOPNOTSUPP. Only packed
 * true-colour pixels: direct-colour visuals pass each field through a
 * hardware colour map we would have to load, and are refused. */
static int fbdev_format(const struct fb_var_screeninfo *v, const struct fb_fix_screeninfo *x,
			struct px_format *f)
{
	if (x->type != FB_TYPE_PACKED_PIXELS || x->visual != FB_VISUAL_TRUECOLOR)
		return -EOPNOTSUPP;
	if (v->red.msb_right || v->green.msb_right || v->blue.msb_right)
		return -EOPNOTSUPP;
	f->bpp = (int)v->bits_per_pixel;
	f->r_off = (int)v->red.offset;
	f->r_len = (int)v->red.length;
	f->g_off = (int)v->green.offset;
	f->g_len = (int)v->green.length;
	f->b_off = (int)v->blue.offset;
	f->b_len = (int)v->blue.length;
	return px_format_check(f) < 0 ? -EOPNOTSUPP : 0;
}

/* Page p's top-left visible pixel (single-buffered: the shown area). */
static uint8_t *fbdev_page(struct dp *d, int p)
{
	size_t y = d->pages == 2 ? (size_t)p * d->var.yres : d->var.yoffset;

	return d->mem + y * d->line_length + d->xbytes;
}

static int fbdev_pan(struct dp *d, uint32_t yoffset)
{
	struct fb_var_screeninfo v = d->var;

	v.yoffset = yoffset;
	if (ioctl(d->fd, FBIOPAN_DISPLAY, &v) < 0)
		return -errno;
	d->var.yoffset = yoffset;
	return 0;
}

/* Two pages when the virtual height, the mapping and the driver's pan
 * step allow it and a pan to page 0 works; else one. */
static void fbdev_buffering(struct dp *d, const struct fb_fix_screeninfo *x)
{
	int rc;

	d->pages = 1;
	if (d->var.yres_virtual < 2 * d->var.yres) {
		snprintf(d->pan_note, sizeof(d->pan_note), " (yres_virtual %u < 2 pages)",
			 d->var.yres_virtual);
		return;
	}
	if (x->ypanstep == 0 || d->var.yres % x->ypanstep != 0) {
		snprintf(d->pan_note, sizeof(d->pan_note), " (driver pan step %u)", x->ypanstep);
		return;
	}
	if ((2 * (size_t)d->var.yres - 1) * d->line_length + d->xbytes +
	    (size_t)d->var.xres * (size_t)(d->panel.fmt.bpp / 8) > d->maplen) {
		snprintf(d->pan_note, sizeof(d->pan_note), " (memory holds one page)");
		return;
	}
	rc = fbdev_pan(d, 0);
	if (rc < 0) {
		snprintf(d->pan_note, sizeof(d->pan_note), " (pan: %s)", strerror(-rc));
		return;
	}
	d->pages = 2;
	d->shown = 0;
}

static int fbdev_open(const struct dp_config *cfg, struct dp **out, char *why, size_t whylen)
{
	const char *dev = cfg->device && cfg->device[0] ? cfg->device : "/dev/fb0";
	struct fb_fix_screeninfo fix;
	struct px_format f;
	struct dp *d;
	size_t bytes, need;
	int rc;

	*out = NULL;
	d = calloc(1, sizeof(*d));
	if (!d) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	d->mem = MAP_FAILED;
	snprintf(d->device, sizeof(d->device), "%s", dev);
	d->fd = open(dev, O_RDWR | O_CLOEXEC);
	if (d->fd < 0) {
		rc = -errno;
		snprintf(why, whylen, "%s: %s", dev, strerror(-rc));
		goto fail;
	}
	if (ioctl(d->fd, FBIOGET_VSCREENINFO, &d->var) < 0 ||
	    ioctl(d->fd, FBIOGET_FSCREENINFO, &fix) < 0) {
		rc = -errno;
		snprintf(why, whylen, "%s: screen info: %s", dev, strerror(-rc));
		goto fail;
	}
	rc = fbdev_format(&d->var, &fix, &f);
	if (rc < 0) {
		snprintf(why, whylen,
			 "%s: unsupported pixels (type %u visual %u, %u bpp, r %u/%u g %u/%u b %u/%u)",
			 dev, fix.type, fix.visual, d->var.bits_per_pixel, d->var.red.offset,
			 d->var.red.length, d->var.green.offset, d->var.green.length,
			 d->var.blue.offset, d->var.blue.length);
		goto fail;
	}
	bytes = (size_t)f.bpp / 8;
	d->line_length = fix.line_length ? fix.line_length : d->var.xres_virtual * bytes;
	d->xbytes = (size_t)d->var.xoffset * bytes;
	d->maplen = fix.smem_len ? fix.smem_len : d->line_length * d->var.yres_virtual;
	d->yoffset0 = d->var.yoffset;
	need = ((size_t)d->var.yoffset + d->var.yres - 1) * d->line_length + d->xbytes +
	       (size_t)d->var.xres * bytes;
	if (d->var.xres == 0 || d->var.yres == 0 || need > d->maplen ||
	    d->xbytes + d->var.xres * bytes > d->line_length) {
		rc = -EINVAL;
		snprintf(why, whylen, "%s: visible area %ux%u+%u+%u outside memory %zu (line %zu)",
			 dev, d->var.xres, d->var.yres, d->var.xoffset, d->var.yoffset, d->maplen,
			 d->line_length);
		goto fail;
	}
	rc = px_panel_init(&d->panel, &f, (int)d->var.xres, (int)d->var.yres, d->line_length,
			   cfg->rotate, cfg->scale == DP_SCALE_FILL, cfg->render_w, cfg->render_h);
	if (rc < 0) {
		snprintf(why, whylen, "%s: %ux%u panel, rotation %d, render size %dx%d refused",
			 dev, d->var.xres, d->var.yres, cfg->rotate, cfg->render_w,
			 cfg->render_h);
		goto fail;
	}
	px_panel_set_par(&d->panel, cfg->par);
	d->mem = mmap(NULL, d->maplen, PROT_READ | PROT_WRITE, MAP_SHARED, d->fd, 0);
	if (d->mem == MAP_FAILED) {
		rc = -errno;
		snprintf(why, whylen, "%s: mmap %zu bytes: %s", dev, d->maplen, strerror(-rc));
		goto fail;
	}
	memset(d->mem, 0, d->maplen);
	fbdev_buffering(d, &fix);
	d->con = con_enter(cfg->tty, 0, d->con_note, sizeof(d->con_note));
	fbdev_describe_update(d);
	*out = d;
	return 0;
fail:
	fbdev_close(d);
	return rc;
}

static void fbdev_set_palette(struct dp *d, const uint8_t rgb[256][3])
{
	px_panel_palette(&d->panel, rgb);
}

static int fbdev_present(struct dp *d, const uint8_t *px, int w, int h, int pitch)
{
	int back, rc;

	if (d->pages == 1)
		return px_panel_draw(&d->panel, fbdev_page(d, 0), px, w, h, pitch);
	back = 1 - d->shown;
	rc = px_panel_draw(&d->panel, fbdev_page(d, back), px, w, h, pitch);
	if (rc < 0)
		return rc;
	rc = fbdev_pan(d, (uint32_t)back * d->var.yres);
	if (rc == 0) {
		d->shown = back;
		return 0;
	}
	/* Panning stopped working: draw into the shown page from now on. */
	snprintf(d->pan_note, sizeof(d->pan_note), " (pan failed: %s)", strerror(-rc));
	d->pages = 1;
	d->var.yoffset = (uint32_t)d->shown * d->var.yres;
	fbdev_describe_update(d);
	return px_panel_draw(&d->panel, fbdev_page(d, 0), px, w, h, pitch);
}

static void fbdev_close(struct dp *d)
{
	if (!d)
		return;
	if (d->con)
		con_leave();
	if (d->pages == 2 && d->var.yoffset != d->yoffset0)
		fbdev_pan(d, d->yoffset0);
	if (d->mem != MAP_FAILED)
		munmap(d->mem, d->maplen);
	if (d->fd >= 0)
		close(d->fd);
	free(d);
}

static const char *fbdev_describe(struct dp *d)
{
	return d->desc;
}

const struct dp_backend dp_fbdev = {
	.name = "fbdev",
	.open = fbdev_open,
	.set_palette = fbdev_set_palette,
	.present = fbdev_present,
	.close = fbdev_close,
	.describe = fbdev_describe,
	.node = "/dev/fb",
};
