/*
 * lim: counting a load's steps against its limit and polling the stop hook
 * (lim.h).
 */
#include "engine/core/lim.h"

#include <errno.h>
#include <stddef.h>

void lim_init(struct lim *l, const struct lim_stop *stop, uint64_t max)
{
	l->stop = stop;
	l->used = 0;
	l->max = max;
	l->poll = LIM_POLL;
	l->err = 0;
}

int lim_check(struct lim *l)
{
	if (!l->err && l->stop && l->stop->fn && l->stop->fn(l->stop->ctx))
		l->err = -ECANCELED;
	return l->err;
}

int lim_take(struct lim *l, uint64_t n)
{
	if (l->err)
		return l->err;
	/* saturating: n may be anything a caller computed */
	l->used = n > UINT64_MAX - l->used ? UINT64_MAX : l->used + n;
	if (l->stop && l->stop->steps)
		*l->stop->steps += n;
	if (l->used >= l->poll) {
		l->poll = l->used > UINT64_MAX - LIM_POLL ? UINT64_MAX : l->used + LIM_POLL;
		if (lim_check(l))
			return l->err;
	}
	if (l->used > l->max)
		l->err = -E2BIG;
	return l->err;
}
