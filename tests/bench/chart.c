/*
 * chart: the PNG chart of `make bench` from its CSV (tests/bench.sh).
 *
 *   chart bench.csv bench.png
 *
 * CSV columns (header line first): path,size,engine,threads,frames,fps,...
 * One group of bars per render size, in the order the sizes first appear;
 * one bar per series (path, engine, threads) in the order series first
 * appear, its height frames/s on a log scale, the figure above it; a legend
 * names the series. Drawn with the engine's 8x8 font (v_video) into an
 * indexed frame and written with display/shot.h (libpng).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "display/shot.h"
#include "engine/render/r_main.h"
#include "engine/ui/v_video.h"

#define MAXS 24
#define MAXZ 8
#define W 1200
#define H 620

enum { C_BG, C_FG, C_GRID, C_MAJOR, C_FIRST };

static const uint8_t colours[][3] = {
	{ 255, 255, 255 }, { 20, 20, 20 }, { 225, 225, 225 }, { 160, 160, 160 },
	{ 31, 119, 180 }, { 174, 199, 232 }, { 44, 160, 44 }, { 152, 223, 138 },
	{ 255, 127, 14 }, { 255, 187, 120 }, { 214, 39, 40 }, { 148, 103, 189 },
	{ 140, 86, 75 }, { 227, 119, 194 }, { 127, 127, 127 }, { 188, 189, 34 },
	{ 23, 190, 207 }, { 57, 59, 121 }, { 99, 121, 57 }, { 140, 109, 49 },
};
#define NCOL ((int)(sizeof(colours) / sizeof(colours[0])) - C_FIRST)

static char series[MAXS][64], sizes[MAXZ][16];
static int nseries, nsizes;
static double fps[MAXS][MAXZ];

static int find(char (*list)[64], int *n, int max, const char *key)
{
	for (int i = 0; i < *n; i++)
		if (strcmp(list[i], key) == 0)
			return i;
	if (*n == max)
		return -1;
	snprintf(list[*n], 64, "%s", key);
	return (*n)++;
}

static int find_size(const char *key)
{
	for (int i = 0; i < nsizes; i++)
		if (strcmp(sizes[i], key) == 0)
			return i;
	if (nsizes == MAXZ)
		return -1;
	snprintf(sizes[nsizes], sizeof(sizes[0]), "%s", key);
	return nsizes++;
}

int main(int argc, char **argv)
{
	static uint8_t px[W * H], rgb[256][3];
	struct r_frame f = { px, W, H, W, NULL };
	char line[512];
	FILE *in;
	double lo = 1e30, hi = 0;
	int x0 = 70, y0 = 40, x1 = W - 250, y1 = H - 60;

	if (argc != 3)
		return fprintf(stderr, "usage: chart CSV PNG\n"), 2;
	in = fopen(argv[1], "re");
	if (!in)
		return fprintf(stderr, "chart: %s: cannot read\n", argv[1]), 1;
	if (!fgets(line, sizeof(line), in))
		return 1;
	while (fgets(line, sizeof(line), in)) {
		char path[24], size[16], engine[24], key[64];
		int threads, frames, s, z;
		double v;

		if (sscanf(line, "%23[^,],%15[^,],%23[^,],%d,%d,%lf", path, size, engine, &threads,
			   &frames, &v) != 6 || v <= 0)
			continue;
		snprintf(key, sizeof(key), "%s %s %dT", engine, path, threads);
		s = find(series, &nseries, MAXS, key);
		z = find_size(size);
		if (s < 0 || z < 0)
			continue;
		fps[s][z] = v;
		lo = v < lo ? v : lo;
		hi = v > hi ? v : hi;
	}
	fclose(in);
	if (nseries == 0)
		return fprintf(stderr, "chart: %s: no figures\n", argv[1]), 1;
	for (int i = 0; i < (int)(sizeof(colours) / sizeof(colours[0])); i++)
		memcpy(rgb[i], colours[i], 3);
	memset(px, C_BG, sizeof(px));
	/* log axis from the decade below the lowest to the one above the
	 * highest figure */
	lo = pow(10, floor(log10(lo)));
	hi = pow(10, ceil(log10(hi)));
	v_text(&f, x0, 10, 2, C_FG, "frames per second (log scale), higher is better");
	for (double d = lo; d <= hi * 1.001; d *= 10) {
		for (int k = 1; k < 10 && d * k <= hi * 1.001; k++) {
			int y = y1 - (int)((log10(d * k) - log10(lo)) / (log10(hi) - log10(lo)) *
					   (y1 - y0));
			char lab[32];

			v_line(&f, x0, y, x1, y, k == 1 ? C_MAJOR : C_GRID, NULL);
			if (k == 1) {
				snprintf(lab, sizeof(lab), "%.0f", d * k);
				v_text(&f, x0 - v_text_width(lab, 1) - 6, y - 4, 1, C_FG, lab);
			}
		}
	}
	v_line(&f, x0, y0, x0, y1, C_FG, NULL);
	v_line(&f, x0, y1, x1, y1, C_FG, NULL);
	{
		int gw = (x1 - x0) / nsizes, bw = (gw - 20) / nseries;

		if (bw < 2)
			bw = 2;
		for (int z = 0; z < nsizes; z++) {
			int gx = x0 + z * gw + 10;

			v_text(&f, gx + (gw - 20 - v_text_width(sizes[z], 2)) / 2, y1 + 12, 2, C_FG,
			       sizes[z]);
			for (int s = 0; s < nseries; s++) {
				int top, bx = gx + s * bw;
				char lab[32];

				if (fps[s][z] <= 0)
					continue;
				top = y1 - (int)((log10(fps[s][z]) - log10(lo)) /
						 (log10(hi) - log10(lo)) * (y1 - y0));
				v_fill(&f, bx, top, bw - 2, y1 - top, (uint8_t)(C_FIRST + s % NCOL));
				snprintf(lab, sizeof(lab), "%.0f", fps[s][z]);
				/* the figure upright above the bar, one character a line
				 * when the bar is narrower than the figure */
				if (v_text_width(lab, 1) <= bw)
					v_text(&f, bx, top - 10, 1, C_FG, lab);
				else
					for (int c = 0; lab[c]; c++) {
						char ch[2] = { lab[c], 0 };

						v_text(&f, bx + (bw - 10) / 2,
						       top - 9 * ((int)strlen(lab) - c) - 2, 1, C_FG, ch);
					}
			}
		}
	}
	for (int s = 0; s < nseries; s++) {
		int ly = y0 + 20 * s;

		v_fill(&f, x1 + 20, ly, 14, 14, (uint8_t)(C_FIRST + s % NCOL));
		v_text(&f, x1 + 40, ly + 3, 1, C_FG, series[s]);
	}
	if (shot_png(argv[2], px, W, H, W, (const uint8_t(*)[3])rgb) < 0)
		return fprintf(stderr, "chart: %s: cannot write\n", argv[2]), 1;
	return 0;
}
