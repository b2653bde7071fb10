/*
 * g_sound: channels, Doom's distance and stereo rules, the voices to mix
 * (contract in g_sound.h).
 */
#include "engine/game/g_sound.h"

#include <string.h>

#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"
#include "engine/sound/mix.h"
#include "engine/sound/snd.h"

_Static_assert(G_VOLUME_MAX == MIX_VOLUME_MAX, "the volume setting is the mixer's");

/* Doom's volume and separation of a sound at (x, y) heard by the player:
 * 1 and both set, or 0 when it is out of hearing. */
static int g_sound_hear(const struct sim *s, fx_t x, fx_t y, int *vol, int *sep)
{
	int64_t adx = (int64_t)x - s->pl.x, ady = (int64_t)y - s->pl.y, dist;
	ang_t rel;

	adx = adx < 0 ? -adx : adx;
	ady = ady < 0 ? -ady : ady;
	dist = adx + ady - (adx < ady ? adx : ady) / 2;
	if (dist > G_SND_CLIP)
		return 0;
	if (adx == 0 && ady == 0) {
		/* on the listener: no direction */
		*sep = 128;
	} else {
		rel = tab_atan2((fx_t)(y - s->pl.y), (fx_t)(x - s->pl.x)) - s->pl.angle;
		*sep = 128 - fx_to_int(fx_mul(G_SND_SWING, tab_sin(rel)));
	}
	if (dist < G_SND_CLOSE)
		*vol = G_SND_VOL;
	else
		*vol = (int)(G_SND_VOL * ((G_SND_CLIP - dist) / FX_ONE) /
			     ((G_SND_CLIP - G_SND_CLOSE) / FX_ONE));
	return *vol > 0;
}

/* Sounds a player hears in attract mode whatever the setting. */
static int g_sound_cabinet(int id)
{
	return id == SFX_COIN || id == SFX_CREDIT || id == SFX_START;
}

int g_sound_attract_on(const struct sim *s)
{
	int n = s->set.attract_sound;

	if (s->mode != SIM_ATTRACT || n == 0)
		return 0;
	/* cycle counts from 1 once the first has begun */
	return n == 1 || (s->attract_cycle ? s->attract_cycle - 1 : 0) % (uint32_t)n == 0;
}

static void g_sound_free(struct g_schan *c)
{
	memset(c, 0, sizeof(*c));
}

/* The channel for a new sound of priority prio from src (Doom's rule, with
 * the least important and oldest taken first), or -1. */
static int g_sound_channel(struct sim *s, int prio, uint16_t src)
{
	struct g_sound *g = &s->snd;
	int best = -1;

	if (src != G_SRC_NONE)
		g_sound_stop(s, src);
	for (int i = 0; i < G_SND_CHANNELS; i++)
		if (g->ch[i].sfx == SFX_NONE)
			return i;
	for (int i = 0; i < G_SND_CHANNELS; i++) {
		const struct g_schan *c = &g->ch[i];
		int p = sfx_info(c->sfx)->priority;

		if (p < prio)
			continue;          /* more important than the new sound */
		if (best < 0) {
			best = i;
			continue;
		}
		int bp = sfx_info(g->ch[best].sfx)->priority;
		if (p > bp || (p == bp && c->age > g->ch[best].age))
			best = i;
	}
	return best;
}

/* Starts id: at (x, y) when at, else at volume 127 and separation sep. */
static int g_sound_put(struct sim *s, int id, int at, fx_t x, fx_t y, int sep, uint16_t src)
{
	struct g_schan *c;
	int vol = G_SND_VOL, i;

	if (id <= SFX_NONE || id >= SFX_COUNT)
		return -1;
	if (s->mode == SIM_ATTRACT && !g_sound_cabinet(id) && !g_sound_attract_on(s))
		return -1;
	if (at && !g_sound_hear(s, x, y, &vol, &sep))
		return -1;
	i = g_sound_channel(s, sfx_info(id)->priority, src);
	if (i < 0)
		return -1;
	c = &s->snd.ch[i];
	g_sound_free(c);
	c->sfx = (uint8_t)id;
	c->vol = (uint8_t)vol;
	c->sep = (uint8_t)(sep < 0 ? 0 : sep > G_SND_SEP_MAX ? G_SND_SEP_MAX : sep);
	c->at = (uint8_t)(at != 0);
	c->src = src;
	c->len = s->snd.len[id];
	if (at) {
		c->x = x;
		c->y = y;
	}
	return i;
}

int g_sound_start(struct sim *s, int id, fx_t x, fx_t y, uint16_t src)
{
	return g_sound_put(s, id, 1, x, y, 128, src);
}

int g_sound_play(struct sim *s, int id, uint16_t src)
{
	return g_sound_put(s, id, 0, 0, 0, 128, src);
}

int g_sound_pan(struct sim *s, int id, int sep, uint16_t src)
{
	return g_sound_put(s, id, 0, 0, 0, sep, src);
}

void g_sound_stop(struct sim *s, uint16_t src)
{
	for (int i = 0; i < G_SND_CHANNELS; i++)
		if (s->snd.ch[i].sfx != SFX_NONE && s->snd.ch[i].src == src)
			g_sound_free(&s->snd.ch[i]);
}

void g_sound_clear(struct sim *s, int cabinet)
{
	for (int i = 0; i < G_SND_CHANNELS; i++) {
		struct g_schan *c = &s->snd.ch[i];
		if (cabinet && (c->src == G_SRC_COIN || c->src == G_SRC_CREDIT ||
				c->src == G_SRC_ANNOUNCE))
			continue;
		g_sound_free(c);
	}
	if (!cabinet)
		s->snd.credit_t = 0;
}

void g_sound_age(struct sim *s)
{
	for (int i = 0; i < G_SND_CHANNELS; i++) {
		struct g_schan *c = &s->snd.ch[i];
		if (c->sfx == SFX_NONE)
			continue;
		if (c->age < UINT16_MAX)
			c->age++;
		if (c->age >= c->len)
			g_sound_free(c);
	}
	/* the credit's chime, G_CREDIT_DELAY ticks after the coin that made it */
	if (s->snd.credit_t && --s->snd.credit_t == 0)
		g_sound_play(s, SFX_CREDIT, G_SRC_CREDIT);
}

void g_sound_follow(struct sim *s)
{
	for (int i = 0; i < G_SND_CHANNELS; i++) {
		struct g_schan *c = &s->snd.ch[i];
		int vol, sep;

		if (c->sfx == SFX_NONE || !c->at)
			continue;
		if (c->src >= G_SRC_ENEMY(0) && c->src < G_SRC_ENEMY(s->g.num_enemies)) {
			/* the cry moves with its enemy */
			const struct g_enemy *e = &s->g.en[c->src - G_SRC_ENEMY(0)];
			c->x = e->x;
			c->y = e->y;
		}
		if (!g_sound_hear(s, c->x, c->y, &vol, &sep)) {
			g_sound_free(c);
			continue;
		}
		c->vol = (uint8_t)vol;
		c->sep = (uint8_t)sep;
	}
}

void g_sound_gains(int vol, int sep, uint16_t *left, uint16_t *right)
{
	int l = (254 - sep) * vol / 127, r = sep * vol / 127;

	*left = (uint16_t)(l < 0 ? 0 : l > MIX_GAIN_MAX ? MIX_GAIN_MAX : l);
	*right = (uint16_t)(r < 0 ? 0 : r > MIX_GAIN_MAX ? MIX_GAIN_MAX : r);
}

/* Appends the voices of s's channels to out[n..max); returns the new n. */
static int g_sound_add(const struct sim *s, const struct snd_set *set, struct mix_voice *out,
		       int n, int max)
{
	for (int i = 0; i < G_SND_CHANNELS && n < max; i++) {
		const struct g_schan *c = &s->snd.ch[i];
		if (c->sfx == SFX_NONE || c->sfx >= SFX_COUNT)
			continue;
		out[n].snd = &set->s[c->sfx];
		out[n].age = c->age;
		g_sound_gains(c->vol, c->sep, &out[n].left, &out[n].right);
		n++;
	}
	return n;
}

int g_sound_voices(const struct sim *s, const struct sim *under, const struct snd_set *set,
		   struct mix_voice *out, int max)
{
	int n = g_sound_add(s, set, out, 0, max);

	if (under && g_sound_attract_on(s))
		n = g_sound_add(under, set, out, n, max);
	return n;
}

/* Sector sec's sound origin, as Doom's soundorg: the centre of the box
 * bounding its lines' vertices (a sector without lines: the origin). */
static void g_sound_origin(const struct map *m, uint32_t sec, fx_t *x, fx_t *y)
{
	uint32_t n;
	const uint32_t *lines = map_sector_lines(m, sec, &n);
	fx_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;

	for (uint32_t k = 0; k < n; k++) {
		const struct map_line *l = &m->lines[lines[k]];
		for (int e = 0; e < 2; e++) {
			const struct map_vertex *v = &m->vertices[e ? l->v2 : l->v1];
			if ((k == 0 && e == 0) || v->x < x0)
				x0 = v->x;
			if ((k == 0 && e == 0) || v->x > x1)
				x1 = v->x;
			if ((k == 0 && e == 0) || v->y < y0)
				y0 = v->y;
			if ((k == 0 && e == 0) || v->y > y1)
				y1 = v->y;
		}
	}
	*x = (fx_t)(((int64_t)x0 + x1) / 2);
	*y = (fx_t)(((int64_t)y0 + y1) / 2);
}

/* Each event's sound as Doom plays it (Chocolate Doom's p_doors.c,
 * p_plats.c, p_floor.c, p_switch.c, p_map.c, p_telept.c): a use on nothing
 * is DSNOWAY, a locked door DSOOF; a secret has none in vanilla Doom, and
 * pickups already play theirs (g_combat.c). */
static int g_event_sfx(enum g_ev ev)
{
	switch (ev) {
	case G_EV_DOOR_OPEN: return SFX_DOOR_OPEN;
	case G_EV_DOOR_CLOSE: return SFX_DOOR_CLOSE;
	case G_EV_BLAZE_OPEN: return SFX_BLAZE_OPEN;
	case G_EV_BLAZE_CLOSE: return SFX_BLAZE_CLOSE;
	case G_EV_PLANE_MOVE: return SFX_PLANE_MOVE;
	case G_EV_PLAT_START: return SFX_PLAT_START;
	case G_EV_PLAT_STOP: return SFX_PLAT_STOP;
	case G_EV_SWITCH: return SFX_SWITCH;
	case G_EV_SWITCH_EXIT: return SFX_SWITCH_EXIT;
	case G_EV_NOWAY: return SFX_NOWAY;
	case G_EV_LOCKED: return SFX_LOCKED;
	case G_EV_TELEPORT: return SFX_TELEPORT;
	default: return SFX_NONE;
	}
}

void g_event(struct sim *s, enum g_ev ev, uint32_t sector)
{
	int id = g_event_sfx(ev);
	fx_t x, y;

	if (id == SFX_NONE)
		return;
	if (sector == MAP_NONE || sector >= s->map->num_sectors) {
		g_sound_play(s, id, G_SRC_PLAYER);
		return;
	}
	g_sound_origin(s->map, sector, &x, &y);
	g_sound_start(s, id, x, y, (uint16_t)G_SRC_SECTOR(sector));
}
