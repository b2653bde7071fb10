#!/bin/sh
# Runs every libFuzzer target in DIR for SECONDS each, from its seed corpus
# (tests/fuzz/corpus/<target>/, read-only: new inputs go to a scratch
# corpus), and first replays the kept crash inputs (tests/fuzz/crashes/
# <target>/) as regression cases. Prints executions per target.
# Usage: tests/fuzz/run.sh DIR SECONDS
set -u
dir=$1
secs=$2
cd "$(dirname "$0")/../.."
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# JOBS targets fuzz at once (default: the number of cores; each libFuzzer
# run is one thread): each has its own scratch corpus and log, and the
# reports are printed in the targets' order afterwards.
. tests/pool.sh
one() { # $1: target binary; prints its report, returns 1 on failure
	bin=$1
	name=$(basename "$bin")
	seeds=tests/fuzz/corpus/$name
	crashes=tests/fuzz/crashes/$name
	mkdir -p "$scratch/$name"
	if [ -d "$crashes" ] && [ -n "$(ls -A "$crashes" 2>/dev/null)" ]; then
		if ! "$bin" "$crashes"/* >"$scratch/$name.regress" 2>&1; then
			tail -n 30 "$scratch/$name.regress"
			echo "FAIL $name: a kept crash input crashes again"
			return 1
		fi
	fi
	"$bin" -max_total_time="$secs" -print_final_stats=1 -artifact_prefix="$scratch/$name-" \
		"$scratch/$name" ${seeds:+$( [ -d "$seeds" ] && echo "$seeds")} >"$scratch/$name.log" 2>&1
	rc=$?
	execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$scratch/$name.log")
	if [ "$rc" -ne 0 ]; then
		tail -n 40 "$scratch/$name.log"
		mkdir -p "$crashes"
		for a in "$scratch/$name"-*; do [ -f "$a" ] && cp "$a" "$crashes/" && echo "kept $crashes/$(basename "$a")"; done
		echo "FAIL $name after ${execs:-?} executions"
		return 1
	fi
	echo "PASS $name: ${execs:-?} executions in ${secs} s, no crash"
}
targets=""
for bin in "$dir"/fuzz_*; do
	[ -x "$bin" ] || continue
	case "$bin" in *.d) continue ;; esac
	targets="$targets $bin"
done
[ -n "$targets" ] || { echo "no fuzz targets in $dir"; exit 1; }
pool_run "$scratch" one $targets
fail=0
k=0
for bin in $targets; do
	k=$((k + 1))
	cat "$scratch/$k.log"
	[ "$(cat "$scratch/$k.rc" 2>/dev/null || echo 1)" -eq 0 ] || fail=1
done
exit "$fail"
