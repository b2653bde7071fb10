/*
 * st: state files that survive power cuts (scores, counters, operator
 * settings written by the cabinet).
 *
 * A state file is a 24-byte header and the payload (little-endian):
 *    0  8  magic "ARCDSTA\0"
 *    8  2  format version (ST_VERSION)
 *   10  2  header size (ST_HEADER_SIZE)
 *   12  4  payload length in bytes (at most ST_MAX_LEN)
 *   16  4  CRC-32 (IEEE 802.3, as zlib's crc32) of the payload
 *   20  4  CRC-32 of bytes 0..19
 *   24  .. payload
 *
 * st_save writes DIR/NAME.tmp, fsyncs it, keeps the current DIR/NAME as
 * DIR/NAME.prev when (and only when) the current file is valid, renames
 * the .tmp over DIR/NAME and fsyncs the directory. At every instant, even
 * if the process is killed or the power fails mid-save, DIR/NAME or
 * DIR/NAME.prev holds a complete, checksummed copy of the last saved or
 * the one before; st_load finds it.
 *
 * A copy whose checksums hold may still be unusable: its payload is in a
 * format this build cannot decode (a newer format byte, say). The _usable
 * variants take the caller's check of the payload; a copy that fails it is
 * a bad copy like a corrupt one: st_load_usable goes on to .prev, and
 * st_save_usable never rotates it into .prev (that would push the last
 * good copy out).
 *
 * st_write_plain is the same write-fsync-rename-fsync sequence for a plain
 * file without the header (one copy, no .prev).
 *
 * Nothing here logs or keeps state; the functions block on disk I/O.
 */
#ifndef ARCADED_CONFIG_ST_H
#define ARCADED_CONFIG_ST_H

#include <stddef.h>
#include <stdint.h>

#define ST_VERSION 1
#define ST_HEADER_SIZE 24
#define ST_MAX_LEN (16u << 20)   /* payload limit: 16 MiB */
#define ST_NAME_MAX 200          /* longest NAME (without .prev / .tmp) */

/* Which copy st_load returned. */
enum st_which {
	ST_MAIN,                 /* DIR/NAME */
	ST_PREV,                 /* DIR/NAME.prev: NAME was missing or corrupt */
};

/* A caller's check of a payload whose checksums hold: 0 when this build
 * can use it, a negative errno when it cannot decode it. */
typedef int (*st_usable_fn)(const void *payload, size_t len);

/* Saves len bytes of data (len <= ST_MAX_LEN) as DIR/NAME, power-cut safe
 * as described above. NAME is a plain file name (no '/', not "." or "..",
 * at most ST_NAME_MAX bytes). Returns 0 once the new file and the
 * directory entry are on disk, or -errno: -EINVAL (bad name or length),
 * -ENOENT (no DIR), -ENOSPC / -EIO / -EFBIG / -EDQUOT (the write or fsync
 * failed: the .tmp is removed and DIR/NAME and DIR/NAME.prev are as they
 * were). */
int st_save(const char *dir, const char *name, const void *data, size_t len);

/* st_save, but the current DIR/NAME is kept as DIR/NAME.prev only when it
 * also passes usable (NULL: st_save). */
int st_save_usable(const char *dir, const char *name, st_usable_fn usable, const void *data,
		   size_t len);

/* Writes len bytes of data (len <= ST_MAX_LEN) as the plain file DIR/NAME
 * (no header: text other programs read, like STATE_DIR/bindings.ini),
 * atomically: DIR/NAME.tmp is written and fsynced, renamed over DIR/NAME,
 * then DIR is fsynced. Whenever the process dies or the power fails,
 * DIR/NAME is the whole old file or the whole new one (no .prev is kept:
 * the rename alone guarantees that). NAME as for st_save. Returns 0 once
 * the file and its directory entry are on disk, or -errno: -EINVAL (bad
 * name or length), -ENOENT (no DIR), -ENOTDIR, -EACCES, or the write,
 * fsync or rename error (the .tmp is removed; DIR/NAME is as it was). */
int st_write_plain(const char *dir, const char *name, const void *data, size_t len);

/* Loads DIR/NAME, or DIR/NAME.prev when NAME is missing or fails its
 * checks (magic, version, sizes, both CRCs). On success returns 0, *buf
 * (malloc'd, owned by the caller, never NULL even for an empty payload),
 * *len and *which; when the .prev copy was used, msg says why, e.g.
 * "NAME: payload checksum mismatch; loaded NAME.prev", else msg is "".
 * Errors: -ENOENT (neither file exists), -EBADMSG (what exists is corrupt;
 * msg names each problem), -ENOMEM, or another -errno from reading. msg
 * may be NULL; which may be NULL. */
int st_load(const char *dir, const char *name, void **buf, size_t *len, enum st_which *which,
	    char *msg, size_t msglen);

/* st_load, where a copy whose payload fails usable (NULL: st_load) is bad
 * too: the reason given is "payload not usable by this version". */
int st_load_usable(const char *dir, const char *name, st_usable_fn usable, void **buf,
		   size_t *len, enum st_which *which, char *msg, size_t msglen);

/* Checks a whole state file image of n bytes: 0 with the payload's offset
 * and length, or -EBADMSG with the reason in why ("too short (10 bytes)",
 * "bad magic", "version 3 not supported", "header checksum mismatch",
 * "length 99 does not match the file (50 bytes of payload)", "payload
 * checksum mismatch"). Pure; for tests and tools. */
int st_check(const uint8_t *img, size_t n, size_t *payload_len, char *why, size_t whylen);

/* Builds the header for a payload of len bytes (len <= ST_MAX_LEN). */
void st_header(uint8_t out[ST_HEADER_SIZE], const void *payload, size_t len);

/* CRC-32 (reflected, polynomial 0xEDB88320, initial and final xor
 * 0xffffffff): st_crc32(0, "123456789", 9) == 0xCBF43926. Chainable:
 * pass the previous result as crc. */
uint32_t st_crc32(uint32_t crc, const void *p, size_t n);

#endif
