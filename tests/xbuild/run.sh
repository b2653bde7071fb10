#!/bin/sh
# Cross-build determinism test (issue 8 item 2). The headless replayer
# tests/xbuild/replay.c (the engine, input/rec.c and the few files SRC
# names, no platform library) is built with gcc -O0, gcc -O3, clang -O2,
# gcc -O2 with UBSan (undefined behaviour such as signed overflow or bad
# shifts is an error: it is what lets optimisers make builds differ) and
# an aarch64 cross gcc (static, run under qemu-user). Every build replays
# every recording:
#   - the committed goldens tests/replay/*.rec,
#   - recordings made now by the daemon from tests/replay/*.scr and
#     tests/script/*.scr (one also with other coin settings and free play,
#     one mixed at 22050 Hz, a rate whose ticks are 367 or 368 frames),
#   - two random-input recordings (replay --make-random, fixed seeds),
#   - one game at 200x150 and 640x480 besides the default 320x240,
#   - the Freedoom exit recordings (tests/replay/freedoom/exits.list), their
#     states and sound only (--no-render),
# and its per-tick "TICK STATEHASH FRAMEHASH AUDIOHASH" output must equal,
# byte for byte, what the daemon itself prints with --replay (gcc -O2):
# the audio hash of every tick is the same on every build. Then the
# hashes the x86-64 replay stores in a format 3 recording are verified by
# every build (--verify), and a recording with one changed state or audio
# hash must fail verification at that tick. Then recordings that start from a sim
# snapshot (as the flight recorder's games do; replay --cut makes them
# from the tail of a recording): every build's replay of one must print
# the daemon's hashes for those ticks of the whole recording, stored
# hashes verify, and a damaged snapshot or a cut on the attract DEMO page
# is refused.
# The daemon's renderer draws with a pool of threads (app/pool.c): the
# daemon's own replays with game.render_threads 1, 2 and 3 must print the
# same hashes.
# Every script must record (except those refused at set-up on purpose,
# "# expect-exit: 2"), and every comparison named here runs: a recording
# or committed file that is missing is a failure, never a silent skip.
# The aarch64 part is skipped, loudly ("SKIP" lines: the suite counts the
# step as skipped, not passed), only when qemu-user cannot run a static
# aarch64 program here; a missing cross compiler is a failure
# (scripts/setup.sh installs it).
# Usage: tests/xbuild/run.sh [path/to/arcaded]    (default build/arcaded)
set -u
cd "$(dirname "$0")/../.."
BIN=${1:-build/arcaded}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
pass=0
say() { printf '%s\n' "$*"; }
ok() { say "PASS $*"; pass=$((pass + 1)); }
bad() { say "FAIL $*"; fail=$((fail + 1)); }

# ---- static checks: what would make builds differ ----------------------
if grep -nE '\b(float|double)\b|<math\.h>' engine/core/*.c engine/core/*.h engine/map/*.c engine/map/*.h engine/sound/*.c engine/sound/*.h engine/game/*.c engine/game/*.h engine/render/*.c engine/render/*.h engine/ui/*.c engine/ui/*.h >"$tmp/fp" 2>/dev/null; then
	bad "floating point in the engine (fp contraction and x87/NEON differences):"
	cat "$tmp/fp"
else
	ok "no floating point in the engine (-ffp-contract cannot matter)"
fi

# ---- builds --------------------------------------------------------------
WARN="-std=c11 -Wall -Wextra -Werror -Wshadow -Wvla -Wstrict-prototypes -Wmissing-prototypes"
FLAGS="$WARN -fno-strict-aliasing -I. -D_GNU_SOURCE"
SRC=$(sh tests/xbuild/src.sh)
build() { # $1 name; rest: compiler and flags
	name=$1; shift
	# shellcheck disable=SC2086
	"$@" $FLAGS $SRC -o "$tmp/replay-$name" >"$tmp/build-$name.log" 2>&1
	echo $? >"$tmp/build-$name.rc"
}
BUILDS="gcc-O0 gcc-O3 clang-O2 gcc-O2-ubsan"
build gcc-O0 gcc -O0 &
build gcc-O3 gcc -O3 &
wait
build clang-O2 clang -O2 &
build gcc-O2-ubsan gcc -O2 -fsanitize=undefined -fno-sanitize-recover=all &
wait
A64=""
if command -v aarch64-linux-gnu-gcc >/dev/null 2>&1; then
	build aarch64-O2 aarch64-linux-gnu-gcc -O2 -static
	if [ "$(cat "$tmp/build-aarch64-O2.rc")" -eq 0 ]; then
		QEMU=$(command -v qemu-aarch64-static || command -v qemu-aarch64 || true)
		if [ -n "$QEMU" ] && "$QEMU" "$tmp/replay-aarch64-O2" --make-random "$tmp/probe.rec" 1 1 \
			>/dev/null 2>&1; then
			A64="$QEMU"
			BUILDS="$BUILDS aarch64-O2"
			printf '#!/bin/sh\nexec %s %s "$@"\n' "$QEMU" "$tmp/replay-aarch64-O2" >"$tmp/run-aarch64-O2"
			chmod +x "$tmp/run-aarch64-O2"
		else
			say "SKIP aarch64: ******************************************************"
			say "SKIP aarch64: qemu-user cannot run an aarch64 program on this machine"
			say "SKIP aarch64: (${QEMU:-no qemu-aarch64-static}); the ARM part is NOT tested"
			say "SKIP aarch64: ******************************************************"
		fi
	else
		BUILDS="$BUILDS aarch64-O2"
	fi
else
	bad "aarch64-linux-gnu-gcc missing: run scripts/setup.sh (gcc-aarch64-linux-gnu)"
fi
for b in $BUILDS; do
	if [ "$(cat "$tmp/build-$b.rc")" -ne 0 ]; then
		bad "build $b:"
		tail -n 20 "$tmp/build-$b.log"
		BUILDS=$(echo "$BUILDS" | sed "s/\b$b\b//")
		continue
	fi
	[ -e "$tmp/run-$b" ] || ln -s "replay-$b" "$tmp/run-$b"
done
say "builds: $BUILDS"

# ---- recordings ----------------------------------------------------------
common="--config-dir $tmp/etc --state-dir $tmp/state"
mkdir -p "$tmp/rec"
for g in golden-attract golden-game golden-walk; do
	if [ -f "tests/replay/$g.rec" ]; then
		cp "tests/replay/$g.rec" "$tmp/rec/committed-$g.rec"
	else
		bad "tests/replay/$g.rec is missing (a committed golden)"
	fi
done
top=$(pwd)
. tests/script/args.sh
top_bin=$(realpath "$BIN")
record() { # $1 script, $2 output name, rest: daemon options
	s=$1; n=$2; shift 2
	# in a directory of its own: a script's screenshot (screenshot.scr's
	# shot.png) is written relative to it, not into the tree
	mkdir -p "$tmp/cwd"
	(cd "$tmp/cwd" && "$top_bin" $common "$@" --script "$top/$s" --record "$tmp/rec/$n.rec") \
		>/dev/null 2>"$tmp/record.err"
	# expect_fails.scr fails on purpose and records; a script refused at
	# set-up on purpose (expect-exit 2) records nothing; any other script
	# that records nothing is a failure
	if [ ! -s "$tmp/rec/$n.rec" ]; then
		rm -f "$tmp/rec/$n.rec"
		grep -q '^# expect-exit: *2' "$s" ||
			bad "$s recorded nothing: $(head -n 1 "$tmp/record.err")"
	fi
}
for s in tests/replay/*.scr tests/script/*.scr; do
	# with the options of its "# args:" and "# set:" lines, as
	# tests/script/run.sh runs it
	# shellcheck disable=SC2046
	n="$(basename "$(dirname "$s")")-$(basename "$s" .scr)"
	record "$s" "$n" $(script_args "$s")
	# its content options (a grid map: "# args: --grid builtin"), which
	# its replays need too
	script_content_args "$s" > "$tmp/rec/$n.args"
done
record tests/replay/game.scr settings-game --set game.coins_per_credit=3 --set game.freeplay=1
# a rate that 60 does not divide: the mixer carries the remainder
record tests/replay/game.scr rate22050-game --set audio.rate=22050 --set game.volume=100
FIRST=$(echo "$BUILDS" | awk '{print $1}')
for seed in 1 20261121; do
	"$tmp/run-$FIRST" --make-random "$tmp/rec/random-$seed.rec" 3000 "$seed" ||
		bad "make a random recording (seed $seed)"
done
nrec=$(ls "$tmp/rec" | wc -l)
say "recordings: $nrec ($(ls "$tmp/rec" | tr '\n' ' '))"

# ---- replays -------------------------------------------------------------
# $1 label, $2 recording, $3 WxH, rest: content options for both (--wad,
# --map): the daemon's output is the reference.
compare() {
	label=$1; rec=$2; size=$3; shift 3
	w=${size%x*}; h=${size#*x}
	"$BIN" $common "$@" --size "$w"x"$h" \
		--replay "$rec" >"$tmp/ref" 2>"$tmp/ref.err"
	if [ $? -ne 0 ] || [ ! -s "$tmp/ref" ]; then
		bad "$label: the daemon did not replay it: $(head -n 1 "$tmp/ref.err")"
		return
	fi
	n=$(wc -l <"$tmp/ref")
	for b in $BUILDS; do
		"$tmp/run-$b" "$@" --size "$size" "$rec" >"$tmp/out-$b" 2>"$tmp/err-$b" &
	done
	wait
	for b in $BUILDS; do
		if ! cmp -s "$tmp/ref" "$tmp/out-$b"; then
			first=$(cmp "$tmp/ref" "$tmp/out-$b" 2>&1 | head -n 1)
			bad "$label $size: $b differs from the daemon ($first; $(head -n 1 "$tmp/err-$b"))"
			diff "$tmp/ref" "$tmp/out-$b" | head -n 4
		else
			ticks=$((ticks + n))
		fi
	done
	say "     $label $size: $n ticks, $BUILDS"
}
ticks=0
before=$fail
for rec in "$tmp"/rec/*.rec; do
	# shellcheck disable=SC2046
	compare "$(basename "$rec" .rec)" "$rec" 320x240 $(cat "${rec%.rec}.args" 2>/dev/null)
done
# a Freedoom map, read from the WAD by every build
W=/usr/share/games/doom/freedoom1.wad
if [ -f "$W" ]; then
	compare freedoom-e1m1 tests/replay/freedoom/golden-e1m1.rec 320x240 --wad "$W" --map E1M1
else
	bad "$W missing: run scripts/setup.sh (package freedoom)"
fi
# The exit recordings of Freedoom maps (tests/replay/freedoom/exits.list,
# 38,000 ticks in all): their states and sound on every build, without
# rendering (--no-render: frame hash 0), which keeps the emulated aarch64
# build's share small; the frames of Freedoom maps are the E1M1 walk's above.
while read -r name wad map settings; do
	case $name in '#'*|'') continue ;; esac
	if [ -f "$wad" ]; then
		compare "$name" "tests/replay/freedoom/golden-$name.rec" 320x240 --wad "$wad" --map "$map" \
			--no-render
	else
		bad "$wad missing: run scripts/setup.sh (package freedoom)"
	fi
done <tests/replay/freedoom/exits.list
compare replay-game "$tmp/rec/replay-game.rec" 200x150
compare replay-game "$tmp/rec/replay-game.rec" 640x480
[ "$fail" -eq "$before" ] &&
	ok "every build prints the daemon's state, frame and audio hashes for every recording ($ticks build-ticks compared)"

# ---- the daemon's render threads ------------------------------------------
# $1 label, $2 recording, $3 WxH, rest: content options: the daemon's
# replays with 1, 2 and 3 render threads print the same hashes, and the
# pools really started (no "drawing on one").
threads() {
	label=$1; rec=$2; size=$3; shift 3
	for n in 1 2 3; do
		"$BIN" $common "$@" --size "$size" --set game.render_threads=$n \
			--replay "$rec" >"$tmp/thr-$n" 2>"$tmp/thr-$n.err"
	done
	if [ ! -s "$tmp/thr-1" ]; then
		bad "threads $label: the daemon did not replay it: $(head -n 1 "$tmp/thr-1.err")"
	elif grep -q "drawing on one" "$tmp/thr-2.err" "$tmp/thr-3.err"; then
		bad "threads $label: a pool did not start: $(grep -h "drawing on one" "$tmp"/thr-*.err | head -n 1)"
	elif ! cmp -s "$tmp/thr-1" "$tmp/thr-2" || ! cmp -s "$tmp/thr-1" "$tmp/thr-3"; then
		bad "threads $label $size: 1, 2 and 3 render threads differ"
		diff "$tmp/thr-1" "$tmp/thr-2" | head -n 4
	else
		ok "threads $label $size: 1, 2 and 3 render threads print the same hashes ($(wc -l <"$tmp/thr-1") ticks)"
	fi
}
threads replay-game "$tmp/rec/replay-game.rec" 640x480
threads golden-walk "$tmp/rec/committed-golden-walk.rec" 320x240
[ -f "$W" ] && threads freedoom-e1m1 tests/replay/freedoom/golden-e1m1.rec 320x240 --wad "$W" --map E1M1

# ---- hashes stored in a recording: --verify ------------------------------
src=$tmp/rec/random-1.rec
if "$tmp/run-$FIRST" --quiet --rehash "$tmp/v2.rec" "$src"; then
	before=$fail
	for b in $BUILDS; do
		if ! "$tmp/run-$b" --quiet --verify "$tmp/v2.rec" 2>"$tmp/verify.err"; then
			bad "$b --verify: $(cat "$tmp/verify.err")"
		fi
	done
	[ "$fail" -eq "$before" ] && ok "every build verifies the stored hashes: $(cat "$tmp/verify.err")"
	# Record 1000's state hash: the header (its size at bytes 12..15: 104
	# in format 3) + 1000 records of 30 (command, state, frame and audio
	# hashes), then 6 bytes of command.
	hdr=$(od -An -tu4 -j 12 -N 4 "$tmp/v2.rec" | tr -d ' ')
	cp "$tmp/v2.rec" "$tmp/v2bad.rec"
	printf '\125' | dd of="$tmp/v2bad.rec" bs=1 seek=$((hdr + 30 * 1000 + 6)) conv=notrunc 2>/dev/null
	"$tmp/run-$FIRST" --quiet --verify "$tmp/v2bad.rec" 2>"$tmp/verify.err"
	rc=$?
	if [ "$rc" -eq 1 ] && grep -q "first difference at tick 1000: state hash" "$tmp/verify.err"; then
		ok "a changed hash fails verification at its tick: $(cat "$tmp/verify.err")"
	else
		bad "a changed hash (exit $rc): $(cat "$tmp/verify.err")"
	fi
	# Record 1200's audio hash: 22 bytes into its record.
	cp "$tmp/v2.rec" "$tmp/v2badaudio.rec"
	printf '\125' | dd of="$tmp/v2badaudio.rec" bs=1 seek=$((hdr + 30 * 1200 + 22)) conv=notrunc 2>/dev/null
	"$tmp/run-$FIRST" --quiet --verify "$tmp/v2badaudio.rec" 2>"$tmp/verify.err"
	rc=$?
	if [ "$rc" -eq 1 ] && grep -q "first difference at tick 1200: audio hash" "$tmp/verify.err"; then
		ok "a changed audio hash fails verification at its tick: $(cat "$tmp/verify.err")"
	else
		bad "a changed audio hash (exit $rc): $(cat "$tmp/verify.err")"
	fi
	"$tmp/run-$FIRST" --quiet --verify --size 640x480 "$tmp/v2.rec" 2>"$tmp/verify.err"
	rc=$?
	if [ "$rc" -eq 2 ] && grep -q "render size differs: recording 320x240, this run 640x480" \
		"$tmp/verify.err"; then
		ok "verify at another size is refused: $(cat "$tmp/verify.err")"
	else
		bad "verify at another size (exit $rc): $(cat "$tmp/verify.err")"
	fi
else
	bad "rehash $src"
fi

# ---- recordings that start from a snapshot --------------------------------
# $1 label, $2 recording, $3 K: the recording's ticks K.. replayed from a
# snapshot of tick K must give, on every build, the hashes the daemon prints
# for them in a replay of the whole recording (tick numbers aside: the cut
# counts from 0).
mkdir -p "$tmp/cut"
cut_compare() {
	label=$1; rec=$2; k=$3
	out=$tmp/cut/$label-at-$k.rec
	if ! "$tmp/run-$FIRST" --cut "$rec" "$k" "$out" 2>"$tmp/cut.err"; then
		bad "cut $label at tick $k: $(cat "$tmp/cut.err")"
		return
	fi
	"$BIN" $common --set game.render_width=320 --set game.render_height=240 \
		--replay "$rec" 2>/dev/null | tail -n +$((k + 1)) | cut -d' ' -f2- >"$tmp/cutref"
	n=$(wc -l <"$tmp/cutref")
	if [ "$n" -eq 0 ]; then
		bad "cut $label at tick $k: the daemon's replay has no ticks after $k"
		return
	fi
	for b in $BUILDS; do
		"$tmp/run-$b" --size 320x240 "$out" 2>"$tmp/err-$b" | cut -d' ' -f2- >"$tmp/cut-$b" &
	done
	wait
	for b in $BUILDS; do
		if ! cmp -s "$tmp/cutref" "$tmp/cut-$b"; then
			bad "$label cut at $k: $b differs from the daemon's ticks $k.. ($(head -n 1 "$tmp/err-$b"))"
			diff "$tmp/cutref" "$tmp/cut-$b" | head -n 4
		else
			cticks=$((cticks + n))
		fi
	done
	say "     $label from a snapshot of tick $k: $n ticks, $BUILDS"
}
cticks=0
before=$fail
cut_compare random-1 "$tmp/rec/random-1.rec" 1500
cut_compare random-20261121 "$tmp/rec/random-20261121.rec" 2200
cut_compare replay-game "$tmp/rec/replay-game.rec" 700
cut_compare golden-game "$tmp/rec/committed-golden-game.rec" 900
[ "$fail" -eq "$before" ] &&
	ok "every build replays recordings that start from a snapshot to the daemon's hashes ($cticks build-ticks compared)"
if [ -e "$tmp/v2.rec" ] && "$tmp/run-$FIRST" --cut "$tmp/v2.rec" 1000 "$tmp/v2cut.rec" 2>"$tmp/cut.err"; then
	before=$fail
	for b in $BUILDS; do
		if ! "$tmp/run-$b" --quiet --verify "$tmp/v2cut.rec" 2>"$tmp/verify.err"; then
			bad "$b --verify of a recording with a snapshot: $(cat "$tmp/verify.err")"
		fi
	done
	[ "$fail" -eq "$before" ] &&
		ok "every build verifies the hashes stored after a snapshot: $(cat "$tmp/verify.err")"
	# The snapshot starts at byte 104 (format 3): change a byte in it.
	cp "$tmp/v2cut.rec" "$tmp/v2cutbad.rec"
	printf '\125' | dd of="$tmp/v2cutbad.rec" bs=1 seek=200 conv=notrunc 2>/dev/null
	"$tmp/run-$FIRST" --quiet "$tmp/v2cutbad.rec" 2>"$tmp/cut.err"
	rc=$?
	if [ "$rc" -eq 2 ] && grep -q "snapshot damaged (checksum" "$tmp/cut.err"; then
		ok "a damaged snapshot is refused: $(cat "$tmp/cut.err")"
	else
		bad "a damaged snapshot (exit $rc): $(cat "$tmp/cut.err")"
	fi
else
	bad "cut the recording with hashes: $(cat "$tmp/cut.err" 2>/dev/null)"
fi
"$tmp/run-$FIRST" --cut "$tmp/rec/committed-golden-attract.rec" 1000 "$tmp/demo.rec" \
	2>"$tmp/cut.err"
rc=$?
if [ "$rc" -eq 2 ] && grep -q "DEMO page" "$tmp/cut.err"; then
	ok "a cut on the attract DEMO page is refused: $(cat "$tmp/cut.err")"
else
	bad "a cut on the DEMO page (exit $rc): $(cat "$tmp/cut.err")"
fi
[ -n "$A64" ] || say "NOTE aarch64 was NOT compared (see SKIP above)"
say "xbuild: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
