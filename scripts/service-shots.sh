#!/bin/sh
# Screenshots of every page of the service menu for docs/operator.md, made
# by the daemon's own screenshot command while a script walks the menu with
# the cabinet's controls (forward/back move the cursor, FIRE selects,
# SERVICE goes back): the main page, the input test (FORWARD held, one coin
# seen), the three display test patterns, the sound test, game settings,
# bookkeeping (after two coins), the reset confirmation, and the
# diagnostics pages DEVICES and LATENCY (their text is this run's: a script
# opens no device and lists none, and its figures are those of a run that
# does not wait for the clock); the app's pages CONTENT PACK (and a pack's
# maps), SCREEN and CONFIG ERRORS, with the configuration error's notice on
# the attract screen and the main page. The input wizard is not among them:
# it runs only on a live cabinet, never under a script (docs/wizard.md).
# Usage: scripts/service-shots.sh [path/to/arcaded]
set -eu
cd "$(dirname "$0")/.."
BIN=$(realpath "${1:-build/arcaded}")
out=$(pwd)/docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
# tap TICK CONTROL: press at TICK, release a tick later.
tap() { printf '%d press %s\n%d release %s\n' "$1" "$2" $(($1 + 1)) "$2"; }
{
	tap 2 coin
	tap 4 coin
	tap 6 service
	echo "7 expect mode == service"
	echo "10 screenshot $out/service-main.png"
	tap 12 fire                     # INPUT TEST
	tap 14 coin
	echo "16 press forward"
	echo "18 screenshot $out/service-input.png"
	echo "19 release forward"
	tap 20 service                  # back to the main page, cursor on INPUT TEST
	tap 22 back                     # DISPLAY TEST
	tap 24 fire
	echo "28 screenshot $out/service-display-bars.png"
	tap 30 fire
	echo "34 screenshot $out/service-display-grid.png"
	tap 36 fire
	echo "40 screenshot $out/service-display-orientation.png"
	tap 42 service
	tap 44 back                     # SOUND TEST
	tap 46 fire
	echo "50 screenshot $out/service-sound.png"
	tap 52 service
	tap 54 back                     # GAME SETTINGS
	tap 56 fire
	echo "60 screenshot $out/service-settings.png"
	tap 62 service
	tap 64 back                     # BOOKKEEPING
	tap 66 fire
	echo "70 screenshot $out/service-bookkeeping.png"
	tap 72 fire
	tap 74 back                     # RESET HIGH SCORES
	tap 76 fire
	echo "80 screenshot $out/service-reset-confirm.png"
	tap 82 service
	echo "84 expect menu == 0"
	tap 86 back                     # RESET BOOKKEEPING
	tap 88 back                     # DEVICES
	tap 90 fire
	echo "94 screenshot $out/service-devices.png"
	tap 96 fire
	tap 98 back                     # LATENCY
	tap 100 fire
	tap 110 coin                    # inputs to measure; moves do nothing here
	tap 120 back
	tap 130 start
	echo "160 screenshot $out/service-latency.png"
	tap 162 service
	echo "164 expect menu == 0"
} >"$tmp/service.scr"
"$BIN" --script "$tmp/service.scr" --config-dir "$tmp/etc" --state-dir "$tmp/state" \
	--set game.render_width=640 --set game.render_height=480 >"$tmp/log" 2>&1 || {
	cat "$tmp/log" >&2
	echo "service-shots: failed" >&2
	exit 1
}
# The app's pages (app/pick.h): CONTENT PACK on a content directory made
# here (Freedoom's IWADs when the freedoom package is installed, and a
# truncated WAD that is named as not listed), the map list of the first
# pack, and SCREEN. Then, with a configuration file that has two errors,
# the attract screen's notice, the main page's line and CONFIG ERRORS.
mkdir -p "$tmp/content" "$tmp/etc2"
for w in /usr/share/games/doom/freedoom1.wad /usr/share/games/doom/freedoom2.wad; do
	[ -r "$w" ] && ln -s "$w" "$tmp/content/"
done
printf 'PWAD\003\000\000\000\377\377\000\000' > "$tmp/content/broken.wad"
{
	tap 2 service
	t=4; for i in 1 2 3 4 5 6 7 8 9; do tap $t back; t=$((t + 2)); done
	tap 24 fire                     # CONTENT PACK
	tap 26 back                     # the first WAD
	echo "30 screenshot $out/service-content.png"
	tap 32 fire                     # its maps
	tap 34 back
	tap 36 back                     # FROM ...M2
	echo "40 screenshot $out/service-content-maps.png"
	tap 42 service                  # back to the packs
	tap 44 service                  # out of the page
	tap 46 back                     # SCREEN
	tap 48 fire
	tap 50 turn_right               # 90
	echo "54 screenshot $out/service-screen.png"
	tap 56 service
	echo "58 expect menu == 0"
} >"$tmp/app.scr"
"$BIN" --script "$tmp/app.scr" --config-dir "$tmp/etc" --state-dir "$tmp/state" \
	--set game.render_width=640 --set game.render_height=480 \
	--set "game.content_dirs=$tmp/content" >"$tmp/log" 2>&1 || {
	cat "$tmp/log" >&2
	echo "service-shots: the app's pages failed" >&2
	exit 1
}
printf '[game]\nlives = 12\n\n[display]\nrotate = 45\n' > "$tmp/etc2/50-local.ini"
{
	echo "60 screenshot $out/attract-config-error.png"
	tap 62 service
	echo "66 screenshot $out/service-main-config-error.png"
	t=68; for i in 1 2 3 4 5 6 7 8 9 10 11; do tap $t back; t=$((t + 2)); done
	tap 92 fire                     # CONFIG ERRORS
	echo "96 screenshot $out/service-config.png"
	tap 98 service
	echo "100 expect menu == 0"
} >"$tmp/cfg.scr"
"$BIN" --script "$tmp/cfg.scr" --config-dir "$tmp/etc2" --state-dir "$tmp/state" \
	--set game.render_width=640 --set game.render_height=480 >"$tmp/log" 2>&1 || {
	cat "$tmp/log" >&2
	echo "service-shots: the configuration errors' pages failed" >&2
	exit 1
}
ls -1 "$out"/service-*.png "$out"/attract-config-error.png
