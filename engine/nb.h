/*
 * nb: the project's own BSP node builder.
 *
 * Builds segs, subsectors and nodes for a map that has level geometry but no
 * BSP (built-in levels, grid imports, maps saved without nodes). Exact
 * integer arithmetic: the same input gives the same tree on every compiler
 * and CPU. Split points are new vertices appended to map.vertices.
 */
#ifndef ARCADED_ENGINE_NB_H
#define ARCADED_ENGINE_NB_H

#include <stddef.h>

struct map;

/* Replaces m's segs, subsectors and nodes (and may grow m's vertices).
 * Returns 0, -EINVAL (err says why, e.g. a zero-length line) or -ENOMEM;
 * on error m's BSP arrays are left empty. */
int nb_build(struct map *m, char *err, size_t errlen);

#endif
