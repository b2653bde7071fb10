/*
 * glr: the OSMesa renderer (engine/gl, `--renderer gl`) as a plugin the
 * daemon loads only when asked. Linking OSMesa into the daemon would map
 * and relocate Mesa's LLVM on every start: about 43 MiB of resident memory
 * a cabinet that draws with the software renderer never uses.
 *
 * The plugin, arcaded-gl.so, is engine/gl built as a shared object linked
 * with OSMesa; the engine functions it calls resolve against the daemon,
 * which exports its symbols (-rdynamic). It is looked for next to the
 * running executable (a build tree: build/arcaded-gl.so), then in
 * ARCADED_LIBDIR (make install: $(PREFIX)/lib/arcaded).
 *
 * OSMesa draws with llvmpipe, which compiles its shaders to machine code
 * at run time: it needs memory it may write and then execute. A process
 * that may not make memory executable (systemd's
 * MemoryDenyWriteExecute=yes, which the shipped unit sets) would fail
 * inside LLVM; glr_load looks first and refuses with the reason.
 *
 * Ownership: glr_load fills a struct glr the caller owns; glr_unload
 * (NULL-safe, idempotent) closes the plugin once nothing of it is in use.
 */
#ifndef ARCADED_APP_GLR_H
#define ARCADED_APP_GLR_H

#include <stddef.h>

#include "engine/gl/rgl.h"

#define GLR_FILE "arcaded-gl.so"

struct glr {
	void *so;                        /* dlopen handle, NULL: not loaded */
	int (*create)(int w, int h, struct rgl_ctx **out, char *err, size_t errlen);
	void (*destroy)(struct rgl_ctx *g);
	void (*render)(struct rgl_ctx *g, const struct map *m, const struct tex_set *t,
		       const struct r_view *v, const struct r_sprite *spr, int nspr,
		       struct r_frame *f);
	const char *(*name)(const struct rgl_ctx *g);
	char path[512];                  /* where it was loaded from */
};

/* Loads the plugin. 0, or -ENOENT / -ELIBBAD with why naming each place
 * tried and dlopen's or dlsym's message, or the error of glr_can_jit
 * (nothing loaded) with why saying what stops it and what allows it. */
int glr_load(struct glr *g, char *why, size_t whylen);

/* Whether this process may make memory it wrote executable, as a JIT
 * does (an anonymous page mapped read-write, then turned read-execute).
 * 0 yes, else the -errno that refused it (-EPERM under
 * MemoryDenyWriteExecute=yes). */
int glr_can_jit(void);

void glr_unload(struct glr *g);

#endif
