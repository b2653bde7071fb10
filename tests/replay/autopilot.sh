#!/bin/sh
# Writes the scripts of the golden exit recordings from their routes
# (and the attract demo's, levels/demo.scr from levels/demo.route):
# tests/replay/freedoom/NAME.scr from NAME.route for every line of
# freedoom/exits.list, with the autopilot (tests/replay/autopilot.c, built
# by `make tests`). Only after a change of a route or of the game's rules;
# then record them again with tests/replay/regen.sh and look at the frames.
# Usage: tests/replay/autopilot.sh [path/to/autopilot]
set -eu
cd "$(dirname "$0")/../.."
AP=${1:-build/tests/autopilot}
grep -v '^#' tests/replay/freedoom/exits.list | while read -r name wad map settings; do
	# shellcheck disable=SC2086
	"$AP" --wad "$wad" --map "$map" $settings --route "tests/replay/freedoom/$name.route" \
		--out "tests/replay/freedoom/$name.scr"
done
# the attract demo (app/demo.c): a game on the first built-in level until
# it is cleared, compiled into the daemon
"$AP" --level 1 --demo --route levels/demo.route --out levels/demo.scr
tools/mkdemo.sh levels/demo.scr > app/demo_game.h
