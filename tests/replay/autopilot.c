/*
 * autopilot: writes the input script (.scr, input/scr.h) of a walk from a
 * Doom map's start to its exit, for the golden exit recordings of
 * tests/replay/freedoom (tests/replay/README.md).
 *
 *   autopilot --wad FILE [--wad FILE...] --map NAME [--set S.K=V...]
 *             --route ROUTE [--out SCRIPT] [--inter N] [--verbose | --trace]
 *   autopilot --wad FILE --map NAME --explore X,Y[,KEYS]
 *
 * It loads the content with the daemon's own code (app/ct.c), starts the
 * sim as the daemon does with no configuration files and the --set
 * options given (app/app.c's settings from config/cfg.c, the default
 * tables, the content's sounds), and plays it tick by tick through the
 * same path as a script (actions -> cmd_build -> sim_tick). Every change
 * of the actions it holds becomes a script line; the script then is
 * recorded by the daemon (`arcaded --wad W --map M --script S --record R`)
 * like every other golden, so the tool is not needed to regenerate them.
 *
 * The ROUTE file is the person's part: the way through the map as a list
 * of steps, one a line, '#' starting a comment:
 *   go X Y [TOL]      walk to within TOL (default 16) units of map point
 *                     (X, Y); the way is found on a grid of 8-unit cells
 *                     over the map as the sim has it now (walls, steps of
 *                     more than 24, openings lower than the player); while
 *                     there is none (a lift still moving) it waits. A
 *                     closed manual door (D1/DR; a locked one once its key
 *                     is held) counts as open: the walk stops in front of
 *                     it, presses USE and waits for it (one that does not
 *                     open counts as a wall for 900 ticks)
 *   use X Y           turn to face point (X, Y) (a switch) and press USE
 *   face X Y          turn to face point (X, Y)
 *   lift X Y SX SY    get onto the lift at (X, Y), pressing the switch at
 *                     (SX, SY) while the lift is neither reachable nor
 *                     moving
 *   dash X Y          run (forward and strafe held, the fastest move) to
 *                     (X, Y), over a gap a walk would drop into; the run-up
 *                     that lands is found by trying on copies of the sim
 *   wait N            stand N ticks
 *   ride X Y          stand until the floor under (X, Y) stops moving
 * After the last step it waits for the map's exit (the intermission page),
 * shows that page for --inter ticks (default 240) and ends the script
 * with checks that the daemon runs when it records it: mode play, phase 3
 * (the intermission), and the player's position and the score there.
 *
 * On the way it fights: an awake enemy in sight within 700 units (or any
 * within 384) is turned to and shot when the shot passes well inside its
 * body, standing (braking) or backing off from a biter; one that five
 * shots do not hurt, or that 6 s of shooting do not kill, is left alone.
 * Low on ammunition (under 40) or health (under 60), it first takes the
 * nearest pickup that gives it when the way there is short. A life lost
 * restarts the walk from the map's start with what was done kept (the
 * game's rule). No cheats: the route and the game's own settings
 * (difficulty, lives: --set) must do.
 *
 * --explore X,Y[,KEYS], for writing routes: no play; prints the way from
 * the map's start to (X, Y) with every door and tagged sector open (locked
 * doors only for the G_KEY_* bits KEYS), sector by sector, marking the
 * ones opened; AUTOPILOT_DUMP=FILE draws the last search as a PPM picture
 * (also when a step fails).
 *
 * Exit: 0 with the script written; 1 when a step could not be done (the
 * message names the route's line, the tick and the player's position);
 * 2 on bad usage or content that does not load.
 *
 * Geometry here is in doubles: this is a test tool, not the sim; only its
 * output (the script) is committed, and the sim that plays it is the
 * daemon's.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/cmd.h"
#include "app/ct.h"
#include "config/cfg.h"
#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "input/act.h"

#define AP_CELL 8.0                    /* grid cell, map units */
#define AP_RADIUS 17.0                 /* clearance from walls: the player's 16 and one */
#define AP_NEAR 32.0                   /* walls nearer than this cost more */
#define AP_MAX_LINES 4096              /* script lines */
#define AP_MAX_STEPS 256               /* route steps */
#define AP_MAX_TICKS 60000             /* per map, before giving up */
#define AP_WAIT_MAX 1800               /* ticks a step may wait for a way */
#define AP_FIGHT_MAX 360               /* ticks shooting one enemy */
#define B(a) ((uint16_t)(1u << (a)))

enum ap_op { AP_GO, AP_USE, AP_FACE, AP_WAIT, AP_RIDE, AP_LIFT, AP_DASH };

struct ap_step {
	enum ap_op op;
	double x, y, tol, sx, sy;         /* lift: the switch at (sx, sy) */
	int n, line;
};

struct ap {
	struct sim s;
	struct cmd_state cs;
	const struct map *m;
	uint16_t held;
	FILE *out;
	int verbose;
	const char *route;
	/* the grid: cells near each line (CSR), for the way finder */
	double x0, y0;
	int nx, ny;
	uint32_t *cfirst, *clines;
	/* per sector: 0, or behind a manual door line (D1/DR): 1, or the
	 * G_KEY_* bits its lock takes (a door when they are held) */
	uint8_t *door;
	uint32_t *door_ban;            /* per sector: not tried as a door before this tick */
	/* per search */
	int8_t *stand;                 /* -1 unknown, 0 no, 1 yes; 2 near a wall */
	uint32_t *g, *from;
	uint8_t *closed;
	uint32_t *heap;
	int nheap;
	int *path, npath;
	/* fighting */
	int target, target_t, shots;
	int16_t target_hp;
	uint8_t ignored[G_MAX_ENEMIES];
	uint8_t skipped[G_MAX_PICKUPS];  /* pickups gone for once */
	int detour;
	int deaths;                    /* lives lost */
	int nshots, nhits;             /* shots fired, shots that hit */
	/* the way being walked */
	int cur;
	double lastd;
	int noprog;
};

static void ap_dump(struct ap *a);
static double ap_dist(const struct ap *a, double x, double y);
static void ap_die(struct ap *a, const struct ap_step *st, const char *fmt, ...)
	__attribute__((format(printf, 3, 4), noreturn));
static void ap_die(struct ap *a, const struct ap_step *st, const char *fmt, ...)
{
	va_list ap;

	fprintf(stderr, "autopilot: %s:%d: tick %u at (%.0f, %.0f) health %d: ", a->route,
		st ? st->line : 0, a->s.tick, a->s.pl.x / 65536.0, a->s.pl.y / 65536.0,
		a->s.pl.health / FX_ONE);
	fprintf(stderr, "(shots %d, %d hit) ", a->nshots, a->nhits);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	exit(1);
}

static double ap_fx(fx_t v)
{
	return v / 65536.0;
}

/* ---- ticks and script lines --------------------------------------------- */

/* One tick with the actions in want held; changes become script lines. */
static void ap_tick(struct ap *a, uint16_t want)
{
	struct sim_cmd c;

	for (int i = 0; i < ACT_COUNT; i++) {
		uint16_t bit = B(i);
		if ((want & bit) && !(a->held & bit)) {
			if (a->out)
				fprintf(a->out, "%u press %s\n", a->s.tick, act_name(i));
			cmd_action(&a->cs, i, 1);
		} else if (!(want & bit) && (a->held & bit)) {
			if (a->out)
				fprintf(a->out, "%u release %s\n", a->s.tick, act_name(i));
			cmd_action(&a->cs, i, 0);
		}
	}
	a->held = want;
	if (a->verbose > 1 && a->s.tick % 30 == 0)
		fprintf(stderr, "autopilot: tick %u (%.0f, %.0f) z %.0f health %d ammo %u sector %u "
			"special %u\n", a->s.tick, ap_fx(a->s.pl.x), ap_fx(a->s.pl.y), ap_fx(a->s.pl.z),
			a->s.pl.health / FX_ONE, a->s.pl.ammo, a->s.pl.sector,
			a->s.w.sec[a->s.pl.sector].special);
	cmd_build(&a->cs, &c);
	sim_tick(&a->s, &c);
	if (a->s.tick > AP_MAX_TICKS)
		ap_die(a, NULL, "more than %d ticks", AP_MAX_TICKS);
}

/* ---- geometry ------------------------------------------------------------ */

static double ap_seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
	double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy, t;

	t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	dx = ax + t * dx - px;
	dy = ay + t * dy - py;
	return sqrt(dx * dx + dy * dy);
}

static void ap_cell_xy(const struct ap *a, int c, double *x, double *y)
{
	*x = a->x0 + (c % a->nx + 0.5) * AP_CELL;
	*y = a->y0 + (c / a->nx + 0.5) * AP_CELL;
}

static int ap_cell_at(const struct ap *a, double x, double y)
{
	int cx = (int)floor((x - a->x0) / AP_CELL), cy = (int)floor((y - a->y0) / AP_CELL);

	if (cx < 0 || cy < 0 || cx >= a->nx || cy >= a->ny)
		return -1;
	return cy * a->nx + cx;
}

/* Doom's manual door types: the sector behind the line is the door. */
static int ap_manual_door(uint16_t sp)
{
	return sp == 1 || sp == 31 || sp == 117 || sp == 118 || (sp >= 26 && sp <= 28) ||
	       (sp >= 32 && sp <= 34);
}

/* What the door of manual door type sp needs: 1 nothing, else the G_KEY_*
 * bits of its colour (card or skull). */
static uint8_t ap_door_keys(uint16_t sp)
{
	if (sp == 26 || sp == 32)
		return G_KEY_BLUE | G_KEY_BLUE_SKULL;
	if (sp == 27 || sp == 34)
		return G_KEY_YELLOW | G_KEY_YELLOW_SKULL;
	if (sp == 28 || sp == 33)
		return G_KEY_RED | G_KEY_RED_SKULL;
	return 1;
}

/* The lines within AP_NEAR of each cell's centre. */
static void ap_grid(struct ap *a)
{
	const struct map *m = a->m;
	double x1 = -1e9, y1 = -1e9;
	size_t n = 0, cap = 0;
	uint32_t *cnt;

	a->x0 = a->y0 = 1e9;
	for (uint32_t i = 0; i < m->num_vertices; i++) {
		double x = ap_fx(m->vertices[i].x), y = ap_fx(m->vertices[i].y);
		a->x0 = x < a->x0 ? x : a->x0;
		a->y0 = y < a->y0 ? y : a->y0;
		x1 = x > x1 ? x : x1;
		y1 = y > y1 ? y : y1;
	}
	a->x0 -= 64;
	a->y0 -= 64;
	a->nx = (int)((x1 + 64 - a->x0) / AP_CELL) + 1;
	a->ny = (int)((y1 + 64 - a->y0) / AP_CELL) + 1;
	cnt = calloc((size_t)a->nx * a->ny + 1, sizeof(*cnt));
	a->cfirst = calloc((size_t)a->nx * a->ny + 1, sizeof(*a->cfirst));
	for (int pass = 0; pass < 2; pass++) {
		for (uint32_t li = 0; li < m->num_lines; li++) {
			const struct map_line *l = &m->lines[li];
			double ax = ap_fx(m->vertices[l->v1].x), ay = ap_fx(m->vertices[l->v1].y);
			double bx = ap_fx(m->vertices[l->v2].x), by = ap_fx(m->vertices[l->v2].y);
			int cx0 = (int)((fmin(ax, bx) - AP_NEAR - a->x0) / AP_CELL) - 1;
			int cx1 = (int)((fmax(ax, bx) + AP_NEAR - a->x0) / AP_CELL) + 1;
			int cy0 = (int)((fmin(ay, by) - AP_NEAR - a->y0) / AP_CELL) - 1;
			int cy1 = (int)((fmax(ay, by) + AP_NEAR - a->y0) / AP_CELL) + 1;
			for (int cy = cy0 < 0 ? 0 : cy0; cy <= cy1 && cy < a->ny; cy++)
				for (int cx = cx0 < 0 ? 0 : cx0; cx <= cx1 && cx < a->nx; cx++) {
					int c = cy * a->nx + cx;
					double px, py;
					ap_cell_xy(a, c, &px, &py);
					if (ap_seg_dist(px, py, ax, ay, bx, by) > AP_NEAR)
						continue;
					if (pass == 0)
						n++, a->cfirst[c + 1]++;
					else
						a->clines[a->cfirst[c] + cnt[c]++] = li;
				}
		}
		if (pass == 0) {
			for (int c = 0; c < a->nx * a->ny; c++)
				a->cfirst[c + 1] += a->cfirst[c];
			cap = n;
			a->clines = malloc((cap ? cap : 1) * sizeof(*a->clines));
		}
	}
	free(cnt);
	a->door = calloc(m->num_sectors, 1);
	a->door_ban = calloc(m->num_sectors, sizeof(*a->door_ban));
	for (uint32_t li = 0; a->door && li < m->num_lines; li++) {
		const struct map_line *l = &m->lines[li];
		if (ap_manual_door(l->special) && l->side[1] != MAP_NONE)
			a->door[m->sides[l->side[1]].sector] = ap_door_keys(l->special);
	}
	n = (size_t)a->nx * a->ny;
	a->stand = malloc(n);
	a->g = malloc(n * sizeof(*a->g));
	a->from = malloc(n * sizeof(*a->from));
	a->closed = malloc(n);
	a->heap = malloc(n * 8 * sizeof(*a->heap));
	a->path = malloc(n * sizeof(*a->path));
	if (!a->door || !a->door_ban || !a->stand || !a->g || !a->from || !a->closed || !a->heap || !a->path || !a->clines) {
		fprintf(stderr, "autopilot: out of memory\n");
		exit(2);
	}
}

static uint32_t ap_sector(const struct ap *a, double x, double y)
{
	return map_point_sector(a->m, (fx_t)lrint(x * 65536), (fx_t)lrint(y * 65536));
}

/* Sector sec's floor and ceiling as the way finder takes them: a closed
 * manual door counts as open (the walk opens it on the way, ap_door). */
static void ap_heights(const struct ap *a, uint32_t sec, fx_t *fl, fx_t *cl)
{
	const struct g_sector *q = &a->s.w.sec[sec];

	*fl = q->floor_h;
	*cl = q->ceil_h;
	if (a->door[sec] && (a->door[sec] == 1 || (a->s.w.keys & a->door[sec])) &&
	    a->s.tick >= a->door_ban[sec] &&
	    *cl - *fl < SIM_PLAYER_HEIGHT + 8 * FX_ONE)
		*cl = *fl + 72 * FX_ONE;
}

/* g_opening with ap_heights. */
static int ap_opening(const struct ap *a, const struct map_line *l, fx_t *fl, fx_t *cl)
{
	fx_t f0, c0, f1, c1;

	if (l->side[1] == MAP_NONE || (l->flags & ML_BLOCKING))
		return -1;
	ap_heights(a, a->m->sides[l->side[0]].sector, &f0, &c0);
	ap_heights(a, a->m->sides[l->side[1]].sector, &f1, &c1);
	*fl = f0 > f1 ? f0 : f1;
	*cl = c0 < c1 ? c0 : c1;
	return 0;
}

/* Whether the player can stand at cell c (1, 2 when near a wall that
 * costs more), at the floor of the sector under its centre: every line
 * within AP_RADIUS lets a body of the player's height through there (a
 * step up to a higher floor is judged by the move, ap_step_ok). */
static int ap_stand(struct ap *a, int c)
{
	double px, py;
	uint32_t sec;
	fx_t z;
	int near = 0;

	if (a->stand[c] >= 0)
		return a->stand[c];
	ap_cell_xy(a, c, &px, &py);
	sec = ap_sector(a, px, py);
	{
		fx_t cz;
		ap_heights(a, sec, &z, &cz);
		if (cz - z < SIM_PLAYER_HEIGHT) {
			a->stand[c] = 0;
			return 0;
		}
	}
	for (uint32_t k = a->cfirst[c]; k < a->cfirst[c + 1]; k++) {
		const struct map_line *l = &a->m->lines[a->clines[k]];
		const struct map_vertex *v1 = &a->m->vertices[l->v1], *v2 = &a->m->vertices[l->v2];
		double d = ap_seg_dist(px, py, ap_fx(v1->x), ap_fx(v1->y), ap_fx(v2->x), ap_fx(v2->y));
		fx_t fl, cl;
		int wall = ap_opening(a, l, &fl, &cl) < 0 || cl - fl < SIM_PLAYER_HEIGHT ||
			   cl - z < SIM_PLAYER_HEIGHT;
		int ledge = !wall && fl - z > SIM_MAX_STEP;
		if (wall && d < AP_RADIUS) {
			a->stand[c] = 0;
			return 0;
		}
		if (wall || ledge)
			near = 1;
	}
	a->stand[c] = (int8_t)(near ? 2 : 1);
	return a->stand[c];
}

/* Whether a move between neighbouring points (x0, y0) -> (x1, y1) is
 * possible: the same sector, or a step up of at most 24 into an opening
 * the player fits (down any height). */
static int ap_step_ok(const struct ap *a, double x0, double y0, double x1, double y1)
{
	uint32_t s0 = ap_sector(a, x0, y0), s1 = ap_sector(a, x1, y1);
	fx_t pf, pc, qf, qc;

	if (s0 == s1)
		return 1;
	ap_heights(a, s0, &pf, &pc);
	ap_heights(a, s1, &qf, &qc);
	return qf - pf <= SIM_MAX_STEP &&
	       (pc < qc ? pc : qc) - (pf > qf ? pf : qf) >= SIM_PLAYER_HEIGHT;
}

/* Extra cost of a cell: near walls, and on floors that hurt. */
static uint32_t ap_cost(struct ap *a, int c)
{
	double px, py;
	uint32_t sec, cost = ap_stand(a, c) == 2 ? 6 : 0;
	uint16_t sp;

	ap_cell_xy(a, c, &px, &py);
	sec = ap_sector(a, px, py);
	sp = a->s.w.sec[sec].special;
	if (sp == 4 || sp == 5 || sp == 7 || sp == 16 || sp == 11 || (sp >= 32 && (sp & 0x60)))
		cost += 60;
	return cost;
}

static void ap_push(struct ap *a, uint32_t c, uint32_t f)
{
	int i = a->nheap++;

	a->heap[2 * i] = f;
	a->heap[2 * i + 1] = c;
	while (i > 0) {
		int p = (i - 1) / 2;
		if (a->heap[2 * p] <= a->heap[2 * i])
			break;
		uint32_t t0 = a->heap[2 * p], t1 = a->heap[2 * p + 1];
		a->heap[2 * p] = a->heap[2 * i];
		a->heap[2 * p + 1] = a->heap[2 * i + 1];
		a->heap[2 * i] = t0;
		a->heap[2 * i + 1] = t1;
		i = p;
	}
}

static uint32_t ap_pop(struct ap *a)
{
	uint32_t c = a->heap[1];
	int i = 0, n = --a->nheap;

	a->heap[0] = a->heap[2 * n];
	a->heap[1] = a->heap[2 * n + 1];
	for (;;) {
		int l = 2 * i + 1, r = l + 1, m = i;
		if (l < n && a->heap[2 * l] < a->heap[2 * m])
			m = l;
		if (r < n && a->heap[2 * r] < a->heap[2 * m])
			m = r;
		if (m == i)
			break;
		uint32_t t0 = a->heap[2 * m], t1 = a->heap[2 * m + 1];
		a->heap[2 * m] = a->heap[2 * i];
		a->heap[2 * m + 1] = a->heap[2 * i + 1];
		a->heap[2 * i] = t0;
		a->heap[2 * i + 1] = t1;
		i = m;
	}
	return c;
}

static uint32_t ap_h(const struct ap *a, int c, double tx, double ty)
{
	double x, y;

	ap_cell_xy(a, c, &x, &y);
	return (uint32_t)(sqrt((x - tx) * (x - tx) + (y - ty) * (y - ty)) / AP_CELL * 10);
}

/* A* from the player to within tol of (tx, ty) on the grid as the sim has
 * the map now; the way in a->path (cells). Returns whether there is one. */
static int ap_plan(struct ap *a, double tx, double ty, double tol)
{
	static const int dx[8] = { 1, -1, 0, 0, 1, 1, -1, -1 }, dy[8] = { 0, 0, 1, -1, 1, -1, 1, -1 };
	size_t n = (size_t)a->nx * a->ny;
	double sx = ap_fx(a->s.pl.x), sy = ap_fx(a->s.pl.y);
	int start = ap_cell_at(a, sx, sy), goal = -1;

	if (start < 0)
		return 0;
	memset(a->stand, -1, n);
	memset(a->closed, 0, n);
	for (size_t i = 0; i < n; i++)
		a->g[i] = UINT32_MAX;
	a->nheap = 0;
	a->g[start] = 0;
	a->from[start] = (uint32_t)start;
	ap_push(a, (uint32_t)start, ap_h(a, start, tx, ty));
	while (a->nheap > 0) {
		int c = (int)ap_pop(a), cx = c % a->nx, cy = c / a->nx;
		double px, py;
		if (a->closed[c])
			continue;
		a->closed[c] = 1;
		ap_cell_xy(a, c, &px, &py);
		if (sqrt((px - tx) * (px - tx) + (py - ty) * (py - ty)) <= tol) {
			goal = c;
			break;
		}
		for (int k = 0; k < 8; k++) {
			int nx = cx + dx[k], ny = cy + dy[k], d;
			double qx, qy;
			uint32_t g;
			if (nx < 0 || ny < 0 || nx >= a->nx || ny >= a->ny)
				continue;
			d = ny * a->nx + nx;
			if (a->closed[d] || !ap_stand(a, d))
				continue;
			/* diagonals only where both straight neighbours are free */
			if (k >= 4 && (!ap_stand(a, cy * a->nx + nx) || !ap_stand(a, ny * a->nx + cx)))
				continue;
			ap_cell_xy(a, d, &qx, &qy);
			if (!ap_step_ok(a, px, py, qx, qy))
				continue;
			g = a->g[c] + (k >= 4 ? 14 : 10) + ap_cost(a, d);
			if (g >= a->g[d])
				continue;
			a->g[d] = g;
			a->from[d] = (uint32_t)c;
			ap_push(a, (uint32_t)d, g + ap_h(a, d, tx, ty));
		}
	}
	a->npath = 0;
	if (goal < 0)
		return 0;
	for (int c = goal;; c = (int)a->from[c]) {
		a->path[a->npath++] = c;
		if (c == start)
			break;
	}
	for (int i = 0; i < a->npath / 2; i++) {
		int t = a->path[i];
		a->path[i] = a->path[a->npath - 1 - i];
		a->path[a->npath - 1 - i] = t;
	}
	a->cur = 0;
	return 1;
}

/* Whether the straight walk from the player to (x, y) stays on cells the
 * player can stand on, with possible steps. */
static int ap_clear(struct ap *a, double x, double y)
{
	double sx = ap_fx(a->s.pl.x), sy = ap_fx(a->s.pl.y);
	double d = sqrt((x - sx) * (x - sx) + (y - sy) * (y - sy));
	int n = (int)(d / 4) + 1;
	double lx = sx, ly = sy;

	for (int i = 1; i <= n; i++) {
		double px = sx + (x - sx) * i / n, py = sy + (y - sy) * i / n;
		int c = ap_cell_at(a, px, py);
		if (c < 0 || !ap_stand(a, c) || !ap_step_ok(a, lx, ly, px, py))
			return 0;
		lx = px;
		ly = py;
	}
	return 1;
}

/* With AUTOPILOT_DUMP=FILE set, the last search as a picture (PPM, north
 * up): cells reached white, cells stood on but not reached grey, the
 * player red; for writing routes. */
static void ap_dump(struct ap *a)
{
	const char *path = getenv("AUTOPILOT_DUMP");
	int pc = ap_cell_at(a, ap_fx(a->s.pl.x), ap_fx(a->s.pl.y));
	FILE *f;

	if (!path || !(f = fopen(path, "wb")))
		return;
	size_t n = (size_t)a->nx * a->ny;
	unsigned char *img = calloc(n, 3);

	if (!img) {
		fclose(f);
		return;
	}
	for (size_t c = 0; c < n; c++) {
		unsigned char *px = img + 3 * c;
		if (a->closed[c])
			px[0] = px[1] = px[2] = 150;
		else if (a->stand[c] > 0)
			px[0] = px[1] = px[2] = 50;
	}
	for (uint32_t li = 0; li < a->m->num_lines; li++) {
		const struct map_line *l = &a->m->lines[li];
		double ax = ap_fx(a->m->vertices[l->v1].x), ay = ap_fx(a->m->vertices[l->v1].y);
		double bx = ap_fx(a->m->vertices[l->v2].x), by = ap_fx(a->m->vertices[l->v2].y);
		int k = (int)(fmax(fabs(bx - ax), fabs(by - ay)) / 4) + 1;
		for (int i = 0; i <= k; i++) {
			int c = ap_cell_at(a, ax + (bx - ax) * i / k, ay + (by - ay) * i / k);
			unsigned char *px = img + 3 * (size_t)c;
			if (c < 0)
				continue;
			px[0] = l->special ? 0 : 255;
			px[1] = 255;
			px[2] = l->side[1] == MAP_NONE ? 255 : 0;
		}
	}
	if (pc >= 0)
		img[3 * pc] = 255, img[3 * pc + 1] = img[3 * pc + 2] = 0;
	fprintf(f, "P6 %d %d 255\n", a->nx, a->ny);
	for (int cy = a->ny - 1; cy >= 0; cy--)
		fwrite(img + 3 * (size_t)cy * a->nx, 3, (size_t)a->nx, f);
	fclose(f);
	free(img);
}

/* ---- steering ------------------------------------------------------------ */

static int32_t ap_diff(ang_t to, ang_t from)
{
	return (int32_t)(to - from);
}

static ang_t ap_angle_to(const struct ap *a, double x, double y)
{
	return tab_atan2((fx_t)lrint((y - ap_fx(a->s.pl.y)) * 65536),
			 (fx_t)lrint((x - ap_fx(a->s.pl.x)) * 65536));
}

/* The turn towards angle t; *aimed when within half a turn step. */
static uint16_t ap_turn(const struct ap *a, ang_t t, int *aimed)
{
	int32_t d = ap_diff(t, a->s.pl.angle), st = CMD_TURN_SPEED * 65536;

	*aimed = d < st / 2 && d > -st / 2;
	if (*aimed)
		return 0;
	return d > 0 ? B(ACT_TURN_LEFT) : B(ACT_TURN_RIGHT);
}

/* The enemy to shoot now, or -1. */
static int ap_enemy(struct ap *a)
{
	const struct sim *s = &a->s;
	int best = -1;
	double bd = 1e18;

	if (s->pl.ammo == 0)
		return -1;
	for (int i = 0; i < s->g.num_enemies; i++) {
		const struct g_enemy *e = &s->g.en[i];
		double dx = ap_fx(e->x - s->pl.x), dy = ap_fx(e->y - s->pl.y), d = dx * dx + dy * dy;
		if (e->state == G_E_DEAD || a->ignored[i] || d >= bd)
			continue;
		if (d > 700.0 * 700 || (e->state == G_E_IDLE && d > 384.0 * 384))
			continue;
		if (!g_sight(s, s->pl.x, s->pl.y, s->pl.viewz, e->x, e->y,
			     e->z + g_kinds[e->kind].eye))
			continue;
		best = i;
		bd = d;
	}
	return best;
}

/* The move keys that push against the player's momentum (a player's
 * brake: thrust the other way), none when it is nearly still. */
static uint16_t ap_brake(const struct ap *a)
{
	double mx = ap_fx(a->s.pl.momx), my = ap_fx(a->s.pl.momy);
	double ang = a->s.pl.angle * (2 * M_PI / 4294967296.0);
	double along = mx * cos(ang) + my * sin(ang), left = -mx * sin(ang) + my * cos(ang);
	uint16_t k = 0;

	if (along > 0.5)
		k |= B(ACT_BACK);
	else if (along < -0.5)
		k |= B(ACT_FORWARD);
	if (left > 0.5)
		k |= B(ACT_STRAFE_RIGHT);
	else if (left < -0.5)
		k |= B(ACT_STRAFE_LEFT);
	return k;
}

/* One tick of fighting if there is an enemy to shoot: returns 1 if it
 * took the tick. */
static int ap_fight(struct ap *a)
{
	int t = ap_enemy(a), aimed;
	uint16_t act;

	if (t < 0) {
		a->target = -1;
		return 0;
	}
	if (t != a->target || a->s.g.en[t].health != a->target_hp) {
		a->shots = 0;
		a->target_hp = a->s.g.en[t].health;
	}
	/* shots that do not hurt it (a wall or ledge in the way of the shot
	 * if not of the eyes): leave it */
	if (a->shots > 4) {
		a->ignored[t] = 1;
		a->target = -1;
		return 0;
	}
	if (t != a->target) {
		a->target = t;
		a->target_t = 0;
		if (a->verbose)
			fprintf(stderr, "autopilot: tick %u (%.0f, %.0f) health %d: shooting enemy %d "
				"(%s at %.0f, %.0f)\n", a->s.tick, ap_fx(a->s.pl.x), ap_fx(a->s.pl.y),
				a->s.pl.health / FX_ONE, t, g_kinds[a->s.g.en[t].kind].name,
				ap_fx(a->s.g.en[t].x), ap_fx(a->s.g.en[t].y));
	}
	if (++a->target_t > AP_FIGHT_MAX) {
		a->ignored[t] = 1;
		a->target = -1;
		return 0;
	}
	act = ap_turn(a, ap_angle_to(a, ap_fx(a->s.g.en[t].x), ap_fx(a->s.g.en[t].y)), &aimed);
	/* a biter near: back off while shooting (the player is the faster);
	 * else stand, braking, so as not to glide off a ledge */
	if (g_kinds[a->s.g.en[t].kind].range <= 64 * FX_ONE &&
	    ap_dist(a, ap_fx(a->s.g.en[t].x), ap_fx(a->s.g.en[t].y)) < 160)
		act |= B(ACT_BACK);
	else
		act |= ap_brake(a);
	/* FIRE is a level: let it go between shots so each is a new press */
	{
		/* fire only when the shot passes well inside its body */
		const struct g_enemy *e = &a->s.g.en[t];
		double d = ap_dist(a, ap_fx(e->x), ap_fx(e->y));
		double err = ap_diff(ap_angle_to(a, ap_fx(e->x), ap_fx(e->y)), a->s.pl.angle) *
			     (2 * M_PI / 4294967296.0);
		aimed = fabs(d * sin(err)) < ap_fx(g_kinds[e->kind].radius) * 0.6;
	}
	if (aimed && !(a->held & B(ACT_FIRE)) && a->s.pl.refire == 0) {
		act |= B(ACT_FIRE);
		a->shots++;
	}
	ap_tick(a, act);
	if (act & B(ACT_FIRE)) {
		a->nshots++;
		a->nhits += a->s.g.shot == G_SHOT_ENEMY;
	}
	return 1;
}

/* A tick of standing (fighting when there is something to shoot); dead
 * players wait for the respawn. */
static void ap_stand_tick(struct ap *a)
{
	if (a->s.g.phase == G_PH_PLAY && ap_fight(a))
		return;
	ap_tick(a, 0);
}

/* ---- steps --------------------------------------------------------------- */

static void ap_face(struct ap *a, double x, double y);
static void ap_stop(struct ap *a);

static double ap_dist(const struct ap *a, double x, double y)
{
	double dx = x - ap_fx(a->s.pl.x), dy = y - ap_fx(a->s.pl.y);

	return sqrt(dx * dx + dy * dy);
}

/* The nearest point (*x, *y) of the nearest manual door line of door
 * sector sec; returns its distance from the player. */
static double ap_door_line(const struct ap *a, uint32_t sec, double *x, double *y)
{
	uint32_t n;
	const uint32_t *ls = map_sector_lines(a->m, sec, &n);
	double px = ap_fx(a->s.pl.x), py = ap_fx(a->s.pl.y), best = 1e18;

	for (uint32_t i = 0; i < n; i++) {
		const struct map_line *l = &a->m->lines[ls[i]];
		const struct map_vertex *v1 = &a->m->vertices[l->v1], *v2 = &a->m->vertices[l->v2];
		double ax = ap_fx(v1->x), ay = ap_fx(v1->y), bx = ap_fx(v2->x), by = ap_fx(v2->y);
		double dx = bx - ax, dy = by - ay, t, d;
		if (!ap_manual_door(l->special) || l->side[1] == MAP_NONE ||
		    a->m->sides[l->side[1]].sector != sec)
			continue;
		t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
		/* a little inside the line's ends, so USE meets it */
		t = t < 0.1 ? 0.1 : t > 0.9 ? 0.9 : t;
		d = ap_seg_dist(px, py, ax, ay, bx, by);
		if (d < best) {
			best = d;
			*x = ax + t * dx;
			*y = ay + t * dy;
		}
	}
	return best;
}

/* A closed manual door on the next stretch of the way: when the player is
 * near it, stop, face it, press USE and wait for it to open. Returns 1 if
 * it took ticks. */
static int ap_door(struct ap *a)
{
	for (int k = a->cur; k < a->npath && k < a->cur + 10; k++) {
		double px, py, dx = 0, dy = 0;
		uint32_t sec;
		ap_cell_xy(a, a->path[k], &px, &py);
		sec = ap_sector(a, px, py);
		if (!a->door[sec] || a->s.tick < a->door_ban[sec] ||
		    a->s.w.sec[sec].ceil_h - a->s.w.sec[sec].floor_h >= SIM_PLAYER_HEIGHT + 4 * FX_ONE)
			continue;
		if (ap_door_line(a, sec, &dx, &dy) > 64)
			return 0;
		ap_stop(a);
		ap_face(a, dx, dy);
		if (a->verbose)
			fprintf(stderr, "autopilot: tick %u (%.0f, %.0f): opening the door of sector %u\n",
				a->s.tick, ap_fx(a->s.pl.x), ap_fx(a->s.pl.y), sec);
		ap_tick(a, B(ACT_USE));
		ap_tick(a, 0);
		for (int i = 0; i < 120; i++) {
			if (a->s.w.sec[sec].ceil_h - a->s.w.sec[sec].floor_h >=
			    SIM_PLAYER_HEIGHT + 8 * FX_ONE)
				return 1;
			ap_stand_tick(a);
		}
		/* a door that opens from its other side only (or whose key
		 * is missing): a wall from now on; find another way */
		if (a->verbose)
			fprintf(stderr, "autopilot: tick %u: the door of sector %u does not open "
				"from here\n", a->s.tick, sec);
		a->door_ban[sec] = a->s.tick + 900;
		a->npath = 0;
		return 1;
	}
	return 0;
}

static int ap_go(struct ap *a, const struct ap_step *st);

/* Low on ammo or health: the nearest pickup that gives it, if the way
 * there is short, is taken first. Returns 1 if it went for one. */
static int ap_detour(struct ap *a)
{
	const struct sim *s = &a->s;
	int want_ammo = s->pl.ammo < 40, want_health = s->pl.health < 60 * FX_ONE;
	int best = -1;
	double bd = 640;

	if (!want_ammo && !want_health)
		return 0;
	for (int i = 0; i < s->g.num_pickups; i++) {
		const struct g_pickup *k = &s->g.pk[i];
		double d = ap_dist(a, ap_fx(k->x), ap_fx(k->y));
		if (k->taken || d >= bd || a->skipped[i] ||
		    !((want_ammo && k->kind == G_P_AMMO) || (want_health && k->kind == G_P_HEALTH)))
			continue;
		best = i;
		bd = d;
	}
	if (best < 0)
		return 0;
	a->skipped[best] = 1;            /* once: taken or not */
	if (!ap_plan(a, ap_fx(s->g.pk[best].x), ap_fx(s->g.pk[best].y), 8) ||
	    a->g[a->path[a->npath - 1]] > 1100) {
		a->npath = 0;
		return 0;
	}
	{
		struct ap_step go = { .op = AP_GO, .x = ap_fx(s->g.pk[best].x),
				      .y = ap_fx(s->g.pk[best].y), .tol = 8, .n = 300 };
		if (a->verbose)
			fprintf(stderr, "autopilot: tick %u (%.0f, %.0f): for the %s at (%.0f, %.0f)\n",
				s->tick, ap_fx(s->pl.x), ap_fx(s->pl.y),
				s->g.pk[best].kind == G_P_AMMO ? "ammo" : "health", go.x, go.y);
		a->detour = 1;
		ap_go(a, &go);
		a->detour = 0;
	}
	a->npath = 0;
	return 1;
}

static int ap_go(struct ap *a, const struct ap_step *st)
{
	int waited = 0, since_plan = 0, stuck = 0, stuck_n = 0;
	double best = 1e18;

	a->npath = 0;
	while (ap_dist(a, st->x, st->y) > st->tol) {
		double px, py;
		uint16_t act = 0;
		int aimed, j;
		if (a->s.g.phase == G_PH_DEAD) {
			/* a life lost: the game goes on from the map's start with
			 * what was done kept (keys, doors, the dead): walk on */
			if (a->verbose)
				fprintf(stderr, "autopilot: tick %u (%.0f, %.0f): died, %d lives left\n",
					a->s.tick, ap_fx(a->s.pl.x), ap_fx(a->s.pl.y), a->s.g.lives - 1);
			while (a->s.mode == SIM_PLAY && a->s.g.phase == G_PH_DEAD)
				ap_tick(a, 0);
			if (a->s.mode != SIM_PLAY)
				ap_die(a, st, "game over");
			a->deaths++;
			a->npath = 0;
			if (a->detour)
				return -1;       /* the pickup is far from the start now */
			memset(a->ignored, 0, sizeof(a->ignored));
			best = 1e18;
			continue;
		}
		if (a->s.g.phase != G_PH_PLAY) {
			if (a->s.g.phase == G_PH_INTER)
				return 0;
			ap_tick(a, 0);
			a->npath = 0;
			continue;
		}
		if (ap_fight(a)) {
			a->npath = 0;
			continue;
		}
		if (a->npath == 0 || since_plan > 120) {
			if (!a->detour && ap_detour(a))
				continue;
			since_plan = 0;
			if (!ap_plan(a, st->x, st->y, fmax(st->tol, 12))) {
				/* a door opening, a lift moving: look again in a while */
				waited += 15;
				if (waited > (st->n ? st->n : AP_WAIT_MAX)) {
					if (st->op == AP_LIFT || a->detour)
						return -1;
					ap_dump(a);
					ap_die(a, st, "no way to (%.0f, %.0f)", st->x, st->y);
				}
				for (int i = 0; i < 15; i++)
					ap_stand_tick(a);
				continue;
			}
		}
		since_plan++;
		if (ap_door(a))
			continue;
		/* the furthest point of the way that can be walked to straight */
		for (j = a->npath - 1; j > a->cur; j--) {
			ap_cell_xy(a, a->path[j], &px, &py);
			if (j - a->cur <= 64 && ap_clear(a, px, py))
				break;
		}
		/* at least the next cell of the way not yet reached */
		if (j == a->cur && j + 1 < a->npath) {
			ap_cell_xy(a, a->path[j], &px, &py);
			if (ap_dist(a, px, py) < AP_CELL)
				j++;
		}
		a->cur = j;
		ap_cell_xy(a, a->path[j], &px, &py);
		if (j == a->npath - 1) {
			px = st->x;
			py = st->y;
		}
		act = ap_turn(a, ap_angle_to(a, px, py), &aimed);
		{
			int32_t d = ap_diff(ap_angle_to(a, px, py), a->s.pl.angle);
			if (d < 0)
				d = -d;
			double v = sqrt(ap_fx(a->s.pl.momx) * ap_fx(a->s.pl.momx) +
					ap_fx(a->s.pl.momy) * ap_fx(a->s.pl.momy));
			/* forward when roughly facing it (20 degrees), but
			 * coasting into the end of the way: the player glides
			 * about ten ticks' worth of its speed */
			if (d < 0x0e38e38e && !(j == a->npath - 1 &&
						ap_dist(a, st->x, st->y) < 10 * v + st->tol / 2))
				act |= B(ACT_FORWARD);
		}
		ap_tick(a, act);
		/* stuck: no nearer in 90 ticks: find the way again */
		if (ap_dist(a, st->x, st->y) < best - 4) {
			best = ap_dist(a, st->x, st->y);
			stuck = 0;
		} else if (++stuck > 90) {
			stuck = 0;
			best = 1e18;
			a->npath = 0;
			if (++stuck_n > 20) {
				ap_dump(a);
				ap_die(a, st, "stuck on the way to (%.0f, %.0f)", st->x, st->y);
			}
			if (a->verbose)
				fprintf(stderr, "autopilot: tick %u (%.0f, %.0f): stuck, backing off\n",
					a->s.tick, ap_fx(a->s.pl.x), ap_fx(a->s.pl.y));
			for (int i = 0; i < 12; i++)
				ap_tick(a, B(ACT_BACK) | B(stuck_n % 2 ? ACT_STRAFE_LEFT : ACT_STRAFE_RIGHT));
		}
	}
	return 0;
}

/* Stands until the momentum is spent (at most half a second). */
static void ap_stop(struct ap *a)
{
	for (int i = 0; i < 30 && (fx_abs(a->s.pl.momx) > FX_ONE / 4 || fx_abs(a->s.pl.momy) > FX_ONE / 4);
	     i++)
		ap_tick(a, 0);
}

/* Walks to within 40 units of (x, y) (a switch), if not there. */
static void ap_go_near(struct ap *a, double x, double y)
{
	struct ap_step go = { .op = AP_GO, .x = x, .y = y, .tol = 40 };

	if (ap_dist(a, x, y) > 48) {
		ap_go(a, &go);
		ap_stop(a);
	}
}

static void ap_face_at(struct ap *a, ang_t t)
{
	int aimed;

	for (int i = 0; i < 400; i++) {
		uint16_t act = ap_turn(a, t, &aimed);
		if (aimed)
			return;
		ap_tick(a, act);
	}
}

static void ap_face(struct ap *a, double x, double y)
{
	ap_face_at(a, ap_angle_to(a, x, y));
}

/* One try of a dash: w ticks backing off, then facing 45 degrees (plus
 * da 64ths of a right angle... da * 2.8 degrees) left of (x, y) and running there with forward and strafe right held (the
 * fastest a player moves: about 10 units a tick). Returns whether the
 * player stands at the height of (x, y)'s floor, near it, once stopped. */
static int ap_dash_try(struct ap *a, const struct ap_step *st, int w, int da)
{
	uint32_t sec = ap_sector(a, st->x, st->y);

	ap_face(a, st->x, st->y);
	for (int i = 0; i < w; i++)
		ap_tick(a, B(ACT_BACK));
	ap_stop(a);
	ap_face_at(a, ap_angle_to(a, st->x, st->y) + 0x20000000u + (uint32_t)da * 0x02000000u);
	for (int i = 0; i < 90 && ap_dist(a, st->x, st->y) > 16; i++) {
		ap_tick(a, B(ACT_FORWARD) | B(ACT_STRAFE_RIGHT));
		if (a->verbose > 1)
			fprintf(stderr, "autopilot: dash %d: tick %u (%.1f, %.1f) z %.0f\n", w, a->s.tick,
				ap_fx(a->s.pl.x), ap_fx(a->s.pl.y), ap_fx(a->s.pl.z));
		if (a->s.pl.z < a->s.w.sec[sec].floor_h)
			return 0;
	}
	ap_stop(a);
	return a->s.pl.z == a->s.w.sec[sec].floor_h && ap_dist(a, st->x, st->y) <= 96;
}

/* A run over a gap a walk falls into (a floor under the centre only, in
 * this game, where Doom takes the highest floor under the body): the first
 * run-up (0..40 ticks backed off, five headings) that lands, found on copies of the game,
 * then run for real. */
static void ap_dash(struct ap *a, const struct ap_step *st)
{
	static struct sim keep;
	static const int da[5] = { 0, 1, -1, 2, -2 };  /* 2.8 degrees each */
	struct cmd_state cs = a->cs;
	uint16_t held = a->held;
	FILE *out = a->out;
	int w;

	keep = a->s;
	a->out = NULL;
	for (w = 0; w <= 40 * 5; w++) {
		int ok = ap_dash_try(a, st, w / 5, da[w % 5]);
		a->s = keep;
		a->cs = cs;
		a->held = held;
		if (ok)
			break;
	}
	a->out = out;
	if (w > 40 * 5)
		ap_die(a, st, "no run-up lands at (%.0f, %.0f)", st->x, st->y);
	if (!ap_dash_try(a, st, w / 5, da[w % 5]))
		ap_die(a, st, "the dash to (%.0f, %.0f) did not land twice", st->x, st->y);
}

static void ap_do(struct ap *a, const struct ap_step *st)
{
	if (a->verbose)
		fprintf(stderr, "autopilot: tick %u (%.0f, %.0f): step of line %d\n", a->s.tick,
			ap_fx(a->s.pl.x), ap_fx(a->s.pl.y), st->line);
	switch (st->op) {
	case AP_GO:
		ap_go(a, st);
		ap_stop(a);
		break;
	case AP_FACE:
		ap_face(a, st->x, st->y);
		break;
	case AP_USE:
		ap_face(a, st->x, st->y);
		ap_tick(a, B(ACT_USE));
		ap_tick(a, 0);
		break;
	case AP_WAIT:
		for (int i = 0; i < st->n; i++)
			ap_stand_tick(a);
		break;
	case AP_LIFT: {
		/* onto the lift at (x, y), calling it with the switch at (sx,
		 * sy) while it is neither reachable nor moving */
		uint32_t sec = ap_sector(a, st->x, st->y);
		struct ap_step go = *st;
		int i;
		go.tol = 16;
		go.n = 15;
		for (i = 0; i < 20; i++) {
			int moving = 0;
			if (ap_go(a, &go) == 0)
				break;
			for (int k = 0; k < a->s.w.num_movers; k++)
				moving |= a->s.w.mv[k].sector == sec;
			if (!moving) {
				ap_go_near(a, st->sx, st->sy);
				ap_face(a, st->sx, st->sy);
				ap_tick(a, B(ACT_USE));
				ap_tick(a, 0);
			}
		}
		if (i == 20)
			ap_die(a, st, "the lift at (%.0f, %.0f) does not come", st->x, st->y);
		ap_stop(a);
		break;
	}
	case AP_DASH:
		ap_dash(a, st);
		break;
	case AP_RIDE: {
		uint32_t sec = ap_sector(a, st->x, st->y);
		fx_t last = a->s.w.sec[sec].floor_h;
		int still = 0;
		for (int i = 0; i < AP_WAIT_MAX && still < 8; i++) {
			ap_stand_tick(a);
			still = a->s.w.sec[sec].floor_h == last ? still + 1 : 0;
			last = a->s.w.sec[sec].floor_h;
		}
		break;
	}
	}
}

static int ap_read_route(const char *path, struct ap_step *st, int max)
{
	char line[256];
	int n = 0, ln = 0;
	FILE *f = fopen(path, "r");

	if (!f) {
		fprintf(stderr, "autopilot: %s: %s\n", path, strerror(errno));
		return -1;
	}
	while (fgets(line, sizeof(line), f)) {
		char op[16], *h = strchr(line, '#');
		double x = 0, y = 0, t = 16, sy = 0;
		int k;
		ln++;
		if (h)
			*h = '\0';
		k = sscanf(line, "%15s %lf %lf %lf %lf", op, &x, &y, &t, &sy);
		if (k <= 0)
			continue;
		if (n == max)
			goto bad;
		memset(&st[n], 0, sizeof(st[n]));
		st[n].line = ln;
		st[n].x = x;
		st[n].y = y;
		st[n].tol = t;
		if (strcmp(op, "go") == 0 && k >= 3)
			st[n].op = AP_GO;
		else if (strcmp(op, "use") == 0 && k == 3)
			st[n].op = AP_USE;
		else if (strcmp(op, "dash") == 0 && k == 3)
			st[n].op = AP_DASH;
		else if (strcmp(op, "face") == 0 && k == 3)
			st[n].op = AP_FACE;
		else if (strcmp(op, "lift") == 0 && k == 5)
			st[n].op = AP_LIFT, st[n].sx = t, st[n].sy = sy;
		else if (strcmp(op, "ride") == 0 && k == 3)
			st[n].op = AP_RIDE;
		else if (strcmp(op, "wait") == 0 && k == 2 && x >= 1)
			st[n].op = AP_WAIT, st[n].n = (int)x;
		else
			goto bad;
		n++;
	}
	fclose(f);
	return n;
bad:
	fprintf(stderr, "autopilot: %s:%d: not a step (go X Y [TOL], use X Y, face X Y, "
		"lift X Y SX SY, dash X Y, ride X Y, wait N)\n", path, ln);
	fclose(f);
	return -1;
}

static void ap_cfg_err(void *user, const char *file, int line, const char *msg)
{
	(void)user;
	(void)line;
	fprintf(stderr, "autopilot: %s: %s\n", file, msg);
}

static int ap_usage(void)
{
	fprintf(stderr, "usage: autopilot --wad FILE [--wad FILE...] --map NAME [--set S.K=V...] "
			"--route ROUTE [--out SCRIPT] [--inter N] [--verbose | --trace]\n"
			"       autopilot --wad FILE --map NAME --explore X,Y[,KEYS]\n");
	return 2;
}

int main(int argc, char **argv)
{
	static struct ap a;
	static struct ap_step steps[AP_MAX_STEPS];
	struct ct_spec spec = { 0 };
	struct sim_settings set = { 0 };
	struct cfg c;
	struct ct ct;
	char err[512];
	const char *outp = NULL;
	int nsteps, inter = 240, explore = 0;
	double ex_x = 0, ex_y = 0;
	unsigned ex_keys = 0;

	cfg_defaults(&c);
	for (int i = 1; i < argc; i++) {
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;
		if (strcmp(argv[i], "--verbose") == 0 || strcmp(argv[i], "--trace") == 0) {
			a.verbose = argv[i][2] == 'v' ? 1 : 2;
			continue;
		}
		if (!v)
			return ap_usage();
		if (strcmp(argv[i], "--wad") == 0 && spec.nwads < CT_MAX_WADS)
			spec.wads[spec.nwads++] = v;
		else if (strcmp(argv[i], "--map") == 0)
			spec.map = v;
		else if (strcmp(argv[i], "--set") == 0) {
			if (cfg_set(&c, v, ap_cfg_err, NULL) < 0)
				return 2;
		} else if (strcmp(argv[i], "--route") == 0)
			a.route = v;
		else if (strcmp(argv[i], "--out") == 0)
			outp = v;
		else if (strcmp(argv[i], "--explore") == 0) {
			explore = 1;
			if (sscanf(v, "%lf,%lf,%u", &ex_x, &ex_y, &ex_keys) < 2)
				return ap_usage();
		} else if (strcmp(argv[i], "--inter") == 0)
			inter = atoi(v);
		else
			return ap_usage();
		i++;
	}
	if (!spec.nwads || !spec.map || (!a.route && !explore))
		return ap_usage();
	nsteps = explore ? 0 : ap_read_route(a.route, steps, AP_MAX_STEPS);
	if (nsteps < 0)
		return 2;
	if (ct_load(&ct, &spec, err, sizeof(err)) < 0) {
		fprintf(stderr, "autopilot: %s\n", err);
		return 2;
	}
	/* the daemon's settings (app/app.c setup_game) and start (keep_start
	 * with nothing kept: the default tables; then the content's sounds) */
	set.coins_per_credit = (uint8_t)c.game.coins_per_credit;
	set.freeplay = (uint8_t)c.game.freeplay;
	set.start_in_play = (uint8_t)c.game.start_in_play;
	set.difficulty = (uint8_t)c.game.difficulty;
	set.lives = (uint8_t)c.game.lives;
	set.volume = (uint8_t)c.game.volume;
	set.attract_sound = (uint8_t)c.game.attract_sound;
	sim_init_stages(&a.s, (const struct map *const *)ct.maps, ct.nmaps, &set, NULL, NULL);
	sim_set_sounds(&a.s, ct.sounds);
	cmd_reset(&a.cs);
	a.m = ct.map;
	a.target = -1;
	a.out = outp ? fopen(outp, "w") : stdout;
	if (explore) {
		/* for writing routes: every door open, every lift down; the
		 * ways from the player start (or X,Y) as AUTOPILOT_DUMP shows */
		ap_grid(&a);
		uint8_t *opened = calloc(a.m->num_sectors, 1);
		uint32_t last = UINT32_MAX;
		for (uint32_t i = 0; opened && i < a.m->num_lines; i++) {
			const struct map_line *l = &a.m->lines[i];
			if (!l->special || l->side[1] == MAP_NONE)
				continue;
			for (int k = 0; k < 2; k++) {
				uint32_t sec = a.m->sides[l->side[k]].sector;
				/* locked doors stay shut: their keys are to be found */
				if (a.door[sec] > 1 && !(ex_keys & a.door[sec]))
					continue;
				struct g_sector *q = &a.s.w.sec[sec];
				if (q->ceil_h - q->floor_h < SIM_PLAYER_HEIGHT)
					q->ceil_h = q->floor_h + 128 * FX_ONE, opened[sec] = 1;
			}
		}
		for (uint32_t i = 0; opened && i < a.m->num_sectors; i++) {
			struct g_sector *q = &a.s.w.sec[i];
			if (a.m->sectors[i].tag && q->ceil_h - q->floor_h < SIM_PLAYER_HEIGHT)
				q->ceil_h = q->floor_h + 128 * FX_ONE, opened[i] = 2;
		}
		if (!ap_plan(&a, ex_x, ex_y, 16))
			fprintf(stderr, "autopilot: no way from the start to (%.0f, %.0f)\n", ex_x, ex_y);
		for (int i = 0; opened && i < a.npath; i++) {
			double px, py;
			uint32_t sec;
			ap_cell_xy(&a, a.path[i], &px, &py);
			sec = ap_sector(&a, px, py);
			if (sec != last)
				printf("(%.0f, %.0f) sector %u floor %.0f%s\n", px, py, sec,
				       ap_fx(a.s.w.sec[sec].floor_h),
				       opened[sec] == 1 ? " door (opened)" : opened[sec] == 2 ?
				       " tagged (opened)" : "");
			last = sec;
		}
		free(opened);
		ap_dump(&a);
		return 0;
	}
	if (!a.out) {
		fprintf(stderr, "autopilot: %s: %s\n", outp, strerror(errno));
		return 2;
	}
	ap_grid(&a);
	fprintf(a.out, "# Written by tests/replay/autopilot from %s (see it and README.md):\n",
		a.route);
	fprintf(a.out, "# %s %s, from the start to the exit and the intermission page.\n",
		ct.what, spec.map);
	/* coin-up and start, as the other scripts */
	while (a.s.tick < 10)
		ap_tick(&a, 0);
	ap_tick(&a, B(ACT_COIN));
	while (a.s.tick < 20)
		ap_tick(&a, 0);
	ap_tick(&a, B(ACT_START));
	ap_tick(&a, 0);
	if (a.s.mode != SIM_PLAY)
		ap_die(&a, NULL, "the game did not start");
	for (int i = 0; i < nsteps && a.s.g.phase != G_PH_INTER; i++)
		ap_do(&a, &steps[i]);
	for (int i = 0; i < 600 && a.s.g.phase != G_PH_INTER; i++)
		ap_stand_tick(&a);
	if (a.s.g.phase != G_PH_INTER)
		ap_die(&a, NULL, "the route ended without the map's exit");
	fprintf(stderr, "autopilot: %s: exit taken on tick %u (%u ticks into the map), health %d, "
		"ammo %u, kills %u, score %u, lives lost %d, shots %d (%d hit)\n", spec.map,
		a.s.tick - 1, a.s.w.exit_t, a.s.pl.health / FX_ONE, a.s.pl.ammo, a.s.g.kills, a.s.g.score,
		a.deaths, a.nshots, a.nhits);
	fprintf(a.out, "%u expect phase == %d\n", a.s.tick - 1, G_PH_INTER);
	for (int i = 0; i < inter; i++)
		ap_tick(&a, 0);
	fprintf(a.out, "%u expect mode == play\n", a.s.tick - 1);
	fprintf(a.out, "%u expect phase == %d\n", a.s.tick - 1, G_PH_INTER);
	fprintf(a.out, "%u expect x == %.6f\n", a.s.tick - 1, ap_fx(a.s.pl.x));
	fprintf(a.out, "%u expect y == %.6f\n", a.s.tick - 1, ap_fx(a.s.pl.y));
	fprintf(a.out, "%u expect score == %u\n", a.s.tick - 1, a.s.g.score);
	fprintf(a.out, "%u end\n", a.s.tick - 1);
	if (outp && fclose(a.out) != 0) {
		fprintf(stderr, "autopilot: %s: %s\n", outp, strerror(errno));
		return 2;
	}
	ct_free(&ct);
	return 0;
}
