/*
 * wads: content directories made here, byte by byte, with WADs whose
 * headers and directories are written by hand (so what counts as a map
 * and where a directory ends are known without the code under test), and
 * the junk an operator's USB stick brings: a truncated WAD, a text file
 * named .wad, a FIFO (opening it without O_NONBLOCK would block), a
 * directory named .wad, a WAD without maps, a hidden file.
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

#include "app/wads.h"
#include "file_fixture.h"

static char dir[64];

static void put32(uint8_t *b, uint32_t v)
{
	b[0] = (uint8_t)v;
	b[1] = (uint8_t)(v >> 8);
	b[2] = (uint8_t)(v >> 16);
	b[3] = (uint8_t)(v >> 24);
}

/* Writes dir/name: magic, the lumps' names (no data: every lump is 0 bytes
 * at offset 12), the directory right after the header; cut keeps only the
 * first cut bytes (0: all). */
static void write_wad(const char *name, const char *magic, const char *const *lumps, int n,
		      size_t cut)
{
	uint8_t buf[12 + 16 * 16] = { 0 };
	char path[128];
	size_t len = 12 + 16 * (size_t)n;
	FILE *f;

	memcpy(buf, magic, 4);
	put32(buf + 4, (uint32_t)n);
	put32(buf + 8, 12);
	for (int i = 0; i < n; i++) {
		put32(buf + 12 + 16 * i, 12);
		strncpy((char *)buf + 12 + 16 * i + 8, lumps[i], 8);
	}
	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(buf, 1, cut ? cut : len, f), cut ? cut : len);
	fclose(f);
}

struct seen {
	int n;
	char path[16][128];
	char why[16][160];
};

static void on_bad(void *user, const char *path, const char *why)
{
	struct seen *s = user;

	assert_true(s->n < 16);
	snprintf(s->path[s->n], sizeof(s->path[0]), "%s", path);
	snprintf(s->why[s->n], sizeof(s->why[0]), "%s", why);
	s->n++;
}

/* The reason reported for dir/name, or NULL when it was not refused. */
static const char *why_for(const struct seen *s, const char *name)
{
	char path[128];

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	for (int i = 0; i < s->n; i++)
		if (strcmp(s->path[i], path) == 0)
			return s->why[i];
	return NULL;
}

static int setup(void **state)
{
	static const char *const doom[] = { "E1M1", "THINGS", "LINEDEFS", "E1M2", "THINGS",
					    "PLAYPAL" };
	static const char *const pwad[] = { "MAP01", "THINGS", "MAP07", "THINGS" };
	static const char *const nomaps[] = { "PLAYPAL", "COLORMAP", "E1M10", "MAP1" };
	char p[128];

	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/test_wads.XXXXXX");
	assert_non_null(mkdtemp(dir));
	write_wad("b_doom.wad", "IWAD", doom, 6, 0);
	write_wad("a_extra.WAD", "PWAD", pwad, 4, 0);
	/* the directory promised 6 entries; 2 of them are missing */
	write_wad("c_trunc.wad", "IWAD", doom, 6, 12 + 16 * 4);
	ff_put(dir, "d_text.wad", "these are not the maps you are looking for\n");
	write_wad("e_nomaps.wad", "PWAD", nomaps, 4, 0);
	write_wad(".hidden.wad", "IWAD", doom, 6, 0);
	write_wad("f_doom.wad.bak", "IWAD", doom, 6, 0);
	snprintf(p, sizeof(p), "%s/g_fifo.wad", dir);
	assert_int_equal(mkfifo(p, 0600), 0);
	snprintf(p, sizeof(p), "%s/h_dir.wad", dir);
	assert_int_equal(mkdir(p, 0700), 0);
	return 0;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void test_scan_lists_the_wads_in_name_order_with_their_maps(void **state)
{
	static struct wads w;
	struct seen s = { 0 };
	char dirs[160];

	(void)state;
	snprintf(dirs, sizeof(dirs), "/nonexistent/arcaded %s", dir);
	assert_int_equal(wads_scan(&w, dirs, on_bad, &s), 2);
	assert_string_equal(wads_name(&w.pack[0]), "a_extra.WAD");
	assert_int_equal(w.pack[0].iwad, 0);
	assert_int_equal(w.pack[0].nmaps, 2);
	assert_string_equal(w.pack[0].maps[0], "MAP01");
	assert_string_equal(w.pack[0].maps[1], "MAP07");
	assert_string_equal(wads_name(&w.pack[1]), "b_doom.wad");
	assert_int_equal(w.pack[1].iwad, 1);
	assert_int_equal(w.pack[1].nmaps, 2);
	assert_string_equal(w.pack[1].maps[0], "E1M1");
	assert_string_equal(w.pack[1].maps[1], "E1M2");
}

static void test_scan_names_every_refused_file_with_its_reason(void **state)
{
	static struct wads w;
	struct seen s = { 0 };
	const char *why;

	(void)state;
	wads_scan(&w, dir, on_bad, &s);
	/* five refused: the hidden file and the .bak are not WAD names */
	assert_int_equal(s.n, 5);
	assert_int_equal(w.nbad, 5);
	why = why_for(&s, "c_trunc.wad");
	assert_non_null(why);
	/* its header: directory at 12, 6 entries; the file: 12 + 4 x 16 */
	assert_string_equal(why, "truncated: directory at 12 + 16 x 6 bytes, file 76 bytes");
	why = why_for(&s, "d_text.wad");
	assert_non_null(why);
	assert_non_null(strstr(why, "not a WAD"));
	why = why_for(&s, "e_nomaps.wad");
	assert_non_null(why);
	assert_non_null(strstr(why, "no maps"));
	why = why_for(&s, "g_fifo.wad");
	assert_non_null(why);
	assert_string_equal(why, "not a regular file");
	why = why_for(&s, "h_dir.wad");
	assert_non_null(why);
	assert_string_equal(why, "not a regular file");
	assert_null(why_for(&s, ".hidden.wad"));
	/* kept for the screen by file name, in name order */
	assert_int_equal(strncmp(w.bad[0], "c_trunc.wad: truncated", 22), 0);
}

static void test_check_refuses_a_directory_past_the_end(void **state)
{
	static const char *const one[] = { "MAP01" };
	struct wads_pack p;
	char why[160], path[128];

	(void)state;
	/* a lump count so large the directory cannot be in a 28-byte file */
	write_wad("z_big.wad", "PWAD", one, 1, 0);
	snprintf(path, sizeof(path), "%s/z_big.wad", dir);
	{
		FILE *f = fopen(path, "r+b");
		uint8_t n[4];
		assert_non_null(f);
		put32(n, 2);
		fseek(f, 4, SEEK_SET);
		fwrite(n, 1, 4, f);
		fclose(f);
	}
	assert_int_equal(wads_check(path, &p, why, sizeof(why)), -EBADMSG);
	assert_string_equal(why, "truncated: directory at 12 + 16 x 2 bytes, file 28 bytes");
	unlink(path);
	snprintf(path, sizeof(path), "%s/none.wad", dir);
	assert_int_equal(wads_check(path, &p, why, sizeof(why)), -ENOENT);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_scan_lists_the_wads_in_name_order_with_their_maps),
		cmocka_unit_test(test_scan_names_every_refused_file_with_its_reason),
		cmocka_unit_test(test_check_refuses_a_directory_past_the_end),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
