#!/bin/sh
# Flight recorder, end to end: the live daemon (terminal preview in tmux,
# keys typed into it) with a state directory; a coin and START begin a
# game, which is played a little, then SIGTERM stops the cabinet. The game
# must be kept in STATE/recordings/ and `arcaded replay FILE --verify`
# must reproduce every tick's state hash from the recording's own start
# state (the cabinet's, not sim_init's).
# Usage: tests/flight/run.sh path/to/arcaded
set -u
BIN=$(realpath "$1")
tmp=$(mktemp -d)
sock="$tmp/tmux.sock"
cleanup() { tmux -S "$sock" kill-server 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
fail=0
check() { if [ "$2" -eq 0 ]; then echo "PASS $1"; else echo "FAIL $1"; fail=1; fi; }
mkdir -p "$tmp/state"

tmux -S "$sock" -f /dev/null new-session -d -x 100 -y 35 \
	"sh -c 'echo \$\$ > $tmp/pid; exec $BIN --display term --set input.evdev=none --set input.hid=none --config-dir $tmp/etc --state-dir $tmp/state 2>$tmp/err'; sleep 30"
sleep 2
# some attract time first, so the game does not start from sim_init's state
for k in 5 1; do tmux -S "$sock" send-keys "$k"; sleep 0.5; done
for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15; do
	tmux -S "$sock" send-keys w; sleep 0.05
done
for k in 1 2 3 4 5 6 7 8; do tmux -S "$sock" send-keys Left; sleep 0.05; done
tmux -S "$sock" send-keys Space; sleep 0.5
kill -TERM "$(cat "$tmp/pid")"
i=0
while [ $i -lt 50 ] && kill -0 "$(cat "$tmp/pid")" 2>/dev/null; do sleep 0.1; i=$((i + 1)); done
rec=$(ls "$tmp"/state/recordings/game-*.rec 2>/dev/null | head -n 1)
check "the game is kept in the state directory's recordings/ ($(basename "${rec:-none}"))" \
	$([ -n "$rec" ] && [ -s "$rec" ]; echo $?)
if [ -n "$rec" ]; then
	"$BIN" --config-dir "$tmp/etc" --state-dir "$tmp/state2" replay "$rec" --verify --no-render \
		--quiet >/dev/null 2>"$tmp/v.err"
	rc=$?
	check "replay --verify reproduces it from its start state (exit $rc): $(tail -n 1 "$tmp/v.err" | sed 's/^arcaded: [^:]*: //')" \
		$([ "$rc" -eq 0 ] && grep -q "hashes equal" "$tmp/v.err" && ! grep -q FAILED "$tmp/v.err"; echo $?)
	# The header names the sounds the game was mixed from (their hash,
	# made after the first frame): the replay mixes the same built-in
	# sounds, so every tick's audio hash is compared, none skipped.
	ticks=$(sed -n 's/.*verify: \([0-9]*\) ticks, .*/\1/p' "$tmp/v.err" | tail -n 1)
	check "its header names the sounds it was mixed from: all ${ticks:-?} audio hashes compared" \
		$([ -n "$ticks" ] && [ "$ticks" -gt 0 ] &&
			grep -q " ${ticks} audio hashes equal" "$tmp/v.err"; echo $?)
fi
[ "$fail" -eq 0 ] || { echo "daemon stderr:"; cat "$tmp/err"; }
exit "$fail"
