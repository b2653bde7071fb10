#!/bin/sh
# Installs the Debian 12 packages that arcaded's build, run and tests need,
# when any is missing: one `apt-get update`, then one install. Run by
# `make run` and `make test`; safe to run again (it then does nothing).
set -eu

PACKAGES="
build-essential
pkg-config
clang
libevdev-dev
libhidapi-dev
libgpiod-dev
libusb-1.0-0-dev
libasound2-dev
libpng-dev
libosmesa6-dev
libsystemd-dev
libcmocka-dev
systemd
udev
tmux
valgrind
freedoom
gcc-aarch64-linux-gnu
libc6-dev-arm64-cross
qemu-user-static
qemu-system-x86
busybox-static
cpio
kmod
xz-utils
"

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
