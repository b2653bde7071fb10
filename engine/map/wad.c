/*
 * wad: the lump directory of layered WAD images.
 *
 * wad_add checks the header and every directory entry against the image
 * size once, then keeps a flat array of lumps over all files (pointers into
 * the borrowed images), so nothing later reads out of bounds. Entries that
 * overlap each other or the directory are tolerated (Doom tools write them:
 * shared data, markers with odd offsets); a lump of size 0 is a marker and
 * its offset is not checked.
 *
 * Lookups by name go through an index of (name, lump) pairs sorted once
 * per wad_add, so a loader that looks up every name of a long list (PNAMES)
 * does O(log n) work per name, not a scan of the directory; the number of
 * lumps is bounded by WAD_MAX_LUMPS (wad.h).
 */
#include "engine/map/wad.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/le.h"
#include "engine/core/msg.h"
#include "engine/map/map.h"

#define WAD_HEADER 12
#define WAD_ENTRY 16

struct wad_lump {
	const uint8_t *data;
	size_t size;
	char name[9];                  /* upper case, NUL-padded */
	int file;
};

/* An index entry: a lump's name and number. */
struct wad_key {
	char name[9];
	int lump;
};

struct wad {
	char **files;
	int num_files;
	struct wad_lump *lumps;
	int num_lumps;
	struct wad_key *index;         /* num_lumps entries, by name then lump */
};

static int wad_key_cmp(const void *pa, const void *pb)
{
	const struct wad_key *a = pa, *b = pb;
	int c = memcmp(a->name, b->name, 9);

	return c ? c : (a->lump > b->lump) - (a->lump < b->lump);
}

/* The first index entry not below (name, lump). */
static int wad_lower(const struct wad *w, const char name[9], int lump)
{
	int lo = 0, hi = w->num_lumps;
	struct wad_key k;

	memcpy(k.name, name, 9);
	k.lump = lump;
	while (lo < hi) {
		int mid = lo + (hi - lo) / 2;

		if (wad_key_cmp(&w->index[mid], &k) < 0)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

/* Upper-cases up to 8 chars of a name into out (NUL-padded to 9 bytes);
 * stops at a NUL. Returns 0, or -1 when src has more than 8 chars and
 * long_ok is 0. */
static int wad_norm(char out[9], const char *src, size_t max, int long_ok)
{
	size_t i;

	memset(out, 0, 9);
	for (i = 0; i < max && src[i]; i++) {
		char c = src[i];

		if (i == 8)
			return long_ok ? 0 : -1;
		out[i] = (c >= 'a' && c <= 'z') ? (char)(c - 'a' + 'A') : c;
	}
	return 0;
}

int wad_new(struct wad **out)
{
	*out = calloc(1, sizeof **out);
	return *out ? 0 : -ENOMEM;
}

/* err = "<file>: <what>" */
static int wad_fail(char *err, size_t errlen, const char *file, const char *what)
{
	if (err && errlen)
		err[0] = '\0';
	msg_cat(err, errlen, file);
	msg_cat(err, errlen, ": ");
	msg_cat(err, errlen, what);
	return -EINVAL;
}

/* err = "<file>: lump <i> (<name>) " */
static int wad_fail_lump(char *err, size_t errlen, const char *file, int i, const char *name)
{
	wad_fail(err, errlen, file, "lump ");
	msg_int(err, errlen, i);
	msg_cat(err, errlen, " (");
	msg_cat(err, errlen, name);
	msg_cat(err, errlen, ") ");
	return -EINVAL;
}

int wad_add(struct wad *w, const uint8_t *data, size_t len, const char *name, char *err,
	    size_t errlen)
{
	int32_t count, dir;
	struct wad_lump *lumps;
	struct wad_key *index;
	char **files;
	char *fname;
	size_t nlen = strlen(name);

	if (err && errlen)
		err[0] = '\0';
	if (len < WAD_HEADER)
		return wad_fail(err, errlen, name, "shorter than a WAD header (12 bytes)");
	if (memcmp(data, "IWAD", 4) != 0 && memcmp(data, "PWAD", 4) != 0)
		return wad_fail(err, errlen, name, "not a WAD file (no IWAD/PWAD signature)");
	count = le_s32(data + 4);
	dir = le_s32(data + 8);
	if (count < 0 || dir < 0 || (uint64_t)dir + (uint64_t)count * WAD_ENTRY > len) {
		wad_fail(err, errlen, name, "directory of ");
		msg_int(err, errlen, count);
		msg_cat(err, errlen, " lumps at ");
		msg_int(err, errlen, dir);
		msg_cat(err, errlen, " runs past the end of the file (");
		msg_int(err, errlen, (int64_t)len);
		msg_cat(err, errlen, ")");
		return -EINVAL;
	}
	if (count > WAD_MAX_LUMPS - w->num_lumps) {
		wad_fail(err, errlen, name, "");
		msg_int(err, errlen, count);
		msg_cat(err, errlen, " lumps, more than the limit of ");
		msg_int(err, errlen, WAD_MAX_LUMPS);
		msg_cat(err, errlen, " in all files (WAD_MAX_LUMPS)");
		return -E2BIG;
	}
	for (int32_t i = 0; i < count; i++) {
		const uint8_t *e = data + dir + (size_t)i * WAD_ENTRY;
		int32_t ofs = le_s32(e), size = le_s32(e + 4);
		char lname[9];

		wad_norm(lname, (const char *)e + 8, 8, 1);
		if (size < 0 || (size > 0 && ofs < 0)) {
			wad_fail_lump(err, errlen, name, i, lname);
			msg_cat(err, errlen, "has a negative offset or size");
			return -EINVAL;
		}
		if (size > 0 && (uint64_t)ofs + (uint64_t)size > len) {
			wad_fail_lump(err, errlen, name, i, lname);
			msg_cat(err, errlen, "ends at ");
			msg_int(err, errlen, (int64_t)ofs + size);
			msg_cat(err, errlen, ", past the end of the file (");
			msg_int(err, errlen, (int64_t)len);
			msg_cat(err, errlen, ")");
			return -EINVAL;
		}
	}
	fname = malloc(nlen + 1);
	files = realloc(w->files, (size_t)(w->num_files + 1) * sizeof *files);
	if (files)
		w->files = files;
	lumps = realloc(w->lumps, ((size_t)w->num_lumps + (size_t)count + 1) * sizeof *lumps);
	if (lumps)
		w->lumps = lumps;
	index = realloc(w->index, ((size_t)w->num_lumps + (size_t)count + 1) * sizeof *index);
	if (index)
		w->index = index;
	if (!fname || !files || !lumps || !index) {
		free(fname);
		return -ENOMEM;
	}
	memcpy(fname, name, nlen + 1);
	w->files[w->num_files] = fname;
	for (int32_t i = 0; i < count; i++) {
		const uint8_t *e = data + dir + (size_t)i * WAD_ENTRY;
		struct wad_lump *l = &w->lumps[w->num_lumps + i];
		int32_t size = le_s32(e + 4);

		l->size = (size_t)size;
		l->data = size > 0 ? data + le_s32(e) : data;
		l->file = w->num_files;
		wad_norm(l->name, (const char *)e + 8, 8, 1);
		memcpy(w->index[w->num_lumps + i].name, l->name, 9);
		w->index[w->num_lumps + i].lump = w->num_lumps + i;
	}
	w->num_files++;
	w->num_lumps += count;
	qsort(w->index, (size_t)w->num_lumps, sizeof *w->index, wad_key_cmp);
	return 0;
}

int wad_count(const struct wad *w)
{
	return w->num_lumps;
}

int wad_find(const struct wad *w, const char *name)
{
	char key[9];
	int i;

	if (wad_norm(key, name, SIZE_MAX, 0))
		return -1;
	/* the last entry of the name: the one before the first past it */
	i = wad_lower(w, key, INT_MAX) - 1;
	return i >= 0 && memcmp(w->index[i].name, key, 9) == 0 ? w->index[i].lump : -1;
}

int wad_find_from(const struct wad *w, const char *name, int from)
{
	char key[9];
	int i;

	if (wad_norm(key, name, SIZE_MAX, 0))
		return -1;
	i = wad_lower(w, key, from < 0 ? 0 : from);
	return i < w->num_lumps && memcmp(w->index[i].name, key, 9) == 0 ? w->index[i].lump : -1;
}

const uint8_t *wad_data(const struct wad *w, int i, size_t *len)
{
	if (i < 0 || i >= w->num_lumps) {
		*len = 0;
		return NULL;
	}
	*len = w->lumps[i].size;
	return w->lumps[i].data;
}

const char *wad_name(const struct wad *w, int i)
{
	return i < 0 || i >= w->num_lumps ? "" : w->lumps[i].name;
}

const char *wad_file(const struct wad *w, int i)
{
	return i < 0 || i >= w->num_lumps ? "" : w->files[w->lumps[i].file];
}

void wad_free(struct wad *w)
{
	if (!w)
		return;
	for (int i = 0; i < w->num_files; i++)
		free(w->files[i]);
	free(w->files);
	free(w->lumps);
	free(w->index);
	free(w);
}
