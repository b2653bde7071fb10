/*
 * grid_lvl: the built-in grid level, the text of levels/grid1.txt compiled
 * in (the engine does no I/O; tests/unit/test_grid.c checks both are the
 * same). Loaded like any grid map: grid_parse(grid_builtin_text(...)).
 */
#include <stddef.h>

#include "engine/map/grid.h"

static const char grid_lvl_text[] =
	"; GRID1: arcaded's grid level (syntax: docs/grid.md). One tile = 64 units.\n"
	"; Texture and flat names are the built-in set's (tex_builtin).\n"
	"name GRID1\n"
	"# = wall AR_BRICK\n"
	"O = wall AR_STONE\n"
	". = floor 0 ceil 128 light 112 ftex AR_FLOOR ctex AR_CEIL\n"
	"@ = . player east\n"
	"* = . lamp 192 320\n"
	"D = floor 0 ceil 96 light 112 ftex AR_FLOOR ctex AR_CEIL edge AR_METAL\n"
	"W = floor 40 ceil 88 light 112 ftex AR_SLATE ctex AR_SLATE edge AR_MARBL\n"
	"~ = floor -24 ceil 128 light 112 ftex AR_WAT1 ctex AR_CEIL edge AR_STONE\n"
	"- = floor 16 ceil 128 light 112 ftex AR_SLATE ctex AR_CEIL edge AR_WOOD\n"
	", = floor 0 ceil 256 light 160 ftex AR_GRASS ctex F_SKY1\n"
	"+ = , lamp 160 256 orange\n"
	"^ = floor 40 ceil 256 light 160 ftex AR_DIRT ctex F_SKY1 edge AR_STONE\n"
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
