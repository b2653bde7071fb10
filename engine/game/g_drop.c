/*
 * g_drop: what a dying enemy leaves behind, as Doom's soldiers drop what
 * they carried: the zombieman and the Wolfenstein SS a clip, the shotgun
 * guy his shotgun (the spread gun here), the chaingunner his chaingun (the
 * rapid gun). The drop is a new pickup (g_game.h struct g_pickup) where the
 * enemy died, on the floor there, taken as any other (g_pickups_tick); as
 * Doom's dropped items it holds half the ammo of a placed one (a clip 5
 * rounds, a weapon 10), and it is not one of the map's counted items. No
 * drop when the stage's pickups are full (G_MAX_PICKUPS).
 */
#include <stddef.h>

#include "engine/game/g_local.h"
#include "engine/map/map.h"

struct g_drop_row {
	uint16_t enemy, pickup;        /* Doom thing types */
};

static const struct g_drop_row g_drops[] = {
	{ 3004, 2007 },                /* zombieman: a clip */
	{ 84, 2007 },                  /* Wolfenstein SS: a clip */
	{ 9, 2001 },                   /* shotgun guy: a shotgun */
	{ 65, 2002 },                  /* chaingunner: a chaingun */
};

uint16_t g_drop_type(uint16_t enemy)
{
	for (size_t k = 0; k < sizeof(g_drops) / sizeof(g_drops[0]); k++)
		if (g_drops[k].enemy == enemy)
			return g_drops[k].pickup;
	return 0;
}

int g_drop(struct sim *s, int i)
{
	const struct g_enemy *e = &s->g.en[i];
	uint16_t type = g_drop_type(e->type);
	struct g_thing_info ti;
	struct g_pickup *p;

	if (!type || s->g.num_pickups >= G_MAX_PICKUPS)
		return -1;
	g_thing_info(type, &ti);
	if (ti.cls != G_C_PICKUP)
		return -1;
	p = &s->g.pk[s->g.num_pickups];
	*p = (struct g_pickup){ 0 };
	p->x = e->x;
	p->y = e->y;
	p->z = s->w.sec[map_point_sector(s->map, e->x, e->y)].floor_h;
	p->type = type;
	p->kind = ti.kind;
	p->amount = (uint16_t)(ti.amount / 2);
	return s->g.num_pickups++;
}
