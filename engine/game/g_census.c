/*
 * g_census: which line and sector special types a map uses, how often, and
 * whether the game plays each (g_line_special, g_sector_special). For the
 * tools and the log (app/: --print-specials, the load-time note of what is
 * not played); the game itself never calls it.
 */
#include <errno.h>
#include <stddef.h>
#include <string.h>

#include "engine/game/g_world.h"
#include "engine/map/map.h"

/* Adds one use of (sector, type) to the n entries of out, kept in order
 * (line specials first, then by type). The new n, or -E2BIG when a new
 * type would be entry max + 1. */
static int g_census_add(struct g_spec_use *out, int n, int max, uint8_t sector, uint16_t type)
{
	uint32_t key = (uint32_t)sector << 16 | type;
	int lo = 0, hi = n;

	while (lo < hi) {
		int mid = lo + (hi - lo) / 2;
		uint32_t k = (uint32_t)out[mid].sector << 16 | out[mid].type;
		if (k == key) {
			out[mid].count++;
			return n;
		}
		if (k < key)
			lo = mid + 1;
		else
			hi = mid;
	}
	if (n >= max)
		return -E2BIG;
	memmove(&out[lo + 1], &out[lo], (size_t)(n - lo) * sizeof(*out));
	out[lo].type = type;
	out[lo].sector = sector;
	out[lo].played = (uint8_t)(sector ? g_sector_special(type, NULL, 0)
				   : g_line_special(type, NULL, 0));
	out[lo].count = 1;
	return n + 1;
}

int g_census(const struct map *m, struct g_spec_use *out, int max)
{
	int n = 0;

	for (uint32_t i = 0; i < m->num_lines && n >= 0; i++)
		if (m->lines[i].special)
			n = g_census_add(out, n, max, 0, m->lines[i].special);
	for (uint32_t i = 0; i < m->num_sectors && n >= 0; i++)
		if (m->sectors[i].special)
			n = g_census_add(out, n, max, 1, m->sectors[i].special);
	return n;
}
