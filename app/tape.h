/*
 * tape: the developer's recordings (input/rec.h). --record writes every
 * tick's command with its state, frame and audio hashes; --replay takes
 * the commands from a recording instead of the devices and prints each
 * tick's hashes ("TICK STATE FRAME AUDIO", hex); --verify compares them
 * with the ones the recording stores. A
 * recording made by the flight recorder (app/keep.h) starts from a
 * snapshot of the sim, which a replay restores.
 */
#ifndef ARCADED_APP_TAPE_H
#define ARCADED_APP_TAPE_H

#include <stdint.h>
#include <stdio.h>

#include "app/ct.h"
#include "input/rec.h"

struct r_frame;

struct tape {
	const char *record;        /* --record path, NULL none */
	const char *replay;        /* --replay path, NULL none */
	struct rec_writer *rec;    /* NULL: not recording (or stopped by an error) */
	struct rec_reader *rep;
	struct rec_verify verify;
	int verifying;             /* --verify, once the recording was accepted */
	int damaged;               /* the reader reported the file not whole */
	int quiet;                 /* replay: print no per-tick hashes */
	int no_render;             /* replay: no frames, so no frame hashes */
	FILE *out;                 /* per-tick hashes */
};

/* A version-3 header for a recording of this run: content hash map_hash,
 * settings set, frame size w x h, the level or map of content, sounds
 * sound_hash mixed at audio_rate, the time now; tick count unknown, no
 * hash flags (the caller's), no snapshot. */
void tape_header(struct rec_header *h, uint64_t map_hash, const struct sim_settings *set, int w,
		 int hgt, const struct ct_spec *content, uint32_t audio_rate, uint64_t sound_hash);

/* Opens recording path to replay it; run gets what it asks for (level,
 * settings, frame size; rec_run_from_header). 0 or -errno (logged). */
int tape_replay_open(struct tape *t, const char *path, struct rec_run *run);

/* Whether the recording replays on what this run loaded (run, whose
 * settings are set to the recording's: the game's rules come from it;
 * with verify, everything its hashes depend on too): 0 and *set = those
 * settings, or -errno (logged: "refused" and why). */
int tape_replay_check(struct tape *t, struct rec_run *run, int verify, struct sim_settings *set);

/* A recording that starts from a snapshot: s is put in that state. 0 or
 * -errno (logged). */
int tape_replay_restore(struct tape *t, struct sim *s);

/* Starts recording to path with header h. 0 or -errno (logged). */
int tape_record_open(struct tape *t, const char *path, const struct rec_header *h);

/* The path being recorded, NULL when not recording. t may be NULL. */
const char *tape_recording(const struct tape *t);

/* The replay's next tick (its command and stored hashes) into rt, 1; 0 at
 * the end of the recording (a short one is logged). */
int tape_next(struct tape *t, uint32_t tick, struct rec_tick *rt);

/* After tick `tick` ran with rt's command, its sound was mixed (audio
 * hash audio) and frame f was drawn (unless no_render): prints, verifies
 * and records its hashes. A failed write stops the recording (logged).
 * Nothing without a recording or replay. */
void tape_hashes(struct tape *t, uint32_t tick, const struct rec_tick *rt, const struct sim *s,
		 const struct r_frame *f, uint64_t audio);

/* --verify's verdict, logged: 1 when the replay differed from (or could
 * not be compared with) the recording, else 0. */
int tape_verdict(struct tape *t);

/* Finishes the recording (count, fsync; a failure is logged) and closes
 * the replay. */
void tape_close(struct tape *t);

#endif
