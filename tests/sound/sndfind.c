/*
 * sndfind: finds a game sound in a WAV recording of what was played, by
 * normalized cross-correlation with the sound's own samples. A test tool
 * (tests/script/run.sh, tests/vm/run.sh), independent of the mixer: the
 * sound is taken from the game's sound set (the built-in one, or a WAD's
 * with --wad) at its own rate and brought to the recording's rate here,
 * by linear interpolation in double precision; the recording is read as
 * 16-bit PCM, mono (left + right) / 2.
 *
 *   sndfind [--wad FILE] [--ms N] [--min SCORE] WAV NAME
 *       NAME: the sound's name on the sound test page ("PISTOL SHOT",
 *       "COIN DROP") or its SFX name ("PISTOL", "COIN"). Uses the sound's
 *       first N ms (default 40) as the template. Prints one line per place
 *       the template matches with a score of at least SCORE (default 0.9;
 *       local maxima at least the template's length apart):
 *         found FRAME SCORE FIRST
 *       FRAME: where the sound starts in the recording (frames from the
 *       first sample); FIRST: the frame of its first audible sample
 *       (|sample| >= 328 in the sound itself, at the recording's rate);
 *       then "sndfind: N found, rate R, frames F, template T frames".
 *   sndfind --dump NAME RATE   prints the resampled template, one value a line
 *
 * Exit 0, or 2 on bad usage or an unreadable file. Floating point is
 * fine here: this is a test tool, not the engine.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/map/wad.h"
#include "engine/sound/sfx.h"
#include "engine/sound/snd.h"
#include "input/io.h"

static const char *const sf_ids[] = {
#define SF_NAME(id, shown, lump, prio) #id,
	"NONE", SFX_LIST(SF_NAME)
#undef SF_NAME
};

static int sf_find(const char *name)
{
	for (int id = 1; id < SFX_COUNT; id++)
		if (strcmp(name, sf_ids[id]) == 0 || strcmp(name, sfx_info(id)->name) == 0)
			return id;
	return -1;
}

/* The whole file (input/io.h), NULL when it cannot be read. */
static uint8_t *sf_slurp(const char *path, size_t *len)
{
	uint8_t *d;

	return io_read_file(path, (size_t)1 << 30, 0, &d, len) == 0 ? d : NULL;
}

static uint32_t sf_le32(const uint8_t *p)
{
	return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The sound resampled to rate: *n values. */
static double *sf_template(const struct snd *s, uint32_t rate, size_t *n)
{
	size_t m = (size_t)((double)s->len * rate / s->rate);
	double *t = calloc(m ? m : 1, sizeof(*t));

	for (size_t j = 0; t && j < m; j++) {
		double pos = (double)j * s->rate / rate;
		size_t i = (size_t)pos;
		double f = pos - (double)i, a = s->pcm[i], b = i + 1 < s->len ? s->pcm[i + 1] : 0;
		t[j] = a + (b - a) * f;
	}
	*n = m;
	return t;
}

int main(int argc, char **argv)
{
	const char *wadpath = NULL, *wav, *name;
	double min = 0.9, tt = 0, *t, *mono, *e;
	struct snd_set *set = NULL;
	size_t len, tn, frames, found = 0, first = 0;
	uint32_t rate;
	int ms = 40, i = 1, id;
	uint8_t *w;

	for (; i < argc && argv[i][0] == '-'; i += 2) {
		if (i + 1 >= argc)
			break;
		if (strcmp(argv[i], "--wad") == 0)
			wadpath = argv[i + 1];
		else if (strcmp(argv[i], "--ms") == 0)
			ms = atoi(argv[i + 1]);
		else if (strcmp(argv[i], "--min") == 0)
			min = atof(argv[i + 1]);
		else if (strcmp(argv[i], "--dump") == 0)
			break;
		else
			i = argc;
	}
	if (wadpath) {
		struct wad *wd;
		uint8_t *img = sf_slurp(wadpath, &len);
		char err[256], report[512] = "";
		if (!img || wad_new(&wd) < 0 || wad_add(wd, img, len, wadpath, err, sizeof(err)) < 0 ||
		    snd_load_wad(wd, &set, report, sizeof(report)) < 0) {
			fprintf(stderr, "sndfind: %s: cannot load its sounds\n", wadpath);
			return 2;
		}
	} else if (snd_builtin(&set) < 0) {
		return 2;
	}
	if (i + 2 < argc + 0 && strcmp(argv[i], "--dump") == 0) {
		id = sf_find(argv[i + 1]);
		if (id < 0)
			return 2;
		t = sf_template(&set->s[id], (uint32_t)atoi(argv[i + 2]), &tn);
		for (size_t k = 0; k < tn; k++)
			printf("%.3f\n", t[k]);
		return 0;
	}
	if (argc - i != 2) {
		fprintf(stderr, "usage: sndfind [--wad FILE] [--ms N] [--min SCORE] WAV NAME\n"
				"       sndfind [--wad FILE] --dump NAME RATE\n");
		return 2;
	}
	wav = argv[i];
	name = argv[i + 1];
	id = sf_find(name);
	if (id < 0) {
		fprintf(stderr, "sndfind: no sound called %s\n", name);
		return 2;
	}
	w = sf_slurp(wav, &len);
	if (!w || len < 44 || memcmp(w, "RIFF", 4) != 0 || memcmp(w + 8, "WAVE", 4) != 0) {
		fprintf(stderr, "sndfind: %s: not a WAV file\n", wav);
		return 2;
	}
	/* the fmt chunk, then the data chunk (QEMU's files have the plain
	 * 44-byte layout, as do the daemon's) */
	if (w[20] != 1 || w[22] != 2 || w[34] != 16) {
		fprintf(stderr, "sndfind: %s: not 16-bit stereo PCM\n", wav);
		return 2;
	}
	rate = sf_le32(w + 24);
	frames = (len - 44) / 4;
	mono = malloc((frames + 1) * sizeof(*mono));
	e = malloc((frames + 1) * sizeof(*e));
	if (!mono || !e)
		return 2;
	e[0] = 0;
	for (size_t k = 0; k < frames; k++) {
		int16_t l = (int16_t)(w[44 + 4 * k] | w[45 + 4 * k] << 8);
		int16_t r = (int16_t)(w[46 + 4 * k] | w[47 + 4 * k] << 8);
		mono[k] = ((double)l + r) / 2;
		e[k + 1] = e[k] + mono[k] * mono[k];        /* prefix sums of energy */
	}
	t = sf_template(&set->s[id], rate, &tn);
	for (size_t k = 0; k < tn; k++)
		if (fabs(t[k]) >= 328) {
			first = k;
			break;
		}
	if (tn > (size_t)ms * rate / 1000)
		tn = (size_t)ms * rate / 1000;
	for (size_t k = 0; k < tn; k++)
		tt += t[k] * t[k];
	if (tn == 0 || tt == 0 || frames < tn) {
		printf("sndfind: 0 found, rate %u, frames %zu, template %zu frames\n", rate, frames, tn);
		return 0;
	}
	/* the score at every frame; a peak is kept when no better one follows
	 * within a template's length */
	double best = 0;
	size_t at = 0;
	int have = 0;
	for (size_t o = 0; o + tn <= frames; o++) {
		double ee = e[o + tn] - e[o], num = 0, sc = 0;

		if (have && o - at >= tn) {
			printf("found %zu %.4f %zu\n", at, best, at + first);
			found++;
			have = 0;
		}
		if (ee >= tt * 1e-4) {                      /* not next to silence */
			for (size_t k = 0; k < tn; k++)
				num += mono[o + k] * t[k];
			sc = num / sqrt(ee * tt);
		}
		if (sc >= min && (!have || sc > best)) {
			best = sc;
			at = o;
			have = 1;
		}
	}
	if (have) {
		printf("found %zu %.4f %zu\n", at, best, at + first);
		found++;
	}
	printf("sndfind: %zu found, rate %u, frames %zu, template %zu frames\n", found, rate, frames,
	       tn);
	free(mono);
	free(e);
	free(t);
	free(w);
	snd_free(set);
	return 0;
}
