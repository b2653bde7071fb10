# Sourced by tests/run_unit.sh and tests/fuzz/run.sh: runs one command per
# item, JOBS at once (default: the number of cores), for the steps whose
# items are independent and would otherwise leave the second core idle.
#
# pool_run DIR CMD ITEM...: runs `CMD ITEM` for every ITEM (CMD may be a
# shell function of the caller). Each worker takes the next item no other
# has claimed (mkdir DIR/K.claim is atomic), so a long item never holds up
# a queue of short ones behind it. Item K (from 1, in the order given)
# writes its output to DIR/K.log and its exit status to DIR/K.rc; the
# caller reports them in that order once pool_run returns.
pool_run() {
	pool_dir=$1
	pool_cmd=$2
	shift 2
	pool_w=0
	while [ "$pool_w" -lt "${JOBS:-$(nproc 2>/dev/null || echo 1)}" ]; do
		(
			k=0
			for item in "$@"; do
				k=$((k + 1))
				mkdir "$pool_dir/$k.claim" 2>/dev/null || continue
				"$pool_cmd" "$item" >"$pool_dir/$k.log" 2>&1
				echo $? >"$pool_dir/$k.rc"
			done
		) &
		pool_w=$((pool_w + 1))
	done
	wait
}
