/*
 * st: state files. The header layout is written out by hand from st.h
 * with CRCs from zlib's crc32 (a second implementation); every damage to
 * either copy falls back or fails as st.h says; a failed write (a file
 * size limit makes the kernel cut the write short, as a full disk would)
 * loses nothing.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "config/st.h"

static char dir[64];

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/test_st.XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void path_of(char *buf, size_t len, const char *name)
{
	snprintf(buf, len, "%s/%s", dir, name);
}

static long file_size(const char *name)
{
	char p[128];
	struct stat sb;

	path_of(p, sizeof(p), name);
	return stat(p, &sb) == 0 ? (long)sb.st_size : -1;
}

static int exists(const char *name)
{
	return file_size(name) >= 0;
}

/* Overwrites one byte of a file at off with v. */
static void poke(const char *name, long off, uint8_t v)
{
	char p[128];
	int fd;

	path_of(p, sizeof(p), name);
	fd = open(p, O_WRONLY | O_CLOEXEC);
	assert_true(fd >= 0);
	assert_int_equal(pwrite(fd, &v, 1, off), 1);
	close(fd);
}

static void cut(const char *name, long size)
{
	char p[128];

	path_of(p, sizeof(p), name);
	assert_int_equal(truncate(p, size), 0);
}

static void rm(const char *name)
{
	char p[128];

	path_of(p, sizeof(p), name);
	assert_int_equal(unlink(p), 0);
}

/* Loads and expects payload want (a string) from copy w. */
static void expect_load(const char *name, const char *want, enum st_which w, char *msg,
			size_t msglen)
{
	enum st_which which = (enum st_which)-1;
	void *buf = NULL;
	size_t len = 99;

	assert_int_equal(st_load(dir, name, &buf, &len, &which, msg, msglen), 0);
	assert_int_equal(len, strlen(want));
	assert_memory_equal(buf, want, len);
	assert_int_equal(which, w);
	free(buf);
}

static void save_str(const char *name, const char *s)
{
	assert_int_equal(st_save(dir, name, s, strlen(s)), 0);
}

static void test_crc32_standard_check_values(void **state)
{
	(void)state;
	assert_int_equal(st_crc32(0, "123456789", 9), 0xcbf43926u);
	assert_int_equal(st_crc32(0, "abc", 3), 0x352441c2u);
	assert_int_equal(st_crc32(0, "", 0), 0);
	/* Chained in two parts equals one pass. */
	assert_int_equal(st_crc32(st_crc32(0, "1234", 4), "56789", 5), 0xcbf43926u);
}

static void test_header_layout_by_hand(void **state)
{
	static const uint8_t want[ST_HEADER_SIZE] = {
		'A', 'R', 'C', 'D', 'S', 'T', 'A', 0,    /* magic */
		0x01, 0x00,                              /* version 1 */
		0x18, 0x00,                              /* header size 24 */
		0x03, 0x00, 0x00, 0x00,                  /* length 3 */
		0xc2, 0x41, 0x24, 0x35,                  /* crc32("abc") */
		0x18, 0xbb, 0x27, 0x19,                  /* crc32 of bytes 0..19 */
	};
	uint8_t hdr[ST_HEADER_SIZE], img[ST_HEADER_SIZE + 3];
	size_t plen = 0;

	(void)state;
	st_header(hdr, "abc", 3);
	assert_memory_equal(hdr, want, sizeof(want));
	memcpy(img, hdr, sizeof(hdr));
	memcpy(img + ST_HEADER_SIZE, "abc", 3);
	assert_int_equal(st_check(img, sizeof(img), &plen, NULL, 0), 0);
	assert_int_equal(plen, 3);
	/* The saved file is exactly header + payload. */
	save_str("layout", "abc");
	assert_int_equal(file_size("layout"), ST_HEADER_SIZE + 3);
}

static void test_check_names_each_damage(void **state)
{
	uint8_t img[ST_HEADER_SIZE + 3], bad[sizeof(img)];
	char why[128];
	size_t plen;

	(void)state;
	st_header(img, "abc", 3);
	memcpy(img + ST_HEADER_SIZE, "abc", 3);

	assert_int_equal(st_check(img, 10, &plen, why, sizeof(why)), -EBADMSG);
	assert_string_equal(why, "too short (10 bytes)");
	memcpy(bad, img, sizeof(img));
	bad[0] = 'X';
	assert_int_equal(st_check(bad, sizeof(bad), &plen, why, sizeof(why)), -EBADMSG);
	assert_string_equal(why, "bad magic");
	memcpy(bad, img, sizeof(img));
	bad[12] = 4;                         /* length, without fixing the header CRC */
	assert_int_equal(st_check(bad, sizeof(bad), &plen, why, sizeof(why)), -EBADMSG);
	assert_string_equal(why, "header checksum mismatch");
	memcpy(bad, img, sizeof(img));
	bad[ST_HEADER_SIZE + 1] ^= 0x01;
	assert_int_equal(st_check(bad, sizeof(bad), &plen, why, sizeof(why)), -EBADMSG);
	assert_string_equal(why, "payload checksum mismatch");
	/* A whole header for 3 bytes but only 2 of them. */
	assert_int_equal(st_check(img, sizeof(img) - 1, &plen, why, sizeof(why)), -EBADMSG);
	assert_string_equal(why, "length 3 does not match the file (2 bytes of payload)");
}

static void test_round_trip_and_prev_keeps_the_one_before(void **state)
{
	char msg[256];
	void *buf;
	size_t len;

	(void)state;
	save_str("rt", "first");
	expect_load("rt", "first", ST_MAIN, msg, sizeof(msg));
	assert_string_equal(msg, "");
	assert_false(exists("rt.prev"));     /* nothing before the first save */
	save_str("rt", "second");
	save_str("rt", "third!");
	expect_load("rt", "third!", ST_MAIN, msg, sizeof(msg));
	/* .prev is a valid state file with the save before. */
	rm("rt");
	expect_load("rt", "second", ST_PREV, msg, sizeof(msg));
	assert_false(exists("rt.tmp"));
	assert_false(exists("rt.prev.tmp"));
	/* An empty payload is a payload; buf is never NULL. */
	assert_int_equal(st_save(dir, "empty", "", 0), 0);
	assert_int_equal(st_load(dir, "empty", &buf, &len, NULL, NULL, 0), 0);
	assert_non_null(buf);
	assert_int_equal(len, 0);
	free(buf);
}

static void test_corrupt_main_falls_back_to_prev_saying_why(void **state)
{
	char msg[256];

	(void)state;
	save_str("c", "old");
	save_str("c", "new");
	poke("c", ST_HEADER_SIZE + 1, 'X');
	expect_load("c", "old", ST_PREV, msg, sizeof(msg));
	assert_string_equal(msg, "c: payload checksum mismatch; loaded c.prev");

	save_str("h", "old");
	save_str("h", "new");
	poke("h", 3, 'X');                   /* the magic */
	expect_load("h", "old", ST_PREV, msg, sizeof(msg));
	assert_string_equal(msg, "h: bad magic; loaded h.prev");

	save_str("t", "old");
	save_str("t", "newer");
	cut("t", ST_HEADER_SIZE + 2);        /* a torn write */
	expect_load("t", "old", ST_PREV, msg, sizeof(msg));
	assert_string_equal(msg, "t: length 5 does not match the file (2 bytes of payload); "
				 "loaded t.prev");
	cut("t", 0);
	expect_load("t", "old", ST_PREV, msg, sizeof(msg));
	assert_string_equal(msg, "t: too short (0 bytes); loaded t.prev");

	save_str("m", "old");
	save_str("m", "new");
	rm("m");
	expect_load("m", "old", ST_PREV, msg, sizeof(msg));
	assert_string_equal(msg, "m: No such file or directory; loaded m.prev");
}

static void test_corrupt_prev_is_ignored_while_main_is_good(void **state)
{
	char msg[256];

	(void)state;
	save_str("p", "old");
	save_str("p", "new");
	poke("p.prev", ST_HEADER_SIZE, 'Z');
	expect_load("p", "new", ST_MAIN, msg, sizeof(msg));
	assert_string_equal(msg, "");
}

static void test_both_bad_or_missing_are_errors(void **state)
{
	char msg[256];
	void *buf = NULL;
	size_t len;

	(void)state;
	assert_int_equal(st_load(dir, "none", &buf, &len, NULL, msg, sizeof(msg)), -ENOENT);
	assert_string_equal(msg, "none: No such file or directory; none.prev: No such file or "
				 "directory");
	save_str("b", "old");
	save_str("b", "new");
	poke("b", ST_HEADER_SIZE, 'Z');
	poke("b.prev", ST_HEADER_SIZE, 'Z');
	assert_int_equal(st_load(dir, "b", &buf, &len, NULL, msg, sizeof(msg)), -EBADMSG);
	assert_string_equal(msg, "b: payload checksum mismatch; b.prev: payload checksum mismatch");
	/* Only a corrupt main: still corruption, not "missing". */
	rm("b.prev");
	assert_int_equal(st_load(dir, "b", &buf, &len, NULL, msg, sizeof(msg)), -EBADMSG);
	assert_null(buf);
}

static void test_saving_over_a_corrupt_main_keeps_the_good_prev(void **state)
{
	char msg[256];

	(void)state;
	save_str("k", "good-1");
	save_str("k", "good-2");
	poke("k", ST_HEADER_SIZE, 'Z');      /* main rots; .prev holds good-1 */
	save_str("k", "good-3");
	rm("k");
	/* good-1 survived: the rotten main did not replace it. */
	expect_load("k", "good-1", ST_PREV, msg, sizeof(msg));
}

/* The caller's payload check: payloads that start with "v9" are a format
 * this "build" cannot decode, although their checksums hold. */
static int usable_not_v9(const void *p, size_t len)
{
	return len >= 2 && memcmp(p, "v9", 2) == 0 ? -EINVAL : 0;
}

static void test_undecodable_main_is_a_bad_copy(void **state)
{
	char msg[256];
	enum st_which which = ST_MAIN;
	void *buf = NULL;
	size_t len = 0;

	(void)state;
	save_str("u", "v1-good");
	assert_int_equal(st_save_usable(dir, "u", usable_not_v9, "v9-newer", 8), 0);
	/* checksums hold: plain st_load takes it */
	expect_load("u", "v9-newer", ST_MAIN, msg, sizeof(msg));
	/* the payload check makes it a bad copy: .prev is loaded */
	assert_int_equal(st_load_usable(dir, "u", usable_not_v9, &buf, &len, &which, msg,
					sizeof(msg)), 0);
	assert_int_equal(which, ST_PREV);
	assert_int_equal(len, 7);
	assert_memory_equal(buf, "v1-good", 7);
	free(buf);
	assert_string_equal(msg, "u: payload not usable by this version; loaded u.prev");
	/* a save does not rotate the undecodable copy into .prev */
	assert_int_equal(st_save_usable(dir, "u", usable_not_v9, "v1-next", 7), 0);
	rm("u");
	expect_load("u", "v1-good", ST_PREV, msg, sizeof(msg));
	/* neither copy usable: -EBADMSG naming both */
	save_str("w", "v9-a");
	save_str("w", "v9-b");
	buf = NULL;
	assert_int_equal(st_load_usable(dir, "w", usable_not_v9, &buf, &len, NULL, msg,
					sizeof(msg)), -EBADMSG);
	assert_null(buf);
	assert_string_equal(msg, "w: payload not usable by this version; w.prev: payload not "
				 "usable by this version");
}

static void test_leftovers_of_a_killed_save_do_not_matter(void **state)
{
	char p[128], msg[256];
	FILE *f;

	(void)state;
	save_str("l", "old");
	path_of(p, sizeof(p), "l.tmp");
	f = fopen(p, "w");
	assert_non_null(f);
	fputs("half a wri", f);
	fclose(f);
	path_of(p, sizeof(p), "l.prev.tmp");
	f = fopen(p, "w");
	assert_non_null(f);
	fclose(f);
	expect_load("l", "old", ST_MAIN, msg, sizeof(msg));
	save_str("l", "new");
	expect_load("l", "new", ST_MAIN, msg, sizeof(msg));
	assert_false(exists("l.tmp"));
	assert_false(exists("l.prev.tmp"));
}

static void test_short_write_loses_nothing(void **state)
{
	static char big[64 * 1024];
	struct rlimit old, lim;
	char msg[256];
	int ret;

	(void)state;
	save_str("w", "one");
	save_str("w", "two");
	memset(big, 'q', sizeof(big));
	/* The kernel writes up to the limit, then fails the write with EFBIG:
	 * the same path as ENOSPC on a full disk. */
	assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
	signal(SIGXFSZ, SIG_IGN);
	lim = old;
	lim.rlim_cur = 4096;
	assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
	ret = st_save(dir, "w", big, sizeof(big));
	assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
	signal(SIGXFSZ, SIG_DFL);
	assert_int_equal(ret, -EFBIG);
	assert_false(exists("w.tmp"));
	expect_load("w", "two", ST_MAIN, msg, sizeof(msg));
	rm("w");
	expect_load("w", "one", ST_PREV, msg, sizeof(msg));
}

static void test_bad_arguments_are_refused(void **state)
{
	char big_name[ST_NAME_MAX + 2], msg[64];
	void *buf;
	size_t len;

	(void)state;
	memset(big_name, 'n', sizeof(big_name) - 1);
	big_name[sizeof(big_name) - 1] = '\0';
	assert_int_equal(st_save(dir, "a/b", "x", 1), -EINVAL);
	assert_int_equal(st_save(dir, "", "x", 1), -EINVAL);
	assert_int_equal(st_save(dir, "..", "x", 1), -EINVAL);
	assert_int_equal(st_save(dir, big_name, "x", 1), -EINVAL);
	assert_int_equal(st_save(dir, "x", "x", (size_t)ST_MAX_LEN + 1), -EINVAL);
	assert_int_equal(st_save("/nonexistent/dir", "x", "x", 1), -ENOENT);
	assert_int_equal(st_load(dir, "a/b", &buf, &len, NULL, msg, sizeof(msg)), -EINVAL);
	assert_int_equal(st_load("/nonexistent/dir", "x", &buf, &len, NULL, msg, sizeof(msg)),
			 -ENOENT);
	assert_string_equal(msg, "/nonexistent/dir: No such file or directory");
}

/* The whole content of file NAME in dir, NUL-terminated, into buf. */
static size_t read_plain(const char *name, char *buf, size_t len)
{
	char p[128];
	size_t n;
	FILE *f;

	path_of(p, sizeof(p), name);
	f = fopen(p, "rb");
	assert_non_null(f);
	n = fread(buf, 1, len - 1, f);
	fclose(f);
	buf[n] = '\0';
	return n;
}

/* Names in dir that start with prefix. */
static int count_entries(const char *prefix)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	int n = 0;

	assert_non_null(d);
	while ((e = readdir(d)))
		n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
	closedir(d);
	return n;
}

static void test_plain_write_replaces_the_whole_file_without_header(void **state)
{
	const char *one = "[keyboard]\nfire = KEY_SPACE\n", *two = "short\n";
	char buf[256];

	(void)state;
	assert_int_equal(st_write_plain(dir, "plain.ini", one, strlen(one)), 0);
	assert_int_equal(read_plain("plain.ini", buf, sizeof(buf)), strlen(one));
	assert_string_equal(buf, one);
	/* a shorter file replaces a longer one whole (no tail of the old) */
	assert_int_equal(st_write_plain(dir, "plain.ini", two, strlen(two)), 0);
	assert_int_equal(read_plain("plain.ini", buf, sizeof(buf)), strlen(two));
	assert_string_equal(buf, two);
	/* nothing else is left: no .tmp, no .prev */
	assert_int_equal(count_entries("plain.ini"), 1);
	assert_false(exists("plain.ini.tmp"));
	assert_false(exists("plain.ini.prev"));
	/* empty content (data may be NULL then) */
	assert_int_equal(st_write_plain(dir, "plain.ini", NULL, 0), 0);
	assert_int_equal(file_size("plain.ini"), 0);
}

static void test_plain_write_over_a_leftover_temp(void **state)
{
	char p[128], buf[64];
	FILE *f;

	(void)state;
	path_of(p, sizeof(p), "left.ini.tmp");
	f = fopen(p, "w");
	assert_non_null(f);
	fputs("half a write of something much longer", f);
	fclose(f);
	assert_int_equal(st_write_plain(dir, "left.ini", "new\n", 4), 0);
	read_plain("left.ini", buf, sizeof(buf));
	assert_string_equal(buf, "new\n");
	assert_int_equal(count_entries("left.ini"), 1);
}

static void test_plain_write_errors_keep_the_old_file(void **state)
{
	static char big[64 * 1024];
	struct rlimit old, lim;
	char notdir[128], buf[64];
	int ret;

	(void)state;
	assert_int_equal(st_write_plain("/nonexistent/dir", "b.ini", "x", 1), -ENOENT);
	assert_int_equal(st_write_plain(dir, "a/b", "x", 1), -EINVAL);
	assert_int_equal(st_write_plain(dir, "..", "x", 1), -EINVAL);
	assert_int_equal(st_write_plain(dir, "", "x", 1), -EINVAL);
	assert_int_equal(st_write_plain(dir, "x", NULL, 1), -EINVAL);
	assert_int_equal(st_write_plain(dir, "x", "x", (size_t)ST_MAX_LEN + 1), -EINVAL);
	/* a file where the directory should be */
	assert_int_equal(st_write_plain(dir, "file", "f", 1), 0);
	path_of(notdir, sizeof(notdir), "file");
	assert_int_equal(st_write_plain(notdir, "b.ini", "x", 1), -ENOTDIR);

	/* a write cut short (as by a full disk): the old file stays whole */
	assert_int_equal(st_write_plain(dir, "cut.ini", "old\n", 4), 0);
	memset(big, 'q', sizeof(big));
	assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
	signal(SIGXFSZ, SIG_IGN);
	lim = old;
	lim.rlim_cur = 4096;
	assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
	ret = st_write_plain(dir, "cut.ini", big, sizeof(big));
	assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
	signal(SIGXFSZ, SIG_DFL);
	assert_int_equal(ret, -EFBIG);
	assert_false(exists("cut.ini.tmp"));
	read_plain("cut.ini", buf, sizeof(buf));
	assert_string_equal(buf, "old\n");
}

static int count_fds(void)
{
	DIR *d = opendir("/proc/self/fd");
	int n = 0;

	assert_non_null(d);
	while (readdir(d))
		n++;
	closedir(d);
	return n;
}

static void test_no_descriptor_leaks(void **state)
{
	void *buf;
	size_t len;
	int before;

	(void)state;
	save_str("fd", "warm-up");
	before = count_fds();
	for (int i = 0; i < 20; i++) {
		save_str("fd", "again");
		assert_int_equal(st_load(dir, "fd", &buf, &len, NULL, NULL, 0), 0);
		free(buf);
		assert_int_equal(st_load(dir, "fd-none", &buf, &len, NULL, NULL, 0), -ENOENT);
	}
	for (int i = 0; i < 20; i++) {
		assert_int_equal(st_write_plain(dir, "fd.ini", "x\n", 2), 0);
		assert_int_equal(st_write_plain(dir, "a/b", "x", 1), -EINVAL);
		assert_int_equal(st_write_plain("/nonexistent/dir", "x", "x", 1), -ENOENT);
	}
	assert_int_equal(st_save(dir, "a/b", "x", 1), -EINVAL);
	assert_int_equal(count_fds(), before);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_crc32_standard_check_values),
		cmocka_unit_test(test_header_layout_by_hand),
		cmocka_unit_test(test_check_names_each_damage),
		cmocka_unit_test(test_round_trip_and_prev_keeps_the_one_before),
		cmocka_unit_test(test_corrupt_main_falls_back_to_prev_saying_why),
		cmocka_unit_test(test_corrupt_prev_is_ignored_while_main_is_good),
		cmocka_unit_test(test_both_bad_or_missing_are_errors),
		cmocka_unit_test(test_saving_over_a_corrupt_main_keeps_the_good_prev),
		cmocka_unit_test(test_undecodable_main_is_a_bad_copy),
		cmocka_unit_test(test_leftovers_of_a_killed_save_do_not_matter),
		cmocka_unit_test(test_short_write_loses_nothing),
		cmocka_unit_test(test_bad_arguments_are_refused),
		cmocka_unit_test(test_plain_write_replaces_the_whole_file_without_header),
		cmocka_unit_test(test_plain_write_over_a_leftover_temp),
		cmocka_unit_test(test_plain_write_errors_keep_the_old_file),
		cmocka_unit_test(test_no_descriptor_leaks),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
