#!/bin/sh
# The sources of the engine-only replayer (tests/xbuild/replay.c), one
# list for every script that builds it (tests/xbuild/run.sh, tests/soak/run.sh):
# the engine without its OSMesa folder (engine/sound included), and the few input and app files
# that carry content loading and recordings. Run from the tree's top.
echo tests/xbuild/replay.c $(ls engine/*/*.c | grep -v '^engine/gl/') \
	input/rec.c input/rec_check.c input/scr.c input/act.c input/io.c input/txt.c \
	app/ct.c app/view.c app/demo.c app/cmd.c app/hear.c app/mdir.c
