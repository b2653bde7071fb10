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
#include "app/wiz.h"
#include "display/dp.h"
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
			say("render threads: %s; drawing on one", strerror(-prc));
			s->pool = NULL;
		} else {
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
		say("renderer %dx%d: %s", w, h, strerror(-rc));
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
			say("renderer gl %dx%d: %s", w, h, gerr[0] ? gerr : strerror(-rc));
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
	s->frame.h = h;
	view_set_renderer(&s->view, r);
	return 0;
}

int scene_open_display(struct scene *s, int headless)
{
	const struct cfg *c = s->cfg;
	struct dp_config dc;
	char why[1024] = "";
	int rc;

	memset(&dc, 0, sizeof(dc));
	dc.backend = c->display.backend;
	/* Scripts and replays run headless unless a display is named. */
	if (headless && strcmp(dc.backend, "auto") == 0)
		dc.backend = c->display.file[0] ? "file" : "null";
	dc.device = c->display.device;
	dc.card = c->display.card;
	dc.mode = c->display.mode;
	dc.buffers = c->display.buffers;
	dc.tty = c->display.tty;
	dc.file = c->display.file;
	dc.file_w = c->display.file_width;
	dc.file_h = c->display.file_height;
	dc.file_stride = c->display.file_stride;
	dc.file_format = c->display.file_format;
	dc.rotate = c->display.rotate;
	dc.scale = c->display.fill ? DP_SCALE_FILL : DP_SCALE_INTEGER;
	dc.render_w = s->frame.w;
	dc.render_h = s->frame.h;
	dc.par = s->pool ? &s->ppar : NULL;
	rc = dp_open(&dc, &s->dpb, &s->dp, why, sizeof(why));
	if (rc < 0) {
		say("display %s: %s", dc.backend, why[0] ? why : strerror(-rc));
		return rc;
	}
	say("display: %s", s->dpb->describe(s->dp));
	if (why[0])
		say("display: skipped %s", why);
	s->dpb->set_palette(s->dp, s->ct->tex->pal.rgb);
	return 0;
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
	       const struct wiz *wiz)
{
	int rc;

	if (wiz)
		wiz_draw(wiz, &s->ct->tex->pal, &s->frame);
	else
		view_draw(&s->view, sim, under, &s->frame);
	rc = s->dpb->present(s->dp, s->frame.px, s->frame.w, s->frame.h, s->frame.pitch);
	if (rc < 0 && s->present_errors++ == 0)
		say("display %s: present: %s", s->dpb->name, strerror(-rc));
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
		say("display %s: %s", s->dpb->name, strerror(-n));
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
