# Sourced by tests/script/run.sh and regen.sh (so a script's frame is
# stored and checked with the same command line).
# script_args FILE: the daemon options a script names on its "# args:"
# lines (words without spaces or quotes, e.g. "# args: --grid builtin"
# plays the built-in grid map, which has no enemies).
script_args() {
	sed -n 's/^# args: //p' "$1"
}
