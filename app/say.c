/*
 * say: the daemon's log (contract in say.h).
 */
#include "app/say.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "systemd/svc.h"

/* Set by say_open from the main thread before anything else logs. */
static int say_journal;

/* sd-daemon's priority prefixes (sd-daemon.h SD_ERR, SD_WARNING, SD_INFO). */
#define SAY_ERR "<3>"
#define SAY_WARN "<4>"
#define SAY_INFO "<6>"

void say_open(void)
{
	say_journal = svc_journal_fd(2) > 0;
}

void say_fatal(const char *text)
{
	if (say_journal && write(STDERR_FILENO, SAY_ERR, sizeof(SAY_ERR) - 1) < 0)
		return;
	if (write(STDERR_FILENO, text, strlen(text)) < 0)
		return;
}

/* One line at once (a single fprintf into the locked stream), so lines
 * of the render threads' or a library's do not cut into it. */
static void say_line(const char *prio, const char *fmt, va_list ap)
{
	char msg[1024];

	vsnprintf(msg, sizeof(msg), fmt, ap);
	fprintf(stderr, "%sarcaded: %s\n", say_journal ? prio : "", msg);
}

void say(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	say_line(SAY_INFO, fmt, ap);
	va_end(ap);
}

void say_warn(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	say_line(SAY_WARN, fmt, ap);
	va_end(ap);
}

void say_err(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	say_line(SAY_ERR, fmt, ap);
	va_end(ap);
}

void say_cfg(void *user, const char *file, int line, const char *msg)
{
	(void)user;
	if (line > 0)
		say_warn("%s:%d: %s", file, line, msg);
	else
		say_warn("%s: %s", file, msg);
}
