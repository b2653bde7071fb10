/*
 * g_line: Doom's line specials by type number (the vanilla set, 1..141, as
 * the Doom wiki's linedef table lists them, plus Boom's scroll right, 85),
 * and the three ways they are triggered:
 *   walk over (W1 once, WR repeatable): the body's centre crosses the line
 *     (g_cross); enemies trigger only Doom's few (raise door 4, the lifts
 *     10 and 88, the teleporters 39, 97 and the monster-only 125, 126);
 *   use (S1/SR switches, D1/DR manual doors): the player's USE reaches the
 *     first line within 64 units in front (g_use), from its front side;
 *     a wall with nothing to use there says so (the message and the
 *     NOWAY event); enemies open the plain manual doors they bump into
 *     (g_enemy_bump), never secret ones;
 *   shoot (G1/GR): the player's shot passes or hits the line.
 * A once-only line is used up (w.used) when Doom clears its special; a
 * switch shows its other texture (w.switched; the renderers swap SW1/SW2),
 * and a button (SR, GR) pops back after a second (w.bt).
 */
#include <stddef.h>
#include <string.h>

#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_USE_RANGE (64 * FX_ONE)
#define G_ML_SECRET 0x0020             /* Doom's "secret" line flag */

enum g_trig { T_W, T_S, T_D, T_G, T_EFFECT };

enum g_act {
	A_DOOR,                        /* arg: enum g_door, the tagged sectors */
	A_LOCKED,                      /* arg: enum g_door; a key switch */
	A_MANUAL,                      /* the door behind the line */
	A_FLOOR,                       /* arg: enum g_floor */
	A_PLAT,                        /* arg: enum g_plat, arg2: units */
	A_CEIL,                        /* arg: enum g_ceil */
	A_CEIL_STOP,
	A_PLAT_STOP,
	A_STAIRS,                      /* arg: 1 turbo */
	A_DONUT,
	A_LIGHT,                       /* arg: level, -1 brightest, -2 darkest neighbour */
	A_STROBE,
	A_EXIT,                        /* arg: 1 secret */
	A_TELE,                        /* arg: 1 monsters only */
	A_CEIL_FLOOR,                  /* 40: ceiling up to the highest, floor down */
	A_NONE                         /* effects: 48 and 85 scroll */
};

struct g_special {
	uint16_t type;
	uint8_t trig, once, mon, act;
	int16_t arg, arg2;
	char name[36];
};

#define W1(t, a, arg, n) { t, T_W, 1, 0, a, arg, 0, n }
#define WR(t, a, arg, n) { t, T_W, 0, 0, a, arg, 0, n }
#define S1(t, a, arg, n) { t, T_S, 1, 0, a, arg, 0, n }
#define SR(t, a, arg, n) { t, T_S, 0, 0, a, arg, 0, n }
#define G1(t, a, arg, n) { t, T_G, 1, 0, a, arg, 0, n }
#define GR(t, a, arg, n) { t, T_G, 0, 0, a, arg, 0, n }
#define D1(t, n) { t, T_D, 1, 0, A_MANUAL, 0, 0, n }
#define DR(t, n) { t, T_D, 0, 0, A_MANUAL, 0, 0, n }

/* Sorted by type (g_special_of searches it). mon: enemies trigger it. */
static const struct g_special g_specials[] = {
	{ 1, T_D, 0, 1, A_MANUAL, 0, 0, "door open wait close" },
	W1(2, A_DOOR, G_DOOR_OPEN, "door open stay"),
	W1(3, A_DOOR, G_DOOR_CLOSE, "door close"),
	{ 4, T_W, 1, 1, A_DOOR, G_DOOR_NORMAL, 0, "door open wait close" },
	W1(5, A_FLOOR, G_FLOOR_RAISE, "floor raise to lowest ceiling"),
	W1(6, A_CEIL, G_CEIL_FAST_CRUSH_RAISE, "fast crusher"),
	S1(7, A_STAIRS, 0, "stairs build by 8"),
	W1(8, A_STAIRS, 0, "stairs build by 8"),
	S1(9, A_DONUT, 0, "donut"),
	{ 10, T_W, 1, 1, A_PLAT, G_PLAT_DWUS, 0, "lift" },
	S1(11, A_EXIT, 0, "exit"),
	W1(12, A_LIGHT, -1, "light to brightest neighbour"),
	W1(13, A_LIGHT, 255, "light to 255"),
	{ 14, T_S, 1, 0, A_PLAT, G_PLAT_RAISE_CHANGE, 32, "floor raise by 32, change flat" },
	{ 15, T_S, 1, 0, A_PLAT, G_PLAT_RAISE_CHANGE, 24, "floor raise by 24, change flat" },
	W1(16, A_DOOR, G_DOOR_CLOSE30, "door close wait open (30 s)"),
	W1(17, A_STROBE, 0, "light start strobing"),
	S1(18, A_FLOOR, G_FLOOR_RAISE_NEAREST, "floor raise to next floor"),
	W1(19, A_FLOOR, G_FLOOR_LOWER, "floor lower to highest floor"),
	S1(20, A_PLAT, G_PLAT_RAISE_NEAREST_CHANGE, "floor raise to next, change flat"),
	S1(21, A_PLAT, G_PLAT_DWUS, "lift"),
	W1(22, A_PLAT, G_PLAT_RAISE_NEAREST_CHANGE, "floor raise to next, change flat"),
	S1(23, A_FLOOR, G_FLOOR_LOWEST, "floor lower to lowest floor"),
	G1(24, A_FLOOR, G_FLOOR_RAISE, "floor raise to lowest ceiling"),
	W1(25, A_CEIL, G_CEIL_CRUSH_RAISE, "crusher"),
	DR(26, "blue key door open wait close"),
	DR(27, "yellow key door open wait close"),
	DR(28, "red key door open wait close"),
	S1(29, A_DOOR, G_DOOR_NORMAL, "door open wait close"),
	W1(30, A_FLOOR, G_FLOOR_RAISE_TEXTURE, "floor raise by shortest lower"),
	D1(31, "door open stay"),
	{ 32, T_D, 1, 1, A_MANUAL, 0, 0, "blue key door open stay" },
	{ 33, T_D, 1, 1, A_MANUAL, 0, 0, "red key door open stay" },
	{ 34, T_D, 1, 1, A_MANUAL, 0, 0, "yellow key door open stay" },
	W1(35, A_LIGHT, 35, "light to 35"),
	W1(36, A_FLOOR, G_FLOOR_TURBO_LOWER, "floor lower fast to highest + 8"),
	W1(37, A_FLOOR, G_FLOOR_LOWER_CHANGE, "floor lower to lowest, change"),
	W1(38, A_FLOOR, G_FLOOR_LOWEST, "floor lower to lowest floor"),
	{ 39, T_W, 1, 1, A_TELE, 0, 0, "teleport" },
	W1(40, A_CEIL_FLOOR, 0, "ceiling raise to highest"),
	S1(41, A_CEIL, G_CEIL_LOWER_TO_FLOOR, "ceiling lower to floor"),
	SR(42, A_DOOR, G_DOOR_CLOSE, "door close"),
	SR(43, A_CEIL, G_CEIL_LOWER_TO_FLOOR, "ceiling lower to floor"),
	W1(44, A_CEIL, G_CEIL_LOWER_AND_CRUSH, "ceiling lower to floor + 8"),
	SR(45, A_FLOOR, G_FLOOR_LOWER, "floor lower to highest floor"),
	GR(46, A_DOOR, G_DOOR_OPEN, "door open stay"),
	G1(47, A_PLAT, G_PLAT_RAISE_NEAREST_CHANGE, "floor raise to next, change flat"),
	{ 48, T_EFFECT, 0, 0, A_NONE, 0, 0, "scroll texture left" },
	S1(49, A_CEIL, G_CEIL_CRUSH_RAISE, "crusher"),
	S1(50, A_DOOR, G_DOOR_CLOSE, "door close"),
	S1(51, A_EXIT, 1, "secret exit"),
	W1(52, A_EXIT, 0, "exit"),
	W1(53, A_PLAT, G_PLAT_PERPETUAL, "platform perpetual"),
	W1(54, A_PLAT_STOP, 0, "platform stop"),
	S1(55, A_FLOOR, G_FLOOR_RAISE_CRUSH, "floor raise to ceiling - 8, crush"),
	W1(56, A_FLOOR, G_FLOOR_RAISE_CRUSH, "floor raise to ceiling - 8, crush"),
	W1(57, A_CEIL_STOP, 0, "crusher stop"),
	W1(58, A_FLOOR, G_FLOOR_RAISE24, "floor raise by 24"),
	W1(59, A_FLOOR, G_FLOOR_RAISE24_CHANGE, "floor raise by 24, change"),
	SR(60, A_FLOOR, G_FLOOR_LOWEST, "floor lower to lowest floor"),
	SR(61, A_DOOR, G_DOOR_OPEN, "door open stay"),
	SR(62, A_PLAT, G_PLAT_DWUS, "lift"),
	SR(63, A_DOOR, G_DOOR_NORMAL, "door open wait close"),
	SR(64, A_FLOOR, G_FLOOR_RAISE, "floor raise to lowest ceiling"),
	SR(65, A_FLOOR, G_FLOOR_RAISE_CRUSH, "floor raise to ceiling - 8, crush"),
	{ 66, T_S, 0, 0, A_PLAT, G_PLAT_RAISE_CHANGE, 24, "floor raise by 24, change flat" },
	{ 67, T_S, 0, 0, A_PLAT, G_PLAT_RAISE_CHANGE, 32, "floor raise by 32, change flat" },
	SR(68, A_PLAT, G_PLAT_RAISE_NEAREST_CHANGE, "floor raise to next, change flat"),
	SR(69, A_FLOOR, G_FLOOR_RAISE_NEAREST, "floor raise to next floor"),
	SR(70, A_FLOOR, G_FLOOR_TURBO_LOWER, "floor lower fast to highest + 8"),
	S1(71, A_FLOOR, G_FLOOR_TURBO_LOWER, "floor lower fast to highest + 8"),
	WR(72, A_CEIL, G_CEIL_LOWER_AND_CRUSH, "ceiling lower to floor + 8"),
	WR(73, A_CEIL, G_CEIL_CRUSH_RAISE, "crusher"),
	WR(74, A_CEIL_STOP, 0, "crusher stop"),
	WR(75, A_DOOR, G_DOOR_CLOSE, "door close"),
	WR(76, A_DOOR, G_DOOR_CLOSE30, "door close wait open (30 s)"),
	WR(77, A_CEIL, G_CEIL_FAST_CRUSH_RAISE, "fast crusher"),
	WR(79, A_LIGHT, 35, "light to 35"),
	WR(80, A_LIGHT, -1, "light to brightest neighbour"),
	WR(81, A_LIGHT, 255, "light to 255"),
	WR(82, A_FLOOR, G_FLOOR_LOWEST, "floor lower to lowest floor"),
	WR(83, A_FLOOR, G_FLOOR_LOWER, "floor lower to highest floor"),
	WR(84, A_FLOOR, G_FLOOR_LOWER_CHANGE, "floor lower to lowest, change"),
	{ 85, T_EFFECT, 0, 0, A_NONE, 0, 0, "scroll texture right (Boom)" },
	WR(86, A_DOOR, G_DOOR_OPEN, "door open stay"),
	WR(87, A_PLAT, G_PLAT_PERPETUAL, "platform perpetual"),
	{ 88, T_W, 0, 1, A_PLAT, G_PLAT_DWUS, 0, "lift" },
	WR(89, A_PLAT_STOP, 0, "platform stop"),
	WR(90, A_DOOR, G_DOOR_NORMAL, "door open wait close"),
	WR(91, A_FLOOR, G_FLOOR_RAISE, "floor raise to lowest ceiling"),
	WR(92, A_FLOOR, G_FLOOR_RAISE24, "floor raise by 24"),
	WR(93, A_FLOOR, G_FLOOR_RAISE24_CHANGE, "floor raise by 24, change"),
	WR(94, A_FLOOR, G_FLOOR_RAISE_CRUSH, "floor raise to ceiling - 8, crush"),
	WR(95, A_PLAT, G_PLAT_RAISE_NEAREST_CHANGE, "floor raise to next, change flat"),
	WR(96, A_FLOOR, G_FLOOR_RAISE_TEXTURE, "floor raise by shortest lower"),
	{ 97, T_W, 0, 1, A_TELE, 0, 0, "teleport" },
	WR(98, A_FLOOR, G_FLOOR_TURBO_LOWER, "floor lower fast to highest + 8"),
	SR(99, A_LOCKED, G_DOOR_BLAZE_OPEN, "blue key door open stay, fast"),
	W1(100, A_STAIRS, 1, "stairs build by 16, fast"),
	S1(101, A_FLOOR, G_FLOOR_RAISE, "floor raise to lowest ceiling"),
	S1(102, A_FLOOR, G_FLOOR_LOWER, "floor lower to highest floor"),
	S1(103, A_DOOR, G_DOOR_OPEN, "door open stay"),
	W1(104, A_LIGHT, -2, "light to darkest neighbour"),
	WR(105, A_DOOR, G_DOOR_BLAZE_RAISE, "door open wait close, fast"),
	WR(106, A_DOOR, G_DOOR_BLAZE_OPEN, "door open stay, fast"),
	WR(107, A_DOOR, G_DOOR_BLAZE_CLOSE, "door close, fast"),
	W1(108, A_DOOR, G_DOOR_BLAZE_RAISE, "door open wait close, fast"),
	W1(109, A_DOOR, G_DOOR_BLAZE_OPEN, "door open stay, fast"),
	W1(110, A_DOOR, G_DOOR_BLAZE_CLOSE, "door close, fast"),
	S1(111, A_DOOR, G_DOOR_BLAZE_RAISE, "door open wait close, fast"),
	S1(112, A_DOOR, G_DOOR_BLAZE_OPEN, "door open stay, fast"),
	S1(113, A_DOOR, G_DOOR_BLAZE_CLOSE, "door close, fast"),
	SR(114, A_DOOR, G_DOOR_BLAZE_RAISE, "door open wait close, fast"),
	SR(115, A_DOOR, G_DOOR_BLAZE_OPEN, "door open stay, fast"),
	SR(116, A_DOOR, G_DOOR_BLAZE_CLOSE, "door close, fast"),
	DR(117, "door open wait close, fast"),
	D1(118, "door open stay, fast"),
	W1(119, A_FLOOR, G_FLOOR_RAISE_NEAREST, "floor raise to next floor"),
	WR(120, A_PLAT, G_PLAT_BLAZE_DWUS, "lift, fast"),
	W1(121, A_PLAT, G_PLAT_BLAZE_DWUS, "lift, fast"),
	S1(122, A_PLAT, G_PLAT_BLAZE_DWUS, "lift, fast"),
	SR(123, A_PLAT, G_PLAT_BLAZE_DWUS, "lift, fast"),
	W1(124, A_EXIT, 1, "secret exit"),
	{ 125, T_W, 1, 1, A_TELE, 1, 0, "teleport, monsters only" },
	{ 126, T_W, 0, 1, A_TELE, 1, 0, "teleport, monsters only" },
	S1(127, A_STAIRS, 1, "stairs build by 16, fast"),
	WR(128, A_FLOOR, G_FLOOR_RAISE_NEAREST, "floor raise to next floor"),
	WR(129, A_FLOOR, G_FLOOR_RAISE_TURBO, "floor raise fast to next floor"),
	W1(130, A_FLOOR, G_FLOOR_RAISE_TURBO, "floor raise fast to next floor"),
	S1(131, A_FLOOR, G_FLOOR_RAISE_TURBO, "floor raise fast to next floor"),
	SR(132, A_FLOOR, G_FLOOR_RAISE_TURBO, "floor raise fast to next floor"),
	S1(133, A_LOCKED, G_DOOR_BLAZE_OPEN, "blue key door open stay, fast"),
	SR(134, A_LOCKED, G_DOOR_BLAZE_OPEN, "red key door open stay, fast"),
	S1(135, A_LOCKED, G_DOOR_BLAZE_OPEN, "red key door open stay, fast"),
	SR(136, A_LOCKED, G_DOOR_BLAZE_OPEN, "yellow key door open stay, fast"),
	S1(137, A_LOCKED, G_DOOR_BLAZE_OPEN, "yellow key door open stay, fast"),
	SR(138, A_LIGHT, 255, "light to 255"),
	SR(139, A_LIGHT, 35, "light to 35"),
	S1(140, A_FLOOR, G_FLOOR_RAISE512, "floor raise by 512"),
	W1(141, A_CEIL, G_CEIL_SILENT_CRUSH_RAISE, "silent crusher"),
};

#define G_NSPECIALS (sizeof(g_specials) / sizeof(g_specials[0]))

static const struct g_special *g_special_of(uint16_t type)
{
	size_t lo = 0, hi = G_NSPECIALS;

	while (lo < hi) {
		size_t mid = (lo + hi) / 2;
		if (g_specials[mid].type == type)
			return &g_specials[mid];
		if (g_specials[mid].type < type)
			lo = mid + 1;
		else
			hi = mid;
	}
	return NULL;
}

int g_line_special(uint16_t type, char *out, size_t len)
{
	static const char trig[5][2] = { "W", "S", "D", "G", "" };
	const struct g_special *sp = g_special_of(type);
	size_t n = 0;

	if (!sp)
		return 0;
	if (out && len > 0) {
		const char *parts[4] = { trig[sp->trig], sp->trig == T_EFFECT ? "" : sp->once ? "1 " : "R ",
					 sp->name, sp->mon ? " (monsters too)" : "" };
		for (int i = 0; i < 4; i++)
			for (const char *c = parts[i]; *c && n + 1 < len; c++)
				out[n++] = *c;
		out[n] = '\0';
	}
	return 1;
}

/* The special of line `line` now: 0 when it has none or is used up. */
static const struct g_special *g_live(const struct sim *s, uint32_t line)
{
	uint16_t t = s->map->lines[line].special;

	if (t == 0 || g_world_bit(s->w.used, line))
		return NULL;
	return g_special_of(t);
}

/* Doom's P_ChangeSwitchTexture: the line's front shows its other switch
 * texture; a button (again) pops back after G_BUTTON_TICKS, a switch is
 * used up. */
static void g_switch(struct sim *s, uint32_t line, int again)
{
	struct g_world *w = &s->w;
	uint32_t front = s->map->sides[s->map->lines[line].side[0]].sector;

	if (!again)
		g_line_set(w->used, line, 1);
	g_line_set(w->switched, line, !g_world_bit(w->switched, line));
	g_event(s, s->map->lines[line].special == 11 ? G_EV_SWITCH_EXIT : G_EV_SWITCH, front);
	if (!again)
		return;
	for (int i = 0; i < w->num_buttons; i++)
		if (w->bt[i].line == line)
			return;                /* already counting down */
	if (w->num_buttons < G_MAX_BUTTONS) {
		w->bt[w->num_buttons].line = line;
		w->bt[w->num_buttons].timer = G_BUTTON_TICKS;
		w->num_buttons++;
	}
}

void g_buttons_tick(struct sim *s)
{
	struct g_world *w = &s->w;

	for (int i = 0; i < w->num_buttons;) {
		struct g_button *b = &w->bt[i];
		if (b->timer > 1) {
			b->timer--;
			i++;
			continue;
		}
		/* back to the texture it had before it was pressed */
		g_line_set(w->switched, b->line, 0);
		g_event(s, G_EV_SWITCH, s->map->sides[s->map->lines[b->line].side[0]].sector);
		memmove(b, b + 1, (size_t)(w->num_buttons - i - 1) * sizeof(*b));
		w->num_buttons--;
	}
}

/* Does what special sp of line `line` does, for who (having crossed from
 * `side`); 1 when it started something (Doom's EV_ return values). */
static int g_act(struct sim *s, uint32_t line, const struct g_special *sp, int who, int side)
{
	const struct map_line *l = &s->map->lines[line];

	switch (sp->act) {
	case A_DOOR:
		return g_door_tagged(s, l, sp->arg);
	case A_LOCKED:
		return g_door_locked(s, line, sp->arg, who);
	case A_MANUAL:
		return g_door_manual(s, line, who);
	case A_FLOOR:
		return g_floor_tagged(s, l, sp->arg);
	case A_PLAT:
		return g_plat_tagged(s, l, sp->arg, sp->arg2);
	case A_CEIL:
		return g_ceil_tagged(s, l, sp->arg);
	case A_CEIL_STOP:
		return g_ceil_stop(s, l->tag);
	case A_PLAT_STOP:
		g_plat_stop(s, l->tag);
		return 1;
	case A_STAIRS:
		return g_stairs(s, l, sp->arg);
	case A_DONUT:
		return g_donut(s, l);
	case A_LIGHT:
		g_light_set(s, l->tag, sp->arg);
		return 1;
	case A_STROBE:
		g_light_strobe_tagged(s, l->tag);
		return 1;
	case A_EXIT:
		g_exit(s, sp->arg);
		return 1;
	case A_TELE:
		return g_teleport(s, l, side, who);
	case A_CEIL_FLOOR:
		/* Doom starts both; the floor finds the ceiling's mover there */
		g_ceil_tagged(s, l, G_CEIL_RAISE_TO_HIGHEST);
		g_floor_tagged(s, l, G_FLOOR_LOWEST);
		return 1;
	default:
		return 0;
	}
}

/* ---- walking over -------------------------------------------------------- */

/* Doom's side of a point: 1 behind (left of v1 -> v2), 0 in front or on it. */
static int g_side_of(const struct map *m, const struct map_line *l, fx_t x, fx_t y)
{
	const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
	int64_t c = ((int64_t)b->x - a->x) * ((int64_t)y - a->y) -
		    ((int64_t)b->y - a->y) * ((int64_t)x - a->x);

	return c > 0;
}

void g_cross(struct sim *s, int who, fx_t ox, fx_t oy, fx_t nx, fx_t ny, fx_t r)
{
	const struct map *m = s->map;

	for (uint32_t k = 0; k < m->num_spec_lines; k++) {
		uint32_t i = m->spec_lines[k];
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		const struct g_special *sp;
		int side;

		/* the body's box at its new place meets the line's box ... */
		if ((nx + (int64_t)r <= a->x && nx + (int64_t)r <= b->x) ||
		    (nx - (int64_t)r >= a->x && nx - (int64_t)r >= b->x) ||
		    (ny + (int64_t)r <= a->y && ny + (int64_t)r <= b->y) ||
		    (ny - (int64_t)r >= a->y && ny - (int64_t)r >= b->y))
			continue;
		/* ... and its centre went to the other side */
		side = g_side_of(m, l, ox, oy);
		if (side == g_side_of(m, l, nx, ny))
			continue;
		sp = g_live(s, i);
		if (!sp || sp->trig != T_W)
			continue;
		if (who != G_WHO_PLAYER && !sp->mon)
			continue;
		if (sp->act == A_TELE && sp->arg == 1 && who == G_WHO_PLAYER)
			continue;              /* monsters only */
		if (sp->act == A_TELE) {
			int moved = g_act(s, i, sp, who, side);
			if (sp->once)
				g_line_set(s->w.used, i, 1);
			if (moved)
				return;        /* the body is elsewhere now */
			continue;
		}
		g_act(s, i, sp, who, side);
		if (sp->once && sp->act != A_EXIT)
			g_line_set(s->w.used, i, 1);
	}
}

/* ---- using -------------------------------------------------------------- */

/* Doom's P_UseSpecialLine for the player or an enemy; 1 if the line has a
 * use special (whatever it did). */
static int g_use_special(struct sim *s, uint32_t line, int side, int who)
{
	const struct g_special *sp = g_live(s, line);

	if (!sp || side)
		return 0;
	if (who != G_WHO_PLAYER &&
	    ((s->map->lines[line].flags & G_ML_SECRET) || sp->trig != T_D || !sp->mon))
		return 0;
	if (sp->trig == T_D) {
		if (g_act(s, line, sp, who, side) && sp->once)
			g_line_set(s->w.used, line, 1);
		return 1;
	}
	if (sp->trig != T_S)
		return 1;
	if (sp->act == A_EXIT) {
		g_switch(s, line, 0);
		g_act(s, line, sp, who, side);
		return 1;
	}
	if (g_act(s, line, sp, who, side) || (sp->act == A_LIGHT && !sp->once))
		g_switch(s, line, !sp->once);
	return 1;
}

/* A line met by a ray from (x1, y1) by (dx, dy): its index and where along
 * the ray (a fraction scaled by 2^16). */
struct g_hit {
	uint32_t line;
	int64_t at;
};

/* The lines the segment from (x1, y1) by (dx, dy) meets, nearest first,
 * up to max of them. */
static int g_trace(const struct sim *s, fx_t x1, fx_t y1, int64_t dx, int64_t dy,
		   struct g_hit *hits, int max)
{
	const struct map *m = s->map;
	int64_t x2 = x1 + dx, y2 = y1 + dy;
	int64_t lox = x1 < x2 ? x1 : x2, hix = x1 > x2 ? x1 : x2;
	int64_t loy = y1 < y2 ? y1 : y2, hiy = y1 > y2 ? y1 : y2;
	int n = 0;

	for (uint32_t i = 0; i < m->num_lines && n < max; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		int64_t wx, wy, den, num;
		if ((a->x < lox && b->x < lox) || (a->x > hix && b->x > hix) ||
		    (a->y < loy && b->y < loy) || (a->y > hiy && b->y > hiy))
			continue;
		if (!g_segs_cross(x1, y1, x2, y2, a, b))
			continue;
		wx = (int64_t)b->x - a->x;
		wy = (int64_t)b->y - a->y;
		den = dx * wy - dy * wx;
		num = ((int64_t)a->x - x1) * wy - ((int64_t)a->y - y1) * wx;
		if (den < 0) {
			den = -den;
			num = -num;
		}
		/* the segments are short (a use or a shot): num and den fit;
		 * scale down the long lines' products before the division */
		while (den >= ((int64_t)1 << 46)) {
			den >>= 1;
			num >>= 1;
		}
		hits[n].line = i;
		hits[n].at = den == 0 || num <= 0 ? 0 : num * FX_ONE / den;
		n++;
	}
	/* nearest first; a tie goes to the lower line number */
	for (int i = 1; i < n; i++)
		for (int j = i; j > 0 && (hits[j].at < hits[j - 1].at ||
					  (hits[j].at == hits[j - 1].at && hits[j].line < hits[j - 1].line));
		     j--) {
			struct g_hit t = hits[j];
			hits[j] = hits[j - 1];
			hits[j - 1] = t;
		}
	return n;
}

#define G_MAX_HITS 64

void g_use(struct sim *s)
{
	const struct map *m = s->map;
	const struct sim_player *p = &s->pl;
	struct g_hit hits[G_MAX_HITS];
	int n = g_trace(s, p->x, p->y, fx_mul(G_USE_RANGE, tab_cos(p->angle)),
			fx_mul(G_USE_RANGE, tab_sin(p->angle)), hits, G_MAX_HITS);

	for (int i = 0; i < n; i++) {
		uint32_t line = hits[i].line;
		const struct map_line *l = &m->lines[line];
		if (!g_live(s, line)) {
			/* no special: go on through an opening, else it is a wall */
			fx_t fl = 0, cl = 0;
			if (l->side[1] != MAP_NONE) {
				const struct g_sector *f = &s->w.sec[m->sides[l->side[0]].sector];
				const struct g_sector *b = &s->w.sec[m->sides[l->side[1]].sector];
				fl = f->floor_h > b->floor_h ? f->floor_h : b->floor_h;
				cl = f->ceil_h < b->ceil_h ? f->ceil_h : b->ceil_h;
			}
			if ((int64_t)cl - fl > 0)
				continue;
			g_message(s, G_MSG_NOTHING);
			g_event(s, G_EV_NOWAY, MAP_NONE);
			return;
		}
		/* Doom stops at the first line with a special, whatever it is */
		g_use_special(s, line, g_side_of(m, l, p->x, p->y), G_WHO_PLAYER);
		return;
	}
}

void g_enemy_bump(struct sim *s, int i, fx_t x, fx_t y)
{
	const struct map *m = s->map;
	const struct g_enemy *e = &s->g.en[i];
	int64_t r = g_kinds[e->kind].radius + 4 * FX_ONE;
	uint32_t n;
	const uint32_t *ls = map_sector_lines(m, e->sector, &n);

	for (uint32_t k = 0; k < n; k++) {
		const struct map_line *l = &m->lines[ls[k]];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		int64_t dx, dy, px, py, t, len2, c;
		if (!l->special || l->side[1] == MAP_NONE)
			continue;
		/* near enough: within the line's span and r of it (1/16 units) */
		dx = ((int64_t)b->x - a->x) >> 12;
		dy = ((int64_t)b->y - a->y) >> 12;
		px = ((int64_t)x - a->x) >> 12;
		py = ((int64_t)y - a->y) >> 12;
		len2 = dx * dx + dy * dy;
		t = px * dx + py * dy;
		if (len2 == 0 || t < 0 || t > len2)
			continue;
		c = dx * py - dy * px;
		if ((c < 0 ? -c : c) / ((int64_t)fx_isqrt64((uint64_t)len2) + 1) >= (r >> 12))
			continue;
		/* Doom's monsters use a line as from its front */
		if (g_use_special(s, ls[k], 0, i))
			return;
	}
}

/* ---- shooting ----------------------------------------------------------- */

void g_shoot_lines(struct sim *s, fx_t x1, fx_t y1, fx_t x2, fx_t y2)
{
	struct g_hit hits[G_MAX_HITS];
	int64_t dx = (int64_t)x2 - x1, dy = (int64_t)y2 - y1;
	int64_t len = fx_len((fx_t)(dx / 2), (fx_t)(dy / 2)) * 2;
	int n;

	/* 2 units on, so the wall the shot stopped at is met */
	if (len > 0) {
		dx += dx * (2 * FX_ONE) / len;
		dy += dy * (2 * FX_ONE) / len;
	}
	n = g_trace(s, x1, y1, dx, dy, hits, G_MAX_HITS);
	for (int i = 0; i < n; i++) {
		const struct g_special *sp = g_live(s, hits[i].line);
		if (!sp || sp->trig != T_G)
			continue;
		g_act(s, hits[i].line, sp, G_WHO_PLAYER, 0);
		g_switch(s, hits[i].line, !sp->once);
	}
}
