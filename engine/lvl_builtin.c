/*
 * lvl_builtin: the levels compiled into the daemon, as integer tables turned
 * into maps by map_alloc + map_finish (the node builder makes their BSP).
 *
 * ARENA1 (map units; x east, y north; f = floor, c = ceiling, l = light):
 *
 *    y
 *  1024 +--------------------------------------+--------------------------+
 *       |                                      :                          |
 *       |  GALLERY f64 c192 l160               : <- ledge: drop of 64     |
 *       |                                      :                          |
 *   736 +--------+===========+-----------------+                          |
 *   704 |  void  | STEP3 f48 |     void        |                          |
 *   672 |        | STEP2 f32 |                 |     YARD f0 c256 l176    |
 *   640 +--------+=STEP1 f16=+-------+         |                          |
 *       |                            | notch   |       +--------+ 576     |
 *       |                            | (void)  |       |  DAIS  |         |
 *   448 |   HALL f0 c144 l208        +---------+       |f40 l240|         |
 *   416 |                                      D       +--------+ 448     |
 *   384 |             +----+                   D  DOOR f0 c120            |
 *   320 |             |pill|                   D                          |
 *   256 |             +----+                   W                          |
 *       |                                      W  WINDOW f40 c88          |
 *   128 |    @->                               W                          |
 *     0 +--------------------------------------+--------------------------+
 *       0        128         320     448     640 656  800     928     1024
 *
 * (D and W are 16-unit-deep sectors in the wall x 640..656; the pillar is
 * x 224..288, y 320..384; the stairs are x 128..320.)
 *
 * - HALL is non-convex twice over: an L (the void notch x 448..640,
 *   y 448..640) with a pillar (a hole) in it.
 * - STEP1..3 rise by 16 from the hall (0) to the gallery (64): climbable,
 *   SIM_MAX_STEP is 24.
 * - WINDOW: a 16-unit-deep sector in the hall's east wall whose floor (40) is
 *   higher and ceiling (88) lower than both the hall's and the yard's, so
 *   both sides show an upper and a lower wall part around the opening; it
 *   blocks the player twice over (a 40 step; a 48 opening, lower than the
 *   56-unit player).
 * - DOOR: a doorway sector with a low lintel (120) between hall and yard.
 * - DAIS: a 40-unit platform in the yard, too high to climb.
 * - The gallery's east edge is a 64-unit drop into the yard.
 * - Player 1 starts at @ (96, 192) facing east: the pillar ahead on the
 *   left, the window straight ahead with the yard and the dais behind it.
 */
#include <errno.h>
#include <string.h>

#include "engine/map.h"
#include "engine/pal.h"

struct lvl_sector {
	int16_t floor, ceil;
	uint8_t floor_tex, ceil_tex, light;
};

struct lvl_line {
	uint16_t v1, v2;
	int8_t front, back;            /* sector indices; back -1: one-sided */
	uint8_t tex;                   /* wall colour on both sides */
};

struct lvl_thing {
	int16_t x, y;
	ang_t angle;
	uint16_t type;
};

struct lvl {
	const char *name;
	const int16_t (*vertices)[2];
	const struct lvl_sector *sectors;
	const struct lvl_line *lines;
	const struct lvl_thing *things;
	uint32_t num_vertices, num_sectors, num_lines, num_things;
};

enum {
	A1_HALL, A1_STEP1, A1_STEP2, A1_STEP3, A1_GALLERY, A1_YARD, A1_DAIS, A1_DOOR, A1_WINDOW
};

#define T_HALL PAL_RGB(PAL_TAN, 2)
#define T_PILLAR PAL_RGB(PAL_RED, 2)
#define T_STEP PAL_RGB(PAL_SLATE, 1)
#define T_GALLERY PAL_RGB(PAL_TEAL, 2)
#define T_YARD PAL_RGB(PAL_BLUE, 2)
#define T_DAIS PAL_RGB(PAL_YELLOW, 2)
#define T_WINDOW PAL_RGB(PAL_PURPLE, 1)
#define T_DOOR PAL_RGB(PAL_CYAN, 2)
#define T_LEDGE PAL_RGB(PAL_GREEN, 1)

static const int16_t arena1_vertices[][2] = {
	{ 0, 0 }, { 0, 640 }, { 128, 640 }, { 320, 640 },              /* 0 */
	{ 448, 640 }, { 448, 448 }, { 640, 448 }, { 640, 416 },        /* 4 */
	{ 640, 320 }, { 640, 256 }, { 640, 128 }, { 640, 0 },          /* 8 */
	{ 224, 320 }, { 288, 320 }, { 288, 384 }, { 224, 384 },        /* 12 pillar */
	{ 128, 672 }, { 320, 672 }, { 128, 704 }, { 320, 704 },        /* 16 steps */
	{ 128, 736 }, { 320, 736 }, { 0, 736 }, { 0, 1024 },           /* 20 */
	{ 656, 1024 }, { 656, 736 }, { 656, 416 }, { 656, 320 },       /* 24 */
	{ 656, 256 }, { 656, 128 }, { 656, 0 }, { 1024, 1024 },        /* 28 */
	{ 1024, 0 }, { 800, 448 }, { 928, 448 }, { 928, 576 },         /* 32 dais */
	{ 800, 576 },                                                  /* 36 */
};

static const struct lvl_sector arena1_sectors[] = {
	[A1_HALL] = { 0, 144, PAL_RGB(PAL_BROWN, 2), PAL_RGB(PAL_GREY, 2), 208 },
	[A1_STEP1] = { 16, 192, PAL_RGB(PAL_OLIVE, 2), PAL_RGB(PAL_GREY, 3), 176 },
	[A1_STEP2] = { 32, 192, PAL_RGB(PAL_OLIVE, 2), PAL_RGB(PAL_GREY, 3), 176 },
	[A1_STEP3] = { 48, 192, PAL_RGB(PAL_OLIVE, 2), PAL_RGB(PAL_GREY, 3), 176 },
	[A1_GALLERY] = { 64, 192, PAL_RGB(PAL_GREEN, 3), PAL_RGB(PAL_SLATE, 3), 160 },
	[A1_YARD] = { 0, 256, PAL_RGB(PAL_OLIVE, 3), PAL_RGB(PAL_SKY, 1), 176 },
	[A1_DAIS] = { 40, 256, PAL_RGB(PAL_ORANGE, 1), PAL_RGB(PAL_SKY, 1), 240 },
	[A1_DOOR] = { 0, 120, PAL_RGB(PAL_BROWN, 2), PAL_RGB(PAL_CYAN, 3), 176 },
	[A1_WINDOW] = { 40, 88, PAL_RGB(PAL_PURPLE, 2), PAL_RGB(PAL_PURPLE, 3), 176 },
};

/* Each sector's boundary runs clockwise (its interior on the right). */
static const struct lvl_line arena1_lines[] = {
	/* hall outline, from the south-west corner clockwise */
	{ 0, 1, A1_HALL, -1, T_HALL },               /* 0 */
	{ 1, 2, A1_HALL, -1, T_HALL },
	{ 2, 3, A1_HALL, A1_STEP1, T_STEP },
	{ 3, 4, A1_HALL, -1, T_HALL },
	{ 4, 5, A1_HALL, -1, T_HALL },               /* 4: the notch */
	{ 5, 6, A1_HALL, -1, T_HALL },
	{ 6, 7, A1_HALL, -1, T_HALL },
	{ 7, 8, A1_HALL, A1_DOOR, T_DOOR },
	{ 8, 9, A1_HALL, -1, T_HALL },               /* 8 */
	{ 9, 10, A1_HALL, A1_WINDOW, T_WINDOW },
	{ 10, 11, A1_HALL, -1, T_HALL },
	{ 11, 0, A1_HALL, -1, T_HALL },
	/* pillar: counter-clockwise, so the hall is on the right */
	{ 12, 13, A1_HALL, -1, T_PILLAR },           /* 12 */
	{ 13, 14, A1_HALL, -1, T_PILLAR },
	{ 14, 15, A1_HALL, -1, T_PILLAR },
	{ 15, 12, A1_HALL, -1, T_PILLAR },
	/* stairs */
	{ 2, 16, A1_STEP1, -1, T_STEP },             /* 16 */
	{ 17, 3, A1_STEP1, -1, T_STEP },
	{ 16, 17, A1_STEP1, A1_STEP2, T_STEP },
	{ 16, 18, A1_STEP2, -1, T_STEP },
	{ 19, 17, A1_STEP2, -1, T_STEP },            /* 20 */
	{ 18, 19, A1_STEP2, A1_STEP3, T_STEP },
	{ 18, 20, A1_STEP3, -1, T_STEP },
	{ 21, 19, A1_STEP3, -1, T_STEP },
	{ 20, 21, A1_STEP3, A1_GALLERY, T_STEP },    /* 24 */
	/* gallery */
	{ 22, 23, A1_GALLERY, -1, T_GALLERY },
	{ 23, 24, A1_GALLERY, -1, T_GALLERY },
	{ 24, 25, A1_GALLERY, A1_YARD, T_LEDGE },
	{ 25, 21, A1_GALLERY, -1, T_GALLERY },       /* 28 */
	{ 20, 22, A1_GALLERY, -1, T_GALLERY },
	/* doorway */
	{ 7, 26, A1_DOOR, -1, T_DOOR },
	{ 27, 8, A1_DOOR, -1, T_DOOR },
	{ 26, 27, A1_DOOR, A1_YARD, T_DOOR },        /* 32 */
	/* window */
	{ 9, 28, A1_WINDOW, -1, T_WINDOW },
	{ 29, 10, A1_WINDOW, -1, T_WINDOW },
	{ 28, 29, A1_WINDOW, A1_YARD, T_WINDOW },
	/* yard outline */
	{ 30, 29, A1_YARD, -1, T_YARD },             /* 36 */
	{ 28, 27, A1_YARD, -1, T_YARD },
	{ 26, 25, A1_YARD, -1, T_YARD },
	{ 24, 31, A1_YARD, -1, T_YARD },
	{ 31, 32, A1_YARD, -1, T_YARD },             /* 40 */
	{ 32, 30, A1_YARD, -1, T_YARD },
	/* dais: counter-clockwise, the yard in front */
	{ 33, 34, A1_YARD, A1_DAIS, T_DAIS },
	{ 34, 35, A1_YARD, A1_DAIS, T_DAIS },
	{ 35, 36, A1_YARD, A1_DAIS, T_DAIS },        /* 44 */
	{ 36, 33, A1_YARD, A1_DAIS, T_DAIS },
};

static const struct lvl_thing arena1_things[] = {
	{ 96, 192, 0, 1 },                           /* player 1 start, facing east */
};

#define LVL_COUNT(a) ((uint32_t)(sizeof(a) / sizeof((a)[0])))

static const struct lvl lvl_levels[] = {
	{ "ARENA1", arena1_vertices, arena1_sectors, arena1_lines, arena1_things,
	  LVL_COUNT(arena1_vertices), LVL_COUNT(arena1_sectors), LVL_COUNT(arena1_lines),
	  LVL_COUNT(arena1_things) },
};

int map_builtin_count(void)
{
	return (int)LVL_COUNT(lvl_levels);
}

static uint32_t lvl_num_sides(const struct lvl *lv)
{
	uint32_t i, n = 0;

	for (i = 0; i < lv->num_lines; i++)
		n += lv->lines[i].back >= 0 ? 2 : 1;
	return n;
}

/* One side facing sector sec; one-sided walls use the middle texture,
 * portals the upper and lower ones. */
static void lvl_side(struct map_side *s, int sec, uint8_t tex, int two)
{
	memset(s, 0, sizeof *s);
	s->sector = (uint32_t)sec;
	if (two) {
		s->top_tex = tex;
		s->bot_tex = tex;
	} else {
		s->mid_tex = tex;
	}
}

int map_builtin(int i, struct map **out)
{
	const struct lvl *lv;
	struct map *m;
	uint32_t k, side = 0;
	int r;

	*out = NULL;
	if (i < 0 || i >= map_builtin_count())
		return -EINVAL;
	lv = &lvl_levels[i];
	r = map_alloc(&m, lv->num_vertices, lv->num_sectors, lvl_num_sides(lv), lv->num_lines,
		      lv->num_things);
	if (r)
		return r;
	memcpy(m->name, lv->name, strlen(lv->name) + 1);
	for (k = 0; k < lv->num_vertices; k++) {
		m->vertices[k].x = fx_from_int(lv->vertices[k][0]);
		m->vertices[k].y = fx_from_int(lv->vertices[k][1]);
	}
	for (k = 0; k < lv->num_sectors; k++) {
		const struct lvl_sector *s = &lv->sectors[k];
		m->sectors[k].floor_h = fx_from_int(s->floor);
		m->sectors[k].ceil_h = fx_from_int(s->ceil);
		m->sectors[k].floor_tex = s->floor_tex;
		m->sectors[k].ceil_tex = s->ceil_tex;
		m->sectors[k].light = s->light;
	}
	for (k = 0; k < lv->num_lines; k++) {
		const struct lvl_line *l = &lv->lines[k];
		struct map_line *ml = &m->lines[k];
		int two = l->back >= 0;
		ml->v1 = l->v1;
		ml->v2 = l->v2;
		ml->flags = two ? ML_TWOSIDED : ML_BLOCKING;
		ml->side[0] = side;
		lvl_side(&m->sides[side++], l->front, l->tex, two);
		ml->side[1] = MAP_NONE;
		if (two) {
			ml->side[1] = side;
			lvl_side(&m->sides[side++], l->back, l->tex, two);
		}
	}
	for (k = 0; k < lv->num_things; k++) {
		m->things[k].x = fx_from_int(lv->things[k].x);
		m->things[k].y = fx_from_int(lv->things[k].y);
		m->things[k].angle = lv->things[k].angle;
		m->things[k].type = lv->things[k].type;
	}
	/* the tables are the project's own: a failure is a bug the unit tests
	 * catch, reported like any bad map */
	r = map_finish(m, NULL, 0);
	if (r) {
		map_free(m);
		return r;
	}
	*out = m;
	return 0;
}
