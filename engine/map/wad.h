/*
 * wad: WAD files (IWAD and PWAD) held in memory, layered.
 *
 * The engine does no I/O: the caller reads each file into memory and adds
 * it; later files override earlier lumps of the same name (as Doom's -file
 * does). Every directory entry is checked against the file's size when it
 * is added, so lookups never read out of bounds.
 *
 * Layout (little-endian): 12-byte header "IWAD"/"PWAD", int32 number of
 * lumps, int32 directory offset; directory entries of 16 bytes: int32
 * offset, int32 size, 8-byte name padded with NULs.
 */
#ifndef ARCADED_ENGINE_WAD_H
#define ARCADED_ENGINE_WAD_H

#include <stddef.h>
#include <stdint.h>

struct wad;

/* A new, empty set. 0 or -ENOMEM. Owned by the caller: wad_free. */
int wad_new(struct wad **out);

/* Lumps in all files of a set: Freedoom 2 has 3,649; the bound keeps a
 * directory that claims millions of entries from taking the memory and
 * time of one (issue 13 item 8). */
#define WAD_MAX_LUMPS (1 << 18)

/* Adds one WAD image. data must stay valid and unchanged until wad_free
 * (borrowed). name is for messages (a file name). Returns 0, or -EINVAL
 * with err naming the file and the problem ("doom.wad: lump 12 (E1M1)
 * ends at 9000, past the end of the file (8000)"), -E2BIG past
 * WAD_MAX_LUMPS (err names the file and the limit), or -ENOMEM. */
int wad_add(struct wad *w, const uint8_t *data, size_t len, const char *name, char *err,
	    size_t errlen);

/* Number of lumps over all files (later files after earlier ones). */
int wad_count(const struct wad *w);

/* Index of the last lump called name (case-insensitive; a name of more
 * than 8 chars matches nothing), or -1. O(log n). */
int wad_find(const struct wad *w, const char *name);

/* Index of the first lump called name at or after index from, or -1 (for
 * the lumps that follow a map marker, and F_START/F_END ranges).
 * O(log n). */
int wad_find_from(const struct wad *w, const char *name, int from);

/* Lump data and size; NULL and 0 for a bad index. */
const uint8_t *wad_data(const struct wad *w, int i, size_t *len);

/* Lump name, NUL-terminated, upper case; "" for a bad index. */
const char *wad_name(const struct wad *w, int i);

/* Name of the file lump i came from ("" for a bad index); lumps of one
 * file return the same pointer. */
const char *wad_file(const struct wad *w, int i);

void wad_free(struct wad *w);

#endif
