/*
 * g_hurt: damage to the player and to the enemies, from every source:
 * enemies' attacks, the player's shot, crushing ceilings, damaging floors,
 * telefrags. Its own module so that the specials (which crush and
 * telefrag) and the enemies (which trigger specials) call it without
 * calling each other in a loop.
 */
#include "engine/game/g_local.h"

#define G_PAIN_TICKS 8
#define G_HURT_TICKS 12

/* Chance (of 256) that a hit makes an enemy flinch, per kind. */
static const uint8_t g_pain_chance[G_KINDS] = { 200, 80, 128, 200, 255 };

/* Each kind's sounds, by G_CRY_* (g_local.h); SFX_NONE for a wind-up
 * the kind does not have. */
static const uint8_t g_cries[G_KINDS][G_CRIES] = {
	[G_GRUNT] = { SFX_GRUNT_SIGHT, SFX_GRUNT_ATTACK, SFX_GRUNT_PAIN, SFX_GRUNT_DEATH,
		      SFX_GRUNT_WINDUP },
	[G_BRUTE] = { SFX_BRUTE_SIGHT, SFX_BRUTE_ATTACK, SFX_BRUTE_PAIN, SFX_BRUTE_DEATH, SFX_NONE },
	[G_SENTRY] = { SFX_SENTRY_SIGHT, SFX_SENTRY_ATTACK, SFX_SENTRY_PAIN, SFX_SENTRY_DEATH,
		       SFX_NONE },
	/* the imp's: Doom's imp cries as the brute's, its throw the fireball's */
	[G_THROWER] = { SFX_BRUTE_SIGHT, SFX_SENTRY_ATTACK, SFX_BRUTE_PAIN, SFX_BRUTE_DEATH,
			SFX_NONE },
	/* the lost soul's own: its charge is the bite's cry (Doom's DSSKLATK) */
	[G_FLYER] = { SFX_FLYER_SIGHT, SFX_FLYER_ATTACK, SFX_FLYER_PAIN, SFX_FLYER_DEATH,
		      SFX_NONE },
};

void g_cry(struct sim *s, int i, int cry)
{
	const struct g_enemy *e = &s->g.en[i];

	g_sound_start(s, g_cries[e->kind % G_KINDS][cry], e->x, e->y, (uint16_t)G_SRC_ENEMY(i));
}

void g_player_dies(struct sim *s, int why)
{
	if (s->g.phase != G_PH_PLAY)
		return;
	s->pl.health = 0;
	s->g.phase = G_PH_DEAD;
	s->g.phase_t = 0;
	s->g.why = (uint8_t)why;
	g_sound_play(s, SFX_PLAYER_DEATH, G_SRC_PLAYER);
}

void g_hurt_player(struct sim *s, fx_t dmg)
{
	if (s->g.phase != G_PH_PLAY)
		return;
	s->pl.health -= dmg;
	s->pl.hurt = G_HURT_TICKS;
	if (s->pl.health <= 0) {
		g_player_dies(s, G_WHY_KILLED);
		return;
	}
	g_sound_play(s, SFX_PLAYER_HURT, G_SRC_PLAYER);
}

static void g_hurt_state(struct g_enemy *e, int st, uint16_t timer)
{
	e->state = (uint8_t)st;
	e->timer = timer;
	e->anim = 0;
}

void g_hurt_enemy(struct sim *s, int i, int dmg)
{
	struct g_enemy *e = &s->g.en[i];

	if (e->state == G_E_DEAD)
		return;
	e->health = (int16_t)(e->health - dmg);
	if (e->health <= 0) {
		e->health = 0;
		g_hurt_state(e, G_E_DEAD, 0);
		e->flash = 0;
		s->g.alive--;
		s->g.kills++;
		s->g.score += g_kinds[e->kind].score;
		g_cry(s, i, G_CRY_DEATH);
		g_drop(s, i);
		return;
	}
	if ((g_random(s) & 255) < g_pain_chance[e->kind]) {
		g_hurt_state(e, G_E_PAIN, G_PAIN_TICKS);
		g_cry(s, i, G_CRY_PAIN);
	} else if (e->state == G_E_IDLE) {
		g_hurt_state(e, G_E_CHASE, 0);
		g_cry(s, i, G_CRY_SIGHT);
	}
}
