/*
 * mesh: the OBJ subset reader. A good file with every statement and corner
 * form is read into the vertices and triangles mesh.h says (axes swapped,
 * quads split, negative indices); each kind of bad line is refused with
 * its file:line; the limits are enforced.
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

#include "engine/map/mesh.h"

#define U(x) ((fx_t)((x) * FX_ONE))

static void test_good_file(void **state)
{
	static const char text[] =
		"# a unit quad and a triangle\r\n"
		"o thing\n"
		"v 0 0 0\n"
		"v 1 0 0\n"
		"v 1.5 2.25 -3\n"
		"v -0.5 0 -.5\n"
		"vt 0 0\n"
		"vt 1 0 0\n"
		"vn 0 1 0\n"
		"g part\n"
		"s off\n"
		"f 1 2 3 4\n"
		"f 1/1 -2/2/1 -1//1   # negative: counted back from the last vertex\n"
		"\n";
	struct mesh m;
	char err[128];

	(void)state;
	assert_int_equal(mesh_parse("good.obj", text, strlen(text), &m, err, sizeof(err)), 0);
	assert_int_equal(m.nv, 4);
	assert_int_equal(m.nt, 3);
	/* OBJ (1.5, 2.25, -3) is map (1.5, 3, 2.25) */
	assert_int_equal(m.v[2].x, U(1.5));
	assert_int_equal(m.v[2].y, U(3));
	assert_int_equal(m.v[2].z, U(2.25));
	assert_int_equal(m.v[3].x, -U(0.5));
	assert_int_equal(m.v[3].y, U(0.5));
	/* the quad 1 2 3 4 is 0-1-2 and 0-2-3 */
	assert_int_equal(m.t[0].v[0], 0);
	assert_int_equal(m.t[0].v[1], 1);
	assert_int_equal(m.t[0].v[2], 2);
	assert_int_equal(m.t[1].v[0], 0);
	assert_int_equal(m.t[1].v[1], 2);
	assert_int_equal(m.t[1].v[2], 3);
	/* -2 and -1 of four vertices are the third and fourth */
	assert_int_equal(m.t[2].v[1], 2);
	assert_int_equal(m.t[2].v[2], 3);
	assert_int_equal(m.radius, U(3));
	assert_int_equal(m.zmin, 0);
	assert_int_equal(m.zmax, U(2.25));
	mesh_free(&m);
	assert_null(m.v);
	mesh_free(NULL);
}

static void test_decimals_round_to_nearest(void **state)
{
	/* 0.00001 is 0.65536 of 1/65536: rounds to 1; 0.000007 (0.46) to 0;
	 * 511.99999 to 512 - 1/65536 (0.99999 * 65536 = 65535.34) */
	static const char text[] = "v 0.00001 0.000007 511.99999\nf 1 1 1\n";
	struct mesh m;
	char err[128];

	(void)state;
	assert_int_equal(mesh_parse("r.obj", text, strlen(text), &m, err, sizeof(err)), 0);
	assert_int_equal(m.v[0].x, 1);
	assert_int_equal(m.v[0].z, 0);
	assert_int_equal(m.v[0].y, -(U(512) - 1));
	mesh_free(&m);
}

static void expect_bad(const char *text, int rc, const char *want)
{
	struct mesh m;
	char err[160] = "x";
	int got = mesh_parse("bad.obj", text, strlen(text), &m, err, sizeof(err));

	if (got != rc || strcmp(err, want) != 0)
		fail_msg("%s: got %d '%s', want %d '%s'", text, got, err, rc, want);
	assert_null(m.v);
	assert_int_equal(m.nt, 0);
}

static void test_each_bad_line_names_file_and_line(void **state)
{
	(void)state;
	expect_bad("v 0 0 0\nv 1 0\n", -EINVAL, "bad.obj:2: wrong count of numbers after 'v'");
	expect_bad("v 0 0 0 1\n", -EINVAL, "bad.obj:1: wrong count of numbers after 'v'");
	expect_bad("\n\nv 0 x 0\n", -EINVAL, "bad.obj:3: bad number (decimal within +/-512) 'x'");
	expect_bad("v 1e3 0 0\n", -EINVAL, "bad.obj:1: bad number (decimal within +/-512) '1e3'");
	expect_bad("v 513 0 0\n", -EINVAL, "bad.obj:1: bad number (decimal within +/-512) '513'");
	expect_bad("v 512.00001 0 0\n", -EINVAL,
		   "bad.obj:1: bad number (decimal within +/-512) '512.00001'");
	expect_bad("v . 0 0\n", -EINVAL, "bad.obj:1: bad number (decimal within +/-512) '.'");
	expect_bad("vn 0 1\n", -EINVAL, "bad.obj:1: wrong count of numbers after 'vn'");
	expect_bad("vt\n", -EINVAL, "bad.obj:1: wrong count of numbers after 'vt'");
	expect_bad("v 0 0 0\nv 1 0 0\nf 1 2\n", -EINVAL,
		   "bad.obj:3: f needs 3 or 4 corners (triangles and quads)");
	expect_bad("v 0 0 0\nf 1 1 1 1 1\n", -EINVAL,
		   "bad.obj:2: f needs 3 or 4 corners (triangles and quads)");
	expect_bad("v 0 0 0\nf 1 1 2\n", -EINVAL, "bad.obj:2: vertex index out of range '2'");
	expect_bad("v 0 0 0\nf 1 1 0\n", -EINVAL, "bad.obj:2: vertex index out of range '0'");
	expect_bad("v 0 0 0\nf 1 1 -2\n", -EINVAL, "bad.obj:2: vertex index out of range '-2'");
	expect_bad("v 0 0 0\nf 1 1 1/1\n", -EINVAL,
		   "bad.obj:2: texture coordinate index out of range '1/1'");
	expect_bad("v 0 0 0\nvt 0 0\nf 1 1 1//1\n", -EINVAL,
		   "bad.obj:3: normal index out of range '1//1'");
	expect_bad("v 0 0 0\nf 1 1 a\n", -EINVAL, "bad.obj:2: bad face corner 'a'");
	expect_bad("v 0 0 0\nf 1 1 1/\n", -EINVAL, "bad.obj:2: bad face corner '1/'");
	expect_bad("v 0 0 0\nvn 0 0 1\nf 1 1 1//1/1\n", -EINVAL,
		   "bad.obj:3: bad face corner '1//1/1'");
	expect_bad("mtllib a.mtl\n", -EINVAL, "bad.obj:1: unsupported statement 'mtllib'");
	expect_bad("v 0 0 0\nusemtl red\n", -EINVAL, "bad.obj:2: unsupported statement 'usemtl'");
	expect_bad("v 0 0 0\nl 1 1\n", -EINVAL, "bad.obj:2: unsupported statement 'l'");
	expect_bad("v 0 0 0\n", -EINVAL, "bad.obj:1: no faces");
	expect_bad("", -EINVAL, "bad.obj:1: no faces");
	expect_bad("v 0 0 0\n\x01x 1\n", -EINVAL, "bad.obj:2: unsupported statement '?x'");
	expect_bad("v 0 0 0 0 0 0 0 0 0\n", -EINVAL, "bad.obj:1: too many words on the line");
	{
		static const char nul[] = "v 0 0 0\nv 0\0 0 0\nf 1 1 1\n";
		struct mesh m;
		char err[80];

		assert_int_equal(mesh_parse("bad.obj", nul, sizeof nul - 1, &m, err, sizeof(err)),
				 -EINVAL);
		assert_string_equal(err, "bad.obj:2: NUL byte in the line");
	}
}

/* text of n lines "v 0 0 0" then "f 1 1 1" lines */
static char *repeat(const char *line, unsigned n, const char *tail)
{
	size_t l = strlen(line), t = strlen(tail);
	char *s = malloc(l * n + t + 1);

	assert_non_null(s);
	for (unsigned i = 0; i < n; i++)
		memcpy(s + i * l, line, l);
	memcpy(s + (size_t)n * l, tail, t + 1);
	return s;
}

static void test_limits(void **state)
{
	struct mesh m;
	char err[128];
	char *s;

	(void)state;
	s = repeat("v 0 0 0\n", MESH_MAX_VERTS, "f 1 2 3\n");
	assert_int_equal(mesh_parse("lim.obj", s, strlen(s), &m, err, sizeof(err)), 0);
	assert_int_equal(m.nv, MESH_MAX_VERTS);
	mesh_free(&m);
	free(s);
	s = repeat("v 0 0 0\n", MESH_MAX_VERTS + 1, "f 1 2 3\n");
	assert_int_equal(mesh_parse("lim.obj", s, strlen(s), &m, err, sizeof(err)), -E2BIG);
	assert_string_equal(err, "lim.obj:1025: more than 1024 vertices");
	free(s);
	/* 1024 quads are 2048 triangles; one triangle more is too many */
	{
		size_t l = strlen("v 0 0 0\n") * 4;
		char *q = repeat("f 1 2 3 4\n", MESH_MAX_TRIS / 2, "f 1 2 3\n");
		char *all = malloc(l + strlen(q) + 1);

		assert_non_null(all);
		memcpy(all, "v 0 0 0\nv 0 0 0\nv 0 0 0\nv 0 0 0\n", l);
		strcpy(all + l, q);
		assert_int_equal(mesh_parse("lim.obj", all, strlen(all), &m, err, sizeof(err)), -E2BIG);
		assert_string_equal(err, "lim.obj:1029: more than 2048 triangles");
		all[strlen(all) - strlen("f 1 2 3\n")] = '\0';
		assert_int_equal(mesh_parse("lim.obj", all, strlen(all), &m, err, sizeof(err)), 0);
		assert_int_equal(m.nt, MESH_MAX_TRIS);
		mesh_free(&m);
		free(all);
		free(q);
	}
	s = repeat("vt 0\n", MESH_MAX_AUX + 1, "");
	assert_int_equal(mesh_parse("lim.obj", s, strlen(s), &m, err, sizeof(err)), -E2BIG);
	assert_string_equal(err, "lim.obj:4097: more than 4096 texture coordinates");
	free(s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_good_file),
		cmocka_unit_test(test_decimals_round_to_nearest),
		cmocka_unit_test(test_each_bad_line_names_file_and_line),
		cmocka_unit_test(test_limits),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
