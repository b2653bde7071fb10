/*
 * out: lamps, meters and sound (contract in out.h).
 */
#include "app/out.h"

#include <errno.h>
#include <string.h>

#include "app/hear.h"
#include "app/say.h"
#include "app/slot.h"
#include "app/stats.h"
#include "audio/au.h"
#include "engine/game/sim.h"
#include "input/gpo.h"
#include "input/in.h"

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

/* Tries to open the output; logs a success, or the first failure of a
 * loss. */
static void out_audio_try(struct out_audio *o)
{
	char why[512] = "";
	int rc = o->be->open(o->arg, o->rate, &o->dev, why, sizeof(why));

	if (rc == 0) {
		say("sound: %s", o->be->describe(o->dev));
		o->silent_said = 0;
		return;
	}
	o->dev = NULL;
	o->retry_ns = in_now_ns() + OUT_AUDIO_RETRY_NS;
	if (!o->silent_said)
		say("sound: %s %s: %s; %s", o->be->name, o->arg, why[0] ? why : strerror(-rc),
		    o->be->live ? "no sound card: playing silent (looking again every second)"
				: "no sound output");
	o->silent_said = 1;
}

int out_audio_open(struct out_audio *o, const struct cfg *c, uint32_t rate, int headless)
{
	const char *spec = c->audio.output, *arg = NULL;
	char why[256] = "";

	memset(o, 0, sizeof(*o));
	o->rate = rate;
	if (strcmp(spec, "auto") == 0) {
		if (headless)
			return 0;          /* scripts and replays: nothing, unless named */
		spec = "alsa";
	}
	if (au_parse(spec, c->audio.device, &o->be, &arg, why, sizeof(why)) < 0) {
		say("audio.output: %s", why);
		o->be = NULL;
		return -EINVAL;
	}
	snprintf(o->arg, sizeof(o->arg), "%s", arg);
	if (o->be->live && !headless) {
		/* a sound card can take milliseconds to open (ALSA reads its
		 * configuration, sets the card up): after the first frame */
		o->retry_ns = UINT64_MAX;
		return 0;
	}
	out_audio_try(o);
	/* a file that cannot be written is the caller's mistake: no retries */
	if (!o->dev && !o->be->live)
		return -EIO;
	return 0;
}

void out_audio_play(struct out_audio *o, const struct hear *h, struct stats *st)
{
	struct au_status as;
	uint64_t t0;
	int rc;

	if (!o->be)
		return;
	if (!o->dev) {
		if (!o->be->live || in_now_ns() < o->retry_ns)
			return;
		out_audio_try(o);
		if (!o->dev)
			return;
	}
	t0 = in_now_ns();
	rc = o->be->write(o->dev, h->buf, h->frames, &as);
	if (rc == -ENODEV && o->be->live) {
		say("sound: %s went away: playing silent until it returns", o->be->describe(o->dev));
		o->silent_said = 1;
		o->be->close(o->dev);
		o->dev = NULL;
		o->retry_ns = t0 + OUT_AUDIO_RETRY_NS;
		return;
	}
	if (rc < 0) {
		say("sound: %s: %s; sound stopped", o->be->describe(o->dev), strerror(-rc));
		o->be->close(o->dev);
		o->dev = NULL;
		o->be = NULL;
		return;
	}
	st->underruns += as.underruns;
	st->audio_dropped += as.dropped;
	if (as.raised)   /* describe() says raised, and why */
		say("sound: %s", o->be->describe(o->dev));
	if (h->onset >= 0 && as.delay >= 0)
		stats_sound(st, t0 + (uint64_t)(as.delay + h->onset) * 1000000000ull / h->rate);
}

void out_audio_start(struct out_audio *o)
{
	if (!o->be || o->dev || o->retry_ns != UINT64_MAX)
		return;
	o->retry_ns = 0;
	out_audio_try(o);
}

void out_audio_close(struct out_audio *o)
{
	if (o->be && o->dev)
		o->be->close(o->dev);
	o->dev = NULL;
	o->be = NULL;
}
