/*
 * fx: 16.16 fixed point and binary angles, the only number types of the
 * simulation and the renderer.
 *
 * Contract: every operation here is exact integer arithmetic with 64-bit
 * intermediates, so results are identical on every compiler, optimisation
 * level and CPU. Right shifts of negative values rely on arithmetic shift,
 * which gcc and clang define for every target they support (checked by a
 * static assertion below). Left shifts of negative values are undefined in C,
 * so conversions multiply by the unit instead.
 */
#ifndef ARCADED_ENGINE_FX_H
#define ARCADED_ENGINE_FX_H

#include <stdint.h>

typedef int32_t fx_t;                 /* 16.16 signed fixed point */
typedef uint32_t ang_t;               /* binary angle: 2^32 = one full turn */

#define FX_SHIFT 16
#define FX_ONE ((fx_t)1 << FX_SHIFT)
#define FX_HALF (FX_ONE / 2)
#define FX_MAX INT32_MAX
#define FX_MIN INT32_MIN

#define ANG45 0x20000000u
#define ANG90 0x40000000u
#define ANG180 0x80000000u
#define ANG270 0xc0000000u

_Static_assert((-1 >> 1) == -1, "arithmetic right shift required");
_Static_assert(((int64_t)-1 >> 1) == -1, "arithmetic right shift required");

/* Integer map units to fixed point. */
static inline fx_t fx_from_int(int32_t i) { return (fx_t)(i * FX_ONE); }

/* Fixed point to integer map units, rounding towards minus infinity. */
static inline int32_t fx_to_int(fx_t a) { return a >> FX_SHIFT; }

/* a * b, rounded towards minus infinity. Overflow of the 16.16 result is the
 * caller's responsibility (it wraps like int32 arithmetic on two's
 * complement after the conversion, which C11 makes implementation-defined
 * but gcc/clang define as modular). */
static inline fx_t fx_mul(fx_t a, fx_t b)
{
	return (fx_t)(((int64_t)a * b) >> FX_SHIFT);
}

/* a / b, truncated towards zero; saturates to FX_MIN/FX_MAX when the quotient
 * does not fit or b is 0 (Doom's FixedDiv behaviour, without its crash). */
static inline fx_t fx_div(fx_t a, fx_t b)
{
	int64_t q;
	if (b == 0)
		return a < 0 ? FX_MIN : FX_MAX;
	q = ((int64_t)a * FX_ONE) / b;
	if (q > FX_MAX)
		return FX_MAX;
	if (q < FX_MIN)
		return FX_MIN;
	return (fx_t)q;
}

static inline fx_t fx_abs(fx_t a) { return a < 0 ? -a : a; }

/* floor(sqrt(n)) for every 64-bit n, by the digit-by-digit method (exact,
 * no floating point). */
static inline uint32_t fx_isqrt64(uint64_t n)
{
	uint64_t r = 0, bit = (uint64_t)1 << 62;

	while (bit > n)
		bit >>= 2;
	while (bit) {
		if (n >= r + bit) {
			n -= r + bit;
			r = (r >> 1) + bit;
		} else {
			r >>= 1;
		}
		bit >>= 2;
	}
	return (uint32_t)r;
}

/* Length of the vector (dx, dy), rounded to nearest; exact integer for every
 * pair of fx_t (the sum of squares fits uint64). Saturates to FX_MAX. */
static inline fx_t fx_len(fx_t dx, fx_t dy)
{
	uint64_t ax = dx < 0 ? (uint64_t)(-(int64_t)dx) : (uint64_t)dx;
	uint64_t ay = dy < 0 ? (uint64_t)(-(int64_t)dy) : (uint64_t)dy;
	uint64_t n = ax * ax + ay * ay;
	uint64_t r = fx_isqrt64(n);

	/* round up when n >= (r + 1/2)^2 = r^2 + r + 1/4, i.e. n > r^2 + r */
	if (n - r * r > r)
		r++;
	return r > FX_MAX ? FX_MAX : (fx_t)r;
}

#endif
