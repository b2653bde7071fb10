#include "app/ct.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "engine/core/lim.h"
#include "engine/map/grid.h"
#include "engine/map/lmap.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/map/map_wad.h"
#include "engine/map/tex.h"
#include "engine/map/wad.h"
#include "engine/render/r_game.h"
#include "engine/sound/snd.h"
#include "engine/ui/hud.h"
#include "input/io.h"

/* Freedoom 2 is 28 MiB; anything far larger is not a WAD meant for us. */
#define CT_FILE_MAX (512u << 20)

int ct_read_file(const char *path, uint8_t **buf, size_t *len)
{
	return io_read_file(path, CT_FILE_MAX, IO_REGULAR, buf, len);
}

/* The loaders' stop hook: the app's signal flag. */
static int ct_stop_fn(void *ctx)
{
	return *(const volatile sig_atomic_t *)ctx != 0;
}

static int ct_stopped(const struct ct_spec *s, char *err, size_t errlen)
{
	if (!s->stop || !*s->stop)
		return 0;
	snprintf(err, errlen, "loading stopped by a signal");
	return -ECANCELED;
}

void ct_spec_config(struct ct_spec *out, const struct ct_spec *cmdline, const char *wad,
		    const char *maps, char *buf, size_t len)
{
	char *save = NULL;

	*out = *cmdline;
	if (out->nwads || out->grid || !wad[0])
		return;
	snprintf(buf, len, "%s", wad);
	for (char *w = strtok_r(buf, " \t", &save); w && out->nwads < CT_MAX_WADS;
	     w = strtok_r(NULL, " \t", &save))
		out->wads[out->nwads++] = w;
	if (!out->map && maps[0])
		out->map = maps;
}

void ct_first_map(const struct ct_spec *s, char out[9])
{
	const char *m = s->map ? s->map : "";
	size_t n;

	m += strspn(m, " \t");
	n = strcspn(m, " \t");
	if (n > 8)
		n = 8;
	memcpy(out, m, n);
	out[n] = '\0';
}

/* An episode word: E and one digit ("E1"). */
static int ct_episode(const char *w, size_t n)
{
	return n == 2 && (w[0] == 'E' || w[0] == 'e') && w[1] >= '1' && w[1] <= '9';
}

/* The maps list names, among the WADs' maps names[0..n), into picked: a
 * map name adds that map, an episode every map of it in the WADs' order.
 * The count (at least 1), or -ENOENT / -E2BIG with err naming the word. */
static int ct_pick_maps(const char *list, char (*names)[9], int n, char (*picked)[9],
			char *err, size_t errlen)
{
	int np = 0;

	for (const char *w = list + strspn(list, " \t"); *w; w += strspn(w, " \t")) {
		size_t len = strcspn(w, " \t");
		int found = 0;

		for (int i = 0; i < n; i++) {
			int hit = ct_episode(w, len)
					  ? (names[i][0] == 'E' && names[i][1] == w[1] && names[i][2] == 'M')
					  : (strlen(names[i]) == len && strncasecmp(names[i], w, len) == 0);
			if (!hit)
				continue;
			if (np == CT_MAX_STAGES) {
				snprintf(err, errlen, "maps: more than %d maps", CT_MAX_STAGES);
				return -E2BIG;
			}
			memcpy(picked[np++], names[i], 9);
			found = 1;
		}
		if (!found) {
			snprintf(err, errlen, "map %.*s: not in the WADs (they have %s..%s)",
				 (int)(len > 16 ? 16 : len), w, names[0], names[n - 1]);
			return -ENOENT;
		}
		w += len;
	}
	if (!np) {
		snprintf(err, errlen, "maps: no map named");
		return -ENOENT;
	}
	return np;
}

/* Composes the wall textures and decodes the sprites c's stages can show
 * (tex_want_map, r_game_want over every stage, and the HUD's). */
static int ct_compose(struct ct *c, const struct wad *w, const struct lim_stop *stop,
		      char *err, size_t errlen)
{
	uint8_t *want = calloc((size_t)c->tex->num_textures, 1);
	uint8_t *spr = calloc((size_t)c->tex->num_sprpics, 1);
	int rc;

	if (!want || !spr) {
		free(want);
		free(spr);
		snprintf(err, errlen, "textures: %s", strerror(ENOMEM));
		return -ENOMEM;
	}
	for (int i = 0; i < c->nmaps; i++) {
		tex_want_map(c->tex, c->maps[i], want);
		r_game_want(c->tex, c->maps[i], spr);
	}
	hud_want(c->tex, spr);
	rc = tex_compose(c->tex, w, want, spr, stop, err, errlen);
	free(want);
	free(spr);
	return rc;
}

/* Light maps of stages first, first + step, ...: a WAD's, every stage on a
 * thread of their own while the loader composes textures (they need only
 * the maps; Freedoom 1 E1M1: 4.7 ms of thread CPU time, 10 ms before
 * lmap_texel compared squares); the built-in ones split (ct_lights_split). */
struct ct_lights_job {
	struct ct *c;
	const struct lim_stop *stop;
	int first, step;               /* the stages first, first + step, ... */
	int rc;
	/* load_lights's "SRC: MAP: THINGS: WHY" fits (160 + 8 + 160 + 12) */
	char err[384];
	char note[sizeof(((struct ct *)0)->note)];  /* c->note's, merged after the join */
};

static int load_lights(struct ct *c, int i, const struct lim_stop *stop, char *note,
		       size_t notelen, char *err, size_t errlen);

static void ct_lights_run(void *p)
{
	struct ct_lights_job *j = p;

	j->rc = 0;
	for (int i = j->first; j->rc == 0 && i < j->c->nmaps; i += j->step)
		j->rc = load_lights(j->c, i, j->stop, j->note, sizeof j->note, j->err,
				    sizeof j->err);
}

/* After a lights job: its error into err (0 or negative) and its note into
 * c->note unless one is there. */
static int ct_lights_done(struct ct *c, const struct ct_lights_job *j, char *err, size_t errlen)
{
	if (j->note[0] && !c->note[0])
		snprintf(c->note, sizeof c->note, "%s", j->note);
	if (j->rc < 0)
		snprintf(err, errlen, "%s", j->err);
	return j->rc < 0 ? j->rc : 0;
}

/* The stages' light maps where no WAD loader made them (built-in levels,
 * a grid): every other stage on a thread, when there is one and more than
 * one stage, the rest here (the built-in eight: 9 ms of the way to the
 * first frame, all here before). */
static int ct_lights_split(struct ct *c, const struct ct_spec *s, const struct lim_stop *stop,
			   char *err, size_t errlen)
{
	struct ct_lights_job here = { c, stop, 0, 2, 0, "", "" };
	struct ct_lights_job away = { c, stop, 1, 2, 0, "", "" };
	struct pool_task *task = NULL;
	int rc;

	if (c->nmaps < 2 || !s->task_start || !s->task_join ||
	    s->task_start(ct_lights_run, &away, &task) < 0) {
		task = NULL;
		here.step = 1;
	}
	ct_lights_run(&here);
	if (task)
		s->task_join(task);
	/* the lower stage's error first: here has stage 0 */
	rc = ct_lights_done(c, &here, err, errlen);
	if (rc == 0 && task)
		rc = ct_lights_done(c, &away, err, errlen);
	return rc;
}

/* The WADs' sounds, on a thread of their own from the moment the WADs are
 * mapped: they need nothing else. Their hash is not made here
 * (snd_set_hash: on its first use, after the first frame unless a
 * recording needs it before), which on Freedoom 1 is about 2 ms of serial
 * work off the way to the first frame. */
struct ct_sounds_job {
	struct ct *c;
	const struct wad *w;
	int rc;
};

static void ct_sounds_run(void *p)
{
	struct ct_sounds_job *j = p;

	/* the sounds are copied out: the mappings go after the join */
	j->rc = snd_load_wad(j->w, &j->c->sounds, j->c->sound_note, sizeof(j->c->sound_note));
}

/* The WADs' textures, stages and sounds; with lights, the stages' light
 * maps too (*lit set to 1 when they were made here). */
static int load_wads(struct ct *c, const struct ct_spec *s, const struct lim_stop *stop,
		     int *lit, char *err, size_t errlen)
{
	const uint8_t *bufs[CT_MAX_WADS] = { 0 };
	size_t lens[CT_MAX_WADS] = { 0 };
	uint8_t read[CT_MAX_WADS] = { 0 };  /* bufs[i] was read, not mapped */
	char names[64][9], picked[CT_MAX_STAGES][9];
	struct ct_lights_job job = { c, stop, 0, 1, 0, "", "" };
	struct ct_sounds_job snd = { c, NULL, 0 };
	struct pool_task *task = NULL, *snd_task = NULL;
	int snd_done = 0;
	int npicked = 0;
	struct wad *w = NULL;
	const char *name = "";
	int rc, i;

	rc = wad_new(&w);
	/* Mapped, not read: the file's pages stay the page cache's (never
	 * private memory), and only the lumps used are read from disk. */
	for (i = 0; rc == 0 && i < s->nwads; i++) {
		rc = io_map_file(s->wads[i], CT_FILE_MAX, &bufs[i], &lens[i]);
		if (rc == -ENODEV) {
			/* a filesystem that cannot map files (some network and
			 * FUSE ones): read it instead */
			uint8_t *b = NULL;

			rc = ct_read_file(s->wads[i], &b, &lens[i]);
			bufs[i] = b;
			read[i] = 1;
		}
		if (rc < 0)
			snprintf(err, errlen, "%s: %s", s->wads[i], strerror(-rc));
		else
			rc = wad_add(w, bufs[i], lens[i], s->wads[i], err, errlen);
		if (rc == 0)
			rc = ct_stopped(s, err, errlen);
	}
	if (rc == 0 && s->task_start && s->task_join) {
		snd.w = w;
		snd_done = s->task_start(ct_sounds_run, &snd, &snd_task) == 0;
	}
	/* Wall textures are composed once the maps say which they show (a
	 * grid level names its textures later: it gets them all). */
	if (rc == 0 && s->grid)
		rc = tex_load_wad_lim(w, stop, &c->tex, err, errlen);
	else if (rc == 0)
		rc = tex_load_wad_names(w, stop, &c->tex, err, errlen);
	if (rc == 0) {
		int nnames = map_list_wad(w, names, 64);
		if (nnames < 1) {
			snprintf(err, errlen, "%s: no maps in the WADs", s->wads[0]);
			rc = -ENOENT;
		} else if (s->map) {
			rc = ct_pick_maps(s->map, names, nnames > 64 ? 64 : nnames, picked, err,
					  errlen);
		} else {
			memcpy(picked[0], names[0], sizeof(picked[0]));
			rc = 1;
		}
		npicked = rc > 0 ? rc : 0;
		rc = rc < 0 ? rc : 0;
		name = picked[0];
	}
	for (i = 0; rc == 0 && !s->grid && i < npicked; i++) {
		rc = map_load_wad_lim(w, c->tex, picked[i], stop, &c->maps[i], err, errlen);
		if (rc == 0)
			c->nmaps++;
	}
	if (rc == 0 && !s->grid)   /* the loader takes the last marker of the name */
		snprintf(c->src, sizeof c->src, "%s", wad_file(w, wad_find(w, name)));
	if (rc == 0 && s->lights && c->nmaps > 0) {
		*lit = 1;
		/* without a thread the lights are made here, after the rest */
		if (s->task_start && s->task_join)
			s->task_start(ct_lights_run, &job, &task);
	}
	if (rc == 0) {
		/* one sky, the first map's (Doom changes it per episode) */
		tex_pick_sky(c->tex, name);
		if (!s->grid)
			rc = ct_compose(c, w, stop, err, errlen);
	}
	if (rc == 0 && !snd_done) {
		/* without a thread the sounds are read here */
		snd.w = w;
		ct_sounds_run(&snd);
		snd_done = 1;
	}
	if (snd_task)
		s->task_join(snd_task);
	if (rc == 0 && snd_done && snd.rc < 0) {
		rc = snd.rc;
		snprintf(err, errlen, "sounds: %s", strerror(-rc));
	}
	if (task)
		s->task_join(task);
	else if (*lit)
		ct_lights_run(&job);
	if (rc == 0 && *lit)
		rc = ct_lights_done(c, &job, err, errlen);
	if (rc == 0) {
		snprintf(c->what, sizeof(c->what), "%s%s %s", s->wads[s->nwads - 1],
			 s->nwads > 1 ? " (layered)" : "", s->grid ? "textures" : name);
		if (c->nmaps > 1) {
			size_t at = strlen(c->what);
			snprintf(c->what + at, sizeof(c->what) - at, " to %s (%d maps)",
				 picked[npicked - 1], npicked);
		}
	}
	/* The texture set, the sounds and the maps copied what they need: the
	 * mappings can go now. */
	wad_free(w);
	for (i = 0; i < CT_MAX_WADS; i++) {
		if (read[i])
			free((void *)(uintptr_t)bufs[i]);
		else
			io_unmap_file(bufs[i], lens[i]);
	}
	return rc;
}

static int load_grid(struct ct *c, const struct ct_spec *s, const struct lim_stop *stop,
		     char *err, size_t errlen)
{
	struct grid_names names;
	uint8_t *buf = NULL;
	const char *text;
	size_t len = 0;
	int rc;

	if (!c->tex) {
		rc = tex_builtin(&c->tex);
		if (rc < 0) {
			snprintf(err, errlen, "built-in textures: %s", strerror(-rc));
			return rc;
		}
	}
	if (strcmp(s->grid, "builtin") == 0) {
		text = grid_builtin_text(&len);
	} else {
		rc = ct_read_file(s->grid, &buf, &len);
		if (rc < 0) {
			snprintf(err, errlen, "%s: %s", s->grid, strerror(-rc));
			return rc;
		}
		text = (const char *)buf;
	}
	grid_names_from_tex(&names, c->tex);
	snprintf(c->src, sizeof c->src, "%s", s->grid);
	rc = grid_parse_lim(text, len, s->grid, &names, stop, &c->maps[0], err, errlen);
	c->nmaps = rc == 0;
	free(buf);
	if (rc == 0)
		snprintf(c->what, sizeof(c->what), "grid map %s", s->grid);
	return rc;
}

/* A map over a light-map limit is drawn without light maps (lights are
 * cosmetic; the cabinet keeps running), and c->note says so. */
static int load_lights(struct ct *c, int i, const struct lim_stop *stop, char *note,
		       size_t notelen, char *err, size_t errlen)
{
	struct lmap_light *lights;
	char why[160] = "";
	int n, rc;

	n = lmap_lights_from_map(c->maps[i], LMAP_DECOR, NULL, 0);
	if (i == 0)
		c->nlights = n;
	if (n <= 0)
		return 0;
	if (n > LMAP_MAX_LIGHTS) {
		rc = -E2BIG;
		snprintf(why, sizeof why, "%d lights, more than the limit of %d (LMAP_MAX_LIGHTS)",
			 n, LMAP_MAX_LIGHTS);
	} else {
		lights = calloc((size_t)n, sizeof(*lights));
		if (!lights)
			return -ENOMEM;
		lmap_lights_from_map(c->maps[i], LMAP_DECOR, lights, n);
		rc = lmap_new_lim(c->maps[i], lights, n, stop, &c->lms[i], why, sizeof why);
		free(lights);
	}
	if (rc == -E2BIG) {
		snprintf(note, notelen, "%s: %s: THINGS: %s: drawn without light maps", c->src,
			 c->maps[i]->name, why);
		return 0;
	}
	if (rc == -ECANCELED)
		snprintf(err, errlen, "%s: %s: THINGS: %s", c->src, c->maps[i]->name, why);
	else if (rc < 0)
		snprintf(err, errlen, "light maps of %s: %s", c->maps[i]->name, strerror(-rc));
	return rc;
}

/* The built-in stages: level `first` and every one after it. */
static int load_builtin(struct ct *c, int first, char *err, size_t errlen)
{
	int n = lvl_builtin_count(), rc;

	if (first < 1 || first > n) {
		snprintf(err, errlen, "built-in level %d: no such level (there are %d)", first, n);
		return -EINVAL;
	}
	/* The built-in levels' texture numbers index tex_builtin's set
	 * (map.h: lvl_builtin): made once, and every level's names resolved
	 * against it. */
	rc = tex_builtin(&c->tex);
	if (rc < 0) {
		snprintf(err, errlen, "built-in textures: %s", strerror(-rc));
		return rc;
	}
	for (int i = first - 1; i < n && c->nmaps < CT_MAX_STAGES && rc == 0; i++) {
		rc = lvl_builtin_for(i, c->tex, &c->maps[c->nmaps]);
		if (rc < 0)
			snprintf(err, errlen, "built-in level %d: %s", i + 1, strerror(-rc));
		else
			c->nmaps++;
	}
	if (rc < 0)
		return rc;
	snprintf(c->src, sizeof c->src, "built-in levels");
	snprintf(c->what, sizeof(c->what), "built-in levels %d..%d (%s first)", first,
		 first + c->nmaps - 1, c->maps[0]->name);
	return 0;
}

/* The built-in sounds (no WAD named): synthesized on a thread of their own
 * while the levels, their textures and light maps are made here (8 ms of
 * the 40 a built-in start took before its first frame). */
static void ct_builtin_sounds_run(void *p)
{
	struct ct_sounds_job *j = p;

	j->rc = snd_builtin(&j->c->sounds);
}

int ct_load(struct ct *c, const struct ct_spec *s, char *err, size_t errlen)
{
	struct lim_stop stop = { ct_stop_fn, (void *)(uintptr_t)s->stop, NULL };
	const struct lim_stop *hook = s->stop ? &stop : NULL;
	struct ct_sounds_job snd = { c, NULL, 0 };
	struct pool_task *snd_task = NULL;
	int rc, lit = 0;

	memset(c, 0, sizeof(*c));
	rc = ct_stopped(s, err, errlen);
	if (rc == 0 && s->nwads == 0 && s->task_start && s->task_join &&
	    s->task_start(ct_builtin_sounds_run, &snd, &snd_task) < 0)
		snd_task = NULL;
	if (rc == 0 && s->nwads > 0)
		rc = load_wads(c, s, hook, &lit, err, errlen);
	if (rc == 0 && s->grid)
		rc = load_grid(c, s, hook, err, errlen);
	else if (rc == 0 && s->nwads == 0)
		rc = load_builtin(c, s->level, err, errlen);
	if (rc == 0 && s->lights && !lit)
		rc = ct_lights_split(c, s, hook, err, errlen);
	/* joined before anything is freed: the thread writes c->sounds */
	if (snd_task) {
		s->task_join(snd_task);
		if (rc == 0 && snd.rc < 0) {
			rc = snd.rc;
			snprintf(err, errlen, "built-in sounds: %s", strerror(-rc));
		}
	}
	if (rc == 0 && !c->sounds) {
		/* no thread: made here */
		rc = snd_builtin(&c->sounds);
		if (rc < 0)
			snprintf(err, errlen, "built-in sounds: %s", strerror(-rc));
	}
	c->map = c->maps[0];
	if (rc < 0)
		ct_free(c);
	return rc;
}

struct lmap *ct_lmap_for(const struct ct *c, const struct map *m)
{
	for (int i = 0; i < c->nmaps; i++)
		if (c->maps[i] == m)
			return c->lms[i];
	return NULL;
}

void ct_free(struct ct *c)
{
	for (int i = 0; i < c->nmaps; i++) {
		lmap_free(c->lms[i]);
		map_free(c->maps[i]);
	}
	tex_free(c->tex);
	snd_free(c->sounds);
	memset(c, 0, sizeof(*c));
}
