/*
 * Power-cut test driver for config/st.c (built by tests/powercut/run.sh).
 *
 *   stsave kill DIR RUNS SEED MAXUS
 *     RUNS times: fork a saver that loads DIR/state and then saves it
 *     again and again with the next sequence number, reporting each
 *     completed save through a pipe; after a random delay of 0..MAXUS
 *     microseconds (xorshift32 seeded with SEED) SIGKILL it; then load
 *     DIR/state and check that it holds a whole payload whose sequence
 *     is the last one reported complete ("old") or the one after ("new",
 *     finished but not yet reported), never older, never torn. Prints the
 *     counts; exit 1 on any violation.
 *   stsave kill-plain DIR RUNS SEED MAXUS
 *     The same with st_write_plain (the bindings file the input wizard
 *     saves: one plain copy, no header, no .prev): the file must hold the
 *     last save known complete or the one after, whole.
 *   stsave fill DIR
 *     Saves ever larger payloads until the file system is full: the
 *     failing save must return -ENOSPC (or -EFBIG/-EDQUOT) and the last
 *     successful one must still load.
 *
 * A payload of sequence s is 8 bytes of s (little-endian) then a length
 * that varies with s, filled with bytes derived from s, so a payload of
 * one save cannot pass for another's.
 */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "config/st.h"

#define SS_NAME "state"

/* kill-plain: st_write_plain and plain reads instead of st_save/st_load.
 * Set once by main before any fork. */
static int ss_plain;
static const char *ss_name = SS_NAME;
#define SS_MAX_PAYLOAD (64 * 1024)

static size_t ss_len(uint64_t seq)
{
	return 8 + (size_t)((seq * 2654435761u) % (SS_MAX_PAYLOAD - 8));
}

static void ss_fill(uint8_t *p, uint64_t seq, size_t len)
{
	for (int i = 0; i < 8; i++)
		p[i] = (uint8_t)(seq >> (8 * i));
	for (size_t i = 8; i < len; i++)
		p[i] = (uint8_t)(seq * 31 + i * 7);
}

/* 0 with *seq if buf is exactly the payload of some sequence. */
static int ss_parse(const uint8_t *p, size_t len, uint64_t *seq)
{
	static uint8_t want[SS_MAX_PAYLOAD];
	uint64_t s = 0;

	if (len < 8)
		return -1;
	for (int i = 0; i < 8; i++)
		s |= (uint64_t)p[i] << (8 * i);
	if (len != ss_len(s))
		return -1;
	ss_fill(want, s, len);
	if (memcmp(want, p, len) != 0)
		return -1;
	*seq = s;
	return 0;
}

/* Loads the state: 1 with *seq and *which, 0 when there is none yet, -1
 * when it is corrupt or torn (msg says why). */
static int ss_load(const char *dir, uint64_t *seq, enum st_which *which, char *msg, size_t ml)
{
	void *buf;
	size_t len;
	int ret;

	if (ss_plain) {
		static uint8_t pbuf[SS_MAX_PAYLOAD + 1];
		char p[4096];
		ssize_t n;
		int fd;

		snprintf(p, sizeof(p), "%s/%s", dir, ss_name);
		fd = open(p, O_RDONLY | O_CLOEXEC);
		if (fd < 0 && errno == ENOENT)
			return 0;
		if (fd < 0) {
			snprintf(msg, ml, "%.200s: %s", p, strerror(errno));
			return -1;
		}
		n = read(fd, pbuf, sizeof(pbuf));   /* a regular file: one read */
		close(fd);
		*which = ST_MAIN;
		if (n < 0 || ss_parse(pbuf, (size_t)n, seq) != 0) {
			snprintf(msg, ml, "%zd bytes that are not any save's", n);
			return -1;
		}
		return 1;
	}
	ret = st_load(dir, SS_NAME, &buf, &len, which, msg, ml);
	if (ret == -ENOENT)
		return 0;
	if (ret < 0)
		return -1;
	ret = ss_parse(buf, len, seq) == 0 ? 1 : -1;
	if (ret < 0)
		snprintf(msg, ml, "payload of %zu bytes is not any save's", len);
	free(buf);
	return ret;
}

static void ss_saver(const char *dir, int report_fd)
{
	static uint8_t buf[SS_MAX_PAYLOAD];
	enum st_which which;
	char msg[256];
	uint64_t seq = 0;

	if (ss_load(dir, &seq, &which, msg, sizeof(msg)) < 0)
		_exit(3);
	for (;;) {
		size_t len = ss_len(++seq);

		ss_fill(buf, seq, len);
		if ((ss_plain ? st_write_plain(dir, ss_name, buf, len)
			      : st_save(dir, SS_NAME, buf, len)) < 0)
			_exit(4);
		if (write(report_fd, &seq, sizeof(seq)) != (ssize_t)sizeof(seq))
			_exit(5);
	}
}

static int ss_take_tmp(const char *dir)
{
	char p[4096];

	snprintf(p, sizeof(p), "%s/%s.tmp", dir, ss_name);
	/* Removed once counted, so the next kill's count is its own. */
	return unlink(p) == 0;
}

static uint32_t ss_rand(uint32_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 17;
	*s ^= *s << 5;
	return *s;
}

static int ss_kill(const char *dir, long runs, uint32_t seed, long maxus)
{
	long old = 0, fresh = 0, prev = 0, bad = 0, none = 0, mid = 0;
	uint32_t seed0 = seed;
	uint64_t known = 0;
	struct timespec t0, t1;
	char msg[256];

	clock_gettime(CLOCK_MONOTONIC, &t0);
	if (!seed)
		seed = 1;
	for (long run = 0; run < runs; run++) {
		long us = (long)(ss_rand(&seed) % (uint32_t)(maxus + 1));
		struct timespec d = { .tv_sec = us / 1000000, .tv_nsec = us % 1000000 * 1000 };
		enum st_which which = ST_MAIN;
		uint64_t seq = 0, r;
		int fds[2], status, got;
		pid_t pid;

		if (pipe2(fds, O_CLOEXEC) < 0)
			return 2;
		pid = fork();
		if (pid < 0)
			return 2;
		if (pid == 0) {
			close(fds[0]);
			ss_saver(dir, fds[1]);
		}
		close(fds[1]);
		nanosleep(&d, NULL);
		kill(pid, SIGKILL);
		while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
			;
		while (read(fds[0], &r, sizeof(r)) == (ssize_t)sizeof(r)) {
			known = r;
		}
		close(fds[0]);
		if (!(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)) {
			printf("run %ld: the saver exited with status %d before the kill\n", run,
			       WIFEXITED(status) ? WEXITSTATUS(status) : -1);
			bad++;
			continue;
		}
		/* A .tmp left behind: the kill landed inside st_save. */
		mid += ss_take_tmp(dir);
		got = ss_load(dir, &seq, &which, msg, sizeof(msg));
		if (got == 0 && known == 0) {
			none++;               /* killed before the very first save */
			continue;
		}
		if (got <= 0 || seq < known || seq > known + 1) {
			printf("run %ld (killed after %ld us): last complete save %" PRIu64
			       ", loaded %s seq %" PRIu64 " %s\n",
			       run, us, known, got < 0 ? "corrupt" : got == 0 ? "nothing" : "",
			       seq, msg);
			bad++;
			continue;
		}
		if (which == ST_PREV)
			prev++;
		if (seq == known)
			old++;
		else
			fresh++;
		known = seq;
	}
	clock_gettime(CLOCK_MONOTONIC, &t1);
	printf("powercut%s: %ld kills in %.1f s (delays 0..%ld us, seed %u), %ld of them inside "
	       "a save (.tmp left): loaded %ld old, %ld new (%ld of them from .prev), %ld "
	       "before the first save, %ld torn or lost; %" PRIu64 " saves in all\n",
	       ss_plain ? " (plain file, st_write_plain)" : "", runs, (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) / 1e9,
	       maxus, (unsigned)seed0, mid, old, fresh, prev, none, bad, known);
	return bad ? 1 : 0;
}

static int ss_full(const char *dir)
{
	static uint8_t buf[SS_MAX_PAYLOAD];
	enum st_which which;
	char msg[256];
	uint64_t last = 0, seq, s;
	int ret = 0;

	/* Each save needs room for two copies (the new .tmp while the current
	 * file and .prev exist): growing payloads fill the disk. */
	for (s = 1; s < 100000; s++) {
		size_t len = ss_len(s);

		ss_fill(buf, s, len);
		ret = st_save(dir, SS_NAME, buf, len);
		if (ret < 0)
			break;
		last = s;
	}
	if (ret != -ENOSPC && ret != -EFBIG && ret != -EDQUOT) {
		printf("fill: save %" PRIu64 " returned %d (%s), expected -ENOSPC\n", s, ret,
		       strerror(-ret));
		return 1;
	}
	if (ss_load(dir, &seq, &which, msg, sizeof(msg)) != 1 || seq != last ||
	    which != ST_MAIN) {
		printf("fill: after the failed save %" PRIu64 " the state is not save %" PRIu64
		       " (%s)\n", s, last, msg);
		return 1;
	}
	if (access("state.tmp", F_OK) == 0) {
		printf("fill: state.tmp left behind\n");
		return 1;
	}
	printf("fill: save %" PRIu64 " failed with %s; save %" PRIu64 " still loads\n", s,
	       strerror(-ret), last);
	return 0;
}

int main(int argc, char **argv)
{
	if (argc == 6 && strcmp(argv[1], "kill") == 0)
		return ss_kill(argv[2], strtol(argv[3], NULL, 10),
			       (uint32_t)strtoul(argv[4], NULL, 10), strtol(argv[5], NULL, 10));
	if (argc == 6 && strcmp(argv[1], "kill-plain") == 0) {
		ss_plain = 1;
		ss_name = "bindings.ini";
		return ss_kill(argv[2], strtol(argv[3], NULL, 10),
			       (uint32_t)strtoul(argv[4], NULL, 10), strtol(argv[5], NULL, 10));
	}
	if (argc == 3 && strcmp(argv[1], "fill") == 0) {
		if (chdir(argv[2]) < 0)
			return 2;
		return ss_full(".");
	}
	fprintf(stderr, "usage: stsave kill|kill-plain DIR RUNS SEED MAXUS | stsave fill DIR\n");
	return 2;
}
