/*
 * r_game: the camera and the sprites the renderer draws for a sim, and
 * the map's things as sprites for still views (r_game.c).
 */
#ifndef ARCADED_ENGINE_R_GAME_H
#define ARCADED_ENGINE_R_GAME_H

#include "engine/game/g_game.h"

struct map;
struct r_sprite;
struct r_view;
struct sim;
struct tex_set;

/* The camera for the current tick. */
void r_game_view(const struct sim *s, struct r_view *v);

/* Fills out (up to max) with the sprites of the current tick for
 * r_render: enemies (frames by state: standing A, walking, attacking with
 * a full-bright firing frame, pain, dying into the corpse), pickups not
 * taken, the map's lights and decorations (cycling their frames), and the
 * puff (PUFF) or blood (BLUD) of the last shot for R_PUFF_TICKS ticks. Sprite
 * numbers come from t by Doom's names; a name t lacks is drawn as a
 * stand-in of t (POSS for enemies, MEDI, CLIP, COLU, BAR1), and failing
 * that as a number past t's sprites (the renderer's fallback checker); a
 * corpse frame t lacks is not drawn. Returns how many were written (0 when
 * t is NULL). */
int r_game_sprites(const struct sim *s, const struct tex_set *t, struct r_sprite *out, int max);

/* The most sprites r_game_sprites can produce for a sim on map m: enemies,
 * pickups, the map's things and the puff. */
#define R_GAME_SPRITES_MAX(m) (G_MAX_ENEMIES + G_MAX_PICKUPS + (int)(m)->num_things + 1)

/* The map's things as sprites for a still view (viewers, the renderer
 * tests and the cross-check; the game builds its own from the sim, see
 * r_game_sprites): every thing with a sprite in t, players and
 * invisible things left out, standing on its sector's floor (hanging ones from the
 * ceiling), full-bright when it gives light. out needs room for
 * m->num_things entries. Returns how many were stored. */
int r_map_sprites(const struct map *m, const struct tex_set *t, struct r_sprite *out);

#endif
