#!/bin/sh
# Screenshots of the arcade game for docs/, made by the daemon's own
# screenshot command while it plays the whole-flow script
# (tests/script/game/flow.scr): the service menu, play with the HUD and
# minimap, game over with the continue countdown, initials entry, and the
# new score in attract; plus the attract title page.
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
printf '100 screenshot %s\n' "$out/game-attract-title.png" >"$tmp/title.scr"
"$BIN" --script "$tmp/title.scr" --config-dir "$tmp/etc" --state-dir "$tmp/state2" \
	--set game.render_width=640 --set game.render_height=480 >/dev/null
ls -1 "$out"/game-*.png
