/*
 * pspec: what a Doom-format map's specials are and which the game plays
 * (issue 15 item 7), from the engine's census (engine/game/g_world.h:
 * g_census). `arcaded --wad FILE [--map NAME] --print-specials` prints
 * them; at load the daemon logs the specials it does not play.
 */
#ifndef ARCADED_APP_PSPEC_H
#define ARCADED_APP_PSPEC_H

#include <stddef.h>
#include <stdio.h>

struct map;

/* --print-specials: loads the WADs wads[0..nwads-1] (IWAD first, later
 * ones override) and prints to out, for map `map` (NULL or "all": every
 * map of the WADs, in lump order), each special type used with its count
 * and the game's description, "UNSUPPORTED" for the ones it does not play,
 * then the map's supported share of special lines and special sectors
 * (counted over lines/sectors and over types). With more than one map a
 * closing summary gives the shares over all of them and every unsupported
 * type with its count and maps. 0; or 2 after logging the error (the
 * file, map and lump) when a WAD or a map cannot be loaded. */
int pspec_print(const char *const *wads, int nwads, const char *map, FILE *out);

/* The load-time note of map m's unplayed specials, into out: "map E1M1:
 * unsupported specials: line 24576 x2, sector 256 x1" (types in order,
 * lines first); 1 when there are any, 0 (out "") when the game plays
 * every special of m or out could not be filled (no memory). */
int pspec_unplayed(const struct map *m, char *out, size_t len);

/* The load-time note of a map with more enemies or pickups at difficulty
 * (0..3) than the game keeps (G_MAX_ENEMIES, G_MAX_PICKUPS; the first in
 * the map's order stay): "map E1M3: 48 enemies and 164 pickups at
 * difficulty 0; the game keeps ...". 1 when there are more, 0 (out "")
 * when not. */
int pspec_crowded(const struct map *m, int difficulty, char *out, size_t len);

#endif
