/* libFuzzer target: the state-file decoders of the high-score table and
 * the bookkeeping (engine/game/g_score.c). Any bytes decode or are refused; a
 * decoded table re-encodes to exactly the same bytes and is sorted. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/game/g_game.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	struct g_scores t;
	struct g_books b;
	uint8_t back[G_SCORES_BYTES > G_BOOKS_BYTES ? G_SCORES_BYTES : G_BOOKS_BYTES];

	if (g_scores_decode(data, len, &t) == 0) {
		g_scores_encode(&t, back);
		if (len != G_SCORES_BYTES || memcmp(back, data, len) != 0)
			abort();
		for (int i = 1; i < G_SCORES; i++)
			if (t.e[i].score > t.e[i - 1].score)
				abort();
	}
	if (g_books_decode(data, len, &b) == 0) {
		g_books_encode(&b, back);
		if (len != G_BOOKS_BYTES || memcmp(back, data, len) != 0)
			abort();
	}
	return 0;
}
