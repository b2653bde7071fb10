/*
 * stats: what the daemon measures of itself, and the summary it prints on
 * SIGUSR1 and at exit: ticks, frames, ticks dropped by the clock, peak
 * RSS, open file descriptors (the soak test compares them), frame time
 * (render + present), frames presented late (after the next tick was due:
 * the frame missed its tick), input-to-present latency, overall and per
 * kind of input source (each input backend, scripts): from the kernel's
 * stamp of the first event that changed an action to the end of the
 * present that first showed it; and, for a display that flips pages,
 * present-to-flip time: from the end of a frame's present to the moment
 * its page flip completed (the screen began to show it). And sound:
 * input-to-sound latency (from the first input event of a tick in which
 * a sound starts to the time the sound card plays that sound's first
 * audible sample, as the output reports its queue), the output's
 * underruns and the frames it dropped.
 */
#ifndef ARCADED_APP_STATS_H
#define ARCADED_APP_STATS_H

#include <stdint.h>

#include "app/lat.h"

#define STATS_SRCS 8

struct stats {
	struct lat_series frame_time, latency, flip, sound;
	struct lat_series src[STATS_SRCS];
	const char *src_name[STATS_SRCS];  /* borrowed */
	int nsrc;
	uint64_t pending_ns;               /* earliest unpresented input event, 0 none */
	uint64_t src_pending_ns[STATS_SRCS];
	uint64_t start_ns, ticks, frames, dropped, late;
	uint64_t underruns, audio_dropped;   /* of the sound output */
};

/* Empty statistics of sources names[0..n) (at most STATS_SRCS; the
 * summary lists them in this order). The caller sets start_ns when the
 * loop starts. */
void stats_init(struct stats *s, const char *const *names, int n);

/* An input event of source src stamped t changed an action: its effect is
 * due on the next presented frame. */
void stats_input(struct stats *s, int src, uint64_t t);

/* A frame was drawn from t0 and presented at t1: frame time, and the
 * latency of every input waiting for it. due: when the next tick was due
 * (a present ending after it is late), 0 when the loop does not follow
 * the clock. */
void stats_presented(struct stats *s, uint64_t t0, uint64_t t1, uint64_t due);

/* A frame whose present returned at presented began to be shown at shown
 * (its page flip completed). */
void stats_flip(struct stats *s, uint64_t presented, uint64_t shown);

/* A sound that began this tick is heard at heard_ns: the latency of the
 * input waiting for this tick's present (when there is one). */
void stats_sound(struct stats *s, uint64_t heard_ns);

/* Prints the summary lines ("arcaded: summary: ...") on stderr; only the
 * sources that gave input get a latency line. */
void stats_print(const struct stats *s);

#endif
