/*
 * xcheck: renders maps from seeded viewpoints with both renderers, the
 * software one (engine/render/r_main.h) and the OSMesa one (engine/gl/rgl.h), in
 * surface-id mode, and prints per view and per map how many pixels show
 * the same surface. Views below the threshold fail the run and get a
 * difference image: software frame | OSMesa frame | the software frame
 * dimmed with disagreeing pixels in red.
 *
 * Two ids agree when they are equal after one normalisation: a floor (or
 * ceiling) id names the lowest-numbered sector whose floor (ceiling) has the
 * same height, flat and light, since the software renderer's visplanes merge
 * such sectors and they look identical (docs/crosscheck.md).
 *
 *   xcheck [--builtin] [--grid builtin|FILE] [--wad FILE [--map NAME]]...
 *          [--views N] [--seed S] [--size WxH] [--min PCT] [--diff DIR]
 *          [--diff-all] [--no-sprites] [--verbose] [--view K] [--probe X,Y]
 *          [--cover PCT] [--blank-ids] [--movers]
 *
 * --builtin: every built-in level (palette-colour set); --grid: a grid map
 * with the built-in texture set; --wad: every map of the WAD (or --map),
 * each WAD on its own. Content options may repeat; the other options apply
 * to all. Views: a random point inside a sector at least 16 units from
 * every one-sided or blocking line, in a sector at least 56 units tall,
 * not within a thing's radius plus 16,
 * eye 41 above the floor, a random angle, and a random shear within h/4 in
 * one view of four. The map's things are drawn as sprites. --view K runs
 * only view K of each map (the same viewpoint as in a full run), --probe
 * prints both renderers' ids at one pixel, --verbose every view and the
 * disagreeing pixels by kind. --movers replaces the random views by the
 * mover views (tests/crosscheck/xc_move.h): door sectors a quarter, half
 * and three quarters open and lift sectors as far down, each view with
 * that one sector's heights set in the map both renderers draw (and put
 * back after). Exit status 0
 * when every view reaches --min (default 99.5), 1 otherwise, 2 on bad
 * arguments or content.
 *
 * Two empty id buffers agree everywhere, which would prove nothing: a view
 * fails too when either renderer gave fewer than --cover PCT (default 99)
 * of its pixels a surface (id kind other than "none"); every view from
 * inside a closed map shows some surface at every pixel. --blank-ids
 * clears both buffers after rendering, a self-test of that rule
 * (tests/crosscheck/run.sh expects it to fail).
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "app/ct.h"
#include "display/shot.h"
#include "engine/core/pal.h"
#include "engine/gl/rgl.h"
#include "engine/map/grid.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"
#include "engine/map/wad.h"
#include "engine/render/r_game.h"
#include "engine/render/r_id.h"
#include "engine/render/r_main.h"
#include "tests/crosscheck/xc_mesh.h"
#include "tests/crosscheck/xc_move.h"

#define XC_MAX_SETS 16
#define XC_MAX_MAPS 64

struct xc_set {
	char kind;                      /* 'b' built-in, 'g' grid, 'w' WAD */
	const char *arg;                /* grid or WAD file */
	const char *map;                /* --map, or NULL for all */
};

struct xc_opts {
	struct xc_set sets[XC_MAX_SETS];
	int nsets;
	int views, w, h, sprites, verbose, diff_all;
	int only_view;                  /* --view K: only view K of each map, or -1 */
	int movers;                     /* --movers: the mover views, not random ones */
	int meshes;                     /* --meshes: the mesh views, not random ones */
	double mesh_min;                /* --mesh-min PCT: least agreement on a mesh
					 * view's mesh pixels */
	long mesh_least;                /* --mesh-least N: mesh pixels a mesh view
					 * needs for that rule to apply */
	int blank;                      /* --blank-ids: clear the id buffers (self-test) */
	double cover;                   /* --cover PCT: least share of pixels with a surface */
	int probe_x, probe_y;           /* --probe X,Y: print both ids there, or -1 */
	uint64_t seed;
	double min;
	const char *diff;
};

/* One renderer pair at one size, and the buffers of a view. */
struct xc_run {
	const struct xc_opts *o;
	struct r_ctx *sw;
	struct rgl_ctx *gl;
	struct r_frame fs, fg;
	uint32_t *ids_sw, *ids_gl;
	uint8_t *diffpx;
	double t_sw, t_gl;
	long views, failed;
	double set_min, set_sum;
	uint64_t set_mesh_px, set_mesh_same;   /* mesh_px, mesh_same at the set's start */
	long set_views;
	double cover_min;               /* the least surface coverage of any view, % */
	uint64_t kinds[R_IDK_COUNT][R_IDK_COUNT];   /* disagreements: sw kind, gl kind */
	/* mesh pixels (either renderer shows a mesh there) of every view, and
	 * of those where both show the same surface; mesh views without any */
	uint64_t mesh_px, mesh_same;
	long mesh_blind;
	double mesh_worst;              /* the least agreement on a mesh view's
					 * mesh pixels, % */
};

static double xc_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static uint64_t xc_rand(uint64_t *s)
{
	/* splitmix64 */
	uint64_t z = (*s += 0x9e3779b97f4a7c15ull);

	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

/* The file at path, or NULL (ct_read_file, app/ct.h). */
static uint8_t *slurp(const char *path, size_t *len)
{
	uint8_t *d = NULL;

	return ct_read_file(path, &d, len) == 0 ? d : NULL;
}

/* Distance (map units) from (x, y) to the segment of line l. */
int xc_clear_of_things(const struct map *m, double x, double y)
{
	/* a player stands at least its radius plus its own (16) away from a
	 * thing's centre */
	for (uint32_t i = 0; i < m->num_things; i++) {
		const struct th_info *in = th_find(m->things[i].type);
		double dx = m->things[i].x / 65536.0 - x, dy = m->things[i].y / 65536.0 - y;
		double r = in ? in->radius + 16.0 : 32.0;

		if (in && (in->flags & (TH_PLAYER | TH_INVISIBLE)))
			continue;
		if (dx * dx + dy * dy < r * r)
			return 0;
	}
	return 1;
}

double xc_line_dist(const struct map *m, const struct map_line *l, double x, double y)
{
	double ax = m->vertices[l->v1].x / 65536.0, ay = m->vertices[l->v1].y / 65536.0;
	double bx = m->vertices[l->v2].x / 65536.0, by = m->vertices[l->v2].y / 65536.0;
	double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
	double t = len2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0;

	t = t < 0 ? 0 : t > 1 ? 1 : t;
	dx = ax + t * dx - x;
	dy = ay + t * dy - y;
	return dx * dx + dy * dy;
}

/* 1 when (x, y) lies inside sector s's polygon (even-odd rule over the
 * lines with exactly one side facing s), in a sector tall enough to stand
 * in, far enough from walls. */
static int xc_viewpoint_ok(const struct map *m, uint32_t s, double x, double y)
{
	const struct map_sector *sec = &m->sectors[s];
	int inside = 0;

	if (sec->ceil_h - sec->floor_h < 56 * FX_ONE)
		return 0;
	if (!xc_clear_of_things(m, x, y))
		return 0;
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		uint32_t s0 = m->sides[l->side[0]].sector;
		uint32_t s1 = l->side[1] == MAP_NONE ? MAP_NONE : m->sides[l->side[1]].sector;
		double ay = m->vertices[l->v1].y / 65536.0, by = m->vertices[l->v2].y / 65536.0;
		double ax = m->vertices[l->v1].x / 65536.0, bx = m->vertices[l->v2].x / 65536.0;
		double d2 = xc_line_dist(m, l, x, y);

		if (d2 < 1.0 || ((s1 == MAP_NONE || (l->flags & ML_BLOCKING)) && d2 < 16.0 * 16.0))
			return 0;
		if ((s0 == s) == (s1 == s))
			continue;
		if ((ay > y) != (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay))
			inside ^= 1;
	}
	return inside;
}

/* View k of map m: 0, or -1 when no viewpoint was found. */
static int xc_view(const struct map *m, uint64_t *rng, int h, struct r_view *v)
{
	fx_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;

	for (uint32_t i = 0; i < m->num_vertices; i++) {
		x0 = m->vertices[i].x < x0 ? m->vertices[i].x : x0;
		y0 = m->vertices[i].y < y0 ? m->vertices[i].y : y0;
		x1 = m->vertices[i].x > x1 ? m->vertices[i].x : x1;
		y1 = m->vertices[i].y > y1 ? m->vertices[i].y : y1;
	}
	for (int tries = 0; tries < 20000; tries++) {
		fx_t x = (fx_t)(x0 + (int64_t)(xc_rand(rng) % ((uint64_t)x1 - (uint64_t)x0 + 1)));
		fx_t y = (fx_t)(y0 + (int64_t)(xc_rand(rng) % ((uint64_t)y1 - (uint64_t)y0 + 1)));
		uint32_t s = map_point_sector(m, x, y);

		if (!xc_viewpoint_ok(m, s, x / 65536.0, y / 65536.0))
			continue;
		v->x = x;
		v->y = y;
		v->z = m->sectors[s].floor_h + 41 * FX_ONE;
		v->angle = (ang_t)xc_rand(rng);
		v->shear = 0;
		if (xc_rand(rng) % 4 == 0)
			v->shear = (int32_t)(xc_rand(rng) % (uint64_t)(h / 2 + 1)) - h / 4;
		return 0;
	}
	return -1;
}

/* Normalises an id: floors and ceilings to the lowest sector that looks
 * the same (see the top of this file). */
static uint32_t xc_norm(uint32_t id, const uint32_t *cf, const uint32_t *cc, uint32_t nsec)
{
	enum r_id_kind k = r_id_kind(id);
	uint32_t i = r_id_index(id);

	if (k == R_IDK_FLOOR && i < nsec)
		return r_id(k, cf[i]);
	if (k == R_IDK_CEIL && i < nsec)
		return r_id(k, cc[i]);
	return id;
}

static int xc_canon(const struct map *m, uint32_t **cf, uint32_t **cc)
{
	uint32_t n = m->num_sectors;

	*cf = malloc((size_t)n * sizeof(**cf));
	*cc = malloc((size_t)n * sizeof(**cc));
	if (!*cf || !*cc)
		return -ENOMEM;
	for (uint32_t i = 0; i < n; i++) {
		const struct map_sector *a = &m->sectors[i];

		(*cf)[i] = (*cc)[i] = i;
		for (uint32_t j = 0; j < i; j++) {
			const struct map_sector *b = &m->sectors[j];

			if ((*cf)[i] == i && a->floor_h == b->floor_h &&
			    a->floor_tex == b->floor_tex && a->light == b->light)
				(*cf)[i] = j;
			if ((*cc)[i] == i && a->ceil_h == b->ceil_h && a->ceil_tex == b->ceil_tex &&
			    a->light == b->light)
				(*cc)[i] = j;
		}
	}
	return 0;
}

static void xc_diff_image(struct xc_run *x, const struct tex_set *t, const char *name, int k,
			  const uint32_t *cf, const uint32_t *cc, uint32_t nsec, char *path,
			  size_t plen)
{
	int w = x->o->w, h = x->o->h;
	uint8_t red = pal_nearest(&t->pal, 255, 0, 0);
	char clean[64];
	int i;

	for (i = 0; name[i] && i < (int)sizeof(clean) - 1; i++)
		clean[i] = (name[i] == '/' || name[i] == ' ' || name[i] == '.') ? '-' : name[i];
	clean[i] = 0;
	snprintf(path, plen, "%s/%s-view%02d.png", x->o->diff, clean, k);
	for (int y = 0; y < h; y++) {
		uint8_t *row = x->diffpx + (size_t)y * (size_t)w * 3;

		for (int c = 0; c < w; c++) {
			size_t p = (size_t)y * (size_t)w + (size_t)c;
			int same = xc_norm(x->ids_sw[p], cf, cc, nsec) ==
				   xc_norm(x->ids_gl[p], cf, cc, nsec);

			row[c] = x->fs.px[p];
			row[w + c] = x->fg.px[p];
			row[2 * w + c] = same ? t->pal.cmap[20][x->fs.px[p]] : red;
		}
	}
	mkdir(x->o->diff, 0755);
	if (shot_png(path, x->diffpx, 3 * w, h, 3 * w, t->pal.rgb) < 0)
		fprintf(stderr, "xcheck: %s: cannot write\n", path);
}

/* 1 when (normalised) id a shows one of the meshes of spr. */
static int xc_is_mesh(uint32_t a, const struct r_sprite *spr, int nspr)
{
	return r_id_kind(a) == R_IDK_SPRITE && r_id_index(a) < (uint32_t)nspr &&
	       spr[r_id_index(a)].mesh != 0;
}

/* Renders view v (number k of map name, described by what: "" for a random
 * view) with both renderers and compares the ids; counts the view and its
 * failures in x. Returns the share of agreeing pixels, %. */
static double xc_one(struct xc_run *x, const struct map *m, const struct tex_set *t,
		     const char *name, int k, const struct r_view *vp, const struct r_sprite *spr,
		     int nspr, const uint32_t *cf, const uint32_t *cc, const char *what)
{
	const struct xc_opts *o = x->o;
	size_t npx = (size_t)o->w * (size_t)o->h;
	struct r_view v = *vp;
	long same = 0, csame = 0, sur_sw = 0, sur_gl = 0, mpx = 0, msame = 0;
	double pct, t0, cover;

	t0 = xc_now();
	r_render(x->sw, m, t, &v, spr, nspr, &x->fs);
	x->t_sw += xc_now() - t0;
	t0 = xc_now();
	rgl_render(x->gl, m, t, &v, spr, nspr, &x->fg);
	x->t_gl += xc_now() - t0;
	if (o->blank) {
		memset(x->ids_sw, 0, npx * sizeof(*x->ids_sw));
		memset(x->ids_gl, 0, npx * sizeof(*x->ids_gl));
	}
	for (size_t p = 0; p < npx; p++) {
		sur_sw += r_id_kind(x->ids_sw[p]) != R_IDK_NONE;
		sur_gl += r_id_kind(x->ids_gl[p]) != R_IDK_NONE;
	}
	cover = 100.0 * (double)(sur_sw < sur_gl ? sur_sw : sur_gl) / (double)npx;
	if (cover < x->cover_min)
		x->cover_min = cover;
	if (cover < o->cover) {
		printf("FAIL %s view %d%s at (%.1f, %.1f): surfaces on %.3f%% of the software "
		       "and %.3f%% of the OSMesa pixels, < %.2f%%: an (almost) empty id "
		       "buffer proves nothing\n",
		       name, k, what, v.x / 65536.0, v.y / 65536.0,
		       100.0 * (double)sur_sw / (double)npx, 100.0 * (double)sur_gl / (double)npx,
		       o->cover);
		x->failed++;
	}
	for (size_t p = 0; p < npx; p++) {
		uint32_t a = xc_norm(x->ids_sw[p], cf, cc, m->num_sectors);
		uint32_t b = xc_norm(x->ids_gl[p], cf, cc, m->num_sectors);

		if (xc_is_mesh(a, spr, nspr) || xc_is_mesh(b, spr, nspr)) {
			mpx++;
			msame += a == b;
		}
		if (a == b)
			same++;
		else if (r_id_kind(a) < R_IDK_COUNT && r_id_kind(b) < R_IDK_COUNT)
			x->kinds[r_id_kind(a)][r_id_kind(b)]++;
		csame += x->fs.px[p] == x->fg.px[p];
	}
	pct = 100.0 * (double)same / (double)npx;
	x->mesh_px += (uint64_t)mpx;
	x->mesh_same += (uint64_t)msame;
	if (o->meshes && mpx < o->mesh_least)
		x->mesh_blind++;
	if (o->meshes && mpx > 0 && mpx >= o->mesh_least) {
		double mp = 100.0 * (double)msame / (double)mpx;

		x->mesh_worst = mp < x->mesh_worst ? mp : x->mesh_worst;
		if (o->verbose)
			printf("  %-26s view %2d%s: mesh pixels %ld, %.2f%% agree\n", name, k, what,
			       mpx, mp);
		if (mp < o->mesh_min) {
			printf("FAIL %s view %d%s at (%.1f, %.1f) angle %.1f: the mesh pixels agree "
			       "on %.2f%% (%ld of %ld) < %.2f%%\n",
			       name, k, what, v.x / 65536.0, v.y / 65536.0,
			       v.angle * (360.0 / 4294967296.0), 100.0 * (double)msame / (double)mpx,
			       msame, mpx, o->mesh_min);
			x->failed++;
		}
	}
	if (o->probe_x >= 0 && o->probe_x < o->w && o->probe_y >= 0 && o->probe_y < o->h) {
		size_t p = (size_t)o->probe_y * (size_t)o->w + (size_t)o->probe_x;

		printf("  probe (%d, %d): software kind %u index %u, OSMesa kind %u index %u\n",
		       o->probe_x, o->probe_y, r_id_kind(x->ids_sw[p]), r_id_index(x->ids_sw[p]),
		       r_id_kind(x->ids_gl[p]), r_id_index(x->ids_gl[p]));
	}
	if (o->verbose)
		printf("  %-26s view %2d%s at (%.1f, %.1f) angle %.1f shear %d: ids %.3f%%, "
		       "pixels %.2f%%\n",
		       name, k, what, v.x / 65536.0, v.y / 65536.0, v.angle * (360.0 / 4294967296.0),
		       v.shear, pct, 100.0 * (double)csame / (double)npx);
	if (pct < o->min || (o->diff_all && o->diff)) {
		char path[512] = "(no --diff)";

		if (o->diff)
			xc_diff_image(x, t, name, k, cf, cc, m->num_sectors, path, sizeof(path));
		if (pct < o->min) {
			printf("FAIL %s view %d%s at (%.1f, %.1f) angle %.1f shear %d: %.3f%% < "
			       "%.2f%%; difference image %s\n",
			       name, k, what, v.x / 65536.0, v.y / 65536.0,
			       v.angle * (360.0 / 4294967296.0), v.shear, pct, o->min, path);
			x->failed++;
		}
	}
	x->views++;
	return pct;
}

/* Adds one view's agreement to a map's figures. */
static void xc_tally(double pct, int k, double *worst, int *wk, double *sum, int *nv)
{
	if (pct < *worst) {
		*worst = pct;
		*wk = k;
	}
	*sum += pct;
	(*nv)++;
}

/* The mover views of map m (xc_move.h): each sets its sector's heights,
 * renders, and puts them back. */
static void xc_movers(struct xc_run *x, struct map *m, const struct tex_set *t, const char *name,
		      const struct r_sprite *spr, int nspr, double *worst, int *wk, double *sum,
		      int *nv, int *ndoor)
{
	int n = xcm_views(m, NULL, 0);
	struct xcm_view *mv = n > 0 ? calloc((size_t)n, sizeof(*mv)) : NULL;

	if (n < 0 || (n > 0 && !mv)) {
		fprintf(stderr, "xcheck: out of memory\n");
		exit(2);
	}
	xcm_views(m, mv, n);
	for (int k = 0; k < n; k++) {
		struct map_sector *sec = &m->sectors[mv[k].sector];
		fx_t f = sec->floor_h, c = sec->ceil_h;
		uint32_t *cf = NULL, *cc = NULL;
		char what[80];

		if (x->o->only_view >= 0 && k != x->o->only_view)
			continue;
		snprintf(what, sizeof(what), " (%s sector %u at %d/4)",
			 mv[k].kind == 'd' ? "door" : "lift", mv[k].sector, mv[k].quarter);
		sec->floor_h = mv[k].floor_h;
		sec->ceil_h = mv[k].ceil_h;
		/* the normalisation compares heights: made for these ones */
		if (xc_canon(m, &cf, &cc) < 0) {
			fprintf(stderr, "xcheck: out of memory\n");
			exit(2);
		}
		xc_tally(xc_one(x, m, t, name, k, &mv[k].v, spr, nspr, cf, cc, what), k, worst, wk,
			 sum, nv);
		*ndoor += mv[k].kind == 'd';
		sec->floor_h = f;
		sec->ceil_h = c;
		free(cf);
		free(cc);
	}
	free(mv);
}

/* The mesh views of map m (xc_mesh.h), the things spr[0..nspr-1] made by
 * r_map_things (remade at each view's tick). */
static void xc_meshes(struct xc_run *x, const struct map *m, const struct tex_set *t,
		      const char *name, struct r_sprite *spr, int nspr, const uint32_t *cf,
		      const uint32_t *cc, double *worst, int *wk, double *sum, int *nv)
{
	int n = xcx_views(m, spr, nspr, NULL, 0);
	struct xcx_view *mv = n > 0 ? calloc((size_t)n, sizeof(*mv)) : NULL;

	if (n < 0 || (n > 0 && !mv)) {
		fprintf(stderr, "xcheck: out of memory\n");
		exit(2);
	}
	xcx_views(m, spr, nspr, mv, n);
	for (int k = 0; k < n; k++) {
		char what[40];

		if (x->o->only_view >= 0 && k != x->o->only_view)
			continue;
		snprintf(what, sizeof(what), " (mesh %d, tick %u)", mv[k].sprite, mv[k].tick);
		nspr = r_map_things(m, t, mv[k].tick, spr);
		xc_tally(xc_one(x, m, t, name, k, &mv[k].v, spr, nspr, cf, cc, what), k, worst, wk,
			 sum, nv);
	}
	free(mv);
}

/* Every view of one map: --views random ones, or with --movers the mover
 * views. The map's sector heights are changed and restored by the mover
 * views. Returns the worst agreement. */
static double xc_map(struct xc_run *x, struct map *m, const struct tex_set *t, const char *name)
{
	const struct xc_opts *o = x->o;
	struct r_sprite *spr = calloc(m->num_things + 1, sizeof(*spr));
	uint64_t rng = o->seed;
	uint32_t *cf = NULL, *cc = NULL;
	double worst = 100, sum = 0;
	int nspr, nv = 0, wk = -1, ndoor = 0;

	if (!spr || xc_canon(m, &cf, &cc) < 0) {
		fprintf(stderr, "xcheck: out of memory\n");
		exit(2);
	}
	for (const char *c = name; *c; c++)
		rng = (rng ^ (uint8_t)*c) * 0x100000001b3ull;
	nspr = o->sprites ? r_map_things(m, t, 0, spr) : 0;
	if (o->meshes)
		xc_meshes(x, m, t, name, spr, nspr, cf, cc, &worst, &wk, &sum, &nv);
	for (int k = 0; k < o->views && !o->movers && !o->meshes; k++) {
		struct r_view v;

		if (xc_view(m, &rng, o->h, &v) < 0) {
			printf("%-28s no viewpoint found\n", name);
			x->failed++;
			break;
		}
		if (o->only_view >= 0 && k != o->only_view)
			continue;
		/* the meshes turned as at a tick of the view's own */
		nspr = o->sprites ? r_map_things(m, t, (uint32_t)(7 * k + 3), spr) : 0;
		xc_tally(xc_one(x, m, t, name, k, &v, spr, nspr, cf, cc, ""), k, &worst, &wk, &sum,
			 &nv);
	}
	if (o->movers)
		xc_movers(x, m, t, name, spr, nspr, &worst, &wk, &sum, &nv, &ndoor);
	if (nv > 0 && o->meshes)
		printf("%-28s %3d mesh views  min %7.3f%% (view %d)  mean %7.3f%%\n", name, nv, worst,
		       wk, sum / nv);
	else if (nv > 0 && o->movers)
		printf("%-28s %3d mover views (%d door, %d lift)  min %7.3f%% (view %d)  "
		       "mean %7.3f%%\n",
		       name, nv, ndoor, nv - ndoor, worst, wk, sum / nv);
	else if (nv > 0)
		printf("%-28s %3d views  min %7.3f%% (view %d)  mean %7.3f%%\n", name, nv, worst, wk,
		       sum / nv);
	if (nv > 0) {
		x->set_sum += sum;
		x->set_views += nv;
		if (worst < x->set_min)
			x->set_min = worst;
	}
	free(spr);
	free(cf);
	free(cc);
	return worst;
}

static void xc_set_begin(struct xc_run *x)
{
	x->set_min = 100;
	x->set_sum = 0;
	x->set_views = 0;
	x->set_mesh_px = x->mesh_px;
	x->set_mesh_same = x->mesh_same;
}

static void xc_set_end(struct xc_run *x, const char *what, int nmaps)
{
	if (x->set_views > 0)
		printf("== %s: %d maps, %ld %sviews, min %.3f%%, mean %.3f%%; mesh pixels %llu, "
		       "%.2f%% agree\n",
		       what, nmaps, x->set_views,
		       x->o->movers ? "mover " : x->o->meshes ? "mesh " : "", x->set_min,
		       x->set_sum / (double)x->set_views,
		       (unsigned long long)(x->mesh_px - x->set_mesh_px),
		       x->mesh_px > x->set_mesh_px ?
			       100.0 * (double)(x->mesh_same - x->set_mesh_same) /
				       (double)(x->mesh_px - x->set_mesh_px) : 100.0);
}

static int xc_builtin(struct xc_run *x)
{
	struct tex_set *t;
	int n = lvl_builtin_count();

	if (r_pal_set_new(&t) < 0)
		return -ENOMEM;
	xc_set_begin(x);
	for (int i = 0; i < n; i++) {
		struct map *m;
		char name[64];

		if (lvl_builtin(i, &m) < 0) {
			r_pal_set_free(t);
			return -ENOMEM;
		}
		snprintf(name, sizeof(name), "built-in %d %s", i + 1, m->name);
		xc_map(x, m, t, name);
		rgl_flush(x->gl);
		map_free(m);
	}
	xc_set_end(x, "built-in levels", n);
	rgl_flush(x->gl);
	r_pal_set_free(t);
	return 0;
}

static int xc_grid(struct xc_run *x, const char *file)
{
	struct grid_names names;
	struct tex_set *t;
	struct map *m = NULL;
	uint8_t *buf = NULL;
	const char *text;
	char err[256] = "", name[80];
	size_t len = 0;
	int rc;

	if (tex_builtin(&t) < 0)
		return -ENOMEM;
	if (strcmp(file, "builtin") == 0) {
		text = grid_builtin_text(&len);
	} else {
		buf = slurp(file, &len);
		if (!buf) {
			fprintf(stderr, "xcheck: %s: %s\n", file, strerror(errno));
			tex_free(t);
			return -ENOENT;
		}
		text = (const char *)buf;
	}
	grid_names_from_tex(&names, t);
	rc = grid_parse(text, len, file, &names, &m, err, sizeof(err));
	free(buf);
	if (rc < 0) {
		fprintf(stderr, "xcheck: %s: %s\n", file, err);
		tex_free(t);
		return rc;
	}
	snprintf(name, sizeof(name), "grid %s", file);
	xc_set_begin(x);
	xc_map(x, m, t, name);
	xc_set_end(x, name, 1);
	rgl_flush(x->gl);
	map_free(m);
	tex_free(t);
	return 0;
}

static int xc_wad(struct xc_run *x, const char *file, const char *only)
{
	char names[XC_MAX_MAPS][9], err[512] = "";
	const char *base = strrchr(file, '/') ? strrchr(file, '/') + 1 : file;
	struct wad *wd = NULL;
	struct tex_set *t = NULL;
	size_t len = 0;
	uint8_t *d = slurp(file, &len);
	int n, done = 0;

	if (!d || wad_new(&wd) < 0 || wad_add(wd, d, len, file, err, sizeof(err)) < 0 ||
	    tex_load_wad(wd, &t, err, sizeof(err)) < 0) {
		fprintf(stderr, "xcheck: %s: %s\n", file, d ? err : strerror(errno));
		free(d);
		wad_free(wd);
		return -EINVAL;
	}
	n = map_list_wad(wd, names, XC_MAX_MAPS);
	xc_set_begin(x);
	for (int i = 0; i < n && i < XC_MAX_MAPS; i++) {
		struct map *m;
		char name[64];

		if (only && strcasecmp(only, names[i]) != 0)
			continue;
		if (map_load_wad(wd, t, names[i], &m, err, sizeof(err)) < 0) {
			fprintf(stderr, "xcheck: %s %s: %s\n", file, names[i], err);
			x->failed++;
			continue;
		}
		tex_pick_sky(t, names[i]);
		snprintf(name, sizeof(name), "%.40s %.8s", base, names[i]);
		xc_map(x, m, t, name);
		rgl_flush(x->gl);
		map_free(m);
		done++;
	}
	xc_set_end(x, base, done);
	rgl_flush(x->gl);
	tex_free(t);
	wad_free(wd);
	free(d);
	return 0;
}

static int xc_args(int argc, char **argv, struct xc_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->views = 20;
	o->w = 320;
	o->h = 200;
	o->sprites = 1;
	o->min = 99.5;
	o->seed = 1;
	o->only_view = -1;
	o->cover = 99;
	o->mesh_min = 85;
	o->mesh_least = 200;
	o->probe_x = o->probe_y = -1;
	for (int i = 1; i < argc; i++) {
		const char *a = argv[i], *b = i + 1 < argc ? argv[i + 1] : NULL;
		struct xc_set *s = o->nsets < XC_MAX_SETS ? &o->sets[o->nsets] : NULL;

		if (!strcmp(a, "--builtin") && s) {
			s->kind = 'b';
			o->nsets++;
		} else if (!strcmp(a, "--grid") && b && s) {
			s->kind = 'g';
			s->arg = argv[++i];
			o->nsets++;
		} else if (!strcmp(a, "--wad") && b && s) {
			s->kind = 'w';
			s->arg = argv[++i];
			o->nsets++;
		} else if (!strcmp(a, "--map") && b && o->nsets > 0 &&
			   o->sets[o->nsets - 1].kind == 'w') {
			o->sets[o->nsets - 1].map = argv[++i];
		} else if (!strcmp(a, "--views") && b) {
			o->views = atoi(argv[++i]);
		} else if (!strcmp(a, "--seed") && b) {
			o->seed = strtoull(argv[++i], NULL, 0);
		} else if (!strcmp(a, "--size") && b) {
			if (sscanf(argv[++i], "%dx%d", &o->w, &o->h) != 2)
				return -1;
		} else if (!strcmp(a, "--min") && b) {
			o->min = atof(argv[++i]);
		} else if (!strcmp(a, "--diff") && b) {
			o->diff = argv[++i];
		} else if (!strcmp(a, "--diff-all")) {
			o->diff_all = 1;
		} else if (!strcmp(a, "--view") && b) {
			o->only_view = atoi(argv[++i]);
		} else if (!strcmp(a, "--probe") && b) {
			if (sscanf(argv[++i], "%d,%d", &o->probe_x, &o->probe_y) != 2)
				return -1;
		} else if (!strcmp(a, "--blank-ids")) {
			o->blank = 1;
		} else if (!strcmp(a, "--cover") && b) {
			o->cover = atof(argv[++i]);
		} else if (!strcmp(a, "--movers")) {
			o->movers = 1;
		} else if (!strcmp(a, "--meshes")) {
			o->meshes = 1;
		} else if (!strcmp(a, "--mesh-min") && b) {
			o->mesh_min = atof(argv[++i]);
		} else if (!strcmp(a, "--mesh-least") && b) {
			o->mesh_least = atol(argv[++i]);
		} else if (!strcmp(a, "--no-sprites")) {
			o->sprites = 0;
		} else if (!strcmp(a, "--verbose")) {
			o->verbose = 1;
		} else {
			fprintf(stderr, "xcheck: bad argument %s\n", a);
			return -1;
		}
	}
	if (o->nsets == 0 || o->views < 1 || o->w < 1 || o->h < 1 || o->w > 4096 || o->h > 4096)
		return -1;
	return 0;
}

int main(int argc, char **argv)
{
	static const char *kname[R_IDK_COUNT] = { "none", "sky", "floor", "ceiling", "upper",
						  "middle", "lower", "masked", "sprite", "back" };
	struct xc_opts o;
	struct xc_run x;
	char err[256] = "";
	size_t npx;
	double t0 = xc_now();
	int rc = 0;

	if (xc_args(argc, argv, &o) < 0) {
		fprintf(stderr, "usage: xcheck [--builtin] [--grid builtin|FILE] [--wad FILE "
				"[--map NAME]]... [--views N] [--seed S] [--size WxH] [--min PCT] "
				"[--diff DIR] [--diff-all] [--no-sprites] [--verbose] [--view K] "
				"[--probe X,Y] [--cover PCT] [--blank-ids] [--movers] [--meshes] "
				"[--mesh-min PCT] [--mesh-least N]\n");
		return 2;
	}
	memset(&x, 0, sizeof(x));
	x.o = &o;
	x.cover_min = 100;
	x.mesh_worst = 100;
	npx = (size_t)o.w * (size_t)o.h;
	x.fs.w = x.fg.w = x.fs.pitch = x.fg.pitch = o.w;
	x.fs.rec = x.fg.rec = NULL;
	x.fs.h = x.fg.h = o.h;
	x.fs.px = malloc(npx);
	x.fg.px = malloc(npx);
	x.ids_sw = malloc(npx * sizeof(uint32_t));
	x.ids_gl = malloc(npx * sizeof(uint32_t));
	x.diffpx = malloc(npx * 3);
	if (!x.fs.px || !x.fg.px || !x.ids_sw || !x.ids_gl || !x.diffpx ||
	    r_new(o.w, o.h, &x.sw) < 0) {
		fprintf(stderr, "xcheck: out of memory\n");
		return 2;
	}
	if (rgl_new(o.w, o.h, &x.gl, err, sizeof(err)) < 0) {
		fprintf(stderr, "xcheck: OSMesa: %s\n", err);
		return 2;
	}
	r_set_idbuf(x.sw, x.ids_sw);
	rgl_set_idbuf(x.gl, x.ids_gl);
	if (o.meshes)
		printf("xcheck: %dx%d, mesh views, threshold %.2f%%, on mesh pixels %.2f%% (views "
		       "with %ld or more), GL: %s\n",
		       o.w, o.h, o.min, o.mesh_min, o.mesh_least, rgl_name(x.gl));
	else if (o.movers)
		printf("xcheck: %dx%d, mover views, threshold %.2f%%, GL: %s\n", o.w, o.h, o.min,
		       rgl_name(x.gl));
	else
		printf("xcheck: %dx%d, %d views per map, seed %llu, threshold %.2f%%, GL: %s\n",
		       o.w, o.h, o.views, (unsigned long long)o.seed, o.min, rgl_name(x.gl));
	for (int i = 0; i < o.nsets && rc == 0; i++) {
		const struct xc_set *s = &o.sets[i];

		if (s->kind == 'b')
			rc = xc_builtin(&x);
		else if (s->kind == 'g')
			rc = xc_grid(&x, s->arg);
		else
			rc = xc_wad(&x, s->arg, s->map);
	}
	if (o.verbose) {
		printf("disagreeing pixels by kind (software -> OSMesa):\n");
		for (int a = 0; a < R_IDK_COUNT; a++)
			for (int b = 0; b < R_IDK_COUNT; b++)
				if (x.kinds[a][b])
					printf("  %-8s -> %-8s %10llu\n", kname[a], kname[b],
					       (unsigned long long)x.kinds[a][b]);
	}
	printf("xcheck: %ld views, %ld failed; least surface coverage %.3f%%; render time "
	       "software %.2f s, OSMesa %.2f s (both passes); total %.1f s\n",
	       x.views, x.failed, x.cover_min, x.t_sw, x.t_gl, xc_now() - t0);
	printf("xcheck: mesh pixels %llu, %llu agree (%.2f%%)", (unsigned long long)x.mesh_px,
	       (unsigned long long)x.mesh_same,
	       x.mesh_px ? 100.0 * (double)x.mesh_same / (double)x.mesh_px : 100.0);
	if (o.meshes)
		printf("; least on a mesh view %.2f%%; mesh views with fewer than %ld mesh "
		       "pixels (not judged on them) %ld",
		       x.mesh_worst, o.mesh_least, x.mesh_blind);
	printf("\n");
	r_free(x.sw);
	rgl_free(x.gl);
	free(x.fs.px);
	free(x.fg.px);
	free(x.ids_sw);
	free(x.ids_gl);
	free(x.diffpx);
	if (rc < 0)
		return 2;
	return x.failed ? 1 : 0;
}
