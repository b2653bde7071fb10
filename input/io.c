/*
 * io: whole-file reads (io.h).
 */
#include "input/io.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

/* Room to start with when the size is not known (a pipe, /proc). */
#define IO_FIRST 4096

int io_read_fd(int fd, size_t max, uint8_t **buf, size_t *len)
{
	struct stat sb;
	uint8_t *b, *nb;
	size_t cap, n = 0;
	int ret;

	*buf = NULL;
	*len = 0;
	if (max > SIZE_MAX / 2)
		max = SIZE_MAX / 2;
	if (fstat(fd, &sb) < 0)
		return -errno;
	if (S_ISDIR(sb.st_mode))
		return -EISDIR;
	if (S_ISREG(sb.st_mode) && (uint64_t)sb.st_size > max)
		return -EFBIG;
	/* The size is a hint (0 for a pipe, 4096 for a sysfs file): read to
	 * the end, one byte past max at most, so a file that grows or a pipe
	 * is still bounded. */
	cap = S_ISREG(sb.st_mode) && sb.st_size > 0 ? (size_t)sb.st_size + 1 : IO_FIRST;
	if (cap > max + 1)
		cap = max + 1;
	b = malloc(cap);
	if (!b)
		return -ENOMEM;
	for (;;) {
		ssize_t r;

		/* Full: grow, unless max + 1 bytes are in (too large). So the
		 * loop ends with n < cap, room for the terminating 0. */
		if (n == cap) {
			size_t ncap = cap > (max + 1) / 2 ? max + 1 : cap * 2;

			if (ncap <= cap) {
				ret = -EFBIG;
				goto fail;
			}
			nb = realloc(b, ncap);
			if (!nb) {
				ret = -ENOMEM;
				goto fail;
			}
			b = nb;
			cap = ncap;
		}
		r = read(fd, b + n, cap - n);
		if (r < 0) {
			if (errno == EINTR)
				continue;
			ret = -errno;
			goto fail;
		}
		if (r == 0)
			break;
		n += (size_t)r;
	}
	b[n] = 0;
	*buf = b;
	*len = n;
	return 0;
fail:
	free(b);
	return ret;
}

int io_write_all(int fd, const void *p, size_t n)
{
	const uint8_t *b = p;

	while (n) {
		ssize_t w = write(fd, b, n);

		if (w < 0) {
			if (errno == EINTR)
				continue;
			return -errno;
		}
		if (w == 0)
			return -EIO;
		b += w;
		n -= (size_t)w;
	}
	return 0;
}

int io_read_file(const char *path, size_t max, int flags, uint8_t **buf, size_t *len)
{
	struct stat sb;
	int fd, ret;

	*buf = NULL;
	*len = 0;
	/* O_NONBLOCK with IO_REGULAR: opening a FIFO for reading blocks until
	 * a writer comes, before fstat could refuse it; for a regular file the
	 * flag changes nothing. */
	fd = open(path, O_RDONLY | O_CLOEXEC | ((flags & IO_REGULAR) ? O_NONBLOCK : 0));
	if (fd < 0)
		return -errno;
	if (!(flags & IO_REGULAR))
		ret = io_read_fd(fd, max, buf, len);
	else if (fstat(fd, &sb) < 0)
		ret = -errno;
	else if (S_ISDIR(sb.st_mode))
		ret = -EISDIR;
	else if (!S_ISREG(sb.st_mode))
		ret = -EINVAL;
	else
		ret = io_read_fd(fd, max, buf, len);
	close(fd);
	return ret;
}

int io_map_file(const char *path, size_t max, const uint8_t **buf, size_t *len)
{
	struct stat sb;
	void *p;
	int fd, ret = 0;

	*buf = NULL;
	*len = 0;
	fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
	if (fd < 0)
		return -errno;
	if (fstat(fd, &sb) < 0)
		ret = -errno;
	else if (S_ISDIR(sb.st_mode))
		ret = -EISDIR;
	else if (!S_ISREG(sb.st_mode))
		ret = -EINVAL;
	else if ((uint64_t)sb.st_size > (uint64_t)max || (uint64_t)sb.st_size > SIZE_MAX / 2)
		ret = -EFBIG;
	if (ret == 0) {
		size_t n = (size_t)sb.st_size;

		/* an empty file: a zero page stands in, so callers see a buffer */
		p = n ? mmap(NULL, n, PROT_READ, MAP_PRIVATE, fd, 0)
		      : mmap(NULL, 1, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
		if (p == MAP_FAILED) {
			ret = -errno;
		} else {
			*buf = p;
			*len = n;
		}
	}
	close(fd);
	return ret;
}

void io_unmap_file(const uint8_t *buf, size_t len)
{
	if (buf)
		munmap((void *)(uintptr_t)buf, len ? len : 1);
}
