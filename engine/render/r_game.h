/*
 * r_game: the camera and the sprites the renderer draws for a sim, and
 * the map's things as sprites for still views (r_game.c).
 */
#ifndef ARCADED_ENGINE_R_GAME_H
#define ARCADED_ENGINE_R_GAME_H

#include <stdint.h>

#include "engine/game/g_game.h"
#include "engine/map/map.h"
#include "engine/map/mesh.h"

struct map;
struct r_sprite;
struct r_view;
struct sim;
struct tex_set;

/* The map as a sim has it now, for the renderers (both draw a struct
 * map): a shallow copy of the current stage map whose sectors carry the
 * sim's heights, floor flats and light (g_world.h) and whose sides show
 * the switches' other textures (SW1/SW2, tex_switch_partner) and the
 * scrolling walls' offsets (line 48 left, Boom's 85 right: a unit a Doom
 * tic). Owns its arrays (r_live_free); the stage map is borrowed. */
struct r_live {
	struct map map;
	struct map_sector *sectors;
	struct map_side *sides;
	uint32_t cap_sectors, cap_sides;
};

/* Fills l from s (t: the texture set, for the switch pairs; may be NULL)
 * and returns &l->map; s->map itself when the arrays cannot grow (the
 * frame then shows the map as loaded). */
const struct map *r_game_live(struct r_live *l, const struct sim *s, const struct tex_set *t);

/* NULL-safe; frees l's arrays. */
void r_live_free(struct r_live *l);

/* The camera for the current tick, for a frame w pixels wide: the
 * player's pitch (vertical aim) becomes the shear, so that the line of
 * sight along the pitch is the middle row (focal length w / 2). */
void r_game_view(const struct sim *s, int w, struct r_view *v);

/* Fills out (up to max) with the sprites of the current tick for
 * r_render: enemies (frames by state: standing A, walking, attacking with
 * a full-bright firing frame, pain, dying into the corpse), pickups not
 * taken, the map's lights and decorations (cycling their frames), the
 * missiles (BAL1, full bright: A and B flying, C..E exploding; the puff
 * stands in for a set without BAL1), and the
 * puff (PUFF) or blood (BLUD) of the last shot for R_PUFF_TICKS ticks. Sprite
 * numbers come from t by Doom's names; a name t lacks is drawn as a
 * stand-in of t (POSS for enemies, MEDI, CLIP, COLU, BAR1), and failing
 * that as a number past t's sprites (the renderer's fallback checker); a
 * corpse frame t lacks is not drawn. Pickups and props with a mesh are
 * that mesh (r_game_mesh; meshes: those loaded at run time, borrowed, may
 * be NULL). Returns how many were written (0 when t is NULL). Reads only
 * s, t and meshes and writes only out, so it may run on another thread
 * while the renderer walks the map (app/view.c does, r_set_beside_walk). */
int r_game_sprites(const struct sim *s, const struct tex_set *t, const struct mesh_set *meshes,
		   struct r_sprite *out, int max);

/* Marks in want_pics (tex_want_sprite) every sprite r_game_sprites may
 * draw on map m: each thing's own sprite (enemies and pickups come only
 * from the map's things) and the fixed stand-ins, puff, blood and the missile. For a
 * set loaded by tex_load_wad_names. */
void r_game_want(const struct tex_set *t, const struct map *m, uint8_t *want_pics);

/* The most sprites r_game_sprites can produce for a sim on map m: enemies,
 * pickups, missiles, the map's things and the puff. */
#define R_GAME_SPRITES_MAX(m) \
	(G_MAX_ENEMIES + G_MAX_PICKUPS + G_MAX_MISSILES + (int)(m)->num_things + 1)

/* The map's things as sprites for a still view (viewers, the renderer
 * tests and the cross-check; the game builds its own from the sim, see
 * r_game_sprites): every thing with a sprite in t, players and
 * invisible things left out, standing on its sector's floor (hanging ones from the
 * ceiling), full-bright when it gives light. out needs room for
 * m->num_things entries. Returns how many were stored. */
int r_map_sprites(const struct map *m, const struct tex_set *t, struct r_sprite *out);

/* As r_map_sprites, but the things the game draws as built-in meshes (the
 * keys, the floor lamp: r_game_mesh without loaded meshes) are those meshes, on their sector's
 * floor, turned as the game turns them at tick `tick`, whether or not t
 * has their sprite (the cross-check's scene). out needs room for
 * m->num_things entries. Returns how many were stored. */
int r_map_things(const struct map *m, const struct tex_set *t, uint32_t tick, struct r_sprite *out);

/* When thing type `type` is drawn as a mesh: the one ms has for it
 * (loaded at run time, in its own colour; r_sprite.mp points into ms,
 * which must outlive the frame; ms may be NULL), else a built-in one (the
 * key pickups, cards and skulls, in their key's colour; the floor lamp
 * 2028 in brass),
 * fills *out with it standing at (x, y, z), turned a quarter turn a second
 * by the tick alone (frames stay a function of the sim's state), in t's
 * palette colour, lit by its sector (not full bright: the Lambert term
 * shows its shape), and returns 1; else 0 with *out untouched. The one
 * rule for the game's sprites (r_game_sprites) and the still views'
 * (r_map_things). */
int r_game_mesh(const struct tex_set *t, const struct mesh_set *ms, uint16_t type, uint32_t tick,
		fx_t x, fx_t y, fx_t z, struct r_sprite *out);

/* The built-in colour of thing type `type`'s mesh into (r, g, b) and 1,
 * or 0 (untouched) when it has no built-in mesh: the colour a loaded mesh
 * without its own colour takes (app/mdir.h). */
int r_game_mesh_colour(uint16_t type, int *r, int *g, int *b);

#endif
