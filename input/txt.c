/*
 * txt: printf-style text into a caller's buffer (txt.h).
 */
#include "input/txt.h"

#include <stdarg.h>
#include <stdio.h>

void txt_set(char *buf, size_t len, const char *fmt, ...)
{
	va_list ap;

	if (!buf || !len)
		return;
	va_start(ap, fmt);
	vsnprintf(buf, len, fmt, ap);
	va_end(ap);
}

void txt_put(struct txt *t, const char *fmt, ...)
{
	size_t room = t->buf && t->n < t->len ? t->len - t->n : 0;
	va_list ap;
	int w;

	va_start(ap, fmt);
	w = vsnprintf(room ? t->buf + t->n : NULL, room, fmt, ap);
	va_end(ap);
	if (w > 0)
		t->n += (size_t)w;
}
