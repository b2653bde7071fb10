#!/bin/sh
# Hostile maps through the real daemon (issue 13 items 7-9), and maps with
# specials the game does not play (issue 15 item 7, below). tests/hostile/
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
# Then hostile state and config files (items 10-14), further down.
# Usage: tests/hostile/run.sh path/to/arcaded
# PART=files runs only the hostile files, PART=maps only the maps.
set -u
BIN=$(realpath "$1")
GUARD=${GUARD:-30}
PART=${PART:-all}
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

if [ "$PART" != files ]; then
case_ dag.wad 2 "dag.wad: MAP01: node 1199: child[1] node 1198 is reached a second time: the BSP is not a tree"
case_ high.wad 2 "high.wad: MAP01: SECTORS entry 0: floor 32730 out of range (+/-16383 units"
case_ tall.wad 2 "tall.wad: TEXTURE1 entry 0 (SOLID): the textures need more than 268435456 steps to compose (limit TEX_MAX_STEPS)"
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

# ---- specials the game does not play (issue 15 item 7) ------------------
# specials.wad (hf_specials): line 1 x1 and sector 9 x1 are played, line
# 24576 x3 (Boom generalized floor) and sector 256 x1 (Boom friction) not.
# --print-specials lists each with its count, marking the two; the daemon
# logs them once at load.
ps_out="$tmp/ps.out"
"$BIN" --wad "$tmp/w/specials.wad" --print-specials >"$ps_out" 2>"$tmp/err"
rc=$?
if [ "$rc" -ne 0 ]; then
	bad "print-specials specials.wad: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
elif ! grep -qx "  line 24576 x3: UNSUPPORTED: Boom generalized floor" "$ps_out" ||
	! grep -qx "  sector 256 x1: UNSUPPORTED: Boom: friction/wind" "$ps_out" ||
	! grep -qx "  line 1 x1: DR door open wait close (monsters too)" "$ps_out" ||
	! grep -qx "  sector 9 x1: secret" "$ps_out" ||
	! grep -qF "map MAP01 supported: special lines 1 of 4 (25.0%), special sectors 1 of 2 (50.0%)" "$ps_out"; then
	bad "print-specials specials.wad: not the 4 types with their counts and marks, output:"
	sed 's/^/    /' "$ps_out"
else
	ok "print-specials specials.wad: $(grep -c UNSUPPORTED "$ps_out") unsupported of $(grep -c '^  ' "$ps_out") types, counts right"
fi
start specials.wad
wait_for "$GUARD"
note="map MAP01: unsupported specials: line 24576 x3, sector 256 x1"
if [ "$rc" -ne 0 ]; then
	bad "specials.wad load: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
elif [ "$(grep -c "unsupported specials" "$tmp/err")" -ne 1 ] || ! grep -qF "arcaded: $note" "$tmp/err"; then
	bad "specials.wad load: not the one line '$note', log:"; sed 's/^/    /' "$tmp/err"
else
	ok "specials.wad load: $(grep -F "unsupported specials" "$tmp/err")"
fi
# bad input: a map that is not there, a broken map, no --wad: exit 2 with
# the file (and lump) named
"$BIN" --wad "$tmp/w/specials.wad" --map E9M9 --print-specials >/dev/null 2>"$tmp/err"
rc=$?
if [ "$rc" -ne 2 ] || ! grep -qF "$tmp/w/specials.wad: no map E9M9 (maps: MAP01)" "$tmp/err"; then
	bad "print-specials, no such map: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
else
	ok "print-specials, no such map: exit 2: $(cat "$tmp/err")"
fi
"$BIN" --wad "$tmp/w/dag.wad" --print-specials >/dev/null 2>"$tmp/err"
rc=$?
if [ "$rc" -ne 2 ] || ! grep -qF "$tmp/w/dag.wad: MAP01: node 1199" "$tmp/err"; then
	bad "print-specials, broken map: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
else
	ok "print-specials, broken map: exit 2: $(cat "$tmp/err")"
fi
"$BIN" --print-specials >/dev/null 2>"$tmp/err"
rc=$?
if [ "$rc" -ne 2 ] || ! grep -qF -- "--print-specials goes with --wad" "$tmp/err"; then
	bad "print-specials without --wad: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
else
	ok "print-specials without --wad: exit 2"
fi
# Freedoom: every type and count of the daemon's list against a second
# reading of the WAD (census.py), for E1M1 and for every map of both
# IWADs; the shares are printed as FIGURE lines. E1M1 plays every special,
# so its load logs none.
# ps_rows: the daemon's list as census.py's rows
ps_rows() {
	awk '/^unsupported:/ { exit }
	     /^map [^ ]+ \(/ { m = $2 }
	     /^  (line|sector) / { n = substr($3, 2); sub(":", "", n); print m, $1, $2, n, ($4 == "UNSUPPORTED:") ? 0 : 1 }' "$1"
}
for spec in freedoom1.wad:E1M1 freedoom1.wad:all freedoom2.wad:all; do
	iwad=/usr/share/games/doom/${spec%%:*}; map=${spec#*:}
	if [ ! -r "$iwad" ]; then
		echo "SKIP print-specials $spec: no $iwad (the freedoom package)"
		continue
	fi
	"$BIN" --wad "$iwad" --map "$map" --print-specials >"$ps_out" 2>"$tmp/err"
	rc=$?
	python3 tests/hostile/census.py "$iwad" "$([ "$map" = all ] || echo "$map")" >"$tmp/want" ||
		{ bad "census.py $spec failed"; continue; }
	grep -v '^total' "$tmp/want" >"$tmp/want.rows"
	set -- $(grep '^total' "$tmp/want")
	[ "$map" = all ] && sum="all [0-9]* maps" || sum="map $map"
	if [ "$rc" -ne 0 ]; then
		bad "print-specials $spec: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
	elif ! ps_rows "$ps_out" | diff "$tmp/want.rows" - >"$tmp/diff"; then
		bad "print-specials $spec: types or counts differ from census.py (< census.py, > daemon):"
		sed 's/^/    /' "$tmp/diff"
	elif ! grep -q "^$sum supported: special lines $2 of $3 ([0-9.]*%), special sectors $4 of $5 " "$ps_out"; then
		bad "print-specials $spec: the share is not $2 of $3 lines, $4 of $5 sectors:"
		grep "supported:" "$ps_out" | tail -n 1 | sed 's/^/    /'
	else
		ok "print-specials $spec: $(wc -l <"$tmp/want.rows") types as census.py reads them"
		echo "FIGURE $(grep "^$sum supported:" "$ps_out" | tail -n 1)"
		sed -n 's/^  \(.*([A-Z0-9 .]*)\)$/FIGURE '"$spec"' unsupported: \1/p' "$ps_out"
	fi
done
if [ -r /usr/share/games/doom/freedoom1.wad ]; then
	"$BIN" --config-dir "$tmp/etc" --state-dir "$tmp/state" --wad /usr/share/games/doom/freedoom1.wad \
		--map E1M1 --script "$tmp/end.scr" --set display.backend=file --set display.file="$tmp/fb" \
		>/dev/null 2>"$tmp/err"
	rc=$?
	if [ "$rc" -ne 0 ] || grep -q "unsupported specials" "$tmp/err"; then
		bad "freedoom1 E1M1 load: exit $rc or a note of unsupported specials, log:"; sed 's/^/    /' "$tmp/err"
	else
		ok "freedoom1 E1M1 load: no unsupported specials logged"
	fi
	grep -q "enemies and .* pickups at difficulty" "$tmp/err" &&
		bad "freedoom1 E1M1 load: a note of too many things (it has 40 items)"
	# E1M3 has more pickups than the game keeps (G_MAX_PICKUPS, 96): the
	# load says so, with the map's own count of enemies at that skill
	# (Doom's monster types with the easy bit, read here from THINGS)
	want=$(python3 - /usr/share/games/doom/freedoom1.wad <<'PY'
import struct, sys
d = open(sys.argv[1], 'rb').read()
n, ofs = struct.unpack('<ii', d[4:12])
lumps = [struct.unpack('<ii8s', d[ofs + 16 * i:ofs + 16 * i + 16]) for i in range(n)]
i = [l[2].rstrip(b'\0') for l in lumps].index(b'E1M3')
o, size, _ = lumps[i + 1]
mon = {3004, 9, 65, 3001, 3002, 58, 3005, 3003, 69, 3006, 7, 68, 16, 71, 84, 64, 66, 67, 88, 89, 72}
e = 0
for k in range(size // 10):
    t, f = struct.unpack('<hh', d[o + 10 * k + 6:o + 10 * k + 10])
    if f & 16 or ((f & 7) and not f & 1):
        continue
    e += t in mon
print(e)
PY
)
	"$BIN" --config-dir "$tmp/etc" --state-dir "$tmp/state" --wad /usr/share/games/doom/freedoom1.wad \
		--map E1M3 --set game.difficulty=0 --script "$tmp/end.scr" --set display.backend=file \
		--set display.file="$tmp/fb" >/dev/null 2>"$tmp/err"
	line=$(grep -m 1 "map E1M3: .* enemies and .* pickups at difficulty 0" "$tmp/err")
	got=$(echo "$line" | sed -n 's/.*E1M3: \([0-9]*\) enemies and \([0-9]*\) pickups.*/\1 \2/p')
	if [ -n "$got" ] && [ "${got% *}" = "$want" ] && [ "${got#* }" -gt 96 ]; then
		ok "freedoom1 E1M3 load: too many pickups named (THINGS: $want enemies at easy): $line"
	else
		bad "freedoom1 E1M3 load: no note of its pickups over the game's 96, or enemies not $want: ${line:-none}"
	fi
else
	echo "SKIP freedoom1 E1M1 load: no /usr/share/games/doom/freedoom1.wad (the freedoom package)"
fi
# Content from the configuration ([game] wad and maps, docs/config.md):
# the maps named, an episode (Doom's ExMy: E1 is E1M1..E1M9, 9 maps), and
# a wrong map or a missing WAD, which leave the cabinet on its built-in
# levels with the reason in the log (exit 0: it plays on).
wadcase() { # label maps-value want-pattern [wad]
	"$BIN" --config-dir "$tmp/etc" --state-dir "$tmp/state" --script "$tmp/end.scr" \
		--set display.backend=file --set display.file="$tmp/fb" \
		--set "game.wad=${4:-/usr/share/games/doom/freedoom1.wad}" --set "game.maps=$2" \
		>/dev/null 2>"$tmp/err"
	rc=$?
	if [ "$rc" -eq 0 ] && grep -q -e "$3" "$tmp/err"; then
		ok "game.wad/maps $1: $(grep -m 1 -e "$3" "$tmp/err")"
	else
		bad "game.wad/maps $1: exit $rc, no line matching '$3' in:"; sed 's/^/    /' "$tmp/err"
	fi
}
if [ -r /usr/share/games/doom/freedoom1.wad ]; then
	wadcase "two maps" "E1M1 E1M2" 'content: .*freedoom1.wad E1M1 to E1M2 (2 maps),'
	wadcase "an episode" "E1" 'content: .*freedoom1.wad E1M1 to E1M9 (9 maps),'
	wadcase "a map not in the WAD" "E1M1 E9M9" 'game.wad / game.maps: map E9M9: not in the WADs.*playing the built-in levels'
	grep -q "content: built-in levels" "$tmp/err" && ok "game.wad/maps a map not in the WAD: the built-in levels play" ||
		bad "game.wad/maps a map not in the WAD: not the built-in levels"
else
	echo "SKIP game.wad/maps with Freedoom: no /usr/share/games/doom/freedoom1.wad (the freedoom package)"
fi
wadcase "a missing WAD" "" "game.wad / game.maps: $tmp/none.wad: No such file or directory; playing the built-in levels" "$tmp/none.wad"
# A file on a filesystem that cannot map files (sysfs says ENODEV, as some
# network and FUSE ones do) is read instead: the message is about what it
# holds, not "No such device".
if [ -r /sys/kernel/profiling ]; then
	wadcase "a file that cannot be mapped" "" "game.wad / game.maps: /sys/kernel/profiling: shorter than a WAD header" /sys/kernel/profiling
else
	echo "SKIP game.wad/maps a file that cannot be mapped: no /sys/kernel/profiling"
fi
fi

# ---- hostile files (issue 13 items 10-14) -------------------------------
if [ "$PART" != maps ]; then
# run_ STATE [ARGS...]: the daemon, not headless (so it keeps state in
# STATE), for 10 ticks; rc (124: still running after GUARD s), log in err
run_() {
	st=$1; shift
	timeout -s KILL "$GUARD" "$BIN" --config-dir "$tmp/etc" --state-dir "$st" --ticks 10 \
		--set display.backend=file --set display.file="$tmp/fb" "$@" \
		>/dev/null 2>"$tmp/err"
	rc=$?
	[ "$rc" -eq 137 ] && rc=124
}
# crc_ : the CRC-32 of stdin as 4 little-endian bytes (gzip's trailer
# holds it: a second implementation, not config/st.c's)
crc_() { gzip -c | tail -c 8 | head -c 4; }
# poke_ FILE OFFSET OCTAL: one byte of FILE set
poke_() { printf "\\$3" | dd of="$1" bs=1 seek="$2" conv=notrunc 2>/dev/null; }
# reseal_ FILE: the payload and header CRCs of a state file made valid again
reseal_() {
	tail -c +25 "$1" | crc_ | dd of="$1" bs=1 seek=16 conv=notrunc 2>/dev/null
	head -c 20 "$1" | crc_ | dd of="$1" bs=1 seek=20 conv=notrunc 2>/dev/null
}
# u64_ FILE OFFSET: a little-endian 64-bit field
u64_() { od -An -t u8 -j "$2" -N 8 "$1" | tr -d ' '; }

# item 10: books with valid checksums but a format byte this build does
# not know (payload byte 2: G_FORMAT) is a bad copy: books.prev is loaded,
# and the next save does not rotate the bad copy into books.prev.
S="$tmp/s10"; mkdir -p "$S"
run_ "$S"; run_ "$S"
cp "$S/books.prev" "$tmp/books.A"; cp "$S/books" "$tmp/books.B"
poke_ "$S/books" 26 377; reseal_ "$S/books"
run_ "$S"
if [ "$rc" -ne 0 ]; then
	bad "state: undecodable books: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
elif ! grep -qF "books: payload not usable by this version; loaded books.prev" "$tmp/err"; then
	bad "state: undecodable books did not load books.prev, log:"; sed 's/^/    /' "$tmp/err"
elif ! cmp -s "$S/books.prev" "$tmp/books.A"; then
	bad "state: the save rotated the undecodable books into books.prev (the good copy is lost)"
elif [ "$(u64_ "$S/books" 44)" != "$(u64_ "$tmp/books.B" 44)" ]; then
	# the same 10 ticks on top of the same copy A: the same power-on time
	bad "state: power-on ticks $(u64_ "$S/books" 44) after the run, $(u64_ "$tmp/books.B" 44) expected (counted on books.prev)"
else
	ok "state: undecodable books: $(grep -F "loaded books.prev" "$tmp/err" | head -n 1); books.prev kept"
fi
# item 10: a save that fails with no earlier copy does not claim one
S="$tmp/s10b"; mkdir -p "$S/books.tmp"
run_ "$S"
if grep -qF "previous copy is intact" "$tmp/err"; then
	bad "state: a failed first save claims a previous copy: $(grep -F "not saved" "$tmp/err" | head -n 1)"
elif ! grep -qF "books: not saved:" "$tmp/err"; then
	bad "state: the failed save is not reported, log:"; sed 's/^/    /' "$tmp/err"
else
	ok "state: failed first save: $(grep -F "not saved" "$tmp/err" | head -n 1)"
fi
# item 13: a FIFO named *.ini in the config directory and one named books
# in the state directory: start-up must not block in open() (the guard
# catches a hang); each is refused by name and the cabinet runs.
S="$tmp/s13"; mkdir -p "$S" "$tmp/etc13"
mkfifo "$tmp/etc13/zz.ini" "$S/books"
timeout -s KILL 10 "$BIN" --config-dir "$tmp/etc13" --state-dir "$S" --ticks 10 \
	--set display.backend=file --set display.file="$tmp/fb" >/dev/null 2>"$tmp/err"
rc=$?; [ "$rc" -eq 137 ] && rc=124
if [ "$rc" -eq 124 ]; then
	bad "fifo: start-up blocked on a FIFO (killed after 10 s)"
elif [ "$rc" -ne 0 ]; then
	bad "fifo: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
elif ! grep -qF "$tmp/etc13/zz.ini: not a regular file" "$tmp/err"; then
	bad "fifo: the config FIFO is not named as such, log:"; sed 's/^/    /' "$tmp/err"
elif ! grep -qF "$S/books: books: not a regular file" "$tmp/err"; then
	bad "fifo: the state FIFO is not named as such, log:"; sed 's/^/    /' "$tmp/err"
else
	ok "fifo: $(grep -F "zz.ini" "$tmp/err" | head -n 1) / $(grep -F "not a regular" "$tmp/err" | grep -F books | head -n 1)"
fi
# item 14: a --state-dir of 256 bytes (one more than paths.state_dir holds)
# is refused by name; cut at 255 bytes the state would go to another
# directory (here one that exists, so nothing else would stop the run)
long="$tmp/s14/$(printf '%0*d' $((255 - ${#tmp} - 5)) 0)"
mkdir -p "$long"
run_ "${long}y"
if [ "${#long}" -ne 255 ]; then
	bad "state-dir: the test path is ${#long} bytes, not 255"
elif [ "$rc" -ne 2 ] || ! grep -qF -- "--state-dir: path too long (at most 255 bytes)" "$tmp/err"; then
	bad "state-dir: 256 bytes: exit $rc (expected 2), state in the cut path: $(ls "$long" | tr '\n' ' ') log:"
	sed 's/^/    /' "$tmp/err"
else
	ok "state-dir: 256 bytes: exit 2: $(grep -F -- "--state-dir" "$tmp/err" | head -n 1)"
fi
fi


# ---- the service menu's content directory (issue 18 item 4) -------------
if [ "$PART" != maps ]; then
# A content directory as an operator's USB stick may leave it: one WAD
# that is whole (mkhostile's specials.wad: PWAD, one map), a truncated
# copy of it, a zip named .wad, a FIFO named .wad (opening it blocking
# would hang the cabinet), a dangling symlink and a directory named .wad.
# (The tests run as root, for whom a mode-000 file is readable: the
# unreadable ones here are the FIFO, the link and the directory.) A
# script opens CONTENT PACK (nine moves down, FIRE) and the pack's map
# list: the cabinet keeps running, lists the one good WAD and names every
# other file with its reason.
C="$tmp/content"; mkdir -p "$C"
cp "$tmp/w/specials.wad" "$C/a_good.wad"
head -c 40 "$tmp/w/specials.wad" > "$C/b_trunc.wad"
printf 'PK\003\004 this is a zip archive, not a WAD' > "$C/c_zip.wad"
mkfifo "$C/d_fifo.wad"
ln -s "$tmp/nowhere.wad" "$C/e_dangling.wad"
mkdir "$C/f_dir.wad"
{
	echo "2 press service"; echo "3 release service"
	t=4; for i in 1 2 3 4 5 6 7 8 9; do echo "$t press back"; echo "$((t + 1)) release back"; t=$((t + 2)); done
	echo "24 press fire"; echo "25 release fire"
	echo "30 screenshot $tmp/content.png"
	echo "32 press back"; echo "33 release back"
	echo "34 press fire"; echo "35 release fire"
	echo "40 screenshot $tmp/content-maps.png"
	echo "42 end"
} >"$tmp/content.scr"
timeout -s KILL "$GUARD" "$BIN" --config-dir "$tmp/etc" --state-dir "$tmp/state" \
	--script "$tmp/content.scr" --set display.backend=file --set display.file="$tmp/fb" \
	--set "game.content_dirs=$tmp/nodir $C" >/dev/null 2>"$tmp/err"
rc=$?; [ "$rc" -eq 137 ] && rc=124
miss=""
for want in "b_trunc.wad: truncated" "c_zip.wad: not a WAD (no IWAD or PWAD magic)" \
	    "d_fifo.wad: not a regular file" "e_dangling.wad: No such file or directory" \
	    "f_dir.wad: not a regular file" "content: 1 WAD(s) in" "service menu: content pack"; do
	grep -qF "$want" "$tmp/err" || miss="$miss [$want]"
done
if [ "$rc" -eq 124 ]; then
	bad "content dir: the cabinet hung (killed after $GUARD s)"
elif [ "$rc" -ne 0 ] || [ -n "$miss" ]; then
	bad "content dir: exit $rc, log lacks:$miss; log:"; sed 's/^/    /' "$tmp/err"
elif ! head -c 8 "$tmp/content-maps.png" 2>/dev/null | grep -q PNG; then
	bad "content dir: no screenshot of the page"
else
	ok "content dir: 1 WAD listed, 5 files named: $(grep -F "b_trunc.wad" "$tmp/err" | head -n 1)"
fi
# The pack chosen on screen (STATE_DIR/content.ini, a state file whose
# payload is INI text) broke since: the cabinet plays its built-in levels,
# says why, and keeps running (a live run of 10 ticks).
S="$tmp/s18"; mkdir -p "$S"
ini=$(printf '[game]\nwad = %s\nmaps = \n' "$C/b_trunc.wad")
{ printf 'ARCDSTA\000\001\000\030\000'; printf "$(printf '\\%03o' $((${#ini} + 1)))\\000\\000\\000"
  printf '\000\000\000\000\000\000\000\000'; printf '%s\n' "$ini"; } >"$S/content.ini"
reseal_ "$S/content.ini"
run_ "$S"
if [ "$rc" -ne 0 ]; then
	bad "content.ini: a broken chosen WAD: exit $rc, log:"; sed 's/^/    /' "$tmp/err"
elif ! grep -qF "game.wad / game.maps: $C/b_trunc.wad" "$tmp/err" ||
     ! grep -qF "content: built-in levels" "$tmp/err"; then
	bad "content.ini: no fallback naming the WAD, log:"; sed 's/^/    /' "$tmp/err"
else
	ok "content.ini: $(grep -F "game.wad / game.maps" "$tmp/err" | head -n 1)"
fi
fi

echo "hostile: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
