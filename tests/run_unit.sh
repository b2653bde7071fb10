#!/bin/sh
# Runs cmocka test binaries; prints each one's output (in the order given)
# and, last, one line "unit: P passed, F failed, S skipped" (P/F count test
# cases). Exit 1 if any failed.
# Usage: tests/run_unit.sh BINARY...
# JOBS binaries run at once (default: the number of cores): each test makes
# its own temporary files (mkdtemp), so they may. The longest one
# (test_sim_hash) then runs beside all the others instead of after them.
set -u
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 1)}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
i=0
for t in "$@"; do
	i=$((i + 1))
	printf '%s\n' "$t" > "$out/$i.name"
done
# each worker takes the next binary no other has claimed (mkdir is atomic),
# so a long one never holds up a queue of short ones behind it
worker() {
	j=1
	while [ "$j" -le "$i" ]; do
		if mkdir "$out/$j.claim" 2>/dev/null; then
			t=$(cat "$out/$j.name")
			"$t" > "$out/$j.log" 2>&1
			echo $? > "$out/$j.rc"
		fi
		j=$((j + 1))
	done
}
w=1
while [ "$w" -le "$JOBS" ]; do
	worker &
	w=$((w + 1))
done
wait
passed=0
failed=0
skipped=0
j=1
while [ "$j" -le "$i" ]; do
	t=$(cat "$out/$j.name")
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
	j=$((j + 1))
done
echo "unit: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
