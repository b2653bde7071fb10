/*
 * wads: finding and checking the content directories' WADs (contract in
 * wads.h).
 */
#include "app/wads.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "engine/core/le.h"

const char *wads_name(const struct wads_pack *p)
{
	const char *s = strrchr(p->path, '/');

	return s ? s + 1 : p->path;
}

/* Reads exactly n bytes at off; 0, -EBADMSG when the file is shorter, or
 * -errno. */
static int wads_pread(int fd, void *buf, size_t n, off_t off)
{
	size_t got = 0;

	while (got < n) {
		ssize_t r = pread(fd, (uint8_t *)buf + got, n - got, off + (off_t)got);
		if (r < 0 && errno == EINTR)
			continue;
		if (r < 0)
			return -errno;
		if (r == 0)
			return -EBADMSG;
		got += (size_t)r;
	}
	return 0;
}

/* A map marker the maps list takes: ExMy or MAPxx (upper case in the
 * directory, as Doom's own lookup assumes). */
static int wads_map_name(const char name[8], char out[9])
{
	char n[9];

	memcpy(n, name, 8);
	n[8] = '\0';
	if (!((n[0] == 'E' && n[1] >= '1' && n[1] <= '9' && n[2] == 'M' && n[3] >= '1' &&
	       n[3] <= '9' && n[4] == '\0') ||
	      (strncmp(n, "MAP", 3) == 0 && n[3] >= '0' && n[3] <= '9' && n[4] >= '0' &&
	       n[4] <= '9' && n[5] == '\0')))
		return 0;
	memcpy(out, n, 9);
	return 1;
}

/* The header and directory of the open regular file fd of size size. */
static int wads_read(int fd, off_t size, struct wads_pack *p, char *why, size_t len)
{
	uint8_t h[12], *dir;
	uint32_t nl, at;
	int rc;

	if (size < 12) {
		snprintf(why, len, "not a WAD: %lld bytes, shorter than a header", (long long)size);
		return -EBADMSG;
	}
	rc = wads_pread(fd, h, sizeof(h), 0);
	if (rc < 0) {
		snprintf(why, len, "%s", strerror(-rc));
		return rc;
	}
	if (memcmp(h, "IWAD", 4) != 0 && memcmp(h, "PWAD", 4) != 0) {
		snprintf(why, len, "not a WAD (no IWAD or PWAD magic)");
		return -EBADMSG;
	}
	p->iwad = h[0] == 'I';
	nl = le_get32(h + 4);
	at = le_get32(h + 8);
	if (nl > WADS_LUMPS_MAX) {
		snprintf(why, len, "not a WAD: %u lumps (at most %u)", nl, WADS_LUMPS_MAX);
		return -EBADMSG;
	}
	if ((uint64_t)at + (uint64_t)nl * 16 > (uint64_t)size) {
		snprintf(why, len, "truncated: directory at %u + 16 x %u bytes, file %lld bytes",
			 at, nl, (long long)size);
		return -EBADMSG;
	}
	dir = malloc((size_t)nl * 16 + 1);
	if (!dir) {
		snprintf(why, len, "out of memory");
		return -ENOMEM;
	}
	rc = wads_pread(fd, dir, (size_t)nl * 16, (off_t)at);
	p->nmaps = 0;
	for (uint32_t i = 0; rc == 0 && i < nl && p->nmaps < WADS_MAPS; i++)
		p->nmaps += wads_map_name((const char *)dir + i * 16 + 8, p->maps[p->nmaps]);
	free(dir);
	if (rc < 0) {
		snprintf(why, len, "%s", rc == -EBADMSG ? "truncated directory" : strerror(-rc));
		return rc;
	}
	if (p->nmaps == 0) {
		snprintf(why, len, "no maps (no ExMy or MAPxx marker in its %u lumps)", nl);
		return -EBADMSG;
	}
	return 0;
}

int wads_check(const char *path, struct wads_pack *p, char *why, size_t len)
{
	struct stat st;
	int fd, rc;

	memset(p, 0, sizeof(*p));
	if (strlen(path) >= sizeof(p->path)) {
		snprintf(why, len, "path too long");
		return -ENAMETOOLONG;
	}
	/* O_NONBLOCK: a FIFO named .wad must not block the cabinet */
	fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
	if (fd < 0) {
		rc = -errno;
		snprintf(why, len, "%s", strerror(-rc));
		return rc;
	}
	if (fstat(fd, &st) < 0) {
		rc = -errno;
		snprintf(why, len, "%s", strerror(-rc));
	} else if (!S_ISREG(st.st_mode)) {
		rc = -EINVAL;
		snprintf(why, len, "not a regular file");
	} else {
		rc = wads_read(fd, st.st_size, p, why, len);
	}
	close(fd);
	if (rc == 0)
		snprintf(p->path, sizeof(p->path), "%s", path);
	return rc;
}

static int wads_is_wad_name(const char *n)
{
	size_t k = strlen(n);

	return n[0] != '.' && k > 4 && strcasecmp(n + k - 4, ".wad") == 0;
}

static int wads_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* A refused file: reported, and kept for the screen. */
static void wads_bad(struct wads *w, wads_err_fn fn, void *user, const char *path,
		     const char *why)
{
	const char *name = strrchr(path, '/');

	if (w->nbad < WADS_BAD)
		snprintf(w->bad[w->nbad], sizeof(w->bad[0]), "%s: %s", name ? name + 1 : path, why);
	w->nbad++;
	if (fn)
		fn(user, path, why);
}

/* One directory's WADs, in name order. */
static void wads_dir(struct wads *w, const char *dir, wads_err_fn fn, void *user)
{
	char *names[256], path[CFG_PATH_MAX + 256], why[160];
	int n = 0, over = 0;
	struct dirent *e;
	DIR *d = opendir(dir);

	if (!d) {
		if (errno != ENOENT)
			wads_bad(w, fn, user, dir, strerror(errno));
		return;
	}
	while ((e = readdir(d))) {
		if (!wads_is_wad_name(e->d_name))
			continue;
		if (n == (int)(sizeof(names) / sizeof(names[0]))) {
			over++;
			continue;
		}
		names[n] = strdup(e->d_name);
		if (names[n])
			n++;
	}
	closedir(d);
	if (over)
		wads_bad(w, fn, user, dir, "more than 256 .wad files: the rest are not listed");
	qsort(names, (size_t)n, sizeof(names[0]), wads_cmp);
	for (int i = 0; i < n; i++) {
		int m = snprintf(path, sizeof(path), "%s/%s", dir, names[i]);

		if (w->n == WADS_MAX)
			wads_bad(w, fn, user, path, "more than 32 WADs found");
		else if (m >= CFG_PATH_MAX)
			wads_bad(w, fn, user, path, "path too long");
		else if (wads_check(path, &w->pack[w->n], why, sizeof(why)) == 0)
			w->n++;
		else
			wads_bad(w, fn, user, path, why);
		free(names[i]);
	}
}

int wads_scan(struct wads *w, const char *dirs, wads_err_fn fn, void *user)
{
	char buf[sizeof(((struct cfg *)0)->game.content_dirs)], *save = NULL;

	w->n = 0;
	w->nbad = 0;
	snprintf(buf, sizeof(buf), "%s", dirs);
	for (char *d = strtok_r(buf, " \t", &save); d; d = strtok_r(NULL, " \t", &save))
		wads_dir(w, d, fn, user);
	return w->n;
}
