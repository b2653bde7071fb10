/*
 * tex: the graphics a map is drawn with: palette and light tables, wall
 * textures, flats, sprites and the sky, either loaded from WADs (PLAYPAL,
 * COLORMAP, PNAMES, TEXTURE1/TEXTURE2 composed from patches, flats between
 * F_START/F_END, sprites between S_START/S_END) or the project's own
 * procedural set (tex_builtin), so the game needs no WAD at all.
 *
 * Numbering, as map sides and sectors store it (map.h):
 *   - wall texture 0 is "no texture" (Doom's "-"); 1..num_textures-1 real;
 *     texture 0 is a 1x1 fully transparent picture, never meant to be drawn;
 *   - flat 0 is a valid flat; sky ceilings use the flat sky_flat.
 * From a WAD, textures 1.. are TEXTURE1's entries then TEXTURE2's, in lump
 * order, then the fallback checker (fallback_tex); flats are in lump order
 * over every F_START/F_END (FF_START/FF_END) range, a later flat of the same
 * name replacing the earlier one's pixels in place, then the fallback flat.
 * Sprite picture 0 is the fallback picture: a frame or rotation with no
 * lump points at it, so every tex_sprframe entry is drawable.
 * Pictures are decoded once at load into plain arrays (no format parsing
 * while drawing): wall textures and sprites column-major, flats row-major.
 * Animations (Doom's fixed table of animated textures and flats) are
 * resolved per tick by tex_animate, which the renderer reads as
 * tex_set.tex_xlat / flat_xlat (identity when nothing animates).
 */
#ifndef ARCADED_ENGINE_TEX_H
#define ARCADED_ENGINE_TEX_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/core/pal.h"

struct lim_stop;
struct map;
struct wad;

/* A decoded picture. px is column-major: column x is px[x * h .. x * h +
 * h - 1]. opaque is NULL when every pixel is opaque, else w*h bytes laid
 * out like px, 1 where the pixel is drawn (masked textures, sprites). */
struct tex_pic {
	char name[9];
	int16_t w, h;
	int16_t left, top;             /* sprite offsets (Doom picture format) */
	uint8_t *px;
	uint8_t *opaque;
};

#define TEX_FLAT_SIZE 64

struct tex_flat {
	char name[9];
	uint8_t px[TEX_FLAT_SIZE * TEX_FLAT_SIZE];   /* row-major */
};

/* One sprite frame: for each of 8 rotations (0 = facing the viewer, then
 * counter-clockwise in 45 degree steps as Doom's A1..A8), the picture and
 * whether it is drawn mirrored. A frame with a single rotation-0 picture
 * has all eight entries equal. */
struct tex_sprframe {
	uint16_t pic[8];               /* index into tex_set.sprpics */
	uint8_t flip[8];
};

struct tex_sprite {
	char name[5];                  /* e.g. "TROO" */
	int num_frames;                /* frames A, B, ... */
	struct tex_sprframe *frames;
};

/* An animation: count textures (or flats) with consecutive indices from
 * first, cycling every TEX_ANIM_TICKS (Doom's animated table, existing
 * ranges only). */
struct tex_anim {
	uint8_t flat;                  /* 1: flats, 0: wall textures */
	uint16_t first, count;
};

#define TEX_ANIM_TICKS 14              /* Doom's 8 tics at 35 Hz, at 60 Hz */

struct tex_set {
	struct pal pal;                /* palette and PAL_LIGHTS colormaps */
	struct tex_pic *textures;      /* [0] is the empty "-" texture */
	int num_textures;
	struct tex_flat *flats;
	int num_flats;
	int sky_flat;                  /* index of F_SKY1, -1 if none */
	int sky_tex;                   /* wall texture drawn as the sky: SKY1, else
					* fallback_tex; always valid. The app may set
					* it to tex_find(t, "SKY2") etc. per episode. */
	struct tex_pic *sprpics;
	int num_sprpics;
	struct tex_sprite *sprites;
	int num_sprites;
	uint16_t *tex_xlat;            /* current texture per texture (animation) */
	uint16_t *flat_xlat;           /* current flat per flat */
	uint32_t missing;              /* names that fell back (counted, drawn as a checker) */
	/* Added for the map loader and animation (after the fields above, so
	 * their layout is unchanged): */
	int fallback_tex;              /* the checker texture an unknown name becomes */
	int fallback_flat;             /* the checker flat an unknown flat name becomes */
	struct tex_anim *anims;
	int num_anims;
	/* Name indexes (tex_set_finish): textures 1..num_textures-1,
	 * flats 0..num_flats-1 and sprites 0..num_sprites-1 sorted by name,
	 * then number; NULL until then (tex_find, tex_find_flat and
	 * tex_find_sprite then scan). */
	uint16_t *tex_by_name;
	uint16_t *flat_by_name;
	uint16_t *spr_by_name;
	/* each index's names as numbers in the same order (tex.c tex_key):
	 * what a lookup compares */
	uint64_t *tex_keys;
	uint64_t *flat_keys;
	uint64_t *spr_keys;
};

/* Steps of one tex_load_wad (issue 13 item 8): a step is a column, post or
 * pixel composed (tex_pic_draw), a flat name compared, or a sprite name
 * compared while building frames. Freedoom 2's whole set takes 17.0
 * million (16 times fewer); one texture of 2,000 patches sharing one
 * tall column took 77 s without a bound and now stops here in under a
 * second. */
#define TEX_MAX_STEPS ((uint64_t)1 << 28)

/* Loads everything from the layered WAD set. The set owns copies of all it
 * uses (decoded pictures, flats, names): the WADs and their file images may
 * be freed once it is loaded. Problems that leave a
 * texture unusable (a missing patch, a bad TEXTURE1 entry) make that
 * texture a fallback checker and are counted, not fatal; a WAD without
 * PLAYPAL or with a truncated one is -EINVAL (err names the lump). A set
 * that takes more than TEX_MAX_STEPS is -E2BIG, err naming the file, the
 * lump and entry being composed, and the limit; stop (may be NULL, lim.h)
 * is polled, and when it says stop the load ends with -ECANCELED.
 * tex_load_wad is tex_load_wad_lim without a stop hook. */
int tex_load_wad_lim(const struct wad *w, const struct lim_stop *stop, struct tex_set **out,
		     char *err, size_t errlen);
int tex_load_wad(const struct wad *w, struct tex_set **out, char *err, size_t errlen);

/* tex_load_wad_lim, but the wall textures and sprite pictures are not
 * decoded: each has its name and size (and a sprite its offsets: all
 * tex_find, tex_map_heights, the sprite frames and the map loader need)
 * and no pixels, so tex_wall_index and tex_sprite_pic say it cannot be
 * drawn until tex_compose makes it. All of Freedoom 1's 900 textures
 * take 14 MiB and its 850 sprite pictures 9 MiB; a map shows 50 to 150
 * textures and a few dozen sprites. The loader that knows its maps only
 * after resolving their names against the set loads the names, then the
 * maps, then composes what tex_want_map and tex_want_sprite mark. Flats
 * (4 KiB each) are read whole. */
int tex_load_wad_names(const struct wad *w, const struct lim_stop *stop, struct tex_set **out,
		       char *err, size_t errlen);

/* Marks in want (t->num_textures bytes, set to 1) the wall textures map m
 * can show: its sides' textures, their switch partners (a switch shows the
 * other when pressed), every member of a wall animation any of them is
 * in, and t->sky_tex (pick the sky first). Never marks texture 0. */
void tex_want_map(const struct tex_set *t, const struct map *m, uint8_t *want);

/* Marks in want_pics (t->num_sprpics bytes, set to 1) every picture of
 * the sprite called name (4 characters, "POSS"): each frame and rotation.
 * An unknown name marks nothing. */
void tex_want_sprite(const struct tex_set *t, const char *name, uint8_t *want_pics);

/* Composes the textures marked in want, and the sprite pictures marked in
 * spr_want (NULL: none), that have no pixels yet, from w: the WADs t was
 * loaded from by tex_load_wad_names (-EINVAL with err naming TEXTURE1 or
 * S_START when their lists do not number the same textures or pictures).
 * What tex_load_wad_lim does for one picture happens here: a bad one
 * becomes the checker, counted in missing; the step count and the stop
 * hook give -E2BIG or -ECANCELED with err naming the lump. What is left
 * unmarked stays without pixels (the renderers skip it). */
int tex_compose(struct tex_set *t, const struct wad *w, const uint8_t *want,
		const uint8_t *spr_want, const struct lim_stop *stop, char *err, size_t errlen);

/* The project's own procedural set: palette, colormaps, textures, flats,
 * sky and sprites, made by code. 0 or -ENOMEM. */
int tex_builtin(struct tex_set **out);

void tex_free(struct tex_set *t);

/* Index of a texture / flat / sprite by name (case-insensitive); "-" is
 * texture 0; -1 if unknown. The first of equal names wins. Textures and
 * flats: O(log n) once the set is finished. */
int tex_find(const struct tex_set *t, const char *name);
int tex_find_flat(const struct tex_set *t, const char *name);
int tex_find_sprite(const struct tex_set *t, const char *name);

/* The picture a wall shows for texture number num (a sidedef's), after
 * the animation's translation: its index (> 0), 0 for "no texture" (num 0),
 * or -1 when it cannot be drawn (out of range, empty or without pixels):
 * the renderers then draw their fallback checker and count it missing.
 * One rule for the software and the OSMesa renderer. */
int tex_wall_index(const struct tex_set *t, uint16_t num);

/* The picture frame `frame` of sprite `sprite` shows from angle view (the
 * direction from the viewer to the thing minus the thing's facing; Doom's
 * eight rotations): its index in sprpics, with *flip set when it is drawn
 * mirrored; or -1 when it cannot be drawn (unknown sprite or frame, a
 * picture out of range, empty or without pixels): the renderers skip the
 * thing and count it missing. One rule for the software and the OSMesa
 * renderer. */
int tex_sprite_pic(const struct tex_set *t, unsigned sprite, unsigned frame, ang_t view,
		   int *flip);

/* The other state of a switch texture: for texture number num named
 * SW1name its SW2name and the other way round (every switch pair of Doom
 * and Freedoom is named so), when the set has it; else 0. */
int tex_switch_partner(const struct tex_set *t, uint16_t num);

/* Fills m->tex_h with the height of each of t's wall textures (map.h), for
 * the floors that rise by a lower texture's height. 0 or -ENOMEM. */
int tex_map_heights(const struct tex_set *t, struct map *m);

/* Sets sky_tex for map `map` by Doom's rule, when that texture exists:
 * ExMy -> SKYx; MAP01-11 -> SKY1, MAP12-20 -> SKY2, MAP21 on -> SKY3;
 * otherwise (and for other names) sky_tex stays as it is. */
void tex_pick_sky(struct tex_set *t, const char *map);

/* Advances animations to game tick `tick` (Doom: every 8 tics at 35 Hz;
 * here every TEX_ANIM_TICKS at 60 Hz), updating tex_xlat and flat_xlat:
 * member k (0-based) of an animation of n shows member (tick /
 * TEX_ANIM_TICKS + k) % n. A pure function of tick. */
void tex_animate(struct tex_set *t, uint32_t tick);

#endif
