/*
 * out: outputs (contract in out.h).
 */
#include "app/out.h"

#include <errno.h>

#include "app/slot.h"
#include "engine/game/sim.h"
#include "input/gpo.h"

void out_update(struct slot_set *set, const struct sim *s)
{
	struct gpo_state gs = {
		.coins_total = s->coins_total,
		.credits = s->credits,
		.playing = s->mode != SIM_ATTRACT && s->mode != SIM_GAMEOVER,
	};
	uint64_t now = 0;

	for (int i = 0; i < set->n; i++) {
		struct slot *sl = &set->s[i];
		if (!sl->be->outputs || !sl->dev)
			continue;
		if (!now)
			now = set->now();
		if (sl->be->outputs(sl->dev, &gs, now) == -ENODEV)
			slot_drop(set, sl);
	}
}
