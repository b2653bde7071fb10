/*
 * hud_local: helpers shared by hud.c, hud_page.c and menu_draw.c.
 */
#ifndef ARCADED_ENGINE_HUD_LOCAL_H
#define ARCADED_ENGINE_HUD_LOCAL_H

#include <stddef.h>
#include <stdint.h>

#include "engine/ui/hud.h"

struct sim;
struct r_frame;

/* Appends v in decimal, at least width digits padded with pad. */
void hud_cat_num(char *buf, size_t len, uint64_t v, int width, char pad);
/* Appends ticks as H:MM:SS. */
void hud_cat_time(char *buf, size_t len, uint64_t ticks);

/* Text with a one-scale-pixel black shadow, left aligned at x. */
void hud_text(struct r_frame *f, const struct hud_colours *c, int x, int y, int scale,
	      uint8_t colour, const char *s);
/* The same, centred on the frame's width. */
void hud_text_centre(struct r_frame *f, const struct hud_colours *c, int y, int scale,
		     uint8_t colour, const char *s);
/* The same, right aligned to x. */
void hud_text_right(struct r_frame *f, const struct hud_colours *c, int x, int y, int scale,
		    uint8_t colour, const char *s);

/* Whether blinking things show on this tick (on half a second, off half). */
int hud_blink(const struct sim *s);

/* The credits line: "CREDITS n" or "FREE PLAY". */
void hud_credits_text(const struct sim *s, char *buf, size_t len);

/* hud_page.c: the arcade flow's screens. */
void hud_page_attract(const struct sim *s, const struct hud_colours *c, struct r_frame *f);
void hud_page_gameover(const struct sim *s, const struct hud_colours *c, struct r_frame *f);
void hud_page_initials(const struct sim *s, const struct hud_colours *c, struct r_frame *f);
/* The intermission after a map's exit (phase G_PH_INTER): kills, items,
 * secrets, time, score, the next map. */
void hud_page_inter(const struct sim *s, const struct hud_colours *c, struct r_frame *f);
/* Two players: the "PLAYER n" page between turns (phase G_PH_TURN): the
 * player up, their stage and lives, both scores. */
void hud_page_turn(const struct sim *s, const struct hud_colours *c, struct r_frame *f);
/* Two players: "1UP 001234" (n 0) or "2UP 000500" (n 1), player n's score
 * (the player up's from the game, the other's from the waiting seat). */
void hud_up_text(const struct sim *s, int n, char *buf, size_t len);

#endif
