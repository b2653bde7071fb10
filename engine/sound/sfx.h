/*
 * sfx: the game's sounds by number. One list (SFX_LIST) gives every sound
 * its id, the name the service menu's sound test shows, the Doom sound
 * lump a WAD may give it, and its priority; the enum, the names and the
 * table all come from that list.
 *
 * Priority as in Doom: a smaller number is more important. When every
 * channel is busy, a new sound takes the channel of the least important
 * sound that is not more important than it (engine/game/g_sound.c).
 *
 * Lumps: with a WAD, a sound whose lump the WAD holds plays the lump's
 * samples; one without ("" here, or a lump the WAD lacks or that is
 * malformed) plays the built-in synthesized sound (engine/sound/syn.c).
 */
#ifndef ARCADED_ENGINE_SFX_H
#define ARCADED_ENGINE_SFX_H

#include <stdint.h>

/* X(ID, "SHOWN NAME", "DSLUMP", priority) */
#define SFX_LIST(X) \
	X(PISTOL, "PISTOL SHOT", "DSPISTOL", 64) \
	X(WALLHIT, "SHOT HITS WALL", "", 90) \
	X(GRUNT_SIGHT, "GRUNT SIGHT", "DSPOSIT1", 98) \
	X(GRUNT_ATTACK, "GRUNT ATTACK", "DSSHOTGN", 70) \
	X(GRUNT_PAIN, "GRUNT PAIN", "DSPOPAIN", 96) \
	X(GRUNT_DEATH, "GRUNT DEATH", "DSPODTH1", 70) \
	X(GRUNT_WINDUP, "GRUNT WIND-UP", "DSSGCOCK", 70) \
	X(BRUTE_SIGHT, "BRUTE SIGHT", "DSBGSIT1", 98) \
	X(BRUTE_ATTACK, "BRUTE ATTACK", "DSCLAW", 70) \
	X(BRUTE_PAIN, "BRUTE PAIN", "DSDMPAIN", 96) \
	X(BRUTE_DEATH, "BRUTE DEATH", "DSBGDTH1", 70) \
	X(SENTRY_SIGHT, "SENTRY SIGHT", "DSCACSIT", 98) \
	X(SENTRY_ATTACK, "SENTRY ATTACK", "DSFIRSHT", 70) \
	X(SENTRY_PAIN, "SENTRY PAIN", "DSDMPAIN", 96) \
	X(SENTRY_DEATH, "SENTRY DEATH", "DSCACDTH", 70) \
	X(FLYER_SIGHT, "FLYER SIGHT", "", 98) \
	X(FLYER_ATTACK, "FLYER CHARGE", "DSSKLATK", 70) \
	X(FLYER_PAIN, "FLYER PAIN", "DSDMPAIN", 96) \
	X(FLYER_DEATH, "FLYER DEATH", "DSFIRXPL", 70) \
	X(PICKUP, "PICKUP", "DSITEMUP", 78) \
	X(PLAYER_HURT, "PLAYER HURT", "DSPLPAIN", 96) \
	X(PLAYER_DEATH, "PLAYER DEATH", "DSPLDETH", 32) \
	X(DOOR_OPEN, "DOOR OPEN", "DSDOROPN", 100) \
	X(DOOR_CLOSE, "DOOR CLOSE", "DSDORCLS", 100) \
	X(BLAZE_OPEN, "FAST DOOR OPEN", "DSBDOPN", 100) \
	X(BLAZE_CLOSE, "FAST DOOR CLOSE", "DSBDCLS", 100) \
	X(PLANE_MOVE, "FLOOR MOVING", "DSSTNMOV", 119) \
	X(PLAT_START, "LIFT START", "DSPSTART", 100) \
	X(PLAT_STOP, "LIFT STOP", "DSPSTOP", 100) \
	X(SWITCH, "SWITCH", "DSSWTCHN", 78) \
	X(SWITCH_EXIT, "EXIT SWITCH", "DSSWTCHX", 78) \
	X(NOWAY, "NO WAY", "DSNOWAY", 78) \
	X(LOCKED, "LOCKED", "DSOOF", 96) \
	X(TELEPORT, "TELEPORT", "DSTELEPT", 32) \
	X(COIN, "COIN DROP", "", 8) \
	X(CREDIT, "CREDIT ADDED", "", 8) \
	X(START, "GAME START", "", 10) \
	X(STAGE_CLEAR, "STAGE CLEAR", "", 20) \
	X(FANFARE, "STAGE FANFARE", "", 20) \
	X(EXTRA_LIFE, "EXTRA LIFE", "", 12) \
	X(GAME_OVER, "GAME OVER", "", 20) \
	X(COUNTDOWN, "CONTINUE TICK", "", 30) \
	X(MENU_MOVE, "MENU MOVE", "DSPSTOP", 16) \
	X(MENU_SELECT, "MENU SELECT", "DSPISTOL", 16) \
	X(JINGLE, "ATTRACT JINGLE", "", 40) \
	X(TONE, "TEST TONE", "", 16)

#define SFX_ENUM(id, shown, lump, prio) SFX_##id,
enum sfx_id { SFX_NONE, SFX_LIST(SFX_ENUM) SFX_COUNT };
#undef SFX_ENUM

struct sfx_info {
	char name[16];                 /* shown on the sound test page */
	char lump[9];                  /* Doom lump, "" none */
	uint8_t priority;              /* smaller: more important */
};

/* Indexed by enum sfx_id; SFX_NONE's entry is empty. */
extern const struct sfx_info sfx_table[SFX_COUNT];

/* The entry of id, or SFX_NONE's for an id out of range. */
const struct sfx_info *sfx_info(int id);

#endif
