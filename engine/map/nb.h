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

/* Replaces m's segs, subsectors and nodes (and may grow m's vertices with
 * split points; a rebuild appends new ones). One seg per line side, split
 * where partitions cross it; subsectors are convex; nodes are listed
 * children first (the root is the last) with exact child bounding boxes;
 * seg.offset and seg.angle are those of the seg's line side. Deterministic:
 * the same map gives the same arrays. Vertex coordinates must be within
 * MAP_COORD_MAX. Returns 0, -EINVAL (err says why, e.g. "line 3: zero
 * length") or -ENOMEM; on error m's BSP arrays are left empty and its
 * vertices as they were. err may be NULL. */
int nb_build(struct map *m, char *err, size_t errlen);

#endif
