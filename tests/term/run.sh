#!/bin/sh
# Terminal preview, as `make run` shows it: the daemon runs in a tmux pane,
# draws the level with half-block characters, and keys typed into the pane
# move the view (the picture changes), one tap moves the service menu's
# cursor one item; Ctrl-C ends it cleanly.
# Usage: tests/term/run.sh path/to/arcaded
set -u
BIN=$(realpath "$1")
tmp=$(mktemp -d)
sock="$tmp/tmux.sock"
cleanup() { tmux -S "$sock" kill-server 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
fail=0
check() { if [ "$2" -eq 0 ]; then echo "PASS $1"; else echo "FAIL $1"; fail=1; fi; }

tmux -S "$sock" -f /dev/null new-session -d -x 120 -y 40 \
	"$BIN --display term --play --set input.evdev=none --config-dir $tmp/etc --state-dir $tmp/state 2>$tmp/err; echo exit=\$? > $tmp/status; sleep 30"
# wait for the first picture
i=0
while [ $i -lt 50 ]; do
	tmux -S "$sock" capture-pane -p -e > "$tmp/a" 2>/dev/null
	grep -q '▀' "$tmp/a" && break
	sleep 0.1; i=$((i + 1))
done
check "the level is drawn with half blocks and 24-bit colour" \
	$(grep -q '▀' "$tmp/a" && grep -q '38;2;' "$tmp/a"; echo $?)
sleep 0.5
tmux -S "$sock" capture-pane -p -e > "$tmp/a"
# hold "turn left" by repeating the key, as a terminal's autorepeat does
for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
	tmux -S "$sock" send-keys Left; sleep 0.03
done
sleep 0.4
tmux -S "$sock" capture-pane -p -e > "$tmp/b"
check "the Left arrow turns the view (picture changed)" $(! cmp -s "$tmp/a" "$tmp/b"; echo $?)
for k in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20; do
	tmux -S "$sock" send-keys w; sleep 0.03
done
sleep 0.4
tmux -S "$sock" capture-pane -p -e > "$tmp/c"
check "W moves the view (picture changed)" $(! cmp -s "$tmp/b" "$tmp/c"; echo $?)
# One tap moves the service menu's cursor once (the terminal sends one byte
# for a tap, and the key decoder must not hold it past the menu's repeat
# delay). Service (9), then fire (space) on the first item opens INPUT;
# service goes back to the list with the cursor kept; one Down tap and fire
# must open the next item, DISPLAY, whose first screen is eight colour bars
# across the top of the picture. The INPUT page before it shows that the
# count can fail.
tap() { tmux -S "$sock" send-keys "$1"; sleep 0.8; }
# distinct 24-bit colours on the picture's first line
top_colours() {
	tmux -S "$sock" capture-pane -p -e | head -n 1 |
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
tmux -S "$sock" send-keys C-c
i=0
while [ $i -lt 50 ] && [ ! -s "$tmp/status" ]; do sleep 0.1; i=$((i + 1)); done
check "Ctrl-C exits cleanly ($(cat "$tmp/status" 2>/dev/null))" \
	$(grep -q 'exit=0' "$tmp/status" 2>/dev/null; echo $?)
grep -q 'summary' "$tmp/err"
check "exit prints the timing summary" $?
[ "$fail" -eq 0 ] || { echo "stderr:"; cat "$tmp/err"; }
exit "$fail"
