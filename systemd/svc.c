/*
 * svc: sd_notify wrappers (svc.h). libsystemd's sd_notify already returns
 * 0 without NOTIFY_SOCKET, > 0 when sent and -errno on failure; these keep
 * the environment (unset_environment = 0) so later pings still find the
 * socket.
 */
#include "systemd/svc.h"

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <systemd/sd-daemon.h>

int svc_ready(void)
{
	return sd_notify(0, "READY=1\nSTATUS=running");
}

int svc_status(const char *fmt, ...)
{
	char text[256];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(text, sizeof(text), fmt, ap);
	va_end(ap);
	/* A newline would start another assignment (READY=1, ...). */
	for (char *p = text; *p; p++)
		if (*p == '\n')
			*p = ' ';
	return sd_notifyf(0, "STATUS=%s", text);
}

int svc_stopping(void)
{
	return sd_notify(0, "STOPPING=1");
}

int svc_watchdog_ping(void)
{
	return sd_notify(0, "WATCHDOG=1");
}

uint64_t svc_watchdog_interval_ns(void)
{
	uint64_t usec = 0;

	if (sd_watchdog_enabled(0, &usec) <= 0)
		return 0;
	return usec * 1000u / 2;
}

int svc_journal_fd(int fd)
{
	const char *e = getenv("JOURNAL_STREAM");
	uintmax_t dev, ino;
	struct stat st;
	int used = 0;

	if (!e || sscanf(e, "%ju:%ju%n", &dev, &ino, &used) != 2 || e[used] != '\0')
		return 0;
	if (fstat(fd, &st) != 0)
		return -errno;
	return (uintmax_t)st.st_dev == dev && (uintmax_t)st.st_ino == ino;
}
