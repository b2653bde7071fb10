#!/bin/sh
# Screenshots of the arcade game for docs/, made by the daemon's own
# screenshot command while it plays the whole-flow script
# (tests/script/game/flow.scr): the service menu, play with the HUD and
# minimap, game over with the continue countdown, initials entry, and the
# new score in attract; plus the attract title page, and the stage clock's
# HURRY UP and the idle player's STILL THERE? from their scripts, and a
# thrower's missile in flight, the grunt's wind-up, the brute and the flyer,
# and a mesh (the floor lamp).
# Usage: scripts/game-shots.sh [path/to/arcaded]
set -eu
cd "$(dirname "$0")/.."
BIN=$(realpath "${1:-build/arcaded}")
out=$(pwd)/docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
# The flow script plus screenshot steps at moments it reaches, found from
# its own expect lines (test_g_flow writes the script again when the game
# changes, and the ticks move): the service menu and play at fixed early
# ticks, the first game over with its countdown running, the initials page
# before any letter is entered, the scores page in attract.
flow=tests/script/game/flow.scr
at() { # the first tick of "expect KEY == VALUE" in the flow script
	awk -v k="$1" -v v="$2" '$2 == "expect" && $3 == k && $5 == v { print $1; exit }' "$flow"
}
over=$(at mode gameover)
initials=$(at mode initials)
scores=$(at page scores)
[ -n "$over" ] && [ -n "$initials" ] && [ -n "$scores" ] ||
	{ echo "game-shots: $flow has no game over, initials or scores expect line" >&2; exit 1; }
{
	cat "$flow"
	echo "10 screenshot $out/game-service-menu.png"
	echo "200 screenshot $out/game-play-hud.png"
	echo "$((over + 96)) screenshot $out/game-over-continue.png"
	echo "$((initials + 11)) screenshot $out/game-initials.png"
	echo "$((scores + 7)) screenshot $out/game-attract-scores.png"
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
# Each new enemy on a grid corridor (docs/grid.md), lit 200, the player at
# its west end facing east: the grunt (zombieman) 192 units ahead in its
# wind-up (it wakes at tick 8 and aims over ticks 15..38: its aiming frame,
# the telegraph before its shot); the brute (demon) 384 units ahead,
# walking in to some 90 units by tick 92; the flyer (lost soul) 256 units
# ahead, circling in at the player's height at tick 70.
enemy_shot() { # NAME TYPE TILES TICK
	{
		printf 'name %s\n# = wall AR_BRICK\n' "$1"
		printf '. = floor 0 ceil 128 light 200 ftex AR_FLOOR ctex AR_CEIL\n'
		printf '@ = . player east\nX = . thing %s west\nmap\n' "$2"
		printf '##########\n#........#\n#@%sX%s#\n#........#\n##########\n' \
			"$(printf '%*s' "$(($3 - 1))" '' | tr ' ' .)" \
			"$(printf '%*s' "$((7 - $3))" '' | tr ' ' .)"
	} >"$tmp/$1.txt"
	printf '%s\n' '0 tap coin' '1 tap start' "$4 screenshot $out/game-$5.png" "$4 end" \
		>"$tmp/$1.scr"
	(cd "$tmp" && "$BIN" --script "$tmp/$1.scr" --grid "$tmp/$1.txt" --config-dir "$tmp/etc" \
		--state-dir "$tmp/state-$1" --set game.render_width=640 \
		--set game.render_height=480 >/dev/null)
}
enemy_shot WINDUP 3004 3 30 windup
enemy_shot BRUTE 3002 6 92 brute
enemy_shot FLYSHOT 3006 4 70 flyer
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
