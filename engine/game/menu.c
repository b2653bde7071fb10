/*
 * menu: the service menu's state machine (drawing: menu_draw.c).
 */
#include "engine/game/menu.h"

#include <string.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"

#define MENU_DONE_TICKS 180            /* "done" note after a reset: 3 s */

static const uint16_t menu_res[MENU_RES_COUNT][2] = {
	{ 320, 240 }, { 400, 300 }, { 480, 360 }, { 640, 480 }, { 800, 600 }, { 960, 720 },
};

void menu_res_size(int i, int *w, int *h)
{
	if (i < 1 || i > MENU_RES_COUNT) {
		*w = 0;
		*h = 0;
		return;
	}
	*w = menu_res[i - 1][0];
	*h = menu_res[i - 1][1];
}

const char *menu_difficulty_name(int d)
{
	static const char names[4][8] = { "EASY", "NORMAL", "HARD", "BRUTAL" };

	return d >= 0 && d < 4 ? names[d] : NULL;
}

const char *menu_sound_name(int i)
{
	if (i == MENU_SOUND_LEFT)
		return "LEFT CHANNEL";
	if (i == MENU_SOUND_RIGHT)
		return "RIGHT CHANNEL";
	return i >= 0 && i < MENU_SOUND_LEFT ? sfx_info(i + 1)->name : "";
}

/* The menu's blips (G_SRC_MENU: a new one cuts the last). */
static void menu_blip(struct sim *s, int id)
{
	g_sound_play(s, id, G_SRC_MENU);
}

void menu_enter(struct menu *m)
{
	uint8_t res = m->res;

	memset(m, 0, sizeof(*m));
	m->res = res;
	m->page = MENU_MAIN;
}

static void menu_back(struct menu *m)
{
	m->page = MENU_MAIN;
	m->cursor = m->main_cursor;
}

/* Steps v by +1 or -1 within lo..hi, wrapping round. */
static uint8_t menu_step(int v, int dir, int lo, int hi)
{
	v += dir;
	if (v > hi)
		v = lo;
	if (v < lo)
		v = hi;
	return (uint8_t)v;
}

/* Up/down steps *cursor through 0..count - 1 (wrapping), with a blip. */
static int menu_up_down(struct sim *s, uint8_t *cursor, uint8_t nav, int count)
{
	int dir = nav & MENU_NAV_UP ? -1 : nav & MENU_NAV_DOWN ? 1 : 0;

	if (!dir)
		return 0;
	*cursor = menu_step(*cursor, dir, 0, count - 1);
	menu_blip(s, SFX_MENU_MOVE);
	return 1;
}

static int menu_main(struct sim *s, uint8_t pressed, uint8_t nav)
{
	struct menu *m = &s->menu;

	if (pressed & SIM_BT_SERVICE)
		return 1;
	menu_up_down(s, &m->cursor, nav, MENU_ITEMS);
	if (!(pressed & SIM_BT_FIRE))
		return 0;
	m->main_cursor = m->cursor;
	menu_blip(s, SFX_MENU_SELECT);
	switch (m->cursor) {
	case MENU_I_INPUT:
		m->page = MENU_INPUT;
		m->coins_seen = 0;
		break;
	case MENU_I_DISPLAY:
		m->page = MENU_DISPLAY;
		m->display = MENU_D_BARS;
		break;
	case MENU_I_SOUND:
		m->page = MENU_SOUND;
		break;
	case MENU_I_SETTINGS:
		m->page = MENU_SETTINGS;
		m->cursor = 0;
		break;
	case MENU_I_BOOKS:
		m->page = MENU_BOOKS;
		break;
	case MENU_I_RESET_SCORES:
	case MENU_I_RESET_BOOKS:
		m->page = MENU_CONFIRM;
		m->confirm = m->cursor;
		m->yes = 0;
		break;
	case MENU_I_DEVICES:
		m->page = MENU_DEVICES;
		break;
	case MENU_I_LATENCY:
		m->page = MENU_LATENCY;
		break;
	case MENU_I_WIZARD:
		m->page = MENU_WIZARD;
		break;
	case MENU_I_CONTENT:
		m->page = MENU_CONTENT;
		break;
	case MENU_I_SCREEN:
		m->page = MENU_SCREEN;
		break;
	case MENU_I_CONFIG:
		m->page = MENU_CONFIG;
		break;
	case MENU_I_EXIT:
	default:
		return 1;
	}
	return 0;
}

/* Changes the setting under the cursor by dir (+1 / -1). */
static void menu_change(struct sim *s, int dir)
{
	struct sim_settings *t = &s->set;
	struct menu *m = &s->menu;

	switch (m->cursor) {
	case MENU_S_DIFFICULTY:
		t->difficulty = menu_step(g_difficulty(s), dir, 0, 3);
		break;
	case MENU_S_LIVES:
		t->lives = menu_step(g_lives_setting(s), dir, 1, 9);
		break;
	case MENU_S_COINS:
		t->coins_per_credit =
			menu_step(t->coins_per_credit ? t->coins_per_credit : 1, dir, 1, 9);
		break;
	case MENU_S_FREEPLAY:
		t->freeplay = (uint8_t)!t->freeplay;
		break;
	case MENU_S_VOLUME: {
		/* no wrap: a press must never jump from silent to full */
		int v = (t->volume > G_VOLUME_MAX ? G_VOLUME_MAX : t->volume) +
			dir * MENU_VOLUME_STEP;
		t->volume = (uint8_t)(v < 0 ? 0 : v > G_VOLUME_MAX ? G_VOLUME_MAX : v);
		break;
	}
	case MENU_S_ATTRACT_SOUND:
		t->attract_sound = menu_step(t->attract_sound > MENU_ATTRACT_SOUND_MAX ?
						     MENU_ATTRACT_SOUND_MAX : t->attract_sound,
					     dir, 0, MENU_ATTRACT_SOUND_MAX);
		break;
	case MENU_S_STAGE_TIME: {
		/* OFF, then 1..G_STAGE_TIME_MAX minutes, wrapping */
		uint8_t v = menu_step((int)(g_pace_full(s) / (60u * SIM_TICRATE)), dir, 0,
				      G_STAGE_TIME_MAX);
		t->stage_time = v == 0 ? G_STAGE_TIME_OFF : v;
		break;
	}
	case MENU_S_IDLE:
		t->idle_out = menu_step(t->idle_out >= G_IDLE_COUNT ? G_IDLE_OFF : t->idle_out, dir,
					0, G_IDLE_COUNT - 1);
		break;
	case MENU_S_AUTOAIM:
		t->free_aim = (uint8_t)!t->free_aim;
		break;
	case MENU_S_RES:
		m->res = menu_step(m->res, dir, 0, MENU_RES_COUNT);
		return;
	default:
		return;
	}
	s->set_gen++;
	menu_blip(s, SFX_MENU_MOVE);   /* at the new volume */
}

static void menu_settings(struct sim *s, uint8_t pressed, uint8_t nav)
{
	struct menu *m = &s->menu;

	if (pressed & SIM_BT_SERVICE) {
		menu_back(m);
		return;
	}
	if (menu_up_down(s, &m->cursor, nav, MENU_SETTINGS_COUNT))
		return;
	if (m->cursor == MENU_S_BACK) {
		if (pressed & SIM_BT_FIRE) {
			menu_blip(s, SFX_MENU_SELECT);
			menu_back(m);
		}
		return;
	}
	if (m->cursor == MENU_S_DEFAULTS) {
		if (pressed & SIM_BT_FIRE) {
			s->set.coins_per_credit = 1;
			s->set.freeplay = 0;
			s->set.difficulty = MENU_DEFAULT_DIFFICULTY;
			s->set.lives = G_LIVES_DEFAULT;
			s->set.volume = MENU_DEFAULT_VOLUME;
			s->set.attract_sound = MENU_DEFAULT_ATTRACT_SOUND;
			s->set.stage_time = G_STAGE_TIME_DEFAULT;
			s->set.idle_out = G_IDLE_LIFE;
			s->set.free_aim = 0;
			m->res = 0;
			s->set_gen++;
			menu_blip(s, SFX_MENU_SELECT);
		}
		return;
	}
	if (nav & MENU_NAV_LEFT)
		menu_change(s, -1);
	else if ((nav & MENU_NAV_RIGHT) || (pressed & SIM_BT_FIRE))
		menu_change(s, 1);
}

static void menu_confirm(struct sim *s, uint8_t pressed, uint8_t nav)
{
	struct menu *m = &s->menu;

	if (pressed & SIM_BT_SERVICE) {
		menu_back(m);
		return;
	}
	if (nav)
		m->yes = (uint8_t)!m->yes;
	if (!(pressed & SIM_BT_FIRE))
		return;
	if (m->yes) {
		if (m->confirm == MENU_I_RESET_SCORES) {
			g_scores_default(&s->scores);
			s->new_rank = -1;
			s->scores_gen++;
		} else {
			memset(&s->books, 0, sizeof(s->books));
			s->books_gen++;
		}
		m->done = m->confirm;
		m->done_t = 0;
	}
	menu_back(m);
}

/* The sound test: up/down choose, fire plays, service goes back. */
static void menu_sound(struct sim *s, uint8_t pressed, uint8_t nav)
{
	struct menu *m = &s->menu;

	if (pressed & SIM_BT_SERVICE) {
		g_sound_stop(s, G_SRC_TEST);
		menu_back(m);
		return;
	}
	if (menu_up_down(s, &m->snd, nav, MENU_SOUNDS) || !(pressed & SIM_BT_FIRE))
		return;
	if (m->snd == MENU_SOUND_LEFT)
		g_sound_pan(s, SFX_TONE, 0, G_SRC_TEST);
	else if (m->snd == MENU_SOUND_RIGHT)
		g_sound_pan(s, SFX_TONE, G_SND_SEP_MAX, G_SRC_TEST);
	else
		g_sound_play(s, m->snd + 1, G_SRC_TEST);
}

int menu_tick(struct sim *s, uint8_t pressed, uint8_t nav)
{
	struct menu *m = &s->menu;

	if (m->t < UINT32_MAX)
		m->t++;
	if (m->done && ++m->done_t >= MENU_DONE_TICKS)
		m->done = 0;
	switch (m->page) {
	case MENU_MAIN:
		return menu_main(s, pressed, nav);
	case MENU_INPUT:
		m->coins_seen += s->cmd.coins;
		if (pressed & SIM_BT_SERVICE)
			menu_back(m);
		break;
	case MENU_DISPLAY:
		if (pressed & SIM_BT_FIRE)
			m->display = (uint8_t)((m->display + 1) % MENU_D_COUNT);
		if (pressed & SIM_BT_SERVICE)
			menu_back(m);
		break;
	case MENU_SOUND:
		menu_sound(s, pressed, nav);
		break;
	case MENU_SETTINGS:
		menu_settings(s, pressed, nav);
		break;
	case MENU_BOOKS:
	case MENU_DEVICES:
	case MENU_LATENCY:
		if (pressed & (SIM_BT_SERVICE | SIM_BT_FIRE))
			menu_back(m);
		break;
	case MENU_WIZARD:
	case MENU_CONTENT:
	case MENU_SCREEN:
	case MENU_CONFIG:
		/* one tick: the app has seen the request (menu.h) */
		menu_back(m);
		break;
	case MENU_CONFIRM:
	default:
		menu_confirm(s, pressed, nav);
		break;
	}
	return 0;
}
