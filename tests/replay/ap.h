/*
 * ap: the autopilot's shared parts (tests/replay/autopilot.c, the play;
 * tests/replay/ap_way.c, the way finder). A test tool, not the daemon.
 */
#ifndef ARCADED_TESTS_REPLAY_AP_H
#define ARCADED_TESTS_REPLAY_AP_H

#include <stdint.h>
#include <stdio.h>

#include "app/cmd.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"

#define AP_CELL 8.0                    /* grid cell, map units */
#define AP_RADIUS 17.0                 /* clearance from walls: the player's 16 and one */
#define AP_NEAR 32.0                   /* walls nearer than this cost more */
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
	/* the first tick the stage showed cleared (0: not yet), and the
	 * kills and the weapon held then (--demo's checks) */
	uint32_t clear_t, clear_kills;
	int demo;                      /* --demo: a clear ends the route */
	int to_clear;                  /* a stage without an exit (built-in
					* 1..3): its clear ends the route */
	uint8_t clear_weapon;
	/* the way being walked */
	int cur;
	double lastd;
	int noprog;
};

/* ---- ap_way.c: the map as a grid, and the way over it ---------------- */

/* 16.16 to map units. */
double ap_fx(fx_t v);
/* Distance from the player to (x, y). */
double ap_dist(const struct ap *a, double x, double y);
/* Distance from (px, py) to the segment (ax, ay)-(bx, by). */
double ap_seg_dist(double px, double py, double ax, double ay, double bx, double by);
/* The centre of cell c; the cell at (x, y), or -1 off the grid. */
void ap_cell_xy(const struct ap *a, int c, double *x, double *y);
int ap_cell_at(const struct ap *a, double x, double y);
/* Whether line special sp is one of Doom's manual doors (D1/DR). */
int ap_manual_door(uint16_t sp);
/* Builds the grid of a->m (the lines near each cell, the door sectors and
 * the search arrays); exits the program with 2 when out of memory. */
void ap_grid(struct ap *a);
/* The sector at (x, y). */
uint32_t ap_sector(const struct ap *a, double x, double y);
/* Whether the player can stand at cell c: 0 no, 1 yes, 2 yes but near a wall. */
int ap_stand(struct ap *a, int c);
/* Whether the move between neighbouring points is a step the player makes. */
int ap_step_ok(const struct ap *a, double x0, double y0, double x1, double y1);
/* The way from the player to within tol of (tx, ty) into a->path (cells,
 * a->npath of them, a->cur 0); returns whether there is one. */
int ap_plan(struct ap *a, double tx, double ty, double tol);
/* Whether the straight walk from the player to (x, y) is clear. */
int ap_clear(struct ap *a, double x, double y);
/* With AUTOPILOT_DUMP=FILE, the last search as a PPM picture. */
void ap_dump(struct ap *a);

/* ---- autopilot.c: ticks and failures --------------------------------- */

/* One tick with the actions in want held (a bit per enum act); the
 * changes become script lines (when a->out is set). */
void ap_tick(struct ap *a, uint16_t want);
/* Says what could not be done, where and when, and exits with 1. */
void ap_die(struct ap *a, const struct ap_step *st, const char *fmt, ...)
	__attribute__((format(printf, 3, 4), noreturn));

/* ---- ap_walk.c: walking and fighting ----------------------------------- */

/* A tick standing (shooting when there is an enemy to shoot). */
void ap_stand_tick(struct ap *a);
/* The go step (autopilot.c's head comment): 0 there, -1 no way in time
 * (lift steps and pickups only; else it dies). */
int ap_go(struct ap *a, const struct ap_step *st);
/* Stands until the momentum is spent (at most half a second). */
void ap_stop(struct ap *a);
/* Turns to face angle t, or point (x, y). */
void ap_face_at(struct ap *a, ang_t t);
void ap_face(struct ap *a, double x, double y);
/* Walks to within 40 units of (x, y) (a switch), if not there. */
void ap_go_near(struct ap *a, double x, double y);
/* The dash step: a run over a gap (the run-up found on copies of the sim). */
void ap_dash(struct ap *a, const struct ap_step *st);

#endif
