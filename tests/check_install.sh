#!/bin/sh
# `make install DESTDIR=...` lays out the binary, the unit (with its
# ExecStart pointing at the installed binary), the udev rules, sysusers and
# tmpfiles entries and the default configuration.
set -u
cd "$(dirname "$0")/.."
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
make --no-print-directory install DESTDIR="$root" PREFIX=/usr >/dev/null || { echo "FAIL make install"; exit 1; }
fail=0
for f in usr/bin/arcaded lib/systemd/system/arcaded.service lib/udev/rules.d/70-arcaded.rules \
	usr/lib/sysusers.d/arcaded.conf usr/lib/tmpfiles.d/arcaded.conf etc/arcaded/arcaded.ini \
	etc/arcaded/bindings.ini usr/lib/arcaded/arcaded-gl.so; do
	[ -s "$root/$f" ] || { echo "FAIL missing $f"; fail=1; }
done
[ -x "$root/usr/bin/arcaded" ] || { echo "FAIL usr/bin/arcaded is not executable"; fail=1; }
grep -q '^ExecStart=/usr/bin/arcaded' "$root/lib/systemd/system/arcaded.service" ||
	{ echo "FAIL ExecStart does not point at /usr/bin/arcaded"; fail=1; }
grep -q '@BINDIR@' "$root/lib/systemd/system/arcaded.service" && { echo "FAIL @BINDIR@ left in the unit"; fail=1; }
"$root/usr/bin/arcaded" --version >/dev/null || { echo "FAIL installed binary does not run"; fail=1; }
# The OSMesa renderer is a plugin: the daemon maps no Mesa (nor its LLVM)
# unless --renderer gl asks for it, and then loads it (here from the build
# tree, next to the binary).
bin=${BUILD:-build}/arcaded
st=$(mktemp -d)
out=$("$bin" --config-dir /nonexistent --state-dir "$st" --display null --set input.evdev=none \
	--set input.hid=none --play --renderer gl --ticks 3 2>&1)
echo "$out" | grep -q '^arcaded: renderer: gl (.*arcaded-gl.so)$' ||
	{ echo "FAIL --renderer gl did not load the plugin: $(echo "$out" | grep -m 2 'renderer')"; fail=1; }
maps=$("$bin" --config-dir /nonexistent --state-dir "$st" --display null --set input.evdev=none \
	--set input.hid=none --ticks 30 > /dev/null 2>&1 & p=$!; sleep 0.3; cat "/proc/$p/maps" 2>/dev/null; wait "$p")
echo "$maps" | grep -q -i -e osmesa -e libllvm &&
	{ echo "FAIL the daemon maps OSMesa or LLVM without --renderer gl"; fail=1; }
echo "$maps" | grep -q 'arcaded' || { echo "FAIL could not read the daemon's maps"; fail=1; }
rm -rf "$st"
[ "$fail" -eq 0 ] && echo "check-install: binary, GL plugin, unit, udev rules, sysusers, tmpfiles and /etc/arcaded in place; --renderer gl loads the plugin, the daemon maps no Mesa without it"
exit "$fail"
