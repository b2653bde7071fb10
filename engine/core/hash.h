/*
 * hash: 64-bit FNV-1a over explicit little-endian field encodings.
 *
 * Used for map content hashes, per-tick sim state hashes and frame hashes.
 * Callers hash fields one by one (never struct bytes, which carry padding),
 * so a hash is the same on every compiler and CPU.
 */
#ifndef ARCADED_ENGINE_HASH_H
#define ARCADED_ENGINE_HASH_H

#include <stddef.h>
#include <stdint.h>

#define HASH_INIT 0xcbf29ce484222325ull

uint64_t hash_bytes(uint64_t h, const void *p, size_t n);
uint64_t hash_u8(uint64_t h, uint8_t v);
uint64_t hash_u16(uint64_t h, uint16_t v);
uint64_t hash_u32(uint64_t h, uint32_t v);
uint64_t hash_u64(uint64_t h, uint64_t v);
/* Frame hash, as `arcaded --replay` prints and recordings store: FNV-1a
 * from HASH_INIT over the w bytes of each of the h rows, top to bottom,
 * rows pitch bytes apart (bytes between rows are not hashed). */
uint64_t hash_frame(const uint8_t *px, int w, int h, int pitch);
static inline uint64_t hash_i32(uint64_t h, int32_t v) { return hash_u32(h, (uint32_t)v); }

#endif
