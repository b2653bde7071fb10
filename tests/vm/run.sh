#!/bin/sh
# The appliance tests (make test-vm; docs/vm.md): QEMU boots Debian's kernel
# with this machine's own root read-only over virtio-9p, a tmpfs overlay,
# the project installed as `make install` lays it out, and systemd as PID 1
# running the real arcaded.service on real kernel devices. Boots:
#   fb32    bochs-drm framebuffer, 32 bpp (DRM fbdev emulation): boot time,
#           screen = the daemon's frame, uinput keyboard, unprivileged user
#           and device policy, watchdog restart, a DragonRise USB joystick
#           (HID gadget on dummy_hcd, read through hidraw), GPIO on gpio-sim
#           (bouncing coin, start, coin meter), latency per kind of input,
#           SIGTERM; then the unit tests that need real devices (uinput,
#           fbdev, uhid, gpio-sim);
#   fb16    vesafb, 16 bpp RGB565 (vga=0x317): screen = the daemon's frame;
#           a USB keyboard (HID gadget on dummy_hcd) unplugged and replugged
#           20 times with a key held; the joystick likewise with buttons
#           held; two identical joysticks on two ports keep their bindings
#           across a restart;
#   latefb  no framebuffer driver at boot: the daemon runs unseen, says why
#           (status, journal) and does not hold the boot; then bochs is
#           loaded by hand and the daemon must take the screen (the game's
#           frame after coin and start); a USB gadget plug first noticed
#           by libusb's callback; --renderer gl refused under the unit and
#           drawing with the documented drop-in;
#   kms     virtio-vga (virtio-gpu, a DRM driver with page-flip events) and
#           display.backend = auto, which must take KMS: screen = the
#           daemon's frame, page flips never issued while one is pending
#           (the kernel's EBUSY refusals counted), present-to-flip times,
#           a VT switch away and back (DRM master dropped and taken
#           again), SIGTERM; then the KMS unit tests;
#   units   only the device unit tests (quicker, to debug them).
# Every boot keeps QEMU's PS/2 keyboard: the daemon must take the uinput
# keyboard (an encoder) too, and coin comes from the PS/2 keyboard (QMP
# send-key) while start comes from the encoder. Every boot ends by checking
# that `journalctl -p warning` shows exactly the daemon's warnings and
# errors.
# The guest side is tests/vm/guest.sh; this script drives QEMU, serves the
# guest's screendump requests through QMP and judges the screens.
#
# usage: tests/vm/run.sh [BOOT...]   (default: fb32 fb16 latefb kms)
# Environment: BUILD (build folder, default build); ARCADED_VM_ASAN (a
# sanitizer build folder, e.g. build/asan, whose device unit tests run too);
# ARCADED_VM_CACHE (kernel cache, default
# ${XDG_CACHE_HOME:-$HOME/.cache}/arcaded-vm); ARCADED_VM_KERNEL (kernel
# version instead of linux-image-amd64's); ARCADED_VM_TIMEOUT (seconds per
# boot, default 1200: a guard against a hung guest; an idle
# machine boots and tests each in under 2 minutes, a loaded one can take 5+);
# ARCADED_VM_PHASES (to debug: only these guest phases of each boot,
# comma-separated, e.g. phase_boot,phase_twop; the others and the screens
# they take are counted as skipped, and the run exits 77 when nothing failed).
#
# Exit status: 0 all passed, 1 a failure, 77 skipped (QEMU cannot run here,
# printed loudly; or parts skipped by ARCADED_VM_PHASES).
set -u
cd "$(dirname "$0")/../.."
top=$(pwd)
BUILD=${BUILD:-build}
B=$top/$BUILD/vm
CACHE=${ARCADED_VM_CACHE:-${XDG_CACHE_HOME:-${HOME:-/root}/.cache}/arcaded-vm}
TIMEOUT=${ARCADED_VM_TIMEOUT:-1200}
boots=${*:-fb32 fb16 latefb kms}

skip() {
	echo "################################################################"
	echo "# VM TESTS SKIPPED: $*"
	echo "################################################################"
	exit 77
}
die() {
	echo "vm: FAIL: $*"
	exit 1
}
now() { date +%s.%N; }
# seconds between two timestamps, 2 decimals
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }

if [ "$(id -u)" != 0 ]; then
	# The root is exported through a bind mount in a private mount
	# namespace, and the guest's systemd needs files only root can read.
	if command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
		exec sudo -n -E "$0" "$@"
	fi
	skip "needs root (or password-less sudo) to export the root file system to QEMU"
fi
[ "$(uname -m)" = x86_64 ] || skip "the VM tests boot Debian's amd64 kernel; this is $(uname -m)"
for t in qemu-system-x86_64 unshare cpio depmod apt-get dpkg xz; do
	command -v "$t" >/dev/null || die "$t missing (scripts/setup.sh installs it)"
done
[ -x /bin/busybox ] || die "/bin/busybox missing (package busybox-static; scripts/setup.sh)"
echo quit | qemu-system-x86_64 -machine pc -accel tcg -display none -nodefaults -S \
	-monitor stdio > /dev/null 2>&1 ||
	skip "qemu-system-x86_64 cannot start a TCG machine here"

t_all=$(now)
mkdir -p "$B"
echo "vm: building the daemon, its unit tests and the VM helpers"
make --no-print-directory -s -j"$(nproc)" BUILD="$BUILD" all tests > "$B/build.log" 2>&1 ||
	{ tail -n 30 "$B/build.log"; die "build"; }
CFLAGS="-std=c11 -D_GNU_SOURCE -O2 -g -Wall -Wextra -Werror -Wshadow -Wvla -Wstrict-prototypes -Wmissing-prototypes"
# shellcheck disable=SC2086
cc $CFLAGS $(pkg-config --cflags libevdev zlib) -o "$B/vm_guest" tests/vm/vm_guest.c \
	$(pkg-config --libs libevdev zlib) || die "vm_guest"
# shellcheck disable=SC2086
cc $CFLAGS $(pkg-config --cflags libpng) -o "$B/vm_host" tests/vm/vm_host.c \
	$(pkg-config --libs libpng) || die "vm_host"
H=$B/vm_host

t=$(now)
kdir=$(tests/vm/kernel.sh "$CACHE") || die "kernel"
version=$(cat "$kdir/version")
tests/vm/initramfs.sh "$kdir" "$B/initramfs.cpio" || die "initramfs"
gpio_ko=$(tests/vm/gpio-sim.sh "$kdir") || gpio_ko=""
echo "vm: kernel $version, initramfs ready in $(secs "$t" "$(now)") s"

# The stage: what the guest installs and runs (shared read-only). Outside
# the build folder: the Makefile includes every "*.d" under it, and the
# install tree has directories named so (tmpfiles.d, rules.d).
ST=$(mktemp -d "${TMPDIR:-/tmp}/arcaded-vm-stage.XXXXXX") || die "mktemp"
qpid=""
# On any exit, interrupted too: no QEMU left running, no stage left over.
trap 'if [ -n "$qpid" ]; then kill "$qpid" 2>/dev/null; fi; rm -rf "$ST"' EXIT
trap 'exit 130' INT TERM
mkdir -p "$ST/bin"
make --no-print-directory -s BUILD="$BUILD" install DESTDIR="$ST/destdir" > "$B/install.log" 2>&1 ||
	{ cat "$B/install.log"; die "make install"; }
cp "$B/vm_guest" "$ST/bin/"
# Unit tests that need real devices (they skip on this machine).
mkdir -p "$ST/tests" "$ST/modules"
for t in test_in_evdev test_con test_dp_fbdev test_dp_kms test_in_hid test_in_gpio; do
	[ -x "$BUILD/tests/$t" ] && cp "$BUILD/tests/$t" "$ST/tests/"
done
# The same tests built with ASan and UBSan, when asked for (run_all.sh
# builds them first): ARCADED_VM_ASAN=build/asan.
if [ -n "${ARCADED_VM_ASAN:-}" ]; then
	for t in test_in_evdev test_con test_dp_fbdev test_dp_kms test_in_hid test_in_gpio; do
		[ -x "$ARCADED_VM_ASAN/tests/$t" ] && cp "$ARCADED_VM_ASAN/tests/$t" "$ST/tests/$t-asan"
	done
fi
# They read fixtures by paths relative to the repository root.
mkdir -p "$ST/repo/tests"
cp -r tests/data "$ST/repo/tests/"
cp tests/vm/guest.sh "$ST/guest.sh"
mkdir -p "$ST/overlay/lib/systemd/system"
cp tests/vm/vm-test.service tests/vm/vm-test-nofb.service "$ST/overlay/lib/systemd/system/"
[ -n "$gpio_ko" ] && cp "$gpio_ko" "$ST/modules/"
# The fault-injection switch (off by default) is enabled for the watchdog test.
mkdir -p "$ST/overlay/etc/systemd/system/arcaded.service.d"
cp tests/vm/arcaded-vm.conf "$ST/overlay/etc/systemd/system/arcaded.service.d/vm.conf"
# Settings of the VM tests (input.log on, the GPIO spec), read after the
# installed arcaded.ini.
mkdir -p "$ST/overlay/etc/arcaded"
cp tests/vm/arcaded-vm.ini "$ST/overlay/etc/arcaded/zz-vm.ini"
# Per boot (init copies overlay-BOOT after overlay): fb32 and latefb test
# the fbdev backend on bochs-drm, whose card auto would prefer (KMS).
for b in fb32 latefb; do
	mkdir -p "$ST/overlay-$b/etc/arcaded"
	printf '; VM boot %s tests fbdev (tests/vm/run.sh)\n[display]\nbackend = fbdev\n' "$b" \
		> "$ST/overlay-$b/etc/arcaded/zz-vm-boot.ini"
done

# Reference frames, rendered headless by the same binary with the installed
# configuration. The comparison needs a still picture: a start view must
# settle (the stage banner goes away) and then not change, checked at two
# ticks far apart; the guest takes screendumps until one matches, so a
# daemon slowed down by emulation gets there too.
# ref_still NAME IDLE_OUT START TICK_A TICK_B [LINES...]: the script is START
# (the script lines that begin the game) plus those of LINES (expects) up to
# each tick; writes $B/ref-NAME.png, the frame at TICK_A.
# The VM's [game] settings (tests/vm/arcaded-vm.ini, its zz-vm.ini) as
# --set options, so the references are drawn as the VM plays.
vm_game_sets=$(awk '/^\[/ { g = ($0 == "[game]") } g && /^[a-z_]+ *=/ {
	k = $1; v = $0; sub(/^[^=]*= */, "", v); printf "--set game.%s=%s ", k, v }' tests/vm/arcaded-vm.ini)
ref_still() {
	tn=$1
	idle=$2
	start=$3
	ta=$4
	tb=$5
	shift 5
	for n in "$ta" "$tb"; do
		rm -rf "$B/refstate-$tn"
		mkdir -p "$B/refstate-$tn"
		{ printf '%s' "$start"
		  printf '%s\n' "$@" | awk -v n="$n" 'NF && $1 + 0 <= n + 0'; printf '%d end\n' "$n"; } \
			> "$B/ref-$tn-$n.scr"
		"$BUILD/arcaded" --config-dir "$ST/destdir/etc/arcaded" --state-dir "$B/refstate-$tn" \
			$vm_game_sets --set game.idle_out="$idle" \
			--script "$B/ref-$tn-$n.scr" --screenshot "$B/ref-$tn-$n.png" > "$B/ref.log" 2>&1 ||
			{ cat "$B/ref.log"; die "reference frame $tn"; }
	done
	cmp -s "$B/ref-$tn-$ta.png" "$B/ref-$tn-$tb.png" ||
		die "the $tn start view still changes with no input (ticks $ta and $tb differ): the screen comparison needs a still frame"
	cp "$B/ref-$tn-$ta.png" "$B/ref-$tn.png"
}
# The frame the daemon shows after coin and start.
ref_still play off '0 tap coin
1 tap start
2 expect mode == play
' 600 1800
ref=$B/ref-play.png
# Two players (guest.sh phase_twop, which sets game.idle_out = life): the
# start view of a two-player game with player 1 up and, after player 1
# gave no input for 30 s and lost the life, with player 2 up. Each is
# still (the idle warning comes 20 s into a turn's play: the turn's page
# ends at tick 156, player 1's life at 1956, player 2's page at 2226), and
# they differ (the HUD marks the player up), so a screen that matches the
# second shows player 2 up.
twop_start='2 tap coin
4 tap coin
6 tap start2
6 expect players == 2
'
ref_still twop-p1 life "$twop_start" 600 1200 "600 expect up == 1" "1200 expect up == 1"
ref_still twop-p2 life "$twop_start" 2600 3300 "2600 expect up == 2" "2600 expect phase == 0" "3300 expect up == 2"
cmp -s "$B/ref-twop-p1.png" "$B/ref-twop-p2.png" &&
	die "the two-player start views with player 1 up and with player 2 up are the same picture"
render_w=$("$BUILD/arcaded" --config-dir "$ST/destdir/etc/arcaded" --print-config |
	sed -n 's/^render_width *= *//p')
render_h=$("$BUILD/arcaded" --config-dir "$ST/destdir/etc/arcaded" --print-config |
	sed -n 's/^render_height *= *//p')

passed=0
failed=0
skipped=0
failures=""
result() { # PASS|FAIL|SKIP name detail
	echo "$1 $2${3:+: $3}"
	if [ "$1" = PASS ]; then
		passed=$((passed + 1))
	elif [ "$1" = SKIP ]; then
		skipped=$((skipped + 1))
	else
		failed=$((failed + 1))
		failures="$failures $2"
	fi
}
figures=""
figure() { # text
	echo "FIGURE $*"
	figures="$figures
  $*"
}

bpp_of() { case $1 in fb16) echo 16 ;; *) echo 32 ;; esac; }

# Boots one VM and serves it until it powers off. $1: boot name.
boot() {
	name=$1
	res=$B/results-$name
	bpp=$(bpp_of "$name")
	rm -rf "$res"
	mkdir -p "$res/req" "$res/ack" "$B/rootmnt"
	sock=/tmp/arcaded-vm-$$-$name.qmp
	# no_timer_check: on a loaded host TCG can run the guest too slowly for
	# the kernel's IO-APIC timer check, which then panics ("IO-APIC + timer
	# doesn't work"); the check only guards against broken firmware. The
	# PS/2 keyboard stays (a cabinet's PC has one): the daemon must take
	# the encoder under test as well as it.
	base="console=ttyS0 quiet loglevel=3 panic=-1 no_timer_check i8042.noaux"
	base="$base vt.global_cursor_default=0 systemd.unit=multi-user.target"
	base="$base systemd.show_status=0 arcaded.vm=$name"
	[ -n "${ARCADED_VM_PHASES:-}" ] && base="$base arcaded.phases=$ARCADED_VM_PHASES"
	# Modules udev would load for the emulated PC's other hardware and the
	# CPU's features: seconds each under emulation, of no use here.
	base="$base modprobe.blacklist=floppy,ata_piix,pata_acpi,ata_generic,pcspkr,kvm,kvm_amd"
	base="$base,kvm_intel,powernow_k8,acpi_cpufreq,serio_raw,i2c_piix4,joydev,evbug"
	vga="-vga std"
	snd=""
	case $name in
	kms)
		kernel=$kdir/vmlinux
		append="$base"
		# virtio-gpu: page flips complete with an event
		vga="-vga none -device virtio-vga"
		# an Intel HDA card: what the guest plays, QEMU writes to a WAV
		# file at the daemon's rate (no resampling in QEMU)
		snd="-audiodev wav,id=snd0,path=$res/sound.wav,out.frequency=48000,out.channels=2,out.format=s16"
		snd="$snd -device ich9-intel-hda -device hda-output,audiodev=snd0"
		;;
	fb32 | units)
		# PVH entry of the ELF kernel: no firmware, no decompression.
		kernel=$kdir/vmlinux
		# Debian allocates the DRM fbdev memory for one page (overalloc
		# 100%); twice that lets the daemon double-buffer by panning.
		append="$base drm_kms_helper.drm_fbdev_overalloc=200"
		;;
	latefb)
		# no framebuffer driver at boot: the guest loads bochs by hand
		kernel=$kdir/vmlinux
		append="$base drm_kms_helper.drm_fbdev_overalloc=200"
		append=$(echo "$append" | sed 's/modprobe.blacklist=/modprobe.blacklist=bochs,/')
		;;
	fb16)
		# VESA modes are set by the bzImage's real-mode code (vga=);
		# bochs-drm must not replace vesafb.
		kernel=$kdir/vmlinuz
		append="$base vga=0x317 modprobe.blacklist=bochs"
		;;
	*) die "unknown boot $name" ;;
	esac
	fs() { # tag path [readonly]
		echo "-fsdev local,id=$1,path=$2,security_model=passthrough${3:+,readonly=on}"
		echo "-device virtio-9p-pci,fsdev=$1,mount_tag=$1"
	}
	qargs="-nodefaults -machine pc -accel tcg,thread=multi -cpu qemu64 -smp 2 -m 512
		$vga $snd -display none -no-reboot
		-serial file:$res/serial.log -qmp unix:$sock,server=on,wait=off
		-kernel $kernel -initrd $B/initramfs.cpio
		$(fs root "$B/rootmnt" ro) $(fs kmod "$kdir/root/lib/modules" ro)
		$(fs stage "$ST" ro) $(fs results "$res")"
	echo "vm: boot $name: $kernel"
	echo "qemu-system-x86_64 $qargs -append \"$append\"" > "$res/qemu.cmd"
	t0=$(now)
	# The root is exported as a non-recursive read-only bind mount in a
	# private mount namespace: /proc, /sys, /dev and other mounts stay
	# out, and the mount goes away with QEMU.
	# shellcheck disable=SC2086
	unshare -m --propagation private sh -c '
		mount --bind / "$1" && mount -o remount,bind,ro "$1" || exit 1
		shift; exec "$@"' sh "$B/rootmnt" \
		qemu-system-x86_64 $qargs -append "$append" > "$res/qemu.log" 2>&1 &
	qpid=$!
	t_ready=""
	deadline=$(($(date +%s) + TIMEOUT))
	# Few processes per round: the host's CPUs are the guest's.
	while kill -0 "$qpid" 2>/dev/null; do
		for r in "$res"/req/*; do
			[ -e "$r" ] || continue
			n=$(basename "$r")
			[ -e "$res/ack/$n" ] && continue
			rq=$(cat "$r")
			# "match" compares with the game's start view, "match NAME"
			# with the reference $B/ref-NAME.png
			rf=$ref
			case $rq in match\ *) rf=$B/ref-${rq#match }.png; rq=match ;; esac
			case $rq in key\ *)
				# "key QCODE MS": a key on QEMU's PS/2 keyboard
				read -r _ kq kms < "$r"
				# when it went (for the sound's latency): before and
				# after the command that presses it
				[ -n "$snd" ] && [ -e "$res/sound.wav" ] &&
					echo "$(now) $(stat -c %s "$res/sound.wav")" >> "$res/wavsize.txt"
				tk=$(now)
				"$H" qmp "$sock" "{\"execute\":\"send-key\",\"arguments\":{\"keys\":[{\"type\":\"qcode\",\"data\":\"$kq\"}],\"hold-time\":$kms}}" \
					> "$res/ack/.$n" 2>&1
				echo "$kq $tk $(now)" >> "$res/keys.txt"
				mv "$res/ack/.$n" "$res/ack/$n"
				continue
				;;
			esac
			"$H" shot "$sock" "$res/$n.ppm" > "$res/shot-$n.log" 2>&1
			if [ "$rq" = match ]; then
				# NAME-K of a series: compare now, keep the last as NAME.
				"$H" match "$rf" "$res/$n.ppm" "$bpp" > "$res/ack/.$n" 2>&1 &&
					sed -i 's/^/match /' "$res/ack/.$n"
				cp "$res/$n.ppm" "$res/${n%-*}.ppm"
				mv "$res/ack/.$n" "$res/ack/$n"
			else
				touch "$res/ack/$n"
			fi
		done
		# the sound file's growth: maps its frames to this clock
		[ -n "$snd" ] && [ -e "$res/sound.wav" ] &&
			echo "$(now) $(stat -c %s "$res/sound.wav")" >> "$res/wavsize.txt"
		if [ -z "$t_ready" ] && grep -q '@@vm-ready' "$res/serial.log" 2>/dev/null; then
			t_ready=$(now)
		fi
		if [ "$(date +%s)" -ge "$deadline" ]; then
			echo "vm: boot $name: no power-off after $TIMEOUT s; stopping QEMU"
			kill "$qpid"
			break
		fi
		sleep 0.2
	done
	wait "$qpid"
	qrc=$?
	qpid=""
	t_end=$(now)
	rm -f "$sock"
	echo "vm: boot $name: QEMU ran $(secs "$t0" "$t_end") s, exit status $qrc"
	figure "$name: whole boot (QEMU start to power-off): $(secs "$t0" "$t_end") s"
	if [ ! -e "$res/done" ]; then
		result FAIL "$name-guest-finished" "the guest test did not finish (serial log: $res/serial.log)"
		tail -n 30 "$res/serial.log"
		[ -e "$res/guest.log" ] && tail -n 30 "$res/guest.log"
		return
	fi
	result PASS "$name-guest-finished"
	# Guest results: lines "PASS|FAIL name detail", "FIGURE text".
	while read -r kind rest; do
		case $kind in
		PASS | FAIL | SKIP) result "$kind" "$name-${rest%%:*}" "$(echo "${rest#*:}" | sed 's/^ //')" ;;
		FIGURE) figure "$name: $rest" ;;
		esac
	done < "$res/results.txt"
	# QEMU start to READY=1: when the host saw the guest's marker on the
	# serial line, less how long after READY the guest wrote it.
	if [ -n "$t_ready" ]; then
		lag=$(sed -n 's/.*@@vm-ready uptime=\([0-9.]*\) ready=\([0-9.]*\).*/\1 \2/p' \
			"$res/serial.log" | head -n 1 | awk '{ printf "%.2f", $1 - $2 }')
		figure "$name: QEMU start to READY=1 (first frame shown): $(awk -v a="$(secs "$t0" "$t_ready")" -v l="${lag:-0}" 'BEGIN { printf "%.2f", a - l }') s"
	fi
	judge "$name" "$res"
}

# The screendumps each boot's phases take (tests/vm/guest.sh) and the host
# judges below; the wizard's are kept for the docs, not judged.
screens_of() {
	case $1 in
	fb32) echo "attract-1 attract-2 play-start play-moved wd-attract-1 wd-attract-2 wd-play" \
		"hid-before hid-turned hid-still-1 hid-still-2 gpio-still-1 gpio-still-2" \
		"gpio-fired after-stop" ;;
	fb16) echo "attract-1 attract-2 play-start play-moved hp-before hp-turned" \
		"hp-still-1 hp-still-2 hp-still-3 hp-still-4 hp-still-5" \
		"hid-replug-still-1 hid-replug-still-2 hid-replug-still-3 hid-replug-still-4" \
		"hid-replug-still-5 twop-p1-start twop-p1-turned twop-p2-start twop-p1-stick" \
		"twop-p2-turned after-stop" ;;
	latefb) echo "late-screen gl-screen" ;;
	kms) echo "attract-1 attract-2 play-start play-moved vt-away vt-back after-stop" ;;
	*) echo "" ;;
	esac
}

# Screens: the guest asked for screendumps at these moments. Every screen
# the boot's phases take must be there: a missing one fails (the phase
# that should have taken it went wrong), and every check of the boot runs.
judge() {
	name=$1
	res=$2
	bpp=$(bpp_of "$name")
	want=" $(screens_of "$name" | tr '\n' ' ') "
	has() { case $want in *" $1 "*) return 0 ;; esac; return 1; }
	for s in "$res"/*.ppm; do
		[ -e "$s" ] && "$H" topng "$s" "${s%.ppm}.png"
	done
	for w in $want; do
		if [ -e "$res/$w.ppm" ]; then
			result PASS "$name-screendump-$w" "taken"
		elif [ -n "${ARCADED_VM_PHASES:-}" ]; then
			# its phase did not run: it and the checks of it are skipped
			result SKIP "$name-screendump-$w" "ARCADED_VM_PHASES=$ARCADED_VM_PHASES"
			want=$(echo "$want" | sed "s/ $w / /")
		else
			result FAIL "$name-screendump-$w" "the guest never took it (see $res/results.txt)"
		fi
	done
	screen() { # test name, command...
		tn=$1
		shift
		if out=$("$@" 2>&1); then
			result PASS "$name-$tn" "$out"
		else
			result FAIL "$name-$tn" "$out"
		fi
	}
	# Moved: at least 1 in 10 pixels differ (a turn or a walk moves most
	# of the view, about half of it in these runs); not just any pixel,
	# since the decorations drawn as meshes turn by themselves.
	moved() { # A.ppm B.ppm
		d=$("$H" differ "$1" "$2")
		echo "$d (at least 1 in 10)"
		echo "$d" | awk '$2 == "of" && $1 * 10 >= $3 { f = 1 } END { exit !f }'
	}
	if has attract-1; then
		screen first-frame "$H" picture "$res/attract-1.ppm" "$render_w" "$render_h"
		screen attract-animates moved "$res/attract-1.ppm" "$res/attract-2.ppm"
	fi
	has play-start && screen screen-is-frame "$H" match "$ref" "$res/play-start.ppm" "$bpp"
	# The comparison must be able to fail: an attract screen is not that frame.
	has attract-1 && screen screen-compare-rejects-attract \
		sh -c '! "$1" match "$2" "$3" "$4"' sh "$H" "$ref" "$res/attract-1.ppm" "$bpp"
	has play-moved && screen input-changes-screen moved "$res/play-start.ppm" "$res/play-moved.ppm"
	has hp-turned && screen usb-keyboard-changes-screen moved "$res/hp-before.ppm" "$res/hp-turned.ppm"
	# no stuck input, as the screen shows it: of five screens a second
	# apart, two that follow each other differ in under a tenth of the
	# pixels. A held turn or move changes most of the 3D view between
	# every two (hp-turned and play-moved, one short press each, changed
	# about half of the screen); what the game does by itself (an enemy
	# walking, a countdown) changes a small part. But the replugs' shots
	# wake the enemies, and they kill the player (a passing run's screens
	# show one life left of three): a death, the respawn or the game over
	# that follows change most of the screen, and a clean-clone run had
	# both pairs of three screens across such a moment. Five screens give
	# four pairs, and a held control changes all four. The guest's
	# *-nothing-held checks ask the daemon itself.
	still_pair() { # helper prefix
		out=""
		ok=1
		for p in 1-2 2-3 3-4 4-5; do
			d=$("$H" differ "$res/$1-${p%-*}.ppm" "$res/$1-${p#*-}.ppm")
			out="$out${out:+; }screens ${p%-*} and ${p#*-}: $d"
			echo "$d" | awk '$2 == "of" && $1 * 10 < $3 { f = 1 } END { exit !f }' && ok=0
		done
		echo "$out (limit: one pair under a tenth)"
		return $ok
	}
	has hp-still-5 && screen hotplug-no-stuck-input still_pair hp-still
	has hid-turned && screen hid-changes-screen moved "$res/hid-before.ppm" "$res/hid-turned.ppm"
	# Still, 1 s apart: under 1 in 100 pixels differ. Not none: the
	# decorations drawn as meshes turn by themselves (stage 1's lamps, 189
	# pixels of 1280x800 in a second); a stuck turn or walk moves the whole
	# view.
	nearly_still() { # A.ppm B.ppm
		d=$("$H" differ "$1" "$2")
		echo "$d (limit: under 1 in 100)"
		echo "$d" | awk '$2 == "of" && $1 * 100 < $3 { f = 1 } END { exit !f }'
	}
	has hid-still-2 && screen hid-no-stuck-input \
		nearly_still "$res/hid-still-1.ppm" "$res/hid-still-2.ppm"
	has gpio-still-2 && screen gpio-still-before \
		nearly_still "$res/gpio-still-1.ppm" "$res/gpio-still-2.ppm"
	# the HUD's ammunition count: the status line lies in the bottom eighth
	# of the screen whether the frame fills it or is framed in black
	has gpio-fired && screen gpio-changes-screen "$H" differ "$res/gpio-still-2.ppm" "$res/gpio-fired.ppm" 8
	has hid-replug-still-5 && screen hid-replug-no-stuck-input still_pair hid-replug-still
	# Two players (guest.sh phase_twop): player 1's start view, then the
	# joystick turned player 1; player 2's start view (player 2 up); then
	# the joystick's stick did not move the view and the second device's
	# key (player 2's turn right) did.
	if has twop-p2-turned; then
		r1=$B/ref-twop-p1.png
		r2=$B/ref-twop-p2.png
		screen twop-p1-start-view "$H" match "$r1" "$res/twop-p1-start.ppm" "$bpp"
		screen twop-p1-stick-drives-p1 \
			sh -c '! "$1" match "$2" "$3" "$4"' sh "$H" "$r1" "$res/twop-p1-turned.ppm" "$bpp"
		screen twop-p2-start-view "$H" match "$r2" "$res/twop-p2-start.ppm" "$bpp"
		screen twop-p1-stick-not-p2 "$H" match "$r2" "$res/twop-p1-stick.ppm" "$bpp"
		screen twop-second-device-drives-p2 \
			sh -c 'if "$1" match "$2" "$3" "$4" > /dev/null; then
				echo "the screen is still player 2'"'"'s start view"; exit 1; fi
				"$1" differ "$5" "$3"' sh \
			"$H" "$r2" "$res/twop-p2-turned.ppm" "$bpp" "$res/twop-p1-stick.ppm"
	fi
	has after-stop && screen sigterm-console-shows-text "$H" text "$res/after-stop.ppm"
	# KMS: switched away, the other terminal's text is on the screen (the
	# daemon dropped DRM master, so fbcon could set its mode); back, the
	# game's frame again (master and mode taken back)
	has vt-away && screen vt-away-shows-console "$H" text "$res/vt-away.ppm"
	has vt-back && screen vt-back-screen-is-frame "$H" match "$ref" "$res/vt-back.ppm" "$bpp"
	has late-screen && screen late-fb-picture "$H" picture "$res/late-screen.ppm" "$render_w" "$render_h"
	has gl-screen && screen gl-picture "$H" picture "$res/gl-screen.ppm" "$render_w" "$render_h"
	if has wd-attract-1; then
		screen watchdog-back-in-attract moved "$res/wd-attract-1.ppm" "$res/wd-attract-2.ppm"
		screen watchdog-screen-is-frame "$H" match "$ref" "$res/wd-play.ppm" "$bpp"
	fi
	[ -n "$snd" ] && sound_checks
	return 0
}

# The sound the kms boot's HDA card played (QEMU's WAV file): every coin
# key the host sent (qcode 5) must be heard, and the time from the key to
# the coin's first audible sample is the coin-to-sound latency.
# The file holds what the card played, frame after frame, while the
# daemon's stream ran (an underrun stops it: the file then has a gap in
# time but not in frames). So each key is placed in the file by the file's
# growth near it: polled on this host's clock (wavsize.txt, also just
# before each key), frame k was played at t0 + k / rate, and QEMU's writes
# lag behind what it played, never lead, so t - frames / rate >= t0 at
# every poll: the least of those within a second of the key is its t0.
# That estimate can only be late, and a key's time is taken before the
# command that presses it: both err towards longer latencies.
sound_checks() {
	w=$res/sound.wav
	[ -e "$w" ] || { result FAIL "$name-sound-file" "QEMU wrote no $w"; return; }
	awk '$1 == "5" { print $2, $3 }' "$res/keys.txt" 2>/dev/null > "$res/coin-keys.txt"
	"$BUILD/tests/sndfind" --min 0.9 "$w" COIN > "$res/coin-found.txt" 2>&1
	rate=$(sed -n 's/.*, rate \([0-9]*\),.*/\1/p' "$res/coin-found.txt")
	nf=$(grep -c '^found ' "$res/coin-found.txt")
	out=$(awk -v rate="${rate:-0}" '
		FILENAME ~ /coin-keys/ { kp[++np] = $1; ka[np] = $2; next }
		FILENAME ~ /wavsize/ { ws_t[++nw] = $1; ws_f[nw] = ($2 - 44) / 4; next }
		$1 == "found" { on[++no] = $4 }
		END {
			if (!np || !rate) { print "0 0 0 0| (no coin keys sent, or no rate in the file)"; exit 1 }
			heard = 0; bad = ""
			for (i = 1; i <= np; i++) {
				t0 = ""
				for (k = 1; k <= nw; k++)
					if (ws_t[k] >= kp[i] - 1 && ws_t[k] <= kp[i] + 1 && ws_f[k] > 0) {
						c = ws_t[k] - ws_f[k] / rate
						if (t0 == "" || c < t0) t0 = c
					}
				best = 0
				if (t0 == "") { bad = bad " " i; continue }
				for (j = 1; j <= no; j++) {
					t = t0 + on[j] / rate
					if (!used[j] && t >= kp[i] - 0.05 && t < kp[i] + 1) { best = j; break }
				}
				if (!best) { bad = bad " " i; miss[++nm] = i; mt0[nm] = t0; continue }
				used[best] = 1
				lat[++heard] = t0 + on[best] / rate - kp[i]
			}
			# A sound found but not within 1 s of a key: late, when it is
			# within 3 s after a key that was not heard (a stalled guest
			# or a WAV-size sample taken late shifts it), else a coin
			# sound no key asked for.
			late = 0; stray = 0
			for (j = 1; j <= no; j++) {
				if (used[j]) continue
				ok = 0
				for (m = 1; m <= nm; m++) {
					if (mused[m]) continue
					t = mt0[m] + on[j] / rate
					if (t >= kp[miss[m]] - 0.25 && t < kp[miss[m]] + 3) { mused[m] = 1; ok = 1; break }
				}
				if (ok) late++; else stray++
			}
			for (i = 1; i <= heard; i++) for (j = i + 1; j <= heard; j++)
				if (lat[j] < lat[i]) { x = lat[i]; lat[i] = lat[j]; lat[j] = x }
			printf "%d %d %d %d", np, heard, late, stray
			if (heard) printf " %.1f %.1f %.1f %.1f", lat[1] * 1000,
				lat[int((heard + 1) / 2)] * 1000, lat[int((heard * 99 + 99) / 100)] * 1000, lat[heard] * 1000
			printf "|%s\n", bad
		}' "$res/coin-keys.txt" "$res/wavsize.txt" "$res/coin-found.txt")
	set -- ${out%%|*}
	if [ "${2:-0}" -gt 0 ]; then
		figure "$name: coin key to the coin's first audible sample through the HDA card, over the $2 coins heard whole: min $5 ms, p50 $6 ms, p99 $7 ms, max $8 ms (QEMU's WAV file, $(wc -c < "$w") bytes at $rate Hz)"
	fi
	figure "$name: coins heard whole (score 0.9 or more, within 1 s of the key): ${2:-0} of ${1:-0} (not heard:${out#*|}; an underrun inside a coin's first 40 ms breaks it up: the guest's underrun figure); found later than 1 s after an unheard key: ${3:-0}"
	# The coin is heard: at least one key's coin sound whole in what the
	# card played (a muted card, a stream that never starts or the wrong
	# sound give none), and every sound found as a coin follows a key: within
	# 1 s (heard), or within 3 s after a key not heard so (late: the wall
	# clock of the WAV's samples drifts when the emulated guest stalls). A
	# coin sound no key accounts for (stray) fails. How many are whole and
	# how many late depends on the guest keeping up (the underruns): a
	# figure, not a limit.
	if [ "${2:-0}" -gt 0 ] && [ "${4:-1}" = 0 ] && [ "$nf" = "$(( $2 + $3 ))" ]; then
		result PASS "$name-sound-coin-heard" "${2} of ${1} coin keys heard whole, each within 1 s after its key, ${3} late; $nf coin sounds found in all ($(awk '$1 == "found" { s = s " " $3 } END { print "scores" s }' "$res/coin-found.txt"))"
	else
		result FAIL "$name-sound-coin-heard" "keys ${1:-0}, heard ${2:-0}, late ${3:-0}, stray ${4:-0}, coin sounds found at score 0.9 or more $nf (keys not heard:${out#*|}); $(tail -n 1 "$res/coin-found.txt")"
	fi
}

if [ -n "$gpio_ko" ]; then
	result PASS gpio-sim-module "built $gpio_ko"
else
	result FAIL gpio-sim-module "tests/vm/gpio-sim.sh failed: test_in_gpio will skip its gpio-sim cases"
fi
for b in $boots; do
	boot "$b"
done

echo
echo "vm: figures:$figures"
echo "vm: whole VM test $(secs "$t_all" "$(now)") s"
[ -n "$failures" ] && echo "vm: failed:$failures"
echo "vm: $passed passed, $failed failed${ARCADED_VM_PHASES:+, $skipped skipped (ARCADED_VM_PHASES)}"
[ "$failed" -eq 0 ] || exit 1
[ "$skipped" -eq 0 ] || exit 77
