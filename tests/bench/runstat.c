/*
 * runstat: runs a command and prints its wall time and peak RSS, for timing
 * the peer engines in `make bench` (tests/bench.sh).
 *
 *   runstat OUT command [args...]
 *
 * The command's stdout and stderr go to the file OUT, its stdin is
 * /dev/null. Prints "wall_ns=N rss_kib=K status=S" (S: exit status, or
 * 128 + signal) and exits 0, or 1 when the command could not be started.
 */
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static uint64_t now_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

int main(int argc, char **argv)
{
	struct rusage ru;
	uint64_t t0, t1;
	int st, out;
	pid_t pid;

	if (argc < 3)
		return fprintf(stderr, "usage: runstat OUT command [args...]\n"), 2;
	out = open(argv[1], O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (out < 0)
		return perror(argv[1]), 1;
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
	if (wait4(pid, &st, 0, &ru) < 0)
		return perror("wait4"), 1;
	t1 = now_ns();
	printf("wall_ns=%llu rss_kib=%ld status=%d\n", (unsigned long long)(t1 - t0), ru.ru_maxrss,
	       WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st));
	return 0;
}
