/* libFuzzer target: the WAD reader, the texture loader and the map loader
 * (engine/map/wad.c, tex*.c, map_wad.c). Any bytes are added as a WAD; if they
 * load, their textures load (or the built-in set stands in) and every map
 * they list loads or fails with a message. A loaded map must be finished:
 * point location from a few points ends in a subsector of a valid sector,
 * and every side's texture index is within the set. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

static void check_map(const struct map *m, const struct tex_set *t)
{
	static const fx_t pts[4][2] = {
		{ 0, 0 }, { 64 * FX_ONE, 64 * FX_ONE }, { -MAP_COORD_MAX, MAP_COORD_MAX },
		{ 12345 * FX_ONE, -321 * FX_ONE },
	};

	for (int i = 0; i < 4; i++) {
		uint32_t ss = map_point_subsector(m, pts[i][0], pts[i][1]);
		if (ss >= m->num_subsectors || m->subsectors[ss].sector >= m->num_sectors)
			abort();
	}
	for (uint32_t i = 0; i < m->num_sides; i++)
		if (m->sides[i].top_tex >= t->num_textures || m->sides[i].mid_tex >= t->num_textures ||
		    m->sides[i].bot_tex >= t->num_textures)
			abort();
	for (uint32_t i = 0; i < m->num_sectors; i++)
		if (m->sectors[i].floor_tex >= t->num_flats || m->sectors[i].ceil_tex >= t->num_flats)
			abort();
}

/* The built-in set stands in for WADs without graphics; made once (it takes
 * milliseconds) and never changed but by tex_animate, which is a pure
 * function of the tick. */
static struct tex_set *builtin;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	struct wad *w = NULL;
	struct tex_set *t = NULL, *own = NULL;
	char err[256], names[16][9];
	uint8_t *copy = malloc(len ? len : 1);
	int n;

	/* an exact-size copy, so a read past the image is caught */
	if (!copy || wad_new(&w)) {
		free(copy);
		return 0;
	}
	memcpy(copy, data, len);
	if (wad_add(w, copy, len, "fuzz.wad", err, sizeof err) == 0) {
		if (tex_load_wad(w, &own, err, sizeof err) == 0) {
			t = own;
		} else {
			if (!builtin && tex_builtin(&builtin) != 0)
				goto out;
			t = builtin;
		}
		tex_animate(t, 12345);
		n = map_list_wad(w, names, 16);
		for (int i = 0; i < n && i < 16; i++) {
			struct map *m;

			if (map_load_wad(w, t, names[i], &m, err, sizeof err) == 0) {
				check_map(m, t);
				map_free(m);
			}
		}
	}
out:
	tex_free(own);
	wad_free(w);
	free(copy);
	return 0;
}
