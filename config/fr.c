/*
 * fr: the flight recorder's directory. Every name change is a rename in
 * one directory followed by an fsync of the directory, so after a power
 * cut a recording is either still a .part (repaired at the next fr_open)
 * or a whole .rec, never half renamed.
 */
#include "config/fr.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "input/rec.h"

#define FR_PREFIX "game-"
#define FR_TIME_LEN 16                 /* YYYYMMDDTHHMMSSZ */

enum fr_kind { FR_DONE, FR_CUT, FR_PART };

struct fr {
	char *dir;
	int dfd;
	int keep;
	uint64_t cap;
	uint64_t next_seq;
	int active;                    /* a game is being recorded */
	char part[FR_NAME_MAX];        /* its .part name */
	char done[FR_NAME_MAX];        /* and its final name */
};

__attribute__((format(printf, 4, 5)))
static void fr_append(char *msg, size_t msglen, size_t *n, const char *fmt, ...)
{
	va_list ap;
	int w;

	if (!msg || *n + 1 >= msglen)
		return;
	va_start(ap, fmt);
	w = vsnprintf(msg + *n, msglen - *n, fmt, ap);
	va_end(ap);
	if (w > 0)
		*n = (size_t)w < msglen - *n ? *n + (size_t)w : msglen - 1;
}

/* Parses a name fr made: 0 with *seq and *kind, or -1 for any other file.
 * stem (FR_NAME_MAX bytes, may be NULL) gets "game-SEQ-TIME". */
static int fr_parse(const char *name, uint64_t *seq, enum fr_kind *kind, char *stem)
{
	const char *p = name + strlen(FR_PREFIX), *rest;
	uint64_t s = 0;
	int digits = 0;

	if (strncmp(name, FR_PREFIX, strlen(FR_PREFIX)) != 0)
		return -1;
	while (*p >= '0' && *p <= '9' && digits < 19) {
		s = s * 10 + (uint64_t)(*p++ - '0');
		digits++;
	}
	if (digits < 1 || *p++ != '-')
		return -1;
	for (int i = 0; i < FR_TIME_LEN; i++)
		if (!p[i] || (i == 8 && p[i] != 'T') || (i == 15 && p[i] != 'Z') ||
		    (i != 8 && i != 15 && (p[i] < '0' || p[i] > '9')))
			return -1;
	rest = p + FR_TIME_LEN;
	if (strcmp(rest, ".rec") == 0)
		*kind = FR_DONE;
	else if (strcmp(rest, "-cut.rec") == 0)
		*kind = FR_CUT;
	else if (strcmp(rest, ".rec.part") == 0)
		*kind = FR_PART;
	else
		return -1;
	if (stem) {
		size_t n = (size_t)(rest - name);

		if (n >= FR_NAME_MAX)
			return -1;
		memcpy(stem, name, n);
		stem[n] = '\0';
	}
	*seq = s;
	return 0;
}

static int fr_entry_cmp(const void *a, const void *b)
{
	const struct fr_entry *x = a, *y = b;

	return x->seq < y->seq ? -1 : x->seq > y->seq;
}

/* A listing of the recordings directory, on an fd of its own (readdir
 * must not move f->dfd, which the caller keeps using): 0 with *out, or
 * -errno. */
static int fr_opendir(struct fr *f, DIR **out)
{
	int dfd = openat(f->dfd, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);

	if (dfd < 0)
		return -errno;
	*out = fdopendir(dfd);
	if (!*out) {
		int e = errno;

		close(dfd);
		return -e;
	}
	return 0;
}

/* Every finished recording, sorted oldest first: *out malloc'd (NULL when
 * none), returns the count or -errno. Also raises f->next_seq past every
 * sequence seen, .part files included. */
static int fr_scan(struct fr *f, struct fr_entry **out)
{
	struct fr_entry *list = NULL;
	struct dirent *de;
	int n = 0, cap = 0, rc;
	DIR *d;

	*out = NULL;
	rc = fr_opendir(f, &d);
	if (rc < 0)
		return rc;
	while ((de = readdir(d)) != NULL) {
		enum fr_kind kind;
		struct stat sb;
		uint64_t seq;

		size_t len = strlen(de->d_name);

		if (len >= FR_NAME_MAX || fr_parse(de->d_name, &seq, &kind, NULL) < 0)
			continue;
		if (seq >= f->next_seq)
			f->next_seq = seq + 1;
		if (kind == FR_PART)
			continue;
		if (fstatat(f->dfd, de->d_name, &sb, AT_SYMLINK_NOFOLLOW) < 0 ||
		    !S_ISREG(sb.st_mode))
			continue;
		if (n == cap) {
			struct fr_entry *nl;

			cap = cap ? cap * 2 : 32;
			nl = realloc(list, (size_t)cap * sizeof(*list));
			if (!nl) {
				free(list);
				closedir(d);
				return -ENOMEM;
			}
			list = nl;
		}
		memset(&list[n], 0, sizeof(list[n]));
		memcpy(list[n].name, de->d_name, len + 1);
		list[n].seq = seq;
		list[n].size = (uint64_t)sb.st_size;
		list[n].cut = kind == FR_CUT;
		n++;
	}
	closedir(d);
	if (n > 1)
		qsort(list, (size_t)n, sizeof(*list), fr_entry_cmp);
	*out = list;
	return n;
}

/* Deletes the oldest recordings beyond keep and cap; returns how many, or
 * -errno. */
static int fr_prune(struct fr *f)
{
	struct fr_entry *list;
	uint64_t total = 0;
	int n, first = 0, removed = 0, ret = 0;

	n = fr_scan(f, &list);
	if (n < 0)
		return n;
	for (int i = 0; i < n; i++)
		total += list[i].size;
	while (n - first > 1 && (n - first > f->keep || (f->cap && total > f->cap))) {
		if (unlinkat(f->dfd, list[first].name, 0) < 0 && errno != ENOENT) {
			ret = -errno;
			break;
		}
		total -= list[first].size;
		first++;
		removed++;
	}
	free(list);
	if (removed && fsync(f->dfd) < 0 && ret == 0)
		ret = -errno;
	return ret < 0 ? ret : removed;
}

/* Repairs every .part left by a cut and renames it NAME-cut.rec (or
 * deletes it when not even its header was written). */
static int fr_recover(struct fr *f, char *msg, size_t msglen, size_t *mn)
{
	struct dirent *de;
	int changed = 0, ret;
	DIR *d;

	ret = fr_opendir(f, &d);
	if (ret < 0)
		return ret;
	while ((de = readdir(d)) != NULL) {
		char stem[FR_NAME_MAX], cut[FR_NAME_MAX + 8], path[4096], why[160];
		enum fr_kind kind;
		uint32_t count;
		uint64_t seq;
		int rc;

		if (fr_parse(de->d_name, &seq, &kind, stem) < 0 || kind != FR_PART)
			continue;
		/* Numbers are never reused, even a removed one's. */
		if (seq >= f->next_seq)
			f->next_seq = seq + 1;
		snprintf(path, sizeof(path), "%s/%s", f->dir, de->d_name);
		rc = rec_repair(path, &count, why, sizeof(why));
		if (rc == -EINVAL) {
			/* Cut before its header was whole: nothing to replay. */
			if (unlinkat(f->dfd, de->d_name, 0) < 0 && ret == 0)
				ret = -errno;
			fr_append(msg, msglen, mn, "%sremoved %s (%s)", *mn ? "; " : "",
				  de->d_name, why);
			changed = 1;
			continue;
		}
		if (rc < 0) {
			ret = rc;
			continue;
		}
		snprintf(cut, sizeof(cut), "%s-cut.rec", stem);
		if (renameat(f->dfd, de->d_name, f->dfd, cut) < 0) {
			ret = -errno;
			continue;
		}
		fr_append(msg, msglen, mn, "%srecovered %s (%" PRIu32 " ticks)", *mn ? "; " : "",
			  cut, count);
		changed = 1;
	}
	closedir(d);
	if (changed && fsync(f->dfd) < 0 && ret == 0)
		ret = -errno;
	return ret;
}

int fr_open(const char *dir, int keep, uint64_t cap, struct fr **out, char *msg, size_t msglen)
{
	struct fr *f;
	size_t mn = 0;
	int ret;

	if (msg && msglen)
		msg[0] = '\0';
	if (keep < 1 || keep > FR_KEEP_MAX)
		return -EINVAL;
	f = calloc(1, sizeof(*f));
	if (!f)
		return -ENOMEM;
	f->keep = keep;
	f->cap = cap;
	f->next_seq = 1;
	f->dfd = -1;
	f->dir = strdup(dir);
	if (!f->dir) {
		ret = -ENOMEM;
		goto fail;
	}
	if (mkdir(dir, 0755) < 0 && errno != EEXIST) {
		ret = -errno;
		goto fail;
	}
	f->dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (f->dfd < 0) {
		ret = -errno;
		goto fail;
	}
	ret = fr_recover(f, msg, msglen, &mn);
	if (ret < 0)
		goto fail;
	ret = fr_prune(f);
	if (ret < 0)
		goto fail;
	if (ret > 0)
		fr_append(msg, msglen, &mn, "%sremoved %d old recording%s", mn ? "; " : "", ret,
			  ret == 1 ? "" : "s");
	*out = f;
	return 0;
fail:
	fr_close(f);
	return ret;
}

void fr_close(struct fr *f)
{
	if (!f)
		return;
	if (f->dfd >= 0)
		close(f->dfd);
	free(f->dir);
	free(f);
}

const char *fr_dir(const struct fr *f)
{
	return f->dir;
}

int fr_begin_game(struct fr *f, time_t now, char *path, size_t pathlen)
{
	char stamp[FR_TIME_LEN + 1];
	struct tm tm;
	int n;

	if (f->active)
		return -EBUSY;
	if (!gmtime_r(&now, &tm) || strftime(stamp, sizeof(stamp), "%Y%m%dT%H%M%SZ", &tm) !=
				       FR_TIME_LEN)
		memcpy(stamp, "00000000T000000Z", sizeof(stamp));
	/* At most 5 + 20 + 1 + 16 + 4 = 46 bytes: ".part" fits too. */
	n = snprintf(f->done, sizeof(f->done), FR_PREFIX "%06" PRIu64 "-%s.rec", f->next_seq,
		     stamp);
	if (n < 0 || (size_t)n + sizeof(".part") > sizeof(f->part))
		return -ENAMETOOLONG;
	memcpy(f->part, f->done, (size_t)n);
	memcpy(f->part + n, ".part", sizeof(".part"));
	n = snprintf(path, pathlen, "%s/%s", f->dir, f->part);
	if (n < 0 || (size_t)n >= pathlen)
		return -ENAMETOOLONG;
	f->next_seq++;
	f->active = 1;
	return 0;
}

int fr_end_game(struct fr *f, int keep_it)
{
	int ret;

	if (!f->active)
		return -ENOENT;
	f->active = 0;
	if (!keep_it) {
		if (unlinkat(f->dfd, f->part, 0) < 0 && errno != ENOENT)
			return -errno;
		return 0;
	}
	if (renameat(f->dfd, f->part, f->dfd, f->done) < 0)
		return -errno;
	if (fsync(f->dfd) < 0)
		return -errno;
	ret = fr_prune(f);
	return ret < 0 ? ret : 0;
}

int fr_list(struct fr *f, struct fr_entry *out, int max)
{
	struct fr_entry *list;
	int n = fr_scan(f, &list);

	if (n < 0)
		return n;
	for (int i = 0; i < n && i < max; i++)
		out[i] = list[i];
	free(list);
	return n;
}
