/*
 * g_weapon: the player's weapons (g_game.h struct g_weapon_info): their
 * numbers, changing the one held, and a weapon pickup's gift. The shot
 * itself is g_combat.c's g_fire, which reads the held weapon's row.
 *
 * Every weapon is hitscan and spends the one ammo count: the spread gun's
 * pellets are fanned at fixed angles (no randomness, so a shot's outcome
 * depends only on where the player stands and looks).
 */
#include "engine/game/g_local.h"

/* The fan: ANG45 / 36 is 1.25 degrees between neighbouring pellets, so
 * seven pellets cover 7.5 degrees, about 34 units to each side at 512
 * units (a grunt is 40 across). */
const struct g_weapon_info g_weapons[G_WEAPONS] = {
	[G_W_PISTOL] = { "PISTOL", G_SHOT_DAMAGE, 1, 1, G_REFIRE, 0, SFX_PISTOL },
	[G_W_SPREAD] = { "SPREAD", 10, 7, 3, 42, ANG45 / 36, SFX_GRUNT_ATTACK },
	[G_W_RAPID] = { "RAPID", 10, 1, 1, 6, 0, SFX_PISTOL },
};

int g_weapon_can_fire(const struct sim *s)
{
	const struct sim_player *p = &s->pl;

	return p->weapon < G_WEAPONS && p->refire == 0 && p->ammo >= g_weapons[p->weapon].ammo;
}

void g_weapon_next(struct sim *s)
{
	struct sim_player *p = &s->pl;

	for (int k = 1; k < G_WEAPONS; k++) {
		int w = (p->weapon + k) % G_WEAPONS;
		if (p->weapons & G_W_BIT(w)) {
			p->weapon = (uint8_t)w;
			return;
		}
	}
}

int g_weapon_give(struct sim *s, int w, int ammo)
{
	struct sim_player *p = &s->pl;
	int fresh = !(p->weapons & G_W_BIT(w));
	uint32_t a = (uint32_t)p->ammo + (uint32_t)ammo;

	if (!fresh && p->ammo >= G_AMMO_MAX)
		return 0;
	p->ammo = (uint16_t)(a > G_AMMO_MAX ? G_AMMO_MAX : a);
	if (fresh) {
		p->weapons = (uint8_t)(p->weapons | G_W_BIT(w));
		p->weapon = (uint8_t)w;
	}
	return 1;
}

void g_weapon_reset(struct sim *s)
{
	s->pl.weapons = G_W_BIT(G_W_PISTOL);
	s->pl.weapon = G_W_PISTOL;
}
