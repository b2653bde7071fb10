/*
 * app: one run of the daemon: sets up the modules of app/ in order, runs
 * the main loop (app/loop.h) with the steps below, reports and tears down.
 * Each step is a line or two into the module that does the work.
 */
#include "app/app.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/cmd.h"
#include "app/ctl.h"
#include "app/demo.h"
#include "app/diag.h"
#include "app/hear.h"
#include "app/keep.h"
#include "app/loop.h"
#include "app/mdir.h"
#include "app/op.h"
#include "app/out.h"
#include "app/pace.h"
#include "app/pool.h"
#include "app/prog.h"
#include "app/pspec.h"
#include "app/say.h"
#include "app/scene.h"
#include "app/script.h"
#include "app/sig.h"
#include "app/slot.h"
#include "app/stats.h"
#include "app/tape.h"
#include "display/dp.h"
#include "display/shot.h"
#include "engine/game/menu.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/sound/snd.h"
#include "systemd/svc.h"

struct app {
	const struct cfg *cfg;
	const struct app_opts *o;
	int headless;              /* a script or replay: no devices, no clock, nothing kept */
	struct ct ct;              /* stage maps, texture set, light maps */
	/* what was asked to be played: the command line's content, or else
	 * [game] wad and maps (whose words wadbuf holds) */
	struct ct_spec content;
	char wadbuf[sizeof(((struct cfg *)0)->game.wad)];
	uint64_t map_hash;         /* of every stage: what recordings are tied to */
	struct sim_settings set;
	struct sim sim;
	struct demo demo;          /* the attract mode's demo */
	struct hear hear;          /* each tick's sound, mixed and hashed */
	struct out_audio audio;    /* where it goes */
	struct scene scene;        /* frame, renderers, display */
	struct mdir meshes;        /* [game] meshes: loaded at start-up, drawn by the view */
	struct slot_kind kinds[SLOT_KINDS];
	int nkinds;
	struct slot_set slots;     /* input devices */
	struct ctl ctl;            /* bindings, actions, the wizard */
	struct keep keep;          /* settings, scores, books, flight recorder */
	struct tape tape;          /* --record, --replay, --verify */
	struct script script;      /* --script (scr NULL: none) */
	struct stats stats;
	struct op op;              /* the menu's content, screen and config pages */
	struct diag_view dv;       /* the service menu's diagnostics text */
	struct diag_src ds;        /* what it is made from */
	struct pace pace;
	uint32_t hang_at;          /* fault injection: hang after this tick */
	uint64_t wd_interval, wd_next;
	int ready;
	int devices_open;          /* the live inputs and sound card, after the first frame */
};

/* The display's completed page flips into the statistics. */
static void app_flips(void *ctx)
{
	struct app *a = ctx;
	struct dp_flip done[8];
	int n;

	do {
		n = scene_flips(&a->scene, done, 8);
		for (int i = 0; i < n; i++)
			stats_flip(&a->stats, done[i].presented_ns, done[i].shown_ns);
	} while (n == 8);
}

/* Whether the loop follows the 60 Hz clock: live, or --realtime. */
static int app_paced(const struct app *a)
{
	return !a->o->fast && (!a->headless || a->o->realtime);
}

/* The summary, and the display's counters when it has some. */
static void app_summary(struct app *a)
{
	const char *st = scene_status(&a->scene);
	char held[160];

	stats_print(&a->stats);
	/* what the controls hold now: after an unplug, nothing of its own */
	say("summary: actions held: %s", cmd_held_text(&a->ctl.cs, held, sizeof(held)));
	if (st)
		say("summary: display: %s", st);
}

/* ---- the steps of a tick (their order is loop.c's) -------------------- */

static int step_begin(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	if (sig_stop()) {
		say("signal %d: stopping", sig_stop());
		return 0;
	}
	if (sig_summary())
		app_summary(a);
	if (a->op.reload)
		return 0;                  /* the service menu's choice: run again (app/op.h) */
	if (a->o->ticks && k->t >= a->o->ticks)
		return 0;
	if (k->t == a->hang_at || sig_fault())
		sig_hang();
	return !(a->script.scr && script_over(&a->script, k->t));
}

static void step_wait(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	struct pace_fd w = { scene_wait_fd(&a->scene), app_flips, a };

	if (app_paced(a))
		a->stats.dropped += pace_wait(&a->pace, k->t, &w);
}

static int step_input(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	if (a->tape.rep)
		return tape_next(&a->tape, k->t, &k->rt);
	if (a->script.scr)
		script_inputs(&a->script, k->t, &a->ctl.cs, &a->stats, a->nkinds);
	else
		slot_read(&a->slots);
	return 1;
}

static void step_command(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	if (!a->tape.rep)
		/* the controls of the player whose turn it is */
		cmd_build_for(&a->ctl.cs, a->sim.up, &k->rt.cmd);
	op_command(&a->op, &k->rt.cmd);
}

static void step_wizard(void *ctx, struct loop_tick *k)
{
	(void)k;
	ctl_wizard_tick(&((struct app *)ctx)->ctl);
}

static void step_flight_before(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	keep_flight_before(&a->keep, &a->sim, &k->rt.cmd);
}

static void step_sim(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;
	char line[256];

	sim_tick(&a->sim, &k->rt.cmd);
	if (prog_exit(&a->sim, line, sizeof(line)))
		say("%s", line);
	demo_tick(&a->demo, &a->sim);
	a->stats.ticks++;
}

static void step_sound(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	(void)k;
	hear_tick(&a->hear, &a->sim, demo_under(&a->demo, &a->sim));
	out_audio_play(&a->audio, &a->hear, &a->stats);
}

static void step_flight_after(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	keep_flight_after(&a->keep, &a->sim, &k->rt.cmd, a->scene.frame.w, a->scene.frame.h,
			  a->hear.hash);
}

static void step_requests(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	a->scene.view.diag = diag_frame(&a->dv, &a->ds,
					a->sim.mode == SIM_SERVICE ? a->sim.menu.page : 0,
					a->tape.rec || a->tape.rep, k->t);
	/* CONFIGURE INPUTS: the menu shows its request for one tick */
	if (a->sim.mode == SIM_SERVICE && a->sim.menu.page == MENU_WIZARD)
		ctl_wizard_start(&a->ctl, "service menu");
	op_request(&a->op, &a->sim);
	a->scene.view.notice = op_notice(&a->op);
	scene_follow_menu(&a->scene, &a->sim);
}

static void step_outputs(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	(void)k;
	out_update(&a->slots, &a->sim);
}

static void step_persist(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	(void)k;
	keep_tick(&a->keep, &a->sim, a->scene.frame.w, a->scene.frame.h);
}

/* The service's status while no display shows the game. */
static void app_status_no_display(const struct app *a)
{
	if (!a->headless)
		svc_status("no display: %s; the game runs, looking for one",
			   a->scene.missing);
}

static void step_present(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;
	uint64_t t0;

	(void)k;
	if (a->o->no_render)
		return;
	t0 = in_now_ns();
	/* a display that was missing is looked for again */
	if (scene_poll_display(&a->scene, t0) == SCENE_STILL_MISSING)
		app_status_no_display(a);
	scene_show(&a->scene, &a->sim, demo_under(&a->demo, &a->sim),
		   a->ctl.wiz_on ? &a->ctl.wiz : NULL, a->op.on ? &a->op.pick : NULL);
	stats_presented(&a->stats, t0, in_now_ns(),
			app_paced(a) ? pace_due(&a->pace, k->t + 1) : 0);
	app_flips(a);
}

static void step_hashes(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	tape_hashes(&a->tape, k->t, &k->rt, &a->sim, &a->scene.frame, a->hear.hash);
}

static void step_checks(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	if (a->script.scr)
		script_checks(&a->script, k->t, &a->sim, &a->scene.frame, a->ct.tex->pal.rgb);
}

static void step_notify(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	(void)k;
	if (!a->ready && !a->headless && a->scene.shown) {
		/* READY=1 only once a frame was presented on the display asked
		 * for: not while a missing one is waited for, not after a
		 * present that failed. */
		svc_ready();
		a->ready = 1;
	}
	if (!a->devices_open) {
		/* Once the first frame is presented (or, with no display, has
		 * been drawn): the input devices (an enumeration of every
		 * hidraw, evdev and GPIO node, libusb) and the sound card.
		 * Nothing can press a button or hear a sound before the
		 * picture is up; the first tick reads no input and is silent. */
		a->devices_open = 1;
		if (!a->headless) {
			/* the sounds' hash, which only the flight recorder needs
			 * here: made now, not while the first frame waited, and
			 * before any game can begin (input is read from the next
			 * tick on); --record and --replay made it at setup */
			snd_set_hash(a->ct.sounds);
			slot_open(&a->slots, a->kinds, a->nkinds, a->scene.dpb);
			out_audio_start(&a->audio);
		}
	}
	if (a->wd_interval) {
		uint64_t now = in_now_ns();
		if (now >= a->wd_next) {
			svc_watchdog_ping();
			a->wd_next = now + a->wd_interval;
		}
	}
}

static void step_end(void *ctx, struct loop_tick *k)
{
	struct app *a = ctx;

	(void)k;
	if (!a->headless)
		svc_stopping();
}

static const struct loop_ops app_steps = {
	.begin = step_begin,
	.wait = step_wait,
	.input = step_input,
	.command = step_command,
	.wizard = step_wizard,
	.flight_before = step_flight_before,
	.sim = step_sim,
	.sound = step_sound,
	.flight_after = step_flight_after,
	.requests = step_requests,
	.outputs = step_outputs,
	.persist = step_persist,
	.present = step_present,
	.hashes = step_hashes,
	.checks = step_checks,
	.notify = step_notify,
	.end = step_end,
};

/* ---- set-up and tear-down --------------------------------------------- */

static void app_mesh_note(void *user, int bad, const char *msg)
{
	(void)user;
	if (bad)
		say_warn("game.meshes: %s", msg);
	else
		say("game.meshes: %s", msg);
}

/* [game] meshes: read, and handed to the view; a bad file or directory
 * is logged and the built-in pictures stay (the cabinet runs on). The
 * hash is logged as what a replay's frames depend on besides the map. */
static void app_meshes(struct app *a)
{
	const char *dir = a->cfg->game.meshes;
	int n = mdir_load(&a->meshes, dir, app_mesh_note, NULL);

	if (!dir[0])
		return;
	if (n == -ENOMEM)
		say_warn("game.meshes: out of memory; the built-in pictures only");
	if (n > 0)
		a->scene.view.meshes = &a->meshes.set;
	say("game.meshes: %d mesh(es) from %s, %u refused, %u ignored, hash %016llx", n < 0 ? 0 : n,
	    dir, a->meshes.nbad, a->meshes.nignored, (unsigned long long)a->meshes.hash);
}

/* The content, the game's settings and the replay's checks; *rate: the
 * sound's output rate (a recording's own). */
static int setup_game(struct app *a, int *rw, int *rh, uint32_t *rate)
{
	const struct cfg *c = a->cfg;
	const struct app_opts *o = a->o;
	struct ct_spec spec;
	char err[512] = "", first[9];
	int rc;

	ct_spec_config(&a->content, &o->content, c->game.wad, c->game.maps, a->wadbuf,
		       sizeof(a->wadbuf));
	spec = a->content;

	if (o->replay) {
		/* A recording says which built-in level and frame size it was
		 * made with (format 2); the replay uses them. */
		struct rec_run run;
		rc = tape_replay_open(&a->tape, o->replay, &run);
		if (rc < 0)
			return rc;
		if (run.level && spec.nwads == 0 && !spec.grid)
			spec.level = run.level;
		if (run.render_w && run.render_h && o->size_w <= 0) {
			*rw = run.render_w;
			*rh = run.render_h;
		}
		/* and the rate its audio hashes were mixed at (format 3) */
		if (run.audio_rate)
			*rate = run.audio_rate;
	}
	if (o->size_w > 0) {
		*rw = o->size_w;
		*rh = o->size_h;
	}
	spec.stop = sig_stop_flag();   /* a stop signal ends a long load */
	spec.task_start = pool_task_start;
	spec.task_join = pool_task_join;
	rc = ct_load(&a->ct, &spec, err, sizeof(err));
	if (rc < 0 && rc != -ECANCELED && a->content.nwads && !o->content.nwads && !o->replay) {
		/* [game] wad or maps is wrong: the cabinet plays its built-in
		 * levels rather than not at all, and says why */
		say_err("game.wad / game.maps: %s; playing the built-in levels", err);
		if (o->errs)       /* on screen too, as a configuration error */
			cfgerr_keep(o->errs, "game.wad / game.maps", 0, err);
		memset(&a->content, 0, sizeof(a->content));
		a->content.level = c->game.level;
		a->content.lights = o->content.lights;
		spec = a->content;
		spec.stop = sig_stop_flag();
		rc = ct_load(&a->ct, &spec, err, sizeof(err));
	}
	if (rc < 0) {
		say_err("%s", err);
		return rc;
	}
	if (a->ct.note[0])
		say("%s", a->ct.note);
	for (int i = 0; i < a->ct.nmaps; i++) {
		/* once per map, at its load: what of it the game does not play */
		char un[512];
		if (pspec_unplayed(a->ct.maps[i], un, sizeof un))
			say_warn("%s", un);
		if (pspec_crowded(a->ct.maps[i], c->game.difficulty, un, sizeof un))
			say_warn("%s", un);
	}
	say("content: %s, %u sectors, %u lines, %d light(s)%s", a->ct.what, a->ct.map->num_sectors,
	    a->ct.map->num_lines, a->ct.nlights,
	    a->ct.map->missing_textures ? ", some textures missing (drawn as a checker)" : "");
	if (a->ct.sound_note[0])
		say("sounds: %s; their built-in sounds play instead", a->ct.sound_note);
	a->map_hash = sim_stages_hash((const struct map *const *)a->ct.maps, a->ct.nmaps);
	cfg_settings(c, &a->set);
	ct_first_map(&a->content, first);
	if (a->tape.rep) {
		struct rec_run run = {
			.map_hash = a->map_hash,
			.render_w = (uint16_t)(o->no_render ? 0 : *rw),
			.render_h = (uint16_t)(o->no_render ? 0 : *rh),
			.level = (uint8_t)(spec.nwads || spec.grid ? 0 : spec.level),
			.map_name = first,
			.audio_rate = *rate,
			.sound_hash = snd_set_hash(a->ct.sounds),
		};
		rc = tape_replay_check(&a->tape, &run, o->verify, &a->set);
		if (rc < 0)
			return rc;
	}
	return 0;
}

static int setup(struct app *a)
{
	const struct cfg *c = a->cfg;
	const struct app_opts *o = a->o;
	int rw = c->game.render_width, rh = c->game.render_height;
	uint32_t rate = (uint32_t)c->audio.rate;
	const char *names[SLOT_KINDS + 1];
	char err[512] = "";
	int rc, persist;

	a->headless = o->script || o->replay;
	a->tape.out = o->out;
	a->tape.quiet = o->quiet;
	a->tape.no_render = o->no_render;
	rc = setup_game(a, &rw, &rh, &rate);
	if (rc < 0)
		return rc;
	/* Scripts and replays start from the defaults, so they replay the
	 * same anywhere; only a live cabinet keeps its tables. */
	persist = !a->headless && c->paths.state_dir[0];
	if (o->script) {
		rc = script_load(&a->script, o->script, o->out);
		if (rc < 0)
			return rc;
	}
	keep_start(&a->keep, c->paths.state_dir, persist, &a->sim, &a->ct, &a->set);
	/* the sounds' lengths (a restored snapshot brings its own) */
	sim_set_sounds(&a->sim, a->ct.sounds);
	hear_init(&a->hear, a->ct.sounds, rate);
	if (a->tape.rep) {
		rc = tape_replay_restore(&a->tape, &a->sim);
		if (rc < 0)
			return rc;
	}
	keep_flight_open(&a->keep, c->recorder.keep, c->recorder.max_mb, a->map_hash, &a->content,
			 a->hear.rate, a->ct.sounds);
	rc = demo_init(&a->demo, &a->ct, err, sizeof(err));
	if (rc < 0) {
		say_err("%s", err);
		return rc;
	}
	rc = scene_init(&a->scene, c, &a->ct, o->gl, rw, rh);
	if (rc == 0) {
		app_meshes(a);
		rc = scene_open_display(&a->scene, a->headless);
	}
	if (rc == 0)
		rc = out_audio_open(&a->audio, c, a->hear.rate, a->headless);
	if (rc < 0)
		return rc;
	if (a->scene.waiting)
		app_status_no_display(a);

	/* latency by source: each input backend, then scripts */
	a->nkinds = slot_kinds(c, a->kinds);
	for (int k = 0; k < a->nkinds; k++)
		names[k] = a->kinds[k].be->name;
	names[a->nkinds] = "script";
	stats_init(&a->stats, names, a->nkinds + 1);
	ctl_load(&a->ctl, c, o->config_dir, o->bindings, !a->headless, persist, &a->stats,
		 &a->tape);
	op_init(&a->op, c, o->errs, &a->tape, persist, a->ct.what);
	a->ds = (struct diag_src){ c, o->config_dir, o->bindings, a->headless, &a->ctl, &a->stats,
				   a->kinds, a->nkinds, &a->slots };
	slot_init(&a->slots, &ctl_hooks, &a->ctl);
	a->slots.log_nodes = c->input.log;

	if (o->record) {
		/* Format 3: the run it was made with and every tick's state,
		 * frame and audio hashes, so `--verify` can prove a replay. */
		struct rec_header h;
		tape_header(&h, a->map_hash, &a->set, a->scene.frame.w, a->scene.frame.h,
			    &a->content, a->hear.rate, snd_set_hash(a->ct.sounds));
		h.hash_flags = REC_HAS_STATE | REC_HAS_FRAME | REC_HAS_AUDIO;
		rc = tape_record_open(&a->tape, o->record, &h);
		if (rc < 0)
			return rc;
	}
	return 0;
}

static void teardown(struct app *a)
{
	slot_close(&a->slots);
	out_audio_close(&a->audio);
	scene_close_display(&a->scene);
	tape_close(&a->tape);
	script_free(&a->script);
	keep_close(&a->keep, &a->sim, a->stats.ticks);
	scene_free(&a->scene);
	mdir_free(&a->meshes);
	diag_view_free(&a->dv);
	demo_free(&a->demo);
	ct_free(&a->ct);
}

/* What the run ends with: the screenshot, the verdicts of --verify and
 * of a script, the summary. Returns the exit code. */
static int finish(struct app *a)
{
	const struct app_opts *o = a->o;
	const struct r_frame *f = &a->scene.frame;
	int code = APP_OK;

	if (o->screenshot) {
		int rc = shot_png(o->screenshot, f->px, f->w, f->h, f->pitch, a->ct.tex->pal.rgb);
		if (rc < 0) {
			char why[160];

			shot_why(o->screenshot, rc, why, sizeof(why));
			say_err("%s: %s", o->screenshot, why);
			code = APP_SETUP_FAILED;
		}
	}
	if (tape_verdict(&a->tape))
		code = APP_EXPECT_FAILED;
	if (a->script.scr) {
		if (a->script.failures)
			say_err("%s: %d check(s) failed", o->script, a->script.failures);
		code = a->script.failures ? APP_EXPECT_FAILED : APP_OK;
	}
	/* The summary while everything is still open: its fd count is the
	 * running daemon's (the soak test compares runs by it). */
	if (a->stats.ticks &&
	    ((!o->replay && !o->script) || o->realtime || getenv("ARCADED_SUMMARY")))
		app_summary(a);
	return code;
}

int app_run(const struct cfg *c, const struct app_opts *o)
{
	struct app *a = calloc(1, sizeof(*a));
	int code = APP_SETUP_FAILED;
	int rc;

	if (!a) {
		say_err("out of memory");
		return APP_SETUP_FAILED;
	}
	a->cfg = c;
	a->o = o;
	sig_install();
	rc = setup(a);
	if (rc == 0) {
		uint64_t now;
		a->wd_interval = a->headless ? 0 : svc_watchdog_interval_ns();
		now = in_now_ns();
		pace_start(&a->pace, now);
		a->stats.start_ns = now;
		a->hang_at = sig_fault_setup();
		loop_run(&app_steps, a);
		code = finish(a);
		if (code == APP_OK && a->op.reload)
			code = APP_RELOAD;
	} else if (rc == -ECANCELED && sig_stop()) {
		code = APP_OK;                 /* stopped by a signal while loading: an ordinary end */
	}
	teardown(a);
	free(a);
	return code;
}
