/*
 * replay: the headless replayer of the cross-build determinism test.
 *
 * Links only the engine (every engine/ source but gl), the recording and
 * script code (input/rec.c, rec_check.c, scr.c, act.c, with their file
 * and message helpers io.c and txt.c) and the app's content, view and
 * sound code (app/ct.c, view.c, demo.c, cmd.c, hear.c): no platform
 * library, so it builds with any C11 compiler for any CPU
 * (tests/xbuild/run.sh builds it with gcc -O0, gcc -O3, clang -O2 and an
 * aarch64 cross gcc). It does per tick exactly what `arcaded --replay`
 * does, through the same engine functions, and prints the same lines:
 * "TICK STATEHASH FRAMEHASH AUDIOHASH" (frame hash 0 without rendering);
 * the test diffs its output with the daemon's.
 *
 *   replay [options] FILE
 *     --no-render       state hashes only (frame hash printed as 0)
 *     --size WxH        render size (default: the recording's, else 320x240)
 *     --level N         built-in level (default: the recording's, else 1)
 *     --until T         stop after tick T (ticks 0..T run)
 *     --quiet           no per-tick lines
 *     --verify          compare with the hashes stored in the recording
 *                       (format 2 or 3); print the verdict; exit 1 on a
 *                       difference
 *     --rehash OUT      write the recording again as format 3 with the
 *                       state, frame and audio hashes of this replay
 *     --bench           print ticks per second to stderr
 *     --set game.meshes=DIR
 *                       draw with the meshes of DIR, as the daemon does
 *                       with that setting (app/mdir.h: frames depend on
 *                       them, the state does not); the only --set taken
 *     --balance         print, at the end, a line per stage played:
 *                       "balance STAGE MAP TICKS DAMAGE SHOTS HITS KILLS
 *                       DEATHS" (tests/replay/balance.sh, docs/game.md):
 *                       the ticks fought on it (phase PLAY) until its end
 *                       (exit or clear), the player's health lost (every
 *                       drop, deaths included), shots fired and shots that
 *                       hit an enemy (the sim's shot_t and shot), kills and
 *                       lives lost there; read from the sim as it runs
 *     --modes           print to stderr, at the end, how many times the
 *                       game entered each mode ("modes: attract 3 play 2
 *                       gameover 2 initials 1 service 0"): the soak test's
 *                       proof that its input went through the whole flow
 *   replay --make-random OUT TICKS SEED
 *     writes a format 3 recording without hashes for built-in level 1,
 *     volume 100 and attract sound on: a coin and START,
 *     then TICKS ticks of random play (xorshift32 from SEED): movement,
 *     turning and strafing held for random spans, running into walls
 *   replay --cut IN K OUT
 *     writes the rest of IN from tick K on as a recording of its own that
 *     starts from a snapshot (as the flight recorder's games do): IN's
 *     ticks 0..K-1 run as a replay runs them, the sim is snapshotted
 *     (sim_snapshot), and OUT (format 3) holds that snapshot and IN's
 *     records from tick K (with their stored hashes). Its replay prints
 *     the hashes of IN's ticks K.. (numbered from 0). Refused when the
 *     state at the cut shows the attract DEMO page: the demo's own sim
 *     (app/demo.c) is not part of the snapshot, so the frames of a demo
 *     under way could not be reproduced.
 *
 * A recording with a snapshot starts from it: sim_init_stages on the
 * recording's content and settings, then sim_restore, before the first
 * tick (what the daemon must do too). The sound is mixed at the
 * recording's audio rate (48000 Hz when it has none), from the content's
 * sounds (sim_set_sounds before a restore, as the daemon).
 *
 * Exit: 0, 1 (verification failed or nothing to verify), 2 (bad usage,
 * unreadable or refused recording).
 *
 * It loads content, draws frames and mixes sound with the daemon's own
 * code (app/ct.c ct_load, app/view.c view_draw, app/hear.c hear_tick), and
 * mirrors the daemon's replay set-up (app/app.c, app/tape.c, app/keep.c:
 * level, render size, audio rate and settings from the recording,
 * sim_init_stages with the default tables) and loop (app/loop.c's input,
 * sim, sound, present and hashes steps: rec_reader_next_tick, sim_tick,
 * hear_tick, view_draw, hash_frame). run.sh fails when their hashes
 * differ.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/ct.h"
#include "app/demo.h"
#include "app/hear.h"
#include "app/mdir.h"
#include "app/view.h"
#include "engine/core/hash.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/render/r_main.h"
#include "engine/sound/snd.h"
#include "input/rec.h"

#define RP_DEFAULT_W 320
#define RP_DEFAULT_H 240
#define RP_DEFAULT_RATE 48000

struct rp_opts {
	const char *file, *rehash;
	const char *wads[CT_MAX_WADS], *map, *grid;
	const char *meshes;        /* --set game.meshes=DIR, else NULL */
	int nwads;
	int render, quiet, verify, bench, modes, balance;
	int w, h, level;
	int64_t until;
};

static int rp_usage(void)
{
	fprintf(stderr, "usage: replay [--no-render] [--size WxH] [--level N] [--wad F --map M | --grid G] [--until T] "
			"[--quiet] [--verify] [--rehash OUT] [--bench] [--modes] [--balance] "
			"[--set game.meshes=DIR] FILE\n");
	return 2;
}

static int rp_args(int argc, char **argv, struct rp_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->render = 1;
	o->until = -1;
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i];
		const char *v = i + 1 < argc ? argv[i + 1] : NULL;

		if (strcmp(a, "--no-render") == 0) {
			o->render = 0;
		} else if (strcmp(a, "--quiet") == 0) {
			o->quiet = 1;
		} else if (strcmp(a, "--balance") == 0) {
			o->balance = 1;
		} else if (strcmp(a, "--verify") == 0) {
			o->verify = 1;
		} else if (strcmp(a, "--bench") == 0) {
			o->bench = 1;
		} else if (strcmp(a, "--modes") == 0) {
			o->modes = 1;
		} else if (strcmp(a, "--size") == 0 && v) {
			if (sscanf(v, "%dx%d", &o->w, &o->h) != 2 || o->w < 1 || o->h < 1 ||
			    o->w > 4096 || o->h > 4096)
				return -1;
			i++;
		} else if (strcmp(a, "--level") == 0 && v) {
			o->level = atoi(v);
			if (o->level < 1 || o->level > 99)
				return -1;
			i++;
		} else if (strcmp(a, "--wad") == 0 && v && o->nwads < CT_MAX_WADS) {
			o->wads[o->nwads++] = v;
			i++;
		} else if (strcmp(a, "--map") == 0 && v) {
			o->map = v;
			i++;
		} else if (strcmp(a, "--grid") == 0 && v) {
			o->grid = v;
			i++;
		} else if (strcmp(a, "--until") == 0 && v) {
			o->until = strtoll(v, NULL, 10);
			i++;
		} else if (strcmp(a, "--set") == 0 && v) {
			/* the one setting that changes what a replay draws */
			if (strncmp(v, "game.meshes=", 12) != 0) {
				fprintf(stderr, "replay: --set %s: only game.meshes=DIR is taken\n", v);
				return -1;
			}
			o->meshes = v + 12;
			i++;
		} else if (strcmp(a, "--rehash") == 0 && v) {
			o->rehash = v;
			i++;
		} else if (a[0] != '-' && !o->file) {
			o->file = a;
		} else {
			return -1;
		}
	}
	return o->file ? 0 : -1;
}

static uint32_t rp_rand(uint32_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 17;
	*s ^= *s << 5;
	return *s;
}

/* A value in -127..127, often the full speed a digital control gives. */
static int8_t rp_axis(uint32_t *s)
{
	uint32_t v = rp_rand(s);

	if (v % 4 == 0)
		return 0;
	if (v % 4 == 1)
		return (int8_t)((v >> 8) % 2 ? 127 : -127);
	return (int8_t)((int32_t)((v >> 8) % 255) - 127);
}

static int rp_make_random(const char *out, uint32_t ticks, uint32_t seed)
{
	struct rec_header h = {
		.version = REC_VERSION_3,
		.tick_rate = SIM_TICRATE,
		.engine_version = REC_ENGINE_VERSION,
		.set = { .coins_per_credit = 1, .volume = 100, .attract_sound = 1 },
	};
	struct sim_cmd c = { 0 };
	struct ct_spec spec = { .level = 1 };
	struct rec_writer *w;
	struct ct ct;
	char err[256];
	uint32_t span = 0;
	int rc;

	if (!seed)
		seed = 1;
	/* tied to every built-in stage, as the daemon's recordings are */
	rc = ct_load(&ct, &spec, err, sizeof(err));
	if (rc < 0)
		return rc;
	h.map_hash = sim_stages_hash((const struct map *const *)ct.maps, ct.nmaps);
	ct_free(&ct);
	rc = rec_writer_open(out, &h, &w);
	if (rc < 0)
		return rc;
	for (uint32_t t = 0; t < ticks + 30 && rc == 0; t++) {
		if (t < 30) {
			struct sim_cmd idle = { .coins = t == 5, .buttons = t == 15 ? SIM_BT_START : 0 };

			rc = rec_writer_put(w, &idle);
			continue;
		}
		if (span-- == 0) {
			span = rp_rand(&seed) % 90;
			c.forward = rp_axis(&seed);
			c.side = rp_axis(&seed);
			c.turn = (int16_t)((int32_t)(rp_rand(&seed) % 1025) - 512);
			if (rp_rand(&seed) % 3 == 0)
				c.turn = 0;
		}
		c.buttons = rp_rand(&seed) % 16 == 0 ? SIM_BT_FIRE : 0;
		rc = rec_writer_put(w, &c);
	}
	if (rec_writer_close(w) < 0 && rc == 0)
		rc = -EIO;
	return rc;
}

/* replay --cut IN K OUT (see the top of the file). */
static int rp_cut(const char *in, uint32_t k, const char *out)
{
	struct rec_reader *rd = NULL;
	struct rec_writer *w = NULL;
	const struct rec_header *h;
	struct rec_header nh;
	struct ct_spec spec = { 0 };
	struct ct ct = { 0 };
	struct sim sim;
	struct rec_tick rt;
	uint8_t *snap = NULL;
	char err[512];
	int rc;

	rc = rec_reader_open(in, &rd, err, sizeof(err));
	if (rc < 0) {
		fprintf(stderr, "replay: %s\n", err);
		return 2;
	}
	h = rec_reader_header(rd);
	rc = 2;
	spec.level = h->level ? h->level : 1;
	if (ct_load(&ct, &spec, err, sizeof(err)) < 0) {
		fprintf(stderr, "replay: %s\n", err);
		goto out;
	}
	if (rec_check(h, sim_stages_hash((const struct map *const *)ct.maps, ct.nmaps), err,
		      sizeof(err)) < 0) {
		fprintf(stderr, "replay: %s: refused: %s\n", in, err);
		goto out;
	}
	sim_init_stages(&sim, (const struct map *const *)ct.maps, ct.nmaps, &h->set, NULL, NULL);
	sim_set_sounds(&sim, ct.sounds);
	if (h->snapshot_len && sim_restore(&sim, h->snapshot, h->snapshot_len) < 0) {
		fprintf(stderr, "replay: %s: refused: its snapshot does not fit this build\n", in);
		goto out;
	}
	for (uint32_t t = 0; t < k; t++) {
		if (rec_reader_next_tick(rd, &rt) != 1) {
			fprintf(stderr, "replay: %s: no tick %u to cut at\n", in, k);
			goto out;
		}
		sim_tick(&sim, &rt.cmd);
	}
	if (sim.mode == SIM_ATTRACT && sim.page == SIM_PAGE_DEMO) {
		fprintf(stderr, "replay: %s: tick %u shows the attract DEMO page, whose demo is "
				"not in a snapshot\n", in, k);
		goto out;
	}
	snap = malloc(sim_snapshot_size());
	if (!snap)
		goto out;
	sim_snapshot(&sim, snap);
	nh = *h;
	nh.version = REC_VERSION_3;
	nh.level = (uint8_t)spec.level;
	nh.snapshot = snap;
	nh.snapshot_len = (uint32_t)sim_snapshot_size();
	if (rec_writer_open(out, &nh, &w) < 0) {
		fprintf(stderr, "replay: %s: cannot write\n", out);
		goto out;
	}
	rc = 0;
	while (rc == 0 && rec_reader_next_tick(rd, &rt) == 1)
		rc = rec_writer_put_tick(w, &rt) < 0 ? 2 : 0;
	if (rec_writer_close(w) < 0)
		rc = 2;
out:
	free(snap);
	ct_free(&ct);
	rec_reader_close(rd);
	return rc;
}

static double rp_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

/* --balance: what happened on each stage, measured from the sim tick by
 * tick (nothing here changes it). A stage's row starts when its fighting
 * starts and ends when it is left (the intermission after an exit, or the
 * clear banner); a stage played twice (a loop) adds to its row. */
struct rp_bal {
	uint32_t ticks, damage, shots, hits, kills, deaths;
	int seen, done;
};

static void rp_bal_tick(struct rp_bal *b, int nb, const struct sim *before, const struct sim *s)
{
	int st = s->g.stage;

	if (s->mode != SIM_PLAY || before->mode != SIM_PLAY || st < 0 || st >= nb ||
	    before->g.stage != st)
		return;
	b += st;
	b->seen = 1;
	if (s->g.phase == G_PH_PLAY)
		b->ticks++;
	if (s->pl.health < before->pl.health)
		b->damage += (uint32_t)((before->pl.health - s->pl.health + FX_ONE - 1) / FX_ONE);
	/* a shot resets shot_t to 0 (then the tick's end counts it up) */
	if (s->g.shot_t < before->g.shot_t) {
		b->shots++;
		b->hits += s->g.shot == G_SHOT_ENEMY;
	}
	if (s->g.kills > before->g.kills)
		b->kills += s->g.kills - before->g.kills;
	if (s->g.phase == G_PH_DEAD && before->g.phase != G_PH_DEAD)
		b->deaths++;
	if ((s->g.phase == G_PH_INTER || s->g.phase == G_PH_CLEAR) && before->g.phase == G_PH_PLAY)
		b->done = 1;
}

int main(int argc, char **argv)
{
	static struct rp_bal bal[CT_MAX_STAGES];
	static struct sim before;
	struct rp_opts o;
	struct rec_reader *rd = NULL;
	struct rec_writer *wr = NULL;
	const struct rec_header *h;
	struct rec_verify ver;
	struct rec_run run;
	struct r_ctx *r = NULL;
	struct r_frame f = { 0 };
	struct ct ct = { 0 };
	struct ct_spec spec = { .lights = 1 };
	struct view view = { 0 };
	struct mdir meshes = { 0 };
	struct demo demo = { 0 };
	static struct hear hear;
	struct sim sim;
	char err[512];
	uint32_t t = 0, entered[SIM_MODE_COUNT] = { 0 };
	enum sim_mode mode;
	double t0;
	int rc, code = 2;

	if (argc == 5 && strcmp(argv[1], "--make-random") == 0) {
		rc = rp_make_random(argv[2], (uint32_t)strtoul(argv[3], NULL, 10),
				    (uint32_t)strtoul(argv[4], NULL, 10));
		if (rc < 0)
			fprintf(stderr, "replay: %s: %s\n", argv[2], strerror(-rc));
		return rc < 0 ? 2 : 0;
	}
	if (argc == 5 && strcmp(argv[1], "--cut") == 0)
		return rp_cut(argv[2], (uint32_t)strtoul(argv[3], NULL, 10), argv[4]);
	if (rp_args(argc, argv, &o) < 0)
		return rp_usage();
	rc = rec_reader_open(o.file, &rd, err, sizeof(err));
	if (rc < 0) {
		fprintf(stderr, "replay: %s\n", err);
		return 2;
	}
	h = rec_reader_header(rd);
	/* The run the recording asks for; options override. */
	rec_run_from_header(h, &run);
	if (o.level)
		run.level = (uint8_t)o.level;
	if (!run.level)
		run.level = 1;
	if (o.w) {
		run.render_w = (uint16_t)o.w;
		run.render_h = (uint16_t)o.h;
	} else if (!run.render_w) {
		run.render_w = RP_DEFAULT_W;
		run.render_h = RP_DEFAULT_H;
	}
	/* The same content the daemon loads (app/ct.c): the built-in
	 * stages from run.level on, with their light maps. */
	spec.level = run.level;
	/* a map from WADs, as the daemon's --wad/--map */
	for (int i = 0; i < o.nwads; i++)
		spec.wads[spec.nwads++] = o.wads[i];
	spec.map = o.map;
	spec.grid = o.grid;     /* a grid map, as the daemon's --grid */
	if (o.nwads || o.grid) {
		run.level = 0;
		run.map_name = o.map;
	}
	rc = ct_load(&ct, &spec, err, sizeof(err));
	if (rc < 0) {
		fprintf(stderr, "replay: %s\n", err);
		goto out;
	}
	run.map_hash = sim_stages_hash((const struct map *const *)ct.maps, ct.nmaps);
	if (!o.render)
		run.render_w = run.render_h = 0;
	if (!run.audio_rate)
		run.audio_rate = RP_DEFAULT_RATE;
	run.sound_hash = snd_set_hash(ct.sounds);
	rc = o.verify ? rec_check_run(h, &run, err, sizeof(err))
		      : rec_check(h, run.map_hash, err, sizeof(err));
	if (rc < 0) {
		fprintf(stderr, "replay: %s: refused: %s\n", o.file, err);
		goto out;
	}
	rec_verify_init(&ver, h, &run);
	sim_init_stages(&sim, (const struct map *const *)ct.maps, ct.nmaps, &run.set, NULL, NULL);
	sim_set_sounds(&sim, ct.sounds);
	hear_init(&hear, ct.sounds, run.audio_rate);
	if (h->snapshot_len && sim_restore(&sim, h->snapshot, h->snapshot_len) < 0) {
		fprintf(stderr, "replay: %s: refused: its start snapshot does not fit this build "
				"and content\n", o.file);
		goto out;
	}
	if (demo_init(&demo, &ct, err, sizeof(err)) < 0) {
		fprintf(stderr, "replay: %s\n", err);
		goto out;
	}
	if (o.render) {
		f.w = f.pitch = run.render_w;
		f.h = run.render_h;
		f.px = calloc((size_t)f.w * (size_t)f.h, 1);
		if (!f.px || r_new(f.w, f.h, &r) < 0 || view_init(&view, &ct, r, 0) < 0) {
			fprintf(stderr, "replay: renderer %dx%d: out of memory\n", f.w, f.h);
			goto out;
		}
		if (o.meshes) {
			/* refused and ignored files are the daemon's business (it
			 * logs them); what loads is drawn, as the daemon draws it */
			if (mdir_load(&meshes, o.meshes, NULL, NULL) < 0) {
				fprintf(stderr, "replay: game.meshes: %s: cannot be read\n", o.meshes);
				goto out;
			}
			view.meshes = &meshes.set;
		}
	}
	if (o.rehash) {
		struct rec_header nh = *h;

		nh.version = REC_VERSION_3;
		nh.hash_flags = REC_HAS_STATE | REC_HAS_AUDIO | (o.render ? REC_HAS_FRAME : 0);
		nh.render_w = (uint16_t)f.w;
		nh.render_h = (uint16_t)f.h;
		nh.render_version = REC_RENDER_VERSION;
		nh.level = run.level;
		nh.audio_rate = hear.rate;
		nh.audio_version = REC_AUDIO_VERSION;
		nh.sound_hash = snd_set_hash(ct.sounds);
		rc = rec_writer_open(o.rehash, &nh, &wr);
		if (rc < 0) {
			fprintf(stderr, "replay: %s: %s\n", o.rehash, strerror(-rc));
			goto out;
		}
	}

	code = 0;
	t0 = rp_now();
	entered[sim.mode]++;
	for (;; t++) {
		struct rec_tick rt, mine;

		if (o.until >= 0 && t > (uint64_t)o.until)
			break;
		rc = rec_reader_next_tick(rd, &rt);
		if (rc < 0)
			fprintf(stderr, "replay: %s: tick %u: %s\n", o.file, t, strerror(-rc));
		if (rc <= 0)
			break;
		mode = sim.mode;
		if (o.balance)
			before = sim;
		sim_tick(&sim, &rt.cmd);
		if (o.balance)
			rp_bal_tick(bal, ct.nmaps, &before, &sim);
		if (sim.mode != mode && (unsigned)sim.mode < SIM_MODE_COUNT)
			entered[sim.mode]++;
		demo_tick(&demo, &sim);
		/* the daemon's own mixing (app/hear.c) */
		hear_tick(&hear, &sim, demo_under(&demo, &sim));
		mine.cmd = rt.cmd;
		mine.frame_hash = 0;
		if (o.render) {
			/* the daemon's own drawing (app/view.c) */
			view_draw(&view, &sim, demo_under(&demo, &sim), &f);
			mine.frame_hash = hash_frame(f.px, f.w, f.h, f.pitch);
		}
		mine.state_hash = sim_hash(&sim);
		mine.audio_hash = hear.hash;
		if (!o.quiet)
			printf("%u %016" PRIx64 " %016" PRIx64 " %016" PRIx64 "\n", t,
			       mine.state_hash, mine.frame_hash, mine.audio_hash);
		if (o.verify)
			rec_verify_tick(&ver, t, &rt, &mine);
		if (wr) {
			if (rec_writer_put_tick(wr, &mine) < 0) {
				fprintf(stderr, "replay: %s: write failed\n", o.rehash);
				code = 2;
				break;
			}
		}
	}
	if (o.bench) {
		double el = rp_now() - t0;

		fprintf(stderr, "replay: %u ticks in %.3f s: %.0f ticks/s (%s)\n", t, el,
			el > 0 ? t / el : 0.0,
			o.render ? "rendering" : "no rendering");
	}
	for (int k = 0; o.balance && k < ct.nmaps; k++)
		if (bal[k].seen)
			printf("balance %d %s %u %u %u %u %u %u %s\n", run.level + k, ct.maps[k]->name,
			       bal[k].ticks, bal[k].damage, bal[k].shots, bal[k].hits, bal[k].kills,
			       bal[k].deaths, bal[k].done ? "cleared" : "unfinished");
	if (o.modes) {
		fprintf(stderr, "modes:");
		for (int k = 0; k < SIM_MODE_COUNT; k++)
			fprintf(stderr, " %s %u", sim_mode_name((enum sim_mode)k), entered[k]);
		fprintf(stderr, "\n");
	}
	if (o.verify) {
		rc = rec_verify_summary(&ver, err, sizeof(err));
		fprintf(stderr, "replay: %s\n", err);
		if (rc != 0 && code == 0)
			code = 1;
	}
out:
	if (wr && rec_writer_close(wr) < 0 && code == 0)
		code = 2;
	view_free(&view);
	mdir_free(&meshes);
	demo_free(&demo);
	r_free(r);
	free(f.px);
	ct_free(&ct);
	rec_reader_close(rd);
	return code;
}
