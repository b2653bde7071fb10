/*
 * rview: a hand-run viewer and benchmark for the renderer (not part of
 * `make test`): renders a Doom-format map from its player 1 start with the
 * WAD's textures and sprites, writes PNG screenshots, and measures frames
 * per second turning in place.
 *
 *   make BUILD=build/rtx build/rtx/libarcaded.a
 *   cc -O2 -I. -D_GNU_SOURCE -std=c11 -o build/rtx/rview tests/render/rview.c \
 *       build/rtx/libarcaded.a $(pkg-config --libs libpng) -lm
 *   build/rtx/rview --wad /usr/share/games/doom/freedoom1.wad --map E1M1 \
 *       --size 1280x720 --shot /tmp/e1m1 --bench 720
 *
 *   build/rtx/rview --builtin 1 --size 320x240 --bench 720
 *
 * Options: --wad FILE (repeatable, later files override), --map NAME,
 * --builtin N (built-in level N with the built-in texture set, no WAD),
 * --size WxH, --shot PREFIX (PREFIX-A.png for angles 0, 90, 180, 270
 * degrees from the start's facing), --bench N (N frames, one full turn,
 * five times: frames per second of the fastest turn),
 * --pos X,Y (map units, instead of the start), --angle DEG, --shear S,
 * --no-sprites. Prints the frame statistics of the first frame.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/ct.h"
#include "display/shot.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"
#include "engine/map/wad.h"
#include "engine/render/r_game.h"
#include "engine/render/r_main.h"

#define MAX_WADS 8

/* The file at path, or NULL (ct_read_file, app/ct.h). */
static uint8_t *slurp(const char *path, size_t *len)
{
	uint8_t *d = NULL;

	return ct_read_file(path, &d, len) == 0 ? d : NULL;
}

static double now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

int main(int argc, char **argv)
{
	const char *wads[MAX_WADS], *mapname = "E1M1", *shot = NULL;
	int nwads = 0, w = 320, h = 200, bench = 0, sprites = 1, have_pos = 0, shear = 0;
	int builtin = 0;
	double px = 0, py = 0, adeg = -1;
	char err[512] = "";
	struct wad *wd;
	struct tex_set *t;
	struct map *m;
	struct r_ctx *r;
	struct r_frame f;
	struct r_view v = { 0 };
	struct r_sprite *spr;
	struct r_stats st;
	int nspr, rc;

	for (int i = 1; i < argc; i++) {
		const char *a = argv[i], *b = i + 1 < argc ? argv[i + 1] : NULL;

		if (!strcmp(a, "--wad") && b && nwads < MAX_WADS)
			wads[nwads++] = argv[++i];
		else if (!strcmp(a, "--map") && b)
			mapname = argv[++i];
		else if (!strcmp(a, "--size") && b && sscanf(argv[++i], "%dx%d", &w, &h) == 2)
			;
		else if (!strcmp(a, "--shot") && b)
			shot = argv[++i];
		else if (!strcmp(a, "--bench") && b)
			bench = atoi(argv[++i]);
		else if (!strcmp(a, "--pos") && b && sscanf(argv[++i], "%lf,%lf", &px, &py) == 2)
			have_pos = 1;
		else if (!strcmp(a, "--angle") && b)
			adeg = atof(argv[++i]);
		else if (!strcmp(a, "--shear") && b)
			shear = atoi(argv[++i]);
		else if (!strcmp(a, "--builtin") && b)
			builtin = atoi(argv[++i]);
		else if (!strcmp(a, "--no-sprites"))
			sprites = 0;
		else {
			fprintf(stderr, "rview: bad argument %s\n", a);
			return 2;
		}
	}
	if (builtin > 0) {
		wd = NULL;
		if (lvl_builtin(builtin - 1, &m) < 0 || tex_builtin(&t) < 0)
			return 1;
		mapname = "built-in";
		goto loaded;
	}
	if (nwads == 0 || wad_new(&wd) < 0)
		return 2;
	for (int i = 0; i < nwads; i++) {
		size_t len = 0;
		uint8_t *d = slurp(wads[i], &len);

		if (!d || wad_add(wd, d, len, wads[i], err, sizeof(err)) < 0) {
			fprintf(stderr, "rview: %s: %s\n", wads[i], d ? err : strerror(errno));
			return 1;
		}
	}
	if (tex_load_wad(wd, &t, err, sizeof(err)) < 0 ||
	    map_load_wad(wd, t, mapname, &m, err, sizeof(err)) < 0) {
		fprintf(stderr, "rview: %s\n", err);
		return 1;
	}
loaded:
	spr = calloc(m->num_things + 1, sizeof(*spr));
	nspr = sprites ? r_map_sprites(m, t, spr) : 0;
	for (uint32_t i = 0; i < m->num_things; i++)
		if (m->things[i].type == 1) {
			v.x = m->things[i].x;
			v.y = m->things[i].y;
			v.angle = m->things[i].angle;
		}
	if (have_pos) {
		v.x = (fx_t)(px * FX_ONE);
		v.y = (fx_t)(py * FX_ONE);
	}
	if (adeg >= 0)
		v.angle = (ang_t)(adeg / 360.0 * 4294967296.0);
	v.z = m->sectors[map_point_sector(m, v.x, v.y)].floor_h + 41 * FX_ONE;
	v.shear = shear;
	rc = r_new(w, h, &r);
	f.w = f.pitch = w;
	f.rec = NULL;
	f.h = h;
	f.px = malloc((size_t)w * (size_t)h);
	if (rc < 0 || !f.px)
		return 1;
	r_render(r, m, t, &v, spr, nspr, &f);
	r_get_stats(r, &st);
	printf("%s %dx%d at (%d, %d) %u sprites: written %u empty %u masked %u planes %u spans %u "
	       "drawsegs %u openings %u segs %u sprites drawn %u missing %u degraded %u "
	       "(map missing %u, set missing %u)\n",
	       mapname, w, h, v.x >> 16, v.y >> 16, nspr, st.pixels_written, st.pixels_empty,
	       st.pixels_masked, st.planes, st.spans, st.drawsegs, st.openings, st.segs,
	       st.sprites, st.missing, st.degraded, m->missing_textures, t->missing);
	if (shot) {
		for (int k = 0; k < 4; k++) {
			struct r_view vk = v;
			char path[512];

			vk.angle += (ang_t)k * 0x40000000u;
			r_render(r, m, t, &vk, spr, nspr, &f);
			snprintf(path, sizeof(path), "%s-%c.png", shot, 'a' + k);
			if (shot_png(path, f.px, w, h, w, t->pal.rgb) < 0)
				fprintf(stderr, "rview: %s: cannot write\n", path);
		}
	}
	if (bench > 0) {
		double best = 1e30;

		/* the best of five turns: the least disturbed by other load */
		for (int rep = 0; rep < 5; rep++) {
			double t0 = now(), dt;

			for (int k = 0; k < bench; k++) {
				struct r_view vk = v;

				vk.angle += (ang_t)((uint64_t)k * 0x100000000ull / (uint64_t)bench);
				r_render(r, m, t, &vk, spr, nspr, &f);
			}
			dt = now() - t0;
			best = dt < best ? dt : best;
		}
		printf("bench %s %dx%d: %d frames turning in place, %.1f frames/s (best of 5)\n",
		       mapname, w, h, bench, bench / best);
	}
	r_free(r);
	free(f.px);
	free(spr);
	map_free(m);
	tex_free(t);
	wad_free(wd);
	return 0;
}
