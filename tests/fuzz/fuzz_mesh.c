/* libFuzzer target: the OBJ subset reader (engine/map/mesh.c). Any bytes
 * must parse or fail with a message naming the file and a line; a parsed
 * mesh must have faces, stay within the limits, and every triangle must
 * name vertices it has. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/map/mesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	struct mesh m;
	char err[256];

	if (mesh_parse("fuzz.obj", (const char *)data, len, &m, err, sizeof(err)) == 0) {
		if (m.nt == 0 || m.nt > MESH_MAX_TRIS || m.nv > MESH_MAX_VERTS)
			abort();
		for (uint32_t i = 0; i < m.nt; i++)
			for (int k = 0; k < 3; k++)
				if (m.t[i].v[k] >= m.nv)
					abort();
		if (m.radius > MESH_MAX_COORD * FX_ONE || m.zmin > m.zmax)
			abort();
		mesh_free(&m);
	} else if (strncmp(err, "fuzz.obj:", 9) != 0) {
		abort();
	}
	return 0;
}
