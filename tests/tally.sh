# Sourced by tests/run_all.sh (and tests/check_tally.sh, its test): the
# suite's counters and step(), which runs one step and counts it. LOG
# must name a folder for the steps' logs.
passed=0
failed=0
skipped=0
failures=""
skips=""

# A step's outcome, by the convention of docs/testing.md ("Skipped is not
# passed"): exit 0 passes, unless the step printed a line starting "SKIP "
# or "SKIP:" (it left part of itself untested): then it counts as skipped,
# not passed, and those lines are shown; exit 77 is skipped as a whole;
# any other exit fails.
step() { # $1: name; rest: command. Counts as one check.
	name=$1; shift
	echo "=== $name"
	"$@" > "$LOG/$name.log" 2>&1
	rc=$?
	if [ "$rc" -eq 0 ] && ! grep -qE '^SKIP[: ]' "$LOG/$name.log"; then
		tail -n 3 "$LOG/$name.log"
		echo "PASS $name"; passed=$((passed + 1))
	elif [ "$rc" -eq 0 ] || [ "$rc" -eq 77 ]; then
		grep -E '^SKIP[: ]' "$LOG/$name.log" | head -n 10
		echo "SKIP $name: part of it did not run (log: $LOG/$name.log)"
		skipped=$((skipped + 1)); skips="$skips $name"
	else
		tail -n 40 "$LOG/$name.log"
		echo "FAIL $name (log: $LOG/$name.log)"; failed=$((failed + 1)); failures="$failures $name"
	fi
}
