/*
 * keep: settings, scores, books and the flight recorder (contract in
 * keep.h).
 */
#include "app/keep.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/say.h"
#include "app/tape.h"
#include "config/cfg.h"
#include "config/fr.h"
#include "config/st.h"
#include "engine/game/g_game.h"
#include "engine/sound/snd.h"
#include "input/rec.h"

/* The payload checks st_load_usable and st_save_usable take: a scores or
 * books copy that this build cannot decode (a newer format byte, say) is
 * a bad copy, so .prev is loaded instead and the copy is never rotated
 * into .prev. */
static int keep_scores_usable(const void *p, size_t len)
{
	struct g_scores s;

	return g_scores_decode(p, len, &s);
}

static int keep_books_usable(const void *p, size_t len)
{
	struct g_books b;

	return g_books_decode(p, len, &b);
}

/* Loads a state file's payload; NULL when missing or unusable (reported). */
static void *keep_load(struct keep *k, const char *name, st_usable_fn usable, size_t *len)
{
	char msg[256] = "";
	void *buf = NULL;
	int rc = st_load_usable(k->dir, name, usable, &buf, len, NULL, msg, sizeof(msg));

	if (msg[0] && rc != -ENOENT)
		say_warn("%s/%s: %s", k->dir, name, msg);
	if (rc < 0) {
		if (rc != -ENOENT)
			say_warn("%s/%s: %s; using defaults", k->dir, name, strerror(-rc));
		return NULL;
	}
	return buf;
}

static void keep_save(struct keep *k, const char *name, st_usable_fn usable, const void *data,
		      size_t len)
{
	void *old = NULL;
	size_t olen;
	int rc = st_save_usable(k->dir, name, usable, data, len);

	if (rc >= 0)
		return;
	/* A failed save leaves both copies as they were: say so only when one
	 * of them is a copy that loads. */
	if (st_load_usable(k->dir, name, usable, &old, &olen, NULL, NULL, 0) == 0)
		say_err("%s/%s: not saved: %s (the previous copy is intact)", k->dir, name,
			strerror(-rc));
	else
		say_err("%s/%s: not saved: %s (and there is no previous copy)", k->dir, name,
			strerror(-rc));
	free(old);
}

void keep_start(struct keep *k, const char *dir, int on, struct sim *s, const struct ct *ct,
		const struct sim_settings *set)
{
	struct g_scores scores, *sp = NULL;
	struct g_books books, *bp = NULL;
	size_t len = 0;
	void *buf;

	k->dir = dir;
	k->on = on;
	if (on) {
		buf = keep_load(k, "scores", keep_scores_usable, &len);
		if (buf && g_scores_decode(buf, len, &scores) == 0)
			sp = &scores;
		else if (buf)
			say_warn("%s/scores: not a high-score table; using the defaults", dir);
		free(buf);
		buf = keep_load(k, "books", keep_books_usable, &len);
		if (buf && g_books_decode(buf, len, &books) == 0)
			bp = &books;
		else if (buf)
			say_warn("%s/books: not bookkeeping; starting from zero", dir);
		free(buf);
	}
	sim_init_stages(s, (const struct map *const *)ct->maps, ct->nmaps, set, sp, bp);
	k->set_gen = s->set_gen;
	k->scores_gen = s->scores_gen;
	k->books_gen = s->books_gen;
}

/* Settings changed in the service menu go to the state directory's
 * settings.ini (a state file whose payload is INI text), the layer main.c
 * reads after /etc/arcaded. */
static void keep_settings(struct keep *k, const struct sim *s, int w, int h)
{
	const struct sim_settings *st = &s->set;
	char ini[400];
	int n = snprintf(ini, sizeof(ini),
			 "[game]\ncoins_per_credit = %u\nfreeplay = %s\ndifficulty = %u\nlives = %u\n"
			 "volume = %u\nattract_sound = %u\nstage_time = %u\nidle_out = %s\n"
			 "autoaim = %s\n"
			 "render_width = %d\nrender_height = %d\n",
			 st->coins_per_credit, st->freeplay ? "yes" : "no", st->difficulty,
			 st->lives, st->volume, st->attract_sound,
			 st->stage_time == G_STAGE_TIME_OFF ? 0
			 : st->stage_time ? st->stage_time : G_STAGE_TIME_DEFAULT,
			 cfg_idle_name(st->idle_out), st->free_aim ? "off" : "on", w, h);
	keep_save(k, "settings.ini", NULL, ini, (size_t)n);
}

void keep_tick(struct keep *k, const struct sim *s, int w, int h)
{
	uint8_t buf[G_SCORES_BYTES > G_BOOKS_BYTES ? G_SCORES_BYTES : G_BOOKS_BYTES];

	if (s->menu.res != k->res) {
		/* the frame is already w x h (app/scene.c follows the menu) */
		k->res = s->menu.res;
		if (k->on)
			keep_settings(k, s, w, h);
	}
	if (!k->on)
		return;
	if (s->set_gen != k->set_gen) {
		k->set_gen = s->set_gen;
		keep_settings(k, s, w, h);
	}
	if (s->scores_gen != k->scores_gen) {
		k->scores_gen = s->scores_gen;
		g_scores_encode(&s->scores, buf);
		keep_save(k, "scores", keep_scores_usable, buf, G_SCORES_BYTES);
	}
	if (s->books_gen != k->books_gen) {
		k->books_gen = s->books_gen;
		g_books_encode(&s->books, buf);
		keep_save(k, "books", keep_books_usable, buf, G_BOOKS_BYTES);
	}
}

/* ---- flight recorder ---------------------------------------------------- */

void keep_flight_open(struct keep *k, int keep, int max_mb, uint64_t map_hash,
		      const struct ct_spec *content, uint32_t audio_rate, struct snd_set *sounds)
{
	char dir[CFG_PATH_MAX + 16], msg[512] = "";
	int rc;

	k->map_hash = map_hash;
	k->content = content;
	k->audio_rate = audio_rate;
	k->sounds = sounds;
	if (!k->on || keep <= 0)
		return;
	snprintf(dir, sizeof(dir), "%s/recordings", k->dir);
	rc = fr_open(dir, keep, (uint64_t)max_mb << 20, &k->fr, msg, sizeof(msg));
	if (msg[0])
		say_warn("%s: %s", dir, msg);
	if (rc < 0) {
		say_warn("%s: %s; games are not recorded", dir, strerror(-rc));
		k->fr = NULL;
	}
}

/* The snapshot buffer, made at the first START rather than at the open:
 * sim_snapshot_size walks a whole zeroed sim (0.5 ms here), which the
 * first frame need not wait for. 0, or -ENOMEM logged (that game is then
 * not recorded; the next START tries again). */
static int keep_snap_room(struct keep *k)
{
	if (k->snap)
		return 0;
	k->snap_len = sim_snapshot_size();
	k->snap = malloc(k->snap_len);
	if (!k->snap) {
		say_err("flight recorder: %s; this game is not recorded", strerror(ENOMEM));
		return -ENOMEM;
	}
	return 0;
}

void keep_flight_before(struct keep *k, const struct sim *s, const struct sim_cmd *cmd)
{
	k->snap_taken = 0;
	if (k->fr && !k->game && s->mode == SIM_ATTRACT &&
	    (cmd->buttons & (SIM_BT_START | SIM_BT_START2)) && keep_snap_room(k) == 0) {
		sim_snapshot(s, k->snap);
		k->snap_taken = 1;
		k->snap_plays = s->plays;
	}
}

static void keep_flight_finish(struct keep *k)
{
	int rc = rec_writer_close(k->game);
	k->game = NULL;
	if (rc < 0)
		say_err("flight recorder: %s", strerror(-rc));
	rc = fr_end_game(k->fr, rc == 0);
	if (rc < 0)
		say_err("flight recorder: %s", strerror(-rc));
}

void keep_flight_after(struct keep *k, const struct sim *s, const struct sim_cmd *cmd, int w,
		       int h, uint64_t audio_hash)
{
	if (!k->fr)
		return;
	/* a game began: plays grew (a START that opened the service menu on
	 * the same tick is no game) */
	if (!k->game && k->snap_taken && s->plays != k->snap_plays) {
		char path[CFG_PATH_MAX + 96];
		struct rec_header hd;
		int rc;

		/* the settings as the service menu left them; state and
		 * audio hashes are cheap, frame hashes are not */
		tape_header(&hd, k->map_hash, &s->set, w, h, k->content, k->audio_rate,
			    snd_set_hash(k->sounds));
		hd.hash_flags = REC_HAS_STATE | REC_HAS_AUDIO;
		hd.snapshot = k->snap;
		hd.snapshot_len = (uint32_t)k->snap_len;
		rc = fr_begin_game(k->fr, time(NULL), path, sizeof(path));
		if (rc < 0) {
			say_err("flight recorder: %s", strerror(-rc));
			return;
		}
		rc = rec_writer_open(path, &hd, &k->game);
		if (rc < 0) {
			/* give the slot back, or every later game would be refused */
			say_err("flight recorder: %s: %s", path, strerror(-rc));
			k->game = NULL;
			fr_end_game(k->fr, 0);
			return;
		}
	}
	if (!k->game)
		return;
	struct rec_tick t = { *cmd, sim_hash(s), 0, audio_hash };
	if (rec_writer_put_tick(k->game, &t) < 0) {
		say_err("flight recorder: write failed; this game is not kept whole");
		keep_flight_finish(k);
		return;
	}
	/* back in attract, or left for the service menu: the game is over */
	if (s->mode == SIM_ATTRACT || s->mode == SIM_SERVICE)
		keep_flight_finish(k);
}

void keep_close(struct keep *k, const struct sim *s, uint64_t ticks)
{
	if (k->game)
		keep_flight_finish(k);   /* a game cut by a stop is kept too */
	fr_close(k->fr);
	k->fr = NULL;
	free(k->snap);
	k->snap = NULL;
	if (k->on && ticks) {
		/* play and power-on time count up without a generation bump */
		uint8_t buf[G_BOOKS_BYTES];
		g_books_encode(&s->books, buf);
		keep_save(k, "books", keep_books_usable, buf, G_BOOKS_BYTES);
	}
}
