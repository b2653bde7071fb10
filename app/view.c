#include "app/view.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app/ct.h"
#include "engine/game/g_game.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/render/r_game.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud.h"

int view_init(struct view *v, const struct ct *ct, struct r_ctx *r, int rotate)
{
	memset(v, 0, sizeof(*v));
	v->ct = ct;
	v->r = r;
	v->rotate = rotate;
	/* the palette is the content's for the daemon's life */
	hud_colours(&ct->tex->pal, &v->colours);
	for (int i = 0; i < ct->nmaps; i++)
		if (R_GAME_SPRITES_MAX(ct->maps[i]) > v->spr_max)
			v->spr_max = R_GAME_SPRITES_MAX(ct->maps[i]);
	v->spr = calloc((size_t)v->spr_max, sizeof(*v->spr));
	return v->spr ? 0 : -ENOMEM;
}

void view_set_renderer(struct view *v, struct r_ctx *r)
{
	v->r = r;
	v->lit = NULL;
}

/* r_set_strip_done: the recorded HUD over the strip's columns, unless the
 * recording ran out of memory (then it is drawn whole after the world;
 * the recording has returned before the first call: r_set_beside_walk). */
static void view_strip_done(void *arg, int x0, int x1)
{
	struct view *v = arg;

	if (!v->hud.failed)
		v_replay(v->hud_f, &v->hud, x0, x1);
}

/* w's HUD or page, then banner's (the attract banner over the demo; may
 * be NULL), into f: drawn, or recorded when f->rec is set. */
static void view_hud(const struct sim *w, const struct sim *banner, const struct hud_env *env,
		     struct r_frame *f)
{
	hud_draw(w, env, f);
	if (banner)
		hud_draw(banner, env, f);
}

/* What view_beside makes. */
struct view_rec {
	struct view *v;
	const struct sim *w, *banner;
	const struct hud_env *env;
	struct r_frame *f;             /* f->rec the list */
};

/* r_set_beside_walk: while the renderer walks, on any of the pool's
 * threads, the world's sprites listed (r_beside_sprites) and the HUD
 * recorded. It only reads the sims, the textures and the meshes, and
 * writes v->spr and v->hud (a recording draws nothing and never runs the
 * pool: v_remap_par records too), none of which the walk touches, so it
 * may run inside the pool's batch beside the walk. */
static void view_beside(void *arg)
{
	struct view_rec *vr = arg;
	struct view *v = vr->v;
	int n = r_game_sprites(vr->w, v->ct->tex, v->meshes, v->spr, v->spr_max);

	r_beside_sprites(v->r, v->spr, n);
	view_hud(vr->w, vr->banner, vr->env, vr->f);
}

void view_draw(struct view *v, const struct sim *s, const struct sim *under,
	       struct r_frame *f)
{
	struct tex_set *tex = v->ct->tex;
	struct hud_env env = { &tex->pal, tex, v->rotate, v->par, v->diag, v->notice,
			       &v->colours };
	/* the sim whose world shows: the demo's under a banner */
	const struct sim *w = under ? under : s, *banner = under ? s : NULL;
	struct r_frame rf = *f;
	struct r_view rv;
	struct view_rec vr = { v, w, banner, &env, &rf };
	const struct map *m;
	int replay;

	if (w->map != v->lit) {
		/* a new stage: its own light maps and Doom's sky for its name */
		r_set_lmap(v->r, ct_lmap_for(v->ct, w->map));
		tex_pick_sky(tex, w->map->name);
		v->lit = w->map;
	}
	/* Animated textures follow the game tick, so replays see the same. */
	tex_animate(tex, w->tick);
	if (!hud_world(w)) {
		view_hud(w, banner, &env, f);
		return;
	}
	m = r_game_live(&v->live, w, tex);
	r_game_view(w, f->w, &rv);
	if (v->world) {
		/* another renderer: the HUD after it */
		int n = r_game_sprites(w, tex, v->meshes, v->spr, v->spr_max);

		v->world(v->world_ctx, m, tex, &rv, v->spr, n, f);
		replay = 0;
	} else {
		/* the sprites listed and the HUD (the demo's, then the banner)
		 * recorded beside the walk, the HUD as a list the strips draw
		 * (view_strip_done) */
		v_list_reset(&v->hud);
		rf.rec = &v->hud;
		v->hud_f = f;
		r_set_beside_walk(v->r, view_beside, &vr);
		r_set_strip_done(v->r, view_strip_done, v);
		r_render(v->r, m, tex, &rv, NULL, 0, f);
		r_set_beside_walk(v->r, NULL, NULL);
		r_set_strip_done(v->r, NULL, NULL);
		/* out of memory: the list is not whole, so after the world */
		replay = !v->hud.failed;
	}
	if (!replay)
		view_hud(w, banner, &env, f);
}

void view_free(struct view *v)
{
	free(v->spr);
	v->spr = NULL;
	v_list_free(&v->hud);
	r_live_free(&v->live);
}
