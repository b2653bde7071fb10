/* Tests for engine/map/wad.c: header and directory checks, names, lookups and
 * layering, the lookup index against a plain scan, and the limit on lumps
 * (issue 13 item 8). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/map/wad.h"
#include "wad_fixture.h"

/* A PWAD of three lumps: "e1m1" (lower case in the file, 0 bytes, offset
 * 99999 on purpose: markers may point anywhere), "DATA" (4 bytes 1 2 3 4),
 * and "LONGNAME" (8 chars, no NUL, 2 bytes 9 9). */
static uint8_t *small_wad(size_t *len)
{
	struct wfix f;
	static const uint8_t data[4] = { 1, 2, 3, 4 }, two[2] = { 9, 9 };
	uint8_t *w;

	wf_init(&f);
	wf_lump(&f, "e1m1", NULL, 0);
	wf_lump(&f, "DATA", data, 4);
	wf_lump(&f, "LONGNAME", two, 2);
	w = wf_finish(&f, "PWAD", len);
	/* directory entry 0's offset: the directory is the last 48 bytes */
	wb_put32(&(struct wbuf){ w, *len, *len }, *len - 48, 99999);
	return w;
}

static int add(struct wad *w, const uint8_t *d, size_t len, char *err)
{
	return wad_add(w, d, len, "t.wad", err, 160);
}

static void reads_names_and_data(void **state)
{
	size_t len, n;
	uint8_t *d = small_wad(&len);
	struct wad *w;
	char err[160];
	const uint8_t *p;

	(void)state;
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(add(w, d, len, err), 0);
	assert_int_equal(wad_count(w), 3);
	assert_string_equal(wad_name(w, 0), "E1M1");
	assert_string_equal(wad_name(w, 2), "LONGNAME");
	assert_int_equal(wad_find(w, "data"), 1);
	assert_int_equal(wad_find(w, "E1m1"), 0);
	assert_int_equal(wad_find(w, "LONGNAME"), 2);
	assert_int_equal(wad_find(w, "LONGNAMEX"), -1);
	assert_int_equal(wad_find(w, "NOPE"), -1);
	p = wad_data(w, 1, &n);
	assert_int_equal(n, 4);
	assert_int_equal(p[0], 1);
	assert_int_equal(p[3], 4);
	wad_data(w, 0, &n);
	assert_int_equal(n, 0);
	assert_null(wad_data(w, 3, &n));
	assert_int_equal(n, 0);
	assert_null(wad_data(w, -1, &n));
	assert_string_equal(wad_name(w, 7), "");
	assert_string_equal(wad_file(w, 2), "t.wad");
	assert_string_equal(wad_file(w, 3), "");
	wad_free(w);
	free(d);
}

static void later_file_wins(void **state)
{
	struct wfix f;
	size_t l1, l2, n;
	uint8_t *a, *b;
	struct wad *w;
	char err[160];
	static const uint8_t one = 1, two = 2;

	(void)state;
	wf_init(&f);
	wf_lump(&f, "X", &one, 1);
	wf_lump(&f, "ONLYA", &one, 1);
	a = wf_finish(&f, "IWAD", &l1);
	wf_init(&f);
	wf_lump(&f, "X", &two, 1);
	b = wf_finish(&f, "PWAD", &l2);
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, a, l1, "a.wad", err, sizeof err), 0);
	assert_int_equal(wad_add(w, b, l2, "b.wad", err, sizeof err), 0);
	assert_int_equal(wad_count(w), 3);
	assert_int_equal(wad_find(w, "X"), 2);
	assert_int_equal(*wad_data(w, wad_find(w, "X"), &n), 2);
	assert_string_equal(wad_file(w, 2), "b.wad");
	assert_string_equal(wad_file(w, 1), "a.wad");
	assert_int_equal(wad_find_from(w, "X", 0), 0);
	assert_int_equal(wad_find_from(w, "X", 1), 2);
	assert_int_equal(wad_find_from(w, "X", 3), -1);
	assert_int_equal(wad_find(w, "ONLYA"), 1);
	wad_free(w);
	free(a);
	free(b);
}

/* wad_add on a copy of small_wad changed by `breakit`; the set stays
 * empty on error. */
static int add_broken(void (*breakit)(uint8_t *d, size_t *len), char *err)
{
	size_t len;
	uint8_t *d = small_wad(&len);
	struct wad *w;
	int r;

	breakit(d, &len);
	assert_int_equal(wad_new(&w), 0);
	r = add(w, d, len, err);
	if (r)
		assert_int_equal(wad_count(w), 0);
	wad_free(w);
	free(d);
	return r;
}

static void cut_header(uint8_t *d, size_t *len) { (void)d; *len = 11; }
static void bad_magic(uint8_t *d, size_t *len) { (void)len; memcpy(d, "JWAD", 4); }
static void dir_past_end(uint8_t *d, size_t *len) { (void)d; *len -= 1; }
static void many_lumps(uint8_t *d, size_t *len) { (void)len; d[4] = 0xff; d[5] = 0xff; }
static void neg_count(uint8_t *d, size_t *len) { (void)len; d[7] = 0x80; }
static void lump_past_end(uint8_t *d, size_t *len)
{
	/* DATA's size (entry 1 at len-32, size at +4) grows to 9000 */
	wb_put32(&(struct wbuf){ d, *len, *len }, *len - 32 + 4, 9000);
}
static void neg_size(uint8_t *d, size_t *len)
{
	wb_put32(&(struct wbuf){ d, *len, *len }, *len - 32 + 4, -5);
}
static void huge_offset(uint8_t *d, size_t *len)
{
	wb_put32(&(struct wbuf){ d, *len, *len }, *len - 16, 0x7fffffff);
}

static void bad_files_name_file_lump_and_problem(void **state)
{
	char err[160], want[160];
	size_t len;
	uint8_t *d = small_wad(&len);

	(void)state;
	free(d);
	assert_int_equal(add_broken(cut_header, err), -EINVAL);
	assert_string_equal(err, "t.wad: shorter than a WAD header (12 bytes)");
	assert_int_equal(add_broken(bad_magic, err), -EINVAL);
	assert_string_equal(err, "t.wad: not a WAD file (no IWAD/PWAD signature)");
	assert_int_equal(add_broken(dir_past_end, err), -EINVAL);
	/* 12 header + 4 + 2 data = 18: the directory starts at 18 */
	snprintf(want, sizeof want,
		 "t.wad: directory of 3 lumps at 18 runs past the end of the file (%zu)", len - 1);
	assert_string_equal(err, want);
	assert_int_equal(add_broken(many_lumps, err), -EINVAL);
	assert_int_equal(add_broken(neg_count, err), -EINVAL);
	assert_int_equal(add_broken(lump_past_end, err), -EINVAL);
	/* DATA starts at 12 (e1m1 is empty) */
	snprintf(want, sizeof want,
		 "t.wad: lump 1 (DATA) ends at 9012, past the end of the file (%zu)", len);
	assert_string_equal(err, want);
	assert_int_equal(add_broken(neg_size, err), -EINVAL);
	assert_string_equal(err, "t.wad: lump 1 (DATA) has a negative offset or size");
	assert_int_equal(add_broken(huge_offset, err), -EINVAL);
	snprintf(want, sizeof want,
		 "t.wad: lump 2 (LONGNAME) ends at 2147483649, past the end of the file (%zu)",
		 len);
	assert_string_equal(err, want);
}

static void every_truncation_is_refused_or_bounded(void **state)
{
	size_t len;
	uint8_t *d = small_wad(&len);
	char err[160];

	(void)state;
	/* each prefix in its own exact-size buffer, so ASan sees any read past
	 * it; a prefix either fails or (only the whole file) loads */
	for (size_t n = 0; n <= len; n++) {
		uint8_t *cut = malloc(n ? n : 1);
		struct wad *w;
		int r;

		memcpy(cut, d, n);
		assert_int_equal(wad_new(&w), 0);
		r = wad_add(w, cut, n, "cut.wad", err, sizeof err);
		assert_int_equal(r, n == len ? 0 : -EINVAL);
		wad_free(w);
		free(cut);
	}
	free(d);
}

static void free_accepts_null(void **state)
{
	(void)state;
	wad_free(NULL);
}

/* A directory claiming more lumps than WAD_MAX_LUMPS (each entry really
 * there) is refused with the file and the limit, before anything is kept;
 * exactly the limit is fine, and one more in a second file is refused. */
static void lumps_over_the_limit_are_refused(void **state)
{
	struct wad *w;
	struct wfix f;
	uint8_t *img, *one;
	size_t len, len1;
	char err[160];

	(void)state;
	wf_init(&f);
	for (int i = 0; i < WAD_MAX_LUMPS + 1; i++)
		wf_lump(&f, "M", NULL, 0);
	img = wf_finish(&f, "PWAD", &len);
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "many.wad", err, sizeof err), -E2BIG);
	assert_string_equal(err, "many.wad: 262145 lumps, more than the limit of 262144 in all "
				 "files (WAD_MAX_LUMPS)");
	assert_int_equal(wad_count(w), 0);
	/* the same directory less one entry: exactly the limit */
	wb_put32(&(struct wbuf){ img, len, len }, 4, WAD_MAX_LUMPS);
	assert_int_equal(wad_add(w, img, len, "many.wad", err, sizeof err), 0);
	assert_int_equal(wad_count(w), WAD_MAX_LUMPS);
	wf_init(&f);
	wf_lump(&f, "X", NULL, 0);
	one = wf_finish(&f, "PWAD", &len1);
	assert_int_equal(wad_add(w, one, len1, "one.wad", err, sizeof err), -E2BIG);
	assert_non_null(strstr(err, "one.wad: 1 lumps, more than the limit"));
	wad_free(w);
	free(img);
	free(one);
}

/* Last and first-from lookups by a linear scan, the definition the index
 * must agree with. */
static int scan_last(const struct wad *w, const char *name)
{
	for (int i = wad_count(w) - 1; i >= 0; i--)
		if (strcmp(wad_name(w, i), name) == 0)
			return i;
	return -1;
}

static int scan_from(const struct wad *w, const char *name, int from)
{
	for (int i = from < 0 ? 0 : from; i < wad_count(w); i++)
		if (strcmp(wad_name(w, i), name) == 0)
			return i;
	return -1;
}

/* Three files of 500 lumps named from a small alphabet (many repeats):
 * every name's wad_find and wad_find_from at every start equal the scan's. */
static void index_lookups_equal_a_scan(void **state)
{
	static const char *const pool[] = { "A", "B", "THINGS", "E1M1", "F_START", "ZZZZZZZZ",
					    "b2", "MAP01" };
	uint8_t *img[3];
	struct wad *w;
	uint32_t seed = 12345;
	char err[160];

	(void)state;
	assert_int_equal(wad_new(&w), 0);
	for (int k = 0; k < 3; k++) {
		struct wfix f;
		size_t len;

		wf_init(&f);
		for (int i = 0; i < 500; i++) {
			seed = seed * 1103515245u + 12345u;
			wf_lump(&f, pool[(seed >> 16) % 8], NULL, 0);
		}
		img[k] = wf_finish(&f, "PWAD", &len);
		assert_int_equal(wad_add(w, img[k], len, "r.wad", err, sizeof err), 0);
	}
	for (int p = 0; p < 8; p++) {
		char up[9] = "";

		for (int c = 0; c < 8 && pool[p][c]; c++)
			up[c] = (char)(pool[p][c] >= 'a' && pool[p][c] <= 'z' ? pool[p][c] - 32
									      : pool[p][c]);
		assert_int_equal(wad_find(w, pool[p]), scan_last(w, up));
		for (int from = -1; from <= wad_count(w); from++)
			assert_int_equal(wad_find_from(w, pool[p], from), scan_from(w, up, from));
	}
	assert_int_equal(wad_find(w, "NONE"), -1);
	assert_int_equal(wad_find_from(w, "NONE", 0), -1);
	wad_free(w);
	for (int k = 0; k < 3; k++)
		free(img[k]);
}

/* The committed files (tests/data/wad/, written by mkfixtures.c) are the
 * images the tests build. They are part of the repository: a missing one is
 * a failure, not a skip (the suite runs from the repository root). */
static void fixtures_on_disk_match_generator(void **state)
{
	static const char *const names[2] = { "tests/data/wad/fixture.wad",
					      "tests/data/wad/nonodes.wad" };
	(void)state;
	for (int i = 0; i < 2; i++) {
		size_t len, flen;
		uint8_t *want = i ? wfx_nonodes(&len) : wfx_iwad(&len), *got;
		FILE *f = fopen(names[i], "rbe");

		if (!f) {
			free(want);
			fail_msg("%s not found: it is part of the repository (run the test from "
				 "the repository root)", names[i]);
		}
		got = malloc(len + 1);
		assert_non_null(got);
		flen = fread(got, 1, len + 1, f);
		fclose(f);
		if (flen != len || memcmp(got, want, len) != 0)
			fail_msg("%s differs from wad_fixture.h: rerun tests/data/wad/mkfixtures.c",
				 names[i]);
		free(got);
		free(want);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(reads_names_and_data),
		cmocka_unit_test(later_file_wins),
		cmocka_unit_test(bad_files_name_file_lump_and_problem),
		cmocka_unit_test(every_truncation_is_refused_or_bounded),
		cmocka_unit_test(free_accepts_null),
		cmocka_unit_test(fixtures_on_disk_match_generator),
		cmocka_unit_test(lumps_over_the_limit_are_refused),
		cmocka_unit_test(index_lookups_equal_a_scan),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
