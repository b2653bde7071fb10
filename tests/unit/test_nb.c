/* Tests for engine/map/nb.c: the BSP node builder. Geometry checks use doubles
 * (a second method, independent of the builder's integer arithmetic). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <cmocka.h>

#include "engine/core/tab.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "engine/map/nb.h"
#include "map_fixture.h"

#define U(v) ((double)(v) / 65536.0)   /* fx to map units */
#define EPS (1.0 / 1024)               /* geometric tolerance, map units */

/* ---- maps ---- */

static const struct fix_sector one_room[] = { { 0, 128, 160 } };

static const int square_v[][2] = { { 0, 0 }, { 0, 256 }, { 256, 256 }, { 256, 0 } };
static const struct fix_line square_l[] = {
	{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, -1 }, { 3, 0, 0, -1 },
};
static const struct fix_map square = { square_v, 4, one_room, 1, square_l, 4, 64, 64, 0 };

static const int ell_v[][2] = {
	{ 0, 0 }, { 0, 256 }, { 128, 256 }, { 128, 128 }, { 256, 128 }, { 256, 0 },
};
static const struct fix_line ell_l[] = {
	{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, -1 },
	{ 3, 4, 0, -1 }, { 4, 5, 0, -1 }, { 5, 0, 0, -1 },
};
static const struct fix_map ell = { ell_v, 6, one_room, 1, ell_l, 6, 64, 64, 0 };

static int ell_sector(double x, double y)
{
	return ((x > 0 && x < 256 && y > 0 && y < 128) || (x > 0 && x < 128 && y > 0 && y < 256))
		       ? 0 : -1;
}

static const int pillar_v[][2] = {
	{ 0, 0 }, { 0, 256 }, { 256, 256 }, { 256, 0 },
	{ 96, 96 }, { 160, 96 }, { 160, 160 }, { 96, 160 },
};
static const struct fix_line pillar_l[] = {
	{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, -1 }, { 3, 0, 0, -1 },
	{ 4, 5, 0, -1 }, { 5, 6, 0, -1 }, { 6, 7, 0, -1 }, { 7, 4, 0, -1 },
};
static const struct fix_map pillar = { pillar_v, 8, one_room, 1, pillar_l, 8, 32, 32, 0 };

static int pillar_sector(double x, double y)
{
	if (x <= 0 || x >= 256 || y <= 0 || y >= 256)
		return -1;
	return (x > 96 && x < 160 && y > 96 && y < 160) ? -1 : 0;
}

/* Octagon with a diamond pillar and a triangular second sector: diagonal
 * lines, so split points are not on the integer grid. */
static const int oct_v[][2] = {
	{ 100, 0 }, { 0, 100 }, { 0, 300 }, { 100, 400 },
	{ 300, 400 }, { 400, 300 }, { 400, 100 }, { 300, 0 },
	{ 200, 130 }, { 270, 200 }, { 200, 270 }, { 130, 200 },
	{ 40, 170 }, { 90, 190 }, { 60, 240 },
};
static const struct fix_sector oct_s[] = { { 0, 128, 160 }, { 16, 128, 200 } };
static const struct fix_line oct_l[] = {
	{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, -1 }, { 3, 4, 0, -1 },
	{ 4, 5, 0, -1 }, { 5, 6, 0, -1 }, { 6, 7, 0, -1 }, { 7, 0, 0, -1 },
	{ 8, 9, 0, -1 }, { 9, 10, 0, -1 }, { 10, 11, 0, -1 }, { 11, 8, 0, -1 },
	{ 12, 13, 0, 1 }, { 13, 14, 0, 1 }, { 14, 12, 0, 1 },
};
static const struct fix_map octagon = { oct_v, 15, oct_s, 2, oct_l, 15, 200, 50, 0 };

static double side_of(double ax, double ay, double bx, double by, double x, double y)
{
	return (bx - ax) * (y - ay) - (by - ay) * (x - ax);
}

static int oct_sector(double x, double y)
{
	if (!(x > 0 && x < 400 && y > 0 && y < 400 && x + y > 100 && y - x > -300 &&
	      x + y < 700 && y - x < 300))
		return -1;
	if (fabs(x - 200) + fabs(y - 200) < 70)
		return -1;
	if (side_of(40, 170, 90, 190, x, y) > 0 && side_of(90, 190, 60, 240, x, y) > 0 &&
	    side_of(60, 240, 40, 170, x, y) > 0)
		return 1;
	return 0;
}

/* GRID_N x GRID_N cells of 64 units, one sector per cell, portals between. */
#define GRID_N 6
#define GRID_V(i, j) ((j) * (GRID_N + 1) + (i))
static int grid_v[(GRID_N + 1) * (GRID_N + 1)][2];
static struct fix_sector grid_s[GRID_N * GRID_N];
static struct fix_line grid_l[2 * GRID_N * (GRID_N + 1)];
static struct fix_map grid;

static void grid_make(void)
{
	int i, j, n = 0;

	for (j = 0; j <= GRID_N; j++)
		for (i = 0; i <= GRID_N; i++) {
			grid_v[GRID_V(i, j)][0] = i * 64;
			grid_v[GRID_V(i, j)][1] = j * 64;
		}
	for (j = 0; j < GRID_N; j++)
		for (i = 0; i < GRID_N; i++)
			grid_s[j * GRID_N + i] = (struct fix_sector){ (i + 2 * j) % 5 * 8, 160, 100 + i * 10 };
	/* horizontal edges: going east, the cell below is on the right */
	for (j = 0; j <= GRID_N; j++)
		for (i = 0; i < GRID_N; i++) {
			int below = j > 0 ? (j - 1) * GRID_N + i : -1;
			int above = j < GRID_N ? j * GRID_N + i : -1;
			if (below < 0)
				grid_l[n++] = (struct fix_line){ GRID_V(i + 1, j), GRID_V(i, j), above, -1 };
			else
				grid_l[n++] = (struct fix_line){ GRID_V(i, j), GRID_V(i + 1, j), below, above };
		}
	/* vertical edges: going north, the cell east is on the right */
	for (i = 0; i <= GRID_N; i++)
		for (j = 0; j < GRID_N; j++) {
			int east = i < GRID_N ? j * GRID_N + i : -1;
			int west = i > 0 ? j * GRID_N + i - 1 : -1;
			if (east < 0)
				grid_l[n++] = (struct fix_line){ GRID_V(i, j + 1), GRID_V(i, j), west, -1 };
			else
				grid_l[n++] = (struct fix_line){ GRID_V(i, j), GRID_V(i, j + 1), east, west };
		}
	grid = (struct fix_map){ grid_v, FIX_N(grid_v), grid_s, FIX_N(grid_s), grid_l, n, 32, 32, 0 };
}

static int grid_sector(double x, double y)
{
	if (x <= 0 || y <= 0 || x >= 64 * GRID_N || y >= 64 * GRID_N)
		return -1;
	return (int)(y / 64) * GRID_N + (int)(x / 64);
}

/* A room of RND_N x RND_N cells of 64 units, each holding a random triangle
 * (deterministic LCG): a solid pillar, or a raised sector behind portals
 * every third cell. Random slopes make many rounded split points. */
#define RND_N 10
static int rnd_v[4 + 3 * RND_N * RND_N][2];
static struct fix_line rnd_l[4 + 3 * RND_N * RND_N];
static const struct fix_sector rnd_s[] = { { 0, 128, 160 }, { 24, 128, 200 } };
static struct fix_map rnd;

static int rnd_tri(int c, double x, double y)
{
	const int *a = rnd_v[4 + 3 * c], *b = rnd_v[5 + 3 * c], *d = rnd_v[6 + 3 * c];
	return side_of(a[0], a[1], b[0], b[1], x, y) > 0 && side_of(b[0], b[1], d[0], d[1], x, y) > 0 &&
	       side_of(d[0], d[1], a[0], a[1], x, y) > 0;
}

static void rnd_make(void)
{
	static const int corners[4][2] = { { 0, 0 }, { 0, 64 * RND_N }, { 64 * RND_N, 64 * RND_N },
					   { 64 * RND_N, 0 } };
	uint32_t r = 777;
	int i, k, n = 0;

	for (i = 0; i < 4; i++) {
		rnd_v[i][0] = corners[i][0];
		rnd_v[i][1] = corners[i][1];
		rnd_l[n++] = (struct fix_line){ i, (i + 1) % 4, 0, -1 };
	}
	for (i = 0; i < RND_N * RND_N; i++) {
		int cx = i % RND_N * 64, cy = i / RND_N * 64;
		int *p[3] = { rnd_v[4 + 3 * i], rnd_v[5 + 3 * i], rnd_v[6 + 3 * i] };
		/* one vertex in each of three sectors of the cell's inner 48x48 */
		for (k = 0; k < 3; k++) {
			r = r * 1664525u + 1013904223u;
			p[k][0] = cx + 8 + (int)(r >> 16) % 20 + (k == 1 ? 20 : 0);
			r = r * 1664525u + 1013904223u;
			p[k][1] = cy + 8 + (int)(r >> 16) % 20 + (k == 2 ? 20 : 0);
		}
		/* counter-clockwise, so the room is on the right */
		if (side_of(p[0][0], p[0][1], p[1][0], p[1][1], p[2][0], p[2][1]) < 0) {
			int t0 = p[1][0], t1 = p[1][1];
			p[1][0] = p[2][0];
			p[1][1] = p[2][1];
			p[2][0] = t0;
			p[2][1] = t1;
		}
		for (k = 0; k < 3; k++)
			rnd_l[n++] = (struct fix_line){ 4 + 3 * i + k, 4 + 3 * i + (k + 1) % 3, 0,
							i % 3 == 0 ? 1 : -1 };
	}
	rnd = (struct fix_map){ rnd_v, FIX_N(rnd_v), rnd_s, 2, rnd_l, n, 4, 4, 0 };
}

static int rnd_sector(double x, double y)
{
	int c;
	if (x <= 0 || y <= 0 || x >= 64 * RND_N || y >= 64 * RND_N)
		return -1;
	c = (int)(y / 64) * RND_N + (int)(x / 64);
	if (rnd_tri(c, x, y))
		return c % 3 == 0 ? 1 : -1;
	return 0;
}

/* ---- checks ---- */

static struct map *build(const struct fix_map *f)
{
	char err[128];
	struct map *m = fix_build(f, err, sizeof err);
	if (!m)
		fail_msg("map_finish: %s", err);
	return m;
}

static double vx(const struct map *m, uint32_t v) { return U(m->vertices[v].x); }
static double vy(const struct map *m, uint32_t v) { return U(m->vertices[v].y); }

/* Signed distance of (x, y) from the line of seg s, positive in front (right). */
static double seg_dist(const struct map *m, const struct map_seg *s, double x, double y)
{
	const struct map_line *l = &m->lines[s->line];
	uint32_t a = s->side ? l->v2 : l->v1, b = s->side ? l->v1 : l->v2;
	double dx = vx(m, b) - vx(m, a), dy = vy(m, b) - vy(m, a);
	return -side_of(vx(m, a), vy(m, a), vx(m, b), vy(m, b), x, y) / sqrt(dx * dx + dy * dy);
}

/* Every seg under child lies on side `side` of node n's partition line (or
 * on it): the BSP invariant the renderer and point location rely on. */
static void check_under(const struct map *m, uint32_t child, const struct map_node *n, int side)
{
	double ax = U(n->x), ay = U(n->y), bx = U(n->x) + U(n->dx), by = U(n->y) + U(n->dy);
	double len = hypot(U(n->dx), U(n->dy));

	if (!(child & MAP_NF_SUBSECTOR)) {
		check_under(m, m->nodes[child].child[0], n, side);
		check_under(m, m->nodes[child].child[1], n, side);
		return;
	}
	{
		const struct map_subsector *ss = &m->subsectors[child & ~MAP_NF_SUBSECTOR];
		for (uint32_t i = ss->first_seg; i < ss->first_seg + ss->num_segs; i++) {
			uint32_t v[2] = { m->segs[i].v1, m->segs[i].v2 };
			for (int k = 0; k < 2; k++) {
				/* > 0: left (back) */
				double d = side_of(ax, ay, bx, by, U(m->vertices[v[k]].x),
						   U(m->vertices[v[k]].y)) / len;
				assert_true(side ? d > -EPS : d < EPS);
			}
		}
	}
}

/* Bounding box (fx) of the segs under a child; checks each node's boxes and
 * that its children lie on their sides of its partition. */
static void subtree(const struct map *m, uint32_t child, fx_t box[4], int *seen)
{
	if (child & MAP_NF_SUBSECTOR) {
		const struct map_subsector *ss = &m->subsectors[child & ~MAP_NF_SUBSECTOR];
		uint32_t i;
		seen[child & ~MAP_NF_SUBSECTOR]++;
		box[BOX_TOP] = box[BOX_RIGHT] = FX_MIN;
		box[BOX_BOTTOM] = box[BOX_LEFT] = FX_MAX;
		for (i = ss->first_seg; i < ss->first_seg + ss->num_segs; i++) {
			uint32_t v[2] = { m->segs[i].v1, m->segs[i].v2 };
			for (int k = 0; k < 2; k++) {
				const struct map_vertex *p = &m->vertices[v[k]];
				if (p->y > box[BOX_TOP]) box[BOX_TOP] = p->y;
				if (p->y < box[BOX_BOTTOM]) box[BOX_BOTTOM] = p->y;
				if (p->x < box[BOX_LEFT]) box[BOX_LEFT] = p->x;
				if (p->x > box[BOX_RIGHT]) box[BOX_RIGHT] = p->x;
			}
		}
		return;
	}
	{
		const struct map_node *n = &m->nodes[child];
		fx_t b[2][4];
		for (int c = 0; c < 2; c++) {
			check_under(m, n->child[c], n, c);
			subtree(m, n->child[c], b[c], seen);
			for (int k = 0; k < 4; k++)
				assert_int_equal(n->bbox[c][k], b[c][k]);
		}
		box[BOX_TOP] = b[0][BOX_TOP] > b[1][BOX_TOP] ? b[0][BOX_TOP] : b[1][BOX_TOP];
		box[BOX_BOTTOM] = b[0][BOX_BOTTOM] < b[1][BOX_BOTTOM] ? b[0][BOX_BOTTOM] : b[1][BOX_BOTTOM];
		box[BOX_LEFT] = b[0][BOX_LEFT] < b[1][BOX_LEFT] ? b[0][BOX_LEFT] : b[1][BOX_LEFT];
		box[BOX_RIGHT] = b[0][BOX_RIGHT] > b[1][BOX_RIGHT] ? b[0][BOX_RIGHT] : b[1][BOX_RIGHT];
	}
}

/* The tree reaches every subsector once, node boxes are exact, subsectors
 * partition the segs. */
static void check_tree(const struct map *m)
{
	int *seen = calloc(m->num_subsectors, sizeof *seen);
	uint32_t i, next = 0;
	fx_t box[4];

	assert_non_null(seen);
	if (m->num_nodes == 0)
		assert_int_equal(m->num_subsectors, 1);
	else
		assert_int_equal(m->num_nodes, m->num_subsectors - 1);
	subtree(m, m->num_nodes ? m->num_nodes - 1 : MAP_NF_SUBSECTOR, box, seen);
	for (i = 0; i < m->num_subsectors; i++) {
		assert_int_equal(seen[i], 1);
		assert_int_equal(m->subsectors[i].first_seg, next);
		next += m->subsectors[i].num_segs;
	}
	assert_int_equal(next, m->num_segs);
	free(seen);
}

/* Every leaf is convex (each seg's end points in front of or on every other
 * seg's line, and segs along one line run the same way) and faces one sector. */
static void check_convex(const struct map *m)
{
	uint32_t i, a, b;

	for (i = 0; i < m->num_subsectors; i++) {
		const struct map_subsector *ss = &m->subsectors[i];
		assert_int_equal(ss->sector, m->segs[ss->first_seg].front);
		for (a = ss->first_seg; a < ss->first_seg + ss->num_segs; a++) {
			const struct map_seg *s = &m->segs[a];
			assert_int_equal(s->front, ss->sector);
			for (b = ss->first_seg; b < ss->first_seg + ss->num_segs; b++) {
				const struct map_seg *t = &m->segs[b];
				double d1 = seg_dist(m, s, vx(m, t->v1), vy(m, t->v1));
				double d2 = seg_dist(m, s, vx(m, t->v2), vy(m, t->v2));
				assert_true(d1 > -EPS && d2 > -EPS);
				if (fabs(d1) < EPS && fabs(d2) < EPS) {
					/* collinear: same direction */
					double sx = vx(m, s->v2) - vx(m, s->v1), sy = vy(m, s->v2) - vy(m, s->v1);
					double tx = vx(m, t->v2) - vx(m, t->v1), ty = vy(m, t->v2) - vy(m, t->v1);
					assert_true(sx * tx + sy * ty > 0);
				}
			}
		}
	}
}

/* The segs of each line side chain from its start vertex to its end vertex
 * through shared vertices, their lengths add up to the line's length, and
 * offsets and angles are those of their line. */
static void check_coverage(const struct map *m)
{
	uint32_t li, i;

	for (li = 0; li < m->num_lines; li++) {
		const struct map_line *l = &m->lines[li];
		for (uint8_t side = 0; side < 2; side++) {
			uint32_t start = side ? l->v2 : l->v1, end = side ? l->v1 : l->v2, at = start;
			double len = hypot(vx(m, end) - vx(m, start), vy(m, end) - vy(m, start));
			double sum = 0, want_angle;
			int steps = 0;
			if (l->side[side] == MAP_NONE)
				continue;
			want_angle = atan2(vy(m, end) - vy(m, start), vx(m, end) - vx(m, start));
			while (at != end) {
				const struct map_seg *s = NULL;
				double ang;
				for (i = 0; i < m->num_segs && !s; i++)
					if (m->segs[i].line == li && m->segs[i].side == side && m->segs[i].v1 == at)
						s = &m->segs[i];
				assert_non_null(s);
				assert_true(fabs(U(s->offset) - hypot(vx(m, at) - vx(m, start),
								      vy(m, at) - vy(m, start))) < 2.0 / 65536);
				ang = (double)s->angle / 4294967296.0 * 2 * M_PI;
				ang = remainder(ang - want_angle, 2 * M_PI);
				assert_true(fabs(ang) < 0.0005);
				sum += hypot(vx(m, s->v2) - vx(m, s->v1), vy(m, s->v2) - vy(m, s->v1));
				at = s->v2;
				assert_true(++steps <= (int)m->num_segs);
			}
			assert_true(fabs(sum - len) < EPS);
			/* no other segs of this side */
			for (i = 0; i < m->num_segs; i++)
				if (m->segs[i].line == li && m->segs[i].side == side)
					steps--;
			assert_int_equal(steps, 0);
		}
	}
}

/* Distance from (x, y) to the nearest line segment, in map units. */
static double near_line(const struct map *m, double x, double y)
{
	double best = 1e30;
	for (uint32_t i = 0; i < m->num_lines; i++) {
		double ax = vx(m, m->lines[i].v1), ay = vy(m, m->lines[i].v1);
		double bx = vx(m, m->lines[i].v2), by = vy(m, m->lines[i].v2);
		double dx = bx - ax, dy = by - ay;
		double t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);
		double d;
		t = t < 0 ? 0 : t > 1 ? 1 : t;
		d = hypot(ax + t * dx - x, ay + t * dy - y);
		if (d < best)
			best = d;
	}
	return best;
}

/* Points on a grid land in the expected sector, inside their leaf. */
static void check_points(const struct map *m, int (*expect)(double, double), int lo, int hi)
{
	int checked = 0;

	for (int y = lo; y < hi; y += 5) {
		for (int x = lo; x < hi; x += 5) {
			double px = x + 0.25, py = y + 0.5;
			int want = expect(px, py);
			uint32_t ssi;
			const struct map_subsector *ss;
			if (want < 0 || near_line(m, px, py) < 1.0)
				continue;
			ssi = map_point_subsector(m, (fx_t)(px * 65536), (fx_t)(py * 65536));
			assert_true(ssi < m->num_subsectors);
			ss = &m->subsectors[ssi];
			if ((int)ss->sector != want)
				fail_msg("point (%g, %g): sector %u, want %d", px, py, ss->sector, want);
			for (uint32_t k = ss->first_seg; k < ss->first_seg + ss->num_segs; k++)
				assert_true(seg_dist(m, &m->segs[k], px, py) > -EPS);
			checked++;
		}
	}
	assert_true(checked > 100);
}

static void check_all(const struct map *m, int (*expect)(double, double), int lo, int hi)
{
	check_tree(m);
	check_convex(m);
	check_coverage(m);
	check_points(m, expect, lo, hi);
}

/* ---- tests ---- */

static int square_sector(double x, double y)
{
	return x > 0 && x < 256 && y > 0 && y < 256 ? 0 : -1;
}

static void square_room_is_one_subsector(void **state)
{
	struct map *m = build(&square);
	(void)state;
	assert_int_equal(m->num_nodes, 0);
	assert_int_equal(m->num_subsectors, 1);
	assert_int_equal(m->num_segs, 4);
	assert_int_equal(m->num_vertices, 4);
	check_all(m, square_sector, -20, 280);
	map_free(m);
}

static void l_shaped_room_splits_into_convex_leaves(void **state)
{
	struct map *m = build(&ell);
	(void)state;
	assert_true(m->num_subsectors >= 2);
	check_all(m, ell_sector, -20, 280);
	map_free(m);
}

static void room_with_pillar_splits_into_convex_leaves(void **state)
{
	struct map *m = build(&pillar);
	(void)state;
	assert_true(m->num_subsectors >= 4);
	check_all(m, pillar_sector, -20, 280);
	map_free(m);
}

static void diagonal_walls_split_exactly(void **state)
{
	struct map *m = build(&octagon);
	(void)state;
	assert_true(m->num_vertices > (uint32_t)octagon.nv);   /* it did split */
	check_all(m, oct_sector, -10, 410);
	map_free(m);
}

static void grid_of_sectors_maps_points_to_cells(void **state)
{
	struct map *m;
	(void)state;
	grid_make();
	m = build(&grid);
	assert_int_equal(m->num_sectors, GRID_N * GRID_N);
	check_all(m, grid_sector, -10, 64 * GRID_N + 10);
	map_free(m);
}

static void random_pillars_split_consistently(void **state)
{
	struct map *m;
	uint32_t i, fractional = 0;
	(void)state;
	rnd_make();
	m = build(&rnd);
	for (i = (uint32_t)rnd.nv; i < m->num_vertices; i++)
		if ((m->vertices[i].x | m->vertices[i].y) & 0xffff)
			fractional++;
	assert_true(fractional > 10);          /* the test exercises rounding */
	check_all(m, rnd_sector, -10, 64 * RND_N + 10);
	map_free(m);
}

/* ARENA1's sectors, read off levels/arena1.txt. */
static int arena1_sector(double x, double y)
{
	if (x > 0 && x < 640 && y > 0 && y < 640) {
		if ((x > 448 && y > 448) || (x > 224 && x < 288 && y > 320 && y < 384))
			return -1;
		return 0;
	}
	if (x > 128 && x < 320 && y > 640 && y < 736)
		return 1 + (int)((y - 640) / 32);
	if (x > 0 && x < 656 && y > 736 && y < 1024)
		return 4;
	if (x > 656 && x < 1024 && y > 0 && y < 1024)
		return (x > 800 && x < 928 && y > 448 && y < 576) ? 6 : 5;
	if (x > 640 && x < 656 && y > 320 && y < 416)
		return 7;
	if (x > 640 && x < 656 && y > 128 && y < 256)
		return 8;
	return -1;
}

static void builtin_level_bsp_is_valid(void **state)
{
	struct map *m;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	check_all(m, arena1_sector, -10, 1034);
	map_free(m);
}

static void builds_are_identical(void **state)
{
	struct map *a = build(&octagon), *b = build(&octagon);
	uint32_t i;
	(void)state;
	assert_int_equal(a->num_vertices, b->num_vertices);
	assert_int_equal(a->num_segs, b->num_segs);
	assert_int_equal(a->num_subsectors, b->num_subsectors);
	assert_int_equal(a->num_nodes, b->num_nodes);
	for (i = 0; i < a->num_vertices; i++) {
		assert_int_equal(a->vertices[i].x, b->vertices[i].x);
		assert_int_equal(a->vertices[i].y, b->vertices[i].y);
	}
	for (i = 0; i < a->num_segs; i++) {
		const struct map_seg *s = &a->segs[i], *t = &b->segs[i];
		assert_int_equal(s->v1, t->v1);
		assert_int_equal(s->v2, t->v2);
		assert_int_equal(s->angle, t->angle);
		assert_int_equal(s->offset, t->offset);
		assert_int_equal(s->line, t->line);
		assert_int_equal(s->side, t->side);
		assert_int_equal(s->front, t->front);
		assert_int_equal(s->back, t->back);
	}
	for (i = 0; i < a->num_subsectors; i++) {
		assert_int_equal(a->subsectors[i].first_seg, b->subsectors[i].first_seg);
		assert_int_equal(a->subsectors[i].num_segs, b->subsectors[i].num_segs);
		assert_int_equal(a->subsectors[i].sector, b->subsectors[i].sector);
	}
	for (i = 0; i < a->num_nodes; i++) {
		assert_int_equal(a->nodes[i].x, b->nodes[i].x);
		assert_int_equal(a->nodes[i].y, b->nodes[i].y);
		assert_int_equal(a->nodes[i].dx, b->nodes[i].dx);
		assert_int_equal(a->nodes[i].dy, b->nodes[i].dy);
		assert_memory_equal(a->nodes[i].bbox, b->nodes[i].bbox, sizeof a->nodes[i].bbox);
		assert_int_equal(a->nodes[i].child[0], b->nodes[i].child[0]);
		assert_int_equal(a->nodes[i].child[1], b->nodes[i].child[1]);
	}
	map_free(a);
	map_free(b);
}

static void two_sided_lines_get_a_seg_per_side(void **state)
{
	struct map *m = build(&octagon);
	uint32_t i, front = 0, back = 0;
	(void)state;
	for (i = 0; i < m->num_segs; i++) {
		const struct map_seg *s = &m->segs[i];
		if (s->line < 12) {
			assert_int_equal(s->side, 0);
			assert_int_equal(s->back, MAP_NONE);
		} else if (s->side == 0) {
			assert_int_equal(s->front, 0);
			assert_int_equal(s->back, 1);
			front++;
		} else {
			assert_int_equal(s->front, 1);
			assert_int_equal(s->back, 0);
			back++;
		}
	}
	assert_true(front >= 3 && back >= 3);
	map_free(m);
}

static void zero_length_line_is_refused(void **state)
{
	struct map *m = fix_alloc(&square);
	char err[128];
	(void)state;
	assert_non_null(m);
	m->vertices[2] = m->vertices[1];
	assert_int_equal(nb_build(m, NULL, err, sizeof err), -EINVAL);
	assert_string_equal(err, "line 1: zero length");
	assert_int_equal(m->num_segs, 0);
	assert_int_equal(m->num_nodes, 0);
	assert_int_equal(m->num_subsectors, 0);
	map_free(m);
}

static void rebuild_replaces_the_bsp(void **state)
{
	struct map *m = build(&pillar);
	uint32_t segs = m->num_segs, nodes = m->num_nodes;
	char err[64];
	(void)state;
	assert_int_equal(nb_build(m, NULL, err, sizeof err), 0);
	assert_int_equal(m->num_segs, segs);
	assert_int_equal(m->num_nodes, nodes);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(square_room_is_one_subsector),
		cmocka_unit_test(l_shaped_room_splits_into_convex_leaves),
		cmocka_unit_test(room_with_pillar_splits_into_convex_leaves),
		cmocka_unit_test(diagonal_walls_split_exactly),
		cmocka_unit_test(grid_of_sectors_maps_points_to_cells),
		cmocka_unit_test(random_pillars_split_consistently),
		cmocka_unit_test(builtin_level_bsp_is_valid),
		cmocka_unit_test(builds_are_identical),
		cmocka_unit_test(two_sided_lines_get_a_seg_per_side),
		cmocka_unit_test(zero_length_line_is_refused),
		cmocka_unit_test(rebuild_replaces_the_bsp),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
