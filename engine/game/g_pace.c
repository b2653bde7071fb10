/*
 * g_pace: arcade pacing. A credit must not hold the cabinet for ever, so
 * every stage runs against a clock (set.stage_time minutes, full again for
 * each life; the operator may turn it off), whose last G_HURRY_TICKS wake every enemy, ambushers too,
 * and make them faster; at zero the player dies ("TIME UP"). A player who
 * gives no input for G_IDLE_TICKS is taken to have walked away
 * (set.idle_out: a life lost, the game ended, or nothing), as arcade
 * machines do; the last G_IDLE_WARN of those ticks count down on screen
 * and in sound. The whole seconds left at a clear or an exit score
 * G_TIME_BONUS each.
 */
#include "engine/game/g_local.h"

uint32_t g_pace_full(const struct sim *s)
{
	uint32_t min = s->set.stage_time;

	if (min == G_STAGE_TIME_OFF)
		return 0;
	if (min == 0)
		min = G_STAGE_TIME_DEFAULT;
	if (min > G_STAGE_TIME_MAX)
		min = G_STAGE_TIME_MAX;
	return min * 60u * SIM_TICRATE;
}

void g_pace_start(struct sim *s)
{
	s->g.clock = g_pace_full(s);
	s->g.idle_t = 0;
}

int g_pace_hurry(const struct sim *s)
{
	return s->mode == SIM_PLAY && s->g.phase == G_PH_PLAY && s->g.clock <= G_HURRY_TICKS &&
	       s->set.stage_time != G_STAGE_TIME_OFF;
}

/* Any stick, button or coin is a player at the controls. */
static int g_pace_input(const struct sim_cmd *c)
{
	return c->forward || c->side || c->turn || c->coins ||
	       (c->buttons & (SIM_BT_FIRE | SIM_BT_USE | SIM_BT_START | SIM_BT_START2 | SIM_BT_WEAPON));
}

static int g_idle_setting(const struct sim *s)
{
	return s->set.idle_out >= G_IDLE_COUNT ? G_IDLE_OFF : s->set.idle_out;
}

void g_pace_tick(struct sim *s, const struct sim_cmd *cmd)
{
	struct g_game *g = &s->g;
	int idle = g_idle_setting(s);

	if (g->phase != G_PH_PLAY)
		return;
	if (g_pace_input(cmd) || idle == G_IDLE_OFF)
		g->idle_t = 0;
	else if (g->idle_t < UINT16_MAX)
		g->idle_t++;
	if (g->idle_t >= G_IDLE_TICKS) {
		if (idle == G_IDLE_END)
			g->lives = 1;          /* this death ends the game */
		g_player_dies(s, G_WHY_IDLE);
		return;
	}
	if (g->idle_t > G_IDLE_TICKS - G_IDLE_WARN && (G_IDLE_TICKS - g->idle_t) % SIM_TICRATE == 0)
		g_sound_play(s, SFX_COUNTDOWN, G_SRC_TICKER);
	if (s->set.stage_time == G_STAGE_TIME_OFF)
		return;
	if (g->clock > 0)
		g->clock--;
	if (g->clock == 0) {
		g_player_dies(s, G_WHY_TIME);
		return;
	}
	if (g->clock == G_HURRY_TICKS) {
		/* everyone comes for the player */
		for (int i = 0; i < g->num_enemies; i++)
			if (g->en[i].state == G_E_IDLE) {
				g->en[i].state = G_E_CHASE;
				g->en[i].timer = 0;
				g->en[i].anim = 0;
			}
		g_sound_play(s, SFX_COUNTDOWN, G_SRC_TICKER);
	} else if (g->clock < 10 * SIM_TICRATE && g->clock % SIM_TICRATE == 0) {
		g_sound_play(s, SFX_COUNTDOWN, G_SRC_TICKER);
	}
}

void g_pace_bonus(struct sim *s)
{
	struct g_game *g = &s->g;

	g->time_bonus = (g->clock + SIM_TICRATE - 1) / SIM_TICRATE * G_TIME_BONUS;
	g->score += g->time_bonus;
}
