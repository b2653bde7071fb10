/*
 * sim_field: the sim's named values, for test scripts (input/scr.c parses
 * the names, the app reads the values) and tools. One table, so a new
 * field is one line here.
 */
#include <string.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"

struct sim_field_def {
	char name[12];
	enum sim_fkind kind;
};

enum {
	F_X, F_Y, F_Z, F_ANGLE, F_SECTOR, F_CREDITS, F_COINS, F_TICK, F_MODE,
	F_SCORE, F_LIVES, F_HEALTH, F_AMMO, F_STAGE, F_ENEMIES, F_KILLS, F_CONTINUES,
	F_COUNTDOWN, F_PAGE, F_PHASE, F_PLAYS, F_RANK, F_HISCORE, F_MENU, F_DIFFICULTY,
	F_CLOCK, F_WHY, F_WEAPON, F_MISSILES, F_MEND, F_PITCH, F_PLAYERS, F_UP, F_SCORE1,
	F_SCORE2, F_LIVES1, F_LIVES2, F_WINDING, F_WINDCRY, F_COUNT
};

static const struct sim_field_def sim_fields[F_COUNT] = {
	[F_X] = { "x", SIM_FK_FX },
	[F_Y] = { "y", SIM_FK_FX },
	[F_Z] = { "z", SIM_FK_FX },
	[F_ANGLE] = { "angle", SIM_FK_ANGLE },
	[F_SECTOR] = { "sector", SIM_FK_INT },
	[F_CREDITS] = { "credits", SIM_FK_INT },
	[F_COINS] = { "coins", SIM_FK_INT },
	[F_TICK] = { "tick", SIM_FK_INT },
	[F_MODE] = { "mode", SIM_FK_MODE },
	[F_SCORE] = { "score", SIM_FK_INT },
	[F_LIVES] = { "lives", SIM_FK_INT },
	[F_HEALTH] = { "health", SIM_FK_INT },
	[F_AMMO] = { "ammo", SIM_FK_INT },
	[F_STAGE] = { "stage", SIM_FK_INT },
	[F_ENEMIES] = { "enemies", SIM_FK_INT },
	[F_KILLS] = { "kills", SIM_FK_INT },
	[F_CONTINUES] = { "continues", SIM_FK_INT },
	[F_COUNTDOWN] = { "countdown", SIM_FK_INT },
	[F_PAGE] = { "page", SIM_FK_PAGE },
	[F_PHASE] = { "phase", SIM_FK_INT },
	[F_PLAYS] = { "plays", SIM_FK_INT },
	[F_RANK] = { "rank", SIM_FK_INT },
	[F_HISCORE] = { "hiscore", SIM_FK_INT },
	[F_MENU] = { "menu", SIM_FK_INT },
	[F_DIFFICULTY] = { "difficulty", SIM_FK_INT },
	[F_CLOCK] = { "clock", SIM_FK_INT },
	[F_WHY] = { "why", SIM_FK_INT },
	[F_WEAPON] = { "weapon", SIM_FK_INT },
	[F_MISSILES] = { "missiles", SIM_FK_INT },
	[F_MEND] = { "mend", SIM_FK_INT },
	[F_PITCH] = { "pitch", SIM_FK_INT },
	[F_PLAYERS] = { "players", SIM_FK_INT },
	[F_UP] = { "up", SIM_FK_INT },
	[F_SCORE1] = { "score1", SIM_FK_INT },
	[F_SCORE2] = { "score2", SIM_FK_INT },
	[F_LIVES1] = { "lives1", SIM_FK_INT },
	[F_LIVES2] = { "lives2", SIM_FK_INT },
	[F_WINDING] = { "winding", SIM_FK_INT },
	[F_WINDCRY] = { "windcry", SIM_FK_INT },
};

int sim_field_count(void)
{
	return F_COUNT;
}

const char *sim_field_name(int i)
{
	return i >= 0 && i < F_COUNT ? sim_fields[i].name : NULL;
}

enum sim_fkind sim_field_kind(int i)
{
	return i >= 0 && i < F_COUNT ? sim_fields[i].kind : SIM_FK_INT;
}

int sim_field_find(const char *name)
{
	for (int i = 0; i < F_COUNT; i++)
		if (strcmp(name, sim_fields[i].name) == 0)
			return i;
	return -1;
}

int64_t sim_field_value(const struct sim *s, int i)
{
	switch (i) {
	case F_X: return s->pl.x;
	case F_Y: return s->pl.y;
	case F_Z: return s->pl.z;
	case F_ANGLE: return (int64_t)(((uint64_t)s->pl.angle * 360u) >> 32);
	case F_SECTOR: return s->pl.sector;
	case F_CREDITS: return s->credits;
	case F_COINS: return s->coins_total;
	case F_TICK: return s->tick;
	case F_MODE: return s->mode;
	case F_SCORE: return s->g.score;
	case F_LIVES: return s->g.lives;
	/* whole points, rounded up: 0 only when dead */
	case F_HEALTH: return ((int64_t)s->pl.health + FX_ONE - 1) >> FX_SHIFT;
	case F_AMMO: return s->pl.ammo;
	case F_STAGE: return s->g.stage + 1;
	case F_ENEMIES: return s->g.alive;
	case F_KILLS: return s->g.kills;
	case F_CONTINUES: return s->g.continues;
	/* whole seconds left, rounded up: the number on the screen */
	case F_COUNTDOWN: return (s->countdown + SIM_TICRATE - 1) / SIM_TICRATE;
	case F_PAGE: return s->page;
	case F_PHASE: return s->g.phase;
	case F_PLAYS: return s->plays;
	case F_RANK: return s->new_rank + 1;
	case F_HISCORE: return s->scores.e[0].score;
	case F_MENU: return s->menu.page;
	case F_DIFFICULTY: return s->set.difficulty;
	/* the stage clock's whole seconds left, rounded up: the number on the screen */
	case F_CLOCK: return (s->g.clock + SIM_TICRATE - 1) / SIM_TICRATE;
	/* the last death's cause: 0 killed, 1 time up, 2 gone idle (enum g_why) */
	case F_WHY: return s->g.why;
	/* the weapon held, numbered from 1 as on the HUD (enum g_weapon + 1) */
	case F_WEAPON: return s->pl.weapon + 1;
	/* missiles flying (not exploding) */
	case F_MISSILES: return g_missiles_flying(s);
	/* how the last missile ended: 0 none yet, 1 wall, 2 floor or ceiling,
	 * 3 the player (enum g_mend) */
	case F_MEND: return s->g.mend;
	/* vertical aim in look steps (G_PITCH_STEP): -30 down .. 30 up */
	case F_PITCH: return s->pl.pitch / G_PITCH_STEP;
	/* players in the game (1, 2; 0 before the first) and whose turn it
	 * is, numbered as on the HUD (1 or 2) */
	case F_PLAYERS: return s->players;
	case F_UP: return s->up + 1;
	/* each player's score and lives: the player up's from the game, the
	 * other's from the waiting seat */
	case F_SCORE1: return s->up == 0 ? s->g.score : s->wait.score;
	case F_SCORE2: return s->up == 1 ? s->g.score : s->wait.score;
	case F_LIVES1: return s->up == 0 ? s->g.lives : s->wait.lives;
	case F_LIVES2: return s->up == 1 ? s->g.lives : s->wait.lives;
	/* enemies in their attack's wind-up (g_enemy_winding) */
	case F_WINDING: {
		int n = 0;
		for (int k = 0; k < s->g.num_enemies; k++)
			n += g_enemy_winding(&s->g.en[k]);
		return n;
	}
	/* channels playing a grunt's wind-up cry */
	case F_WINDCRY: {
		int n = 0;
		for (int k = 0; k < G_SND_CHANNELS; k++)
			n += s->snd.ch[k].sfx == SFX_GRUNT_WINDUP;
		return n;
	}
	default: return 0;
	}
}
