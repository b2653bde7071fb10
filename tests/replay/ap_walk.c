/*
 * ap_walk: the autopilot's walking and fighting (contract in ap.h): the
 * steering towards a point, the enemy to shoot, the steps of a route that
 * move (go, with the doors and pickups on the way; lift; dash).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "app/cmd.h"
#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "input/act.h"
#include "tests/replay/ap.h"

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
			     e->z + g_kinds[e->kind].eye) ||
		    !g_shot_reaches(s, i))
			continue;              /* seen, but a shot cannot reach it */
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
void ap_stand_tick(struct ap *a)
{
	if (a->s.g.phase == G_PH_PLAY && ap_fight(a))
		return;
	ap_tick(a, 0);
}

/* ---- steps --------------------------------------------------------------- */

void ap_face(struct ap *a, double x, double y);
void ap_stop(struct ap *a);

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

int ap_go(struct ap *a, const struct ap_step *st);

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
		    !((want_ammo && (k->kind == G_P_AMMO || k->kind == G_P_WEAPON)) ||
		      (want_health && k->kind == G_P_HEALTH)))
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
				s->g.pk[best].kind == G_P_HEALTH ? "health" : "ammo", go.x, go.y);
		a->detour = 1;
		ap_go(a, &go);
		a->detour = 0;
	}
	a->npath = 0;
	return 1;
}

int ap_go(struct ap *a, const struct ap_step *st)
{
	int waited = 0, since_plan = 0, stuck = 0, stuck_n = 0;
	double best = 1e18;

	a->npath = 0;
	/* --demo, or a stage without an exit: a cleared stage ends the walk
	 * (the next one is not the grid's map) */
	while (ap_dist(a, st->x, st->y) > st->tol && !((a->demo || a->to_clear) && a->clear_t)) {
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
void ap_stop(struct ap *a)
{
	for (int i = 0; i < 30 && (fx_abs(a->s.pl.momx) > FX_ONE / 4 || fx_abs(a->s.pl.momy) > FX_ONE / 4);
	     i++)
		ap_tick(a, 0);
}

/* Walks to within 40 units of (x, y) (a switch), if not there. */
void ap_go_near(struct ap *a, double x, double y)
{
	struct ap_step go = { .op = AP_GO, .x = x, .y = y, .tol = 40 };

	if (ap_dist(a, x, y) > 48) {
		ap_go(a, &go);
		ap_stop(a);
	}
}

void ap_face_at(struct ap *a, ang_t t)
{
	int aimed;

	for (int i = 0; i < 400; i++) {
		uint16_t act = ap_turn(a, t, &aimed);
		if (aimed)
			return;
		ap_tick(a, act);
	}
}

void ap_face(struct ap *a, double x, double y)
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
void ap_dash(struct ap *a, const struct ap_step *st)
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
