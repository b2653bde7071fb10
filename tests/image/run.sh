#!/bin/sh
# The cabinet image test (make test-image; docs/packaging.md): QEMU boots
# the image made by `make image` from its own disk, through its own
# bootloader and kernel (UEFI: OVMF), on a disk larger than the image (a
# bigger card). Checks:
#   - the first boot grows the state partition and its file system to the
#     end of the disk;
#   - every boot reaches the game: the screen (QMP screendump) shows the
#     attract screen (a 320x240 picture, integer-scaled, black around it,
#     at least 8 colours) and it animates; power-on to first frame is timed;
#   - the screen shows nothing but black before the game (quiet boot) once
#     the firmware has handed over;
#   - POWERCUTS times (default 20): keys through QEMU's PS/2 keyboard (coin,
#     start, fire, turns: config/bindings.ini) at random moments, each coin
#     and game start a save of the bookkeeping, and QEMU stopped dead (QMP
#     quit) at a random moment among them. Then, offline, from the disk
#     file: the root file system was never written (e2fsck -fn clean, its
#     superblock's write time is the image's); the state partition, after
#     its journal is replayed as the next mount would, passes e2fsck -fn
#     with nothing in lost+found; the bookkeeping file (or its previous
#     copy) checks out (vm_guest books: magic, sizes, CRCs) and counts no
#     fewer coins than the last check and no more than were inserted. The
#     next boot must reach the game again, and the daemon must have loaded
#     that state: the coins it counts next start from it.
#
# usage: tests/image/run.sh IMAGE   (POWERCUTS=N, SEED=N)
# Environment: ARCADED_IMAGE_DEBUG=1 adds a serial console to the copy's
# boot entry (serial.log per boot); ARCADED_IMAGE_TIMEOUT (seconds a boot
# may take to show the game, default 240).
# Exit status: 0 all passed, 1 a failure, 77 skipped (QEMU cannot run).
set -u
cd "$(dirname "$0")/../.."
img=$1
CUTS=${POWERCUTS:-20}
SEED=${SEED:-20261125}
TIMEOUT=${ARCADED_IMAGE_TIMEOUT:-240}
B=build/image-test
mkdir -p "$B"
W=$(mktemp -d "${TMPDIR:-/tmp}/arcaded-image.XXXXXX")
qpid=""
trap 'if [ -n "$qpid" ]; then kill "$qpid" 2>/dev/null; fi; rm -rf "$W"' EXIT
trap 'exit 130' INT TERM

passed=0
failed=0
failures=""
result() { # PASS|FAIL name detail
	echo "$1 $2${3:+: $3}"
	if [ "$1" = PASS ]; then passed=$((passed + 1)); else
		failed=$((failed + 1)); failures="$failures $2"; fi
}
figure() { echo "FIGURE $*"; }
now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }
die() { echo "image-test: FAIL: $*"; exit 1; }

[ -s "$img" ] || die "no image $img (make image)"
echo quit | qemu-system-x86_64 -machine pc -accel tcg -display none -nodefaults -S \
	-monitor stdio > /dev/null 2>&1 || { echo "IMAGE TEST SKIPPED: QEMU cannot start a TCG machine"; exit 77; }
CODE=/usr/share/OVMF/OVMF_CODE_4M.fd
VARS=/usr/share/OVMF/OVMF_VARS_4M.fd
[ -s "$CODE" ] && [ -s "$VARS" ] || die "OVMF missing (package ovmf; scripts/setup.sh test)"

CFLAGS="-std=c11 -D_GNU_SOURCE -O2 -Wall -Wextra -Werror"
# shellcheck disable=SC2086
cc $CFLAGS $(pkg-config --cflags libpng) -o "$B/vm_host" tests/vm/vm_host.c \
	$(pkg-config --libs libpng) || die "vm_host"
# shellcheck disable=SC2086
cc $CFLAGS $(pkg-config --cflags libevdev zlib) -o "$B/vm_guest" tests/vm/vm_guest.c \
	$(pkg-config --libs libevdev zlib) || die "vm_guest"
H=$B/vm_host

# The disk: the image on a card 256 MiB larger.
disk=$W/disk.img
cp --sparse=always "$img" "$disk"
img_bytes=$(stat -c %s "$img")
truncate -s $((img_bytes + 256 * 1048576)) "$disk"
cp "$VARS" "$W/vars.fd"
part() { # N: "start size" in sectors of partition N
	sfdisk -d "$disk" 2>/dev/null | sed -n "s|^$disk$1 : start= *\([0-9]*\), size= *\([0-9]*\),.*|\1 \2|p"
}
set -- $(part 2)
root_off=$(($1 * 512))
set -- $(part 3)
state_start0=$1
state_size0=$2
root_written0=$(dumpe2fs -h "$img?offset=$root_off" 2>/dev/null | sed -n 's/^Last write time: *//p')

# What the image says about its boot, read from the image itself: the
# entry's kernel options silence kernel, initramfs and systemd and hide the
# cursor; the root is mounted read-only; no getty on tty1; no network
# service enabled.
set -- $(part 1)
opts=$(mtype -i "$img@@$(($1 * 512))" ::/loader/entries/arcaded.conf 2>/dev/null | sed -n 's/^options //p')
miss=""
for o in ro quiet loglevel=0 systemd.show_status=0 vt.global_cursor_default=0; do
	case " $opts " in *" $o "*) ;; *) miss="$miss $o" ;; esac
done
if [ -z "$miss" ]; then result PASS boot-entry-quiet "options: $opts"; else
	result FAIL boot-entry-quiet "missing:$miss in: $opts"; fi
rdbg() { debugfs -R "$1" "$img?offset=$root_off" 2>/dev/null; }
g=$(rdbg 'stat /etc/systemd/system/getty@tty1.service' | sed -n 's/^Fast link dest: "\(.*\)"/\1/p')
net=$(rdbg 'ls /etc/systemd/system/multi-user.target.wants' | tr -s ' ' '\n' | grep -E -c 'network|ssh|dhc|ifup' )
fstab_root=$(rdbg 'cat /etc/fstab' | awk '$2 == "/" { print $4 }')
if [ "$g" = /dev/null ] && [ "$net" = 0 ] && echo ",$fstab_root," | grep -q ',ro,'; then
	result PASS image-config "getty@tty1 masked, no network service enabled, fstab mounts / with $fstab_root"
else
	result FAIL image-config "getty@tty1 -> '$g', $net network services enabled, / mounted with '$fstab_root'"
fi

if [ "${ARCADED_IMAGE_DEBUG:-}" = 1 ]; then
	set -- $(part 1)
	esp="$disk@@$(($1 * 512))"
	mtype -i "$esp" ::/loader/entries/arcaded.conf | sed 's/^options .*/& console=ttyS0 systemd.show_status=1 loglevel=6/' |
		sed 's/ quiet / /' > "$W/entry.conf"
	mcopy -o -i "$esp" "$W/entry.conf" ::/loader/entries/arcaded.conf
	echo "image-test: debug: serial console on"
fi

sock=/tmp/arcaded-img-$$.qmp
qmp() { "$H" qmp "$sock" "$1" > /dev/null 2>&1; }
key() { # qcode, hold ms
	qmp "{\"execute\":\"send-key\",\"arguments\":{\"keys\":[{\"type\":\"qcode\",\"data\":\"$1\"}],\"hold-time\":${2:-150}}}"
}
lit() { "$H" text "$1" 2>/dev/null | sed -n 's/.*: \([0-9]*\) of .*/\1/p'; }
# The game's picture: a 320x240 frame integer-scaled with black around it
# and at least 8 colours in it (vm_host picture), and lit over at least a
# third of the screen (the 3D view fills the frame; the firmware's logo and
# text, which also sit inside that area, light a few per cent).
game() { # screen.ppm
	"$H" picture "$1" 320 240 > /dev/null 2>&1 || return 1
	set -- "$("$H" text "$1" 2>/dev/null | sed -n 's/.*: \([0-9]*\) of \([0-9]*\) .*/\1 \2/p')"
	set -- $1
	[ "${1:-0}" -ge $((${2:-1} / 3)) ]
}

# Is the firmware's logo on the screen? OVMF centres it: something lit on
# the screen's middle row within 96 pixels of the centre.
logo() { # screen.ppm (P6, 8-bit)
	set -- "$1" $(head -c 20 "$1" | tr -s ' \n' '  ' | cut -d' ' -f2,3)
	hdr=$(head -c 20 "$1" | awk 'NR <= 3 { n += length($0) + 1 } END { print n }')
	tail -c +$((hdr + ($3 / 2 * $2 + $2 / 2 - 96) * 3 + 1)) "$1" | head -c 576 | od -An -tu1 |
		tr -s ' \n' '\n\n' | grep -q '[1-9]'
}

# Starts QEMU on the disk; returns when the attract screen shows (0) or not
# within TIMEOUT (1). Sets t_frame (QEMU start to the first frame) and
# boot_text: screens lit before the game but after the firmware's logo went
# (the kernel's), kept as boot-text-N.ppm.
boot() { # name
	res=$B/boot-$1
	rm -rf "$res"
	mkdir -p "$res"
	t0=$(now)
	qemu-system-x86_64 -nodefaults -machine q35 -accel tcg,thread=multi -cpu qemu64 -smp 2 -m 512 \
		-vga std -display none \
		-drive if=pflash,format=raw,readonly=on,file="$CODE" \
		-drive if=pflash,format=raw,file="$W/vars.fd" \
		-drive file="$disk",format=raw,if=virtio \
		-serial file:"$res/serial.log" -qmp unix:"$sock",server=on,wait=off \
		> "$res/qemu.log" 2>&1 &
	qpid=$!
	n=0
	fw=0
	dark=0
	fw_text=0
	boot_text=0
	t_frame=""
	stage="no screen"
	t_stage=0
	last=""
	unshot=0
	while kill -0 "$qpid" 2>/dev/null; do
		n=$((n + 1))
		s=$res/s$n.ppm
		if "$H" shot "$sock" "$s" 2>/dev/null && [ -s "$s" ]; then
			last=$s
			if game "$s"; then
				t_frame=$(secs "$t0" "$(now)")
				cp "$s" "$res/first-frame.ppm"
				break
			fi
			# The firmware's own screens (its logo in the middle, its
			# messages) are not the image's to silence and are not
			# judged. After the logo the firmware may still print
			# (OVMF's "BdsDxe: loading Boot0001 ..." and "starting",
			# caught by one screen in one of 21 boots of a clean-clone
			# run) until the kernel takes the screen and it goes black;
			# anything lit after that black and before the game is boot
			# text. Before the logo, QEMU's own "Guest has not
			# initialized the display" shows: not judged either.
			l=$(lit "$s")
			if [ "${l:-0}" = 0 ]; then
				rm -f "$s"
				last=""
				[ "$fw" = 1 ] && dark=1
				now_stage=black
				[ "$dark" = 1 ] && now_stage="black after the firmware's logo (the kernel's screen)"
			elif logo "$s"; then
				fw=1
				now_stage="the firmware's logo"
			elif [ "$dark" = 1 ]; then
				boot_text=$((boot_text + 1))
				cp "$s" "$res/boot-text-$boot_text.ppm"
				now_stage="text after the kernel took the screen ($l pixels lit)"
			elif [ "$fw" = 1 ]; then
				fw_text=$((fw_text + 1))
				cp "$s" "$res/firmware-text-$fw_text.ppm"
				now_stage="the firmware's text"
			else
				now_stage="QEMU's own screen (no display set up yet)"
			fi
			if [ "$now_stage" != "$stage" ]; then
				stage=$now_stage
				t_stage=$(secs "$t0" "$(now)")
			fi
		else
			unshot=$((unshot + 1))
		fi
		[ "$(secs "$t0" "$(now)" | cut -d. -f1)" -lt "$TIMEOUT" ] || break
		sleep 0.3
	done
	[ -n "$t_frame" ]
}
# What a boot that never showed the game had reached, for its FAIL line
# (a clean-clone run's screens are not kept where its log is read): QEMU
# alive or not, the last screen seen and since when, each CPU's state (in
# the firmware, the kernel or a program; halted or running) and the last
# line the firmware wrote to the serial port. The last screen, when not
# black, is kept as last.png.
stuck() {
	if kill -0 "$qpid" 2>/dev/null; then
		how="QEMU running after $(secs "$t0" "$(now)") s"
	else
		how="QEMU gone after $(secs "$t0" "$(now)") s ($(tail -n 1 "$res/qemu.log" 2>/dev/null))"
	fi
	how="$how; screen since $t_stage s: $stage; $n screendumps asked, $unshot failed"
	[ -n "$last" ] && [ -s "$last" ] && "$H" topng "$last" "$res/last.png" 2>/dev/null
	# info registers, one CPU a call (a reply fits vm_host's 8 KiB line):
	# "RIP=... RFL=... [...] CPL=n II=n A20=n SMM=n HLT=n" (EIP= before
	# long mode)
	for c in 0 1; do
		r=$("$H" qmp "$sock" "{\"execute\":\"human-monitor-command\",\"arguments\":{\"command-line\":\"info registers\",\"cpu-index\":$c}}" 2>/dev/null |
			grep -o '[ER]IP=[0-9a-f]*\|CPL=[0-3]\|HLT=[01]' | paste -sd' ' -)
		[ -n "$r" ] && how="$how; CPU $c: $r"
	done
	ser=$(tr -d '\033' < "$res/serial.log" 2>/dev/null | sed 's/\[[0-9;=]*[A-Za-z]//g' | grep -a '[[:alnum:]]' | tail -n 1)
	echo "$how; serial: ${ser:-nothing}"
}
powercut() { # QEMU stopped dead, as a pulled plug
	qmp '{"execute":"quit"}'
	i=0
	while kill -0 "$qpid" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
	kill -9 "$qpid" 2>/dev/null
	wait "$qpid" 2>/dev/null
	qpid=""
	rm -f "$sock"
}

# Offline checks after a cut; sets books_coins. $1: cut number.
coins_known=0
coins_sent=0
from_prev=0
offline() {
	c=$1
	rw=$(dumpe2fs -h "$disk?offset=$root_off" 2>/dev/null | sed -n 's/^Last write time: *//p')
	if out=$(e2fsck -fn "$disk?offset=$root_off" 2>&1) && [ "$rw" = "$root_written0" ]; then
		root_ok=$((root_ok + 1))
	else
		result FAIL "cut$c-root-clean" "e2fsck -fn: $(echo "$out" | tail -n 3 | tr '\n' ' '); last write $rw (image: $root_written0)"
	fi
	set -- $(part 3)
	dd if="$disk" of="$W/state.img" bs=512 skip="$1" count="$2" conv=sparse status=none
	e2fsck -E journal_only -y "$W/state.img" > "$W/replay.log" 2>&1
	if out=$(e2fsck -fn "$W/state.img" 2>&1); then
		# ls -p: /inode/mode/uid/gid/name/size/ per entry
		lf=$(debugfs -R 'ls -p /lost+found' "$W/state.img" 2>/dev/null |
			awk -F/ 'NF > 5 && $2 != 0 && $6 != "." && $6 != ".." { printf "%s ", $6 }')
		if [ -z "$lf" ]; then
			state_ok=$((state_ok + 1))
		else
			result FAIL "cut$c-state-nothing-lost" "lost+found holds: $lf"
		fi
	else
		result FAIL "cut$c-state-fsck" "$(echo "$out" | tail -n 5 | tr '\n' ' ')"
	fi
	rm -f "$W/books" "$W/books.prev"
	debugfs -R "dump /books $W/books" "$W/state.img" > /dev/null 2>&1
	debugfs -R "dump /books.prev $W/books.prev" "$W/state.img" > /dev/null 2>&1
	which=""
	if [ -s "$W/books" ] && bk=$("$B/vm_guest" books "$W/books"); then
		which=books
	elif [ -s "$W/books.prev" ] && bk=$("$B/vm_guest" books "$W/books.prev"); then
		which=books.prev
		from_prev=$((from_prev + 1))
	fi
	if [ -z "$which" ]; then
		if [ "$coins_known" -eq 0 ] && [ ! -e "$W/books" ]; then
			loads_ok=$((loads_ok + 1))   # nothing saved yet
			echo "cut $c: no bookkeeping saved yet"
			return
		fi
		result FAIL "cut$c-state-loads" "neither books nor books.prev checks out"
		return
	fi
	coins=$(echo "$bk" | sed -n 's/^coins \([0-9]*\) .*/\1/p')
	echo "cut $c: $which: $bk (coins inserted so far $coins_sent, last known $coins_known)"
	if [ "$coins" -ge "$coins_known" ] && [ "$coins" -le "$coins_sent" ]; then
		loads_ok=$((loads_ok + 1))
		coins_known=$coins
	else
		result FAIL "cut$c-state-loads" "$which counts $coins coins; expected $coins_known..$coins_sent"
	fi
}

rnd_state=$SEED
rnd() { # N: sets r to a number 0..N-1 (xorshift32, seeded: the same run each time)
	x=$rnd_state
	x=$(((x ^ (x << 13)) & 4294967295))
	x=$((x ^ (x >> 17)))
	x=$(((x ^ (x << 5)) & 4294967295))
	rnd_state=$x
	r=$((x % $1))
}

# First boot: the game shows; the state partition grows to the disk's end.
echo "image-test: $(basename "$img"), $(($(stat -c %s "$disk") / 1048576)) MiB disk, $CUTS cuts, seed $SEED"
root_ok=0
state_ok=0
loads_ok=0
boots_ok=0
quiet_bad=0
cuts_done=0
frames=""
b=0
while [ "$b" -le "$CUTS" ]; do
	if boot "$b"; then
		boots_ok=$((boots_ok + 1))
		frames="$frames $t_frame"
		[ "$boot_text" -eq 0 ] || { quiet_bad=$((quiet_bad + 1)); echo "boot $b: $boot_text lit screens between black and the game (kept in $res)"; }
	else
		[ "$boot_text" -eq 0 ] || { quiet_bad=$((quiet_bad + 1)); echo "boot $b: $boot_text lit screens after the firmware's logo (kept in $res)"; }
		result FAIL "boot$b-reaches-game" "no attract screen within $TIMEOUT s: $(stuck) (screens in $res)"
		powercut
		# The same disk once more, as an operator would power-cycle: a
		# boot that hung once is told apart from a disk the cut left
		# unbootable. Reported, not counted: the failure above stands.
		if boot "$b-again"; then
			figure "boot $b again, from the same disk: first frame after $t_frame s"
		else
			figure "boot $b again, from the same disk: no attract screen within $TIMEOUT s either: $(stuck)"
		fi
		powercut
		break
	fi
	echo "boot $b: first frame after $t_frame s"
	if [ "$b" -eq 0 ]; then
		sleep 1
		"$H" shot "$sock" "$res/attract-2.ppm"
		if d=$("$H" differ "$res/first-frame.ppm" "$res/attract-2.ppm"); then
			result PASS attract-animates "$d"
		else
			result FAIL attract-animates "two screens 1 s apart are the same"
		fi
		"$H" picture "$res/first-frame.ppm" 320 240 > "$W/p" 2>&1
		result PASS first-frame-is-attract "$(cat "$W/p")"
		"$H" topng "$res/first-frame.ppm" "$B/first-frame.png"
	fi
	[ "$b" -lt "$CUTS" ] || { powercut; break; }
	# Random moments: 2..5 steps of coin / start / fire / turn, 0.2..2 s
	# apart, then the cut 0..2.5 s after the last one.
	rnd 4
	steps=$((2 + r))
	log=""
	while [ "$steps" -gt 0 ]; do
		rnd 5
		case $r in
		0 | 1) key 5 && coins_sent=$((coins_sent + 1)) && log="$log coin" ;;
		2) key 1 && log="$log start" ;;
		3) key ctrl && log="$log fire" ;;
		4) key left 400 && log="$log turn" ;;
		esac
		rnd 1800
		sleep "$(awk -v r="$r" 'BEGIN { printf "%.2f", 0.2 + r / 1000 }')"
		steps=$((steps - 1))
	done
	rnd 2500
	sleep "$(awk -v r="$r" 'BEGIN { printf "%.2f", r / 1000 }')"
	powercut
	cuts_done=$((b + 1))
	echo "cut $cuts_done: after$log"
	offline $((b + 1))
	if [ "$b" -eq 0 ]; then
		set -- $(part 3)
		disk_sectors=$(($(stat -c %s "$disk") / 512))
		blocks=$(dumpe2fs -h "$W/state.img" 2>/dev/null | sed -n 's/^Block count: *//p')
		end=$(($1 + $2))
		if [ "$1" = "$state_start0" ] && [ "$end" -ge $((disk_sectors - 34 - 2048)) ] &&
			[ $((blocks * 8)) -ge $(($2 - 2048)) ]; then
			result PASS state-grown "partition $state_size0 -> $2 sectors (disk $disk_sectors), file system $blocks blocks"
		else
			result FAIL state-grown "partition $1+$2 (was $state_start0+$state_size0) on a disk of $disk_sectors sectors, file system $blocks 4 KiB blocks"
		fi
	fi
	b=$((b + 1))
done

[ "$boots_ok" -eq $((CUTS + 1)) ] && result PASS boots-reach-game "$boots_ok of $((CUTS + 1)) boots showed the attract screen"
# The summaries below pass only on something seen: no boot, no pass.
[ "$quiet_bad" -eq 0 ] && [ "$boots_ok" -gt 0 ] && result PASS quiet-boot "no lit screen between the firmware and the game in $boots_ok boots"
[ "$quiet_bad" -eq 0 ] || result FAIL quiet-boot "$quiet_bad boots showed something lit after the firmware's logo and before the game"
[ "$CUTS" -gt 0 ] || { echo "image-test: no cuts asked for (POWERCUTS=0)"; }
[ "$CUTS" -gt 0 ] && [ "$root_ok" -eq "$CUTS" ] && result PASS root-never-repaired "$root_ok of $CUTS cuts: e2fsck -fn clean, never written"
[ "$CUTS" -gt 0 ] && [ "$state_ok" -eq "$CUTS" ] && result PASS state-fsck-nothing-lost "$state_ok of $CUTS cuts: journal replayed, e2fsck -fn clean, lost+found empty"
# Some coins must have been kept at all: a state directory that never
# reaches the disk would pass every check above with nothing saved.
if [ "$CUTS" -eq 0 ]; then :; elif [ "$coins_known" -gt 0 ]; then result PASS state-persists "$coins_known coins kept over $cuts_done cuts"; else
	result FAIL state-persists "no coin was ever found saved ($coins_sent inserted)"; fi
[ "$CUTS" -gt 0 ] && [ "$loads_ok" -eq "$CUTS" ] && result PASS state-loads "$loads_ok of $CUTS cuts: bookkeeping checks out ($from_prev from books.prev), $coins_known of $coins_sent coins kept"
first=$(echo "$frames" | awk '{ print $1 }')
rest=$(echo "$frames" | tr ' ' '\n' | sed 1,2d | sort -n | awk '{ a[NR] = $1 } END { if (NR) printf "median %s s, max %s s", a[int((NR + 1) / 2)], a[NR] }')
figure "power-on to first frame (TCG, 2 vCPUs, OVMF): first boot ${first:-?} s (grows the state partition); later boots $rest"
figure "cuts: $cuts_done of $CUTS, boots: $boots_ok, coins inserted $coins_sent, kept $coins_known"
echo "image-test: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
