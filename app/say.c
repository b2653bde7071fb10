/*
 * say: the daemon's log (contract in say.h).
 */
#include "app/say.h"

#include <stdarg.h>
#include <stdio.h>

void say(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	fputs("arcaded: ", stderr);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
	va_end(ap);
}

void say_cfg(void *user, const char *file, int line, const char *msg)
{
	(void)user;
	if (line > 0)
		say("%s:%d: %s", file, line, msg);
	else
		say("%s: %s", file, msg);
}
