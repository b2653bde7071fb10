/*
 * tex_local: what the tex_*.c files share (not for other modules).
 *
 * A set is built in three steps: tex_set_alloc with every count known,
 * filling the arrays (pictures through tex_pic_new / tex_pic_draw /
 * tex_pic_seal), then tex_set_finish, which adds what both the WAD loader
 * and the built-in set need (sprite frames from picture names, the
 * animation table, the identity translations, sky and fallbacks).
 */
#ifndef ARCADED_ENGINE_TEX_LOCAL_H
#define ARCADED_ENGINE_TEX_LOCAL_H

#include <stddef.h>
#include <stdint.h>

#include "engine/map/tex.h"

struct lim;

/* Limits that keep a hostile WAD from asking for unbounded memory: a side
 * of a picture, and the bytes of all pictures of one set together (px plus
 * opaque masks). Freedoom 2 needs about 30 MB. Past them a picture becomes
 * the fallback, counted in missing. */
#define TEX_MAX_SIDE 4096
#define TEX_BUDGET ((uint64_t)256 << 20)

#define TEX_CHECKER_SIDE 64

/* Copies up to 8 chars of src (stopping at NUL) upper-cased into out,
 * NUL-padded to 9 bytes. */
void tex_name(char out[9], const char *src);

/* Allocates a set with num_textures textures (index 0 included), num_flats
 * flats and num_sprpics sprite pictures (index 0 included), all zeroed,
 * sky_flat -1. 0 or -ENOMEM. */
int tex_set_alloc(struct tex_set **out, int num_textures, int num_flats, int num_sprpics);

/* Makes p a w x h picture called name, all transparent index 0 with an
 * opaque mask of zeros, charging *budget (bytes left). 0, -ENOMEM, or
 * -E2BIG when the size is beyond TEX_MAX_SIDE or the budget (p is then
 * left empty). */
int tex_pic_new(struct tex_pic *p, const char *name, int w, int h, uint64_t *budget);

/* Draws a Doom-format picture (the lump bytes d, len) into p with its top
 * left at (x, y), clipped to p; marks drawn pixels opaque. Columns whose
 * posts run past the lump are cut there. Tall patches: a post whose
 * topdelta is not above the previous one continues from it (DeePsea).
 * Takes from lim (may be NULL: unbounded, for the built-in set) one step
 * per column and per post and one per pixel of a post: a lump whose
 * columns all share one long column costs its width times its posts.
 * 0, -EINVAL when the header or column table is bad (nothing drawn), or
 * lim's error (-E2BIG, -ECANCELED; the picture is then partly drawn). */
int tex_pic_draw(struct tex_pic *p, const uint8_t *d, size_t len, int x, int y, struct lim *lim);

/* Size and offsets from a picture header; -EINVAL when bad (size <= 0 or
 * past TEX_MAX_SIDE, or the column table past the lump). */
int tex_pic_header(const uint8_t *d, size_t len, int *w, int *h, int *left, int *top);

/* Frees the opaque mask when every pixel is opaque (opaque = NULL). */
void tex_pic_seal(struct tex_pic *p);

/* Frees p's arrays (not p). */
void tex_pic_clear(struct tex_pic *p);

/* Makes p the fallback checker (8-pixel squares of colours a and b), w x
 * h, fully opaque; the checker has no budget (it is small or the size of
 * a texture that was in budget). 0 or -ENOMEM. */
int tex_pic_checker(struct tex_pic *p, const char *name, int w, int h, uint8_t a, uint8_t b);

void tex_flat_checker(struct tex_flat *f, const char *name, uint8_t a, uint8_t b);

/* Builds t->sprites from the names of sprpics 1.. ("TROOA1", "TROOA2A8":
 * 4-char sprite, frame letter A.., rotation 0..8, optionally a second
 * frame and rotation drawn mirrored); later pictures override earlier
 * entries. Rotations and frames without a picture point at picture 0,
 * counted in t->missing. Then the animation table, identity tex_xlat /
 * flat_xlat, sky_flat (F_SKY1) and sky_tex (SKY1, else fallback_tex).
 * Then the name indexes of tex_find and tex_find_flat. fallback_tex /
 * fallback_flat must be set. Sprite building compares every picture name
 * with every sprite's: it takes a step per comparison from lim (may be
 * NULL). 0, -ENOMEM, or lim's error. */
int tex_set_finish(struct tex_set *t, struct lim *lim);

/* The built-in set's sprite pictures (tex_bspr.c): how many there are,
 * and making them into pics[0 .. count-1] (names, pixels, offsets),
 * charging *budget. 0 or a negative errno from tex_pic_new. */
int tex_bspr_count(void);
int tex_bspr_make(struct tex_pic *pics, uint64_t *budget);

#endif
