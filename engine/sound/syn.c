/*
 * syn: the built-in sounds' recipes and the synthesizer (contract in
 * syn.h). The recipes are data: one row per part, naming its sound.
 */
#include "engine/sound/syn.h"

#include <string.h>

#include "engine/core/tab.h"
#include "engine/sound/sfx.h"

enum syn_wave { SYN_SQUARE, SYN_TRI, SYN_SAW, SYN_SINE, SYN_NOISE };

/* One part: wave from `at` for `len` ms, f0 to f1 Hz (noise: how often a
 * new random value is drawn), peak amp, a rise of `attack` ms, then
 * `hold` percent of the rest at the peak before the linear fall. */
struct syn_part {
	uint8_t id;                    /* enum sfx_id */
	uint8_t wave;                  /* enum syn_wave */
	uint16_t at, len;
	uint16_t f0, f1;
	uint16_t amp;
	uint8_t attack, hold;
};

#define P(sfx, w, at, len, f0, f1, amp, att, hold) \
	{ SFX_##sfx, SYN_##w, at, len, f0, f1, amp, att, hold },
/* A note: a part of one frequency. */
#define N(sfx, w, at, len, f, amp, att, hold) P(sfx, w, at, len, f, f, amp, att, hold)

/* Notes, Hz. */
enum {
	F2 = 87, G2 = 98, C3 = 131, E3 = 165, G3 = 196, C4 = 262, D4 = 294, E4 = 330, F4 = 349,
	G4 = 392, A4 = 440, B4 = 494, C5 = 523, D5 = 587, E5 = 659, F5 = 698, G5 = 784,
	A5 = 880, B5 = 988, C6 = 1047, E6 = 1319, G6 = 1568, C7 = 2093, E7 = 2637, G7 = 3136,
};

static const struct syn_part syn_parts[] = {
	/* the player's pistol: a crack of white noise, a rumble, a thump */
	P(PISTOL, NOISE, 0, 150, 11025, 11025, 16000, 0, 5)
	P(PISTOL, NOISE, 0, 250, 3000, 1200, 7000, 0, 10)
	P(PISTOL, SQUARE, 0, 120, 180, 50, 8000, 0, 0)
	/* a bullet on a wall: a short tick and a ricochet's glide */
	P(WALLHIT, NOISE, 0, 50, 8000, 8000, 12000, 0, 0)
	P(WALLHIT, TRI, 0, 80, 2400, 1200, 5000, 0, 0)
	/* grunts: a rough "hup", a gunshot, a yelp, a falling groan */
	P(GRUNT_SIGHT, SAW, 0, 200, 150, 220, 11000, 20, 40)
	P(GRUNT_SIGHT, SAW, 200, 150, 220, 160, 9000, 5, 20)
	P(GRUNT_SIGHT, NOISE, 0, 300, 1500, 1500, 2500, 20, 40)
	P(GRUNT_ATTACK, NOISE, 0, 180, 11025, 11025, 15000, 0, 5)
	P(GRUNT_ATTACK, NOISE, 0, 300, 2000, 800, 7000, 0, 10)
	P(GRUNT_ATTACK, SQUARE, 0, 150, 140, 45, 8000, 0, 0)
	P(GRUNT_PAIN, SAW, 0, 300, 330, 200, 12000, 10, 20)
	P(GRUNT_PAIN, SQUARE, 0, 300, 165, 100, 4000, 10, 20)
	P(GRUNT_DEATH, SAW, 0, 700, 280, 70, 12000, 10, 20)
	P(GRUNT_DEATH, NOISE, 0, 500, 1800, 600, 4000, 10, 10)
	/* a grunt's wind-up: a gun cocked, two metal clicks and a rising whine
	 * for the 0.4 s before its shot */
	P(GRUNT_WINDUP, NOISE, 0, 30, 7000, 7000, 11000, 0, 0)
	N(GRUNT_WINDUP, SQUARE, 0, 60, 1500, 5000, 0, 20)
	P(GRUNT_WINDUP, NOISE, 160, 30, 9000, 9000, 11000, 0, 0)
	N(GRUNT_WINDUP, SQUARE, 160, 60, 2000, 5000, 0, 20)
	P(GRUNT_WINDUP, TRI, 0, 400, 600, 1400, 4000, 30, 60)
	/* brutes: a growl, a claw's swipe, a grunt, a long roar down */
	P(BRUTE_SIGHT, SAW, 0, 600, 80, 140, 12000, 40, 50)
	P(BRUTE_SIGHT, NOISE, 0, 600, 600, 900, 6000, 40, 50)
	P(BRUTE_SIGHT, SQUARE, 0, 600, 160, 280, 3000, 40, 50)
	P(BRUTE_ATTACK, NOISE, 0, 220, 2000, 9000, 16000, 30, 10)
	P(BRUTE_PAIN, SAW, 0, 350, 160, 90, 12000, 10, 20)
	P(BRUTE_PAIN, NOISE, 0, 350, 900, 900, 4000, 10, 20)
	P(BRUTE_DEATH, SAW, 0, 1000, 130, 35, 13000, 20, 30)
	P(BRUTE_DEATH, NOISE, 0, 1000, 700, 200, 6000, 20, 30)
	/* sentries: an electric warble, a fireball, a buzz, a dying whine */
	P(SENTRY_SIGHT, SQUARE, 0, 200, 500, 900, 7000, 5, 60)
	P(SENTRY_SIGHT, SQUARE, 200, 250, 900, 600, 7000, 5, 40)
	P(SENTRY_SIGHT, TRI, 0, 450, 1000, 1800, 4000, 5, 40)
	P(SENTRY_ATTACK, NOISE, 0, 500, 4000, 300, 15000, 5, 10)
	P(SENTRY_ATTACK, SINE, 0, 400, 260, 70, 9000, 5, 10)
	P(SENTRY_PAIN, SQUARE, 0, 250, 600, 320, 9000, 5, 20)
	P(SENTRY_DEATH, SQUARE, 0, 1100, 420, 45, 9000, 5, 20)
	P(SENTRY_DEATH, NOISE, 0, 1100, 2500, 150, 9000, 10, 10)
	/* the flyer (a burning skull): a flare of fire under a hollow rising
	 * shriek; its charge, a roar of fire that rises as it rushes in over
	 * a snapping jaw; a cracked squeal; a burst of fire and bone that
	 * crackles down to embers */
	P(FLYER_SIGHT, NOISE, 0, 450, 2500, 6000, 7000, 80, 30)
	P(FLYER_SIGHT, TRI, 0, 450, 600, 1500, 7000, 60, 40)
	P(FLYER_SIGHT, SQUARE, 100, 300, 1200, 1800, 2500, 40, 30)
	P(FLYER_ATTACK, NOISE, 0, 500, 1200, 9000, 13000, 250, 20)
	P(FLYER_ATTACK, SAW, 0, 500, 180, 520, 6000, 250, 20)
	P(FLYER_ATTACK, NOISE, 420, 40, 9000, 9000, 10000, 0, 0)
	N(FLYER_ATTACK, SQUARE, 420, 60, 900, 6000, 0, 10)
	P(FLYER_PAIN, SQUARE, 0, 220, 1400, 700, 8000, 5, 20)
	P(FLYER_PAIN, NOISE, 0, 150, 5000, 5000, 5000, 0, 10)
	P(FLYER_DEATH, NOISE, 0, 900, 7000, 300, 13000, 0, 10)
	P(FLYER_DEATH, SINE, 0, 600, 200, 45, 9000, 0, 10)
	P(FLYER_DEATH, TRI, 0, 500, 1000, 180, 4000, 5, 20)
	P(FLYER_DEATH, NOISE, 300, 600, 900, 900, 3000, 50, 10)
	/* a pickup: two quick notes up a fifth */
	N(PICKUP, TRI, 0, 60, C6, 12000, 2, 50)
	N(PICKUP, TRI, 60, 90, G6, 12000, 2, 40)
	/* the player: a grunt of pain, a long fall */
	P(PLAYER_HURT, SAW, 0, 250, 250, 150, 12000, 5, 20)
	P(PLAYER_HURT, NOISE, 0, 120, 2500, 2500, 5000, 0, 10)
	P(PLAYER_DEATH, SAW, 0, 1300, 320, 45, 13000, 10, 20)
	P(PLAYER_DEATH, SQUARE, 0, 1100, 160, 30, 5000, 10, 20)
	/* doors: a grinding slide up and a slide down that ends in a thud;
	 * the blazing door's are shorter, higher and hiss */
	P(DOOR_OPEN, NOISE, 0, 450, 700, 1100, 9000, 40, 60)
	P(DOOR_OPEN, SAW, 0, 450, 70, 110, 7000, 40, 60)
	P(DOOR_CLOSE, NOISE, 0, 400, 1100, 600, 9000, 30, 50)
	P(DOOR_CLOSE, SAW, 0, 400, 110, 60, 7000, 30, 50)
	P(DOOR_CLOSE, SQUARE, 380, 120, 90, 40, 9000, 0, 0)
	P(BLAZE_OPEN, NOISE, 0, 300, 2500, 5000, 10000, 10, 40)
	P(BLAZE_OPEN, SAW, 0, 300, 140, 260, 6000, 10, 40)
	P(BLAZE_CLOSE, NOISE, 0, 300, 5000, 2000, 10000, 10, 40)
	P(BLAZE_CLOSE, SAW, 0, 300, 260, 120, 6000, 10, 40)
	P(BLAZE_CLOSE, SQUARE, 280, 100, 100, 45, 8000, 0, 0)
	/* a floor or ceiling moving: a low stony rumble (started again every
	 * 8 Doom tics while it moves) */
	P(PLANE_MOVE, NOISE, 0, 230, 300, 300, 9000, 20, 60)
	N(PLANE_MOVE, SQUARE, 0, 230, 55, 5000, 20, 60)
	/* a lift: a motor starting up, and a clank as it stops */
	P(PLAT_START, SAW, 0, 350, 60, 180, 9000, 20, 50)
	P(PLAT_START, NOISE, 0, 350, 900, 1500, 4000, 20, 50)
	P(PLAT_STOP, NOISE, 0, 60, 6000, 6000, 9000, 0, 0)
	P(PLAT_STOP, SQUARE, 0, 200, 150, 70, 9000, 0, 10)
	/* switches: a click; the exit switch's is a click and a clunk */
	P(SWITCH, NOISE, 0, 25, 9000, 9000, 10000, 0, 0)
	N(SWITCH, SQUARE, 0, 70, 1200, 6000, 0, 20)
	P(SWITCH_EXIT, NOISE, 0, 25, 9000, 9000, 10000, 0, 0)
	N(SWITCH_EXIT, SQUARE, 0, 70, 1200, 6000, 0, 20)
	P(SWITCH_EXIT, SQUARE, 120, 160, 200, 80, 9000, 0, 10)
	/* a use on nothing: a short grunt; a locked door: a lower "oof" */
	P(NOWAY, SAW, 0, 180, 240, 180, 11000, 10, 30)
	P(NOWAY, NOISE, 0, 80, 2000, 2000, 3000, 5, 20)
	P(LOCKED, SAW, 0, 220, 180, 110, 12000, 10, 30)
	P(LOCKED, SQUARE, 0, 220, 90, 55, 4000, 10, 30)
	/* a teleport: a shimmering sweep up over a hiss */
	P(TELEPORT, TRI, 0, 700, 300, 2400, 9000, 30, 30)
	P(TELEPORT, SQUARE, 0, 700, 600, 4800, 3000, 30, 30)
	P(TELEPORT, NOISE, 0, 700, 6000, 6000, 5000, 60, 20)
	/* a coin: a metallic clink, inharmonic partials over a noise click,
	 * and a second, softer clink (distinct enough to be found by
	 * correlation in a recording of what the card played) */
	P(COIN, NOISE, 0, 12, 11025, 11025, 9000, 0, 0)
	N(COIN, SINE, 0, 180, 2794, 15000, 1, 10)
	N(COIN, SINE, 0, 120, 4186, 9000, 1, 0)
	N(COIN, SINE, 60, 120, 3322, 8000, 1, 0)
	/* a credit: an arpeggio up, after the coin's clink (g_sound.c) */
	N(CREDIT, TRI, 0, 80, C6, 12000, 2, 40)
	N(CREDIT, TRI, 80, 80, E6, 12000, 2, 40)
	N(CREDIT, TRI, 160, 80, G6, 12000, 2, 40)
	N(CREDIT, TRI, 240, 120, C7, 12000, 2, 40)
	N(CREDIT, SQUARE, 0, 80, C6, 3000, 2, 40)
	N(CREDIT, SQUARE, 80, 80, E6, 3000, 2, 40)
	N(CREDIT, SQUARE, 160, 80, G6, 3000, 2, 40)
	N(CREDIT, SQUARE, 240, 120, C7, 3000, 2, 40)
	/* a game starts: a rising sweep, then a high note */
	P(START, SQUARE, 0, 250, 220, 880, 9000, 5, 50)
	P(START, TRI, 0, 250, 330, 1320, 6000, 5, 50)
	N(START, TRI, 250, 250, C6, 12000, 2, 30)
	/* the last enemy falls: a major chord */
	N(STAGE_CLEAR, TRI, 0, 450, C5, 8000, 5, 50)
	N(STAGE_CLEAR, TRI, 0, 450, E5, 8000, 5, 50)
	N(STAGE_CLEAR, TRI, 0, 450, G5, 8000, 5, 50)
	N(STAGE_CLEAR, SQUARE, 0, 450, C6, 3000, 5, 50)
	/* the stage-clear fanfare */
	N(FANFARE, SQUARE, 0, 150, G4, 7000, 3, 60)
	N(FANFARE, SQUARE, 150, 150, C5, 7000, 3, 60)
	N(FANFARE, SQUARE, 300, 150, E5, 7000, 3, 60)
	N(FANFARE, SQUARE, 450, 300, G5, 7000, 3, 60)
	N(FANFARE, SQUARE, 750, 150, E5, 7000, 3, 60)
	N(FANFARE, SQUARE, 900, 900, G5, 7000, 3, 60)
	N(FANFARE, TRI, 900, 900, C6, 5000, 3, 60)
	N(FANFARE, TRI, 0, 900, C3, 7000, 5, 80)
	N(FANFARE, TRI, 900, 900, C3, 7000, 5, 60)
	N(FANFARE, TRI, 900, 900, G3, 5000, 5, 60)
	/* an extra life: two arpeggios up */
	N(EXTRA_LIFE, TRI, 0, 60, C6, 11000, 2, 50)
	N(EXTRA_LIFE, TRI, 60, 60, E6, 11000, 2, 50)
	N(EXTRA_LIFE, TRI, 120, 60, G6, 11000, 2, 50)
	N(EXTRA_LIFE, TRI, 180, 60, C7, 11000, 2, 50)
	N(EXTRA_LIFE, TRI, 240, 60, E7, 11000, 2, 50)
	N(EXTRA_LIFE, TRI, 300, 60, G7, 11000, 2, 50)
	N(EXTRA_LIFE, TRI, 360, 240, C7, 11000, 2, 40)
	/* game over: five steps down */
	N(GAME_OVER, SAW, 0, 300, G4, 9000, 5, 60)
	N(GAME_OVER, SAW, 300, 300, F4, 9000, 5, 60)
	N(GAME_OVER, SAW, 600, 300, E4, 9000, 5, 60)
	N(GAME_OVER, SAW, 900, 300, D4, 9000, 5, 60)
	N(GAME_OVER, SAW, 1200, 600, C4, 9000, 5, 60)
	N(GAME_OVER, TRI, 0, 600, G3, 6000, 5, 60)
	N(GAME_OVER, TRI, 600, 600, E3, 6000, 5, 60)
	N(GAME_OVER, TRI, 1200, 600, C3, 6000, 5, 60)
	/* the continue countdown's tick */
	N(COUNTDOWN, SQUARE, 0, 50, A5, 8000, 1, 50)
	N(COUNTDOWN, TRI, 0, 30, 1760, 3000, 1, 30)
	/* the menu: a blip to move, a rising blip to select */
	N(MENU_MOVE, TRI, 0, 35, 660, 9000, 1, 30)
	P(MENU_SELECT, TRI, 0, 90, 990, 1320, 10000, 1, 40)
	P(MENU_SELECT, SQUARE, 0, 90, 495, 660, 3000, 1, 40)
	/* the attract jingle: a tune over a walking bass */
	N(JINGLE, SQUARE, 0, 160, C5, 6000, 3, 60)
	N(JINGLE, SQUARE, 160, 160, E5, 6000, 3, 60)
	N(JINGLE, SQUARE, 320, 160, G5, 6000, 3, 60)
	N(JINGLE, SQUARE, 480, 160, C6, 6000, 3, 60)
	N(JINGLE, SQUARE, 640, 160, B5, 6000, 3, 60)
	N(JINGLE, SQUARE, 800, 160, G5, 6000, 3, 60)
	N(JINGLE, SQUARE, 960, 160, E5, 6000, 3, 60)
	N(JINGLE, SQUARE, 1120, 160, G5, 6000, 3, 60)
	N(JINGLE, SQUARE, 1280, 160, A5, 6000, 3, 60)
	N(JINGLE, SQUARE, 1440, 160, F5, 6000, 3, 60)
	N(JINGLE, SQUARE, 1600, 160, D5, 6000, 3, 60)
	N(JINGLE, SQUARE, 1760, 160, F5, 6000, 3, 60)
	N(JINGLE, SQUARE, 1920, 680, G5, 6000, 3, 60)
	N(JINGLE, TRI, 1920, 680, B5, 5000, 3, 60)
	N(JINGLE, TRI, 0, 640, C3, 7000, 5, 80)
	N(JINGLE, TRI, 640, 640, E3, 7000, 5, 80)
	N(JINGLE, TRI, 1280, 640, F2, 7000, 5, 80)
	N(JINGLE, TRI, 1920, 680, G2, 7000, 5, 60)
	/* the channel test: a steady 1 kHz sine */
	N(TONE, SINE, 0, 1000, 1000, 20000, 10, 95)
};

#define SYN_NPARTS (sizeof(syn_parts) / sizeof(syn_parts[0]))

static uint32_t syn_ms(uint32_t ms)
{
	return ms * SYN_RATE / 1000;
}

uint32_t syn_len(int id)
{
	uint32_t end = 0;

	for (size_t i = 0; i < SYN_NPARTS; i++)
		if (syn_parts[i].id == id && syn_ms((uint32_t)syn_parts[i].at + syn_parts[i].len) > end)
			end = syn_ms((uint32_t)syn_parts[i].at + syn_parts[i].len);
	return end;
}

static uint32_t syn_rand(uint32_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 17;
	*s ^= *s << 5;
	return *s;
}

/* The wave's value at phase ph (a binary angle: 2^32 is one period),
 * -32768..32767; noise keeps *held until the phase wraps. */
static int32_t syn_wave(int wave, uint32_t ph, uint32_t prev, uint32_t *seed, int32_t *held)
{
	switch (wave) {
	case SYN_SQUARE:
		return ph < 0x80000000u ? 32767 : -32767;
	case SYN_TRI: {
		int32_t q = (int32_t)(ph >> 15);          /* 0..131071 */
		return q < 65536 ? q - 32768 : 98303 - q;
	}
	case SYN_SAW:
		return (int32_t)(ph >> 16) - 32768;
	case SYN_SINE:
		return (int32_t)((int64_t)tab_sin(ph) * 32767 / FX_ONE);
	case SYN_NOISE:
	default:
		if (ph < prev)                  /* wrapped (or the first sample): a new value */
			*held = (int32_t)(syn_rand(seed) >> 16) - 32768;
		return *held;
	}
}

/* Adds part p (the k-th row of the table) to acc. */
static void syn_part(const struct syn_part *p, size_t k, int32_t *acc)
{
	uint32_t at = syn_ms(p->at), len = syn_ms(p->len), att = syn_ms(p->attack);
	uint32_t hold, fall, ph = 0, prev = UINT32_MAX, seed = 0x9e3779b9u ^ (uint32_t)(k * 2654435761u);
	int32_t held = 0;

	if (len == 0)
		return;
	if (att > len)
		att = len;
	hold = (len - att) * p->hold / 100;
	fall = len - att - hold;
	if (!seed)
		seed = 1;
	for (uint32_t t = 0; t < len; t++) {
		/* the frequency glides linearly; the step is 2^32 * f / rate */
		int64_t f = p->f0 + ((int64_t)p->f1 - p->f0) * t / len;
		int64_t env;
		int32_t v = syn_wave(p->wave, ph, prev, &seed, &held);

		if (t < att)
			env = (int64_t)p->amp * t / att;
		else if (t < att + hold)
			env = p->amp;
		else
			env = (int64_t)p->amp * (len - t) / (fall ? fall : 1);
		acc[at + t] += (int32_t)(v * env / 32768);
		prev = ph;
		ph += (uint32_t)(((uint64_t)f << 32) / SYN_RATE);
	}
}

uint32_t syn_make(int id, int16_t *out, int32_t *acc)
{
	uint32_t n = syn_len(id);

	if (n == 0)
		return 0;
	memset(acc, 0, n * sizeof(acc[0]));
	for (size_t i = 0; i < SYN_NPARTS; i++)
		if (syn_parts[i].id == id)
			syn_part(&syn_parts[i], i, acc);
	for (uint32_t t = 0; t < n; t++)
		out[t] = (int16_t)(acc[t] > 32767 ? 32767 : acc[t] < -32768 ? -32768 : acc[t]);
	return n;
}
