/*
 * g_spec: a stage's specials from start to exit: the world copied from the
 * map and its sector specials started (Doom's P_SpawnSpecials), then every
 * tick the movers in the order they were made, the light effects on each
 * Doom tic, the buttons, and what the player's sector does (Doom's
 * P_PlayerInSpecialSector: damage every 32 tics, secrets, the exit floor
 * of E1M8).
 *
 * The exit and the map after it: g_exit.c.
 *
 * Sector specials 0..17 are Doom's; a special of 32 and above is Boom's
 * generalized form, of which the game plays the light effect (bits 0-4, a
 * Doom special), the damage (bits 5-6: 5, 10, 20) and the secret (bit 7);
 * friction and wind (bits 8, 9) it does not.
 */
#include <stddef.h>
#include <string.h>

#include "engine/core/msg.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_SECRET_BIT 0x80              /* Boom's generalized secret */
#define G_BOOM_DAMAGE(sp) (((sp) >> 5) & 3)
#define G_BOOM_UNPLAYED 0xff00         /* friction, wind and above */

int g_world_fits(const struct map *m, char *err, size_t errlen)
{
	if (m->num_sectors <= G_MAX_SECTORS && m->num_lines <= G_MAX_LINES)
		return 1;
	if (err && errlen) {
		err[0] = '\0';
		msg_cat(err, errlen, m->name);
		msg_cat(err, errlen, ": ");
		msg_int(err, errlen, m->num_sectors);
		msg_cat(err, errlen, " sectors and ");
		msg_int(err, errlen, m->num_lines);
		msg_cat(err, errlen, " lines; the game plays maps of up to ");
		msg_int(err, errlen, G_MAX_SECTORS);
		msg_cat(err, errlen, " sectors and ");
		msg_int(err, errlen, G_MAX_LINES);
		msg_cat(err, errlen, " lines");
	}
	return 0;
}

static const char g_sector_names[18][44] = {
	"", "light blinks", "light strobes fast", "light strobes slow",
	"damage 20 and light strobes fast", "damage 10", "", "damage 5", "light glows", "secret",
	"door closes after 30 s", "damage 20, exit when health <= 10",
	"light strobes slow, together", "light strobes fast, together",
	"door opens after 5 minutes", "", "damage 20", "light flickers",
};

int g_sector_special(uint16_t type, char *out, size_t len)
{
	static const char dmg[4][12] = { "", "damage 5", "damage 10", "damage 20" };
	unsigned low = type & 31;
	int ok = (low < 18 && g_sector_names[low][0]) || low == 0;

	if (type < 32) {
		if (out && len) {
			out[0] = '\0';
			msg_cat(out, len, type < 18 ? g_sector_names[type] : "");
		}
		return type != 0 && ok;
	}
	if (out && len) {
		out[0] = '\0';
		msg_cat(out, len, "Boom:");
		if (low) {
			msg_cat(out, len, " ");
			msg_cat(out, len, low < 18 && g_sector_names[low][0] ? g_sector_names[low] : "?");
		}
		if (G_BOOM_DAMAGE(type)) {
			msg_cat(out, len, " ");
			msg_cat(out, len, dmg[G_BOOM_DAMAGE(type)]);
		}
		if (type & G_SECRET_BIT)
			msg_cat(out, len, " secret");
		if (type & G_BOOM_UNPLAYED)
			msg_cat(out, len, " friction/wind");
	}
	return ok && !(type & G_BOOM_UNPLAYED);
}

/* Doom's P_SpawnSpecials for one sector. */
static void g_spawn_sector(struct sim *s, uint32_t i)
{
	struct g_sector *g = &s->w.sec[i];
	uint16_t sp = g->special;
	int low = sp & 31;

	if ((sp & G_SECRET_BIT) || low == 9)
		s->w.secrets_total++;
	switch (low) {
	case 1:
		g_light_spawn(s, i, G_LFX_FLASH, 0);
		break;
	case 2:
	case 4:
		g_light_spawn(s, i, G_LFX_STROBE_FAST, 0);
		break;
	case 3:
		g_light_spawn(s, i, G_LFX_STROBE_SLOW, 0);
		break;
	case 8:
		g_light_spawn(s, i, G_LFX_GLOW, 0);
		break;
	case 12:
		g_light_spawn(s, i, G_LFX_STROBE_SLOW, 1);
		break;
	case 13:
		g_light_spawn(s, i, G_LFX_STROBE_FAST, 1);
		break;
	case 17:
		g_light_spawn(s, i, G_LFX_FLICKER, 0);
		break;
	case 10:
	case 14:
		g_door_spawn(s, i, low == 14);
		return;
	default:
		return;
	}
	/* a light effect is "nothing special during play" (but 4's damage) */
	if (low != 4)
		g->special = (uint16_t)(sp & ~31u);
}

void g_spec_start(struct sim *s)
{
	const struct map *m = s->map;
	struct g_world *w = &s->w;

	memset(w, 0, sizeof(*w));
	w->num_sectors = m->num_sectors;
	w->num_lines = m->num_lines;
	for (uint32_t i = 0; i < m->num_sectors; i++) {
		struct g_sector *g = &w->sec[i];
		g->floor_h = m->sectors[i].floor_h;
		g->ceil_h = m->sectors[i].ceil_h;
		g->floor_tex = m->sectors[i].floor_tex;
		g->special = m->sectors[i].special;
		g->light = m->sectors[i].light;
	}
	for (uint32_t i = 0; i < m->num_lines; i++) {
		uint16_t t = m->lines[i].special;
		if (t == 11 || t == 51 || t == 52 || t == 124)
			w->has_exit = 1;
	}
	for (uint32_t i = 0; i < m->num_sectors; i++) {
		if ((m->sectors[i].special & 31) == 11)
			w->has_exit = 1;
		g_spawn_sector(s, i);
	}
}

/* What the sector under the player does to it this tick. */
static void g_player_sector(struct sim *s)
{
	struct sim_player *p = &s->pl;
	struct g_sector *g = &s->w.sec[p->sector];
	int low = g->special & 31, boom = G_BOOM_DAMAGE(g->special);
	int dmg = boom ? 5 << (boom - 1) : 0;
	int due = g_dtic_now(s) && (g_dtic(s) & 31) == 0;

	if (g->special == 0)
		return;
	switch (low) {
	case 5:
		dmg = 10;
		break;
	case 7:
		dmg = 5;
		break;
	case 4:
	case 16:
		dmg = 20;
		break;
	case 11:
		if (due)
			g_hurt_player(s, 20 * FX_ONE);
		if (s->g.phase == G_PH_PLAY && p->health <= 10 * FX_ONE)
			g_exit(s, 0);
		return;
	default:
		break;
	}
	if ((g->special & G_SECRET_BIT) || low == 9) {
		s->w.secrets++;
		g->special = (uint16_t)(low == 9 ? g->special & ~31u : g->special & ~G_SECRET_BIT);
		g_message(s, G_MSG_SECRET);
		g_event(s, G_EV_SECRET, p->sector);
	}
	if (!dmg)
		return;
	/* the suit keeps it off, but a 20 leaks through at times (Doom) */
	if (s->w.suit && !(dmg == 20 && (g_random(s) & 255) < 5))
		return;
	if (due)
		g_hurt_player(s, dmg * FX_ONE);
}

void g_spec_tick(struct sim *s)
{
	struct g_world *w = &s->w;

	for (int i = 0; i < w->num_movers;) {
		struct g_mover *m = &w->mv[i];
		int gone;
		switch (m->kind) {
		case G_MV_DOOR:
			gone = g_door_tick(s, m);
			break;
		case G_MV_FLOOR:
			gone = g_floor_tick(s, m);
			break;
		case G_MV_CEIL:
			gone = g_ceil_tick(s, m);
			break;
		case G_MV_PLAT:
		default:
			gone = g_plat_tick(s, m);
			break;
		}
		if (!gone)
			i++;
	}
	if (g_dtic_now(s))
		g_lights_tic(s);
	g_buttons_tick(s);
	if (s->g.phase == G_PH_PLAY)
		g_player_sector(s);
	if (w->suit)
		w->suit--;
	if (w->msg) {
		if (w->msg_t < UINT16_MAX)
			w->msg_t++;
		if (w->msg_t >= G_MSG_TICKS) {
			w->msg = G_MSG_NONE;
			w->msg_t = 0;
		}
	}
}
