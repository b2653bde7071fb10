/*
 * px: pixel formats, the conversion table and the one pass that writes
 * panel pixels (contracts in px.h).
 *
 * px_blit is the display's hot loop: every presented frame goes through it
 * once. It walks the destination in memory order (each panel line left to
 * right, lines top to bottom), so writes stream through the cache and the
 * frame, a few hundred KiB at most, is what gets read at random. All the
 * geometry (scale, rotation, centring) was folded by px_layout_init into
 * two offset tables, so the inner loop is: read an index, look it up,
 * store.
 */
#include "display/px.h"

#include <assert.h>
#include <errno.h>
#include <stdint.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

struct px_named {
	const char *name;
	struct px_format f;
};

static const struct px_named px_named[] = {
	{ "rgb565", { 16, 11, 5, 5, 6, 0, 5 } },
	{ "bgr565", { 16, 0, 5, 5, 6, 11, 5 } },
	{ "xrgb8888", { 32, 16, 8, 8, 8, 0, 8 } },
	{ "xbgr8888", { 32, 0, 8, 8, 8, 16, 8 } },
	{ "rgb888", { 24, 16, 8, 8, 8, 0, 8 } },
};

#define PX_NNAMED (sizeof(px_named) / sizeof(px_named[0]))

int px_format_by_name(const char *name, struct px_format *f)
{
	size_t i;

	if (!name)
		return -EINVAL;
	for (i = 0; i < PX_NNAMED; i++) {
		if (strcmp(name, px_named[i].name) == 0) {
			*f = px_named[i].f;
			return 0;
		}
	}
	return -EINVAL;
}

const char *px_format_name(const struct px_format *f)
{
	size_t i;

	for (i = 0; i < PX_NNAMED; i++) {
		const struct px_format *n = &px_named[i].f;

		if (f->bpp == n->bpp && f->r_off == n->r_off && f->r_len == n->r_len &&
		    f->g_off == n->g_off && f->g_len == n->g_len && f->b_off == n->b_off &&
		    f->b_len == n->b_len)
			return px_named[i].name;
	}
	return "custom";
}

/* Mask of one field, or 0 if it does not fit in a pixel of bpp bits. */
static uint32_t px_field_mask(int off, int len, int bpp)
{
	if (len < 1 || len > 8 || off < 0 || off + len > bpp)
		return 0;
	return (((uint32_t)1 << len) - 1) << off;
}

int px_format_check(const struct px_format *f)
{
	uint32_t r, g, b;

	if (f->bpp != 16 && f->bpp != 24 && f->bpp != 32)
		return -EINVAL;
	r = px_field_mask(f->r_off, f->r_len, f->bpp);
	g = px_field_mask(f->g_off, f->g_len, f->bpp);
	b = px_field_mask(f->b_off, f->b_len, f->bpp);
	if (!r || !g || !b || (r & g) || (r & b) || (g & b))
		return -EINVAL;
	return 0;
}

/* 8-bit channel c reduced to len bits, rounded to nearest. */
static uint32_t px_chan(uint8_t c, int len, int off)
{
	uint32_t max = ((uint32_t)1 << len) - 1;

	return ((c * max + 127) / 255) << off;
}

void px_table_build(struct px_table *t, const struct px_format *f, const uint8_t rgb[256][3])
{
	int i;

	assert(px_format_check(f) == 0);
	t->bytes = f->bpp / 8;
	for (i = 0; i < 256; i++)
		t->v[i] = px_chan(rgb[i][0], f->r_len, f->r_off) |
			  px_chan(rgb[i][1], f->g_len, f->g_off) |
			  px_chan(rgb[i][2], f->b_len, f->b_off);
}

/* Nearest source coordinate (0..n-1) of destination coordinate u of d,
 * sampled at the pixel centre. */
static int32_t px_near(int u, int d, int n)
{
	return (int32_t)(((2 * (int64_t)u + 1) * n) / (2 * (int64_t)d));
}

int px_layout_init(struct px_layout *l)
{
	int quarter, fw, fh, pitch, u, v;

	if (l->rotate != 0 && l->rotate != 90 && l->rotate != 180 && l->rotate != 270)
		return -EINVAL;
	if (l->panel_w < 1 || l->panel_h < 1 || l->panel_w > PX_MAX_DIM ||
	    l->panel_h > PX_MAX_DIM)
		return -EINVAL;
	if (l->src_w < 1 || l->src_h < 1 || l->src_w > PX_MAX_DIM || l->src_h > PX_MAX_DIM)
		return -EINVAL;
	pitch = l->src_pitch ? l->src_pitch : l->src_w;
	if (pitch < l->src_w || (int64_t)pitch * l->src_h > INT32_MAX)
		return -EINVAL;

	quarter = l->rotate == 90 || l->rotate == 270;
	fw = quarter ? l->src_h : l->src_w;
	fh = quarter ? l->src_w : l->src_h;
	l->scale = 0;
	if (l->fill) {
		l->dst_w = l->panel_w;
		l->dst_h = l->panel_h;
	} else if (fw <= l->panel_w && fh <= l->panel_h) {
		int kx = l->panel_w / fw, ky = l->panel_h / fh;

		l->scale = kx < ky ? kx : ky;
		l->dst_w = l->scale * fw;
		l->dst_h = l->scale * fh;
	} else if ((int64_t)fw * l->panel_h <= (int64_t)fh * l->panel_w) {
		/* Relatively taller than the panel: full height. */
		l->dst_h = l->panel_h;
		l->dst_w = (int)((int64_t)fw * l->panel_h / fh);
		if (l->dst_w < 1)
			l->dst_w = 1;
	} else {
		l->dst_w = l->panel_w;
		l->dst_h = (int)((int64_t)fh * l->panel_w / fw);
		if (l->dst_h < 1)
			l->dst_h = 1;
	}
	l->dst_x = (l->panel_w - l->dst_w) / 2;
	l->dst_y = (l->panel_h - l->dst_h) / 2;

	/* Rotated-frame (rx, ry) to frame (sx, sy), split so that the offset
	 * sy * pitch + sx is col(rx) + row(ry):
	 *   0:   sx = rx,          sy = ry
	 *   90:  sx = ry,          sy = fw - 1 - rx
	 *   180: sx = src_w-1-rx,  sy = src_h - 1 - ry
	 *   270: sx = fh - 1 - ry, sy = rx */
	for (u = 0; u < l->dst_w; u++) {
		int32_t rx = px_near(u, l->dst_w, fw);

		switch (l->rotate) {
		case 0: l->col[u] = rx; break;
		case 90: l->col[u] = (fw - 1 - rx) * pitch; break;
		case 180: l->col[u] = l->src_w - 1 - rx; break;
		default: l->col[u] = rx * pitch; break;
		}
	}
	for (v = 0; v < l->dst_h; v++) {
		int32_t ry = px_near(v, l->dst_h, fh);

		switch (l->rotate) {
		case 0: l->row[v] = ry * pitch; break;
		case 90: l->row[v] = ry; break;
		case 180: l->row[v] = (l->src_h - 1 - ry) * pitch; break;
		default: l->row[v] = fh - 1 - ry; break;
		}
	}
	return 0;
}

/* Stores go through memcpy: one plain store after optimisation, and no
 * alignment assumption about the panel memory. */
static inline void px_st32(uint8_t *d, uint32_t v)
{
	memcpy(d, &v, 4);
}

static inline void px_st16(uint8_t *d, uint32_t v)
{
	uint16_t w = (uint16_t)v;

	memcpy(d, &w, 2);
}

static inline void px_st24(uint8_t *d, uint32_t v)
{
	d[0] = (uint8_t)v;
	d[1] = (uint8_t)(v >> 8);
	d[2] = (uint8_t)(v >> 16);
}

/* General rows: any scale, any rotation. */
static void px_row32(uint8_t *d, const uint8_t *s, const int32_t *col, int n, const uint32_t *t)
{
	int u;

	for (u = 0; u < n; u++, d += 4)
		px_st32(d, t[s[col[u]]]);
}

static void px_row16(uint8_t *d, const uint8_t *s, const int32_t *col, int n, const uint32_t *t)
{
	int u;

	for (u = 0; u < n; u++, d += 2)
		px_st16(d, t[s[col[u]]]);
}

static void px_row24(uint8_t *d, const uint8_t *s, const int32_t *col, int n, const uint32_t *t)
{
	int u;

	for (u = 0; u < n; u++, d += 3)
		px_st24(d, t[s[col[u]]]);
}

/* Unrotated integer scale k: n consecutive frame pixels, each stored k
 * times; no table lookup for the column. px_row*_k call the repeat loops
 * with constant k for the usual factors so the compiler unrolls them. */
static inline void px_rep32(uint8_t *d, const uint8_t *s, int n, int k, const uint32_t *t)
{
	int i, j;

	for (i = 0; i < n; i++) {
		uint32_t v = t[s[i]];

		for (j = 0; j < k; j++, d += 4)
			px_st32(d, v);
	}
}

static inline void px_rep16(uint8_t *d, const uint8_t *s, int n, int k, const uint32_t *t)
{
	int i, j;

	for (i = 0; i < n; i++) {
		uint32_t v = t[s[i]];

		for (j = 0; j < k; j++, d += 2)
			px_st16(d, v);
	}
}

/* Scale 1, 4 bytes a pixel: the common case (a panel the frame's size).
 * Where SSE2 is there, the row is written with streaming stores: the panel
 * is only written, never read back, so the cache lines need not be fetched
 * first (the plain stores' read-for-ownership doubles the memory traffic,
 * which at 3840x2160 is 33 MB a frame) and the frame's texture and column
 * data stay in the cache. The bytes written are the same either way;
 * px_blit_rows ends with a store fence so that they are visible before
 * the caller hands the buffer on. */
static void px_row32_1(uint8_t *d, const uint8_t *s, int n, const uint32_t *t)
{
#if defined(__SSE2__)
	int i = 0;

	/* up to 16-byte alignment (a pitch not a multiple of 4 never gets
	 * there: then the whole row is plain stores) */
	for (; i < n && ((uintptr_t)d & 15) != 0; i++, d += 4)
		px_st32(d, t[s[i]]);
	for (; i + 4 <= n; i += 4, d += 16)
		_mm_stream_si128((__m128i *)(void *)d,
				 _mm_set_epi32((int)t[s[i + 3]], (int)t[s[i + 2]],
					       (int)t[s[i + 1]], (int)t[s[i]]));
	for (; i < n; i++, d += 4)
		px_st32(d, t[s[i]]);
#else
	px_rep32(d, s, n, 1, t);
#endif
}

static void px_row32_k(uint8_t *d, const uint8_t *s, int n, int k, const uint32_t *t)
{
	switch (k) {
	case 1: px_row32_1(d, s, n, t); break;
	case 2: px_rep32(d, s, n, 2, t); break;
	case 3: px_rep32(d, s, n, 3, t); break;
	case 4: px_rep32(d, s, n, 4, t); break;
	default: px_rep32(d, s, n, k, t); break;
	}
}

static void px_row16_k(uint8_t *d, const uint8_t *s, int n, int k, const uint32_t *t)
{
	switch (k) {
	case 1: px_rep16(d, s, n, 1, t); break;
	case 2: px_rep16(d, s, n, 2, t); break;
	case 3: px_rep16(d, s, n, 3, t); break;
	case 4: px_rep16(d, s, n, 4, t); break;
	default: px_rep16(d, s, n, k, t); break;
	}
}

void px_blit_rows(const struct px_layout *l, const struct px_table *t, const uint8_t *src,
		  uint8_t *dst, size_t line_length, int y0, int y1)
{
	size_t bytes = (size_t)t->bytes;
	size_t vis = (size_t)l->panel_w * bytes;
	size_t left = (size_t)l->dst_x * bytes;
	size_t span = (size_t)l->dst_w * bytes;
	size_t right = vis - left - span;
	/* Unrotated integer scale: a destination line is k copies of each of
	 * fw consecutive frame pixels starting at col[0]. */
	int plain = l->rotate == 0 && l->scale > 0;
	int fw = plain ? l->dst_w / l->scale : 0;
	uint8_t *d;
	int y;

	assert(t->bytes == 2 || t->bytes == 3 || t->bytes == 4);
	assert(line_length >= vis);
	if (y0 < 0)
		y0 = 0;
	if (y1 > l->panel_h)
		y1 = l->panel_h;
	d = dst + (size_t)y0 * line_length;
	for (y = y0; y < y1; y++, d += line_length) {
		int v = y - l->dst_y;
		const uint8_t *s;

		if (v < 0 || v >= l->dst_h) {
			memset(d, 0, vis);
			continue;
		}
		s = src + l->row[v];
		if (left)
			memset(d, 0, left);
		if (right)
			memset(d + left + span, 0, right);
		/* a repeated source line is copied from the line above, when
		 * that line is this call's own (another call may be writing
		 * the line above a range's first) */
		if (y > y0 && v > 0 && l->row[v] == l->row[v - 1]) {
			memcpy(d + left, d - line_length + left, span);
			continue;
		}
		if (plain && bytes == 4)
			px_row32_k(d + left, s + l->col[0], fw, l->scale, t->v);
		else if (plain && bytes == 2)
			px_row16_k(d + left, s + l->col[0], fw, l->scale, t->v);
		else if (bytes == 4)
			px_row32(d + left, s, l->col, l->dst_w, t->v);
		else if (bytes == 2)
			px_row16(d + left, s, l->col, l->dst_w, t->v);
		else
			px_row24(d + left, s, l->col, l->dst_w, t->v);
	}
#if defined(__SSE2__)
	_mm_sfence();
#endif
}

void px_blit(const struct px_layout *l, const struct px_table *t, const uint8_t *src,
	     uint8_t *dst, size_t line_length)
{
	px_blit_rows(l, t, src, dst, line_length, 0, l->panel_h);
}

int px_panel_init(struct px_panel *p, const struct px_format *f, int panel_w, int panel_h,
		  size_t line_length, int rotate, int fill, int src_w, int src_h)
{
	int rc;

	if (px_format_check(f) < 0)
		return -EINVAL;
	if (panel_w < 1 || line_length < (size_t)panel_w * (size_t)(f->bpp / 8))
		return -EINVAL;
	memset(&p->layout, 0, sizeof(p->layout));
	p->layout.panel_w = panel_w;
	p->layout.panel_h = panel_h;
	p->layout.rotate = rotate;
	p->layout.fill = fill;
	p->layout.src_w = src_w;
	p->layout.src_h = src_h;
	p->layout.src_pitch = src_w;
	rc = px_layout_init(&p->layout);
	if (rc < 0)
		return rc;
	p->fmt = *f;
	memset(&p->table, 0, sizeof(p->table));
	p->table.bytes = f->bpp / 8;
	p->line_length = line_length;
	memset(&p->par, 0, sizeof(p->par));
	return 0;
}

void px_panel_set_par(struct px_panel *p, const struct px_par *par)
{
	if (par && par->run && par->threads > 1)
		p->par = *par;
	else
		memset(&p->par, 0, sizeof(p->par));
}

/* One row range of a parallel draw. */
struct px_job {
	const struct px_panel *p;
	const uint8_t *src;
	uint8_t *mem;
	int n;
};

static void px_job_rows(void *arg, int i)
{
	const struct px_job *j = arg;
	const struct px_layout *l = &j->p->layout;

	px_blit_rows(l, &j->p->table, j->src, j->mem, j->p->line_length,
		     (int)((int64_t)l->panel_h * i / j->n), (int)((int64_t)l->panel_h * (i + 1) / j->n));
}

void px_panel_palette(struct px_panel *p, const uint8_t rgb[256][3])
{
	px_table_build(&p->table, &p->fmt, rgb);
}

int px_panel_draw(struct px_panel *p, uint8_t *mem, const uint8_t *src, int w, int h,
		  int pitch)
{
	struct px_layout *l = &p->layout;

	if (w != l->src_w || h != l->src_h || pitch != l->src_pitch) {
		/* Checked here so that a refused frame leaves the layout as
		 * it was (px_layout_init cannot fail on the panel fields,
		 * which px_panel_init accepted). */
		if (w < 1 || h < 1 || w > PX_MAX_DIM || h > PX_MAX_DIM || pitch < w ||
		    (int64_t)pitch * h > INT32_MAX)
			return -EINVAL;
		l->src_w = w;
		l->src_h = h;
		l->src_pitch = pitch;
		if (px_layout_init(l) < 0)
			return -EINVAL;
	}
	if (p->par.run && l->panel_h >= PX_PAR_MIN_ROWS * p->par.threads) {
		struct px_job j = { p, src, mem, PX_JOBS_PER_THREAD * p->par.threads };

		if (l->panel_h / PX_ROWS_PER_JOB > j.n)
			j.n = l->panel_h / PX_ROWS_PER_JOB;
		p->par.run(p->par.pool, j.n, px_job_rows, &j);
	} else {
		px_blit(l, &p->table, src, mem, p->line_length);
	}
	return 0;
}
