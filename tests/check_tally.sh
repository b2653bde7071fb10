#!/bin/sh
# Test of the suite's tally (tests/tally.sh, issue 13 item 20): fake steps
# that pass, skip part of themselves ("SKIP " or "SKIP:" lines, exit 0),
# skip as a whole (exit 77) and fail must be counted 1 passed, 3 skipped,
# 1 failed: a step that skipped part of itself is never counted as passed.
set -u
cd "$(dirname "$0")/.."
LOG=$(mktemp -d)
trap 'rm -rf "$LOG"' EXIT
. tests/tally.sh
step fake-pass sh -c 'echo all good; exit 0' >/dev/null
step fake-part-skipped sh -c 'echo "SKIP aarch64: not run"; echo done; exit 0' >/dev/null
step fake-part-skipped-colon sh -c 'echo "SKIP: needs root"; exit 0' >/dev/null
step fake-skipped sh -c 'echo "nothing to do here"; exit 77' >/dev/null
step fake-fail sh -c 'echo "FAIL something"; exit 1' >/dev/null
step fake-says-skip-mid-line sh -c 'echo "a NOTE that says SKIP is not a skip"; exit 0' >/dev/null
want="2 passed, 3 skipped, 1 failed; skipped: fake-part-skipped fake-part-skipped-colon fake-skipped; failed: fake-fail"
got="$passed passed, $skipped skipped, $failed failed; skipped:$skips; failed:$failures"
if [ "$got" = "$want" ]; then
	echo "PASS check-tally: $got"
else
	echo "FAIL check-tally: $got"
	echo "     expected: $want"
	exit 1
fi
