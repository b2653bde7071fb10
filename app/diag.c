/*
 * diag: the diagnostics pages' text (contract in diag.h).
 */
#include "app/diag.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "app/ctl.h"
#include "app/slot.h"
#include "app/stats.h"
#include "audio/au.h"
#include "config/bind.h"
#include "config/cfg.h"
#include "config/prof.h"
#include "engine/game/menu.h"

struct diag_list_ctx {
	const struct prof_set *profs;
	const char *backend;
};

static const char *diag_profile(void *u, const struct in_ident *id)
{
	const struct diag_list_ctx *l = u;
	const struct prof *p = prof_match(l->profs, l->backend, id);

	return p ? p->name : NULL;
}

int diag_list(FILE *out, const struct cfg *c, const char *config_dir, const char *bindings)
{
	struct prof_set *profs = calloc(1, sizeof(*profs));
	struct bind_table *binds = calloc(1, sizeof(*binds));
	struct slot_kind kinds[SLOT_KINDS];
	char path[CFG_PATH_MAX + 32];
	int n, saved;

	if (!profs || !binds) {
		free(profs);
		free(binds);
		return -ENOMEM;
	}
	/* auto-detection by the bindings a run would use: which devices it
	 * takes */
	ctl_bindings_load(binds, c, config_dir, bindings, &saved);
	prof_init(profs);
	snprintf(path, sizeof(path), "%s/profiles", config_dir);
	prof_load_dir(profs, path, NULL, NULL);
	prof_load_dir(profs, ARCADED_DATADIR "/profiles", NULL, NULL);
	n = slot_kinds(NULL, kinds);
	for (int k = 0; k < n; k++) {
		struct diag_list_ctx l = { profs, kinds[k].be->name };
		if (kinds[k].be->set_bound)
			kinds[k].be->set_bound(ctl_bound, binds);
		if (kinds[k].be->list)
			kinds[k].be->list(out, diag_profile, &l);
		if (kinds[k].be->set_bound)
			kinds[k].be->set_bound(NULL, NULL);
	}
	for (int k = 0; au_backends[k]; k++)
		if (au_backends[k]->list)
			au_backends[k]->list(out);
	free(binds);
	free(profs);
	return 0;
}

void diag_clear(struct hud_diag *d)
{
	d->n = 0;
}

void diag_add(struct hud_diag *d, const char *text)
{
	const char *p = text;

	while (*p && d->n < HUD_DIAG_LINES) {
		char *l = d->line[d->n++];
		size_t k = 0;
		for (; *p && *p != '\n'; p++) {
			int tab = *p == '\t';
			for (int r = 0; r < (tab ? 2 : 1) && k < HUD_DIAG_COLS - 1; r++)
				l[k++] = tab ? ' ' : *p;
		}
		l[k] = '\0';
		if (*p == '\n')
			p++;
	}
}

/* Appends one formatted line. */
static void diag_addf(struct hud_diag *d, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

static void diag_addf(struct hud_diag *d, const char *fmt, ...)
{
	char buf[HUD_DIAG_COLS];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(buf, sizeof(buf), fmt, ap);
	va_end(ap);
	if (buf[0])
		diag_add(d, buf);
	else if (d->n < HUD_DIAG_LINES)
		d->line[d->n++][0] = '\0';
}

void diag_devices(struct hud_diag *d, const struct slot_kind *kinds, int nkinds,
		  const struct slot_set *set, const char *found)
{
	diag_clear(d);
	diag_add(d, "IN USE");
	for (int k = 0; k < nkinds; k++) {
		const char *v = kinds[k].devices;
		int any = 0;
		if (v && strcmp(v, "none") == 0)
			continue;
		diag_addf(d, "  %s: %s", kinds[k].be->name, v ? v : "the display's keys");
		for (int i = 0; i < set->n; i++) {
			const struct slot *s = &set->s[i];
			if (s->kind != k)
				continue;
			any = 1;
			if (s->dev && s->id.vid)
				diag_addf(d, "    %s: %s (%04x:%04x)", s->path ? s->path : "auto",
					  s->id.name[0] ? s->id.name : "?", s->id.vid, s->id.pid);
			else if (s->dev)
				diag_addf(d, "    %s: %s", s->path ? s->path : "auto",
					  s->id.name[0] ? s->id.name : "open");
			else
				diag_addf(d, "    %s: MISSING", s->path ? s->path : "auto");
		}
		if (!any)
			diag_add(d, "    no device opened");
	}
	if (found) {
		diag_add(d, "FOUND");
		diag_add(d, found);
	}
}

/* "  P50 1.23 P99 4.56 MAX 7.89 N 12" in ms (39 columns fit the narrowest
 * frame), or NO INPUT YET. */
static void diag_series(struct hud_diag *d, const struct lat_series *s)
{
	uint32_t p50, p99;

	if (!s->count) {
		diag_add(d, "  NO INPUT YET");
		return;
	}
	p50 = lat_percentile(s, 50);
	p99 = lat_percentile(s, 99);
	diag_addf(d, "  P50 %u.%02u P99 %u.%02u MAX %u.%02u N %llu", p50 / 1000,
		  p50 % 1000 / 10, p99 / 1000, p99 % 1000 / 10, s->max_us / 1000,
		  s->max_us % 1000 / 10, (unsigned long long)s->count);
}

void diag_latency(struct hud_diag *d, const struct stats *st)
{
	diag_clear(d);
	diag_add(d, "FRAME TIME IN MS (RENDER + PRESENT)");
	diag_series(d, &st->frame_time);
	diag_add(d, "INPUT TO PRESENT IN MS, EVERY SOURCE");
	diag_series(d, &st->latency);
	for (int k = 0; k < st->nsrc; k++) {
		diag_addf(d, "INPUT TO PRESENT IN MS, %s", st->src_name[k] ? st->src_name[k] : "?");
		diag_series(d, &st->src[k]);
	}
}

void diag_raw(struct hud_diag *d, const struct ctl *c)
{
	unsigned n = c->raw_n < CTL_RAW ? c->raw_n : CTL_RAW;

	diag_clear(d);
	diag_add(d, "RAW CONTROLS, NEWEST FIRST");
	if (!n)
		diag_add(d, "  NONE YET");
	for (unsigned i = 0; i < n; i++)
		diag_addf(d, "  %s", c->raw[(c->raw_n - 1 - i) % CTL_RAW]);
}

const struct hud_diag *diag_frame(struct diag_view *v, const struct diag_src *src, int page,
				  int taping, uint32_t t)
{
	int opened = page != v->page;

	if (page == MENU_INPUT && !taping) {
		/* the devices' raw controls: every tick, they are a few lines */
		diag_raw(&v->diag, src->ctl);
		v->page = page;
		return &v->diag;
	}
	if ((page != MENU_DEVICES && page != MENU_LATENCY) || taping) {
		v->page = 0;
		return NULL;
	}
	if (!opened && t - v->at < DIAG_TICKS)
		return &v->diag;
	v->page = page;
	v->at = t;
	if (page == MENU_LATENCY) {
		diag_latency(&v->diag, src->stats);
		return &v->diag;
	}
	if (opened) {
		size_t len = 0;
		FILE *f;
		free(v->found);
		v->found = NULL;
		f = src->headless ? NULL : open_memstream(&v->found, &len);
		if (f) {
			diag_list(f, src->cfg, src->config_dir, src->bindings);
			fclose(f);
		}
	}
	diag_devices(&v->diag, src->kinds, src->nkinds, src->slots, v->found);
	return &v->diag;
}

void diag_view_free(struct diag_view *v)
{
	free(v->found);
	v->found = NULL;
}
