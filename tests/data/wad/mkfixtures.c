/*
 * mkfixtures: writes the WAD fixtures of tests/unit/wad_fixture.h as files,
 * for the fuzz seed corpus and for looking at with other tools (Eureka,
 * a hex dump). The unit tests build the same images in memory and check
 * that these files still match (test_wad).
 *
 *   cc -std=c11 -I. -Itests/unit -o build/mkfixtures tests/data/wad/mkfixtures.c
 *   build/mkfixtures tests/data/wad
 *   cp tests/data/wad/fixture.wad tests/data/wad/nonodes.wad tests/fuzz/corpus/fuzz_wad/
 *
 * fixture.wad   IWAD: the graphics fixture and maps MAP01 and E1M1
 * nonodes.wad   PWAD: MAP01 without SEGS, SSECTORS and NODES
 */
#include <stdio.h>
#include <stdlib.h>

#include "wad_fixture.h"

static int put(const char *dir, const char *name, const uint8_t *d, size_t len)
{
	char path[512];
	FILE *f;

	snprintf(path, sizeof path, "%s/%s", dir, name);
	f = fopen(path, "wbe");
	if (!f || fwrite(d, 1, len, f) != len || fclose(f) != 0) {
		perror(path);
		return 1;
	}
	return 0;
}

int main(int argc, char **argv)
{
	size_t len;
	uint8_t *d;
	int r;

	if (argc != 2) {
		fprintf(stderr, "usage: %s DIR\n", argv[0]);
		return 2;
	}
	d = wfx_iwad(&len);
	r = put(argv[1], "fixture.wad", d, len);
	free(d);
	d = wfx_nonodes(&len);
	r |= put(argv[1], "nonodes.wad", d, len);
	free(d);
	return r;
}
