/* Tests for engine/map/lmap.c: falloff values worked out by hand from the
 * formula in lmap.h, shadows checked against a second visibility method
 * (where a ray crosses the pillar's rows, by interval arithmetic), the 3D
 * opening of a window, walls that stop light, determinism, and the light
 * things that are lights. Maps are grid maps (one tile = 64 units; tile (r, c) of
 * an R-row map covers x in [64c, 64c+64), y in [64(R-1-r), 64(R-r))). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/lim.h"
#include "engine/map/grid.h"
#include "engine/map/lmap.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"
#include "hostile_fixture.h"
#include "engine/render/r_main.h"

static struct map *grid(const char *text)
{
	struct map *m = NULL;
	char err[256];
	int r = grid_parse(text, strlen(text), "t", NULL, &m, err, sizeof err);

	if (r)
		fail_msg("grid_parse: %s", err);
	return m;
}

static struct lmap_light light_at(int x, int y, int z, int intensity, int radius)
{
	struct lmap_light l = { fx_from_int(x), fx_from_int(y), fx_from_int(z), intensity, radius };
	return l;
}

/* The spec's falloff for a light at (lx, ly, lz) and a point, both in
 * 1/16 units: floor(I (R - d)^2 / R^2), d = floor(sqrt(dx^2+dy^2+dz^2)). */
static int64_t falloff16(int64_t dx, int64_t dy, int64_t dz, int64_t inten, int64_t radius)
{
	int64_t r = radius * 16, d = (int64_t)fx_isqrt64((uint64_t)(dx * dx + dy * dy + dz * dz));
	return d >= r ? 0 : inten * (r - d) * (r - d) / (r * r);
}

/* The vertical line at x (map units) whose front faces east (fe) or west. */
static uint32_t vertical_line(const struct map *m, int x, int fe)
{
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_vertex *a = &m->vertices[m->lines[i].v1];
		const struct map_vertex *b = &m->vertices[m->lines[i].v2];
		/* front east = right of a northward run */
		if (a->x == fx_from_int(x) && b->x == a->x && (fe ? b->y > a->y : b->y < a->y))
			return i;
	}
	fail_msg("no line at x = %d", x);
	return 0;
}

static const char room[] =
	"# = wall 1\n. = floor 0 ceil 128\n@ = . player east\nmap\n"
	"########\n"
	"#......#\n"
	"#......#\n"
	"#......#\n"
	"#@.....#\n"
	"########\n";

static void near_wall_gets_more_light_than_far_wall(void **state)
{
	/* room x 64..448, y 64..320; light 32 units from the west wall */
	struct map *m = grid(room);
	struct lmap_light l = light_at(96, 192, 64, 64, 512);
	struct lmap *lm = NULL;
	uint32_t west = vertical_line(m, 64, 1), east = vertical_line(m, 448, 0);
	(void)state;
	assert_int_equal(lmap_new(m, &l, 1, &lm), 0);
	/* west wall texel column 8, row 3: centre u = 136 from the wall's
	 * south end (y = 200), z = 56; sampled 1 unit into the room, x = 65:
	 * d = sqrt(496^2 + 128^2 + 128^2) = 528 (1/16 units) exactly;
	 * 64 * (8192 - 528)^2 / 8192^2 = 56.02 -> 56 light units -> boost 14 */
	assert_int_equal(lmap_wall(lm, west, 0, fx_from_int(136), fx_from_int(56)), 14);
	/* east wall column 7 (u = 120 from its north end: y = 200), row 3,
	 * at x = 447: d = floor(sqrt(5616^2 + 128^2 + 128^2)) = 5618;
	 * 64 * 2574^2 / 8192^2 = 6.3 -> 6 -> boost 1 */
	assert_int_equal(lmap_wall(lm, east, 0, fx_from_int(120), fx_from_int(56)), 1);
	/* the same numbers by the formula */
	assert_int_equal(falloff16(-496, 128, -128, 64, 512) / 4, 14);
	assert_int_equal(falloff16(5616, 128, -128, 64, 512) / 4, 1);
	/* whole-wall comparison: every texel of the near wall is at least as
	 * bright as the texel facing it on the far wall */
	for (int u = 8; u < 256; u += 16)
		for (int z = 8; z < 128; z += 16)
			assert_true(lmap_wall(lm, west, 0, fx_from_int(u), fx_from_int(z)) >=
				    lmap_wall(lm, east, 0, fx_from_int(256 - u), fx_from_int(z)));
	lmap_free(lm);
	map_free(m);
}

static const char pillar[] =
	"# = wall 1\nO = wall 2\n. = floor 0 ceil 128\n@ = . player east\nmap\n"
	"#########\n"
	"#@......#\n"
	"#.......#\n"
	"#...O...#\n"
	"#.......#\n"
	"#.......#\n"
	"#########\n";

/* 1 when the segment from (lx, ly) to (px, py) (1/16 units), with
 * ly > 256 > 192 > py in map units, touches the square [256, 320] x
 * [192, 256]: x is linear in y, so the segment's x over y in [192, 256]
 * is the interval between its x at the two heights, compared scaled by
 * (ly - py) > 0. */
static int hits_pillar(int64_t lx, int64_t ly, int64_t px, int64_t py)
{
	int64_t k = ly - py;
	int64_t xa = lx * k + (px - lx) * (ly - 256 * 16);   /* x(256) * k */
	int64_t xb = lx * k + (px - lx) * (ly - 192 * 16);   /* x(192) * k */
	int64_t lo = xa < xb ? xa : xb, hi = xa < xb ? xb : xa;
	return hi >= 256 * 16 * k && lo <= 320 * 16 * k;
}

static void pillar_shadows_exactly_the_texels_behind_it(void **state)
{
	/* room x 64..512, y 64..384; pillar x 256..320, y 192..256; light
	 * above it at (288, 352), z 64 */
	struct map *m = grid(pillar);
	struct lmap_light l = light_at(288, 352, 64, 128, 512);
	struct lmap *lm = NULL;
	int shadowed = 0, lit = 0;
	(void)state;
	assert_int_equal(lmap_new(m, &l, 1, &lm), 0);
	/* floor texels of the row centred at y = 88, x centres 72 .. 504;
	 * points in 1/16 units: centre, then the quarter points (-,-), (+,-),
	 * (-,+), (+,+) four units away */
	for (int x = 72; x < 512; x += 16) {
		static const int qx[5] = { 0, -4, 4, -4, 4 }, qy[5] = { 0, -4, -4, 4, 4 };
		int64_t want = 0;
		for (int k = 0; k < 5; k++) {
			int64_t px = (x + qx[k]) * 16, py = (88 + qy[k]) * 16;
			if (!hits_pillar(288 * 16, 352 * 16, px, py)) {
				want = falloff16(px - 288 * 16, py - 352 * 16, -64 * 16, 128, 512) / 4;
				break;
			}
		}
		assert_int_equal(lmap_flat(lm, 0, 0, fx_from_int(x), fx_from_int(88)), want);
		shadowed += want == 0;
		lit += want > 0;
	}
	/* directly behind the pillar: dark; far to the side: lit */
	assert_int_equal(lmap_flat(lm, 0, 0, fx_from_int(296), fx_from_int(88)), 0);
	assert_true(lmap_flat(lm, 0, 0, fx_from_int(104), fx_from_int(88)) > 0);
	assert_true(shadowed >= 4 && lit >= 10);
	lmap_free(lm);
	map_free(m);
}

static void light_beyond_a_one_sided_wall_adds_nothing(void **state)
{
	/* two rooms, x 64..256 and x 320..512, y 64..192, no opening */
	struct map *m = grid("# = wall 1\n. = floor 0 ceil 128\n@ = . player east\nmap\n"
			     "#########\n"
			     "#@..#...#\n"
			     "#...#...#\n"
			     "#########\n");
	struct lmap_light l = light_at(224, 128, 64, 256, 1024);
	struct lmap *lm = NULL;
	uint32_t east_room = map_point_sector(m, fx_from_int(400), fx_from_int(128));
	uint32_t far_wall = vertical_line(m, 512, 0);
	(void)state;
	assert_int_not_equal(east_room, map_point_sector(m, fx_from_int(100), fx_from_int(100)));
	assert_int_equal(lmap_new(m, &l, 1, &lm), 0);
	for (int x = 328; x < 512; x += 16)
		for (int y = 72; y < 192; y += 16) {
			assert_int_equal(lmap_flat(lm, east_room, 0, fx_from_int(x), fx_from_int(y)), 0);
			assert_int_equal(lmap_flat(lm, east_room, 1, fx_from_int(x), fx_from_int(y)), 0);
		}
	for (int u = 8; u < 128; u += 16)
		for (int z = 8; z < 128; z += 16)
			assert_int_equal(lmap_wall(lm, far_wall, 0, fx_from_int(u), fx_from_int(z)), 0);
	/* while its own room is lit */
	assert_true(lmap_flat(lm, 1 - east_room, 0, fx_from_int(200), fx_from_int(120)) > 0);
	lmap_free(lm);
	map_free(m);
}

static void window_sill_and_lintel_block_in_3d(void **state)
{
	/* hall y 256..384 (ceil 128), window sector x 256..320, y 192..256
	 * (floor 16, ceil 112), south room y 64..192. Light 32 units north of
	 * the window at z 120. A ray to a south floor point at horizontal
	 * distance D (straight south) is at z = 120 - 120 * 96 / D where it
	 * leaves the window (y 192): above the sill (16) only for D > 110.8;
	 * at y 256 it is at 120 - 3840 / D, below the lintel (112) for
	 * D <= 480. */
	struct map *m = grid("# = wall 1\n. = floor 0 ceil 128\n@ = . player east\n"
			     "W = floor 16 ceil 112\nmap\n"
			     "#########\n"
			     "#@......#\n"
			     "#.......#\n"
			     "####W####\n"
			     "#.......#\n"
			     "#.......#\n"
			     "#########\n");
	struct lmap_light l = light_at(288, 288, 120, 128, 512);
	struct lmap *lm = NULL;
	uint32_t south = map_point_sector(m, fx_from_int(288), fx_from_int(100));
	(void)state;
	assert_int_equal(lmap_new(m, &l, 1, &lm), 0);
	/* y 184: D = 104 (and 100, 108 for the quarter points): below the sill */
	assert_int_equal(lmap_flat(lm, south, 0, fx_from_int(296), fx_from_int(184)), 0);
	/* y 168: D = 120 at x 296, 8 units east: lit; value of the centre */
	assert_int_equal(lmap_flat(lm, south, 0, fx_from_int(296), fx_from_int(168)),
			 falloff16(8 * 16, -120 * 16, -120 * 16, 128, 512) / 4);
	assert_true(lmap_flat(lm, south, 0, fx_from_int(296), fx_from_int(168)) > 0);
	lmap_free(lm);
	map_free(m);
}

static void same_map_gives_same_bytes(void **state)
{
	size_t len;
	const char *text = grid_builtin_text(&len);
	struct map *m = NULL;
	struct tex_set *tex = NULL;
	struct grid_names names;
	struct lmap_light lights[16];
	struct lmap *a = NULL, *b = NULL;
	struct lmap_stats sa, sb;
	char err[256];
	int n;
	(void)state;
	assert_int_equal(tex_builtin(&tex), 0);
	grid_names_from_tex(&names, tex);
	assert_int_equal(grid_parse(text, len, "grid1", &names, &m, err, sizeof err), 0);
	tex_free(tex);
	n = lmap_lights_from_map(m, 0, lights, 16);
	assert_int_equal(n, 5);
	assert_int_equal(lmap_new(m, lights, n, &a), 0);
	assert_int_equal(lmap_new(m, lights, n, &b), 0);
	assert_int_equal(lmap_hash(a), lmap_hash(b));
	lmap_get_stats(a, &sa);
	lmap_get_stats(b, &sb);
	assert_int_equal(sa.texels, sb.texels);
	assert_int_equal(sa.rays, sb.rays);
	assert_int_equal(sa.lights, 5);
	assert_true(sa.texels > 0 && sa.grids > 0 && sa.bytes > sa.texels);
	/* a different light changes the bytes */
	lights[0].intensity += 64;
	lmap_free(b);
	assert_int_equal(lmap_new(m, lights, n, &b), 0);
	assert_int_not_equal(lmap_hash(a), lmap_hash(b));
	lmap_free(a);
	lmap_free(b);
	map_free(m);
}

static void lights_come_from_things_half_way_up(void **state)
{
	/* things in tile order: the player (1), then the lamp: th.h type
	 * 15000 + 64 * 3 + 8 * 3 (radius 256, intensity 128, white) */
	struct map *m = grid("# = wall 1\n. = floor 16 ceil 144\n@ = . player east\n"
			     "* = . lamp 128 256\nmap\n#####\n#@*.#\n#####\n");
	struct lmap_light out[2];
	(void)state;
	assert_int_equal(m->things[1].type, 15000 + 64 * 3 + 8 * 3);
	assert_int_equal(lmap_lights_from_map(m, 0, out, 2), 1);
	assert_int_equal(out[0].x, fx_from_int(160));
	assert_int_equal(out[0].z, fx_from_int(80));       /* (16 + 144) / 2 */
	assert_int_equal(out[0].intensity, 128);
	assert_int_equal(out[0].radius, 256);
	/* a Doom floor lamp (2028) counts only with LMAP_DECOR, its flame 44
	 * units above the floor; a zombieman (3004) never */
	m->things[0].type = 2028;
	m->things[1].type = 3004;
	assert_int_equal(lmap_lights_from_map(m, 0, out, 2), 0);
	assert_int_equal(lmap_lights_from_map(m, LMAP_DECOR, NULL, 0), 1);
	assert_int_equal(lmap_lights_from_map(m, LMAP_DECOR, out, 2), 1);
	assert_int_equal(out[0].z, fx_from_int(16 + 44));
	assert_int_equal(out[0].intensity, 160);
	map_free(m);
}

static void no_lights_and_bad_lights(void **state)
{
	struct map *m = grid(room);
	struct lmap *lm = NULL;
	struct lmap_light bad = light_at(96, 192, 64, 0, 512);
	struct lmap_stats st;
	(void)state;
	assert_int_equal(lmap_new(m, NULL, 0, &lm), 0);
	assert_null(lmap_flat_grid(lm, 0, 0));
	assert_null(lmap_wall_grid(lm, 0, 0));
	assert_int_equal(lmap_flat(lm, 0, 0, 0, 0), 0);
	assert_int_equal(lmap_wall(lm, 99, 0, 0, 0), 0);
	lmap_get_stats(lm, &st);
	assert_int_equal(st.texels, 0);
	lmap_free(lm);
	assert_int_equal(lmap_new(m, &bad, 1, &lm), -EINVAL);
	assert_null(lm);
	bad = light_at(96, 192, 64, 64, LMAP_RADIUS_MAX + 1);
	assert_int_equal(lmap_new(m, &bad, 1, &lm), -EINVAL);
	assert_int_equal(lmap_new(m, &bad, -1, &lm), -EINVAL);
	lmap_free(NULL);
	map_free(m);
}

static void only_surfaces_facing_a_light_get_grids(void **state)
{
	struct map *m = grid(room);
	struct lmap_light l = light_at(96, 192, 64, 64, 128);
	struct lmap *lm = NULL;
	const struct lmap_grid *g;
	(void)state;
	assert_int_equal(lmap_new(m, &l, 1, &lm), 0);
	/* the floor: its box x 64..448, y 64..320 in 16-unit texels */
	g = lmap_flat_grid(lm, 0, 0);
	assert_non_null(g);
	assert_int_equal(g->x0, 64);
	assert_int_equal(g->y0, 64);
	assert_int_equal(g->w, 24);
	assert_int_equal(g->h, 16);
	assert_int_equal(g->shift, 4);
	/* the west wall faces it and lies within 128; the east wall is 352
	 * away: no grid */
	g = lmap_wall_grid(lm, vertical_line(m, 64, 1), 0);
	assert_non_null(g);
	assert_int_equal(g->w, 16);                       /* 256 / 16 */
	assert_int_equal(g->h, 8);                        /* 128 / 16 */
	assert_null(lmap_wall_grid(lm, vertical_line(m, 448, 0), 0));
	lmap_free(lm);
	map_free(m);
}


static void huge_surfaces_get_coarser_texels(void **state)
{
	/* one open room of 250 x 250 tiles: its floor is 16000 units square,
	 * 1000 x 1000 texels of 16 units, past LMAP_GRID_MAX (65536): 32-unit
	 * texels give 500 x 500, still past; 64-unit ones 250 x 250 = 62500 */
	size_t n = 64 + 253 * 252, k;
	char *t = malloc(n);
	struct map *m = NULL;
	struct lmap *lm = NULL;
	struct lmap_light l = light_at(8000, 8000, 64, 128, 512);
	const struct lmap_grid *g;
	char err[128];
	(void)state;
	assert_non_null(t);
	k = (size_t)sprintf(t, "# = wall 1\n. = open\n@ = . player east\nmap\n");
	for (int r = 0; r < 252; r++) {
		for (int c = 0; c < 252; c++)
			t[k++] = r == 0 || c == 0 || r == 251 || c == 251 ? '#' : r == 1 && c == 1 ? '@' : '.';
		t[k++] = '\n';
	}
	assert_int_equal(grid_parse(t, k, "big", NULL, &m, err, sizeof err), 0);
	free(t);
	assert_int_equal(lmap_new(m, &l, 1, &lm), 0);
	g = lmap_flat_grid(lm, 0, 0);
	assert_non_null(g);
	assert_int_equal(g->shift, 6);
	assert_int_equal(g->w, 250);
	assert_int_equal(g->h, 250);
	/* under the light, lit; 600 units away (radius 512), not */
	assert_true(lmap_flat(lm, 0, 0, fx_from_int(8000), fx_from_int(8000)) > 0);
	assert_int_equal(lmap_flat(lm, 0, 0, fx_from_int(8600), fx_from_int(8000)), 0);
	lmap_free(lm);
	map_free(m);
}


/* The renderer with light maps: GRID1 seen from room 2's doorway towards
 * its lamp. Without an lmap (or after setting NULL) the frame is the plain
 * one; with it the lamp brightens many pixels (lower colormap levels: the
 * palette's total brightness rises) and every pixel is still written once
 * with nothing left empty. */
static void renderer_applies_light_maps(void **state)
{
	size_t len;
	const char *text = grid_builtin_text(&len);
	struct tex_set *tex = NULL;
	struct grid_names names;
	struct map *m = NULL;
	struct lmap *lm = NULL;
	struct lmap_light lights[16];
	struct r_ctx *r = NULL;
	struct r_stats st;
	enum { W = 160, H = 100 };
	uint8_t *plain = malloc(W * H), *lit = malloc(W * H);
	struct r_frame f = { plain, W, H, W, NULL };
	/* room 2's west doorway (row 3, column 7 of 13 rows) facing east */
	struct r_view v = { fx_from_int(7 * 64 + 32), fx_from_int(64 * 10 - 32), fx_from_int(41), 0, 0 };
	uint64_t sum_plain = 0, sum_lit = 0;
	int changed = 0, n;
	char err[256];
	(void)state;
	assert_non_null(plain);
	assert_non_null(lit);
	assert_int_equal(tex_builtin(&tex), 0);
	grid_names_from_tex(&names, tex);
	assert_int_equal(grid_parse(text, len, "grid1", &names, &m, err, sizeof err), 0);
	n = lmap_lights_from_map(m, 0, lights, 16);
	assert_int_equal(lmap_new(m, lights, n, &lm), 0);
	assert_int_equal(r_new(W, H, &r), 0);
	r_render(r, m, tex, &v, NULL, 0, &f);
	r_set_lmap(r, lm);
	f.px = lit;
	r_render(r, m, tex, &v, NULL, 0, &f);
	r_get_stats(r, &st);
	assert_int_equal(st.pixels_written, W * H);
	assert_int_equal(st.pixels_empty, 0);
	for (int i = 0; i < W * H; i++) {
		changed += plain[i] != lit[i];
		for (int c = 0; c < 3; c++) {
			sum_plain += tex->pal.rgb[plain[i]][c];
			sum_lit += tex->pal.rgb[lit[i]][c];
		}
	}
	assert_true(changed > W * H / 10);
	assert_true(sum_lit > sum_plain);
	/* NULL: the plain frame again, byte for byte */
	r_set_lmap(r, NULL);
	r_render(r, m, tex, &v, NULL, 0, &f);
	assert_memory_equal(lit, plain, W * H);
	r_free(r);
	lmap_free(lm);
	map_free(m);
	tex_free(tex);
	free(plain);
	free(lit);
}

/* MAP01 of hostile image img (freed here), loaded as "hostile.wad". */
static struct map *load_hostile(uint8_t *img, size_t len)
{
	struct wad *w;
	struct tex_set *t;
	struct map *m;
	char err[200];

	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "hostile.wad", err, sizeof err), 0);
	assert_int_equal(tex_load_wad(w, &t, err, sizeof err), 0);
	if (map_load_wad(w, t, "MAP01", &m, err, sizeof err))
		fail_msg("%s", err);
	tex_free(t);
	wad_free(w);
	free(img);
	return m;
}

/* lmap_new_lim on every light of m (LMAP_DECOR) with stop hook `stop`. */
static int light_all(const struct map *m, const struct lim_stop *stop, char *err, size_t errlen)
{
	int n = lmap_lights_from_map(m, LMAP_DECOR, NULL, 0), r;
	struct lmap_light *l = calloc((size_t)n + 1, sizeof *l);
	struct lmap *lm = NULL;

	assert_non_null(l);
	lmap_lights_from_map(m, LMAP_DECOR, l, n);
	r = lmap_new_lim(m, l, n, stop, &lm, err, errlen);
	if (r)
		assert_null(lm);
	lmap_free(lm);
	free(l);
	return r;
}

/* Issue 13 item 8: 30,000 lights took 60 s; more than LMAP_MAX_LIGHTS are
 * refused before any work. Lights whose rays cross many blocking lines
 * stop at LMAP_MAX_STEPS; the stop hook ends the work at its next poll. */
static void lights_past_the_limits_are_refused(void **state)
{
	struct hf_polls halt = { 0, 3 };
	uint64_t steps = 0;
	struct lim_stop count = { NULL, NULL, &steps }, stop = { hf_poll, &halt, NULL };
	struct map *m;
	size_t len;
	uint8_t *img;
	char err[200];

	(void)state;
	img = hf_lights(30000, &len);
	m = load_hostile(img, len);
	assert_int_equal(light_all(m, &count, err, sizeof err), -E2BIG);
	assert_string_equal(err, "30000 lights, more than the limit of 4096 (LMAP_MAX_LIGHTS)");
	assert_true(steps == 0);
	map_free(m);
	img = hf_lit_lines(4096, 1000, &len);
	m = load_hostile(img, len);
	assert_int_equal(light_all(m, &count, err, sizeof err), -E2BIG);
	assert_string_equal(err, "light maps need more than 209715200 steps (limit "
				 "LMAP_MAX_STEPS)");
	/* past the limit by at most one ray's or one light's steps */
	assert_true(steps > LMAP_MAX_STEPS && steps < LMAP_MAX_STEPS + 1000000);
	assert_int_equal(light_all(m, &stop, err, sizeof err), -ECANCELED);
	assert_string_equal(err, "light maps: stopped");
	assert_int_equal(halt.polls, 3);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(near_wall_gets_more_light_than_far_wall),
		cmocka_unit_test(pillar_shadows_exactly_the_texels_behind_it),
		cmocka_unit_test(light_beyond_a_one_sided_wall_adds_nothing),
		cmocka_unit_test(window_sill_and_lintel_block_in_3d),
		cmocka_unit_test(same_map_gives_same_bytes),
		cmocka_unit_test(lights_come_from_things_half_way_up),
		cmocka_unit_test(no_lights_and_bad_lights),
		cmocka_unit_test(lights_past_the_limits_are_refused),
		cmocka_unit_test(only_surfaces_facing_a_light_get_grids),
		cmocka_unit_test(huge_surfaces_get_coarser_texels),
		cmocka_unit_test(renderer_applies_light_maps),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
