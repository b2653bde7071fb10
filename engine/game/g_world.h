/*
 * g_world: the parts of the current map that the game changes, held in the
 * sim's state (struct sim's `w`): sector heights, floor flats, light and
 * specials, which lines were used up or show their switch pressed, the
 * movers (Doom's door, floor, ceiling and platform thinkers) and the
 * switches waiting to pop back. The map itself (engine/map/map.h) stays
 * read only and shared; the sim starts every stage by copying what may
 * change into `w` (g_spec_start), and the renderers draw the map as `w`
 * says (r_game_live, engine/render/r_game.h).
 *
 * Why fixed arrays in struct sim and not a mutable copy of the map: struct
 * sim stays a plain value (two sims in one process, copied by a restore),
 * and its field lists (sim_table.h) then hash, snapshot and check every
 * changing height with no new code. The price is a limit on the maps the
 * game plays: G_MAX_SECTORS sectors and G_MAX_LINES lines (Freedoom's
 * largest map has 1692 and 10884); the content loader refuses larger ones
 * by name (g_world_fits).
 *
 * Time: the sim ticks at 60 Hz, Doom's thinkers at 35. Movers move every
 * tick at Doom's speed times 35/60 (G_PER_TICK), so a door takes the time
 * it takes in Doom and moves smoothly; their waits are Doom's converted to
 * ticks (G_TICS). Light effects, damaging floors and crushing run on
 * Doom's own clock, the 35 Hz tics of the stage (g_dtic), so their periods
 * and Doom's `leveltime & 31` rules are exact.
 */
#ifndef ARCADED_ENGINE_G_WORLD_H
#define ARCADED_ENGINE_G_WORLD_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/game/sim_table.h"

#define G_MAX_SECTORS 4096
#define G_MAX_LINES 16384
#define G_LINE_WORDS (G_MAX_LINES / 32)
#define G_MAX_MOVERS 512
#define G_MAX_BUTTONS 32

/* Doom's tics (35 Hz) in sim ticks (60 Hz), rounded; Doom's speeds per tic
 * as speeds per tick. */
#define G_TICS(t) (((t) * 60 + 17) / 35)
#define G_PER_TICK(v) ((fx_t)(((int64_t)(v) * 35 + 30) / 60))

/* A count of the sim's current map, in the field lists' limits (0 while
 * there is none: sim_snapshot_size walks a zeroed sim). */
#define G_MAP_COUNT(s, n) ((s)->map ? (int64_t)(s)->map->n : 0)
#define G_MAP_EXACT(s, n) SIM_RANGE(G_MAP_COUNT(s, n), G_MAP_COUNT(s, n))

/* Light effects of a sector (Doom's light thinkers). */
enum g_lfx {
	G_LFX_NONE,
	G_LFX_FLASH,                   /* 1: random blink (Doom's lightflash) */
	G_LFX_STROBE_FAST,             /* 2, 4, 13: strobe, 15 tics dark */
	G_LFX_STROBE_SLOW,             /* 3, 12, line 17: strobe, 35 tics dark */
	G_LFX_GLOW,                    /* 8: glow down then up, 8 a tic */
	G_LFX_FLICKER,                 /* 17: fire flicker */
	G_LFX_COUNT
};

/* A sector as the game has it now. Its fields: engine/game/sim_table.h. */
#define G_SECTOR_FIELDS(X) \
	/* heights stay in the loader's range (g_plane_move holds them there) */ \
	X(VAL, fx_t, floor_h, SIM_RANGE(-MAP_HEIGHT_MAX, MAP_HEIGHT_MAX)) \
	X(VAL, fx_t, ceil_h, SIM_RANGE(-MAP_HEIGHT_MAX, MAP_HEIGHT_MAX)) \
	X(VAL, uint16_t, floor_tex, SIM_ANY)        /* flat (changed by some floors) */ \
	X(VAL, uint16_t, special, SIM_ANY)          /* Doom's sector special now */ \
	X(VAL, uint8_t, light, SIM_ANY) \
	X(VAL, uint8_t, lfx, SIM_MAX(G_LFX_COUNT - 1))  /* enum g_lfx */ \
	X(VAL, uint8_t, lmin, SIM_ANY)              /* the effect's dark level */ \
	X(VAL, uint8_t, lmax, SIM_ANY)              /* its bright level */ \
	/* tics to the effect's next change; GLOW: 1 rising, 0 falling */ \
	X(VAL, uint8_t, lcount, SIM_ANY)
struct g_sector {
	G_SECTOR_FIELDS(SIM_MEMBER)
};

/* Movers: what moves a sector (at most one at a time, as Doom's
 * specialdata). */
enum g_mkind { G_MV_DOOR, G_MV_FLOOR, G_MV_CEIL, G_MV_PLAT, G_MV_KINDS };

/* Door types (Doom's vldoor_e). */
enum g_door {
	G_DOOR_NORMAL,                 /* open, wait, close */
	G_DOOR_CLOSE30,                /* close, wait 30 s, open */
	G_DOOR_CLOSE,                  /* close and stay */
	G_DOOR_OPEN,                   /* open and stay */
	G_DOOR_RAISE5,                 /* wait 5 minutes, then a normal door */
	G_DOOR_BLAZE_RAISE,
	G_DOOR_BLAZE_OPEN,
	G_DOOR_BLAZE_CLOSE,
	G_DOOR_TYPES
};

/* Floor types (Doom's floor_e, and the stairs' and donut's moves). */
enum g_floor {
	G_FLOOR_LOWER,                 /* to the highest neighbour floor */
	G_FLOOR_LOWEST,                /* to the lowest neighbour floor */
	G_FLOOR_TURBO_LOWER,           /* to the highest neighbour + 8, fast */
	G_FLOOR_RAISE,                 /* to the lowest neighbour ceiling */
	G_FLOOR_RAISE_NEAREST,         /* to the next higher neighbour floor */
	G_FLOOR_RAISE_TEXTURE,         /* by the shortest lower texture */
	G_FLOOR_LOWER_CHANGE,          /* to the lowest, taking its flat and special */
	G_FLOOR_RAISE24,
	G_FLOOR_RAISE24_CHANGE,
	G_FLOOR_RAISE_CRUSH,           /* to the lowest neighbour ceiling - 8, crushing */
	G_FLOOR_RAISE_TURBO,           /* to the next higher floor, fast */
	G_FLOOR_RAISE512,
	G_FLOOR_DONUT_RAISE,           /* the donut's ring: takes the outside's flat */
	G_FLOOR_STAIR,                 /* a step of a staircase (crushing) */
	G_FLOOR_TYPES
};

/* Ceiling types (Doom's ceiling_e). */
enum g_ceil {
	G_CEIL_LOWER_TO_FLOOR,
	G_CEIL_RAISE_TO_HIGHEST,
	G_CEIL_LOWER_AND_CRUSH,        /* to the floor + 8 */
	G_CEIL_CRUSH_RAISE,
	G_CEIL_FAST_CRUSH_RAISE,
	G_CEIL_SILENT_CRUSH_RAISE,
	G_CEIL_TYPES
};

/* Platform types (Doom's plattype_e). */
enum g_plat {
	G_PLAT_PERPETUAL,              /* between lowest and highest neighbour, forever */
	G_PLAT_DWUS,                   /* lift: down, wait, up, stay */
	G_PLAT_BLAZE_DWUS,
	G_PLAT_RAISE_CHANGE,           /* up by an amount, taking the line's flat */
	G_PLAT_RAISE_NEAREST_CHANGE,   /* up to the next floor, taking the line's flat */
	G_PLAT_TYPES
};

/* Mover directions / states. Doors: G_DIR_DOWN, G_DIR_WAIT (at the top or
 * bottom, count running), G_DIR_UP, G_DIR_INIT (the 5-minute door's first
 * wait). Ceilings: DOWN, UP, STASIS (stopped by a line; `old` keeps the
 * direction). Platforms: DOWN, WAIT, UP, STASIS. */
#define G_DIR_DOWN (-1)
#define G_DIR_WAIT 0
#define G_DIR_UP 1
#define G_DIR_INIT 2
#define G_DIR_STASIS 3

#define G_MOVER_FIELDS(X) \
	X(VAL, uint8_t, kind, SIM_MAX(G_MV_KINDS - 1))  /* enum g_mkind */ \
	X(VAL, uint8_t, type, SIM_ANY)               /* enum g_door / g_floor / g_ceil / g_plat */ \
	X(VAL, uint32_t, sector, SIM_SECTOR) \
	X(VAL, int8_t, dir, SIM_RANGE(-1, 3))        /* G_DIR_* */ \
	X(VAL, int8_t, old, SIM_RANGE(-1, 3))        /* direction before a stop */ \
	X(VAL, uint8_t, crush, SIM_MAX(1)) \
	X(VAL, fx_t, speed, SIM_ANY)                 /* per tick */ \
	/* door: the top; floor: the destination; ceiling and platform: the bottom */ \
	X(VAL, fx_t, low, SIM_ANY) \
	X(VAL, fx_t, high, SIM_ANY)                  /* ceiling and platform: the top */ \
	X(VAL, uint16_t, wait, SIM_ANY)              /* ticks a door or platform waits */ \
	X(VAL, uint16_t, count, SIM_ANY)             /* ticks left of the wait */ \
	X(VAL, uint16_t, tag, SIM_ANY)               /* the line tag that started it */ \
	X(VAL, uint16_t, tex, SIM_ANY)               /* floor: the flat it ends with */ \
	X(VAL, uint16_t, newspecial, SIM_ANY)        /* floor: the special it ends with */
struct g_mover {
	G_MOVER_FIELDS(SIM_MEMBER)
};

/* A pressed button, popping back after G_BUTTON_TICKS. */
#define G_BUTTON_FIELDS(X) \
	X(VAL, uint32_t, line, SIM_MAX(G_MAP_COUNT(s, num_lines) - 1)) \
	X(VAL, uint16_t, timer, SIM_ANY)
struct g_button {
	G_BUTTON_FIELDS(SIM_MEMBER)
};

#define G_BUTTON_TICKS G_TICS(35)      /* Doom's BUTTONTIME: one second */

/* Keys (g_world.keys): cards and skulls; a door takes either of its colour. */
#define G_KEY_BLUE 0x01
#define G_KEY_YELLOW 0x02
#define G_KEY_RED 0x04
#define G_KEY_BLUE_SKULL 0x08
#define G_KEY_YELLOW_SKULL 0x10
#define G_KEY_RED_SKULL 0x20

/* Messages the HUD shows (g_world.msg), for G_MSG_TICKS. */
enum g_msg {
	G_MSG_NONE,
	G_MSG_BLUE_DOOR,               /* "YOU NEED A BLUE KEY TO OPEN THIS DOOR" */
	G_MSG_YELLOW_DOOR,
	G_MSG_RED_DOOR,
	G_MSG_BLUE_OBJECT,             /* "... TO ACTIVATE THIS OBJECT" (locked switches) */
	G_MSG_YELLOW_OBJECT,
	G_MSG_RED_OBJECT,
	G_MSG_SECRET,                  /* "A SECRET IS REVEALED" */
	G_MSG_NOTHING,                 /* USE on a wall with no special */
	G_MSG_KEY,                     /* a key was picked up */
	G_MSG_COUNT
};
#define G_MSG_TICKS 180

/* How the map was left (g_world.exit). */
enum g_exit { G_EXIT_NONE, G_EXIT_NORMAL, G_EXIT_SECRET };

#define G_WORLD_FIELDS(X) \
	X(VAL, uint32_t, num_sectors, G_MAP_EXACT(s, num_sectors)) \
	X(SUBS, g_sector, sec, G_MAX_SECTORS, p->num_sectors) \
	X(VAL, uint32_t, num_lines, G_MAP_EXACT(s, num_lines)) \
	/* once-only lines already triggered, a bit a line */ \
	X(ARR, uint32_t, used, G_LINE_WORDS, (p->num_lines + 31) / 32, SIM_ANY) \
	/* lines whose front shows the other switch texture, a bit a line */ \
	X(ARR, uint32_t, switched, G_LINE_WORDS, (p->num_lines + 31) / 32, SIM_ANY) \
	X(VAL, uint16_t, num_movers, SIM_MAX(G_MAX_MOVERS)) \
	X(SUBS, g_mover, mv, G_MAX_MOVERS, p->num_movers) \
	X(VAL, uint8_t, num_buttons, SIM_MAX(G_MAX_BUTTONS)) \
	X(SUBS, g_button, bt, G_MAX_BUTTONS, p->num_buttons) \
	X(VAL, uint8_t, keys, SIM_MAX(0x3f))        /* G_KEY_* held on this map */ \
	X(VAL, uint8_t, msg, SIM_MAX(G_MSG_COUNT - 1))  /* enum g_msg */ \
	X(VAL, uint16_t, msg_t, SIM_ANY)            /* ticks the message has shown */ \
	X(VAL, uint16_t, secrets, SIM_ANY)          /* secret sectors entered */ \
	X(VAL, uint16_t, secrets_total, SIM_ANY) \
	X(VAL, uint16_t, items, SIM_ANY)            /* counted items taken */ \
	X(VAL, uint16_t, items_total, SIM_ANY) \
	X(VAL, uint16_t, suit, SIM_ANY)             /* ticks of radiation suit left */ \
	/* the map has an exit (line or sector): clearing it does not end it */ \
	X(VAL, uint8_t, has_exit, SIM_MAX(1)) \
	X(VAL, uint8_t, exit, SIM_MAX(G_EXIT_SECRET))  /* enum g_exit: how it was left */ \
	X(VAL, uint32_t, exit_t, SIM_ANY)           /* stage ticks when it was left */ \
	/* the stage the exit leads to */ \
	X(VAL, uint8_t, next, SIM_MAX(s->num_stages > 0 ? s->num_stages - 1 : 0))
struct g_world {
	G_WORLD_FIELDS(SIM_MEMBER)
};

/* A line's bit in g_world.used or .switched. */
static inline int g_world_bit(const uint32_t *bits, uint32_t line)
{
	return (int)((bits[line / 32] >> (line % 32)) & 1u);
}

struct map;

/* Whether the game can play map m: at most G_MAX_SECTORS sectors and
 * G_MAX_LINES lines. If not, 0 and err (may be NULL) says so, naming the
 * map: "E1M1: 5000 sectors and 9000 lines; the game plays maps of up to
 * 4096 sectors and 16384 lines". */
int g_world_fits(const struct map *m, char *err, size_t errlen);

/* What line special `type` does in the game (g_line.c), for tools
 * (--print-specials): 1 and its description in out ("DR door open wait
 * close (monsters too)": trigger, once or repeatable, what it does), or 0
 * for a type the game does not play (out untouched). out may be NULL. */
int g_line_special(uint16_t type, char *out, size_t len);

/* The same for sector special `type` (g_spec.c): 1 when the game plays it
 * ("light strobes fast", "Boom: light glows damage 10 secret"); 0 for 0,
 * for types Doom does not define, and for Boom's friction and wind (out
 * still describes what it can). */
int g_sector_special(uint16_t type, char *out, size_t len);

/* One special type a map uses (g_census.c). */
struct g_spec_use {
	uint16_t type;
	uint8_t sector;                /* 0: a line special, 1: a sector special */
	uint8_t played;                /* g_line_special's or g_sector_special's answer */
	uint32_t count;                /* lines or sectors that have it */
};

/* Every special type map m uses (0, no special, is left out) with its
 * count, into out: line specials first, each kind by type. Returns the
 * number of entries, or -E2BIG when there are more than max types
 * (m->num_lines + m->num_sectors entries always suffice). For tools and
 * the log (app/); the sim does not call it. */
int g_census(const struct map *m, struct g_spec_use *out, int max);

#endif
