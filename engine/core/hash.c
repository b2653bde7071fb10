/*
 * hash: 64-bit FNV-1a (http://www.isthe.com/chongo/tech/comp/fnv/).
 * Multi-byte values are hashed as their little-endian bytes, whatever the
 * CPU's byte order.
 */
#include "engine/core/hash.h"

#include "engine/core/le.h"

#define HASH_PRIME 0x100000001b3ull

uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
	const unsigned char *b = p;
	size_t i;

	for (i = 0; i < n; i++) {
		h ^= b[i];
		h *= HASH_PRIME;
	}
	return h;
}

uint64_t hash_u8(uint64_t h, uint8_t v)
{
	return hash_bytes(h, &v, 1);
}

uint64_t hash_u16(uint64_t h, uint16_t v)
{
	uint8_t b[2];

	le_put16(b, v);
	return hash_bytes(h, b, sizeof b);
}

uint64_t hash_u32(uint64_t h, uint32_t v)
{
	uint8_t b[4];

	le_put32(b, v);
	return hash_bytes(h, b, sizeof b);
}

uint64_t hash_u64(uint64_t h, uint64_t v)
{
	uint8_t b[8];

	le_put64(b, v);
	return hash_bytes(h, b, sizeof b);
}

uint64_t hash_frame(const uint8_t *px, int w, int h, int pitch)
{
	uint64_t hv = HASH_INIT;

	for (int y = 0; y < h; y++)
		hv = hash_bytes(hv, px + (size_t)y * (size_t)pitch, (size_t)w);
	return hv;
}
