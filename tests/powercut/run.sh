#!/bin/sh
# Power-cut test of the state files (config/st.c), issue 7 item 3:
#  1. 1000 times, a process saving a state file over and over is SIGKILLed
#     after a random delay (0..3 ms, seeded); each time the state must load
#     with a valid checksum and hold the last save known complete or the
#     one after it: never torn, never older;
#     the same for a plain file written by st_write_plain (the wizard's
#     bindings.ini): old or new, whole;
#  2. on a full file system (a 96 KiB tmpfs in a private mount namespace;
#     skipped loudly where that cannot be made) a failing save returns
#     ENOSPC and the previous state still loads.
# Usage: tests/powercut/run.sh [RUNS [SEED]]   (CC picks the compiler)
set -u
cd "$(dirname "$0")/../.."
RUNS=${1:-1000}
SEED=${2:-20261121}
CC=${CC:-cc}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

$CC -std=c11 -O2 -g -Wall -Wextra -Werror -I. -D_GNU_SOURCE \
	tests/powercut/stsave.c config/st.c input/io.c input/txt.c -o "$tmp/stsave" || exit 1
mkdir "$tmp/state"
if "$tmp/stsave" kill "$tmp/state" "$RUNS" "$SEED" 3000; then
	echo "PASS power-cut kills"
else
	echo "FAIL power-cut kills"; fail=1
fi

mkdir "$tmp/plain"
if "$tmp/stsave" kill-plain "$tmp/plain" "$RUNS" "$SEED" 3000; then
	echo "PASS power-cut kills of the plain file (bindings.ini)"
else
	echo "FAIL power-cut kills of the plain file"; fail=1
fi

mkdir "$tmp/full"
if [ "$(id -u)" = 0 ] && unshare -m sh -c "mount -t tmpfs -o size=96k none '$tmp/full'" 2>/dev/null; then
	if unshare -m sh -c "mount -t tmpfs -o size=96k none '$tmp/full' && '$tmp/stsave' fill '$tmp/full'"; then
		echo "PASS full file system loses nothing"
	else
		echo "FAIL full file system"; fail=1
	fi
else
	echo "SKIP full file system: cannot mount a tmpfs here (needs root and mount namespaces);"
	echo "     the unit test test_st covers a short write through RLIMIT_FSIZE instead"
fi
exit "$fail"
