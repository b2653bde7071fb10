#!/bin/sh
# Script tests: runs every tests/script/*.scr through the real daemon,
# headless on a file framebuffer, and checks
#  - the exit status (0, or the value of a "# expect-exit: N" line),
#    the script run with the settings of its "# set: KEY=VALUE" lines,
#  - every "# expect-stderr: TEXT" line appears in stderr,
#  - every "# expect-file: NAME" exists afterwards (relative to the run's
#    working directory, a fresh temporary one) and is a PNG,
#  - stdout (snapshot lines) equals NAME.out when that file exists,
#  - when the run ended normally, the file framebuffer (640x480 xrgb8888)
#    has its full size and is, byte for byte, the frame stored for the
#    script: its SHA-256 in tests/script/frames.sha256. Those were written
#    by tests/script/regen.sh, which also writes each frame as a PNG to
#    look at before committing; a script without a stored frame fails.
# Then the sound: tests/script/sound/shots.scr played with --audio wav:FILE
# at 48000 Hz and at 22050 Hz (ticks of 367 or 368 frames): the pistol's
# sound, found in the file by correlation with its own samples
# (tests/sound/sndfind.c, built next to the daemon's unit tests), begins at
# the first frame of exactly the ticks where the script fires, and the
# file holds exactly every tick's frames.
# Usage: tests/script/run.sh path/to/arcaded
set -u
BIN=$(realpath "$1")
cd "$(dirname "$0")/../.."
top=$(pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. tests/script/args.sh
pass=0
fail=0
for scr in tests/script/*.scr tests/script/game/*.scr; do
	name=$(basename "$scr" .scr)
	want_exit=$(sed -n 's/^# expect-exit: *\([0-9]*\).*/\1/p' "$scr" | head -n 1)
	want_exit=${want_exit:-0}
	rm -rf "$tmp/run"; mkdir "$tmp/run"
	(cd "$tmp/run" && "$BIN" --script "$top/$scr" $(script_args "$top/$scr") --config-dir "$tmp/etc" --state-dir "$tmp/state" \
		--set display.backend=file --set display.file="$tmp/fb" \
		--set display.file_format=xrgb8888 --set display.file_width=640 \
		--set display.file_height=480 >"$tmp/out" 2>"$tmp/err")
	rc=$?
	ok=1
	if [ "$rc" -ne "$want_exit" ]; then
		echo "$name: exit status $rc, expected $want_exit"; ok=0
	fi
	while IFS= read -r text; do
		if ! grep -qF -- "$text" "$tmp/err"; then
			echo "$name: stderr lacks: $text"; ok=0
		fi
	done <<EOT
$(sed -n 's/^# expect-stderr: //p' "$scr")
EOT
	for f in $(sed -n 's/^# expect-file: //p' "$scr"); do
		if ! head -c 8 "$tmp/run/$f" 2>/dev/null | grep -q PNG; then
			echo "$name: $f is missing or not a PNG"; ok=0
		fi
	done
	if [ "$rc" -eq 0 ]; then
		size=$(stat -c %s "$tmp/fb" 2>/dev/null || echo 0)
		got=$(sha256sum < "$tmp/fb" 2>/dev/null | cut -d' ' -f1)
		want=$(awk -v n="$name" '$2 == n { print $1 }' tests/script/frames.sha256)
		if [ "$size" -ne $((640 * 480 * 4)) ]; then
			echo "$name: file framebuffer size $size, not 640x480x4"; ok=0
		elif [ -z "$want" ]; then
			echo "$name: no frame stored in tests/script/frames.sha256 (tests/script/regen.sh)"; ok=0
		elif [ "$got" != "$want" ]; then
			echo "$name: the last frame differs from the stored one ($got, stored $want)"; ok=0
		fi
	fi
	if [ -f "tests/script/$name.out" ] && ! diff -u "tests/script/$name.out" "$tmp/out"; then
		echo "$name: stdout differs from tests/script/$name.out"; ok=0
	fi
	if [ "$ok" -eq 1 ]; then
		echo "PASS script $name"; pass=$((pass + 1))
	else
		sed 's/^/  stderr: /' "$tmp/err"
		echo "FAIL script $name"; fail=$((fail + 1))
	fi
done
# ---- sound -----------------------------------------------------------------
FIND=$(dirname "$BIN")/tests/sndfind
shots="200 260 345 420 470 482 494"
end=520
for rate in 48000 22050; do
	name="sound-shots-$rate"
	rm -rf "$tmp/run"; mkdir "$tmp/run"
	"$BIN" --script tests/script/sound/shots.scr --config-dir "$tmp/etc" --state-dir "$tmp/state" \
		--audio wav:"$tmp/run/shots.wav" --set audio.rate=$rate >"$tmp/out" 2>"$tmp/err"
	rc=$?
	if [ ! -x "$FIND" ]; then
		echo "$name: $FIND missing (make tests builds it)"; ok=0
	else
		"$FIND" --min 0.9 "$tmp/run/shots.wav" PISTOL >"$tmp/found" 2>&1
		got=$(awk '$1 == "found" { printf "%s ", $2 }' "$tmp/found")
		want=$(for t in $shots; do printf '%s ' $((t * rate / 60)); done)
		scores=$(awk '$1 == "found" { printf "%s ", $3 }' "$tmp/found")
		frames=$(sed -n 's/.*frames \([0-9]*\),.*/\1/p' "$tmp/found")
		ok=1
		[ "$rc" -eq 0 ] || { echo "$name: exit status $rc"; ok=0; }
		[ "$got" = "$want" ] || { echo "$name: the shot found at frames $got; fire at $want"; ok=0; }
		# ticks 0..end: F(end + 1) frames
		[ "$frames" = $(((end + 1) * rate / 60)) ] ||
			{ echo "$name: $frames frames, not $(((end + 1) * rate / 60))"; ok=0; }
	fi
	if [ "$ok" -eq 1 ]; then
		echo "PASS script $name: the shot at frames $got(scores $scores)"; pass=$((pass + 1))
	else
		cat "$tmp/found" "$tmp/err" 2>/dev/null | sed 's/^/  /'
		echo "FAIL script $name"; fail=$((fail + 1))
	fi
done

echo "scripts: $pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
