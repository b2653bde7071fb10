/*
 * ct: content, what the game is played on: a map, the texture set it is drawn
 * with, its shadowed light maps and the sounds it plays. From the built-in
 * levels, a grid map (--grid), or Doom-format WADs (--wad, repeatable, later
 * files override earlier ones; --map picks the map). The sounds are the
 * WADs' DS lumps where they have them, else the built-in synthesized set
 * (engine/sound/snd.h).
 */
#ifndef ARCADED_APP_CT_H
#define ARCADED_APP_CT_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "engine/game/g_game.h"

struct lmap;
struct map;
struct pool_task;
struct snd_set;
struct tex_set;

#define CT_MAX_WADS 8
#define CT_MAX_STAGES G_MAX_STAGES

struct ct_spec {
	const char *wads[CT_MAX_WADS];
	int nwads;
	/* The maps to play from the WADs, in order, blank-separated: map
	 * names (E1M1, MAP01) and episodes (E1: every E1Mn the WADs have, in
	 * order); NULL: the first map. An exit goes to the next one (the
	 * secret exit to the map the format names, when it is in the list). */
	const char *map;
	const char *grid;       /* grid map file, or "builtin" for GRID1 */
	int level;              /* built-in level, 1-based (no WAD, no grid) */
	int lights;             /* build light maps (arcaded lights + Doom lamps) */
	/* The app's stop flag (set by its SIGTERM/SIGINT handler), or NULL:
	 * the loaders poll it (engine/core/lim.h) and a load ends within
	 * well under a second of it becoming nonzero. */
	const volatile sig_atomic_t *stop;
	/* Starts fn(arg) on a thread of its own and waits for it (the
	 * daemon's app/pool.h pool_task_start and pool_task_join), for the
	 * WADs' sounds (from when the WADs are mapped) and the stages' light
	 * maps (from when the maps are loaded) while the textures load; with
	 * no WAD, for the built-in sounds (from the start) and every other
	 * stage's light maps (the loader makes the rest); NULL: the loader
	 * makes them all itself (the engine-only replayer of tests/xbuild
	 * links no threads). */
	int (*task_start)(void (*fn)(void *arg), void *arg, struct pool_task **out);
	void (*task_join)(struct pool_task *t);
};

struct ct {
	/* The game's stages, played in order: every built-in level starting
	 * with the chosen one, or the one WAD/grid map. */
	struct map *maps[CT_MAX_STAGES];
	struct lmap *lms[CT_MAX_STAGES];   /* per stage; NULL: no lights */
	int nmaps;
	struct map *map;        /* = maps[0] */
	struct tex_set *tex;
	struct snd_set *sounds; /* one per enum sfx_id */
	int nlights;            /* lights of the first stage */
	char what[160];         /* "freedoom1.wad E1M1", "built-in level 1 (ARENA1)" */
	/* malformed sound lumps, each played by its built-in sound instead:
	 * "DSPEDTH: format 0, not 3 (Doom's digital sound)"; "" none */
	char sound_note[512];
	char src[160];          /* the file the maps came from, for messages */
	char note[400];         /* what was left out and why ("" if nothing): a
				 * map over a light-map limit is drawn without
				 * light maps (issue 13 item 8); the app logs it */
};

/* *out: cmdline when it names WADs or a grid, else the configuration's
 * [game] wad (blank-separated files, split into buf, which must outlive
 * out) and maps; cmdline's other fields (lights, level) kept. */
void ct_spec_config(struct ct_spec *out, const struct ct_spec *cmdline, const char *wad,
		    const char *maps, char *buf, size_t len);

/* The first map s->map names (its first word, at most 8 characters), or
 * "" when s names none: what a recording's header keeps. */
void ct_first_map(const struct ct_spec *s, char out[9]);

/* Loads the content s names. 0, or -errno with err naming the file, lump
 * or entry: -E2BIG when a file is over a loader's limit, -ECANCELED when
 * s->stop became nonzero during the load. On error c holds nothing
 * (ct_free is still safe). */
int ct_load(struct ct *c, const struct ct_spec *s, char *err, size_t errlen);

/* Reads the whole regular file path (at most 512 MiB: a WAD) into *buf, a
 * new buffer the caller frees, of *len bytes. 0, or -errno: -EINVAL (not a
 * regular file), -EFBIG (too large), -ENOMEM, or open's or read's error.
 * Also the one file reader of the tests and tools that load WADs. */
int ct_read_file(const char *path, uint8_t **buf, size_t *len);

/* The light maps of stage map m (NULL if none or unknown). */
struct lmap *ct_lmap_for(const struct ct *c, const struct map *m);

/* NULL-safe members; frees everything ct_load made. */
void ct_free(struct ct *c);

#endif
