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
fail=0
found=0
for bin in "$dir"/fuzz_*; do
	[ -x "$bin" ] || continue
	case "$bin" in *.d) continue ;; esac
	found=1
	name=$(basename "$bin")
	seeds=tests/fuzz/corpus/$name
	crashes=tests/fuzz/crashes/$name
	mkdir -p "$scratch/$name"
	if [ -d "$crashes" ] && [ -n "$(ls -A "$crashes" 2>/dev/null)" ]; then
		if ! "$bin" "$crashes"/* >"$scratch/$name.regress" 2>&1; then
			tail -n 30 "$scratch/$name.regress"
			echo "FAIL $name: a kept crash input crashes again"; fail=1; continue
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
		echo "FAIL $name after ${execs:-?} executions"; fail=1
	else
		echo "PASS $name: ${execs:-?} executions in ${secs} s, no crash"
	fi
done
[ "$found" -eq 1 ] || { echo "no fuzz targets in $dir"; exit 1; }
exit "$fail"
