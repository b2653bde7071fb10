#!/bin/sh
# Runs cmocka test binaries; prints each one's output (in the order given)
# and, last, one line "unit: P passed, F failed, S skipped" (P/F count test
# cases). Exit 1 if any failed.
# Usage: tests/run_unit.sh BINARY...
# JOBS binaries run at once (tests/pool.sh; default: the number of cores):
# each test makes its own temporary files (mkdtemp), so they may. The
# longest one (test_sim_hash) then runs beside the others, not after them.
set -u
. "$(dirname "$0")/pool.sh"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
unit_one() { "$1"; }
pool_run "$out" unit_one "$@"
passed=0
failed=0
skipped=0
j=0
for t in "$@"; do
	j=$((j + 1))
	cat "$out/$j.log"
	rc=$(cat "$out/$j.rc" 2>/dev/null || echo 1)
	p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$out/$j.log" | tail -n 1)
	f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$out/$j.log" | tail -n 1)
	sk=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$out/$j.log" | tail -n 1)
	passed=$((passed + ${p:-0}))
	skipped=$((skipped + ${sk:-0}))
	if [ "$rc" -ne 0 ] && [ -z "$f" ]; then
		# crashed or aborted before cmocka could count
		echo "$t: exited with status $rc"
		f=1
	fi
	failed=$((failed + ${f:-0}))
done
echo "unit: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
