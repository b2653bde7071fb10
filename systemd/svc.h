/*
 * svc: the service manager's notification protocol (sd_notify), for a
 * Type=notify unit with a watchdog.
 *
 * Contract with systemd/arcaded.service: svc_ready once the first frame
 * is presented; svc_watchdog_ping from the main loop (never from a timer
 * or thread, so a hung loop stops the pings and gets restarted) at least
 * every svc_watchdog_interval_ns; svc_stopping when shutting down.
 *
 * Every notification is a no-op returning 0 when the process does not run
 * under systemd (NOTIFY_SOCKET unset). Sending returns a positive value; a
 * failure -errno. Nothing here logs, blocks or keeps state.
 */
#ifndef ARCADED_SYSTEMD_SVC_H
#define ARCADED_SYSTEMD_SVC_H

#include <stdint.h>

/* Sends READY=1 and STATUS=running. */
int svc_ready(void);

/* Sends STATUS=<formatted text> (shown by systemctl status; newlines become
 * spaces, the text is cut at 255 bytes). */
int svc_status(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Sends STOPPING=1. */
int svc_stopping(void);

/* Sends WATCHDOG=1. */
int svc_watchdog_ping(void);

/* How often to ping: half of WATCHDOG_USEC, in ns; 0 when the watchdog is
 * off for this process (unset, or WATCHDOG_PID names another process). */
uint64_t svc_watchdog_interval_ns(void);

/* Whether fd is the stream systemd connected to the journal: the device
 * and inode in JOURNAL_STREAM ("DEV:INO", set by the service manager for
 * StandardOutput=/StandardError=journal) are fd's. 1 yes, 0 no (unset, a
 * terminal, a file or a pipe of our own: a child inherits the variable
 * with other fds), -errno when fd cannot be looked at. Lines written to
 * such a stream may start with a "<N>" priority prefix (app/say.h). */
int svc_journal_fd(int fd);

#endif
