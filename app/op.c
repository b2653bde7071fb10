/*
 * op: the app's service pages, run and applied (contract in op.h).
 */
#include "app/op.h"

#include <stdio.h>
#include <string.h>

#include "app/say.h"
#include "app/tape.h"
#include "config/st.h"
#include "engine/game/menu.h"
#include "engine/game/sim.h"

#define OP_REPEAT_FIRST 20         /* ticks up/down is held before it repeats */
#define OP_REPEAT_EVERY 5          /* then one step every this many */

void op_init(struct op *o, const struct cfg *cfg, struct cfgerr *errs, const struct tape *tape,
	     int persist, const char *now)
{
	static struct cfgerr none;

	memset(o, 0, sizeof(*o));
	o->cfg = cfg;
	o->errs = errs ? errs : &none;
	o->tape = tape;
	o->persist = persist;
	o->acked = cfgerr_acked(o->errs, persist ? cfg->paths.state_dir : NULL);
	snprintf(o->now, sizeof(o->now), "%s", now ? now : "");
}

/* A file name for the log from a refused WAD: its path and reason. */
static void op_refused(void *user, const char *path, const char *why)
{
	(void)user;
	say_warn("content: %s: %s; not listed", path, why);
}

void op_request(struct op *o, const struct sim *s)
{
	int page = s->mode == SIM_SERVICE ? s->menu.page : MENU_MAIN;
	const char *what = page == MENU_CONTENT ? "content pack"
			   : page == MENU_SCREEN ? "screen"
			   : page == MENU_CONFIG ? "config errors" : NULL;

	if (!what || o->on)
		return;
	if (o->tape->rec || o->tape->rep) {
		/* its page would not replay through the engine alone */
		say_warn("service menu: %s: not while recording or replaying", what);
		return;
	}
	if (page == MENU_CONTENT) {
		int n = wads_scan(&o->wads, o->cfg->game.content_dirs, op_refused, NULL);
		say("content: %d WAD(s) in %s", n, o->cfg->game.content_dirs);
		pick_content(&o->pick, &o->wads, o->now);
	} else if (page == MENU_SCREEN) {
		pick_screen(&o->pick, o->cfg->display.rotate, o->cfg->display.fill);
	} else {
		pick_config(&o->pick, o->errs);
	}
	o->on = 1;
	/* what is held now (the FIRE that chose the item) is not a press */
	o->held = PICK_K_FIRE | PICK_K_SERVICE | PICK_K_UP | PICK_K_DOWN | PICK_K_LEFT |
		  PICK_K_RIGHT;
	o->held_ticks = 0;
	say("service menu: %s", what);
}

/* The controls held in cmd, as PICK_K_* bits (directions as the sim reads
 * them in the menu: forward up, back down, turn or strafe left/right). */
static unsigned op_held(const struct sim_cmd *c)
{
	return (c->forward > 0 ? PICK_K_UP : 0) | (c->forward < 0 ? PICK_K_DOWN : 0) |
	       (c->turn > 0 || c->side < 0 ? PICK_K_LEFT : 0) |
	       (c->turn < 0 || c->side > 0 ? PICK_K_RIGHT : 0) |
	       (c->buttons & SIM_BT_FIRE ? PICK_K_FIRE : 0) |
	       (c->buttons & SIM_BT_SERVICE ? PICK_K_SERVICE : 0);
}

/* Keeps INI text as dir/name, a state file as settings.ini is. */
static int op_keep(struct op *o, const char *name, const char *ini)
{
	const char *dir = o->cfg->paths.state_dir;
	int rc;

	if (!o->persist) {
		say("service menu: %s not kept and not applied (a script run keeps nothing)", name);
		return -1;
	}
	rc = st_save(dir, name, ini, strlen(ini));
	if (rc < 0) {
		say_err("service menu: %s/%s not saved: %s; nothing changed", dir, name,
			strerror(-rc));
		return rc;
	}
	say("service menu: saved %s/%s", dir, name);
	return 0;
}

static void op_apply(struct op *o)
{
	char wad[sizeof(o->cfg->game.wad)], maps[sizeof(o->cfg->game.maps)];
	char ini[sizeof(wad) + sizeof(maps) + 64];

	switch (o->pick.page) {
	case PICK_CONTENT:
		if (pick_content_choice(&o->pick, wad, sizeof(wad), maps, sizeof(maps)) < 0) {
			say_err("content: the chosen WADs' paths are too long for [game] wad");
			return;
		}
		say("content: chosen: %s%s%s", wad[0] ? wad : "the built-in levels",
		    maps[0] ? ", maps " : "", maps);
		snprintf(ini, sizeof(ini), "[game]\nwad = %s\nmaps = %s\n", wad, maps);
		if (op_keep(o, OP_CONTENT_FILE, ini) == 0)
			o->reload = 1;
		break;
	case PICK_SCREEN:
		say("screen: chosen: rotation %d, scale %s", o->pick.rotate,
		    o->pick.fill ? "fill" : "integer");
		snprintf(ini, sizeof(ini), "[display]\nrotate = %d\nscale = %s\n", o->pick.rotate,
			 o->pick.fill ? "fill" : "integer");
		if (op_keep(o, OP_SCREEN_FILE, ini) == 0)
			o->reload = 1;
		break;
	case PICK_CONFIG:
	default:
		o->acked = 1;
		say("config errors: acknowledged");
		if (o->persist) {
			int rc = cfgerr_ack(o->errs, o->cfg->paths.state_dir);
			if (rc < 0)
				say_err("config errors: %s/%s not saved: %s", o->cfg->paths.state_dir,
					CFGERR_ACK_FILE, strerror(-rc));
		}
		break;
	}
}

/* The sim sees none of cmd but its coins. */
static void op_take(struct sim_cmd *cmd)
{
	cmd->forward = 0;
	cmd->side = 0;
	cmd->turn = 0;
	cmd->buttons = 0;
}

void op_command(struct op *o, struct sim_cmd *cmd)
{
	unsigned held, keys;

	if (!o->on) {
		o->swallow &= op_held(cmd);
		if (o->swallow)
			op_take(cmd);
		return;
	}
	held = op_held(cmd);
	keys = held & ~o->held;
	if (held & (PICK_K_UP | PICK_K_DOWN) & o->held) {
		/* a held up or down repeats: long lists of maps */
		if (++o->held_ticks >= OP_REPEAT_FIRST &&
		    (o->held_ticks - OP_REPEAT_FIRST) % OP_REPEAT_EVERY == 0)
			keys |= held & (PICK_K_UP | PICK_K_DOWN);
	} else {
		o->held_ticks = 0;
	}
	o->held = held;
	/* the sim sees none of it: the menu stays where it was */
	op_take(cmd);
	if (pick_keys(&o->pick, keys) == PICK_RUNNING)
		return;
	o->on = 0;
	o->swallow = held;
	if (o->pick.status == PICK_CHOSEN)
		op_apply(o);
}

const char *op_notice(const struct op *o)
{
	if (o->acked || o->errs->n == 0 || o->tape->rec || o->tape->rep)
		return NULL;
	return o->errs->text[0];
}
