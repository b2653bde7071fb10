#!/bin/sh
# make bench-pacing: frame pacing of the daemon in real time (a benchmark:
# figures and targets are reported, not asserted). A recording of random
# cabinet input on Freedoom's E1M1 (tests/soak/gen.py: coins, starts,
# movement, turning, strafing, fire; the game goes through play, game over
# and attract) is replayed with --realtime, so the loop follows the 60 Hz
# clock as live play does, rendering at 1920x1080 on two threads and
# presenting on the file framebuffer. The summary counts the ticks the clock
# dropped and the frames presented late (after the next tick was due).
# Targets: no tick dropped, no frame late.
# The framebuffer file is on tmpfs (/dev/shm), memory as a real
# framebuffer's is: a file on a disk would have its dirty pages written
# back under the running game, which no display does. Run as root, the
# daemon gets the unit's Nice= (systemd/arcaded.service).
# Usage: tests/bench/pacing.sh path/to/arcaded [SECONDS]   (default 600)
set -u
BIN=$(realpath "$1")
SECS=${2:-600}
cd "$(dirname "$0")/../.."
WAD=/usr/share/games/doom/freedoom1.wad
[ -f "$WAD" ] || { echo "pacing: $WAD missing (apt-get install freedoom)"; exit 1; }
tmp=$(mktemp -d)
shm=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d)
trap 'rm -rf "$tmp" "$shm"' EXIT
nice=$(sed -n 's/^Nice=//p' systemd/arcaded.service)
PRIO=
if [ -n "$nice" ] && [ "$(id -u)" = 0 ]; then
	PRIO="nice -n $nice"
fi
common="--config-dir $tmp/etc --state-dir $tmp/state"
content="--wad $WAD --map E1M1"

printf '0 end\n' >"$tmp/one.scr"
"$BIN" $common $content --play --script "$tmp/one.scr" --record "$tmp/tmpl.rec" >/dev/null 2>&1
python3 tests/soak/gen.py "$tmp/tmpl.rec" "$tmp/play.rec" $((SECS * 60)) 20261125 ||
	{ echo "pacing: could not write the recording"; exit 1; }
echo "pacing: $SECS s of play (E1M1, random input) replayed in real time at 1920x1080 on two"
echo "  threads, file framebuffer 1920x1080 xrgb8888 on $(df --output=fstype "$shm" | tail -1)," \
	"${PRIO:-priority unchanged (not root, or no Nice= in the unit)}"
echo "  load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
# steal: time the hypervisor ran something else while this machine's
# vCPUs wanted to run (the 8th number of /proc/stat's cpu line, in ticks
# of 1/USER_HZ s), summed over all vCPUs; 0 on bare metal
steal() { awk '/^cpu / { print $9 }' /proc/stat; }
st0=$(steal)
$PRIO "$BIN" $common $content replay "$tmp/play.rec" --realtime --quiet --size 1920x1080 \
	--set game.render_threads=2 --set display.backend=file --set display.file="$shm/fb" \
	--set display.file_width=1920 --set display.file_height=1080 >/dev/null 2>"$tmp/err"
rc=$?
grep 'summary:' "$tmp/err" | sed 's/^arcaded: //'
echo "  load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "  steal time during the run (the host running others on this machine's vCPUs):" \
	"$(( ($(steal) - st0) * 1000 / $(getconf CLK_TCK) )) ms"
ticks=$(sed -n 's/.*summary: \([0-9]*\) ticks, .*/\1/p' "$tmp/err")
dropped=$(sed -n 's/.* \([0-9]*\) ticks dropped.*/\1/p' "$tmp/err")
late=$(sed -n 's/.* \([0-9]*\) frames late.*/\1/p' "$tmp/err")
[ "$rc" = 0 ] && [ -n "$ticks" ] || { echo "pacing: the replay failed (exit $rc):"; tail -5 "$tmp/err"; exit 1; }
verdict() { [ "$2" = 0 ] && echo "met" || echo "NOT MET"; }
echo "targets:"
printf '  %-40s %8s   = 0   %s\n' "ticks dropped of $ticks" "$dropped" "$(verdict x "$dropped")"
printf '  %-40s %8s   = 0   %s\n' "frames presented late" "$late" "$(verdict x "$late")"
