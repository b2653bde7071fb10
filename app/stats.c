/*
 * stats: the daemon's own figures (contract in stats.h).
 */
#include "app/stats.h"

#include <dirent.h>
#include <inttypes.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>

#include "app/say.h"
#include "input/in.h"

void stats_init(struct stats *s, const char *const *names, int n)
{
	memset(s, 0, sizeof(*s));
	lat_reset(&s->frame_time);
	lat_reset(&s->latency);
	lat_reset(&s->sound);
	lat_reset(&s->flip);
	s->nsrc = n < STATS_SRCS ? n : STATS_SRCS;
	for (int k = 0; k < s->nsrc; k++) {
		s->src_name[k] = names[k];
		lat_reset(&s->src[k]);
	}
}

void stats_input(struct stats *s, int src, uint64_t t)
{
	if (s->pending_ns == 0 || t < s->pending_ns)
		s->pending_ns = t;
	if (src < 0 || src >= s->nsrc)
		return;
	if (s->src_pending_ns[src] == 0 || t < s->src_pending_ns[src])
		s->src_pending_ns[src] = t;
}

void stats_sound(struct stats *s, uint64_t heard_ns)
{
	if (s->pending_ns && heard_ns > s->pending_ns)
		lat_add_ns(&s->sound, heard_ns - s->pending_ns);
}

void stats_presented(struct stats *s, uint64_t t0, uint64_t t1, uint64_t due)
{
	s->frames++;
	if (due && t1 > due)
		s->late++;
	lat_add_ns(&s->frame_time, t1 - t0);
	if (s->pending_ns) {
		if (t1 > s->pending_ns)
			lat_add_ns(&s->latency, t1 - s->pending_ns);
		s->pending_ns = 0;
	}
	for (int k = 0; k < s->nsrc; k++) {
		if (!s->src_pending_ns[k])
			continue;
		if (t1 > s->src_pending_ns[k])
			lat_add_ns(&s->src[k], t1 - s->src_pending_ns[k]);
		s->src_pending_ns[k] = 0;
	}
}

void stats_flip(struct stats *s, uint64_t presented, uint64_t shown)
{
	lat_add_ns(&s->flip, shown > presented ? shown - presented : 0);
}

/* Open file descriptors of this process (the soak test compares them). */
static int count_fds(void)
{
	DIR *d = opendir("/proc/self/fd");
	int n = 0;

	if (!d)
		return -1;
	while (readdir(d))
		n++;
	closedir(d);
	return n - 3;  /* ".", ".." and the directory's own fd */
}

void stats_print(const struct stats *s)
{
	char line[256];
	struct rusage ru;
	uint64_t el = in_now_ns() - s->start_ns;

	getrusage(RUSAGE_SELF, &ru);
	say("summary: %" PRIu64 " ticks, %" PRIu64 " frames in %" PRIu64
		".%03" PRIu64 " s (%.1f frames/s), %" PRIu64 " ticks dropped, %" PRIu64
		" frames late, peak RSS %ld KiB, %d open fds",
		s->ticks, s->frames, el / 1000000000u, el / 1000000u % 1000u,
		el ? (double)s->frames * 1e9 / (double)el : 0.0, s->dropped, s->late, ru.ru_maxrss,
		count_fds());
	lat_format(&s->frame_time, "frame time (render+present)", line, sizeof(line));
	say("summary: %s", line);
	lat_format(&s->latency, "input-to-present latency", line, sizeof(line));
	say("summary: %s", line);
	lat_format(&s->sound, "input-to-sound latency", line, sizeof(line));
	say("summary: %s; sound output: %" PRIu64 " underruns, %" PRIu64 " frames dropped", line,
	    s->underruns, s->audio_dropped);
	if (s->flip.count) {
		lat_format(&s->flip, "present-to-flip", line, sizeof(line));
		say("summary: %s", line);
	}
	for (int k = 0; k < s->nsrc; k++) {
		char name[64];
		if (!s->src[k].count)
			continue;   /* only the kinds that gave input */
		snprintf(name, sizeof(name), "input-to-present latency (%s)", s->src_name[k]);
		lat_format(&s->src[k], name, line, sizeof(line));
		say("summary: %s", line);
	}
}
