/*
 * hud: the play HUD (status line, score, crosshair, weapon, minimap,
 * banners) and the dispatcher to the flow's pages (hud_page.c) and the
 * service menu (menu_draw.c). All pixels go through v_video.
 */
#include "engine/ui/hud.h"

#include <string.h>

#include "engine/core/msg.h"
#include "engine/core/pal.h"
#include "engine/core/tab.h"
#include "engine/game/menu.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud_local.h"
#include "engine/ui/v_video.h"

#define HUD_MAP_SPAN 1024              /* map units across the minimap */

void hud_minimap_rect(const struct r_frame *f, int *x, int *y, int *size)
{
	int s = hud_scale(f), m = f->h / 3;

	if (m < 40)
		m = 40;
	*size = m;
	*x = f->w - m - 2 * s;
	*y = 2 * s;
}

int hud_world(const struct sim *s)
{
	if (s->mode == SIM_PLAY)
		return s->g.phase != G_PH_INTER && s->g.phase != G_PH_TURN;
	return s->mode == SIM_GAMEOVER || s->mode == SIM_ATTRACT;
}

/* What the specials tell the player (g_world.h enum g_msg), Doom's words. */
static const char *hud_msg_text(int msg)
{
	static const char text[G_MSG_COUNT][48] = {
		[G_MSG_BLUE_DOOR] = "YOU NEED A BLUE KEY TO OPEN THIS DOOR",
		[G_MSG_YELLOW_DOOR] = "YOU NEED A YELLOW KEY TO OPEN THIS DOOR",
		[G_MSG_RED_DOOR] = "YOU NEED A RED KEY TO OPEN THIS DOOR",
		[G_MSG_BLUE_OBJECT] = "YOU NEED A BLUE KEY TO ACTIVATE THIS",
		[G_MSG_YELLOW_OBJECT] = "YOU NEED A YELLOW KEY TO ACTIVATE THIS",
		[G_MSG_RED_OBJECT] = "YOU NEED A RED KEY TO ACTIVATE THIS",
		[G_MSG_SECRET] = "A SECRET IS REVEALED!",
		[G_MSG_NOTHING] = "NOTHING TO USE HERE",
		[G_MSG_KEY] = "PICKED UP A KEY",
	};

	return msg > 0 && msg < G_MSG_COUNT ? text[msg] : "";
}

/* ---- the minimap ------------------------------------------------------ */

struct hud_mm {
	struct v_rect r;
	int cx, cy;                    /* the player's pixel */
	int64_t num, den;              /* pixels per 16.16 unit: num / den */
	fx_t px, py;
	/* Offsets (16.16, either way, along x or y) from which a point is off
	 * the square: at least (size / 2 + 2) pixels, whose truncated
	 * projection is past both edges (the square reaches size / 2 pixels
	 * left of and up from the player, size - size / 2 - 1 right and down) */
	int64_t far;
};

static void hud_mm_point(const struct hud_mm *m, fx_t x, fx_t y, int *sx, int *sy)
{
	*sx = m->cx + (int)(((int64_t)x - m->px) * m->num / m->den);
	*sy = m->cy - (int)(((int64_t)y - m->py) * m->num / m->den);
}

/* 1 when every point of the segment a-b (map units, 16.16) lies at least
 * m->far from the player along x or y, on one side: it then projects
 * outside the minimap's square, so neither a line nor a dot of it can
 * show. A test without the projection's two divisions per point, for the
 * map's lines and things, of which the square shows a few. */
static int hud_mm_far(const struct hud_mm *m, fx_t ax, fx_t ay, fx_t bx, fx_t by)
{
	int64_t x0 = (int64_t)ax - m->px, y0 = (int64_t)ay - m->py;
	int64_t x1 = (int64_t)bx - m->px, y1 = (int64_t)by - m->py;

	return (x0 <= -m->far && x1 <= -m->far) || (x0 >= m->far && x1 >= m->far) ||
	       (y0 <= -m->far && y1 <= -m->far) || (y0 >= m->far && y1 >= m->far);
}

static void hud_mm_dot(struct r_frame *f, const struct hud_mm *m, fx_t x, fx_t y, int size,
		       uint8_t c)
{
	int sx, sy;

	hud_mm_point(m, x, y, &sx, &sy);
	if (sx < m->r.x || sy < m->r.y || sx >= m->r.x + m->r.w || sy >= m->r.y + m->r.h)
		return;
	v_fill(f, sx - size / 2, sy - size / 2, size, size, c);
}

/* North up, centred on the player: walls, steps, pickups, lights, living
 * enemies, and the player as an arrow along its view. */
static void hud_minimap(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	const struct map *map = s->map;
	int sc = hud_scale(f), size, dot;
	struct hud_mm m;

	hud_minimap_rect(f, &m.r.x, &m.r.y, &size);
	m.r.w = m.r.h = size;
	m.cx = m.r.x + size / 2;
	m.cy = m.r.y + size / 2;
	m.num = size;
	m.den = (int64_t)HUD_MAP_SPAN * FX_ONE;
	m.px = s->pl.x;
	m.py = s->pl.y;
	m.far = ((int64_t)(size / 2 + 2) * m.den + m.num - 1) / m.num;
	{
		/* darkened twice: one pass through the composed map */
		uint8_t dim2[256];

		for (int i = 0; i < 256; i++)
			dim2[i] = c->dim[c->dim[i]];
		v_remap_par(f, m.r.x, m.r.y, size, size, dim2, c->par);
	}
	for (uint32_t i = 0; i < map->num_lines; i++) {
		const struct map_line *l = &map->lines[i];
		const struct map_vertex *a = &map->vertices[l->v1], *b = &map->vertices[l->v2];
		uint8_t col = c->grey;
		int x0, y0, x1, y1;
		if (hud_mm_far(&m, a->x, a->y, b->x, b->y))
			continue;
		if (l->side[1] != MAP_NONE && !(l->flags & ML_BLOCKING)) {
			/* heights as they are now: an open door is a passage */
			const struct g_sector *fs = &s->w.sec[map->sides[l->side[0]].sector];
			const struct g_sector *bs = &s->w.sec[map->sides[l->side[1]].sector];
			if (fs->floor_h == bs->floor_h && fs->ceil_h == bs->ceil_h)
				continue;
			col = c->dark;
		}
		hud_mm_point(&m, a->x, a->y, &x0, &y0);
		hud_mm_point(&m, b->x, b->y, &x1, &y1);
		v_line(f, x0, y0, x1, y1, col, &m.r);
	}
	dot = sc + 1;
	for (uint32_t i = 0; i < map->num_things; i++) {
		struct g_thing_info ti;
		if (hud_mm_far(&m, map->things[i].x, map->things[i].y, map->things[i].x,
			       map->things[i].y))
			continue;
		g_thing_info(map->things[i].type, &ti);
		if (ti.cls == G_C_LIGHT)
			hud_mm_dot(f, &m, map->things[i].x, map->things[i].y, dot, c->yellow);
	}
	for (int i = 0; i < s->g.num_pickups; i++) {
		const struct g_pickup *p = &s->g.pk[i];
		if (!p->taken)
			hud_mm_dot(f, &m, p->x, p->y, dot, p->kind == G_P_HEALTH ? c->green
							   : p->kind == G_P_KEY ? c->purple : c->cyan);
	}
	for (int i = 0; i < s->g.num_enemies; i++) {
		const struct g_enemy *e = &s->g.en[i];
		if (e->state != G_E_DEAD)
			hud_mm_dot(f, &m, e->x, e->y, dot + sc, c->red);
	}
	{
		/* the arrow: tip along the view, the tail corners 140 degrees
		 * either side; screen y grows downwards */
		int64_t len = size / 12 < 4 ? 4 : size / 12;
		ang_t a = s->pl.angle, l = a + ANG90 + ANG45 + ANG45 / 9 * 2, r = a - (l - a);
		int tx = m.cx + (int)((tab_cos(a) * len) >> FX_SHIFT);
		int ty = m.cy - (int)((tab_sin(a) * len) >> FX_SHIFT);
		int lx = m.cx + (int)((tab_cos(l) * len * 3 / 4) >> FX_SHIFT);
		int ly = m.cy - (int)((tab_sin(l) * len * 3 / 4) >> FX_SHIFT);
		int rx = m.cx + (int)((tab_cos(r) * len * 3 / 4) >> FX_SHIFT);
		int ry = m.cy - (int)((tab_sin(r) * len * 3 / 4) >> FX_SHIFT);
		v_tri(f, tx, ty, lx, ly, m.cx, m.cy, c->white, &m.r);
		v_tri(f, tx, ty, m.cx, m.cy, rx, ry, c->white, &m.r);
	}
	v_box(f, m.r.x - 1, m.r.y - 1, size + 2, size + 2, c->grey);
}

/* ---- the weapon --------------------------------------------------------- */

static int hud_held(const struct sim *s)
{
	return s->pl.weapon < G_WEAPONS ? s->pl.weapon : G_W_PISTOL;
}

/* Frame of the weapon animation: 0 ready, 1..4 the shot's recoil, four
 * equal parts of the held weapon's refire, by ticks since the last shot. */
static int hud_weapon_frame(const struct sim *s)
{
	uint32_t t = s->g.shot_t, r = g_weapons[hud_held(s)].refire;

	return t < r ? 1 + (int)(t * 4 / r) : 0;
}

/* Doom's weapon sprites for each weapon: the gun's frames and its flash. */
static const char hud_gun[G_WEAPONS][5] = { "PISG", "SHTG", "CHGG" };
static const char hud_flash[G_WEAPONS][5] = { "PISF", "SHTF", "CHGF" };

void hud_want(const struct tex_set *t, uint8_t *want_pics)
{
	for (int w = 0; w < G_WEAPONS; w++) {
		tex_want_sprite(t, hud_gun[w], want_pics);
		tex_want_sprite(t, hud_flash[w], want_pics);
	}
}

/* The texture set's gun for the held weapon (Doom's PISG, SHTG, CHGG
 * frames and their flashes PISF, SHTF, CHGF), placed as Doom places weapon
 * sprites on its 320x200 screen. Returns 0 when the set has none. */
static int hud_weapon_pics(const struct sim *s, const struct tex_set *t, struct r_frame *f,
			   int bottom)
{
	int w = hud_held(s);
	int g = t ? tex_find_sprite(t, hud_gun[w]) : -1, fl = t ? tex_find_sprite(t, hud_flash[w]) : -1;
	int frame = hud_weapon_frame(s), ws = f->h / 200 < 1 ? 1 : f->h / 200;
	int ox = (f->w - 320 * ws) / 2, oy = bottom - 168 * ws;
	const struct tex_sprite *sp;

	if (g < 0)
		return 0;
	sp = &t->sprites[g];
	if (frame >= sp->num_frames)
		frame = 0;
	/* a set loaded for its maps decodes the guns (hud_want); without
	 * pixels, the project's own drawing is drawn instead */
	if (sp->num_frames < 1 || !t->sprpics[sp->frames[frame].pic[0]].px)
		return 0;
	{
		const struct tex_pic *p = &t->sprpics[sp->frames[frame].pic[0]];
		v_pic(f, p, ox + (1 - p->left) * ws, oy + (32 - p->top) * ws, ws);
	}
	if (fl >= 0 && hud_weapon_frame(s) == 1 && t->sprites[fl].num_frames > 0 &&
	    t->sprpics[t->sprites[fl].frames[0].pic[0]].px) {
		const struct tex_pic *p = &t->sprpics[t->sprites[fl].frames[0].pic[0]];
		v_pic(f, p, ox + (1 - p->left) * ws, oy + (32 - p->top) * ws, ws);
	}
	return 1;
}

/* A barrel from the muzzle (x, top) down to the breech, w wide and h long:
 * steel with a dark bore at the muzzle. */
static void hud_barrel(const struct hud_colours *c, struct r_frame *f, int sc, int x, int top,
		       int w, int h)
{
	v_fill(f, x - w / 2 * sc, top, w * sc, h * sc, c->steel);
	v_fill(f, x - (w / 2 - 1) * sc, top, (w - 2) * sc, 2 * sc, c->black);
}

/* The project's own guns, seen from behind, drawn with rectangles and
 * triangles in units of the 320x240 screen: the hand round the grip and
 * the held weapon (the pistol's slide narrowing to the muzzle and its
 * sights; the spread gun's two wide barrels on a stock; the rapid gun's
 * cluster of four thin barrels round a drum). Each kicks up on a shot
 * (the spread gun most) and shows a muzzle flash for the first ticks. */
static void hud_weapon_drawn(const struct sim *s, const struct hud_colours *c, struct r_frame *f,
			     int bottom)
{
	static const int8_t kick[G_WEAPONS][5] = {
		{ 0, 7, 4, 2, 1 }, { 0, 12, 8, 4, 2 }, { 0, 3, 2, 1, 0 }
	};
	int w = hud_held(s), sc = hud_scale(f), frame = hud_weapon_frame(s);
	int cx = f->w / 2 + 20 * sc, top = bottom - 52 * sc - kick[w][frame] * sc;
	int fy = top - 2 * sc, flash = 10;

	/* the hand and wrist */
	v_fill(f, cx - 16 * sc, top + 36 * sc, 32 * sc, bottom - top - 36 * sc, c->skin);
	v_tri(f, cx - 16 * sc, top + 36 * sc, cx - 22 * sc, bottom, cx - 16 * sc, bottom, c->skin,
	      NULL);
	v_fill(f, cx - 16 * sc, top + 40 * sc, 32 * sc, 2 * sc, c->orange);   /* knuckles */
	if (w == G_W_SPREAD) {
		v_fill(f, cx - 14 * sc, top + 26 * sc, 28 * sc, 12 * sc, c->dark);  /* stock */
		hud_barrel(c, f, sc, cx - 6 * sc, top, 11, 28);
		hud_barrel(c, f, sc, cx + 6 * sc, top, 11, 28);
		v_fill(f, cx - 1 * sc, top + 2 * sc, 2 * sc, 24 * sc, c->grey);   /* rib */
		v_fill(f, cx - 1 * sc, top - 2 * sc, 2 * sc, 3 * sc, c->white);   /* bead */
		flash = 16;
	} else if (w == G_W_RAPID) {
		v_fill(f, cx - 12 * sc, top + 22 * sc, 24 * sc, 16 * sc, c->dark);  /* drum */
		v_fill(f, cx - 12 * sc, top + 28 * sc, 24 * sc, 2 * sc, c->grey);
		for (int b = 0; b < 4; b++)
			hud_barrel(c, f, sc, cx + (b * 6 - 9) * sc, top + (b == 1 || b == 2 ? 0 : 3) * sc,
				   5, 24);
		flash = 8;
	} else {
		/* the grip and the slide */
		v_fill(f, cx - 9 * sc, top + 24 * sc, 18 * sc, 14 * sc, c->dark);
		v_tri(f, cx - 11 * sc, top + 26 * sc, cx + 11 * sc, top + 26 * sc, cx - 7 * sc, top,
		      c->steel, NULL);
		v_tri(f, cx + 11 * sc, top + 26 * sc, cx + 7 * sc, top, cx - 7 * sc, top, c->steel,
		      NULL);
		v_fill(f, cx - 1 * sc, top + 2 * sc, 2 * sc, 22 * sc, c->grey);   /* top rib */
		v_fill(f, cx - 4 * sc, top + 1 * sc, 8 * sc, 3 * sc, c->black);   /* muzzle */
		v_fill(f, cx - 1 * sc, top - 2 * sc, 2 * sc, 3 * sc, c->white);   /* front sight */
		v_fill(f, cx - 6 * sc, top + 22 * sc, 4 * sc, 3 * sc, c->white);  /* rear sight */
		v_fill(f, cx + 2 * sc, top + 22 * sc, 4 * sc, 3 * sc, c->white);
	}
	if (frame == 1) {
		v_tri(f, cx, fy - (flash + 8) * sc, cx - flash * sc, fy, cx + flash * sc, fy, c->orange,
		      NULL);
		v_tri(f, cx - (flash + 4) * sc, fy - 8 * sc, cx + (flash + 4) * sc, fy - 8 * sc, cx,
		      fy + 2 * sc, c->orange, NULL);
		v_tri(f, cx, fy - (flash + 1) * sc, cx - flash / 2 * sc, fy, cx + flash / 2 * sc, fy,
		      c->yellow, NULL);
	}
}

/* ---- the play HUD ------------------------------------------------------ */

static void hud_crosshair(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f), cx = f->w / 2, cy = f->h / 2;
	uint8_t col = s->g.shot == G_SHOT_ENEMY && s->g.shot_t < 8 ? c->red : c->white;

	v_fill(f, cx - 5 * sc, cy, 3 * sc, sc, col);
	v_fill(f, cx + 2 * sc + sc, cy, 3 * sc, sc, col);
	v_fill(f, cx, cy - 5 * sc, sc, 3 * sc, col);
	v_fill(f, cx, cy + 3 * sc, sc, 3 * sc, col);
}

static void hud_banners(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f), y = f->h / 3;
	char buf[48] = "";

	if (s->g.phase == G_PH_DEAD) {
		static const char why[][12] = { "YOU DIED", "TIME UP", "PLAYER GONE" };
		hud_text_centre(f, c, y, 2 * sc, c->red, why[s->g.why <= G_WHY_IDLE ? s->g.why : 0]);
		if (s->g.lives > 1) {
			hud_cat_num(buf, sizeof(buf), (uint64_t)s->g.lives - 1, 1, '0');
			msg_cat(buf, sizeof(buf), s->g.lives == 2 ? " LIFE LEFT" : " LIVES LEFT");
			hud_text_centre(f, c, y + 20 * sc, sc, c->white, buf);
		}
	} else if (s->g.phase == G_PH_CLEAR) {
		hud_text_centre(f, c, y, 2 * sc, c->yellow, "STAGE CLEAR");
		msg_cat(buf, sizeof(buf), "BONUS ");
		hud_cat_num(buf, sizeof(buf), (uint64_t)G_STAGE_BONUS * (s->g.stage + 1u), 1, '0');
		hud_text_centre(f, c, y + 20 * sc, sc, c->white, buf);
		buf[0] = '\0';
		msg_cat(buf, sizeof(buf), "TIME BONUS ");
		hud_cat_num(buf, sizeof(buf), s->g.time_bonus, 1, '0');
		hud_text_centre(f, c, y + 32 * sc, sc, c->white, buf);
	} else if (s->g.stage_t < G_BANNER_TICKS) {
		msg_cat(buf, sizeof(buf), "STAGE ");
		hud_cat_num(buf, sizeof(buf), s->g.stage + 1u, 1, '0');
		hud_text_centre(f, c, y, 2 * sc, c->white, buf);
		if (s->map && s->map->name[0])
			hud_text_centre(f, c, y + 20 * sc, sc, c->grey, s->map->name);
	}
}

/* The stage clock at the top, red and blinking in a hurry; "HURRY UP" for
 * the hurry's first 3 seconds; the idle player's countdown. */
static void hud_clock(const struct sim *s, const struct hud_colours *c, struct r_frame *f)
{
	int sc = hud_scale(f);
	uint32_t secs = (s->g.clock + SIM_TICRATE - 1) / SIM_TICRATE;
	int on = s->set.stage_time != G_STAGE_TIME_OFF;
	int hurry = on && s->g.phase == G_PH_PLAY && s->g.clock <= G_HURRY_TICKS;
	char buf[32] = "";

	msg_cat(buf, sizeof(buf), "TIME ");
	hud_cat_num(buf, sizeof(buf), secs / 60, 1, '0');
	msg_cat(buf, sizeof(buf), ":");
	hud_cat_num(buf, sizeof(buf), secs % 60, 2, '0');
	if (on && (!hurry || hud_blink(s)))
		hud_text_centre(f, c, 2 * sc, sc, hurry ? c->red : c->white, buf);
	if (hurry && s->g.clock > G_HURRY_TICKS - 3 * SIM_TICRATE)
		hud_text_centre(f, c, f->h / 3, 2 * sc, c->red, "HURRY UP!");
	if (s->g.phase == G_PH_PLAY && s->set.idle_out != G_IDLE_OFF &&
	    s->set.idle_out < G_IDLE_COUNT && s->g.idle_t > G_IDLE_TICKS - G_IDLE_WARN) {
		buf[0] = '\0';
		msg_cat(buf, sizeof(buf), "STILL THERE? ");
		hud_cat_num(buf, sizeof(buf),
			    (uint64_t)(G_IDLE_TICKS - s->g.idle_t + SIM_TICRATE - 1) / SIM_TICRATE, 1,
			    '0');
		hud_text_centre(f, c, f->h / 3 + 20 * sc, 2 * sc, c->yellow, buf);
	}
}

/* The keys held: a small card (and a skull's dot) of each colour. */
static void hud_keys(const struct sim *s, const struct hud_colours *c, struct r_frame *f, int x,
		     int y)
{
	static const uint8_t bits[3] = { G_KEY_BLUE, G_KEY_YELLOW, G_KEY_RED };
	const uint8_t col[3] = { c->blue, c->yellow, c->red };
	int sc = hud_scale(f);

	for (int i = 0; i < 3; i++) {
		int have = s->w.keys & bits[i], skull = s->w.keys & (bits[i] << 3);
		if (!have && !skull)
			continue;
		v_fill(f, x, y, 5 * sc, 7 * sc, col[i]);
		if (skull)
			v_fill(f, x + 2 * sc, y + 2 * sc, sc, 2 * sc, c->white);
		x += 7 * sc;
	}
}

static void hud_play(const struct sim *s, const struct hud_env *env, const struct hud_colours *c,
		     struct r_frame *f)
{
	int sc = hud_scale(f), bar = 12 * sc, y0 = f->h - bar, ty = y0 + 2 * sc;
	int health = (int)(((int64_t)s->pl.health + FX_ONE - 1) >> FX_SHIFT);
	char buf[48];

	if (s->pl.hurt || s->pl.bonus) {
		uint8_t col = s->pl.hurt ? c->red : c->yellow;
		int t = 3 * sc;
		v_fill(f, 0, 0, f->w, t, col);
		v_fill(f, 0, f->h - t, f->w, t, col);
		v_fill(f, 0, 0, t, f->h, col);
		v_fill(f, f->w - t, 0, t, f->h, col);
	}
	if (s->g.phase != G_PH_DEAD) {
		if (!hud_weapon_pics(s, env->tex, f, y0))
			hud_weapon_drawn(s, c, f, y0);
		hud_crosshair(s, c, f);
	}
	v_remap_par(f, 0, y0, f->w, bar, c->dim, c->par);
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "HEALTH ");
	hud_cat_num(buf, sizeof(buf), (uint64_t)(health < 0 ? 0 : health), 3, ' ');
	hud_text(f, c, 2 * sc, ty, sc, health <= 25 ? c->red : c->white, buf);
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "AMMO ");
	hud_cat_num(buf, sizeof(buf), s->pl.ammo, 3, ' ');
	hud_text(f, c, 2 * sc + v_text_width("HEALTH 100  ", sc), ty, sc,
		 s->pl.ammo == 0 ? c->red : c->white, buf);
	/* the weapon held: its number (what the change button steps through)
	 * and name */
	buf[0] = '\0';
	hud_cat_num(buf, sizeof(buf), (uint64_t)hud_held(s) + 1, 1, '0');
	msg_cat(buf, sizeof(buf), " ");
	msg_cat(buf, sizeof(buf), g_weapons[hud_held(s)].name);
	hud_text(f, c, 2 * sc + v_text_width("HEALTH 100  AMMO 200  ", sc), ty, sc,
		 s->pl.ammo < g_weapons[hud_held(s)].ammo ? c->red : c->yellow, buf);
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "STAGE ");
	hud_cat_num(buf, sizeof(buf), s->g.stage + 1u, 1, '0');
	hud_text_right(f, c, f->w - 2 * sc, ty, sc, c->white, buf);
	if (s->players == 2) {
		/* both scores, the player up's bright */
		for (int n = 0; n < 2; n++) {
			hud_up_text(s, n, buf, sizeof(buf));
			hud_text(f, c, 2 * sc + n * v_text_width("1UP 000000  ", sc), 2 * sc, sc,
				 n == s->up ? c->white : c->grey, buf);
		}
	} else {
		buf[0] = '\0';
		msg_cat(buf, sizeof(buf), "SCORE ");
		hud_cat_num(buf, sizeof(buf), s->g.score, 6, '0');
		hud_text(f, c, 2 * sc, 2 * sc, sc, c->white, buf);
	}
	buf[0] = '\0';
	msg_cat(buf, sizeof(buf), "LIVES ");
	hud_cat_num(buf, sizeof(buf), s->g.lives, 1, '0');
	hud_text(f, c, 2 * sc, 12 * sc, sc, c->white, buf);
	if (s->credits || s->set.freeplay) {
		hud_credits_text(s, buf, sizeof(buf));
		hud_text(f, c, 2 * sc, 22 * sc, sc, c->grey, buf);
	}
	hud_keys(s, c, f, 2 * sc + v_text_width("LIVES 9 ", sc), 12 * sc);
	if (s->w.msg)
		hud_text_centre(f, c, 34 * sc, sc, c->yellow, hud_msg_text(s->w.msg));
	hud_minimap(s, c, f);
	hud_clock(s, c, f);
	hud_banners(s, c, f);
}

void hud_draw(const struct sim *s, const struct hud_env *env, struct r_frame *f)
{
	struct hud_colours c;

	if (env->colours)
		c = *env->colours;
	else
		hud_colours(env->pal, &c);
	c.par = env->par;
	if (!hud_world(s))
		v_fill(f, 0, 0, f->w, f->h, c.black);
	switch (s->mode) {
	case SIM_PLAY:
		if (s->g.phase == G_PH_INTER)
			hud_page_inter(s, &c, f);
		else if (s->g.phase == G_PH_TURN)
			hud_page_turn(s, &c, f);
		else
			hud_play(s, env, &c, f);
		break;
	case SIM_GAMEOVER:
		hud_page_gameover(s, &c, f);
		break;
	case SIM_INITIALS:
		hud_page_initials(s, &c, f);
		break;
	case SIM_SERVICE:
		menu_draw(s, env, f);
		break;
	case SIM_ATTRACT:
	default:
		hud_page_attract(s, &c, f);
		if (env->notice) {
			/* small, at the foot, on a black band: readable over the demo */
			int sc = hud_scale(f);
			v_fill(f, 0, f->h - 11 * sc, f->w, 11 * sc, c.black);
			hud_text_centre(f, &c, f->h - 10 * sc, sc, c.red,
					"CONFIG ERROR: SEE SERVICE MENU");
		}
		break;
	}
}
