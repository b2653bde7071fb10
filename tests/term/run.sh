#!/bin/sh
# Terminal preview, as `make run` shows it: the daemon runs in a tmux pane and
# draws the level with half-block characters; keys typed into the pane must
# reach the game, one tap moves the service menu's cursor one item, and
# Ctrl-C ends it cleanly.
#
# The picture changes on its own (the STAGE banner, moving enemies), so
# "the picture changed after a key" proves nothing. Instead each run records
# its commands (--record), and the same run is made with no key pressed:
#  - the run that held Left must hold turning commands, the one that typed W
#    forward commands, the one with no key neither;
#  - replayed (deterministic: the sim reads only the commands), each keyed
#    run's last common tick must show another state and another frame than
#    the run with no key at the same tick.
# Usage: tests/term/run.sh path/to/arcaded
set -u
BIN=$(realpath "$1")
tmp=$(mktemp -d)
sock="$tmp/tmux.sock"
cleanup() { tmux -S "$sock" kill-server 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
fail=0
check() { if [ "$2" -eq 0 ]; then echo "PASS $1"; else echo "FAIL $1"; fail=1; fi; }
common="--config-dir $tmp/etc --state-dir $tmp/state"
# A session that outlives every run: tmux's server exits with its last
# session, and a loaded machine could start the next run while the old
# server was still going away ("server exited unexpectedly").
tmux -S "$sock" -f /dev/null new-session -d -s keep "sleep 900"

# run NAME KEY: the daemon in a pane, recording to $tmp/NAME.rec; once the
# first picture is up, KEY ("none": nothing) is typed 20 times, 30 ms apart,
# as a terminal's autorepeat does; then Ctrl-C. Leaves $tmp/NAME.first (the
# first picture), $tmp/NAME.status ("exit=N") and $tmp/NAME.err.
run() {
	name=$1; key=$2
	tmux -S "$sock" -f /dev/null new-session -d -s "$name" -x 120 -y 40 \
		"$BIN --display term --play --set input.evdev=none $common --record $tmp/$name.rec 2>$tmp/$name.err; echo exit=\$? > $tmp/$name.status; sleep 30"
	i=0
	while [ $i -lt 50 ]; do
		tmux -S "$sock" capture-pane -t "$name" -p -e > "$tmp/$name.first" 2>/dev/null
		grep -q '▀' "$tmp/$name.first" && break
		sleep 0.1; i=$((i + 1))
	done
	sleep 0.5
	for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
		[ "$key" = none ] || tmux -S "$sock" send-keys -t "$name" "$key"
		sleep 0.03
	done
	sleep 0.4
	tmux -S "$sock" send-keys -t "$name" C-c
	i=0
	while [ $i -lt 50 ] && [ ! -s "$tmp/$name.status" ]; do sleep 0.1; i=$((i + 1)); done
	tmux -S "$sock" kill-session -t "$name" 2>/dev/null
}

# moves REC: "F T" = how many records have a forward, a turn command
moves() {
	python3 - "$1" <<'EOF'
import struct, sys
raw = open(sys.argv[1], 'rb').read()
version, = struct.unpack_from('<H', raw, 8)
hsize, = struct.unpack_from('<I', raw, 12)
count, = struct.unpack_from('<I', raw, 32)
flags = raw[44] if version >= 2 else 0
# each hash flag adds 8 bytes: state 0x01, frame 0x02, audio 0x08 (format 3);
# 0x04 is the snapshot, in the header
rsize = 6 + 8 * bin(flags & 0x0b).count('1')
n = min(count, (len(raw) - hsize) // rsize)
fwd = turn = 0
for i in range(n):
    f, s, t, b, c = struct.unpack_from('<bbhBB', raw, hsize + i * rsize)
    fwd += f != 0
    turn += t != 0
print(fwd, turn)
EOF
}

run nokey none
run left Left
run w w

check "the level is drawn with half blocks and 24-bit colour" \
	$(grep -q '▀' "$tmp/left.first" && grep -q '38;2;' "$tmp/left.first"; echo $?)
for r in nokey left w; do
	check "Ctrl-C exits cleanly ($r: $(cat "$tmp/$r.status" 2>/dev/null))" \
		$(grep -q 'exit=0' "$tmp/$r.status" 2>/dev/null; echo $?)
done
grep -q 'summary' "$tmp/left.err"
check "exit prints the timing summary" $?

set -- $(moves "$tmp/nokey.rec" 2>/dev/null) x x
check "with no key pressed: no forward and no turning commands ($1, $2)" \
	$([ "$1" = 0 ] && [ "$2" = 0 ]; echo $?)
set -- $(moves "$tmp/left.rec" 2>/dev/null) x x
check "Left held: turning commands recorded ($2 ticks), no forward ($1)" \
	$([ "$1" = 0 ] && [ "$2" != x ] && [ "$2" -gt 0 ]; echo $?)
set -- $(moves "$tmp/w.rec" 2>/dev/null) x x
check "W held: forward commands recorded ($1 ticks), no turning ($2)" \
	$([ "$1" != x ] && [ "$1" -gt 0 ] && [ "$2" = 0 ]; echo $?)

# One tap moves the service menu's cursor once (the terminal sends one byte
# for a tap, and the key decoder must not hold it past the menu's repeat
# delay). Service (9), then fire (space) on the first item opens INPUT;
# service goes back to the list with the cursor kept; one Down tap and fire
# must open the next item, DISPLAY, whose first screen is eight colour bars
# across the top of the picture. The INPUT page before it shows that the
# count can fail.
tmux -S "$sock" -f /dev/null new-session -d -s menu -x 120 -y 40 \
	"$BIN --display term --play --set input.evdev=none $common 2>$tmp/menu.err; echo exit=\$? > $tmp/menu.status; sleep 30"
i=0
while [ $i -lt 50 ]; do
	tmux -S "$sock" capture-pane -t menu -p -e 2>/dev/null | grep -q '▀' && break
	sleep 0.1; i=$((i + 1))
done
sleep 0.5
tap() { tmux -S "$sock" send-keys -t menu "$1"; sleep 0.8; }
# distinct 24-bit colours on the picture's first line
top_colours() {
	tmux -S "$sock" capture-pane -t menu -p -e | head -n 1 |
		grep -o '[34]8;2;[0-9]*;[0-9]*;[0-9]*' | sed 's/^[34]8;2;//' | sort -u | wc -l
}
tap 9; tap Space
n_input=$(top_colours)
tap 9; tap Down; tap Space
n_display=$(top_colours)
check "the INPUT page has fewer than 8 colours on its top line ($n_input)" \
	$([ "$n_input" -lt 8 ]; echo $?)
check "one Down tap moves the menu cursor one item: DISPLAY's 8 colour bars ($n_display colours on the top line)" \
	$([ "$n_display" -eq 8 ]; echo $?)
tmux -S "$sock" send-keys -t menu C-c
i=0
while [ $i -lt 50 ] && [ ! -s "$tmp/menu.status" ]; do sleep 0.1; i=$((i + 1)); done
tmux -S "$sock" kill-session -t menu 2>/dev/null

# The replays: each run's hashes per tick; a keyed run against the run
# with no key at their last common tick.
for r in nokey left w; do
	"$BIN" $common --replay "$tmp/$r.rec" >"$tmp/$r.hashes" 2>"$tmp/$r.replay.err"
done
differs() { # $1 run: "TICK STATE FRAME" of both at the last common tick
	n=$(wc -l <"$tmp/$1.hashes"); m=$(wc -l <"$tmp/nokey.hashes")
	[ "$m" -lt "$n" ] && n=$m
	[ "$n" -gt 0 ] || { echo "no ticks"; return 1; }
	a=$(sed -n "${n}p" "$tmp/$1.hashes"); b=$(sed -n "${n}p" "$tmp/nokey.hashes")
	echo "tick $(echo "$a" | cut -d' ' -f1): $1 $(echo "$a" | cut -d' ' -f2-), no key $(echo "$b" | cut -d' ' -f2-)"
	[ "$(echo "$a" | cut -d' ' -f2)" != "$(echo "$b" | cut -d' ' -f2)" ] &&
		[ "$(echo "$a" | cut -d' ' -f3)" != "$(echo "$b" | cut -d' ' -f3)" ]
}
for r in left w; do
	out=$(differs "$r"); rc=$?
	check "$r: another state and another picture than with no key ($out)" $rc
done
[ "$fail" -eq 0 ] || { echo "stderr:"; cat "$tmp/left.err"; }
exit "$fail"
