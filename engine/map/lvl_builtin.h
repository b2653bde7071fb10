/*
 * lvl_builtin: the game's own levels (lvl_builtin.c).
 */
#ifndef ARCADED_ENGINE_LVL_BUILTIN_H
#define ARCADED_ENGINE_LVL_BUILTIN_H

struct map;
struct tex_set;

/* Number of built-in levels, and a newly allocated, finished copy of level i
 * (0-based; ARENA1, ARENA2, ARENA3, the order the game plays them).
 * Returns 0, -EINVAL for a bad index, or -ENOMEM.
 *
 * Contract for drawing them: their texture and flat numbers are indices
 * into the set tex_builtin() returns, which numbers the same on every call
 * and every build; draw a built-in level with such a set. They are loaded
 * from the compiled-in PWAD (engine/map/lvl_wad.c, made by tools/mklevels from
 * levels/arena*.txt) by map_load_wad against a set made and freed inside
 * the call (about 10 ms at -O2), with the BSP from the node builder. */
int lvl_builtin_count(void);
int lvl_builtin(int i, struct map **out);

/* Level i as lvl_builtin makes it, its names resolved against t, which
 * must be a set tex_builtin made (the caller keeps it). What a caller
 * loading several levels uses: one set for all of them, not one each
 * (the app's eight levels took 80 ms that way before their first frame). */
int lvl_builtin_for(int i, const struct tex_set *t, struct map **out);

#endif
