/*
 * snd: Doom's sound lumps and the sound sets (contract in snd.h).
 */
#include "engine/sound/snd.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/hash.h"
#include "engine/core/le.h"
#include "engine/core/msg.h"
#include "engine/map/wad.h"
#include "engine/sound/syn.h"

#define SND_DS_HEADER 8
#define SND_DS_FORMAT 3
/* DMX skips this many bytes at each end of the sample data. */
#define SND_DS_PAD 16

int snd_ds_parse(const uint8_t *p, size_t len, struct snd_ds *out, char *why, size_t whylen)
{
	uint32_t fmt, rate, count;

	if (len < SND_DS_HEADER) {
		msg_int(why, whylen, (int64_t)len);
		msg_cat(why, whylen, " bytes, shorter than the 8-byte header");
		return -EINVAL;
	}
	fmt = le_get16(p);
	rate = le_get16(p + 2);
	count = le_get32(p + 4);
	if (fmt != SND_DS_FORMAT) {
		msg_cat(why, whylen, "format ");
		msg_int(why, whylen, fmt);
		msg_cat(why, whylen, ", not 3 (Doom's digital sound)");
		return -EINVAL;
	}
	if (rate < SND_RATE_MIN || rate > SND_RATE_MAX) {
		msg_cat(why, whylen, "sample rate ");
		msg_int(why, whylen, rate);
		msg_cat(why, whylen, " out of range 1000..96000");
		return -EINVAL;
	}
	if (count > len - SND_DS_HEADER) {
		msg_cat(why, whylen, "header says ");
		msg_int(why, whylen, count);
		msg_cat(why, whylen, " samples, the lump holds ");
		msg_int(why, whylen, (int64_t)(len - SND_DS_HEADER));
		return -EINVAL;
	}
	if (count <= 2 * SND_DS_PAD) {
		msg_int(why, whylen, count);
		msg_cat(why, whylen, " samples: less than the 32 padding bytes and one sample");
		return -EINVAL;
	}
	if (count - 2 * SND_DS_PAD > SND_LEN_MAX) {
		msg_int(why, whylen, count - 2 * SND_DS_PAD);
		msg_cat(why, whylen, " samples, more than ");
		msg_int(why, whylen, SND_LEN_MAX);
		return -EINVAL;
	}
	out->rate = rate;
	out->count = count - 2 * SND_DS_PAD;
	out->u8 = p + SND_DS_HEADER + SND_DS_PAD;
	return 0;
}

void snd_ds_decode(const struct snd_ds *d, int16_t *out)
{
	for (uint32_t i = 0; i < d->count; i++)
		out[i] = (int16_t)(((int32_t)d->u8[i] - 128) * 256);
}

uint64_t snd_hash(const struct snd *s, int n)
{
	uint64_t h = HASH_INIT;

	for (int i = 0; i < n; i++) {
		h = hash_u32(h, s[i].rate);
		h = hash_u32(h, s[i].len);
		for (uint32_t k = 0; k < s[i].len; k++)
			h = hash_u16(h, (uint16_t)s[i].pcm[k]);
	}
	return h;
}

uint16_t snd_ticks(const struct snd *s)
{
	uint64_t t;

	if (s->len == 0 || s->rate == 0)
		return 0;
	t = ((uint64_t)s->len + 1) * 60 + s->rate - 1;
	t /= s->rate;
	return (uint16_t)(t > 65535 ? 65535 : t);
}

/* A set with room for total samples; the sounds are filled in by the
 * caller. NULL without memory. */
static struct snd_set *snd_alloc(size_t total)
{
	struct snd_set *set = calloc(1, sizeof(*set));

	if (!set)
		return NULL;
	set->store = calloc(total ? total : 1, sizeof(int16_t));
	if (!set->store) {
		free(set);
		return NULL;
	}
	return set;
}

/* Synthesizes sound id at pcm (room for syn_len(id)) into set, summing
 * its parts in acc (room for as many). */
static void snd_synth(struct snd_set *set, int id, int16_t *pcm, int32_t *acc)
{
	set->s[id].pcm = pcm;
	set->s[id].len = syn_make(id, pcm, acc);
	set->s[id].rate = SYN_RATE;
	set->from_lump[id] = 0;
}

/* One sum buffer for every sound synthesized, with the longest built-in
 * sound's room: one allocation, not one per sound (pages a set that
 * synthesizes nothing never touches). NULL without memory. */
static int32_t *snd_acc(void)
{
	uint32_t longest = 1;

	for (int id = 1; id < SFX_COUNT; id++)
		longest = syn_len(id) > longest ? syn_len(id) : longest;
	return malloc(longest * sizeof(int32_t));
}

int snd_builtin(struct snd_set **out)
{
	size_t total = 0, at = 0;
	struct snd_set *set;
	int32_t *acc;

	for (int id = 1; id < SFX_COUNT; id++)
		total += syn_len(id);
	set = snd_alloc(total);
	acc = snd_acc();
	if (!set || !acc) {
		snd_free(set);
		free(acc);
		return -ENOMEM;
	}
	for (int id = 1; id < SFX_COUNT; id++) {
		snd_synth(set, id, set->store + at, acc);
		at += set->s[id].len;
	}
	free(acc);
	*out = set;
	return 0;
}

/* The lump of sound id in w when it names one that parses, else -1 (a
 * malformed one reported). */
static int snd_lump(const struct wad *w, int id, struct snd_ds *ds, char *report,
		    size_t reportlen)
{
	const struct sfx_info *in = sfx_info(id);
	const uint8_t *data;
	char why[160] = "";
	size_t len = 0;
	int i;

	if (!in->lump[0])
		return -1;
	i = wad_find(w, in->lump);
	if (i < 0)
		return -1;
	data = wad_data(w, i, &len);
	if (snd_ds_parse(data, len, ds, why, sizeof(why)) == 0)
		return i;
	if (report && report[0])
		msg_cat(report, reportlen, "; ");
	msg_cat(report, reportlen, in->lump);
	msg_cat(report, reportlen, ": ");
	msg_cat(report, reportlen, why);
	return -1;
}

int snd_load_wad(const struct wad *w, struct snd_set **out, char *report, size_t reportlen)
{
	struct snd_ds ds[SFX_COUNT];
	int lump[SFX_COUNT];
	size_t total = 0, at = 0;
	struct snd_set *set;
	int32_t *acc;

	for (int id = 1; id < SFX_COUNT; id++) {
		/* a lump named by two sounds is reported once */
		int dup = 0;
		for (int k = 1; k < id; k++)
			dup |= strcmp(sfx_info(k)->lump, sfx_info(id)->lump) == 0;
		lump[id] = snd_lump(w, id, &ds[id], dup ? NULL : report, dup ? 0 : reportlen);
		total += lump[id] >= 0 ? ds[id].count : syn_len(id);
	}
	set = snd_alloc(total);
	acc = snd_acc();
	if (!set || !acc) {
		snd_free(set);
		free(acc);
		return -ENOMEM;
	}
	for (int id = 1; id < SFX_COUNT; id++) {
		int16_t *pcm = set->store + at;
		if (lump[id] >= 0) {
			snd_ds_decode(&ds[id], pcm);
			set->s[id].pcm = pcm;
			set->s[id].len = ds[id].count;
			set->s[id].rate = ds[id].rate;
			set->from_lump[id] = 1;
		} else {
			snd_synth(set, id, pcm, acc);
		}
		at += set->s[id].len;
	}
	free(acc);
	*out = set;
	return 0;
}

uint64_t snd_set_hash(struct snd_set *set)
{
	if (!set->hashed) {
		set->lazy_hash = snd_hash(set->s, SFX_COUNT);
		set->hashed = 1;
	}
	return set->lazy_hash;
}

void snd_free(struct snd_set *set)
{
	if (!set)
		return;
	free(set->store);
	free(set);
}
