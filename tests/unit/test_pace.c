/* Tests for app/pace.c: when ticks are due, the wait that serves a file
 * descriptor (a display's page-flip events) until the tick is due, and the
 * restart of a clock that fell far behind. Times are only ever checked as
 * lower bounds or counts, never as speeds. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <fcntl.h>
#include <unistd.h>

#include "app/pace.h"
#include "input/in.h"

static void ticks_are_due_sixty_a_second(void **state)
{
	struct pace p;
	(void)state;

	pace_start(&p, 1000);
	assert_int_equal(pace_due(&p, 0), 1000);
	assert_int_equal(pace_due(&p, 1), 1000 + 16666666);
	assert_int_equal(pace_due(&p, 60), 1000 + 1000000000);
	/* never drifts: tick 3600 is exactly a minute on */
	assert_int_equal(pace_due(&p, 3600), 1000 + 60000000000ull);
}

struct reader {
	int fd, calls, bytes;
	char got[8];
};

static void ready(void *ctx)
{
	struct reader *r = ctx;

	r->calls++;
	if (r->bytes < 8 && read(r->fd, r->got + r->bytes, 1) == 1)
		r->bytes++;
}

static void readable_fd_is_served_and_the_wait_still_lasts(void **state)
{
	int pfd[2];
	struct reader r = { .calls = 0 };
	struct pace p;
	struct pace_fd w;
	uint64_t t0;
	(void)state;

	assert_int_equal(pipe2(pfd, O_CLOEXEC | O_NONBLOCK), 0);
	r.fd = pfd[0];
	w.fd = pfd[0];
	w.ready = ready;
	w.ctx = &r;
	assert_int_equal(write(pfd[1], "ab", 2), 2);
	t0 = in_now_ns();
	pace_start(&p, t0);
	/* tick 2 is due 33 ms on: both bytes are taken meanwhile */
	assert_int_equal(pace_wait(&p, 2, &w), 0);
	assert_true(in_now_ns() >= pace_due(&p, 2));
	assert_int_equal(r.bytes, 2);
	assert_int_equal(r.calls, 2);
	assert_memory_equal(r.got, "ab", 2);
	/* nothing to read: the wait is a plain sleep */
	assert_int_equal(pace_wait(&p, 3, &w), 0);
	assert_true(in_now_ns() >= pace_due(&p, 3));
	assert_int_equal(r.calls, 2);
	close(pfd[0]);
	close(pfd[1]);
}

static void hung_up_fd_is_left_alone(void **state)
{
	int pfd[2];
	struct reader r = { .calls = 0 };
	struct pace p;
	struct pace_fd w;
	(void)state;

	assert_int_equal(pipe2(pfd, O_CLOEXEC | O_NONBLOCK), 0);
	close(pfd[1]);   /* POLLHUP for good: must not spin on it */
	r.fd = pfd[0];
	w.fd = pfd[0];
	w.ready = ready;
	w.ctx = &r;
	pace_start(&p, in_now_ns());
	assert_int_equal(pace_wait(&p, 1, &w), 0);
	assert_true(in_now_ns() >= pace_due(&p, 1));
	assert_int_equal(r.calls, 0);   /* not called once, let alone in a loop */
	close(pfd[0]);
}

static void far_behind_restarts_the_clock_and_counts_the_drop(void **state)
{
	struct pace p;
	uint64_t now = in_now_ns();
	(void)state;

	/* tick 0 was due a second ago: 60 ticks behind, more than 250 ms */
	pace_start(&p, now - 1000000000ull);
	assert_true(pace_wait(&p, 0, NULL) >= 59);
	assert_true(pace_due(&p, 0) >= now);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(ticks_are_due_sixty_a_second),
		cmocka_unit_test(readable_fd_is_served_and_the_wait_still_lasts),
		cmocka_unit_test(hung_up_fd_is_left_alone),
		cmocka_unit_test(far_behind_restarts_the_clock_and_counts_the_drop),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
