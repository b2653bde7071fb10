# Sourced by tests/script/run.sh and regen.sh (so a script's frame is
# stored and checked with the same command line).
# script_args FILE: the daemon options a script names: the words of its
# "# args:" lines (no spaces or quotes inside a word, e.g.
# "# args: --grid builtin" plays the built-in grid map, which has no
# enemies), and "--set KEY=VALUE" for each "# set: KEY=VALUE" line (a
# setting the script runs with, e.g. "# set: game.difficulty=0").
script_args() {
	script_content_args "$1"
	sed -n 's/^# set: *\([^ ]*\).*/--set \1/p' "$1"
}

# script_content_args FILE: its "# args:" words alone (the content
# options a replay of its recording needs too; settings are in the
# recording's header).
# A word starting "@/" names a file of the tree ("# args: --grid
# @/tests/script/maps/windup.txt"): "@" becomes the tree's top (the
# directory the callers source this file from), as the daemon runs in a
# directory of its own.
script_top=$(pwd)
script_content_args() {
	sed -n 's/^# args: //p' "$1" | sed "s|@/|$script_top/|g"
}
