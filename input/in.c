/*
 * in: helpers shared by the input backends.
 */
#include "input/in.h"

#include <time.h>

uint64_t in_now_ns(void)
{
	struct timespec ts;

	/* CLOCK_MONOTONIC cannot fail with a valid pointer; it is the clock
	 * evdev is asked to stamp events with, so the two compare. */
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}
