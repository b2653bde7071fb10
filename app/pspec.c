#include "app/pspec.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "app/ct.h"
#include "app/say.h"
#include "engine/game/g_game.h"
#include "engine/game/g_world.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"

/* Boom's generalized line types by range (boomref.txt's table): the
 * family named for a type the game does not play. */
static const char *pspec_boom_family(uint16_t type)
{
	static const struct {
		uint16_t first;
		const char *name;
	} fam[] = {
		{ 0x2f80, "crusher" }, { 0x3000, "stairs" }, { 0x3400, "lift" },
		{ 0x3800, "locked door" }, { 0x3c00, "door" }, { 0x4000, "ceiling" },
		{ 0x6000, "floor" },
	};
	const char *name = NULL;

	for (size_t i = 0; i < sizeof(fam) / sizeof(fam[0]); i++)
		if (type >= fam[i].first)
			name = fam[i].name;
	return name;
}

/* What type u is, into d: the game's description, or why it is not
 * played. */
static void pspec_describe(const struct g_spec_use *u, char *d, size_t len)
{
	const char *fam;

	d[0] = '\0';
	if (u->sector) {
		g_sector_special(u->type, d, len);
		if (!d[0])
			snprintf(d, len, "not a Doom sector type");
		return;
	}
	if (g_line_special(u->type, d, len))
		return;
	fam = pspec_boom_family(u->type);
	if (fam)
		snprintf(d, len, "Boom generalized %s", fam);
	else
		snprintf(d, len, "not a vanilla Doom line type");
}

/* "n of total (p.p%)", p rounded down: 97.96% is not shown as 98.0%. */
static void pspec_share(FILE *out, uint64_t n, uint64_t total)
{
	uint64_t pm = total ? n * 1000 / total : 1000;

	fprintf(out, "%llu of %llu (%llu.%llu%%)", (unsigned long long)n,
		(unsigned long long)total, (unsigned long long)(pm / 10),
		(unsigned long long)(pm % 10));
}

/* Special lines and sectors counted two ways: [0] lines, [1] sectors. */
struct pspec_tally {
	uint64_t uses[2], played[2];   /* over lines/sectors */
	uint64_t types[2], ptypes[2];  /* over types */
};

static void pspec_tally_print(FILE *out, const struct pspec_tally *t)
{
	fputs("special lines ", out);
	pspec_share(out, t->played[0], t->uses[0]);
	fputs(", special sectors ", out);
	pspec_share(out, t->played[1], t->uses[1]);
	fputs("; by type: line types ", out);
	pspec_share(out, t->ptypes[0], t->types[0]);
	fputs(", sector types ", out);
	pspec_share(out, t->ptypes[1], t->types[1]);
	fputc('\n', out);
}

/* One type over all maps: its count and, for a type not played, the maps
 * it is in ("E3M9 MAP20 ...": the list is cut with " ..." when full). */
struct pspec_type {
	struct g_spec_use u;
	uint64_t count;
	char maps[120];
};

struct pspec_all {
	struct pspec_tally t;
	struct pspec_type *types;      /* every type of every map, in first-seen order */
	int ntypes, cap;
	int unplayed;                  /* types not played */
};

/* Adds map `name`'s census u[0..n-1] to a. */
static int pspec_merge(struct pspec_all *a, const char *name, const struct g_spec_use *u, int n)
{
	for (int i = 0; i < n; i++) {
		struct pspec_type *e;
		size_t l;
		int k = 0;

		a->t.uses[u[i].sector] += u[i].count;
		a->t.played[u[i].sector] += u[i].played ? u[i].count : 0;
		while (k < a->ntypes && (a->types[k].u.type != u[i].type ||
					 a->types[k].u.sector != u[i].sector))
			k++;
		if (k == a->ntypes) {
			if (a->ntypes == a->cap) {
				int cap = a->cap ? a->cap * 2 : 32;
				void *q = realloc(a->types, (size_t)cap * sizeof(*a->types));
				if (!q)
					return -ENOMEM;
				a->types = q;
				a->cap = cap;
			}
			memset(&a->types[k], 0, sizeof(a->types[k]));
			a->types[k].u = u[i];
			a->ntypes++;
			a->t.types[u[i].sector]++;
			a->t.ptypes[u[i].sector] += u[i].played;
			a->unplayed += !u[i].played;
		}
		e = &a->types[k];
		e->count += u[i].count;
		l = strlen(e->maps);
		if (u[i].played)
			continue;
		if (l + strlen(name) + 5 < sizeof(e->maps))
			snprintf(e->maps + l, sizeof(e->maps) - l, "%s%s", l ? " " : "", name);
		else if (strcmp(e->maps + l - 3, "...") != 0)
			snprintf(e->maps + l, sizeof(e->maps) - l, " ...");
	}
	return 0;
}

/* Prints one map's census u[0..n-1]. */
static void pspec_map(FILE *out, const struct map *m, const char *file,
		      const struct g_spec_use *u, int n)
{
	struct pspec_tally t = { 0 };
	char d[128];

	for (int i = 0; i < n; i++) {
		t.uses[u[i].sector] += u[i].count;
		t.types[u[i].sector]++;
		if (u[i].played) {
			t.played[u[i].sector] += u[i].count;
			t.ptypes[u[i].sector]++;
		}
	}
	fprintf(out, "map %s (%s): %llu special lines of %u, %llu special sectors of %u\n",
		m->name, file, (unsigned long long)t.uses[0], m->num_lines,
		(unsigned long long)t.uses[1], m->num_sectors);
	for (int i = 0; i < n; i++) {
		pspec_describe(&u[i], d, sizeof d);
		fprintf(out, "  %s %u x%u: %s%s\n", u[i].sector ? "sector" : "line", u[i].type,
			u[i].count, u[i].played ? "" : "UNSUPPORTED: ", d);
	}
	fprintf(out, "map %s supported: ", m->name);
	pspec_tally_print(out, &t);
}

/* The census of m into a new array *u (the caller frees it). */
static int pspec_census(const struct map *m, struct g_spec_use **u)
{
	size_t max = (size_t)m->num_lines + m->num_sectors;
	int n;

	*u = malloc((max ? max : 1) * sizeof(**u));
	if (!*u)
		return -ENOMEM;
	n = g_census(m, *u, (int)max);
	if (n < 0) {
		free(*u);
		*u = NULL;
	}
	return n;
}

/* The maps of w to print: `map`, or all of them (names, *n); 0 or -errno. */
static int pspec_names(const struct wad *w, const char *file, const char *map,
		       char (**names)[9], int *n)
{
	int all = !map || strcasecmp(map, "all") == 0;
	int count = all ? map_list_wad(w, NULL, 0) : 1;

	if (count < 0)
		return count;
	if (!all && strlen(map) > 8) {
		say_err("--map: '%s' is longer than a map name (8 characters)", map);
		return -EINVAL;
	}
	if (count == 0) {
		say_err("%s: no maps in the WADs", file);
		return -ENOENT;
	}
	*names = calloc((size_t)count, sizeof(**names));
	if (!*names)
		return -ENOMEM;
	if (all)
		map_list_wad(w, *names, count);
	else
		snprintf((*names)[0], sizeof((*names)[0]), "%.8s", map);
	*n = count;
	return 0;
}

/* Every map of names[0..n-1] printed and merged into a; an error names
 * the file the map is in, or `top` (the last WAD) for a map not there. */
static int pspec_maps(FILE *out, const struct wad *w, const struct tex_set *tex, const char *top,
		      char (*names)[9], int n, struct pspec_all *a)
{
	char err[512];

	for (int i = 0; i < n; i++) {
		struct map *m = NULL;
		struct g_spec_use *u = NULL;
		int rc = map_load_wad(w, tex, names[i], &m, err, sizeof err), k = 0;
		const char *file;

		if (rc < 0) {
			file = rc == -ENOENT ? top : wad_file(w, wad_find(w, names[i]));
			if (!file || strstr(err, file))
				say_err("%s", err);
			else
				say_err("%s: %s", file, err);
			return rc;
		}
		rc = k = pspec_census(m, &u);
		if (rc >= 0) {
			pspec_map(out, m, wad_file(w, wad_find(w, names[i])), u, k);
			rc = pspec_merge(a, m->name, u, k);
		}
		free(u);
		map_free(m);
		if (rc < 0)
			return rc;     /* -ENOMEM: the caller says so */
	}
	return 0;
}

int pspec_print(const char *const *wads, int nwads, const char *map, FILE *out)
{
	uint8_t *bufs[CT_MAX_WADS] = { 0 };
	struct pspec_all a = { 0 };
	struct tex_set *tex = NULL;
	struct wad *w = NULL;
	char (*names)[9] = NULL;
	char err[512] = "";
	int rc, n = 0;

	rc = wad_new(&w);
	for (int i = 0; rc == 0 && i < nwads && i < CT_MAX_WADS; i++) {
		size_t len = 0;
		rc = ct_read_file(wads[i], &bufs[i], &len);
		if (rc < 0)
			say_err("%s: %s", wads[i], strerror(-rc));
		else if ((rc = wad_add(w, bufs[i], len, wads[i], err, sizeof err)) < 0)
			say_err("%s", err);
	}
	if (rc == 0 && (rc = tex_load_wad(w, &tex, err, sizeof err)) < 0)
		say_err("%s", err);
	if (rc == 0)
		rc = pspec_names(w, wads[0], map, &names, &n);
	if (rc == 0)
		rc = pspec_maps(out, w, tex, wads[nwads - 1], names, n, &a);
	if (rc == 0 && n > 1) {
		fprintf(out, "all %d maps supported: ", n);
		pspec_tally_print(out, &a.t);
		fprintf(out, "unsupported:%s\n", a.unplayed ? "" : " none");
		for (int i = 0; i < a.ntypes; i++)
			if (!a.types[i].u.played)
				fprintf(out, "  %s %u x%llu (%s)\n",
					a.types[i].u.sector ? "sector" : "line", a.types[i].u.type,
					(unsigned long long)a.types[i].count, a.types[i].maps);
	}
	if (rc == -ENOMEM)
		say_err("out of memory");
	free(a.types);
	free(names);
	tex_free(tex);
	wad_free(w);
	for (int i = 0; i < CT_MAX_WADS; i++)
		free(bufs[i]);
	return rc < 0 ? 2 : 0;
}

int pspec_unplayed(const struct map *m, char *out, size_t len)
{
	struct g_spec_use *u = NULL;
	int n = pspec_census(m, &u), any = 0;
	size_t l;

	if (len)
		out[0] = '\0';
	if (n < 0 || !len) {
		free(u);
		return 0;
	}
	l = (size_t)snprintf(out, len, "map %s: unsupported specials:", m->name);
	for (int i = 0; i < n && l < len; i++) {
		if (u[i].played)
			continue;
		l += (size_t)snprintf(out + l, len - l, "%s %s %u x%u", any ? "," : "",
				      u[i].sector ? "sector" : "line", u[i].type, u[i].count);
		any = 1;
	}
	free(u);
	if (!any)
		out[0] = '\0';
	return any;
}

int pspec_crowded(const struct map *m, int difficulty, char *out, size_t len)
{
	int ne, np;

	if (len)
		out[0] = '\0';
	g_spawn_count(m, difficulty, &ne, &np);
	if (!len || (ne <= G_MAX_ENEMIES && np <= G_MAX_PICKUPS))
		return 0;
	snprintf(out, len,
		 "map %s: %d enemies and %d pickups at difficulty %d; the game keeps the first %d "
		 "enemies and %d pickups in the map's order, the rest never appear",
		 m->name, ne, np, difficulty, G_MAX_ENEMIES, G_MAX_PICKUPS);
	return 1;
}
