/*
 * ctl: controls to actions, profiles, the wizard's hookup (contract in
 * ctl.h).
 */
#include "app/ctl.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/say.h"
#include "app/stats.h"
#include "app/tape.h"
#include "config/st.h"

void ctl_bindings_load(struct bind_table *b, const struct cfg *cfg, const char *config_dir,
		       const char *extra, int *saved)
{
	char path[CFG_PATH_MAX + 32];
	int rc;

	bind_defaults(b);
	*saved = 0;
	/* Until the wizard has saved STATE_DIR/bindings.ini the cabinet was
	 * never configured on screen (a first boot): the wizard then starts
	 * by itself for a pad nothing names (ctl_opened). The shipped
	 * CONFIG_DIR/bindings.ini only repeats the keyboard defaults. */
	if (config_dir) {
		snprintf(path, sizeof(path), "%s/bindings.ini", config_dir);
		bind_load(b, path, say_cfg, NULL);
	}
	if (cfg->paths.state_dir[0]) {
		/* what the wizard saved: the operator's choice on screen wins
		 * over the configuration directory's file */
		snprintf(path, sizeof(path), "%s/bindings.ini", cfg->paths.state_dir);
		*saved = bind_load(b, path, say_cfg, NULL) != -ENOENT;
	}
	if (cfg->input.bindings[0]) {
		rc = bind_load(b, cfg->input.bindings, say_cfg, NULL);
		if (rc == -ENOENT)
			say_warn("%s: %s", cfg->input.bindings, strerror(-rc));
	}
	if (extra) {
		rc = bind_load(b, extra, say_cfg, NULL);
		if (rc < 0)
			say_warn("%s: %s", extra, strerror(-rc));
	}
}

int ctl_bound(void *b, const struct in_ident *id, int code)
{
	int acts[ACT_COUNT];

	return bind_lookup_dev(b, id, code, acts, ACT_COUNT) > 0;
}

void ctl_load(struct ctl *c, const struct cfg *cfg, const char *config_dir, const char *extra,
	      int live, int persist, struct stats *stats, const struct tape *tape)
{
	char path[CFG_PATH_MAX + 32];
	int saved;

	c->cfg = cfg;
	c->live = live;
	c->persist = persist;
	c->stats = stats;
	c->tape = tape;
	ctl_bindings_load(&c->binds, cfg, config_dir, extra, &saved);
	c->wiz_auto = persist && !saved;
	prof_init(&c->profs);
	if (config_dir) {
		/* the operator's profiles first: they win ties */
		snprintf(path, sizeof(path), "%s/profiles", config_dir);
		prof_load_dir(&c->profs, path, say_cfg, NULL);
	}
	prof_load_dir(&c->profs, ARCADED_DATADIR "/profiles", say_cfg, NULL);
	cmd_reset(&c->cs);
}

/* ---- the input configuration wizard ---------------------------------- */

void ctl_wizard_start(struct ctl *c, const char *why)
{
	const char *rec = tape_recording(c->tape);

	if (c->wiz_on || !c->live)
		return;
	if (rec) {
		/* its screens are not the sim's: they would not replay */
		say_warn("input wizard: not while recording (%s)", rec);
		return;
	}
	c->wiz_auto = 0;
	cmd_reset(&c->cs);   /* nothing stays held for the game meanwhile */
	wiz_start(&c->wiz, &c->binds, in_now_ns());
	c->wiz_on = 1;
	say("input wizard: started (%s)", why);
}

/* Saves the bindings as STATE_DIR/bindings.ini, replaced atomically (a
 * power cut leaves the old file or the new one). */
static void ctl_wizard_save(struct ctl *c)
{
	const char *dir = c->cfg->paths.state_dir;
	struct bind_table *t = malloc(sizeof(*t));
	size_t n;
	char *text;
	int rc;

	if (!t) {
		say_err("input wizard: bindings not saved: out of memory");
		return;
	}
	/* What the operator set: [keyboard] and every device section except
	 * those a profile made and nobody changed. */
	*t = c->binds;
	for (int k = 0; k < c->nprof_secs; k++)
		for (int d = 0; d < t->ndev; d++) {
			if (strcmp(t->dev[d].id, c->prof_secs[k].id) != 0 ||
			    memcmp(t->dev[d].key, c->prof_secs[k].p->key, sizeof(t->dev[d].key)) != 0)
				continue;
			memmove(&t->dev[d], &t->dev[d + 1], (size_t)(t->ndev - d - 1) * sizeof(t->dev[0]));
			t->ndev--;
			break;
		}
	n = bind_format(t, NULL, 0);
	text = malloc(n + 1);

	if (!text) {
		say_err("input wizard: bindings not saved: out of memory");
		free(t);
		return;
	}
	bind_format(t, text, n + 1);
	free(t);
	rc = dir[0] ? st_write_plain(dir, "bindings.ini", text, n) : -ENOENT;
	if (rc < 0)
		say_err("input wizard: %s/bindings.ini not saved: %s (the bindings apply until the "
		    "daemon stops)", dir, strerror(-rc));
	else
		say("input wizard: bindings saved in %s/bindings.ini", dir);
	free(text);
}

void ctl_wizard_tick(struct ctl *c)
{
	struct bind_table t;
	enum wiz_status st;

	if (!c->wiz_on)
		return;
	st = wiz_tick(&c->wiz, in_now_ns());
	if (st == WIZ_RUNNING)
		return;
	c->wiz_on = 0;
	if (st == WIZ_DONE && wiz_result(&c->wiz, &t)) {
		c->binds = t;
		say("input wizard: done: new bindings in effect");
		if (c->persist)
			ctl_wizard_save(c);
	} else {
		say("input wizard: %s: bindings unchanged", st == WIZ_DONE ? "done" : "cancelled");
	}
}

/* ---- the slot hooks --------------------------------------------------- */

/* A device just opened: a profile's bindings when the operator has none
 * for it (a known encoder works without configuration). */
static void ctl_opened(void *ctx, struct slot *s)
{
	struct ctl *c = ctx;
	const struct prof *p = prof_match(&c->profs, s->be->name, &s->id);
	char why[160];
	int named;

	/* Checked before the profile adds its section: whether anything but
	 * the generic guess names this device. */
	named = (p && !p->any) || bind_find_device(&c->binds, &s->id);
	if (p) {
		if (prof_bind(p, &c->binds, &s->id) == 1 && c->nprof_secs < BIND_DEVICES) {
			const struct bind_dev *d = bind_find_device(&c->binds, &s->id);
			snprintf(c->prof_secs[c->nprof_secs].id, BIND_ID_MAX, "%s", d->id);
			c->prof_secs[c->nprof_secs++].p = p;
		}
		if (s->be->configure && p->hid[0] &&
		    s->be->configure(s->dev, p->hid, why, sizeof(why)) < 0)
			say_warn("input %s: profile %s: %s", s->be->name, p->name, why);
		say("input %s: %s: profile %s", s->be->name, s->be->describe(s->dev), p->name);
	}
	if (!named && c->wiz_auto && (s->be->flags & IN_NEEDS_BINDINGS)) {
		/* First boot (the wizard never saved): a pad nothing names (no
		 * section of its own, no profile but the generic guess): ask
		 * the operator, starting from that guess. */
		say("input %s: %s: no bindings and no profile for it", s->be->name,
		    s->be->describe(s->dev));
		ctl_wizard_start(c, "first boot");
	}
}

/* What a control change does, in words: "evdev usb-1-1.2 KEY_LEFTCTRL
 * down -> fire" (the device by USB port, else VID:PID, else "-"; a code
 * without a name as "code N"; "unbound" when it does nothing). */
static void ctl_key_text(const struct slot *s, int code, int down, const int *acts, int n,
			 char *buf, size_t len)
{
	char dev[48], key[24], what[160] = "";
	const char *name = in_key_name(code);
	size_t wl = 0;

	if (s->id.port[0])
		snprintf(dev, sizeof(dev), "usb-%s", s->id.port);
	else if (s->id.vid || s->id.pid)
		snprintf(dev, sizeof(dev), "%04x:%04x", s->id.vid, s->id.pid);
	else
		snprintf(dev, sizeof(dev), "-");
	if (name)
		snprintf(key, sizeof(key), "%s", name);
	else
		snprintf(key, sizeof(key), "code %d", code);
	for (int i = 0; i < n && wl < sizeof(what); i++)
		wl += (size_t)snprintf(what + wl, sizeof(what) - wl, "%s%s", i ? "," : "",
				       act_name(acts[i]));
	snprintf(buf, len, "%s %s %s %s -> %s", s->be->name, dev, key, down ? "down" : "up",
		 n ? what : "unbound");
}

/* Control code of s changed: to the actions it is bound to, which makes
 * its effect due on the next frame. Kept in words for the input test;
 * with input.log also logged, one line per press and release (the
 * operator's view of a device; the VM tests read it too). */
static int ctl_act(struct ctl *c, const struct slot *s, int code, int down)
{
	int acts[ACT_COUNT];
	int n = bind_lookup_dev(&c->binds, &s->id, code, acts, ACT_COUNT);
	char *raw = c->raw[c->raw_n++ % CTL_RAW];

	ctl_key_text(s, code, down, acts, n, raw, CTL_RAW_LEN);
	if (c->cfg->input.log)
		say("input: %s", raw);
	for (int i = 0; i < n; i++)
		cmd_action(&c->cs, acts[i], down);
	return n;
}

static void ctl_key(void *ctx, struct slot *s, int code, int down, uint64_t time_ns)
{
	struct ctl *c = ctx;

	if (c->wiz_on) {
		wiz_event(&c->wiz, s->be->name, s->be->ident ? &s->id : NULL, code, down, time_ns);
		return;
	}
	if (ctl_act(c, s, code, down) > 0)
		stats_input(c->stats, s->kind, time_ns);
}

static void ctl_released(void *ctx, struct slot *s, int code)
{
	ctl_act(ctx, s, code, 0);
}

static void ctl_gone(void *ctx, struct slot *s)
{
	struct ctl *c = ctx;

	if (c->wiz_on)
		wiz_drop(&c->wiz, &s->id);
}

static int ctl_hook_bound(void *ctx, const struct in_ident *id, int code)
{
	return ctl_bound(&((struct ctl *)ctx)->binds, id, code);
}

const struct slot_hooks ctl_hooks = {
	.opened = ctl_opened,
	.key = ctl_key,
	.released = ctl_released,
	.gone = ctl_gone,
	.bound = ctl_hook_bound,
};
