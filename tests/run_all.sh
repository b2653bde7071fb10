#!/bin/sh
# The whole suite, as `make test` runs it after set-up. Prints each step,
# cmocka's summaries, and last one line "N passed, N failed, N skipped" counting unit
# test cases plus every other check. A step that skipped part of itself
# counts as skipped, not passed (tests/tally.sh). Exit status 0 only if
# nothing failed.
set -u
cd "$(dirname "$0")/.."
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
LOG=build/test-logs
mkdir -p "$LOG"
# step(), the counters passed, failed, skipped and the lists failures, skips
. tests/tally.sh

count_unit() { # $1: log of run_unit.sh
	line=$(grep -E '^unit: [0-9]+ passed, [0-9]+ failed, [0-9]+ skipped$' "$1" | tail -n 1)
	if [ -z "$line" ]; then
		failed=$((failed + 1)); failures="$failures $2"; return
	fi
	p=$(echo "$line" | sed 's/unit: \([0-9]*\) passed.*/\1/')
	f=$(echo "$line" | sed 's/.* \([0-9]*\) failed.*/\1/')
	k=$(echo "$line" | sed 's/.* \([0-9]*\) skipped/\1/')
	passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + k))
	[ "$f" -eq 0 ] || failures="$failures $2"
}

unit() { # $1: name, $2: build dir, rest: make variables
	name=$1; dir=$2; shift 2
	echo "=== $name"
	if ! make --no-print-directory -j"$JOBS" BUILD="$dir" "$@" tests > "$LOG/$name-build.log" 2>&1; then
		tail -n 40 "$LOG/$name-build.log"
		echo "FAIL $name: build"; failed=$((failed + 1)); failures="$failures $name-build"
		return
	fi
	tests/run_unit.sh $(find "$dir/tests" -maxdepth 1 -type f -name "test_*" ! -name "*.d" | sort) > "$LOG/$name.log" 2>&1
	grep -E '^\[  (PASSED|FAILED|SKIPPED)  \]|^\[  FAILED  \]|^unit:|exited with' "$LOG/$name.log" | tail -n 60
	count_unit "$LOG/$name.log" "$name"
}

echo "=== build (gcc, -O2)"
if ! make --no-print-directory -j"$JOBS" all tests > "$LOG/build.log" 2>&1; then
	tail -n 60 "$LOG/build.log"
	echo "FAIL build"
	echo "0 passed, 1 failed"
	exit 1
fi
passed=$((passed + 1))

step check-tally tests/check_tally.sh
step check-layers make --no-print-directory check-layers
step check-state make --no-print-directory check-state
step check-tables make --no-print-directory check-tables
step check-levels make --no-print-directory check-levels
step check-systemd make --no-print-directory check-systemd
step check-install make --no-print-directory check-install
step check-docs make --no-print-directory check-docs
unit unit-gcc build
unit unit-asan-ubsan build/asan OPT="-O1 -g -fno-omit-frame-pointer" \
	SAN="-fsanitize=address,undefined -fno-sanitize-recover=all"
unit unit-clang build/clang CC=clang
echo "=== vm"
ARCADED_VM_ASAN=build/asan tests/vm/run.sh > "$LOG/vm.log" 2>&1
rc=$?
grep -E '^(FAIL|FIGURE)|^vm: ' "$LOG/vm.log" | tail -n 40
case $rc in
0) echo "PASS vm"; passed=$((passed + 1)) ;;
77) grep -A1 'VM TESTS SKIPPED' "$LOG/vm.log"; echo "SKIP vm"; skipped=$((skipped + 1)); skips="$skips vm" ;;
*) echo "FAIL vm (log: $LOG/vm.log)"; failed=$((failed + 1)); failures="$failures vm" ;;
esac
# The Debian package, its life cycle in a clean chroot, the cabinet image
# and its boots with power cuts (docs/packaging.md).
step deb scripts/deb.sh
step package-lifecycle tests/pkg/run.sh build/deb/arcaded.deb
step image scripts/image.sh build/deb/arcaded.deb build/image
echo "=== image-powercuts"
if [ -s build/image/arcaded.img ]; then
	POWERCUTS=${POWERCUTS:-20} tests/image/run.sh build/image/arcaded.img > "$LOG/image-powercuts.log" 2>&1
	rc=$?
else
	echo "no image (see the image step)" > "$LOG/image-powercuts.log"
	rc=1
fi
grep -E '^(PASS|FAIL|FIGURE)|^image-test: ' "$LOG/image-powercuts.log" | tail -n 40
case $rc in
0) echo "PASS image-powercuts"; passed=$((passed + 1)) ;;
77) echo "SKIP image-powercuts"; skipped=$((skipped + 1)) ;;
*) echo "FAIL image-powercuts (log: $LOG/image-powercuts.log)"; failed=$((failed + 1)); failures="$failures image-powercuts" ;;
esac
step build-O0 make --no-print-directory -j"$JOBS" BUILD=build/O0 OPT="-O0 -g" all
step script-tests tests/script/run.sh build/arcaded
step sound tests/sound/run.sh build/arcaded
step replay-tests tests/replay/run.sh build/arcaded build/O0/arcaded
step powercut tests/powercut/run.sh
step xbuild tests/xbuild/run.sh build/arcaded
step crosscheck tests/crosscheck/run.sh build
step soak tests/soak/run.sh build/arcaded
step terminal-preview tests/term/run.sh build/arcaded
step flight-recorder tests/flight/run.sh build/arcaded
step hostile-maps tests/hostile/run.sh build/arcaded
step fuzz make --no-print-directory -j"$JOBS" fuzz FUZZ_SECONDS="${FUZZ_SECONDS:-20}"

echo
[ -n "$failures" ] && echo "failed:$failures"
[ -n "$skips" ] && echo "skipped steps (not counted as passed):$skips"
[ "$skipped" -gt 0 ] && echo "skipped (not counted as passed): $skipped in all: the steps above and unit test cases that need devices this machine lacks; see the logs in $LOG"
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
