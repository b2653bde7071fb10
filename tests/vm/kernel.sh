#!/bin/sh
# Fetches Debian's kernel for the VM tests and caches it.
#
# usage: tests/vm/kernel.sh CACHE_DIR
# Prints the kernel directory on stdout: DIR/vmlinux (uncompressed ELF, boots
# by PVH without firmware or decompression), DIR/vmlinuz (bzImage, for VESA
# modes set by vga=, which need the real-mode set-up code), DIR/version, and
# DIR/root/lib/modules/VERSION with depmod's indexes.
#
# The version is what the linux-image-amd64 metapackage depends on, or
# $ARCADED_VM_KERNEL (e.g. 6.1.0-56-amd64). A cached kernel is used as is.
set -eu
cache=$1
mkdir -p "$cache"

say() { echo "vm-kernel: $*" >&2; }

version=${ARCADED_VM_KERNEL:-}
if [ -z "$version" ]; then
	deps=$(apt-cache depends linux-image-amd64 2>/dev/null || true)
	if ! echo "$deps" | grep -q 'Depends: linux-image-'; then
		say "apt-cache does not know linux-image-amd64; running apt-get update"
		apt-get update -qq >&2
		deps=$(apt-cache depends linux-image-amd64)
	fi
	version=$(echo "$deps" | sed -n 's/^ *Depends: linux-image-\([0-9][^ ]*\)$/\1/p' | head -n 1)
fi
[ -n "$version" ] || { say "cannot tell which kernel linux-image-amd64 depends on"; exit 1; }

dir=$cache/kernel-$version
if [ -f "$dir/done" ]; then
	echo "$dir"
	exit 0
fi

say "fetching linux-image-$version"
tmp=$(mktemp -d "$cache/.fetch.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
# apt drops privileges to _apt for downloads into a directory it can write.
chmod 0777 "$tmp"
(cd "$tmp" && apt-get download -q "linux-image-$version" >&2)
dpkg -x "$tmp"/linux-image-"$version"_*.deb "$tmp/root"

# vmlinux: the first xz stream in the bzImage that unpacks to an ELF file.
bz=$tmp/root/boot/vmlinuz-$version
for off in $(LC_ALL=C grep -obUaP '\xFD7zXZ\x00' "$bz" | cut -d: -f1); do
	tail -c +$((off + 1)) "$bz" | xz -dc 2>/dev/null > "$tmp/vmlinux" || true
	if [ "$(head -c 4 "$tmp/vmlinux" | od -An -c | tr -d ' ')" = '177ELF' ]; then
		break
	fi
	rm -f "$tmp/vmlinux"
done
[ -s "$tmp/vmlinux" ] || { say "no xz-compressed ELF kernel inside $bz"; exit 1; }

depmod -b "$tmp/root" "$version"
mkdir -p "$tmp/out"
mv "$tmp/vmlinux" "$tmp/out/vmlinux"
mv "$bz" "$tmp/out/vmlinuz"
mv "$tmp/root" "$tmp/out/root"
echo "$version" > "$tmp/out/version"
touch "$tmp/out/done"
rm -rf "$dir"
mv "$tmp/out" "$dir"
say "cached in $dir"
echo "$dir"
