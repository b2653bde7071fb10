/*
 * mklevels: the built-in levels' generator. Reads level descriptions
 * (levels/arena*.txt; the syntax is in docs/maps.md, "The built-in
 * levels"), writes them as one PWAD in Doom's format and prints that
 * PWAD as C source for engine/map/lvl_wad.c, which the engine loads through
 * its own WAD and map loaders (engine/map/lvl_builtin.c):
 *
 *   mklevels [--wad OUT.wad] levels/arena1.txt levels/arena2.txt ... > engine/map/lvl_wad.c
 *
 * --wad also writes the PWAD itself (to look at with WAD tools or an
 * editor; its texture names are the built-in set's, which Freedoom lacks).
 * The output depends only on the input text: tests/check_levels.sh
 * regenerates the C file and compares. The BSP lumps are
 * written empty (the loader's node builder makes the BSP, the same on
 * every build); texture and flat names are checked by the unit tests,
 * which load every level against the built-in set (tex_builtin).
 *
 * Each map's lumps: the marker, THINGS, LINEDEFS, SIDEDEFS, VERTEXES,
 * SEGS, SSECTORS, NODES (empty), SECTORS, REJECT, BLOCKMAP (empty).
 * Sidedefs are written in line order, each line's front side then its
 * back side.
 *
 * Exit status 0, 1 on a bad description (the message names the file and
 * line), 2 on bad usage or an I/O error.
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ML_MAX 4096                    /* vertices, sectors, lines, things per map */
#define ML_MAPS 32
#define ML_TOKENS 32

struct ml_sector {
	char name[32];
	int floor, ceil, light, special, tag;
	char ftex[9], ctex[9], wall[9];
};

struct ml_line {
	int v1, v2, front, back, flags, special, tag, xoff, yoff;
	char tex[9], upper[9], lower[9], mid[9];   /* "" when not given */
};

struct ml_thing {
	int x, y, angle, type, flags;
};

struct ml_map {
	char name[9];
	int nv, ns, nl, nt;
	int vx[ML_MAX], vy[ML_MAX];
	struct ml_sector s[ML_MAX];
	struct ml_line l[ML_MAX];
	struct ml_thing t[ML_MAX];
};

struct ml_in {
	const char *file;
	int line;
};

static void ml_fail(const struct ml_in *in, const char *fmt, const char *arg)
{
	fprintf(stderr, "mklevels: %s:%d: ", in->file, in->line);
	fprintf(stderr, fmt, arg);
	fputc('\n', stderr);
	exit(1);
}

static int ml_int(const struct ml_in *in, const char *s, int lo, int hi)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(s, &end, 10);
	if (errno || end == s || *end || v < lo || v > hi)
		ml_fail(in, "bad number '%s'", s);
	return (int)v;
}

/* A texture or flat name: up to 8 characters, stored upper-case. */
static void ml_name8(const struct ml_in *in, char out[9], const char *s)
{
	size_t n = strlen(s);

	if (n == 0 || n > 8)
		ml_fail(in, "name '%s' is not 1..8 characters", s);
	memset(out, 0, 9);
	for (size_t i = 0; i < n; i++)
		out[i] = (char)(s[i] >= 'a' && s[i] <= 'z' ? s[i] - 'a' + 'A' : s[i]);
}

static int ml_sector_find(const struct ml_map *m, const char *name)
{
	for (int i = 0; i < m->ns; i++)
		if (strcmp(m->s[i].name, name) == 0)
			return i;
	return -1;
}

static int ml_dir(const char *s)
{
	static const char *const dirs[8] = { "east",  "northeast", "north", "northwest",
					     "west",  "southwest", "south", "southeast" };

	for (int i = 0; i < 8; i++)
		if (strcmp(s, dirs[i]) == 0)
			return i * 45;
	return -1;
}

static void ml_sector(const struct ml_in *in, struct ml_map *m, char **tok, int n)
{
	struct ml_sector *s = &m->s[m->ns];

	if (n < 2 || n % 2)
		ml_fail(in, "%s", "sector NAME KEY VALUE...: keys come in pairs");
	if (m->ns == ML_MAX)
		ml_fail(in, "%s", "too many sectors");
	if (strlen(tok[1]) >= sizeof(s->name) || ml_sector_find(m, tok[1]) >= 0)
		ml_fail(in, "sector name '%s' too long or defined twice", tok[1]);
	memset(s, 0, sizeof(*s));
	strcpy(s->name, tok[1]);
	s->ceil = 128;
	s->light = 160;
	for (int i = 2; i + 1 < n; i += 2) {
		const char *k = tok[i], *v = tok[i + 1];

		if (strcmp(k, "floor") == 0)
			s->floor = ml_int(in, v, -32768, 32767);
		else if (strcmp(k, "ceil") == 0)
			s->ceil = ml_int(in, v, -32768, 32767);
		else if (strcmp(k, "light") == 0)
			s->light = ml_int(in, v, 0, 255);
		else if (strcmp(k, "special") == 0)
			s->special = ml_int(in, v, 0, 65535);
		else if (strcmp(k, "tag") == 0)
			s->tag = ml_int(in, v, 0, 65535);
		else if (strcmp(k, "ftex") == 0)
			ml_name8(in, s->ftex, v);
		else if (strcmp(k, "ctex") == 0)
			ml_name8(in, s->ctex, v);
		else if (strcmp(k, "wall") == 0)
			ml_name8(in, s->wall, v);
		else
			ml_fail(in, "unknown sector key '%s'", k);
	}
	if (!s->ftex[0] || !s->ctex[0] || !s->wall[0])
		ml_fail(in, "sector %s needs ftex, ctex and wall", s->name);
	if (s->ceil < s->floor)
		ml_fail(in, "sector %s: ceiling below the floor", s->name);
	m->ns++;
}

static void ml_line(const struct ml_in *in, struct ml_map *m, char **tok, int n)
{
	struct ml_line *l = &m->l[m->nl];
	int i = 4;

	if (n < 4)
		ml_fail(in, "%s", "line V1 V2 FRONT [BACK] [KEY VALUE]...");
	if (m->nl == ML_MAX)
		ml_fail(in, "%s", "too many lines");
	memset(l, 0, sizeof(*l));
	l->v1 = ml_int(in, tok[1], 0, m->nv - 1);
	l->v2 = ml_int(in, tok[2], 0, m->nv - 1);
	l->front = ml_sector_find(m, tok[3]);
	l->back = -1;
	if (l->front < 0)
		ml_fail(in, "unknown sector '%s'", tok[3]);
	if (n > 4 && ml_sector_find(m, tok[4]) >= 0)
		l->back = ml_sector_find(m, tok[i++]);
	if ((n - i) % 2)
		ml_fail(in, "'%s': keys come in pairs (or an unknown back sector)", tok[i]);
	for (; i + 1 < n; i += 2) {
		const char *k = tok[i], *v = tok[i + 1];

		if (strcmp(k, "tex") == 0)
			ml_name8(in, l->tex, v);
		else if (strcmp(k, "upper") == 0)
			ml_name8(in, l->upper, v);
		else if (strcmp(k, "lower") == 0)
			ml_name8(in, l->lower, v);
		else if (strcmp(k, "mid") == 0)
			ml_name8(in, l->mid, v);
		else if (strcmp(k, "flags") == 0)
			l->flags = ml_int(in, v, 0, 65535);
		else if (strcmp(k, "special") == 0)
			l->special = ml_int(in, v, 0, 65535);
		else if (strcmp(k, "tag") == 0)
			l->tag = ml_int(in, v, 0, 65535);
		else if (strcmp(k, "xoff") == 0)
			l->xoff = ml_int(in, v, -32768, 32767);
		else if (strcmp(k, "yoff") == 0)
			l->yoff = ml_int(in, v, -32768, 32767);
		else
			ml_fail(in, "unknown line key '%s'", k);
	}
	if (l->v1 == l->v2)
		ml_fail(in, "%s", "a line from a vertex to itself");
	if (l->back < 0 && (l->upper[0] || l->lower[0] || l->mid[0]))
		ml_fail(in, "%s", "upper, lower and mid are for two-sided lines (one-sided: tex)");
	m->nl++;
}

/* thing TYPE X Y [DIR] [all|hard] [flags N]: DIR a compass word or degrees
 * 0..359 (default east); the skill bits Doom's, 7 (all) unless hard (4,
 * hard and brutal only) or flags N gives them. */
static void ml_thing(const struct ml_in *in, struct ml_map *m, char **tok, int n)
{
	struct ml_thing *t = &m->t[m->nt];
	int i = 4;

	if (n < 4)
		ml_fail(in, "%s", "thing TYPE X Y [DIR] [all|hard] [flags N]");
	if (m->nt == ML_MAX)
		ml_fail(in, "%s", "too many things");
	t->type = ml_int(in, tok[1], 1, 65535);
	t->x = ml_int(in, tok[2], -16383, 16383);
	t->y = ml_int(in, tok[3], -16383, 16383);
	t->angle = 0;
	t->flags = 7;
	if (i < n && ml_dir(tok[i]) >= 0)
		t->angle = ml_dir(tok[i++]);
	else if (i < n && tok[i][0] >= '0' && tok[i][0] <= '9')
		t->angle = ml_int(in, tok[i++], 0, 359);
	for (; i < n; i++) {
		if (strcmp(tok[i], "all") == 0)
			t->flags = 7;
		else if (strcmp(tok[i], "hard") == 0)
			t->flags = 4;
		else if (strcmp(tok[i], "flags") == 0 && i + 1 < n)
			t->flags = ml_int(in, tok[++i], 0, 65535);
		else
			ml_fail(in, "unexpected '%s'", tok[i]);
	}
	m->nt++;
}

/* Parses one file's maps into maps[*nmaps..]. */
static void ml_parse(const char *file, struct ml_map **maps, int *nmaps)
{
	FILE *f = fopen(file, "re");
	struct ml_in in = { file, 0 };
	struct ml_map *m = NULL;
	char buf[1024];

	if (!f) {
		fprintf(stderr, "mklevels: %s: %s\n", file, strerror(errno));
		exit(2);
	}
	while (fgets(buf, sizeof(buf), f)) {
		char *tok[ML_TOKENS], *p = strchr(buf, ';');
		int n = 0;

		in.line++;
		if (!strchr(buf, '\n') && !feof(f))
			ml_fail(&in, "%s", "line too long");
		if (p)
			*p = '\0';
		for (p = strtok(buf, " \t\r\n"); p; p = strtok(NULL, " \t\r\n")) {
			if (n == ML_TOKENS)
				ml_fail(&in, "%s", "too many words");
			tok[n++] = p;
		}
		if (n == 0)
			continue;
		if (strcmp(tok[0], "map") == 0) {
			if (n != 2)
				ml_fail(&in, "%s", "map NAME");
			if (*nmaps == ML_MAPS)
				ml_fail(&in, "%s", "too many maps");
			m = calloc(1, sizeof(*m));
			if (!m) {
				fprintf(stderr, "mklevels: out of memory\n");
				exit(2);
			}
			ml_name8(&in, m->name, tok[1]);
			maps[(*nmaps)++] = m;
		} else if (!m) {
			ml_fail(&in, "'%s' before the first map line", tok[0]);
		} else if (strcmp(tok[0], "vertex") == 0) {
			if (n < 3 || n % 2 == 0)
				ml_fail(&in, "%s", "vertex X Y [X Y]...");
			for (int i = 1; i + 1 < n; i += 2) {
				if (m->nv == ML_MAX)
					ml_fail(&in, "%s", "too many vertices");
				m->vx[m->nv] = ml_int(&in, tok[i], -16383, 16383);
				m->vy[m->nv] = ml_int(&in, tok[i + 1], -16383, 16383);
				m->nv++;
			}
		} else if (strcmp(tok[0], "sector") == 0) {
			ml_sector(&in, m, tok, n);
		} else if (strcmp(tok[0], "line") == 0) {
			ml_line(&in, m, tok, n);
		} else if (strcmp(tok[0], "thing") == 0) {
			ml_thing(&in, m, tok, n);
		} else {
			ml_fail(&in, "unknown keyword '%s'", tok[0]);
		}
	}
	fclose(f);
	if (m && (m->ns == 0 || m->nl == 0))
		ml_fail(&in, "map %s has no sectors or no lines", m->name);
}

/* ---- the PWAD ------------------------------------------------------------ */

struct ml_out {
	uint8_t *d;
	size_t n, cap;
	uint8_t dir[ML_MAPS * 11][16];
	int ndir;
};

static void ml_put(struct ml_out *o, const void *p, size_t len)
{
	if (o->n + len > o->cap) {
		o->cap = (o->n + len) * 2 + 1024;
		o->d = realloc(o->d, o->cap);
		if (!o->d) {
			fprintf(stderr, "mklevels: out of memory\n");
			exit(2);
		}
	}
	memcpy(o->d + o->n, p, len);
	o->n += len;
}

static void ml_16(struct ml_out *o, int v)
{
	uint8_t b[2] = { (uint8_t)(v & 255), (uint8_t)((v >> 8) & 255) };

	ml_put(o, b, 2);
}

static void ml_32at(uint8_t *b, uint32_t v)
{
	for (int i = 0; i < 4; i++)
		b[i] = (uint8_t)(v >> (8 * i));
}

static void ml_8(struct ml_out *o, const char *name)
{
	char n[8] = { 0 };

	memcpy(n, name, strnlen(name, 8));
	ml_put(o, n, 8);
}

/* The directory entry of the lump from byte start to the current end. */
static void ml_lump(struct ml_out *o, const char *name, size_t start)
{
	uint8_t *e = o->dir[o->ndir++];

	ml_32at(e, (uint32_t)start);
	ml_32at(e + 4, (uint32_t)(o->n - start));
	memset(e + 8, 0, 8);
	memcpy(e + 8, name, strnlen(name, 8));
}

/* A side's texture: the line's part, else its tex, else the wall of the
 * sector the side faces; "-" where nothing is drawn. */
static const char *ml_part(const char *part, const char *tex, const struct ml_sector *s)
{
	return part[0] ? part : tex[0] ? tex : s->wall;
}

static void ml_side(struct ml_out *o, const struct ml_map *m, const struct ml_line *l, int sec)
{
	const struct ml_sector *s = &m->s[sec];

	ml_16(o, l->xoff);
	ml_16(o, l->yoff);
	if (l->back < 0) {
		ml_8(o, "-");
		ml_8(o, "-");
		ml_8(o, ml_part("", l->tex, s));
	} else {
		ml_8(o, ml_part(l->upper, l->tex, s));
		ml_8(o, ml_part(l->lower, l->tex, s));
		ml_8(o, l->mid[0] ? l->mid : "-");
	}
	ml_16(o, sec);
}

static void ml_map(struct ml_out *o, const struct ml_map *m)
{
	static const char *const bsp[3] = { "SEGS", "SSECTORS", "NODES" };
	size_t at;
	int side = 0;

	ml_lump(o, m->name, o->n);
	at = o->n;
	for (int i = 0; i < m->nt; i++) {
		ml_16(o, m->t[i].x);
		ml_16(o, m->t[i].y);
		ml_16(o, m->t[i].angle);
		ml_16(o, m->t[i].type);
		ml_16(o, m->t[i].flags);
	}
	ml_lump(o, "THINGS", at);
	at = o->n;
	for (int i = 0; i < m->nl; i++) {
		const struct ml_line *l = &m->l[i];

		ml_16(o, l->v1);
		ml_16(o, l->v2);
		ml_16(o, l->flags | (l->back >= 0 ? 0x0004 : 0x0001));   /* two-sided, blocking */
		ml_16(o, l->special);
		ml_16(o, l->tag);
		ml_16(o, side++);
		ml_16(o, l->back >= 0 ? side++ : 0xFFFF);
	}
	ml_lump(o, "LINEDEFS", at);
	at = o->n;
	for (int i = 0; i < m->nl; i++) {
		ml_side(o, m, &m->l[i], m->l[i].front);
		if (m->l[i].back >= 0)
			ml_side(o, m, &m->l[i], m->l[i].back);
	}
	ml_lump(o, "SIDEDEFS", at);
	at = o->n;
	for (int i = 0; i < m->nv; i++) {
		ml_16(o, m->vx[i]);
		ml_16(o, m->vy[i]);
	}
	ml_lump(o, "VERTEXES", at);
	for (int i = 0; i < 3; i++)
		ml_lump(o, bsp[i], o->n);
	at = o->n;
	for (int i = 0; i < m->ns; i++) {
		const struct ml_sector *s = &m->s[i];

		ml_16(o, s->floor);
		ml_16(o, s->ceil);
		ml_8(o, s->ftex);
		ml_8(o, s->ctex);
		ml_16(o, s->light);
		ml_16(o, s->special);
		ml_16(o, s->tag);
	}
	ml_lump(o, "SECTORS", at);
	ml_lump(o, "REJECT", o->n);
	ml_lump(o, "BLOCKMAP", o->n);
}

static void ml_wad(struct ml_out *o, struct ml_map **maps, int nmaps)
{
	uint8_t head[12] = { 'P', 'W', 'A', 'D' };
	size_t dir;

	ml_put(o, head, sizeof(head));
	for (int i = 0; i < nmaps; i++)
		ml_map(o, maps[i]);
	dir = o->n;
	for (int i = 0; i < o->ndir; i++)
		ml_put(o, o->dir[i], 16);
	ml_32at(o->d + 4, (uint32_t)o->ndir);
	ml_32at(o->d + 8, (uint32_t)dir);
}

static void ml_c(const struct ml_out *o, char **files, int nfiles)
{
	printf("/*\n * lvl_wad: the built-in levels, one PWAD in Doom's format (%zu bytes).\n"
	       " * Generated by tools/mklevels from", o->n);
	for (int i = 0; i < nfiles; i++)
		printf(" %s", files[i]);
	printf(";\n * do not edit: change the text and regenerate (docs/maps.md).\n */\n"
	       "#include \"engine/map/lvl_wad.h\"\n\nconst uint8_t lvl_wad[%zu] = {", o->n);
	for (size_t i = 0; i < o->n; i++)
		printf("%s%u,", i % 20 ? " " : "\n\t", o->d[i]);
	printf("\n};\n\nconst size_t lvl_wad_len = sizeof(lvl_wad);\n");
}

int main(int argc, char **argv)
{
	static struct ml_out o;
	struct ml_map *maps[ML_MAPS];
	const char *wad = NULL;
	int nmaps = 0, first = 1;

	if (argc > 2 && strcmp(argv[1], "--wad") == 0) {
		wad = argv[2];
		first = 3;
	}
	if (first >= argc || argv[first][0] == '-') {
		fprintf(stderr, "usage: mklevels [--wad OUT.wad] LEVEL.txt... > engine/map/lvl_wad.c\n");
		return 2;
	}
	for (int i = first; i < argc; i++)
		ml_parse(argv[i], maps, &nmaps);
	ml_wad(&o, maps, nmaps);
	if (wad) {
		FILE *f = fopen(wad, "we");

		if (!f || fwrite(o.d, 1, o.n, f) != o.n || fclose(f) != 0) {
			fprintf(stderr, "mklevels: %s: %s\n", wad, strerror(errno));
			return 2;
		}
	}
	ml_c(&o, argv + first, argc - first);
	if (fflush(stdout) != 0 || ferror(stdout)) {
		fprintf(stderr, "mklevels: writing the C file failed\n");
		return 2;
	}
	for (int i = 0; i < nmaps; i++)
		free(maps[i]);
	free(o.d);
	return 0;
}
