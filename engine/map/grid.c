/*
 * grid: ASCII tile maps to sectors, lines and things (grid.h; syntax in
 * docs/grid.md).
 *
 * Two passes over the text: the legend fills one definition per tile
 * character, then the rows are checked (defined characters, equal widths,
 * open tiles closed in by wall tiles). The import flood-fills 4-connected
 * regions of open tiles with the same surface into sectors, walks every
 * horizontal and vertical tile boundary emitting runs of equal edges as
 * single lines, and hands the map to map_finish.
 */
#include "engine/map/grid.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/msg.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"

#define GRID_THINGS 4                  /* things per tile definition */
#define GRID_TOKENS 24                 /* tokens per legend line */
#define GRID_NAMELEN 32                /* longest texture name token */
#define GRID_HEIGHT_MAX 16383          /* |floor|, |ceiling| in map units */

enum grid_kind { GK_UNDEF, GK_VOID, GK_WALL, GK_OPEN };

struct grid_thing {
	uint16_t type;
	ang_t angle;
};

struct grid_def {
	enum grid_kind kind;
	int tex;                       /* wall tiles: their face texture */
	int32_t floor, ceil;
	int light, ftex, ctex, special, tag;
	int edge;                      /* texture of this tile's step and lintel
					* faces; -1: the first wall tile's */
	struct grid_thing things[GRID_THINGS];
	int nthings, players;
	int surf;                      /* surface class of open tiles */
};

struct grid_tok {
	const char *s;
	size_t n;
	int col;
};

struct grid_p {
	const char *name;
	const struct grid_names *names;
	char *err;
	size_t errlen;
	struct grid_def defs[256];
	char mapname[9];
	int first_wall_tex;            /* -1 until a wall tile is defined */
	/* rows */
	const char **row;
	int rows, cols, row_line0;     /* row_line0: text line of row 0 */
	/* import */
	uint32_t *sec;                 /* per cell: sector, MAP_NONE if solid */
	uint32_t nsec;
	uint32_t *sec_cell;            /* first cell of each sector */
};

/* "name:line:col: " (col 0: "name:line: "; line 0: "name: "), then msg. */
static int grid_fail(struct grid_p *p, int line, int col, const char *msg)
{
	if (p->err && p->errlen)
		p->err[0] = '\0';
	msg_cat(p->err, p->errlen, p->name);
	if (line > 0) {
		msg_cat(p->err, p->errlen, ":");
		msg_int(p->err, p->errlen, line);
		if (col > 0) {
			msg_cat(p->err, p->errlen, ":");
			msg_int(p->err, p->errlen, col);
		}
	}
	msg_cat(p->err, p->errlen, ": ");
	msg_cat(p->err, p->errlen, msg);
	return -EINVAL;
}

/* Appends " 'c'" (printable) or " (byte N)" to the message. */
static void grid_msg_char(struct grid_p *p, unsigned char c)
{
	char q[4] = { '\'', (char)c, '\'', '\0' };

	if (c > 32 && c < 127) {
		msg_cat(p->err, p->errlen, " ");
		msg_cat(p->err, p->errlen, q);
	} else {
		msg_cat(p->err, p->errlen, " (byte ");
		msg_int(p->err, p->errlen, c);
		msg_cat(p->err, p->errlen, ")");
	}
}

static void grid_msg_tok(struct grid_p *p, const struct grid_tok *t)
{
	size_t n = t->n < GRID_NAMELEN ? t->n : GRID_NAMELEN;
	char buf[GRID_NAMELEN + 3];

	buf[0] = '\'';
	memcpy(buf + 1, t->s, n);
	buf[n + 1] = '\'';
	buf[n + 2] = '\0';
	msg_cat(p->err, p->errlen, buf);
}

static int grid_tok_is(const struct grid_tok *t, const char *s)
{
	return t->n == strlen(s) && memcmp(t->s, s, t->n) == 0;
}

/* Splits a line into blank-separated tokens up to a token starting with
 * ';' (a comment); returns the count, or -1 when there are more than max. */
static int grid_split(const char *s, size_t n, struct grid_tok *tok, int max)
{
	int k = 0;
	size_t i = 0;

	while (i < n) {
		size_t b;

		if (s[i] == ' ' || s[i] == '\t') {
			i++;
			continue;
		}
		if (s[i] == ';')
			break;
		if (k == max)
			return -1;
		b = i;
		while (i < n && s[i] != ' ' && s[i] != '\t')
			i++;
		tok[k].s = s + b;
		tok[k].n = i - b;
		tok[k].col = (int)b + 1;
		k++;
	}
	return k;
}

/* Decimal integer token, optional sign; 0 or -1 when not a number or
 * outside [lo, hi]. */
static int grid_int(const struct grid_tok *t, int32_t lo, int32_t hi, int32_t *out)
{
	size_t i = 0;
	int neg = 0;
	int64_t v = 0;

	if (t->n > 0 && (t->s[0] == '-' || t->s[0] == '+')) {
		neg = t->s[0] == '-';
		i = 1;
	}
	if (i == t->n)
		return -1;
	for (; i < t->n; i++) {
		if (t->s[i] < '0' || t->s[i] > '9')
			return -1;
		v = v * 10 + (t->s[i] - '0');
		if (v > (int64_t)1 << 32)
			return -1;
	}
	if (neg)
		v = -v;
	if (v < lo || v > hi)
		return -1;
	*out = (int32_t)v;
	return 0;
}

/* Texture (flat 0) or flat (flat 1) token: digits are a number, anything
 * else a name for the caller's lookup. */
static int grid_texture(struct grid_p *p, int line, const struct grid_tok *t, int flat, int *out)
{
	int32_t v;
	char name[GRID_NAMELEN + 1];
	int (*fn)(void *, const char *) = NULL;
	int r;

	if (t->n > 0 && t->s[0] >= '0' && t->s[0] <= '9') {
		if (grid_int(t, 0, 65535, &v)) {
			grid_fail(p, line, t->col, flat ? "bad flat number " : "bad texture number ");
			grid_msg_tok(p, t);
			return -EINVAL;
		}
		*out = v;
		return 0;
	}
	if (p->names)
		fn = flat ? p->names->flat : p->names->wall;
	r = -1;
	if (fn && t->n <= GRID_NAMELEN) {
		memcpy(name, t->s, t->n);
		name[t->n] = '\0';
		r = fn(p->names->ctx, name);
	}
	if (r < 0 || r > 65535) {
		grid_fail(p, line, t->col, flat ? "unknown flat " : "unknown texture ");
		grid_msg_tok(p, t);
		return -EINVAL;
	}
	*out = r;
	return 0;
}

/* Direction word or degrees (counter-clockwise from east). */
static int grid_angle(const struct grid_tok *t, ang_t *out)
{
	static const char words[8][10] = { "east", "northeast", "north", "northwest",
					   "west", "southwest", "south", "southeast" };
	int32_t deg;

	for (int i = 0; i < 8; i++)
		if (grid_tok_is(t, words[i])) {
			*out = (ang_t)i * ANG45;
			return 0;
		}
	if (grid_int(t, 0, 359, &deg))
		return -1;
	*out = (ang_t)(((uint64_t)deg << 32) / 360);
	return 0;
}

static int grid_add_thing(struct grid_p *p, struct grid_def *d, int line, int col,
			  uint16_t type, ang_t angle)
{
	if (d->nthings == GRID_THINGS)
		return grid_fail(p, line, col, "too many things on one tile (4 at most)");
	d->things[d->nthings].type = type;
	d->things[d->nthings].angle = angle;
	d->nthings++;
	return 0;
}

/* An open tile's keyword at tok[*i] and its values. */
static int grid_open_key(struct grid_p *p, struct grid_def *d, int line, const struct grid_tok *t,
			 int n, int *i)
{
	const struct grid_tok *k = &t[*i];
	int32_t a, b;
	ang_t ang = 0;
	int need = grid_tok_is(k, "lamp") ? 2 : 1;

	if (*i + need >= n) {
		grid_fail(p, line, k->col, "missing value after ");
		grid_msg_tok(p, k);
		return -EINVAL;
	}
	if (grid_tok_is(k, "floor") || grid_tok_is(k, "ceil")) {
		if (grid_int(&t[*i + 1], -GRID_HEIGHT_MAX, GRID_HEIGHT_MAX, &a))
			return grid_fail(p, line, t[*i + 1].col, "height must be -16383..16383");
		*(grid_tok_is(k, "floor") ? &d->floor : &d->ceil) = a;
	} else if (grid_tok_is(k, "light")) {
		if (grid_int(&t[*i + 1], 0, 255, &a))
			return grid_fail(p, line, t[*i + 1].col, "light must be 0..255");
		d->light = a;
	} else if (grid_tok_is(k, "special") || grid_tok_is(k, "tag")) {
		if (grid_int(&t[*i + 1], 0, 65535, &a))
			return grid_fail(p, line, t[*i + 1].col, "value must be 0..65535");
		*(grid_tok_is(k, "tag") ? &d->tag : &d->special) = a;
	} else if (grid_tok_is(k, "ftex") || grid_tok_is(k, "ctex")) {
		if (grid_texture(p, line, &t[*i + 1], 1, grid_tok_is(k, "ftex") ? &d->ftex : &d->ctex))
			return -EINVAL;
	} else if (grid_tok_is(k, "edge")) {
		if (grid_texture(p, line, &t[*i + 1], 0, &d->edge))
			return -EINVAL;
	} else if (grid_tok_is(k, "player")) {
		if (grid_angle(&t[*i + 1], &ang))
			return grid_fail(p, line, t[*i + 1].col,
					 "bad direction (east, north, ... or degrees 0..359)");
		if (grid_add_thing(p, d, line, k->col, 1, ang))
			return -EINVAL;
		d->players++;
	} else if (grid_tok_is(k, "thing")) {
		if (grid_int(&t[*i + 1], 1, 65535, &a))
			return grid_fail(p, line, t[*i + 1].col, "thing type must be 1..65535");
		if (*i + 2 < n && grid_angle(&t[*i + 2], &ang) == 0)
			(*i)++;
		if (grid_add_thing(p, d, line, k->col, (uint16_t)a, ang))
			return -EINVAL;
	} else if (grid_tok_is(k, "lamp")) {
		static const char colours[8][7] = { "white", "red",   "orange", "yellow",
						     "green", "cyan", "blue",   "purple" };
		int c = 0;
		if (grid_int(&t[*i + 1], 32, 256, &a))
			return grid_fail(p, line, t[*i + 1].col, "lamp intensity must be 32..256");
		if (grid_int(&t[*i + 2], 64, 512, &b))
			return grid_fail(p, line, t[*i + 2].col, "lamp radius must be 64..512");
		if (*i + 3 < n)
			for (int q = 1; q < 8; q++)
				if (grid_tok_is(&t[*i + 3], colours[q]))
					c = q;
		if (c || (*i + 3 < n && grid_tok_is(&t[*i + 3], "white")))
			(*i)++;
		/* th.h's light thing: nearest intensity step of 32, radius step
		 * of 64 */
		if (grid_add_thing(p, d, line, k->col,
				   th_light_type((b + 32) / 64 - 1, (a + 16) / 32 - 1, c), 0))
			return -EINVAL;
		(*i)++;
	} else {
		grid_fail(p, line, k->col, "unknown keyword ");
		grid_msg_tok(p, k);
		return -EINVAL;
	}
	*i += 2;
	return 0;
}

static void grid_open_defaults(struct grid_def *d)
{
	memset(d, 0, sizeof *d);
	d->kind = GK_OPEN;
	d->ceil = 128;
	d->light = 160;
	d->edge = -1;
}

/* "C = ..." */
static int grid_legend(struct grid_p *p, int line, const struct grid_tok *t, int n)
{
	unsigned char c = (unsigned char)t[0].s[0];
	struct grid_def *d = &p->defs[c];
	int i = 2;

	if (n < 3 || !grid_tok_is(&t[1], "="))
		return grid_fail(p, line, t[0].col, "expected 'C = definition', 'name NAME' or 'map'");
	if (d->kind != GK_UNDEF) {
		grid_fail(p, line, t[0].col, "tile");
		grid_msg_char(p, c);
		msg_cat(p->err, p->errlen, " defined twice");
		return -EINVAL;
	}
	if (grid_tok_is(&t[2], "wall")) {
		memset(d, 0, sizeof *d);
		d->kind = GK_WALL;
		if (n > 4)
			return grid_fail(p, line, t[4].col, "a wall takes one texture");
		if (n == 4 && grid_texture(p, line, &t[3], 0, &d->tex))
			return -EINVAL;
		if (p->first_wall_tex < 0)
			p->first_wall_tex = d->tex;
		return 0;
	}
	if (grid_tok_is(&t[2], "void")) {
		if (n > 3)
			return grid_fail(p, line, t[3].col, "void takes no values");
		memset(d, 0, sizeof *d);
		d->kind = GK_VOID;
		return 0;
	}
	if (t[2].n == 1 && p->defs[(unsigned char)t[2].s[0]].kind == GK_OPEN) {
		*d = p->defs[(unsigned char)t[2].s[0]];
		d->nthings = 0;
		d->players = 0;
		i = 3;
	} else {
		grid_open_defaults(d);
		if (grid_tok_is(&t[2], "open"))
			i = 3;
		else if (t[2].n == 1 && (t[2].s[0] < 'a' || t[2].s[0] > 'z')) {
			grid_fail(p, line, t[2].col, "tile");
			grid_msg_char(p, (unsigned char)t[2].s[0]);
			msg_cat(p->err, p->errlen, " is not an open tile defined above");
			return -EINVAL;
		}
	}
	while (i < n)
		if (grid_open_key(p, d, line, t, n, &i))
			return -EINVAL;
	if (d->ceil < d->floor)
		return grid_fail(p, line, t[0].col, "ceiling below floor");
	return 0;
}

/* The legend, up to and including the "map" line; *pos is left at the
 * first row. */
static int grid_header(struct grid_p *p, const char *text, size_t len, size_t *pos, int *line)
{
	struct grid_tok t[GRID_TOKENS];

	while (*pos < len) {
		const char *s = text + *pos;
		const char *nl = memchr(s, '\n', len - *pos);
		size_t n = nl ? (size_t)(nl - s) : len - *pos;
		int k;

		*pos += n + (nl ? 1 : 0);
		(*line)++;
		if (n && s[n - 1] == '\r')
			n--;
		k = grid_split(s, n, t, GRID_TOKENS);
		if (k < 0)
			return grid_fail(p, *line, 0, "too many words on one line");
		if (k == 0)
			continue;
		if (t[0].n == 1) {
			if (grid_legend(p, *line, t, k))
				return -EINVAL;
			continue;
		}
		if (grid_tok_is(&t[0], "map") && k == 1)
			return 0;
		if (grid_tok_is(&t[0], "name") && k == 2 && t[1].n <= 8) {
			memcpy(p->mapname, t[1].s, t[1].n);
			p->mapname[t[1].n] = '\0';
			continue;
		}
		grid_fail(p, *line, t[0].col, "expected 'C = definition', 'name NAME' (8 chars) or 'map', got ");
		grid_msg_tok(p, &t[0]);
		return -EINVAL;
	}
	return grid_fail(p, 0, 0, "no 'map' line before the rows");
}

static const struct grid_def *grid_at(const struct grid_p *p, int r, int c)
{
	static const struct grid_def outside = { .kind = GK_VOID };

	if (r < 0 || c < 0 || r >= p->rows || c >= p->cols)
		return &outside;
	return &p->defs[(unsigned char)p->row[r][c]];
}

/* Collects the rows after "map" and checks them. */
static int grid_rows(struct grid_p *p, const char *text, size_t len, size_t pos, int line)
{
	size_t *rlen;
	int cap = 0, players = 0;

	p->row_line0 = line + 1;
	for (size_t q = pos; q < len;) {
		const char *nl = memchr(text + q, '\n', len - q);
		q = nl ? (size_t)(nl - text) + 1 : len;
		cap++;
	}
	p->row = calloc(cap ? (size_t)cap : 1, sizeof *p->row);
	rlen = calloc(cap ? (size_t)cap : 1, sizeof *rlen);
	if (!p->row || !rlen) {
		free(rlen);
		return -ENOMEM;
	}
	while (pos < len) {
		const char *s = text + pos;
		const char *nl = memchr(s, '\n', len - pos);
		size_t n = nl ? (size_t)(nl - s) : len - pos;

		pos += n + (nl ? 1 : 0);
		if (n && s[n - 1] == '\r')
			n--;
		p->row[p->rows] = s;
		rlen[p->rows++] = n;
	}
	while (p->rows > 0 && rlen[p->rows - 1] == 0)
		p->rows--;
	if (p->rows == 0) {
		free(rlen);
		return grid_fail(p, 0, 0, "no rows after 'map'");
	}
	if (p->rows > GRID_MAX_DIM || rlen[0] > GRID_MAX_DIM) {
		free(rlen);
		return grid_fail(p, p->row_line0, 0, "map larger than 255 x 255 tiles");
	}
	p->cols = (int)rlen[0];
	for (int r = 0; r < p->rows; r++) {
		if (rlen[r] != (size_t)p->cols || p->cols == 0) {
			int col = (int)(rlen[r] < (size_t)p->cols ? rlen[r] : (size_t)p->cols) + 1;
			grid_fail(p, p->row_line0 + r, col, "row is ");
			msg_int(p->err, p->errlen, (int64_t)rlen[r]);
			msg_cat(p->err, p->errlen, " tiles wide, the first row ");
			msg_int(p->err, p->errlen, p->cols);
			free(rlen);
			return -EINVAL;
		}
	}
	free(rlen);
	for (int r = 0; r < p->rows; r++) {
		for (int c = 0; c < p->cols; c++) {
			unsigned char ch = (unsigned char)p->row[r][c];
			const struct grid_def *d = &p->defs[ch];
			if (ch == ' ')
				continue;
			if (d->kind == GK_UNDEF) {
				grid_fail(p, p->row_line0 + r, c + 1, "unknown tile");
				grid_msg_char(p, ch);
				return -EINVAL;
			}
		}
	}
	for (int r = 0; r < p->rows; r++) {
		for (int c = 0; c < p->cols; c++) {
			const struct grid_def *d = grid_at(p, r, c);
			static const int dr[4] = { -1, 1, 0, 0 }, dc[4] = { 0, 0, -1, 1 };
			if (d->kind != GK_OPEN)
				continue;
			for (int k = 0; k < 4; k++) {
				int rr = r + dr[k], cc = c + dc[k];
				if (grid_at(p, rr, cc)->kind != GK_VOID)
					continue;
				grid_fail(p, p->row_line0 + r, c + 1, "open tile");
				grid_msg_char(p, (unsigned char)p->row[r][c]);
				msg_cat(p->err, p->errlen,
					rr < 0 || cc < 0 || rr >= p->rows || cc >= p->cols
						? " on the map edge (close the map with wall tiles)"
						: " next to void (close the map with wall tiles)");
				return -EINVAL;
			}
			players += d->players;
			if (players > 1 && d->players)
				return grid_fail(p, p->row_line0 + r, c + 1, "second player start");
		}
	}
	if (players == 0)
		return grid_fail(p, 0, 0, "no player start (a tile with 'player DIRECTION')");
	return 0;
}

static int grid_same_surface(const struct grid_def *a, const struct grid_def *b)
{
	return a->floor == b->floor && a->ceil == b->ceil && a->light == b->light &&
	       a->ftex == b->ftex && a->ctex == b->ctex && a->edge == b->edge &&
	       a->special == b->special && a->tag == b->tag;
}

/* Surface classes of open definitions, then sectors: 4-connected regions
 * of one class, numbered in row-major order of their first tile. */
static int grid_sectors(struct grid_p *p)
{
	size_t cells = (size_t)p->rows * (size_t)p->cols;
	uint32_t *queue;
	int nsurf = 0;

	for (int c = 0; c < 256; c++) {
		struct grid_def *d = &p->defs[c];
		if (d->kind != GK_OPEN)
			continue;
		if (d->edge < 0)
			d->edge = p->first_wall_tex < 0 ? 0 : p->first_wall_tex;
		d->surf = nsurf++;
		for (int e = 0; e < c; e++)
			if (p->defs[e].kind == GK_OPEN && grid_same_surface(d, &p->defs[e])) {
				d->surf = p->defs[e].surf;
				nsurf--;
				break;
			}
	}
	p->sec = malloc(cells * sizeof *p->sec);
	p->sec_cell = malloc(cells * sizeof *p->sec_cell);
	queue = malloc(cells * sizeof *queue);
	if (!p->sec || !p->sec_cell || !queue) {
		free(queue);
		return -ENOMEM;
	}
	for (size_t i = 0; i < cells; i++)
		p->sec[i] = MAP_NONE;
	for (size_t i = 0; i < cells; i++) {
		int r0 = (int)(i / (size_t)p->cols), c0 = (int)(i % (size_t)p->cols);
		const struct grid_def *d = grid_at(p, r0, c0);
		size_t head = 0, tail = 0;

		if (d->kind != GK_OPEN || p->sec[i] != MAP_NONE)
			continue;
		p->sec_cell[p->nsec] = (uint32_t)i;
		p->sec[i] = p->nsec;
		queue[tail++] = (uint32_t)i;
		while (head < tail) {
			uint32_t q = queue[head++];
			int r = (int)(q / (uint32_t)p->cols), c = (int)(q % (uint32_t)p->cols);
			static const int dr[4] = { -1, 1, 0, 0 }, dc[4] = { 0, 0, -1, 1 };
			for (int k = 0; k < 4; k++) {
				const struct grid_def *e = grid_at(p, r + dr[k], c + dc[k]);
				size_t j = (size_t)(r + dr[k]) * (size_t)p->cols + (size_t)(c + dc[k]);
				if (e->kind != GK_OPEN || e->surf != d->surf || p->sec[j] != MAP_NONE)
					continue;
				p->sec[j] = p->nsec;
				queue[tail++] = (uint32_t)j;
			}
		}
		p->nsec++;
	}
	free(queue);
	return 0;
}

/* A line before numbering: corners as (row boundary, column boundary)
 * indices, front sector s0, back s1 (MAP_NONE: one-sided, tex the wall). */
struct grid_line {
	uint32_t c1, c2;
	uint32_t s0, s1;
	int tex;
};

/* The edge between tiles a (north or west) and b (south or east). kind 0:
 * no line; 1: a is in front; 2: b is in front. */
struct grid_edge {
	int kind;
	uint32_t s0, s1;
	int tex;
};

static struct grid_edge grid_edge(const struct grid_p *p, int ra, int ca, int rb, int cb)
{
	const struct grid_def *a = grid_at(p, ra, ca), *b = grid_at(p, rb, cb);
	struct grid_edge e = { 0, MAP_NONE, MAP_NONE, 0 };
	uint32_t sa = a->kind == GK_OPEN ? p->sec[(size_t)ra * (size_t)p->cols + (size_t)ca] : MAP_NONE;
	uint32_t sb = b->kind == GK_OPEN ? p->sec[(size_t)rb * (size_t)p->cols + (size_t)cb] : MAP_NONE;

	if (sa == sb)
		return e;              /* both solid, or one sector */
	if (sa != MAP_NONE && sb != MAP_NONE) {
		e.kind = 1;
		e.s0 = sa;
		e.s1 = sb;
	} else if (sa != MAP_NONE) {
		e.kind = 1;
		e.s0 = sa;
		e.tex = b->tex;
	} else {
		e.kind = 2;
		e.s0 = sb;
		e.tex = a->tex;
	}
	return e;
}

static int grid_edge_eq(const struct grid_edge *a, const struct grid_edge *b)
{
	return a->kind == b->kind && a->s0 == b->s0 && a->s1 == b->s1 && a->tex == b->tex;
}

struct grid_lines {
	struct grid_line *v;
	size_t n, cap;
};

static int grid_push(struct grid_lines *L, uint32_t c1, uint32_t c2, const struct grid_edge *e)
{
	if (L->n == L->cap) {
		size_t cap = L->cap ? L->cap * 2 : 64;
		struct grid_line *v = realloc(L->v, cap * sizeof *v);
		if (!v)
			return -ENOMEM;
		L->v = v;
		L->cap = cap;
	}
	L->v[L->n].c1 = c1;
	L->v[L->n].c2 = c2;
	L->v[L->n].s0 = e->s0;
	L->v[L->n].s1 = e->s1;
	L->v[L->n].tex = e->tex;
	L->n++;
	return 0;
}

/* Every boundary, runs of equal edges merged. Corner (row boundary j,
 * column boundary i) has id j * (cols + 1) + i; row boundary 0 is the
 * north edge. Fronts face right of v1 -> v2. */
static int grid_edges(const struct grid_p *p, struct grid_lines *L)
{
	uint32_t cw = (uint32_t)p->cols + 1;

	/* horizontal boundaries: tile (j-1, c) north of (j, c) */
	for (int j = 0; j <= p->rows; j++) {
		int c = 0;
		while (c < p->cols) {
			struct grid_edge e = grid_edge(p, j - 1, c, j, c), f;
			int b = c;
			if (!e.kind) {
				c++;
				continue;
			}
			while (b + 1 < p->cols && (f = grid_edge(p, j - 1, b + 1, j, b + 1),
						   grid_edge_eq(&e, &f)))
				b++;
			uint32_t west = (uint32_t)j * cw + (uint32_t)c;
			uint32_t east = (uint32_t)j * cw + (uint32_t)b + 1;
			/* front north: run westwards; front south: eastwards */
			if (grid_push(L, e.kind == 1 ? east : west, e.kind == 1 ? west : east, &e))
				return -ENOMEM;
			c = b + 1;
		}
	}
	/* vertical boundaries: tile (r, i-1) west of (r, i) */
	for (int i = 0; i <= p->cols; i++) {
		int r = 0;
		while (r < p->rows) {
			struct grid_edge e = grid_edge(p, r, i - 1, r, i), f;
			int b = r;
			if (!e.kind) {
				r++;
				continue;
			}
			while (b + 1 < p->rows && (f = grid_edge(p, b + 1, i - 1, b + 1, i),
						   grid_edge_eq(&e, &f)))
				b++;
			uint32_t north = (uint32_t)r * cw + (uint32_t)i;
			uint32_t south = (uint32_t)(b + 1) * cw + (uint32_t)i;
			/* front west: run southwards; front east: northwards */
			if (grid_push(L, e.kind == 1 ? north : south, e.kind == 1 ? south : north, &e))
				return -ENOMEM;
			r = b + 1;
		}
	}
	return 0;
}

static const struct grid_def *grid_sec_def(const struct grid_p *p, uint32_t s)
{
	uint32_t cell = p->sec_cell[s];

	return grid_at(p, (int)(cell / (uint32_t)p->cols), (int)(cell % (uint32_t)p->cols));
}

static void grid_side(struct map_side *sd, uint32_t sector, int mid, int edge)
{
	memset(sd, 0, sizeof *sd);
	sd->sector = sector;
	sd->mid_tex = (uint16_t)mid;
	sd->top_tex = (uint16_t)edge;
	sd->bot_tex = (uint16_t)edge;
}

static int grid_build(struct grid_p *p, const struct grid_lines *L, struct map **out)
{
	uint32_t cw = (uint32_t)p->cols + 1;
	size_t corners = (size_t)cw * ((size_t)p->rows + 1);
	uint32_t *vid = malloc(corners * sizeof *vid);
	uint32_t nv = 0, nsides = 0, nthings = 0, k = 0, sd = 0;
	struct map *m = NULL;
	int r;

	if (!vid)
		return -ENOMEM;
	for (size_t i = 0; i < corners; i++)
		vid[i] = MAP_NONE;
	for (size_t i = 0; i < L->n; i++) {
		if (vid[L->v[i].c1] == MAP_NONE)
			vid[L->v[i].c1] = nv++;
		if (vid[L->v[i].c2] == MAP_NONE)
			vid[L->v[i].c2] = nv++;
		nsides += L->v[i].s1 == MAP_NONE ? 1 : 2;
	}
	for (int rr = 0; rr < p->rows; rr++)
		for (int c = 0; c < p->cols; c++)
			nthings += (uint32_t)grid_at(p, rr, c)->nthings;
	r = map_alloc(&m, nv, p->nsec, nsides, (uint32_t)L->n, nthings);
	if (r) {
		free(vid);
		return r;
	}
	memcpy(m->name, p->mapname, sizeof m->name);
	for (size_t i = 0; i < corners; i++) {
		if (vid[i] == MAP_NONE)
			continue;
		m->vertices[vid[i]].x = fx_from_int((int32_t)(i % cw) * GRID_TILE);
		m->vertices[vid[i]].y = fx_from_int((p->rows - (int32_t)(i / cw)) * GRID_TILE);
	}
	for (uint32_t s = 0; s < p->nsec; s++) {
		const struct grid_def *d = grid_sec_def(p, s);
		struct map_sector *ms = &m->sectors[s];
		ms->floor_h = fx_from_int(d->floor);
		ms->ceil_h = fx_from_int(d->ceil);
		ms->floor_tex = (uint16_t)d->ftex;
		ms->ceil_tex = (uint16_t)d->ctex;
		ms->light = (uint8_t)d->light;
		ms->special = (uint16_t)d->special;
		ms->tag = (uint16_t)d->tag;
	}
	for (size_t i = 0; i < L->n; i++) {
		const struct grid_line *gl = &L->v[i];
		struct map_line *ml = &m->lines[i];

		ml->v1 = vid[gl->c1];
		ml->v2 = vid[gl->c2];
		ml->side[0] = sd;
		ml->side[1] = MAP_NONE;
		if (gl->s1 == MAP_NONE) {
			ml->flags = ML_BLOCKING;
			grid_side(&m->sides[sd++], gl->s0, gl->tex, 0);
		} else {
			ml->flags = ML_TWOSIDED;
			grid_side(&m->sides[sd++], gl->s0, 0, grid_sec_def(p, gl->s1)->edge);
			ml->side[1] = sd;
			grid_side(&m->sides[sd++], gl->s1, 0, grid_sec_def(p, gl->s0)->edge);
		}
	}
	free(vid);
	for (int rr = 0; rr < p->rows; rr++)
		for (int c = 0; c < p->cols; c++) {
			const struct grid_def *d = grid_at(p, rr, c);
			for (int t = 0; t < d->nthings; t++, k++) {
				m->things[k].x = fx_from_int(c * GRID_TILE + GRID_TILE / 2);
				m->things[k].y = fx_from_int((p->rows - rr) * GRID_TILE - GRID_TILE / 2);
				m->things[k].type = d->things[t].type;
				m->things[k].angle = d->things[t].angle;
			}
		}
	*out = m;
	return 0;
}

int grid_parse(const char *text, size_t len, const char *name, const struct grid_names *names,
	       struct map **out, char *err, size_t errlen)
{
	return grid_parse_lim(text, len, name, names, NULL, out, err, errlen);
}

int grid_parse_lim(const char *text, size_t len, const char *name, const struct grid_names *names,
		   const struct lim_stop *stop, struct map **out, char *err, size_t errlen)
{
	struct grid_p *p = calloc(1, sizeof *p);
	struct grid_lines L = { NULL, 0, 0 };
	struct map *m = NULL;
	size_t pos = 0;
	int line = 0, r;

	*out = NULL;
	if (err && errlen)
		err[0] = '\0';
	if (!p)
		return -ENOMEM;
	p->name = name ? name : "grid";
	p->names = names;
	p->err = err;
	p->errlen = errlen;
	p->first_wall_tex = -1;
	memcpy(p->mapname, "GRID", 5);
	p->defs[' '].kind = GK_VOID;
	r = grid_header(p, text, len, &pos, &line);
	if (!r)
		r = grid_rows(p, text, len, pos, line);
	if (!r)
		r = grid_sectors(p);
	if (!r)
		r = grid_edges(p, &L);
	if (!r)
		r = grid_build(p, &L, &m);
	if (!r) {
		r = map_finish_lim(m, stop, err, errlen);
		if (r == -E2BIG || r == -ECANCELED) {
			/* the node builder's limits and stop: "name: node builder: ..." */
			char why[160] = "";
			msg_cat(why, sizeof why, err ? err : "");
			grid_fail(p, 0, 0, "");
			msg_cat(err, errlen, why);
		} else if (r == -EINVAL) {
			/* the import only makes valid maps: reaching this is a bug,
			 * reported with the finisher's message behind the name */
			char why[160] = "";
			msg_cat(why, sizeof why, err ? err : "");
			grid_fail(p, 0, 0, "import made an invalid map: ");
			msg_cat(err, errlen, why);
		}
	}
	if (r) {
		map_free(m);
		m = NULL;
	}
	free(L.v);
	free(p->row);
	free(p->sec);
	free(p->sec_cell);
	free(p);
	*out = m;
	return r;
}

static int grid_tex_wall(void *ctx, const char *name)
{
	return tex_find(ctx, name);
}

static int grid_tex_flat(void *ctx, const char *name)
{
	return tex_find_flat(ctx, name);
}

void grid_names_from_tex(struct grid_names *n, const struct tex_set *t)
{
	n->ctx = (void *)(uintptr_t)t;
	n->wall = grid_tex_wall;
	n->flat = grid_tex_flat;
}
