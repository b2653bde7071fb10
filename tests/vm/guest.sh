#!/bin/sh
# The VM tests' guest side: run by vm-test.service once arcaded.service is
# up (tests/vm/run.sh boots the VM; docs/vm.md). Writes its findings to
# /vm/results/results.txt as "PASS name: detail", "FAIL name: detail" and
# "FIGURE text" lines, asks the host for screendumps (the host judges the
# pictures), saves the journal and powers the VM off.
#
# Under emulation every process start costs milliseconds and journalctl
# much more: waits poll /proc and systemctl, and the journal is read once
# per phase for the exact times.
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

# Polls a command every 0.1 s for up to $1 s (by the clock: one round can
# take long under emulation); its status.
wait_until() {
	read -r u _ < /proc/uptime
	end=$((${u%.*}${u#*.} + $1 * 100))
	shift
	while ! "$@"; do
		read -r u _ < /proc/uptime
		[ "${u%.*}${u#*.}" -lt "$end" ] || return 1
		sleep 0.1
	done
}
# The unit's journal as "MONOTONIC-SECONDS message" lines, from time $1 on.
log_since() {
	journalctl -o short-monotonic -u "$U" --no-pager -q |
		sed -n 's/^\[ *\([0-9]*\.[0-9]*\)\] [^ ]* \(.*\)$/\1 \2/p' |
		awk -v t="${1:-0}" '$1 + 0 >= t + 0'
}
# Time of the first line matching $1 in the journal text $2 ("" if none).
first() { echo "$2" | grep -m 1 -e "$1" | cut -d' ' -f1; }
prop() { systemctl show -p "$1" --value "$U"; }

# Asks the host for a screendump named $1 and waits until it is taken.
acked() { [ -e "$R/ack/$1" ]; }
shot() {
	: > "$R/req/$1"
	wait_until 60 acked "$1" || fail "screendump-$1" "the host did not answer"
}
# Screendumps $1-1, $1-2, ... until the host finds the reference frame on
# the screen, for up to $2 s; the host keeps the last one as $1. The game
# shows a stage banner first, and emulation slows its clock down.
shot_match() {
	k=0
	read -r u _ < /proc/uptime
	mend=$((${u%.*}${u#*.} + $2 * 100))
	while :; do
		k=$((k + 1))
		echo match > "$R/req/$1-$k"
		wait_until 60 acked "$1-$k" || { fail "screendump-$1" "the host did not answer"; return 1; }
		if grep -q '^match' "$R/ack/$1-$k"; then
			figure "$1: the screen showed the reference frame at screendump $k"
			return 0
		fi
		read -r u _ < /proc/uptime
		[ "${u%.*}${u#*.}" -lt "$mend" ] || return 1
		sleep 0.5
	done
}

# --- boot: READY=1 is sent after the first frame is presented ---------------
phase_boot() {
	journal=$(log_since 0)
	t_ready=$(first 'Started arcaded' "$journal")
	# For the host: QEMU start to READY = when it sees this line, less the lag.
	echo "@@vm-ready uptime=$(cut -d' ' -f1 /proc/uptime) ready=${t_ready:-0}" > /dev/ttyS0
	check service-ready "READY=1 at ${t_ready:-never} s after kernel start" [ -n "$t_ready" ]
	[ -n "$t_ready" ] && figure "kernel start to READY=1 (first frame shown): $t_ready s"
	"$G" fbinfo /dev/fb0 > "$R/fbinfo.txt"
	disp=$(echo "$journal" | grep -m 1 'arcaded: display: ' | sed 's/.*arcaded: display: //')
	case $BOOT in
	fb16) want='^fbdev /dev/fb0 .* rgb565 ' ;;
	*) want='^fbdev /dev/fb0 .* xrgb8888 .* double-buffered ' ;;
	esac
	check display-fbdev "$disp" sh -c "echo '$disp' | grep -q -e '$want'"

	# Attract mode: the camera turns, two screens a second apart differ.
	shot attract-1
	sleep 1
	shot attract-2
}

# --- input: a uinput keyboard plugged in after start -----------------------
coins=0
coin_start() {
	coins=$((coins + 1))
	echo "tap KEY_5 150" >&3
	sleep 0.5
	echo "tap KEY_1 150" >&3
	sleep 1.5
}
phase_input() {
	pid=$(prop MainPID)
	mkfifo /run/vm-kbd
	"$G" kbd /run/vm-kbd > "$R/kbd.log" 2>&1 &
	kbd_pid=$!
	exec 3> /run/vm-kbd
	t_plug=$(now)
	sys=$(sed -n 's/^ready //p' "$R/kbd.log")
	ev=/dev/input/$(ls "$sys" | grep -m 1 '^event')
	if took=$("$G" waitfd "$pid" "$ev" 15); then
		pass keyboard-attached "the daemon opened the uinput keyboard $ev $took s after it appeared (it retries every second)"
	else
		fail keyboard-attached "the daemon did not open $ev within 15 s"
	fi
	coin_start
	shot_match play-start 30
	# forward and a turn: the picture must change
	echo "tap KEY_UP 600" >&3
	echo "tap KEY_LEFT 300" >&3
	sleep 1.5
	shot play-moved
}

# --- the service's user, capabilities and devices ---------------------------
phase_sandbox() {
	uid=$(awk '/^Uid:/ { print $2 }' "/proc/$pid/status")
	want_uid=$(id -u arcaded)
	check own-user "main process $pid runs as uid $uid (arcaded is $want_uid)" \
		[ "$uid" = "$want_uid" -a "$uid" != 0 ]
	capeff=$(awk '/^CapEff:/ { print $2 }' "/proc/$pid/status")
	# CAP_SYS_TTY_CONFIG is capability 26: 0x4000000, nothing else.
	check capabilities "CapEff $capeff (only CAP_SYS_TTY_CONFIG)" [ "$capeff" = 0000000004000000 ]
	ls -l "/proc/$pid/fd" > "$R/daemon-fds.txt" 2>&1
	# The unit's device policy is a BPF program on its cgroup: probe from a
	# process placed in that cgroup, once as root (only the policy can refuse)
	# and once as the service's user and group (the udev rules grant access).
	cg=/sys/fs/cgroup$(sed -n 's/^0:://p' "/proc/$pid/cgroup")
	"$G" probe "$cg" root /dev/fb0:rw:ok /dev/tty0:rw:ok "$ev:r:ok" "$ev:rw:EPERM" \
		/dev/mem:r:EPERM /dev/ttyS0:rw:EPERM /dev/uinput:rw:EPERM /dev/kmsg:r:EPERM \
		> "$R/probe.txt" 2>&1
	rc_root=$?
	"$G" probe "$cg" arcaded /dev/fb0:rw:ok /dev/tty0:rw:ok "$ev:r:ok" >> "$R/probe.txt" 2>&1
	rc_user=$?
	check device-policy "in the unit's cgroup: fb0 and tty0 rw, the keyboard r open; the keyboard rw, /dev/mem, ttyS0, uinput, kmsg refused (EPERM)$(grep WANTED "$R/probe.txt" | tr '\n' ';')" \
		[ "$rc_root" = 0 -a "$rc_user" = 0 ]
}

# --- watchdog: a hung main loop is killed and restarted ---------------------
phase_watchdog() {
	wd_s=$(prop WatchdogUSec | sed -n 's/^\([0-9.]*\)s$/\1/p')
	old=$pid
	t_sent=$(now)
	if echo "$journal" | grep -q 'fault injection: SIGUSR2 hangs the main loop'; then
		systemctl kill --kill-whom=main -s SIGUSR2 "$U"
		back() { # a new main process, running (READY=1 received)
			v=$(systemctl show -p MainPID -p SubState "$U")
			case " $v " in *"MainPID=$old"[!0-9]*) return 1 ;; esac
			case $v in *SubState=running*) return 0 ;; esac
			return 1
		}
		wait_until 40 back
		new=$(prop MainPID)
		journal=$(log_since "$t_sent")
		echo "$journal" > "$R/watchdog-journal.txt"
		# The daemon's own line says when the loop stopped.
		t_hang=$(first 'fault injection: main loop hung' "$journal")
		t_wd=$(first 'Watchdog timeout' "$journal")
		t_restart=$(first 'Starting arcaded' "$journal")
		t_back=$(first 'Started arcaded' "$journal")
		if [ -n "$t_hang" ] && [ -n "$t_wd" ] && [ -n "$t_restart" ] && [ -n "$t_back" ]; then
			kill_s=$(sub "$t_hang" "$t_wd")
			restart_s=$(sub "$t_hang" "$t_restart")
			back_s=$(sub "$t_hang" "$t_back")
			figure "watchdog (WatchdogSec=$wd_s): main loop hung to watchdog kill $kill_s s, to restart $restart_s s, to READY=1 again $back_s s"
			check watchdog-restart "hung to kill $kill_s s, to restart $restart_s s (limit WatchdogSec + 2 = $(awk -v w="$wd_s" 'BEGIN { print w + 2 }') s), READY=1 again at $back_s s; pid $old -> $new" \
				sh -c "[ '$new' != '$old' ] && awk -v k='$restart_s' -v w='$wd_s' 'BEGIN { exit !(k <= w + 2) }'"
		else
			fail watchdog-restart "hang '$t_hang', watchdog kill '$t_wd', restart '$t_restart', READY '$t_back': see watchdog-journal.txt"
		fi
	else
		fail watchdog-restart "the daemon did not log 'fault injection: SIGUSR2 hangs the main loop' (ARCADED_FAULT=sigusr2 is set by the VM's drop-in)"
	fi
	pid=$(prop MainPID)
	# back in attract, with the keyboard taken again
	"$G" waitfd "$pid" "$ev" 15 || fail keyboard-after-restart "the restarted daemon did not open $ev"
	shot wd-attract-1
	sleep 1
	shot wd-attract-2
	coin_start
	shot_match wd-play 30
}

# --- SIGTERM: clean exit, console back in text mode --------------------------
phase_sigterm() {
	# Text for the console to show again once it is back in text mode.
	printf '\n\n   arcaded VM test: the console shows text again\n' > /dev/tty1
	before=$("$G" kdmode /dev/tty0)
	t_stop=$(now)
	wall_stop=$(date +%s.%N)
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
	# State saved: the bookkeeping file counts every coin and game of this
	# boot (its state directory starts empty), checks out (vm_guest books
	# reads it independently of the daemon's code) and was written at the
	# stop (play and power-on time are saved on the way out).
	f=/var/lib/arcaded/books
	books=$("$G" books "$f")
	brc=$?
	meta=$(stat -c '%U %a %.9Y' "$f" 2>&1)
	check sigterm-state-saved "$f: $books; owner, mode, mtime: $meta; $coins coin(s) and game(s) this boot" \
		sh -c "[ $brc = 0 ] && echo '$books' | grep -q '^coins $coins plays $coins ' &&
			echo '$meta' | grep -q '^arcaded 600 ' &&
			awk -v m='${meta##* }' -v s='$wall_stop' 'BEGIN { exit !(m + 0 >= s + 0) }'"
}

# --- a USB keyboard (HID gadget on dummy_hcd) unplugged and replugged ------
# A configfs HID gadget with the boot keyboard descriptor, bound to
# dummy_hcd's UDC, enumerates through the real USB and HID stack (usbhid,
# hid-generic) and reaches the daemon through evdev. Unbinding the UDC is
# an unplug. The uinput keyboard is removed first, so the daemon takes this
# one (it holds one evdev keyboard).
BOOT_KBD_DESC="05 01 09 06 a1 01 05 07 19 e0 29 e7 15 00 25 01 75 01 95 08 81 02 95 01 75 08 81 03 95 05 75 01 05 08 19 01 29 05 91 02 95 01 75 03 91 03 95 06 75 08 15 00 25 65 05 07 19 00 29 65 81 00 c0"
GADGET=/sys/kernel/config/usb_gadget/arcvm
GADGET_NAME="arcaded-vm USB keyboard"
# HID boot keyboard report: modifiers, reserved, up to 6 usages (0x50 left).
hid_key() { "$G" hidwrite /dev/hidg0 "00 00 $1 00 00 00 00 00"; }
plug() { echo dummy_udc.0 > "$GADGET/UDC"; }
unplug() { echo "" > "$GADGET/UDC"; }
# Plugs the gadget in and waits until the daemon ($pid) has its event node
# open; prints the node and the seconds that took.
plug_attach() {
	plug && "$G" waitdev "$pid" "$GADGET_NAME" 20
}
phase_hotplug() {
	exec 3>&-
	wait "$kbd_pid"
	kbd_pid=""
	for m in dummy_hcd libcomposite usb_f_hid; do
		modprobe "$m" || { fail hid-gadget "modprobe $m failed"; return; }
	done
	mkdir -p "$GADGET/strings/0x409" "$GADGET/functions/hid.usb0" "$GADGET/configs/c.1"
	echo 0x1209 > "$GADGET/idVendor"
	echo 0x0001 > "$GADGET/idProduct"
	echo arcaded > "$GADGET/strings/0x409/manufacturer"
	echo "$GADGET_NAME" > "$GADGET/strings/0x409/product"
	echo 1 > "$GADGET/functions/hid.usb0/protocol"
	echo 1 > "$GADGET/functions/hid.usb0/subclass"
	echo 8 > "$GADGET/functions/hid.usb0/report_length"
	"$G" hidwrite "$GADGET/functions/hid.usb0/report_desc" "$BOOT_KBD_DESC"
	ln -s "$GADGET/functions/hid.usb0" "$GADGET/configs/c.1/"
	pid=$(prop MainPID)
	t_hp=$(now)
	if ! got=$(plug_attach); then
		fail hid-gadget "the daemon did not take the USB keyboard gadget: $got"
		return
	fi
	pass hid-gadget "USB keyboard gadget on dummy_hcd: the daemon reads ${got% *} ${got#* } s after the plug"
	shot hp-before
	hid_key 50
	sleep 1
	hid_key 00
	sleep 0.5
	shot hp-turned
	# 20 unplugs with a key held, each followed by a replug.
	i=0
	ok=1
	while [ $i -lt 20 ]; do
		i=$((i + 1))
		hid_key 50
		sleep 0.2
		unplug
		sleep 0.2
		plug_attach > /dev/null || { ok=0; break; }
	done
	# Re-attach times from the journal: the kernel's "new ... USB device"
	# to the daemon's "attached" line.
	journal=$(journalctl -o short-monotonic --no-pager -q |
		sed -n 's/^\[ *\([0-9]*\.[0-9]*\)\] [^ ]* \(.*\)$/\1 \2/p' |
		awk -v t="$t_hp" '$1 + 0 >= t + 0')
	stats=$(echo "$journal" | awk -v name="$GADGET_NAME" '
		/kernel: usb 1-1: new .* USB device/ { plug = $1 }
		index($0, "input evdev: attached") && index($0, name) && plug { v[++n] = $1 - plug; plug = 0 }
		END {
			for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] < v[i]) { x = v[i]; v[i] = v[j]; v[j] = x }
			if (n) printf "min %.2f median %.2f max %.2f s over %d plugs", v[1], v[int((n + 1) / 2)], v[n], n
		}')
	n=$(echo "$journal" | grep -c "$GADGET_NAME.* went away; its controls are released")
	figure "hotplug: USB keyboard plugged (kernel enumerates it) to the daemon reading it: $stats"
	check hotplug-cycles "$i unplugs with a key held, each replugged and read again ($stats); the daemon logged $n release(s) of the gadget's controls; main PID $pid -> $(prop MainPID)" \
		[ "$ok" = 1 -a "$n" -ge 20 -a "$(prop MainPID)" = "$pid" ]
	# No stuck input: nothing held now, so the view must stay still.
	sleep 1
	shot hp-still-1
	sleep 1
	shot hp-still-2
	unplug
}

# --- a framebuffer that appears after the daemon started --------------------
phase_latefb() {
	has_fb() { [ -e /sys/class/graphics/fb0 ]; }
	wait_until 90 has_fb || { fail late-fb "bochs was not loaded (vm-late-fb.service)"; return; }
	t_fb=$(now)
	draws() { ls -l "/proc/$(prop MainPID)/fd" 2>/dev/null | grep -q ' -> /dev/fb0$'; }
	if wait_until 20 draws; then
		pass late-fb "the daemon opened /dev/fb0 $(sub "$t_fb" "$(now)") s after it appeared"
		sleep 1
		shot late-screen
	else
		fail late-fb "/dev/fb0 appeared after the daemon started; 20 s later the daemon still does not draw on it: $(log_since 0 | grep -m 1 'arcaded: display' | cut -d' ' -f2-)"
	fi
	log_since 0 > "$R/late-fb-journal.txt"
}

# The device unit tests skip on a machine without uinput, a framebuffer,
# uhid or gpio-sim; here all exist (the daemon is stopped: nothing holds
# them), so nothing may skip.
unit_tests() {
	if [ -e "$S/modules/gpio-sim-oot.ko" ]; then
		insmod "$S/modules/gpio-sim-oot.ko" || fail gpio-sim-module "insmod gpio-sim-oot.ko failed"
	fi
	for t in "$S"/tests/test_*; do
		n=${t##*/}
		(cd "$S/repo" && exec "$t") > "$R/$n.log" 2>&1
		rc=$?
		sum=$(grep -E '^\[  (PASSED|FAILED|SKIPPED)  \] [0-9]' "$R/$n.log" | tr '\n' ' ')
		check "unit-$n" "exit $rc: $sum" sh -c "[ $rc = 0 ] && ! grep -q '^\[  SKIPPED  \]' '$R/$n.log'"
	done
}

kbd_pid=""
case $BOOT in
fb32) phase_boot; phase_input; phase_sandbox; phase_watchdog; phase_sigterm; unit_tests ;;
fb16) phase_boot; phase_input; phase_sandbox; phase_hotplug; phase_sigterm ;;
latefb) phase_latefb ;;
units) systemctl stop "$U"; unit_tests ;;
*) fail boot "unknown boot '$BOOT'" ;;
esac

if [ -n "$kbd_pid" ]; then
	exec 3>&-
	wait "$kbd_pid"
fi
figure "guest tests took $(sub "$t_start" "$(now)") s"
journalctl -o short-monotonic -b --no-pager > "$R/journal.txt" 2>&1
dmesg > "$R/dmesg.txt" 2>&1
sync
: > "$R/done"
systemctl poweroff --force --force
