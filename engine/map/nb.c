/*
 * nb: BSP node builder, exact integer arithmetic.
 *
 * Algorithm (the classic Doom one):
 * 1. One seg per line side (side 0: v1->v2, side 1: v2->v1).
 * 2. A set of segs is a leaf (subsector) when it is convex: every seg lies
 *    on the front of (or along, in the same direction as) every other seg's
 *    line. Otherwise some seg's line has segs behind it; every such line is
 *    a candidate partition, scored splits * NB_SPLIT_COST + |front - back|;
 *    the lowest score wins, ties going to the earliest seg of the set.
 * 3. Segs are classified against the partition; a seg crossing it is split
 *    at a new vertex appended to map.vertices, and the builder recurses on
 *    both halves. Nodes are emitted children first, so the root is last.
 *
 * Exactness. Partitions are always whole map lines (never a seg's rounded
 * split points), and every side test is the sign of a 64-bit cross product
 * (map.h's coordinate limit keeps it exact). A split point is rounded to
 * 1/65536 unit, so it is not exactly on either line. To keep decisions
 * consistent, the builder remembers the partition each split vertex was made
 * on and treats the vertex as exactly on every line collinear with it
 * ("line groups": lines on the same infinite line, found exactly from
 * gcd-reduced line equations). Segs of a line in the partition's group are
 * classified by direction only. The same classification decides convexity,
 * scoring and splitting, so a chosen partition always has segs on both sides
 * and the recursion terminates (each directed line group partitions at most
 * once on any path; NB_MAX_DEPTH is a guard that turns a pathological set
 * into a leaf).
 *
 * Bounds (nb.h): every classification and every split-list link walked is
 * a step of b->lim (which also polls the caller's stop hook); every array
 * the builder holds is charged to b->bytes when it is allocated or grown
 * and refunded when freed, so a map whose splits explode fails early
 * with -E2BIG instead of running for minutes or taking the machine's
 * memory.
 */
#include "engine/map/nb.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/lim.h"
#include "engine/core/msg.h"
#include "engine/core/tab.h"
#include "engine/map/map.h"

#define NB_SPLIT_COST 8
#define NB_MAX_CANDIDATES 128  /* larger sets try an evenly spaced sample */
#define NB_MAX_DEPTH 1000

enum { NB_FRONT, NB_BACK, NB_SPLIT };

struct nb_seg {
	uint32_t v1, v2, line;
	uint8_t side;
};

/* A directed partition line: a map line, taken in the direction of its side. */
struct nb_part {
	fx_t x, y, dx, dy;
	uint32_t group;
	int orient;                    /* +1/-1 relative to the group's direction */
};

struct nb_split {
	uint32_t group, vertex, next;  /* per-line list: line crossed by group */
};

struct nb {
	struct map *m;
	uint32_t *group;               /* per line: line group */
	int8_t *orient;                /* per line: +1/-1 vs the group's direction */
	uint32_t num_groups;
	uint32_t *vrec;                /* per vertex: group a split vertex lies on */
	uint32_t vcap;                 /* capacity of m->vertices and vrec */
	uint32_t *split_head;          /* per line: first nb_split, or MAP_NONE */
	struct nb_split *splits;
	uint32_t num_splits, split_cap;
	uint32_t *stamp, gen;          /* per directed group: candidate dedup */
	struct map_seg *segs;
	struct map_subsector *subs;
	struct map_node *nodes;
	uint32_t num_segs, seg_cap, num_subs, sub_cap, num_nodes, node_cap;
	struct lim lim;                /* steps (nb.h) and the stop hook */
	uint64_t links;                /* split-list links walked, not yet taken */
	uint64_t bytes, peak;          /* held now, and at most (NB_MAX_BYTES) */
	int over_bytes;                /* -E2BIG came from NB_MAX_BYTES */
};

/* Charges (add > 0) or refunds (add < 0) bytes; -E2BIG past NB_MAX_BYTES. */
static int nb_bytes(struct nb *b, int64_t add)
{
	if (add > 0 && (uint64_t)add > NB_MAX_BYTES - b->bytes) {
		b->over_bytes = 1;
		return -E2BIG;
	}
	b->bytes = add < 0 ? b->bytes - (uint64_t)-add : b->bytes + (uint64_t)add;
	if (b->bytes > b->peak)
		b->peak = b->bytes;
	return 0;
}

/* New capacity of at least need items (doubling from *cap), or 0 if it
 * would not fit uint32_t. */
static uint32_t nb_cap(uint32_t cap, uint32_t need)
{
	uint32_t n = cap ? cap : 64;

	while (n < need) {
		if (n > UINT32_MAX / 2)
			return 0;
		n *= 2;
	}
	return n;
}

/* Returns p with room for need items of elem bytes (updating *cap and
 * charging the growth to b), or NULL on failure (p is then untouched and
 * still owned by the caller; *r says why: -ENOMEM or -E2BIG). */
static void *nb_grow(struct nb *b, void *p, uint32_t *cap, uint32_t need, size_t elem, int *r)
{
	uint32_t n;
	void *q;

	if (p && need <= *cap)
		return p;
	*r = -ENOMEM;
	n = nb_cap(*cap, need);
	if (!n)
		return NULL;
	if (nb_bytes(b, (int64_t)((uint64_t)(n - (p ? *cap : 0)) * elem))) {
		*r = -E2BIG;
		return NULL;
	}
	q = realloc(p, (size_t)n * elem);
	if (q)
		*cap = n;
	else
		nb_bytes(b, -(int64_t)((uint64_t)(n - (p ? *cap : 0)) * elem));
	return q;
}

static uint64_t nb_gcd(uint64_t a, uint64_t b)
{
	while (b) {
		uint64_t t = a % b;
		a = b;
		b = t;
	}
	return a;
}

struct nb_key {
	int64_t a, b, c;               /* a*x + b*y = c, gcd(a, b) = 1, canonical sign */
	uint32_t line;
};

static int nb_key_cmp(const void *pa, const void *pb)
{
	const struct nb_key *x = pa, *y = pb;

	if (x->a != y->a)
		return x->a < y->a ? -1 : 1;
	if (x->b != y->b)
		return x->b < y->b ? -1 : 1;
	if (x->c != y->c)
		return x->c < y->c ? -1 : 1;
	return x->line < y->line ? -1 : x->line > y->line;
}

/* Assigns every line its group of exactly collinear lines. */
static int nb_groups(struct nb *b)
{
	const struct map *m = b->m;
	struct nb_key *k = malloc((size_t)m->num_lines * sizeof *k);
	uint32_t i;

	if (!k)
		return -ENOMEM;
	for (i = 0; i < m->num_lines; i++) {
		const struct map_vertex *v1 = &m->vertices[m->lines[i].v1];
		const struct map_vertex *v2 = &m->vertices[m->lines[i].v2];
		int64_t a = (int64_t)v2->y - v1->y, bb = (int64_t)v1->x - v2->x;
		int64_t g = (int64_t)nb_gcd((uint64_t)(a < 0 ? -a : a), (uint64_t)(bb < 0 ? -bb : bb));
		a /= g;
		bb /= g;
		b->orient[i] = 1;
		if (a < 0 || (a == 0 && bb < 0)) {
			a = -a;
			bb = -bb;
			b->orient[i] = -1;
		}
		k[i].a = a;
		k[i].b = bb;
		k[i].c = a * v1->x + bb * v1->y;
		k[i].line = i;
	}
	qsort(k, m->num_lines, sizeof *k, nb_key_cmp);
	b->num_groups = 0;
	for (i = 0; i < m->num_lines; i++) {
		if (i > 0 && (k[i].a != k[i - 1].a || k[i].b != k[i - 1].b || k[i].c != k[i - 1].c))
			b->num_groups++;
		b->group[k[i].line] = b->num_groups;
	}
	b->num_groups++;
	free(k);
	return 0;
}

static void nb_part_of(const struct nb *b, uint32_t line, unsigned side, struct nb_part *p)
{
	const struct map_line *l = &b->m->lines[line];
	const struct map_vertex *s = &b->m->vertices[side ? l->v2 : l->v1];
	const struct map_vertex *e = &b->m->vertices[side ? l->v1 : l->v2];

	p->x = s->x;
	p->y = s->y;
	p->dx = e->x - s->x;
	p->dy = e->y - s->y;
	p->group = b->group[line];
	p->orient = side ? -b->orient[line] : b->orient[line];
}

/* Cross product of the partition direction and (v - origin): < 0 front
 * (right), > 0 back (left); 0 for a split vertex made on this line group. */
static int64_t nb_cross(const struct nb *b, const struct nb_part *p, uint32_t v)
{
	const struct map_vertex *q = &b->m->vertices[v];

	if (b->vrec[v] == p->group)
		return 0;
	return (int64_t)p->dx * ((int64_t)q->y - p->y) - (int64_t)p->dy * ((int64_t)q->x - p->x);
}

/* The split vertex of line made on group, or MAP_NONE. Each link walked is
 * counted in b->links: mutually crossing lines make the lists long. */
static uint32_t nb_find_split(struct nb *b, uint32_t line, uint32_t group)
{
	uint32_t i;

	for (i = b->split_head[line]; i != MAP_NONE; i = b->splits[i].next, b->links++)
		if (b->splits[i].group == group)
			return b->splits[i].vertex;
	return MAP_NONE;
}

static uint64_t nb_mag(int64_t v)
{
	return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
}

/* v + d * num / den rounded to nearest, num <= den < 2^32, |d| < 2^31. */
static fx_t nb_lerp(fx_t v, int64_t d, uint64_t num, uint64_t den)
{
	uint64_t q = (nb_mag(d) * num + den / 2) / den;
	int64_t r = d < 0 ? (int64_t)v - (int64_t)q : (int64_t)v + (int64_t)q;

	return r < -MAP_COORD_MAX ? -MAP_COORD_MAX : r > MAP_COORD_MAX ? MAP_COORD_MAX : (fx_t)r;
}

/* Where seg s's line crosses the partition, if strictly inside s: the
 * existing split vertex of (line, group) or a new point computed from the
 * line's original (exact) end points, so both sides of a two-sided line and
 * all pieces of a line split at the same place. Returns 1 and fills *at
 * (and *vertex, MAP_NONE for a new point). */
static int nb_intersect(struct nb *b, const struct nb_part *p, const struct nb_seg *s,
			struct map_vertex *at, uint32_t *vertex)
{
	const struct map *m = b->m;
	const struct map_line *l = &m->lines[s->line];
	const struct map_vertex *a = &m->vertices[l->v1], *e = &m->vertices[l->v2];
	const struct map_vertex *s1 = &m->vertices[s->v1], *s2 = &m->vertices[s->v2];
	int64_t dx = (int64_t)e->x - a->x, dy = (int64_t)e->y - a->y;

	*vertex = nb_find_split(b, s->line, p->group);
	if (*vertex != MAP_NONE) {
		*at = m->vertices[*vertex];
	} else {
		int64_t ca = (int64_t)p->dx * ((int64_t)a->y - p->y) -
			     (int64_t)p->dy * ((int64_t)a->x - p->x);
		int64_t ce = (int64_t)p->dx * ((int64_t)e->y - p->y) -
			     (int64_t)p->dy * ((int64_t)e->x - p->x);
		uint64_t num = nb_mag(ca), den;
		if (!((ca < 0 && ce > 0) || (ca > 0 && ce < 0)))
			return 0;
		/* |ca| + |ce| < 2^64; scale both down to 32 bits so that the
		 * interpolation product fits 64 bits (relative error < 2^-31) */
		den = num + nb_mag(ce);
		while (den > UINT32_MAX) {
			den >>= 1;
			num >>= 1;
		}
		at->x = nb_lerp(a->x, dx, num, den);
		at->y = nb_lerp(a->y, dy, num, den);
	}
	/* strictly between the seg's end points along the line's major axis */
	if (nb_mag(dx) >= nb_mag(dy))
		return (at->x > s1->x && at->x < s2->x) || (at->x < s1->x && at->x > s2->x);
	return (at->y > s1->y && at->y < s2->y) || (at->y < s1->y && at->y > s2->y);
}

/* NB_FRONT, NB_BACK or NB_SPLIT (then *at, *vertex: see nb_intersect). */
static int nb_classify(struct nb *b, const struct nb_part *p, const struct nb_seg *s,
		       struct map_vertex *at, uint32_t *vertex)
{
	const struct map *m = b->m;
	int64_t c1, c2;

	if (b->group[s->line] == p->group) {
		int o = s->side ? -b->orient[s->line] : b->orient[s->line];
		return o == p->orient ? NB_FRONT : NB_BACK;
	}
	c1 = nb_cross(b, p, s->v1);
	c2 = nb_cross(b, p, s->v2);
	if (c1 == 0 && c2 == 0) {
		/* on the partition without being in its group (rounded split
		 * points): by direction */
		const struct map_vertex *v1 = &m->vertices[s->v1], *v2 = &m->vertices[s->v2];
		int64_t dot = ((int64_t)v2->x - v1->x) * p->dx + ((int64_t)v2->y - v1->y) * p->dy;
		return dot > 0 ? NB_FRONT : NB_BACK;
	}
	if (c1 <= 0 && c2 <= 0)
		return NB_FRONT;
	if (c1 >= 0 && c2 >= 0)
		return NB_BACK;
	if (nb_intersect(b, p, s, at, vertex))
		return NB_SPLIT;
	/* the crossing rounds onto an end point: the seg only touches the
	 * partition; it goes with its farther end */
	if (nb_mag(c1) >= nb_mag(c2))
		return c1 < 0 ? NB_FRONT : NB_BACK;
	return c2 < 0 ? NB_FRONT : NB_BACK;
}

/* Picks the best partition for set[0..n): 1, 0 if the set is convex, or a
 * negative errno. Steps taken: n per candidate tried, and the links walked
 * meanwhile. */
static int nb_choose(struct nb *b, const struct nb_seg *set, uint32_t n, struct nb_part *best)
{
	uint32_t *cand;
	uint32_t nc = 0, i, j, step;
	int64_t best_score = -1;
	int r = nb_bytes(b, (int64_t)n * (int64_t)sizeof *cand);

	if (r)
		return r;
	cand = malloc((size_t)n * sizeof *cand);
	if (!cand) {
		nb_bytes(b, -(int64_t)n * (int64_t)sizeof *cand);
		return -ENOMEM;
	}
	b->gen++;
	for (i = 0; i < n; i++) {
		struct nb_part p;
		uint32_t key;
		nb_part_of(b, set[i].line, set[i].side, &p);
		key = p.group * 2 + (p.orient < 0);
		if (b->stamp[key] != b->gen) {
			b->stamp[key] = b->gen;
			cand[nc++] = i;
		}
	}
	step = nc > NB_MAX_CANDIDATES ? (nc + NB_MAX_CANDIDATES - 1) / NB_MAX_CANDIDATES : 1;
	for (;;) {
		for (i = 0; i < nc; i += step) {
			struct nb_part p;
			int64_t front = 0, back = 0, splits = 0, score;
			r = lim_take(&b->lim, n + b->links);
			b->links = 0;
			if (r)
				goto out;
			nb_part_of(b, set[cand[i]].line, set[cand[i]].side, &p);
			for (j = 0; j < n; j++) {
				struct map_vertex at;
				uint32_t v;
				switch (nb_classify(b, &p, &set[j], &at, &v)) {
				case NB_FRONT: front++; break;
				case NB_BACK: back++; break;
				default: splits++; break;
				}
			}
			if (back + splits == 0)
				continue;
			score = splits * NB_SPLIT_COST + (front > back ? front - back : back - front);
			if (best_score < 0 || score < best_score) {
				best_score = score;
				*best = p;
			}
		}
		if (best_score >= 0 || step == 1)
			break;
		step = 1;      /* the sample found nothing: decide convexity on all */
	}
	r = best_score >= 0;
out:
	free(cand);
	nb_bytes(b, -(int64_t)n * (int64_t)sizeof *cand);
	return r;
}

static int nb_new_vertex(struct nb *b, uint32_t line, uint32_t group, struct map_vertex at,
			 uint32_t *out)
{
	struct map *m = b->m;
	struct nb_split *sp;
	int r;

	if (m->num_vertices + 1 > b->vcap) {
		/* map.vertices and vrec always share one capacity */
		uint32_t n = nb_cap(b->vcap, m->num_vertices + 1);
		struct map_vertex *v;
		uint32_t *rec;
		if (!n)
			return -ENOMEM;
		if (nb_bytes(b, (int64_t)(n - b->vcap) * (int64_t)(sizeof *v + sizeof *rec)))
			return -E2BIG;
		v = realloc(m->vertices, (size_t)n * sizeof *v);
		if (!v)
			return -ENOMEM;
		m->vertices = v;
		rec = realloc(b->vrec, (size_t)n * sizeof *rec);
		if (!rec)
			return -ENOMEM;
		b->vrec = rec;
		b->vcap = n;
	}
	sp = nb_grow(b, b->splits, &b->split_cap, b->num_splits + 1, sizeof *sp, &r);
	if (!sp)
		return r;
	b->splits = sp;
	*out = m->num_vertices++;
	m->vertices[*out] = at;
	b->vrec[*out] = group;
	sp[b->num_splits].group = group;
	sp[b->num_splits].vertex = *out;
	sp[b->num_splits].next = b->split_head[line];
	b->split_head[line] = b->num_splits++;
	return 0;
}

static void nb_box_add(fx_t box[4], const struct map_vertex *v)
{
	if (v->y > box[BOX_TOP])
		box[BOX_TOP] = v->y;
	if (v->y < box[BOX_BOTTOM])
		box[BOX_BOTTOM] = v->y;
	if (v->x < box[BOX_LEFT])
		box[BOX_LEFT] = v->x;
	if (v->x > box[BOX_RIGHT])
		box[BOX_RIGHT] = v->x;
}

static void nb_box_clear(fx_t box[4])
{
	box[BOX_TOP] = box[BOX_RIGHT] = FX_MIN;
	box[BOX_BOTTOM] = box[BOX_LEFT] = FX_MAX;
}

static int nb_leaf(struct nb *b, const struct nb_seg *set, uint32_t n, uint32_t *child,
		   fx_t box[4])
{
	const struct map *m = b->m;
	struct map_subsector *ss;
	uint32_t i;
	int r;

	struct map_seg *sg = nb_grow(b, b->segs, &b->seg_cap, b->num_segs + n, sizeof *sg, &r);
	struct map_subsector *sb;

	if (!sg)
		return r;
	b->segs = sg;
	sb = nb_grow(b, b->subs, &b->sub_cap, b->num_subs + 1, sizeof *sb, &r);
	if (!sb)
		return r;
	b->subs = sb;
	nb_box_clear(box);
	for (i = 0; i < n; i++) {
		const struct nb_seg *s = &set[i];
		const struct map_line *l = &m->lines[s->line];
		const struct map_vertex *v1 = &m->vertices[s->v1];
		const struct map_vertex *start = &m->vertices[s->side ? l->v2 : l->v1];
		const struct map_vertex *end = &m->vertices[s->side ? l->v1 : l->v2];
		struct map_seg *o = &b->segs[b->num_segs + i];
		o->v1 = s->v1;
		o->v2 = s->v2;
		o->angle = tab_atan2(end->y - start->y, end->x - start->x);
		o->offset = fx_len(v1->x - start->x, v1->y - start->y);
		o->line = s->line;
		o->side = s->side;
		o->front = m->sides[l->side[s->side]].sector;
		o->back = l->side[s->side ^ 1] == MAP_NONE ? MAP_NONE
							    : m->sides[l->side[s->side ^ 1]].sector;
		nb_box_add(box, v1);
		nb_box_add(box, &m->vertices[s->v2]);
	}
	ss = &b->subs[b->num_subs];
	ss->first_seg = b->num_segs;
	ss->num_segs = n;
	ss->sector = b->segs[b->num_segs].front;
	b->num_segs += n;
	*child = b->num_subs++ | MAP_NF_SUBSECTOR;
	return 0;
}

static int nb_node(struct nb *b, const struct nb_seg *set, uint32_t n, int depth,
		   uint32_t *child, fx_t box[4])
{
	struct nb_seg *side[2] = { NULL, NULL };
	uint32_t count[2] = { 0, 0 }, kids[2], i;
	struct map_node *nd;
	struct nb_part p;
	fx_t kbox[2][4];
	int r = depth < NB_MAX_DEPTH ? nb_choose(b, set, n, &p) : 0;

	if (r < 0)
		return r;
	if (r == 0)
		return nb_leaf(b, set, n, child, box);
	/* each side holds at most n pieces: a split seg puts one in each */
	r = nb_bytes(b, 2 * (int64_t)n * (int64_t)sizeof *side[0]);
	if (r)
		return r;
	r = lim_take(&b->lim, n);
	if (r)
		goto out;
	side[0] = malloc((size_t)n * sizeof *side[0]);
	side[1] = malloc((size_t)n * sizeof *side[1]);
	r = -ENOMEM;
	if (!side[0] || !side[1])
		goto out;
	for (i = 0; i < n; i++) {
		struct nb_seg s = set[i], t;
		struct map_vertex at;
		uint32_t v;
		int c = nb_classify(b, &p, &s, &at, &v);
		if (c != NB_SPLIT) {
			side[c][count[c]++] = s;
			continue;
		}
		if (v == MAP_NONE) {
			r = nb_new_vertex(b, s.line, p.group, at, &v);
			if (r)
				goto out;
			r = -ENOMEM;
		}
		t = s;
		s.v2 = v;
		t.v1 = v;
		/* the piece at v1 goes to v1's side (c1 < 0 is front) */
		c = nb_cross(b, &p, s.v1) < 0 ? NB_FRONT : NB_BACK;
		side[c][count[c]++] = s;
		side[c ^ 1][count[c ^ 1]++] = t;
	}
	for (i = 0; i < 2; i++) {
		r = nb_node(b, side[i], count[i], depth + 1, &kids[i], kbox[i]);
		if (r)
			goto out;
	}
	nd = nb_grow(b, b->nodes, &b->node_cap, b->num_nodes + 1, sizeof *nd, &r);
	if (!nd)
		goto out;
	b->nodes = nd;
	nd = &b->nodes[b->num_nodes];
	nd->x = p.x;
	nd->y = p.y;
	nd->dx = p.dx;
	nd->dy = p.dy;
	memcpy(nd->bbox, kbox, sizeof nd->bbox);
	nd->child[0] = kids[0];
	nd->child[1] = kids[1];
	*child = b->num_nodes++;
	box[BOX_TOP] = kbox[0][BOX_TOP] > kbox[1][BOX_TOP] ? kbox[0][BOX_TOP] : kbox[1][BOX_TOP];
	box[BOX_BOTTOM] = kbox[0][BOX_BOTTOM] < kbox[1][BOX_BOTTOM] ? kbox[0][BOX_BOTTOM]
								     : kbox[1][BOX_BOTTOM];
	box[BOX_LEFT] = kbox[0][BOX_LEFT] < kbox[1][BOX_LEFT] ? kbox[0][BOX_LEFT]
							       : kbox[1][BOX_LEFT];
	box[BOX_RIGHT] = kbox[0][BOX_RIGHT] > kbox[1][BOX_RIGHT] ? kbox[0][BOX_RIGHT]
								  : kbox[1][BOX_RIGHT];
	r = 0;
out:
	free(side[0]);
	free(side[1]);
	nb_bytes(b, -2 * (int64_t)n * (int64_t)sizeof *side[0]);
	return r;
}

static int nb_bad_line(char *err, size_t errlen, uint32_t i, const char *why)
{
	if (err && errlen)
		err[0] = '\0';
	msg_cat(err, errlen, "line ");
	msg_int(err, errlen, i);
	msg_cat(err, errlen, ": ");
	msg_cat(err, errlen, why);
	return -EINVAL;
}

/* The builder's own preconditions (map_finish checks more, with details). */
static int nb_check(const struct map *m, char *err, size_t errlen)
{
	uint32_t i;

	if (m->num_lines == 0) {
		msg_cat(err, errlen, "map has no lines");
		return -EINVAL;
	}
	for (i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		const struct map_vertex *a, *e;
		if (l->v1 >= m->num_vertices || l->v2 >= m->num_vertices)
			return nb_bad_line(err, errlen, i, "vertex out of range");
		if (l->side[0] >= m->num_sides || m->sides[l->side[0]].sector >= m->num_sectors ||
		    (l->side[1] != MAP_NONE && (l->side[1] >= m->num_sides ||
						m->sides[l->side[1]].sector >= m->num_sectors)))
			return nb_bad_line(err, errlen, i, "side or its sector out of range");
		a = &m->vertices[l->v1];
		e = &m->vertices[l->v2];
		if (a->x == e->x && a->y == e->y)
			return nb_bad_line(err, errlen, i, "zero length");
		if (a->x < -MAP_COORD_MAX || a->x > MAP_COORD_MAX || a->y < -MAP_COORD_MAX ||
		    a->y > MAP_COORD_MAX || e->x < -MAP_COORD_MAX || e->x > MAP_COORD_MAX ||
		    e->y < -MAP_COORD_MAX || e->y > MAP_COORD_MAX)
			return nb_bad_line(err, errlen, i, "vertex out of range (+/-16384 units)");
	}
	return 0;
}

/* "node builder: <lines> lines need more than <limit> <what> (<NAME>)" */
static void nb_over(char *err, size_t errlen, const struct map *m, uint64_t limit,
		    const char *what, const char *name)
{
	msg_cat(err, errlen, "node builder: ");
	msg_int(err, errlen, m->num_lines);
	msg_cat(err, errlen, " lines need more than ");
	msg_int(err, errlen, (int64_t)limit);
	msg_cat(err, errlen, what);
	msg_cat(err, errlen, " (limit ");
	msg_cat(err, errlen, name);
	msg_cat(err, errlen, ")");
}

int nb_build(struct map *m, const struct lim_stop *stop, char *err, size_t errlen)
{
	struct nb b;
	struct nb_seg *set = NULL;
	uint32_t n = 0, i, root, orig_vertices = m->num_vertices;
	fx_t box[4];
	int r;

	free(m->segs);
	free(m->subsectors);
	free(m->nodes);
	m->segs = NULL;
	m->subsectors = NULL;
	m->nodes = NULL;
	m->num_segs = m->num_subsectors = m->num_nodes = 0;
	if (err && errlen)
		err[0] = '\0';
	r = nb_check(m, err, errlen);
	if (r)
		return r;

	memset(&b, 0, sizeof b);
	b.m = m;
	b.vcap = m->num_vertices;
	lim_init(&b.lim, stop, NB_MAX_STEPS);
	/* the per-line and per-vertex arrays below, nb_groups' keys and the
	 * candidate stamps (at most two per line) */
	r = nb_bytes(&b, (int64_t)m->num_lines * (int64_t)(sizeof *b.group + sizeof *b.orient +
						      sizeof *b.split_head + 2 * sizeof *set +
						      sizeof(struct nb_key) + 2 * sizeof *b.stamp) +
			     (int64_t)(b.vcap + 1) * (int64_t)sizeof *b.vrec);
	if (r)
		goto out;
	r = -ENOMEM;
	b.group = malloc((size_t)m->num_lines * sizeof *b.group);
	b.orient = malloc((size_t)m->num_lines * sizeof *b.orient);
	b.split_head = malloc((size_t)m->num_lines * sizeof *b.split_head);
	b.vrec = malloc((size_t)(b.vcap ? b.vcap : 1) * sizeof *b.vrec);
	set = malloc((size_t)m->num_lines * 2 * sizeof *set);
	if (!b.group || !b.orient || !b.split_head || !b.vrec || !set)
		goto out;
	for (i = 0; i < m->num_vertices; i++)
		b.vrec[i] = MAP_NONE;
	for (i = 0; i < m->num_lines; i++)
		b.split_head[i] = MAP_NONE;
	r = nb_groups(&b);
	if (r)
		goto out;
	r = -ENOMEM;
	b.stamp = calloc((size_t)b.num_groups * 2, sizeof *b.stamp);
	if (!b.stamp)
		goto out;
	for (i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		set[n++] = (struct nb_seg){ l->v1, l->v2, i, 0 };
		if (l->side[1] != MAP_NONE)
			set[n++] = (struct nb_seg){ l->v2, l->v1, i, 1 };
	}
	r = nb_node(&b, set, n, 0, &root, box);
	if (r)
		goto out;
	m->segs = b.segs;
	m->subsectors = b.subs;
	m->nodes = b.nodes;
	m->num_segs = b.num_segs;
	m->num_subsectors = b.num_subs;
	m->num_nodes = b.num_nodes;
	b.segs = NULL;
	b.subs = NULL;
	b.nodes = NULL;
out:
	if (r) {
		m->num_vertices = orig_vertices;
		if (err && errlen && !err[0]) {
			if (r == -E2BIG && b.over_bytes)
				nb_over(err, errlen, m, NB_MAX_BYTES, " bytes", "NB_MAX_BYTES");
			else if (r == -E2BIG)
				nb_over(err, errlen, m, NB_MAX_STEPS, " steps", "NB_MAX_STEPS");
			else if (r == -ECANCELED)
				msg_cat(err, errlen, "node builder: stopped");
			else
				msg_cat(err, errlen, "node builder: out of memory");
		}
	}
	free(set);
	free(b.group);
	free(b.orient);
	free(b.split_head);
	free(b.vrec);
	free(b.splits);
	free(b.stamp);
	free(b.segs);
	free(b.subs);
	free(b.nodes);
	return r;
}
