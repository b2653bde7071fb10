/*
 * tex_wad: a texture set from layered WADs.
 *
 *   PLAYPAL   14 palettes of 768 bytes; the first is used.
 *   COLORMAP  34 maps of 256; the first PAL_LIGHTS (32) are the light
 *             levels. Without it the colormaps are computed (pal.h).
 *   PNAMES    int32 count, then 8-byte patch names (looked up as lumps).
 *   TEXTURE1, TEXTURE2  int32 count, int32 offsets; each entry: name[8],
 *             int32 flags, int16 width, int16 height, int32 unused, int16
 *             patch count, then 10-byte patches: int16 x, int16 y, int16
 *             PNAMES index, 2 unused int16.
 *   flats     4096-byte lumps between F_START and F_END (or FF_START /
 *             FF_END; nested F1_START etc. are just more markers).
 *   sprites   Doom pictures between S_START and S_END (or SS_*).
 * Lump lookups go through wad_find, so the last file wins (a PWAD's
 * TEXTURE1 replaces the whole list, as in Doom); flats and sprites are
 * gathered from every file's ranges in order.
 *
 * Bounded (tex.h TEX_MAX_STEPS): composing, flat replacement and sprite
 * frames take steps from one count, which also polls the stop hook. The
 * lump being worked on when the count runs out is named in the message.
 */
#include "engine/map/tex.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/le.h"
#include "engine/core/lim.h"
#include "engine/core/msg.h"
#include "engine/map/map.h"
#include "engine/map/tex_local.h"
#include "engine/map/wad.h"

struct tw {
	const struct wad *w;
	struct tex_set *t;
	uint64_t budget;
	const uint8_t *tl[2];          /* TEXTURE1, TEXTURE2 lumps (or NULL) */
	size_t tlen[2];
	int tcount[2];
	int tlump[2];                  /* their lump numbers, for messages */
	struct lim lim;                /* TEX_MAX_STEPS and the stop hook */
	int *patches;                  /* PNAMES entry -> lump, -1 if none */
	int num_patches;
	uint8_t check_a, check_b;      /* fallback colours */
	int defer;                     /* textures, sprites: names and sizes only */
	const uint8_t *spr_want;       /* tex_compose: sprite pictures to decode */
	int spr_k;                     /* tex_compose: the picture the range is at */
	char *err;
	size_t errlen;
};

static int tw_fail(struct tw *c, const char *lump, const char *what, int64_t a, int64_t b)
{
	if (c->err && c->errlen)
		c->err[0] = '\0';
	msg_cat(c->err, c->errlen, lump);
	msg_cat(c->err, c->errlen, ": ");
	msg_cat(c->err, c->errlen, what);
	msg_int(c->err, c->errlen, a);
	if (b >= 0) {
		msg_cat(c->err, c->errlen, " (lump has ");
		msg_int(c->err, c->errlen, b);
		msg_cat(c->err, c->errlen, " bytes)");
	}
	return -EINVAL;
}

/* The message of a limit or stop while working on lump `lump` (entry
 * `entry` of it and its name, when entry >= 0):
 * "<file>: <LUMP>[ entry <i> (<name>)]: more than N steps (limit
 * TEX_MAX_STEPS)" or "...: stopped". Returns the count's error. */
static int tw_over(struct tw *c, int lump, int entry, const char *name)
{
	if (c->err && c->errlen)
		c->err[0] = '\0';
	msg_cat(c->err, c->errlen, wad_file(c->w, lump));
	msg_cat(c->err, c->errlen, ": ");
	msg_cat(c->err, c->errlen, wad_name(c->w, lump));
	if (entry >= 0) {
		msg_cat(c->err, c->errlen, " entry ");
		msg_int(c->err, c->errlen, entry);
		msg_cat(c->err, c->errlen, " (");
		msg_cat(c->err, c->errlen, name);
		msg_cat(c->err, c->errlen, ")");
	}
	if (c->lim.err == -ECANCELED) {
		msg_cat(c->err, c->errlen, ": stopped");
	} else {
		msg_cat(c->err, c->errlen, ": the textures need more than ");
		msg_int(c->err, c->errlen, (int64_t)TEX_MAX_STEPS);
		msg_cat(c->err, c->errlen, " steps to compose (limit TEX_MAX_STEPS)");
	}
	return c->lim.err;
}

static int tw_palette(struct tw *c, struct pal *p)
{
	size_t len;
	int i = wad_find(c->w, "PLAYPAL");
	const uint8_t *d = wad_data(c->w, i, &len);

	if (i < 0) {
		if (c->err && c->errlen)
			c->err[0] = '\0';
		msg_cat(c->err, c->errlen, "PLAYPAL: no palette in the WADs");
		return -EINVAL;
	}
	if (len < 768)
		return tw_fail(c, "PLAYPAL", "a palette needs 768 bytes, has ", (int64_t)len, -1);
	memcpy(p->rgb, d, 768);
	i = wad_find(c->w, "COLORMAP");
	if (i < 0) {
		pal_make_colormaps(p);
		return 0;
	}
	d = wad_data(c->w, i, &len);
	if (len < PAL_LIGHTS * 256)
		return tw_fail(c, "COLORMAP", "32 light maps need 8192 bytes, has ", (int64_t)len,
			       -1);
	memcpy(p->cmap, d, PAL_LIGHTS * 256);
	return 0;
}

/* TEXTURE1/TEXTURE2 and PNAMES headers; counts must fit their lumps. */
static int tw_lists(struct tw *c)
{
	static const char names[2][9] = { "TEXTURE1", "TEXTURE2" };
	size_t len;
	const uint8_t *d;
	int i;

	for (int k = 0; k < 2; k++) {
		i = wad_find(c->w, names[k]);
		if (i < 0)
			continue;
		d = wad_data(c->w, i, &len);
		if (len < 4)
			return tw_fail(c, names[k], "no count: ", (int64_t)len, -1);
		if (le_s32(d) < 0 || 4 + 4 * (uint64_t)(uint32_t)le_s32(d) > len)
			return tw_fail(c, names[k], "offsets of textures: ", le_s32(d),
				       (int64_t)len);
		c->tl[k] = d;
		c->tlen[k] = len;
		c->tcount[k] = le_s32(d);
		c->tlump[k] = i;
	}
	if ((int64_t)c->tcount[0] + c->tcount[1] > UINT16_MAX - 2)
		return tw_fail(c, "TEXTURE1", "too many textures: ",
			       (int64_t)c->tcount[0] + c->tcount[1], -1);
	if (!c->tl[0] && !c->tl[1])
		return 0;
	i = wad_find(c->w, "PNAMES");
	d = wad_data(c->w, i, &len);
	if (i < 0 || len < 4 || le_s32(d) < 0 ||
	    4 + 8 * (uint64_t)(uint32_t)le_s32(d) > len)
		return tw_fail(c, "PNAMES", "missing, or names past the end: ",
			       i < 0 || len < 4 ? 0 : le_s32(d), (int64_t)len);
	c->num_patches = le_s32(d);
	c->patches = calloc((size_t)(c->num_patches ? c->num_patches : 1), sizeof *c->patches);
	if (!c->patches)
		return -ENOMEM;
	for (int p = 0; p < c->num_patches; p++) {
		char name[9];

		memcpy(name, d + 4 + 8 * (size_t)p, 8);
		name[8] = '\0';
		c->patches[p] = wad_find(c->w, name);
	}
	return 0;
}

/* Texture entry k of list `list` into p; a bad entry, missing patch or a
 * picture over budget makes the fallback checker, counted. The step count
 * running out is an error (tw_over). */
static int tw_texture(struct tw *c, struct tex_pic *p, int list, int k)
{
	const uint8_t *d = c->tl[list];
	size_t len = c->tlen[list];
	int32_t ofs = le_s32(d + 4 + 4 * (size_t)k);
	const uint8_t *e = d + ofs;
	char name[9] = "";
	int w = TEX_CHECKER_SIDE, h = TEX_CHECKER_SIDE, np, r;

	if (ofs < 0 || (uint64_t)ofs + 22 > len)
		goto fallback;
	memcpy(name, e, 8);
	w = le_s16(e + 12);
	h = le_s16(e + 14);
	np = le_s16(e + 20);
	if (w <= 0 || h <= 0 || w > TEX_MAX_SIDE || h > TEX_MAX_SIDE) {
		w = h = TEX_CHECKER_SIDE;
		goto fallback;
	}
	if (np < 0 || (uint64_t)ofs + 22 + 10 * (uint64_t)np > len)
		goto fallback;
	r = tex_pic_new(p, name, w, h, &c->budget);
	if (r == -ENOMEM)
		return r;
	if (r)
		goto fallback;
	for (int i = 0; i < np; i++) {
		const uint8_t *pp = e + 22 + 10 * (size_t)i;
		int pn = le_get16(pp + 4);
		size_t plen;
		const uint8_t *pd;

		if (pn >= c->num_patches || c->patches[pn] < 0)
			goto fallback;
		pd = wad_data(c->w, c->patches[pn], &plen);
		r = tex_pic_draw(p, pd, plen, le_s16(pp), le_s16(pp + 2), &c->lim);
		if (r == -E2BIG || r == -ECANCELED) {
			tex_pic_clear(p);
			return tw_over(c, c->tlump[list], k, p->name);
		}
		if (r)
			goto fallback;
	}
	tex_pic_seal(p);
	return 0;
fallback:
	/* the texture's own size keeps its neighbours aligned; a texture that
	 * was in budget already paid for it, others pay now or get 8x8 */
	if (!p->px) {
		if ((uint64_t)w * (uint64_t)h > c->budget)
			w = h = 8;
		else
			c->budget -= (uint64_t)w * (uint64_t)h;
	}
	tex_pic_clear(p);
	c->t->missing++;
	return tex_pic_checker(p, name, w, h, c->check_a, c->check_b);
}

/* Texture entry k of list `list` described in p without its pixels (a
 * deferred set, tex_load_wad_names): the name and the size tw_texture
 * would give it, px NULL. A bad entry gets the checker's size, as there. */
static void tw_texture_meta(struct tw *c, struct tex_pic *p, int list, int k)
{
	const uint8_t *d = c->tl[list];
	size_t len = c->tlen[list];
	int32_t ofs = le_s32(d + 4 + 4 * (size_t)k);
	char name[9] = "";
	int w = TEX_CHECKER_SIDE, h = TEX_CHECKER_SIDE;

	memset(p, 0, sizeof *p);
	if (ofs >= 0 && (uint64_t)ofs + 22 <= len) {
		memcpy(name, d + ofs, 8);
		w = le_s16(d + ofs + 12);
		h = le_s16(d + ofs + 14);
		if (w <= 0 || h <= 0 || w > TEX_MAX_SIDE || h > TEX_MAX_SIDE)
			w = h = TEX_CHECKER_SIDE;
	}
	tex_name(p->name, name);
	p->w = (int16_t)w;
	p->h = (int16_t)h;
}

static int tw_flat_start(const char *n)
{
	return strcmp(n, "F_START") == 0 || strcmp(n, "FF_START") == 0;
}

static int tw_flat_end(const char *n)
{
	return strcmp(n, "F_END") == 0 || strcmp(n, "FF_END") == 0;
}

static int tw_spr_start(const char *n)
{
	return strcmp(n, "S_START") == 0 || strcmp(n, "SS_START") == 0;
}

static int tw_spr_end(const char *n)
{
	return strcmp(n, "S_END") == 0 || strcmp(n, "SS_END") == 0;
}

/* Calls fn(c, lump) for every lump inside a start/end range of its file
 * (an unclosed range ends with its file); returns the number of calls
 * when fn is NULL. */
static int tw_range(struct tw *c, int (*start)(const char *), int (*end)(const char *),
		    int (*fn)(struct tw *, int))
{
	int in = 0, n = 0;

	for (int i = 0; i < wad_count(c->w); i++) {
		const char *name = wad_name(c->w, i);
		size_t len;

		if (i > 0 && wad_file(c->w, i) != wad_file(c->w, i - 1))
			in = 0;
		if (start(name)) {
			in = 1;
			continue;
		}
		if (end(name)) {
			in = 0;
			continue;
		}
		wad_data(c->w, i, &len);
		if (!in || len == 0)
			continue;
		if (fn) {
			int r = fn(c, i);
			if (r < 0)
				return r;
		}
		n++;
	}
	return n;
}

/* A flat lump: a new flat, or new pixels for an earlier flat of its name. */
static int tw_flat(struct tw *c, int lump)
{
	struct tex_set *t = c->t;
	size_t len;
	const uint8_t *d = wad_data(c->w, lump, &len);
	char name[9];
	int k;

	if (len != TEX_FLAT_SIZE * TEX_FLAT_SIZE)
		return 0;
	if (lim_take(&c->lim, (uint64_t)t->num_flats + 1))
		return tw_over(c, lump, -1, NULL);
	tex_name(name, wad_name(c->w, lump));
	for (k = 0; k < t->num_flats; k++)
		if (memcmp(t->flats[k].name, name, 9) == 0)
			break;
	memcpy(t->flats[k].name, name, 9);
	memcpy(t->flats[k].px, d, sizeof t->flats[k].px);
	if (k == t->num_flats)
		t->num_flats++;
	return 0;
}

/* Sprite lump `lump` into p: decoded, or in a deferred set only its name,
 * size and offsets (px NULL) when its header is good; a bad header or a
 * picture over budget is the 8x8 checker, counted. */
static int tw_sprite_pic(struct tw *c, struct tex_pic *p, int lump)
{
	struct tex_set *t = c->t;
	size_t len;
	const uint8_t *d = wad_data(c->w, lump, &len);
	const char *name = wad_name(c->w, lump);
	int w, h, left, top, r;

	if (tex_pic_header(d, len, &w, &h, &left, &top)) {
		r = -EINVAL;
	} else if (c->defer) {
		memset(p, 0, sizeof *p);
		tex_name(p->name, name);
		p->w = (int16_t)w;
		p->h = (int16_t)h;
		p->left = (int16_t)left;
		p->top = (int16_t)top;
		return 0;
	} else {
		r = tex_pic_new(p, name, w, h, &c->budget);
		if (r == -ENOMEM)
			return r;
	}
	if (r) {
		t->missing++;
		r = tex_pic_checker(p, name, 8, 8, c->check_a, c->check_b);
		if (r)
			return r;
	} else {
		r = tex_pic_draw(p, d, len, 0, 0, &c->lim);
		if (r == -E2BIG || r == -ECANCELED) {
			tex_pic_clear(p);
			return tw_over(c, lump, -1, NULL);
		}
		tex_pic_seal(p);
		p->left = (int16_t)left;
		p->top = (int16_t)top;
	}
	return 0;
}

static int tw_sprite(struct tw *c, int lump)
{
	int r = tw_sprite_pic(c, &c->t->sprpics[c->t->num_sprpics], lump);

	if (r == 0)
		c->t->num_sprpics++;
	return r;
}

/* tex_compose's walk over the sprite lumps, in tw_sprite's order: decodes
 * picture spr_k when it is wanted and has no pixels yet. */
static int tw_sprite_compose(struct tw *c, int lump)
{
	int k = c->spr_k++;
	struct tex_pic *p;

	if (k >= c->t->num_sprpics)
		return 0;
	p = &c->t->sprpics[k];
	if (!c->spr_want[k] || p->px)
		return 0;
	return tw_sprite_pic(c, p, lump);
}

static int tw_load(struct tw *c, struct pal *pal)
{
	struct tex_set *t;
	int ntex, nflats, nspr, r;

	ntex = 1 + c->tcount[0] + c->tcount[1] + 1;
	nflats = tw_range(c, tw_flat_start, tw_flat_end, NULL) + 1;
	nspr = 1 + tw_range(c, tw_spr_start, tw_spr_end, NULL);
	if (nflats > UINT16_MAX || nspr > UINT16_MAX)
		return tw_fail(c, nspr > UINT16_MAX ? "S_START" : "F_START", "too many lumps: ",
			       nspr > UINT16_MAX ? nspr : nflats, -1);
	r = tex_set_alloc(&c->t, ntex, nflats, nspr);
	if (r)
		return r;
	t = c->t;
	t->pal = *pal;
	c->check_a = pal_nearest(pal, 255, 0, 255);
	c->check_b = pal_nearest(pal, 0, 0, 0);
	/* texture 0, Doom's "-": 1x1, transparent */
	r = tex_pic_new(&t->textures[0], "-", 1, 1, &c->budget);
	for (int k = 0, i = 1; !r && k < 2; k++)
		for (int e = 0; !r && e < c->tcount[k]; e++) {
			if (c->defer)
				tw_texture_meta(c, &t->textures[i++], k, e);
			else
				r = tw_texture(c, &t->textures[i++], k, e);
		}
	if (r)
		return r;
	t->fallback_tex = ntex - 1;
	r = tex_pic_checker(&t->textures[ntex - 1], "", TEX_CHECKER_SIDE, TEX_CHECKER_SIDE,
			    c->check_a, c->check_b);
	if (r)
		return r;
	/* flats: counted anew as names repeat; the fallback last */
	t->num_flats = 0;
	r = tw_range(c, tw_flat_start, tw_flat_end, tw_flat);
	if (r < 0)
		return r;
	t->fallback_flat = t->num_flats;
	tex_flat_checker(&t->flats[t->num_flats++], "", c->check_a, c->check_b);
	t->num_sprpics = 1;
	r = tex_pic_checker(&t->sprpics[0], "", 8, 8, c->check_a, c->check_b);
	if (!r)
		r = tw_range(c, tw_spr_start, tw_spr_end, tw_sprite);
	if (r < 0)
		return r;
	r = tex_set_finish(t, &c->lim);
	if (r == -E2BIG || r == -ECANCELED) {
		/* sprite frames: name the last sprite lump, S_END's range */
		int last = wad_count(c->w) - 1;

		while (last > 0 && !tw_spr_end(wad_name(c->w, last)))
			last--;
		return tw_over(c, last, -1, NULL);
	}
	return r;
}

int tex_load_wad(const struct wad *w, struct tex_set **out, char *err, size_t errlen)
{
	return tex_load_wad_lim(w, NULL, out, err, errlen);
}

static void tw_init(struct tw *c, const struct wad *w, const struct lim_stop *stop, char *err,
		    size_t errlen)
{
	memset(c, 0, sizeof *c);
	c->w = w;
	lim_init(&c->lim, stop, TEX_MAX_STEPS);
	c->budget = TEX_BUDGET;
	c->err = err;
	c->errlen = errlen;
	if (err && errlen)
		err[0] = '\0';
}

static int tw_load_set(const struct wad *w, const struct lim_stop *stop, int defer,
		       struct tex_set **out, char *err, size_t errlen)
{
	struct tw c;
	struct pal pal;
	int r;

	*out = NULL;
	tw_init(&c, w, stop, err, errlen);
	c.defer = defer;
	r = tw_palette(&c, &pal);
	if (!r)
		r = tw_lists(&c);
	if (!r)
		r = tw_load(&c, &pal);
	free(c.patches);
	if (r) {
		tex_free(c.t);
		return r;
	}
	*out = c.t;
	return 0;
}

int tex_load_wad_lim(const struct wad *w, const struct lim_stop *stop, struct tex_set **out,
		     char *err, size_t errlen)
{
	return tw_load_set(w, stop, 0, out, err, errlen);
}

int tex_load_wad_names(const struct wad *w, const struct lim_stop *stop, struct tex_set **out,
		       char *err, size_t errlen)
{
	return tw_load_set(w, stop, 1, out, err, errlen);
}

int tex_compose(struct tex_set *t, const struct wad *w, const uint8_t *want,
		const uint8_t *spr_want, const struct lim_stop *stop, char *err, size_t errlen)
{
	struct tw c;
	int r;

	tw_init(&c, w, stop, err, errlen);
	c.t = t;
	c.check_a = pal_nearest(&t->pal, 255, 0, 255);
	c.check_b = pal_nearest(&t->pal, 0, 0, 0);
	r = tw_lists(&c);
	/* the set's textures 1.. are TEXTURE1's then TEXTURE2's entries, as
	 * tw_load numbered them: the same WADs give the same lists */
	if (!r && 1 + c.tcount[0] + c.tcount[1] + 1 != t->num_textures)
		r = tw_fail(&c, "TEXTURE1", "not the lists the set was loaded from: ",
			    (int64_t)c.tcount[0] + c.tcount[1], -1);
	for (int i = 1; !r && i < t->num_textures - 1; i++) {
		int k = i - 1 < c.tcount[0] ? 0 : 1;

		if (!want[i] || t->textures[i].px)
			continue;
		r = tw_texture(&c, &t->textures[i], k, k ? i - 1 - c.tcount[0] : i - 1);
	}
	if (!r && spr_want) {
		int n;

		c.spr_want = spr_want;
		c.spr_k = 1;
		n = tw_range(&c, tw_spr_start, tw_spr_end, tw_sprite_compose);
		if (n < 0)
			r = n;             /* err names the lump (tw_over) */
		else if (c.spr_k != t->num_sprpics)
			r = tw_fail(&c, "S_START", "not the sprites the set was loaded from: ",
				    c.spr_k - 1, -1);
	}
	free(c.patches);
	return r;
}
