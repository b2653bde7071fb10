/*
 * mesh: the OBJ subset reader (mesh.h). One pass over the lines; each
 * statement is checked completely before the next, so the first bad line
 * is the one reported. The work is linear in the text's length and the
 * arrays are bounded by the MESH_MAX_* limits.
 */
#include "engine/map/mesh.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/msg.h"

/* The reader's state: arrays growing by doubling up to their limits. */
struct mesh_rd {
	const char *name;
	uint32_t line;
	char *err;
	size_t errlen;
	struct mesh_vert *v;
	struct mesh_tri *t;
	uint32_t nv, nt, capv, capt, nvt, nvn;
};

/* A word of the line: [p, p + n). */
struct mesh_word {
	const char *p;
	size_t n;
};

#define MESH_MAX_WORDS 8

static int mesh_fail(struct mesh_rd *rd, int rc, const char *what, const char *word, size_t n)
{
	char w[40];

	if (rd->err && rd->errlen) {
		rd->err[0] = '\0';
		msg_cat(rd->err, rd->errlen, rd->name);
		msg_cat(rd->err, rd->errlen, ":");
		msg_int(rd->err, rd->errlen, rd->line);
		msg_cat(rd->err, rd->errlen, ": ");
		msg_cat(rd->err, rd->errlen, what);
		if (word) {
			/* the word quoted, cut short and with control bytes shown as '?' */
			size_t k = n < sizeof w - 4 ? n : sizeof w - 4;

			for (size_t i = 0; i < k; i++)
				w[i] = (word[i] >= 0x20 && word[i] < 0x7f) ? word[i] : '?';
			w[k] = '\0';
			msg_cat(rd->err, rd->errlen, " '");
			msg_cat(rd->err, rd->errlen, w);
			msg_cat(rd->err, rd->errlen, n > k ? "...'" : "'");
		}
	}
	return rc;
}

static int mesh_is(const struct mesh_word *w, const char *s)
{
	return w->n == strlen(s) && memcmp(w->p, s, w->n) == 0;
}

/* A decimal: [+-]digits[.digits] or [+-].digits, |value| <= MESH_MAX_COORD,
 * to 16.16 rounded to the nearest (halves away from zero). 0, or -1. */
static int mesh_num(const char *p, size_t n, fx_t *out)
{
	size_t i = 0;
	int neg = 0, digits = 0;
	int64_t ip = 0, fnum = 0, fden = 1, v;

	if (i < n && (p[i] == '-' || p[i] == '+'))
		neg = p[i++] == '-';
	for (; i < n && p[i] >= '0' && p[i] <= '9'; i++, digits++)
		if ((ip = ip * 10 + (p[i] - '0')) > MESH_MAX_COORD)
			return -1;
	if (i < n && p[i] == '.') {
		for (i++; i < n && p[i] >= '0' && p[i] <= '9'; i++, digits++)
			if (fden < 1000000000) {
				/* nine digits are below 2^-16 of a unit: the rest
				 * cannot change the rounding but for exact halves,
				 * which only the ninth digit could make */
				fnum = fnum * 10 + (p[i] - '0');
				fden *= 10;
			}
	}
	if (i != n || digits == 0)
		return -1;
	v = ip * FX_ONE + (fnum * FX_ONE * 2 + fden) / (2 * fden);
	if (v > (int64_t)MESH_MAX_COORD * FX_ONE)
		return -1;
	*out = (fx_t)(neg ? -v : v);
	return 0;
}

/* An index of a face corner: 1..have, or -1..-have counting back. 0 and
 * out of range: -1. */
static int mesh_index(const char *p, size_t n, uint32_t have, uint32_t *out)
{
	size_t i = 0;
	int neg = 0;
	uint64_t v = 0;

	if (n && p[0] == '-')
		neg = 1, i = 1;
	if (i == n)
		return -1;
	for (; i < n; i++) {
		if (p[i] < '0' || p[i] > '9')
			return -1;
		v = v * 10 + (uint64_t)(p[i] - '0');
		if (v > UINT32_MAX)
			return -2;
	}
	if (v == 0 || v > have)
		return -2;
	*out = neg ? have - (uint32_t)v : (uint32_t)v - 1;
	return 0;
}

static int mesh_grow(void **p, uint32_t *cap, size_t elem, uint32_t need)
{
	uint32_t c = *cap ? *cap : 64;
	void *q;

	if (need <= *cap)
		return 0;
	while (c < need)
		c *= 2;
	q = realloc(*p, (size_t)c * elem);
	if (!q)
		return -ENOMEM;
	*p = q;
	*cap = c;
	return 0;
}

/* The numbers of a v, vt or vn line: between min and max of them. */
static int mesh_nums(struct mesh_rd *rd, const struct mesh_word *w, int nw, int min, int max,
		     fx_t *out)
{
	if (nw - 1 < min || nw - 1 > max)
		return mesh_fail(rd, -EINVAL, "wrong count of numbers after", w[0].p, w[0].n);
	for (int i = 1; i < nw; i++)
		if (mesh_num(w[i].p, w[i].n, &out[i - 1]) < 0)
			return mesh_fail(rd, -EINVAL, "bad number (decimal within +/-512)",
					 w[i].p, w[i].n);
	return 0;
}

/* One corner of a face: v, v/vt, v//vn or v/vt/vn. */
static int mesh_corner(struct mesh_rd *rd, const struct mesh_word *w, uint16_t *out)
{
	const char *p = w->p, *end = w->p + w->n, *s1, *s2;
	uint32_t v, a;
	int rc;

	s1 = memchr(p, '/', w->n);
	s2 = s1 ? memchr(s1 + 1, '/', (size_t)(end - s1 - 1)) : NULL;
	if (s2 && memchr(s2 + 1, '/', (size_t)(end - s2 - 1)))
		return mesh_fail(rd, -EINVAL, "bad face corner", w->p, w->n);
	rc = mesh_index(p, (size_t)((s1 ? s1 : end) - p), rd->nv, &v);
	if (rc == -2)
		return mesh_fail(rd, -EINVAL, "vertex index out of range", w->p, w->n);
	if (rc < 0)
		return mesh_fail(rd, -EINVAL, "bad face corner", w->p, w->n);
	if (s1 && (s2 ? s2 : end) > s1 + 1) {
		rc = mesh_index(s1 + 1, (size_t)((s2 ? s2 : end) - s1 - 1), rd->nvt, &a);
		if (rc < 0)
			return mesh_fail(rd, -EINVAL, rc == -2 ? "texture coordinate index out of range" :
					 "bad face corner", w->p, w->n);
	} else if (s1 && !s2) {
		return mesh_fail(rd, -EINVAL, "bad face corner", w->p, w->n);
	}
	if (s2) {
		rc = mesh_index(s2 + 1, (size_t)(end - s2 - 1), rd->nvn, &a);
		if (rc < 0)
			return mesh_fail(rd, -EINVAL, rc == -2 ? "normal index out of range" :
					 "bad face corner", w->p, w->n);
	}
	*out = (uint16_t)v;
	return 0;
}

static int mesh_face(struct mesh_rd *rd, const struct mesh_word *w, int nw)
{
	uint16_t c[4];
	int n = nw - 1;

	if (n < 3 || n > 4)
		return mesh_fail(rd, -EINVAL, "f needs 3 or 4 corners (triangles and quads)", NULL, 0);
	for (int i = 0; i < n; i++)
		if (mesh_corner(rd, &w[i + 1], &c[i]) < 0)
			return -EINVAL;
	if (rd->nt + (uint32_t)(n - 2) > MESH_MAX_TRIS)
		return mesh_fail(rd, -E2BIG, "more than 2048 triangles", NULL, 0);
	if (mesh_grow((void **)&rd->t, &rd->capt, sizeof(*rd->t), rd->nt + 2) < 0)
		return -ENOMEM;
	for (int k = 0; k + 2 < n; k++) {
		struct mesh_tri *t = &rd->t[rd->nt++];

		t->v[0] = c[0];
		t->v[1] = c[k + 1];
		t->v[2] = c[k + 2];
	}
	return 0;
}

static int mesh_line(struct mesh_rd *rd, const char *p, size_t n)
{
	struct mesh_word w[MESH_MAX_WORDS];
	int nw = 0;
	fx_t num[3];
	size_t i = 0;

	while (i < n) {
		size_t s;

		while (i < n && (p[i] == ' ' || p[i] == '\t' || p[i] == '\r'))
			i++;
		if (i == n || p[i] == '#')
			break;
		s = i;
		while (i < n && p[i] != ' ' && p[i] != '\t' && p[i] != '\r' && p[i] != '#')
			i++;
		if (nw == MESH_MAX_WORDS)
			return mesh_fail(rd, -EINVAL, "too many words on the line", NULL, 0);
		w[nw].p = p + s;
		w[nw++].n = i - s;
	}
	if (nw == 0)
		return 0;
	if (mesh_is(&w[0], "v")) {
		if (mesh_nums(rd, w, nw, 3, 3, num) < 0)
			return -EINVAL;
		if (rd->nv == MESH_MAX_VERTS)
			return mesh_fail(rd, -E2BIG, "more than 1024 vertices", NULL, 0);
		if (mesh_grow((void **)&rd->v, &rd->capv, sizeof(*rd->v), rd->nv + 1) < 0)
			return -ENOMEM;
		/* OBJ's y is up: (x, y, z) is the map's (x, -z, y) */
		rd->v[rd->nv].x = num[0];
		rd->v[rd->nv].y = -num[2];
		rd->v[rd->nv++].z = num[1];
		return 0;
	}
	if (mesh_is(&w[0], "vt") || mesh_is(&w[0], "vn")) {
		int vt = w[0].p[1] == 't';
		uint32_t *cnt = vt ? &rd->nvt : &rd->nvn;

		if (mesh_nums(rd, w, nw, vt ? 1 : 3, 3, num) < 0)
			return -EINVAL;
		if (*cnt == MESH_MAX_AUX)
			return mesh_fail(rd, -E2BIG, vt ? "more than 4096 texture coordinates" :
					 "more than 4096 normals", NULL, 0);
		(*cnt)++;
		return 0;
	}
	if (mesh_is(&w[0], "f"))
		return mesh_face(rd, w, nw);
	if (mesh_is(&w[0], "o") || mesh_is(&w[0], "g") || mesh_is(&w[0], "s"))
		return 0;
	return mesh_fail(rd, -EINVAL, "unsupported statement", w[0].p, w[0].n);
}

int mesh_parse(const char *name, const char *buf, size_t len, struct mesh *out, char *err,
	       size_t errlen)
{
	struct mesh_rd rd = { .name = name, .err = err, .errlen = errlen };
	size_t i = 0;
	int rc = 0;

	memset(out, 0, sizeof(*out));
	if (err && errlen)
		err[0] = '\0';
	while (i < len && rc == 0) {
		const char *nl = memchr(buf + i, '\n', len - i);
		size_t e = nl ? (size_t)(nl - buf) : len;

		rd.line++;
		if (memchr(buf + i, '\0', e - i))
			rc = mesh_fail(&rd, -EINVAL, "NUL byte in the line", NULL, 0);
		else
			rc = mesh_line(&rd, buf + i, e - i);
		i = e + 1;
	}
	if (rc == 0 && rd.nt == 0) {
		rd.line = rd.line ? rd.line : 1;
		rc = mesh_fail(&rd, -EINVAL, "no faces", NULL, 0);
	}
	if (rc < 0) {
		if (rc == -ENOMEM)
			mesh_fail(&rd, -ENOMEM, "out of memory", NULL, 0);
		free(rd.v);
		free(rd.t);
		return rc;
	}
	out->v = rd.v;
	out->t = rd.t;
	out->nv = rd.nv;
	out->nt = rd.nt;
	out->zmin = out->zmax = rd.v[0].z;
	for (uint32_t k = 0; k < rd.nv; k++) {
		fx_t ax = fx_abs(rd.v[k].x), ay = fx_abs(rd.v[k].y);

		if (ax > out->radius)
			out->radius = ax;
		if (ay > out->radius)
			out->radius = ay;
		if (rd.v[k].z < out->zmin)
			out->zmin = rd.v[k].z;
		if (rd.v[k].z > out->zmax)
			out->zmax = rd.v[k].z;
	}
	return 0;
}

void mesh_free(struct mesh *m)
{
	if (!m)
		return;
	free((void *)m->v);
	free((void *)m->t);
	memset(m, 0, sizeof(*m));
}

const struct mesh_thing *mesh_set_find(const struct mesh_set *s, uint16_t type)
{
	if (!s)
		return NULL;
	for (uint32_t i = 0; i < s->n; i++)
		if (s->v[i].type == type)
			return &s->v[i];
	return NULL;
}
