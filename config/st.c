/*
 * st: power-cut-safe state files. Why each step of st_save is there:
 *  - the new bytes go to NAME.tmp and are fsynced before any name changes,
 *    so a rename never publishes data that is not on disk;
 *  - the current NAME is kept as NAME.prev only if it checks out (and its
 *    payload passes the caller's usable check): rotating a corrupt or
 *    undecodable NAME would push the last good copy out of .prev;
 *  - .prev is made by a hard link and a rename, so NAME itself never
 *    disappears (file systems without hard links fall back to renaming
 *    NAME to NAME.prev: for that instant only .prev exists, and st_load
 *    finds it);
 *  - renaming NAME.tmp over NAME is atomic; the directory fsync then makes
 *    the renames durable before st_save reports success.
 */
#include "config/st.h"

#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "engine/core/le.h"
#include "input/io.h"
#include "input/txt.h"

static const uint8_t st_magic[8] = { 'A', 'R', 'C', 'D', 'S', 'T', 'A', '\0' };

/* CRC-32 a nibble at a time: a 16-entry constant table, no set-up. */
static const uint32_t st_crc_nibble[16] = {
	0x00000000u, 0x1db71064u, 0x3b6e20c8u, 0x26d930acu, 0x76dc4190u, 0x6b6b51f4u,
	0x4db26158u, 0x5005713cu, 0xedb88320u, 0xf00f9344u, 0xd6d6a3e8u, 0xcb61b38cu,
	0x9b64c2b0u, 0x86d3d2d4u, 0xa00ae278u, 0xbdbdf21cu,
};

uint32_t st_crc32(uint32_t crc, const void *p, size_t n)
{
	const uint8_t *b = p;

	crc = ~crc;
	for (size_t i = 0; i < n; i++) {
		crc ^= b[i];
		crc = (crc >> 4) ^ st_crc_nibble[crc & 15];
		crc = (crc >> 4) ^ st_crc_nibble[crc & 15];
	}
	return ~crc;
}

void st_header(uint8_t out[ST_HEADER_SIZE], const void *payload, size_t len)
{
	memcpy(out, st_magic, sizeof(st_magic));
	le_put16(out + 8, ST_VERSION);
	le_put16(out + 10, ST_HEADER_SIZE);
	le_put32(out + 12, (uint32_t)len);
	le_put32(out + 16, st_crc32(0, payload, len));
	le_put32(out + 20, st_crc32(0, out, 20));
}

int st_check(const uint8_t *img, size_t n, size_t *payload_len, char *why, size_t whylen)
{
	uint32_t len;

	if (n < ST_HEADER_SIZE) {
		txt_set(why, whylen, "too short (%zu bytes)", n);
		return -EBADMSG;
	}
	if (memcmp(img, st_magic, sizeof(st_magic)) != 0) {
		txt_set(why, whylen, "bad magic");
		return -EBADMSG;
	}
	if (le_get32(img + 20) != st_crc32(0, img, 20)) {
		txt_set(why, whylen, "header checksum mismatch");
		return -EBADMSG;
	}
	if (le_get16(img + 8) != ST_VERSION || le_get16(img + 10) != ST_HEADER_SIZE) {
		txt_set(why, whylen, "version %u (header size %u) not supported", le_get16(img + 8),
			le_get16(img + 10));
		return -EBADMSG;
	}
	len = le_get32(img + 12);
	if (len > ST_MAX_LEN || len != n - ST_HEADER_SIZE) {
		txt_set(why, whylen,
			"length %" PRIu32 " does not match the file (%zu bytes of payload)", len,
			n - ST_HEADER_SIZE);
		return -EBADMSG;
	}
	if (le_get32(img + 16) != st_crc32(0, img + ST_HEADER_SIZE, len)) {
		txt_set(why, whylen, "payload checksum mismatch");
		return -EBADMSG;
	}
	*payload_len = len;
	return 0;
}

static int st_name_ok(const char *name)
{
	size_t n = strlen(name);

	return n > 0 && n <= ST_NAME_MAX && !strchr(name, '/') && strcmp(name, ".") != 0 &&
	       strcmp(name, "..") != 0;
}

/* Reads the whole file NAME in dfd (a regular file, not a link): 0 with
 * *img (malloc'd) and *n, or -errno (-EFBIG when it is larger than any
 * valid state file). */
static int st_read_file(int dfd, const char *name, uint8_t **img, size_t *n)
{
	struct stat sb;
	int fd, ret;

	/* O_NONBLOCK: the open of a FIFO would block until a writer comes;
	 * fstat then refuses it. No effect on a regular file. */
	fd = openat(dfd, name, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
	if (fd < 0)
		return -errno;
	if (fstat(fd, &sb) < 0)
		ret = -errno;
	else if (!S_ISREG(sb.st_mode))
		ret = -EINVAL;
	else
		ret = io_read_fd(fd, (size_t)ST_HEADER_SIZE + ST_MAX_LEN, img, n);
	close(fd);
	return ret;
}

/* 1 if NAME in dfd is a valid state file whose payload passes usable (when
 * not NULL), 0 if missing or invalid, -errno on a read error other than a
 * missing file. */
static int st_valid(int dfd, const char *name, st_usable_fn usable)
{
	uint8_t *img;
	size_t n, plen;
	int ret;

	ret = st_read_file(dfd, name, &img, &n);
	if (ret == -ENOENT || ret == -EFBIG || ret == -EINVAL)
		return 0;
	if (ret < 0)
		return ret;
	ret = st_check(img, n, &plen, NULL, 0) == 0 &&
	      (!usable || usable(img + ST_HEADER_SIZE, plen) == 0);
	free(img);
	return ret;
}

/* Makes prev a copy of the (valid) current file: hard link then rename, or
 * a plain rename where hard links are not supported. */
static int st_keep_prev(int dfd, const char *name, const char *prev, const char *prevtmp)
{
	if (unlinkat(dfd, prevtmp, 0) < 0 && errno != ENOENT)
		return -errno;
	if (linkat(dfd, name, dfd, prevtmp, 0) == 0) {
		if (renameat(dfd, prevtmp, dfd, prev) < 0)
			return -errno;
		return 0;
	}
	if (errno != EPERM && errno != ENOTSUP && errno != EOPNOTSUPP && errno != EMLINK &&
	    errno != ENOSYS)
		return -errno;
	if (renameat(dfd, name, dfd, prev) < 0)
		return -errno;
	return 0;
}

/* Writes the parts (pieces of one file, in order) to TMP in dfd and
 * fsyncs it: 0, or -errno with TMP removed. */
static int st_write_tmp(int dfd, const char *tmp, const void *const *part, const size_t *plen,
			int nparts)
{
	int fd, ret = 0;

	fd = openat(dfd, tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
	if (fd < 0)
		return -errno;
	for (int i = 0; i < nparts && ret == 0; i++)
		ret = io_write_all(fd, part[i], plen[i]);
	if (ret == 0 && fsync(fd) < 0)
		ret = -errno;
	if (close(fd) < 0 && ret == 0 && errno != EINTR)
		ret = -errno;
	if (ret < 0)
		unlinkat(dfd, tmp, 0);
	return ret;
}

/* Publishes TMP as NAME in dfd and makes it durable: the rename, then the
 * directory's fsync. On a failed rename TMP is removed. */
static int st_publish(int dfd, const char *tmp, const char *name)
{
	if (renameat(dfd, tmp, dfd, name) < 0) {
		int ret = -errno;

		unlinkat(dfd, tmp, 0);
		return ret;
	}
	return fsync(dfd) < 0 ? -errno : 0;
}

int st_save(const char *dir, const char *name, const void *data, size_t len)
{
	return st_save_usable(dir, name, NULL, data, len);
}

int st_save_usable(const char *dir, const char *name, st_usable_fn usable, const void *data,
		   size_t len)
{
	char tmp[ST_NAME_MAX + 16], prev[ST_NAME_MAX + 16], prevtmp[ST_NAME_MAX + 16];
	uint8_t hdr[ST_HEADER_SIZE];
	const void *part[2] = { hdr, data };
	size_t plen[2] = { sizeof(hdr), len };
	int dfd, ret;

	if (!st_name_ok(name) || len > ST_MAX_LEN || (!data && len))
		return -EINVAL;
	snprintf(tmp, sizeof(tmp), "%s.tmp", name);
	snprintf(prev, sizeof(prev), "%s.prev", name);
	snprintf(prevtmp, sizeof(prevtmp), "%s.prev.tmp", name);
	dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (dfd < 0)
		return -errno;

	st_header(hdr, data, len);
	ret = st_write_tmp(dfd, tmp, part, plen, len ? 2 : 1);
	if (ret < 0)
		goto out;
	ret = st_valid(dfd, name, usable);
	if (ret == 1)
		ret = st_keep_prev(dfd, name, prev, prevtmp);
	if (ret < 0) {
		unlinkat(dfd, tmp, 0);
		goto out;
	}
	ret = st_publish(dfd, tmp, name);
out:
	close(dfd);
	return ret;
}

int st_write_plain(const char *dir, const char *name, const void *data, size_t len)
{
	char tmp[ST_NAME_MAX + 16];
	int dfd, ret;

	if (!st_name_ok(name) || len > ST_MAX_LEN || (!data && len))
		return -EINVAL;
	snprintf(tmp, sizeof(tmp), "%s.tmp", name);
	dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (dfd < 0)
		return -errno;
	ret = st_write_tmp(dfd, tmp, &data, &len, len ? 1 : 0);
	if (ret == 0)
		ret = st_publish(dfd, tmp, name);
	close(dfd);
	return ret;
}

/* Loads and checks one copy: 0 with the payload moved to the front of a
 * malloc'd buffer, or -errno with the reason in why. */
static int st_load_one(int dfd, const char *name, st_usable_fn usable, void **buf, size_t *len,
		       char *why, size_t whylen)
{
	uint8_t *img;
	size_t n, plen;
	int ret;

	ret = st_read_file(dfd, name, &img, &n);
	if (ret == -EFBIG || ret == -EINVAL) {
		txt_set(why, whylen, "%s", ret == -EFBIG ? "larger than any state file"
							: "not a regular file");
		return -EBADMSG;
	}
	if (ret < 0) {
		txt_set(why, whylen, "%s", strerror(-ret));
		return ret;
	}
	ret = st_check(img, n, &plen, why, whylen);
	if (ret < 0) {
		free(img);
		return ret;
	}
	if (usable && usable(img + ST_HEADER_SIZE, plen) < 0) {
		txt_set(why, whylen, "payload not usable by this version");
		free(img);
		return -EBADMSG;
	}
	memmove(img, img + ST_HEADER_SIZE, plen);
	*buf = img;
	*len = plen;
	return 0;
}

int st_load(const char *dir, const char *name, void **buf, size_t *len, enum st_which *which,
	    char *msg, size_t msglen)
{
	return st_load_usable(dir, name, NULL, buf, len, which, msg, msglen);
}

int st_load_usable(const char *dir, const char *name, st_usable_fn usable, void **buf,
		   size_t *len, enum st_which *which, char *msg, size_t msglen)
{
	char prev[ST_NAME_MAX + 16], why1[128], why2[128];
	int dfd, r1, r2;

	txt_set(msg, msglen, "%s", "");
	if (!st_name_ok(name)) {
		txt_set(msg, msglen, "bad state file name");
		return -EINVAL;
	}
	snprintf(prev, sizeof(prev), "%s.prev", name);
	dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (dfd < 0) {
		r1 = -errno;
		txt_set(msg, msglen, "%s: %s", dir, strerror(-r1));
		return r1;
	}
	r1 = st_load_one(dfd, name, usable, buf, len, why1, sizeof(why1));
	if (r1 == 0) {
		if (which)
			*which = ST_MAIN;
		close(dfd);
		return 0;
	}
	r2 = st_load_one(dfd, prev, usable, buf, len, why2, sizeof(why2));
	close(dfd);
	if (r2 == 0) {
		if (which)
			*which = ST_PREV;
		txt_set(msg, msglen, "%s: %s; loaded %s", name, why1, prev);
		return 0;
	}
	txt_set(msg, msglen, "%s: %s; %s: %s", name, why1, prev, why2);
	if (r1 == -ENOENT && r2 == -ENOENT)
		return -ENOENT;
	/* Corruption outranks a missing copy; a read error outranks both. */
	if (r1 != -ENOENT && r1 != -EBADMSG)
		return r1;
	if (r2 != -ENOENT && r2 != -EBADMSG)
		return r2;
	return -EBADMSG;
}
