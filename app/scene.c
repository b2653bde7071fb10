/*
 * scene: frame, renderers, display (contract in scene.h).
 */
#include "app/scene.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app/ct.h"
#include "app/pool.h"
#include "app/say.h"
#include "app/pick.h"
#include "app/wiz.h"
#include "display/dp.h"
#include "input/hp.h"
#include "input/in.h"
#include "engine/game/menu.h"
#include "engine/game/sim.h"
#include "engine/map/tex.h"

static void scene_gl_world(void *ctx, const struct map *m, const struct tex_set *t,
			   const struct r_view *v, const struct r_sprite *spr, int nspr,
			   struct r_frame *f)
{
	struct scene *s = ctx;

	s->glr.render(s->gl, m, t, v, spr, nspr, f);
}

int scene_init(struct scene *s, const struct cfg *c, const struct ct *ct, int gl, int w, int h)
{
	int rc;

	s->cfg = c;
	s->ct = ct;
	s->use_gl = gl;
	rc = view_init(&s->view, ct, NULL, c->display.rotate);
	if (rc < 0)
		return rc;
	/* render threads: game.render_threads, 0 = one per CPU; frames are
	 * the same bytes whatever the count */
	int n = c->game.render_threads ? c->game.render_threads : pool_cpus();
	if (n > 1) {
		int prc = pool_new(n, &s->pool);
		if (prc < 0) {
			say_warn("render threads: %s; drawing on one", strerror(-prc));
			s->pool = NULL;
		} else {
			/* a thread per CPU: each keeps its own (pool.h says why) */
			if (n == pool_cpus() && (prc = pool_pin(s->pool)) < 0)
				say_warn("render threads: not pinned to CPUs: %s", strerror(-prc));
			pool_r_par(s->pool, &s->par);
			pool_px_par(s->pool, &s->ppar);
			s->view.par = &s->par;
		}
	}
	return scene_resize(s, w, h);
}

int scene_resize(struct scene *s, int w, int h)
{
	struct r_ctx *r = NULL;
	uint8_t *px;
	int rc = r_new(w, h, &r);

	if (rc < 0) {
		say_err("renderer %dx%d: %s", w, h, strerror(-rc));
		return rc;
	}
	px = calloc((size_t)w * (size_t)h, 1);
	if (!px) {
		r_free(r);
		return -ENOMEM;
	}
	if (s->pool)
		r_set_par(r, &s->par);
	if (s->use_gl) {
		/* the OSMesa renderer, the software one's oracle, as the game's */
		char gerr[1024] = "";
		struct rgl_ctx *g = NULL;
		rc = s->glr.so ? 0 : glr_load(&s->glr, gerr, sizeof(gerr));
		if (rc == 0)
			rc = s->glr.create(w, h, &g, gerr, sizeof(gerr));
		if (rc < 0) {
			say_err("renderer gl %dx%d: %s", w, h, gerr[0] ? gerr : strerror(-rc));
			r_free(r);
			free(px);
			return rc;
		}
		if (s->gl)
			s->glr.destroy(s->gl);
		s->gl = g;
		s->view.world = scene_gl_world;
		s->view.world_ctx = s;
		say("renderer: gl (%s, %s)", s->glr.name(g), s->glr.path);
	}
	r_free(s->r);
	free(s->frame.px);
	s->r = r;
	s->frame.px = px;
	s->frame.w = s->frame.pitch = w;
	s->frame.rec = NULL;
	s->frame.h = h;
	view_set_renderer(&s->view, r);
	return 0;
}

/* The display configuration (headless: unless one is named, the file
 * framebuffer when configured, else none). */
static void scene_dp_config(const struct scene *s, int headless, struct dp_config *dc)
{
	const struct cfg *c = s->cfg;

	memset(dc, 0, sizeof(*dc));
	dc->backend = c->display.backend;
	/* Scripts and replays run headless unless a display is named. */
	if (headless && strcmp(dc->backend, "auto") == 0)
		dc->backend = c->display.file[0] ? "file" : "null";
	dc->device = c->display.device;
	dc->card = c->display.card;
	dc->mode = c->display.mode;
	dc->buffers = c->display.buffers;
	dc->tty = c->display.tty;
	dc->file = c->display.file;
	dc->file_w = c->display.file_width;
	dc->file_h = c->display.file_height;
	dc->file_stride = c->display.file_stride;
	dc->file_format = c->display.file_format;
	dc->rotate = c->display.rotate;
	dc->scale = c->display.fill ? DP_SCALE_FILL : DP_SCALE_INTEGER;
	dc->render_w = s->frame.w;
	dc->render_h = s->frame.h;
	dc->par = s->pool ? &s->ppar : NULL;
}

/* Whether a display be opened for dc is a stand-in for a missing one:
 * "auto" fell through to the display that shows nothing. Named, that
 * one is what was asked for. */
static int scene_stand_in(const struct dp_config *dc, const struct dp_backend *be)
{
	return (be->flags & DP_SHOWS_NOTHING) && strcmp(dc->backend, "auto") == 0;
}

/* Takes display dp of be: the content's palette, the log. */
static void scene_take(struct scene *s, const struct dp_backend *be, struct dp *dp)
{
	s->dpb = be;
	s->dp = dp;
	s->present_errors = 0;
	s->dpb->set_palette(s->dp, s->ct->tex->pal.rgb);
}

/* Begins waiting for the display (why it is missing): the stand-in is
 * shown, the display nodes are watched. */
static int scene_wait(struct scene *s, const struct dp_config *dc, const char *why)
{
	const char *nodes[HP_MAX_NODES];
	char hwhy[256] = "", where[160] = "";
	int n = dp_nodes(nodes, HP_MAX_NODES);

	if (!s->dp) {
		const struct dp_backend *be;
		struct dp *dp;
		int rc = dp_open_stand_in(dc, &be, &dp);
		if (rc < 0) {
			say_err("display: %s; %s", why, strerror(-rc));
			return rc;
		}
		scene_take(s, be, dp);
	}
	s->waiting = 1;
	snprintf(s->missing, sizeof(s->missing), "%s", why);
	for (int i = 0; i < n; i++)
		in_say(where, sizeof(where), "%s%s*", i ? ", " : "", nodes[i]);
	if (hp_open(nodes, n, HP_INOTIFY, &s->hp, hwhy, sizeof(hwhy)) < 0) {
		s->hp = NULL;
		say_warn("display: none: %s; the game runs unseen; looking again every second (no "
			 "notices: %s)", why, hwhy);
	} else {
		say_warn("display: none: %s; the game runs unseen; looking again when %s appear "
			 "and every second", why, where[0] ? where : "display nodes");
	}
	return 0;
}

int scene_open_display(struct scene *s, int headless)
{
	struct dp_config dc;
	const struct dp_backend *be;
	struct dp *dp;
	char why[1024] = "";
	int rc;

	scene_dp_config(s, headless, &dc);
	rc = dp_open(&dc, &be, &dp, why, sizeof(why));
	if (rc < 0 && headless) {
		say_err("display %s: %s", dc.backend, why[0] ? why : strerror(-rc));
		return rc;
	}
	if (rc < 0) {
		char missing[1100];
		snprintf(missing, sizeof(missing), "%s: %s", dc.backend, why[0] ? why : strerror(-rc));
		return scene_wait(s, &dc, missing);
	}
	scene_take(s, be, dp);
	if (!headless && scene_stand_in(&dc, be))
		return scene_wait(s, &dc, why[0] ? why : "no display backend opened");
	say("display: %s", s->dpb->describe(s->dp));
	if (why[0])
		say("display: skipped %s", why);
	return 0;
}

enum scene_poll scene_poll_display(struct scene *s, uint64_t now_ns)
{
	struct dp_config dc;
	const struct dp_backend *be;
	struct dp *dp;
	char why[1024] = "", missing[sizeof(s->missing)];
	int rc;

	if (!s->waiting)
		return SCENE_SAME;
	if (!hp_poll(s->hp) && now_ns < s->retry_ns)
		return SCENE_SAME;
	s->retry_ns = now_ns + SCENE_RETRY_NS;
	scene_dp_config(s, 0, &dc);
	rc = dp_open(&dc, &be, &dp, why, sizeof(why));
	if (rc == 0 && !scene_stand_in(&dc, be)) {
		/* found: the stand-in goes, the display takes the frames */
		s->dpb->close(s->dp);
		scene_take(s, be, dp);
		s->waiting = 0;
		hp_close(s->hp);
		s->hp = NULL;
		say("display: %s (it was missing: %s)", s->dpb->describe(s->dp), s->missing);
		return SCENE_ACQUIRED;
	}
	if (rc == 0) {
		be->close(dp);
		snprintf(missing, sizeof(missing), "%s", why[0] ? why : "no display backend opened");
	} else {
		snprintf(missing, sizeof(missing), "%s: %s", dc.backend, why[0] ? why : strerror(-rc));
	}
	if (strcmp(missing, s->missing) == 0)
		return SCENE_SAME;
	snprintf(s->missing, sizeof(s->missing), "%s", missing);
	say_warn("display: still none: %s", s->missing);
	return SCENE_STILL_MISSING;
}

void scene_follow_menu(struct scene *s, const struct sim *sim)
{
	int w = s->cfg->game.render_width, h = s->cfg->game.render_height;

	if (sim->menu.res == s->res)
		return;
	s->res = sim->menu.res;
	if (s->res)
		menu_res_size(s->res, &w, &h);
	if (scene_resize(s, w, h) == 0)
		say("render size %dx%d", w, h);
}

int scene_show(struct scene *s, const struct sim *sim, const struct sim *under,
	       const struct wiz *wiz, const struct pick *pick)
{
	int rc;

	if (wiz)
		wiz_draw(wiz, &s->ct->tex->pal, &s->frame);
	else if (pick)
		pick_draw(pick, &s->ct->tex->pal, &s->frame);
	else
		view_draw(&s->view, sim, under, &s->frame);
	rc = s->dpb->present(s->dp, s->frame.px, s->frame.w, s->frame.h, s->frame.pitch);
	if (rc < 0 && s->present_errors++ == 0)
		say_err("display %s: present: %s", s->dpb->name, strerror(-rc));
	if (rc == 0 && !s->waiting)
		s->shown++;
	return rc;
}

int scene_wait_fd(struct scene *s)
{
	return s->dpb && s->dpb->wait_fd ? s->dpb->wait_fd(s->dp) : -1;
}

int scene_flips(struct scene *s, struct dp_flip *done, int max)
{
	int n;

	if (!s->dpb || !s->dpb->event)
		return 0;
	n = s->dpb->event(s->dp, done, max);
	if (n < 0 && s->event_errors++ == 0)
		say_warn("display %s: %s", s->dpb->name, strerror(-n));
	return n < 0 ? 0 : n;
}

const char *scene_status(struct scene *s)
{
	return s->dpb && s->dpb->status ? s->dpb->status(s->dp) : NULL;
}

void scene_close_display(struct scene *s)
{
	if (s->dpb)
		s->dpb->close(s->dp);
	s->dpb = NULL;
	s->dp = NULL;
	hp_close(s->hp);
	s->hp = NULL;
	s->waiting = 0;
}

void scene_free(struct scene *s)
{
	scene_close_display(s);
	r_free(s->r);
	if (s->gl)
		s->glr.destroy(s->gl);
	glr_unload(&s->glr);
	pool_free(s->pool);
	free(s->frame.px);
	view_free(&s->view);
}
