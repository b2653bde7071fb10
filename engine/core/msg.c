/*
 * msg: appending to a fixed-size, NUL-terminated message buffer, for the
 * error texts the engine's loaders fill in and the HUD's strings. The
 * engine never allocates or formats with printf for these: a message is
 * built from pieces and truncated to the buffer.
 */
#include "engine/core/msg.h"

#include <string.h>

void msg_cat(char *err, size_t errlen, const char *s)
{
	size_t n;

	if (!err || errlen == 0)
		return;
	n = strlen(err);
	while (*s && n + 1 < errlen)
		err[n++] = *s++;
	err[n] = '\0';
}

void msg_int(char *err, size_t errlen, int64_t v)
{
	char buf[24];
	char *p = buf + sizeof buf - 1;
	uint64_t u = v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;

	*p = '\0';
	do {
		*--p = (char)('0' + u % 10);
		u /= 10;
	} while (u);
	if (v < 0)
		*--p = '-';
	msg_cat(err, errlen, p);
}

void msg_fx(char *err, size_t errlen, fx_t v)
{
	uint64_t u = v < 0 ? (uint64_t)0 - (uint64_t)(int64_t)v : (uint64_t)v;
	uint64_t frac = u & 0xffff;
	char digits[8];
	int n = 0;

	if (v < 0)
		msg_cat(err, errlen, "-");
	msg_int(err, errlen, (int64_t)(u >> 16));
	if (!frac)
		return;
	/* up to 5 decimals, truncated, trailing zeros dropped */
	digits[n++] = '.';
	frac = frac * 100000 / 65536;
	for (int d = 10000; d > 0 && frac; d /= 10) {
		digits[n++] = (char)('0' + frac / (uint64_t)d);
		frac %= (uint64_t)d;
	}
	digits[n] = '\0';
	msg_cat(err, errlen, digits);
}
