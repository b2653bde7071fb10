/*
 * rec_check: whether a recording replays on what a run loaded, and the
 * verification of a replay against the hashes a recording stores
 * (contracts in rec.h, next to the format they judge). Apart from rec.c,
 * which reads and writes the bytes, to keep both files short.
 */
#include "input/rec.h"

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "input/txt.h"

int rec_check(const struct rec_header *h, uint64_t map_hash, char *err, size_t errlen)
{
	char buf[256];
	size_t n = 0;

	buf[0] = '\0';
	if (h->map_hash != map_hash)
		n += (size_t)snprintf(buf + n, sizeof(buf) - n,
				      "map content differs: recording 0x%016" PRIx64
				      ", loaded 0x%016" PRIx64,
				      h->map_hash, map_hash);
	if (h->engine_version != REC_ENGINE_VERSION)
		snprintf(buf + n, sizeof(buf) - n,
			 "%sengine version differs: recording %" PRIu32 ", this build %d",
			 n ? "; " : "", h->engine_version, REC_ENGINE_VERSION);
	if (buf[0] == '\0')
		return 0;
	txt_set(err, errlen, "%s", buf);
	return -EINVAL;
}

/* Appends "; " (unless first) and a formatted part to buf of size len at
 * *n, never past the end. */
__attribute__((format(printf, 4, 5)))
static void rec_join(char *buf, size_t len, size_t *n, const char *fmt, ...)
{
	va_list ap;
	int w;

	if (*n >= len - 1)
		return;
	if (*n) {
		w = snprintf(buf + *n, len - *n, "; ");
		*n += (size_t)w < len - *n ? (size_t)w : len - 1 - *n;
	}
	va_start(ap, fmt);
	w = vsnprintf(buf + *n, len - *n, fmt, ap);
	va_end(ap);
	if (w > 0)
		*n += (size_t)w < len - *n ? (size_t)w : len - 1 - *n;
}

static bool rec_frames_comparable(const struct rec_header *h, const struct rec_run *run)
{
	return (h->hash_flags & REC_HAS_FRAME) && run->render_w != 0;
}

static bool rec_audio_comparable(const struct rec_header *h, const struct rec_run *run)
{
	return (h->hash_flags & REC_HAS_AUDIO) && run->audio_rate != 0;
}

int rec_check_run(const struct rec_header *h, const struct rec_run *run, char *err,
		  size_t errlen)
{
	const char *name = run->map_name ? run->map_name : "";
	char buf[512];
	size_t n = 0;

	buf[0] = '\0';
	if (h->map_hash != run->map_hash)
		rec_join(buf, sizeof(buf), &n,
			 "map content differs: recording 0x%016" PRIx64 ", loaded 0x%016" PRIx64,
			 h->map_hash, run->map_hash);
	if (h->engine_version != REC_ENGINE_VERSION)
		rec_join(buf, sizeof(buf), &n,
			 "engine version differs: recording %" PRIu32 ", this build %d",
			 h->engine_version, REC_ENGINE_VERSION);
	/* every setting, from the settings' field list (engine/game/sim.h) */
#define REC_SETTING_DIFFERS(kind, type, name, limit)                                     \
	if (h->set.name != run->set.name)                                                \
		rec_join(buf, sizeof(buf), &n,                                           \
			 "settings differ: " #name " recording %u, this run %u",          \
			 h->set.name, run->set.name);
	SIM_SETTINGS_FIELDS(REC_SETTING_DIFFERS)
#undef REC_SETTING_DIFFERS
	if (h->level && h->level != run->level)
		rec_join(buf, sizeof(buf), &n, "level differs: recording %u, loaded %u", h->level,
			 run->level);
	if (h->map_name[0] && strcmp(h->map_name, name) != 0)
		rec_join(buf, sizeof(buf), &n, "map differs: recording %s, loaded %s", h->map_name,
			 name[0] ? name : "(a built-in level)");
	if (rec_frames_comparable(h, run)) {
		if (h->render_w != run->render_w || h->render_h != run->render_h)
			rec_join(buf, sizeof(buf), &n,
				 "render size differs: recording %ux%u, this run %ux%u",
				 h->render_w, h->render_h, run->render_w, run->render_h);
		if (h->render_version != REC_RENDER_VERSION)
			rec_join(buf, sizeof(buf), &n,
				 "renderer version differs: recording %" PRIu32 ", this build %d",
				 h->render_version, REC_RENDER_VERSION);
	}
	if (rec_audio_comparable(h, run)) {
		if (h->audio_rate != run->audio_rate)
			rec_join(buf, sizeof(buf), &n,
				 "audio rate differs: recording %" PRIu32 ", this run %" PRIu32,
				 h->audio_rate, run->audio_rate);
		if (h->audio_version != REC_AUDIO_VERSION)
			rec_join(buf, sizeof(buf), &n,
				 "audio version differs: recording %" PRIu32 ", this build %d",
				 h->audio_version, REC_AUDIO_VERSION);
		if (h->sound_hash != run->sound_hash)
			rec_join(buf, sizeof(buf), &n,
				 "sounds differ: recording 0x%016" PRIx64 ", loaded 0x%016" PRIx64,
				 h->sound_hash, run->sound_hash);
	}
	if (n == 0)
		return 0;
	txt_set(err, errlen, "%s", buf);
	return -EINVAL;
}

void rec_run_from_header(const struct rec_header *h, struct rec_run *run)
{
	memset(run, 0, sizeof(*run));
	run->set = h->set;
	run->render_w = h->render_w;
	run->render_h = h->render_h;
	run->level = h->level;
	run->map_name = h->map_name;
	run->audio_rate = h->audio_rate;
}

/* Why the audio hashes of h are not compared by run into note, or 0 when
 * they are. */
static int rec_audio_note(const struct rec_header *h, const struct rec_run *run, char *note,
			  size_t len)
{
	if (run->audio_rate == 0)
		txt_set(note, len, "audio hashes not compared: not mixing");
	else if (h->audio_rate != run->audio_rate)
		txt_set(note, len,
			"audio hashes not compared: mixed at %" PRIu32 " Hz, mixing at %" PRIu32 " Hz",
			h->audio_rate, run->audio_rate);
	else if (h->audio_version != REC_AUDIO_VERSION)
		txt_set(note, len,
			"audio hashes not compared: mixed by audio version %" PRIu32
			", this build mixes version %d",
			h->audio_version, REC_AUDIO_VERSION);
	else if (h->sound_hash != run->sound_hash)
		txt_set(note, len, "audio hashes not compared: mixed from other sounds");
	else
		return 0;
	return 1;
}

void rec_verify_init(struct rec_verify *v, const struct rec_header *h, const struct rec_run *run)
{
	char audio[sizeof(v->note)] = "";

	memset(v, 0, sizeof(*v));
	v->first_bad = -1;
	v->compare = h->hash_flags & REC_HAS_STATE;
	if ((h->hash_flags & REC_HAS_AUDIO) && !rec_audio_note(h, run, audio, sizeof(audio)))
		v->compare |= REC_HAS_AUDIO;
	if (!(h->hash_flags & REC_HAS_FRAME))
		txt_set(v->note, sizeof(v->note), "%s", audio);
	else if (run->render_w == 0)
		txt_set(v->note, sizeof(v->note), "frame hashes not compared: not rendering");
	else if (h->render_w != run->render_w || h->render_h != run->render_h)
		txt_set(v->note, sizeof(v->note),
			"frame hashes not compared: recorded at %ux%u, rendering %ux%u",
			h->render_w, h->render_h, run->render_w, run->render_h);
	else if (h->render_version != REC_RENDER_VERSION)
		txt_set(v->note, sizeof(v->note),
			"frame hashes not compared: drawn by renderer version %" PRIu32
			", this build draws version %d",
			h->render_version, REC_RENDER_VERSION);
	else
		v->compare |= REC_HAS_FRAME;
	if (audio[0] && v->note[0] && strcmp(v->note, audio) != 0) {
		size_t n = strlen(v->note);
		snprintf(v->note + n, sizeof(v->note) - n, "; %s", audio);
	} else if (audio[0]) {
		txt_set(v->note, sizeof(v->note), "%s", audio);
	}
}

int rec_verify_tick(struct rec_verify *v, uint32_t tick, const struct rec_tick *rec,
		    const struct rec_tick *run)
{
	bool sbad = false, fbad = false, abad = false;

	v->ticks++;
	if (v->compare & REC_HAS_STATE) {
		v->state_checked++;
		sbad = rec->state_hash != run->state_hash;
		v->state_bad += sbad;
	}
	if (v->compare & REC_HAS_FRAME) {
		v->frame_checked++;
		fbad = rec->frame_hash != run->frame_hash;
		v->frame_bad += fbad;
	}
	if (v->compare & REC_HAS_AUDIO) {
		v->audio_checked++;
		abad = rec->audio_hash != run->audio_hash;
		v->audio_bad += abad;
	}
	if (!sbad && !fbad && !abad)
		return 0;
	if (v->first_bad < 0) {
		v->first_bad = tick;
		if (sbad)
			txt_set(v->first, sizeof(v->first),
				"state hash recording 0x%016" PRIx64 ", replay 0x%016" PRIx64,
				rec->state_hash, run->state_hash);
		else if (fbad)
			txt_set(v->first, sizeof(v->first),
				"frame hash recording 0x%016" PRIx64 ", replay 0x%016" PRIx64
				" (state hashes equal)",
				rec->frame_hash, run->frame_hash);
		else
			txt_set(v->first, sizeof(v->first),
				"audio hash recording 0x%016" PRIx64 ", replay 0x%016" PRIx64
				" (state and frame hashes equal)",
				rec->audio_hash, run->audio_hash);
	}
	return -EDOM;
}

int rec_verify_summary(const struct rec_verify *v, char *buf, size_t len)
{
	char note[sizeof(v->note) + 4] = "";
	int ret;

	if (v->note[0])
		snprintf(note, sizeof(note), " (%s)", v->note);
	if (v->first_bad >= 0) {
		txt_set(buf, len,
			"verify: FAILED: first difference at tick %" PRId64 ": %s; %" PRIu32
			" state, %" PRIu32 " frame and %" PRIu32 " audio hashes differ of %" PRIu32
			" ticks%s",
			v->first_bad, v->first, v->state_bad, v->frame_bad, v->audio_bad, v->ticks,
			note);
		return -EDOM;
	}
	ret = v->state_checked + v->frame_checked + v->audio_checked ? 0 : 1;
	if (ret)
		txt_set(buf, len, "verify: %" PRIu32 " ticks, nothing compared: the recording "
			"holds no hashes%s", v->ticks, note);
	else
		txt_set(buf, len, "verify: %" PRIu32 " ticks, %" PRIu32 " state, %" PRIu32
			" frame and %" PRIu32 " audio hashes equal%s", v->ticks, v->state_checked,
			v->frame_checked, v->audio_checked, note);
	return ret;
}
