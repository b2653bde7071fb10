#!/bin/sh
# The VM tests' guest side: run by vm-test.service once arcaded.service is
# up (tests/vm/run.sh boots the VM; docs/vm.md). Writes its findings to
# /vm/results/results.txt as "PASS name: detail", "FAIL name: detail" and
# "FIGURE text" lines, asks the host for screendumps (the host judges the
# pictures), saves the journal and powers the VM off.
set -u
R=/vm/results
S=/vm/stage
G=$S/bin/vm_guest
U=arcaded.service
BOOT=$(sed -n 's/.*arcaded\.vm=\([a-z0-9]*\).*/\1/p' /proc/cmdline)
exec >> "$R/guest.log" 2>&1
set -x

now() { "$G" now; }
t_start=$(now)

pass() { echo "PASS $1: $2" >> "$R/results.txt"; }
fail() { echo "FAIL $1: $2" >> "$R/results.txt"; }
check() { # name detail condition...
	n=$1
	d=$2
	shift 2
	if "$@"; then pass "$n" "$d"; else fail "$n" "$d"; fi
}
figure() { echo "FIGURE $*" >> "$R/results.txt"; }
sub() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }
le() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 <= b + 0) }'; }

# The unit's journal as "MONOTONIC-SECONDS message" lines, from time $1 on.
log_since() {
	journalctl -o short-monotonic -u "$U" --no-pager -q |
		sed -n 's/^\[ *\([0-9]*\.[0-9]*\)\] [^ ]* \(.*\)$/\1 \2/p' |
		awk -v t="${1:-0}" '$1 + 0 >= t + 0'
}
# Waits up to $3 s for a journal line matching $1 from time $2 on; prints
# its time.
wait_log() {
	end=$(awk -v n="$(now)" -v s="$3" 'BEGIN { print n + s }')
	while :; do
		l=$(log_since "$2" | grep -m 1 -e "$1")
		if [ -n "$l" ]; then
			echo "${l%% *}"
			return 0
		fi
		le "$(now)" "$end" || return 1
		sleep 0.2
	done
}
prop() { systemctl show -p "$1" --value "$U"; }

# Asks the host for a screendump named $1 and waits until it is taken.
shot() {
	: > "$R/req/$1"
	i=0
	while [ ! -e "$R/ack/$1" ]; do
		sleep 0.1
		i=$((i + 1))
		[ $i -lt 600 ] || { fail "screendump-$1" "the host did not answer"; return 1; }
	done
}

# --- boot: READY=1 is sent after the first frame is presented ---------------
t_ready=$(log_since 0 | grep -m 1 'Started arcaded' | cut -d' ' -f1)
# For the host: QEMU start to READY = when it sees this line, less the lag.
echo "@@vm-ready uptime=$(cut -d' ' -f1 /proc/uptime) ready=${t_ready:-0}" > /dev/ttyS0
check service-ready "READY=1 at ${t_ready:-never} s after kernel start" [ -n "$t_ready" ]
[ -n "$t_ready" ] && figure "kernel start to READY=1 (first frame shown): $t_ready s"
"$G" fbinfo /dev/fb0 > "$R/fbinfo.txt"
disp=$(log_since 0 | grep -m 1 'arcaded: display: ' | sed 's/.*arcaded: display: //')
case $BOOT in
fb16) want='fbdev /dev/fb0 .* rgb565 ' ;;
*) want='fbdev /dev/fb0 .* xrgb8888 ' ;;
esac
check display-fbdev "$disp" sh -c "echo '$disp' | grep -q -e '$want'"

# Attract mode: the camera turns, two screens a second apart differ.
shot attract-1
sleep 1
shot attract-2

# --- input: a uinput keyboard plugged in after start -----------------------
mkfifo /run/vm-kbd
"$G" kbd /run/vm-kbd > "$R/kbd.log" 2>&1 &
kbd_pid=$!
exec 3> /run/vm-kbd
t_plug=$(now)
if t_att=$(wait_log 'input evdev: attached arcaded-vm keyboard' "$t_plug" 15); then
	pass keyboard-attached "the daemon took the uinput keyboard $(sub "$t_plug" "$t_att") s after it appeared"
else
	fail keyboard-attached "no 'attached' line within 15 s"
fi
coin_start() {
	echo "tap KEY_5 150" >&3
	sleep 0.5
	echo "tap KEY_1 150" >&3
	sleep 1.5
}
coin_start
shot play-start
# forward and a turn: the picture must change
echo "tap KEY_UP 600" >&3
echo "tap KEY_LEFT 300" >&3
sleep 1.5
shot play-moved

# --- the service's user, capabilities and devices ---------------------------
pid=$(prop MainPID)
uid=$(awk '/^Uid:/ { print $2 }' "/proc/$pid/status")
want_uid=$(id -u arcaded)
check own-user "main process $pid runs as uid $uid (arcaded is $want_uid)" \
	[ "$uid" = "$want_uid" -a "$uid" != 0 ]
capeff=$(awk '/^CapEff:/ { print $2 }' "/proc/$pid/status")
# CAP_SYS_TTY_CONFIG is capability 26: 0x4000000, nothing else.
check capabilities "CapEff $capeff (only CAP_SYS_TTY_CONFIG)" [ "$capeff" = 0000000004000000 ]
ls -l "/proc/$pid/fd" > "$R/daemon-fds.txt" 2>&1
devs=$(ls -l "/proc/$pid/fd" | sed -n 's/.* -> \(\/dev\/.*\)/\1/p' | sort -u | tr '\n' ' ')
echo "devices open: $devs"
ev=$(ls -l "/proc/$pid/fd" | sed -n 's/.* -> \(\/dev\/input\/event[0-9]*\)$/\1/p' | head -n 1)
# The unit's device policy is a BPF program on its cgroup: probe from a
# process placed in that cgroup, once as root (only the policy can refuse)
# and once as the service's user and group (the udev rules grant access).
cg=/sys/fs/cgroup$(sed -n 's/^0:://p' "/proc/$pid/cgroup")
probe() { # user path mode
	sh -c 'echo $$ > "$1/cgroup.procs" || exit 9
		if [ "$2" = root ]; then exec "$5" open "$3" "$4"; fi
		exec setpriv --reuid="$2" --regid="$2" --clear-groups "$5" open "$3" "$4"' \
		sh "$cg" "$1" "$2" "$3" "$G"
}
devcheck() { # user path mode expected
	got=$(probe "$1" "$2" "$3")
	echo "probe $1 $2 $3: $got (want $4)"
	[ "$got" = "$4" ]
}
dp_ok=1
dp_detail=""
for spec in "root /dev/fb0 rw ok" "root /dev/tty0 rw ok" "root ${ev:-/dev/input/event0} r ok" \
	"root ${ev:-/dev/input/event0} rw EPERM" "root /dev/mem r EPERM" "root /dev/ttyS0 rw EPERM" \
	"root /dev/uinput rw EPERM" "root /dev/kmsg r EPERM" \
	"arcaded /dev/fb0 rw ok" "arcaded /dev/tty0 rw ok" "arcaded ${ev:-/dev/input/event0} r ok"; do
	# shellcheck disable=SC2086
	set -- $spec
	if ! devcheck "$1" "$2" "$3" "$4"; then
		dp_ok=0
		dp_detail="$dp_detail $1:$2:$3=$got(want $4)"
	fi
done
check device-policy "in the unit's cgroup: fb0, tty0 rw and the keyboard r open; input rw, /dev/mem, ttyS0, uinput, kmsg refused (EPERM)${dp_detail:+; wrong:$dp_detail}" [ "$dp_ok" = 1 ]
echo "open by the daemon: $devs" >> "$R/daemon-fds.txt"

if [ "$BOOT" = fb32 ]; then
	# --- watchdog: a hung main loop is killed and restarted ---------------------
	wd=$(prop WatchdogUSec)
	wd_s=$(echo "$wd" | sed -n 's/^\([0-9.]*\)s$/\1/p')
	old=$(prop MainPID)
	t_old=$(log_since 0 | grep "arcaded\[$old\]" | head -n 1 | cut -d' ' -f1)
	if log_since "${t_old:-0}" | grep -q 'fault injection: SIGUSR2 hangs the main loop'; then
		t_sent=$(now)
		systemctl kill --kill-whom=main -s SIGUSR2 "$U"
		# The daemon's own line says when the loop stopped.
		t_hang=$(wait_log 'fault injection: main loop hung' "$t_sent" 10) || t_hang=$t_sent
		t_wd=$(wait_log 'Watchdog timeout' "$t_hang" 30) || t_wd=""
		t_restart=$(wait_log 'Starting arcaded' "$t_hang" 40) || t_restart=""
		t_back=$(wait_log 'Started arcaded' "$t_hang" 40) || t_back=""
		new=$(prop MainPID)
		log_since "$t_sent" > "$R/watchdog-journal.txt"
		if [ -n "$t_wd" ] && [ -n "$t_restart" ] && [ -n "$t_back" ]; then
			kill_s=$(sub "$t_hang" "$t_wd")
			restart_s=$(sub "$t_hang" "$t_restart")
			back_s=$(sub "$t_hang" "$t_back")
			figure "watchdog (WatchdogSec=$wd_s): main loop hung to watchdog kill $kill_s s, to restart $restart_s s, to READY=1 again $back_s s"
			check watchdog-restart "hung to kill $kill_s s, to restart $restart_s s (limit WatchdogSec + 2 = $(awk -v w="$wd_s" 'BEGIN { print w + 2 }') s), READY=1 again at $back_s s; pid $old -> $new" \
				sh -c "[ '$new' != '$old' ] && awk -v k='$restart_s' -v w='$wd_s' 'BEGIN { exit !(k <= w + 2) }'"
		else
			fail watchdog-restart "no watchdog kill, restart or READY after the hang: see watchdog-journal.txt"
		fi
	else
		fail watchdog-restart "the daemon did not log 'fault injection: SIGUSR2 hangs the main loop' (ARCADED_FAULT=sigusr2 from the VM's drop-in)"
	fi
	sleep 1
	shot wd-attract-1
	sleep 1
	shot wd-attract-2
	coin_start
	shot wd-play
fi

# --- SIGTERM: clean exit, console back in text mode --------------------------
before=$("$G" kdmode /dev/tty0)
t_stop=$(now)
systemctl stop "$U"
code=$(prop ExecMainCode)
status=$(prop ExecMainStatus)
result=$(prop Result)
after=$("$G" kdmode /dev/tty0)
stopping=$(log_since "$t_stop" | grep -c 'signal 15: stopping')
check sigterm-clean-exit "ExecMainCode=$code (1 = exited) ExecMainStatus=$status Result=$result, 'signal 15: stopping' logged $stopping time(s)" \
	[ "$code" = 1 -a "$status" = 0 -a "$result" = success -a "$stopping" = 1 ]
check sigterm-console-text "tty0 while running: $before; after stop: $after" \
	sh -c "echo '$before' | grep -q 'kd graphics kb off' && echo '$after' | grep -q '^kd text' && ! echo '$after' | grep -q 'kb off'"
shot after-stop

# The evdev and fbdev unit tests skip on a machine without uinput or a
# framebuffer; here both exist (the daemon is stopped: nothing holds them).
if [ "$BOOT" = fb32 ]; then
	for t in test_in_evdev test_dp_fbdev; do
		"$S/bin/$t" > "$R/$t.log" 2>&1
		rc=$?
		sum=$(grep -E '^\[  (PASSED|FAILED|SKIPPED)  \]' "$R/$t.log" | tr '\n' ' ')
		check "unit-$t" "exit $rc: $sum" [ "$rc" = 0 ]
	done
fi

exec 3>&-
wait "$kbd_pid"
figure "guest tests took $(sub "$t_start" "$(now)") s"
journalctl -o short-monotonic -b --no-pager > "$R/journal.txt" 2>&1
dmesg > "$R/dmesg.txt" 2>&1
sync
: > "$R/done"
systemctl poweroff --force --force
