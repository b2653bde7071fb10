/*
 * lat: timing statistics of the main loop: frame time (render + present)
 * and input-to-present latency (from the kernel's event timestamp to the
 * end of the present that first showed its effect). Keeps the most recent
 * LAT_SAMPLES of each; percentiles are computed on demand.
 */
#ifndef ARCADED_APP_LAT_H
#define ARCADED_APP_LAT_H

#include <stddef.h>
#include <stdint.h>

#define LAT_SAMPLES 8192

struct lat_series {
	uint32_t us[LAT_SAMPLES];      /* ring of samples, microseconds */
	uint64_t count;                /* samples ever added */
	uint32_t max_us;
};

void lat_reset(struct lat_series *s);
void lat_add_ns(struct lat_series *s, uint64_t ns);

/* p-th percentile (0..100) of the kept samples in microseconds, nearest
 * rank; 0 when empty. */
uint32_t lat_percentile(const struct lat_series *s, int p);

/* "NAME p50 1.23 ms p99 4.56 ms max 7.89 ms (n 1234)" or "NAME: no samples". */
void lat_format(const struct lat_series *s, const char *name, char *buf, size_t len);

#endif
