/*
 * autopilot: writes the input script (.scr, input/scr.h) of a walk from a
 * Doom map's start to its exit, for the golden exit recordings of
 * tests/replay/freedoom (tests/replay/README.md).
 *
 *   autopilot --wad FILE [--wad FILE...] --map NAME [--set S.K=V...]
 *             --route ROUTE [--out SCRIPT] [--inter N] [--verbose | --trace]
 *   autopilot --wad FILE --map NAME --explore X,Y[,KEYS]
 *   autopilot --level N ... (a built-in stage and the ones after it,
 *             instead of --wad and --map: tests/replay/stages)
 *   autopilot --level N --demo --route ROUTE [--out SCRIPT]
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
 * A map without an exit (built-in stages 1..3) ends when its enemies are
 * dead instead: the route's goal is the clear (its steps end there), then
 * the banner shows for up to --inter ticks; the checks are the clear's
 * tick (phase G_PH_CLEAR), the kills and the score.
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
 * --level N plays built-in level N instead of a WAD's map (the stages that
 * follow it too). --demo writes the attract demo (levels/demo.scr, app/demo.c):
 * the game starts in play, without coin or START, by the demo's rules
 * (every setting at its default, 0, but the difficulty: --set
 * game.difficulty=D, default 1); the route's goal is the stage cleared
 * (every enemy dead, phase 2) instead of the exit, and its last step should
 * end with the last kill (a step still going when the next stage starts
 * walks on the wrong map); then it stands and fights what the next stage
 * sends until the attract page's end (SIM_DEMO_TICKS); the script's first line names the map, its content hash and the
 * difficulty ("# demo: ARENA1 HASH D"), which the daemon checks before
 * it plays the demo, and its checks are the clear's tick, the score, the
 * kills and the weapon held, then the page end's kills and score.
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
#include "tests/replay/ap.h"

void ap_die(struct ap *a, const struct ap_step *st, const char *fmt, ...)
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

/* ---- ticks and script lines --------------------------------------------- */

/* One tick with the actions in want held; changes become script lines. */
void ap_tick(struct ap *a, uint16_t want)
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
	if (!a->clear_t && a->s.g.phase == G_PH_CLEAR) {
		a->clear_t = a->s.tick - 1;
		a->clear_kills = a->s.g.kills;
		a->clear_weapon = a->s.pl.weapon;
	}
	if (a->s.tick > AP_MAX_TICKS)
		ap_die(a, NULL, "more than %d ticks", AP_MAX_TICKS);
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

/* --demo: the route played from the start in play until the stage is
 * cleared, then standing and fighting until the attract page's end
 * (SIM_DEMO_TICKS); the script and its checks. */
static int ap_demo(struct ap *a, const struct ct *ct, const struct ap_step *steps, int nsteps,
		   const char *outp)
{
	uint32_t clear_t;

	fprintf(a->out, "# demo: %s %016llx %u\n", ct->map->name,
		(unsigned long long)ct->map->content_hash, a->s.set.difficulty);
	fprintf(a->out, "# The attract demo (app/demo.c): written by tests/replay/autopilot from\n"
		"# %s (see it and tests/replay/README.md): %s, from the start in play\n"
		"# until every enemy is dead. Regenerate: tests/replay/autopilot.sh; then\n"
		"# tools/mkdemo.sh levels/demo.scr > app/demo_game.h.\n", a->route, ct->what);
	if (a->s.mode != SIM_PLAY)
		ap_die(a, NULL, "the demo did not start in play");
	for (int i = 0; i < nsteps && !a->clear_t; i++)
		ap_do(a, &steps[i]);
	for (int i = 0; i < 600 && !a->clear_t; i++)
		ap_stand_tick(a);
	if (!a->clear_t)
		ap_die(a, NULL, "the route ended with %u enemies alive", a->s.g.alive);
	clear_t = a->clear_t;
	fprintf(stderr, "autopilot: %s: cleared on tick %u, health %d, ammo %u, kills %u, score %u, "
		"lives lost %d, shots %d (%d hit), weapon %u\n", ct->map->name, clear_t,
		a->s.pl.health / FX_ONE, a->s.pl.ammo, a->clear_kills, a->s.g.score, a->deaths,
		a->nshots, a->nhits, a->clear_weapon);
	fprintf(a->out, "%u expect phase == %d\n", clear_t, G_PH_CLEAR);
	fprintf(a->out, "%u expect kills == %u\n", clear_t, a->clear_kills);
	fprintf(a->out, "%u expect weapon == %u\n", clear_t, a->clear_weapon);
	/* the rest of the page: the next stage, standing and fighting what
	 * comes (its way is not on the grid, which is the first stage's) */
	while (a->s.tick < SIM_DEMO_TICKS)
		ap_stand_tick(a);
	fprintf(stderr, "autopilot: %s: at the page's end (tick %u): stage %u, kills %u, score %u, "
		"health %d, lives lost %d\n", ct->map->name, a->s.tick - 1, a->s.g.stage + 1,
		a->s.g.kills, a->s.g.score, a->s.pl.health / FX_ONE, a->deaths);
	fprintf(a->out, "%u expect kills == %u\n", a->s.tick - 1, a->s.g.kills);
	fprintf(a->out, "%u expect score == %u\n", a->s.tick - 1, a->s.g.score);
	fprintf(a->out, "%u end\n", a->s.tick - 1);
	if (outp && fclose(a->out) != 0) {
		fprintf(stderr, "autopilot: %s: %s\n", outp, strerror(errno));
		return 2;
	}
	return 0;
}

/* A stage without an exit, after coin-up and start: the route played
 * until the stage is cleared (every enemy dead), then the clear banner
 * shown for up to `inter` ticks (not into the next stage); the checks
 * are the clear's tick, the kills, the score. */
static int ap_to_clear(struct ap *a, struct ct *ct, const struct ap_step *steps, int nsteps,
		    int inter, const char *outp)
{
	uint32_t clear_t;

	for (int i = 0; i < nsteps && !a->clear_t; i++) {
		/* every enemy must die: one left alone (shots that did not hurt
		 * it from where the walk was) is fought again from each step */
		memset(a->ignored, 0, sizeof(a->ignored));
		ap_do(a, &steps[i]);
	}
	for (int i = 0; i < 600 && !a->clear_t; i++)
		ap_stand_tick(a);
	if (!a->clear_t) {
		/* for the route's writer: the ones it did not pass by */
		for (int i = 0; i < a->s.g.num_enemies; i++)
			if (a->s.g.en[i].state != G_E_DEAD)
				fprintf(stderr, "autopilot: alive: enemy %d (%s at %.0f, %.0f)\n", i,
					g_kinds[a->s.g.en[i].kind].name, ap_fx(a->s.g.en[i].x),
					ap_fx(a->s.g.en[i].y));
		ap_die(a, NULL, "the route ended with %u enemies alive", a->s.g.alive);
	}
	clear_t = a->clear_t;
	fprintf(stderr, "autopilot: %s: cleared on tick %u, health %d, ammo %u, kills %u, score %u, "
		"lives lost %d, shots %d (%d hit)\n", ct->what, clear_t, a->s.pl.health / FX_ONE,
		a->s.pl.ammo, a->clear_kills, a->s.g.score, a->deaths, a->nshots, a->nhits);
	fprintf(a->out, "%u expect phase == %d\n", clear_t, G_PH_CLEAR);
	fprintf(a->out, "%u expect kills == %u\n", clear_t, a->clear_kills);
	for (int i = 0; i < inter && a->s.g.phase == G_PH_CLEAR; i++)
		ap_tick(a, 0);
	fprintf(a->out, "%u expect mode == play\n", a->s.tick - 1);
	fprintf(a->out, "%u expect score == %u\n", a->s.tick - 1, a->s.g.score);
	fprintf(a->out, "%u end\n", a->s.tick - 1);
	if (outp && fclose(a->out) != 0) {
		fprintf(stderr, "autopilot: %s: %s\n", outp, strerror(errno));
		return 2;
	}
	ct_free(ct);
	return 0;
}

static int ap_usage(void)
{
	fprintf(stderr, "usage: autopilot --wad FILE [--wad FILE...] --map NAME [--set S.K=V...] "
			"--route ROUTE [--out SCRIPT] [--inter N] [--verbose | --trace]\n"
			"       autopilot --wad FILE --map NAME --explore X,Y[,KEYS]\n"
			"       (--level N instead of --wad and --map: a built-in stage)\n"
			"       autopilot --level N --demo [--set S.K=V...] --route ROUTE [--out SCRIPT]\n");
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
	int nsteps, inter = 240, explore = 0, demo = 0;
	double ex_x = 0, ex_y = 0;
	unsigned ex_keys = 0;

	cfg_defaults(&c);
	for (int i = 1; i < argc; i++) {
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;
		if (strcmp(argv[i], "--verbose") == 0 || strcmp(argv[i], "--trace") == 0) {
			a.verbose = argv[i][2] == 'v' ? 1 : 2;
			continue;
		}
		if (strcmp(argv[i], "--demo") == 0) {
			demo = a.demo = 1;
			continue;
		}
		if (!v)
			return ap_usage();
		if (strcmp(argv[i], "--wad") == 0 && spec.nwads < CT_MAX_WADS)
			spec.wads[spec.nwads++] = v;
		else if (strcmp(argv[i], "--map") == 0)
			spec.map = v;
		else if (strcmp(argv[i], "--level") == 0)
			spec.level = atoi(v);
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
	if ((spec.level > 0) == (spec.nwads > 0) || (spec.nwads && !spec.map) ||
	    (!a.route && !explore) || (demo && (explore || spec.nwads)))
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
	cfg_settings(&c, &set);
	if (demo) {
		/* app/demo.c's rules for the recorded demo */
		uint8_t diff = set.difficulty;
		memset(&set, 0, sizeof(set));
		set.difficulty = diff;
		set.start_in_play = 1;
	}
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
	if (demo)
		return ap_demo(&a, &ct, steps, nsteps, outp);
	ap_grid(&a);
	fprintf(a.out, "# Written by tests/replay/autopilot from %s (see it and README.md):\n",
		a.route);
	fprintf(a.out, "# %s%s%s, from the start to the exit and the intermission page.\n",
		ct.what, spec.map ? " " : "", spec.map ? spec.map : "");
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
	/* a map without an exit (built-in stages 1..3) ends when every enemy
	 * of it is dead: then the route's goal is the clear */
	a.to_clear = !a.s.w.has_exit;
	if (a.to_clear)
		return ap_to_clear(&a, &ct, steps, nsteps, inter, outp);
	for (int i = 0; i < nsteps && a.s.g.phase != G_PH_INTER; i++)
		ap_do(&a, &steps[i]);
	for (int i = 0; i < 600 && a.s.g.phase != G_PH_INTER; i++)
		ap_stand_tick(&a);
	if (a.s.g.phase != G_PH_INTER)
		ap_die(&a, NULL, "the route ended without the map's exit");
	fprintf(stderr, "autopilot: %s: exit taken on tick %u (%u ticks into the map), health %d, "
		"ammo %u, kills %u, score %u, lives lost %d, shots %d (%d hit)\n", ct.what,
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
