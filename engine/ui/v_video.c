/*
 * v_video: 2D drawing into the 8-bit frame (see v_video.h). Everything is
 * clipped here, once, so callers need not care where things fall.
 */
#include "engine/ui/v_video.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "engine/map/tex.h"
#include "engine/render/r_main.h"
#include "engine/ui/v_local.h"

/* Columns a call may write, wx0 <= x < wx1: the whole frame's for a call
 * made directly, a strip's for a replay (v_replay). A window only ever
 * narrows what is written, never the geometry: a replayed call computes
 * what it would over the whole frame and keeps the pixels in its window,
 * so the strips of a frame together write exactly the direct call's
 * bytes. */
struct v_win {
	int64_t x0, x1;
};

static struct v_win v_whole(const struct r_frame *f)
{
	struct v_win w = { 0, f->w };

	return w;
}

/* The rectangle x0..x1 x y0..y1 clipped to the frame, to clip when not
 * NULL and to the window; returns 0 when nothing is left. */
static int v_clip(const struct r_frame *f, const struct v_rect *clip, struct v_win win,
		  int64_t *x0, int64_t *y0, int64_t *x1, int64_t *y1)
{
	int64_t cx0 = 0, cy0 = 0, cx1 = f->w, cy1 = f->h;

	if (clip) {
		if (clip->x > cx0)
			cx0 = clip->x;
		if (clip->y > cy0)
			cy0 = clip->y;
		if ((int64_t)clip->x + clip->w < cx1)
			cx1 = (int64_t)clip->x + clip->w;
		if ((int64_t)clip->y + clip->h < cy1)
			cy1 = (int64_t)clip->y + clip->h;
	}
	if (win.x0 > cx0)
		cx0 = win.x0;
	if (win.x1 < cx1)
		cx1 = win.x1;
	if (*x0 < cx0)
		*x0 = cx0;
	if (*y0 < cy0)
		*y0 = cy0;
	if (*x1 > cx1)
		*x1 = cx1;
	if (*y1 > cy1)
		*y1 = cy1;
	return *x0 < *x1 && *y0 < *y1;
}

static uint8_t *v_at(struct r_frame *f, int64_t x, int64_t y)
{
	return f->px + (size_t)y * (size_t)f->pitch + (size_t)x;
}

/* ---- recording (v_list) ---------------------------------------------- */

/* A new command of f's list for a call that writes no column outside
 * x0 <= x < x1 (clamped to the frame here), or NULL: nothing to write in
 * the frame (the call is dropped), or out of memory (the list is marked
 * failed and the call is lost). */
static struct v_cmd *v_rec(const struct r_frame *f, int op, int64_t x0, int64_t x1)
{
	struct v_list *l = f->rec;
	struct v_cmd *c;

	x0 = x0 < 0 ? 0 : x0;
	x1 = x1 > f->w ? f->w : x1;
	if (l->failed || x0 >= x1)
		return NULL;
	if (l->n == l->cap) {
		int cap = l->cap ? 2 * l->cap : 256;
		struct v_cmd *nc = cap > l->cap ? realloc(l->cmd, (size_t)cap * sizeof(*nc)) : NULL;

		if (!nc) {
			l->failed = 1;
			return NULL;
		}
		l->cmd = nc;
		l->cap = cap;
	}
	c = &l->cmd[l->n++];
	memset(c, 0, sizeof(*c));
	c->op = (uint8_t)op;
	c->x0 = (int)x0;
	c->x1 = (int)x1;
	return c;
}

/* A recorded call's colour and numbers. */
static void v_rec_set(struct v_cmd *k, uint8_t c, int a0, int a1, int a2, int a3, int a4, int a5)
{
	k->c = c;
	k->a[0] = a0;
	k->a[1] = a1;
	k->a[2] = a2;
	k->a[3] = a3;
	k->a[4] = a4;
	k->a[5] = a5;
}

static void v_rec_clip(struct v_cmd *c, const struct v_rect *clip)
{
	if (clip) {
		c->clipped = 1;
		c->clip = *clip;
	}
}

/* Copies n bytes into the list's text: their offset, or -1 (out of
 * memory). */
static int64_t v_rec_bytes(struct v_list *l, const void *p, size_t n)
{
	size_t at = l->ntext;

	if (n > (size_t)1 << 20 || l->ntext + n > (size_t)1 << 30)
		return -1;
	if (l->ntext + n > l->captext) {
		size_t cap = l->captext ? 2 * l->captext : 4096;
		char *nt;

		while (cap < l->ntext + n)
			cap *= 2;
		nt = realloc(l->text, cap);
		if (!nt)
			return -1;
		l->text = nt;
		l->captext = cap;
	}
	memcpy(l->text + at, p, n);
	l->ntext += n;
	return (int64_t)at;
}

void v_list_reset(struct v_list *l)
{
	l->n = 0;
	l->ntext = 0;
	l->failed = 0;
}

void v_list_free(struct v_list *l)
{
	free(l->cmd);
	free(l->text);
	memset(l, 0, sizeof(*l));
}

/* ---- the primitives, each within a window ------------------------------ */

static void v_fill_in(struct r_frame *f, int64_t x, int64_t y, int64_t w, int64_t h, uint8_t c,
		      struct v_win win)
{
	int64_t x0 = x, y0 = y, x1 = x + w, y1 = y + h;

	if (w <= 0 || h <= 0 || !v_clip(f, NULL, win, &x0, &y0, &x1, &y1))
		return;
	for (int64_t yy = y0; yy < y1; yy++)
		memset(v_at(f, x0, yy), c, (size_t)(x1 - x0));
}

void v_fill(struct r_frame *f, int x, int y, int w, int h, uint8_t c)
{
	if (f->rec) {
		struct v_cmd *k = v_rec(f, V_CMD_FILL, x, (int64_t)x + w);

		if (k)
			v_rec_set(k, c, x, y, w, h, 0, 0);
		return;
	}
	v_fill_in(f, x, y, w, h, c, v_whole(f));
}

void v_box(struct r_frame *f, int x, int y, int w, int h, uint8_t c)
{
	if (w <= 0 || h <= 0)
		return;
	v_fill(f, x, y, w, 1, c);
	v_fill(f, x, y + h - 1, w, 1, c);
	v_fill(f, x, y, 1, h, c);
	v_fill(f, x + w - 1, y, 1, h, c);
}

static void v_remap_in(struct r_frame *f, int64_t x, int64_t y, int64_t w, int64_t h,
		       const uint8_t map[256], struct v_win win)
{
	int64_t x0 = x, y0 = y, x1 = x + w, y1 = y + h;

	if (w <= 0 || h <= 0 || !v_clip(f, NULL, win, &x0, &y0, &x1, &y1))
		return;
	for (int64_t yy = y0; yy < y1; yy++) {
		uint8_t *p = v_at(f, x0, yy);
		for (int64_t xx = x0; xx < x1; xx++, p++)
			*p = map[*p];
	}
}

void v_remap(struct r_frame *f, int x, int y, int w, int h, const uint8_t map[256])
{
	if (f->rec) {
		/* the map is copied: callers build it on their stack */
		struct v_cmd *k = v_rec(f, V_CMD_REMAP, x, (int64_t)x + w);
		int64_t at = k ? v_rec_bytes(f->rec, map, 256) : -1;

		if (k && at < 0) {
			f->rec->failed = 1;
		} else if (k) {
			v_rec_set(k, 0, x, y, w, h, 0, 0);
			k->text = (uint32_t)at;
		}
		return;
	}
	v_remap_in(f, x, y, w, h, map, v_whole(f));
}

/* One row range of v_remap_par. */
struct v_remap_job {
	struct r_frame *f;
	int x, y, w, h, n;
	const uint8_t *map;
};

static void v_remap_rows(void *arg, int i)
{
	const struct v_remap_job *j = arg;
	int y0 = j->y + (int)((int64_t)j->h * i / j->n);
	int y1 = j->y + (int)((int64_t)j->h * (i + 1) / j->n);

	v_remap(j->f, j->x, y0, j->w, y1 - y0, j->map);
}

void v_remap_par(struct r_frame *f, int x, int y, int w, int h, const uint8_t map[256],
		 const struct r_par *par)
{
	int64_t x0 = x, y0 = y, x1 = (int64_t)x + w, y1 = (int64_t)y + h;
	struct v_remap_job j;

	if (f->rec || w <= 0 || h <= 0 || !v_clip(f, NULL, v_whole(f), &x0, &y0, &x1, &y1) ||
	    !par || !par->run || par->threads < 2 || (x1 - x0) * (y1 - y0) < V_PAR_MIN ||
	    y1 - y0 < 2 * par->threads) {
		v_remap(f, x, y, w, h, map);
		return;
	}
	/* rows of a range are whole lines of the rectangle: ranges write
	 * disjoint bytes */
	j.f = f;
	j.x = (int)x0;
	j.y = (int)y0;
	j.w = (int)(x1 - x0);
	j.h = (int)(y1 - y0);
	j.n = 2 * par->threads;
	j.map = map;
	par->run(par->pool, j.n, v_remap_rows, &j);
}

/* Cohen-Sutherland outcodes against the inclusive box lo..hi. */
static int v_code(int64_t x, int64_t y, int64_t lx, int64_t ly, int64_t hx, int64_t hy)
{
	return (x < lx ? 1 : 0) | (x > hx ? 2 : 0) | (y < ly ? 4 : 0) | (y > hy ? 8 : 0);
}

/* (a * b) / c rounded to nearest, halves away from zero, for the clip
 * intersections (|a|, |b| < 2^31, so the product fits). */
static int64_t v_muldiv(int64_t a, int64_t b, int64_t c)
{
	int64_t n = a * b;

	if (c < 0) {
		c = -c;
		n = -n;
	}
	return n >= 0 ? (n + c / 2) / c : -((-n + c / 2) / c);
}

/* Coordinates are clamped to +/-V_FAR so the clipping products fit 64
 * bits (2 * 25 bits); only absurd lines are bent by it. */
#define V_FAR (1 << 24)

static int64_t v_far(int64_t v)
{
	return v > V_FAR ? V_FAR : v < -V_FAR ? -V_FAR : v;
}

/* The ends of the line clipped to the frame and clip (never to a window:
 * that would move its ends and so its pixels) into *ax..*by; 0 when
 * nothing of it is left. */
static int v_line_clip(const struct r_frame *f, int x0, int y0, int x1, int y1,
		       const struct v_rect *clip, int64_t *oax, int64_t *oay, int64_t *obx,
		       int64_t *oby)
{
	int64_t lx = 0, ly = 0, hx = f->w, hy = f->h;
	int64_t ax = x0, ay = y0, bx = x1, by = y1;
	int ca, cb;

	int iter = 0;

	if (!v_clip(f, clip, v_whole(f), &lx, &ly, &hx, &hy))
		return 0;
	hx--;
	hy--;
	ax = v_far(ax);
	ay = v_far(ay);
	bx = v_far(bx);
	by = v_far(by);
	ca = v_code(ax, ay, lx, ly, hx, hy);
	cb = v_code(bx, by, lx, ly, hx, hy);
	/* move the outside ends onto the box edges; the rounded ends may drift
	 * by half a pixel from the ideal line (and are clamped into the box if
	 * rounding keeps them out), never outside the box */
	while ((ca | cb) && iter++ < 8) {
		int64_t *px, *py;
		int code;
		if (ca & cb)
			return 0;
		code = ca ? ca : cb;
		px = ca ? &ax : &bx;
		py = ca ? &ay : &by;
		{
			int64_t ox = ca ? bx : ax, oy = ca ? by : ay, nx, ny;
			if (code & 1) {
				nx = lx;
				ny = *py + v_muldiv(oy - *py, lx - *px, ox - *px);
			} else if (code & 2) {
				nx = hx;
				ny = *py + v_muldiv(oy - *py, hx - *px, ox - *px);
			} else if (code & 4) {
				ny = ly;
				nx = *px + v_muldiv(ox - *px, ly - *py, oy - *py);
			} else {
				ny = hy;
				nx = *px + v_muldiv(ox - *px, hy - *py, oy - *py);
			}
			*px = nx;
			*py = ny;
		}
		if (ca)
			ca = v_code(ax, ay, lx, ly, hx, hy);
		else
			cb = v_code(bx, by, lx, ly, hx, hy);
	}
	if (ca | cb) {
		ax = ax < lx ? lx : ax > hx ? hx : ax;
		ay = ay < ly ? ly : ay > hy ? hy : ay;
		bx = bx < lx ? lx : bx > hx ? hx : bx;
		by = by < ly ? ly : by > hy ? hy : by;
	}
	*oax = ax;
	*oay = ay;
	*obx = bx;
	*oby = by;
	return 1;
}

/* The clipped line's pixels (both ends inside the frame) that fall in the
 * window. */
static void v_line_walk(struct r_frame *f, int64_t ax, int64_t ay, int64_t bx, int64_t by,
			uint8_t c, struct v_win win)
{
	int64_t dx, dy, sx, sy, err;

	/* x moves monotonically from ax to bx: nothing to do outside */
	if ((ax < win.x0 && bx < win.x0) || (ax >= win.x1 && bx >= win.x1))
		return;
	dx = bx > ax ? bx - ax : ax - bx;
	dy = by > ay ? ay - by : by - ay;         /* -|dy| */
	sx = ax < bx ? 1 : -1;
	sy = ay < by ? 1 : -1;
	err = dx + dy;
	for (;;) {
		if (ax >= win.x0 && ax < win.x1)
			*v_at(f, ax, ay) = c;
		if (ax == bx && ay == by)
			break;
		int64_t e2 = 2 * err;
		if (e2 >= dy) {
			err += dy;
			ax += sx;
		}
		if (e2 <= dx) {
			err += dx;
			ay += sy;
		}
	}
}

void v_line(struct r_frame *f, int x0, int y0, int x1, int y1, uint8_t c,
	    const struct v_rect *clip)
{
	int64_t ax, ay, bx, by;

	if (!v_line_clip(f, x0, y0, x1, y1, clip, &ax, &ay, &bx, &by))
		return;
	if (f->rec) {
		/* recorded clipped: the replays only walk it */
		struct v_cmd *k = v_rec(f, V_CMD_LINE, ax < bx ? ax : bx, (ax < bx ? bx : ax) + 1);

		if (k)
			v_rec_set(k, c, (int)ax, (int)ay, (int)bx, (int)by, 0, 0);
		return;
	}
	v_line_walk(f, ax, ay, bx, by, c, v_whole(f));
}

/* Twice the signed area of (a, b, p), with pixel centres at +1/2 (all
 * coordinates doubled). */
static int64_t v_edge(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
	return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/* Each pixel is tested on its own, so the window may clip the box. */
static void v_tri_in(struct r_frame *f, int x0, int y0, int x1, int y1, int x2, int y2,
		     uint8_t c, const struct v_rect *clip, struct v_win win)
{
	int64_t ax = 2 * (int64_t)x0, ay = 2 * (int64_t)y0, bx = 2 * (int64_t)x1,
		by = 2 * (int64_t)y1, cx = 2 * (int64_t)x2, cy = 2 * (int64_t)y2;
	int64_t lx = x0, ly = y0, hx = x0, hy = y0;
	int64_t area = v_edge(ax, ay, bx, by, cx, cy);

	if (area == 0)
		return;
	if (area < 0) {                       /* make the winding positive */
		int64_t tx = bx, ty = by;
		bx = cx;
		by = cy;
		cx = tx;
		cy = ty;
	}
	if (x1 < lx) lx = x1;
	if (x2 < lx) lx = x2;
	if (y1 < ly) ly = y1;
	if (y2 < ly) ly = y2;
	if (x1 > hx) hx = x1;
	if (x2 > hx) hx = x2;
	if (y1 > hy) hy = y1;
	if (y2 > hy) hy = y2;
	hx++;
	hy++;
	if (!v_clip(f, clip, win, &lx, &ly, &hx, &hy))
		return;
	for (int64_t y = ly; y < hy; y++) {
		for (int64_t x = lx; x < hx; x++) {
			int64_t px = 2 * x + 1, py = 2 * y + 1;
			if (v_edge(ax, ay, bx, by, px, py) >= 0 && v_edge(bx, by, cx, cy, px, py) >= 0 &&
			    v_edge(cx, cy, ax, ay, px, py) >= 0)
				*v_at(f, x, y) = c;
		}
	}
}

void v_tri(struct r_frame *f, int x0, int y0, int x1, int y1, int x2, int y2, uint8_t c,
	   const struct v_rect *clip)
{
	if (f->rec) {
		/* the columns of its box, within clip */
		int64_t lo = x0 < x1 ? (x0 < x2 ? x0 : x2) : (x1 < x2 ? x1 : x2);
		int64_t hi = (int64_t)(x0 > x1 ? (x0 > x2 ? x0 : x2) : (x1 > x2 ? x1 : x2)) + 1;
		struct v_cmd *k;

		if (clip && clip->x > lo)
			lo = clip->x;
		if (clip && (int64_t)clip->x + clip->w < hi)
			hi = (int64_t)clip->x + clip->w;
		k = v_rec(f, V_CMD_TRI, lo, hi);
		if (k) {
			v_rec_set(k, c, x0, y0, x1, y1, x2, y2);
			v_rec_clip(k, clip);
		}
		return;
	}
	v_tri_in(f, x0, y0, x1, y1, x2, y2, c, clip, v_whole(f));
}

static const char (*v_glyph(char ch))[9]
{
	unsigned char u = (unsigned char)ch;

	if (u >= 'a' && u <= 'z')
		u = (unsigned char)(u - 'a' + 'A');
	if (u < V_FONT_FIRST || u >= V_FONT_FIRST + V_FONT_GLYPHS)
		u = '?';
	return v_font[u - V_FONT_FIRST];
}

int v_glyph_bit(char ch, int x, int y)
{
	if (x < 0 || x >= V_CHAR || y < 0 || y >= V_CHAR)
		return 0;
	return v_glyph(ch)[y][x] == '#';
}

int v_text_width(const char *s, int scale)
{
	int n = 0;

	while (s[n])
		n++;
	return n * V_CHAR * scale;
}

/* Glyph g with its cell at (x, y), the whole cell inside the frame: each
 * row's lit cells as runs, one store loop per run and pixel row (the same
 * bytes as a v_fill per lit cell, without a clip and a call for each). */
static void v_glyph_inside(struct r_frame *f, int x, int y, int scale, uint8_t c,
			   const char (*g)[9])
{
	for (int r = 0; r < V_CHAR; r++) {
		for (int k = 0; k < V_CHAR;) {
			int k0 = k;

			if (g[r][k] != '#') {
				k++;
				continue;
			}
			while (k < V_CHAR && g[r][k] == '#')
				k++;
			for (int yy = 0; yy < scale; yy++)
				memset(v_at(f, x + k0 * scale, y + r * scale + yy), c,
				       (size_t)(k - k0) * (size_t)scale);
		}
	}
}

static int v_scale(int scale)
{
	return scale < 1 ? 1 : scale > 64 ? 64 : scale;
}

/* A glyph whose cell lies wholly inside the frame and the window is drawn
 * in runs (v_glyph_inside); one the edge cuts, cell by cell: the same
 * bytes. */
static void v_text_in(struct r_frame *f, int64_t x, int y, int scale, uint8_t c, const char *s,
		      struct v_win win)
{
	int64_t cell = V_CHAR * scale;

	for (; *s; s++, x += cell) {
		const char(*g)[9] = v_glyph(*s);
		if (x >= win.x1 || x >= f->w || x + cell <= win.x0 || x + cell <= 0 || y >= f->h ||
		    (int64_t)y + cell <= 0)
			continue;
		if (x >= win.x0 && x >= 0 && y >= 0 && x + cell <= win.x1 && x + cell <= f->w &&
		    (int64_t)y + cell <= f->h) {
			v_glyph_inside(f, (int)x, y, scale, c, g);
			continue;
		}
		for (int r = 0; r < V_CHAR; r++)
			for (int k = 0; k < V_CHAR; k++)
				if (g[r][k] == '#')
					v_fill_in(f, x + k * scale, (int64_t)y + r * scale, scale,
						  scale, c, win);
	}
}

int v_text(struct r_frame *f, int x, int y, int scale, uint8_t c, const char *s)
{
	size_t n = strlen(s);

	scale = v_scale(scale);
	if (f->rec) {
		struct v_cmd *k = v_rec(f, V_CMD_TEXT, x, x + (int64_t)n * V_CHAR * scale);
		int64_t at = k ? v_rec_bytes(f->rec, s, n + 1) : -1;

		if (k && at < 0) {
			f->rec->failed = 1;
		} else if (k) {
			v_rec_set(k, c, x, y, 0, 0, 0, 0);
			k->scale = scale;
			k->text = (uint32_t)at;
		}
	} else {
		v_text_in(f, x, y, scale, c, s, v_whole(f));
	}
	return (int)((int64_t)n * V_CHAR * scale);
}

int v_num(char *buf, int len, uint64_t v, int width, char pad)
{
	char tmp[24];
	int n = 0, out = 0;

	do {
		tmp[n++] = (char)('0' + v % 10);
		v /= 10;
	} while (v);
	while (n < width && n < (int)sizeof(tmp))
		tmp[n++] = pad;
	while (n > 0 && out < len - 1)
		buf[out++] = tmp[--n];
	if (len > 0)
		buf[out] = '\0';
	return out;
}

static void v_pic_in(struct r_frame *f, const struct tex_pic *p, int x, int y, int scale,
		     struct v_win win)
{
	if (!p->px)
		return;
	scale = v_scale(scale);
	for (int k = 0; k < p->w; k++) {
		const uint8_t *col = p->px + (size_t)k * (size_t)p->h;
		const uint8_t *op = p->opaque ? p->opaque + (size_t)k * (size_t)p->h : NULL;
		int64_t sx = (int64_t)x + (int64_t)k * scale;
		if (sx >= f->w || sx >= win.x1 || sx + scale <= 0 || sx + scale <= win.x0)
			continue;
		for (int r = 0; r < p->h; r++)
			if (!op || op[r])
				v_fill_in(f, sx, (int64_t)y + (int64_t)r * scale, scale, scale,
					  col[r], win);
	}
}

void v_pic(struct r_frame *f, const struct tex_pic *p, int x, int y, int scale)
{
	if (f->rec) {
		struct v_cmd *k = p->px ? v_rec(f, V_CMD_PIC, x, x + (int64_t)p->w * v_scale(scale))
					: NULL;

		if (k) {
			v_rec_set(k, 0, x, y, 0, 0, 0, 0);
			k->scale = scale;
			k->p = p;
		}
		return;
	}
	v_pic_in(f, p, x, y, scale, v_whole(f));
}

void v_replay(struct r_frame *f, const struct v_list *l, int x0, int x1)
{
	struct v_win win = { x0 < 0 ? 0 : x0, x1 > f->w ? f->w : x1 };

	if (win.x0 >= win.x1)
		return;
	for (int i = 0; i < l->n; i++) {
		const struct v_cmd *k = &l->cmd[i];
		const struct v_rect *clip = k->clipped ? &k->clip : NULL;

		if (k->x1 <= win.x0 || k->x0 >= win.x1)
			continue;
		switch (k->op) {
		case V_CMD_FILL:
			v_fill_in(f, k->a[0], k->a[1], k->a[2], k->a[3], k->c, win);
			break;
		case V_CMD_REMAP:
			v_remap_in(f, k->a[0], k->a[1], k->a[2], k->a[3],
				   (const uint8_t *)l->text + k->text, win);
			break;
		case V_CMD_LINE:
			v_line_walk(f, k->a[0], k->a[1], k->a[2], k->a[3], k->c, win);
			break;
		case V_CMD_TRI:
			v_tri_in(f, k->a[0], k->a[1], k->a[2], k->a[3], k->a[4], k->a[5], k->c, clip,
				 win);
			break;
		case V_CMD_TEXT:
			v_text_in(f, k->a[0], k->a[1], k->scale, k->c, l->text + k->text, win);
			break;
		case V_CMD_PIC:
			v_pic_in(f, k->p, k->a[0], k->a[1], k->scale, win);
			break;
		}
	}
}
