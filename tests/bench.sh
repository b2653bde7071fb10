#!/bin/sh
# make bench: speed of the software renderer beside OSMesa and two Doom
# engines, measured in one run (not a test: speed is reported, never
# asserted; only frames that differ between thread counts fail it).
#
# Camera paths are recorded from scripts first: the built-in level walk
# (tests/replay/walk.scr, ARENA1) and a walk through Freedoom's E1M1
# (tests/bench/e1m1.scr). tests/bench/rbench.c replays each at 320x240,
# 640x480, 1280x720, 1920x1080 and 3840x2160 and draws every frame as the
# daemon does (world, sprites, light maps, HUD) then presents it into an
# xrgb8888 panel in memory (in row ranges on the same threads): frames/s on
# one thread and on all cores, ms per frame p50/p99 and their ratio (and
# the same over each frame's fastest of the two passes every run makes:
# the path's own spread, without frames another process slowed), peak
# RSS and private memory (anonymous and private dirty pages,
# smaps_rollup); then the same path drawn by the OSMesa renderer with
# LP_NUM_THREADS=1 and with llvmpipe's default threads (every 8th frame),
# when engine/gl/ and OSMesa are there. The peers, chocolate-doom and
# dsda-doom (installed here with apt-get when missing and run as root), play
# freedoom1's DEMO1 with -timedemo under Xvfb at the same sizes; their
# steady-state rate is (tics of a 1000-tic cut - tics of a 200-tic cut) /
# (wall time difference), which removes start-up and the real-time screen
# wipe (shared/notes/peers.md). chocolate-doom renders 320x200 only, with
# -noblit (no present); dsda-doom's figure includes its SDL present. The
# peers' peak RSS and private memory are measured by tests/bench/runstat.c.
#
# The daemon itself (tests/bench/runstat.c): its peak RSS and private
# memory playing the E1M1 walk at 640x480 on the file framebuffer with
# freedoom1, and the same walk on freedoom2's MAP01; and exec to its first
# frame (READY=1, which it sends once the first frame is presented) on
# freedoom1 E1M1, the median of five starts.
#
# Run as root, the measured processes get nice -20 (less disturbed by other
# load). The mixer's cost per tick with 16 busy channels (tests/bench/mbench.c)
# is reported too. Output: a table on stdout, build/bench/bench.csv, build/bench/bench.png.
# Each of rbench's figures is the run of median frames/s of BENCH_ROUNDS
# (default 3), the thread counts alternating run by run; rounds where the
# capacity probe just before or after saw the machine give N threads less
# than 0.95 N times one thread's work are left out when any other is calm
# (the CSV's note says how many were). The speed-up is the median of the
# rounds' own ratios (N threads' run over the one-thread run beside it), not
# the ratio of the two medians, which can pair runs from different minutes.
# Usage: tests/bench.sh path/to/arcaded   (BENCH_SECONDS: timed seconds per
# run, default 1; BENCH_PEERS=0 skips the peers)
set -eu
BIN=$1
cd "$(dirname "$0")/.."
B=$(dirname "$BIN")
OUT=build/bench
WAD=/usr/share/games/doom/freedoom1.wad
SECS=${BENCH_SECONDS:-1}
ROUNDS=${BENCH_ROUNDS:-3}
# a round is calm when NCPU threads of integer work ran at least this
# fraction of NCPU times as fast as one, just before and just after it
CALM=0.95
NCPU=$(nproc)
SIZES="320x240 640x480 1280x720 1920x1080 3840x2160"
mkdir -p "$OUT"
tmp=$(mktemp -d)
xpid=
cleanup() {
	[ -n "$xpid" ] && kill "$xpid" 2>/dev/null
	rm -rf "$tmp"
}
trap cleanup EXIT
# As root, every measured process (and Xvfb) runs at nice -20: other load on
# the machine then disturbs the figures much less, and all engines alike.
PRIO=
if [ "$(id -u)" = 0 ] && nice -n -20 true 2>/dev/null; then
	PRIO="nice -n -20"
fi
CC=${CC:-cc}
CFL="-O2 -g -I. -D_GNU_SOURCE -std=c11 -Wall -Wextra -Werror"
LIBS="$(pkg-config --libs libevdev libpng libsystemd hidapi-hidraw libgpiod) -lpthread -lm"

# ---- tools --------------------------------------------------------------
$CC $CFL -o "$tmp/rbench" tests/bench/rbench.c "$B/libarcaded.a" $LIBS
$CC $CFL -o "$tmp/chart" tests/bench/chart.c "$B/libarcaded.a" $LIBS
$CC $CFL -o "$tmp/demo" tests/bench/demo.c
$CC $CFL -o "$tmp/runstat" tests/bench/runstat.c
$CC $CFL -o "$tmp/mbench" tests/bench/mbench.c "$B/libarcaded.a"
gl=0
if [ -f engine/gl/rgl.h ] && pkg-config --exists osmesa &&
	$CC $CFL -DRBENCH_GL -o "$tmp/rbench-gl" tests/bench/rbench.c engine/gl/*.c \
		"$B/libarcaded.a" $LIBS $(pkg-config --libs osmesa) 2>"$tmp/gl.err"; then
	gl=1
else
	echo "bench: no OSMesa renderer (engine/gl/ or libosmesa6-dev missing): its columns stay empty"
fi

# ---- camera paths ---------------------------------------------------------
common="--config-dir $tmp/etc --state-dir $tmp/state"
# a failed expect in a script still leaves a whole recording: only a missing
# one stops the bench
"$BIN" $common --script tests/replay/walk.scr --record "$tmp/arena1.rec" >/dev/null 2>&1 || true
[ -s "$tmp/arena1.rec" ] || { echo "bench: recording the ARENA1 walk failed"; exit 1; }
paths="arena1"
if [ -f "$WAD" ]; then
	"$BIN" $common --wad "$WAD" --map E1M1 --script tests/bench/e1m1.scr \
		--record "$tmp/e1m1.rec" >/dev/null 2>&1 || true
	[ -s "$tmp/e1m1.rec" ] || { echo "bench: recording the E1M1 walk failed"; exit 1; }
	paths="arena1 e1m1"
else
	echo "bench: $WAD missing (apt-get install freedoom): E1M1 left out"
fi
content() { # path -> rbench content options
	case $1 in
	arena1) echo "--level 1" ;;
	e1m1) echo "--wad $WAD --map E1M1" ;;
	esac
}

CSV=$OUT/bench.csv
echo "path,size,engine,threads,frames,fps,render_fps,p50_ms,p99_ms,rss_kib,priv_kib,note,p50_best_ms,p99_best_ms,speedup" >"$CSV"
kv() { # key line -> value
	echo "$2" | tr ' ' '\n' | sed -n "s/^$1=//p"
}
# what N threads can gain on this machine now (pure integer work)
cap=1 mcap=1
if [ "$NCPU" -gt 1 ]; then
	l=$($PRIO "$tmp/rbench" --capacity "$NCPU")
	cap=$(kv capacity "$l")
	mcap=$(kv mem_capacity "$l")
fi
identical=1
threads=1
[ "$NCPU" -gt 1 ] && threads="1 $NCPU"
# rgl LP_THREADS args...: the OSMesa run, llvmpipe on one thread or its default
rgl() {
	if [ "$1" = 1 ]; then
		shift
		LP_NUM_THREADS=1 $PRIO "$tmp/rbench-gl" "$@"
	else
		shift
		$PRIO "$tmp/rbench-gl" "$@"
	fi
}
for p in $paths; do
	for size in $SIZES; do
		h1=
		for t in $threads; do : >"$tmp/runs.$t"; : >"$tmp/calm.$t"; done
		: >"$tmp/ratio.all"
		: >"$tmp/ratio.calm"
		# ROUNDS rounds, one run per thread count in each, alternating:
		# a slower minute of the machine then hits both counts instead
		# of one. Each round is framed by two capacity probes; a round
		# where either saw less than CALM of NCPU (a vCPU the host gave
		# to someone else) is disturbed, and the figures come from the
		# calm rounds when there are any.
		calm=0
		for r in $(seq "$ROUNDS"); do
			c0=$NCPU
			[ "$NCPU" -gt 1 ] && c0=$(kv capacity "$($PRIO "$tmp/rbench" --capacity "$NCPU")")
			: >"$tmp/round"
			for t in $threads; do
				l=$($PRIO "$tmp/rbench" --rec "$tmp/$p.rec" $(content $p) --size "$size" \
					--threads "$t" --seconds "$SECS" --passes 2)
				echo "$t $(kv fps "$l") $l" >>"$tmp/round"
				if [ "$t" = 1 ] && [ -z "$h1" ]; then
					h1=$(kv hash "$l")
				elif [ "$(kv hash "$l")" != "$h1" ]; then
					echo "FAIL $p $size: frames on $t threads differ from one thread"
					identical=0
				fi
			done
			c1=$NCPU
			[ "$NCPU" -gt 1 ] && c1=$(kv capacity "$($PRIO "$tmp/rbench" --capacity "$NCPU")")
			ok=$(awk -v a="$c0" -v b="$c1" -v n="$NCPU" -v k="$CALM" \
				'BEGIN { print (a >= k * n && b >= k * n) ? 1 : 0 }')
			calm=$((calm + ok))
			for t in $threads; do
				sed -n "s/^$t //p" "$tmp/round" >>"$tmp/runs.$t"
				[ "$ok" = 1 ] && sed -n "s/^$t //p" "$tmp/round" >>"$tmp/calm.$t"
			done
			# this round's speed-up: its two runs, minutes apart at
			# most, instead of medians that may come from different
			# rounds (a slow minute for one count alone makes those
			# read above NCPU x or far below)
			if [ "$NCPU" -gt 1 ]; then
				q=$(awk -v n="$NCPU" '$1 == 1 { a = $2 } $1 == n { b = $2 }
					END { if (a > 0 && b > 0) printf "%.4f", b / a }' "$tmp/round")
				if [ -n "$q" ]; then
					echo "$q" >>"$tmp/ratio.all"
					[ "$ok" = 1 ] && echo "$q" >>"$tmp/ratio.calm"
				fi
			fi
		done
		for t in $threads; do
			# the run of median frames/s (calm rounds, else all), with
			# its own p50, p99 and memory
			f=$tmp/runs.$t
			n=$ROUNDS
			if [ "$calm" -gt 0 ]; then
				f=$tmp/calm.$t
				n=$calm
			fi
			l=$(sort -n "$f" | sed -n "$(((n + 1) / 2))p" | cut -d' ' -f2-)
			# the median of the rounds' own speed-ups (same rounds)
			sp=
			if [ "$t" != 1 ]; then
				r=$tmp/ratio.all
				[ "$calm" -gt 0 ] && r=$tmp/ratio.calm
				sp=$(sort -n "$r" | awk '{ v[NR] = $1 } END {
					if (NR) printf "%.4f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
			fi
			echo "$p,$size,arcaded,$t,$(kv frames "$l"),$(kv fps "$l"),$(kv render_fps "$l"),$(kv p50_ms "$l"),$(kv p99_ms "$l"),$(kv rss_kib "$l"),$(kv priv_kib "$l"),median of $n runs ($calm of $ROUNDS rounds calm),$(kv p50_best_ms "$l"),$(kv p99_best_ms "$l"),$sp" >>"$CSV"
		done
		if [ "$gl" = 1 ]; then
			for t in 1 default; do
				l=$(rgl "$t" --rec "$tmp/$p.rec" $(content $p) --size "$size" \
					--renderer gl --stride 8 --seconds "$SECS")
				echo "$p,$size,osmesa,$([ "$t" = 1 ] && echo 1 || echo "$NCPU"),$(kv frames "$l"),$(kv fps "$l"),$(kv render_fps "$l"),$(kv p50_ms "$l"),$(kv p99_ms "$l"),$(kv rss_kib "$l"),$(kv priv_kib "$l"),every 8th frame LP_NUM_THREADS=$t" >>"$CSV"
			done
		fi
	done
done

# ---- peers ------------------------------------------------------------------
peers=${BENCH_PEERS:-1}
DSDA=/usr/games/dsda-doom
CHOC=/usr/games/chocolate-doom
if [ "$peers" = 1 ] && { [ ! -x $DSDA ] || [ ! -x $CHOC ] || ! command -v Xvfb >/dev/null; }; then
	if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
		echo "bench: installing the peers (dsda-doom chocolate-doom xvfb)"
		DEBIAN_FRONTEND=noninteractive apt-get install -y -qq dsda-doom chocolate-doom xvfb \
			>"$tmp/apt.log" 2>&1 ||
			{ apt-get update -qq >/dev/null 2>&1 &&
			  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq dsda-doom chocolate-doom \
				xvfb >"$tmp/apt.log" 2>&1; } ||
			echo "bench: apt-get could not install them: peers left out"
	else
		echo "bench: dsda-doom, chocolate-doom or Xvfb missing (not root): peers left out"
	fi
fi
if [ "$peers" = 1 ] && [ -f "$WAD" ] && command -v Xvfb >/dev/null; then
	# room for the 3840x2160 window
	$PRIO Xvfb -displayfd 3 -screen 0 3900x2250x24 -nolisten tcp 3>"$tmp/dpy" >/dev/null 2>&1 &
	xpid=$!
	for i in $(seq 50); do [ -s "$tmp/dpy" ] && break; sleep 0.1; done
	export DISPLAY=":$(cat "$tmp/dpy")"
	export HOME="$tmp/home"
	mkdir -p "$HOME"
	"$tmp/demo" "$WAD" DEMO1 "$tmp/long.lmp" 1000 >/dev/null
	"$tmp/demo" "$WAD" DEMO1 "$tmp/short.lmp" 200 >/dev/null
	# peer NAME SIZE CMD...: runs CMD with the long and the short demo
	# (DEMO replaced), writes the steady-state row
	peer() {
		name=$1 size=$2
		shift 2
		for cut in long short; do
			args=
			for a in "$@"; do
				[ "$a" = DEMO ] && a="$tmp/$cut.lmp"
				args="$args $a"
			done
			r=$($PRIO "$tmp/runstat" --every 100 "$tmp/$cut.out" $args)
			eval "w_$cut=$(kv wall_ns "$r") m_$cut=$(kv rss_kib "$r") v_$cut=$(kv priv_kib "$r")"
			eval "f_$cut=$(sed -n 's/.*[Tt]imed \([0-9]*\) gametics.*/\1/p' "$tmp/$cut.out" | head -1)"
		done
		if [ -z "$f_long" ] || [ -z "$f_short" ] || [ "$w_long" -le "$w_short" ]; then
			echo "bench: $name $size gave no timedemo figure (see its output below)"
			tail -3 "$tmp/long.out"
			return 0
		fi
		fps=$(awk -v a="$f_long" -v b="$f_short" -v x="$w_long" -v y="$w_short" \
			'BEGIN { printf "%.1f", (a - b) * 1e9 / (x - y) }')
		note="DEMO1 steady state ($f_long - $f_short tics)"
		[ "$name" = chocolate-doom ] && note="$note; 320x200 -noblit"
		echo "demo1,$size,$name,1,$((f_long - f_short)),$fps,,,,$m_long,$v_long,$note" >>"$CSV"
	}
	if [ -x $DSDA ]; then
		for size in $SIZES; do
			peer dsda-doom "$size" $DSDA -iwad "$WAD" -timedemo DEMO -geom "$size" -window \
				-nosound -nomusic
		done
	fi
	if [ -x $CHOC ]; then
		peer chocolate-doom 320x240 $CHOC -iwad "$WAD" -timedemo DEMO -nogui -noblit \
			-nosound -nomusic
	fi
fi

# ---- the daemon: memory and start-up ----------------------------------------
# Peak RSS and private memory of `arcaded` playing the E1M1 walk script at
# 640x480 on a file framebuffer, headless as fast as it runs (freedoom1
# E1M1; the same walk on freedoom2 MAP01); exec to READY=1 (the first frame
# presented) of a live start on freedoom1 E1M1, median of five.
DCSV=$OUT/daemon.csv
echo "what,wad,map,rss_kib,priv_kib,ready_ms" >"$DCSV"
fbopts="--set display.backend=file --set display.file=$tmp/fb --set display.file_width=640"
fbopts="$fbopts --set display.file_height=480 --set display.file_format=xrgb8888"
for wm in freedoom1:E1M1 freedoom2:MAP01; do
	wad=/usr/share/games/doom/${wm%%:*}.wad
	map=${wm#*:}
	[ -f "$wad" ] || { echo "bench: $wad missing: its memory figure left out"; continue; }
	r=$($PRIO "$tmp/runstat" --every 2 "$tmp/mem.out" "$BIN" $common --wad "$wad" --map "$map" \
		--script tests/bench/e1m1.scr --size 640x480 $fbopts)
	echo "memory,${wm%%:*},$map,$(kv rss_kib "$r"),$(kv priv_kib "$r")," >>"$DCSV"
done
if [ -f "$WAD" ]; then
	ready=""
	for i in 1 2 3 4 5; do
		r=$($PRIO "$tmp/runstat" --ready "$tmp/ready.out" "$BIN" $common --wad "$WAD" \
			--map E1M1 --size 640x480 $fbopts --ticks 600)
		ready="$ready $(kv ready_ns "$r")"
	done
	med=$(echo "$ready" | tr ' ' '\n' | grep . | sort -n | sed -n 3p)
	echo "ready,freedoom1,E1M1,,,$(awk -v n="${med:-0}" 'BEGIN { printf "%.1f", n / 1e6 }')" >>"$DCSV"
fi
# The same start on the built-in levels (no WAD): what `make run` and a
# cabinet without a configured WAD boot into. Reported, no target.
ready=""
for i in 1 2 3 4 5; do
	r=$($PRIO "$tmp/runstat" --ready "$tmp/ready.out" "$BIN" $common --size 640x480 $fbopts \
		--ticks 600)
	ready="$ready $(kv ready_ns "$r")"
done
med=$(echo "$ready" | tr ' ' '\n' | grep . | sort -n | sed -n 3p)
echo "ready,builtin,ARENA1,,,$(awk -v n="${med:-0}" 'BEGIN { printf "%.1f", n / 1e6 }')" >>"$DCSV"
cap2=1 mcap2=1
if [ "$NCPU" -gt 1 ]; then
	l=$($PRIO "$tmp/rbench" --capacity "$NCPU")
	cap2=$(kv capacity "$l")
	mcap2=$(kv mem_capacity "$l")
fi

# ---- report -----------------------------------------------------------------
"$tmp/chart" "$CSV" "$OUT/bench.png" || echo "bench: no chart"
# the capacity the thread figures can show: the lower of before and after
capmin=$(awk -v a="$cap" -v b="$cap2" 'BEGIN { print (a < b ? a : b) }')
awk -F, -v ncpu="$NCPU" -v identical="$identical" -v cap="$capmin" -v rounds="$ROUNDS" '
NR == FNR && FNR == 1 { next }
NR == FNR {
	key = $1 SUBSEP $2 SUBSEP $3 SUBSEP ($4 == 1 ? 1 : "n")
	fps[key] = $6; p50[key] = $8; p99[key] = $9; rss[key] = $10; priv[key] = $11
	if ($13 != "" && $13 != "-") { b50[key] = $13; b99[key] = $14 }
	if ($15 != "") sp[key] = $15
	if ($3 == "arcaded" && $12 ~ /rounds calm/) {
		c = $12; sub(/.*\(/, "", c); sub(/ of .*/, "", c); calmr[$1 SUBSEP $2] = c
	}
	if (!($1 in seenp)) { seenp[$1] = 1; if ($1 != "demo1") order[np++] = $1 }
	if (!($2 in seens)) { seens[$2] = 1; sizes[ns++] = $2 }
	next
}
FNR == 1 { next }
$1 == "memory" { drss[$2] = $4; dpriv[$2] = $5; dmap[$2] = $3 }
$1 == "ready" && $2 == "freedoom1" { ready = $6 }
$1 == "ready" && $2 == "builtin" { readyb = $6 }
function f(k) { return (k in fps) ? fps[k] : "-" }
function ratio(a, b) { return (a == "-" || b == "-" || b == 0) ? "-" : sprintf("%.2fx", a / b) }
function mib(v) { return v == "" ? "-" : sprintf("%.1f", v / 1024) }
END {
	printf "%-7s %-10s %9s %9s %7s %17s %6s %6s %5s %5s %8s %8s %8s %8s %5s\n", "path", "size", \
		"sw 1T", "sw " ncpu "T", "speedup", "p50/p99 ms", "p99/50", "best", "RSS", "priv", \
		"gl 1T", "gl " ncpu "T", "dsda", "choc", "calm"
	for (i = 0; i < np; i++) for (j = 0; j < ns; j++) {
		p = order[i]; s = sizes[j]
		one = f(p SUBSEP s SUBSEP "arcaded" SUBSEP 1)
		all = f(p SUBSEP s SUBSEP "arcaded" SUBSEP "n")
		if (all == "-") all = one
		k = p SUBSEP s SUBSEP "arcaded" SUBSEP (ncpu > 1 ? "n" : 1)
		printf "%-7s %-10s %9s %9s %7s %17s %6s %6s %5s %5s %8s %8s %8s %8s %5s\n", p, s, one, all, \
			(k in sp) ? sprintf("%.2fx", sp[k]) : ratio(all, one), p50[k] "/" p99[k], ratio(p99[k], p50[k]), \
			(k in b50) ? ratio(b99[k], b50[k]) : "-", mib(rss[k]), \
			mib(priv[k]), f(p SUBSEP s SUBSEP "osmesa" SUBSEP 1), \
			f(p SUBSEP s SUBSEP "osmesa" SUBSEP "n"), \
			f("demo1" SUBSEP s SUBSEP "dsda-doom" SUBSEP 1), \
			f("demo1" SUBSEP s SUBSEP "chocolate-doom" SUBSEP 1), \
			((p SUBSEP s) in calmr) ? calmr[p SUBSEP s] "/" rounds : "-"
	}
	print "(calm: rounds of " rounds " whose capacity probes before and after saw at least 0.95 of" \
		" " ncpu "x; the figures are the median run of the calm rounds, of all when none was;"
	print " speedup: the median of each round'"'"'s own " ncpu "-thread / 1-thread frames/s, same rounds;"
	print " best: p99/p50 over the fastest time of each frame in any of the passes of the run)"
	for (s in seens) {
		k = "demo1" SUBSEP s SUBSEP "dsda-doom" SUBSEP 1
		if (k in fps) printf "dsda-doom %s: peak RSS %s MiB, private %s MiB\n", s, mib(rss[k]), mib(priv[k])
	}
	print ""
	print "the daemon (file framebuffer 640x480, the E1M1 walk script):"
	for (w in drss) printf "  %-10s %-6s peak RSS %5s MiB, peak private %5s MiB\n", w, dmap[w], \
		mib(drss[w]), mib(dpriv[w])
	printf "  exec to first frame (READY=1), freedoom1 E1M1, median of 5: %s ms\n", ready == "" ? "-" : ready
	printf "  exec to first frame (READY=1), built-in levels (ARENA1), median of 5: %s ms\n", \
		readyb == "" ? "-" : readyb
	print ""
	print "targets (software renderer, each path; dsda-doom on DEMO1):"
	for (i = 0; i < np; i++) {
		p = order[i]
		for (j = 0; j < ns; j++) {
			s = sizes[j]
			one = f(p SUBSEP s SUBSEP "arcaded" SUBSEP 1)
			all = f(p SUBSEP s SUBSEP "arcaded" SUBSEP "n")
			d = f("demo1" SUBSEP s SUBSEP "dsda-doom" SUBSEP 1)
			g1 = f(p SUBSEP s SUBSEP "osmesa" SUBSEP 1)
			k = p SUBSEP s SUBSEP "arcaded" SUBSEP (ncpu > 1 ? "n" : 1)
			if (s == "1280x720" || s == "1920x1080") {
				target(p " " s ": all cores vs dsda-doom", all, d, 2.0)
				target(p " " s ": one core vs dsda-doom", one, d, 1.0)
			}
			if (ncpu > 1 && (s == "1280x720" || s == "1920x1080" || s == "3840x2160")) {
				if (k in sp)
					atleast(p " " s ": " ncpu " threads vs one, median of rounds", sp[k], 1.8)
				else
					target(p " " s ": " ncpu " threads vs one", all, one, 1.8)
			}
			target(p " " s ": one core vs OSMesa one thread", one, g1, 5.0)
			if (k in p50)
				upto(p " " s ": p99 / p50", p99[k] / p50[k], 1.5, "x")
			if (k in b50)
				upto(p " " s ": p99 / p50, fastest pass per frame", b99[k] / b50[k], 1.5, "x")
			if (s == "1920x1080")
				atleast(p " " s ": all cores, frames/s", all, 60)
			if (p == "e1m1" && s == "3840x2160")
				atleast(p " " s ": all cores, frames/s", all, 200)
		}
	}
	if (ncpu > 1)
		atleast("machine capacity (" ncpu " threads vs one)", cap, 1.9)
	if ("freedoom1" in drss) {
		upto("freedoom1 E1M1 640x480: private memory, MiB", dpriv["freedoom1"] / 1024, 16, "")
		upto("freedoom1 E1M1 640x480: peak RSS, MiB", drss["freedoom1"] / 1024, 24, "")
	}
	if (ready != "")
		upto("exec to first frame, freedoom1, ms", ready, 25, "")
	printf "  %-52s %9s           %s\n", "frames identical on 1 and " ncpu " threads", "", \
		(identical ? "met" : "NOT MET")
}
function target(what, a, b, want) {
	if (a == "-" || b == "-") { printf "  %-52s %9s         >= %.1fx   not measured\n", what, "-", want; return }
	printf "  %-52s %8.2fx         >= %.1fx   %s\n", what, a / b, want, (a / b >= want ? "met" : "NOT MET")
}
function atleast(what, a, want) {
	if (a == "-") { printf "  %-52s %9s         >= %-6s not measured\n", what, "-", want; return }
	printf "  %-52s %9.2f         >= %-6s %s\n", what, a, want, (a + 0 >= want ? "met" : "NOT MET")
}
function upto(what, a, want, unit) {
	printf "  %-52s %8.2f%1s         <= %-5s%1s %s\n", what, a, unit, want, unit, (a + 0 <= want ? "met" : "NOT MET")
}' "$CSV" "$DCSV"
# the mixer: one tick of 16 busy channels at 48000 Hz, one core
mix=$($PRIO "$tmp/mbench" "${BENCH_SECONDS:-1}")
mms=$(echo "$mix" | awk '{ print $2 }')
printf '  %-52s %9s ms      <= 0.1     %s\n' "mixer: one tick, 16 busy channels, 48000 Hz" "$mms" \
	"$(awk -v m="$mms" 'BEGIN { print (m <= 0.1 ? "met" : "NOT MET") }')"
echo "mixer_ms_per_tick,$mms" > "$OUT/mixer.csv"
echo
echo "machine: $NCPU threads of pure integer work ran ${cap}x (before) and ${cap2}x (after) as fast as"
echo "  one during this run; below ${NCPU}x, other load (or a CPU share, or hyperthread siblings)"
echo "  caps every thread figure. $NCPU threads filling memory (8 MiB buffers) ran ${mcap}x and ${mcap2}x"
echo "  as fast as one: the renderer at large sizes mostly writes memory and can scale no"
echo "  better. Load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "CSV: $CSV $DCSV  chart: $OUT/bench.png"
[ "$identical" = 1 ]
