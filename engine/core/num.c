/*
 * num: checked decimal numbers and hex digits (num.h).
 */
#include "engine/core/num.h"

#include <errno.h>
#include <stdlib.h>

int num_hex(int c)
{
	if (c >= '0' && c <= '9')
		return c - '0';
	if (c >= 'a' && c <= 'f')
		return c - 'a' + 10;
	if (c >= 'A' && c <= 'F')
		return c - 'A' + 10;
	return -1;
}

int num_parse(const char *s, int64_t lo, int64_t hi, int64_t *out)
{
	const char *d = s + (*s == '+' || *s == '-');
	char *end;
	long long v;

	/* strtoll would skip leading blanks: the first character after the
	 * sign must be a digit */
	if (*d < '0' || *d > '9')
		return -EINVAL;
	errno = 0;
	v = strtoll(s, &end, 10);
	if (*end != '\0')
		return -EINVAL;
	if (errno == ERANGE || v < lo || v > hi)
		return -ERANGE;
	*out = (int64_t)v;
	return 0;
}
