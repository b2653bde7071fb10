/*
 * fr: the flight recorder. Names are checked against dates computed by
 * hand (date -u -d @1795000000 is 2026-11-18 11:06:40 UTC); limits against
 * counts and sizes written by the test; a recording cut mid-record is
 * recovered with exactly its whole records.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "config/fr.h"
#include "input/rec.h"

#define T0 ((time_t)1795000000)

static char base[64], dir[96];

static int setup(void **state)
{
	(void)state;
	snprintf(base, sizeof(base), "/tmp/test_fr.XXXXXX");
	if (!mkdtemp(base))
		return -1;
	return 0;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", base);
	return system(cmd) == 0 ? 0 : -1;
}

/* A fresh recordings directory per test (created by fr_open). */
static void new_dir(const char *name)
{
	snprintf(dir, sizeof(dir), "%s/%s", base, name);
}

static int exists(const char *name)
{
	char p[256];

	snprintf(p, sizeof(p), "%s/%s", dir, name);
	return access(p, F_OK) == 0;
}

static void write_file(const char *path, const void *p, size_t n)
{
	int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);

	assert_true(fd >= 0);
	assert_int_equal(write(fd, p, n), (ssize_t)n);
	close(fd);
}

static struct rec_header header(void)
{
	struct rec_header h = {
		.version = REC_VERSION,
		.tick_rate = 60,
		.map_hash = 42,
		.engine_version = REC_ENGINE_VERSION,
		.set = { .coins_per_credit = 1 },
	};
	return h;
}

/* Records a finished game of n ticks into path. */
static void record(const char *path, uint32_t n)
{
	struct rec_header h = header();
	struct rec_writer *w;

	assert_int_equal(rec_writer_open(path, &h, &w), 0);
	for (uint32_t i = 0; i < n; i++) {
		struct sim_cmd c = { .turn = (int16_t)(i * 100) };

		assert_int_equal(rec_writer_put(w, &c), 0);
	}
	assert_int_equal(rec_writer_close(w), 0);
}

static void play(struct fr *f, time_t t, uint32_t ticks)
{
	char path[256];

	assert_int_equal(fr_begin_game(f, t, path, sizeof(path)), 0);
	record(path, ticks);
	assert_int_equal(fr_end_game(f, 1), 0);
}

static void test_names_carry_sequence_and_utc_time(void **state)
{
	struct fr_entry e[4];
	char path[256], want[256], msg[256];
	struct fr *f;

	(void)state;
	new_dir("names");
	assert_int_equal(fr_open(dir, 5, 0, &f, msg, sizeof(msg)), 0);
	assert_string_equal(msg, "");
	assert_int_equal(fr_begin_game(f, T0, path, sizeof(path)), 0);
	snprintf(want, sizeof(want), "%s/game-000001-20261118T110640Z.rec.part", dir);
	assert_string_equal(path, want);
	assert_int_equal(fr_begin_game(f, T0, path, sizeof(path)), -EBUSY);
	record(path, 10);
	assert_int_equal(fr_end_game(f, 1), 0);
	assert_true(exists("game-000001-20261118T110640Z.rec"));
	assert_false(exists("game-000001-20261118T110640Z.rec.part"));
	assert_int_equal(fr_end_game(f, 1), -ENOENT);
	play(f, T0 + 61, 5);
	assert_int_equal(fr_list(f, e, 4), 2);
	assert_string_equal(e[0].name, "game-000001-20261118T110640Z.rec");
	assert_string_equal(e[1].name, "game-000002-20261118T110741Z.rec");
	assert_int_equal(e[0].size, REC_HEADER_SIZE + 10 * REC_CMD_SIZE);
	assert_int_equal(e[1].seq, 2);
	assert_int_equal(e[1].cut, 0);
	assert_string_equal(fr_dir(f), dir);
	fr_close(f);
	fr_close(NULL);
}

static void test_sequence_goes_on_after_reopening(void **state)
{
	char path[256], p[256];
	struct fr *f;

	(void)state;
	new_dir("seq");
	assert_int_equal(fr_open(dir, 5, 0, &f, NULL, 0), 0);
	play(f, T0, 1);
	fr_close(f);
	/* Someone's later file, and files fr did not make, in the way. */
	snprintf(p, sizeof(p), "%s/game-000041-20261118T110640Z.rec", dir);
	write_file(p, "x", 1);
	snprintf(p, sizeof(p), "%s/notes.txt", dir);
	write_file(p, "keep me", 7);
	snprintf(p, sizeof(p), "%s/game-99-bad.rec", dir);
	write_file(p, "keep me", 7);
	assert_int_equal(fr_open(dir, 5, 0, &f, NULL, 0), 0);
	assert_int_equal(fr_begin_game(f, T0, path, sizeof(path)), 0);
	assert_non_null(strstr(path, "/game-000042-"));
	assert_int_equal(fr_end_game(f, 0), 0);    /* not kept: deleted */
	assert_false(exists("game-000042-20261118T110640Z.rec"));
	assert_false(exists("game-000042-20261118T110640Z.rec.part"));
	assert_int_equal(fr_list(f, NULL, 0), 2);
	fr_close(f);
	assert_true(exists("notes.txt"));
	assert_true(exists("game-99-bad.rec"));
}

static void test_keeps_the_newest_n(void **state)
{
	struct fr_entry e[8];
	struct fr *f;

	(void)state;
	new_dir("keep");
	assert_int_equal(fr_open(dir, 3, 0, &f, NULL, 0), 0);
	for (int i = 0; i < 5; i++)
		play(f, T0 + i, 1);
	assert_int_equal(fr_list(f, e, 8), 3);
	assert_int_equal(e[0].seq, 3);
	assert_int_equal(e[1].seq, 4);
	assert_int_equal(e[2].seq, 5);
	fr_close(f);
	/* Reopened with a smaller limit: pruned at once, and said so. */
	{
		char msg[256];

		assert_int_equal(fr_open(dir, 1, 0, &f, msg, sizeof(msg)), 0);
		assert_string_equal(msg, "removed 2 old recordings");
		assert_int_equal(fr_list(f, e, 8), 1);
		assert_int_equal(e[0].seq, 5);
		fr_close(f);
	}
}

static void test_byte_cap_removes_oldest_but_never_the_newest(void **state)
{
	const uint64_t game = REC_HEADER_SIZE + 100 * REC_CMD_SIZE;   /* 640 bytes */
	struct fr_entry e[8];
	struct fr *f;

	(void)state;
	new_dir("cap");
	/* Room for two games of 640 bytes, not three. */
	assert_int_equal(fr_open(dir, 10, 2 * game + 100, &f, NULL, 0), 0);
	for (int i = 0; i < 4; i++)
		play(f, T0 + i, 100);
	assert_int_equal(fr_list(f, e, 8), 2);
	assert_int_equal(e[0].seq, 3);
	assert_int_equal(e[1].seq, 4);
	/* One game larger than the whole cap: it alone stays. */
	play(f, T0 + 9, 1000);
	assert_int_equal(fr_list(f, e, 8), 1);
	assert_int_equal(e[0].seq, 5);
	fr_close(f);
}

static void test_cut_part_is_recovered_with_its_whole_records(void **state)
{
	struct fr_entry e[4];
	struct rec_reader *r;
	struct sim_cmd c;
	char path[256], msg[512], err[256], p[300];
	uint8_t junk[3] = { 1, 2, 3 };
	struct fr *f;
	int fd, n = 0;

	(void)state;
	new_dir("cut");
	assert_int_equal(fr_open(dir, 5, 0, &f, NULL, 0), 0);
	assert_int_equal(fr_begin_game(f, T0, path, sizeof(path)), 0);
	fr_close(f);                       /* the daemon dies mid-game */
	record(path, 10);
	/* Make it what a cut leaves: count still "unknown" (the writer only
	 * writes it at close) and half a record after the 10 whole ones. */
	fd = open(path, O_WRONLY | O_CLOEXEC);
	assert_true(fd >= 0);
	assert_int_equal(pwrite(fd, junk, 3, REC_HEADER_SIZE + 10 * REC_CMD_SIZE), 3);
	assert_int_equal(pwrite(fd, "\xff\xff\xff\xff", 4, 32), 4);
	close(fd);
	/* A second .part that never got its whole header. */
	snprintf(p, sizeof(p), "%s/game-000009-20261118T110640Z.rec.part", dir);
	write_file(p, "ARCDREC", 7);

	assert_int_equal(fr_open(dir, 5, 0, &f, msg, sizeof(msg)), 0);
	assert_non_null(strstr(msg, "recovered game-000001-20261118T110640Z-cut.rec (10 ticks)"));
	assert_non_null(strstr(msg, "removed game-000009-20261118T110640Z.rec.part (file too "
				    "short (7 bytes, the header needs 40))"));
	assert_int_equal(fr_list(f, e, 4), 1);
	assert_string_equal(e[0].name, "game-000001-20261118T110640Z-cut.rec");
	assert_int_equal(e[0].cut, 1);
	assert_int_equal(e[0].size, REC_HEADER_SIZE + 10 * REC_CMD_SIZE);
	/* The next game comes after both, the removed one included. */
	assert_int_equal(fr_begin_game(f, T0, path, sizeof(path)), 0);
	assert_non_null(strstr(path, "/game-000010-"));
	assert_int_equal(fr_end_game(f, 0), 0);
	fr_close(f);

	snprintf(p, sizeof(p), "%s/game-000001-20261118T110640Z-cut.rec", dir);
	assert_int_equal(rec_reader_open(p, &r, err, sizeof(err)), 0);
	assert_int_equal(rec_reader_header(r)->count, 10);
	while (rec_reader_next(r, &c) == 1) {
		assert_int_equal(c.turn, n * 100);
		n++;
	}
	assert_int_equal(n, 10);
	rec_reader_close(r);
}

static void test_bad_arguments(void **state)
{
	struct fr *f = NULL;
	char path[16];

	(void)state;
	new_dir("bad");
	assert_int_equal(fr_open(dir, 0, 0, &f, NULL, 0), -EINVAL);
	assert_int_equal(fr_open(dir, FR_KEEP_MAX + 1, 0, &f, NULL, 0), -EINVAL);
	assert_int_equal(fr_open("/nonexistent/parent/rec", 5, 0, &f, NULL, 0), -ENOENT);
	assert_null(f);
	assert_int_equal(fr_open(dir, 5, 0, &f, NULL, 0), 0);
	assert_int_equal(fr_begin_game(f, T0, path, sizeof(path)), -ENAMETOOLONG);
	fr_close(f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_names_carry_sequence_and_utc_time),
		cmocka_unit_test(test_sequence_goes_on_after_reopening),
		cmocka_unit_test(test_keeps_the_newest_n),
		cmocka_unit_test(test_byte_cap_removes_oldest_but_never_the_newest),
		cmocka_unit_test(test_cut_part_is_recovered_with_its_whole_records),
		cmocka_unit_test(test_bad_arguments),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
