/*
 * wiz: the input configuration wizard's state machine and page (the
 * contract is in wiz.h). Times only ever come in as arguments; a time
 * earlier than one already seen counts as the one seen (durations never
 * go negative).
 */
#include "app/wiz.h"

#include <stdio.h>
#include <string.h>

#include "engine/render/r_main.h"
#include "engine/ui/hud.h"
#include "engine/ui/v_video.h"
#include "input/act.h"

enum { WIZ_P_STEPS, WIZ_P_SUMMARY, WIZ_P_END };
enum { WIZ_C_PENDING, WIZ_C_ASSIGNED, WIZ_C_SKIPPED };

/* The steps: up, down, left, right as the stick moves, then the buttons,
 * then the optional controls (weapon, look) a small cabinet skips. */
static const struct {
	uint8_t act;
	char prompt[16];               /* after "PRESS" */
	char label[14];                /* the action, as the summary names it */
} wiz_order[WIZ_STEPS] = {
	{ ACT_FORWARD, "P1 UP", "FORWARD" },
	{ ACT_BACK, "P1 DOWN", "BACK" },
	{ ACT_TURN_LEFT, "P1 LEFT", "TURN LEFT" },
	{ ACT_TURN_RIGHT, "P1 RIGHT", "TURN RIGHT" },
	{ ACT_FIRE, "P1 FIRE", "FIRE" },
	{ ACT_USE, "P1 USE", "USE" },
	{ ACT_STRAFE_LEFT, "P1 STRAFE LEFT", "STRAFE LEFT" },
	{ ACT_STRAFE_RIGHT, "P1 STRAFE RIGHT", "STRAFE RIGHT" },
	{ ACT_START, "P1 START", "START" },
	{ ACT_COIN, "COIN", "COIN" },
	{ ACT_SERVICE, "SERVICE", "SERVICE" },
	{ ACT_WEAPON, "P1 WEAPON", "WEAPON" },
	{ ACT_LOOK_UP, "P1 LOOK UP", "LOOK UP" },
	{ ACT_LOOK_DOWN, "P1 LOOK DOWN", "LOOK DOWN" },
};

int wiz_step_action(int k)
{
	return k >= 0 && k < WIZ_STEPS ? wiz_order[k].act : -1;
}

int wiz_step(const struct wiz *w)
{
	return w->phase == WIZ_P_STEPS ? w->step : WIZ_STEPS;
}

/* The section a device's controls are bound in (wiz.h): "usb-PORT", else
 * "VVVV:PPPP", else "" ([keyboard]). A port bind_device_id refuses falls
 * back to the VID:PID. */
static void wiz_section(const struct in_ident *id, char out[BIND_ID_MAX])
{
	char tmp[BIND_ID_MAX + 8];

	out[0] = '\0';
	if (!id)
		return;
	if (id->port[0]) {
		snprintf(tmp, sizeof(tmp), "usb-%.*s", (int)sizeof(id->port), id->port);
		if (strlen(tmp) < BIND_ID_MAX && bind_device_id(tmp, out) == 0)
			return;
		out[0] = '\0';
	}
	if (id->vid || id->pid)
		snprintf(out, BIND_ID_MAX, "%04x:%04x", id->vid, id->pid);
}

static int wiz_same_ctl(const struct wiz_ctl *a, const struct wiz_ctl *b)
{
	return a->code == b->code && strcmp(a->sec, b->sec) == 0;
}

static int wiz_find_held(const struct wiz *w, const struct wiz_ctl *c)
{
	for (int i = 0; i < w->nheld; i++)
		if (wiz_same_ctl(&w->held[i].c, c))
			return i;
	return -1;
}

static void wiz_unhold(struct wiz *w, int i)
{
	w->held[i] = w->held[--w->nheld];
}

static void wiz_spend_all(struct wiz *w)
{
	for (int i = 0; i < w->nheld; i++)
		w->held[i].spent = 1;
}

static void wiz_end(struct wiz *w, enum wiz_status st)
{
	w->phase = WIZ_P_END;
	w->status = (uint8_t)st;
	w->nheld = 0;
}

static void wiz_next_step(struct wiz *w)
{
	w->step++;
	w->idle_from = w->now;
	if (w->step < WIZ_STEPS)
		return;
	/* Controls held from the last step must not answer the summary. */
	w->phase = WIZ_P_SUMMARY;
	w->summary_from = w->now;
	wiz_spend_all(w);
}

static void wiz_skip(struct wiz *w)
{
	w->cap[w->step].state = WIZ_C_SKIPPED;
	w->note = WIZ_N_SKIPPED;
	w->note_step = w->step;
	wiz_spend_all(w);
	wiz_next_step(w);
}

/* Appends at most max bytes of s to out (of size len, NUL-terminated),
 * cutting what does not fit. */
static void wiz_cat(char *out, size_t len, const char *s, size_t max)
{
	size_t n = strlen(out);

	while (*s && max-- && n + 1 < len)
		out[n++] = *s++;
	out[n] = '\0';
}

/* The device's label for the screen: "hid DragonRise ...". */
static void wiz_label(char out[WIZ_LABEL_MAX], const char *backend, const struct in_ident *id)
{
	out[0] = '\0';
	if (backend)
		wiz_cat(out, WIZ_LABEL_MAX, backend, WIZ_LABEL_MAX);
	if (id && id->name[0]) {
		if (backend)
			wiz_cat(out, WIZ_LABEL_MAX, " ", 1);
		wiz_cat(out, WIZ_LABEL_MAX, id->name, sizeof(id->name));
	}
}

/* Removes code from every action of a section, keeping each list compact
 * (free slots last, as parsed lists are: bind_format's round trip). */
static void wiz_remove_code(int key[ACT_COUNT][BIND_MAX], int code)
{
	for (int a = 0; a < ACT_COUNT; a++) {
		int n = 0;

		for (int i = 0; i < BIND_MAX; i++)
			if (key[a][i] >= 0 && key[a][i] != code)
				key[a][n++] = key[a][i];
		while (n < BIND_MAX)
			key[a][n++] = -1;
	}
}

/* The section c is bound in, created from the device's effective bindings
 * when it has none of its own; NULL when there is no room for it. */
static int (*wiz_section_keys(struct wiz *w, const struct wiz_ctl *c,
			      const struct in_ident *id))[BIND_MAX]
{
	int base[ACT_COUNT][BIND_MAX];
	const struct bind_dev *eff;

	if (!c->sec[0])
		return w->cur.key;
	for (int i = 0; i < w->cur.ndev; i++)
		if (strcmp(w->cur.dev[i].id, c->sec) == 0)
			return w->cur.dev[i].key;
	eff = bind_find_device(&w->cur, id);
	memcpy(base, eff ? eff->key : w->cur.key, sizeof(base));
	if (bind_set_device(&w->cur, c->sec, (const int (*)[BIND_MAX])base) < 0)
		return NULL;
	return w->cur.dev[w->cur.ndev - 1].key;
}

static void wiz_assign(struct wiz *w, const struct wiz_ctl *c, const char *backend,
		       const struct in_ident *id)
{
	int (*key)[BIND_MAX];
	int a = wiz_order[w->step].act;

	w->note_ctl = *c;
	wiz_label(w->note_dev, backend, id);
	for (int j = 0; j < WIZ_STEPS; j++) {
		if (w->cap[j].state == WIZ_C_ASSIGNED && wiz_same_ctl(&w->cap[j].c, c)) {
			w->note = WIZ_N_TAKEN;
			w->note_step = (uint8_t)j;
			return;
		}
	}
	key = wiz_section_keys(w, c, id);
	if (!key) {
		w->note = WIZ_N_FULL;
		w->note_step = w->step;
		return;
	}
	/* the control replaces the action's list and leaves every other one */
	wiz_remove_code(key, c->code);
	for (int i = 0; i < BIND_MAX; i++)
		key[a][i] = -1;
	key[a][0] = c->code;
	w->cap[w->step].state = WIZ_C_ASSIGNED;
	w->cap[w->step].c = *c;
	memcpy(w->cap[w->step].dev, w->note_dev, sizeof(w->note_dev));
	w->note = WIZ_N_ASSIGNED;
	w->note_step = w->step;
	wiz_next_step(w);
}

void wiz_start(struct wiz *w, const struct bind_table *cur, uint64_t now)
{
	memset(w, 0, sizeof(*w));
	w->orig = *cur;
	w->cur = *cur;
	w->phase = WIZ_P_STEPS;
	w->status = WIZ_RUNNING;
	w->now = now;
	w->idle_from = now;
}

static void wiz_time(struct wiz *w, uint64_t now)
{
	if (now > w->now)
		w->now = now;
}

static int wiz_held_long(const struct wiz *w)
{
	for (int i = 0; i < w->nheld; i++)
		if (!w->held[i].spent && w->now - w->held[i].t0 >= WIZ_HOLD_NS)
			return 1;
	return 0;
}

static int wiz_any_unspent(const struct wiz *w)
{
	for (int i = 0; i < w->nheld; i++)
		if (!w->held[i].spent)
			return 1;
	return 0;
}

/* What time alone decides: a hold reaching WIZ_HOLD_NS, the timeouts. */
static void wiz_advance(struct wiz *w, uint64_t now)
{
	wiz_time(w, now);
	switch (w->phase) {
	case WIZ_P_STEPS:
		if (wiz_held_long(w))
			wiz_skip(w);
		else if (w->now - w->idle_from >= WIZ_IDLE_NS)
			wiz_end(w, WIZ_CANCELLED);
		break;
	case WIZ_P_SUMMARY:
		if (wiz_held_long(w))
			wiz_end(w, WIZ_CANCELLED);
		else if (!wiz_any_unspent(w) && w->now - w->summary_from >= WIZ_SUMMARY_NS)
			wiz_end(w, WIZ_DONE);
		break;
	default:
		break;
	}
}

void wiz_event(struct wiz *w, const char *backend, const struct in_ident *id, int code, int down,
	       uint64_t now)
{
	struct wiz_ctl c;
	uint64_t t0;
	int i, spent;

	if (code < BIND_CODE_MIN || code > BIND_CODE_MAX)
		return;
	wiz_advance(w, now);
	if (w->phase == WIZ_P_END)
		return;
	if (w->phase == WIZ_P_STEPS)
		w->idle_from = w->now;
	memset(&c, 0, sizeof(c));
	wiz_section(id, c.sec);
	c.code = code;
	i = wiz_find_held(w, &c);
	if (down) {
		/* a repeat, or a press beyond what is tracked: nothing new */
		if (i >= 0 || w->nheld == WIZ_HELD_MAX)
			return;
		w->held[w->nheld].c = c;
		w->held[w->nheld].t0 = w->now;
		w->held[w->nheld].spent = 0;
		w->nheld++;
		return;
	}
	/* a release of a control pressed before the run began: ignored */
	if (i < 0)
		return;
	t0 = w->held[i].t0;
	spent = w->held[i].spent;
	wiz_unhold(w, i);
	if (spent)
		return;
	if (w->phase == WIZ_P_SUMMARY) {
		wiz_end(w, w->now - t0 >= WIZ_HOLD_NS ? WIZ_CANCELLED : WIZ_DONE);
		return;
	}
	if (w->now - t0 >= WIZ_HOLD_NS)
		wiz_skip(w);
	else
		wiz_assign(w, &c, backend, id);
}

void wiz_drop(struct wiz *w, const struct in_ident *id)
{
	char sec[BIND_ID_MAX];

	wiz_section(id, sec);
	for (int i = w->nheld - 1; i >= 0; i--)
		if (strcmp(w->held[i].c.sec, sec) == 0)
			wiz_unhold(w, i);
}

enum wiz_status wiz_tick(struct wiz *w, uint64_t now)
{
	wiz_advance(w, now);
	return w->phase == WIZ_P_END ? (enum wiz_status)w->status : WIZ_RUNNING;
}

void wiz_cancel(struct wiz *w)
{
	if (w->phase != WIZ_P_END)
		wiz_end(w, WIZ_CANCELLED);
}

static int wiz_same_table(const struct bind_table *a, const struct bind_table *b)
{
	if (memcmp(a->key, b->key, sizeof(a->key)) != 0 || a->ndev != b->ndev)
		return 0;
	for (int d = 0; d < a->ndev; d++)
		if (strcmp(a->dev[d].id, b->dev[d].id) != 0 ||
		    memcmp(a->dev[d].key, b->dev[d].key, sizeof(a->dev[d].key)) != 0)
			return 0;
	return 1;
}

int wiz_result(const struct wiz *w, struct bind_table *out)
{
	int done = w->phase == WIZ_P_END && w->status == WIZ_DONE;

	*out = done ? w->cur : w->orig;
	return !wiz_same_table(out, &w->orig);
}

enum wiz_note wiz_last_note(const struct wiz *w, int *step, struct wiz_ctl *ctl)
{
	if (step)
		*step = w->note_step;
	if (ctl)
		*ctl = w->note_ctl;
	return (enum wiz_note)w->note;
}

/* ---- the page --------------------------------------------------------- */

struct wiz_page {
	struct r_frame *f;
	struct hud_colours c;
	int sc;                        /* text scale: 1 per 240 lines */
	int margin;
};

/* Text cut to what fits in maxw pixels at scale; returns its width. */
static int wiz_text(struct wiz_page *p, int x, int y, int scale, uint8_t col, const char *s,
		    int maxw)
{
	char buf[128];
	int fit = maxw / (V_CHAR * scale);

	if (fit <= 0)
		return 0;
	snprintf(buf, sizeof(buf), "%.*s", fit, s);
	return v_text(p->f, x, y, scale, col, buf);
}

static void wiz_centre(struct wiz_page *p, int y, int scale, uint8_t col, const char *s)
{
	int maxw = p->f->w - 2 * p->margin;
	int fit = maxw / (V_CHAR * scale);
	int n = (int)strlen(s) < fit ? (int)strlen(s) : fit;

	wiz_text(p, (p->f->w - n * V_CHAR * scale) / 2, y, scale, col, s, maxw);
}

/* The largest scale up to max at which s fits the width. */
static int wiz_fit(const struct wiz_page *p, const char *s, int max)
{
	int scale = max;

	while (scale > 1 && v_text_width(s, scale) > p->f->w - 2 * p->margin)
		scale--;
	return scale;
}

static void wiz_key_name(int code, char *buf, size_t len)
{
	const char *name = in_key_name(code);

	if (name)
		snprintf(buf, len, "%s", name);
	else
		snprintf(buf, len, "0x%04x", (unsigned)code);
}

/* A section as the screen names it. */
static const char *wiz_sec_name(const struct wiz_ctl *c)
{
	return c->sec[0] ? c->sec : "KEYBOARD";
}

/* A bar filling as the longest unspent hold nears WIZ_HOLD_NS. */
static void wiz_hold_bar(struct wiz_page *p, const struct wiz *w, int y, const char *what,
			 uint8_t col)
{
	uint64_t longest = 0;
	int bw = p->f->w / 2, bh = 6 * p->sc, x = (p->f->w - bw) / 2;

	if (!wiz_any_unspent(w))
		return;
	for (int i = 0; i < w->nheld; i++)
		if (!w->held[i].spent && w->now - w->held[i].t0 > longest)
			longest = w->now - w->held[i].t0;
	if (longest > WIZ_HOLD_NS)
		longest = WIZ_HOLD_NS;
	wiz_centre(p, y, p->sc, p->c.white, what);
	y += 10 * p->sc;
	v_box(p->f, x, y, bw, bh, p->c.grey);
	v_fill(p->f, x + 1, y + 1, (int)((uint64_t)(bw - 2) * longest / WIZ_HOLD_NS), bh - 2, col);
}

/* Up to three lines about the last capture, each short enough for the 39
 * characters a 4:3 frame holds: what happened, then the control's section
 * and device. */
static void wiz_draw_note(struct wiz_page *p, const struct wiz *w, int y)
{
	const char *label = wiz_order[w->note_step].label;
	int dy = 10 * p->sc;
	char line[96], key[24];

	wiz_key_name(w->note_ctl.code, key, sizeof(key));
	switch (w->note) {
	case WIZ_N_ASSIGNED:
		snprintf(line, sizeof(line), "%s = %s", label, key);
		wiz_centre(p, y, p->sc, p->c.green, line);
		snprintf(line, sizeof(line), "%s  %s", wiz_sec_name(&w->note_ctl), w->note_dev);
		wiz_centre(p, y + dy, p->sc, p->c.grey, line);
		break;
	case WIZ_N_SKIPPED:
		snprintf(line, sizeof(line), "%s SKIPPED (KEPT)", label);
		wiz_centre(p, y, p->sc, p->c.orange, line);
		break;
	case WIZ_N_TAKEN:
		snprintf(line, sizeof(line), "REFUSED: ALREADY %s", label);
		wiz_centre(p, y, p->sc, p->c.red, line);
		snprintf(line, sizeof(line), "%s  %s", key, wiz_sec_name(&w->note_ctl));
		wiz_centre(p, y + dy, p->sc, p->c.grey, line);
		wiz_centre(p, y + 2 * dy, p->sc, p->c.red, "PRESS ANOTHER CONTROL");
		break;
	case WIZ_N_FULL:
		snprintf(line, sizeof(line), "NO ROOM FOR ANOTHER DEVICE (%d)", BIND_DEVICES);
		wiz_centre(p, y, p->sc, p->c.red, line);
		snprintf(line, sizeof(line), "%s  %s", wiz_sec_name(&w->note_ctl), w->note_dev);
		wiz_centre(p, y + dy, p->sc, p->c.grey, line);
		break;
	default:
		break;
	}
}

static void wiz_steps_page(struct wiz_page *p, const struct wiz *w)
{
	const char *prompt = wiz_order[w->step].prompt;
	int sc = p->sc, ps = wiz_fit(p, prompt, 3 * sc), y;
	char buf[48];

	snprintf(buf, sizeof(buf), "STEP %d OF %d", w->step + 1, WIZ_STEPS);
	wiz_centre(p, 26 * sc, sc, p->c.grey, buf);
	wiz_centre(p, 44 * sc, wiz_fit(p, "PRESS", 2 * sc), p->c.white, "PRESS");
	y = 64 * sc;
	wiz_centre(p, y, ps, p->c.yellow, prompt);
	y += 8 * ps + 6 * sc;
	snprintf(buf, sizeof(buf), "ACTION: %s", wiz_order[w->step].label);
	wiz_centre(p, y, sc, p->c.grey, buf);
	wiz_draw_note(p, w, y + 18 * sc);
	wiz_hold_bar(p, w, y + 52 * sc, "HOLDING: SKIP", p->c.orange);
	wiz_centre(p, p->f->h - 24 * sc, sc, p->c.white, "HOLD ANY BUTTON 1 S TO SKIP");
	wiz_centre(p, p->f->h - 12 * sc, sc, p->c.grey, "SKIP ALL: NOTHING CHANGES");
}

/* The summary names each section by a letter, [A] for the first one an
 * assignment used, with a legend below: a line "STRAFE RIGHT BTN_TRIGGER_
 * HAPPY40 [B]" fits the 39 characters where the section's name would not.
 * Fills ctl with the distinct sections' first controls in that order;
 * returns how many. */
static int wiz_sections(const struct wiz *w, const struct wiz_ctl *ctl[WIZ_STEPS])
{
	int n = 0;

	for (int k = 0; k < WIZ_STEPS; k++) {
		int seen = 0;

		if (w->cap[k].state != WIZ_C_ASSIGNED)
			continue;
		for (int i = 0; i < n; i++)
			seen |= strcmp(ctl[i]->sec, w->cap[k].c.sec) == 0;
		if (!seen)
			ctl[n++] = &w->cap[k].c;
	}
	return n;
}

static char wiz_tag(const struct wiz_ctl *const ctl[WIZ_STEPS], int n, const struct wiz_ctl *c)
{
	for (int i = 0; i < n; i++)
		if (strcmp(ctl[i]->sec, c->sec) == 0)
			return (char)('A' + i);
	return '?';
}

/* "[A] KEYBOARD  [B] USB-1-1.2", wrapped at the frame's width. */
static void wiz_legend(struct wiz_page *p, const struct wiz_ctl *const ctl[WIZ_STEPS], int n,
		       int y)
{
	int x = p->margin, sc = p->sc, right = p->f->w - p->margin;
	char buf[BIND_ID_MAX + 8];

	for (int i = 0; i < n; i++) {
		snprintf(buf, sizeof(buf), "[%c] %s", 'A' + i, wiz_sec_name(ctl[i]));
		if (x > p->margin && x + v_text_width(buf, sc) > right) {
			x = p->margin;
			y += 10 * sc;
		}
		x += wiz_text(p, x, y, sc, p->c.grey, buf, right - x) + 2 * V_CHAR * sc;
	}
}

/* The summary's rows are 9 lines apart (8 of text, 1 between) from line
 * 36 at scale 1, so the 14 steps, the legend and the hold bar end above
 * the three lines at the bottom of a 240-line frame. */
static void wiz_summary_page(struct wiz_page *p, const struct wiz *w)
{
	int sc = p->sc, x = p->margin, y = 36 * sc, col2 = x + 13 * V_CHAR * sc;
	uint64_t left = WIZ_SUMMARY_NS - (w->now - w->summary_from < WIZ_SUMMARY_NS ?
					  w->now - w->summary_from : WIZ_SUMMARY_NS);
	const struct wiz_ctl *secs[WIZ_STEPS];
	int nsecs = wiz_sections(w, secs);
	char buf[80], key[24];

	wiz_centre(p, 26 * sc, sc, p->c.grey, "SUMMARY");
	for (int k = 0; k < WIZ_STEPS; k++, y += 9 * sc) {
		wiz_text(p, x, y, sc, p->c.white, wiz_order[k].label, col2 - x);
		if (w->cap[k].state == WIZ_C_ASSIGNED) {
			wiz_key_name(w->cap[k].c.code, key, sizeof(key));
			snprintf(buf, sizeof(buf), "%s [%c]", key,
				 wiz_tag(secs, nsecs, &w->cap[k].c));
			wiz_text(p, col2, y, sc, p->c.green, buf, p->f->w - p->margin - col2);
		} else {
			wiz_text(p, col2, y, sc, p->c.dark, "KEPT", p->f->w - p->margin - col2);
		}
	}
	wiz_legend(p, secs, nsecs, y + 4 * sc);
	wiz_hold_bar(p, w, y + 26 * sc, "HOLDING: DISCARD", p->c.red);
	wiz_centre(p, p->f->h - 36 * sc, sc, p->c.white, "PRESS AND RELEASE: SAVE");
	wiz_centre(p, p->f->h - 24 * sc, sc, p->c.white, "HOLD 1 S: DISCARD");
	snprintf(buf, sizeof(buf), "SAVING IN %u S",
		 (unsigned)((left + 999999999ull) / 1000000000ull));
	wiz_centre(p, p->f->h - 12 * sc, sc, p->c.grey, buf);
}

void wiz_draw(const struct wiz *w, const struct pal *pal, struct r_frame *f)
{
	struct wiz_page p;

	p.f = f;
	hud_colours(pal, &p.c);
	p.sc = hud_scale(f);
	p.margin = 4 * p.sc;
	v_fill(f, 0, 0, f->w, f->h, p.c.black);
	wiz_centre(&p, 6 * p.sc, wiz_fit(&p, "INPUT SETUP", 2 * p.sc), p.c.cyan, "INPUT SETUP");
	if (w->phase == WIZ_P_STEPS)
		wiz_steps_page(&p, w);
	else
		wiz_summary_page(&p, w);
}
