/*
 * fr: the flight recorder: the recordings of the last games, kept in a
 * directory (the state directory's recordings/), so a bug seen on a
 * cabinet can be replayed on a desk (`arcaded replay FILE`).
 *
 * Files: game-SEQ-TIME.rec, SEQ a 6-digit (or longer) sequence number that
 * only grows, TIME the UTC start time as YYYYMMDDTHHMMSSZ, e.g.
 * game-000042-20261121T120301Z.rec. A game being recorded is
 * game-SEQ-TIME.rec.part; at its end fr_end_game renames it (atomic, then
 * the directory is fsynced). A .part found by fr_open was cut by a crash or
 * a power cut: its whole records are kept (rec_repair) and it becomes
 * game-SEQ-TIME-cut.rec. At most `keep` recordings and `cap` bytes are
 * kept: the oldest go first (the newest one always stays, even alone above
 * the cap). Other files in the directory are left alone.
 *
 * Not thread-safe; one fr per directory (one daemon). Blocks on disk I/O.
 * No logging: what fr_open recovered or removed is reported in its message.
 */
#ifndef ARCADED_CONFIG_FR_H
#define ARCADED_CONFIG_FR_H

#include <stddef.h>
#include <stdint.h>
#include <time.h>

#define FR_NAME_MAX 64                /* longest file name fr makes, with NUL */
#define FR_KEEP_MAX 1000

struct fr;

struct fr_entry {
	char name[FR_NAME_MAX];       /* file name in the directory */
	uint64_t seq;
	uint64_t size;                /* bytes */
	int cut;                      /* 1: recovered after a crash or power cut */
};

/* Opens the recorder on dir (created, mode 0755, if missing; its parent
 * must exist), keeping at most keep (1..FR_KEEP_MAX) recordings and cap
 * bytes (0: no byte cap). Repairs and renames .part files left by a cut,
 * then prunes. msg (may be NULL) says what was done, e.g. "recovered
 * game-000007-20261121T120301Z-cut.rec (3456 ticks); removed 2 old
 * recordings", or "". Returns 0 or -errno (-EINVAL for a bad keep). */
int fr_open(const char *dir, int keep, uint64_t cap, struct fr **out, char *msg, size_t msglen);

/* NULL-safe. A game still being recorded stays a .part (as after a cut):
 * call fr_end_game first. */
void fr_close(struct fr *f);

/* Starts a game at wall-clock time now: writes into path (pathlen bytes)
 * the .part file to record to (with rec_writer_open). 0, -ENAMETOOLONG,
 * or -EBUSY when a game is already being recorded. */
int fr_begin_game(struct fr *f, time_t now, char *path, size_t pathlen);

/* Ends the game begun last; the recording must be closed already
 * (rec_writer_close has fsynced it). keep_it 0 deletes it (a game not worth
 * keeping, or a recording that failed); else it is renamed to .rec, the
 * directory fsynced, and the oldest recordings pruned to the limits. 0 or
 * -errno (-ENOENT without a game begun). */
int fr_end_game(struct fr *f, int keep_it);

/* The finished recordings, oldest first: fills up to max entries of out
 * (out may be NULL when max is 0) and returns how many there are, or
 * -errno. */
int fr_list(struct fr *f, struct fr_entry *out, int max);

/* The directory (as given to fr_open). */
const char *fr_dir(const struct fr *f);

#endif
