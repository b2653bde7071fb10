/*
 * g_exit: leaving a map (exit lines, the end-of-level floor) and Doom's
 * rule for the map that comes after it (ExM8 ends the episode, secret
 * exits to ExM9 and MAP31/32 and back). Its own module so that the line
 * specials (g_line.c) and the stage's sector specials (g_spec.c), which
 * both end maps, do not call each other.
 */
#include <string.h>

#include "engine/game/g_local.h"
#include "engine/map/map.h"

void g_exit(struct sim *s, int secret)
{
	struct g_game *g = &s->g;

	if (g->phase != G_PH_PLAY)
		return;
	s->w.exit = (uint8_t)(secret ? G_EXIT_SECRET : G_EXIT_NORMAL);
	s->w.exit_t = g->stage_t;
	s->w.next = (uint8_t)g_next_stage(s, secret);
	g->score += G_STAGE_BONUS * ((uint32_t)g->stage + 1);
	g_pace_bonus(s);
	g->phase = G_PH_INTER;
	g->phase_t = 0;
}

/* ---- the map after this one ------------------------------------------------ */

/* The stage whose map is called name, or -1. */
static int g_stage_named(const struct sim *s, const char *name)
{
	for (int i = 0; i < s->num_stages; i++)
		if (s->stages[i] && strncmp(s->stages[i]->name, name, 8) == 0)
			return i;
	return -1;
}

/* Two decimal digits of v into out. */
static void g_two(char *out, int v)
{
	out[0] = (char)('0' + v / 10 % 10);
	out[1] = (char)('0' + v % 10);
}

int g_next_stage(const struct sim *s, int secret)
{
	const char *cur = s->map->name;
	char name[9] = { 0 };
	int next = s->g.stage + 1 < s->num_stages ? s->g.stage + 1 : 0, t = -1;

	if (cur[0] == 'E' && cur[2] == 'M' && cur[1] >= '1' && cur[1] <= '9' && cur[3] >= '1' &&
	    cur[3] <= '9' && cur[4] == '\0') {
		/* Doom: the secret exit leads to ExM9, which leads back to the
		 * map after the one with the secret exit; ExM8 ends the episode */
		static const char back[5] = { '0', '4', '6', '7', '3' };
		int e = cur[1] - '0', mnum = cur[3] - '0';
		memcpy(name, cur, 5);
		if (secret)
			name[3] = '9';
		else if (mnum == 9)
			name[3] = e <= 4 ? back[e] : '1';
		else if (mnum == 8)
			return 0;
		else
			name[3] = (char)('0' + mnum + 1);
		t = g_stage_named(s, name);
		/* a secret exit whose map is not played: the normal exit's */
		if (t < 0 && secret)
			return g_next_stage(s, 0);
	} else if (strncmp(cur, "MAP", 3) == 0 && cur[3] >= '0' && cur[3] <= '9' && cur[4] >= '0' &&
		   cur[4] <= '9' && cur[5] == '\0') {
		/* Doom II: MAP15's secret exit to MAP31, its secret exit to
		 * MAP32, both back to MAP16; MAP30 is the end */
		int mnum = (cur[3] - '0') * 10 + (cur[4] - '0'), to;
		if (secret && mnum == 15)
			to = 31;
		else if (secret && mnum == 31)
			to = 32;
		else if (mnum == 31 || mnum == 32)
			to = 16;
		else if (mnum == 30)
			return 0;
		else
			to = mnum + 1;
		memcpy(name, "MAP", 3);
		g_two(name + 3, to);
		t = g_stage_named(s, name);
		/* a secret exit with no secret map is a normal one (Doom II) */
		if (t < 0 && secret)
			return g_next_stage(s, 0);
	}
	return t >= 0 ? t : next;
}
