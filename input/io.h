/*
 * io: reading a whole file into memory, and writing a whole buffer, the
 * one copy of each loop (reads: INI files, test scripts, state files, HID
 * report descriptors, WADs; writes: state files, recordings).
 *
 * Why in input/: the readers are in input/ (scripts, HID descriptors),
 * config/ (INI files, state files) and app/ (content); config is above
 * input and app above both, so input/ is the lowest folder every one of
 * them may call. The engine below may do no I/O at all.
 *
 * Both functions block until the end of the file (a pipe: until its
 * writer closes it, or max is passed). The buffer is malloc'd, the
 * caller frees it; one byte past the data is allocated and set to 0, so
 * text can be used as a string (len does not count it).
 */
#ifndef ARCADED_INPUT_IO_H
#define ARCADED_INPUT_IO_H

#include <stddef.h>
#include <stdint.h>

/* io_read_file flag: a directory is -EISDIR, anything else but a regular
 * file is -EINVAL (a FIFO or a
 * device would block or never end); the file is opened O_NONBLOCK, so not
 * even the open of a FIFO without a writer blocks. */
#define IO_REGULAR 0x1

/* Reads fd from its position to its end. At most max bytes (taken as at
 * most SIZE_MAX / 2): a longer file, or one that grows past max while it
 * is read, is -EFBIG. Returns 0 with *buf and *len, or -errno with *buf
 * NULL (-EISDIR for a directory). EINTR is retried. fd stays open. */
int io_read_fd(int fd, size_t max, uint8_t **buf, size_t *len);

/* io_read_fd on path, opened O_RDONLY | O_CLOEXEC and closed again; flags:
 * IO_REGULAR or 0. A missing file is -ENOENT. */
int io_read_file(const char *path, size_t max, int flags, uint8_t **buf, size_t *len);

/* Maps the regular file at path read-only (PROT_READ, MAP_PRIVATE) for
 * the big files the loaders only read (WADs): its pages are the page
 * cache's, shared and clean, so they are never the process's private
 * memory, and only the lumps read are brought in. At most max bytes
 * (-EFBIG past it); a directory is -EISDIR, anything else but a regular
 * file -EINVAL, a missing file -ENOENT; an empty file maps to a
 * one-byte private zero page with *len 0 (mmap refuses length 0).
 * Returns 0 with *buf and *len, or -errno with *buf NULL. Release with
 * io_unmap_file(*buf, *len). A file truncated by another process while
 * mapped raises SIGBUS on the lost pages: map only for as long as the
 * load takes. */
int io_map_file(const char *path, size_t max, const uint8_t **buf, size_t *len);

/* Unmaps what io_map_file mapped (buf NULL: nothing). */
void io_unmap_file(const uint8_t *buf, size_t len);

/* Writes the n bytes at p to fd, however many write() calls it takes
 * (EINTR retried). 0, or -errno (-EIO when write makes no progress). */
int io_write_all(int fd, const void *p, size_t n);

#endif
