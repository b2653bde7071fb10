#!/bin/sh
# Proves the layering rules of STYLE.md and engine/README.md on the sources
# and the compiled objects:
# - engine/ is folders by subsystem, and calls and includes go one way
#   between them: core < map < sound < game < render < ui, and gl (the OSMesa
#   plugin) above render beside ui. A folder may use its own and the ones
#   below it, never one above or a sibling. Checked twice: on the
#   `#include "engine/..."` lines, and on the compiled objects (each
#   undefined symbol of an object that another engine object defines must
#   be defined in an allowed folder);
# - inside every engine folder but render (whose stages call each other in
#   a loop, as Doom's do), the modules call each other one way: the call
#   graph between object files has no cycle (tsort finds one);
# - engine/ includes only C standard headers and its own headers, has no
#   floating point and no mutable file-scope state (no .data/.bss symbols
#   in the objects); engine/gl/ is exempt from these three: it is the only
#   code with floating point and with OSMesa or GL headers (in rgl.c);
# - outside engine/, only the files listed below (backends, the thread
#   pool, the plugin loader, screenshots, hotplug) include Linux,
#   device-library or other platform headers, each only the ones it needs;
# - every exported symbol of shipped code starts with its file's prefix
#   (the name up to the first '_': in_evdev.c exports in_*, hidr.c hidr_*).
# BUILD (default build) names the build whose objects are checked.
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
# The objects of the sources that exist now (a build folder may hold stale
# ones of renamed files): objs_of FOLDER [PREFIX].
objs_of() {
	for c in "$1"/*.c; do
		[ -f "$c" ] || continue
		o="$BUILD/${2:-}${c%.c}.o"
		[ -f "$o" ] && echo "$o"
	done
}
fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

DIRS="core map sound game render ui"
# Folders each folder may use (itself included).
allowed() {
	case $1 in
	core) echo "core" ;;
	map) echo "core map" ;;
	sound) echo "core map sound" ;;
	game) echo "core map sound game" ;;
	render) echo "core map sound game render" ;;
	ui) echo "core map sound game render ui" ;;
	gl) echo "core map sound game render gl" ;;
	*) echo "" ;;
	esac
}
may_use() { # $1 folder, $2 folder used
	for a in $(allowed "$1"); do [ "$a" = "$2" ] && return 0; done
	return 1
}

# ---- the folders ------------------------------------------------------
stray=$(ls engine/*.c engine/*.h 2>/dev/null)
if [ -n "$stray" ]; then
	echo "FAIL files directly in engine/ (put them in a subsystem folder):"; echo "$stray"; fail=1
fi
for d in $DIRS gl; do
	if [ ! -f "engine/$d/README.md" ]; then
		echo "FAIL engine/$d has no README.md"; fail=1
	fi
done

# ---- includes between folders -----------------------------------------
for d in $DIRS gl; do
	for f in engine/"$d"/*.c engine/"$d"/*.h; do
		[ -f "$f" ] || continue
		grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*"engine/' "$f" |
			sed -E 's#^([0-9]+):.*"engine/([a-z]+)/.*#\1 \2#' > "$tmp/inc"
		while read -r line used; do
			if ! may_use "$d" "$used"; then
				echo "FAIL $f:$line includes engine/$used/ (engine/$d may use: $(allowed "$d"))"
				fail=1
			fi
		done < "$tmp/inc"
	done
done

# ---- calls between folders and modules (objects) ----------------------
objs=""
for d in $DIRS; do
	objs="$objs $(objs_of engine/"$d" | tr '\n' ' ')"
done
if [ -z "$(echo "$objs" | tr -d ' ')" ]; then
	echo "FAIL no engine objects in $BUILD (build first)"; fail=1
else
	# defined symbols: "symbol folder module"
	for o in $objs; do
		d=$(basename "$(dirname "$o")"); m=$(basename "$o" .o)
		nm -g --defined-only "$o" | awk -v d="$d" -v m="$m" 'NF == 3 { print $3, d, m }'
	done > "$tmp/defs"
	glo=$(objs_of engine/gl pic/ | tr '\n' ' ')
	for o in $objs $glo; do
		d=$(basename "$(dirname "$o")"); m=$(basename "$o" .o)
		nm -u "$o" | awk -v d="$d" -v m="$m" '{ print $NF, d, m }'
	done > "$tmp/uses"
	# "caller-folder caller-module callee-folder callee-module symbol"
	awk 'NR == FNR { df[$1] = $2; dm[$1] = $3; next }
	     ($1 in df) && dm[$1] != $3 { print $2, $3, df[$1], dm[$1], $1 }' \
		"$tmp/defs" "$tmp/uses" > "$tmp/calls"
	while read -r cd cm ed em sym; do
		if ! may_use "$cd" "$ed"; then
			echo "FAIL engine/$cd/$cm calls $sym of engine/$ed/$em (engine/$cd may use: $(allowed "$cd"))"
			fail=1
		fi
	done < "$tmp/calls"
	for d in core map sound game ui; do
		awk -v d="$d" '$1 == d && $3 == d { print $2, $4 }' "$tmp/calls" | sort -u > "$tmp/edges-$d"
		if ! tsort "$tmp/edges-$d" > /dev/null 2> "$tmp/loop-$d"; then
			echo "FAIL modules of engine/$d call each other in a loop:"
			grep -v 'input contains a loop' "$tmp/loop-$d" | sed 's/^tsort: /  /'
			fail=1
		fi
	done
	bad=$(nm $objs | grep -E ' [bBdD] ' || true)
	if [ -n "$bad" ]; then
		echo "FAIL engine has mutable file-scope state:"; echo "$bad"; fail=1
	fi
fi

# ---- portable C -------------------------------------------------------
src=""
for d in $DIRS; do src="$src $(ls engine/"$d"/*.c engine/"$d"/*.h 2>/dev/null | tr '\n' ' ')"; done
# shellcheck disable=SC2086
bad=$(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*<' $src |
	grep -vE '<(stdint|stddef|stdlib|string|errno|limits|stdbool|assert)\.h>' || true)
if [ -n "$bad" ]; then
	echo "FAIL engine includes a non-standard header:"; echo "$bad"; fail=1
fi
# shellcheck disable=SC2086
bad=$(grep -nwE 'float|double|long double' $src || true)
if [ -n "$bad" ]; then
	echo "FAIL engine uses floating point:"; echo "$bad"; fail=1
fi
bad=$(grep -rlE '#[[:space:]]*include[[:space:]]*<(GL|EGL)/' app config display audio engine input \
	systemd tests tools 2>/dev/null | grep -vx 'engine/gl/rgl.c' || true)
if [ -n "$bad" ]; then
	echo "FAIL OSMesa/GL headers outside engine/gl/rgl.c:"; echo "$bad"; fail=1
fi

# ---- platform headers only in backends --------------------------------
# Every file outside engine/ that includes a Linux, device-library or
# other platform header, the headers it may include (an extended regex on
# the name inside <>) and why. A platform header in a file not listed, or
# one its entry does not allow, fails; so does an entry whose file no
# longer includes any (the list names exactly the files that need them).
platform='alsa/|linux/|sys/ioctl|sys/kd|sys/inotify|termios|libevdev|systemd/|hidapi|gpiod|libusb|png\.h|pthread|dlfcn|xf86drm|drm'
cat > "$tmp/platform" <<'EOT'
audio/au_alsa.c	alsa/asoundlib\.h	the ALSA backend: libasound
display/dp_kms.c	drm_fourcc\.h|xf86drm\.h|xf86drmMode\.h	the DRM/KMS backend: libdrm's mode setting, dumb buffers and page flips
display/con.c	linux/kd\.h|linux/vt\.h|sys/ioctl\.h	the console under a full-screen display: graphics mode, keyboard off, VT switching
display/dp_fbdev.c	linux/fb\.h|linux/kd\.h|sys/ioctl\.h	the fbdev backend: FBIOGET_*, the console's graphics mode
display/dp_term.c	sys/ioctl\.h|termios\.h	the terminal backend: the window size, raw mode
display/shot.c	png\.h	PNG screenshots are written with libpng
input/in_evdev.c	libevdev/libevdev\.h	the evdev backend reads keyboards through libevdev
input/in_keys.c	libevdev/libevdev\.h	key names are libevdev's
input/ttyk.c	linux/input-event-codes\.h	terminal keys become the kernel's key codes
input/hidr.c	linux/input-event-codes\.h	HID usages become the kernel's key codes
input/in_hid.c	hidapi\.h|pthread\.h	the HID backend: hidapi, read in a thread (hid_read blocks; no fd to poll)
input/in_gpio.c	gpiod\.h|linux/input-event-codes\.h	the GPIO backend: libgpiod lines as key codes
input/hp.c	sys/inotify\.h|libusb\.h	hotplug notices: inotify on /dev, libusb's hotplug callbacks
app/pool.c	pthread\.h	the render thread pool
app/glr.c	dlfcn\.h	loads the OSMesa renderer plugin (arcaded-gl.so) with dlopen
systemd/svc.c	systemd/sd-daemon\.h	sd_notify through libsystemd
EOT
grep -nE "#[[:space:]]*include[[:space:]]*<($platform)" app/*.c app/*.h input/*.c input/*.h \
	audio/*.c audio/*.h display/*.c display/*.h config/*.c config/*.h systemd/*.c systemd/*.h 2>/dev/null |
	sed -E 's#^([^:]*):([0-9]+):.*<([^>]*)>.*#\1 \2 \3#' > "$tmp/pinc"
while read -r f line hdr; do
	allow=$(awk -F '\t' -v f="$f" '$1 == f { print $2 }' "$tmp/platform")
	if [ -z "$allow" ]; then
		echo "FAIL $f:$line includes <$hdr>, a platform header, but is not a backend listed in tests/check_layers.sh"; fail=1
	elif ! echo "$hdr" | grep -qxE "$allow"; then
		echo "FAIL $f:$line includes <$hdr>; its entry allows only: $allow"; fail=1
	fi
done < "$tmp/pinc"
while IFS='	' read -r f allow why; do
	if ! awk -v f="$f" '$1 == f { found = 1 } END { exit !found }' "$tmp/pinc"; then
		echo "FAIL $f is listed for platform headers ($why) but includes none"; fail=1
	fi
done < "$tmp/platform"

# ---- exported names match their files ----------------------------------
shipped=""
for d in $DIRS; do shipped="$shipped $(objs_of engine/"$d" | tr '\n' ' ')"; done
shipped="$shipped $(objs_of engine/gl pic/ | tr '\n' ' ')"
for d in app input display audio config systemd; do
	shipped="$shipped $(objs_of "$d" | tr '\n' ' ')"
done
for o in $shipped; do
	pre=$(basename "$o" .o | sed 's/_.*//')
	nm -g --defined-only "$o" | awk -v p="$pre" -v f="$o" 'NF == 3 {
		s = $3; sub(/_.*/, "", s)
		if (s != p) printf "FAIL %s exports %s (prefix %s_ expected)\n", f, $3, p }'
done > "$tmp/names"
if [ -s "$tmp/names" ]; then
	cat "$tmp/names"; fail=1
fi

[ "$fail" -eq 0 ] && echo "check-layers: engine folders call one way (core < map < sound < game < render < ui, gl), no module loops outside the renderer; engine is portable and state-free; platform headers only in backends; exported names match their files"
exit "$fail"
