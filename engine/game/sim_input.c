/*
 * sim_input: what the sim makes of a tick's command before the modes act
 * on it: coins into credits, credits spent on a start or continue, and the
 * menu and initials directions with their repeat. Called by sim.c only.
 */
#include "engine/game/g_local.h"
#include "engine/game/sim.h"

#define SIM_NAV_DELAY 20               /* ticks before a held direction repeats */
#define SIM_NAV_REPEAT 6               /* ticks between repeats */

void sim_coins(struct sim *s, uint8_t coins)
{
	uint32_t per = s->set.coins_per_credit ? s->set.coins_per_credit : 1;
	uint32_t credits = s->credits;

	if (!coins)
		return;
	s->coins_total += coins;
	s->books.coins += coins;
	s->books_gen++;
	s->coin_rem += coins;
	while (s->coin_rem >= per) {
		s->coin_rem -= per;
		s->credits++;
	}
	/* the coin's clink; a credit's chime right after it */
	g_sound_play(s, SFX_COIN, G_SRC_COIN);
	if (s->credits != credits)
		s->snd.credit_t = G_CREDIT_DELAY;
}

/* Spends n credits (a credit a player) for a start or continue; 0 if there
 * are fewer. */
int sim_pay(struct sim *s, uint32_t n)
{
	if (s->set.freeplay)
		return 1;
	if (s->credits < n)
		return 0;
	s->credits -= n;
	return 1;
}

/* Directions held in cmd, as MENU_NAV_* bits: forward is up, back is
 * down, turning or strafing left is left, right is right. */
static uint8_t sim_dirs(const struct sim_cmd *c)
{
	return (uint8_t)((c->forward > 0 ? MENU_NAV_UP : 0) | (c->forward < 0 ? MENU_NAV_DOWN : 0) |
			 (c->turn > 0 || c->side < 0 ? MENU_NAV_LEFT : 0) |
			 (c->turn < 0 || c->side > 0 ? MENU_NAV_RIGHT : 0));
}

/* This tick's navigation: new directions, and held ones every
 * SIM_NAV_REPEAT ticks after SIM_NAV_DELAY. */
uint8_t sim_nav(struct sim *s, const struct sim_cmd *c)
{
	uint8_t held = sim_dirs(c), nav = (uint8_t)(held & ~s->prev_nav);

	if (held != s->prev_nav)
		s->nav_t = 0;
	else if (s->nav_t < UINT16_MAX)
		s->nav_t++;
	if (held && s->nav_t >= SIM_NAV_DELAY && (s->nav_t - SIM_NAV_DELAY) % SIM_NAV_REPEAT == 0)
		nav |= held;
	s->prev_nav = held;
	return nav;
}
