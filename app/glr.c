/*
 * glr: loading the OSMesa renderer plugin (contract in glr.h).
 */
#include "app/glr.h"

#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#ifndef ARCADED_LIBDIR
#define ARCADED_LIBDIR "/usr/local/lib/arcaded"
#endif

/* dlsym returns void *; a function pointer is copied out of it bytewise
 * (ISO C has no conversion between the two). */
static int glr_sym(struct glr *g, const char *name, void *fn, size_t size, char *why,
		   size_t whylen)
{
	void *p = dlsym(g->so, name);

	if (!p) {
		snprintf(why, whylen, "%s: no symbol %s", g->path, name);
		return -ELIBBAD;
	}
	memcpy(fn, &p, size);
	return 0;
}

/* Tries one file; 0 when loaded, else appends the reason to why. */
static int glr_try(struct glr *g, const char *path, char *why, size_t whylen)
{
	size_t used = strlen(why);
	const char *err;

	snprintf(g->path, sizeof(g->path), "%s", path);
	g->so = dlopen(path, RTLD_NOW | RTLD_LOCAL);
	if (g->so)
		return 0;
	err = dlerror();
	snprintf(why + used, whylen - used, "%s%s", used ? "; " : "", err ? err : path);
	return -ENOENT;
}

int glr_can_jit(void)
{
	long page = sysconf(_SC_PAGESIZE);
	size_t len = page > 0 ? (size_t)page : 4096;
	void *p = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
	int rc = 0;

	if (p == MAP_FAILED)
		return -errno;
	if (mprotect(p, len, PROT_READ | PROT_EXEC) != 0)
		rc = -errno;
	munmap(p, len);
	return rc;
}

int glr_load(struct glr *g, char *why, size_t whylen)
{
	char exe[PATH_MAX], path[PATH_MAX + 32];
	ssize_t n;
	int rc = -ENOENT;

	memset(g, 0, sizeof(*g));
	if (whylen)
		why[0] = '\0';
	rc = glr_can_jit();
	if (rc < 0) {
		/* llvmpipe would fail inside LLVM, long after the load */
		snprintf(why, whylen,
			 "this process may not make memory executable (mprotect PROT_EXEC: %s), "
			 "and llvmpipe compiles its shaders at run time; under arcaded.service that "
			 "is MemoryDenyWriteExecute=yes: the drop-in in docs/systemd.md allows it",
			 strerror(-rc));
		return rc;
	}
	rc = -ENOENT;
	n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
	if (n > 0) {
		char *slash;
		exe[n] = '\0';
		slash = strrchr(exe, '/');
		if (slash) {
			*slash = '\0';
			snprintf(path, sizeof(path), "%s/%s", exe, GLR_FILE);
			rc = glr_try(g, path, why, whylen);
		}
	}
	if (rc < 0)
		rc = glr_try(g, ARCADED_LIBDIR "/" GLR_FILE, why, whylen);
	if (rc < 0)
		return rc;
	if ((rc = glr_sym(g, "rgl_new", &g->create, sizeof(g->create), why, whylen)) < 0 ||
	    (rc = glr_sym(g, "rgl_free", &g->destroy, sizeof(g->destroy), why, whylen)) < 0 ||
	    (rc = glr_sym(g, "rgl_render", &g->render, sizeof(g->render), why, whylen)) < 0 ||
	    (rc = glr_sym(g, "rgl_name", &g->name, sizeof(g->name), why, whylen)) < 0) {
		dlclose(g->so);
		g->so = NULL;
		return rc;
	}
	if (whylen)
		why[0] = '\0';
	return 0;
}

void glr_unload(struct glr *g)
{
	if (!g || !g->so)
		return;
	dlclose(g->so);
	g->so = NULL;
}
