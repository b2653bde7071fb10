/*
 * tex: the texture set's common parts: pictures (allocation, Doom picture
 * drawing, fallback checkers), lookup by name, sprite frames from lump
 * names, Doom's animation table and tex_animate. The WAD loader is
 * tex_wad.c, the project's own set tex_builtin.c.
 */
#include "engine/map/tex.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/le.h"
#include "engine/core/lim.h"
#include "engine/map/map.h"
#include "engine/map/tex_local.h"
#include "engine/map/wad.h"

void tex_name(char out[9], const char *src)
{
	memset(out, 0, 9);
	for (int i = 0; i < 8 && src[i]; i++) {
		char c = src[i];

		out[i] = (c >= 'a' && c <= 'z') ? (char)(c - 'a' + 'A') : c;
	}
}

int tex_set_alloc(struct tex_set **out, int num_textures, int num_flats, int num_sprpics)
{
	struct tex_set *t = calloc(1, sizeof *t);

	*out = NULL;
	if (!t)
		return -ENOMEM;
	t->textures = calloc((size_t)num_textures, sizeof *t->textures);
	t->flats = calloc((size_t)(num_flats ? num_flats : 1), sizeof *t->flats);
	t->sprpics = calloc((size_t)num_sprpics, sizeof *t->sprpics);
	t->tex_xlat = calloc((size_t)num_textures, sizeof *t->tex_xlat);
	t->flat_xlat = calloc((size_t)(num_flats ? num_flats : 1), sizeof *t->flat_xlat);
	if (!t->textures || !t->flats || !t->sprpics || !t->tex_xlat || !t->flat_xlat) {
		tex_free(t);
		return -ENOMEM;
	}
	t->num_textures = num_textures;
	t->num_flats = num_flats;
	t->num_sprpics = num_sprpics;
	t->sky_flat = -1;
	*out = t;
	return 0;
}

int tex_pic_new(struct tex_pic *p, const char *name, int w, int h, uint64_t *budget)
{
	uint64_t bytes = (uint64_t)w * (uint64_t)h * 2;

	memset(p, 0, sizeof *p);
	tex_name(p->name, name);
	if (w <= 0 || h <= 0 || w > TEX_MAX_SIDE || h > TEX_MAX_SIDE || bytes > *budget)
		return -E2BIG;
	p->px = calloc((size_t)w * (size_t)h, 1);
	p->opaque = calloc((size_t)w * (size_t)h, 1);
	if (!p->px || !p->opaque) {
		tex_pic_clear(p);
		return -ENOMEM;
	}
	p->w = (int16_t)w;
	p->h = (int16_t)h;
	*budget -= bytes;
	return 0;
}

int tex_pic_header(const uint8_t *d, size_t len, int *w, int *h, int *left, int *top)
{
	if (len < 8)
		return -EINVAL;
	*w = le_s16(d);
	*h = le_s16(d + 2);
	*left = le_s16(d + 4);
	*top = le_s16(d + 6);
	if (*w <= 0 || *h <= 0 || *w > TEX_MAX_SIDE || *h > TEX_MAX_SIDE ||
	    8 + 4 * (size_t)*w > len)
		return -EINVAL;
	return 0;
}

/* Draws one column's posts, starting at byte ofs of the lump, into column
 * px of p (already clipped to 0..w-1); y is the picture's top in p. 0 or
 * lim's error. */
static int tex_pic_column(struct tex_pic *p, const uint8_t *d, size_t len, size_t ofs, int px,
			  int y, struct lim *lim)
{
	int top = -1;
	uint8_t *col = p->px + (size_t)px * (size_t)p->h;
	uint8_t *opq = p->opaque + (size_t)px * (size_t)p->h;

	/* each post takes at least 4 bytes, so this ends within len/4 posts */
	while (ofs + 1 < len && d[ofs] != 0xFF) {
		int delta = d[ofs], n = d[ofs + 1];
		const uint8_t *src = d + ofs + 3;

		top = delta <= top ? top + delta : delta;
		if (ofs + 3 + (size_t)n > len)
			n = ofs + 3 > len ? 0 : (int)(len - ofs - 3);
		if (lim && lim_take(lim, 1 + (uint64_t)n))
			return lim->err;
		/* rows y + top + k for k in [k0, k1), those within 0..h-1,
		 * copied at once (a byte and a branch per pixel was the
		 * larger part of composing the textures) */
		int64_t at = (int64_t)y + top, k0 = at < 0 ? -at : 0, k1 = (int64_t)p->h - at;

		if (k1 > n)
			k1 = n;
		if (k0 < k1) {
			memcpy(col + at + k0, src + k0, (size_t)(k1 - k0));
			memset(opq + at + k0, 1, (size_t)(k1 - k0));
		}
		ofs += 4 + (size_t)d[ofs + 1];
	}
	return 0;
}

int tex_pic_draw(struct tex_pic *p, const uint8_t *d, size_t len, int x, int y, struct lim *lim)
{
	int w, h, left, top;

	if (tex_pic_header(d, len, &w, &h, &left, &top))
		return -EINVAL;
	for (int c = 0; c < w; c++) {
		int px = x + c;
		size_t ofs = (size_t)(uint32_t)le_s32(d + 8 + 4 * (size_t)c);

		if (lim && lim_take(lim, 1))
			return lim->err;
		if (px < 0 || px >= p->w || ofs >= len)
			continue;
		if (tex_pic_column(p, d, len, ofs, px, y, lim))
			return lim->err;
	}
	return 0;
}

void tex_pic_seal(struct tex_pic *p)
{
	size_t n = (size_t)p->w * (size_t)p->h;

	/* memchr: the library's word-at-a-time scan */
	if (!p->opaque || memchr(p->opaque, 0, n))
		return;
	free(p->opaque);
	p->opaque = NULL;
}

void tex_pic_clear(struct tex_pic *p)
{
	free(p->px);
	free(p->opaque);
	p->px = NULL;
	p->opaque = NULL;
	p->w = p->h = 0;
}

int tex_pic_checker(struct tex_pic *p, const char *name, int w, int h, uint8_t a, uint8_t b)
{
	memset(p, 0, sizeof *p);
	tex_name(p->name, name);
	p->px = malloc((size_t)w * (size_t)h);
	if (!p->px)
		return -ENOMEM;
	p->w = (int16_t)w;
	p->h = (int16_t)h;
	for (int x = 0; x < w; x++)
		for (int y = 0; y < h; y++)
			p->px[(size_t)x * (size_t)h + (size_t)y] = ((x >> 3) ^ (y >> 3)) & 1 ? b : a;
	return 0;
}

void tex_flat_checker(struct tex_flat *f, const char *name, uint8_t a, uint8_t b)
{
	tex_name(f->name, name);
	for (int y = 0; y < TEX_FLAT_SIZE; y++)
		for (int x = 0; x < TEX_FLAT_SIZE; x++)
			f->px[y * TEX_FLAT_SIZE + x] = ((x >> 3) ^ (y >> 3)) & 1 ? b : a;
}

void tex_free(struct tex_set *t)
{
	if (!t)
		return;
	for (int i = 0; t->textures && i < t->num_textures; i++)
		tex_pic_clear(&t->textures[i]);
	for (int i = 0; t->sprpics && i < t->num_sprpics; i++)
		tex_pic_clear(&t->sprpics[i]);
	for (int i = 0; t->sprites && i < t->num_sprites; i++)
		free(t->sprites[i].frames);
	free(t->textures);
	free(t->flats);
	free(t->sprpics);
	free(t->sprites);
	free(t->tex_xlat);
	free(t->flat_xlat);
	free(t->anims);
	free(t->tex_by_name);
	free(t->flat_by_name);
	free(t->spr_by_name);
	free(t->tex_keys);
	free(t->flat_keys);
	free(t->spr_keys);
	free(t);
}

int tex_wall_index(const struct tex_set *t, uint16_t num)
{
	const struct tex_pic *p;
	int n = num;

	if (n == 0)
		return 0;
	if (t->tex_xlat && n < t->num_textures)
		n = t->tex_xlat[n];
	if (n <= 0 || n >= t->num_textures || !t->textures)
		return -1;
	p = &t->textures[n];
	if (p->w <= 0 || p->h <= 0 || !p->px)
		return -1;
	return n;
}

/* The index of name among entries first .. n - 1 of an array of stride
 * bytes at base whose first member is a name of at most len (8 or 4)
 * characters in tex_name's form; -1 if none, or when name is empty or
 * longer than len. The scan that defines every lookup of textures, flats
 * and sprites (textures and flats use their name index when they have
 * one, which finds the same entry: the first of that name). */
static int tex_find_in(const void *base, size_t stride, int first, int n, size_t len,
		       const char *name)
{
	char key[9];

	if (!name[0] || strlen(name) > len)
		return -1;
	tex_name(key, name);
	for (int i = first; i < n; i++)
		if (memcmp((const char *)base + (size_t)i * stride, key, len + 1) == 0)
			return i;
	return -1;
}

/* What a name index indexes: wall textures, flats or sprites. */
enum { TEX_BY_WALL, TEX_BY_FLAT, TEX_BY_SPRITE };

/* The name of entry i of t's kind `by` (TEX_BY_*). */
static const char *tex_name_of(const struct tex_set *t, int by, int i)
{
	return by == TEX_BY_FLAT ? t->flats[i].name
	       : by == TEX_BY_SPRITE ? t->sprites[i].name : t->textures[i].name;
}

/* A name as one number whose order is the names' byte order: its first
 * eight bytes, the first the most significant, and zeros from its end on.
 * upper: a name asked for, upper-cased as tex_name does (stored names are
 * taken as they are, so the index's order is their bytes'). -1 for an
 * empty name or one longer than max characters, else 0. A lookup is then
 * a binary search of integers: comparing the names byte by byte cost more
 * than the list of sprites a frame shows looked up by name. */
static int tex_key(const char *name, size_t max, int upper, uint64_t *key)
{
	uint64_t k = 0;
	size_t i = 0;

	for (; i < 8 && name[i]; i++) {
		unsigned char c = (unsigned char)name[i];

		if (upper && c >= 'a' && c <= 'z')
			c = (unsigned char)(c - 'a' + 'A');
		k = k << 8 | c;
	}
	if (i == 0 || i > max || (i == 8 && name[8]))
		return -1;
	*key = k << (8 * (8 - i));
	return 0;
}

/* The entry whose key is that of name in idx[0..n) (entries sorted by key,
 * then index, keys[k] idx[k]'s key; names of at most max characters), the
 * first of equals, or -1. */
static int tex_bsearch(const uint16_t *idx, const uint64_t *keys, int n, size_t max,
		       const char *name)
{
	uint64_t key;
	int lo = 0, hi = n;

	if (tex_key(name, max, 1, &key) < 0)
		return -1;
	while (lo < hi) {
		int mid = lo + (hi - lo) / 2;

		if (keys[mid] < key)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo < n && keys[lo] == key ? idx[lo] : -1;
}

int tex_find(const struct tex_set *t, const char *name)
{
	if (strcmp(name, "-") == 0)
		return 0;
	if (t->tex_by_name)
		return t->num_textures > 1
			       ? tex_bsearch(t->tex_by_name, t->tex_keys, t->num_textures - 1, 8, name)
			       : -1;
	return tex_find_in(t->textures, sizeof(*t->textures), 1, t->num_textures, 8, name);
}

int tex_switch_partner(const struct tex_set *t, uint16_t num)
{
	char other[9];
	int i;

	if (num == 0 || num >= t->num_textures)
		return 0;
	memcpy(other, t->textures[num].name, sizeof(other));
	other[8] = '\0';
	if (strncmp(other, "SW1", 3) == 0)
		other[2] = '2';
	else if (strncmp(other, "SW2", 3) == 0)
		other[2] = '1';
	else
		return 0;
	i = tex_find(t, other);
	return i > 0 ? i : 0;
}

void tex_want_map(const struct tex_set *t, const struct map *m, uint8_t *want)
{
	int n = t->num_textures;

	for (uint32_t i = 0; i < m->num_sides; i++) {
		const uint16_t *side[3] = { &m->sides[i].top_tex, &m->sides[i].mid_tex,
					    &m->sides[i].bot_tex };

		for (int k = 0; k < 3; k++) {
			if (*side[k] == 0 || *side[k] >= n)
				continue;
			want[*side[k]] = 1;
			want[tex_switch_partner(t, *side[k])] = 1;
		}
	}
	if (t->sky_tex > 0 && t->sky_tex < n)
		want[t->sky_tex] = 1;
	/* an animation shows every member in turn */
	for (int a = 0; a < t->num_anims; a++) {
		const struct tex_anim *an = &t->anims[a];
		int any = 0;

		if (an->flat || an->first + an->count > n)
			continue;
		for (int k = 0; k < an->count; k++)
			any |= want[an->first + k];
		for (int k = 0; any && k < an->count; k++)
			want[an->first + k] = 1;
	}
	want[0] = 0;
}

void tex_want_sprite(const struct tex_set *t, const char *name, uint8_t *want_pics)
{
	int i = tex_find_sprite(t, name);

	if (i < 0)
		return;
	for (int f = 0; f < t->sprites[i].num_frames; f++)
		for (int r = 0; r < 8; r++)
			want_pics[t->sprites[i].frames[f].pic[r]] = 1;
}

int tex_map_heights(const struct tex_set *t, struct map *m)
{
	uint16_t *h = calloc(t->num_textures > 0 ? (size_t)t->num_textures : 1, sizeof(*h));

	if (!h)
		return -ENOMEM;
	for (int i = 0; i < t->num_textures; i++)
		h[i] = t->textures[i].h > 0 ? (uint16_t)t->textures[i].h : 0;
	free(m->tex_h);
	m->tex_h = h;
	m->num_tex_h = (uint32_t)t->num_textures;
	return 0;
}

int tex_find_flat(const struct tex_set *t, const char *name)
{
	if (t->flat_by_name)
		return tex_bsearch(t->flat_by_name, t->flat_keys, t->num_flats, 8, name);
	return tex_find_in(t->flats, sizeof(*t->flats), 0, t->num_flats, 8, name);
}

/* Sorts idx[0..n) and keys[0..n) (keys[k] the key of entry idx[k]) by key,
 * then index: a bottom-up merge sort through scratch arrays, stable
 * (equal keys keep index order) and n log n whatever the names. */
static void tex_sort_keys(uint16_t *idx, uint64_t *keys, uint16_t *ti, uint64_t *tk, int n)
{
	for (int width = 1; width < n; width *= 2) {
		for (int lo = 0; lo < n; lo += 2 * width) {
			int mid = lo + width < n ? lo + width : n;
			int hi = lo + 2 * width < n ? lo + 2 * width : n;
			int i = lo, j = mid, k = lo;

			while (i < mid && j < hi) {
				int b = keys[j] < keys[i];
				int from = b ? j++ : i++;

				ti[k] = idx[from];
				tk[k++] = keys[from];
			}
			for (; i < mid; i++, k++) {
				ti[k] = idx[i];
				tk[k] = keys[i];
			}
			for (; j < hi; j++, k++) {
				ti[k] = idx[j];
				tk[k] = keys[j];
			}
		}
		memcpy(idx, ti, (size_t)n * sizeof *idx);
		memcpy(keys, tk, (size_t)n * sizeof *keys);
	}
}

/* One name index: idx the n entries first..first + n - 1 of kind by
 * sorted by key, keys their keys. A stored name too long for its key (a
 * name has at most 8 bytes) gets key 0, which no lookup asks for. */
static void tex_index_kind(const struct tex_set *t, int by, int first, int n, uint16_t *idx,
			   uint64_t *keys, uint16_t *ti, uint64_t *tk)
{
	for (int i = 0; i < n; i++) {
		idx[i] = (uint16_t)(first + i);
		if (tex_key(tex_name_of(t, by, first + i), 8, 0, &keys[i]) < 0)
			keys[i] = 0;
	}
	tex_sort_keys(idx, keys, ti, tk, n);
}

/* tex_by_name, flat_by_name and spr_by_name, with their keys. */
static int tex_index(struct tex_set *t)
{
	int nt = t->num_textures > 1 ? t->num_textures - 1 : 0;
	int n = nt > t->num_flats ? nt : t->num_flats;
	uint16_t *ti;
	uint64_t *tk;

	if (t->num_sprites > n)
		n = t->num_sprites;
	if (n < 1)
		n = 1;
	ti = malloc((size_t)n * sizeof *ti);
	tk = malloc((size_t)n * sizeof *tk);
	t->tex_by_name = malloc((size_t)(nt ? nt : 1) * sizeof *t->tex_by_name);
	t->flat_by_name = malloc((size_t)(t->num_flats ? t->num_flats : 1) *
				 sizeof *t->flat_by_name);
	t->spr_by_name = malloc((size_t)(t->num_sprites ? t->num_sprites : 1) *
				sizeof *t->spr_by_name);
	t->tex_keys = malloc((size_t)(nt ? nt : 1) * sizeof *t->tex_keys);
	t->flat_keys = malloc((size_t)(t->num_flats ? t->num_flats : 1) * sizeof *t->flat_keys);
	t->spr_keys = malloc((size_t)(t->num_sprites ? t->num_sprites : 1) * sizeof *t->spr_keys);
	if (!ti || !tk || !t->tex_by_name || !t->flat_by_name || !t->spr_by_name ||
	    !t->tex_keys || !t->flat_keys || !t->spr_keys) {
		free(ti);
		free(tk);
		return -ENOMEM;
	}
	tex_index_kind(t, TEX_BY_WALL, 1, nt, t->tex_by_name, t->tex_keys, ti, tk);
	tex_index_kind(t, TEX_BY_FLAT, 0, t->num_flats, t->flat_by_name, t->flat_keys, ti, tk);
	tex_index_kind(t, TEX_BY_SPRITE, 0, t->num_sprites, t->spr_by_name, t->spr_keys, ti, tk);
	free(ti);
	free(tk);
	return 0;
}

int tex_find_sprite(const struct tex_set *t, const char *name)
{
	if (t->spr_by_name)
		return tex_bsearch(t->spr_by_name, t->spr_keys, t->num_sprites, 4, name);
	return tex_find_in(t->sprites, sizeof(*t->sprites), 0, t->num_sprites, 4, name);
}

int tex_sprite_pic(const struct tex_set *t, unsigned sprite, unsigned frame, ang_t view,
		   int *flip)
{
	const struct tex_sprframe *fr;
	unsigned rot, pi;

	if (!t->sprites || sprite >= (unsigned)t->num_sprites ||
	    frame >= (unsigned)t->sprites[sprite].num_frames || !t->sprites[sprite].frames)
		return -1;
	fr = &t->sprites[sprite].frames[frame];
	/* eight rotations of 45 degrees, rotation 0 centred on facing the viewer */
	rot = (view + (ANG45 / 2) * 9) >> 29;
	pi = fr->pic[rot];
	if (!t->sprpics || pi >= (unsigned)t->num_sprpics || t->sprpics[pi].w <= 0 ||
	    t->sprpics[pi].h <= 0 || !t->sprpics[pi].px)
		return -1;
	*flip = fr->flip[rot] != 0;
	return (int)pi;
}

/* Doom's animated textures and flats (p_spec.c's animdefs: first and last
 * member by name, in lump / TEXTURE order), then arcaded's own. A range
 * whose ends are missing or out of order is skipped. */
static const struct {
	uint8_t flat;
	char first[9], last[9];
} tex_animdefs[] = {
	{ 1, "NUKAGE1", "NUKAGE3" }, { 1, "FWATER1", "FWATER4" }, { 1, "SWATER1", "SWATER4" },
	{ 1, "LAVA1", "LAVA4" }, { 1, "BLOOD1", "BLOOD3" }, { 1, "RROCK05", "RROCK08" },
	{ 1, "SLIME01", "SLIME04" }, { 1, "SLIME05", "SLIME08" }, { 1, "SLIME09", "SLIME12" },
	{ 0, "BLODGR1", "BLODGR4" }, { 0, "SLADRIP1", "SLADRIP3" }, { 0, "BLODRIP1", "BLODRIP4" },
	{ 0, "FIREWALA", "FIREWALL" }, { 0, "GSTFONT1", "GSTFONT3" }, { 0, "FIRELAV3", "FIRELAVA" },
	{ 0, "FIREMAG1", "FIREMAG3" }, { 0, "FIREBLU1", "FIREBLU2" }, { 0, "ROCKRED1", "ROCKRED3" },
	{ 0, "BFALL1", "BFALL4" }, { 0, "SFALL1", "SFALL4" }, { 0, "WFALL1", "WFALL4" },
	{ 0, "DBRAIN1", "DBRAIN4" },
	{ 1, "AR_WAT1", "AR_WAT4" },
};

#define TEX_NANIMDEFS ((int)(sizeof tex_animdefs / sizeof tex_animdefs[0]))

static int tex_anims(struct tex_set *t)
{
	t->anims = calloc(TEX_NANIMDEFS, sizeof *t->anims);
	if (!t->anims)
		return -ENOMEM;
	for (int i = 0; i < TEX_NANIMDEFS; i++) {
		int a, b;

		if (tex_animdefs[i].flat) {
			a = tex_find_flat(t, tex_animdefs[i].first);
			b = tex_find_flat(t, tex_animdefs[i].last);
		} else {
			a = tex_find(t, tex_animdefs[i].first);
			b = tex_find(t, tex_animdefs[i].last);
		}
		if (a <= 0 && !tex_animdefs[i].flat)
			continue;
		if (a < 0 || b <= a)
			continue;
		t->anims[t->num_anims].flat = tex_animdefs[i].flat;
		t->anims[t->num_anims].first = (uint16_t)a;
		t->anims[t->num_anims].count = (uint16_t)(b - a + 1);
		t->num_anims++;
	}
	return 0;
}

void tex_animate(struct tex_set *t, uint32_t tick)
{
	uint32_t step = tick / TEX_ANIM_TICKS;

	for (int i = 0; i < t->num_anims; i++) {
		const struct tex_anim *a = &t->anims[i];
		uint16_t *xlat = a->flat ? t->flat_xlat : t->tex_xlat;

		for (uint32_t k = 0; k < a->count; k++)
			xlat[a->first + k] = (uint16_t)(a->first + (step + k) % a->count);
	}
}

/* Sprite name checks: 4 name chars, then frame letter and rotation digit. */
static int tex_spr_frame(char c)
{
	return c >= 'A' && c < 'A' + 29 ? c - 'A' : -1;
}

static int tex_spr_rot(char c)
{
	return c >= '0' && c <= '8' ? c - '0' : -1;
}

static int tex_spr_valid(const char *n)
{
	if (strlen(n) != 6 && strlen(n) != 8)
		return 0;
	if (tex_spr_frame(n[4]) < 0 || tex_spr_rot(n[5]) < 0)
		return 0;
	return strlen(n) == 6 || (tex_spr_frame(n[6]) >= 0 && tex_spr_rot(n[7]) >= 0);
}

static void tex_spr_set(struct tex_sprframe *f, int rot, uint16_t pic, uint8_t flip)
{
	for (int r = 0; r < 8; r++) {
		if (rot == 0 || r == rot - 1) {
			f->pic[r] = pic;
			f->flip[r] = flip;
		}
	}
}

/* A sprite picture by its name's first 4 characters, then its index:
 * sorted, the pictures of one sprite are a run in index order. */
struct tex_spr_key {
	char name[4];
	uint32_t i;
};

static int tex_spr_key_cmp(const void *pa, const void *pb)
{
	const struct tex_spr_key *a = pa, *b = pb;
	int c = memcmp(a->name, b->name, 4);

	return c ? c : (a->i > b->i) - (a->i < b->i);
}

/* One sprite: the pictures keys[0..n) (those whose name starts with its
 * 4 chars, in index order). Takes a step per picture of the set (twice),
 * as the scan over every picture it replaced did. */
static int tex_sprite_build(struct tex_set *t, struct tex_sprite *s, const struct tex_spr_key *keys,
			    size_t n, struct lim *lim)
{
	int frames = 0;

	if (lim && lim_take(lim, 2 * (uint64_t)t->num_sprpics))
		return lim->err;
	for (size_t k = 0; k < n; k++) {
		const char *nm = t->sprpics[keys[k].i].name;

		if (tex_spr_frame(nm[4]) + 1 > frames)
			frames = tex_spr_frame(nm[4]) + 1;
		if (nm[6] && tex_spr_frame(nm[6]) + 1 > frames)
			frames = tex_spr_frame(nm[6]) + 1;
	}
	s->frames = calloc((size_t)frames, sizeof *s->frames);
	if (!s->frames)
		return -ENOMEM;
	s->num_frames = frames;
	for (size_t k = 0; k < n; k++) {
		const char *nm = t->sprpics[keys[k].i].name;
		uint16_t i = (uint16_t)keys[k].i;

		tex_spr_set(&s->frames[tex_spr_frame(nm[4])], tex_spr_rot(nm[5]), i, 0);
		if (nm[6])
			tex_spr_set(&s->frames[tex_spr_frame(nm[6])], tex_spr_rot(nm[7]), i, 1);
	}
	for (int f = 0; f < frames; f++)
		for (int r = 0; r < 8; r++)
			t->missing += s->frames[f].pic[r] == 0;
	return 0;
}

/* The sprites, in the order of their first valid picture. The valid
 * pictures are sorted by name once, so each sprite finds its pictures
 * as a run (a scan of every picture per sprite and per picture, with
 * tex_spr_valid each time, was half of tex_load_wad_names' time on
 * Freedoom 1); the steps taken are the scans' as before. */
static int tex_sprites(struct tex_set *t, struct lim *lim)
{
	struct tex_spr_key *keys;
	size_t nk = 0;
	int r = 0;

	t->sprites = calloc((size_t)t->num_sprpics, sizeof *t->sprites);
	keys = malloc((size_t)t->num_sprpics * sizeof *keys);
	if (!t->sprites || !keys) {
		free(keys);
		return -ENOMEM;
	}
	for (int i = 1; i < t->num_sprpics; i++)
		if (tex_spr_valid(t->sprpics[i].name)) {
			memcpy(keys[nk].name, t->sprpics[i].name, 4);
			keys[nk++].i = (uint32_t)i;
		}
	qsort(keys, nk, sizeof *keys, tex_spr_key_cmp);
	for (int i = 1; !r && i < t->num_sprpics; i++) {
		const char *n = t->sprpics[i].name;
		size_t lo = 0, hi = nk, end;

		if (!tex_spr_valid(n))
			continue;
		if (lim && lim_take(lim, (uint64_t)t->num_sprites)) {
			r = lim->err;
			break;
		}
		/* the run of n's 4 characters: seen unless it starts with i */
		while (lo < hi) {
			size_t mid = lo + (hi - lo) / 2;
			if (memcmp(keys[mid].name, n, 4) < 0)
				lo = mid + 1;
			else
				hi = mid;
		}
		if (keys[lo].i != (uint32_t)i)
			continue;
		for (end = lo + 1; end < nk && memcmp(keys[end].name, n, 4) == 0; end++)
			;
		memcpy(t->sprites[t->num_sprites].name, n, 4);
		t->sprites[t->num_sprites].name[4] = '\0';
		t->num_sprites++;
		r = tex_sprite_build(t, &t->sprites[t->num_sprites - 1], keys + lo, end - lo, lim);
	}
	free(keys);
	return r;
}

int tex_set_finish(struct tex_set *t, struct lim *lim)
{
	int r = tex_sprites(t, lim);

	if (!r)
		r = tex_index(t);
	if (!r)
		r = tex_anims(t);
	if (r)
		return r;
	for (int i = 0; i < t->num_textures; i++)
		t->tex_xlat[i] = (uint16_t)i;
	for (int i = 0; i < t->num_flats; i++)
		t->flat_xlat[i] = (uint16_t)i;
	t->sky_flat = tex_find_flat(t, "F_SKY1");
	t->sky_tex = tex_find(t, "SKY1");
	if (t->sky_tex < 0)
		t->sky_tex = t->fallback_tex;
	return 0;
}

void tex_pick_sky(struct tex_set *t, const char *map)
{
	char name[5] = "SKY1";
	char m[9];
	int i;

	tex_name(m, map);
	if (m[0] == 'E' && m[1] >= '1' && m[1] <= '9' && m[2] == 'M') {
		name[3] = m[1];
	} else if (memcmp(m, "MAP", 3) == 0 && m[3] >= '0' && m[3] <= '9' && m[4] >= '0' &&
		   m[4] <= '9') {
		int n = (m[3] - '0') * 10 + (m[4] - '0');

		name[3] = n < 12 ? '1' : n < 21 ? '2' : '3';
	} else {
		return;
	}
	i = tex_find(t, name);
	if (i > 0)
		t->sky_tex = i;
}
