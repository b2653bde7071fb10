/*
 * px: panel pixel formats, the index -> panel conversion table, and the one
 * pass that converts, scales and rotates a frame into panel memory. This is
 * the only display file that writes panel pixels.
 */
#ifndef ARCADED_DISPLAY_PX_H
#define ARCADED_DISPLAY_PX_H

#include <stddef.h>
#include <stdint.h>

/* A pixel format as fb_var_screeninfo describes it: bits per pixel and the
 * offset/length of each colour field (offset counted from the least
 * significant bit of the little-endian pixel value). */
struct px_format {
	int bpp;                 /* 16, 24 or 32 */
	int r_off, r_len, g_off, g_len, b_off, b_len;
};

/* Named formats: "rgb565", "bgr565", "xrgb8888", "xbgr8888", "rgb888".
 * Returns 0 or -EINVAL. */
int px_format_by_name(const char *name, struct px_format *f);
/* Name of a format if it matches a named one, else "custom". */
const char *px_format_name(const struct px_format *f);
/* 0 if f is usable (bpp 16/24/32, fields inside the pixel, lengths 1..8). */
int px_format_check(const struct px_format *f);

/* 256 panel pixel values, one per palette index. */
struct px_table {
	uint32_t v[256];
	int bytes;               /* bytes per panel pixel: 2, 3 or 4 */
};

void px_table_build(struct px_table *t, const struct px_format *f, const uint8_t rgb[256][3]);

/* Where a frame lands on the panel. */
struct px_layout {
	int panel_w, panel_h;    /* visible panel pixels */
	int rotate;              /* 0, 90, 180, 270 clockwise */
	int fill;                /* 0 integer scale + letterbox, 1 stretch */
	int src_w, src_h;        /* frame size */
	/* derived by px_layout_init: destination rectangle on the panel */
	int dst_x, dst_y, dst_w, dst_h;
};

/* Computes the destination rectangle. Returns 0 or -EINVAL (bad rotation
 * or sizes). */
int px_layout_init(struct px_layout *l);

/* Writes the whole visible panel (letterbox bars black, index 0 of no
 * table: value 0) from the frame src (w*h indices, stride src_pitch) into
 * dst (line_length bytes per line). */
void px_blit(const struct px_layout *l, const struct px_table *t, const uint8_t *src,
	     int src_pitch, uint8_t *dst, size_t line_length);

#endif
