/*
 * say: the daemon's log, one line on stderr starting "arcaded: " (systemd's
 * journal takes it from there). The app is the one place that logs:
 * library code returns errors and the app names the file or device.
 *
 * Every line has a syslog priority: say_err for what failed (set-up that
 * stops the run, state or recordings not saved, a present that failed),
 * say_warn for what runs degraded (a bad configuration line and its
 * default, a device or display missing and looked for, a fallback), say
 * for everything else (info: what was opened, chosen, done). When stderr
 * is the journal's stream (svc_journal_fd), each line starts with the
 * sd-daemon prefix of its priority ("<3>", "<4>", "<6>"), which the
 * journal strips and records as the entry's PRIORITY, so
 * `journalctl -p warning -u arcaded` shows the warnings and errors only.
 * On a terminal or a file there is no prefix.
 */
#ifndef ARCADED_APP_SAY_H
#define ARCADED_APP_SAY_H

/* Looks (again) whether stderr is the journal's stream, which decides the
 * prefixes; until it is called there are none. main calls it first. */
void say_open(void);

/* Logs one line (no newline in fmt): info, warning, error. */
void say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void say_warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void say_err(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* From a fatal signal's handler: text (a whole line, newline included) as
 * an error, with write(2) only (async-signal-safe: no stdio, no malloc). */
void say_fatal(const char *text);

/* A cfg_err_fn (config/cfg.h) for every loader of configuration files:
 * "file:line: msg", or "file: msg" for line 0, as a warning (the value
 * keeps its default or previous setting). user is unused. */
void say_cfg(void *user, const char *file, int line, const char *msg);

#endif
