/* libFuzzer target: the grid map parser (engine/map/grid.c). Any bytes must
 * import or fail with a message; an imported map must be finished (a BSP
 * whose point location works) with exactly one player start, and its
 * light maps must build. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/map/grid.h"
#include "engine/map/lmap.h"
#include "engine/map/map.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

/* Any name is a texture: its length, so the seeds with names import. */
static int fuzz_name(void *ctx, const char *name)
{
	(void)ctx;
	return (int)strlen(name);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	struct map *m = NULL;
	struct lmap *lm = NULL;
	struct lmap_light lights[8];
	struct grid_names names = { NULL, fuzz_name, fuzz_name };
	char err[256];
	int players = 0, n;

	if (len > 4096)
		return 0;                      /* 64x64 maps are enough to find bugs */
	if (grid_parse((const char *)data, len, "fuzz", &names, &m, err, sizeof err) != 0) {
		if (m || err[0] == '\0')
			abort();
		return 0;
	}
	for (uint32_t i = 0; i < m->num_things; i++) {
		players += m->things[i].type == 1;
		if (map_point_sector(m, m->things[i].x, m->things[i].y) >= m->num_sectors)
			abort();
	}
	if (players != 1)
		abort();
	n = lmap_lights_from_map(m, LMAP_DECOR, lights, 8);
	if (lmap_new(m, lights, n < 8 ? n : 8, &lm) != 0)
		abort();
	lmap_free(lm);
	map_free(m);
	return 0;
}
