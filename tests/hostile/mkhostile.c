/*
 * mkhostile: writes the hostile WADs of issue 13 (items 7-9) and the map
 * of specials the game does not play (issue 15 item 7) into a folder,
 * for tests/hostile/run.sh, which feeds them to the daemon. The generators
 * are tests/unit/hostile_fixture.h, shared with the unit tests.
 * Usage: mkhostile DIR
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tests/unit/hostile_fixture.h"

static int put(const char *dir, const char *name, uint8_t *img, size_t len)
{
	char path[4096];
	FILE *f;
	int ok;

	snprintf(path, sizeof path, "%s/%s", dir, name);
	f = fopen(path, "wb");
	if (!f) {
		perror(path);
		free(img);
		return 1;
	}
	ok = fwrite(img, 1, len, f) == len;
	ok &= fclose(f) == 0;
	free(img);
	if (!ok)
		perror(path);
	return !ok;
}

int main(int argc, char **argv)
{
	uint8_t *img;
	size_t len;
	int bad = 0;

	if (argc != 2) {
		fprintf(stderr, "usage: mkhostile DIR\n");
		return 2;
	}
	/* one call per statement: an argument list has no order of evaluation */
	img = hf_dag(1200, &len);
	bad |= put(argv[1], "dag.wad", img, len);
	img = hf_tall_texture(2000, 6000, &len);
	bad |= put(argv[1], "tall.wad", img, len);
	img = hf_crossing(2004, &len);
	bad |= put(argv[1], "cross2004.wad", img, len);
	img = hf_crossing(30004, &len);
	bad |= put(argv[1], "cross30004.wad", img, len);
	img = hf_lights(30000, &len);
	bad |= put(argv[1], "lights30000.wad", img, len);
	img = hf_lit_lines(4096, 1000, &len);
	bad |= put(argv[1], "litlines.wad", img, len);
	/* 100,000 markers: the quadratic listing took 8.7 s for 40,000 */
	img = hf_markers(100000, &len);
	bad |= put(argv[1], "markers100000.wad", img, len);
	img = hf_heights(32730, 32760, &len);
	bad |= put(argv[1], "high.wad", img, len);
	img = hf_specials(&len);
	bad |= put(argv[1], "specials.wad", img, len);
	return bad;
}
