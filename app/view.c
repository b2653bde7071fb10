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

void view_draw(struct view *v, const struct sim *s, const struct sim *under,
	       struct r_frame *f)
{
	struct tex_set *tex = v->ct->tex;
	struct hud_env env = { &tex->pal, tex, v->rotate, v->par, v->diag, v->notice };
	struct r_view rv;

	if (under) {
		/* the demo's own frame, then this sim's banner over it */
		view_draw(v, under, NULL, f);
		hud_draw(s, &env, f);
		return;
	}
	if (s->map != v->lit) {
		/* a new stage: its own light maps and Doom's sky for its name */
		r_set_lmap(v->r, ct_lmap_for(v->ct, s->map));
		tex_pick_sky(tex, s->map->name);
		v->lit = s->map;
	}
	/* Animated textures follow the game tick, so replays see the same. */
	tex_animate(tex, s->tick);
	if (hud_world(s)) {
		int n = r_game_sprites(s, tex, v->meshes, v->spr, v->spr_max);
		const struct map *m = r_game_live(&v->live, s, tex);
		r_game_view(s, f->w, &rv);
		if (v->world)
			v->world(v->world_ctx, m, tex, &rv, v->spr, n, f);
		else
			r_render(v->r, m, tex, &rv, v->spr, n, f);
	}
	hud_draw(s, &env, f);
}

void view_free(struct view *v)
{
	free(v->spr);
	v->spr = NULL;
	r_live_free(&v->live);
}
