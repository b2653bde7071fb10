/*
 * lvl_builtin: the levels compiled into the daemon (map.h: lvl_builtin).
 *
 * They are real maps in Doom's format: levels/arena1.txt .. arena8.txt
 * describe them (geometry, the built-in set's texture and flat names,
 * things), tools/mklevels writes them as one PWAD and that PWAD as C
 * (engine/map/lvl_wad.c), and this file loads it through the same loaders as
 * any WAD (wad_add, map_load_wad), resolving names against tex_builtin's
 * set; the node builder makes the BSP. docs/maps.md, "The built-in
 * levels", says how to change and regenerate them.
 *
 * Level i is the i-th map in the PWAD (ARENA1 .. ARENA8), the order
 * the game plays them: rising difficulty.
 */
#include "engine/map/lvl_builtin.h"

#include <errno.h>
#include <stddef.h>

#include "engine/map/lvl_wad.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"

#define LVL_MAX 16

/* The embedded PWAD as a WAD set, and the names of its maps (up to
 * LVL_MAX). Returns the number of maps, or a negative errno. */
static int lvl_open(struct wad **w, char (*names)[9])
{
	int r = wad_new(w);

	if (r)
		return r;
	r = wad_add(*w, lvl_wad, lvl_wad_len, "built-in levels", NULL, 0);
	if (r) {
		wad_free(*w);
		*w = NULL;
		return r;
	}
	r = map_list_wad(*w, names, LVL_MAX);
	return r > LVL_MAX ? LVL_MAX : r;
}

int lvl_builtin_count(void)
{
	char names[LVL_MAX][9];
	struct wad *w;
	int n = lvl_open(&w, names);

	wad_free(w);
	return n < 0 ? 0 : n;
}

int lvl_builtin_for(int i, const struct tex_set *t, struct map **out)
{
	char names[LVL_MAX][9];
	struct wad *w;
	int n, r;

	*out = NULL;
	n = lvl_open(&w, names);
	if (n < 0)
		return n;
	r = i < 0 || i >= n ? -EINVAL : 0;
	/* the levels are the project's own: an error or a name the built-in
	 * set lacks is a bug the unit tests catch, reported as a bad map */
	if (!r)
		r = map_load_wad(w, t, names[i], out, NULL, 0);
	if (!r && (*out)->missing_textures) {
		map_free(*out);
		*out = NULL;
		r = -EINVAL;
	}
	if (r < 0 && r != -ENOMEM)
		r = -EINVAL;
	wad_free(w);
	return r;
}

int lvl_builtin(int i, struct map **out)
{
	struct tex_set *t = NULL;
	int r;

	*out = NULL;
	if (i < 0 || i >= lvl_builtin_count())
		return -EINVAL;
	r = tex_builtin(&t);
	if (!r)
		r = lvl_builtin_for(i, t, out);
	tex_free(t);
	return r;
}
