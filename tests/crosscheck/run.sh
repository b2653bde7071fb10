#!/bin/sh
# The renderer cross-check (docs/crosscheck.md): builds tests/crosscheck/xcheck
# with the OSMesa renderer (engine/gl/) against a build's library, then
# renders every built-in level, the built-in grid map and every Freedoom map
# (freedoom1 and freedoom2) from 20 seeded viewpoints each with both
# renderers, and fails when a view's surface ids agree on less than 99.5% of
# its pixels, naming the difference image (under BUILD/crosscheck/diff/),
# or when either renderer's id buffer is (nearly) empty (surfaces on fewer
# than 99% of the pixels: two empty buffers agree everywhere). First a
# self-test: with the id buffers cleared (--blank-ids) xcheck must fail.
# Then the mover views (--movers) of freedoom1 E1M1 and freedoom2 MAP01:
# door sectors part open and lift sectors mid-travel, seen from in front;
# they fail the same way, and the step fails when there are none. Then the
# mesh views (--meshes) of the built-in levels, freedoom1 and freedoom2
# MAP01: every key and floor lamp seen from around it; a view fails as
# above or when its mesh pixels (200 or more) agree on fewer than 85%, and
# the step fails when no mesh pixel was compared.
# Usage: tests/crosscheck/run.sh [BUILD] [xcheck options...]
#   BUILD: the folder holding libarcaded.a (default build); further
#   arguments replace the default content and views (e.g. --wad F --map M).
set -eu
cd "$(dirname "$0")/../.."
BUILD=${1:-build}
[ $# -gt 0 ] && shift
CC=${CC:-cc}
WADS=${WADS:-/usr/share/games/doom}
out=$BUILD/crosscheck
mkdir -p "$out"
rm -rf "$out/diff"
# shellcheck disable=SC2046
$CC -I. -D_GNU_SOURCE -std=c11 -O2 -g -Wall -Wextra -Werror -Wshadow -Wvla \
	-Wstrict-prototypes -Wmissing-prototypes -fno-strict-aliasing \
	$(pkg-config --cflags osmesa libpng) -o "$out/xcheck" tests/crosscheck/xcheck.c \
	tests/crosscheck/xc_move.c tests/crosscheck/xc_mesh.c \
	engine/gl/rgl.c engine/gl/rgl_geo.c "$BUILD/libarcaded.a" \
	$(pkg-config --libs osmesa libpng) -lm -lpthread
if [ $# -gt 0 ]; then
	exec "$out/xcheck" --diff "$out/diff" "$@"
fi
if "$out/xcheck" --builtin --views 2 --size 80x50 --blank-ids >"$out/blank.log" 2>&1 ||
	! grep -q "empty id buffer proves nothing" "$out/blank.log"; then
	cat "$out/blank.log"
	echo "crosscheck: FAIL self-test: empty id buffers were not caught"
	exit 1
fi
echo "crosscheck: PASS self-test: empty id buffers fail ($(grep -c '^FAIL' "$out/blank.log") views)"
for w in freedoom1 freedoom2; do
	if [ ! -f "$WADS/$w.wad" ]; then
		echo "crosscheck: $WADS/$w.wad missing (Debian package freedoom)"
		exit 1
	fi
done
rc=0
"$out/xcheck" --builtin --grid builtin --wad "$WADS/freedoom1.wad" \
	--wad "$WADS/freedoom2.wad" --views 20 --size 320x200 --min 99.5 --diff "$out/diff" || rc=1
# Doors part open and lifts mid-travel (docs/crosscheck.md), from in front.
echo "crosscheck: mover views (doors part open, lifts mid-travel)"
"$out/xcheck" --movers --wad "$WADS/freedoom1.wad" --map E1M1 \
	--wad "$WADS/freedoom2.wad" --map MAP01 --size 320x200 --min 99.5 \
	--diff "$out/diff" >"$out/movers.log" || rc=1
cat "$out/movers.log"
# no mover view at all would prove nothing
if ! grep -Eq '^xcheck: [1-9][0-9]* views' "$out/movers.log"; then
	echo "crosscheck: FAIL: no mover views"
	rc=1
fi
# The meshes (keys, the floor lamp) seen from around them, each view at a
# tick of its own (docs/crosscheck.md): the same threshold, and a view with
# 200 or more mesh pixels fails when fewer than 85% of them agree.
echo "crosscheck: mesh views (keys and lamps from around them)"
"$out/xcheck" --meshes --builtin --wad "$WADS/freedoom1.wad" \
	--wad "$WADS/freedoom2.wad" --map MAP01 --size 320x200 --min 99.5 \
	--mesh-min 85 --mesh-least 200 --diff "$out/diff" >"$out/meshes.log" || rc=1
grep -v '^ ' "$out/meshes.log" | grep -Ev '^(built-in|freedoom)' || true
# no mesh pixels at all would prove nothing
if ! grep -Eq '^xcheck: mesh pixels [1-9]' "$out/meshes.log"; then
	echo "crosscheck: FAIL: no mesh pixels compared"
	rc=1
fi
exit $rc
