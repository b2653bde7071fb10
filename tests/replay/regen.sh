#!/bin/sh
# Regenerates every golden recording and its hashes from its script:
# tests/replay/golden-NAME.rec and golden-NAME.hashes from NAME.scr, with
# the built-in defaults (no configuration files). Only after an intended
# change of the sim, renderer or level, having looked at the frames
# (README.md); say so in the commit.
# Usage: tests/replay/regen.sh [path/to/arcaded]
set -eu
cd "$(dirname "$0")/../.."
BIN=${1:-build/arcaded}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
common="--config-dir $tmp/none --state-dir $tmp/state"
for rec in tests/replay/golden-*.rec; do
	name=$(basename "$rec" .rec)
	scr=tests/replay/${name#golden-}.scr
	"$BIN" $common --script "$scr" --record "$rec" >/dev/null
	"$BIN" $common --replay "$rec" >"tests/replay/$name.hashes"
	echo "$name: $(wc -l <"tests/replay/$name.hashes") ticks from $scr"
done
# the Freedoom map (its sounds are Freedoom's DS lumps)
W=/usr/share/games/doom/freedoom1.wad
fd="--wad $W --map E1M1"
"$BIN" $common $fd --script tests/replay/freedoom/e1m1.scr \
	--record tests/replay/freedoom/golden-e1m1.rec >/dev/null
"$BIN" $common $fd replay tests/replay/freedoom/golden-e1m1.rec >tests/replay/freedoom/golden-e1m1.hashes
echo "golden-e1m1: $(wc -l <tests/replay/freedoom/golden-e1m1.hashes) ticks from tests/replay/freedoom/e1m1.scr"
# the exit recordings (freedoom/exits.list): each script ends with checks
# that the map was left (phase 3, the intermission), run while recording
grep -v '^#' tests/replay/freedoom/exits.list | while read -r name wad map settings; do
	d=tests/replay/freedoom
	# shellcheck disable=SC2086
	"$BIN" $common --wad "$wad" --map "$map" $settings --script "$d/$name.scr" \
		--record "$d/golden-$name.rec" >/dev/null
	"$BIN" $common --wad "$wad" --map "$map" replay "$d/golden-$name.rec" >"$d/golden-$name.hashes"
	echo "golden-$name: $(wc -l <"$d/golden-$name.hashes") ticks from $d/$name.scr"
done
