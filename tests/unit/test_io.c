/* Tests for input/io.c: whole-file reads. Files are made in a fresh
 * temporary directory; pipes carry data written before the read. */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

#include "input/io.h"

struct dir {
	char path[64];
};

static void dir_make(struct dir *d)
{
	snprintf(d->path, sizeof(d->path), "/tmp/test_io.XXXXXX");
	assert_non_null(mkdtemp(d->path));
}

/* A file of n bytes, byte i being (i * 7) & 255; its path in out. */
static void file_make(const struct dir *d, const char *name, size_t n, char *out, size_t len)
{
	FILE *f;

	snprintf(out, len, "%s/%s", d->path, name);
	f = fopen(out, "wb");
	assert_non_null(f);
	for (size_t i = 0; i < n; i++)
		fputc((int)((i * 7) & 255), f);
	assert_int_equal(fclose(f), 0);
}

static void expect_content(const uint8_t *b, size_t len, size_t n)
{
	assert_int_equal(len, n);
	for (size_t i = 0; i < n; i++)
		if (b[i] != ((i * 7) & 255))
			fail_msg("byte %zu is %u", i, b[i]);
	assert_int_equal(b[n], 0);                      /* the terminating 0 */
}

static void a_file_is_read_whole_with_a_zero_after(void **state)
{
	struct dir d;
	char p[128], q[128];
	uint8_t *b;
	size_t len;
	(void)state;
	dir_make(&d);
	file_make(&d, "a", 100000, p, sizeof(p));
	assert_int_equal(io_read_file(p, 1 << 20, 0, &b, &len), 0);
	expect_content(b, len, 100000);
	free(b);
	assert_int_equal(io_read_file(p, 1 << 20, IO_REGULAR, &b, &len), 0);
	expect_content(b, len, 100000);
	free(b);
	file_make(&d, "empty", 0, q, sizeof(q));
	assert_int_equal(io_read_file(q, 10, 0, &b, &len), 0);
	assert_non_null(b);
	expect_content(b, len, 0);
	free(b);
	unlink(p);
	unlink(q);
	rmdir(d.path);
}

/* max bytes are fine; one more is -EFBIG, with no buffer. */
static void the_limit_is_max_bytes(void **state)
{
	struct dir d;
	char p[128];
	uint8_t *b = (uint8_t *)"x";
	size_t len = 5;
	(void)state;
	dir_make(&d);
	file_make(&d, "a", 5000, p, sizeof(p));
	assert_int_equal(io_read_file(p, 5000, 0, &b, &len), 0);
	expect_content(b, len, 5000);
	free(b);
	assert_int_equal(io_read_file(p, 4999, 0, &b, &len), -EFBIG);
	assert_null(b);
	assert_int_equal(len, 0);
	unlink(p);
	rmdir(d.path);
}

static void missing_files_directories_and_devices(void **state)
{
	struct dir d;
	char p[128];
	uint8_t *b;
	size_t len;
	(void)state;
	dir_make(&d);
	snprintf(p, sizeof(p), "%s/none", d.path);
	assert_int_equal(io_read_file(p, 100, 0, &b, &len), -ENOENT);
	assert_null(b);
	assert_int_equal(io_read_file(d.path, 100, 0, &b, &len), -EISDIR);
	assert_null(b);
	/* a device: read to its end without the flag, refused with it */
	assert_int_equal(io_read_file("/dev/null", 100, 0, &b, &len), 0);
	assert_int_equal(len, 0);
	free(b);
	assert_int_equal(io_read_file("/dev/null", 100, IO_REGULAR, &b, &len), -EINVAL);
	assert_null(b);
	rmdir(d.path);
}

/* A FIFO without a writer: with IO_REGULAR it is refused at once, not
 * waited on in open() (alarm: a blocked open ends the test, as a failure). */
static void a_fifo_is_refused_without_blocking(void **state)
{
	struct dir d;
	char p[128];
	uint8_t *b;
	size_t len;
	(void)state;
	dir_make(&d);
	snprintf(p, sizeof(p), "%s/fifo.ini", d.path);
	assert_int_equal(mkfifo(p, 0600), 0);
	alarm(5);
	assert_int_equal(io_read_file(p, 100, IO_REGULAR, &b, &len), -EINVAL);
	alarm(0);
	assert_null(b);
	/* a directory stays -EISDIR with the flag */
	assert_int_equal(io_read_file(d.path, 100, IO_REGULAR, &b, &len), -EISDIR);
	unlink(p);
	rmdir(d.path);
}

/* A pipe has no size: the reader grows its buffer to the end, bounded by
 * max; more than max is -EFBIG. */
static void a_pipe_is_read_to_its_end_within_max(void **state)
{
	static uint8_t data[20000];
	int fds[2];
	uint8_t *b;
	size_t len;
	(void)state;
	for (size_t i = 0; i < sizeof(data); i++)
		data[i] = (uint8_t)((i * 7) & 255);
	assert_int_equal(pipe(fds), 0);
	assert_int_equal(write(fds[1], data, sizeof(data)), (ssize_t)sizeof(data));
	close(fds[1]);
	assert_int_equal(io_read_fd(fds[0], sizeof(data), &b, &len), 0);
	expect_content(b, len, sizeof(data));
	free(b);
	close(fds[0]);
	assert_int_equal(pipe(fds), 0);
	assert_int_equal(write(fds[1], data, sizeof(data)), (ssize_t)sizeof(data));
	close(fds[1]);
	assert_int_equal(io_read_fd(fds[0], sizeof(data) - 1, &b, &len), -EFBIG);
	assert_null(b);
	close(fds[0]);
}

/* A file whose size says 0 (/proc) is read all the same; an fd is read
 * from where it stands. */
static void sizeless_files_and_the_fd_position(void **state)
{
	struct dir d;
	char p[128];
	uint8_t *b;
	size_t len;
	int fd;
	(void)state;
	assert_int_equal(io_read_file("/proc/self/status", 1 << 20, 0, &b, &len), 0);
	assert_true(len > 5);
	assert_memory_equal(b, "Name:", 5);
	assert_int_equal(strlen((const char *)b), len);
	free(b);
	dir_make(&d);
	file_make(&d, "a", 300, p, sizeof(p));
	fd = open(p, O_RDONLY | O_CLOEXEC);
	assert_true(fd >= 0);
	assert_int_equal(lseek(fd, 100, SEEK_SET), 100);
	assert_int_equal(io_read_fd(fd, 1000, &b, &len), 0);
	assert_int_equal(len, 200);
	assert_int_equal(b[0], (100 * 7) & 255);
	free(b);
	close(fd);
	unlink(p);
	rmdir(d.path);
}

/* Every byte is written (read back whole); the device's or the fd's
 * error comes back as -errno. */
/* io_map_file: the file's bytes, read-only; an empty file is a buffer of
 * length 0; max bytes are fine and one more is -EFBIG; a directory, a
 * FIFO (without blocking) and a missing file are refused with no buffer. */
static void a_file_is_mapped_whole_or_refused(void **state)
{
	struct dir d;
	char p[128], q[128], fifo[160];
	const uint8_t *b;
	size_t len;

	(void)state;
	dir_make(&d);
	file_make(&d, "a", 100000, p, sizeof(p));
	assert_int_equal(io_map_file(p, 100000, &b, &len), 0);
	assert_int_equal(len, 100000);
	for (size_t i = 0; i < len; i++)
		if (b[i] != ((i * 7) & 255))
			fail_msg("byte %zu is %u", i, b[i]);
	io_unmap_file(b, len);
	b = (const uint8_t *)"x";
	assert_int_equal(io_map_file(p, 99999, &b, &len), -EFBIG);
	assert_null(b);
	file_make(&d, "empty", 0, q, sizeof(q));
	assert_int_equal(io_map_file(q, 10, &b, &len), 0);
	assert_non_null(b);
	assert_int_equal(len, 0);
	io_unmap_file(b, len);
	assert_int_equal(io_map_file(d.path, 10, &b, &len), -EISDIR);
	assert_null(b);
	snprintf(fifo, sizeof(fifo), "%s/fifo", d.path);
	assert_int_equal(mkfifo(fifo, 0600), 0);
	assert_int_equal(io_map_file(fifo, 10, &b, &len), -EINVAL);
	assert_null(b);
	snprintf(fifo, sizeof(fifo), "%s/none", d.path);
	assert_int_equal(io_map_file(fifo, 10, &b, &len), -ENOENT);
	assert_null(b);
	/* sysfs cannot map its files: the loader's cue to read them */
	if (access("/sys/kernel/profiling", R_OK) == 0) {
		assert_int_equal(io_map_file("/sys/kernel/profiling", 1 << 20, &b, &len), -ENODEV);
		assert_null(b);
	}
	io_unmap_file(NULL, 0);
	unlink(p);
	unlink(q);
	snprintf(fifo, sizeof(fifo), "%s/fifo", d.path);
	unlink(fifo);
	rmdir(d.path);
}

static void write_all_writes_everything_or_says_why(void **state)
{
	static uint8_t data[300000];
	struct dir d;
	char p[128];
	uint8_t *b;
	size_t len;
	int fd;
	(void)state;
	for (size_t i = 0; i < sizeof(data); i++)
		data[i] = (uint8_t)((i * 7) & 255);
	dir_make(&d);
	snprintf(p, sizeof(p), "%s/w", d.path);
	fd = open(p, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
	assert_true(fd >= 0);
	assert_int_equal(io_write_all(fd, data, sizeof(data)), 0);
	assert_int_equal(io_write_all(fd, data, 0), 0);
	close(fd);
	assert_int_equal(io_read_file(p, sizeof(data), 0, &b, &len), 0);
	expect_content(b, len, sizeof(data));
	free(b);
	fd = open("/dev/full", O_WRONLY | O_CLOEXEC);
	assert_true(fd >= 0);
	assert_int_equal(io_write_all(fd, data, 10), -ENOSPC);
	close(fd);
	assert_int_equal(io_write_all(-1, data, 10), -EBADF);
	unlink(p);
	rmdir(d.path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_file_is_read_whole_with_a_zero_after),
		cmocka_unit_test(the_limit_is_max_bytes),
		cmocka_unit_test(missing_files_directories_and_devices),
		cmocka_unit_test(a_fifo_is_refused_without_blocking),
		cmocka_unit_test(a_pipe_is_read_to_its_end_within_max),
		cmocka_unit_test(sizeless_files_and_the_fd_position),
		cmocka_unit_test(a_file_is_mapped_whole_or_refused),
		cmocka_unit_test(write_all_writes_everything_or_says_why),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
