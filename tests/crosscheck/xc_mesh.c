/*
 * xc_mesh: viewpoints looking at the map's meshes (xc_mesh.h). The
 * points are taken at angles 0.3 radians off the axes so that a mesh is
 * not seen exactly edge-on along the map's grid, and each view has a
 * different tick so that the meshes are seen at many turns.
 */
#include "tests/crosscheck/xc_mesh.h"

#include <math.h>

#include "tests/crosscheck/xc_move.h"

int xcx_views(const struct map *m, const struct r_sprite *spr, int nspr, struct xcx_view *out,
	      int max)
{
	const double pi = 3.14159265358979323846;
	int n = 0;

	for (int i = 0; i < nspr; i++) {
		double mx = spr[i].x / 65536.0, my = spr[i].y / 65536.0;

		if (!spr[i].mesh)
			continue;
		for (int j = 0; j < XCX_PER_MESH; j++) {
			double a = j * pi / 4 + 0.3, dist = j & 1 ? 160.0 : 96.0;
			double x = mx + dist * cos(a), y = my + dist * sin(a), look;
			uint32_t s = xcm_eye(m, MAP_NONE, x, y, mx, my);

			if (s == MAP_NONE)
				continue;
			if (n < max) {
				struct xcx_view *o = &out[n];

				o->v.x = (fx_t)lround(x * 65536.0);
				o->v.y = (fx_t)lround(y * 65536.0);
				o->v.z = m->sectors[s].floor_h + 41 * FX_ONE;
				look = atan2(my - y, mx - x);
				look = look < 0 ? look + 2 * pi : look;
				o->v.angle = (ang_t)(uint32_t)llround(look / (2 * pi) * 4294967296.0);
				o->v.shear = 0;
				o->sprite = i;
				/* a different turn per view: 13 ticks is 33 degrees */
				o->tick = (uint32_t)(13 * n + 5);
			}
			n++;
		}
	}
	return n;
}
