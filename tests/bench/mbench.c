/*
 * mbench: the mixer's cost per tick (make bench; issue 14: at most 0.1 ms
 * a tick on one core with 16 busy channels). 16 voices of the built-in
 * sound set, the longest sounds first, each panned differently and
 * started at a different tick, are mixed at 48000 Hz, volume 80, tick
 * after tick (a voice that ends starts again) for at least the given
 * seconds. Prints "mix_ms_per_tick X ticks N voices 16 rate 48000" and the
 * buffer's hash of the last tick (so the work cannot be optimised away).
 *   mbench [SECONDS]
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "engine/sound/mix.h"
#include "engine/sound/sfx.h"
#include "engine/sound/snd.h"

#define MB_VOICES 16
#define MB_RATE 48000

static double mb_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

int main(int argc, char **argv)
{
	double secs = argc > 1 ? atof(argv[1]) : 1.0, t0, el;
	struct snd_set *set;
	struct mix_voice v[MB_VOICES];
	uint32_t start[MB_VOICES], ticklen[MB_VOICES];
	static int16_t out[2 * MIX_FRAMES_MAX];
	uint64_t h = 0;
	uint32_t t = 0;
	int used[SFX_COUNT] = { 0 };

	if (snd_builtin(&set) < 0) {
		fprintf(stderr, "mbench: out of memory\n");
		return 2;
	}
	for (int k = 0; k < MB_VOICES; k++) {
		int best = SFX_NONE + 1;
		for (int id = SFX_NONE + 1; id < SFX_COUNT; id++)
			if (!used[id] && (used[best] || set->s[id].len > set->s[best].len))
				best = id;
		used[best] = 1;
		v[k].snd = &set->s[best];
		v[k].left = (uint16_t)(255 - k * 15);
		v[k].right = (uint16_t)(k * 15 + 15);
		start[k] = (uint32_t)k;
		/* ticks the sound lasts at its own rate, rounded up */
		ticklen[k] = (uint32_t)(((uint64_t)set->s[best].len * 60 + set->s[best].rate - 1) /
					set->s[best].rate);
	}
	t0 = mb_now();
	do {
		for (int i = 0; i < 600; i++, t++) {
			for (int k = 0; k < MB_VOICES; k++) {
				if (t - start[k] >= ticklen[k])
					start[k] = t;   /* ended: starts again */
				v[k].age = t - start[k];
			}
			mix_tick(MB_RATE, t, 80, v, MB_VOICES, out);
		}
		el = mb_now() - t0;
	} while (el < secs);
	h = mix_hash(out, mix_frames(MB_RATE, t - 1));
	printf("mix_ms_per_tick %.4f ticks %" PRIu32 " voices %d rate %d hash %016" PRIx64 "\n",
	       el * 1000.0 / t, t, MB_VOICES, MB_RATE, h);
	snd_free(set);
	return 0;
}
