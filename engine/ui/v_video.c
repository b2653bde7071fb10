/*
 * v_video: 2D drawing into the 8-bit frame (see v_video.h). Everything is
 * clipped here, once, so callers need not care where things fall.
 */
#include "engine/ui/v_video.h"

#include <stddef.h>
#include <string.h>

#include "engine/map/tex.h"
#include "engine/render/r_main.h"
#include "engine/ui/v_local.h"

/* The rectangle r clipped to the frame (and to clip when not NULL);
 * returns 0 when nothing is left. */
static int v_clip(const struct r_frame *f, const struct v_rect *clip, int64_t *x0, int64_t *y0,
		  int64_t *x1, int64_t *y1)
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

void v_fill(struct r_frame *f, int x, int y, int w, int h, uint8_t c)
{
	int64_t x0 = x, y0 = y, x1 = (int64_t)x + w, y1 = (int64_t)y + h;

	if (w <= 0 || h <= 0 || !v_clip(f, NULL, &x0, &y0, &x1, &y1))
		return;
	for (int64_t yy = y0; yy < y1; yy++) {
		uint8_t *p = v_at(f, x0, yy);
		for (int64_t xx = x0; xx < x1; xx++)
			*p++ = c;
	}
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

void v_remap(struct r_frame *f, int x, int y, int w, int h, const uint8_t map[256])
{
	int64_t x0 = x, y0 = y, x1 = (int64_t)x + w, y1 = (int64_t)y + h;

	if (w <= 0 || h <= 0 || !v_clip(f, NULL, &x0, &y0, &x1, &y1))
		return;
	for (int64_t yy = y0; yy < y1; yy++) {
		uint8_t *p = v_at(f, x0, yy);
		for (int64_t xx = x0; xx < x1; xx++, p++)
			*p = map[*p];
	}
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

	if (w <= 0 || h <= 0 || !v_clip(f, NULL, &x0, &y0, &x1, &y1))
		return;
	if (!par || !par->run || par->threads < 2 || (x1 - x0) * (y1 - y0) < V_PAR_MIN ||
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

void v_line(struct r_frame *f, int x0, int y0, int x1, int y1, uint8_t c,
	    const struct v_rect *clip)
{
	int64_t lx = 0, ly = 0, hx = f->w, hy = f->h;
	int64_t ax = x0, ay = y0, bx = x1, by = y1, dx, dy, sx, sy, err;
	int ca, cb;

	int iter = 0;

	if (!v_clip(f, clip, &lx, &ly, &hx, &hy))
		return;
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
			return;
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
	dx = bx > ax ? bx - ax : ax - bx;
	dy = by > ay ? ay - by : by - ay;         /* -|dy| */
	sx = ax < bx ? 1 : -1;
	sy = ay < by ? 1 : -1;
	err = dx + dy;
	for (;;) {
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

/* Twice the signed area of (a, b, p), with pixel centres at +1/2 (all
 * coordinates doubled). */
static int64_t v_edge(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
	return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

void v_tri(struct r_frame *f, int x0, int y0, int x1, int y1, int x2, int y2, uint8_t c,
	   const struct v_rect *clip)
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
	if (!v_clip(f, clip, &lx, &ly, &hx, &hy))
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

int v_text(struct r_frame *f, int x, int y, int scale, uint8_t c, const char *s)
{
	int x0 = x;

	if (scale < 1)
		scale = 1;
	if (scale > 64)
		scale = 64;
	for (; *s; s++, x += V_CHAR * scale) {
		const char(*g)[9] = v_glyph(*s);
		if (x >= f->w || (int64_t)x + V_CHAR * scale <= 0 || y >= f->h ||
		    (int64_t)y + V_CHAR * scale <= 0)
			continue;
		if (x >= 0 && y >= 0 && (int64_t)x + V_CHAR * scale <= f->w &&
		    (int64_t)y + V_CHAR * scale <= f->h) {
			v_glyph_inside(f, x, y, scale, c, g);
			continue;
		}
		for (int r = 0; r < V_CHAR; r++)
			for (int k = 0; k < V_CHAR; k++)
				if (g[r][k] == '#')
					v_fill(f, x + k * scale, y + r * scale, scale, scale, c);
	}
	return x - x0;
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

void v_pic(struct r_frame *f, const struct tex_pic *p, int x, int y, int scale)
{
	if (!p->px)
		return;
	if (scale < 1)
		scale = 1;
	if (scale > 64)
		scale = 64;
	for (int k = 0; k < p->w; k++) {
		const uint8_t *col = p->px + (size_t)k * (size_t)p->h;
		const uint8_t *op = p->opaque ? p->opaque + (size_t)k * (size_t)p->h : NULL;
		int64_t sx = (int64_t)x + (int64_t)k * scale;
		if (sx >= f->w || sx + scale <= 0)
			continue;
		for (int r = 0; r < p->h; r++)
			if (!op || op[r])
				v_fill(f, (int)sx, y + r * scale, scale, scale, col[r]);
	}
}
