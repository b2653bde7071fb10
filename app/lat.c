#include "app/lat.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void lat_reset(struct lat_series *s)
{
	memset(s, 0, sizeof(*s));
}

void lat_add_ns(struct lat_series *s, uint64_t ns)
{
	uint64_t us = ns / 1000;
	uint32_t v = us > UINT32_MAX ? UINT32_MAX : (uint32_t)us;

	s->us[s->count % LAT_SAMPLES] = v;
	s->count++;
	if (v > s->max_us)
		s->max_us = v;
}

static int cmp_u32(const void *a, const void *b)
{
	uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
	return (x > y) - (x < y);
}

uint32_t lat_percentile(const struct lat_series *s, int p)
{
	size_t n = s->count < LAT_SAMPLES ? (size_t)s->count : LAT_SAMPLES;
	uint32_t *tmp, v;
	size_t rank;

	if (n == 0)
		return 0;
	tmp = malloc(n * sizeof(*tmp));
	if (!tmp)
		return 0;
	memcpy(tmp, s->us, n * sizeof(*tmp));
	qsort(tmp, n, sizeof(*tmp), cmp_u32);
	if (p < 0)
		p = 0;
	if (p > 100)
		p = 100;
	/* nearest rank: ceil(p/100 * n), 1-based */
	rank = ((size_t)p * n + 99) / 100;
	if (rank == 0)
		rank = 1;
	v = tmp[rank - 1];
	free(tmp);
	return v;
}

void lat_format(const struct lat_series *s, const char *name, char *buf, size_t len)
{
	if (s->count == 0) {
		snprintf(buf, len, "%s: no samples", name);
		return;
	}
	uint32_t p50 = lat_percentile(s, 50), p99 = lat_percentile(s, 99);
	snprintf(buf, len, "%s p50 %u.%02u ms p99 %u.%02u ms max %u.%02u ms (n %llu)", name,
		 p50 / 1000, p50 % 1000 / 10, p99 / 1000, p99 % 1000 / 10, s->max_us / 1000,
		 s->max_us % 1000 / 10, (unsigned long long)s->count);
}
