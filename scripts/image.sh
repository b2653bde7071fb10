#!/bin/sh
# `make image`: the cabinet's bootable x86-64 disk image, built from Debian
# 12 packages by mmdebstrap with the arcaded package installed, assembled
# with mke2fs -d, mkfs.vfat + mtools and sfdisk on plain files: no loop
# device, no mount (docs/packaging.md).
#
# usage: scripts/image.sh ARCADED.deb OUTDIR
# Writes OUTDIR/arcaded.img (GPT: ESP with systemd-boot, kernel and
# initramfs; read-only ext4 root; ext4 state partition for
# /var/lib/arcaded, grown at the first boot), OUTDIR/manifest.txt (the
# image's packages) and OUTDIR/info.txt (sizes, build time).
#
# Cached in $ARCADED_IMAGE_CACHE (default ~/.cache/arcaded-image), keyed by
# the package, debian/image/, this script and the apt sources: a rerun with
# the same inputs copies the cached image. The downloaded .debs are kept
# there too (essential ones included), so a rebuild after a change
# downloads nothing new.
# Environment: ARCADED_IMAGE_SOURCES (apt sources for mmdebstrap, default
# this machine's Debian ones), ARCADED_IMAGE_SUITE (default bookworm).
set -eu
cd "$(dirname "$0")/.."
top=$(pwd)
deb=$(realpath "$1")
out=$2
cache=${ARCADED_IMAGE_CACHE:-${XDG_CACHE_HOME:-${HOME:-/root}/.cache}/arcaded-image}
suite=${ARCADED_IMAGE_SUITE:-bookworm}
sources=${ARCADED_IMAGE_SOURCES:-}
if [ -z "$sources" ]; then
	for f in /etc/apt/sources.list.d/debian.sources /etc/apt/sources.list; do
		[ -s "$f" ] && { sources=$f; break; }
	done
fi
[ -n "$sources" ] || { echo "image: no apt sources (set ARCADED_IMAGE_SOURCES)" >&2; exit 1; }
say() { echo "image: $*"; }
t0=$(date +%s)

[ "$(id -u)" = 0 ] || { echo "image: mmdebstrap runs as root here (root mode)" >&2; exit 1; }
for t in mmdebstrap mke2fs mkfs.vfat mcopy sfdisk; do
	command -v "$t" >/dev/null || { echo "image: $t missing (scripts/setup.sh test)" >&2; exit 1; }
done

key=$( (echo "$suite"; cat "$deb" "$sources" scripts/image.sh $(find debian/image -type f | sort)) | sha256sum | cut -c1-16)
mkdir -p "$cache/debs" "$out"
if [ -s "$cache/img-$key/arcaded.img" ]; then
	cp --sparse=always "$cache/img-$key/arcaded.img" "$out/arcaded.img"
	cp "$cache/img-$key/manifest.txt" "$cache/img-$key/info.txt" "$out/"
	say "cached image $key copied in $(($(date +%s) - t0)) s"
	cat "$out/info.txt"
	exit 0
fi

tmp=$(mktemp -d "$cache/.build.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
. debian/image/ids.sh
R=$tmp/root

# The system: Debian's minimal base, systemd, udev, the kernel and its
# initramfs, systemd-boot's EFI program, then the package, installed by apt
# inside the new system (which resolves its dependencies; dpkg there must
# see the file, hence the copy). No documentation, manual pages or
# translations.
say "mmdebstrap $suite (log: $out/mmdebstrap.log)"
mmdebstrap --variant=minbase --mode=root \
	--include=systemd,systemd-sysv,udev,kmod,linux-image-amd64,initramfs-tools,zstd,systemd-boot-efi,alsa-utils \
	--dpkgopt='path-exclude=/usr/share/doc/*' --dpkgopt='path-include=/usr/share/doc/*/copyright' \
	--dpkgopt='path-exclude=/usr/share/man/*' --dpkgopt='path-exclude=/usr/share/info/*' \
	--dpkgopt='path-exclude=/usr/share/locale/*' --dpkgopt='path-include=/usr/share/locale/locale.alias' \
	--skip=download/empty --skip=essential/unlink \
	--setup-hook='mkdir -p "$1/var/cache/apt/archives"' \
	--setup-hook="cp -a '$cache/debs/.' \"\$1/var/cache/apt/archives/\"" \
	--setup-hook="mkdir -p \"\$1/etc/initramfs-tools/conf.d\" \"\$1/etc/initramfs-tools/hooks\"" \
	--setup-hook="cp '$top/debian/image/initramfs.conf' \"\$1/etc/initramfs-tools/conf.d/arcaded-image\"" \
	--setup-hook="cp '$top/debian/image/initramfs-hook' \"\$1/etc/initramfs-tools/hooks/arcaded-image\"" \
	--customize-hook="cp '$deb' \"\$1/tmp/arcaded.deb\"" \
	--customize-hook='chroot "$1" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends /tmp/arcaded.deb' \
	--customize-hook='rm "$1/tmp/arcaded.deb"' \
	--customize-hook="cp -a \"\$1/var/cache/apt/archives/.\" '$cache/debs/'" \
	--customize-hook='rm -f "$1"/var/cache/apt/archives/*.deb' \
	--customize-hook="chroot \"\$1\" dpkg-query -W -f='\${Package} \${Version}\\n' > '$tmp/manifest.txt'" \
	--customize-hook="'$top/debian/image/customize.sh' \"\$1\"" \
	"$suite" "$R" "$sources" < /dev/null > "$out/mmdebstrap.log" 2>&1 ||
	{ tail -n 30 "$out/mmdebstrap.log"; echo "image: mmdebstrap failed" >&2; exit 1; }
t_strap=$(date +%s)
grep -q '^arcaded ' "$tmp/manifest.txt" || { echo "image: arcaded is not installed" >&2; exit 1; }

# The ESP: systemd-boot as the removable-media loader, one entry that boots
# at once (timeout 0; a key held at power-on shows the menu), the kernel and
# the initramfs.
kver=$(ls "$R/boot" | sed -n 's/^vmlinuz-//p' | sort -V | tail -n 1)
[ -n "$kver" ] || { echo "image: no kernel in /boot" >&2; exit 1; }
mkdir -p "$tmp/esp/EFI/BOOT" "$tmp/esp/loader/entries" "$tmp/esp/arcaded"
cp "$R/usr/lib/systemd/boot/efi/systemd-bootx64.efi" "$tmp/esp/EFI/BOOT/BOOTX64.EFI"
mv "$R/boot/vmlinuz-$kver" "$tmp/esp/arcaded/vmlinuz"
mv "$R/boot/initrd.img-$kver" "$tmp/esp/arcaded/initrd.img"
printf 'default arcaded.conf\ntimeout 0\neditor no\nconsole-mode keep\n' > "$tmp/esp/loader/loader.conf"
# Quiet: no kernel, initramfs or systemd text and no cursor on the screen.
cmdline="root=PARTUUID=$ROOT_UUID ro quiet loglevel=0 systemd.show_status=0 udev.log_level=0"
cmdline="$cmdline vt.global_cursor_default=0 systemd.gpt_auto=0 panic=10"
printf 'title arcaded cabinet\nlinux /arcaded/vmlinuz\ninitrd /arcaded/initrd.img\noptions %s\n' \
	"$cmdline" > "$tmp/esp/loader/entries/arcaded.conf"

mib() { du -s -B1M --apparent-size "$1" | cut -f1; }
esp_mib=$(($(mib "$tmp/esp") * 5 / 4 + 16))
[ "$esp_mib" -ge 64 ] || esp_mib=64
truncate -s "${esp_mib}M" "$tmp/esp.img"
mkfs.vfat -F 32 -S 512 -s 1 -n ARCADED -i 61726364 "$tmp/esp.img" > /dev/null
(cd "$tmp/esp" && find . -mindepth 1 -type d | sed 's|^\./||' | sort) | while read -r d; do
	mmd -i "$tmp/esp.img" "::/$d"
done
(cd "$tmp/esp" && find . -type f | sed 's|^\./||') | while read -r f; do
	mcopy -i "$tmp/esp.img" "$tmp/esp/$f" "::/$f"
done

# The root: read-only, never written, so a small journal only for whoever
# mounts it writable by hand.
root_mib=$(($(du -s -B1M "$R" | cut -f1) * 11 / 10 + 48))
mke2fs -q -t ext4 -b 4096 -i 8192 -J size=4 -L arcaded-root -U "$ROOT_UUID" \
	-E root_owner=0:0 -d "$R" "$tmp/root.img" "${root_mib}M"

# The state partition: the daemon's state directory, owned by its user.
# Small in the image; grown to fill the disk at the first boot. resize=
# reserves room in the group descriptor table for online growth to 2 TiB.
uid=$(awk -F: '$1 == "arcaded" { print $3 }' "$R/etc/passwd")
gid=$(awk -F: '$1 == "arcaded" { print $3 }' "$R/etc/group")
[ -n "$uid" ] && [ -n "$gid" ] || { echo "image: no arcaded user in the image" >&2; exit 1; }
state_mib=64
mkdir -m 0750 "$tmp/state"
mke2fs -q -t ext4 -b 4096 -J size=16 -L arcaded-state -U "$STATE_UUID" -E root_owner="$uid:$gid",resize=536870912 \
	-d "$tmp/state" "$tmp/state.img" "${state_mib}M" > /dev/null

# GPT on the image file: ESP, root (the x86-64 root type), state (generic
# Linux data, the type the repart.d entry grows). 1 MiB before, 1 MiB after
# for the backup table.
total_mib=$((1 + esp_mib + root_mib + state_mib + 1))
img=$tmp/arcaded.img
truncate -s "${total_mib}M" "$img"
sfdisk --quiet --no-reread --no-tell-kernel "$img" <<PT
label: gpt
label-id: $DISK_UUID
first-lba: 2048
start=2048, size=$((esp_mib * 2048)), type=C12A7328-F81F-11D2-BA4B-00A0C93EC93B, uuid=$ESP_UUID, name="arcaded-esp"
start=$(((1 + esp_mib) * 2048)), size=$((root_mib * 2048)), type=4F68BCE3-E8CD-4DB1-96E7-FBCAF984B709, uuid=$ROOT_UUID, name="arcaded-root"
start=$(((1 + esp_mib + root_mib) * 2048)), size=$((state_mib * 2048)), type=0FC63DAF-8483-4772-8E79-3D69D8477DE4, uuid=$STATE_UUID, name="arcaded-state"
PT
dd if="$tmp/esp.img" of="$img" bs=1M seek=1 conv=notrunc,sparse status=none
dd if="$tmp/root.img" of="$img" bs=1M seek=$((1 + esp_mib)) conv=notrunc,sparse status=none
dd if="$tmp/state.img" of="$img" bs=1M seek=$((1 + esp_mib + root_mib)) conv=notrunc,sparse status=none
t_end=$(date +%s)

{
	echo "image: arcaded.img $total_mib MiB (ESP $esp_mib, root $root_mib, state $state_mib MiB);" \
		"kernel $kver; $(wc -l < "$tmp/manifest.txt") packages;" \
		"$(grep '^arcaded ' "$tmp/manifest.txt")"
	echo "image: built in $((t_end - t0)) s (mmdebstrap $((t_strap - t0)) s), key $key"
} > "$tmp/info.txt"
[ "$total_mib" -le 1024 ] || { cat "$tmp/info.txt"; echo "image: larger than 1 GiB" >&2; exit 1; }
mkdir -p "$cache/img-$key"
cp --sparse=always "$img" "$cache/img-$key/arcaded.img"
cp "$tmp/manifest.txt" "$tmp/info.txt" "$cache/img-$key/"
# Older images of this cache are of no more use.
find "$cache" -maxdepth 1 -name 'img-*' ! -name "img-$key" -exec rm -rf {} +
mv "$img" "$out/arcaded.img"
cp "$tmp/manifest.txt" "$tmp/info.txt" "$out/"
cat "$out/info.txt"
