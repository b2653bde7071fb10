/*
 * px: panel pixel formats, the index -> panel conversion table, and the one
 * pass that converts, scales and rotates a frame into panel memory. This is
 * the only display file that writes panel pixels.
 */
#ifndef ARCADED_DISPLAY_PX_H
#define ARCADED_DISPLAY_PX_H

#include <stddef.h>
#include <stdint.h>

/* Largest panel or frame side px_layout_init accepts (sizes the layout's
 * mapping tables, so px_blit needs no allocation). */
#define PX_MAX_DIM 16384

/* A pixel format as fb_var_screeninfo describes it: bits per pixel and the
 * offset/length of each colour field (offset counted from the least
 * significant bit of the pixel value). 16- and 32-bit pixels are stored as
 * native-endian words (little-endian on every target arcaded builds for, as
 * fbdev expects); 24-bit pixels as three bytes, least significant first, so
 * "rgb888" (r 16, g 8, b 0) is B,G,R in memory. */
struct px_format {
	int bpp;                 /* 16, 24 or 32 */
	int r_off, r_len, g_off, g_len, b_off, b_len;
};

/* Named formats: "rgb565" (r 11/5 g 5/6 b 0/5), "bgr565" (b 11/5 g 5/6
 * r 0/5), "xrgb8888" (r 16 g 8 b 0), "xbgr8888" (r 0 g 8 b 16), "rgb888"
 * (24 bpp, r 16 g 8 b 0). Returns 0 or -EINVAL (unknown or NULL name). */
int px_format_by_name(const char *name, struct px_format *f);
/* Name of a format if it matches a named one, else "custom". */
const char *px_format_name(const struct px_format *f);
/* 0 if f is usable (bpp 16/24/32, fields inside the pixel, lengths 1..8,
 * no two fields overlapping), else -EINVAL. */
int px_format_check(const struct px_format *f);

/* 256 panel pixel values, one per palette index. */
struct px_table {
	uint32_t v[256];
	int bytes;               /* bytes per panel pixel: 2, 3 or 4 */
};

/* Fills t for format f (which must pass px_format_check): each 8-bit
 * channel c becomes (c * (2^len - 1) + 127) / 255 (rounded), shifted to its
 * offset; bits outside the three fields are 0. */
void px_table_build(struct px_table *t, const struct px_format *f, const uint8_t rgb[256][3]);

/* Where a frame lands on the panel, and the mapping px_blit follows.
 *
 * Rotation is clockwise: at 90 the frame's top row is the panel's right
 * column, read top to bottom; at 270 it is the left column, read bottom to
 * top. The rotated frame is fw x fh (src_h x src_w at 90/270).
 * - fill: the rotated frame is stretched over the whole panel.
 * - integer (fill 0), frame fits: the largest k >= 1 with k*fw <= panel_w
 *   and k*fh <= panel_h; the k*fw x k*fh rectangle is centred (odd spare
 *   pixel on the right/bottom), the rest is black letterbox.
 * - integer, frame larger than the panel: downscaled (nearest) to the
 *   largest rectangle of the frame's aspect that fits, centred, letterbox.
 *   The whole picture stays visible; nothing is cropped.
 * Every mapping is nearest-neighbour sampling at the centre of the
 * destination pixel: rotated-frame x = ((2u + 1) * fw) / (2 * dst_w) for
 * destination column u of the rectangle (same for y), which is exactly
 * u / k at integer scale. */
struct px_layout {
	/* inputs */
	int panel_w, panel_h;    /* visible panel pixels, 1..PX_MAX_DIM */
	int rotate;              /* 0, 90, 180, 270 clockwise */
	int fill;                /* 0 integer scale + letterbox, 1 stretch */
	int src_w, src_h;        /* frame size, 1..PX_MAX_DIM */
	int src_pitch;           /* bytes between frame rows; 0 means src_w */
	/* derived by px_layout_init: destination rectangle on the panel */
	int dst_x, dst_y, dst_w, dst_h;
	int scale;               /* integer factor k, or 0 (fill or downscale) */
	/* Frame byte offset of destination pixel (dst_x + u, dst_y + v) is
	 * row[v] + col[u]: rotation and scaling folded into two tables. */
	int32_t col[PX_MAX_DIM];
	int32_t row[PX_MAX_DIM];
};

/* Computes the destination rectangle and the mapping tables from the input
 * fields. Returns 0 or -EINVAL (bad rotation, size out of range, pitch
 * smaller than src_w, frame larger than 2 GiB). */
int px_layout_init(struct px_layout *l);

/* Writes the whole visible panel, panel_w x panel_h pixels, from the frame
 * src (laid out as l->src_w x l->src_h with pitch l->src_pitch) into dst
 * (line_length bytes per line, line_length >= panel_w * t->bytes), row by
 * row in memory order. Letterbox bars get value 0 (black in every format).
 * Bytes of a line beyond the visible width are never written. No allocation,
 * no division per pixel; rows that repeat the previous row's source are
 * copied. */
void px_blit(const struct px_layout *l, const struct px_table *t, const uint8_t *src,
	     uint8_t *dst, size_t line_length);

/* The same for panel rows y0 <= y < y1 only (clamped to the panel): the
 * lines px_blit writes there, byte for byte. Calls for disjoint ranges may
 * run at once on different threads. */
void px_blit_rows(const struct px_layout *l, const struct px_table *t, const uint8_t *src,
		  uint8_t *dst, size_t line_length, int y0, int y1);

/* A pool of threads the present may run row ranges on, provided by the
 * caller (app/pool.h), the same contract as the renderer's struct r_par:
 * run(pool, n, job, arg) calls job(arg, i) once for every i in 0..n-1, any
 * number at a time, and returns when all have returned (a full barrier). */
struct px_par {
	void (*run)(void *pool, int n, void (*job)(void *arg, int i), void *arg);
	void *pool;
	int threads;             /* how many jobs the pool runs at once */
};

/* A parallel present cuts the panel into row ranges of about
 * PX_ROWS_PER_JOB rows (the rows cost alike, and a range that small is
 * about 40 us at 1920x1080, so the thread that ends first waits at most
 * about that long for the other: with 2 ranges per thread one thread
 * waited 0.06-0.17 ms a frame at 1920x1080 and 0.27-0.58 ms at 3840x2160,
 * with 64 rows 0.02-0.03 and 0.06-0.07), and at least PX_JOBS_PER_THREAD
 * ranges per thread; and only panels of at least PX_PAR_MIN_ROWS rows per
 * thread (below that a batch costs more than it saves). */
#define PX_ROWS_PER_JOB 64
#define PX_JOBS_PER_THREAD 2
#define PX_PAR_MIN_ROWS 32

/* A panel in memory as fbdev and the file framebuffer use it: format, table,
 * layout and line length. Lives inside the backend's handle (the layout's
 * tables make it about 128 KiB). */
struct px_panel {
	struct px_format fmt;
	struct px_table table;
	struct px_layout layout;
	size_t line_length;
	struct px_par par;       /* run NULL: drawn on the calling thread */
};

/* Sets up p for a panel_w x panel_h panel of format f (checked) with
 * line_length bytes per line, for frames of src_w x src_h (packed) shown
 * at rotate / fill. The table starts all black (0) until px_panel_palette.
 * Returns 0 or -EINVAL (bad format, sizes, rotation, or line_length too
 * small). */
int px_panel_init(struct px_panel *p, const struct px_format *f, int panel_w, int panel_h,
		  size_t line_length, int rotate, int fill, int src_w, int src_h);
/* Rebuilds the table for palette rgb. */
void px_panel_palette(struct px_panel *p, const uint8_t rgb[256][3]);
/* Draws the next frames in row ranges through par (copied; the pool must
 * outlive its use), or on the calling thread when par is NULL or has fewer
 * than two threads (the default after px_panel_init). The bytes written
 * are the same either way. */
void px_panel_set_par(struct px_panel *p, const struct px_par *par);
/* Draws one frame (w x h indices, row stride pitch) into the panel memory
 * mem (the top-left visible pixel), in row ranges on the pool set by
 * px_panel_set_par if any. A frame of another size or pitch than the last
 * one re-derives the layout first. 0 or -EINVAL (bad geometry; nothing
 * written). */
int px_panel_draw(struct px_panel *p, uint8_t *mem, const uint8_t *src, int w, int h,
		  int pitch);

#endif
