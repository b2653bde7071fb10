/*
 * pick: the app's service pages (contract in pick.h).
 */
#include "app/pick.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "app/ct.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud.h"
#include "engine/ui/v_video.h"

static void pick_open(struct pick *p, int page)
{
	memset(p, 0, sizeof(*p));
	p->page = page;
	p->pack = -1;
}

void pick_content(struct pick *p, const struct wads *w, const char *now)
{
	pick_open(p, PICK_CONTENT);
	p->w = w;
	snprintf(p->now, sizeof(p->now), "%s", now ? now : "");
}

void pick_screen(struct pick *p, int rotate, int fill)
{
	pick_open(p, PICK_SCREEN);
	p->rotate = rotate == 90 || rotate == 180 || rotate == 270 ? rotate : 0;
	p->fill = !!fill;
}

void pick_config(struct pick *p, const struct cfgerr *e)
{
	pick_open(p, PICK_CONFIG);
	p->errs = e;
}

/* The rows the cursor moves over. */
static int pick_rows(const struct pick *p)
{
	switch (p->page) {
	case PICK_CONTENT:
		/* packs: built-in, each WAD, BACK; starts: ALL, each map, BACK */
		return p->maps ? p->w->pack[p->pack].nmaps + 2 : p->w->n + 2;
	case PICK_SCREEN:
		return PICK_S_COUNT;
	case PICK_CONFIG:
	default:
		return p->errs->n || p->errs->more ? 2 : 1;  /* [ACKNOWLEDGE,] BACK */
	}
}

static void pick_content_fire(struct pick *p)
{
	int last = pick_rows(p) - 1;

	if (!p->maps) {
		if (p->cursor == last) {
			p->status = PICK_LEFT;
		} else if (p->cursor == 0) {
			p->pack = -1;
			p->status = PICK_CHOSEN;
		} else {
			p->pack = p->cursor - 1;
			p->maps = 1;
			p->cursor = 0;
		}
		return;
	}
	if (p->cursor == last) {
		p->maps = 0;
		p->cursor = p->pack + 1;
		return;
	}
	p->start = p->cursor;
	p->status = PICK_CHOSEN;
}

static void pick_screen_change(struct pick *p, int dir)
{
	if (p->cursor == PICK_S_ROTATE)
		p->rotate = (p->rotate + 360 + dir * 90) % 360;
	else if (p->cursor == PICK_S_SCALE)
		p->fill = !p->fill;
}

enum pick_status pick_keys(struct pick *p, unsigned keys)
{
	int rows;

	if (p->status != PICK_RUNNING)
		return p->status;
	rows = pick_rows(p);
	if (keys & PICK_K_SERVICE) {
		if (p->page == PICK_CONTENT && p->maps) {
			p->maps = 0;
			p->cursor = p->pack + 1;
		} else {
			p->status = PICK_LEFT;
		}
		return p->status;
	}
	if (keys & PICK_K_UP)
		p->cursor = (p->cursor + rows - 1) % rows;
	else if (keys & PICK_K_DOWN)
		p->cursor = (p->cursor + 1) % rows;
	if (p->page == PICK_SCREEN && (keys & (PICK_K_LEFT | PICK_K_RIGHT)))
		pick_screen_change(p, keys & PICK_K_LEFT ? -1 : 1);
	if (!(keys & PICK_K_FIRE))
		return p->status;
	switch (p->page) {
	case PICK_CONTENT:
		pick_content_fire(p);
		break;
	case PICK_SCREEN:
		if (p->cursor == PICK_S_APPLY)
			p->status = PICK_CHOSEN;
		else if (p->cursor == PICK_S_BACK)
			p->status = PICK_LEFT;
		else
			pick_screen_change(p, 1);
		break;
	case PICK_CONFIG:
	default:
		p->status = p->cursor == 0 && rows == 2 ? PICK_CHOSEN : PICK_LEFT;
		break;
	}
	return p->status;
}

/* Appends s (and a blank before it unless out is empty); -ENAMETOOLONG
 * when it does not fit. */
static int pick_cat(char *out, size_t len, const char *s)
{
	size_t n = strlen(out), k = strlen(s) + (n ? 1 : 0);

	if (n + k >= len)
		return -ENAMETOOLONG;
	snprintf(out + n, len - n, "%s%s", n ? " " : "", s);
	return 0;
}

int pick_content_choice(const struct pick *p, char *wad, size_t wlen, char *maps, size_t mlen)
{
	const struct wads_pack *k;

	if (wlen)
		wad[0] = '\0';
	if (mlen)
		maps[0] = '\0';
	if (p->page != PICK_CONTENT || p->status != PICK_CHOSEN)
		return -ENOENT;
	if (p->pack < 0)
		return 0;
	k = &p->w->pack[p->pack];
	if (!k->iwad) {
		/* a PWAD: the first IWAD found gives it what it lacks */
		for (int i = 0; i < p->w->n; i++)
			if (p->w->pack[i].iwad) {
				if (pick_cat(wad, wlen, p->w->pack[i].path) < 0)
					return -ENAMETOOLONG;
				break;
			}
	}
	if (pick_cat(wad, wlen, k->path) < 0)
		return -ENAMETOOLONG;
	for (int i = p->start ? p->start - 1 : 0, n = 0; i < k->nmaps && n < CT_MAX_STAGES; i++, n++)
		if (pick_cat(maps, mlen, k->maps[i]) < 0)
			break;              /* as many as fit */
	return 0;
}

/* ---- drawing ----------------------------------------------------------- */

struct pick_dc {
	struct r_frame *f;
	struct hud_colours c;
	int sc, x, y;
};

/* Text in upper case (the font's), cut at the frame's edge. */
static void pick_text(struct pick_dc *d, int x, int y, int scale, uint8_t col, const char *s)
{
	char buf[CFGERR_LEN];
	int max = (d->f->w - x) / (V_CHAR * scale);
	int n = 0;

	for (; s[n] && n < max && n < (int)sizeof(buf) - 1; n++)
		buf[n] = s[n] >= 'a' && s[n] <= 'z' ? (char)(s[n] - 'a' + 'A') : s[n];
	buf[n < 0 ? 0 : n] = '\0';
	v_text(d->f, x, y, scale, col, buf);
}

static void pick_centre(struct pick_dc *d, int y, int scale, uint8_t col, const char *s)
{
	int w = v_text_width(s, scale);

	pick_text(d, w < d->f->w ? (d->f->w - w) / 2 : 0, y, scale, col, s);
}

static void pick_row(struct pick_dc *d, int sel, const char *label, const char *value)
{
	uint8_t col = sel ? d->c.yellow : d->c.white;

	if (sel)
		pick_text(d, d->x - 2 * V_CHAR * d->sc, d->y, d->sc, col, ">");
	pick_text(d, d->x, d->y, d->sc, col, label);
	if (value)
		pick_text(d, d->x + 20 * V_CHAR * d->sc, d->y, d->sc, col, value);
	d->y += 11 * d->sc;
}

/* The label of row i of the current list. */
static void pick_label(const struct pick *p, int i, char *out, size_t len)
{
	int last = pick_rows(p) - 1;

	if (i == last) {
		snprintf(out, len, "BACK");
	} else if (!p->maps) {
		const struct wads_pack *k = i ? &p->w->pack[i - 1] : NULL;
		if (!k)
			snprintf(out, len, "BUILT-IN LEVELS");
		else
			snprintf(out, len, "%.24s %s %d MAP%s", wads_name(k), k->iwad ? "IWAD" : "PWAD",
				 k->nmaps, k->nmaps == 1 ? "" : "S");
	} else if (i == 0) {
		snprintf(out, len, "ALL MAPS");
	} else {
		snprintf(out, len, "FROM %s", p->w->pack[p->pack].maps[i - 1]);
	}
}

static void pick_list(struct pick_dc *d, const struct pick *p, int bottom)
{
	int rows = pick_rows(p), fit = (bottom - d->y) / (11 * d->sc), top = 0;
	char label[64];

	if (fit < 1)
		fit = 1;
	if (p->cursor >= fit)
		top = p->cursor - fit + 1;   /* keep the cursor's row in view */
	for (int i = top; i < rows && i < top + fit; i++) {
		pick_label(p, i, label, sizeof(label));
		pick_row(d, i == p->cursor, label, NULL);
	}
}

static void pick_draw_content(struct pick_dc *d, const struct pick *p, int bottom)
{
	char line[96];

	pick_centre(d, 6 * d->sc, 2 * d->sc, d->c.cyan, "CONTENT PACK");
	if (p->maps) {
		snprintf(line, sizeof(line), "%s: START WHERE?", wads_name(&p->w->pack[p->pack]));
		pick_text(d, 2 * d->sc, 24 * d->sc, d->sc, d->c.green, line);
	} else if (p->now[0]) {
		snprintf(line, sizeof(line), "NOW: %s", p->now);
		pick_text(d, 2 * d->sc, 24 * d->sc, d->sc, d->c.green, line);
	}
	d->y = 36 * d->sc;
	if (!p->maps && p->w->nbad) {
		/* the files not listed, named, at the foot (half scale when it
		 * has one to spare) */
		int sc = d->sc > 1 ? d->sc / 2 : 1;
		int k = p->w->nbad < WADS_BAD ? p->w->nbad : WADS_BAD;
		int y = bottom - (k + 1) * 10 * sc;
		snprintf(line, sizeof(line), "NOT LISTED (%d):", p->w->nbad);
		pick_text(d, 2 * d->sc, y, sc, d->c.orange, line);
		for (int i = 0; i < k; i++)
			pick_text(d, 2 * d->sc, y + (i + 1) * 10 * sc, sc, d->c.red, p->w->bad[i]);
		bottom = y - 4 * sc;
	}
	pick_list(d, p, bottom);
}

static void pick_draw_screen(struct pick_dc *d, const struct pick *p)
{
	char rot[8];

	pick_centre(d, 6 * d->sc, 2 * d->sc, d->c.cyan, "SCREEN");
	d->y = 36 * d->sc;
	snprintf(rot, sizeof(rot), "%d", p->rotate);
	pick_row(d, p->cursor == PICK_S_ROTATE, "ROTATION", rot);
	pick_row(d, p->cursor == PICK_S_SCALE, "SCALE", p->fill ? "FILL" : "INTEGER");
	pick_row(d, p->cursor == PICK_S_APPLY, "APPLY", NULL);
	pick_row(d, p->cursor == PICK_S_BACK, "BACK", NULL);
	d->y += 11 * d->sc;
	pick_text(d, d->x, d->y, d->sc, d->c.grey, "ROTATION: CLOCKWISE DEGREES");
	pick_text(d, d->x, d->y + 11 * d->sc, d->sc, d->c.grey, "INTEGER: WHOLE SCALE, BORDERS");
	pick_text(d, d->x, d->y + 22 * d->sc, d->sc, d->c.grey, "FILL: STRETCHED OVER THE PANEL");
}

static void pick_draw_config(struct pick_dc *d, const struct pick *p, int bottom)
{
	const struct cfgerr *e = p->errs;
	int rows = pick_rows(p), y = 26 * d->sc, room = bottom - (rows + 1) * 11 * d->sc;
	int sc = d->sc > 1 ? d->sc / 2 : 1;
	char more[48];

	pick_centre(d, 6 * d->sc, 2 * d->sc, d->c.cyan, "CONFIG ERRORS");
	if (rows == 1)
		pick_text(d, 2 * d->sc, y, d->sc, d->c.green, "NO CONFIGURATION ERRORS");
	/* the errors at half the menu's scale when it has one to spare, so
	 * that a path and its reason fit, wrapped at the frame's edge */
	for (int i = 0; i < e->n && y + 9 * sc < room; i++) {
		const char *t = e->text[i];
		int cols = (d->f->w - 4 * d->sc) / (V_CHAR * sc);
		char part[CFGERR_LEN];

		if (cols < 8)
			cols = 8;
		while (*t && y + 9 * sc < room) {
			int n = (int)strlen(t) < cols ? (int)strlen(t) : cols;
			snprintf(part, sizeof(part), "%.*s", n, t);
			pick_text(d, 2 * d->sc, y, sc, d->c.red, part);
			y += 10 * sc;
			t += n;
		}
		y += 4 * sc;               /* between two errors */
	}
	if (e->more) {
		snprintf(more, sizeof(more), "AND %d MORE (SEE THE JOURNAL)", e->more);
		pick_text(d, 2 * d->sc, y, d->sc, d->c.red, more);
	}
	d->y = room + 11 * d->sc;
	if (rows == 2)
		pick_row(d, p->cursor == 0, "ACKNOWLEDGE", NULL);
	pick_row(d, p->cursor == rows - 1, "BACK", NULL);
}

void pick_draw(const struct pick *p, const struct pal *pal, struct r_frame *f)
{
	struct pick_dc d;
	int bottom;

	d.f = f;
	hud_colours(pal, &d.c);
	d.sc = hud_scale(f);
	d.x = 4 * V_CHAR * d.sc;
	d.y = 0;
	v_fill(f, 0, 0, f->w, f->h, d.c.black);
	bottom = f->h - 16 * d.sc;
	pick_centre(&d, f->h - 12 * d.sc, d.sc, d.c.grey,
		    p->page == PICK_SCREEN ? "LEFT/RIGHT CHANGE  SERVICE BACK"
					   : "UP/DOWN MOVE  FIRE SELECT  SERVICE BACK");
	switch (p->page) {
	case PICK_CONTENT:
		pick_draw_content(&d, p, bottom);
		break;
	case PICK_SCREEN:
		pick_draw_screen(&d, p);
		break;
	case PICK_CONFIG:
	default:
		pick_draw_config(&d, p, bottom);
		break;
	}
}
