/*
 * dp_term: terminal preview. Draws frames in the terminal on stdout with
 * the upper-half block U+2580: foreground (24-bit colour) is the top pixel,
 * background the bottom one, so a cell shows two square-ish pixels. This
 * makes `make run` playable on any machine, SSH included.
 *
 * - The frame is scaled (nearest, aspect kept, centred) to fit
 *   cols x (rows - 1) cells; the last line is a status line. Rotation and
 *   the scale mode of the configuration are ignored here (a preview).
 * - Only cells that changed since the last drawn frame are sent, colours
 *   only when they change, and at most 30 frames a second (presents that
 *   come sooner are skipped) so a slow link keeps up.
 * - A frame is one write() from a buffer of our own, on our own
 *   non-blocking open of the terminal: what the terminal does not take at
 *   once stays pending and is sent before anything else; frames presented
 *   meanwhile are skipped. The game loop never blocks on the terminal, and
 *   stdin/stdout's own file flags are never touched, so the keyboard
 *   reader may set O_NONBLOCK on stdin freely.
 * - The whole screen is redrawn on a size change and every 5 seconds, which
 *   repairs anything else written to the terminal (log lines on stderr).
 * - The terminal (stdin if it is one, else /dev/tty) goes to a raw-ish
 *   mode for the keyboard reader (input/in_tty.c), which this file never
 *   reads: no canonical mode, no echo, no flow control, VMIN 0 VTIME 0.
 *   ISIG stays, so Ctrl-C is SIGINT and the app exits cleanly; the suspend
 *   character is disabled because a stopped game would leave the shell on
 *   the alternate screen without echo. Alternate screen, hidden cursor.
 *   All of it is undone on close and by dp_emergency_restore (write and
 *   tcsetattr, both async-signal-safe), which finds the fds and the saved
 *   mode in the file-scope state below.
 */
#include "display/dp.h"
#include "display/dp_int.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#define TERM_FRAME_NS 33333333ull        /* 30 frames a second */
#define TERM_SLACK_NS 4000000ull         /* a present this early still counts */
#define TERM_REPAINT_NS 5000000000ull    /* full redraw period */
#define TERM_CELL_MAX 64                 /* bytes one cell can cost */
#define TERM_UNKNOWN UINT64_MAX          /* cell content / colour not known */

static const char term_enter[] = "\033[?1049h\033[?25l\033[0m\033[2J";
/* CAN first: ends any escape sequence a partial write left open. */
static const char term_leave[] = "\030\033[0m\033[?25h\033[?1049l";
static const char term_status[] =
	"arcaded \u2014 arrows/WASD move, ctrl fire, 5 coin, 1 start, Ctrl-C quits";

/* For dp_term_emergency; written outside signal handlers only, before
 * term_active is raised and after it is cleared. */
static volatile sig_atomic_t term_active;
static volatile sig_atomic_t term_in_fd = -1;  /* -1: terminal mode not changed */
static volatile sig_atomic_t term_out_fd = -1;
static struct termios term_saved;

struct dp {
	int out;                  /* our own open of the terminal, O_NONBLOCK */
	int in;                   /* terminal whose mode we changed, or -1 */
	int in_owned;             /* in was opened here (/dev/tty) */
	int holds_state;          /* this display is the one in term_* above */
	uint32_t pal[256];        /* 0xRRGGBB */
	int cols, rows;           /* terminal size of the current layout */
	int fw, fh;               /* frame size of the current layout */
	int cw, ch, ox, oy;       /* picture size and origin in cells */
	int *sx;                  /* frame column of each picture column */
	uint64_t *cells;          /* last sent (top << 32 | bottom) per cell */
	char *buf;                /* output: [off, len) still to send */
	size_t cap, len, off;
	uint64_t next_ns, repaint_ns;
	int cur_x, cur_y;         /* cursor cell, -1 unknown */
	uint64_t fg, bg;          /* current colours, TERM_UNKNOWN unknown */
	char in_name[16];
	char desc[160];
};

static void term_close(struct dp *d);

/* Terminal size, 80x24 if it cannot be told. */
static void term_size(struct dp *d, int *cols, int *rows)
{
	struct winsize ws;

	*cols = 80;
	*rows = 24;
	if (ioctl(d->out, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0 && ws.ws_row > 0) {
		*cols = ws.ws_col;
		*rows = ws.ws_row;
	}
}

static uint64_t term_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

/* ---- output buffer ---------------------------------------------------- */

static void term_put(struct dp *d, const char *s, size_t n)
{
	memcpy(d->buf + d->len, s, n);
	d->len += n;
}

static void term_putu(struct dp *d, unsigned v)
{
	char tmp[12];
	int n = 0;

	do {
		tmp[n++] = (char)('0' + v % 10);
		v /= 10;
	} while (v);
	while (n)
		d->buf[d->len++] = tmp[--n];
}

static void term_rgb(struct dp *d, uint32_t c)
{
	term_putu(d, c >> 16 & 0xff);
	d->buf[d->len++] = ';';
	term_putu(d, c >> 8 & 0xff);
	d->buf[d->len++] = ';';
	term_putu(d, c & 0xff);
}

static void term_colours(struct dp *d, uint32_t fg, int set_fg, uint32_t bg, int set_bg)
{
	term_put(d, "\033[", 2);
	if (set_fg) {
		term_put(d, "38;2;", 5);
		term_rgb(d, fg);
		d->fg = fg;
	}
	if (set_bg) {
		if (set_fg)
			d->buf[d->len++] = ';';
		term_put(d, "48;2;", 5);
		term_rgb(d, bg);
		d->bg = bg;
	}
	d->buf[d->len++] = 'm';
}

static void term_goto(struct dp *d, int x, int y)
{
	term_put(d, "\033[", 2);
	term_putu(d, (unsigned)y + 1);
	d->buf[d->len++] = ';';
	term_putu(d, (unsigned)x + 1);
	d->buf[d->len++] = 'H';
	d->cur_x = x;
	d->cur_y = y;
}

/* Sends what is pending with one write(); 0 (all sent or some left for
 * later) or -errno. */
static int term_flush(struct dp *d)
{
	ssize_t n;

	if (d->off == d->len) {
		d->off = d->len = 0;
		return 0;
	}
	n = write(d->out, d->buf + d->off, d->len - d->off);
	if (n < 0)
		return errno == EAGAIN || errno == EINTR ? 0 : -errno;
	d->off += (size_t)n;
	if (d->off == d->len)
		d->off = d->len = 0;
	return 0;
}

/* Close: wait (bounded) for the terminal to take everything. */
static void term_drain(struct dp *d, const char *s, size_t n)
{
	int tries;

	for (tries = 0; tries < 20 && n; tries++) {
		ssize_t w = write(d->out, s, n);

		if (w > 0) {
			s += w;
			n -= (size_t)w;
			continue;
		}
		if (w < 0 && errno != EAGAIN && errno != EINTR)
			return;
		struct pollfd p = { .fd = d->out, .events = POLLOUT };

		poll(&p, 1, 50);
	}
}

/* ---- mode ------------------------------------------------------------- */

static void term_mode_enter(struct dp *d)
{
	struct termios raw;

	if (isatty(0)) {
		d->in = 0;
		snprintf(d->in_name, sizeof(d->in_name), "stdin");
	} else {
		d->in = open("/dev/tty", O_RDWR | O_CLOEXEC | O_NOCTTY);
		d->in_owned = d->in >= 0;
		snprintf(d->in_name, sizeof(d->in_name), d->in >= 0 ? "/dev/tty" : "none");
	}
	if (d->in < 0 || tcgetattr(d->in, &term_saved) < 0) {
		snprintf(d->in_name, sizeof(d->in_name), "none");
		if (d->in_owned)
			close(d->in);
		d->in = -1;
		d->in_owned = 0;
		return;
	}
	raw = term_saved;
	raw.c_lflag &= (tcflag_t)~(ICANON | ECHO | IEXTEN);
	raw.c_iflag &= (tcflag_t)~(IXON);
	raw.c_cc[VMIN] = 0;
	raw.c_cc[VTIME] = 0;
	raw.c_cc[VSUSP] = _POSIX_VDISABLE;
	if (tcsetattr(d->in, TCSANOW, &raw) < 0) {
		snprintf(d->in_name, sizeof(d->in_name), "none");
		if (d->in_owned)
			close(d->in);
		d->in = -1;
		d->in_owned = 0;
	}
}

void dp_term_emergency(void)
{
	ssize_t n;

	if (!term_active)
		return;
	n = write(term_out_fd, term_leave, sizeof(term_leave) - 1);
	(void)n;
	if (term_in_fd >= 0)
		tcsetattr(term_in_fd, TCSANOW, &term_saved);
}

/* ---- layout ----------------------------------------------------------- */

/* Fits the frame to the terminal; 0 or -ENOMEM. Everything is redrawn. */
static int term_layout(struct dp *d, int cols, int rows, int fw, int fh)
{
	int aw = cols, ah = 2 * (rows - 1), pw, ph, x;
	size_t ncells, cap;

	d->cols = 0;   /* until this succeeds: the next present lays out again */
	if ((int64_t)fw * ah <= (int64_t)fh * aw) {
		ph = ah;
		pw = (int)((int64_t)fw * ah / fh);
	} else {
		pw = aw;
		ph = (int)((int64_t)fh * aw / fw);
	}
	ph &= ~1;
	if (pw < 1)
		pw = 1;
	if (ph < 2)
		ph = 2;
	ncells = (size_t)pw * (size_t)(ph / 2);
	cap = ncells * TERM_CELL_MAX + (size_t)cols * 4 + 256;
	free(d->sx);
	free(d->cells);
	d->sx = malloc((size_t)pw * sizeof(*d->sx));
	d->cells = malloc(ncells * sizeof(*d->cells));
	if (cap > d->cap) {
		char *b = realloc(d->buf, cap);

		if (!b)
			return -ENOMEM;
		d->buf = b;
		d->cap = cap;
	}
	if (!d->sx || !d->cells)
		return -ENOMEM;
	for (x = 0; x < pw; x++)
		d->sx[x] = (int)(((2 * (int64_t)x + 1) * fw) / (2 * (int64_t)pw));
	memset(d->cells, 0xff, ncells * sizeof(*d->cells));
	d->cols = cols;
	d->rows = rows;
	d->fw = fw;
	d->fh = fh;
	d->cw = pw;
	d->ch = ph / 2;
	d->ox = (cols - pw) / 2;
	d->oy = (rows - 1 - ph / 2) / 2;
	snprintf(d->desc, sizeof(d->desc),
		 "term %dx%d cells, picture %dx%d (half blocks, 24-bit colour), <= 30 fps, "
		 "keyboard mode on %s",
		 cols, rows, pw, ph, d->in_name);
	return 0;
}

/* Clears the screen and writes the status line, truncated to the width. */
static void term_clear(struct dp *d)
{
	const unsigned char *s = (const unsigned char *)term_status;
	int col = 0;

	term_put(d, "\033[0m\033[2J", 8);
	term_goto(d, 0, d->rows - 1);
	while (*s && col < d->cols) {
		/* one column per code point: copy it with its continuation bytes */
		do
			d->buf[d->len++] = (char)*s++;
		while ((*s & 0xc0) == 0x80);
		col++;
	}
	d->cur_x = d->cur_y = -1;
	d->fg = d->bg = TERM_UNKNOWN;
}

/* Appends the cells that differ from what the terminal shows. */
static void term_draw(struct dp *d, const uint8_t *px, int pitch)
{
	int cx, cy, ph = 2 * d->ch;
	uint64_t *cell = d->cells;

	for (cy = 0; cy < d->ch; cy++) {
		int y0 = 2 * cy, y1 = 2 * cy + 1;
		const uint8_t *top = px + (size_t)(((2 * (int64_t)y0 + 1) * d->fh) / (2 * ph)) * pitch;
		const uint8_t *bot = px + (size_t)(((2 * (int64_t)y1 + 1) * d->fh) / (2 * ph)) * pitch;

		for (cx = 0; cx < d->cw; cx++, cell++) {
			uint32_t t = d->pal[top[d->sx[cx]]], b = d->pal[bot[d->sx[cx]]];
			uint64_t key = (uint64_t)t << 32 | b;
			int x = d->ox + cx, y = d->oy + cy;

			if (*cell == key)
				continue;
			*cell = key;
			if (d->cur_x != x || d->cur_y != y)
				term_goto(d, x, y);
			if (t == b) {
				if (d->bg != b)
					term_colours(d, 0, 0, b, 1);
				d->buf[d->len++] = ' ';
			} else {
				if (d->fg != t || d->bg != b)
					term_colours(d, t, d->fg != t, b, d->bg != b);
				term_put(d, "\xe2\x96\x80", 3);
			}
			/* After the last column the cursor waits to wrap. */
			d->cur_x = x + 1 < d->cols ? x + 1 : -1;
		}
	}
}

/* ---- backend ---------------------------------------------------------- */

static int term_open(const struct dp_config *cfg, struct dp **out, char *why, size_t whylen)
{
	char name[PATH_MAX];
	struct dp *d;
	int rc, cols, rows;

	(void)cfg;
	*out = NULL;
	if (!isatty(1)) {
		snprintf(why, whylen, "stdout is not a terminal");
		return -ENOTTY;
	}
	if (term_active) {
		snprintf(why, whylen, "the terminal is already in use by another display");
		return -EBUSY;
	}
	d = calloc(1, sizeof(*d));
	if (!d) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	d->in = -1;
	/* Our own open file description: O_NONBLOCK on it affects no one else. */
	d->out = -1;
	if (ttyname_r(1, name, sizeof(name)) == 0)
		d->out = open(name, O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
	if (d->out < 0)
		d->out = fcntl(1, F_DUPFD_CLOEXEC, 3);
	if (d->out < 0) {
		rc = -errno;
		snprintf(why, whylen, "stdout: %s", strerror(-rc));
		goto fail;
	}
	term_mode_enter(d);
	term_in_fd = d->in;
	term_out_fd = d->out;
	atomic_signal_fence(memory_order_seq_cst);
	term_active = 1;
	d->holds_state = 1;
	term_drain(d, term_enter, sizeof(term_enter) - 1);
	term_size(d, &cols, &rows);
	rc = term_layout(d, cols, rows, cfg->render_w > 0 ? cfg->render_w : 320,
			 cfg->render_h > 0 ? cfg->render_h : 240);
	if (rc < 0) {
		snprintf(why, whylen, "%s", strerror(-rc));
		goto fail;
	}
	*out = d;
	return 0;
fail:
	term_close(d);
	return rc;
}

static void term_set_palette(struct dp *d, const uint8_t rgb[256][3])
{
	int i;

	for (i = 0; i < 256; i++)
		d->pal[i] = (uint32_t)rgb[i][0] << 16 | (uint32_t)rgb[i][1] << 8 | rgb[i][2];
}

static int term_present(struct dp *d, const uint8_t *px, int w, int h, int pitch)
{
	uint64_t now = term_now();
	int cols, rows, rc;

	if (w < 1 || h < 1 || pitch < w)
		return -EINVAL;
	if (d->off < d->len) {
		rc = term_flush(d);
		if (rc < 0 || d->off < d->len)
			return rc;
	}
	if (now + TERM_SLACK_NS < d->next_ns)
		return 0;
	/* Behind by more than a frame (or the first): restart the schedule. */
	d->next_ns = now > d->next_ns + TERM_FRAME_NS ? now + TERM_FRAME_NS
						      : d->next_ns + TERM_FRAME_NS;
	term_size(d, &cols, &rows);
	if (rows < 2)
		return 0;
	if (cols != d->cols || rows != d->rows || w != d->fw || h != d->fh ||
	    now >= d->repaint_ns) {
		rc = term_layout(d, cols, rows, w, h);
		if (rc < 0)
			return rc;
		d->repaint_ns = now + TERM_REPAINT_NS;
		d->len = d->off = 0;
		term_clear(d);
	}
	term_draw(d, px, pitch);
	return term_flush(d);
}

static void term_close(struct dp *d)
{
	if (!d)
		return;
	if (d->holds_state) {
		if (d->off < d->len)
			term_drain(d, d->buf + d->off, d->len - d->off);
		term_drain(d, term_leave, sizeof(term_leave) - 1);
		term_active = 0;
		atomic_signal_fence(memory_order_seq_cst);
		if (d->in >= 0)
			tcsetattr(d->in, TCSANOW, &term_saved);
		term_in_fd = term_out_fd = -1;
	}
	if (d->in_owned)
		close(d->in);
	if (d->out >= 0)
		close(d->out);
	free(d->sx);
	free(d->cells);
	free(d->buf);
	free(d);
}

static const char *term_describe(struct dp *d)
{
	return d->desc;
}

const struct dp_backend dp_term = {
	.name = "term",
	.open = term_open,
	.set_palette = term_set_palette,
	.present = term_present,
	.close = term_close,
	.describe = term_describe,
	.input = "tty",
};
