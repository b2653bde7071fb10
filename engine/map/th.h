/*
 * th: what a map thing's type number means.
 *
 * Doom's editor numbers (the `type` of a THINGS entry, map_thing.type) with
 * the sprite a thing is drawn with, its size and what kind of thing it is,
 * for Doom's documented types (Freedoom uses the same numbers and sprite
 * names); plus arcaded's own light thing, whose type number encodes its
 * radius, intensity and colour (th_light).
 */
#ifndef ARCADED_ENGINE_TH_H
#define ARCADED_ENGINE_TH_H

#include <stdint.h>

enum th_flags {
	TH_SOLID = 1 << 0,             /* blocks movement */
	TH_MONSTER = 1 << 1,
	TH_PICKUP = 1 << 2,            /* picked up by touching it */
	TH_DECOR = 1 << 3,             /* decoration */
	TH_LIGHT = 1 << 4,             /* a light source (Doom: drawn full bright) */
	TH_PLAYER = 1 << 5,            /* a player start (types 1..4: player 1..4) */
	TH_KEY = 1 << 6,
	TH_WEAPON = 1 << 7,
	TH_AMMO = 1 << 8,
	TH_HANGING = 1 << 9,           /* hangs from the ceiling */
	TH_INVISIBLE = 1 << 10,        /* no sprite (markers, arcaded's lights) */
	TH_SHOOTABLE = 1 << 11,        /* can be damaged (barrels) */
};

struct th_info {
	uint16_t type;
	char sprite[5];                /* 4-char sprite name, "" when invisible */
	char frame;                    /* frame letter drawn when standing */
	int16_t radius, height;        /* map units */
	uint16_t flags;                /* enum th_flags */
	char name[40];                 /* for tools and messages */
};

/* The description of thing type `type`, or NULL for a type not in the
 * table (a map may hold any number: the caller ignores or reports it). For
 * any light thing type (th_light) this is one shared entry whose type is
 * TH_LIGHT_FIRST. The pointer is to static data. */
const struct th_info *th_find(uint16_t type);

/* Number of table entries and entry i (0-based, ascending type), for tools
 * and tests; NULL past the end. Light types are not listed. */
int th_count(void);
const struct th_info *th_at(int i);

/* arcaded's light thing: types TH_LIGHT_FIRST .. TH_LIGHT_LAST,
 *   type = TH_LIGHT_FIRST + 64 * r + 8 * i + c   (r, i, c each 0..7)
 * radius 64 * (r + 1) map units (64..512), intensity min(32 * (i + 1), 255)
 * (how much it adds at its centre, in the 0..255 scale of sector light),
 * colour c: white, red, orange, yellow, green, cyan, blue, purple. The
 * thing's angle and flags are ignored. E.g. 15000 is a small dim white
 * light, 15000 + 64*3 + 8*7 = 15248 a white light of radius 256 at full
 * intensity. (14100..14164, the first idea, are ZDoom's music changers.) */
#define TH_LIGHT_FIRST 15000
#define TH_LIGHT_LAST (TH_LIGHT_FIRST + 511)

struct th_light {
	int32_t radius;                /* map units */
	uint8_t intensity;             /* 32..255 */
	uint8_t rgb[3];                /* colour at full intensity */
};

/* If type is a light thing, fills *out and returns 1; else returns 0 and
 * leaves *out alone. */
int th_light(uint16_t type, struct th_light *out);

/* The light thing type for radius index r, intensity index i and colour
 * index c (each 0..7; values outside are clamped). */
uint16_t th_light_type(int r, int i, int c);

#endif
