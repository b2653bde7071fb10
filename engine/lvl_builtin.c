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
 * - Stage 1 of the game (the easiest): three grunts (g) in the yard and at
 *   the gallery's east end, a sentry (s) on the dais; a medikit (+), a
 *   stimpack, a clip and a box of bullets (a); floor lamps (*) in the hall
 *   and the yard and two point lights (L). Placed away from the paths the
 *   movement scripts walk (tests/script), which stay valid.
 *
 *   gallery: g (600, 960)   a (300, 900)
 *   yard:    g (720, 960)  g (960, 960)  s on the dais (864, 512)
 *            + stim (1000, 40)  * (1000, 1000)  L (840, 300)
 *   hall:    + (320, 96)  a clip (96, 560)  * (40, 600)  L (320, 480)
 *
 * ARENA2 (stage 2), a cross of four arms round a square court with a
 * pillar; the west arm is 16 lower, the east arm 16 higher (both steps
 * climbable):
 *
 *    y
 *  1024          +-----------+
 *                |  NORTH    |   f0 c128 l144: g g b, a box of bullets
 *                |           |
 *   640 +--------+-----------+--------+
 *       | WEST   |  COURT  # |  EAST  |  WEST f-16 c112 l128: g b (+g hard)
 *       |        |   [#]     |        |  COURT f0 c192 l192: pillar, +, lamps
 *   384 +--------+-----------+--------+  EAST f16 c144 l176: g s (+b hard)
 *                |  SOUTH    |
 *                |     @     |   f0 c128 l160: start (512, 64) facing north
 *     0          +-----------+
 *       0       384         640      1024
 *
 * ARENA3 (stage 3), a ring round a solid central block; the north side is
 * 32 up, reached by 16-unit steps on the west and east sides:
 *
 *    y
 *  1024 +--------------------------------------------+
 *       |  NORTH f32 c224 l112 (dark): s s b g,       |
 *       |  point lights, torches; +g +s on hard       |
 *   704 +--------+-------------------------+--------+
 *       | WHIGH  |                         | EHIGH  |  f16 c160 l144: g / g b
 *   512 +--------+      (solid block)      +--------+
 *       | WLOW   |                         | ELOW   |  f0 c160 l160: b / s
 *   320 +--------+-------------------------+--------+
 *       |  SOUTH f0 c192 l176   [#] pillar            |  g b (+b on hard)
 *       |  @ (160, 160) facing east                   |
 *     0 +--------------------------------------------+
 *       0       384                       896      1280
 *
 * Thing flags use Doom's skill bits: 7 on every difficulty, 4 only on
 * hard and brutal (difficulty 2, 3).
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
	uint16_t flags;                /* Doom's skill bits: 1 easy, 2 normal, 4 hard */
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

/* Thing types (Doom's numbers, see engine/th.h and engine/g_thing.c). */
enum {
	TT_START = 1, TT_GRUNT = 3004, TT_SHOTGUY = 9, TT_IMP = 3001, TT_DEMON = 3002,
	TT_CACO = 3005, TT_STIM = 2011, TT_MEDI = 2012, TT_CLIP = 2007, TT_AMMO = 2048,
	TT_LAMP = 2028, TT_CANDELABRA = 35, TT_TORCH = 46,
	/* arcaded's point light (th_light): radius 256, intensities 5..7 of 8 */
	TT_LIGHT_WARM = 15226, TT_LIGHT_WHITE = 15232, TT_LIGHT_ORANGE = 15242,
};

#define ALL 7                          /* every difficulty */
#define HARD 4                         /* hard and brutal only */
#define SW (ANG180 + ANG45)
#define SE (ANG270 + ANG45)

static const struct lvl_thing arena1_things[] = {
	{ 96, 192, 0, TT_START, ALL },               /* player 1 start, facing east */
	{ 600, 960, ANG180, TT_GRUNT, ALL },         /* gallery, east end */
	{ 720, 960, ANG270, TT_GRUNT, ALL },         /* yard, north */
	{ 960, 960, SW, TT_GRUNT, ALL },
	{ 864, 512, ANG180, TT_CACO, ALL },          /* on the dais */
	{ 320, 96, 0, TT_MEDI, ALL },
	{ 1000, 40, 0, TT_STIM, ALL },
	{ 96, 560, 0, TT_CLIP, ALL },
	{ 300, 900, 0, TT_AMMO, ALL },
	{ 40, 600, 0, TT_LAMP, ALL },
	{ 1000, 1000, 0, TT_LAMP, ALL },
	{ 320, 480, 0, TT_LIGHT_WARM, ALL },
	{ 840, 300, 0, TT_LIGHT_WHITE, ALL },
};

/* ---- ARENA2 ---------------------------------------------------------- */

enum { A2_SOUTH, A2_COURT, A2_EAST, A2_NORTH, A2_WEST };

static const int16_t arena2_vertices[][2] = {
	{ 384, 0 }, { 640, 0 }, { 384, 384 }, { 640, 384 },            /* 0 */
	{ 1024, 384 }, { 1024, 640 }, { 640, 640 }, { 384, 640 },      /* 4 */
	{ 640, 1024 }, { 384, 1024 }, { 0, 640 }, { 0, 384 },          /* 8 */
	{ 480, 480 }, { 544, 480 }, { 544, 544 }, { 480, 544 },        /* 12 pillar */
};

static const struct lvl_sector arena2_sectors[] = {
	[A2_SOUTH] = { 0, 128, PAL_RGB(PAL_SLATE, 3), PAL_RGB(PAL_GREY, 4), 160 },
	[A2_COURT] = { 0, 192, PAL_RGB(PAL_TAN, 3), PAL_RGB(PAL_SKY, 1), 192 },
	[A2_EAST] = { 16, 144, PAL_RGB(PAL_BROWN, 3), PAL_RGB(PAL_GREY, 5), 176 },
	[A2_NORTH] = { 0, 128, PAL_RGB(PAL_GREEN, 4), PAL_RGB(PAL_GREY, 6), 144 },
	[A2_WEST] = { -16, 112, PAL_RGB(PAL_BLUE, 4), PAL_RGB(PAL_GREY, 6), 128 },
};

#define T2_SOUTH PAL_RGB(PAL_SLATE, 1)
#define T2_COURT PAL_RGB(PAL_TAN, 1)
#define T2_EAST PAL_RGB(PAL_ORANGE, 2)
#define T2_NORTH PAL_RGB(PAL_GREEN, 2)
#define T2_WEST PAL_RGB(PAL_BLUE, 2)
#define T2_PILLAR PAL_RGB(PAL_RED, 1)

static const struct lvl_line arena2_lines[] = {
	{ 0, 2, A2_SOUTH, -1, T2_SOUTH },            /* 0 south arm */
	{ 2, 3, A2_SOUTH, A2_COURT, T2_COURT },
	{ 3, 1, A2_SOUTH, -1, T2_SOUTH },
	{ 1, 0, A2_SOUTH, -1, T2_SOUTH },
	{ 3, 6, A2_EAST, A2_COURT, T2_EAST },        /* 4 east arm: a step up */
	{ 6, 5, A2_EAST, -1, T2_EAST },
	{ 5, 4, A2_EAST, -1, T2_EAST },
	{ 4, 3, A2_EAST, -1, T2_EAST },
	{ 6, 7, A2_NORTH, A2_COURT, T2_COURT },      /* 8 north arm */
	{ 7, 9, A2_NORTH, -1, T2_NORTH },
	{ 9, 8, A2_NORTH, -1, T2_NORTH },
	{ 8, 6, A2_NORTH, -1, T2_NORTH },
	{ 7, 2, A2_WEST, A2_COURT, T2_WEST },        /* 12 west arm: a step down */
	{ 11, 10, A2_WEST, -1, T2_WEST },
	{ 10, 7, A2_WEST, -1, T2_WEST },
	{ 2, 11, A2_WEST, -1, T2_WEST },
	{ 12, 13, A2_COURT, -1, T2_PILLAR },         /* 16 pillar, counter-clockwise */
	{ 13, 14, A2_COURT, -1, T2_PILLAR },
	{ 14, 15, A2_COURT, -1, T2_PILLAR },
	{ 15, 12, A2_COURT, -1, T2_PILLAR },
};

static const struct lvl_thing arena2_things[] = {
	{ 512, 64, ANG90, TT_START, ALL },
	{ 448, 900, ANG270, TT_GRUNT, ALL },         /* north arm */
	{ 576, 900, ANG270, TT_SHOTGUY, ALL },
	{ 512, 980, ANG270, TT_IMP, ALL },
	{ 64, 448, 0, TT_GRUNT, ALL },               /* west arm */
	{ 64, 576, 0, TT_DEMON, ALL },
	{ 300, 576, 0, TT_GRUNT, HARD },
	{ 960, 576, ANG180, TT_GRUNT, ALL },         /* east arm */
	{ 992, 480, ANG180, TT_CACO, ALL },
	{ 800, 448, ANG180, TT_IMP, HARD },
	{ 420, 420, 0, TT_MEDI, ALL },               /* court */
	{ 600, 300, 0, TT_CLIP, ALL },               /* south arm */
	{ 512, 1000, 0, TT_AMMO, ALL },              /* north arm's end */
	{ 32, 512, 0, TT_STIM, ALL },                /* west arm's end */
	{ 400, 400, 0, TT_LAMP, ALL },
	{ 624, 624, 0, TT_LAMP, ALL },
	{ 1000, 400, 0, TT_CANDELABRA, ALL },
	{ 600, 420, 0, TT_LIGHT_WHITE, ALL },
	{ 160, 512, 0, TT_LIGHT_WARM, ALL },
};

/* ---- ARENA3 ---------------------------------------------------------- */

enum { A3_SOUTH, A3_WLOW, A3_WHIGH, A3_ELOW, A3_EHIGH, A3_NORTH };

static const int16_t arena3_vertices[][2] = {
	{ 0, 0 }, { 0, 320 }, { 384, 320 }, { 896, 320 },              /* 0 */
	{ 1280, 320 }, { 1280, 0 }, { 0, 512 }, { 384, 512 },          /* 4 */
	{ 896, 512 }, { 1280, 512 }, { 0, 704 }, { 384, 704 },         /* 8 */
	{ 896, 704 }, { 1280, 704 }, { 0, 1024 }, { 1280, 1024 },      /* 12 */
	{ 608, 128 }, { 672, 128 }, { 672, 192 }, { 608, 192 },        /* 16 pillar */
};

static const struct lvl_sector arena3_sectors[] = {
	[A3_SOUTH] = { 0, 192, PAL_RGB(PAL_BROWN, 4), PAL_RGB(PAL_GREY, 5), 176 },
	[A3_WLOW] = { 0, 160, PAL_RGB(PAL_OLIVE, 4), PAL_RGB(PAL_GREY, 6), 160 },
	[A3_WHIGH] = { 16, 160, PAL_RGB(PAL_OLIVE, 3), PAL_RGB(PAL_GREY, 6), 144 },
	[A3_ELOW] = { 0, 160, PAL_RGB(PAL_OLIVE, 4), PAL_RGB(PAL_GREY, 6), 160 },
	[A3_EHIGH] = { 16, 160, PAL_RGB(PAL_OLIVE, 3), PAL_RGB(PAL_GREY, 6), 144 },
	[A3_NORTH] = { 32, 224, PAL_RGB(PAL_PURPLE, 4), PAL_RGB(PAL_BLACKRAMP, 2), 112 },
};

#define T3_OUTER PAL_RGB(PAL_BROWN, 1)
#define T3_BLOCK PAL_RGB(PAL_GREY, 3)
#define T3_STEP PAL_RGB(PAL_SLATE, 1)
#define T3_NORTH PAL_RGB(PAL_PURPLE, 2)
#define T3_PILLAR PAL_RGB(PAL_RED, 2)

static const struct lvl_line arena3_lines[] = {
	{ 0, 1, A3_SOUTH, -1, T3_OUTER },            /* 0 south */
	{ 1, 2, A3_SOUTH, A3_WLOW, T3_OUTER },
	{ 2, 3, A3_SOUTH, -1, T3_BLOCK },
	{ 3, 4, A3_SOUTH, A3_ELOW, T3_OUTER },
	{ 4, 5, A3_SOUTH, -1, T3_OUTER },            /* 4 */
	{ 5, 0, A3_SOUTH, -1, T3_OUTER },
	{ 1, 6, A3_WLOW, -1, T3_OUTER },             /* 6 west, low half */
	{ 6, 7, A3_WLOW, A3_WHIGH, T3_STEP },
	{ 7, 2, A3_WLOW, -1, T3_BLOCK },             /* 8 */
	{ 6, 10, A3_WHIGH, -1, T3_OUTER },           /* west, high half */
	{ 10, 11, A3_WHIGH, A3_NORTH, T3_STEP },
	{ 11, 7, A3_WHIGH, -1, T3_BLOCK },
	{ 3, 8, A3_ELOW, -1, T3_BLOCK },             /* 12 east, low half */
	{ 8, 9, A3_ELOW, A3_EHIGH, T3_STEP },
	{ 9, 4, A3_ELOW, -1, T3_OUTER },
	{ 8, 12, A3_EHIGH, -1, T3_BLOCK },           /* east, high half */
	{ 12, 13, A3_EHIGH, A3_NORTH, T3_STEP },     /* 16 */
	{ 13, 9, A3_EHIGH, -1, T3_OUTER },
	{ 10, 14, A3_NORTH, -1, T3_NORTH },          /* north */
	{ 14, 15, A3_NORTH, -1, T3_NORTH },
	{ 15, 13, A3_NORTH, -1, T3_NORTH },          /* 20 */
	{ 12, 11, A3_NORTH, -1, T3_BLOCK },
	{ 16, 17, A3_SOUTH, -1, T3_PILLAR },         /* 22 pillar, counter-clockwise */
	{ 17, 18, A3_SOUTH, -1, T3_PILLAR },
	{ 18, 19, A3_SOUTH, -1, T3_PILLAR },
	{ 19, 16, A3_SOUTH, -1, T3_PILLAR },
};

static const struct lvl_thing arena3_things[] = {
	{ 160, 160, 0, TT_START, ALL },
	{ 900, 100, ANG180, TT_SHOTGUY, ALL },       /* south */
	{ 1150, 250, ANG180, TT_DEMON, ALL },
	{ 640, 40, ANG180, TT_DEMON, HARD },
	{ 192, 420, ANG270, TT_IMP, ALL },           /* west */
	{ 100, 650, ANG270, TT_GRUNT, ALL },
	{ 1200, 400, ANG180, TT_CACO, ALL },         /* east */
	{ 1200, 650, ANG270, TT_GRUNT, ALL },
	{ 1000, 600, ANG270, TT_IMP, ALL },
	{ 640, 960, ANG270, TT_CACO, ALL },          /* north */
	{ 200, 900, SE, TT_CACO, ALL },
	{ 1000, 900, SW, TT_DEMON, ALL },
	{ 640, 760, ANG270, TT_SHOTGUY, ALL },
	{ 300, 960, 0, TT_GRUNT, HARD },
	{ 1100, 960, ANG180, TT_CACO, HARD },
	{ 40, 40, 0, TT_MEDI, ALL },
	{ 1240, 980, 0, TT_MEDI, ALL },
	{ 640, 280, 0, TT_STIM, ALL },
	{ 190, 680, 0, TT_CLIP, ALL },
	{ 1090, 680, 0, TT_CLIP, ALL },
	{ 640, 1000, 0, TT_AMMO, ALL },
	{ 1200, 40, 0, TT_AMMO, ALL },
	{ 40, 984, 0, TT_TORCH, ALL },
	{ 1240, 984, 0, TT_TORCH, ALL },
	{ 320, 860, 0, TT_LIGHT_ORANGE, ALL },
	{ 960, 860, 0, TT_LIGHT_ORANGE, ALL },
	{ 640, 60, 0, TT_LIGHT_WHITE, ALL },
};

#define LVL_COUNT(a) ((uint32_t)(sizeof(a) / sizeof((a)[0])))

#define LVL(nm, a) *lv = (struct lvl){ nm, a##_vertices, a##_sectors, a##_lines, a##_things, \
	LVL_COUNT(a##_vertices), LVL_COUNT(a##_sectors), LVL_COUNT(a##_lines), \
	LVL_COUNT(a##_things) }

/* Level i, in the order the game plays them: rising difficulty. A switch
 * rather than a table of pointers, so the engine keeps no relocated data
 * (tests/check_layers.sh). Returns 0 for an unknown i. */
#define LVL_NUM 3

static int lvl_get(int i, struct lvl *lv)
{
	switch (i) {
	case 0: LVL("ARENA1", arena1); return 1;
	case 1: LVL("ARENA2", arena2); return 1;
	case 2: LVL("ARENA3", arena3); return 1;
	default: return 0;
	}
}

int map_builtin_count(void)
{
	return LVL_NUM;
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
	struct lvl lvs;
	const struct lvl *lv = &lvs;
	struct map *m;
	uint32_t k, side = 0;
	int r;

	*out = NULL;
	if (!lvl_get(i, &lvs))
		return -EINVAL;
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
		m->things[k].flags = lv->things[k].flags;
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
