/*
 * map_wad_write: maps back into Doom's binary format (map_wad.h), for the
 * level generator (tools/mklevels.c) and for opening the project's own maps
 * in Doom editors. The records are those map_wad.c reads; the BSP lumps are
 * written empty, so a loader (ours, or an editor's node builder) rebuilds
 * it.
 */
#include "engine/map/map_wad.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/le.h"
#include "engine/core/msg.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"

struct mww {
	uint8_t *d;
	size_t n, cap;
	uint8_t *dir;                  /* 16-byte directory entries */
	size_t ndir, dircap;
	int nlumps;
	int oom;
	char *err;
	size_t errlen;
};

static void mww_bytes(uint8_t **buf, size_t *n, size_t *cap, const void *p, size_t len, int *oom)
{
	if (*oom)
		return;
	if (*n + len > *cap) {
		size_t c = (*n + len) * 2 + 256;
		uint8_t *nb = realloc(*buf, c);

		if (!nb) {
			*oom = 1;
			return;
		}
		*buf = nb;
		*cap = c;
	}
	memcpy(*buf + *n, p, len);
	*n += len;
}

static void mww_put(struct mww *w, const void *p, size_t len)
{
	mww_bytes(&w->d, &w->n, &w->cap, p, len, &w->oom);
}

/* A 16-bit field: v's low 16 bits (two's complement for a negative v). */
static void mww_16(struct mww *w, int v)
{
	uint8_t b[2];

	le_put16(b, (uint16_t)v);
	mww_put(w, b, 2);
}

static void mww_name(struct mww *w, const char *s)
{
	char n[8] = { 0 };

	for (int i = 0; i < 8 && s[i]; i++)
		n[i] = s[i];
	mww_put(w, n, 8);
}

/* Records the lump that runs from byte `start` to the current end. */
static void mww_lump(struct mww *w, const char *name, size_t start)
{
	uint8_t e[16];

	le_put32(e, (uint32_t)start);
	le_put32(e + 4, (uint32_t)(w->n - start));
	memset(e + 8, 0, 8);
	for (int i = 0; i < 8 && name[i]; i++)
		e[8 + i] = (uint8_t)name[i];
	mww_bytes(&w->dir, &w->ndir, &w->dircap, e, 16, &w->oom);
	w->nlumps++;
}

static int mww_fail(struct mww *w, const char *map, const char *what, int64_t i, const char *why)
{
	if (w->err && w->errlen)
		w->err[0] = '\0';
	msg_cat(w->err, w->errlen, map);
	msg_cat(w->err, w->errlen, ": ");
	msg_cat(w->err, w->errlen, what);
	msg_cat(w->err, w->errlen, " ");
	msg_int(w->err, w->errlen, i);
	msg_cat(w->err, w->errlen, ": ");
	msg_cat(w->err, w->errlen, why);
	return -EINVAL;
}

/* A whole number of units within int16. */
static int mww_units(fx_t v)
{
	return v % FX_ONE == 0 && v / FX_ONE >= INT16_MIN && v / FX_ONE <= INT16_MAX;
}

/* Vertices the lines use: the level's own come first, the node builder
 * appends its split points after them. */
static uint32_t mww_num_vertices(const struct map *m)
{
	uint32_t n = 0;

	for (uint32_t i = 0; i < m->num_lines; i++) {
		if (m->lines[i].v1 + 1 > n)
			n = m->lines[i].v1 + 1;
		if (m->lines[i].v2 + 1 > n)
			n = m->lines[i].v2 + 1;
	}
	return n;
}

static int mww_check(struct mww *w, const struct map *m, const char *name,
		     const struct tex_set *t)
{
	if (m->num_sides >= 0xFFFF || m->num_lines > 0xFFFF || m->num_sectors > 0xFFFF ||
	    mww_num_vertices(m) > 0xFFFF || m->num_things > 0xFFFF)
		return mww_fail(w, name, "records over", 65535, "too many for 16-bit indices");
	for (uint32_t i = 0; i < mww_num_vertices(m); i++)
		if (!mww_units(m->vertices[i].x) || !mww_units(m->vertices[i].y))
			return mww_fail(w, name, "vertex", i, "not whole units within int16");
	for (uint32_t i = 0; i < m->num_things; i++)
		if (!mww_units(m->things[i].x) || !mww_units(m->things[i].y))
			return mww_fail(w, name, "thing", i, "not whole units within int16");
	for (uint32_t i = 0; i < m->num_sectors; i++) {
		const struct map_sector *s = &m->sectors[i];

		if (!mww_units(s->floor_h) || !mww_units(s->ceil_h))
			return mww_fail(w, name, "sector", i, "height not whole units within int16");
		if (s->floor_tex >= t->num_flats || s->ceil_tex >= t->num_flats)
			return mww_fail(w, name, "sector", i, "flat not in the texture set");
	}
	for (uint32_t i = 0; i < m->num_sides; i++) {
		const struct map_side *s = &m->sides[i];

		if (!mww_units(s->xoff) || !mww_units(s->yoff))
			return mww_fail(w, name, "side", i, "offset not whole units within int16");
		if (s->top_tex >= t->num_textures || s->mid_tex >= t->num_textures ||
		    s->bot_tex >= t->num_textures)
			return mww_fail(w, name, "side", i, "texture not in the texture set");
	}
	return 0;
}

static const char *mww_tex(const struct tex_set *t, uint16_t i)
{
	return i == 0 ? "-" : t->textures[i].name;
}

static void mww_map(struct mww *w, const struct map *m, const char *name,
		    const struct tex_set *t)
{
	size_t s = w->n;

	mww_lump(w, name, s);
	for (uint32_t i = 0; i < m->num_things; i++) {
		const struct map_thing *th = &m->things[i];

		mww_16(w, th->x / FX_ONE);
		mww_16(w, th->y / FX_ONE);
		/* binary angle to degrees, rounded: exact for whole degrees */
		mww_16(w, (int)((((uint64_t)th->angle * 360) + ((uint64_t)1 << 31)) >> 32) % 360);
		mww_16(w, th->type);
		mww_16(w, th->flags);
	}
	mww_lump(w, "THINGS", s);
	s = w->n;
	for (uint32_t i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];

		mww_16(w, (int)l->v1);
		mww_16(w, (int)l->v2);
		mww_16(w, l->flags);
		mww_16(w, l->special);
		mww_16(w, l->tag);
		mww_16(w, (int)l->side[0]);
		mww_16(w, l->side[1] == MAP_NONE ? 0xFFFF : (int)l->side[1]);
	}
	mww_lump(w, "LINEDEFS", s);
	s = w->n;
	for (uint32_t i = 0; i < m->num_sides; i++) {
		const struct map_side *sd = &m->sides[i];

		mww_16(w, sd->xoff / FX_ONE);
		mww_16(w, sd->yoff / FX_ONE);
		mww_name(w, mww_tex(t, sd->top_tex));
		mww_name(w, mww_tex(t, sd->bot_tex));
		mww_name(w, mww_tex(t, sd->mid_tex));
		mww_16(w, (int)sd->sector);
	}
	mww_lump(w, "SIDEDEFS", s);
	s = w->n;
	for (uint32_t i = 0; i < mww_num_vertices(m); i++) {
		mww_16(w, m->vertices[i].x / FX_ONE);
		mww_16(w, m->vertices[i].y / FX_ONE);
	}
	mww_lump(w, "VERTEXES", s);
	mww_lump(w, "SEGS", w->n);
	mww_lump(w, "SSECTORS", w->n);
	mww_lump(w, "NODES", w->n);
	s = w->n;
	for (uint32_t i = 0; i < m->num_sectors; i++) {
		const struct map_sector *sc = &m->sectors[i];

		mww_16(w, sc->floor_h / FX_ONE);
		mww_16(w, sc->ceil_h / FX_ONE);
		mww_name(w, t->flats[sc->floor_tex].name);
		mww_name(w, t->flats[sc->ceil_tex].name);
		mww_16(w, sc->light);
		mww_16(w, sc->special);
		mww_16(w, sc->tag);
	}
	mww_lump(w, "SECTORS", s);
	mww_lump(w, "REJECT", w->n);
	mww_lump(w, "BLOCKMAP", w->n);
}

int map_wad_write(const struct map *const *maps, const char *const *names, int n,
		  const struct tex_set *t, uint8_t **out, size_t *len, char *err, size_t errlen)
{
	struct mww w;
	uint8_t hdr[12] = { 'P', 'W', 'A', 'D' };
	int r;

	*out = NULL;
	*len = 0;
	memset(&w, 0, sizeof w);
	w.err = err;
	w.errlen = errlen;
	if (err && errlen)
		err[0] = '\0';
	mww_put(&w, hdr, sizeof hdr);
	for (int i = 0; i < n; i++) {
		r = mww_check(&w, maps[i], names[i], t);
		if (r)
			goto fail;
		mww_map(&w, maps[i], names[i], t);
	}
	if (w.oom) {
		r = -ENOMEM;
		goto fail;
	}
	le_put32(w.d + 4, (uint32_t)w.nlumps);
	le_put32(w.d + 8, (uint32_t)w.n);
	if (w.ndir)
		mww_put(&w, w.dir, w.ndir);
	if (w.oom) {
		r = -ENOMEM;
		goto fail;
	}
	free(w.dir);
	*out = w.d;
	*len = w.n;
	return 0;
fail:
	free(w.d);
	free(w.dir);
	return r;
}
