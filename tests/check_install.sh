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
	etc/arcaded/bindings.ini; do
	[ -s "$root/$f" ] || { echo "FAIL missing $f"; fail=1; }
done
[ -x "$root/usr/bin/arcaded" ] || { echo "FAIL usr/bin/arcaded is not executable"; fail=1; }
grep -q '^ExecStart=/usr/bin/arcaded' "$root/lib/systemd/system/arcaded.service" ||
	{ echo "FAIL ExecStart does not point at /usr/bin/arcaded"; fail=1; }
grep -q '@BINDIR@' "$root/lib/systemd/system/arcaded.service" && { echo "FAIL @BINDIR@ left in the unit"; fail=1; }
"$root/usr/bin/arcaded" --version >/dev/null || { echo "FAIL installed binary does not run"; fail=1; }
[ "$fail" -eq 0 ] && echo "check-install: binary, unit, udev rules, sysusers, tmpfiles and /etc/arcaded in place"
exit "$fail"
