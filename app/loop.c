/*
 * loop: the main loop; the order of the steps is the contract of loop.h.
 */
#include "app/loop.h"

#include <string.h>

uint32_t loop_run(const struct loop_ops *op, void *ctx)
{
	struct loop_tick k;

	for (k.t = 0;; k.t++) {
		memset(&k.rt, 0, sizeof(k.rt));
		if (!op->begin(ctx, &k))
			break;
		op->wait(ctx, &k);
		if (!op->input(ctx, &k))
			break;
		op->command(ctx, &k);
		op->wizard(ctx, &k);
		op->flight_before(ctx, &k);
		op->sim(ctx, &k);
		op->sound(ctx, &k);
		op->flight_after(ctx, &k);
		op->requests(ctx, &k);
		op->outputs(ctx, &k);
		op->persist(ctx, &k);
		op->present(ctx, &k);
		op->hashes(ctx, &k);
		op->checks(ctx, &k);
		op->notify(ctx, &k);
	}
	op->end(ctx, &k);
	return k.t;
}
