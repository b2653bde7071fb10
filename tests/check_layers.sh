#!/bin/sh
# Proves the layering rules of STYLE.md on the sources:
# - engine/ includes only C standard headers and its own headers;
# - engine/ has no floating point and no mutable file-scope state
#   (checked on the compiled objects: no .data/.bss symbols);
# - engine/gl/ (the OSMesa renderer, docs/crosscheck.md) is outside the two
#   rules above (the globs are engine/*): it has floating point and is the
#   only code that includes OSMesa or GL headers, in engine/gl/r_gl.c alone;
# - outside engine/, only backend files include Linux or device-library
#   headers.
set -u
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
fail=0

bad=$(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*<' engine/*.c engine/*.h |
	grep -vE '<(stdint|stddef|stdlib|string|errno|limits|stdbool|assert)\.h>' || true)
if [ -n "$bad" ]; then
	echo "FAIL engine includes a non-standard header:"; echo "$bad"; fail=1
fi
bad=$(grep -nwE 'float|double|long double' engine/*.c engine/*.h || true)
if [ -n "$bad" ]; then
	echo "FAIL engine uses floating point:"; echo "$bad"; fail=1
fi
objs=$(ls "$BUILD"/engine/*.o 2>/dev/null)
if [ -z "$objs" ]; then
	echo "FAIL no engine objects in $BUILD (build first)"; fail=1
else
	bad=$(nm "$BUILD"/engine/*.o | grep -E ' [bBdD] ' || true)
	if [ -n "$bad" ]; then
		echo "FAIL engine has mutable file-scope state:"; echo "$bad"; fail=1
	fi
fi
bad=$(grep -rlE '#[[:space:]]*include[[:space:]]*<(GL|EGL)/' app config display engine input \
	systemd tests tools 2>/dev/null | grep -vx 'engine/gl/r_gl.c' || true)
if [ -n "$bad" ]; then
	echo "FAIL OSMesa/GL headers outside engine/gl/r_gl.c:"; echo "$bad"; fail=1
fi
# Backends (one file each) are the only users of kernel and device headers.
allowed='^(display/dp_fbdev\.c|display/dp_term\.c|input/in_evdev\.c|input/in_tty\.c|input/in_ttykeys\.c|input/in_keys\.c|input/hid_dec\.c|input/in_hid\.c|input/in_gpio\.c|systemd/svc\.c)$'
for f in $(grep -lE '#[[:space:]]*include[[:space:]]*<(linux/|sys/ioctl|sys/kd|termios|libevdev|systemd/|hidapi|gpiod)' \
	app/*.c app/*.h input/*.c input/*.h display/*.c display/*.h config/*.c config/*.h 2>/dev/null); do
	if ! echo "$f" | grep -qE "$allowed"; then
		echo "FAIL $f includes a platform header but is not a backend"; fail=1
	fi
done
[ "$fail" -eq 0 ] && echo "check-layers: engine is portable and state-free; platform headers only in backends"
exit "$fail"
