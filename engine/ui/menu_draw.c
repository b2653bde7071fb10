/*
 * menu_draw: the service menu's pages, drawn from the sim state (the menu
 * state machine is menu.c). Pixels through v_video, colours and text
 * helpers from the HUD.
 */
#include <string.h>

#include "engine/core/msg.h"
#include "engine/core/pal.h"
#include "engine/game/menu.h"
#include "engine/game/sim.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud_local.h"
#include "engine/ui/v_video.h"

struct menu_ctx {
	const struct sim *s;
	const struct hud_colours *c;
	struct r_frame *f;
	int sc, x, y;                  /* scale, left margin, next line */
};

static void menu_line(struct menu_ctx *m, uint8_t colour, const char *text)
{
	hud_text(m->f, m->c, m->x, m->y, m->sc, colour, text);
	m->y += 12 * m->sc;
}

/* An item: "> LABEL      VALUE" with the cursor and highlight when sel. */
static void menu_item(struct menu_ctx *m, int sel, const char *label, const char *value)
{
	uint8_t col = sel ? m->c->yellow : m->c->white;

	if (sel)
		hud_text(m->f, m->c, m->x - 2 * V_CHAR * m->sc, m->y, m->sc, col, ">");
	hud_text(m->f, m->c, m->x, m->y, m->sc, col, label);
	if (value)
		hud_text(m->f, m->c, m->x + 20 * V_CHAR * m->sc, m->y, m->sc, col, value);
	m->y += 12 * m->sc;
}

static void menu_title(struct menu_ctx *m, const char *title, const char *help)
{
	hud_text_centre(m->f, m->c, 6 * m->sc, 2 * m->sc, m->c->cyan, title);
	hud_text_centre(m->f, m->c, m->f->h - 12 * m->sc, m->sc, m->c->grey, help);
	m->y = 34 * m->sc;
}

static void menu_main_page(struct menu_ctx *m, const char *notice)
{
	static const char items[MENU_ITEMS][20] = {
		[MENU_I_INPUT] = "INPUT TEST", [MENU_I_DISPLAY] = "DISPLAY TEST",
		[MENU_I_SOUND] = "SOUND TEST",
		[MENU_I_SETTINGS] = "GAME SETTINGS", [MENU_I_BOOKS] = "BOOKKEEPING",
		[MENU_I_RESET_SCORES] = "RESET HIGH SCORES", [MENU_I_RESET_BOOKS] = "RESET BOOKKEEPING",
		[MENU_I_DEVICES] = "DEVICES", [MENU_I_LATENCY] = "LATENCY",
		[MENU_I_CONTENT] = "CONTENT PACK", [MENU_I_SCREEN] = "SCREEN",
		[MENU_I_CONFIG] = "CONFIG ERRORS", [MENU_I_WIZARD] = "CONFIGURE INPUTS", [MENU_I_EXIT] = "EXIT",
	};
	const struct menu *mn = &m->s->menu;

	menu_title(m, "SERVICE MENU", "UP/DOWN MOVE  FIRE SELECT  SERVICE EXIT");
	for (int i = 0; i < MENU_ITEMS; i++)
		menu_item(m, i == mn->cursor, items[i], NULL);
	if (mn->done) {
		m->y += 12 * m->sc;
		menu_line(m, m->c->green, mn->done == MENU_I_RESET_SCORES ? "HIGH SCORES RESET" :
									   "BOOKKEEPING RESET");
	} else if (notice) {
		/* the app's first unacknowledged configuration error (hud.h),
		 * at half the menu's scale when it has one to spare: a path and
		 * its reason are long */
		int sc = m->sc > 1 ? m->sc / 2 : 1;
		hud_text(m->f, m->c, 2 * m->sc, m->f->h - 24 * m->sc, sc, m->c->red, notice);
	}
}

/* The app's lines (hud_env.diag) from the next line down, at half the
 * menu's text scale so that a device's name fits, headings in yellow, as
 * many as fit above the help line. */
static void menu_diag_lines(struct menu_ctx *m, const struct hud_diag *d)
{
	int sc = m->sc > 1 ? m->sc / 2 : 1, x = V_CHAR * sc / 2;

	for (int i = 0; i < d->n && i < HUD_DIAG_LINES; i++) {
		char line[HUD_DIAG_COLS];
		if (m->y + 10 * sc > m->f->h - 14 * m->sc)
			break;             /* above the help line */
		memcpy(line, d->line[i], sizeof(line));
		line[sizeof(line) - 1] = '\0';
		hud_text(m->f, m->c, x, m->y, sc, line[0] == ' ' ? m->c->white : m->c->yellow,
			 line);
		m->y += 10 * sc;
	}
}

/* One row of the input test: the name, and its state in green when
 * held, else "--". */
static void menu_input_row(struct menu_ctx *m, const char *name, const char *held)
{
	hud_text(m->f, m->c, m->x, m->y, m->sc, held ? m->c->green : m->c->white, name);
	hud_text(m->f, m->c, m->x + 20 * V_CHAR * m->sc, m->y, m->sc,
		 held ? m->c->green : m->c->dark, held ? held : "--");
	m->y += 10 * m->sc;
}

/* The actions as the game receives them (the two look buttons on one row:
 * UP, DOWN, or CENTRE for both, as the sim reads them), the coins, then
 * the app's lines when it gives some (the devices' raw controls,
 * hud_env.diag). */
static void menu_input_page(struct menu_ctx *m, const struct hud_diag *d)
{
	const struct sim_cmd *c = &m->s->cmd;
	const int on[] = {
		c->forward > 0, c->forward < 0, c->turn > 0, c->turn < 0, c->side < 0, c->side > 0,
		!!(c->buttons & SIM_BT_FIRE), !!(c->buttons & SIM_BT_USE),
		!!(c->buttons & SIM_BT_START), !!(c->buttons & SIM_BT_SERVICE),
		!!(c->buttons & SIM_BT_WEAPON),
	};
	static const char names[][14] = {
		"FORWARD", "BACK", "TURN LEFT", "TURN RIGHT", "STRAFE LEFT", "STRAFE RIGHT",
		"FIRE", "USE", "START", "SERVICE", "WEAPON",
	};
	static const char look[4][8] = { "", "UP", "DOWN", "CENTRE" };
	int l = (c->buttons & SIM_BT_LOOK_UP ? 1 : 0) + (c->buttons & SIM_BT_LOOK_DOWN ? 2 : 0);
	char buf[32] = "";

	menu_title(m, "INPUT TEST", "SERVICE: BACK");
	for (size_t i = 0; i < sizeof(names) / sizeof(names[0]); i++)
		menu_input_row(m, names[i], on[i] ? "ON" : NULL);
	menu_input_row(m, "LOOK", l ? look[l] : NULL);
	msg_cat(buf, sizeof(buf), "COINS ");
	hud_cat_num(buf, sizeof(buf), m->s->menu.coins_seen, 1, '0');
	m->y += 4 * m->sc;
	menu_line(m, m->c->yellow, buf);
	if (d)
		menu_diag_lines(m, d);
}

static void menu_bars(struct menu_ctx *m, const struct pal *pal)
{
	const struct hud_colours *c = m->c;
	const uint8_t bars[8] = { c->white, c->yellow, c->cyan, c->green,
				  c->purple, c->red, c->blue, c->black };
	struct r_frame *f = m->f;
	int top = f->h * 2 / 3;

	for (int i = 0; i < 8; i++)
		v_fill(f, f->w * i / 8, 0, f->w * (i + 1) / 8 - f->w * i / 8, top, bars[i]);
	for (int i = 0; i < 16; i++) {
		int v = 255 - i * 17;
		v_fill(f, f->w * i / 16, top, f->w * (i + 1) / 16 - f->w * i / 16, f->h - top,
		       pal_nearest(pal, v, v, v));
	}
}

static void menu_grid(struct menu_ctx *m)
{
	struct r_frame *f = m->f;
	uint8_t w = m->c->white;

	for (int i = 0; i <= 16; i++) {
		int x = i == 16 ? f->w - 1 : f->w * i / 16;
		v_line(f, x, 0, x, f->h - 1, w, NULL);
	}
	for (int i = 0; i <= 12; i++) {
		int y = i == 12 ? f->h - 1 : f->h * i / 12;
		v_line(f, 0, y, f->w - 1, y, w, NULL);
	}
	v_line(f, 0, 0, f->w - 1, f->h - 1, m->c->red, NULL);
	v_line(f, f->w - 1, 0, 0, f->h - 1, m->c->red, NULL);
}

static void menu_orient(struct menu_ctx *m, int rotate)
{
	struct r_frame *f = m->f;
	int sc = m->sc, cx = f->w / 2, cy = f->h / 2, a = f->h / 4;
	char buf[32] = "";

	v_tri(f, cx, cy - a, cx - a / 2, cy, cx + a / 2, cy, m->c->green, NULL);
	v_fill(f, cx - a / 6, cy, a / 3, a, m->c->green);
	hud_text_centre(f, m->c, 2 * sc, 2 * sc, m->c->white, "TOP");
	hud_text_centre(f, m->c, f->h - 18 * sc, 2 * sc, m->c->white, "BOTTOM");
	hud_text(f, m->c, 2 * sc, cy, 2 * sc, m->c->white, "LEFT");
	hud_text_right(f, m->c, f->w - 2 * sc, cy, 2 * sc, m->c->white, "RIGHT");
	msg_cat(buf, sizeof(buf), "ROTATE ");
	if (rotate >= 0)
		hud_cat_num(buf, sizeof(buf), (uint64_t)rotate, 1, '0');
	else
		msg_cat(buf, sizeof(buf), "?");
	hud_text(f, m->c, 2 * sc, f->h - 30 * sc, sc, m->c->yellow, buf);
}

static void menu_display_page(struct menu_ctx *m, const struct hud_env *env)
{
	switch (m->s->menu.display) {
	case MENU_D_GRID:
		menu_grid(m);
		break;
	case MENU_D_ORIENT:
		menu_orient(m, env->rotate);
		break;
	case MENU_D_BARS:
	default:
		menu_bars(m, env->pal);
		break;
	}
	hud_text_centre(m->f, m->c, m->f->h / 2 + 20 * m->sc, m->sc, m->c->white,
			"FIRE: NEXT  SERVICE: BACK");
}

static void menu_settings_page(struct menu_ctx *m)
{
	const struct sim *s = m->s;
	const struct menu *mn = &s->menu;
	const char *diff = menu_difficulty_name(s->set.difficulty > 3 ? 3 : s->set.difficulty);
	static const char idles[G_IDLE_COUNT][13] = { "LOSE A LIFE", "END THE GAME", "OFF" };
	char lives[4] = "", coins[4] = "", res[24] = "", vol[8] = "", attract[16] = "";
	char clock[12] = "";
	int w = m->f->w, h = m->f->h;

	hud_cat_num(lives, sizeof(lives), s->set.lives ? s->set.lives : G_LIVES_DEFAULT, 1, '0');
	hud_cat_num(coins, sizeof(coins), s->set.coins_per_credit ? s->set.coins_per_credit : 1, 1,
		    '0');
	if (mn->res)
		menu_res_size(mn->res, &w, &h);
	hud_cat_num(res, sizeof(res), (uint64_t)w, 1, '0');
	msg_cat(res, sizeof(res), "X");
	hud_cat_num(res, sizeof(res), (uint64_t)h, 1, '0');
	if (!mn->res)
		msg_cat(res, sizeof(res), " NOW");
	hud_cat_num(vol, sizeof(vol), s->set.volume > G_VOLUME_MAX ? G_VOLUME_MAX : s->set.volume,
		    1, '0');
	msg_cat(vol, sizeof(vol), "%");
	if (s->set.attract_sound <= 1) {
		msg_cat(attract, sizeof(attract), s->set.attract_sound ? "ON" : "OFF");
	} else {
		msg_cat(attract, sizeof(attract), "1 CYCLE IN ");
		hud_cat_num(attract, sizeof(attract), s->set.attract_sound, 1, '0');
	}
	if (s->set.stage_time == G_STAGE_TIME_OFF) {
		msg_cat(clock, sizeof(clock), "OFF");
	} else {
		hud_cat_num(clock, sizeof(clock),
			    s->set.stage_time == 0 ? G_STAGE_TIME_DEFAULT
			    : s->set.stage_time > G_STAGE_TIME_MAX ? G_STAGE_TIME_MAX
								   : s->set.stage_time,
			    1, '0');
		msg_cat(clock, sizeof(clock), " MIN");
	}
	menu_title(m, "GAME SETTINGS", "LEFT/RIGHT CHANGE  SERVICE BACK");
	menu_item(m, mn->cursor == MENU_S_DIFFICULTY, "DIFFICULTY", diff);
	menu_item(m, mn->cursor == MENU_S_LIVES, "LIVES", lives);
	menu_item(m, mn->cursor == MENU_S_COINS, "COINS PER CREDIT", coins);
	menu_item(m, mn->cursor == MENU_S_FREEPLAY, "FREE PLAY", s->set.freeplay ? "YES" : "NO");
	menu_item(m, mn->cursor == MENU_S_VOLUME, "VOLUME", vol);
	menu_item(m, mn->cursor == MENU_S_ATTRACT_SOUND, "ATTRACT SOUND", attract);
	menu_item(m, mn->cursor == MENU_S_STAGE_TIME, "STAGE CLOCK", clock);
	menu_item(m, mn->cursor == MENU_S_IDLE, "IDLE PLAYER",
		  idles[s->set.idle_out < G_IDLE_COUNT ? s->set.idle_out : G_IDLE_OFF]);
	menu_item(m, mn->cursor == MENU_S_AUTOAIM, "AUTO-AIM", s->set.free_aim ? "OFF" : "ON");
	menu_item(m, mn->cursor == MENU_S_RES, "RENDER SIZE", res);
	menu_item(m, mn->cursor == MENU_S_DEFAULTS, "FACTORY DEFAULTS", NULL);
	menu_item(m, mn->cursor == MENU_S_BACK, "BACK", NULL);
}

/* The sound test: a window of entries round the one chosen. */
static void menu_sound_page(struct menu_ctx *m)
{
	const struct menu *mn = &m->s->menu;
	int rows = (m->f->h - 34 * m->sc - 24 * m->sc) / (12 * m->sc), first;

	if (rows < 1)
		rows = 1;
	if (rows > MENU_SOUNDS)
		rows = MENU_SOUNDS;
	first = mn->snd - rows / 2;
	if (first > MENU_SOUNDS - rows)
		first = MENU_SOUNDS - rows;
	if (first < 0)
		first = 0;
	menu_title(m, "SOUND TEST", "UP/DOWN CHOOSE  FIRE PLAY  SERVICE BACK");
	for (int i = first; i < first + rows; i++)
		menu_item(m, i == mn->snd, menu_sound_name(i), NULL);
}

static void menu_books_page(struct menu_ctx *m)
{
	const struct g_books *b = &m->s->books;
	char buf[5][24];

	for (int i = 0; i < 5; i++)
		buf[i][0] = '\0';
	hud_cat_num(buf[0], sizeof(buf[0]), b->coins, 1, '0');
	hud_cat_num(buf[1], sizeof(buf[1]), b->plays, 1, '0');
	hud_cat_time(buf[2], sizeof(buf[2]), b->play_ticks);
	hud_cat_time(buf[3], sizeof(buf[3]), b->plays ? b->play_ticks / b->plays : 0);
	hud_cat_time(buf[4], sizeof(buf[4]), b->on_ticks);
	menu_title(m, "BOOKKEEPING", "FIRE OR SERVICE: BACK");
	menu_item(m, 0, "COINS", buf[0]);
	menu_item(m, 0, "PLAYS", buf[1]);
	menu_item(m, 0, "PLAY TIME", buf[2]);
	menu_item(m, 0, "AVERAGE PLAY", buf[3]);
	menu_item(m, 0, "POWER-ON TIME", buf[4]);
	buf[0][0] = '\0';
	hud_cat_time(buf[0], sizeof(buf[0]), m->s->tick);
	menu_item(m, 0, "UPTIME", buf[0]);
}

static void menu_diag_page(struct menu_ctx *m, const struct hud_diag *d, const char *title)
{
	menu_title(m, title, "FIRE OR SERVICE: BACK");
	if (!d || d->n <= 0)
		menu_line(m, m->c->grey, "NOTHING TO SHOW");
	else
		menu_diag_lines(m, d);
}

static void menu_confirm_page(struct menu_ctx *m)
{
	const struct menu *mn = &m->s->menu;

	menu_title(m, mn->confirm == MENU_I_RESET_SCORES ? "RESET HIGH SCORES?" :
							    "RESET BOOKKEEPING?",
		   "LEFT/RIGHT CHOOSE  FIRE CONFIRM");
	menu_item(m, !mn->yes, "NO", NULL);
	menu_item(m, mn->yes, "YES", NULL);
}

void menu_draw(const struct sim *s, const struct hud_env *env, struct r_frame *f)
{
	struct hud_colours c;
	struct menu_ctx m;

	hud_colours(env->pal, &c);
	m.s = s;
	m.c = &c;
	m.f = f;
	m.sc = hud_scale(f);
	m.x = 4 * V_CHAR * m.sc;
	m.y = 0;
	v_fill(f, 0, 0, f->w, f->h, c.black);
	switch (s->menu.page) {
	case MENU_INPUT:
		menu_input_page(&m, env->diag);
		break;
	case MENU_DISPLAY:
		menu_display_page(&m, env);
		break;
	case MENU_SETTINGS:
		menu_settings_page(&m);
		break;
	case MENU_BOOKS:
		menu_books_page(&m);
		break;
	case MENU_CONFIRM:
		menu_confirm_page(&m);
		break;
	case MENU_SOUND:
		menu_sound_page(&m);
		break;
	case MENU_DEVICES:
		menu_diag_page(&m, env->diag, "DEVICES");
		break;
	case MENU_LATENCY:
		menu_diag_page(&m, env->diag, "LATENCY");
		break;
	case MENU_MAIN:
	case MENU_WIZARD:              /* its one tick: the app draws the wizard */
	case MENU_CONTENT:             /* and these the app's pages (app/pick.h) */
	case MENU_SCREEN:
	case MENU_CONFIG:
	default:
		menu_main_page(&m, env->notice);
		break;
	}
}
