/*
 * hud_page: the screens of the arcade flow: attract (title, high scores,
 * the demo's banner), game over with the continue countdown, initials
 * entry, and the intermission after a map's exit. Pure functions of the
 * sim state; pixels through v_video.
 */
#include <string.h>

#include "engine/core/msg.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud_local.h"
#include "engine/ui/v_video.h"

/* "INSERT COIN" or "PRESS START", blinking, and the credits under it. */
static void hud_coin_prompt(const struct sim *s, const struct hud_colours *c, struct r_frame *f,
			    int y)
{
	int sc = hud_scale(f);
	char buf[48];

	if (hud_blink(s))
		hud_text_centre(f, c, y, sc, c->yellow,
				s->credits || s->set.freeplay ? "PRESS START" : "INSERT COIN");
	hud_credits_text(s, buf, sizeof(buf));
	hud_text_centre(f, c, y + 12 * sc, sc, c->white, buf);
}

/* In a two-player game, "PLAYER n  " for the player up. */
static void hud_player_cat(const struct sim *s, char *buf, size_t len)
{
	if (s->players != 2)
		return;
	msg_cat(buf, len, "PLAYER ");
	hud_cat_num(buf, len, s->up + 1u, 1, '0');
	msg_cat(buf, len, "  ");
}

/* The high-score table, the new entry (new_rank) blinking. */
static void hud_scores(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f), y = f->h / 10, x = (f->w - v_text_width("10  AAA  0000000  3", sc)) / 2;

	v_remap_par(f, 0, 0, f->w, f->h, c->dim, c->par);
	hud_text_centre(f, c, y, 2 * sc, c->yellow, "HIGH SCORES");
	y += 28 * sc;
	for (int i = 0; i < G_SCORES; i++, y += 12 * sc) {
		const struct g_entry *e = &s->scores.e[i];
		char buf[48] = "", name[G_NAME_LEN + 1];
		uint8_t col = i == s->new_rank ? (hud_blink(s) ? c->yellow : c->orange) :
			      i == 0 ? c->cyan : c->white;
		memcpy(name, e->name, G_NAME_LEN);
		name[G_NAME_LEN] = '\0';
		hud_cat_num(buf, sizeof(buf), (uint64_t)i + 1, 2, ' ');
		msg_cat(buf, sizeof(buf), "  ");
		msg_cat(buf, sizeof(buf), name);
		msg_cat(buf, sizeof(buf), "  ");
		hud_cat_num(buf, sizeof(buf), e->score, 7, ' ');
		msg_cat(buf, sizeof(buf), "  ");
		hud_cat_num(buf, sizeof(buf), e->stage, 1, '0');
		hud_text(f, c, x, y, sc, col, buf);
	}
}

void hud_page_attract(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f), big = 4 * sc;
	char buf[48] = "";

	switch (s->page) {
	case SIM_PAGE_SCORES:
		hud_scores(s, c, f);
		hud_coin_prompt(s, c, f, f->h - 30 * sc);
		break;
	case SIM_PAGE_DEMO:
		/* under the demo's own HUD line (the stage clock) */
		hud_text_centre(f, c, 16 * sc, 2 * sc, c->yellow, "DEMO");
		hud_coin_prompt(s, c, f, f->h - 30 * sc);
		break;
	case SIM_PAGE_TITLE:
	default:
		v_remap_par(f, 0, f->h / 5, f->w, 12 * big, c->dim, c->par);
		hud_text_centre(f, c, f->h / 5 + 2 * big, big, c->red, "ARCADED");
		hud_text_centre(f, c, f->h / 5 + 2 * big + 10 * big, sc, c->white,
				"CLEAR THE STAGES  BEAT THE TABLE");
		msg_cat(buf, sizeof(buf), "HI ");
		hud_cat_num(buf, sizeof(buf), s->scores.e[0].score, 1, '0');
		msg_cat(buf, sizeof(buf), " ");
		{
			char name[G_NAME_LEN + 1];
			memcpy(name, s->scores.e[0].name, G_NAME_LEN);
			name[G_NAME_LEN] = '\0';
			msg_cat(buf, sizeof(buf), name);
		}
		hud_text_centre(f, c, 4 * sc, sc, c->cyan, buf);
		hud_coin_prompt(s, c, f, f->h - 30 * sc);
		break;
	}
}

void hud_page_gameover(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f), y = f->h / 6;
	char buf[48] = "";

	v_remap_par(f, 0, 0, f->w, f->h, c->dim, c->par);
	hud_text_centre(f, c, y, 3 * sc, c->red, "GAME OVER");
	hud_player_cat(s, buf, sizeof(buf));
	msg_cat(buf, sizeof(buf), "SCORE ");
	hud_cat_num(buf, sizeof(buf), s->g.score, 1, '0');
	hud_text_centre(f, c, y + 32 * sc, sc, c->white, buf);
	hud_text_centre(f, c, y + 52 * sc, 2 * sc, c->yellow, "CONTINUE?");
	buf[0] = '\0';
	hud_cat_num(buf, sizeof(buf), (s->countdown + SIM_TICRATE - 1u) / SIM_TICRATE, 1, '0');
	hud_text_centre(f, c, y + 76 * sc, 5 * sc, c->white, buf);
	hud_coin_prompt(s, c, f, f->h - 30 * sc);
}

void hud_page_initials(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f), big = 4 * sc, y = f->h / 8;
	int cell = 2 * V_CHAR * big / 2 + 4 * sc, x0 = (f->w - G_NAME_LEN * cell) / 2;
	char buf[48] = "";

	hud_text_centre(f, c, y, 2 * sc, c->yellow, "NEW HIGH SCORE");
	hud_player_cat(s, buf, sizeof(buf));
	msg_cat(buf, sizeof(buf), "RANK ");
	hud_cat_num(buf, sizeof(buf), (uint64_t)s->ini_rank + 1, 1, '0');
	msg_cat(buf, sizeof(buf), "   SCORE ");
	hud_cat_num(buf, sizeof(buf), s->g.score, 1, '0');
	hud_text_centre(f, c, y + 24 * sc, sc, c->white, buf);
	hud_text_centre(f, c, y + 40 * sc, sc, c->grey, "ENTER YOUR INITIALS");
	y += 60 * sc;
	for (int i = 0; i < G_NAME_LEN; i++) {
		char ch[2] = { G_ALPHABET[s->ini[i] % G_ALPHABET_LEN], '\0' };
		int x = x0 + i * cell + (cell - V_CHAR * big) / 2;
		uint8_t col = i < s->ini_pos ? c->green : c->white;
		if (i > s->ini_pos)
			ch[0] = '-';
		if (i == s->ini_pos) {
			col = hud_blink(s) ? c->yellow : c->orange;
			v_fill(f, x, y + V_CHAR * big + 2 * sc, V_CHAR * big - big, 2 * sc, col);
		}
		if (ch[0] == ' ')
			ch[0] = '-';
		v_text(f, x, y, big, col, ch);
	}
	y += V_CHAR * big + 16 * sc;
	hud_text_centre(f, c, y, sc, c->grey, "UP DOWN: LETTER   FIRE: NEXT");
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "TIME ");
	hud_cat_num(buf, sizeof(buf),
		    (G_INITIALS_TICKS - (s->mode_t < G_INITIALS_TICKS ? s->mode_t : G_INITIALS_TICKS) +
		     SIM_TICRATE - 1) / SIM_TICRATE, 2, '0');
	hud_text_centre(f, c, y + 14 * sc, sc, c->white, buf);
}

/* "KILLS   12 / 25   48%" */
static void hud_inter_line(struct r_frame *f, const struct hud_colours *c, int x, int y, int sc,
			   const char *what, unsigned got, unsigned total)
{
	char buf[48] = "";
	unsigned pct = total ? got * 100u / total : 100u;

	msg_cat(buf, sizeof(buf), what);
	hud_cat_num(buf, sizeof(buf), got, 4, ' ');
	msg_cat(buf, sizeof(buf), " /");
	hud_cat_num(buf, sizeof(buf), total, 4, ' ');
	hud_cat_num(buf, sizeof(buf), pct, 6, ' ');
	msg_cat(buf, sizeof(buf), "%");
	hud_text(f, c, x, y, sc, pct >= 100 ? c->yellow : c->white, buf);
}

void hud_page_inter(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	const struct g_world *w = &s->w;
	int sc = hud_scale(f), y = f->h / 8;
	int x = (f->w - v_text_width("SECRETS 1000 / 1000   100%", sc)) / 2;
	unsigned dead = 0;
	char buf[48] = "";

	for (int i = 0; i < s->g.num_enemies; i++)
		dead += s->g.en[i].state == G_E_DEAD;
	msg_cat(buf, sizeof(buf), s->map->name);
	msg_cat(buf, sizeof(buf), " FINISHED");
	hud_text_centre(f, c, y, 2 * sc, c->red, buf);
	if (w->exit == G_EXIT_SECRET)
		hud_text_centre(f, c, y + 20 * sc, sc, c->cyan, "SECRET EXIT");
	y += 40 * sc;
	hud_inter_line(f, c, x, y, sc, "KILLS   ", dead, s->g.num_enemies);
	hud_inter_line(f, c, x, y + 14 * sc, sc, "ITEMS   ", w->items, w->items_total);
	hud_inter_line(f, c, x, y + 28 * sc, sc, "SECRETS ", w->secrets, w->secrets_total);
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "TIME    ");
	hud_cat_time(buf, sizeof(buf), w->exit_t);
	hud_text(f, c, x, y + 42 * sc, sc, c->white, buf);
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "BONUS   ");
	hud_cat_num(buf, sizeof(buf), s->g.time_bonus, 1, '0');
	hud_text(f, c, x, y + 56 * sc, sc, c->white, buf);
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "SCORE   ");
	hud_cat_num(buf, sizeof(buf), s->g.score, 1, '0');
	hud_text(f, c, x, y + 70 * sc, sc, c->white, buf);
	if (w->next < s->num_stages && s->stages[w->next]) {
		buf[0] = '\0';
		msg_cat(buf, sizeof(buf), "ENTERING ");
		msg_cat(buf, sizeof(buf), s->stages[w->next]->name);
		hud_text_centre(f, c, y + 92 * sc, sc, c->green, buf);
	}
	if (s->g.phase_t >= G_INTER_MIN && hud_blink(s))
		hud_text_centre(f, c, f->h - 24 * sc, sc, c->yellow, "PRESS FIRE");
}

void hud_up_text(const struct sim *s, int n, char *buf, size_t len)
{
	buf[0] = '\0';
	hud_cat_num(buf, len, (uint64_t)n + 1, 1, '0');
	msg_cat(buf, len, "UP ");
	hud_cat_num(buf, len, n == s->up ? s->g.score : s->wait.score, 6, '0');
}

void hud_page_turn(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f), y = f->h / 4;
	char buf[48] = "";

	msg_cat(buf, sizeof(buf), "PLAYER ");
	hud_cat_num(buf, sizeof(buf), s->up + 1u, 1, '0');
	hud_text_centre(f, c, y, 4 * sc, s->up ? c->cyan : c->yellow, buf);
	if (hud_blink(s))
		hud_text_centre(f, c, y + 40 * sc, sc, c->white, "GET READY");
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "STAGE ");
	hud_cat_num(buf, sizeof(buf), s->g.stage + 1u, 1, '0');
	msg_cat(buf, sizeof(buf), "   LIVES ");
	hud_cat_num(buf, sizeof(buf), s->g.lives, 1, '0');
	hud_text_centre(f, c, y + 58 * sc, sc, c->white, buf);
	for (int n = 0; n < 2; n++) {
		hud_up_text(s, n, buf, sizeof(buf));
		hud_text_centre(f, c, y + (80 + 12 * n) * sc, sc, n == s->up ? c->white : c->grey,
				buf);
	}
}
