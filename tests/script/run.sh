#!/bin/sh
# Script tests: runs every tests/script/*.scr through the real daemon,
# headless on a file framebuffer, and checks
#  - the exit status (0, or the value of a "# expect-exit: N" line),
#  - every "# expect-stderr: TEXT" line appears in stderr,
#  - every "# expect-file: NAME" exists afterwards (relative to the run's
#    working directory, a fresh temporary one) and is a PNG,
#  - stdout (snapshot lines) equals NAME.out when that file exists,
#  - when the run ended normally, the file framebuffer (640x480 xrgb8888)
#    has its full size and is, byte for byte, the frame stored for the
#    script: its SHA-256 in tests/script/frames.sha256. Those were written
#    by tests/script/regen.sh, which also writes each frame as a PNG to
#    look at before committing; a script without a stored frame fails.
# Usage: tests/script/run.sh path/to/arcaded
set -u
BIN=$(realpath "$1")
cd "$(dirname "$0")/../.."
top=$(pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
for scr in tests/script/*.scr tests/script/game/*.scr; do
	name=$(basename "$scr" .scr)
	want_exit=$(sed -n 's/^# expect-exit: *\([0-9]*\).*/\1/p' "$scr" | head -n 1)
	want_exit=${want_exit:-0}
	rm -rf "$tmp/run"; mkdir "$tmp/run"
	(cd "$tmp/run" && "$BIN" --script "$top/$scr" --config-dir "$tmp/etc" --state-dir "$tmp/state" \
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
echo "scripts: $pass passed, $fail failed"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
