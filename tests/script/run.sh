#!/bin/sh
# Script tests: runs every tests/script/*.scr through the real daemon,
# headless on a file framebuffer, and checks
#  - the exit status (0, or the value of a "# expect-exit: N" line),
#  - every "# expect-stderr: TEXT" line appears in stderr,
#  - stdout (snapshot lines) equals NAME.out when that file exists.
# Usage: tests/script/run.sh path/to/arcaded
set -u
BIN=$1
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
for scr in tests/script/*.scr; do
	name=$(basename "$scr" .scr)
	want_exit=$(sed -n 's/^# expect-exit: *\([0-9]*\).*/\1/p' "$scr" | head -n 1)
	want_exit=${want_exit:-0}
	(cd "$tmp" && rm -f fb out err)
	"$BIN" --script "$scr" --config-dir "$tmp/etc" --state-dir "$tmp/state" \
		--set display.backend=file --set display.file="$tmp/fb" \
		--set display.file_format=xrgb8888 --set display.file_width=640 \
		--set display.file_height=480 >"$tmp/out" 2>"$tmp/err"
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
