#!/bin/sh
# The balance table of docs/game.md (issue 16 item 9), measured, not
# guessed: every stage recording tests/replay/stages/arenaN.rec (the
# autopilot's clearing run of built-in stage N: arenaN.route -> arenaN.scr,
# recorded by the daemon) is replayed through the engine by the headless
# replayer of tests/xbuild (replay.c, --balance: per stage the ticks
# fought until the exit or the clear, the health lost, shots fired and
# hit, kills and lives lost, read from the sim tick by tick), and the rows
# become one table, in stage order, between the markers
# "<!-- balance: begin -->" and "<!-- balance: end -->" in docs/game.md.
# The stages without an exit (1..3: they end when every enemy is dead)
# have their routes, scripts and recordings in tests/replay/stages/clear;
# their rows say "clear" (time to the clear), the others "exit".
#
#   tests/replay/balance.sh             write the table into docs/game.md
#                                       (then exit 1 if the curve does not
#                                       rise, below)
#   tests/replay/balance.sh --check     exit 1 when docs/game.md's table is
#                                       not what the recordings give now,
#                                       or when the curve does not rise:
#                                       time (to the clear, to the exit)
#                                       and damage taken must each
#                                       strictly grow from each stage to
#                                       the next, 1 to 8
#   tests/replay/balance.sh --record [BIN]
#                                       first write the scripts again with
#                                       the autopilot (build/tests/autopilot)
#                                       and record them with the daemon BIN
#                                       (default build/arcaded): after a
#                                       change of a stage or of the rules
set -eu
cd "$(dirname "$0")/../.."
mode=write
case "${1:-}" in
--check) mode=check ;;
--record) mode=record ;;
"") ;;
*) echo "usage: $0 [--check | --record [BIN]]" >&2; exit 2 ;;
esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
dir=tests/replay/stages
# the stages' recordings are made with these settings (easy, nine lives:
# the autopilot is no champion; a recording keeps its settings)
SET="--set game.difficulty=0 --set game.lives=9"

# the stages that end at their exit switch (4..8) in $dir, the ones that
# end when their enemies are dead (1..3: the autopilot's goal is the
# clear) in $dir/clear; one table holds both
sets="$dir $dir/clear"

if [ "$mode" = record ]; then
	BIN=${2:-build/arcaded}
	for d in $sets; do
		for route in "$d"/arena*.route; do
			n=$(basename "$route" .route); n=${n#arena}
			# shellcheck disable=SC2086
			build/tests/autopilot --level "$n" $SET --route "$route" --out "$d/arena$n.scr"
			# shellcheck disable=SC2086
			"$BIN" --config-dir "$tmp/none" --state-dir "$tmp/state" --level "$n" $SET \
				--script "$d/arena$n.scr" --record "$d/arena$n.rec" >/dev/null
		done
	done
	mode=write
fi

# the replayer, built as tests/xbuild/run.sh builds it (engine only)
WARN="-std=c11 -Wall -Wextra -Werror -Wshadow -Wvla -Wstrict-prototypes -Wmissing-prototypes"
# shellcheck disable=SC2046
${CC:-cc} -O2 $WARN -fno-strict-aliasing -I. -D_GNU_SOURCE $(sh tests/xbuild/src.sh) \
	-o "$tmp/replay"

doc=docs/game.md
cp "$doc" "$tmp/doc"
: >"$tmp/raw"
: >"$tmp/rows"
nrec=0
for d in $sets; do
	if [ "$d" = "$dir" ]; then
		ends="exit"
	else
		ends="clear"
	fi
	for rec in "$d"/arena*.rec; do
		"$tmp/replay" --no-render --quiet --balance "$rec" >"$tmp/row" || {
			echo "balance: $rec: the replay failed" >&2
			exit 1
		}
		# only the recording's own stage (the first row): the next
		# one may have begun during the intermission page
		head -n 1 "$tmp/row" | awk -v rec="$rec" -v raw="$tmp/raw" -v ends="$ends" '
			$1 != "balance" || $10 != "cleared" {
				print "balance: " rec ": the stage was not cleared: " $0 > "/dev/stderr"; exit 1 }
			{ printf "%d | %d | %s | %s | %.1f s | %d | %d | %d (%d%%) | %d | %d |\n",
				$2, $2, $3, ends, $4 / 60, $5, $6, $7, $6 ? 100 * $7 / $6 : 0, $8, $9
			  print $2, $4, $5 >> raw }' >>"$tmp/rows"
		nrec=$((nrec + 1))
	done
done
# One table, in stage order, over both sets: the rows' first field (the
# stage) sorts them and is dropped.
{
	echo "| stage | map | ends at | time | damage taken | shots fired | shots hit | kills | lives lost |"
	echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
	sort -n "$tmp/rows" | sed 's/^[0-9]* //'
} >"$tmp/table"
# The curve rises over all eight stages: from each row to the next (stage
# order), the time (in ticks, not the table's rounded seconds; to the clear
# for 1..3, to the exit for 4..8) and the damage taken each strictly grow.
# Each pair that does not is named.
: >"$tmp/rising"
sort -n "$tmp/raw" | awk '
	NR > 1 && $2 <= t { printf "balance: the time does not rise from stage %d to stage %d (%.1f s, then %.1f s)\n", s, $1, t / 60, $2 / 60 }
	NR > 1 && $3 <= d { printf "balance: the damage does not rise from stage %d to stage %d (%d, then %d)\n", s, $1, d, $3 }
	{ s = $1; t = $2; d = $3 }' >"$tmp/rising"
begin="<!-- balance: begin -->"
end="<!-- balance: end -->"
grep -q "^$begin\$" "$doc" && grep -q "^$end\$" "$doc" || {
	echo "balance: $doc has no '$begin' / '$end' markers" >&2
	exit 1
}
awk -v b="$begin" -v e="$end" -v tf="$tmp/table" '
	$0 == b { print; while ((getline l < tf) > 0) print l; skip = 1; next }
	$0 == e { skip = 0 }
	!skip { print }' "$tmp/doc" >"$tmp/doc.new"
mv "$tmp/doc.new" "$tmp/doc"
[ "$mode" = check ] || cat "$tmp/table"

if [ "$mode" = check ]; then
	if ! cmp -s "$doc" "$tmp/doc"; then
		echo "balance: $doc's table is not what the stage recordings give now:" >&2
		diff "$doc" "$tmp/doc" >&2 || true
		echo "(tests/replay/balance.sh writes it)" >&2
		exit 1
	fi
	if [ -s "$tmp/rising" ]; then
		cat "$tmp/rising" >&2
		echo "balance: the curve does not rise (time and damage must grow stage by stage)" >&2
		exit 1
	fi
	echo "balance: $doc's table equals the replays of $nrec stage recordings; time and damage rise from stage 1 to 8"
else
	cp "$tmp/doc" "$doc"
	if [ -s "$tmp/rising" ]; then
		cat "$tmp/rising" >&2
		echo "balance: table written, but the curve does not rise: --check fails" >&2
		exit 1
	fi
fi
