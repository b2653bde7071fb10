#include "app/demo.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/cmd.h"
#include "app/ct.h"
#include "engine/map/map.h"
#include "input/scr.h"

/* The demo of the first built-in level: a real game (levels/demo.scr,
 * played by tests/replay/autopilot), compiled in as demo_game. Its first
 * line names the map it was played on, that map's content hash and the
 * difficulty it was played at: "# demo: ARENA1 HASH DIFFICULTY". */
#include "app/demo_game.h"

/* For any other content (a WAD, a grid map, another first level), where
 * a recorded game would not replay: a walk about, shooting. The page
 * lasts SIM_DEMO_TICKS; the last command repeats if a script ends sooner. */
static const char demo_walk[] =
	"0 press forward\n"
	"40 press fire\n"
	"70 release fire\n"
	"90 release forward\n"
	"95 hold turn_left 30\n"
	"130 hold fire 40\n"
	"175 hold turn_right 55\n"
	"235 press forward\n"
	"300 hold fire 30\n"
	"340 press strafe_left\n"
	"362 release strafe_left\n"
	"420 hold fire 60\n"
	"500 release forward\n"
	"510 hold turn_left 80\n"
	"600 press forward\n"
	"640 hold fire 45\n"
	"700 hold turn_right 40\n"
	"760 hold fire 60\n"
	"840 release forward\n"
	"850 hold turn_right 90\n"
	"950 press forward\n"
	"980 hold fire 50\n"
	"1100 hold strafe_right 30\n"
	"1150 hold fire 60\n"
	"1250 hold turn_left 60\n"
	"1320 hold fire 80\n"
	"1450 release forward\n"
	"1460 hold turn_right 120\n"
	"1600 hold fire 100\n"
	"1799 end\n";

int demo_game_matches(const struct map *m, int *difficulty)
{
	char name[9];
	unsigned long long hash;
	int diff;

	if (sscanf(demo_game, "# demo: %8s %llx %d", name, &hash, &diff) != 3)
		return 0;
	if (strcmp(m->name, name) != 0 || m->content_hash != (uint64_t)hash)
		return 0;
	*difficulty = diff;
	return 1;
}

int demo_init(struct demo *d, const struct ct *ct, char *err, size_t errlen)
{
	struct cmd_state cs;
	struct scr *s = NULL;
	size_t i = 0;
	int rc;

	memset(d, 0, sizeof(*d));
	d->ct = ct;
	d->game = ct->nmaps > 0 && demo_game_matches(ct->maps[0], &d->difficulty);
	if (d->game)
		rc = scr_parse(demo_game, sizeof(demo_game) - 1, "levels/demo.scr", &s, err, errlen);
	else
		rc = scr_parse(demo_walk, sizeof(demo_walk) - 1, "built-in demo", &s, err, errlen);
	if (rc < 0)
		return rc;
	d->len = s->end_tick + 1;
	d->cmds = calloc(d->len, sizeof(*d->cmds));
	if (!d->cmds) {
		scr_free(s);
		return -ENOMEM;
	}
	/* The same path as a script run: press/release steps into actions,
	 * actions into one command per tick. */
	cmd_reset(&cs);
	for (uint32_t t = 0; t < d->len; t++) {
		for (; i < s->n && s->steps[i].tick == t; i++)
			if (s->steps[i].op == SCR_PRESS || s->steps[i].op == SCR_RELEASE)
				cmd_action(&cs, s->steps[i].action, s->steps[i].op == SCR_PRESS);
		cmd_build(&cs, &d->cmds[t]);
	}
	scr_free(s);
	return 0;
}

static int on_demo_page(const struct sim *m)
{
	return m->mode == SIM_ATTRACT && m->page == SIM_PAGE_DEMO;
}

void demo_tick(struct demo *d, const struct sim *m)
{
	if (!on_demo_page(m)) {
		d->running = 0;
		return;
	}
	if (!d->running || m->mode_t == 0) {
		/* The demo plays from the first stage, straight into play.
		 * The recorded game plays by the rules it was played with:
		 * its difficulty and every other rule at its default (0),
		 * whatever the operator set, or it would not replay; the
		 * cabinet's sound settings are kept. The walk about plays on
		 * the cabinet's settings. */
		struct sim_settings set = m->set;
		if (d->game) {
			memset(&set, 0, sizeof(set));
			set.difficulty = (uint8_t)d->difficulty;
			set.volume = m->set.volume;
			set.attract_sound = m->set.attract_sound;
		}
		set.start_in_play = 1;
		sim_init_stages(&d->sim, (const struct map *const *)d->ct->maps, d->ct->nmaps, &set,
				NULL, NULL);
		sim_set_sounds(&d->sim, d->ct->sounds);
		d->t = 0;
		d->running = 1;
	}
	sim_tick(&d->sim, &d->cmds[d->t < d->len ? d->t : d->len - 1]);
	d->t++;
}

const struct sim *demo_under(const struct demo *d, const struct sim *m)
{
	return d->running && on_demo_page(m) ? &d->sim : NULL;
}

void demo_free(struct demo *d)
{
	free(d->cmds);
	d->cmds = NULL;
}
