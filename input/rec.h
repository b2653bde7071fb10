/*
 * rec: the recording format: one record per tick after a versioned header.
 *
 * Version 1 (all integers little-endian, explicit offsets, never struct
 * dumps):
 *   0  8  magic "ARCDREC\0"
 *   8  2  format version (1, 2 or 3)
 *  10  2  tick rate (60)
 *  12  4  header size in bytes (REC_HEADER_SIZE for version 1)
 *  16  8  content hash of the map (map.content_hash)
 *  24  4  engine version (REC_ENGINE_VERSION: bumped when the sim changes)
 *  28  1  coins_per_credit   29 1 freeplay   30 1 start_in_play
 *  31  1  difficulty 0..3 (0 in recordings of engine version 1)
 *  32  4  number of records, or 0xffffffff if the writer did not finish
 *  36  1  lives 0..9, 0 meaning the default (0 in engine version 1)
 *  37  3  reserved 0; version 3 (engine version 5 on): stage_time 0..30 or
 *        255 (off) (37)
 *        and idle_out 0..2 (38); 39 reserved 0 until engine version 7,
 *        then free_aim 0..1 (0: vertical auto-aim, the default)
 *  40  ... records: the command, REC_CMD_SIZE bytes:
 *        int8 forward, int8 side, int16 turn, uint8 buttons, uint8 coins
 *
 * Version 2 keeps bytes 0..39 and adds (header size REC_HEADER_SIZE_V2):
 *  40  2  render width    42 2 render height (0: unknown)
 *  44  1  flags: REC_HAS_STATE, REC_HAS_FRAME (the per-tick hashes),
 *        REC_HAS_SNAPSHOT (the recording starts from a snapshot)
 *  45  1  built-in level number 1..99, 0 for a map loaded from a file
 *  46  2  reserved 0 (difficulty and lives are bytes 31 and 36, in every version);
 *        version 3: volume 0..100 (46) and attract_sound 0..9 (47)
 *  48  4  renderer version (REC_RENDER_VERSION: bumped when frames change)
 *  52  4  REC_HAS_SNAPSHOT: the snapshot's length in bytes; else reserved 0
 *  56  8  map name, NUL-padded ("MAP01"; empty for a built-in level)
 *  64  8  start time, seconds since 1970 (0: unknown; never read by replay)
 *  72  8  REC_HAS_SNAPSHOT: FNV-1a (engine/core/hash.h, from HASH_INIT) of the
 *        snapshot's bytes; else reserved 0
 *  80  ... REC_HAS_SNAPSHOT: the snapshot (sim_snapshot, engine/game/sim.h): the
 *        sim state before the first record's tick, which a replay restores
 *        (sim_init_stages, then sim_restore) instead of starting from
 *        sim_init. The header size is 80 + its length.
 *  ... bytes up to the header size: skipped (room for a later addition)
 *  then records: the command, then the state hash (8 bytes) if
 *        REC_HAS_STATE, then the frame hash (8 bytes) if REC_HAS_FRAME:
 *        sim_hash after the tick ran, and hash_frame of the frame rendered
 *        after it, exactly what `arcaded --replay` prints for that tick.
 *
 * Version 3 (sound) keeps version 2's bytes 0..79, with the two new
 * settings at 46 and 47, and adds (header size REC_HEADER_SIZE_V3):
 *  80  4  audio rate: the output rate (Hz) the audio hashes were mixed at;
 *        0 without audio hashes
 *  84  4  audio version (REC_AUDIO_VERSION: bumped when the mixer or the
 *        built-in sounds change any sample)
 *  88  8  sound hash: snd_set.hash (engine/sound/snd.h) of the sounds mixed
 *  96  8  header sum: FNV-1a (engine/core/hash.h, from HASH_INIT) of bytes
 *        0..31 and 36..95 (all but the count, which is written last)
 * 104  ... the snapshot, as in version 2 but at 104 (header size 104 + its length)
 *  and the flag REC_HAS_AUDIO (44): each record ends with the audio hash
 *        (8 bytes, after the frame hash): mix_hash of the tick's mixed
 *        buffer (engine/sound/mix.h), what `arcaded --replay` prints last.
 *
 * The writer puts 0xffffffff in the count and writes the real count only
 * when it closes, so a recording cut short (power loss, crash) is
 * recognisable and replays up to its last whole record (a partial last
 * record is ignored; rec_repair truncates to whole records and writes
 * the count). A finished recording (count known) is exactly the header
 * and its counted records: one that holds fewer, or more bytes, was
 * damaged afterwards: its whole counted records replay, then the reader
 * reports -EIO (and --verify fails). A header larger than the version's
 * size (a later minor addition) is skipped.
 *
 * Checks on the header beyond the ranges of its fields: reserved bytes
 * (37..39 before version 3, 39 in it; 46..47 in version 2; 52..55 and 72..79 without a snapshot) are 0, the map
 * name holds nothing after its first NUL, the start time fits 32 bits.
 * Version 3's header sum covers every header byte but the count, which
 * the record count check covers; in version 2 the low four bytes of the
 * start time are the only bytes no check covers (it has no header sum).
 *
 * A build before snapshots refuses a recording with one ("hash flags 0x04
 * unknown") rather than replaying it from the wrong start; this build
 * reads every older file. A version 1 or 2 recording was made by an engine
 * before sound (engine version 2 or older): it decodes, and rec_check then
 * refuses it by its engine version ("engine version differs: recording 2,
 * this build 3").
 */
#ifndef ARCADED_INPUT_REC_H
#define ARCADED_INPUT_REC_H

#include <stddef.h>
#include <stdint.h>

#include "engine/game/sim.h"

#define REC_VERSION 1               /* commands only (see REC_VERSION_2) */
#define REC_VERSION_2 2             /* run description and per-tick hashes */
#define REC_VERSION_3 3             /* sound: settings, audio hashes */
#define REC_VERSION_MAX 3           /* newest version this build reads */
/* 2: the game: enemies, stages, modes, menu; 3: sound (channels,
 * settings) and Doom's specials (the map's changing parts, movers, keys,
 * exits: engine/game/g_world.h), which landed together; 4: the specials'
 * sounds (twelve sounds more, so twelve more lengths in the state); 5: the
 * stage clock, hurry up, the idle player and the time bonus (g_pace.c),
 * with their settings stage_time and idle_out; 6: weapons (g_weapon.c: the
 * player's weapons and the one held, SIM_BT_WEAPON, weapon pickups); 7:
 * the thrower's missiles (g_missile.c), vertical aim (the player's pitch,
 * SIM_BT_LOOK_UP/DOWN, shots as slopes, auto-aim and its setting
 * free_aim), two players alternating (g_turn.c: players, up, the waiting
 * player's seat, phase G_PH_TURN, SIM_BT_START2); 8: the grunt's wind-up
 * (its cry, one sound more), the flyer (Doom's lost soul: flies, circles
 * in), drops (g_drop.c); 9: the flyer's own four sounds (four lengths
 * more) */
#define REC_ENGINE_VERSION 9
/* sim_snapshot_size() at REC_ENGINE_VERSION. A field added to the sim's
 * state (engine/game/sim_table.h) changes the size and every state hash:
 * raise REC_ENGINE_VERSION and set this to the new size, together
 * (test_rec fails on the size until then, as a reminder of the version). */
#define REC_ENGINE_SNAPSHOT 97933
/* Bumped whenever the renderer draws any frame differently (engine/render/r_*.c,
 * textures, palette): recorded frame hashes of another renderer version
 * are not compared. 7: meshes (the lamps and keys, r_mesh.c), the grunt
 * standing until its wind-up (its aiming frame the telegraph), the flyer's
 * sprite (SKUL); 8: the brute's sprite (SARG) redrawn as a figure. */
#define REC_RENDER_VERSION 8
/* Bumped whenever the audio of any tick changes (the mixer, the built-in
 * sounds, a sound's lump): recorded audio hashes of another version are
 * not compared. 2: doors, lifts, switches and teleports sound; 3: the
 * grunt's wind-up cry; 4: the flyer's own sight, charge, pain and death. */
#define REC_AUDIO_VERSION 4
#define REC_HEADER_SIZE 40          /* version 1 */
#define REC_HEADER_SIZE_V2 80
#define REC_HEADER_SIZE_V3 104
#define REC_HEADER_MAX 104
#define REC_CMD_SIZE 6
#define REC_RECORD_MAX 30           /* command and the three hashes */
#define REC_COUNT_UNKNOWN 0xffffffffu
#define REC_HAS_STATE 0x01
#define REC_HAS_FRAME 0x02
#define REC_HAS_SNAPSHOT 0x04
#define REC_HAS_AUDIO 0x08          /* version 3 */
#define REC_AUDIO_RATE_MIN 8000     /* the mixer's (engine/sound/mix.h) */
#define REC_AUDIO_RATE_MAX 192000

struct rec_header {
	uint16_t version;
	uint16_t tick_rate;
	uint32_t header_size;      /* decode: bytes before the first command */
	uint64_t map_hash;
	uint32_t engine_version;
	struct sim_settings set;
	uint32_t count;            /* REC_COUNT_UNKNOWN while being written */
	/* Version 2 only; 0 / "" when read from version 1. */
	uint16_t render_w, render_h;
	uint8_t hash_flags;        /* REC_HAS_STATE | _FRAME | _AUDIO | _SNAPSHOT */
	uint8_t level;             /* built-in level, 0: a map from a file */
	uint32_t render_version;
	char map_name[9];
	int64_t start_time;
	/* Version 3 only; 0 when read from an older one. */
	uint32_t audio_rate;       /* Hz the audio hashes were mixed at, 0 none */
	uint32_t audio_version;
	uint64_t sound_hash;
	/* Version 2: the sim state the recording starts from (sim_snapshot),
	 * snapshot_len bytes; none when snapshot_len is 0. Writer: give both
	 * (REC_HAS_SNAPSHOT follows from snapshot_len; the bytes are copied
	 * out at open). Reader: snapshot points into the reader, valid until
	 * rec_reader_close. rec_header_decode sees only the fixed header: it
	 * fills snapshot_len and snapshot_sum, and leaves snapshot NULL. */
	const uint8_t *snapshot;
	uint32_t snapshot_len;
	uint64_t snapshot_sum;     /* FNV-1a of the snapshot's bytes (encode computes it) */
};

/* One tick as stored: the command and, where the header's hash_flags say
 * so, the hashes after the tick (0 where not stored). */
struct rec_tick {
	struct sim_cmd cmd;
	uint64_t state_hash, frame_hash, audio_hash;
};

/* Bytes of one record for these hash flags: 6, 14, 22 or 30. */
size_t rec_record_size(uint8_t hash_flags);

/* Writes h as the header of its version (h->version 1: 40 bytes, 2: 80,
 * 3: 96) into out (REC_HEADER_MAX bytes); returns the size written. The
 * header size field is that size whatever h->header_size says, plus
 * snapshot_len from version 2 on (the snapshot's bytes follow the bytes
 * written here; its checksum is computed from h->snapshot, or taken from
 * h->snapshot_sum when snapshot is NULL). */
size_t rec_header_encode(uint8_t *out, const struct rec_header *h);
/* Parses and checks a header from len bytes: 0, or -EINVAL with the reason
 * in err ("file too short (12 bytes, the header needs 40)", "bad magic",
 * "version 7 is newer than this build (2)", "header size 8 is smaller than
 * 40", "tick rate 50 is not 60", "coins_per_credit 0 out of range 1..9",
 * "difficulty 4 out of range 0..3", "lives 10 out of range 0..9",
 * "volume 101 out of range 0..100", "attract_sound 10 out of range 0..9",
 * "hash flags 0x10 unknown", "hash flags 0x08 unknown" (audio in version
 * 2), "audio rate 100 out of range 8000..192000", "render size 5000x240
 * out of range", "snapshot of 0 bytes", "snapshot of 7000 bytes does not
 * fit in header size 6700").
 * The map hash and engine version are not judged here: see rec_check. */
int rec_header_decode(const uint8_t *buf, size_t len, struct rec_header *h, char *err,
		      size_t errlen);
void rec_cmd_encode(uint8_t out[REC_CMD_SIZE], const struct sim_cmd *c);
void rec_cmd_decode(const uint8_t in[REC_CMD_SIZE], struct sim_cmd *c);

struct rec_writer;
/* Creates path (truncating, mode 0644, O_CLOEXEC) and writes the header of
 * h->version (1, 2 or 3; hash flags and a snapshot from version 2, audio
 * hashes in version 3) with
 * count REC_COUNT_UNKNOWN, then the snapshot if h->snapshot_len. 0,
 * -EINVAL for a header that could not be read back (or a snapshot_len
 * without snapshot bytes, or in version 1), or -errno. */
int rec_writer_open(const char *path, const struct rec_header *h, struct rec_writer **out);
/* Appends one command (buffered: written when about 4 KiB are pending, on
 * rec_writer_flush and on close). 0 or -errno; -EFBIG after 2^32-2
 * commands; -EINVAL if the header asks for hashes (use rec_writer_put_tick).
 * Once a write fails, every later call returns that error. */
int rec_writer_put(struct rec_writer *w, const struct sim_cmd *c);
/* Appends one tick: the command and the hashes the header's hash_flags
 * ask for (the others are ignored). Same buffering and errors as
 * rec_writer_put. */
int rec_writer_put_tick(struct rec_writer *w, const struct rec_tick *t);
/* Writes the pending commands to the file (no fsync). 0 or -errno. */
int rec_writer_flush(struct rec_writer *w);
/* Writes the final count, fsyncs and closes; NULL-safe. 0 or -errno. */
int rec_writer_close(struct rec_writer *w);

/* Finishes a recording that was cut short (count REC_COUNT_UNKNOWN: a
 * crash or power cut while recording): drops a partial last record, writes
 * the count of the whole ones, fsyncs. A finished recording is left as it
 * is. 0 with *count, -EINVAL (not a readable recording; err says why), or
 * -errno. */
int rec_repair(const char *path, uint32_t *count, char *err, size_t errlen);

struct rec_reader;
/* Opens and checks a recording; 0 or -errno / -EINVAL with reason in err
 * ("FILE: bad magic", "FILE: version 7 is newer than this build (2)").
 * A snapshot is read and checked at open ("FILE: snapshot cut short (100
 * of 96542 bytes)", "FILE: snapshot damaged (checksum 0x..., the header
 * says 0x...)"); rec_reader_header(r)->snapshot then holds it. Whether
 * it suits this build and content is sim_restore's to say. */
int rec_reader_open(const char *path, struct rec_reader **out, char *err, size_t errlen);
const struct rec_header *rec_reader_header(const struct rec_reader *r);
/* How many records rec_reader_next returns in all. */
uint32_t rec_reader_count(const struct rec_reader *r);
/* 1 and *c filled, 0 at the end, -errno on a read error; -EIO at the end
 * of a finished recording that holds fewer records than its count. */
int rec_reader_next(struct rec_reader *r, struct sim_cmd *c);
/* As rec_reader_next, with the stored hashes (0 where not stored). */
int rec_reader_next_tick(struct rec_reader *r, struct rec_tick *t);
/* NULL-safe. */
void rec_reader_close(struct rec_reader *r);

/* Compares a recording's header with what this run plays: 0 if it may be
 * replayed, else -EINVAL and a message naming each difference, joined by
 * "; " ("map content differs: recording 0x..., loaded 0x...; engine
 * version differs: recording 2, this build 1"). */
int rec_check(const struct rec_header *h, uint64_t map_hash, char *err, size_t errlen);

/* What a replay actually runs, to compare with a recording's header. */
struct rec_run {
	uint64_t map_hash;             /* content hash of the loaded map */
	struct sim_settings set;       /* the sim's settings */
	uint16_t render_w, render_h;   /* frame size drawn (0: not rendering) */
	uint8_t level;                 /* built-in level, 0: a map from a file */
	const char *map_name;          /* for a map from a file; NULL or "" */
	uint32_t audio_rate;           /* Hz mixed at (0: not mixing) */
	uint64_t sound_hash;           /* snd_set.hash of the sounds loaded */
};

/* rec_check for everything a replay depends on: the map content, engine
 * version and settings always; the level (or map name) when the recording
 * names one; when the recording holds frame hashes and run renders, the
 * render size and renderer version; when it holds audio hashes and run
 * mixes, the audio rate, audio version and sounds. 0 if the recording
 * replays here and its hashes can be compared, else -EINVAL and every
 * difference joined by "; " ("settings differ: coins_per_credit recording
 * 2, this run 1"; "render size differs: recording 320x240, this run
 * 640x480"; "renderer version differs: recording 1, this build 2"; "level
 * differs: recording 2, loaded 1"; "audio rate differs: recording 48000,
 * this run 44100"; "audio version differs: recording 1, this build 2";
 * "sounds differ: recording 0x..., loaded 0x..."). A caller that takes the
 * settings, level, size and rate from the recording (as it should:
 * rec_run_from_header) is refused only for what it cannot change: content
 * and versions. */
int rec_check_run(const struct rec_header *h, const struct rec_run *run, char *err,
		  size_t errlen);

/* The run a recording asks for: its settings, level, map name, render
 * size (0x0 for version 1, which does not store one: keep the default) and
 * audio rate (0 before version 3: keep the default).
 * map_hash is left 0: the caller loads the map and fills it in. The
 * map_name pointer points into h. */
void rec_run_from_header(const struct rec_header *h, struct rec_run *run);

/* Verification of a replay against the hashes stored in a recording
 * (--verify). A plain value; fill with rec_verify_init. */
struct rec_verify {
	uint8_t compare;               /* REC_HAS_* this replay compares */
	uint32_t ticks;                /* ticks seen */
	uint32_t state_checked, frame_checked, audio_checked;
	uint32_t state_bad, frame_bad, audio_bad;
	int64_t first_bad;             /* tick of the first difference, -1 none */
	char first[192];               /* what differed there */
	char note[192];                /* why something is not compared, or "" */
};

/* Prepares v for a replay of a recording with header h by run (run
 * render_w 0: no rendering). Frame hashes are compared only when the
 * recording holds them, run renders at the recorded size, and the renderer
 * version is this build's; audio hashes only when the recording holds
 * them, run mixes at the recorded rate with the recorded sounds, and the
 * audio version is this build's; otherwise v->note says why not. */
void rec_verify_init(struct rec_verify *v, const struct rec_header *h, const struct rec_run *run);

/* Compares tick `tick`'s stored hashes (rec, from rec_reader_next_tick)
 * with the replay's (run: after sim_tick, the mixing and r_render of that
 * tick; the hashes not compared are ignored). 0 if equal, -EDOM if not
 * (the first difference is kept in v->first_bad and v->first). */
int rec_verify_tick(struct rec_verify *v, uint32_t tick, const struct rec_tick *rec,
		    const struct rec_tick *run);

/* One line: "verify: 800 ticks, 800 state, 800 frame and 800 audio hashes
 * equal" or "verify: FAILED: first difference at tick 17: state hash
 * recording 0x..., replay 0x...; 3 state, 0 frame and 0 audio hashes
 * differ of 800 ticks", with the note appended. Returns 0 if everything compared was equal and
 * something was compared, 1 if nothing could be compared (no hashes
 * stored), -EDOM on a difference. */
int rec_verify_summary(const struct rec_verify *v, char *buf, size_t len);

#endif
