/*
 * view: draws one frame of the game from the sim state: the current
 * stage's 3D view with its light maps and sprites (when the mode shows
 * the world), then the HUD, page or service menu over it. The daemon and
 * the cross-build replayer (tests/xbuild/replay.c) both draw through here,
 * so their frames are the same by construction. Only engine code is
 * called: no platform headers.
 */
#ifndef ARCADED_APP_VIEW_H
#define ARCADED_APP_VIEW_H

struct ct;
struct map;
struct mesh_set;
struct r_ctx;
struct r_frame;
struct r_par;
struct r_sprite;
struct sim;
struct tex_set;
struct hud_diag;

struct r_view;

#include "engine/render/r_game.h"
#include "engine/ui/hud.h"
#include "engine/ui/v_video.h"

/* Draws the world (r_render's shape): the software renderer by default;
 * the daemon may put the OSMesa renderer here (--renderer gl). */
typedef void (*view_world_fn)(void *ctx, const struct map *m, const struct tex_set *t,
			      const struct r_view *v, const struct r_sprite *spr, int nspr,
			      struct r_frame *f);

struct view {
	struct r_ctx *r;           /* borrowed; its size is the frame's */
	view_world_fn world;       /* NULL: r_render on r */
	void *world_ctx;
	const struct ct *ct;       /* borrowed: texture set and light maps */
	struct r_sprite *spr;      /* owned: room for the largest stage's sprites */
	int spr_max;
	const struct map *lit;     /* the stage whose light maps r has */
	struct r_live live;        /* owned: the stage as the sim has changed it */
	int rotate;                /* the display's rotation (service menu) */
	const struct r_par *par;   /* optional, borrowed: threads for the HUD's large
				    * darkened areas (the renderer's pool) */
	const struct hud_diag *diag;   /* optional, borrowed: the service menu's
					* diagnostics text (hud_env.diag), NULL none */
	const char *notice;        /* optional, borrowed: hud_env.notice (app/op.h) */
	const struct mesh_set *meshes; /* optional, borrowed: meshes loaded at run time
					* (game.meshes, app/mdir.h), NULL none */
	struct v_list hud;         /* owned: the frame's HUD, recorded and then
				    * replayed by the strips (view_draw) */
	struct r_frame *hud_f;     /* the frame being drawn, for the replays */
	struct hud_colours colours;    /* the HUD's colours in the content's palette,
					* made once (hud_env.colours) */
};

/* Prepares v for the content's stages. 0 or -ENOMEM. */
int view_init(struct view *v, const struct ct *ct, struct r_ctx *r, int rotate);

/* A new renderer context (after a resize): light maps are set again. */
void view_set_renderer(struct view *v, struct r_ctx *r);

/* Draws s into f (f's size must be r's). Animated textures are advanced to
 * the sim's tick first. under (may be NULL): a sim whose world and HUD are
 * drawn first, under s's page (the attract demo, app/demo.h).
 *
 * Over the software renderer's world, the HUD is recorded first (v_list)
 * and replayed by each strip's thread over that strip's columns as soon
 * as they are final (r_set_strip_done): with a pool, no thread then draws
 * it alone after the others. The bytes are those of drawing it after the
 * world (v_replay's contract); if the recording fails (out of memory) it
 * is drawn that way. */
void view_draw(struct view *v, const struct sim *s, const struct sim *under,
	       struct r_frame *f);

void view_free(struct view *v);

#endif
