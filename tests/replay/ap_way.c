/*
 * ap_way: the autopilot's way finder (contract in ap.h): the map as a grid
 * of AP_CELL-unit cells with the lines near each, where the player can
 * stand and step as the sim has the map now (manual doors counting as
 * open, locked ones once their key is held), and A* over it.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/game/g_local.h"
#include "tests/replay/ap.h"

double ap_fx(fx_t v)
{
	return v / 65536.0;
}

double ap_dist(const struct ap *a, double x, double y)
{
	double dx = x - ap_fx(a->s.pl.x), dy = y - ap_fx(a->s.pl.y);

	return sqrt(dx * dx + dy * dy);
}


/* ---- geometry ------------------------------------------------------------ */

double ap_seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
	double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy, t;

	t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	dx = ax + t * dx - px;
	dy = ay + t * dy - py;
	return sqrt(dx * dx + dy * dy);
}

void ap_cell_xy(const struct ap *a, int c, double *x, double *y)
{
	*x = a->x0 + (c % a->nx + 0.5) * AP_CELL;
	*y = a->y0 + (c / a->nx + 0.5) * AP_CELL;
}

int ap_cell_at(const struct ap *a, double x, double y)
{
	int cx = (int)floor((x - a->x0) / AP_CELL), cy = (int)floor((y - a->y0) / AP_CELL);

	if (cx < 0 || cy < 0 || cx >= a->nx || cy >= a->ny)
		return -1;
	return cy * a->nx + cx;
}

/* Doom's manual door types: the sector behind the line is the door. */
int ap_manual_door(uint16_t sp)
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
void ap_grid(struct ap *a)
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

uint32_t ap_sector(const struct ap *a, double x, double y)
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
int ap_stand(struct ap *a, int c)
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
int ap_step_ok(const struct ap *a, double x0, double y0, double x1, double y1)
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
int ap_plan(struct ap *a, double tx, double ty, double tol)
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
int ap_clear(struct ap *a, double x, double y)
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
void ap_dump(struct ap *a)
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
