/*
 * g_score: the high-score table and the bookkeeping totals, and their byte
 * encodings for the state directory (the app writes the bytes with the
 * persistence layer's atomic, checksummed files).
 *
 * Layouts, little-endian:
 *   scores: "GS" 1 0, then G_SCORES entries of 3 name bytes (G_ALPHABET),
 *           uint32 score, uint8 stage (1..255); best first.
 *   books:  "GB" 1 0, uint32 coins, uint32 plays, uint64 play_ticks,
 *           uint64 on_ticks.
 */
#include <errno.h>
#include <string.h>

#include "engine/core/le.h"
#include "engine/game/g_game.h"

#define G_FORMAT 1

void g_scores_default(struct g_scores *t)
{
	static const char names[G_SCORES][G_NAME_LEN + 1] = {
		"ARC", "ADE", "FIX", "BSP", "SIM", "HUD", "RAY", "MAP", "WAD", "TIC",
	};

	for (int i = 0; i < G_SCORES; i++) {
		memcpy(t->e[i].name, names[i], G_NAME_LEN);
		t->e[i].score = (uint32_t)(G_SCORES - i) * 1000u;
		t->e[i].stage = (uint8_t)(i < 3 ? 3 : i < 6 ? 2 : 1);
	}
}

int g_scores_rank(const struct g_scores *t, uint32_t score)
{
	if (score == 0)
		return -1;
	for (int i = 0; i < G_SCORES; i++)
		if (score > t->e[i].score)
			return i;
	return -1;
}

void g_scores_insert(struct g_scores *t, int rank, const char name[G_NAME_LEN],
		     uint32_t score, uint8_t stage)
{
	if (rank < 0 || rank >= G_SCORES)
		return;
	memmove(&t->e[rank + 1], &t->e[rank], (size_t)(G_SCORES - 1 - rank) * sizeof(t->e[0]));
	memcpy(t->e[rank].name, name, G_NAME_LEN);
	t->e[rank].score = score;
	t->e[rank].stage = stage;
}

static int g_letter_ok(uint8_t c)
{
	return c != '\0' && memchr(G_ALPHABET, c, G_ALPHABET_LEN) != NULL;
}

void g_scores_encode(const struct g_scores *t, uint8_t out[G_SCORES_BYTES])
{
	uint8_t *p = out + 4;

	out[0] = 'G';
	out[1] = 'S';
	out[2] = G_FORMAT;
	out[3] = 0;
	for (int i = 0; i < G_SCORES; i++, p += G_NAME_LEN + 5) {
		memcpy(p, t->e[i].name, G_NAME_LEN);
		le_put32(p + G_NAME_LEN, t->e[i].score);
		p[G_NAME_LEN + 4] = t->e[i].stage;
	}
}

int g_scores_decode(const uint8_t *buf, size_t len, struct g_scores *out)
{
	struct g_scores t;
	const uint8_t *p = buf + 4;

	if (len != G_SCORES_BYTES || buf[0] != 'G' || buf[1] != 'S' || buf[2] != G_FORMAT ||
	    buf[3] != 0)
		return -EINVAL;
	for (int i = 0; i < G_SCORES; i++, p += G_NAME_LEN + 5) {
		for (int k = 0; k < G_NAME_LEN; k++) {
			if (!g_letter_ok(p[k]))
				return -EINVAL;
			t.e[i].name[k] = (char)p[k];
		}
		t.e[i].score = le_get32(p + G_NAME_LEN);
		t.e[i].stage = p[G_NAME_LEN + 4];
		if (t.e[i].stage == 0 || (i > 0 && t.e[i].score > t.e[i - 1].score))
			return -EINVAL;
	}
	*out = t;
	return 0;
}

void g_books_encode(const struct g_books *b, uint8_t out[G_BOOKS_BYTES])
{
	out[0] = 'G';
	out[1] = 'B';
	out[2] = G_FORMAT;
	out[3] = 0;
	le_put32(out + 4, b->coins);
	le_put32(out + 8, b->plays);
	le_put64(out + 12, b->play_ticks);
	le_put64(out + 20, b->on_ticks);
}

int g_books_decode(const uint8_t *buf, size_t len, struct g_books *out)
{
	if (len != G_BOOKS_BYTES || buf[0] != 'G' || buf[1] != 'B' || buf[2] != G_FORMAT ||
	    buf[3] != 0)
		return -EINVAL;
	out->coins = le_get32(buf + 4);
	out->plays = le_get32(buf + 8);
	out->play_ticks = le_get64(buf + 12);
	out->on_ticks = le_get64(buf + 20);
	return 0;
}
