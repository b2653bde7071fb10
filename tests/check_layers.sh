#!/bin/sh
# Proves the layering rules of STYLE.md on the sources:
# - engine/ includes only C standard headers and its own headers;
# - engine/ has no floating point and no mutable file-scope state
#   (checked on the compiled objects: no .data/.bss symbols);
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
