/*
 * sig: signal handlers and the fault injection (contract in sig.h).
 */
#include "app/sig.h"

#include <execinfo.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "app/say.h"
#include "display/dp.h"

static volatile sig_atomic_t sig_stopped;
static volatile sig_atomic_t sig_summary_flag;
static volatile sig_atomic_t sig_fault_flag;

static void on_stop(int sig)
{
	sig_stopped = sig;
}

static void on_summary(int sig)
{
	(void)sig;
	sig_summary_flag = 1;
}

static void on_fault(int sig)
{
	(void)sig;
	sig_fault_flag = 1;
}

/* A crash must not leave the console in graphics mode: restore it (only
 * async-signal-safe calls), say where it happened (the call stack as
 * addresses and symbols on stderr, the journal under systemd: what an
 * operator sends with a bug report), then die of the same signal with the
 * default action (SA_RESETHAND put it back). backtrace() was called once
 * at install, so it does not load libgcc here; backtrace_symbols_fd
 * writes without malloc. */
static void on_fatal(int sig)
{
	void *pc[48];
	int n;

	dp_emergency_restore();
	say_fatal(sig == SIGSEGV   ? "arcaded: fatal signal SIGSEGV; the call stack:\n"
		  : sig == SIGBUS  ? "arcaded: fatal signal SIGBUS; the call stack:\n"
		  : sig == SIGILL  ? "arcaded: fatal signal SIGILL; the call stack:\n"
		  : sig == SIGFPE  ? "arcaded: fatal signal SIGFPE; the call stack:\n"
				   : "arcaded: fatal signal SIGABRT; the call stack:\n");
	n = backtrace(pc, (int)(sizeof(pc) / sizeof(pc[0])));
	backtrace_symbols_fd(pc, n, STDERR_FILENO);
	raise(sig);
}

void sig_install(void)
{
	struct sigaction sa;
	static const int fatal[] = { SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT };
	void *pc[1];

	(void)backtrace(pc, 1);   /* loads what backtrace needs, outside a handler */
	memset(&sa, 0, sizeof(sa));
	sigemptyset(&sa.sa_mask);
	sa.sa_handler = on_stop;
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	sigaction(SIGHUP, &sa, NULL);
	sa.sa_handler = on_summary;
	sa.sa_flags = SA_RESTART;
	sigaction(SIGUSR1, &sa, NULL);
	sa.sa_handler = SIG_IGN;
	sigaction(SIGPIPE, &sa, NULL);
	sa.sa_handler = on_fatal;
	sa.sa_flags = (int)SA_RESETHAND;
	for (size_t i = 0; i < sizeof(fatal) / sizeof(fatal[0]); i++)
		sigaction(fatal[i], &sa, NULL);
}

const volatile sig_atomic_t *sig_stop_flag(void)
{
	return &sig_stopped;
}

int sig_stop(void)
{
	return (int)sig_stopped;
}

int sig_summary(void)
{
	if (!sig_summary_flag)
		return 0;
	sig_summary_flag = 0;
	return 1;
}

uint32_t sig_fault_setup(void)
{
	const char *f = getenv("ARCADED_FAULT");
	struct sigaction sa;

	if (!f || !*f)
		return UINT32_MAX;
	if (strncmp(f, "hang-at:", 8) == 0) {
		char *end;
		unsigned long n = strtoul(f + 8, &end, 10);
		if (*end == '\0' && end != f + 8 && n < UINT32_MAX) {
			say_warn("fault injection: the main loop hangs after tick %lu", n);
			return (uint32_t)n;
		}
	} else if (strcmp(f, "sigusr2") == 0) {
		memset(&sa, 0, sizeof(sa));
		sigemptyset(&sa.sa_mask);
		sa.sa_handler = on_fault;
		sigaction(SIGUSR2, &sa, NULL);
		say_warn("fault injection: SIGUSR2 hangs the main loop");
		return UINT32_MAX;
	}
	say_warn("ARCADED_FAULT=%s not understood (hang-at:N or sigusr2); ignored", f);
	return UINT32_MAX;
}

int sig_fault(void)
{
	return (int)sig_fault_flag;
}

void sig_hang(void)
{
	struct timespec s = { 1, 0 };

	say_err("fault injection: main loop hung");
	/* a stop signal interrupts the sleep (EINTR) and ends the hang */
	while (!sig_stopped)
		nanosleep(&s, NULL);
}
