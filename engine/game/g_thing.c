/*
 * g_thing: what each map thing type is in this game.
 *
 * The thing table th.h says what a Doom type number is (its sprite,
 * standing frame, and whether it is a monster, pickup, light or
 * decoration). This file adds the game's meaning: monsters become one of
 * the five enemy kinds by how they fight in Doom (hitscan soldiers are
 * grunts, the imp a thrower of dodgeable missiles, the lost soul a flyer
 * that circles in at the player's height, melee and close-range
 * monsters brutes, slow or floating ranged monsters sentries, which stand
 * their ground); health items, armour and
 * the health-giving powerups (soulsphere, megasphere, berserk,
 * invulnerability) become health pickups, ammo ammo pickups, Doom's
 * weapons one of the game's three (g_weapon.c; one ammo for all); the six keys open Doom's locked
 * doors; the radiation suit keeps damaging floors off for a minute; the
 * computer map, light visor and invisibility are taken and counted among
 * the map's items, nothing more. `counted` is Doom's COUNTITEM (the
 * intermission's items). Lights are th's light things (Doom's lamps,
 * candles and torches, and arcaded's point-light types); decorations are
 * drawn and nothing else. Types th does not know and monsters not listed
 * here (Commander Keen, the boss brain) are ignored. docs/game.md lists
 * the mapping.
 */
#include <string.h>

#include "engine/game/g_game.h"
#include "engine/game/g_world.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/th.h"

struct g_thing_row {
	uint8_t cls, kind;
	uint16_t amount;
	uint8_t counted;
	uint8_t weapon;                /* G_P_WEAPON: enum g_weapon */
	/* enemies: walk frames and Doom's frame letters (0 = 'A') of the
	 * attack, pain and death (first .. last, the last is the corpse);
	 * pickups: frames cycled */
	uint8_t frames, attack, pain, death0, death1;
};

/* Each row is a case of g_thing_row's switch, so a type listed twice does
 * not compile, and the lookup (several times per thing per frame: the
 * sprite list, the minimap and the sim) is the compiler's jump table or
 * search tree rather than a scan of the rows. */
#define G_ROW(t, ...) case t: return (struct g_thing_row){ __VA_ARGS__ }
#define E(t, k, walk, att, pain, d0, d1) G_ROW(t, G_C_ENEMY, k, 0, 0, 0, walk, att, pain, d0, d1)
#define H(t, n, frames) G_ROW(t, G_C_PICKUP, G_P_HEALTH, n, 0, 0, frames, 0, 0, 0, 0)
/* counted health items (Doom's bonuses and spheres) */
#define HC(t, n, frames) G_ROW(t, G_C_PICKUP, G_P_HEALTH, n, 1, 0, frames, 0, 0, 0, 0)
#define M(t, n) G_ROW(t, G_C_PICKUP, G_P_AMMO, n, 0, 0, 1, 0, 0, 0, 0)
/* weapons: the weapon and its ammo */
#define W(t, w, n) G_ROW(t, G_C_PICKUP, G_P_WEAPON, n, 0, w, 1, 0, 0, 0, 0)
#define K(t, bit, frames) G_ROW(t, G_C_PICKUP, G_P_KEY, bit, 0, 0, frames, 0, 0, 0, 0)
#define I(t, kind, n, frames) G_ROW(t, G_C_PICKUP, kind, n, 1, 0, frames, 0, 0, 0, 0)

/* The row of type, or one of class G_C_NONE when the game gives the type
 * no meaning of its own. */
static struct g_thing_row g_thing_row(uint16_t type)
{
	switch (type) {
	/* grunts: hitscan soldiers */
	E(3004, G_GRUNT, 4, 4, 6, 7, 11);             /* zombieman POSS */
	E(9, G_GRUNT, 4, 4, 6, 7, 11);                /* shotgun guy SPOS */
	E(65, G_GRUNT, 4, 4, 6, 7, 13);               /* chaingunner CPOS */
	E(84, G_GRUNT, 4, 5, 7, 8, 12);               /* wolfenstein SS SSWV */
	/* throwers: a missile the player can dodge */
	E(3001, G_THROWER, 4, 5, 7, 8, 12);           /* imp TROO */
	/* brutes: melee and close range */
	E(3002, G_BRUTE, 4, 5, 7, 8, 13);             /* demon SARG */
	E(58, G_BRUTE, 4, 5, 7, 8, 13);               /* spectre SARG */
	E(3003, G_BRUTE, 4, 5, 7, 8, 14);             /* baron of hell BOSS */
	E(69, G_BRUTE, 4, 5, 7, 8, 14);               /* hell knight BOS2 */
	E(66, G_BRUTE, 6, 8, 11, 11, 16);             /* revenant SKEL */
	E(64, G_BRUTE, 6, 7, 16, 16, 25);             /* arch-vile VILE */
	/* flyers: circling in, at the player's height, to bite */
	E(3006, G_FLYER, 2, 2, 4, 5, 10);             /* lost soul SKUL */
	/* sentries: ranged, standing their ground */
	E(3005, G_SENTRY, 1, 2, 4, 6, 11);            /* cacodemon HEAD */
	E(71, G_SENTRY, 3, 4, 6, 7, 12);              /* pain elemental PAIN */
	E(68, G_SENTRY, 6, 6, 8, 9, 15);              /* arachnotron BSPI */
	E(67, G_SENTRY, 6, 7, 9, 10, 19);             /* mancubus FATT */
	E(16, G_SENTRY, 4, 5, 6, 7, 15);              /* cyberdemon CYBR */
	E(7, G_SENTRY, 6, 6, 8, 9, 18);               /* spider mastermind SPID */
	/* health */
	H(2011, 10, 1);                               /* stimpack STIM */
	H(2012, 25, 1);                               /* medikit MEDI */
	HC(2014, 2, 4);                               /* health bonus BON1 */
	HC(2013, 100, 4);                             /* soulsphere SOUL */
	HC(83, 100, 4);                               /* megasphere MEGA */
	/* armour and powerups, as health */
	HC(2015, 2, 4);                               /* armour bonus BON2 */
	H(2018, 25, 2);                               /* green armour ARM1 */
	H(2019, 50, 2);                               /* blue armour ARM2 */
	HC(2023, 100, 1);                             /* berserk PSTR */
	HC(2022, 100, 4);                             /* invulnerability PINV */
	/* keys: cards and skulls */
	K(5, G_KEY_BLUE, 2);                          /* blue keycard BKEY */
	K(6, G_KEY_YELLOW, 2);                        /* yellow keycard YKEY */
	K(13, G_KEY_RED, 2);                          /* red keycard RKEY */
	K(40, G_KEY_BLUE_SKULL, 2);                   /* blue skull key BSKU */
	K(39, G_KEY_YELLOW_SKULL, 2);                 /* yellow skull key YSKU */
	K(38, G_KEY_RED_SKULL, 2);                    /* red skull key RSKU */
	/* the radiation suit: a minute; items that are only counted */
	G_ROW(2025, G_C_PICKUP, G_P_SUIT, 60 * SIM_TICRATE, 0, 0, 1, 0, 0, 0, 0);  /* SUIT */
	I(2026, G_P_ITEM, 0, 1);                      /* computer area map PMAP */
	I(2045, G_P_ITEM, 0, 2);                      /* light amplification visor PVIS */
	I(2024, G_P_ITEM, 0, 4);                      /* partial invisibility PINS */
	/* ammo */
	M(2007, 10);                                  /* clip CLIP */
	M(2048, 50);                                  /* box of bullets AMMO */
	M(2008, 10);                                  /* shells SHEL */
	M(2049, 25);                                  /* box of shells SBOX */
	M(2010, 5);                                   /* rocket ROCK */
	M(2046, 25);                                  /* box of rockets BROK */
	M(2047, 20);                                  /* cell CELL */
	M(17, 50);                                    /* cell pack CELP */
	M(8, 50);                                     /* backpack BPAK */
	/* weapons: Doom's shotguns and BFG (a fan of rays) and its heavy
	 * launcher give the spread gun, its rapid-fire guns the rapid gun */
	W(2001, G_W_SPREAD, 20);                      /* shotgun SHOT */
	W(82, G_W_SPREAD, 20);                        /* super shotgun SGN2 */
	W(2002, G_W_RAPID, 20);                       /* chaingun MGUN */
	W(2003, G_W_SPREAD, 10);                      /* rocket launcher LAUN */
	W(2004, G_W_RAPID, 20);                       /* plasma rifle PLAS */
	W(2006, G_W_SPREAD, 20);                      /* BFG9000 BFUG */
	default:
		return (struct g_thing_row){ G_C_NONE, 0, 0, 0, 0, 0, 0, 0, 0, 0 };
	}
}

#undef G_ROW
#undef E
#undef H
#undef HC
#undef M
#undef W
#undef K
#undef I

void g_thing_info(uint16_t type, struct g_thing_info *out)
{
	const struct th_info *th = th_find(type);
	struct g_thing_row row;
	struct th_light lt;

	memset(out, 0, sizeof(*out));
	out->cls = G_C_NONE;
	if (!th)
		return;
	memcpy(out->sprite, th->sprite, sizeof(out->sprite));
	out->stand = (uint8_t)(th->frame >= 'A' && th->frame <= 'Z' ? th->frame - 'A' : 0);
	out->frames = 1;
	out->bright = (th->flags & TH_LIGHT) != 0;
	row = g_thing_row(type);
	if (row.cls != G_C_NONE) {
		out->cls = row.cls;
		out->kind = row.kind;
		out->amount = row.amount;
		out->counted = row.counted;
		out->weapon = row.weapon;
		out->frames = row.frames;
		out->attack = row.attack;
		out->pain = row.pain;
		out->death0 = row.death0;
		out->death1 = row.death1;
		return;
	}
	if (type == 1)
		out->cls = G_C_PLAYER;
	else if ((th->flags & TH_LIGHT) || th_light(type, &lt))
		out->cls = G_C_LIGHT;
	else if ((th->flags & TH_DECOR) && !(th->flags & TH_INVISIBLE))
		out->cls = G_C_DECOR;
}

int g_thing_at_difficulty(uint16_t flags, int d)
{
	static const uint16_t bit[4] = { 1, 2, 4, 4 };

	if (flags & G_TF_MULTI)
		return 0;
	if ((flags & 7) == 0)
		return 1;
	return (flags & bit[d < 0 ? 0 : d > 3 ? 3 : d]) != 0;
}

void g_spawn_count(const struct map *m, int d, int *enemies, int *pickups)
{
	*enemies = *pickups = 0;
	for (uint32_t i = 0; i < m->num_things; i++) {
		struct g_thing_info ti;

		g_thing_info(m->things[i].type, &ti);
		if (!g_thing_at_difficulty(m->things[i].flags, d))
			continue;
		*enemies += ti.cls == G_C_ENEMY;
		*pickups += ti.cls == G_C_PICKUP;
	}
}
