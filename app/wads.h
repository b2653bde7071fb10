/*
 * wads: the WADs of the content directories ([game] content_dirs), for
 * the service menu's content picker (app/pick.h). A fact of the machine,
 * not of the game: what this finds never enters the sim state or a
 * recording.
 *
 * A directory's entries whose names end in ".wad" (any case; not in
 * subdirectories; hidden files skipped) are checked, in name order:
 *  - a regular file (a directory, FIFO or device named .wad is refused
 *    without being read: opening a FIFO would block the main loop);
 *  - the 12-byte header: "IWAD" or "PWAD", a lump count of 0..WADS_LUMPS_MAX
 *    and a directory (16 bytes a lump) inside the file;
 *  - the maps: the directory's map markers, ExMy or MAPxx (the names the
 *    game's maps list takes), in the directory's order; a WAD without one
 *    is refused (nothing to play).
 * Lumps are not read: whether the maps load is ct_load's business when the
 * choice is applied (it falls back to the built-in levels and says why).
 * Every refused file is reported with its path and the reason; nothing
 * here logs.
 *
 * Blocks on file I/O: a few reads a file (header and directory).
 */
#ifndef ARCADED_APP_WADS_H
#define ARCADED_APP_WADS_H

#include <stddef.h>

#include "config/cfg.h"

#define WADS_MAX 32             /* packs kept (more: reported and skipped) */
#define WADS_MAPS 64            /* maps kept a pack (more: the first ones) */
#define WADS_LUMPS_MAX 65536    /* a larger lump count is refused */

struct wads_pack {
	char path[CFG_PATH_MAX];    /* "/usr/share/games/doom/freedoom1.wad" */
	int iwad;                   /* 1 IWAD, 0 PWAD */
	int nmaps;
	char maps[WADS_MAPS][9];    /* "E1M1" ..., upper case, in directory order */
};

#define WADS_BAD 8              /* refused files kept for the screen */

struct wads {
	int n;
	struct wads_pack pack[WADS_MAX];
	int nbad;                   /* refused files, all counted */
	char bad[WADS_BAD][96];     /* the first ones: "trunc.wad: truncated: ..." */
};

/* Receives one refused file: its path and why ("not a WAD (magic
 * \"PK\\3\\4\")", "truncated: directory at 1000 + 16 x 20 bytes, file 512
 * bytes", "not a regular file", "no maps", or open's error). Valid during
 * the call only. */
typedef void (*wads_err_fn)(void *user, const char *path, const char *why);

/* Checks one file (as described above) into *p. 0, or -errno with why
 * (len bytes): -EINVAL not a regular file, -EBADMSG not a WAD or
 * truncated or no maps, -ENAMETOOLONG, or open's / read's error. */
int wads_check(const char *path, struct wads_pack *p, char *why, size_t len);

/* Fills w from every directory of dirs (blank-separated; a missing one is
 * not an error, an unreadable one is reported with its reason), each
 * directory's WADs in name order. Refused files go to fn (may be NULL) and
 * are counted in nbad, the first WADS_BAD kept in bad (file name and why).
 * Returns the number of packs found. */
int wads_scan(struct wads *w, const char *dirs, wads_err_fn fn, void *user);

/* The file name of p's path (after the last '/'). */
const char *wads_name(const struct wads_pack *p);

#endif
