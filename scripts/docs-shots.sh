#!/bin/sh
# Regenerates the screenshots in docs/images/ with the daemon's own
# screenshot command: headless runs of `arcaded --play --script S` whose
# scripts walk a few steps and take `screenshot` steps, at 640x480, with no
# configuration files. The views: Freedoom's E1M1 and MAP01 (their player
# starts and one view further on), the built-in levels ARENA1..3 from their
# starts (and ARENA1's yard), and the built-in grid level GRID1. Shots are
# taken from tick 121 on, once the "STAGE 1" banner (120 ticks) is gone.
# Everything is deterministic: the same build makes the same pictures.
# Usage: scripts/docs-shots.sh [path/to/arcaded]   (default build/arcaded;
# Freedoom from $DOOM_DIR, default /usr/share/games/doom)
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build/arcaded}
DOOM=${DOOM_DIR:-/usr/share/games/doom}
OUT=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$OUT"

# shot NAME SCRIPT [arcaded options]: runs SCRIPT (steps separated by ';',
# @ standing for $OUT) with the options.
shot() {
	name=$1
	printf '%s\n' "$2" | tr ';' '\n' | sed "s|@|$OUT|g" > "$tmp/$name.scr"
	shift 2
	if ! "$BIN" --config-dir "$tmp/none" --state-dir "$tmp/state" --display null \
		--set game.render_width=640 --set game.render_height=480 \
		--play --script "$tmp/$name.scr" "$@" > "$tmp/$name.log" 2>&1; then
		cat "$tmp/$name.log" >&2
		echo "docs-shots: $name failed" >&2
		exit 1
	fi
	echo "docs-shots: $name"
}

e1="--wad $DOOM/freedoom1.wad --map E1M1"
m1="--wad $DOOM/freedoom2.wad --map MAP01"

shot e1m1 "121 screenshot @/freedoom1-e1m1.png;122 end" $e1
# along the left wall of the start hall, then right towards the zombieman
shot e1m1-hall "1 press turn_left;7 release turn_left;7 press forward;95 release forward;\
95 press turn_right;115 release turn_right;135 screenshot @/freedoom1-e1m1-hall.png;136 end" $e1
shot map01 "121 screenshot @/freedoom2-map01.png;122 end" $m1
# down the start corridor, then left
shot map01-room "1 press forward;90 release forward;90 press turn_left;110 release turn_left;\
125 screenshot @/freedoom2-map01-room.png;126 end" $m1
shot arena1 "121 screenshot @/arena1-start.png;122 end" --level 1
# across the hall, through the doorway, then left to the sentry on the dais
shot arena1-yard "1 press turn_left;9 release turn_left;9 press forward;97 release forward;\
97 press turn_left;109 release turn_left;121 screenshot @/arena1-yard.png;122 end" --level 1
shot arena2 "121 screenshot @/arena2-start.png;122 end" --level 2
shot arena3 "121 screenshot @/arena3-start.png;122 end" --level 3
shot grid1 "121 screenshot @/grid1-start.png;122 end" --grid builtin
