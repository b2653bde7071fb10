/*
 * demo: writes a demo lump of a WAD to a file, whole or cut after N tics,
 * for timing the peer engines in `make bench` (tests/bench.sh).
 *
 *   demo freedoom1.wad DEMO1 out.lmp [TICS]
 *
 * WAD directory: a 12-byte header ("IWAD"/"PWAD", lump count, directory
 * offset, little-endian), then 16-byte entries (offset, size, 8-byte name).
 * A Doom 1.9 demo (version byte 104..111) is a 13-byte header, then per
 * tic 4 bytes per player in game, then 0x80. A cut keeps the first TICS
 * tics and ends with 0x80. Prints the tics written.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t le32(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

int main(int argc, char **argv)
{
	FILE *f;
	uint8_t *d, hdr[12];
	long len;
	uint32_t n, dir;
	const uint8_t *lump = NULL;
	uint32_t size = 0, players = 0, tics, keep;

	if (argc < 4)
		return fprintf(stderr, "usage: demo WAD LUMP OUT [TICS]\n"), 2;
	f = fopen(argv[1], "rbe");
	if (!f || fseek(f, 0, SEEK_END) != 0 || (len = ftell(f)) < 12 || fseek(f, 0, SEEK_SET) != 0)
		return fprintf(stderr, "demo: %s: cannot read\n", argv[1]), 1;
	d = malloc((size_t)len);
	if (!d || fread(d, 1, (size_t)len, f) != (size_t)len)
		return fprintf(stderr, "demo: %s: cannot read\n", argv[1]), 1;
	fclose(f);
	memcpy(hdr, d, 12);
	n = le32(hdr + 4);
	dir = le32(hdr + 8);
	if (dir > (uint32_t)len || n > ((uint32_t)len - dir) / 16)
		return fprintf(stderr, "demo: %s: bad directory\n", argv[1]), 1;
	for (uint32_t i = 0; i < n; i++) {
		const uint8_t *e = d + dir + 16 * i;
		char name[9] = { 0 };

		memcpy(name, e + 8, 8);
		if (strcmp(name, argv[2]) == 0 && le32(e) <= (uint32_t)len &&
		    le32(e + 4) <= (uint32_t)len - le32(e)) {
			lump = d + le32(e);
			size = le32(e + 4);
		}
	}
	if (!lump || size < 14 || lump[0] < 104 || lump[0] > 111)
		return fprintf(stderr, "demo: %s: no Doom 1.9 demo %s\n", argv[1], argv[2]), 1;
	for (int p = 0; p < 4; p++)
		players += lump[9 + p] != 0;
	if (players == 0)
		return fprintf(stderr, "demo: %s: no player in game\n", argv[2]), 1;
	tics = (size - 14) / (4 * players);
	keep = argc > 4 ? (uint32_t)strtoul(argv[4], NULL, 10) : tics;
	if (keep > tics)
		keep = tics;
	f = fopen(argv[3], "wbe");
	if (!f || fwrite(lump, 1, 13 + 4 * players * keep, f) != 13 + 4 * players * keep ||
	    fputc(0x80, f) == EOF || fclose(f) != 0)
		return fprintf(stderr, "demo: %s: cannot write\n", argv[3]), 1;
	printf("%u\n", keep);
	free(d);
	return 0;
}
