#!/bin/sh
# Builds the gpio-sim kernel module for the VM tests' kernel and caches it:
# Debian's 6.1 kernels do not ship gpio-sim (simulated GPIO chips driven
# through configfs; tests/unit/test_in_gpio.c uses them), but it builds out
# of tree from Debian's own source package.
#
# usage: tests/vm/gpio-sim.sh KERNEL_DIR   (a directory from kernel.sh)
# Prints the module's path: KERNEL_DIR/gpio-sim-oot.ko.
#
# The header, kbuild and source packages are downloaded and unpacked with
# dpkg -x, not installed: nothing on the machine changes. From the source
# only drivers/gpio/gpio-sim.c, drivers/gpio/gpiolib.h and
# kernel/irq/irq_sim.c are taken; irq_sim.c is built into the module with
# its one call of the unexported irq_to_desc replaced by generic_handle_irq.
set -eu
kdir=$1
ko=$kdir/gpio-sim-oot.ko
if [ -s "$ko" ]; then
	echo "$ko"
	exit 0
fi
version=$(cat "$kdir/version")
say() { echo "vm-gpio-sim: $*" >&2; }

tmp=$(mktemp -d "$kdir/.gpio-sim.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
chmod 0777 "$tmp"
# linux-headers-VERSION names its -common and kbuild packages.
common=$(apt-cache depends "linux-headers-$version" |
	sed -n 's/^ *Depends: \(linux-headers-[^ ]*-common\)$/\1/p' | head -n 1)
kbuild=$(apt-cache depends "linux-headers-$version" |
	sed -n 's/^ *Depends: \(linux-kbuild-[0-9.]*\)$/\1/p' | head -n 1)
series=${kbuild#linux-kbuild-}
[ -n "$common" ] && [ -n "$kbuild" ] || { say "no headers package for $version"; exit 1; }
say "fetching linux-headers-$version $common $kbuild linux-source-$series"
(cd "$tmp" && apt-get download -q "linux-headers-$version" "$common" "$kbuild" \
	"linux-source-$series" >&2)
for p in "linux-headers-$version" "$common" "$kbuild"; do
	dpkg -x "$tmp/${p}"_*.deb "$tmp/root"
done
hdr=$tmp/root/usr/src/linux-headers-$version
# The headers' Makefile includes the -common tree by its absolute path.
sed -i "s|^include /usr/src/|include $tmp/root/usr/src/|" "$hdr/Makefile"

mkdir -p "$tmp/src" "$tmp/mod"
dpkg-deb --fsys-tarfile "$tmp"/linux-source-"$series"_*.deb |
	tar -x -O "./usr/src/linux-source-$series.tar.xz" | xz -dc |
	tar -x -C "$tmp/src" "linux-source-$series/drivers/gpio/gpio-sim.c" \
		"linux-source-$series/drivers/gpio/gpiolib.h" \
		"linux-source-$series/kernel/irq/irq_sim.c"
s=$tmp/src/linux-source-$series
cp "$s/drivers/gpio/gpio-sim.c" "$s/drivers/gpio/gpiolib.h" "$s/kernel/irq/irq_sim.c" "$tmp/mod/"
grep -q 'handle_simple_irq(irq_to_desc(irqnum));' "$tmp/mod/irq_sim.c" ||
	{ say "irq_sim.c changed: no handle_simple_irq(irq_to_desc(irqnum)) to replace"; exit 1; }
sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$tmp/mod/irq_sim.c"
printf 'obj-m := gpio-sim-oot.o\ngpio-sim-oot-y := gpio-sim.o irq_sim.o\n' > "$tmp/mod/Kbuild"
make -s -C "$hdr" M="$tmp/mod" modules >&2
cp "$tmp/mod/gpio-sim-oot.ko" "$ko.tmp"
mv "$ko.tmp" "$ko"
say "built $ko"
echo "$ko"
