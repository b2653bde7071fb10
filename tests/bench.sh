#!/bin/sh
# Benchmarks (not tests): headless frames per second of the whole loop
# (sim + render + null present) replaying a scripted walk through the
# built-in level, at several render sizes, and the peak RSS of each run.
# Usage: tests/bench.sh path/to/arcaded
set -eu
BIN=$1
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
common="--config-dir $tmp/etc --state-dir $tmp/state"
"$BIN" $common --script tests/replay/walk.scr --record "$tmp/walk.rec" >/dev/null 2>&1
ticks=$(( ($(stat -c %s "$tmp/walk.rec") - 40) / 6 ))
printf '%-10s %8s %10s %12s %12s %10s\n' size ticks frames/s "p50 ms" "p99 ms" "RSS KiB"
for size in 320x240 640x480 1280x720 1920x1080; do
	w=${size%x*}; h=${size#*x}
	ARCADED_SUMMARY=1 "$BIN" $common --replay "$tmp/walk.rec" --quiet \
		--set game.render_width="$w" --set game.render_height="$h" 2>"$tmp/err" >/dev/null
	fps=$(sed -n 's/.*(\([0-9.]*\) frames\/s).*/\1/p' "$tmp/err")
	rss=$(sed -n 's/.*peak RSS \([0-9]*\) KiB.*/\1/p' "$tmp/err")
	p50=$(sed -n 's/.*frame time (render+present) p50 \([0-9.]*\) ms p99 \([0-9.]*\) ms.*/\1/p' "$tmp/err")
	p99=$(sed -n 's/.*frame time (render+present) p50 \([0-9.]*\) ms p99 \([0-9.]*\) ms.*/\2/p' "$tmp/err")
	printf '%-10s %8s %10s %12s %12s %10s\n' "$size" "$ticks" "$fps" "$p50" "$p99" "$rss"
done
