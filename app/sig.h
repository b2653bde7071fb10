/*
 * sig: the daemon's signals. Handlers only set flags, which the main loop
 * reads (STYLE.md: signal handlers do no work); the one exception is the
 * crash handler, which must put the console back before the process dies.
 *
 *   SIGINT, SIGTERM, SIGHUP   stop: the loop ends after its tick (sig_stop)
 *   SIGUSR1                   print the summary (sig_summary)
 *   SIGPIPE                   ignored
 *   SIGSEGV, SIGBUS, SIGILL,  restore the console and terminal with
 *   SIGFPE, SIGABRT           async-signal-safe calls (dp_emergency_restore),
 *                             then die of the same signal (systemd's watchdog
 *                             stops a hung service with SIGABRT)
 *
 * Fault injection for the watchdog test, off unless the environment asks:
 *   ARCADED_FAULT=hang-at:N   the main loop hangs after tick N
 *   ARCADED_FAULT=sigusr2     the main loop hangs when SIGUSR2 arrives
 * A hung loop stops sending WATCHDOG=1, so systemd must kill and restart
 * the service.
 *
 * The flags are file-scope: a handler has no other way to reach the loop.
 */
#ifndef ARCADED_APP_SIG_H
#define ARCADED_APP_SIG_H

#include <signal.h>
#include <stdint.h>

/* Installs the handlers above (not the fault injection's). */
void sig_install(void);

/* The stop signal received, 0 while none. */
int sig_stop(void);

/* The flag sig_stop reads, for code that polls it while the loop is not
 * running yet (a long content load: ct_spec.stop). */
const volatile sig_atomic_t *sig_stop_flag(void);

/* 1 once per SIGUSR1 received since the last call, else 0. */
int sig_summary(void);

/* Reads ARCADED_FAULT (logging what it will do, or that it is not
 * understood) and installs SIGUSR2's handler for "sigusr2". Returns the
 * tick to hang after, or UINT32_MAX. */
uint32_t sig_fault_setup(void);

/* Whether SIGUSR2 asked for the injected hang. */
int sig_fault(void);

/* The injected hang: sleeps without returning to the loop (so without
 * pinging the watchdog) until a stop signal. */
void sig_hang(void);

#endif
