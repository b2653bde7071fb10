/* libFuzzer target: the test-script parser (input/scr.c). Any bytes must
 * parse or fail with a message; a parsed script's steps must be sorted by
 * tick and its end tick must cover every step but the releases (a tap on
 * the end tick leaves its release after the end, on purpose: it never
 * runs). */
#include <stdint.h>
#include <stdlib.h>

#include "input/scr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	struct scr *s = NULL;
	char err[256];

	if (scr_parse((const char *)data, len, "fuzz", &s, err, sizeof(err)) == 0) {
		for (size_t i = 1; i < s->n; i++)
			if (s->steps[i].tick < s->steps[i - 1].tick)
				abort();
		for (size_t i = 0; i < s->n; i++)
			if (s->steps[i].op != SCR_RELEASE && s->steps[i].tick > s->end_tick)
				abort();
		scr_free(s);
	}
	return 0;
}
