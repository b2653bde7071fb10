/*
 * g_sound: the game's side of sound, part of the deterministic sim.
 *
 * The sim emits sounds from its rules (a shot, an enemy's cry, a coin,
 * the menu): each start names a sound (enum sfx_id, engine/sound/sfx.h),
 * where it is (a point in the map, or nowhere: the player's own sounds
 * and the cabinet's) and its source. The sounds playing are channels in
 * the sim's state (struct g_sound, below): hashed every tick and saved in
 * snapshots like every other field, so a replay, also one that starts
 * from a snapshot (the flight recorder's games), has the very channels the
 * cabinet had. The app mixes them after each tick (g_sound_voices, then
 * engine/sound/mix.h), which is a pure function of this state and the
 * sound set: the audio of a tick is reproduced bit for bit.
 *
 * Doom's rules (Chocolate Doom's s_sound.c, values of vanilla Doom):
 *   - distance: the approximate distance adx + ady - min(adx, ady) / 2
 *     from the listener (the player) to the origin; full volume (127)
 *     within G_SND_CLOSE (200 units), silent past G_SND_CLIP (1200 units:
 *     the sound is not started, or a playing one is stopped), linear
 *     between: 127 * (1200 - dist) / 1000, whole units;
 *   - stereo: separation 128 - 96 * sin(angle of the origin seen from the
 *     listener's view), so 32 is hard left, 224 hard right; the gains are
 *     SDL's panning as Chocolate Doom sets it: left (254 - sep) * vol /
 *     127, right sep * vol / 127, each 0..255; a sound not in the map
 *     plays at volume 127, separation 128;
 *   - volume and separation are computed again every tick as the player
 *     (and an enemy source) moves;
 *   - channels: G_SND_CHANNELS. A source's new sound replaces its old one
 *     (an enemy's death cuts its pain cry); otherwise a free channel;
 *     otherwise the channel of the least important sound (largest
 *     priority number, sfx.h) that is not more important than the new
 *     one, the oldest of those, then the lowest index (Doom takes the
 *     first such channel by index); otherwise the new sound is dropped.
 *
 * Attract mode: the setting attract_sound (sim_settings) is 0 off, 1 on,
 * N (2..9) on in one attract cycle of every N (the first, the N+1-th...).
 * While it is off, attract mode starts no sound but the coin's, the
 * credit's and the game start's (a player putting money in hears it), and
 * the demo's sounds are not mixed.
 *
 * Movers (doors, lifts, switches: line and sector specials) start their
 * sounds with g_sound_start(s, SFX_..., x, y, G_SRC_SECTOR(sector)): one
 * sound per sector, the next replacing the last; g_sound_stop ends one.
 * A new sound is one line in SFX_LIST (sfx.h) and a recipe in syn.c.
 */
#ifndef ARCADED_ENGINE_G_SOUND_H
#define ARCADED_ENGINE_G_SOUND_H

#include <stdint.h>

#include "engine/core/fx.h"
#include "engine/game/sim_table.h"
#include "engine/sound/sfx.h"

struct sim;
struct snd_set;
struct mix_voice;

#define G_SND_CHANNELS 16
#define G_VOLUME_MAX 100               /* the master volume setting's top (MIX_VOLUME_MAX) */
#define G_SND_VOL 127                  /* Doom's full sound volume */
#define G_SND_SEP_MAX 254              /* separation: 0 hard left, 128 centre, 254 hard right */
#define G_SND_CLOSE (200 * FX_ONE)
#define G_SND_CLIP (1200 * FX_ONE)
#define G_SND_SWING (96 * FX_ONE)
/* The credit chime follows the coin's clink by this many ticks. */
#define G_CREDIT_DELAY 12

/* Sources: one sound each at a time. G_SRC_NONE is never replaced. */
#define G_SRC_NONE 0
#define G_SRC_WEAPON 1                 /* the player's shots */
#define G_SRC_PLAYER 2                 /* the player's voice: hurt, death */
#define G_SRC_ITEM 3                   /* pickups */
#define G_SRC_PUFF 4                   /* where the last shot hit a wall */
#define G_SRC_COIN 5
#define G_SRC_CREDIT 6
#define G_SRC_ANNOUNCE 7               /* start, stage clear, game over */
#define G_SRC_MUSIC 8                  /* attract jingle, stage fanfare */
#define G_SRC_BONUS 9                  /* extra life */
#define G_SRC_TICKER 10                /* the continue countdown */
#define G_SRC_MENU 11                  /* menu and initials */
#define G_SRC_TEST 12                  /* the service menu's sound test */
#define G_SRC_ENEMY(i) (64 + (i))      /* enemy i (G_MAX_ENEMIES of them) */
#define G_SRC_SECTOR(i) (1024 + (i))   /* a mover of sector i */

/* One channel; free when sfx is SFX_NONE (then every field is 0). */
#define G_SCHAN_FIELDS(X) \
	X(VAL, uint8_t, sfx, SIM_MAX(SFX_COUNT - 1)) /* enum sfx_id */ \
	X(VAL, uint8_t, vol, SIM_MAX(G_SND_VOL))     /* this tick's volume, 0..127 */ \
	X(VAL, uint8_t, sep, SIM_MAX(G_SND_SEP_MAX)) /* this tick's separation */ \
	X(VAL, uint8_t, at, SIM_MAX(1))              /* 1: at (x, y) in the map */ \
	X(VAL, uint16_t, src, SIM_ANY)               /* G_SRC_* */ \
	X(VAL, uint16_t, age, SIM_ANY)               /* ticks since it started */ \
	X(VAL, uint16_t, len, SIM_ANY)               /* ticks it plays */ \
	X(VAL, fx_t, x, SIM_COORD) \
	X(VAL, fx_t, y, SIM_COORD)
struct g_schan {
	G_SCHAN_FIELDS(SIM_MEMBER)
};

#define G_SOUND_FIELDS(X) \
	X(SUBS, g_schan, ch, G_SND_CHANNELS, SIM_ALL) \
	/* each sound's length in ticks, of the set the app loaded (sim_set_sounds) */ \
	X(ARR, uint16_t, len, SFX_COUNT, SIM_ALL, SIM_ANY) \
	X(VAL, uint8_t, credit_t, SIM_ANY)           /* ticks until the credit chime, 0 none */
struct g_sound {
	G_SOUND_FIELDS(SIM_MEMBER)
};

/* Starts sound id at (x, y) in the current map, from source src, under
 * the rules above. Returns the channel, or -1 when it is not started (out
 * of hearing, muted in attract, no channel free for its priority, or an
 * id out of range). */
int g_sound_start(struct sim *s, int id, fx_t x, fx_t y, uint16_t src);

/* Starts sound id where the player is: full volume, centred (the player's
 * own sounds and the cabinet's). Same return. */
int g_sound_play(struct sim *s, int id, uint16_t src);

/* Starts sound id at full volume on one side: sep 0 (left only) or
 * G_SND_SEP_MAX (right only); the channel test. Same return. */
int g_sound_pan(struct sim *s, int id, int sep, uint16_t src);

/* Stops the sound of source src, if one plays. */
void g_sound_stop(struct sim *s, uint16_t src);

/* Stops every sound; with cabinet set, the coin's, credit's and start's
 * play on (a new stage or mode silences the world, not the cabinet). */
void g_sound_clear(struct sim *s, int cabinet);

/* At the start of each tick: the sounds grow a tick older; finished
 * ones free their channel; the credit's chime when it is due. */
void g_sound_age(struct sim *s);

/* At the end of each tick: volume and separation of the sounds in the
 * map again, from where the player and the enemies are now (out of
 * hearing: stopped). */
void g_sound_follow(struct sim *s);

/* Whether attract mode's sounds are heard now (the setting, this cycle). */
int g_sound_attract_on(const struct sim *s);

/* The voices to mix after a tick of s, with the sounds of set: every
 * playing channel of s, and those of under (the attract demo's sim, may
 * be NULL) while the attract sound is on. Gains from volume and
 * separation as above. Writes at most max voices; returns their number. */
int g_sound_voices(const struct sim *s, const struct sim *under, const struct snd_set *set,
		   struct mix_voice *out, int max);

/* Doom's gains for volume vol (0..127) and separation sep (0..254):
 * left (254 - sep) * vol / 127, right sep * vol / 127, clamped to 0..255. */
void g_sound_gains(int vol, int sep, uint16_t *left, uint16_t *right);

#endif
