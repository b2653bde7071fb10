/*
 * le: little-endian integers in byte buffers, for every file format the
 * project reads or writes (WAD lumps, recordings, state files, the
 * high-score table's bytes). Never a struct dump or a pointer cast: each
 * byte is placed and read by arithmetic, so the result does not depend on
 * the CPU's byte order or on alignment.
 *
 * Why here: the engine parses WADs and encodes its tables, and input/ and
 * config/ (recordings, state files) are above the engine, so engine/core
 * is the one place every user may include. The functions are pure (no
 * I/O), and static inline: they sit in the inner loops of the WAD parsers.
 *
 * get: p must hold the bytes. put: p must have room for them. The signed
 * getters convert by arithmetic, never by an implementation-defined cast.
 */
#ifndef ARCADED_ENGINE_LE_H
#define ARCADED_ENGINE_LE_H

#include <stdint.h>

static inline uint16_t le_get16(const uint8_t *p)
{
	return (uint16_t)(p[0] | (unsigned)p[1] << 8);
}

static inline uint32_t le_get32(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static inline uint64_t le_get64(const uint8_t *p)
{
	return (uint64_t)le_get32(p) | (uint64_t)le_get32(p + 4) << 32;
}

/* Two's complement, 16 and 32 bits. */
static inline int16_t le_s16(const uint8_t *p)
{
	uint16_t v = le_get16(p);

	return (int16_t)(v < 0x8000u ? (int32_t)v : (int32_t)v - 0x10000);
}

static inline int32_t le_s32(const uint8_t *p)
{
	uint32_t v = le_get32(p);

	return v < 0x80000000u ? (int32_t)v : (int32_t)(v - 0x80000000u) + INT32_MIN;
}

/* The first n (0..8) bytes at p as a little-endian number: fields whose
 * width is known only at run time (HID items and report fields, the sim's
 * state walk). */
static inline uint64_t le_getn(const uint8_t *p, int n)
{
	uint64_t v = 0;

	for (int i = 0; i < n; i++)
		v |= (uint64_t)p[i] << (8 * i);
	return v;
}

/* v's low n (0..8) bytes to p, little-endian. */
static inline void le_putn(uint8_t *p, uint64_t v, int n)
{
	for (int i = 0; i < n; i++)
		p[i] = (uint8_t)(v >> (8 * i));
}

static inline void le_put16(uint8_t *p, uint16_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
}

static inline void le_put32(uint8_t *p, uint32_t v)
{
	le_putn(p, v, 4);
}

static inline void le_put64(uint8_t *p, uint64_t v)
{
	le_putn(p, v, 8);
}

#endif
