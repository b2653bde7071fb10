/* Tests for engine/map/grid.c (ASCII tile maps) and engine/map/grid_lvl.c (the
 * built-in grid level). Expected counts come from drawing the maps on
 * paper: tile (row r, column c) of an R-row map covers x in [64c, 64c+64),
 * y in [64(R-1-r), 64(R-r)). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/map/grid.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"
#include "engine/render/r_main.h"

static struct map *parse_ok(const char *text)
{
	struct map *m = NULL;
	char err[256];
	int r = grid_parse(text, strlen(text), "t.txt", NULL, &m, err, sizeof err);

	if (r)
		fail_msg("grid_parse: %d %s", r, err);
	assert_non_null(m);
	return m;
}

/* The error message of a text that must fail with -EINVAL. */
static void parse_err(const char *text, const char *want)
{
	struct map *m = (struct map *)1;
	char err[256];
	int r = grid_parse(text, strlen(text), "t.txt", NULL, &m, err, sizeof err);

	assert_int_equal(r, -EINVAL);
	assert_null(m);
	assert_string_equal(err, want);
}

/* Centre of tile (r, c) in an R-row map. */
static fx_t tile_x(int c) { return fx_from_int(64 * c + 32); }
static fx_t tile_y(int rows, int r) { return fx_from_int(64 * (rows - r) - 32); }

/* 1 when (x, y) (map units) is strictly right of line l: its front. */
static int right_of(const struct map *m, const struct map_line *l, int x, int y)
{
	const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
	int64_t cross = ((int64_t)b->x - a->x) * ((int64_t)fx_from_int(y) - a->y) -
			((int64_t)b->y - a->y) * ((int64_t)fx_from_int(x) - a->x);
	return cross < 0;
}

static const char room3[] =
	"; a 3x3 room\n"
	"# = wall 5\n"
	". = floor 0 ceil 128\n"
	"@ = . player east\n"
	"map\n"
	"#####\n"
	"#...#\n"
	"#.@.#\n"
	"#...#\n"
	"#####\n";

static void room_3x3_is_one_sector_and_four_walls(void **state)
{
	struct map *m = parse_ok(room3);
	(void)state;
	assert_int_equal(m->num_sectors, 1);
	assert_int_equal(m->num_lines, 4);
	assert_int_equal(m->num_sides, 4);
	/* the original vertices: the four corners, before any node-builder
	 * split points */
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
		assert_int_equal(l->side[1], MAP_NONE);
		assert_int_equal(l->flags, ML_BLOCKING);
		assert_int_equal(m->sides[l->side[0]].mid_tex, 5);
		/* each wall is a whole side of the square x, y in [64, 256] */
		assert_true(a->x == b->x || a->y == b->y);
		assert_int_equal(fx_abs(b->x - a->x) + fx_abs(b->y - a->y), fx_from_int(192));
		assert_true(a->x >= fx_from_int(64) && a->x <= fx_from_int(256));
		assert_true(a->y >= fx_from_int(64) && a->y <= fx_from_int(256));
		/* front faces the room's centre (160, 160) */
		assert_true(right_of(m, l, 160, 160));
	}
	assert_int_equal(m->sectors[0].floor_h, 0);
	assert_int_equal(m->sectors[0].ceil_h, fx_from_int(128));
	assert_int_equal(m->sectors[0].light, 160);           /* default */
	assert_int_equal(m->num_things, 1);
	assert_int_equal(m->things[0].type, 1);
	assert_int_equal(m->things[0].x, fx_from_int(160));
	assert_int_equal(m->things[0].y, fx_from_int(160));
	assert_int_equal(m->things[0].angle, 0);
	assert_string_equal(m->name, "GRID");
	map_free(m);
}

static const char three[] =
	"# = wall 5\n"
	". = floor 0 ceil 128 light 200\n"
	"- = floor 16 ceil 128\n"
	"~ = floor -16 ceil 128 edge 7\n"
	"@ = . player north\n"
	"map\n"
	"#######\n"
	"#..-~~#\n"
	"#@.-~~#\n"
	"#######\n";

static void regions_become_sectors_with_steps_between(void **state)
{
	struct map *m = parse_ok(three);
	uint32_t two = 0;
	(void)state;
	/* sectors in order of first tile: '.', '-', '~' */
	assert_int_equal(m->num_sectors, 3);
	assert_int_equal(m->sectors[0].floor_h, 0);
	assert_int_equal(m->sectors[0].light, 200);
	assert_int_equal(m->sectors[1].floor_h, fx_from_int(16));
	assert_int_equal(m->sectors[2].floor_h, fx_from_int(-16));
	/* north and south edges: 3 runs each (one per sector); west and east
	 * one each; two step lines between the columns */
	assert_int_equal(m->num_lines, 10);
	for (uint32_t i = 0; i < m->num_lines; i++)
		if (m->lines[i].side[1] != MAP_NONE) {
			const struct map_line *l = &m->lines[i];
			uint32_t f = m->sides[l->side[0]].sector, b = m->sides[l->side[1]].sector;
			two++;
			assert_int_equal(l->flags, ML_TWOSIDED);
			/* the west tile is in front, and each side shows the other
			 * tile's edge texture: '~' has edge 7, others the first
			 * wall's 5 */
			assert_true(f + 1 == b);
			assert_int_equal(m->sides[l->side[0]].bot_tex, b == 2 ? 7 : 5);
			assert_int_equal(m->sides[l->side[1]].top_tex, 5);
			assert_int_equal(m->sides[l->side[0]].mid_tex, 0);
		}
	assert_int_equal(two, 2);
	/* every tile centre lies in the sector of its region */
	for (int c = 1; c <= 5; c++)
		for (int r = 1; r <= 2; r++)
			assert_int_equal(map_point_sector(m, tile_x(c), tile_y(4, r)),
					 c <= 2 ? 0u : c == 3 ? 1u : 2u);
	assert_int_equal(m->things[0].angle, ANG90);
	map_free(m);
}

static void different_wall_textures_split_a_run(void **state)
{
	struct map *m = parse_ok("# = wall 5\nB = wall 9\n. = ceil 64\n@ = . player 180\n"
				 "map\n##B##\n#.@.#\n#####\n");
	(void)state;
	/* north edge over the open tiles: '#', 'B', '#' -> 3 lines; plus west,
	 * east, south */
	assert_int_equal(m->num_lines, 6);
	assert_int_equal(m->sectors[0].ceil_h, fx_from_int(64));
	assert_int_equal(m->things[0].angle, ANG180);
	map_free(m);
}

static void separate_regions_of_one_kind_are_separate_sectors(void **state)
{
	struct map *m = parse_ok("# = wall 5\n. = open\n@ = . player east\n"
				 "map\n#####\n#@#.#\n#####\n");
	(void)state;
	assert_int_equal(m->num_sectors, 2);
	assert_int_equal(map_point_sector(m, tile_x(1), tile_y(3, 1)), 0);
	assert_int_equal(map_point_sector(m, tile_x(3), tile_y(3, 1)), 1);
	map_free(m);
}

static void lamps_and_things_sit_at_tile_centres(void **state)
{
	struct map *m = parse_ok("# = wall 5\n. = open\n@ = . player east\n"
				 "* = . lamp 192 320\nE = . thing 3004 west\n"
				 "+ = . lamp 250 100 cyan\n"
				 "map\n######\n#@*E+#\n######\n");
	struct th_light tl;
	(void)state;
	assert_int_equal(m->num_things, 4);
	/* things in row-major tile order */
	assert_int_equal(m->things[1].x, tile_x(2));
	assert_int_equal(m->things[1].y, tile_y(3, 1));
	/* th.h: 15000 + 64 * (320 / 64 - 1) + 8 * (192 / 32 - 1) + white 0 */
	assert_int_equal(m->things[1].type, 15000 + 64 * 4 + 8 * 5);
	assert_true(th_light(m->things[1].type, &tl));
	assert_int_equal(tl.intensity, 192);
	assert_int_equal(tl.radius, 320);
	/* nearest steps: intensity 250 -> 255 (index 7), radius 100 -> 128
	 * (index 1), cyan is colour 5 */
	assert_int_equal(m->things[3].type, 15000 + 64 * 1 + 8 * 7 + 5);
	assert_int_equal(m->things[2].type, 3004);
	assert_int_equal(m->things[2].angle, ANG180);
	assert_int_equal(m->things[2].x, tile_x(3));
	map_free(m);
}

static int fake_wall(void *ctx, const char *name)
{
	(void)ctx;
	return strcmp(name, "BRICK") == 0 ? 42 : -1;
}

static int fake_flat(void *ctx, const char *name)
{
	*(int *)ctx += 1;
	return strcmp(name, "FLOOR1") == 0 ? 7 : -1;
}

static void names_resolve_through_the_callbacks(void **state)
{
	static const char text[] = "# = wall BRICK\n. = ftex FLOOR1 ctex 3\n@ = . player east\n"
				   "map\n###\n#@#\n###\n";
	int calls = 0;
	struct grid_names names = { &calls, fake_wall, fake_flat };
	struct map *m = NULL;
	char err[128];
	(void)state;
	assert_int_equal(grid_parse(text, strlen(text), "n", &names, &m, err, sizeof err), 0);
	assert_int_equal(m->sides[0].mid_tex, 42);
	assert_int_equal(m->sectors[0].floor_tex, 7);
	assert_int_equal(m->sectors[0].ceil_tex, 3);          /* digits: no lookup */
	assert_int_equal(calls, 1);
	map_free(m);
	/* without callbacks a name is an error at its column */
	parse_err(text, "t.txt:1:10: unknown texture 'BRICK'");
}

static void errors_name_line_and_column(void **state)
{
	(void)state;
	parse_err("# = wall 1\n. = open\n@ = . player east\nmap\n#####\n#@..#\n#.x.#\n#####\n",
		  "t.txt:7:3: unknown tile 'x'");
	parse_err("# = wall 1\n. = open\n@ = . player east\nmap\n#####\n#@..#\n#..#\n#####\n",
		  "t.txt:7:5: row is 4 tiles wide, the first row 5");
	parse_err("# = wall 1\n. = open\nmap\n####\n#..#\n####\n",
		  "t.txt: no player start (a tile with 'player DIRECTION')");
	parse_err("# = wall 1\n. = open\n@ = . player east\nmap\n####\n#@..\n####\n",
		  "t.txt:6:4: open tile '.' on the map edge (close the map with wall tiles)");
	parse_err("# = wall 1\n. = open\n@ = . player east\nmap\n#####\n#@. #\n#####\n",
		  "t.txt:6:3: open tile '.' next to void (close the map with wall tiles)");
	parse_err("# = wall 1\n. = open floor 10 ceil 5\n",
		  "t.txt:2:1: ceiling below floor");
	parse_err("# = wall 1\n. = open hight 5\n", "t.txt:2:10: unknown keyword 'hight'");
	parse_err("# = wall 1\n# = wall 2\n", "t.txt:2:1: tile '#' defined twice");
	parse_err("# = wall 1\n. = floor\n", "t.txt:2:5: missing value after 'floor'");
	parse_err("# = wall 1\n. = light 300\n", "t.txt:2:11: light must be 0..255");
	parse_err("# = wall 1\n. = open\n@ = . player up\n", "t.txt:3:14: bad direction "
		  "(east, north, ... or degrees 0..359)");
	parse_err("# = wall 1\n. = open\n", "t.txt: no 'map' line before the rows");
	parse_err("# = wall 1\nmap\n\n\n", "t.txt: no rows after 'map'");
	parse_err("# = wall 1\n. = open\n@ = . player east\nmap\n####\n#@@#\n####\n",
		  "t.txt:6:3: second player start");
	parse_err("# = wall 1\n. = X\n", "t.txt:2:5: tile 'X' is not an open tile defined above");
	parse_err("# = wall 1\nbogus line\n", "t.txt:2:1: expected 'C = definition', "
		  "'name NAME' (8 chars) or 'map', got 'bogus'");
}

static void crlf_comments_and_trailing_blank_lines_are_accepted(void **state)
{
	struct map *m = parse_ok("name CRLF ; comment\r\n  ; indented comment\r\n"
				 "# = wall 5 ;a comment\r\n. = open\r\n@ = . player east\r\n"
				 "map\r\n###\r\n#@#\r\n###\r\n\r\n\n");
	(void)state;
	assert_int_equal(m->num_lines, 4);
	assert_string_equal(m->name, "CRLF");
	map_free(m);
}

static void larger_than_255_tiles_is_refused(void **state)
{
	size_t n = 64 + 257 * 3;
	char *t = malloc(n);
	struct map *m = NULL;
	char err[128];
	(void)state;
	assert_non_null(t);
	strcpy(t, "# = wall 1\nmap\n");
	memset(t + strlen(t), '#', 256);
	t[15 + 256] = '\n';
	assert_int_equal(grid_parse(t, 15 + 257, "big", NULL, &m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "big:3: map larger than 255 x 255 tiles");
	free(t);
}

/* Reads a file of the source tree (the tests run from the repository
 * root); NULL when absent. */
static char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	char *buf;
	long n;

	if (!f)
		return NULL;
	fseek(f, 0, SEEK_END);
	n = ftell(f);
	fseek(f, 0, SEEK_SET);
	buf = malloc((size_t)n + 1);
	if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
		free(buf);
		buf = NULL;
	}
	fclose(f);
	*len = (size_t)n;
	return buf;
}

static void builtin_grid_level_matches_its_file_and_imports(void **state)
{
	size_t len, flen = 0;
	const char *text = grid_builtin_text(&len);
	char *file = slurp("levels/grid1.txt", &flen);
	struct map *m = NULL, *m2 = NULL;
	char err[256];
	int players = 0, lamps = 0;
	struct th_light tl;
	struct tex_set *tex = NULL;
	struct grid_names names;
	(void)state;
	assert_int_equal(tex_builtin(&tex), 0);
	grid_names_from_tex(&names, tex);
	assert_non_null(file);
	assert_int_equal(flen, len);
	assert_memory_equal(file, text, len);
	free(file);
	assert_int_equal(grid_parse(text, len, "grid1.txt", &names, &m, err, sizeof err), 0);
	assert_string_equal(m->name, "GRID1");
	for (uint32_t i = 0; i < m->num_things; i++) {
		players += m->things[i].type == 1;
		lamps += th_light(m->things[i].type, &tl);
	}
	assert_int_equal(players, 1);
	assert_int_equal(lamps, 5);
	assert_true(m->num_nodes > 0);                  /* built by map_finish */
	/* the pool '~' (row 3, column 20) is 24 below the hall */
	assert_int_equal(m->sectors[map_point_sector(m, tile_x(20), tile_y(13, 3))].floor_h,
			 fx_from_int(-24));
	/* the window 'W' (row 7, column 3): floor 40, ceiling 88 */
	assert_int_equal(m->sectors[map_point_sector(m, tile_x(3), tile_y(13, 7))].ceil_h,
			 fx_from_int(88));
	/* deterministic */
	assert_int_equal(grid_parse(text, len, "grid1.txt", &names, &m2, err, sizeof err), 0);
	assert_int_equal(m->content_hash, m2->content_hash);
	assert_int_equal(m->num_nodes, m2->num_nodes);
	/* its names are the built-in set's */
	assert_int_equal(m->sides[0].mid_tex, tex_find(tex, "AR_BRICK"));
	assert_int_equal(m->sectors[0].floor_tex, tex_find_flat(tex, "AR_FLOOR"));
	map_free(m);
	map_free(m2);
	/* without the names it does not import */
	assert_int_equal(grid_parse(text, len, "grid1.txt", NULL, &m, err, sizeof err), -EINVAL);
	assert_string_equal(err, "grid1.txt:4:10: unknown texture 'AR_BRICK'");
	tex_free(tex);
}


/* The acceptance path: a grid map (no nodes in it: map_finish built them)
 * renders like any map. From the player start and from the centre of every
 * open tile in four directions, every pixel is written and none is left
 * empty (the map is closed), and nothing falls back to the checker. */
static void builtin_grid_level_renders_without_holes(void **state)
{
	size_t len;
	const char *text = grid_builtin_text(&len);
	struct tex_set *tex = NULL;
	struct grid_names names;
	struct map *m = NULL;
	struct r_ctx *r = NULL;
	struct r_frame f;
	struct r_stats st;
	char err[256];
	int views = 0;
	(void)state;
	assert_int_equal(tex_builtin(&tex), 0);
	grid_names_from_tex(&names, tex);
	assert_int_equal(grid_parse(text, len, "grid1.txt", &names, &m, err, sizeof err), 0);
	assert_int_equal(r_new(160, 100, &r), 0);
	f.w = 160;
	f.h = 100;
	f.pitch = 160;
	f.rec = NULL;
	f.px = malloc(160 * 100);
	assert_non_null(f.px);
	/* the level's rows (13 rows of 26 tiles) follow its "map" line;
	 * wall tiles are '#' and 'O' */
	const char *rows = strstr(text, "\nmap\n") + 5;
	for (int row = 1; row < 12; row++)
		for (int col = 1; col < 25; col++) {
			fx_t x = tile_x(col), y = tile_y(13, row);
			const struct map_sector *s = &m->sectors[map_point_sector(m, x, y)];
			char tile = rows[row * 27 + col];
			if (tile == '#' || tile == 'O' || s->ceil_h - s->floor_h < fx_from_int(56))
				continue;      /* walls; the window: no room for an eye */
			for (int a = 0; a < 4; a++) {
				struct r_view v = { x, y, s->floor_h + fx_from_int(41),
						    (ang_t)a * ANG90 + ANG45 / 3, 0 };
				r_render(r, m, tex, &v, NULL, 0, &f);
				r_get_stats(r, &st);
				assert_int_equal(st.pixels_written, 160 * 100);
				assert_int_equal(st.pixels_empty, 0);
				assert_int_equal(st.missing, 0);
				views++;
			}
		}
	assert_true(views > 500);
	free(f.px);
	r_free(r);
	map_free(m);
	tex_free(tex);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(room_3x3_is_one_sector_and_four_walls),
		cmocka_unit_test(regions_become_sectors_with_steps_between),
		cmocka_unit_test(different_wall_textures_split_a_run),
		cmocka_unit_test(separate_regions_of_one_kind_are_separate_sectors),
		cmocka_unit_test(lamps_and_things_sit_at_tile_centres),
		cmocka_unit_test(names_resolve_through_the_callbacks),
		cmocka_unit_test(errors_name_line_and_column),
		cmocka_unit_test(crlf_comments_and_trailing_blank_lines_are_accepted),
		cmocka_unit_test(larger_than_255_tiles_is_refused),
		cmocka_unit_test(builtin_grid_level_matches_its_file_and_imports),
		cmocka_unit_test(builtin_grid_level_renders_without_holes),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
