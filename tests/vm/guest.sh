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
# Only these phases, when given (ARCADED_VM_PHASES on the host, to debug).
PHASES=$(sed -n 's/.*arcaded\.phases=\([a-z0-9_,]*\).*/\1/p' /proc/cmdline)
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

# Puts request $1 with the text $2 where the host looks (tests/vm/run.sh
# polls $R/req/*): written under a dot name, which the host's glob skips,
# then renamed, so the host never reads it half written. (Written in place,
# the host once read "key 5 150" as an empty file, took it for a plain
# screendump and acked it: the coin key was never sent.)
request() {
	printf '%s\n' "$2" > "$R/req/.$1" && mv "$R/req/.$1" "$R/req/$1"
}
# Asks the host for a screendump named $1 and waits until it is taken.
acked() { [ -e "$R/ack/$1" ]; }
shot() {
	request "$1" ""
	wait_until 60 acked "$1" || fail "screendump-$1" "the host did not answer"
}
# Screendumps $1-1, $1-2, ... until the host finds the reference frame on
# the screen, for up to $2 s; the host keeps the last one as $1. The game
# shows a stage banner first, and emulation slows its clock down. $3: the
# reference's name (tests/vm/run.sh's ref-NAME.png) if not the start view
# of a one-player game.
shot_match() {
	k=0
	read -r u _ < /proc/uptime
	mend=$((${u%.*}${u#*.} + $2 * 100))
	while :; do
		k=$((k + 1))
		request "$1-$k" "match${3:+ $3}"
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
	# The daemon may have started before the driver made /dev/fb0 (the
	# unit does not wait for it): the line that counts is the one of the
	# display it took.
	disp=$(echo "$journal" | grep -m 1 -E 'arcaded: display: (fbdev|kms) ' | sed 's/.*arcaded: display: //')
	case $BOOT in
	fb16) want='^fbdev /dev/fb0 .* rgb565 ' ;;
	kms) want='^kms /dev/dri/card0 Virtual-1 .* xrgb8888 .* page flips at vblank' ;;
	*) want='^fbdev /dev/fb0 .* xrgb8888 .* double-buffered ' ;;
	esac
	dname=display-fbdev
	[ "$BOOT" = kms ] && dname=display-kms
	check "$dname" "$disp" sh -c "echo '$disp' | grep -q -e '$want'"

	# Attract mode: the camera turns, two screens a second apart differ.
	shot attract-1
	sleep 1
	shot attract-2
}

# A key on QEMU's PS/2 keyboard (the host sends it through QMP send-key):
# QCODE ("5"), held MS milliseconds.
nkey=0
hostkey() {
	nkey=$((nkey + 1))
	request "key-$nkey" "key $1 $2"
	wait_until 30 acked "key-$nkey" || fail "hostkey-$1" "the host did not send it"
	sleep "$(awk -v m="$2" 'BEGIN { print m / 1000 + 0.3 }')"
}
# The event node of the PS/2 keyboard ("" if none).
at_keyboard() {
	for e in /sys/class/input/event*; do
		[ "$(cat "$e/device/name" 2>/dev/null)" = "AT Translated Set 2 keyboard" ] &&
			{ echo "/dev/input/${e##*/}"; return; }
	done
}

# --- sound through QEMU's Intel HDA card ----------------------------------
# The kms boot has an ich9-intel-hda card whose output QEMU writes to a
# WAV file on the host (tests/vm/run.sh). udev loads snd_hda_intel; the
# daemon, which looks for a card every second, opens it through ALSA as
# installed (audio.output = auto, device "default"). Then 20 coins on the
# PS/2 keyboard in attract mode: the host times each key it sends and the
# growth of the WAV file, finds each coin's sound in the file by
# correlation and gives the coin-to-first-audible-sample latency. The
# card's mixer starts muted: alsa-utils' udev rule (alsactl restore, which
# with no saved state runs alsactl init) unmutes it, as on a cabinet with
# the package's Recommends. Here:
# the card, the daemon's ALSA line, and its underrun count over the coins.
SOUND_COINS=20
underruns() { # the SIGUSR1 summary's underrun count ("" if none came)
	t_u=$(now)
	systemctl kill --kill-whom=main -s SIGUSR1 "$U"
	for _ in 1 2 3 4 5 6 7 8 9 10; do
		sleep 0.3
		u=$(log_since "$t_u" | grep -m 1 -F "; sound output: " |
			sed -n 's/.*; sound output: \([0-9]*\) underruns.*/\1/p')
		[ -n "$u" ] && { echo "$u"; return; }
	done
}
phase_sound() {
	t_s0=$(now)
	systemctl start "$U"   # Type=notify: back when the first frame is shown
	wait_until 60 grep -q -i "hda" /proc/asound/cards
	card=$(grep -m 1 -i "hda" /proc/asound/cards | sed 's/^ *//')
	check sound-card "the kernel's card: ${card:-none} (/proc/asound/cards)" [ -n "$card" ]
	al=""
	for _ in $(seq 1 60); do
		al=$(log_since "$t_s0" | grep -m 1 -E "arcaded: sound: alsa [^ ]*: [0-9]+ Hz" | sed 's/.*arcaded: sound: //')
		[ -n "$al" ] && break
		sleep 0.5
	done
	if [ -z "$al" ]; then
		# what the service's user meets: the nodes, and ALSA's own word
		ls -l /dev/snd > "$R/snd-nodes.txt" 2>&1
		runuser -u arcaded -- aplay -q -D default -d 1 /dev/zero > "$R/snd-aplay.txt" 2>&1
		log_since "$t_s0" | grep -F "arcaded: sound" > "$R/snd-log.txt"
	fi
	check sound-alsa-open "the daemon's line: ${al:-no 'sound: alsa' line within 30 s: $(tr '\n' ';' < "$R/snd-log.txt"; tr '\n' ';' < "$R/snd-nodes.txt"; tr '\n' ';' < "$R/snd-aplay.txt")}" [ -n "$al" ]
	[ -n "$al" ] && figure "sound output: $al"
	u0=$(underruns)
	t_snd=$(now)
	i=0
	while [ "$i" -lt "$SOUND_COINS" ]; do
		i=$((i + 1))
		hostkey 5 100
		sleep 0.6
	done
	sleep 1
	u1=$(underruns)
	nc=$(log_since "$t_snd" | grep -c -F 'arcaded: input: evdev 0001:0001 KEY_5 down -> coin')
	check sound-coins-read "the daemon read $nc coin key(s) of the $SOUND_COINS sent" [ "$nc" = "$SOUND_COINS" ]
	figure "sound: underruns while $SOUND_COINS coins played: $((${u1:-0} - ${u0:-0})) (summary before ${u0:-none}, after ${u1:-none})"
	raised=$(log_since "$t_s0" | grep -F "arcaded: sound: alsa " | grep -F "(raised" | sed 's/.*arcaded: sound: //')
	[ -n "$raised" ] && figure "sound: the buffer was raised after underruns $(echo "$raised" | wc -l) time(s), last: $(echo "$raised" | tail -n 1)"
	check sound-underruns "the SIGUSR1 summary's underrun count before and after the coins: ${u0:-none} and ${u1:-none}" \
		[ -n "$u0" -a -n "$u1" ]
	systemctl stop "$U"    # as phase_sigterm left it, for the unit tests
}

# --- input: a uinput keyboard plugged in after start -----------------------
coins=0
plays=0
coin_start() {
	coins=$((coins + 1))
	plays=$((plays + 1))
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
	# The PC's PS/2 keyboard is there too (QEMU's i8042): input.evdev =
	# auto must take both it and the encoder (the uinput keyboard), and
	# both must work: coin on the PS/2 keyboard, start on the encoder.
	at=$(at_keyboard)
	if [ -n "$at" ] && "$G" waitfd "$pid" "$at" 10 > /dev/null; then
		pass two-keyboards "the daemon has both the PS/2 keyboard ($at) and the encoder ($ev) open"
	else
		fail two-keyboards "PS/2 keyboard '${at:-none}' not open by the daemon (the encoder $ev is)"
	fi
	/usr/local/bin/arcaded devices > "$R/devices.txt" 2>&1
	used() { # node: `arcaded devices` says auto-detection takes it
		awk -v n="  $1 " 'index($0, n) == 1 { getline; print; exit }' "$R/devices.txt" |
			grep -q 'in use with input.evdev = auto: '
	}
	u_at=no
	u_ev=no
	[ -n "$at" ] && used "$at" && u_at=yes
	used "$ev" && u_ev=yes
	check devices-in-use "arcaded devices says input.evdev = auto takes the PS/2 keyboard ($u_at) and the encoder ($u_ev): $(grep -A1 -e "  ${at:-none} " -e "  $ev " "$R/devices.txt" | tr -s ' ' | tr '\n' ';')" \
		[ "$u_at" = yes -a "$u_ev" = yes ]
	t_keys=$(now)
	coins=$((coins + 1))
	plays=$((plays + 1))
	hostkey 5 150
	echo "tap KEY_1 150" >&3
	sleep 1.5
	shot_match play-start 30
	keys=$(log_since "$t_keys")
	c5=$(echo "$keys" | grep -c -F 'arcaded: input: evdev 0001:0001 KEY_5 down -> coin')
	s1=$(echo "$keys" | grep -c -F 'arcaded: input: evdev 1209:0001 KEY_1 down -> start')
	check keys-from-both "coin from the PS/2 keyboard (0001:0001 KEY_5 -> coin: $c5 line(s)), start from the encoder (1209:0001 KEY_1 -> start: $s1)" \
		[ "$c5" = 1 -a "$s1" = 1 ]
	# KMS: the VT switches while the start view is still the reference
	# frame (it stays so for 30 s of game time with no input)
	[ "$BOOT" = kms ] && phase_vt
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
	# stat's field 19 (the 17th after the name in parentheses): the nice
	# level the unit's Nice= gave the process
	ni=$(sed 's/.*) //' "/proc/$pid/stat" | cut -d' ' -f17)
	want_ni=$(systemctl show -p Nice --value "$U")
	check nice "main process nice $ni (the unit's Nice=$want_ni)" \
		[ "$want_ni" = -10 -a "$ni" = "$want_ni" ]
	# the render worker and the main thread a CPU each (app/pool.h
	# pool_pin; the unit lets sched_setaffinity through its filter), and
	# no "not pinned" warning
	m_cpus=$(awk '/^Cpus_allowed_list:/ { print $2 }' "/proc/$pid/status")
	w_cpus=
	for t in /proc/$pid/task/*; do
		[ "$(cat "$t/comm" 2>/dev/null)" = arcaded-pool ] &&
			w_cpus=$(awk '/^Cpus_allowed_list:/ { print $2 }' "$t/status")
	done
	unpinned=$(log_since 0 | grep -c 'not pinned to CPUs')
	case "$m_cpus,$w_cpus" in
	[0-9],[0-9] | [0-9][0-9],[0-9] | [0-9],[0-9][0-9]) one_each=yes ;;
	*) one_each=no ;;
	esac
	check pinned "main thread on CPU(s) $m_cpus, render worker on CPU(s) ${w_cpus:-none found}; $unpinned 'not pinned' line(s)" \
		[ "$one_each" = yes -a "$m_cpus" != "$w_cpus" -a "$unpinned" = 0 ]
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
	crash_loop
	pid=$(prop MainPID)
	# back in attract, with the keyboard taken again
	"$G" waitfd "$pid" "$ev" 15 || fail keyboard-after-restart "the restarted daemon did not open $ev"
	shot wd-attract-1
	sleep 1
	shot wd-attract-2
	coin_start
	shot_match wd-play 30
}

# A daemon that dies at once, again and again (a state file it trips on, a
# driver that crashes it), is started again every time: under systemd's
# default start limit (5 starts in 10 s) the sixth quick death would leave
# the unit failed and the cabinet dark until someone came. Each new main
# process is killed (SIGKILL) as soon as it exists, 7 times. systemd's
# limit counts starts in a window that opens at the first start after the
# last window closed: the watchdog's restart just before opened one, so the
# loop waits for it to close (11 s), and the first death's restart opens
# the next, in which the sixth death's restart would be refused. So the
# first 6 deaths must fall within 10 s (each restart follows its death by
# the same RestartSec), or the check could not see the limit; the seventh
# is one more for good measure. (7 deaths within 10 s, as this asked
# before, took 10.0 to 10.3 s in two clean-clone runs of a slow hour, and
# the check was skipped.)
crash_loop() {
	sleep 11
	killed=$(prop MainPID)
	nr0=$(prop NRestarts)
	t_c=$(now)
	kill -KILL "$killed"
	k=1
	span6=""
	newer() { p=$(prop MainPID); [ "$p" != 0 ] && [ "$p" != "$killed" ]; }
	while [ $k -lt 7 ] && wait_until 10 newer; do
		killed=$p
		kill -KILL "$killed"
		k=$((k + 1))
		[ $k = 6 ] && span6=$(sub "$t_c" "$(now)")
	done
	span=$(sub "$t_c" "$(now)")
	running() { [ "$(prop SubState)" = running ] && newer; }
	wait_until 30 running
	log_since "$t_c" > "$R/crashloop-journal.txt"
	st=$(systemctl show -p ActiveState -p SubState -p Result --value "$U" | paste -sd' ' -)
	nr=$(prop NRestarts)
	sub_state=$(prop SubState)
	figure "crash loop: $k main processes killed in $span s (the first 6 in ${span6:-?} s); restarts $nr0 -> $nr; then $st"
	# Fewer than 7 deaths: a start did not come within 10 s, which is the
	# limit at work, whatever the span.
	if [ "$k" -lt 7 ] || awk -v s="$span6" 'BEGIN { exit !(s < 10) }'; then
		check crashloop-restarted "$k deaths in $span s, the first 6 in ${span6:-?} s (the default limit: 5 starts in 10 s), restarts $nr0 -> $nr, the unit then: $st" \
			[ "$k" = 7 -a $((nr - nr0)) -ge 7 -a "$sub_state" = running ]
	else
		echo "SKIP crashloop-restarted: the first 6 deaths took $span6 s, not under the 10 s a start limit counts over" >> "$R/results.txt"
	fi
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
	check sigterm-state-saved "$f: $books; owner, mode, mtime: $meta; $coins coin(s) and $plays game(s) this boot" \
		sh -c "[ $brc = 0 ] && echo '$books' | grep -q '^coins $coins plays $plays ' &&
			echo '$meta' | grep -q '^arcaded 600 ' &&
			awk -v m='${meta##* }' -v s='$wall_stop' 'BEGIN { exit !(m + 0 >= s + 0) }'"
}

# --- USB gadgets on dummy_hcd -----------------------------------------------
# dummy_hcd is loaded once per boot, whichever phase needs it first, always
# with two UDCs: dummy_udc.0 and dummy_udc.1, each the only device port of
# its own USB bus (ports 1-1 and 2-1).
gadget_modules() {
	modprobe dummy_hcd num=2 || { echo "modprobe dummy_hcd num=2 failed"; return 1; }
	for m in libcomposite usb_f_hid; do
		modprobe "$m" || { echo "modprobe $m failed"; return 1; }
	done
	[ -e /sys/class/udc/dummy_udc.1 ] ||
		{ echo "dummy_hcd has one UDC: it was loaded without num=2"; return 1; }
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
hid_key() { "$G" hidwrite "$(hidg_of arcvm)" "00 00 $1 00 00 00 00 00"; }
plug() { echo dummy_udc.0 > "$GADGET/UDC"; }
# Makes the keyboard gadget (once; gadget_modules first).
kbd_gadget() {
	[ -d "$GADGET" ] && return 0
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
}
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
	if ! err=$(gadget_modules); then
		fail hid-gadget "$err"
		return
	fi
	kbd_gadget
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
	# 20 unplugs with Left held, each followed by a replug.
	"$G" replug "$pid" input "$GADGET" dummy_udc.0 "$(hidg_of arcvm)" 20 200 \
		"00 00 00 00 00 00 00 00" "00 00 50 00 00 00 00 00" > "$R/kbd-replug.txt" 2>&1
	ok=$((! $?))
	i=$(grep -c '^plug [0-9]* closed' "$R/kbd-replug.txt")
	# Re-attach times from the journal: the kernel's "new ... USB device"
	# to the daemon's "attached" line.
	journal=$(all_since "$t_hp")
	stats=$(echo "$journal" | awk -v name="$GADGET_NAME" '
		/kernel: usb 1-1: new .* USB device/ { plug = $1 }
		index($0, "input evdev: attached") && index($0, name) && plug { v[++n] = $1 - plug; plug = 0 }
		END {
			for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] < v[i]) { x = v[i]; v[i] = v[j]; v[j] = x }
			if (n) printf "min %.2f median %.2f max %.2f s over %d plugs", v[1], v[int((n + 1) / 2)], v[n], n
		}')
	n=$(echo "$journal" | grep -c "$GADGET_NAME.* went away; its controls are released")
	figure "hotplug: USB keyboard plugged (kernel enumerates it) to the daemon reading it: $stats"
	figure "hotplug, medians over $i plugs: UDC bound to event node $(stage node "$R/kbd-replug.txt"), node to udev done with it $(stage udev "$R/kbd-replug.txt"), node to the daemon having it open $(stage open "$R/kbd-replug.txt")"
	check hotplug-cycles "$i unplugs with a key held, each replugged and read again ($stats)$([ "$ok" = 1 ] || echo "; $(tail -n 1 "$R/kbd-replug.txt")"); the daemon logged $n release(s) of the gadget's controls; main PID $pid -> $(prop MainPID)" \
		[ "$ok" = 1 -a "$n" -ge 20 -a "$(prop MainPID)" = "$pid" ]
	# No stuck input: the daemon holds nothing, and the view does not
	# turn (five screens a second apart, compared on the host).
	nothing_held hotplug-nothing-held
	still_shots hp-still
	unplug
}

# --- a DragonRise joystick (HID gadget) read through hidraw -----------------
# The gadget is 0079:0006, so the daemon's autoconfig profile
# config/profiles/dragonrise-0079-0006.ini applies, and the kernel binds it
# to hid-dr (DragonRise's driver, with force feedback), not hid-generic. Its
# report descriptor is the 101-byte original DragonRise descriptor that
# Linux's drivers/hid/hid-dr.c documents (a 0079:0011 pad; also
# tests/unit/test_hidr.c) with one byte changed: the output report holds
# 7 bytes, not 4, because hid-dr's force-feedback set-up for 0079:0006 fails
# the probe when it has fewer than 7 (then no driver binds and there is no
# hidraw node). No byte-exact 0079:0006 descriptor is on record
# (tests/data/hid/README.md).
# Input report, 8 bytes: five axes declared X X X X Y (arcaded's decoder
# gives them ABS_X, ABS_Y, ABS_Z, ABS_RX, ABS_RY: the next free code for a
# repeated usage, so bytes 0 and 1 are the stick), a 4-bit field of no
# usage (0x0f: its null state), buttons 1-10 from bit 44, 10 vendor bits.
# The profile binds button 1 fire, 9 coin, 10 start, the stick's directions
# forward/back/turn.
JOY_DESC="05 01 09 04 a1 01 a1 02 75 08 95 05 15 00 26 ff 00 35 00 46 ff 00 09 30 09 30 09 30 09 30 09 31 81 02 75 04 95 01 25 07 46 3b 01 65 14 09 00 81 42 65 00 75 01 95 0a 25 01 45 01 05 09 19 01 29 0a 81 02 06 00 ff 75 01 95 0a 25 01 45 01 09 01 81 02 c0 a1 02 75 08 95 07 46 ff 00 26 ff 00 09 02 91 02 c0 c0"
JOY_IDLE="7f 7f 7f 7f 7f 0f 00 00"
JOY_LEFT="00 7f 7f 7f 7f 0f 00 00"
JOY_FIRE="7f 7f 7f 7f 7f 1f 00 00"
JOY_FIRE_LEFT="00 7f 7f 7f 7f 1f 00 00"
JOY_COIN="7f 7f 7f 7f 7f 0f 10 00"
JOY_START="7f 7f 7f 7f 7f 0f 20 00"
GADGETS=/sys/kernel/config/usb_gadget

# Creates joystick gadget $1 (once). Every one has the same VID:PID, strings
# and serial number: two of them are identical but for their port.
joy_gadget() {
	gd=$GADGETS/$1
	[ -d "$gd" ] && return 0
	gadget_modules || return 1
	# DragonRise's driver now, so hid-generic does not bind first.
	modprobe hid-dr || { echo "modprobe hid-dr failed"; return 1; }
	mkdir -p "$gd/strings/0x409" "$gd/functions/hid.usb0" "$gd/configs/c.1"
	echo 0x0079 > "$gd/idVendor"
	echo 0x0006 > "$gd/idProduct"
	echo "DragonRise Inc." > "$gd/strings/0x409/manufacturer"
	echo "Generic USB Joystick" > "$gd/strings/0x409/product"
	echo "ZD0001" > "$gd/strings/0x409/serialnumber"
	echo 0 > "$gd/functions/hid.usb0/protocol"
	echo 0 > "$gd/functions/hid.usb0/subclass"
	echo 8 > "$gd/functions/hid.usb0/report_length"
	"$G" hidwrite "$gd/functions/hid.usb0/report_desc" "$JOY_DESC" || return 1
	ln -s "$gd/functions/hid.usb0" "$gd/configs/c.1/"
}
joy_plug() { echo "dummy_udc.$2" > "$GADGETS/$1/UDC"; }   # gadget, UDC 0 or 1
joy_unplug() { echo "" > "$GADGETS/$1/UDC"; }
# The gadget side of $1: /dev/hidgN, N its minor.
hidg_of() {
	mm=$(cat "$GADGETS/$1/functions/hid.usb0/dev")
	echo "/dev/hidg${mm#*:}"
}
# Sends report $2 through the gadget node $1 (once the host takes reports).
joy() { "$G" hidsend "$1" "$2" 5; }
# The hidraw node of the HID device on dummy_udc.$1's bus; fails while
# there is none.
hidraw_on() {
	for hr in /sys/class/hidraw/hidraw*; do
		[ -e "$hr" ] || continue
		case $(readlink -f "$hr/device") in
		*/dummy_hcd."$1"/*) echo "/dev/${hr##*/}"; return 0 ;;
		esac
	done
	return 1
}
# Its USB port path as sysfs names it ("1-1"): the HID device's parent is
# the interface ("1-1:1.0"), whose parent is the device on the port.
port_on() {
	for hr in /sys/class/hidraw/hidraw*; do
		hd=$(readlink -f "$hr/device")
		case $hd in
		*/dummy_hcd."$1"/*) basename "$(dirname "$(dirname "$hd")")"; return 0 ;;
		esac
	done
	return 1
}
# Whether a process in the daemon's cgroup may open $1 read-write, as root
# (only the unit's device policy can refuse) and as user arcaded (the udev
# rules too); the probe's lines go to $2.
policy_probe() {
	cgp=/sys/fs/cgroup$(sed -n 's/^0:://p' "/proc/$(prop MainPID)/cgroup")
	"$G" probe "$cgp" root "$1:rw:ok" > "$2" 2>&1 &&
		"$G" probe "$cgp" arcaded "$1:rw:ok" >> "$2" 2>&1
}
# Plugs gadget $1 into dummy_udc.$2 and waits until the daemon ($pid) has
# its hidraw node open; on failure prints why.
joy_attach() {
	joy_plug "$1" "$2"
	wait_until 20 hidraw_on "$2" > /dev/null ||
		{ echo "no hidraw node appeared for gadget $1 on dummy_udc.$2"; return 1; }
	jn=$(hidraw_on "$2")
	"$G" waitfd "$pid" "$jn" 10 > /dev/null && return 0
	if policy_probe "$jn" "$R/probe-$1.txt"; then
		echo "the daemon did not open $jn within 10 s (its cgroup may open it)"
	else
		echo "the daemon did not open $jn within 10 s; in its cgroup: $(grep WANTED "$R/probe-$1.txt" | tr '\n' ';') (systemd resolves DeviceAllow=char-hidraw through /proc/devices when the unit starts; hidraw's major exists only once the hid module is loaded)"
	fi
	return 1
}
# The whole journal (kernel lines too) as "MONOTONIC-SECONDS message"
# lines, from time $1 on.
# --- the input wizard, by itself at first boot ------------------------------
# A gamepad no profile names (pid.codes' test id 1209:0002, so only the
# generic guess) is plugged into a cabinet whose wizard never saved: the
# wizard starts, is answered with the pad's buttons 1..10 for the first
# ten steps, the eleventh (SERVICE) and the optional last three (P1
# WEAPON, P1 LOOK UP, P1 LOOK DOWN) are skipped by holding button 1 for
# 1.4 s, and a short press on the summary
# saves. The bindings file it wrote
# must hold exactly those, and after a restart the pad's buttons do what
# the wizard set (button 5 is FIRE) and the wizard does not ask again.
pad_gadget() {
	gd=$GADGETS/$1
	[ -d "$gd" ] && return 0
	gadget_modules || return 1
	mkdir -p "$gd/strings/0x409" "$gd/functions/hid.usb0" "$gd/configs/c.1"
	echo 0x1209 > "$gd/idVendor"
	echo 0x0002 > "$gd/idProduct"
	echo "arcaded" > "$gd/strings/0x409/manufacturer"
	echo "arcaded-vm unknown pad" > "$gd/strings/0x409/product"
	echo 0 > "$gd/functions/hid.usb0/protocol"
	echo 0 > "$gd/functions/hid.usb0/subclass"
	echo 8 > "$gd/functions/hid.usb0/report_length"
	"$G" hidwrite "$gd/functions/hid.usb0/report_desc" "$JOY_DESC" || return 1
	ln -s "$gd/functions/hid.usb0" "$gd/configs/c.1/"
}
# The report with button $1 (1..10) down and the stick and hat at rest:
# buttons 1-4 are bits 4-7 of byte 5 (its low nibble is the hat), 5-10
# bits 0-5 of byte 6.
pad_button() {
	if [ "$1" -le 4 ]; then
		printf '7f 7f 7f 7f 7f %02x 00 00' $((0x0f | (1 << (3 + $1))))
	else
		printf '7f 7f 7f 7f 7f 0f %02x 00' $((1 << ($1 - 5)))
	fi
}
pad_tap() { # gadget-side node, button, milliseconds held
	"$G" hidtap "$1" "$(pad_button "$2")" "$JOY_IDLE" "$3"
	sleep 0.4
}
phase_wizard() {
	pid=$(prop MainPID)
	gadget_up pad_gadget arcpad wizard-first-boot || return
	t_w=$t_plug
	port=$(port_on 0)
	joy "$hg" "$JOY_IDLE"
	started() { log_since "$t_w" | grep -q 'input wizard: started (first boot)'; }
	if ! wait_until 10 started; then
		fail wizard-first-boot "no 'input wizard: started (first boot)' after the pad (usb-$port) attached: $(log_since "$t_w" | grep -m 3 'input hid\|wizard' | cut -d' ' -f2- | tr '\n' ';')"
		joy_unplug arcpad
		return
	fi
	pass wizard-first-boot "the unknown pad on usb-$port attached and the wizard started by itself"
	shot wizard-step-1
	for b in 1 2 3 4 5 6 7 8 9 10; do
		pad_tap "$hg" "$b" 150
	done
	pad_tap "$hg" 1 1400    # SERVICE: held 1 s, skipped
	pad_tap "$hg" 1 1400    # P1 WEAPON: skipped too
	pad_tap "$hg" 1 1400    # P1 LOOK UP: skipped
	pad_tap "$hg" 1 1400    # P1 LOOK DOWN: skipped
	shot wizard-summary
	pad_tap "$hg" 2 150     # a short press on the summary saves
	saved() { log_since "$t_w" | grep -q 'input wizard: bindings saved in /var/lib/arcaded/bindings.ini'; }
	wait_until 10 saved
	f=/var/lib/arcaded/bindings.ini
	cp "$f" "$R/wizard-bindings.ini" 2>/dev/null
	# The section of the pad's port, as the file has it, action by action.
	got=$(awk -v s="[device \"usb-$port\"]" '$0 == s { on = 1; next } /^\[/ { on = 0 }
		on && / = / { printf "%s=%s;", $1, $3 }' "$f" 2>/dev/null)
	want="forward=BTN_TRIGGER_HAPPY1;back=BTN_TRIGGER_HAPPY2;turn_left=BTN_TRIGGER_HAPPY3;turn_right=BTN_TRIGGER_HAPPY4;strafe_left=BTN_TRIGGER_HAPPY7;strafe_right=BTN_TRIGGER_HAPPY8;fire=BTN_TRIGGER_HAPPY5;use=BTN_TRIGGER_HAPPY6;start=BTN_TRIGGER_HAPPY9;coin=BTN_TRIGGER_HAPPY10;look_up=BTN_GEAR_UP;look_down=BTN_GEAR_DOWN;"
	svc=$(awk -v s="[device \"usb-$port\"]" '$0 == s { on = 1; next } /^\[/ { on = 0 }
		on && $1 == "service" { print }' "$f" 2>/dev/null)
	meta=$(stat -c '%U %a' "$f" 2>&1)
	# SERVICE was skipped: it keeps what the pad had, the generic gamepad
	# profile's empty list (a cabinet's service switch is its own); so do
	# LOOK UP and LOOK DOWN, the profile's second stick (BTN_GEAR_*).
	check wizard-saved "$f ($meta), section usb-$port: ${got:-none}; skipped: '$svc'" \
		sh -c "[ '$got' = '$want' ] && [ '$svc' = 'service =' ] && [ '$meta' = 'arcaded 600' ] && [ ! -e $f.tmp ]"
	# The new bindings after a restart, and no second wizard.
	t_r=$(now)
	systemctl restart "$U"
	pid=$(prop MainPID)
	jn=$(hidraw_on 0)
	"$G" waitfd "$pid" "$jn" 20 > /dev/null || fail wizard-after-restart "the restarted daemon did not open $jn"
	joy "$hg" "$JOY_IDLE"
	sleep 0.3
	pad_tap "$hg" 5 200
	sleep 0.5
	j=$(log_since "$t_r")
	echo "$j" > "$R/wizard-restart-journal.txt"
	fire=$(echo "$j" | grep -c -F "arcaded: input: hid usb-$port BTN_TRIGGER_HAPPY5 down -> fire")
	again=$(echo "$j" | grep -c 'input wizard: started')
	check wizard-after-restart "after a restart button 5 of usb-$port logged '-> fire' $fire time(s); the wizard started $again time(s)" \
		[ "$fire" = 1 -a "$again" = 0 ]
	joy_unplug arcpad
}
# Makes gadget $2 with $1 (joy_gadget or pad_gadget), plugs it into
# dummy_udc.0 and waits until the daemon ($pid) has its hidraw node open.
# Sets hg (the gadget-side node) and t_plug (when it was plugged); on
# failure reports FAIL $3 with the reason, unplugs it and returns 1.
gadget_up() {
	if ! err=$($1 "$2"); then
		fail "$3" "$err"
		return 1
	fi
	hg=$(hidg_of "$2")
	t_plug=$(now)
	if ! err=$(joy_attach "$2" 0); then
		fail "$3" "$err"
		joy_unplug "$2"
		return 1
	fi
}
all_since() {
	journalctl -o short-monotonic --no-pager -q |
		sed -n 's/^\[ *\([0-9]*\.[0-9]*\)\] [^ ]* \(.*\)$/\1 \2/p' |
		awk -v t="$1" '$1 + 0 >= t + 0'
}

# Nothing held: the daemon's SIGUSR1 summary names the actions its
# controls hold now ("none", or e.g. "fire (1), turn_left (1)"); check $1
# passes when it says none. The screens taken after it are compared on the
# host as well, but the game moves by itself (woken enemies, a death), so
# the daemon's own count is what a stuck control cannot hide from.
nothing_held() { # check name
	t_nh=$(now)
	systemctl kill --kill-whom=main -s SIGUSR1 "$U"
	held=""
	for _ in 1 2 3 4 5 6 7 8 9 10; do
		sleep 0.3
		held=$(log_since "$t_nh" | grep -m 1 -F "summary: actions held: " | sed 's/.*summary: actions held: //')
		[ -n "$held" ] && break
	done
	check "$1" "after the unplugs the daemon's summary says: actions held: ${held:-(no summary line)}" \
		[ "$held" = none ]
}

# Five screendumps $1-1 .. $1-5, a second apart, for the host's
# no-stuck-input check (tests/vm/run.sh still_pair): a held turn or move
# changes every pair; what the game does by itself (the player killed by
# woken enemies, respawned) may change some, so five give it four pairs. A
# game over would move every pair (the attract demo plays): zz-vm.ini's
# nine lives keep the game going through the phases that check this.
still_shots() { # prefix
	for k in 1 2 3 4 5; do
		sleep 1
		shot "$1-$k"
	done
}

# Median and max of stage $1 ("closed", "node", "udev", "open") over the
# lines of a vm_guest replug output in $R/hid-replug.txt (or file $2).
stage() {
	sed -n "s/^plug [0-9]* .*$1 \([-0-9.]*\).*/\1/p" "${2:-$R/hid-replug.txt}" | sort -n |
		awk '{ v[++n] = $1 } END { if (n) printf "%.3f s (max %.3f)", v[int((n + 1) / 2)], v[n] }'
}

# The game is being played: coin and start on the joystick are logged and
# counted (a start during play starts nothing), the stick turns the view.
phase_hid() {
	pid=$(prop MainPID)
	gadget_up joy_gadget arcjoy hid-joystick || return
	t_hid=$t_plug
	node=$(hidraw_on 0)
	port=$(port_on 0)
	pass hid-joystick "DragonRise 0079:0006 gadget on dummy_hcd, port $port: the daemon has $node open $(sub "$t_hid" "$(now)") s after the plug"
	policy_probe "$node" "$R/probe-hidraw.txt"
	check hidraw-access "$(stat -c '%A %U %G' "$node") $node; in the unit's cgroup, as root and as arcaded: $(tr '\n' ';' < "$R/probe-hidraw.txt")" \
		sh -c "! grep -q WANTED '$R/probe-hidraw.txt'"
	# The stick at rest first: an axis gives directions only once seen
	# inside its deadzone.
	joy "$hg" "$JOY_IDLE"
	sleep 0.5
	shot hid-before
	joy "$hg" "$JOY_COIN" && sleep 0.2 && joy "$hg" "$JOY_IDLE"
	sleep 0.3
	joy "$hg" "$JOY_START" && sleep 0.2 && joy "$hg" "$JOY_IDLE"
	sleep 0.3
	coins=$((coins + 1))
	joy "$hg" "$JOY_LEFT" && sleep 1 && joy "$hg" "$JOY_IDLE"
	sleep 0.5
	shot hid-turned
	# Released: the view must stay still.
	sleep 1
	shot hid-still-1
	sleep 1
	shot hid-still-2
	journal=$(log_since "$t_hid")
	echo "$journal" > "$R/hid-journal.txt"
	prof=$(echo "$journal" | grep -m 1 'input hid: .*: profile ' | sed 's/^.*arcaded: //')
	check hid-profile "${prof:-no profile line}" \
		sh -c "echo '$prof' | grep -q '(0079:0006, port $port, .*: profile DragonRise Zero Delay encoder$'"
	missing=""
	for want in "BTN_TRIGGER_HAPPY9 down -> coin" "BTN_TRIGGER_HAPPY9 up -> coin" \
		"BTN_TRIGGER_HAPPY10 down -> start" "BTN_TRIGGER_HAPPY10 up -> start" \
		"BTN_DPAD_LEFT down -> turn_left" "BTN_DPAD_LEFT up -> turn_left"; do
		echo "$journal" | grep -q -F "arcaded: input: hid usb-$port $want" ||
			missing="$missing '$want'"
	done
	check hid-controls "input.log lines for the gadget (usb-$port): coin, start and the stick left, each down and up;${missing:+ missing:$missing}" \
		[ -z "$missing" ]
	# Latency samples (phase_latency): 40 presses of start, which does
	# nothing during play (fire would wake enemies it hits, and the GPIO
	# phase needs a still picture).
	for i in $(seq 40); do
		"$G" hidtap "$hg" "$JOY_START" "$JOY_IDLE" 60 && sleep 0.06
	done
	joy_unplug arcjoy
}

# --- GPIO: a bouncing coin switch, a start button and a coin meter ----------
# A gpio-sim chip labelled arcaded-vm (8 lines) is what the VM's input.gpio
# names (tests/vm/arcaded-vm.ini): line 0 coin, 1 start, 3 fire, 2 the
# meter output. Inputs are active low with the pull-up the daemon requests; the
# test pulls a line down (pressed) and up (released) through sysfs.
GPIO_SIM=/sys/kernel/config/gpio-sim/arcvm
gpio_sim_module() {
	[ -d /sys/kernel/config/gpio-sim ] && return 0
	[ -e "$S/modules/gpio-sim-oot.ko" ] || return 1
	insmod "$S/modules/gpio-sim-oot.ko"
}
phase_gpio() {
	pid=$(prop MainPID)
	if ! gpio_sim_module; then
		fail gpio-chip "no gpio-sim module (tests/vm/gpio-sim.sh)"
		return
	fi
	mkdir -p "$GPIO_SIM/bank0"
	echo 8 > "$GPIO_SIM/bank0/num_lines"
	echo arcaded-vm > "$GPIO_SIM/bank0/label"
	t_gpio=$(now)
	echo 1 > "$GPIO_SIM/live"
	chip=$(cat "$GPIO_SIM/bank0/chip_name")
	gd=/sys/devices/platform/$(cat "$GPIO_SIM/dev_name")/$chip
	echo pull-up > "$gd/sim_gpio0/pull"
	echo pull-up > "$gd/sim_gpio1/pull"
	echo pull-up > "$gd/sim_gpio3/pull"
	# The udev rules give group arcaded the chip node.
	grp() { [ "$(stat -c %G "/dev/$chip" 2>/dev/null)" = arcaded ]; }
	wait_until 10 grp
	policy_probe "/dev/$chip" "$R/probe-gpio.txt"
	check gpio-access "$(stat -c '%A %U %G' "/dev/$chip") /dev/$chip; in the unit's cgroup, as root and as arcaded: $(tr '\n' ';' < "$R/probe-gpio.txt")" \
		sh -c "! grep -q WANTED '$R/probe-gpio.txt'"
	if took=$("$G" waitfd "$pid" "/dev/$chip" 15); then
		pass gpio-chip "gpio-sim chip $chip (label arcaded-vm): the daemon has /dev/$chip open $took s after it went live"
	else
		fail gpio-chip "the daemon did not open /dev/$chip within 15 s: $(log_since "$t_gpio" | grep 'input gpio' | tail -n 1)"
		return
	fi
	sleep 0.5
	# The meter line polled every millisecond while the coin drops: a
	# switch that bounces (five level changes back to back), closes for
	# 50 ms, and bounces again as it opens. One coin. The switch and the
	# meter stand in for hardware, whose timing no scheduler bends: they
	# run as real-time tasks, or a busy daemon (nice -10 on both vCPUs)
	# spaces the "back to back" writes a scheduler slice apart, and
	# edges 5 ms apart are presses, not bounce (input/deb.h).
	rm -f "$R/meter.txt" "$R/meter.txt.ready"
	chrt -f 20 "$G" meter "$gd/sim_gpio2/value" 3 "$R/meter.txt" &
	mpid=$!
	ready() { [ -e "$R/meter.txt.ready" ]; }
	wait_until 5 ready
	chrt -f 20 "$G" pulls "$gd/sim_gpio0" d u d u d u d:50 u d u d u > "$R/gpio-coin.txt" 2>&1
	wait "$mpid"
	# Start: a clean 100 ms press.
	chrt -f 20 "$G" pulls "$gd/sim_gpio1" d:100 u > "$R/gpio-start.txt" 2>&1
	sleep 0.5
	journal=$(log_since "$t_gpio")
	echo "$journal" > "$R/gpio-journal.txt"
	ncoin=$(echo "$journal" | grep -c -F 'arcaded: input: gpio - KEY_5 down -> coin')
	nstart=$(echo "$journal" | grep -c -F 'arcaded: input: gpio - KEY_1 down -> start')
	bounce=$(sed -n 's/^steps \([0-9]*\) total \(.*\)$/\1 writes in \2/p' "$R/gpio-coin.txt")
	held=$(sed -n 's/^hold 6 //p' "$R/gpio-coin.txt")
	apart=$(sed -n 's/^apart \([0-9.]*\) ms$/\1/p' "$R/gpio-coin.txt")
	figure "gpio coin with bounce: 12 sysfs writes, $bounce, held $held, bounce edges at most ${apart:-?} ms apart"
	rises=$(sed -n 's/^rises \([0-9]*\) .*/\1/p' "$R/meter.txt")
	polls=$(sed -n 's/^rises [0-9]* polls \(.*\)$/\1/p' "$R/meter.txt")
	pulses=$(sed -n 's/^pulse //p' "$R/meter.txt" | tr '\n' ' ')
	figure "gpio meter: ${rises:-?} pulse(s) of ${pulses:-none}(polls $polls)"
	# Judged only when the bounce was one: its edges closer than the
	# 5 ms hold-off. Otherwise the writes were separate presses and no
	# count is wrong; both checks are skipped (counted as skipped), and
	# the books must hold what the meter counted.
	if awk -v a="${apart:-99}" 'BEGIN { exit !(a < 5) }'; then
		coins=$((coins + 1))
		check gpio-coin-debounced "a coin switch bouncing 5 times each way around a $held closure ($bounce, bounce edges at most $apart ms apart): the daemon logged $ncoin coin press(es)" \
			[ "$ncoin" = 1 ]
		check gpio-meter "the meter line $chip:2 rose ${rises:-?} time(s) in 3 s around the coin (pulses: ${pulses:-none}; polls $polls)" \
			[ "${rises:-0}" = 1 ]
	else
		coins=$((coins + ${rises:-0}))
		for n in gpio-coin-debounced gpio-meter; do
			echo "SKIP $n: the bounce's writes were ${apart:-?} ms apart, not closer than the 5 ms hold-off: separate presses, not bounce ($ncoin press(es), ${rises:-?} meter pulse(s))" >> "$R/results.txt"
		done
	fi
	check gpio-start "a clean 100 ms press on the start line: the daemon logged $nstart start press(es)" \
		[ "$nstart" = 1 ]
	# The fire line changes the picture (the game is in play, still: two
	# screendumps 1 s apart are equal first; firing uses up ammunition,
	# which the HUD shows), and gives latency samples (phase_latency): 40
	# presses.
	shot gpio-still-1
	sleep 1
	shot gpio-still-2
	"$G" pulls "$gd/sim_gpio3" d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 d:60 u:60 > /dev/null 2>&1
	sleep 0.5
	shot gpio-fired
}

# --- input-to-present latency per kind of input ----------------------------
# After the HID and GPIO phases: the daemon prints its summary on SIGUSR1.
phase_latency() {
	t_lat=$(now)
	systemctl kill --kill-whom=main -s SIGUSR1 "$U"
	sleep 1
	journal=$(log_since "$t_lat")
	missing=""
	for b in "" " (evdev)" " (hid)" " (gpio)"; do
		l=$(echo "$journal" | grep -m 1 -F "summary: input-to-present latency$b " | sed 's/.*summary: //')
		if [ -n "$l" ]; then
			figure "$l"
		elif [ -n "$b" ]; then
			missing="$missing$b"
		fi
	done
	check latency-per-backend "SIGUSR1 summary has the input-to-present latency of the HID and GPIO input${missing:+; missing:$missing}" \
		sh -c "! echo '$missing' | grep -q -e hid -e gpio"
}

# --- the joystick unplugged with a button held, 20 times --------------------
phase_hid_replug() {
	pid=$(prop MainPID)
	gadget_up joy_gadget arcjoy hid-replug || return
	t_rp=$t_plug
	port=$(port_on 0)
	# Each cycle: the stick at rest (a direction needs it seen at rest),
	# then fire and left held; 0.3 s later the plug is pulled.
	"$G" replug "$pid" hidraw "$GADGETS/arcjoy" dummy_udc.0 "$hg" 20 300 "$JOY_IDLE" \
		"$JOY_FIRE_LEFT" > "$R/hid-replug.txt" 2>&1
	rrc=$?
	i=$(grep -c '^plug [0-9]* closed' "$R/hid-replug.txt")
	why=""
	[ "$rrc" = 0 ] || why=$(tail -n 1 "$R/hid-replug.txt")
	# Every release so far came from an unplug: no report released fire.
	t_rp_end=$(now)
	joy "$hg" "$JOY_IDLE"
	journal=$(all_since "$t_rp")
	echo "$journal" > "$R/hid-replug-journal.txt"
	held=$(echo "$journal" | awk -v e="$t_rp_end" '$1 + 0 <= e + 0')
	# Re-attach: the kernel's "new ... USB device" on the gadget's bus to
	# the daemon's "attached" line.
	times=$(echo "$held" | awk -v bus="${port%%-*}" '
		$0 ~ "kernel: usb " bus "-1: new .* USB device" { plug = $1 }
		index($0, "input hid: attached") && index($0, "(0079:0006,") && plug {
			printf "%.2f ", $1 - plug; plug = 0 }')
	stats=$(echo "$times" | tr ' ' '\n' | grep . | sort -n | awk '{ v[++n] = $1 }
		END { if (n) printf "min %.2f median %.2f max %.2f s over %d plugs", v[1], v[int((n + 1) / 2)], v[n], n }')
	maxt=$(echo "$times" | tr ' ' '\n' | grep . | sort -n | tail -n 1)
	nplug=$(echo "$times" | wc -w)
	gone=$(echo "$held" | grep -c '0079:0006.* went away; its controls are released')
	upf=$(echo "$held" | grep -c -F "arcaded: input: hid usb-$port BTN_TRIGGER_HAPPY1 up -> fire")
	upl=$(echo "$held" | grep -c -F "arcaded: input: hid usb-$port BTN_DPAD_LEFT up -> turn_left")
	figure "hid replug: DragonRise joystick plugged (kernel enumerates it) to the daemon's attached line, per plug: $times s ($stats)"
	figure "hid replug, medians over $i plugs: UDC bound to hidraw node $(stage node), node to udev done with it (its ctime) $(stage udev), node to the daemon having it open $(stage open); UDC unbound to the daemon closing it $(stage closed)"
	check hid-replug-cycles "$i unplugs with fire and left held${why:+ ($why)}; the daemon logged $gone 'went away; its controls are released', $upf 'BTN_TRIGGER_HAPPY1 up -> fire' and $upl 'BTN_DPAD_LEFT up -> turn_left' lines, and attached the device $nplug time(s); main PID $pid -> $(prop MainPID)" \
		[ -z "$why" -a "$gone" = 20 -a "$upf" = 20 -a "$upl" = 20 -a "$nplug" = 21 -a "$(prop MainPID)" = "$pid" ]
	# The whole span includes the emulated kernel's enumeration (about
	# 0.5 s under TCG before the hidraw node exists) and udev's work: it
	# is reported, and every plug must be back; the daemon's own share
	# below is what the 500 ms limit is asserted on.
	check hid-replug-reattach "every plug attached again: $stats (the kernel's and udev's time included; not limited)" \
		[ "$nplug" = 21 ]
	# The daemon's own share: from udev's last change of the new node (the
	# earliest the service's user may open it) to the daemon having it open.
	react=$(awk '/^plug [0-9]+ closed/ { print $10 - $8 }' "$R/hid-replug.txt" | sort -n |
		awk '{ v[++n] = $1 } END { if (n) printf "median %.3f max %.3f s over %d plugs", v[int((n + 1) / 2)], v[n], n }')
	# Limits: the median within 0.5 s, and every plug within 1 s, the
	# daemon's periodic retry: each was taken on its hotplug notice, not
	# found by the retry (a loaded host's TCG guest stretches single plugs
	# past 0.5 s; the median and the retry bound are what it cannot fake).
	check hid-replug-daemon-reattach "udev done with the new hidraw node (its ctime) to the daemon having it open: ${react:-no plugs} (limits: median 0.5 s, each under 1 s)" \
		sh -c "echo '$react' | awk '{ exit !(\$7 == 20 && \$2 <= 0.5 && \$4 < 1.0) }'"
	# Dropped: the gadget unbound to the daemon having closed the node (its
	# controls are released in the same tick).
	drop=$(awk '/^plug [0-9]+ closed/ { print $4 }' "$R/hid-replug.txt" | sort -n |
		awk '{ v[++n] = $1 } END { if (n) printf "median %.3f max %.3f s over %d plugs", v[int((n + 1) / 2)], v[n], n }')
	check hid-replug-drop "UDC unbound to the daemon having closed the node, its controls released: ${drop:-no plugs} (limits: median 0.5 s, each under 1 s)" \
		sh -c "echo '$drop' | awk '{ exit !(\$7 == 20 && \$2 <= 0.5 && \$4 < 1.0) }'"
	# Nothing held now: as for the keyboard's replugs above.
	nothing_held hid-replug-nothing-held
	still_shots hid-replug-still
	joy_unplug arcjoy
}

# --- two identical joysticks on two ports keep their bindings ---------------
# Same VID:PID, strings and serial on dummy_udc.0 and dummy_udc.1; bindings
# by port give button 1 fire on one and use on the other. The daemon opens
# both with input.hid = auto. Checked, then again after a restart with the
# plug order reversed (the hidraw numbers swap).
twin_press() { # button 1 pressed and released on A, then on B
	joy "$hga" "$JOY_FIRE" && sleep 0.2 && joy "$hga" "$JOY_IDLE" &&
		sleep 0.2 && joy "$hgb" "$JOY_FIRE" && sleep 0.2 && joy "$hgb" "$JOY_IDLE"
}
# Checks round $1 (described by $2) in the journal text $3: A's button 1
# gave fire and B's use, once each.
twin_check() {
	la=$(echo "$3" | grep -F "arcaded: input: hid usb-$pa BTN_TRIGGER_HAPPY1 down" | sed 's/.*arcaded: input: //' | tr '\n' ';')
	lb=$(echo "$3" | grep -F "arcaded: input: hid usb-$pb BTN_TRIGGER_HAPPY1 down" | sed 's/.*arcaded: input: //' | tr '\n' ';')
	check "twin-$1" "$2; A (usb-$pa): $la B (usb-$pb): $lb" \
		[ "$la" = "hid usb-$pa BTN_TRIGGER_HAPPY1 down -> fire;" -a \
			"$lb" = "hid usb-$pb BTN_TRIGGER_HAPPY1 down -> use;" ]
}
phase_twin() {
	for gt in arcjoy arcjoy2; do
		if ! err=$(joy_gadget $gt); then
			fail twin-plugged "$err"
			return
		fi
	done
	hga=$(hidg_of arcjoy)
	hgb=$(hidg_of arcjoy2)
	# A first: it gets the lower hidraw number.
	joy_plug arcjoy 0
	wait_until 20 hidraw_on 0 > /dev/null
	joy_plug arcjoy2 1
	both() { hidraw_on 0 > /dev/null && hidraw_on 1 > /dev/null; }
	wait_until 20 both || { fail twin-plugged "the two gadgets did not both get a hidraw node"; return; }
	pa=$(port_on 0)
	pb=$(port_on 1)
	printf '[device "usb-%s"]\nfire = BTN_TRIGGER_HAPPY1\n[device "usb-%s"]\nuse = BTN_TRIGGER_HAPPY1\n' \
		"$pa" "$pb" > /etc/arcaded/vm-twin.bindings
	printf '[input]\nbindings = /etc/arcaded/vm-twin.bindings\n' > /etc/arcaded/zz-vm-twin.ini
	systemctl restart "$U"
	pid=$(prop MainPID)
	na=$(hidraw_on 0)
	nb=$(hidraw_on 1)
	if "$G" waitfd "$pid" "$na" 15 > /dev/null && "$G" waitfd "$pid" "$nb" 15 > /dev/null; then
		pass twin-plugged "two gadgets 0079:0006 serial ZD0001: A on port $pa ($na), B on port $pb ($nb); the restarted daemon (input.hid = auto) has both open"
	else
		fail twin-plugged "the restarted daemon does not have both $na and $nb open"
		return
	fi
	t_tw1=$(now)
	twin_press || fail twin-first "a report was not taken"
	desc1="A on $na, B on $nb"
	# Restart with nothing plugged, then B first: B gets the lower hidraw
	# number and the daemon's first HID slot.
	joy_unplug arcjoy
	joy_unplug arcjoy2
	gone() { ! hidraw_on 0 > /dev/null && ! hidraw_on 1 > /dev/null; }
	wait_until 10 gone
	systemctl restart "$U"
	pid=$(prop MainPID)
	if ! err=$(joy_attach arcjoy2 1); then
		fail twin-reversed "B: $err"
		return
	fi
	if ! err=$(joy_attach arcjoy 0); then
		fail twin-reversed "A: $err"
		return
	fi
	na=$(hidraw_on 0)
	nb=$(hidraw_on 1)
	t_tw2=$(now)
	twin_press || fail twin-reversed "a report was not taken"
	sleep 0.5
	journal=$(log_since "$t_tw1")
	echo "$journal" > "$R/twin-journal.txt"
	twin_check first "bindings by port give A's button 1 fire and B's use; $desc1" \
		"$(echo "$journal" | awk -v e="$t_tw2" '$1 + 0 < e + 0')"
	# The test needs the numbers swapped: B now has the lower one.
	twin_check reversed "after a restart with B plugged first: A on $na, B on $nb$([ "${nb#/dev/hidraw}" -lt "${na#/dev/hidraw}" ] || echo ' (NOT swapped: the plug order did not change the numbering)')" \
		"$( [ "${nb#/dev/hidraw}" -lt "${na#/dev/hidraw}" ] && echo "$journal" | awk -v s="$t_tw2" '$1 + 0 >= s + 0')"
	joy_unplug arcjoy
	joy_unplug arcjoy2
	rm -f /etc/arcaded/zz-vm-twin.ini /etc/arcaded/vm-twin.bindings
}

# --- two players: player 2's controls on a second USB device ----------------
# A two-player game (issue 16 item 5) played on two HID gadgets: the
# DragonRise joystick on dummy_udc.0 (its profile binds player 1) and the
# USB keyboard on dummy_udc.1, whose keys the default bindings give MAME's
# player 2 meanings (KEY_2 the 2P start, KEY_G p2_turn_right: a key no
# player 1 action has, so it can only act through player 2's controls).
# With idle_out = life (a drop-in read after zz-vm.ini) player 1, who
# turns once and then touches nothing, loses a life 30 s of game time
# later; player 2 then comes up at the stage's start. Both start views
# are references the host renders headless (tests/vm/run.sh: ref-twop-p1,
# ref-twop-p2; still with the stage clock off and no input, and they
# differ: the HUD marks the player up). While player 2 is up, the
# joystick's stick must not move the view (the screen still matches
# player 2's reference) and the keyboard's G must turn it. The host
# judges the screens (run.sh: twop-*); the guest checks that the daemon
# read every control of both devices.
phase_twop() {
	if ! err=$(joy_gadget arcjoy) || ! err=$(gadget_modules); then
		fail twop-devices "$err"
		return
	fi
	kbd_gadget
	printf '[game]\nidle_out = life\n' > /etc/arcaded/zz-vmp2.ini
	systemctl restart "$U"
	pid=$(prop MainPID)
	t_tp=$(now)
	ja=""
	if err=$(joy_attach arcjoy 0); then
		ja=$(hidraw_on 0)
	fi
	echo dummy_udc.1 > "$GADGET/UDC"
	kb=$("$G" waitdev "$pid" "$GADGET_NAME" 20)
	if [ -z "$ja" ] || [ -z "$kb" ]; then
		fail twop-devices "joystick on dummy_udc.0: ${ja:-$err}; keyboard on dummy_udc.1: ${kb:-not opened by the daemon within 20 s}"
		joy_unplug arcjoy
		unplug
		rm -f /etc/arcaded/zz-vmp2.ini
		return
	fi
	pj=$(port_on 0)
	pass twop-devices "the restarted daemon (game.idle_out = life) has the joystick (usb-$pj, $ja) and the USB keyboard on dummy_udc.1 (${kb% *}) open"
	hg=$(hidg_of arcjoy)
	joy "$hg" "$JOY_IDLE"
	sleep 0.5
	# two coins on the joystick, the 2P start on the keyboard
	for _ in 1 2; do
		joy "$hg" "$JOY_COIN" && sleep 0.2 && joy "$hg" "$JOY_IDLE"
		sleep 0.3
	done
	coins=$((coins + 2))
	hid_key 1f
	sleep 0.2
	hid_key 00
	plays=$((plays + 2))
	# the "PLAYER 1" page (2.5 s of game time), then player 1's start
	# view; player 1 turns with the stick
	shot_match twop-p1-start 60 twop-p1 ||
		fail twop-p1-up "the 2P start did not lead to the stage's start view within 60 s"
	joy "$hg" "$JOY_LEFT" && sleep 1 && joy "$hg" "$JOY_IDLE"
	sleep 0.5
	shot twop-p1-turned
	# 30 s of game time without input, the death, the "PLAYER 2" page:
	# then the start view again
	t_p2=$(now)
	if shot_match twop-p2-start 240 twop-p2; then
		pass twop-p2-up "player 2's start view $(sub "$t_p2" "$(now)") s after player 1's last input (idle out, then player 2's turn)"
	else
		fail twop-p2-up "the screen never showed player 2's start view within 240 s after player 1's last input"
	fi
	t_up=$(now)
	# player 1's stick while player 2 is up: the view must not move
	joy "$hg" "$JOY_LEFT" && sleep 1 && joy "$hg" "$JOY_IDLE"
	sleep 0.5
	shot twop-p1-stick
	# player 2's key on the second device: the view turns
	hid_key 0a
	sleep 1
	hid_key 00
	sleep 0.5
	shot twop-p2-turned
	journal=$(log_since "$t_tp")
	echo "$journal" > "$R/twop-journal.txt"
	upj=$(echo "$journal" | awk -v s="$t_up" '$1 + 0 >= s + 0')
	missing=""
	for want in "hid usb-$pj BTN_TRIGGER_HAPPY9 down -> coin" "evdev usb-2-1 KEY_2 down -> start2" \
		"hid usb-$pj BTN_DPAD_LEFT down -> turn_left"; do
		echo "$journal" | grep -q -F "arcaded: input: $want" || missing="$missing '$want'"
	done
	# while player 2 was up: both devices' controls were read
	for want in "hid usb-$pj BTN_DPAD_LEFT down -> turn_left" "evdev usb-2-1 KEY_G down -> p2_turn_right"; do
		echo "$upj" | grep -q -F "arcaded: input: $want" || missing="$missing '$want' (player 2 up)"
	done
	check twop-controls "input.log lines: coins and the stick from the joystick (usb-$pj), 2P start and G (p2_turn_right) from the keyboard (usb-2-1), the stick and G again while player 2 was up;${missing:+ missing:$missing}" \
		[ -z "$missing" ]
	joy_unplug arcjoy
	unplug
	rm -f /etc/arcaded/zz-vmp2.ini
}

# --- KMS: a VT switch away and back -----------------------------------------
# The daemon holds its terminal in VT_PROCESS mode: a switch away waits
# until it has dropped DRM master (then fbcon can set its own mode and show
# the other terminal's text), a switch back gives it the master again and
# it sets its mode with the newest frame.
phase_vt() {
	pid=$(prop MainPID)
	t_vt=$(now)
	printf '\n\n   arcaded VM test: virtual terminal 2\n' > /dev/tty2
	if sw=$("$G" chvt 2 10); then
		pass vt-switch-away "$sw: the daemon let go of the screen"
	else
		fail vt-switch-away "$sw: the switch did not complete within 10 s"
	fi
	back=${sw#from }
	back=${back%% *}
	sleep 1
	shot vt-away
	if sw=$("$G" chvt "${back:-1}" 10); then
		pass vt-switch-back "$sw"
	else
		fail vt-switch-back "$sw"
	fi
	shot_match vt-back 30
	t_sum=$(now)
	systemctl kill --kill-whom=main -s SIGUSR1 "$U"
	sleep 1
	st=$(log_since "$t_sum" | grep -m 1 -F 'summary: display: kms' | sed 's/.*summary: display: //')
	figure "after the VT switches: $st"
	check vt-master-handover "one switch away and back, the daemon's counters: $st; main PID $pid -> $(prop MainPID)" \
		sh -c "echo '$st' | grep -q 'VT switches 1 away 1 back 0 failed' && [ '$(prop MainPID)' = '$pid' ]"
}

# --- KMS: page flips ---------------------------------------------------------
# The game has run for a while (attract, play, the VT switches). From the
# SIGUSR1 summary: the kernel never refused a flip as busy (refusals are
# counted by the daemon: a flip issued while one was pending), every flip
# completed, and the present-to-flip times are figures.
phase_flips() {
	sleep 5
	t_fl=$(now)
	systemctl kill --kill-whom=main -s SIGUSR1 "$U"
	sleep 1
	journal=$(log_since "$t_fl")
	echo "$journal" > "$R/flips-journal.txt"
	st=$(echo "$journal" | grep -m 1 -F 'summary: display: kms' | sed 's/.*summary: display: //')
	fl=$(echo "$journal" | grep -m 1 -F 'summary: present-to-flip ' | sed 's/.*summary: //')
	sm=$(echo "$journal" | grep -m 1 -F 'frames late' | sed 's/.*summary: //')
	figure "$fl"
	figure "$st"
	figure "$sm"
	n() { echo "$st" | sed -n "s/.* \([0-9]*\) $1.*/\1/p"; }
	issued=$(echo "$st" | sed -n 's/^kms [^:]*: \([0-9]*\) flips issued.*/\1/p')
	done_=$(n 'completed')
	busy=$(n 'refused as busy')
	overdue=$(n 'overdue (')
	check flips-never-while-pending "the kernel refused ${busy:-?} flip(s) as busy (issued while one was pending) of ${issued:-?}; ${done_:-?} completed, ${overdue:-?} overdue" \
		sh -c "[ '${busy:-x}' = 0 ] && [ '${issued:-0}' -ge 100 ] && [ '${overdue:-x}' = 0 ] && [ \$((${issued:-0} - ${done_:-0})) -le 1 ]"
	check present-to-flip "${fl:-no present-to-flip line in the summary}" \
		sh -c "echo '$fl' | grep -q '^present-to-flip p50 '"
}

# --- no framebuffer at boot: the daemon waits for it, the boot does not ------
# The latefb boot blacklists bochs: there is no /dev/fb0 until the guest
# loads the driver. The daemon must run (the game goes on unseen), say
# why in its status and as a warning in the journal, not hold the boot
# (multi-user.target reached while arcaded.service is still starting: its
# READY=1 waits for a frame on a display), and ping the watchdog.
phase_nofb() {
	no_display() { case "$(prop StatusText)" in "no display: "*) return 0 ;; esac; return 1; }
	wait_until 120 no_display
	st=$(prop StatusText)
	act=$(prop ActiveState)
	pid=$(prop MainPID)
	check nofb-status "arcaded.service $act with status '$st'" \
		sh -c "[ '$act' = activating ] && echo '$st' | grep -q '^no display: .*fbdev: /dev/fb0: No such file or directory'"
	mu_up() { [ "$(systemctl is-active multi-user.target)" = active ]; }
	wait_until 120 mu_up
	mu=$(systemctl is-active multi-user.target)
	act=$(prop ActiveState)
	check nofb-boot-not-held "multi-user.target $mu while arcaded.service is $act (pid $pid, no display yet)" \
		[ "$mu" = active -a "$act" = activating -a "$(prop MainPID)" = "$pid" ]
	wl=$(journalctl -u "$U" -t arcaded -p warning -o cat --no-pager -q | grep -m 1 'arcaded: display: none: ')
	check nofb-journal "the journal's warning: ${wl:-none}" [ -n "$wl" ]
	w1=$(prop WatchdogTimestampMonotonic)
	sleep 3
	w2=$(prop WatchdogTimestampMonotonic)
	check nofb-watchdog "the main loop's watchdog pings reach systemd while it starts (WatchdogTimestampMonotonic $w1 then $w2)" \
		sh -c "[ '$w1' -gt 0 ] && [ '$w2' -gt '$w1' ]"
}

# Then bochs is loaded by hand: the daemon must take /dev/fb0 when it
# appears (a hotplug notice, or its retry every second), send READY=1 after
# its first frame there, and say so in its status; same process throughout.
phase_latefb() {
	pid=$(prop MainPID)
	st0=$(prop StatusText)
	t_mod=$(now)
	echo "vm: loading bochs" > /dev/kmsg
	modprobe bochs || { fail late-fb "modprobe bochs failed"; return; }
	has_fb() { [ -e /dev/fb0 ]; }
	wait_until 60 has_fb || { fail late-fb "no /dev/fb0 60 s after modprobe bochs"; return; }
	t_node=$(now)
	if ! took=$("$G" waitfd "$pid" /dev/fb0 30); then
		fail late-fb "/dev/fb0 appeared; 30 s later the daemon still does not have it open: $(log_since "$t_mod" | grep 'arcaded: display' | tail -n 1 | cut -d' ' -f2-)"
		return
	fi
	up() { [ "$(prop ActiveState)" = active ]; }
	wait_until 60 up
	t_up=$(now)
	st=$(prop StatusText)
	act=$(prop ActiveState)
	journal=$(all_since "$t_mod")
	echo "$journal" > "$R/late-fb-journal.txt"
	took_line=$(echo "$journal" | grep -m 1 'arcaded: display: fbdev /dev/fb0 .*(it was missing: ' | cut -d' ' -f2-)
	# From the journal: the kernel's line for the new framebuffer, the
	# daemon's line taking it, systemd's for READY=1.
	t_kfb=$(first 'kernel: .*fb0: .*frame buffer device' "$journal")
	t_take=$(first 'arcaded: display: fbdev /dev/fb0 .*(it was missing: ' "$journal")
	t_rdy=$(first 'Started arcaded' "$journal")
	[ -n "$t_kfb" ] && [ -n "$t_take" ] && [ -n "$t_rdy" ] &&
		figure "display re-acquired: the kernel's fb0 line to the daemon taking it $(sub "$t_kfb" "$t_take") s, to READY=1 $(sub "$t_kfb" "$t_rdy") s (journal times)"
	figure "display re-acquired, as the guest polled: modprobe bochs to /dev/fb0 $(sub "$t_mod" "$t_node") s; /dev/fb0 to the daemon having it open $took s; to the unit active $(sub "$t_node" "$t_up") s"
	check late-fb "the daemon (pid $pid, then $(prop MainPID)) opened /dev/fb0 $took s after it appeared and became $act; status '$st0' -> '$st'; journal: ${took_line:-no acquisition line}" \
		sh -c "[ '$act' = active ] && [ '$(prop MainPID)' = '$pid' ] && [ '$st' = running ] && [ -n '$took_line' ]"
	sleep 1
	shot late-screen
}

# --- libusb under the real unit: a USB plug first noticed by its callback ----
# The unit lets libusb hear udev (AF_NETLINK, the host's network namespace,
# no IP). A USB keyboard gadget is plugged: the first hotplug notice the
# daemon logs for it (input.log is on, so node notices are logged too) must
# be libusb's callback; the time from the kernel's enumeration line to it
# is a figure.
phase_libusb() {
	pid=$(prop MainPID)
	src=$(log_since 0 | grep 'arcaded: input hotplug: inotify /' | tail -n 1 | sed 's/.*arcaded: input hotplug: //')
	check libusb-available "the daemon's hotplug sources under the unit: ${src:-none logged}" \
		sh -c "echo '$src' | grep -q 'libusb hotplug' && ! echo '$src' | grep -q 'not available'"
	if ! err=$(gadget_modules); then
		fail libusb-first-notice "$err"
		return
	fi
	kbd_gadget
	t_usb=$(now)
	if ! got=$(plug_attach); then
		fail libusb-first-notice "the daemon did not take the USB keyboard gadget: $got"
		unplug
		return
	fi
	sleep 0.5
	journal=$(all_since "$t_usb")
	echo "$journal" > "$R/libusb-journal.txt"
	t_k=$(first 'kernel: usb 1-1: new .* USB device' "$journal")
	t_cb=$(first 'arcaded: input hotplug: libusb: USB device 1209:0001 arrived on port 1-1' "$journal")
	firstn=$(echo "$journal" | grep -m 1 'arcaded: input hotplug: ' | sed 's/.*arcaded: //')
	nodes=$(echo "$journal" | grep -c 'arcaded: input hotplug: inotify: ')
	[ -n "$t_k" ] && [ -n "$t_cb" ] &&
		figure "libusb: the kernel's enumeration (usb 1-1: new ... USB device) to the daemon's libusb callback: $(sub "$t_k" "$t_cb") s"
	check libusb-first-notice "USB keyboard gadget plugged (${got#* } s to the daemon reading it): first notice '$firstn', then $nodes inotify node notice(s); kernel line at ${t_k:-?}, callback at ${t_cb:-?}" \
		sh -c "[ -n '$t_cb' ] && [ -n '$t_k' ] && echo '$firstn' | grep -q '^input hotplug: libusb: USB device 1209:0001 arrived on port 1-1'"
	t_un=$(now)
	unplug
	left() { log_since "$t_un" | grep -q 'arcaded: input hotplug: libusb: USB device 1209:0001 left port 1-1'; }
	wait_until 10 left
	check libusb-departure "the unplug logged as libusb's departure: $(log_since "$t_un" | grep -m 1 'libusb: USB device' | cut -d' ' -f2-)" left
}

# --- --renderer gl under the unit --------------------------------------------
# The shipped unit has MemoryDenyWriteExecute=yes, which llvmpipe's JIT
# cannot live with: the daemon must refuse --renderer gl at start with the
# reason; with the drop-in docs/systemd.md gives, it must draw.
phase_gl() {
	dd=/run/systemd/system/arcaded.service.d
	bin=/usr/local/bin/arcaded
	mkdir -p "$dd"
	printf '[Service]\nExecStart=\nExecStart=%s --renderer gl\n' "$bin" > "$dd/gl.conf"
	systemctl daemon-reload
	t_gl=$(now)
	systemctl restart "$U"
	refused() { log_since "$t_gl" | grep -q 'arcaded: renderer gl .*MemoryDenyWriteExecute=yes'; }
	wait_until 30 refused
	systemctl stop "$U"
	journal=$(log_since "$t_gl")
	echo "$journal" > "$R/gl-refused-journal.txt"
	why=$(echo "$journal" | grep -m 1 'arcaded: renderer gl ' | sed 's/.*arcaded: //')
	code=$(echo "$journal" | grep -c 'status=2/INVALIDARGUMENT\|status=2')
	check gl-refused "under the shipped unit: '${why:-nothing logged}'; exits with status 2 ($code time(s))" \
		sh -c "[ -n '$why' ] && [ '$code' -ge 1 ]"
	# The drop-in of docs/systemd.md.
	printf '[Service]\nExecStart=\nExecStart=%s --renderer gl\nMemoryDenyWriteExecute=no\n' "$bin" > "$dd/gl.conf"
	systemctl daemon-reload
	systemctl reset-failed "$U"
	t_gl2=$(now)
	systemctl start "$U"
	t_gl_up=$(now)
	act=$(prop ActiveState)
	journal=$(log_since "$t_gl2")
	echo "$journal" > "$R/gl-journal.txt"
	name=$(echo "$journal" | grep -m 1 'arcaded: renderer: gl ' | sed 's/.*arcaded: //')
	figure "--renderer gl with the drop-in: start to READY=1 $(sub "$t_gl2" "$t_gl_up") s"
	check gl-drop-in "with MemoryDenyWriteExecute=no: $act, '${name:-no renderer line}'" \
		sh -c "[ '$act' = active ] && echo '$name' | grep -q 'llvmpipe'"
	sleep 2
	shot gl-screen
	rm -f "$dd/gl.conf"
	systemctl daemon-reload
	systemctl restart "$U"
}

# --- log priorities ------------------------------------------------------------
# `journalctl -p warning -u arcaded` must show exactly the daemon's warnings
# and errors: every line it shows is one of those (the patterns below name
# every warning and error the daemon logs in these tests), and every line of
# the daemon's that is one of those has that priority. -t arcaded leaves out
# systemd's own lines about the unit.
WARN_PAT='^arcaded: (display: none: |display: still none: |fault injection: |renderer gl |ARCADED_FAULT=|input [a-z]+: .*; retrying as devices appear|input [a-z]+: .* went away; its controls are released|input hotplug: .*(not available|: No such file)|input [a-z]+: not auto-detected|input [a-z]+: more than|input [a-z]+: profile .*: |input wizard: (not while recording|.*not saved)|no input device configured|render threads: |flight recorder: |.*: not saved: |.*\.ini:[0-9]+: |.*; games are not recorded|.*; using (the )?defaults|.*; starting from zero|.*; using the other layers|.*/recordings: recovered .*-cut\.rec |fatal signal SIG[A-Z]*; the call stack:)'
phase_priorities() {
	all=$(journalctl -u "$U" -t arcaded -o cat --no-pager -q)
	warn=$(journalctl -u "$U" -t arcaded -p warning -o cat --no-pager -q)
	echo "$warn" > "$R/journal-warnings.txt"
	na=$(echo "$all" | grep -c .)
	nw=$(echo "$warn" | grep -c .)
	nw_known=$(echo "$warn" | grep -c -E "$WARN_PAT")
	na_known=$(echo "$all" | grep -c -E "$WARN_PAT")
	odd=$(echo "$warn" | grep -v -E "$WARN_PAT" | head -n 3 | tr '\n' ';')
	info=$(echo "$all" | grep -c -E '^arcaded: (display: fbdev |content: |summary: |input: evdev )')
	info_w=$(echo "$warn" | grep -c -E '^arcaded: (display: fbdev |content: |summary: |input: evdev )')
	check log-priorities "journalctl -p warning shows $nw of the daemon's $na lines: $nw_known of them warnings or errors by their text, which the daemon logged $na_known times in all; $info_w of $info info lines (display, content, summary, key lines)${odd:+; not warnings: $odd}" \
		[ "$nw" -gt 0 -a "$nw" = "$nw_known" -a "$nw" = "$na_known" -a "$info" -gt 0 -a "$info_w" = 0 ]
}

# The device unit tests skip on a machine without uinput, a framebuffer,
# uhid or gpio-sim; here all exist (the daemon is stopped: nothing holds
# them), so nothing may skip.
# UNITS: a name prefix of the tests to run (default all).
unit_tests() {
	if [ -z "${UNITS:-}" ] && [ -e "$S/modules/gpio-sim-oot.ko" ]; then
		gpio_sim_module || fail gpio-sim-module "insmod gpio-sim-oot.ko failed"
	fi
	for t in "$S"/tests/${UNITS:-test_}*; do
		n=${t##*/}
		(cd "$S/repo" && ARCADED_TEST_DEVICES=1 exec "$t") > "$R/$n.log" 2>&1
		rc=$?
		# cmocka pads PASSED and FAILED to two spaces, SKIPPED to one
		sum=$(grep -E '^\[  (PASSED|FAILED|SKIPPED) *\] [0-9]' "$R/$n.log" | tr '\n' ' ')
		check "unit-$n" "exit $rc: $sum" sh -c "[ $rc = 0 ] && ! grep -q '^\[  SKIPPED *\]' '$R/$n.log'"
	done
}

# Runs the phases given, each timed (a figure).
run() {
	for ph in "$@"; do
		case ,$PHASES, in ,,| *,"$ph",*) ;; *)
			echo "SKIP $ph: not in arcaded.phases=$PHASES" >> "$R/results.txt"
			continue ;;
		esac
		tp=$(now)
		$ph
		figure "phase ${ph#phase_}: $(sub "$tp" "$(now)") s"
	done
}

kbd_pid=""
case $BOOT in
fb32)
	run phase_boot phase_input phase_sandbox phase_watchdog phase_hid phase_gpio \
		phase_latency phase_wizard phase_sigterm phase_priorities unit_tests
	;;
fb16)
	run phase_boot phase_input phase_sandbox phase_hotplug phase_hid_replug phase_twin \
		phase_twop phase_sigterm phase_priorities
	;;
latefb)
	run phase_nofb phase_latefb phase_input phase_libusb phase_gl phase_priorities
	;;
kms)
	# phase_input runs phase_vt while the start view is still; phase_sound
	# starts the daemon again after phase_sigterm, for coins in attract
	# mode that leave the other phases' screens and counts alone
	run phase_boot phase_input phase_flips phase_sigterm phase_sound
	UNITS=test_dp_kms
	run unit_tests
	UNITS=test_con
	run unit_tests
	;;
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
