#!/bin/sh
# Soak: 1,000,000 ticks (4.6 hours of cabinet time) of random input through
# attract, play, game over and initials, replayed headless with rendering;
# peak RSS and open file descriptors at the end must equal those after the
# first 10,000 ticks (RSS within 256 KiB: run-to-run allocator noise, seen
# +-100 KiB between runs of equal length). Also a replay
# under valgrind memcheck with zero reports.
# Usage: tests/soak/run.sh path/to/arcaded [TICKS]
set -u
BIN=$(realpath "$1")
TICKS=${2:-1000000}
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
common="--config-dir $tmp/etc --state-dir $tmp/state"
fail=0
check() { if [ "$2" -eq 0 ]; then echo "PASS $1"; else echo "FAIL $1"; fail=1; fi; }

printf '0 end\n' >"$tmp/one.scr"
"$BIN" $common --script "$tmp/one.scr" --record "$tmp/tmpl.rec" >/dev/null 2>&1
python3 tests/soak/gen.py "$tmp/tmpl.rec" "$tmp/soak.rec" "$TICKS" 20261121 ||
	{ echo "FAIL could not write the soak recording"; exit 1; }

figures() { # $1 extra args -> "RSS FDS SECONDS"
	# a small frame: every drawing path runs, the pixel work does not
	# dominate (1M ticks take minutes, not tens of minutes)
	ARCADED_SUMMARY=1 "$BIN" $common replay "$tmp/soak.rec" --quiet --size 160x120 $1 \
		>/dev/null 2>"$tmp/err"
	rc=$?
	rss=$(sed -n 's/.*peak RSS \([0-9]*\) KiB.*/\1/p' "$tmp/err")
	fds=$(sed -n 's/.*KiB, \([0-9-]*\) open fds.*/\1/p' "$tmp/err")
	secs=$(sed -n 's/.*frames in \([0-9.]*\) s.*/\1/p' "$tmp/err")
	echo "$rc ${rss:-0} ${fds:-0} ${secs:-0}"
}
set -- $(figures "--until 9999")
rc10=$1 rss10=$2 fds10=$3
set -- $(figures "")
rc1m=$1 rss1m=$2 fds1m=$3 secs1m=$4
echo "soak: after 10,000 ticks: peak RSS $rss10 KiB, $fds10 open fds"
echo "soak: after $TICKS ticks ($secs1m s): peak RSS $rss1m KiB, $fds1m open fds"
check "both runs end normally (exit $rc10, $rc1m)" $([ "$rc10" -eq 0 ] && [ "$rc1m" -eq 0 ]; echo $?)
check "open fds equal ($fds10 vs $fds1m)" $([ "$fds10" -eq "$fds1m" ] && [ "$fds10" -gt 0 ]; echo $?)
check "peak RSS does not grow ($rss10 vs $rss1m KiB)" $([ "$rss1m" -le $((rss10 + 256)) ]; echo $?)

if command -v valgrind >/dev/null 2>&1; then
	"$BIN" $common --script tests/replay/walk.scr --record "$tmp/walk.rec" >/dev/null 2>&1
	valgrind --quiet --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite \
		"$BIN" $common replay "$tmp/walk.rec" --quiet >/dev/null 2>"$tmp/vg"
	rc=$?
	check "a replay under valgrind memcheck: no errors, no definite leaks (exit $rc)" \
		$([ "$rc" -eq 0 ]; echo $?)
	[ "$rc" -eq 0 ] || tail -n 30 "$tmp/vg"
else
	echo "FAIL valgrind is not installed (scripts/setup.sh installs it)"; fail=1
fi
exit "$fail"
