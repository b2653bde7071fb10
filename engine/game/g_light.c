/*
 * g_light: sector light effects and the lines that set lights (Doom's
 * p_lights.c). The effects run on Doom's 35 Hz clock (g_lights_tic once a
 * Doom tic), so their periods are Doom's: a strobe is 5 tics bright and 15
 * (fast) or 35 (slow) dark, a glow moves 8 levels a tic between its dark
 * and bright levels, a flicker changes every 4 tics, a blink stays bright
 * 1 or 65 tics and dark 1..8. Dark levels come from the darkest neighbour.
 * Randomness is the sim's RNG. A sector holds one effect (a second one
 * replaces the first).
 */
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_STROBE_BRIGHT 5
#define G_FAST_DARK 15
#define G_SLOW_DARK 35
#define G_GLOW_SPEED 8
#define G_FLASH_MAX 64                 /* Doom's maxtime: rand & 64 is 0 or 64 */
#define G_FLASH_MIN 7

static uint8_t g_clamp_light(int v)
{
	return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
}

void g_light_spawn(struct sim *s, uint32_t sec, int lfx, int sync)
{
	struct g_sector *g = &s->w.sec[sec];
	int min = g_light_around(s, sec, g->light, 0);

	g->lfx = (uint8_t)lfx;
	g->lmax = g->light;
	g->lmin = g_clamp_light(min);
	switch (lfx) {
	case G_LFX_FLASH:
		g->lcount = (uint8_t)((g_random(s) & G_FLASH_MAX) + 1);
		break;
	case G_LFX_STROBE_FAST:
	case G_LFX_STROBE_SLOW:
		if (g->lmin == g->lmax)
			g->lmin = 0;
		g->lcount = (uint8_t)(sync ? 1 : (g_random(s) & 7) + 1);
		break;
	case G_LFX_GLOW:
		g->lcount = 0;                 /* falling first */
		break;
	case G_LFX_FLICKER:
	default:
		g->lmin = g_clamp_light(min + 16);
		g->lcount = 4;
		break;
	}
}

/* Counts an effect's tics down: 1 when it changes this tic. */
static int g_light_due(struct g_sector *g)
{
	if (g->lcount > 1) {
		g->lcount--;
		return 0;
	}
	return 1;
}

static void g_light_tic(struct sim *s, struct g_sector *g)
{
	int v;

	switch (g->lfx) {
	case G_LFX_FLASH:
		if (!g_light_due(g))
			return;
		if (g->light == g->lmax) {
			g->light = g->lmin;
			g->lcount = (uint8_t)((g_random(s) & G_FLASH_MIN) + 1);
		} else {
			g->light = g->lmax;
			g->lcount = (uint8_t)((g_random(s) & G_FLASH_MAX) + 1);
		}
		return;
	case G_LFX_STROBE_FAST:
	case G_LFX_STROBE_SLOW:
		if (!g_light_due(g))
			return;
		if (g->light == g->lmin) {
			g->light = g->lmax;
			g->lcount = G_STROBE_BRIGHT;
		} else {
			g->light = g->lmin;
			g->lcount = g->lfx == G_LFX_STROBE_FAST ? G_FAST_DARK : G_SLOW_DARK;
		}
		return;
	case G_LFX_GLOW:
		v = g->light;
		if (g->lcount == 0) {
			v -= G_GLOW_SPEED;
			if (v <= g->lmin) {
				v += G_GLOW_SPEED;
				g->lcount = 1;
			}
		} else {
			v += G_GLOW_SPEED;
			if (v >= g->lmax) {
				v -= G_GLOW_SPEED;
				g->lcount = 0;
			}
		}
		g->light = g_clamp_light(v);
		return;
	case G_LFX_FLICKER:
		if (!g_light_due(g))
			return;
		v = (int)(g_random(s) & 3) * 16;
		g->light = g->light - v < g->lmin ? g->lmin : g_clamp_light(g->lmax - v);
		g->lcount = 4;
		return;
	default:
		return;
	}
}

void g_lights_tic(struct sim *s)
{
	for (uint32_t i = 0; i < s->w.num_sectors; i++)
		if (s->w.sec[i].lfx != G_LFX_NONE)
			g_light_tic(s, &s->w.sec[i]);
}

void g_light_set(struct sim *s, uint16_t tag, int level)
{
	/* Doom's EV_LightTurnOn keeps the brightest level it found for the
	 * first tagged sector and gives it to the others too */
	int bright = level == -1 ? 0 : level;

	for (uint32_t i = 0; i < s->w.num_sectors; i++) {
		struct g_sector *g = &s->w.sec[i];
		if (s->map->sectors[i].tag != tag)
			continue;
		if (level == -2) {
			g->light = g_clamp_light(g_light_around(s, i, g->light, 0));
			continue;
		}
		if (bright == 0)
			bright = g_light_around(s, i, 0, 1);
		g->light = g_clamp_light(bright);
	}
}

void g_light_strobe_tagged(struct sim *s, uint16_t tag)
{
	int sec = -1;

	while ((sec = g_tagged(s, tag, sec)) >= 0)
		if (!g_mover_of(s, (uint32_t)sec))
			g_light_spawn(s, (uint32_t)sec, G_LFX_STROBE_SLOW, 0);
}
