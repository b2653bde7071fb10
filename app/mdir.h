/*
 * mdir: the mesh directory ([game] meshes): OBJ files named by the Doom
 * thing type they draw, read at start-up so that a level designer or an
 * operator adds or replaces a prop's or pickup's mesh without rebuilding
 * (docs/maps.md, "Meshes from a directory").
 *
 * The directory's entries, in name order (hidden files skipped, not its
 * subdirectories):
 *  - `NNNN.obj` (1 to 5 digits, a type 1..65535; ".obj" in any case) is
 *    the mesh of thing type NNNN, parsed by the engine's reader (mesh_parse,
 *    its subset and limits); a line `# arcaded colour RRGGBB` (hex) gives its
 *    colour, else the type's built-in mesh colour (r_game_mesh_colour),
 *    else grey 160 160 160;
 *  - a type that is no prop or pickup (unknown to th_find, a monster or a
 *    player start: the game draws only props and pickups as meshes), a
 *    second file for one type ("12.obj" after "0012.obj"), a file past
 *    MESH_SET_MAX, or any other name is ignored with a note;
 *  - a file that is not a regular file, larger than MDIR_FILE_MAX, not
 *    read whole, or refused by mesh_parse ("NAME:LINE: reason") is refused
 *    with a note: its type keeps its built-in picture.
 * Nothing here logs: every note goes to the caller's function (the daemon
 * journals them). Blocks on file I/O (one read a file).
 *
 * What is loaded changes frames, not the game's state: the recordings'
 * frame hashes hold only with the same meshes. mdir.hash identifies them
 * (the daemon logs it); a replay must be run with the same directory.
 */
#ifndef ARCADED_APP_MDIR_H
#define ARCADED_APP_MDIR_H

#include <stdint.h>

#include "engine/map/mesh.h"

#define MDIR_FILE_MAX (1u << 20)   /* larger files are refused unread */

/* A note about one entry: bad 1 for a refused file (the type keeps its
 * built-in picture), 0 for an ignored name; msg says which and why
 * ("0005.obj:12: bad number ..."). */
typedef void (*mdir_note_fn)(void *user, int bad, const char *msg);

struct mdir {
	struct mesh_thing *v;      /* owned: the loaded meshes, by name order */
	uint32_t n;
	struct mesh_set set;       /* { v, n }: what the view borrows */
	uint32_t nbad, nignored;   /* files refused, names ignored */
	/* FNV-1a from HASH_INIT over each loaded mesh's type (u16), colour
	 * (three u8) and file bytes, in name order: HASH_INIT when none */
	uint64_t hash;
};

/* Loads dir's meshes into *d (emptied first). dir NULL or "": none.
 * Returns how many were loaded (>= 0), -ENOENT/-ENOTDIR/-EACCES... when
 * the directory cannot be opened (nothing loaded; noted as well), or
 * -ENOMEM. fn may be NULL. */
int mdir_load(struct mdir *d, const char *dir, mdir_note_fn fn, void *user);

/* Frees d's meshes; NULL-safe; leaves *d empty. */
void mdir_free(struct mdir *d);

#endif
