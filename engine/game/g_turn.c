/*
 * g_turn: two players alternating, the arcade standard. One player plays
 * at a time (the one "up": sim.up); the other's score, lives, continues,
 * stage, loop, kills, ammo and weapons wait in sim.wait. After each life
 * the player up loses, if the other is still in the game, the two change
 * places: the "PLAYER n" page (phase G_PH_TURN, G_TURN_TICKS), then that
 * player's stage from its start with their own state (the world is
 * loaded afresh: doors, pickups and enemies as the map has them). A player
 * whose game is over (no continue) is out; the other then plays on alone.
 */
#include <string.h>

#include "engine/game/g_local.h"

/* The player up's state into seat t. */
static void g_turn_save(const struct sim *s, struct g_seat *t)
{
	memset(t, 0, sizeof *t);
	t->score = s->g.score;
	t->lives = s->g.lives;
	t->continues = s->g.continues;
	t->stage = s->g.stage;
	t->loop = s->g.loop;
	t->kills = s->g.kills;
	t->ammo = s->pl.ammo;
	t->weapons = s->pl.weapons;
	t->weapon = s->pl.weapon;
}

/* The other player comes up: the seats change places (sim.c then loads
 * their stage behind the "PLAYER n" page). */
static void g_turn_swap(struct sim *s)
{
	struct g_seat in = s->wait;

	g_turn_save(s, &s->wait);
	s->up ^= 1;
	s->g.score = in.score;
	s->g.lives = in.lives;
	s->g.continues = in.continues;
	s->g.loop = in.loop;
	s->g.kills = in.kills;
	s->pl.health = G_HEALTH_MAX * FX_ONE;
	s->pl.ammo = in.ammo;
	s->pl.weapons = in.weapons;
	s->pl.weapon = in.weapon;
	s->g.stage = in.stage;
}

void g_turn_begin(struct sim *s, int players)
{
	s->players = (uint8_t)(players == 2 ? 2 : 1);
	s->up = 0;
	g_turn_save(s, &s->wait);
	if (s->players == 2)
		s->g.phase = G_PH_TURN;
}

static int g_turn_other_in(const struct sim *s)
{
	return s->players == 2 && !s->wait.out && s->wait.lives > 0;
}

int g_turn_pass(struct sim *s)
{
	if (!g_turn_other_in(s))
		return 0;
	g_turn_swap(s);
	return 1;
}

int g_turn_over(struct sim *s)
{
	if (!g_turn_other_in(s))
		return 0;
	g_turn_swap(s);
	s->wait.out = 1;               /* the player who just finished */
	return 1;
}
