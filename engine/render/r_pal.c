/*
 * r_pal: the palette-colour texture set (r_main.h), the compatibility path
 * for maps whose texture numbers are palette indices. One allocation holds
 * the set, its pictures' pixels and its tables, so r_pal_set_free is one
 * free.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/pal.h"
#include "engine/map/tex.h"
#include "engine/render/r_main.h"

struct r_palset {
	struct tex_set t;              /* first: the pointer handed out */
	struct tex_pic textures[256];
	struct tex_flat flats[256];
	uint8_t colour[256];
	uint16_t tex_xlat[256], flat_xlat[256];
};

int r_pal_set_new(struct tex_set **out)
{
	struct r_palset *s = calloc(1, sizeof(*s));
	struct tex_set *t;

	*out = NULL;
	if (!s)
		return -ENOMEM;
	t = &s->t;
	pal_builtin(&t->pal);
	strcpy(s->textures[0].name, "-");
	for (int i = 0; i < 256; i++) {
		s->colour[i] = (uint8_t)i;
		s->tex_xlat[i] = s->flat_xlat[i] = (uint16_t)i;
		memset(s->flats[i].px, i, sizeof(s->flats[i].px));
		if (i > 0) {
			s->textures[i].w = s->textures[i].h = 1;
			s->textures[i].px = &s->colour[i];
		}
	}
	t->textures = s->textures;
	t->num_textures = 256;
	t->flats = s->flats;
	t->num_flats = 256;
	t->sky_flat = -1;
	t->sky_tex = 0;
	t->tex_xlat = s->tex_xlat;
	t->flat_xlat = s->flat_xlat;
	t->fallback_tex = 0;
	t->fallback_flat = 0;
	*out = t;
	return 0;
}

void r_pal_set_free(struct tex_set *t)
{
	/* t is the first member of its struct r_palset */
	free(t);
}
