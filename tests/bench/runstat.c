/*
 * runstat: runs a command and prints its wall time, peak RSS and peak
 * private memory, for `make bench` (tests/bench.sh): the peer engines, and
 * the daemon's own memory and start-up.
 *
 *   runstat [--ready] [--every MS] OUT command [args...]
 *
 * The command's stdout and stderr go to the file OUT, its stdin is
 * /dev/null. While it runs, /proc/PID/smaps_rollup is read every MS
 * milliseconds (default 20: reading it walks the process's page tables,
 * which would slow a timed peer down if done much more often):
 * private memory is its anonymous and private dirty pages, max(Anonymous,
 * Private_Dirty) (anonymous pages are private dirty too: their sum would
 * count them twice), and the largest value seen is reported with the RSS
 * seen at that moment. Peak RSS is the kernel's (wait4).
 *
 * --ready: the command gets a NOTIFY_SOCKET of runstat's (a datagram
 * socket, as systemd gives a Type=notify service) and ready_ns is the time
 * from just before exec to its READY=1; arcaded sends it once its first
 * frame is presented. The command is then stopped with SIGTERM.
 *
 * Prints "wall_ns=N rss_kib=K priv_kib=P priv_rss_kib=R status=S" (S: exit
 * status, or 128 + signal; with --ready also ready_ns=T, 0 when READY=1
 * never came) and exits 0, or 1 when the command could not be started.
 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* Private memory and RSS of pid now (kB); 0 when unreadable. */
static void sample(pid_t pid, long *priv, long *rss)
{
	char path[64], line[256];
	long anon = 0, dirty = 0, v;
	FILE *f;

	*priv = *rss = 0;
	snprintf(path, sizeof(path), "/proc/%d/smaps_rollup", (int)pid);
	f = fopen(path, "re");
	if (!f)
		return;
	while (fgets(line, sizeof(line), f)) {
		if (sscanf(line, "Anonymous: %ld kB", &v) == 1)
			anon = v;
		else if (sscanf(line, "Private_Dirty: %ld kB", &v) == 1)
			dirty = v;
		else if (sscanf(line, "Rss: %ld kB", &v) == 1)
			*rss = v;
	}
	fclose(f);
	*priv = anon > dirty ? anon : dirty;
}

int main(int argc, char **argv)
{
	struct sockaddr_un sa = { .sun_family = AF_UNIX };
	struct rusage ru;
	uint64_t t0, t1, ready = 0;
	long priv_max = 0, priv_rss = 0;
	int st = 0, out, ntf = -1, want_ready = 0, done = 0, every = 20;
	uint64_t next = 0;
	pid_t pid;

	for (;;) {
		if (argc > 1 && strcmp(argv[1], "--ready") == 0) {
			want_ready = 1;
			argv++;
			argc--;
		} else if (argc > 2 && strcmp(argv[1], "--every") == 0 && atoi(argv[2]) > 0) {
			every = atoi(argv[2]);
			argv += 2;
			argc -= 2;
		} else {
			break;
		}
	}
	if (argc < 3)
		return fprintf(stderr, "usage: runstat [--ready] [--every MS] OUT command [args...]\n"),
		       2;
	out = open(argv[1], O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (out < 0)
		return perror(argv[1]), 1;
	if (want_ready) {
		/* an abstract socket: nothing to clean up in the file system */
		snprintf(sa.sun_path + 1, sizeof(sa.sun_path) - 1, "runstat-%d", (int)getpid());
		ntf = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
		if (ntf < 0 || bind(ntf, (struct sockaddr *)&sa,
				    (socklen_t)(offsetof(struct sockaddr_un, sun_path) + 1 +
						strlen(sa.sun_path + 1))) < 0)
			return perror("notify socket"), 1;
		char env[120];
		snprintf(env, sizeof(env), "@%s", sa.sun_path + 1);
		setenv("NOTIFY_SOCKET", env, 1);
	}
	t0 = now_ns();
	pid = fork();
	if (pid < 0)
		return perror("fork"), 1;
	if (pid == 0) {
		int in = open("/dev/null", O_RDONLY | O_CLOEXEC);

		if (in < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0)
			_exit(127);
		execvp(argv[2], argv + 2);
		_exit(127);
	}
	while (!done) {
		struct pollfd p = { .fd = ntf, .events = POLLIN };
		long priv, rss;
		pid_t w;

		if (now_ns() >= next) {
			sample(pid, &priv, &rss);
			if (priv > priv_max) {
				priv_max = priv;
				priv_rss = rss;
			}
			next = now_ns() + (uint64_t)every * 1000000u;
		}
		if (poll(&p, ntf >= 0 ? 1 : 0, 1) == 1) {
			char msg[512];
			ssize_t n = recv(ntf, msg, sizeof(msg) - 1, MSG_DONTWAIT);

			if (n > 0) {
				msg[n] = '\0';
				if (!ready && strstr(msg, "READY=1")) {
					ready = now_ns() - t0;
					kill(pid, SIGTERM);
				}
			}
		}
		w = wait4(pid, &st, WNOHANG, &ru);
		if (w < 0 && errno != EINTR)
			return perror("wait4"), 1;
		done = w == pid;
	}
	t1 = now_ns();
	printf("wall_ns=%llu rss_kib=%ld priv_kib=%ld priv_rss_kib=%ld status=%d",
	       (unsigned long long)(t1 - t0), ru.ru_maxrss, priv_max, priv_rss,
	       WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st));
	if (want_ready)
		printf(" ready_ns=%llu", (unsigned long long)ready);
	printf("\n");
	return 0;
}
