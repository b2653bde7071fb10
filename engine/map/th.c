/*
 * th: Doom's thing types (editor numbers, the sprite and frame each is
 * drawn with, radius and height as in Doom's mobjinfo) and arcaded's light
 * thing. The table is sorted by type.
 */
#include "engine/map/th.h"

#include "engine/map/map.h"
#include "engine/map/tex.h"

#include <stddef.h>

#define MON (TH_MONSTER | TH_SOLID | TH_SHOOTABLE)
#define DEC TH_DECOR
#define SOL (TH_DECOR | TH_SOLID)
#define LIT (TH_DECOR | TH_SOLID | TH_LIGHT)
#define HNG (TH_DECOR | TH_SOLID | TH_HANGING)
#define HNS (TH_DECOR | TH_HANGING)
#define PIK TH_PICKUP
#define KEY (TH_PICKUP | TH_KEY)
#define WPN (TH_PICKUP | TH_WEAPON)
#define AMO (TH_PICKUP | TH_AMMO)
#define PWR (TH_PICKUP | TH_LIGHT)
#define INV TH_INVISIBLE

static const struct th_info th_table[] = {
	{ 1, "PLAY", 'A', 16, 56, TH_PLAYER, "Player 1 start" },
	{ 2, "PLAY", 'A', 16, 56, TH_PLAYER, "Player 2 start" },
	{ 3, "PLAY", 'A', 16, 56, TH_PLAYER, "Player 3 start" },
	{ 4, "PLAY", 'A', 16, 56, TH_PLAYER, "Player 4 start" },
	{ 5, "BKEY", 'A', 20, 16, KEY, "Blue keycard" },
	{ 6, "YKEY", 'A', 20, 16, KEY, "Yellow keycard" },
	{ 7, "SPID", 'A', 128, 100, MON, "Spider mastermind" },
	{ 8, "BPAK", 'A', 20, 16, AMO, "Backpack" },
	{ 9, "SPOS", 'A', 20, 56, MON, "Shotgun guy" },
	{ 10, "PLAY", 'W', 16, 16, DEC, "Bloody mess" },
	{ 11, "", 'A', 16, 56, INV, "Deathmatch start" },
	{ 12, "PLAY", 'W', 16, 16, DEC, "Bloody mess" },
	{ 13, "RKEY", 'A', 20, 16, KEY, "Red keycard" },
	{ 14, "", 'A', 20, 16, INV, "Teleport destination" },
	{ 15, "PLAY", 'N', 16, 16, DEC, "Dead player" },
	{ 16, "CYBR", 'A', 40, 110, MON, "Cyberdemon" },
	{ 17, "CELP", 'A', 20, 16, AMO, "Cell pack" },
	{ 18, "POSS", 'L', 20, 16, DEC, "Dead zombieman" },
	{ 19, "SPOS", 'L', 20, 16, DEC, "Dead shotgun guy" },
	{ 20, "TROO", 'M', 20, 16, DEC, "Dead imp" },
	{ 21, "SARG", 'N', 30, 16, DEC, "Dead demon" },
	{ 22, "HEAD", 'L', 31, 16, DEC, "Dead cacodemon" },
	{ 23, "SKUL", 'K', 16, 16, DEC, "Dead lost soul" },
	{ 24, "POL5", 'A', 20, 16, DEC, "Pool of blood and flesh" },
	{ 25, "POL1", 'A', 16, 16, SOL, "Impaled human" },
	{ 26, "POL6", 'A', 16, 16, SOL, "Twitching impaled human" },
	{ 27, "POL4", 'A', 16, 16, SOL, "Skull on a pole" },
	{ 28, "POL2", 'A', 16, 16, SOL, "Five skulls shish kebab" },
	{ 29, "POL3", 'A', 16, 16, LIT, "Pile of skulls and candles" },
	{ 30, "COL1", 'A', 16, 16, SOL, "Tall green pillar" },
	{ 31, "COL2", 'A', 16, 16, SOL, "Short green pillar" },
	{ 32, "COL3", 'A', 16, 16, SOL, "Tall red pillar" },
	{ 33, "COL4", 'A', 16, 16, SOL, "Short red pillar" },
	{ 34, "CAND", 'A', 20, 16, DEC | TH_LIGHT, "Candle" },
	{ 35, "CBRA", 'A', 16, 16, LIT, "Candelabra" },
	{ 36, "COL5", 'A', 16, 16, SOL, "Short green pillar with beating heart" },
	{ 37, "COL6", 'A', 16, 16, SOL, "Short red pillar with skull" },
	{ 38, "RSKU", 'A', 20, 16, KEY, "Red skull key" },
	{ 39, "YSKU", 'A', 20, 16, KEY, "Yellow skull key" },
	{ 40, "BSKU", 'A', 20, 16, KEY, "Blue skull key" },
	{ 41, "CEYE", 'A', 16, 16, LIT, "Evil eye" },
	{ 42, "FSKU", 'A', 16, 16, LIT, "Floating skull rock" },
	{ 43, "TRE1", 'A', 16, 16, SOL, "Burnt tree" },
	{ 44, "TBLU", 'A', 16, 16, LIT, "Tall blue firestick" },
	{ 45, "TGRN", 'A', 16, 16, LIT, "Tall green firestick" },
	{ 46, "TRED", 'A', 16, 16, LIT, "Tall red firestick" },
	{ 47, "SMIT", 'A', 16, 16, SOL, "Brown stump" },
	{ 48, "ELEC", 'A', 16, 16, SOL, "Tall techno column" },
	{ 49, "GOR1", 'A', 16, 68, HNG, "Hanging victim, twitching" },
	{ 50, "GOR2", 'A', 16, 84, HNG, "Hanging victim, arms out" },
	{ 51, "GOR3", 'A', 16, 84, HNG, "Hanging victim, one-legged" },
	{ 52, "GOR4", 'A', 16, 68, HNG, "Hanging pair of legs" },
	{ 53, "GOR5", 'A', 16, 52, HNG, "Hanging leg" },
	{ 54, "TRE2", 'A', 32, 16, SOL, "Large brown tree" },
	{ 55, "SMBT", 'A', 16, 16, LIT, "Short blue firestick" },
	{ 56, "SMGT", 'A', 16, 16, LIT, "Short green firestick" },
	{ 57, "SMRT", 'A', 16, 16, LIT, "Short red firestick" },
	{ 58, "SARG", 'A', 30, 56, MON, "Spectre" },
	{ 59, "GOR2", 'A', 20, 84, HNS, "Hanging victim, arms out (not solid)" },
	{ 60, "GOR4", 'A', 20, 68, HNS, "Hanging pair of legs (not solid)" },
	{ 61, "GOR3", 'A', 20, 52, HNS, "Hanging victim, one-legged (not solid)" },
	{ 62, "GOR5", 'A', 20, 52, HNS, "Hanging leg (not solid)" },
	{ 63, "GOR1", 'A', 20, 68, HNS, "Hanging victim, twitching (not solid)" },
	{ 64, "VILE", 'A', 20, 56, MON, "Arch-vile" },
	{ 65, "CPOS", 'A', 20, 56, MON, "Heavy weapon dude" },
	{ 66, "SKEL", 'A', 20, 56, MON, "Revenant" },
	{ 67, "FATT", 'A', 48, 64, MON, "Mancubus" },
	{ 68, "BSPI", 'A', 64, 64, MON, "Arachnotron" },
	{ 69, "BOS2", 'A', 24, 64, MON, "Hell knight" },
	{ 70, "FCAN", 'A', 16, 16, LIT, "Burning barrel" },
	{ 71, "PAIN", 'A', 31, 56, MON, "Pain elemental" },
	{ 72, "KEEN", 'A', 16, 72, MON | TH_HANGING, "Commander Keen" },
	{ 73, "HDB1", 'A', 16, 88, HNG, "Hanging victim, guts removed" },
	{ 74, "HDB2", 'A', 16, 88, HNG, "Hanging victim, guts and brain removed" },
	{ 75, "HDB3", 'A', 16, 64, HNG, "Hanging torso, looking down" },
	{ 76, "HDB4", 'A', 16, 64, HNG, "Hanging torso, open skull" },
	{ 77, "HDB5", 'A', 16, 64, HNG, "Hanging torso, looking up" },
	{ 78, "HDB6", 'A', 16, 64, HNG, "Hanging torso, brain removed" },
	{ 79, "POB1", 'A', 20, 16, DEC, "Pool of blood" },
	{ 80, "POB2", 'A', 20, 16, DEC, "Pool of blood" },
	{ 81, "BRS1", 'A', 20, 16, DEC, "Pool of brains" },
	{ 82, "SGN2", 'A', 20, 16, WPN, "Super shotgun" },
	{ 83, "MEGA", 'A', 20, 16, PWR, "Megasphere" },
	{ 84, "SSWV", 'A', 20, 56, MON, "Wolfenstein SS" },
	{ 85, "TLMP", 'A', 16, 16, LIT, "Tall techno floor lamp" },
	{ 86, "TLP2", 'A', 16, 16, LIT, "Short techno floor lamp" },
	{ 87, "", 'A', 20, 32, INV, "Monster spawn spot" },
	{ 88, "BBRN", 'A', 16, 16, TH_SOLID | TH_SHOOTABLE, "Boss brain" },
	{ 89, "", 'A', 20, 32, INV, "Monster spawner" },
	{ 2001, "SHOT", 'A', 20, 16, WPN, "Shotgun" },
	{ 2002, "MGUN", 'A', 20, 16, WPN, "Chaingun" },
	{ 2003, "LAUN", 'A', 20, 16, WPN, "Rocket launcher" },
	{ 2004, "PLAS", 'A', 20, 16, WPN, "Plasma gun" },
	{ 2005, "CSAW", 'A', 20, 16, WPN, "Chainsaw" },
	{ 2006, "BFUG", 'A', 20, 16, WPN, "BFG9000" },
	{ 2007, "CLIP", 'A', 20, 16, AMO, "Clip" },
	{ 2008, "SHEL", 'A', 20, 16, AMO, "4 shotgun shells" },
	{ 2010, "ROCK", 'A', 20, 16, AMO, "Rocket" },
	{ 2011, "STIM", 'A', 20, 16, PIK, "Stimpack" },
	{ 2012, "MEDI", 'A', 20, 16, PIK, "Medikit" },
	{ 2013, "SOUL", 'A', 20, 16, PWR, "Soulsphere" },
	{ 2014, "BON1", 'A', 20, 16, PIK, "Health bonus" },
	{ 2015, "BON2", 'A', 20, 16, PIK, "Armor bonus" },
	{ 2018, "ARM1", 'A', 20, 16, PIK, "Green armor" },
	{ 2019, "ARM2", 'A', 20, 16, PIK, "Blue armor" },
	{ 2022, "PINV", 'A', 20, 16, PWR, "Invulnerability" },
	{ 2023, "PSTR", 'A', 20, 16, PWR, "Berserk" },
	{ 2024, "PINS", 'A', 20, 16, PWR, "Partial invisibility" },
	{ 2025, "SUIT", 'A', 20, 16, PWR, "Radiation shielding suit" },
	{ 2026, "PMAP", 'A', 20, 16, PWR, "Computer area map" },
	{ 2028, "COLU", 'A', 16, 16, LIT, "Floor lamp" },
	{ 2035, "BAR1", 'A', 10, 42, SOL | TH_SHOOTABLE, "Barrel" },
	{ 2045, "PVIS", 'A', 20, 16, PWR, "Light amplification visor" },
	{ 2046, "BROK", 'A', 20, 16, AMO, "Box of rockets" },
	{ 2047, "CELL", 'A', 20, 16, AMO, "Energy cell" },
	{ 2048, "AMMO", 'A', 20, 16, AMO, "Box of bullets" },
	{ 2049, "SBOX", 'A', 20, 16, AMO, "Box of shotgun shells" },
	{ 3001, "TROO", 'A', 20, 56, MON, "Imp" },
	{ 3002, "SARG", 'A', 30, 56, MON, "Demon" },
	{ 3003, "BOSS", 'A', 24, 64, MON, "Baron of Hell" },
	{ 3004, "POSS", 'A', 20, 56, MON, "Zombieman" },
	{ 3005, "HEAD", 'A', 31, 56, MON, "Cacodemon" },
	{ 3006, "SKUL", 'A', 16, 56, MON, "Lost soul" },
};

static const struct th_info th_light_info = {
	TH_LIGHT_FIRST, "", 'A', 8, 16, TH_LIGHT | TH_INVISIBLE, "arcaded light",
};

#define TH_N ((int)(sizeof th_table / sizeof th_table[0]))

/* light colours at full intensity, in the order of th.h */
static const uint8_t th_colours[8][3] = {
	{ 255, 255, 255 }, { 255, 64, 48 }, { 255, 160, 64 }, { 255, 240, 128 },
	{ 96, 255, 96 }, { 96, 240, 255 }, { 96, 128, 255 }, { 208, 96, 255 },
};

const struct th_info *th_find(uint16_t type)
{
	int lo = 0, hi = TH_N - 1;

	if (type >= TH_LIGHT_FIRST && type <= TH_LIGHT_LAST)
		return &th_light_info;
	while (lo <= hi) {
		int mid = (lo + hi) / 2;

		if (th_table[mid].type == type)
			return &th_table[mid];
		if (th_table[mid].type < type)
			lo = mid + 1;
		else
			hi = mid - 1;
	}
	return NULL;
}

int th_count(void)
{
	return TH_N;
}

const struct th_info *th_at(int i)
{
	return i < 0 || i >= TH_N ? NULL : &th_table[i];
}

int th_light(uint16_t type, struct th_light *out)
{
	int k, i;

	if (type < TH_LIGHT_FIRST || type > TH_LIGHT_LAST)
		return 0;
	k = type - TH_LIGHT_FIRST;
	i = (k >> 3) & 7;
	out->radius = 64 * ((k >> 6) + 1);
	out->intensity = (uint8_t)(i == 7 ? 255 : 32 * (i + 1));
	out->rgb[0] = th_colours[k & 7][0];
	out->rgb[1] = th_colours[k & 7][1];
	out->rgb[2] = th_colours[k & 7][2];
	return 1;
}

static int th_clamp7(int v)
{
	return v < 0 ? 0 : v > 7 ? 7 : v;
}

uint16_t th_light_type(int r, int i, int c)
{
	return (uint16_t)(TH_LIGHT_FIRST + 64 * th_clamp7(r) + 8 * th_clamp7(i) + th_clamp7(c));
}
