/* Tests for engine/hash.c: FNV-1a 64 and its little-endian encodings. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "engine/hash.h"

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

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(published_vectors_match),
		cmocka_unit_test(hashing_in_pieces_equals_hashing_at_once),
		cmocka_unit_test(integers_hash_as_little_endian_bytes),
		cmocka_unit_test(different_values_give_different_hashes),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
