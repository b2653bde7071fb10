/* Tests for engine/core/hash.c: FNV-1a 64 and its little-endian encodings. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "engine/core/hash.h"

/* Published FNV-1a 64-bit test vectors (isthe.com FNV test suite). */
static void published_vectors_match(void **state)
{
	(void)state;
	assert_true(hash_bytes(HASH_INIT, "", 0) == 0xcbf29ce484222325ull);
	assert_true(hash_bytes(HASH_INIT, "a", 1) == 0xaf63dc4c8601ec8cull);
	assert_true(hash_bytes(HASH_INIT, "foobar", 6) == 0x85944171f73967e8ull);
}

static void hashing_in_pieces_equals_hashing_at_once(void **state)
{
	uint64_t h;
	(void)state;
	h = hash_bytes(HASH_INIT, "foo", 3);
	h = hash_bytes(h, "bar", 3);
	assert_true(h == 0x85944171f73967e8ull);
}

static void integers_hash_as_little_endian_bytes(void **state)
{
	(void)state;
	assert_true(hash_u8(HASH_INIT, 'a') == hash_bytes(HASH_INIT, "a", 1));
	assert_true(hash_u16(HASH_INIT, 0x6261) == hash_bytes(HASH_INIT, "ab", 2));
	assert_true(hash_u32(HASH_INIT, 0x64636261u) == hash_bytes(HASH_INIT, "abcd", 4));
	assert_true(hash_u64(HASH_INIT, 0x6867666564636261ull) ==
		    hash_bytes(HASH_INIT, "abcdefgh", 8));
	assert_true(hash_i32(HASH_INIT, -1) == hash_bytes(HASH_INIT, "\xff\xff\xff\xff", 4));
}

static void different_values_give_different_hashes(void **state)
{
	(void)state;
	assert_true(hash_u32(HASH_INIT, 1) != hash_u32(HASH_INIT, 2));
	assert_true(hash_u32(HASH_INIT, 1) != hash_u64(HASH_INIT, 1));
}

/* A 3x2 frame in a pitch of 5: hashed as its 6 pixels, padding ignored. */
static void frame_hash_skips_row_padding(void **state)
{
	const uint8_t padded[10] = { 'a', 'b', 'c', 9, 9, 'd', 'e', 'f', 9, 9 };
	const uint8_t other_pad[10] = { 'a', 'b', 'c', 1, 2, 'd', 'e', 'f', 3, 4 };
	const uint64_t want = hash_bytes(HASH_INIT, "abcdef", 6);

	(void)state;
	assert_true(hash_frame(padded, 3, 2, 5) == want);
	assert_true(hash_frame(other_pad, 3, 2, 5) == want);
	assert_true(hash_frame((const uint8_t *)"abcdef", 3, 2, 3) == want);
	assert_true(hash_frame(padded, 3, 1, 5) == hash_bytes(HASH_INIT, "abc", 3));
	assert_true(hash_frame(padded, 0, 0, 5) == HASH_INIT);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(published_vectors_match),
		cmocka_unit_test(hashing_in_pieces_equals_hashing_at_once),
		cmocka_unit_test(integers_hash_as_little_endian_bytes),
		cmocka_unit_test(different_values_give_different_hashes),
		cmocka_unit_test(frame_hash_skips_row_padding),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
