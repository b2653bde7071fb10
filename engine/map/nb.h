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
#include <stdint.h>

struct lim_stop;
struct map;

/* Limits on one build (issue 13 item 8). Lines that all cross each other
 * make the splits grow as lines^2: 2,004 of them took 57 s and 180 MB
 * before these limits, 30,004 never finished; now both stop at
 * NB_MAX_STEPS in about 3 s. Freedoom's largest map, freedoom2 MAP12
 * (10,884 lines), rebuilt takes 17.7 million steps (15 times fewer) and
 * 3.8 MB (17 times less).
 *   steps: seg classifications against partitions, and the links walked
 *          to find a line's earlier split points (a few ns each);
 *   bytes: the builder's working sets and its output (segs, subsectors,
 *          nodes, split vertices) at their peak. */
#define NB_MAX_STEPS ((uint64_t)1 << 28)
#define NB_MAX_BYTES ((uint64_t)64 << 20)

/* Replaces m's segs, subsectors and nodes (and may grow m's vertices with
 * split points; a rebuild appends new ones). One seg per line side, split
 * where partitions cross it; subsectors are convex; nodes are listed
 * children first (the root is the last) with exact child bounding boxes;
 * seg.offset and seg.angle are those of the seg's line side. Deterministic:
 * the same map gives the same arrays. Vertex coordinates must be within
 * MAP_COORD_MAX. Polls stop (may be NULL; lim.h). Returns 0, -EINVAL (err
 * says why, e.g. "line 3: zero length"), -E2BIG (past NB_MAX_STEPS or
 * NB_MAX_BYTES; err says which), -ECANCELED (stop said so) or -ENOMEM; on
 * error m's BSP arrays are left empty and its vertices as they were. err
 * may be NULL. */
int nb_build(struct map *m, const struct lim_stop *stop, char *err, size_t errlen);

#endif
