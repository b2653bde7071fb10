/*
 * rec: the recording format: one sim_cmd per tick after a versioned header.
 *
 * Layout (all integers little-endian, explicit offsets, never struct dumps):
 *   0  8  magic "ARCDREC\0"
 *   8  2  format version (REC_VERSION)
 *  10  2  tick rate (60)
 *  12  4  header size in bytes (REC_HEADER_SIZE for version 1)
 *  16  8  content hash of the map (map.content_hash)
 *  24  4  engine version (REC_ENGINE_VERSION: bumped when the sim changes)
 *  28  1  coins_per_credit   29 1 freeplay   30 1 start_in_play   31 1 reserved 0
 *  32  4  number of commands, or 0xffffffff if the writer did not finish
 *  36  4  reserved 0
 *  40  ... commands, REC_CMD_SIZE bytes each:
 *        int8 forward, int8 side, int16 turn, uint8 buttons, uint8 coins
 * The writer puts 0xffffffff in the count and writes the real count only
 * when it closes, so a recording cut short (power loss, crash) is
 * recognisable and replays up to its last whole command. A finished
 * recording (count known) that holds fewer commands than its count was
 * damaged afterwards: its whole commands replay, then the reader reports
 * -EIO. Bytes after the counted commands, and a partial last command, are
 * ignored. A header larger than REC_HEADER_SIZE (a later minor addition)
 * is skipped.
 */
#ifndef ARCADED_INPUT_REC_H
#define ARCADED_INPUT_REC_H

#include <stddef.h>
#include <stdint.h>

#include "engine/sim.h"

#define REC_VERSION 1
#define REC_ENGINE_VERSION 1
#define REC_HEADER_SIZE 40
#define REC_CMD_SIZE 6
#define REC_COUNT_UNKNOWN 0xffffffffu

struct rec_header {
	uint16_t version;
	uint16_t tick_rate;
	uint32_t header_size;      /* decode: bytes before the first command */
	uint64_t map_hash;
	uint32_t engine_version;
	struct sim_settings set;
	uint32_t count;            /* REC_COUNT_UNKNOWN while being written */
};

/* Writes h as the 40-byte header (header size REC_HEADER_SIZE whatever
 * h->header_size says). */
void rec_header_encode(uint8_t out[REC_HEADER_SIZE], const struct rec_header *h);
/* Parses and checks a header from len bytes: 0, or -EINVAL with the reason
 * in err ("file too short (12 bytes, the header needs 40)", "bad magic",
 * "version 7 is newer than this build (1)", "header size 8 is smaller than
 * 40", "tick rate 50 is not 60", "coins_per_credit 0 out of range 1..9").
 * The map hash and engine version are not judged here: see rec_check. */
int rec_header_decode(const uint8_t *buf, size_t len, struct rec_header *h, char *err,
		      size_t errlen);
void rec_cmd_encode(uint8_t out[REC_CMD_SIZE], const struct sim_cmd *c);
void rec_cmd_decode(const uint8_t in[REC_CMD_SIZE], struct sim_cmd *c);

struct rec_writer;
/* Creates path (truncating, mode 0644, O_CLOEXEC) and writes the header
 * with count REC_COUNT_UNKNOWN. 0 or -errno. */
int rec_writer_open(const char *path, const struct rec_header *h, struct rec_writer **out);
/* Appends one command (buffered: written when about 4 KiB are pending, on
 * rec_writer_flush and on close). 0 or -errno; -EFBIG after 2^32-2
 * commands. Once a write fails, every later call returns that error. */
int rec_writer_put(struct rec_writer *w, const struct sim_cmd *c);
/* Writes the pending commands to the file (no fsync). 0 or -errno. */
int rec_writer_flush(struct rec_writer *w);
/* Writes the final count, fsyncs and closes; NULL-safe. 0 or -errno. */
int rec_writer_close(struct rec_writer *w);

struct rec_reader;
/* Opens and checks a recording; 0 or -errno / -EINVAL with reason in err
 * ("FILE: bad magic", "FILE: version 7 is newer than this build (1)"). */
int rec_reader_open(const char *path, struct rec_reader **out, char *err, size_t errlen);
const struct rec_header *rec_reader_header(const struct rec_reader *r);
/* How many commands rec_reader_next returns in all. */
uint32_t rec_reader_count(const struct rec_reader *r);
/* 1 and *c filled, 0 at the end, -errno on a read error; -EIO at the end
 * of a finished recording that holds fewer commands than its count. */
int rec_reader_next(struct rec_reader *r, struct sim_cmd *c);
/* NULL-safe. */
void rec_reader_close(struct rec_reader *r);

/* Compares a recording's header with what this run plays: 0 if it may be
 * replayed, else -EINVAL and a message naming each difference, joined by
 * "; " ("map content differs: recording 0x..., loaded 0x...; engine
 * version differs: recording 2, this build 1"). */
int rec_check(const struct rec_header *h, uint64_t map_hash, char *err, size_t errlen);

#endif
