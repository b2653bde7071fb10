/*
 * keep: what a live cabinet keeps across power cuts, under the state
 * directory (config/st.h: written atomically, with a checksum and the
 * previous copy; docs/persistence.md): the settings the service menu
 * changed (settings.ini, the layer main.c reads after /etc/arcaded), the
 * high scores and the coin bookkeeping, each saved when the game bumps its
 * generation; the books once more at exit (play and power-on time count up
 * without a bump). And the flight recorder (config/fr.h): the last games
 * as recordings that start from a snapshot of the sim.
 *
 * Scripts and replays keep nothing: they start from the defaults, so they
 * replay the same anywhere (on = 0).
 */
#ifndef ARCADED_APP_KEEP_H
#define ARCADED_APP_KEEP_H

#include <stdint.h>

#include "app/ct.h"
#include "engine/game/sim.h"

struct fr;
struct rec_writer;

struct keep {
	const char *dir;           /* the state directory */
	int on;                    /* keep settings, scores, books */
	uint32_t set_gen, scores_gen, books_gen;  /* last saved generations */
	uint8_t res;               /* render size choice last saved */
	/* the flight recorder, fr NULL when off */
	struct fr *fr;
	struct rec_writer *game;   /* the game being recorded */
	uint8_t *snap;             /* sim_snapshot before a tick that may start a game
				    * (snap_len bytes; made at the first START) */
	size_t snap_len;
	int snap_taken;
	uint32_t snap_plays;       /* plays when the snapshot was taken */
	uint64_t map_hash;         /* of every stage: what recordings are tied to */
	const struct ct_spec *content;
	uint32_t audio_rate;       /* the games' audio hashes: mixed at this rate */
	struct snd_set *sounds;    /* mixed from these (borrowed; their hash made at a game's start) */
};

/* Starts sim s on the stages of ct with settings set and, when k is on,
 * the kept high scores and books (unusable ones are logged and replaced
 * by the defaults). k then saves what changes from there. */
void keep_start(struct keep *k, const char *dir, int on, struct sim *s, const struct ct *ct,
		const struct sim_settings *set);

/* Opens the flight recorder when k is on and keep > 0: at most keep
 * games in at most max_mb MiB (0: no cap), recorded against content and
 * map_hash (borrowed), with audio hashes of sounds (borrowed) mixed at
 * audio_rate. The sounds' hash is asked for (snd_set_hash) only when a
 * game begins. Failures are logged; games are then not recorded. */
void keep_flight_open(struct keep *k, int keep, int max_mb, uint64_t map_hash,
		      const struct ct_spec *content, uint32_t audio_rate, struct snd_set *sounds);

/* Before the tick of cmd: a START in attract may begin a game, so the
 * state it begins from is kept (its recording replays from there). */
void keep_flight_before(struct keep *k, const struct sim *s, const struct sim_cmd *cmd);

/* After that tick (and its sound, audio hash audio_hash): a game that
 * began is recorded from its snapshot, at frame size w x h; the tick is
 * added with its state and audio hashes; back in attract (or in the
 * service menu) the game is over and its recording kept. */
void keep_flight_after(struct keep *k, const struct sim *s, const struct sim_cmd *cmd, int w,
		       int h, uint64_t audio_hash);

/* After each tick: saves the settings (also when the render size w x h
 * changed), scores and books that changed. */
void keep_tick(struct keep *k, const struct sim *s, int w, int h);

/* At exit: a game cut by the stop is kept too; after ticks > 0, the books
 * are saved once more. */
void keep_close(struct keep *k, const struct sim *s, uint64_t ticks);

#endif
