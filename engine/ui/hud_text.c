/*
 * hud_text: what the HUD, the flow's pages and the service menu share:
 * colours, scale, number and time strings, shadowed text, the blink and
 * the credits line. It calls only v_video and the core, so hud.c,
 * hud_page.c and menu_draw.c all call it and it calls none of them.
 */
#include <string.h>

#include "engine/core/msg.h"
#include "engine/core/pal.h"
#include "engine/game/sim.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud_local.h"
#include "engine/ui/v_video.h"

#define HUD_DIM_LIGHT 22               /* colormap that darkens behind text */

void hud_colours(const struct pal *pal, struct hud_colours *c)
{
	c->white = pal_nearest(pal, 255, 255, 255);
	c->grey = pal_nearest(pal, 160, 160, 160);
	c->dark = pal_nearest(pal, 64, 64, 64);
	c->black = pal_nearest(pal, 0, 0, 0);
	c->red = pal_nearest(pal, 230, 40, 30);
	c->orange = pal_nearest(pal, 255, 140, 0);
	c->yellow = pal_nearest(pal, 255, 230, 40);
	c->green = pal_nearest(pal, 60, 220, 60);
	c->blue = pal_nearest(pal, 60, 100, 255);
	c->cyan = pal_nearest(pal, 60, 230, 230);
	c->purple = pal_nearest(pal, 180, 80, 220);
	c->skin = pal_nearest(pal, 200, 150, 110);
	c->steel = pal_nearest(pal, 110, 115, 125);
	c->dim = pal->cmap[HUD_DIM_LIGHT];
	c->par = NULL;
}

int hud_scale(const struct r_frame *f)
{
	int a = f->h / 240, b = f->w / 320;
	int s = a < b ? a : b;

	return s < 1 ? 1 : s;
}

void hud_cat_num(char *buf, size_t len, uint64_t v, int width, char pad)
{
	char tmp[24];

	v_num(tmp, (int)sizeof(tmp), v, width, pad);
	msg_cat(buf, len, tmp);
}

void hud_cat_time(char *buf, size_t len, uint64_t ticks)
{
	uint64_t sec = ticks / SIM_TICRATE;

	hud_cat_num(buf, len, sec / 3600, 1, '0');
	msg_cat(buf, len, ":");
	hud_cat_num(buf, len, sec / 60 % 60, 2, '0');
	msg_cat(buf, len, ":");
	hud_cat_num(buf, len, sec % 60, 2, '0');
}

void hud_text(struct r_frame *f, const struct hud_colours *c, int x, int y, int scale,
	      uint8_t colour, const char *s)
{
	v_text(f, x + scale, y + scale, scale, c->black, s);
	v_text(f, x, y, scale, colour, s);
}

void hud_text_centre(struct r_frame *f, const struct hud_colours *c, int y, int scale,
		     uint8_t colour, const char *s)
{
	hud_text(f, c, (f->w - v_text_width(s, scale)) / 2, y, scale, colour, s);
}

void hud_text_right(struct r_frame *f, const struct hud_colours *c, int x, int y, int scale,
		    uint8_t colour, const char *s)
{
	hud_text(f, c, x - v_text_width(s, scale), y, scale, colour, s);
}

int hud_blink(const struct sim *s)
{
	return s->tick / (SIM_TICRATE / 2) % 2 == 0;
}

void hud_credits_text(const struct sim *s, char *buf, size_t len)
{
	buf[0] = '\0';
	if (s->set.freeplay) {
		msg_cat(buf, len, "FREE PLAY");
		return;
	}
	msg_cat(buf, len, "CREDITS ");
	hud_cat_num(buf, len, s->credits, 1, '0');
}
