/* Tests for engine/game/g_score.c: the high-score table and the byte encodings
 * of scores and bookkeeping. */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_game.h"

static void the_default_table_is_sorted_with_valid_names(void **state)
{
	struct g_scores t;
	(void)state;
	g_scores_default(&t);
	assert_int_equal(t.e[0].score, 10000);
	assert_int_equal(t.e[G_SCORES - 1].score, 1000);
	for (int i = 0; i < G_SCORES; i++) {
		if (i > 0)
			assert_true(t.e[i].score < t.e[i - 1].score);
		for (int k = 0; k < G_NAME_LEN; k++)
			assert_non_null(memchr(G_ALPHABET, t.e[i].name[k], G_ALPHABET_LEN));
		assert_true(t.e[i].stage >= 1);
	}
}

static void rank_goes_below_equal_scores_and_zero_never_ranks(void **state)
{
	struct g_scores t;
	(void)state;
	g_scores_default(&t);
	assert_int_equal(g_scores_rank(&t, 10001), 0);
	assert_int_equal(g_scores_rank(&t, 10000), 1);   /* ties stay above */
	assert_int_equal(g_scores_rank(&t, 1001), 9);
	assert_int_equal(g_scores_rank(&t, 1000), -1);
	assert_int_equal(g_scores_rank(&t, 0), -1);
	memset(&t, 0, sizeof(t));
	assert_int_equal(g_scores_rank(&t, 0), -1);
	assert_int_equal(g_scores_rank(&t, 1), 0);
}

static void insert_moves_lower_entries_down(void **state)
{
	struct g_scores t;
	(void)state;
	g_scores_default(&t);
	g_scores_insert(&t, 0, "ZZZ", 20000, 4);
	assert_memory_equal(t.e[0].name, "ZZZ", 3);
	assert_int_equal(t.e[0].stage, 4);
	assert_memory_equal(t.e[1].name, "ARC", 3);
	assert_int_equal(t.e[9].score, 2000);
	g_scores_insert(&t, 9, "YYY", 1500, 1);
	assert_memory_equal(t.e[9].name, "YYY", 3);
	assert_int_equal(t.e[8].score, 3000);
}

static void scores_round_trip_through_bytes(void **state)
{
	struct g_scores t, u;
	uint8_t b[G_SCORES_BYTES];
	(void)state;
	g_scores_default(&t);
	g_scores_insert(&t, 1, "A.9", 0x2520, 7);   /* 9504, between 10000 and 9000 */
	g_scores_encode(&t, b);
	/* layout: magic, then entry 0 name and little-endian score */
	assert_memory_equal(b, "GS\1\0ARC", 7);
	assert_int_equal(b[7], 10000 & 0xff);
	assert_int_equal(b[8], 10000 >> 8);
	assert_int_equal(b[4 + 1 * 8 + 3], 0x20);   /* 0x2520, low byte first */
	assert_int_equal(b[4 + 1 * 8 + 4], 0x25);
	assert_int_equal(b[4 + 1 * 8 + 5], 0);
	assert_int_equal(b[4 + 1 * 8 + 7], 7);      /* stage */
	memset(&u, 0, sizeof(u));
	assert_int_equal(g_scores_decode(b, sizeof(b), &u), 0);
	for (int i = 0; i < G_SCORES; i++) {
		assert_memory_equal(u.e[i].name, t.e[i].name, G_NAME_LEN);
		assert_int_equal(u.e[i].score, t.e[i].score);
		assert_int_equal(u.e[i].stage, t.e[i].stage);
	}
}

static void bad_score_bytes_are_refused_and_leave_the_table(void **state)
{
	struct g_scores t, u;
	uint8_t b[G_SCORES_BYTES], c[G_SCORES_BYTES];
	(void)state;
	g_scores_default(&t);
	g_scores_encode(&t, b);
	memset(&u, 0x5a, sizeof(u));
	assert_int_equal(g_scores_decode(b, sizeof(b) - 1, &u), -EINVAL);
	memcpy(c, b, sizeof(c));
	c[2] = 2;                                   /* unknown format */
	assert_int_equal(g_scores_decode(c, sizeof(c), &u), -EINVAL);
	memcpy(c, b, sizeof(c));
	c[4] = 'a';                                 /* lower case is not a letter here */
	assert_int_equal(g_scores_decode(c, sizeof(c), &u), -EINVAL);
	memcpy(c, b, sizeof(c));
	c[4 + 8 + 5] = 1;                           /* entry 1 (9000) + 65536: above entry 0 */
	assert_int_equal(g_scores_decode(c, sizeof(c), &u), -EINVAL);
	memcpy(c, b, sizeof(c));
	c[4 + 7] = 0;                               /* stage 0 */
	assert_int_equal(g_scores_decode(c, sizeof(c), &u), -EINVAL);
	for (size_t i = 0; i < sizeof(u); i++)
		assert_int_equal(((uint8_t *)&u)[i], 0x5a);
}

static void books_round_trip_through_bytes(void **state)
{
	struct g_books a = { 12345, 678, 0x0102030405060708ull, 99 }, b;
	uint8_t buf[G_BOOKS_BYTES];
	(void)state;
	g_books_encode(&a, buf);
	assert_memory_equal(buf, "GB\1\0", 4);
	assert_int_equal(buf[12], 8);
	assert_int_equal(buf[19], 1);
	memset(&b, 0, sizeof(b));
	assert_int_equal(g_books_decode(buf, sizeof(buf), &b), 0);
	assert_int_equal(b.coins, 12345);
	assert_int_equal(b.plays, 678);
	assert_true(b.play_ticks == 0x0102030405060708ull);
	assert_int_equal(b.on_ticks, 99);
	buf[1] = 'S';
	assert_int_equal(g_books_decode(buf, sizeof(buf), &b), -EINVAL);
	assert_int_equal(g_books_decode(buf, 3, &b), -EINVAL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_default_table_is_sorted_with_valid_names),
		cmocka_unit_test(rank_goes_below_equal_scores_and_zero_never_ranks),
		cmocka_unit_test(insert_moves_lower_entries_down),
		cmocka_unit_test(scores_round_trip_through_bytes),
		cmocka_unit_test(bad_score_bytes_are_refused_and_leave_the_table),
		cmocka_unit_test(books_round_trip_through_bytes),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
