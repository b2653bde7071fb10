/*
 * v_video: 2D drawing into the 8-bit frame, for the HUD, the minimap and
 * the full-screen pages (attract, game over, initials, service menu).
 *
 * This is the one file that writes overlay pixels (the 3D renderer has its
 * own in r_draw.c). Every call clips to the frame (and to a clip rectangle
 * where it takes one), so callers may pass any coordinates. Integer only:
 * the same calls give the same bytes everywhere.
 *
 * Text uses the built-in 8x8 font (v_font.c, the project's own glyphs):
 * space to '_' of ASCII, lower case drawn as upper case, other bytes as
 * '?'. Each character is 8 x 8 pixels at scale 1 (glyphs 7 x 7 and a
 * blank column and row), scaled by whole numbers.
 */
#ifndef ARCADED_ENGINE_V_VIDEO_H
#define ARCADED_ENGINE_V_VIDEO_H

#include <stddef.h>
#include <stdint.h>

struct r_frame;
struct r_par;
struct tex_pic;

#define V_CHAR 8                       /* font cell, pixels at scale 1 */

struct v_rect {
	int x, y, w, h;
};

/* Fills the rectangle x, y, w x h. */
void v_fill(struct r_frame *f, int x, int y, int w, int h, uint8_t c);

/* The outline of the rectangle, one pixel wide. */
void v_box(struct r_frame *f, int x, int y, int w, int h, uint8_t c);

/* Replaces every pixel p of the rectangle by map[p] (a colormap: darkening
 * behind text). */
void v_remap(struct r_frame *f, int x, int y, int w, int h, const uint8_t map[256]);

/* The same, in row ranges on par's threads (engine/render/r_main.h) when
 * the rectangle has at least V_PAR_MIN pixels; par NULL or with fewer than
 * two threads: v_remap. The same bytes either way. */
void v_remap_par(struct r_frame *f, int x, int y, int w, int h, const uint8_t map[256],
		 const struct r_par *par);
/* Smaller rectangles are remapped on the calling thread. At 16384 pixels
 * (the remap is about 0.5 ns a pixel, a batch a few microseconds) the
 * 1280x720 HUD's status bar (46,080) and minimap (57,600) are split too:
 * its time per frame on two threads went from 0.13-0.18 ms to 0.11-0.15
 * (65536 left both on one thread). */
#define V_PAR_MIN 16384

/* A line from (x0, y0) to (x1, y1), both ends drawn (Bresenham), clipped
 * to clip (NULL: the frame). Endpoints may be far outside (they are
 * clipped first, in 64-bit arithmetic); coordinates beyond +/-2^24 are
 * clamped to it. */
void v_line(struct r_frame *f, int x0, int y0, int x1, int y1, uint8_t c,
	    const struct v_rect *clip);

/* A filled triangle: every pixel whose centre is inside or on an edge,
 * clipped to clip (NULL: the frame). */
void v_tri(struct r_frame *f, int x0, int y0, int x1, int y1, int x2, int y2, uint8_t c,
	   const struct v_rect *clip);

/* Text at (x, y) (top left), each font pixel a scale x scale block (scale
 * 1..64). Returns the width in pixels (V_CHAR * scale per character). */
int v_text(struct r_frame *f, int x, int y, int scale, uint8_t c, const char *s);

/* Width v_text would draw. */
int v_text_width(const char *s, int scale);

/* Whether the font has a pixel at column x, row y (0..7) of character ch
 * (for tests and tools). */
int v_glyph_bit(char ch, int x, int y);

/* Writes v in decimal into buf (NUL-terminated, at most len - 1
 * characters), at least `width` digits wide padded with `pad` on the left
 * ('0' or ' '). Returns the length written. The engine has no stdio. */
int v_num(char *buf, int len, uint64_t v, int width, char pad);

/* A picture (tex_pic: column-major, transparent where opaque says 0) with
 * its top left at (x, y), each pixel scale x scale (1..64); a picture
 * without pixels (not decoded: tex_load_wad_names) draws nothing. */
void v_pic(struct r_frame *f, const struct tex_pic *p, int x, int y, int scale);

/* Recording, and replay by columns: how the HUD is drawn by the threads
 * that drew the 3D view, each over the columns of its own strips, right
 * after them (app/view.c; engine/render/r_main.h r_set_strip_done), instead
 * of by one thread after all of them.
 *
 * While a frame's rec is set (struct r_frame.rec), every call above draws
 * nothing and is appended to that list instead (text and remap tables
 * copied; a picture borrowed: it must outlive the replays). v_remap_par records a
 * v_remap. A call that cannot be kept (out of memory) marks the list
 * failed: its replays would miss it, and the caller draws directly
 * instead. A call that writes nothing in the frame is not kept.
 *
 * v_replay(f, l, x0, x1) then draws the list's calls in order, writing only
 * frame columns x0 <= x < x1 (clamped to the frame). Every call is computed
 * over the whole frame as drawn directly and keeps the pixels in those
 * columns (a line is never clipped at the window, which would move its
 * ends), so replays over any columns that cut the frame write together
 * exactly the bytes the direct calls write; replays over disjoint columns
 * may run at once (the list is only read). */
enum {
	V_CMD_FILL = 1,
	V_CMD_REMAP,
	V_CMD_LINE,
	V_CMD_TRI,
	V_CMD_TEXT,
	V_CMD_PIC,
};

struct v_cmd {
	uint8_t op, c;                 /* V_CMD_*, colour */
	uint8_t clipped;               /* triangle: clip holds its clip */
	int x0, x1;                    /* it writes no column outside x0 <= x < x1
					* (a replay elsewhere skips it) */
	int scale;                     /* text, picture */
	int a[6];                      /* x, y, w, h; or the points: a line's clipped
					* to the frame and its clip */
	struct v_rect clip;
	const void *p;                 /* picture: the struct tex_pic */
	uint32_t text;                 /* text, remap: offset of its string or of its
					* 256-byte map in the list's text */
};

/* Zero-initialised is empty. Owned by the caller: v_list_free. */
struct v_list {
	struct v_cmd *cmd;
	int n, cap;
	char *text;                    /* the calls' strings and maps */
	size_t ntext, captext;
	int failed;                    /* a call was lost: do not replay */
};

/* Empties the list (memory kept for the next frame). */
void v_list_reset(struct v_list *l);
void v_list_free(struct v_list *l);
void v_replay(struct r_frame *f, const struct v_list *l, int x0, int x1);

#endif
