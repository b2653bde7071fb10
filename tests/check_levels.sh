#!/bin/sh
# The built-in levels' compiled-in PWAD (engine/map/lvl_wad.c) is exactly what
# tools/mklevels makes of levels/arena*.txt (docs/maps.md, "The built-in
# levels"), engine/map/mesh_builtin.c what tools/mkmeshes makes of meshes/*.obj, and app/demo_game.h what tools/mkdemo.sh makes of levels/demo.scr
# (the attract demo). Needs $BUILD/tools/mklevels (make tools).
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
gen=$BUILD/tools/mklevels
if [ ! -x "$gen" ]; then
	echo "FAIL $gen is not built (make tools)"
	exit 1
fi
"$gen" levels/arena*.txt > "$BUILD/lvl_wad.c.new" || exit 1
if ! cmp -s "$BUILD/lvl_wad.c.new" engine/map/lvl_wad.c; then
	echo "FAIL engine/map/lvl_wad.c differs from what tools/mklevels makes of levels/arena*.txt;"
	echo "     regenerate: $gen levels/arena*.txt > engine/map/lvl_wad.c"
	exit 1
fi
# the built-in meshes (engine/map/mesh_builtin.c), from meshes/*.obj
mm=$BUILD/tools/mkmeshes
if [ ! -x "$mm" ]; then
	echo "FAIL $mm is not built (make $mm)"
	exit 1
fi
"$mm" meshes/*.obj > "$BUILD/mesh_builtin.c.new" || exit 1
if ! cmp -s "$BUILD/mesh_builtin.c.new" engine/map/mesh_builtin.c; then
	echo "FAIL engine/map/mesh_builtin.c differs from what tools/mkmeshes makes of meshes/*.obj;"
	echo "     regenerate: $mm meshes/*.obj > engine/map/mesh_builtin.c"
	exit 1
fi
# the attract demo's script, compiled in (app/demo.c)
tools/mkdemo.sh levels/demo.scr > "$BUILD/demo_game.h.new" || exit 1
if ! cmp -s "$BUILD/demo_game.h.new" app/demo_game.h; then
	echo "FAIL app/demo_game.h differs from what tools/mkdemo.sh makes of levels/demo.scr;"
	echo "     regenerate: tools/mkdemo.sh levels/demo.scr > app/demo_game.h"
	exit 1
fi
echo "check-levels: engine/map/lvl_wad.c matches tools/mklevels levels/arena*.txt, engine/map/mesh_builtin.c tools/mkmeshes meshes/*.obj, app/demo_game.h tools/mkdemo.sh levels/demo.scr"
