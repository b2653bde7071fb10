#!/bin/sh
# Runs cmocka test binaries; prints each one's output and, last, one line
# "unit: P passed, F failed, S skipped" (P/F count test cases). Exit 1 if any failed.
# Usage: tests/run_unit.sh BINARY...
set -u
passed=0
failed=0
skipped=0
for t in "$@"; do
	out=$("$t" 2>&1)
	rc=$?
	printf '%s\n' "$out"
	p=$(printf '%s\n' "$out" | sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' | tail -n 1)
	f=$(printf '%s\n' "$out" | sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' | tail -n 1)
	sk=$(printf '%s\n' "$out" | sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' | tail -n 1)
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
