/*
 * deb: switch debounce and coin pulse counting; the rules are in deb.h.
 */
#include "input/deb.h"

void deb_init(struct deb *d, uint64_t holdoff_ns, int level)
{
	d->holdoff_ns = holdoff_ns ? holdoff_ns : DEB_HOLDOFF_NS;
	d->until_ns = 0;
	d->raw_ns = 0;
	d->level = d->raw = level != 0;
}

static int report(struct deb *d, uint64_t t, struct deb_ev *out)
{
	d->level = d->raw;
	d->until_ns = t + d->holdoff_ns;
	out->time_ns = t;
	out->level = d->level;
	return 1;
}

int deb_edge(struct deb *d, uint64_t t, int level, struct deb_ev out[2])
{
	int n = deb_poll(d, t, out);

	d->raw = level != 0;
	d->raw_ns = t;
	if (t < d->until_ns || d->raw == d->level)
		return n;
	return n + report(d, t, out + n);
}

int deb_poll(struct deb *d, uint64_t now, struct deb_ev *out)
{
	if (now < d->until_ns || d->raw == d->level)
		return 0;
	/* The settling edge fell inside the hold-off: it is the change. */
	return report(d, d->raw_ns, out);
}

int deb_settle(struct deb *d, uint64_t now, int level, struct deb_ev *out)
{
	if ((level != 0) != d->raw) {
		d->raw = level != 0;
		d->raw_ns = now;
	}
	return deb_poll(d, now, out);
}

int deb_level(const struct deb *d)
{
	return d->level;
}

void deb_coin_init(struct deb_coin *c, uint64_t holdoff_ns, uint64_t min_ns, uint64_t max_ns)
{
	deb_init(&c->d, holdoff_ns, 0);
	c->min_ns = min_ns ? min_ns : DEB_COIN_MIN_NS;
	c->max_ns = max_ns ? max_ns : DEB_COIN_MAX_NS;
	c->start_ns = 0;
	c->coins = 0;
	c->rejected = 0;
}

/* A debounced change of the coin line. */
static int coin_change(struct deb_coin *c, const struct deb_ev *e, uint64_t *credit_ns)
{
	uint64_t width;

	if (e->level) {
		c->start_ns = e->time_ns;
		return 0;
	}
	width = e->time_ns - c->start_ns;
	if (width < c->min_ns || width > c->max_ns) {
		c->rejected++;
		return 0;
	}
	c->coins++;
	*credit_ns = e->time_ns;
	return 1;
}

int deb_coin_edge(struct deb_coin *c, uint64_t t, int level, uint64_t *credit_ns)
{
	struct deb_ev e[2];
	int n = deb_edge(&c->d, t, level, e), coins = 0;

	/* Of two changes only a release can end a pulse: at most one coin. */
	for (int i = 0; i < n; i++)
		coins += coin_change(c, &e[i], credit_ns);
	return coins;
}

int deb_coin_poll(struct deb_coin *c, uint64_t now, uint64_t *credit_ns)
{
	struct deb_ev e;

	if (!deb_poll(&c->d, now, &e))
		return 0;
	return coin_change(c, &e, credit_ns);
}

int deb_coin_settle(struct deb_coin *c, uint64_t now, int level, uint64_t *credit_ns)
{
	struct deb_ev e;

	if (!deb_settle(&c->d, now, level, &e))
		return 0;
	return coin_change(c, &e, credit_ns);
}
