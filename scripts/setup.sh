#!/bin/sh
# Installs the Debian 12 packages that arcaded's build, run and tests need,
# when any is missing: one `apt-get update`, then one install. Safe to run
# again (it then does nothing).
#   scripts/setup.sh        what building and running need (`make run`)
#   scripts/setup.sh test   that and what the tests, the package and the
#                           image need (`make test`, `make deb`, `make image`)
set -eu

PACKAGES="
build-essential
pkg-config
libevdev-dev
libhidapi-dev
libgpiod-dev
libusb-1.0-0-dev
libasound2-dev
alsa-utils
libdrm-dev
libpng-dev
libosmesa6-dev
libsystemd-dev
systemd
udev
freedoom
"
TEST_PACKAGES="
python3
clang
libcmocka-dev
tmux
valgrind
gcc-aarch64-linux-gnu
libc6-dev-arm64-cross
qemu-user-static
qemu-system-x86
busybox-static
cpio
kmod
xz-utils
debhelper
lintian
mmdebstrap
ovmf
mtools
dosfstools
fdisk
e2fsprogs
"
case ${1:-run} in
run) ;;
test) PACKAGES="$PACKAGES $TEST_PACKAGES" ;;
*) echo "usage: scripts/setup.sh [run|test]" >&2; exit 2 ;;
esac

missing=""
for p in $PACKAGES; do
	if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
		missing="$missing $p"
	fi
done

if [ -z "$missing" ]; then
	exit 0
fi

echo "setup: installing:$missing"
SUDO=""
if [ "$(id -u)" != 0 ]; then
	SUDO="sudo"
fi
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -qq
# shellcheck disable=SC2086
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
