/*
 * mdir: mesh directories made here file by file: a good mesh for a pickup
 * (drawn for its type, in its colour, by the game's sprites and the
 * software renderer), a bad one for the lamp (refused with file:line, the
 * lamp keeps its built-in mesh), a bad colour line, a file too large, names that are no
 * thing type's, a monster's type, a second file for one type, a FIFO.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/mdir.h"
#include "engine/core/hash.h"
#include "engine/game/sim.h"
#include "engine/map/mesh_builtin.h"
#include "engine/map/tex.h"
#include "engine/render/r_game.h"
#include "engine/render/r_main.h"
#include "file_fixture.h"
#include "g_fixture.h"

static char dir[64];
static char notes[4096];
static int nbad, nign;

/* A pyramid 40 wide and 48 high, faces counter-clockwise from outside. */
static const char pyramid[] =
	"# a marker\n"
	"# arcaded colour 20e040\n"
	"o pyramid\n"
	"v -20 0 -20\nv 20 0 -20\nv 20 0 20\nv -20 0 20\nv 0 48 0\n"
	"f 1 2 3 4\n"            /* the base, seen from below */
	"f 4 3 5\nf 3 2 5\nf 2 1 5\nf 1 4 5\n";

static void note(void *user, int bad, const char *msg)
{
	(void)user;
	if (bad)
		nbad++;
	else
		nign++;
	strncat(notes, msg, sizeof(notes) - strlen(notes) - 2);
	strcat(notes, "\n");
}

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/test_mdir.XXXXXX");
	assert_non_null(mkdtemp(dir));
	notes[0] = 0;
	nbad = nign = 0;
	return 0;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	assert_int_equal(system(cmd), 0);
	return 0;
}

static void good_mesh_is_drawn_for_its_type(void **state)
{
	static const struct gf_thing t[] = {
		{ 100, 128, 0, 1, 0 },
		{ 300, 128, 0, 2012, 0 },                    /* medikit: the file's mesh */
		{ 400, 128, 0, 2028, 0 },                    /* floor lamp: built in */
	};
	static const struct sim_settings play = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
	struct map *m = gf_room(1024, 256, t, 3, NULL, 0);
	struct r_sprite out[8], plain[8];
	struct tex_set *ts;
	struct r_ctx *r;
	struct r_view v = { 0 };
	struct r_frame f = { 0 };
	uint8_t *px;
	struct sim s;
	struct mdir d;
	int n, k, diff = 0;

	(void)state;
	ff_put(dir, "2012.obj", pyramid);
	assert_int_equal(mdir_load(&d, dir, note, NULL), 1);
	assert_int_equal(d.set.n, 1);
	assert_ptr_equal(d.set.v, d.v);
	assert_int_equal(d.v[0].type, 2012);
	assert_int_equal(d.v[0].r, 0x20);
	assert_int_equal(d.v[0].g, 0xe0);
	assert_int_equal(d.v[0].b, 0x40);
	assert_int_equal(d.v[0].m.nv, 5);
	assert_int_equal(d.v[0].m.nt, 6);
	assert_true(d.hash != HASH_INIT);
	assert_int_equal(nbad + nign, 0);

	assert_non_null(m);
	assert_int_equal(tex_builtin(&ts), 0);
	sim_init(&s, m, &play);
	n = r_game_sprites(&s, ts, &d.set, out, 8);
	assert_int_equal(n, 2);
	assert_int_equal(out[0].x, fx_from_int(300));
	assert_int_equal(out[0].mesh, R_MESH_LOADED);
	assert_ptr_equal(out[0].mp, &d.v[0].m);
	assert_int_equal(out[0].colour, pal_nearest(&ts->pal, 0x20, 0xe0, 0x40));
	assert_int_equal(out[1].mesh, MESH_B_LAMP);     /* not in the directory */
	assert_null(out[1].mp);
	/* without the table: the medikit's sprite */
	assert_int_equal(r_game_sprites(&s, ts, NULL, plain, 8), 2);
	assert_int_equal(plain[0].mesh, 0);
	assert_null(plain[0].mp);

	/* and the software renderer draws it: the frame differs from one
	 * without it (the lamp alone) */
	assert_int_equal(r_new(160, 100, &r), 0);
	px = calloc(2, 160 * 100);
	assert_non_null(px);
	f.w = 160, f.h = 100, f.pitch = 160;
	v.x = fx_from_int(100);
	v.y = fx_from_int(128);
	v.z = fx_from_int(41);
	f.px = px;
	r_render(r, m, ts, &v, out, n, &f);
	f.px = px + 160 * 100;
	r_render(r, m, ts, &v, out + 1, n - 1, &f);
	for (k = 0; k < 160 * 100; k++)
		diff += px[k] != px[160 * 100 + k];
	assert_true(diff > 100);                        /* 185 when written */
	free(px);
	r_free(r);
	tex_free(ts);
	map_free(m);
	mdir_free(&d);
	assert_int_equal(d.n, 0);
	assert_null(d.v);
}

static void bad_file_refused_with_file_and_line(void **state)
{
	struct r_sprite sp;
	struct tex_set *ts;
	struct mdir d;

	(void)state;
	/* line 3 names a vertex the file lacks */
	ff_put(dir, "2028.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
	ff_put(dir, "0005.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# arcaded colour 12345\n");
	ff_put(dir, "2012.obj", pyramid);
	{
		/* past MDIR_FILE_MAX: refused unread, even as comments */
		char path[128];
		FILE *f;

		snprintf(path, sizeof(path), "%s/2014.obj", dir);
		f = fopen(path, "w");
		assert_non_null(f);
		for (unsigned k = 0; k <= MDIR_FILE_MAX / 8; k++)
			fputs("# 34567\n", f);
		fclose(f);
	}
	assert_int_equal(mdir_load(&d, dir, note, NULL), 1);
	assert_int_equal(nbad, 3);
	assert_int_equal(d.nbad, 3);
	assert_non_null(strstr(notes, "2014.obj: larger than 1048576 bytes; refused"));
	assert_non_null(strstr(notes, "2028.obj:3: "));
	assert_non_null(strstr(notes, "0005.obj:5: bad colour"));
	/* the lamp and the blue card keep their built-in mesh */
	assert_int_equal(tex_builtin(&ts), 0);
	assert_int_equal(r_game_mesh(ts, &d.set, 2028, 0, 0, 0, 0, &sp), 1);
	assert_int_equal(sp.mesh, MESH_B_LAMP);
	assert_null(sp.mp);
	assert_int_equal(r_game_mesh(ts, &d.set, 5, 0, 0, 0, 0, &sp), 1);
	assert_int_equal(sp.mesh, MESH_B_KEY);
	tex_free(ts);
	mdir_free(&d);
}

static void other_names_ignored_with_a_note(void **state)
{
	struct mdir d;

	(void)state;
	ff_put(dir, "lamp.obj", pyramid);
	ff_put(dir, "readme.txt", "hello\n");
	ff_put(dir, "3004.obj", pyramid);          /* zombieman: not drawn as a mesh */
	ff_put(dir, "20000.obj", pyramid);         /* no such thing */
	ff_put(dir, "2012.OBJ", pyramid);
	ff_put(dir, "02012.obj", pyramid);         /* 2012, before "2012.OBJ" in name order */
	ff_put(dir, ".hidden.obj", pyramid);       /* skipped without a note */
	{
		char fifo[128];
		snprintf(fifo, sizeof(fifo), "%s/2014.obj", dir);
		assert_int_equal(mkfifo(fifo, 0600), 0);
	}
	assert_int_equal(mdir_load(&d, dir, note, NULL), 1);
	assert_int_equal(d.v[0].type, 2012);
	assert_int_equal(nign, 5);
	assert_int_equal(nbad, 1);                      /* the FIFO: never opened for long */
	assert_non_null(strstr(notes, "lamp.obj: not NNNN.obj"));
	assert_non_null(strstr(notes, "readme.txt: not NNNN.obj"));
	assert_non_null(strstr(notes, "3004.obj: thing type 3004 is no prop or pickup"));
	assert_non_null(strstr(notes, "20000.obj: thing type 20000 is no prop or pickup"));
	assert_non_null(strstr(notes, "2012.OBJ: a second mesh for thing type 2012"));
	assert_non_null(strstr(notes, "2014.obj: not a regular file"));
	assert_null(strstr(notes, "hidden"));
	mdir_free(&d);
}

static void colour_defaults_and_no_directory(void **state)
{
	struct mdir d;

	(void)state;
	/* no colour line: the lamp's brass, a medikit's grey */
	ff_put(dir, "2028.obj", pyramid + strlen("# a marker\n# arcaded colour 20e040\n"));
	ff_put(dir, "2012.obj", pyramid + strlen("# a marker\n# arcaded colour 20e040\n"));
	assert_int_equal(mdir_load(&d, dir, note, NULL), 2);
	assert_int_equal(d.v[0].type, 2012);
	assert_int_equal(d.v[0].r, 160);
	assert_int_equal(d.v[0].g, 160);
	assert_int_equal(d.v[1].type, 2028);
	assert_int_equal(d.v[1].r, 232);
	assert_int_equal(d.v[1].g, 176);
	assert_int_equal(d.v[1].b, 64);
	mdir_free(&d);
	assert_int_equal(mdir_load(&d, "", note, NULL), 0);
	assert_null(d.set.v);
	assert_null(mesh_set_find(&d.set, 2012));
	assert_int_equal(mdir_load(&d, "/nonexistent/meshes", note, NULL), -ENOENT);
	assert_int_equal(nbad, 1);
	mdir_free(&d);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(good_mesh_is_drawn_for_its_type, setup, teardown),
		cmocka_unit_test_setup_teardown(bad_file_refused_with_file_and_line, setup, teardown),
		cmocka_unit_test_setup_teardown(other_names_ignored_with_a_note, setup, teardown),
		cmocka_unit_test_setup_teardown(colour_defaults_and_no_directory, setup, teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
