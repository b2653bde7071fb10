/*
 * rbench: frames per second of the software renderer along a recorded
 * camera path, for `make bench` (tests/bench.sh builds and runs it).
 *
 * Loads the content the recording was made on (--level N, or --wad FILE
 * --map NAME), replays the recording through the sim and draws every tick's
 * frame as the daemon does (app/view.c: the world with its sprites and
 * light maps, then the HUD), then presents it into an xrgb8888 panel of the
 * same size in memory (display/px.h, the one pass fbdev and kms use; with
 * --threads above 1 in row ranges on the same pool as the strips). Only
 * drawing and presenting are timed, not the sim. The path is replayed again until
 * --seconds of timed frames have passed (at least once). --stride K draws
 * only every K-th tick's frame (for slow renderers: the same path, fewer
 * frames).
 *
 *   rbench --rec walk.rec --level 1 --size 1280x720 --threads 2
 *
 * --renderer gl draws the world with the OSMesa renderer (engine/gl/rgl.h)
 * instead, HUD and present alike; built in only when compiled with
 * -DRBENCH_GL and the files of engine/gl/ (tests/bench.sh does when OSMesa
 * is there).
 * Its threads are llvmpipe's (LP_NUM_THREADS); --threads is ignored.
 *
 * --passes N replays the path at least N times (default 1), whatever
 * --seconds says.
 *
 * Prints one line of key=value: frames, fps (draw + present), render_fps
 * (draw only), p50_ms and p99_ms (draw + present per frame), passes,
 * p50_best_ms and p99_best_ms (the same over each frame of the path's
 * fastest time in any pass, "-" after one pass: what is left of the spread
 * when a frame another process slowed once is not counted), rss_kib (peak
 * resident set), priv_kib (private memory at the end: anonymous and private
 * dirty pages, smaps_rollup), hash (of every frame of the first pass and of every 16th
 * presented panel: equal for any --threads).
 *
 * rbench --capacity N prints capacity=X: how many times faster N threads
 * run pure integer work than one, on this machine as it is now (a check of
 * what the thread figures can show), and mem_capacity=Y: the same for
 * filling memory.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "app/ct.h"
#include "app/pool.h"
#include "app/view.h"
#include "display/px.h"
#include "display/shot.h"
#include "engine/game/g_game.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/render/r_game.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud.h"
#include "input/rec.h"
#ifdef RBENCH_GL
#include "engine/gl/rgl.h"

/* view_draw (app/view.c) with the OSMesa renderer for the world. */
static void draw_gl(struct rgl_ctx *g, struct view *v, const struct sim *s, struct r_frame *f)
{
	struct tex_set *tex = v->ct->tex;
	struct hud_env env = { &tex->pal, tex, v->rotate, v->par, v->diag, NULL, &v->colours };
	struct r_view rv;

	tex_animate(tex, s->tick);
	if (hud_world(s)) {
		int n = r_game_sprites(s, tex, NULL, v->spr, v->spr_max);

		r_game_view(s, f->w, &rv);
		rgl_render(g, s->map, tex, &rv, v->spr, n, f);
	}
	hud_draw(s, &env, f);
}
#endif

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* A fast hash of a frame (64-bit words, multiply-xorshift): only to see
 * that thread counts give the same frames. */
static uint64_t frame_hash(uint64_t h, const uint8_t *p, size_t n)
{
	size_t i = 0;

	for (; i + 8 <= n; i += 8) {
		uint64_t v;

		memcpy(&v, p + i, 8);
		h = (h ^ v) * 0x9e3779b97f4a7c15ull;
		h ^= h >> 29;
	}
	for (; i < n; i++)
		h = (h ^ p[i]) * 0x100000001b3ull;
	return h;
}

/* --capacity: 8 jobs of pure integer work (no memory) on a pool of 1
 * thread, then of n: how much faster n threads compute on this machine as
 * it is now. On an idle machine with n cores, about n; another process, a
 * cgroup share or hyperthread siblings make it less, and then no renderer
 * can scale either. */
static void spin_job(void *arg, int i)
{
	uint64_t x = (uint64_t)i + 1;

	for (long k = 0; k < 20000000; k++)
		x = x * 6364136223846793005ull + 1442695040888963407ull;
	((volatile uint64_t *)arg)[i] = x;
}

/* The same for memory: each of 8 jobs fills its own 8 MiB buffer 16
 * times (1 GiB in all, far past the caches). Two threads on an idle
 * machine write about twice as fast as one; a neighbour saturating the
 * memory system (in a VM, another tenant) makes it less, and the renderer
 * at large sizes, which mostly writes memory, can then scale no better. */
#define CAP_MEM (8u << 20)

static void mem_job(void *arg, int i)
{
	uint8_t *b = ((uint8_t **)arg)[i];

	for (int k = 0; k < 16; k++) {
		memset(b, k + i, CAP_MEM);
		__asm__ __volatile__("" : : "r"(b) : "memory");
	}
}

static int capacity(int n)
{
	uint64_t out[8], t[2], m[2];
	uint8_t *bufs[8];
	struct pool *p;

	for (int i = 0; i < 8; i++) {
		bufs[i] = malloc(CAP_MEM);
		if (!bufs[i])
			return 1;
		memset(bufs[i], 1, CAP_MEM);
	}
	for (int k = 0; k < 2; k++) {
		if (pool_new(k ? n : 1, &p) < 0)
			return 1;
		t[k] = now_ns();
		pool_run(p, 8, spin_job, out);
		t[k] = now_ns() - t[k];
		m[k] = now_ns();
		pool_run(p, 8, mem_job, bufs);
		m[k] = now_ns() - m[k];
		pool_free(p);
	}
	printf("capacity=%.2f mem_capacity=%.2f threads=%d\n", (double)t[0] / (double)t[1],
	       (double)m[0] / (double)m[1], n);
	for (int i = 0; i < 8; i++)
		free(bufs[i]);
	return 0;
}

/* This process's private memory now: anonymous and private dirty pages
 * from /proc/self/smaps_rollup, as max(Anonymous, Private_Dirty) (anonymous
 * pages are private dirty too: their sum would count them twice); -1 when
 * it cannot be read. */
static long private_kib(void)
{
	FILE *f = fopen("/proc/self/smaps_rollup", "re");
	char line[256];
	long anon = -1, dirty = -1, v;

	if (!f)
		return -1;
	while (fgets(line, sizeof(line), f)) {
		if (sscanf(line, "Anonymous: %ld kB", &v) == 1)
			anon = v;
		else if (sscanf(line, "Private_Dirty: %ld kB", &v) == 1)
			dirty = v;
	}
	fclose(f);
	return anon < 0 || dirty < 0 ? -1 : anon > dirty ? anon : dirty;
}

static int cmp_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;

	return x < y ? -1 : x > y;
}

/* The pct-th percentile of n sorted times, in ms. */
static double ms_at(const uint64_t *sorted, size_t n, int pct)
{
	return (double)sorted[n * (size_t)pct / 100] / 1e6;
}

static int usage(void)
{
	fprintf(stderr, "usage: rbench --rec FILE (--level N | --wad FILE --map NAME) "
		"--size WxH [--threads N] [--seconds S] [--passes N] [--stride K] "
		"[--shot PNG] "
		"[--renderer sw|gl]\n       rbench --capacity N\n");
	return 2;
}

int main(int argc, char **argv)
{
	struct ct_spec spec = { 0 };
	struct ct ct;
	const char *recpath = NULL, *shot = NULL, *renderer = "sw";
	int w = 320, h = 240, threads = 1, stride = 1, minpasses = 1, pass, rc;
	double seconds = 1.0;
	char err[512] = "";
	struct rec_reader *rr;
	struct rec_header hdr;
	struct sim_cmd *cmds = NULL;
	size_t ncmds = 0, capcmds = 0;
	struct sim *sim;
	struct r_ctx *r;
	struct pool *pool = NULL;
	struct r_par par;
	struct px_par ppar;
	struct view view;
	struct r_frame f;
	struct px_panel *panel;
	struct px_format fmt;
	uint8_t *mem;
	uint64_t *times = NULL, *best = NULL, hash = 0x243f6a8885a308d3ull, total = 0, rtotal = 0;
	size_t nt = 0, capt = 0, nbest;
	char bests[64] = "p50_best_ms=- p99_best_ms=-";
	struct rusage ru;
#ifdef RBENCH_GL
	struct rgl_ctx *gl = NULL;
#endif

	/* options come in pairs */
	for (int i = 1; i < argc; i += 2) {
		const char *a = argv[i], *b = i + 1 < argc ? argv[i + 1] : NULL;

		if (!b)
			return usage();
		if (!strcmp(a, "--capacity"))
			return capacity(atoi(b) > 0 ? atoi(b) : 1);
		if (!strcmp(a, "--rec"))
			recpath = b;
		else if (!strcmp(a, "--level"))
			spec.level = atoi(b);
		else if (!strcmp(a, "--wad") && spec.nwads < CT_MAX_WADS)
			spec.wads[spec.nwads++] = b;
		else if (!strcmp(a, "--map"))
			spec.map = b;
		else if (!strcmp(a, "--size") && sscanf(b, "%dx%d", &w, &h) == 2)
			;
		else if (!strcmp(a, "--threads"))
			threads = atoi(b);
		else if (!strcmp(a, "--seconds"))
			seconds = atof(b);
		else if (!strcmp(a, "--passes") && atoi(b) >= 1)
			minpasses = atoi(b);
		else if (!strcmp(a, "--shot"))
			shot = b;
		else if (!strcmp(a, "--stride") && atoi(b) >= 1)
			stride = atoi(b);
		else if (!strcmp(a, "--renderer"))
			renderer = b;
		else
			return usage();
	}
	if (!recpath)
		return usage();
#ifdef RBENCH_GL
	if (strcmp(renderer, "sw") != 0 && strcmp(renderer, "gl") != 0)
		return usage();
#else
	if (strcmp(renderer, "sw") != 0) {
		fprintf(stderr, "rbench: built without the OSMesa renderer\n");
		return 2;
	}
#endif
	if (spec.nwads == 0 && spec.level == 0)
		spec.level = 1;
	spec.lights = 1;
	rc = ct_load(&ct, &spec, err, sizeof(err));
	if (rc < 0) {
		fprintf(stderr, "rbench: %s\n", err);
		return 1;
	}
	rc = rec_reader_open(recpath, &rr, err, sizeof(err));
	if (rc < 0) {
		fprintf(stderr, "rbench: %s: %s\n", recpath, err[0] ? err : strerror(-rc));
		return 1;
	}
	hdr = *rec_reader_header(rr);
	if (rec_check(&hdr, sim_stages_hash((const struct map *const *)ct.maps, ct.nmaps), err,
		      sizeof(err)) < 0) {
		fprintf(stderr, "rbench: %s: %s\n", recpath, err);
		return 1;
	}
	for (;;) {
		struct sim_cmd c;

		if (rec_reader_next(rr, &c) <= 0)
			break;
		if (ncmds == capcmds) {
			capcmds = capcmds ? 2 * capcmds : 1024;
			cmds = realloc(cmds, capcmds * sizeof(*cmds));
			if (!cmds)
				return 1;
		}
		cmds[ncmds++] = c;
	}
	rec_reader_close(rr);
	if (ncmds == 0) {
		fprintf(stderr, "rbench: %s: no ticks\n", recpath);
		return 1;
	}

	sim = malloc(sizeof(*sim));
	panel = malloc(sizeof(*panel));
	f.w = f.pitch = w;
	f.rec = NULL;
	f.h = h;
	/* 64-byte aligned frame and panel: strips never share a cache line */
	f.px = aligned_alloc(64, ((size_t)w * (size_t)h + 63) / 64 * 64);
	mem = aligned_alloc(64, ((size_t)w * (size_t)h * 4 + 63) / 64 * 64);
	if (!sim || !panel || !f.px || !mem || r_new(w, h, &r) < 0 ||
	    view_init(&view, &ct, r, 0) < 0)
		return 1;
#ifdef RBENCH_GL
	if (strcmp(renderer, "gl") == 0) {
		rc = rgl_new(w, h, &gl, err, sizeof(err));
		if (rc < 0) {
			fprintf(stderr, "rbench: OSMesa: %s\n", err[0] ? err : strerror(-rc));
			return 1;
		}
		threads = 0;
	}
#endif
	if (threads > 1) {
		rc = pool_new(threads, &pool);
		if (rc < 0) {
			fprintf(stderr, "rbench: pool of %d: %s\n", threads, strerror(-rc));
			return 1;
		}
		/* as the daemon does with a thread per CPU (app/scene.c) */
		if (threads == pool_cpus())
			pool_pin(pool);
		pool_r_par(pool, &par);
		r_set_par(r, &par);
		view.par = &par;
	}
	if (px_format_by_name("xrgb8888", &fmt) < 0 ||
	    px_panel_init(panel, &fmt, w, h, (size_t)w * 4, 0, 0, w, h) < 0)
		return 1;
	px_panel_palette(panel, ct.tex->pal.rgb);
	if (pool) {
		/* the present in row ranges on the same pool, as the daemon's */
		pool_px_par(pool, &ppar);
		px_panel_set_par(panel, &ppar);
	}

	/* each drawn frame's fastest time over the passes */
	nbest = (ncmds + (size_t)stride - 1) / (size_t)stride;
	best = malloc(nbest * sizeof(*best));
	if (!best)
		return 1;
	for (size_t k = 0; k < nbest; k++)
		best[k] = UINT64_MAX;
	for (pass = 0; pass < minpasses || (double)total < seconds * 1e9; pass++) {
		sim_init_stages(sim, (const struct map *const *)ct.maps, ct.nmaps, &hdr.set, NULL,
				NULL);
		for (size_t k = 0; k < ncmds; k++) {
			uint64_t t0, t1, t2;

			sim_tick(sim, &cmds[k]);
			if (k % (size_t)stride)
				continue;
			t0 = now_ns();
#ifdef RBENCH_GL
			if (gl)
				draw_gl(gl, &view, sim, &f);
			else
#endif
				view_draw(&view, sim, NULL, &f);
			t1 = now_ns();
			px_panel_draw(panel, mem, f.px, w, h, w);
			t2 = now_ns();
			if (nt == capt) {
				capt = capt ? 2 * capt : 4096;
				times = realloc(times, capt * sizeof(*times));
				if (!times)
					return 1;
			}
			times[nt++] = t2 - t0;
			if (t2 - t0 < best[k / (size_t)stride])
				best[k / (size_t)stride] = t2 - t0;
			total += t2 - t0;
			rtotal += t1 - t0;
			if (pass == 0)
				hash = frame_hash(hash, f.px, (size_t)w * (size_t)h);
			/* and the presented panel, every 16th frame (hashing
			 * all of them would take longer than the run) */
			if (pass == 0 && k % 16 == 0)
				hash = frame_hash(hash, mem, (size_t)w * (size_t)h * 4);
		}
	}
	if (shot && shot_png(shot, f.px, w, h, w, ct.tex->pal.rgb) < 0)
		fprintf(stderr, "rbench: %s: cannot write\n", shot);
	qsort(times, nt, sizeof(*times), cmp_u64);
	if (pass > 1) {
		qsort(best, nbest, sizeof(*best), cmp_u64);
		snprintf(bests, sizeof(bests), "p50_best_ms=%.3f p99_best_ms=%.3f",
			 ms_at(best, nbest, 50), ms_at(best, nbest, 99));
	}
	getrusage(RUSAGE_SELF, &ru);
	printf("frames=%zu fps=%.1f render_fps=%.1f p50_ms=%.3f p99_ms=%.3f passes=%d %s "
	       "rss_kib=%ld priv_kib=%ld hash=%016" PRIx64 " threads=%d\n",
	       nt, (double)nt * 1e9 / (double)total, (double)nt * 1e9 / (double)rtotal,
	       ms_at(times, nt, 50), ms_at(times, nt, 99), pass, bests,
	       ru.ru_maxrss, private_kib(), hash, threads);
#ifdef RBENCH_GL
	rgl_free(gl);
#endif
	view_free(&view);
	pool_free(pool);
	r_free(r);
	ct_free(&ct);
	free(times);
	free(best);
	free(cmds);
	free(sim);
	free(panel);
	free(f.px);
	free(mem);
	return 0;
}
