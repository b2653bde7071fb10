/*
 * tape: --record, --replay, --verify (contract in tape.h).
 */
#include "app/tape.h"

#include <errno.h>
#include <inttypes.h>
#include <string.h>
#include <time.h>

#include "app/say.h"
#include "engine/core/hash.h"
#include "engine/render/r_main.h"

void tape_header(struct rec_header *h, uint64_t map_hash, const struct sim_settings *set, int w,
		 int hgt, const struct ct_spec *content, uint32_t audio_rate, uint64_t sound_hash)
{
	memset(h, 0, sizeof(*h));
	h->version = REC_VERSION_3;
	h->tick_rate = SIM_TICRATE;
	h->map_hash = map_hash;
	h->engine_version = REC_ENGINE_VERSION;
	h->set = *set;
	h->count = REC_COUNT_UNKNOWN;
	h->render_w = (uint16_t)w;
	h->render_h = (uint16_t)hgt;
	h->render_version = REC_RENDER_VERSION;
	h->level = (uint8_t)(content->nwads || content->grid ? 0 : content->level);
	h->start_time = (int64_t)time(NULL);
	h->audio_rate = audio_rate;
	h->audio_version = REC_AUDIO_VERSION;
	h->sound_hash = sound_hash;
	ct_first_map(content, h->map_name);   /* the first stage's, of a list */
}

int tape_replay_open(struct tape *t, const char *path, struct rec_run *run)
{
	char err[512] = "";
	int rc = rec_reader_open(path, &t->rep, err, sizeof(err));

	if (rc < 0) {
		say_err("%s", err[0] ? err : strerror(-rc));
		return rc;
	}
	t->replay = path;
	/* A recording says which built-in level and frame size it was made
	 * with (format 2); the replay uses them. */
	rec_run_from_header(rec_reader_header(t->rep), run);
	return 0;
}

int tape_replay_check(struct tape *t, struct rec_run *run, int verify, struct sim_settings *set)
{
	const struct rec_header *rh = rec_reader_header(t->rep);
	char err[512] = "";
	int rc;

	run->set = rh->set;
	/* --verify wants the very run the recording was made with; a plain
	 * replay needs the same map and engine only. */
	rc = verify ? rec_check_run(rh, run, err, sizeof(err))
		    : rec_check(rh, run->map_hash, err, sizeof(err));
	if (rc < 0) {
		say_err("%s: refused: %s", t->replay, err);
		return rc;
	}
	if (verify) {
		rec_verify_init(&t->verify, rh, run);
		t->verifying = 1;
	}
	/* The game's rules come from the recording, not from this cabinet's
	 * settings. */
	*set = rh->set;
	return 0;
}

int tape_replay_restore(struct tape *t, struct sim *s)
{
	const struct rec_header *rh = rec_reader_header(t->rep);
	int rc;

	if (!rh->snapshot_len)
		return 0;
	/* a recording of one game (flight recorder): it starts from the state
	 * the cabinet was in */
	rc = sim_restore(s, rh->snapshot, rh->snapshot_len);
	if (rc < 0)
		say_err("%s: refused: its start state does not fit this build's game", t->replay);
	return rc;
}

int tape_record_open(struct tape *t, const char *path, const struct rec_header *h)
{
	int rc = rec_writer_open(path, h, &t->rec);

	if (rc < 0) {
		say_err("%s: %s", path, strerror(-rc));
		t->rec = NULL;
		return rc;
	}
	t->record = path;
	return 0;
}

const char *tape_recording(const struct tape *t)
{
	return t && t->rec ? t->record : NULL;
}

int tape_next(struct tape *t, uint32_t tick, struct rec_tick *rt)
{
	int rc = rec_reader_next_tick(t->rep, rt);

	if (rc < 0) {
		say_err("%s: tick %u: %s", t->replay, tick,
			rc == -EIO ? "the recording is not the length its header's count says "
				     "(records missing, or bytes after them)"
				   : strerror(-rc));
		t->damaged = 1;
	}
	return rc > 0;
}

void tape_hashes(struct tape *t, uint32_t tick, const struct rec_tick *rt, const struct sim *s,
		 const struct r_frame *f, uint64_t audio)
{
	struct rec_tick nt;

	if (!t->rep && !t->rec)
		return;
	nt.cmd = rt->cmd;
	nt.state_hash = sim_hash(s);
	nt.frame_hash = t->no_render ? 0 : hash_frame(f->px, f->w, f->h, f->pitch);
	nt.audio_hash = audio;
	if (t->rep && !t->quiet)
		fprintf(t->out, "%u %016" PRIx64 " %016" PRIx64 " %016" PRIx64 "\n", tick,
			nt.state_hash, nt.frame_hash, nt.audio_hash);
	if (t->verifying)
		rec_verify_tick(&t->verify, tick, rt, &nt);
	if (t->rec) {
		if (rec_writer_put_tick(t->rec, &nt) < 0) {
			say_err("%s: write failed; recording stopped", t->record);
			rec_writer_close(t->rec);
			t->rec = NULL;
		}
	}
}

int tape_verdict(struct tape *t)
{
	char sum[512];
	int bad;

	if (!t->verifying)
		return 0;
	if (t->damaged) {
		/* the hashes of what was there may all match: a recording that
		 * is not whole does not pass */
		say_err("%s: FAILED: the recording could not be read to its header's count",
			t->replay);
		return 1;
	}
	bad = rec_verify_summary(&t->verify, sum, sizeof(sum));
	if (bad)
		say_err("%s: %s", t->replay, sum);
	else
		say("%s: %s", t->replay, sum);
	return bad != 0;
}

void tape_close(struct tape *t)
{
	if (t->rec) {
		int rc = rec_writer_close(t->rec);
		if (rc < 0)
			say_err("%s: %s", t->record, strerror(-rc));
		t->rec = NULL;
	}
	rec_reader_close(t->rep);
	t->rep = NULL;
}
