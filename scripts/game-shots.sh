#!/bin/sh
# Screenshots of the arcade game for docs/, made by the daemon's own
# screenshot command while it plays the whole-flow script
# (tests/script/game/flow.scr): the service menu, play with the HUD and
# minimap, game over with the continue countdown, initials entry, and the
# new score in attract; plus the attract title page, and the stage clock's
# HURRY UP and the idle player's STILL THERE? from their scripts, and a
# thrower's missile in flight, and a mesh (the floor lamp).
# Usage: scripts/game-shots.sh [path/to/arcaded]
set -eu
cd "$(dirname "$0")/.."
BIN=$(realpath "${1:-build/arcaded}")
out=$(pwd)/docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
# The flow script plus screenshot steps at moments it reaches (ticks read
# off its own expect lines).
{
	cat tests/script/game/flow.scr
	echo "10 screenshot $out/game-service-menu.png"
	echo "200 screenshot $out/game-play-hud.png"
	echo "2000 screenshot $out/game-over-continue.png"
	echo "3930 screenshot $out/game-initials.png"
	echo "3990 screenshot $out/game-attract-scores.png"
} >"$tmp/shots.scr"
(cd "$tmp" && "$BIN" --script "$tmp/shots.scr" --config-dir "$tmp/etc" --state-dir "$tmp/state" \
	--set game.render_width=640 --set game.render_height=480 >/dev/null)
# The stage clock's hurry and the idle player's warning, from their script
# tests (tests/script/pace_*.scr, up to the shot's tick).
{
	awk '/^#/ || $1 <= 1862' tests/script/pace_hurry.scr
	echo "1862 screenshot $out/game-hurry-up.png"
	echo "1863 end"
} >"$tmp/hurry.scr"
{
	awk '/^#/ || $1 <= 3950' tests/script/pace_idle.scr
	echo "3950 screenshot $out/game-still-there.png"
	echo "3951 end"
} >"$tmp/idle.scr"
for s in hurry idle; do
	(cd "$tmp" && "$BIN" --script "$tmp/$s.scr" --config-dir "$tmp/etc" \
		--state-dir "$tmp/state-$s" --set game.render_width=640 \
		--set game.render_height=480 >/dev/null)
done
# The thrower's missile in flight: projectile_hit.scr's start (easy, stage
# 1's thrower behind the pillar), the player turned towards the thrower,
# its second missile 39 ticks out.
{
	awk '/^#/ || $1 <= 25' tests/script/projectile_hit.scr
	echo "26 press turn_left"
	echo "47 release turn_left"
	echo "200 screenshot $out/game-thrower.png"
	echo "201 end"
} >"$tmp/thrower.scr"
(cd "$tmp" && "$BIN" --script "$tmp/thrower.scr" --config-dir "$tmp/etc" \
	--state-dir "$tmp/state-thrower" --set game.difficulty=0 --set game.render_width=640 \
	--set game.render_height=480 >/dev/null)
# A mesh: stage 1's floor lamp (meshes/lamp.obj) near, from the hall's
# west side: turned towards it and walked up to some 130 units.
printf '%s\n' '0 tap coin' '1 tap start' '10 press turn_left' '56 release turn_left' \
	'60 press forward' '95 release forward' "140 screenshot $out/game-mesh.png" '140 end' \
	>"$tmp/mesh.scr"
(cd "$tmp" && "$BIN" --script "$tmp/mesh.scr" --config-dir "$tmp/etc" \
	--state-dir "$tmp/state-mesh" --set game.render_width=640 \
	--set game.render_height=480 >/dev/null)
printf '100 screenshot %s\n1300 screenshot %s\n' "$out/game-attract-title.png" \
	"$out/game-attract-demo.png" >"$tmp/title.scr"
"$BIN" --script "$tmp/title.scr" --config-dir "$tmp/etc" --state-dir "$tmp/state2" \
	--set game.render_width=640 --set game.render_height=480 >/dev/null
ls -1 "$out"/game-*.png
