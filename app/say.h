/*
 * say: the daemon's log, one line on stderr starting "arcaded: " (systemd's
 * journal takes it from there). The app is the one place that logs:
 * library code returns errors and the app names the file or device.
 */
#ifndef ARCADED_APP_SAY_H
#define ARCADED_APP_SAY_H

/* Logs one line (no newline in fmt). */
void say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* A cfg_err_fn (config/cfg.h) for every loader of configuration files:
 * "file:line: msg", or "file: msg" for line 0. user is unused. */
void say_cfg(void *user, const char *file, int line, const char *msg);

#endif
