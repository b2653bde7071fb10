#!/bin/sh
# Writes tests/script/frames.sha256: for every script test that ends
# normally, the SHA-256 of the file framebuffer (640x480 xrgb8888) the
# daemon leaves when tests/script/run.sh runs it. Each frame is also
# written as a PNG under OUT (default: a new temporary folder, printed):
# look at every one before committing new hashes, and say in the commit
# why the frames changed (as for tests/replay/regen.sh).
# Usage: tests/script/regen.sh path/to/arcaded [OUT]
set -eu
BIN=$(realpath "$1")
cd "$(dirname "$0")/../.."
top=$(pwd)
out=${2:-$(mktemp -d)}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: > "$tmp/frames"
for scr in tests/script/*.scr tests/script/game/*.scr; do
	name=$(basename "$scr" .scr)
	rm -rf "$tmp/run"; mkdir "$tmp/run"
	rc=0
	# "# set: KEY=VALUE" lines: settings the script runs with (--set)
	sets=$(sed -n 's/^# set: *\([^ ]*\).*/--set \1/p' "$scr" | tr '\n' ' ')
	# shellcheck disable=SC2086
	(cd "$tmp/run" && "$BIN" --script "$top/$scr" $sets --config-dir "$tmp/etc" --state-dir "$tmp/state" \
		--set display.backend=file --set display.file="$tmp/fb" \
		--set display.file_format=xrgb8888 --set display.file_width=640 \
		--set display.file_height=480 >/dev/null 2>&1) || rc=$?
	[ "$rc" -eq 0 ] || continue
	echo "$(sha256sum < "$tmp/fb" | cut -d' ' -f1) $name" >> "$tmp/frames"
	python3 tests/script/fb2png.py "$tmp/fb" 640 480 "$out/$name.png"
done
sort -k2 "$tmp/frames" > tests/script/frames.sha256
echo "regen: tests/script/frames.sha256 written ($(wc -l < tests/script/frames.sha256) frames); look at $out/*.png"
