/*
 * g_world: the helpers every special shares: a sector's neighbours (Doom's
 * P_Find...Surrounding), sectors by tag, the mover list, line bits, the
 * stage's 35 Hz clock and the HUD message. Calls nothing of the game, so
 * every special file may call it. (The specials' events, g_event, sound in
 * g_sound.c.)
 */
#include <stddef.h>
#include <string.h>

#include "engine/game/g_local.h"
#include "engine/map/map.h"

uint32_t g_other_sector(const struct map *m, const struct map_line *l, uint32_t sec)
{
	uint32_t f, b;

	if (l->side[1] == MAP_NONE)
		return MAP_NONE;
	f = m->sides[l->side[0]].sector;
	b = m->sides[l->side[1]].sector;
	return f == sec ? b : f;
}

/* The k-th neighbour of sec over its bordering lines (n of them), or
 * MAP_NONE for a one-sided line: a neighbour bordering on several lines
 * comes once per line, as in Doom's searches. */
static uint32_t g_nb(const struct sim *s, uint32_t sec, const uint32_t *lines, uint32_t k)
{
	return g_other_sector(s->map, &s->map->lines[lines[k]], sec);
}

fx_t g_lowest_floor_around(const struct sim *s, uint32_t sec)
{
	uint32_t n, o;
	const uint32_t *l = map_sector_lines(s->map, sec, &n);
	fx_t h = s->w.sec[sec].floor_h;

	for (uint32_t k = 0; k < n; k++)
		if ((o = g_nb(s, sec, l, k)) != MAP_NONE && s->w.sec[o].floor_h < h)
			h = s->w.sec[o].floor_h;
	return h;
}

fx_t g_highest_floor_around(const struct sim *s, uint32_t sec)
{
	uint32_t n, o;
	const uint32_t *l = map_sector_lines(s->map, sec, &n);
	fx_t h = -500 * FX_ONE;

	for (uint32_t k = 0; k < n; k++)
		if ((o = g_nb(s, sec, l, k)) != MAP_NONE && s->w.sec[o].floor_h > h)
			h = s->w.sec[o].floor_h;
	return h;
}

fx_t g_next_floor_above(const struct sim *s, uint32_t sec, fx_t h)
{
	uint32_t n, o;
	const uint32_t *l = map_sector_lines(s->map, sec, &n);
	int found = 0;
	fx_t best = h;

	for (uint32_t k = 0; k < n; k++) {
		fx_t f;
		if ((o = g_nb(s, sec, l, k)) == MAP_NONE)
			continue;
		f = s->w.sec[o].floor_h;
		if (f > h && (!found || f < best)) {
			best = f;
			found = 1;
		}
	}
	return best;
}

fx_t g_lowest_ceil_around(const struct sim *s, uint32_t sec)
{
	uint32_t n, o;
	const uint32_t *l = map_sector_lines(s->map, sec, &n);
	fx_t h = FX_MAX;

	for (uint32_t k = 0; k < n; k++)
		if ((o = g_nb(s, sec, l, k)) != MAP_NONE && s->w.sec[o].ceil_h < h)
			h = s->w.sec[o].ceil_h;
	return h;
}

fx_t g_highest_ceil_around(const struct sim *s, uint32_t sec)
{
	uint32_t n, o;
	const uint32_t *l = map_sector_lines(s->map, sec, &n);
	fx_t h = 0;

	for (uint32_t k = 0; k < n; k++)
		if ((o = g_nb(s, sec, l, k)) != MAP_NONE && s->w.sec[o].ceil_h > h)
			h = s->w.sec[o].ceil_h;
	return h;
}

int g_light_around(const struct sim *s, uint32_t sec, int start, int brightest)
{
	uint32_t n, o;
	const uint32_t *l = map_sector_lines(s->map, sec, &n);
	int v = start;

	for (uint32_t k = 0; k < n; k++) {
		int lt;
		if ((o = g_nb(s, sec, l, k)) == MAP_NONE)
			continue;
		lt = s->w.sec[o].light;
		if (brightest ? lt > v : lt < v)
			v = lt;
	}
	return v;
}

int g_tagged(const struct sim *s, uint16_t tag, int after)
{
	for (uint32_t i = (uint32_t)(after + 1); i < s->w.num_sectors; i++)
		if (s->map->sectors[i].tag == tag)
			return (int)i;
	return -1;
}

struct g_mover *g_mover_of(struct sim *s, uint32_t sec)
{
	for (int i = 0; i < s->w.num_movers; i++)
		if (s->w.mv[i].sector == sec)
			return &s->w.mv[i];
	return NULL;
}

struct g_mover *g_mover_new(struct sim *s, uint32_t sec, int kind, int type)
{
	struct g_mover *m;

	if (s->w.num_movers >= G_MAX_MOVERS || g_mover_of(s, sec))
		return NULL;
	m = &s->w.mv[s->w.num_movers++];
	memset(m, 0, sizeof(*m));
	m->sector = sec;
	m->kind = (uint8_t)kind;
	m->type = (uint8_t)type;
	return m;
}

void g_mover_remove(struct sim *s, struct g_mover *m)
{
	size_t i = (size_t)(m - s->w.mv), n = s->w.num_movers;

	/* keep the order: movers run in the order they were made, as Doom's
	 * thinkers do */
	memmove(&s->w.mv[i], &s->w.mv[i + 1], (n - i - 1) * sizeof(*m));
	s->w.num_movers--;
}

void g_line_set(uint32_t *bits, uint32_t line, int on)
{
	if (on)
		bits[line / 32] |= 1u << (line % 32);
	else
		bits[line / 32] &= ~(1u << (line % 32));
}

uint32_t g_dtic(const struct sim *s)
{
	return (uint32_t)((uint64_t)s->g.stage_t * 35 / 60);
}

int g_dtic_now(const struct sim *s)
{
	return s->g.stage_t > 0 && g_dtic(s) != (uint32_t)((uint64_t)(s->g.stage_t - 1) * 35 / 60);
}

void g_message(struct sim *s, int msg)
{
	s->w.msg = (uint8_t)msg;
	s->w.msg_t = 0;
}
