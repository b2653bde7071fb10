/*
 * mesh: 3D meshes for props and pickups, read from the OBJ subset
 * (mesh.c; docs/maps.md, "Meshes").
 *
 * The subset: `v x y z` (a vertex), `vt u [v [w]]` (a texture coordinate),
 * `vn x y z` (a normal), `f` with three or four corners (a triangle or a
 * quad, split into two triangles 0-1-2 and 0-2-3), each corner `v`,
 * `v/vt`, `v//vn` or `v/vt/vn` with 1-based indices or negative ones
 * counting back from the last defined; `#` comments, blank lines and the
 * naming lines `o`, `g` and `s` (ignored). Anything else (materials,
 * lines, curves, exponents in numbers) is refused. Numbers are decimals
 * (sign, digits, optional fraction; no exponent), read into 16.16 rounded
 * to the nearest. Texture coordinates and normals are checked (counts,
 * indices) but not kept: the renderers light each triangle by its own
 * geometric normal.
 *
 * Axes: OBJ's y is up (what modelling tools write); a mesh vertex
 * (x, y, z) of the file is (x, -z, y) in map space (x east, y north, z
 * up), so a model facing OBJ's -z faces north before its thing's rotation.
 * One OBJ unit is one map unit. The origin is the thing's position on the
 * floor.
 *
 * Winding: a face's corners go counter-clockwise seen from outside (OBJ's
 * convention); the renderers draw only the side a triangle faces.
 */
#ifndef ARCADED_ENGINE_MESH_H
#define ARCADED_ENGINE_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"

/* Limits of one mesh (-E2BIG beyond them): far above a prop's needs and
 * small enough that a frame's mesh work stays bounded. */
#define MESH_MAX_VERTS 1024u            /* v lines */
#define MESH_MAX_AUX 4096u              /* vt and vn lines, each */
#define MESH_MAX_TRIS 2048u             /* triangles after quads are split */
#define MESH_MAX_COORD 512              /* |coordinate| in map units */

struct mesh_vert {
	fx_t x, y, z;                  /* map space, relative to the thing */
};

struct mesh_tri {
	uint16_t v[3];                 /* vertex indices, counter-clockwise */
};

struct mesh {
	const struct mesh_vert *v;
	const struct mesh_tri *t;
	uint32_t nv, nt;
	fx_t radius;                   /* largest |x|, |y| of a vertex */
	fx_t zmin, zmax;               /* lowest and highest vertex z */
};

/* Parses OBJ text buf (len bytes, need not be NUL-terminated, any bytes)
 * named name (for messages) into *out (arrays owned: mesh_free). Returns 0,
 * -EINVAL with "NAME:LINE: reason" in err for a bad line ("f needs 3 or 4
 * corners", "vertex index 9 out of range 1..8", "bad number 'x'",
 * "unsupported statement 'usemtl'", ...) or a file without faces,
 * -E2BIG with "NAME:LINE: more than N vertices" (a MESH_MAX_* limit), or
 * -ENOMEM. On error *out is empty. */
int mesh_parse(const char *name, const char *buf, size_t len, struct mesh *out, char *err,
	       size_t errlen);

/* Meshes for thing types, loaded at run time (the app's game.meshes
 * directory, app/mdir.h): type `type` is drawn as mesh m in colour
 * (r, g, b) instead of its built-in mesh or sprite. */
struct mesh_thing {
	uint16_t type;                 /* Doom thing type (editor number) */
	uint8_t r, g, b;               /* colour, 0..255 each */
	struct mesh m;
};

/* A table of them, borrowed by the renderers for a frame (app/view.h
 * passes it to r_game_sprites): at most one entry per type, at most
 * MESH_SET_MAX entries. */
#define MESH_SET_MAX 64u
struct mesh_set {
	const struct mesh_thing *v;
	uint32_t n;
};

/* The entry of s for thing type `type`, or NULL (also for s NULL). */
const struct mesh_thing *mesh_set_find(const struct mesh_set *s, uint16_t type);

/* Frees the arrays of a mesh mesh_parse filled (not of a built-in one);
 * NULL-safe; leaves *m empty. */
void mesh_free(struct mesh *m);

#endif
