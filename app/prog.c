/*
 * prog: a map's exit as a log line (contract in prog.h).
 */
#include "app/prog.h"

#include <stdio.h>

#include "engine/game/sim.h"
#include "engine/map/map.h"

int prog_exit(const struct sim *s, char *buf, size_t len)
{
	const struct g_world *w = &s->w;
	unsigned dead = 0, sec;

	if (s->mode != SIM_PLAY || s->g.phase != G_PH_INTER || s->g.phase_t != 0 || !s->map)
		return 0;
	/* the kills the page counts: the map's enemies now dead */
	for (int i = 0; i < s->g.num_enemies; i++)
		dead += s->g.en[i].state == G_E_DEAD;
	sec = w->exit_t / SIM_TICRATE;
	snprintf(buf, len,
		 "map %s: %s taken after %u:%02u:%02u (%u ticks), kills %u of %u, items %u of %u, "
		 "secrets %u of %u, score %u; next %s",
		 s->map->name, w->exit == G_EXIT_SECRET ? "secret exit" : "exit", sec / 3600,
		 sec / 60 % 60, sec % 60, (unsigned)w->exit_t, dead, (unsigned)s->g.num_enemies,
		 (unsigned)w->items, (unsigned)w->items_total, (unsigned)w->secrets,
		 (unsigned)w->secrets_total, (unsigned)s->g.score,
		 w->next < s->num_stages && s->stages[w->next] ? s->stages[w->next]->name : "?");
	return 1;
}
