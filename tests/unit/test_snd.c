/*
 * snd: Doom's sound lumps and the sound sets. Lumps are made here byte by
 * byte; the real ones are Freedoom's (Debian's freedoom package), whose
 * numbers below were read from the WAD files with a separate script
 * (Python's struct over the directory): freedoom1's DSPISTOL is 11034
 * bytes, format 3, 22050 Hz, 11026 samples, the first after the padding
 * 0x9c; freedoom2 has 4 lumps of 4 bytes (DSPEDTH, DSBSPWLK, DSFLAME,
 * DSFLAMST), too short for a header.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/map/wad.h"
#include "engine/sound/sfx.h"
#include "engine/sound/snd.h"
#include "engine/sound/syn.h"
#include "tests/unit/wad_fixture.h"

/* A DS lump: header (format, rate, count) and count bytes of data; the
 * data is 16 bytes of padding (0x80), then 128 + 2 * i for sample i, then
 * 16 of padding. len is what the lump really holds. */
static size_t ds_lump(uint8_t *b, int fmt, int rate, uint32_t count, size_t samples)
{
	size_t n = 0;

	b[n++] = (uint8_t)fmt;
	b[n++] = (uint8_t)(fmt >> 8);
	b[n++] = (uint8_t)rate;
	b[n++] = (uint8_t)(rate >> 8);
	for (int i = 0; i < 4; i++)
		b[n++] = (uint8_t)(count >> (8 * i));
	for (int i = 0; i < 16; i++)
		b[n++] = 0x80;
	for (size_t i = 0; i < samples; i++)
		b[n++] = (uint8_t)(128 + 2 * i);
	for (int i = 0; i < 16; i++)
		b[n++] = 0x80;
	return n;
}

static void a_good_lump_parses_and_decodes(void **state)
{
	uint8_t b[128];
	size_t len = ds_lump(b, 3, 11025, 32 + 5, 5);
	struct snd_ds d;
	int16_t pcm[5];
	char why[128] = "";

	(void)state;
	assert_int_equal(len, 8 + 37);
	assert_int_equal(snd_ds_parse(b, len, &d, why, sizeof(why)), 0);
	assert_int_equal(d.rate, 11025);
	assert_int_equal(d.count, 5);                /* the padding is skipped */
	assert_ptr_equal(d.u8, b + 8 + 16);
	snd_ds_decode(&d, pcm);
	/* (128 + 2i - 128) * 256 */
	for (int i = 0; i < 5; i++)
		assert_int_equal(pcm[i], 512 * i);
	/* the ends of the 8-bit range */
	b[24] = 0;
	b[25] = 255;
	snd_ds_decode(&d, pcm);
	assert_int_equal(pcm[0], -32768);
	assert_int_equal(pcm[1], 32512);
	/* bytes after the counted ones are ignored */
	assert_int_equal(snd_ds_parse(b, len + 10, &d, why, sizeof(why)), 0);
	assert_int_equal(d.count, 5);
}

/* Parses b (len) and checks the message. */
static void refused(const uint8_t *b, size_t len, const char *want)
{
	struct snd_ds d;
	char why[160] = "";

	assert_int_equal(snd_ds_parse(b, len, &d, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, want);
}

static void malformed_lumps_are_refused_with_the_reason(void **state)
{
	uint8_t b[128];
	size_t len;
	struct snd_ds d;

	(void)state;
	len = ds_lump(b, 3, 11025, 37, 5);
	refused(b, 5, "5 bytes, shorter than the 8-byte header");
	refused(b, 0, "0 bytes, shorter than the 8-byte header");
	ds_lump(b, 0, 11025, 37, 5);
	refused(b, len, "format 0, not 3 (Doom's digital sound)");
	ds_lump(b, 0x103, 11025, 37, 5);
	refused(b, len, "format 259, not 3 (Doom's digital sound)");
	ds_lump(b, 3, 0, 37, 5);
	refused(b, len, "sample rate 0 out of range 1000..96000");
	ds_lump(b, 3, 999, 37, 5);
	refused(b, len, "sample rate 999 out of range 1000..96000");
	ds_lump(b, 3, 11025, 38, 5);                 /* one more than it holds */
	refused(b, len, "header says 38 samples, the lump holds 37");
	ds_lump(b, 3, 11025, 0xffffffffu, 5);
	refused(b, len, "header says 4294967295 samples, the lump holds 37");
	ds_lump(b, 3, 11025, 32, 0);
	refused(b, 8 + 32, "32 samples: less than the 32 padding bytes and one sample");
	/* 96000 Hz is the top, 1000 the bottom */
	ds_lump(b, 3, 1000, 37, 5);
	assert_int_equal(snd_ds_parse(b, len, &d, NULL, 0), 0);
	/* no room for a message is fine */
	ds_lump(b, 2, 11025, 37, 5);
	assert_int_equal(snd_ds_parse(b, len, &d, NULL, 0), -EINVAL);
}

static void a_lump_longer_than_the_limit_is_refused(void **state)
{
	uint32_t count = SND_LEN_MAX + 33;
	uint8_t *b = calloc(1, 8 + (size_t)count);
	char why[160] = "";
	struct snd_ds d;

	(void)state;
	assert_non_null(b);
	b[0] = 3;
	b[2] = 0x11;
	b[3] = 0x2b;                                 /* 11025 */
	for (int i = 0; i < 4; i++)
		b[4 + i] = (uint8_t)(count >> (8 * i));
	assert_int_equal(snd_ds_parse(b, 8 + (size_t)count, &d, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "524289 samples, more than 524288");
	free(b);
}

static void ticks_round_up_and_count_one_more_sample(void **state)
{
	(void)state;
	/* 11025 samples at 11025 Hz: 11026 * 60 / 11025 = 60.005 -> 61 */
	assert_int_equal(snd_ticks(&(struct snd){ NULL, 11025, 11025 }), 61);
	/* 734 at 44100: 735 * 60 / 44100 = 1 exactly */
	assert_int_equal(snd_ticks(&(struct snd){ NULL, 734, 44100 }), 1);
	assert_int_equal(snd_ticks(&(struct snd){ NULL, 735, 44100 }), 2);
	assert_int_equal(snd_ticks(&(struct snd){ NULL, 0, 44100 }), 0);
	/* never more than 65535 */
	assert_int_equal(snd_ticks(&(struct snd){ NULL, 0xffffffffu, 1000 }), 65535);
}

/* A WAD whose DSPISTOL is good and DSITEMUP malformed; DSPOSIT1 missing. */
static uint8_t *sound_wad(size_t *len)
{
	struct wfix f;
	uint8_t b[128];
	size_t n;

	wf_init(&f);
	n = ds_lump(b, 3, 8000, 32 + 10, 10);
	wf_lump(&f, "DSPISTOL", b, n);
	n = ds_lump(b, 7, 8000, 32 + 10, 10);
	wf_lump(&f, "DSITEMUP", b, n);
	return wf_finish(&f, "PWAD", len);
}

static void a_wad_set_takes_good_lumps_and_reports_bad_ones(void **state)
{
	size_t len;
	uint8_t *img = sound_wad(&len);
	struct snd_set *set, *bi;
	struct wad *w;
	char err[256], report[256] = "";

	(void)state;
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, img, len, "sounds.wad", err, sizeof(err)), 0);
	assert_int_equal(snd_load_wad(w, &set, report, sizeof(report)), 0);
	assert_int_equal(snd_builtin(&bi), 0);
	assert_string_equal(report, "DSITEMUP: format 7, not 3 (Doom's digital sound)");
	/* the pistol is the lump's: 10 samples at 8000 Hz, 0, 512, ... */
	assert_int_equal(set->from_lump[SFX_PISTOL], 1);
	assert_int_equal(set->s[SFX_PISTOL].rate, 8000);
	assert_int_equal(set->s[SFX_PISTOL].len, 10);
	assert_int_equal(set->s[SFX_PISTOL].pcm[3], 1536);
	/* the menu's select names DSPISTOL too: the same lump */
	assert_int_equal(set->from_lump[SFX_MENU_SELECT], 1);
	assert_int_equal(set->s[SFX_MENU_SELECT].len, 10);
	/* the malformed pickup and the missing sight play the built-in ones */
	assert_int_equal(set->from_lump[SFX_PICKUP], 0);
	assert_int_equal(set->s[SFX_PICKUP].rate, SYN_RATE);
	assert_int_equal(set->s[SFX_PICKUP].len, bi->s[SFX_PICKUP].len);
	assert_memory_equal(set->s[SFX_PICKUP].pcm, bi->s[SFX_PICKUP].pcm,
			    2 * bi->s[SFX_PICKUP].len);
	assert_int_equal(set->from_lump[SFX_GRUNT_SIGHT], 0);
	/* sounds without a lump name are always built in */
	assert_int_equal(set->from_lump[SFX_COIN], 0);
	/* the hash covers the sounds: another set, another hash */
	assert_true(snd_set_hash(set) != snd_set_hash(bi));
	assert_true(snd_set_hash(set) == snd_hash(set->s, SFX_COUNT));
	snd_free(set);
	snd_free(bi);
	snd_free(NULL);
	wad_free(w);
	free(img);
}

static uint8_t *slurp(const char *path, size_t *len)
{
	FILE *fp = fopen(path, "rb");
	uint8_t *d;
	long n;

	if (!fp)
		return NULL;
	fseek(fp, 0, SEEK_END);
	n = ftell(fp);
	fseek(fp, 0, SEEK_SET);
	d = malloc((size_t)n);
	if (!d || fread(d, 1, (size_t)n, fp) != (size_t)n)
		abort();
	fclose(fp);
	*len = (size_t)n;
	return d;
}

static struct wad *freedoom(const char *path, uint8_t **img)
{
	size_t len = 0;
	struct wad *w;
	char err[256];

	*img = slurp(path, &len);
	if (!*img) {
		print_message("SKIPPED: %s is not installed (Debian package freedoom; "
			      "scripts/setup.sh installs it)\n", path);
		return NULL;
	}
	assert_int_equal(wad_new(&w), 0);
	assert_int_equal(wad_add(w, *img, len, path, err, sizeof(err)), 0);
	return w;
}

/* The set's hash is made on the first ask and kept: a sample changed
 * after it (a set is never changed; this shows what is kept) leaves it. */
static void the_hash_is_made_once(void **state)
{
	struct snd_set *set;
	uint64_t first;

	(void)state;
	assert_int_equal(snd_builtin(&set), 0);
	assert_int_equal(set->hashed, 0);
	first = snd_set_hash(set);
	assert_int_equal(set->hashed, 1);
	assert_true(first == snd_hash(set->s, SFX_COUNT));
	set->store[set->s[SFX_COIN].pcm - set->store] ^= 1;
	assert_true(snd_set_hash(set) == first);
	assert_true(snd_hash(set->s, SFX_COUNT) != first);
	snd_free(set);
}

static void freedoom1_sounds(void **state)
{
	uint8_t *img;
	struct wad *w = freedoom("/usr/share/games/doom/freedoom1.wad", &img);
	struct snd_set *set;
	char report[256] = "";

	(void)state;
	if (!w)
		skip();
	assert_int_equal(snd_load_wad(w, &set, report, sizeof(report)), 0);
	assert_string_equal(report, "");
	assert_int_equal(set->from_lump[SFX_PISTOL], 1);
	assert_int_equal(set->s[SFX_PISTOL].rate, 22050);
	assert_int_equal(set->s[SFX_PISTOL].len, 11026 - 32);
	assert_int_equal(set->s[SFX_PISTOL].pcm[0], (0x9c - 128) * 256);
	/* every sound with a lump name has it in freedoom1 */
	for (int id = 1; id < SFX_COUNT; id++)
		assert_int_equal(set->from_lump[id], sfx_info(id)->lump[0] != '\0');
	snd_free(set);
	wad_free(w);
	free(img);
}

static void freedoom2_short_lumps_are_refused(void **state)
{
	uint8_t *img;
	struct wad *w = freedoom("/usr/share/games/doom/freedoom2.wad", &img);
	char bad[256] = "";
	int good = 0;

	(void)state;
	if (!w)
		skip();
	for (int i = 0; i < wad_count(w); i++) {
		const char *name = wad_name(w, i);
		const uint8_t *p;
		struct snd_ds d;
		char why[160] = "";
		size_t len;

		if (strncmp(name, "DS", 2) != 0)
			continue;
		p = wad_data(w, i, &len);
		if (snd_ds_parse(p, len, &d, why, sizeof(why)) == 0) {
			good++;
			continue;
		}
		assert_string_equal(why, "4 bytes, shorter than the 8-byte header");
		strcat(bad, name);
		strcat(bad, " ");
	}
	assert_string_equal(bad, "DSPEDTH DSBSPWLK DSFLAME DSFLAMST ");
	assert_int_equal(good, 103);
	wad_free(w);
	free(img);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_good_lump_parses_and_decodes),
		cmocka_unit_test(malformed_lumps_are_refused_with_the_reason),
		cmocka_unit_test(a_lump_longer_than_the_limit_is_refused),
		cmocka_unit_test(ticks_round_up_and_count_one_more_sample),
		cmocka_unit_test(a_wad_set_takes_good_lumps_and_reports_bad_ones),
		cmocka_unit_test(the_hash_is_made_once),
		cmocka_unit_test(freedoom1_sounds),
		cmocka_unit_test(freedoom2_short_lumps_are_refused),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
