/*
 * hear: one tick of sound (contract in hear.h).
 */
#include "app/hear.h"

#include <stddef.h>

#include "engine/game/sim.h"

void hear_init(struct hear *h, const struct snd_set *set, uint32_t rate)
{
	h->set = set;
	h->rate = rate < MIX_RATE_MIN ? MIX_RATE_MIN : rate > MIX_RATE_MAX ? MIX_RATE_MAX : rate;
	h->frames = 0;
	h->hash = 0;
	h->onset = -1;
}

/* Whether a channel of s started in the tick that just ran. */
static int hear_new(const struct sim *s)
{
	for (int i = 0; i < G_SND_CHANNELS; i++)
		if (s->snd.ch[i].sfx != SFX_NONE && s->snd.ch[i].age == 0)
			return 1;
	return 0;
}

void hear_tick(struct hear *h, const struct sim *s, const struct sim *under)
{
	struct mix_voice v[MIX_VOICES_MAX];
	int n = g_sound_voices(s, under, h->set, v, MIX_VOICES_MAX);

	h->frames = mix_tick(h->rate, s->tick ? s->tick - 1 : 0, s->set.volume, v, n, h->buf);
	h->hash = mix_hash(h->buf, h->frames);
	h->onset = -1;
	if (!hear_new(s))
		return;
	for (uint32_t i = 0; i < 2 * h->frames; i++) {
		int x = h->buf[i];
		if (x >= HEAR_AUDIBLE || x <= -HEAR_AUDIBLE) {
			h->onset = (int32_t)(i / 2);
			return;
		}
	}
}
