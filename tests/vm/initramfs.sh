#!/bin/sh
# Builds the VM tests' initramfs: busybox (static), tests/vm/init, and the
# kernel modules init needs to reach the 9p shares and build the overlay,
# with their dependencies in load order (from depmod's modules.dep).
#
# usage: tests/vm/initramfs.sh KERNEL_DIR OUT.cpio
# The archive is left uncompressed: under emulation unpacking costs more
# than the copy.
set -eu
kdir=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
version=$(cat "$kdir/version")
mods=$kdir/root/lib/modules/$version
# busybox-static's binary: the initramfs has no libc.
bb=/bin/busybox
[ -x "$bb" ] || { echo "initramfs: $bb missing (package busybox-static)" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/bin" "$tmp/mod" "$tmp/proc" "$tmp/sys" "$tmp/dev" "$tmp/ro" "$tmp/rw"
cp "$bb" "$tmp/bin/busybox"
# Every applet except busybox itself (a self-link loops: ELOOP at exec).
for a in $("$bb" --list); do
	[ "$a" = busybox ] || ln -s busybox "$tmp/bin/$a"
done
cp "$here/init" "$tmp/init"
chmod 0755 "$tmp/init"

# Load order: each wanted module after its dependencies. modules.dep lists
# a module's dependencies with the deepest last, so load them in reverse.
: > "$tmp/modules.order"
add() { # path relative to the modules directory
	grep -qx "$(basename "$1")" "$tmp/modules.order" && return 0
	cp "$mods/$1" "$tmp/mod/"
	basename "$1" >> "$tmp/modules.order"
}
for m in virtio_pci 9pnet_virtio 9p overlay; do
	line=$(grep -E "/$m\.ko(\.xz|\.zst)?:" "$mods/modules.dep" |
		grep -E "(^|/)$(echo "$m" | sed 's/[-_]/[-_]/g')\.ko" | head -n 1)
	[ -n "$line" ] || { echo "initramfs: module $m not in modules.dep" >&2; exit 1; }
	path=${line%%:*}
	deps=${line#*:}
	for d in $(echo $deps | tr ' ' '\n' | tac); do
		add "$d"
	done
	add "$path"
done
(cd "$tmp" && find . | LC_ALL=C sort | cpio -o -H newc --quiet) > "$out.tmp"
mv "$out.tmp" "$out"
