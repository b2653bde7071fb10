#!/bin/sh
# Hostile maps through the real daemon (issue 13 items 7-9). tests/hostile/
# mkhostile.c writes each hostile WAD of the issue (generators shared with
# the unit tests: tests/unit/hostile_fixture.h); the daemon loads each one
# headless and must end with the expected clear error, or with the
# expected logged fallback and a normal run, and never hang: each run has a
# hang guard of GUARD seconds (default 30; before the limits the DAG, the
# tall texture and the crossing lines ran for minutes or for ever).
# Load time and peak RSS are printed as FIGURE lines, not asserted.
# Then a SIGTERM and a SIGINT sent while a long load runs must end it
# (exit 0, "stopped" in the log); the time from the signal to the exit is
# printed, and the guard is 5 s.
# Usage: tests/hostile/run.sh path/to/arcaded
set -u
BIN=$(realpath "$1")
GUARD=${GUARD:-30}
cd "$(dirname "$0")/../.."
CC=${CC:-cc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
ok() { echo "PASS $*"; pass=$((pass + 1)); }
bad() { echo "FAIL $*"; fail=$((fail + 1)); }

if ! $CC -std=c11 -O2 -Wall -Wextra -Werror -I. -D_GNU_SOURCE tests/hostile/mkhostile.c \
	-o "$tmp/mkhostile" 2>"$tmp/cc.err"; then
	cat "$tmp/cc.err"; echo "FAIL build tests/hostile/mkhostile.c"; exit 1
fi
mkdir "$tmp/w"
"$tmp/mkhostile" "$tmp/w" || { echo "FAIL mkhostile could not write the WADs"; exit 1; }
printf '2 end\n' >"$tmp/end.scr"

now_ms() { echo $(($(date +%s%N) / 1000000)); }

# run WAD: the daemon on WAD in the background, its pid in $pid
start() {
	"$BIN" --config-dir "$tmp/etc" --state-dir "$tmp/state" --wad "$tmp/w/$1" \
		--script "$tmp/end.scr" --set display.backend=file --set display.file="$tmp/fb" \
		>/dev/null 2>"$tmp/err" &
	pid=$!
}

# wait_for SECONDS: waits for $pid; sets rc (124 when the guard ran out and
# the daemon was killed), hwm (peak RSS in KiB, sampled from /proc)
wait_for() {
	t_end=$(($(now_ms) + $1 * 1000))
	hwm=0
	while kill -0 "$pid" 2>/dev/null; do
		h=$(sed -n 's/^VmHWM:[[:space:]]*\([0-9]*\) kB/\1/p' "/proc/$pid/status" 2>/dev/null)
		[ -n "$h" ] && hwm=$h
		if [ "$(now_ms)" -gt "$t_end" ]; then
			kill -KILL "$pid" 2>/dev/null
			wait "$pid" 2>/dev/null
			rc=124
			return
		fi
		sleep 0.02
	done
	wait "$pid"
	rc=$?
}

# case WAD EXIT TEXT: the daemon on WAD ends with status EXIT within the
# guard and its log holds TEXT
case_() {
	wad=$1; want=$2; text=$3
	t0=$(now_ms)
	start "$wad"
	wait_for "$GUARD"
	ms=$(($(now_ms) - t0))
	[ "$hwm" -gt 0 ] && rss="peak RSS $hwm KiB" || rss="ended before an RSS sample"
	echo "FIGURE hostile $wad: $ms ms, $rss, exit $rc"
	if [ "$rc" -eq 124 ]; then
		bad "$wad: still running after ${GUARD} s (killed)"
	elif [ "$rc" -ne "$want" ] || ! grep -qF -- "$text" "$tmp/err"; then
		bad "$wad: exit $rc (expected $want), log:"; sed 's/^/    /' "$tmp/err"
	else
		ok "$wad: exit $rc: $(grep -F -- "$text" "$tmp/err" | head -n 1)"
	fi
}

case_ dag.wad 2 "MAP01: node 1199: child[1] node 1198 is reached a second time: the BSP is not a tree"
case_ high.wad 2 "MAP01: SECTORS entry 0: floor 32730 out of range (+/-16383 units"
case_ tall.wad 2 "tall.wad: TEXTURE1 entry 0 (HOSTILE): the textures need more than 268435456 steps to compose (limit TEX_MAX_STEPS)"
case_ cross2004.wad 2 "cross2004.wad: MAP01: NODES (built here): node builder: 2008 lines need more than 268435456 steps (limit NB_MAX_STEPS)"
case_ cross30004.wad 2 "cross30004.wad: MAP01: NODES (built here): node builder: 30008 lines need more than 268435456 steps (limit NB_MAX_STEPS)"
case_ lights30000.wad 0 "lights30000.wad: MAP01: THINGS: 30000 lights, more than the limit of 4096 (LMAP_MAX_LIGHTS): drawn without light maps"
case_ litlines.wad 0 "litlines.wad: MAP01: THINGS: light maps need more than 209715200 steps (limit LMAP_MAX_STEPS): drawn without light maps"
case_ markers100000.wad 0 "content: $tmp/w/markers100000.wad MAP01"

# signal SIG WAD: SIG sent 0.3 s into the load of WAD ends it
signal_() {
	sig=$1; wad=$2
	start "$wad"
	sleep 0.3
	t0=$(now_ms)
	kill -"$sig" "$pid"
	wait_for 5
	ms=$(($(now_ms) - t0))
	echo "FIGURE hostile SIG$sig during the load of $wad: exit after $ms ms"
	if [ "$rc" -eq 0 ] && grep -q "stopped" "$tmp/err"; then
		ok "SIG$sig stops the load of $wad: $(grep stopped "$tmp/err" | head -n 1)"
	else
		bad "SIG$sig during the load of $wad: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
	fi
}
signal_ TERM cross30004.wad
signal_ INT tall.wad
signal_ TERM litlines.wad

echo "hostile: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
