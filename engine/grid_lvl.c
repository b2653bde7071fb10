/*
 * grid_lvl: the built-in grid level, the text of levels/grid1.txt compiled
 * in (the engine does no I/O; tests/unit/test_grid.c checks both are the
 * same). Loaded like any grid map: grid_parse(grid_builtin_text(...)).
 */
#include <stddef.h>

#include "engine/grid.h"

static const char grid_lvl_text[] =
	"; GRID1: arcaded's grid level (syntax: docs/grid.md). One tile = 64 units.\n"
	"; Textures are colours of the built-in palette (ramp * 16 + shade).\n"
	"name GRID1\n"
	"# = wall 195\n"
	"O = wall 146\n"
	". = floor 0 ceil 128 light 112 ftex 227 ctex 4\n"
	"@ = . player east\n"
	"* = . lamp 192 320\n"
	"D = floor 0 ceil 96 light 112 ftex 227 ctex 4 edge 210\n"
	"W = floor 40 ceil 88 light 112 ftex 163 ctex 163 edge 162\n"
	"~ = floor -24 ceil 128 light 112 ftex 115 ctex 4 edge 114\n"
	"- = floor 16 ceil 128 light 112 ftex 226 ctex 4 edge 225\n"
	", = floor 0 ceil 256 light 160 ftex 66 ctex 129\n"
	"+ = , lamp 160 256\n"
	"^ = floor 40 ceil 256 light 160 ftex 50 ctex 129 edge 51\n"
	"map\n"
	"##########################\n"
	"#@.....#.......#.........#\n"
	"#......#...*...#...~~~...#\n"
	"#..O...D.......D...~~~...#\n"
	"#......#...O...#...~~~.*.#\n"
	"#..*...#.......#.........#\n"
	"#......#########---------#\n"
	"###WW###,,,,,,,,,,,,,,,,,#\n"
	"#,,,,,,,,,,,,,,,,,,,,,,,,#\n"
	"#,,,,,,,,,^^^^,,,,,,,,+,,#\n"
	"#,,+,,,,,,^^^^,,,,,,,,,,,#\n"
	"#,,,,,,,,,,,,,,,,,,,,,,,,#\n"
	"##########################\n";

const char *grid_builtin_text(size_t *len)
{
	*len = sizeof grid_lvl_text - 1;
	return grid_lvl_text;
}
