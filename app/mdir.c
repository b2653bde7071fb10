/*
 * mdir: the mesh directory (mdir.h).
 */
#include "app/mdir.h"

#include <dirent.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "engine/core/hash.h"
#include "engine/core/num.h"
#include "engine/map/th.h"
#include "engine/render/r_game.h"
#include "input/io.h"

#define MDIR_NAMES 256             /* entries looked at (more: noted, skipped) */
#define MDIR_GREY 160              /* a mesh without a colour of its own */

static void mdir_note(mdir_note_fn fn, void *user, int bad, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));

static void mdir_note(mdir_note_fn fn, void *user, int bad, const char *fmt, ...)
{
	char msg[320];
	va_list ap;

	if (!fn)
		return;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	fn(user, bad, msg);
}

/* The thing type of name "NNNN.obj" (1 to 5 digits, 1..65535), or 0. */
static uint16_t mdir_type(const char *name)
{
	size_t k = strlen(name), nd = k > 4 ? k - 4 : 0;
	unsigned long v = 0;

	if (nd < 1 || nd > 5 || strcasecmp(name + nd, ".obj") != 0)
		return 0;
	for (size_t i = 0; i < nd; i++) {
		if (name[i] < '0' || name[i] > '9')
			return 0;
		v = v * 10 + (unsigned long)(name[i] - '0');
	}
	return v >= 1 && v <= 65535 ? (uint16_t)v : 0;
}

/* Reads regular file path whole (input/io.h, at most MDIR_FILE_MAX bytes)
 * into *buf: 0, or a negative errno with why filled. */
static int mdir_read(const char *path, char **buf, size_t *len, char *why, size_t wlen)
{
	uint8_t *b = NULL;
	int rc = io_read_file(path, MDIR_FILE_MAX, IO_REGULAR, &b, len);

	*buf = (char *)b;
	if (rc == -EINVAL || rc == -EISDIR)
		snprintf(why, wlen, "not a regular file");
	else if (rc == -EFBIG)
		snprintf(why, wlen, "larger than %u bytes", MDIR_FILE_MAX);
	else if (rc < 0)
		snprintf(why, wlen, "%s", strerror(-rc));
	return rc;
}

/* The colour line "# arcaded colour RRGGBB" of buf, if any: 1 with *rgb
 * set, 0 without one, -1 with *line set for one that is malformed. */
static int mdir_colour(const char *buf, size_t len, uint8_t rgb[3], unsigned *line)
{
	static const char key[] = "# arcaded colour ";
	const size_t kl = sizeof(key) - 1;
	unsigned ln = 1;

	for (size_t i = 0; i < len; ln++) {
		size_t e = i;

		while (e < len && buf[e] != '\n')
			e++;
		if (e - i >= kl && memcmp(buf + i, key, kl) == 0) {
			const char *h = buf + i + kl;
			size_t hl = e - i - kl;

			while (hl && (h[hl - 1] == '\r' || h[hl - 1] == ' ' || h[hl - 1] == '\t'))
				hl--;
			*line = ln;
			if (hl != 6)
				return -1;
			for (int k = 0; k < 3; k++) {
				int a = num_hex(h[2 * k]), b = num_hex(h[2 * k + 1]);
				if (a < 0 || b < 0)
					return -1;
				rgb[k] = (uint8_t)(16 * a + b);
			}
			return 1;
		}
		i = e + 1;
	}
	return 0;
}

static int mdir_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Whether the game draws thing type `type` where a mesh can stand in: a
 * prop or pickup (r_game_sprites draws no monster or player as a mesh). */
static int mdir_drawn(uint16_t type)
{
	const struct th_info *in = th_find(type);

	return in && (in->flags & (TH_PICKUP | TH_DECOR | TH_LIGHT)) &&
	       !(in->flags & (TH_MONSTER | TH_PLAYER));
}

/* One candidate file: loaded into d->v[d->n] or noted. */
static void mdir_file(struct mdir *d, const char *dir, const char *name, uint16_t type,
		      mdir_note_fn fn, void *user)
{
	char path[4096], err[256], why[160];
	struct mesh_thing *mt = &d->v[d->n];
	size_t len = 0;
	char *buf;
	uint8_t rgb[3];
	unsigned line = 0;
	int rc, c;

	if (mesh_set_find(&d->set, type)) {
		d->nignored++;
		mdir_note(fn, user, 0, "%s: a second mesh for thing type %u; ignored", name, type);
		return;
	}
	if (!mdir_drawn(type)) {
		d->nignored++;
		mdir_note(fn, user, 0, "%s: thing type %u is no prop or pickup; ignored", name, type);
		return;
	}
	if (d->n == MESH_SET_MAX) {
		d->nignored++;
		mdir_note(fn, user, 0, "%s: more than %u meshes; ignored", name, MESH_SET_MAX);
		return;
	}
	if ((size_t)snprintf(path, sizeof(path), "%s/%s", dir, name) >= sizeof(path)) {
		d->nbad++;
		mdir_note(fn, user, 1, "%s: path too long; refused", name);
		return;
	}
	rc = mdir_read(path, &buf, &len, why, sizeof(why));
	if (rc < 0) {
		d->nbad++;
		mdir_note(fn, user, 1, "%s: %s; refused", name, why);
		return;
	}
	rc = mesh_parse(name, buf, len, &mt->m, err, sizeof(err));
	c = rc < 0 ? 0 : mdir_colour(buf, len, rgb, &line);
	if (rc < 0 || c < 0) {
		d->nbad++;
		if (rc < 0)
			mdir_note(fn, user, 1, "%s; refused", err);
		else
			mdir_note(fn, user, 1, "%s:%u: bad colour (# arcaded colour RRGGBB, hex); refused",
				  name, line);
		mesh_free(&mt->m);
		free(buf);
		return;
	}
	if (c == 0) {
		int r = MDIR_GREY, g = MDIR_GREY, b = MDIR_GREY;

		r_game_mesh_colour(type, &r, &g, &b);
		rgb[0] = (uint8_t)r, rgb[1] = (uint8_t)g, rgb[2] = (uint8_t)b;
	}
	mt->type = type;
	mt->r = rgb[0], mt->g = rgb[1], mt->b = rgb[2];
	d->hash = hash_u16(d->hash, type);
	for (int k = 0; k < 3; k++)
		d->hash = hash_u8(d->hash, rgb[k]);
	d->hash = hash_bytes(d->hash, buf, len);
	free(buf);
	d->n++;
	d->set.n = d->n;
}

int mdir_load(struct mdir *d, const char *dir, mdir_note_fn fn, void *user)
{
	char *names[MDIR_NAMES];
	struct dirent *e;
	int n = 0, over = 0, rc = 0;
	DIR *dd;

	memset(d, 0, sizeof(*d));
	d->hash = HASH_INIT;
	if (!dir || !dir[0])
		return 0;
	dd = opendir(dir);
	if (!dd) {
		rc = -errno;
		mdir_note(fn, user, 1, "%s: %s; no meshes loaded", dir, strerror(-rc));
		return rc;
	}
	while ((e = readdir(dd))) {
		if (e->d_name[0] == '.')
			continue;
		if (n == MDIR_NAMES) {
			over++;
			continue;
		}
		if (!(names[n] = strdup(e->d_name))) {
			rc = -ENOMEM;
			break;
		}
		n++;
	}
	closedir(dd);
	if (over) {
		d->nignored += (uint32_t)over;
		mdir_note(fn, user, 0, "%s: more than %d entries: %d not looked at", dir, MDIR_NAMES,
			  over);
	}
	qsort(names, (size_t)n, sizeof(names[0]), mdir_cmp);
	if (rc == 0 && n && !(d->v = calloc(MESH_SET_MAX, sizeof(*d->v))))
		rc = -ENOMEM;
	d->set.v = d->v;
	for (int i = 0; i < n; i++) {
		uint16_t type = mdir_type(names[i]);

		if (rc < 0) {
			/* nothing */
		} else if (!type) {
			d->nignored++;
			mdir_note(fn, user, 0, "%s: not NNNN.obj (a thing type's number); ignored",
				  names[i]);
		} else {
			mdir_file(d, dir, names[i], type, fn, user);
		}
		free(names[i]);
	}
	if (rc < 0) {
		mdir_free(d);
		return rc;
	}
	return (int)d->n;
}

void mdir_free(struct mdir *d)
{
	if (!d)
		return;
	for (uint32_t i = 0; d->v && i < d->n; i++)
		mesh_free(&d->v[i].m);
	free(d->v);
	memset(d, 0, sizeof(*d));
	d->hash = HASH_INIT;
}
