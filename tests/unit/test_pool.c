/*
 * Tests for app/pool.c: every job of a batch runs exactly once, batches
 * follow each other without mixing, jobs do run at the same time on
 * several threads, pool_warm wakes a sleeping worker without losing or
 * repeating a job, pool_pin gives each thread a CPU of its own,
 * pool_wait_job returns only once the job waited for has returned, and the
 * edge cases (no jobs, one thread, bad sizes, more threads than CPUs).
 */
#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <cmocka.h>

#include "app/pool.h"
#include "engine/render/r_main.h"

enum { MAXJ = 300 };

struct batch {
	atomic_int runs[MAXJ];
	int tag;                        /* which batch wrote it */
	int seen_tag[MAXJ];
};

static void count_job(void *arg, int i)
{
	struct batch *b = arg;

	atomic_fetch_add(&b->runs[i], 1);
	b->seen_tag[i] = b->tag;
}

static void new_rejects_bad_sizes_and_free_takes_null(void **state)
{
	struct pool *p = (struct pool *)1;
	(void)state;

	assert_int_equal(pool_new(0, &p), -EINVAL);
	assert_null(p);
	assert_int_equal(pool_new(POOL_MAX_THREADS + 1, &p), -EINVAL);
	pool_free(NULL);
	assert_true(pool_cpus() >= 1 && pool_cpus() <= POOL_MAX_THREADS);
}

/* 2000 batches of 0..299 jobs on pools of 1, 2 and 4 threads: each index
 * once per batch, none beyond n, and each job saw its own batch's tag.
 * Consecutive batches grow and shrink, so a worker late from one batch
 * meets the next (the case that once ran a job twice). */
static void every_job_runs_exactly_once_per_batch(void **state)
{
	static const int sizes[] = { 1, 2, 4 };
	static struct batch b;
	(void)state;

	for (size_t z = 0; z < 3; z++) {
		struct pool *p;

		assert_int_equal(pool_new(sizes[z], &p), 0);
		assert_int_equal(pool_threads(p), sizes[z]);
		for (int k = 0; k < 2000; k++) {
			int n = (k * 37) % MAXJ;

			for (int i = 0; i < MAXJ; i++) {
				atomic_store(&b.runs[i], 0);
				b.seen_tag[i] = -1;
			}
			b.tag = k;
			pool_run(p, n, count_job, &b);
			for (int i = 0; i < MAXJ; i++) {
				if (atomic_load(&b.runs[i]) != (i < n ? 1 : 0))
					fail_msg("pool %d batch %d (n %d): job %d ran %d times",
						 sizes[z], k, n, i, atomic_load(&b.runs[i]));
				if (i < n && b.seen_tag[i] != k)
					fail_msg("job %d of batch %d saw batch %d", i, k,
						 b.seen_tag[i]);
			}
		}
		pool_free(p);
	}
}

enum { BIG = 70000 };

static atomic_int big_runs[BIG];

static void big_job(void *arg, int i)
{
	(void)arg;
	atomic_fetch_add(&big_runs[i], 1);
}

/* More jobs than one ticket holds (65,535): still each exactly once. */
static void a_batch_of_70000_jobs_runs_each_once(void **state)
{
	struct pool *p;
	(void)state;

	assert_int_equal(pool_new(2, &p), 0);
	pool_run(p, BIG, big_job, NULL);
	for (int i = 0; i < BIG; i++)
		if (atomic_load(&big_runs[i]) != 1)
			fail_msg("job %d ran %d times", i, atomic_load(&big_runs[i]));
	pool_free(p);
}

struct meet {
	atomic_int in[2];
	int met[2];
};

/* Job i announces itself and waits (at most 5 s) for the other: both can
 * only meet if they run at the same time. */
static void meet_job(void *arg, int i)
{
	struct meet *m = arg;
	struct timespec t0, t;

	atomic_store(&m->in[i], 1);
	clock_gettime(CLOCK_MONOTONIC, &t0);
	do {
		if (atomic_load(&m->in[1 - i])) {
			m->met[i] = 1;
			return;
		}
		clock_gettime(CLOCK_MONOTONIC, &t);
	} while (t.tv_sec - t0.tv_sec < 5);
}

static void two_threads_run_two_jobs_at_once(void **state)
{
	struct pool *p;
	(void)state;

	assert_int_equal(pool_new(2, &p), 0);
	/* several times, after sleeps long enough for the worker to go from
	 * spinning to waiting on the condition variable */
	for (int k = 0; k < 5; k++) {
		struct meet m;
		struct timespec nap = { 0, 20 * 1000 * 1000 };

		memset(&m, 0, sizeof(m));
		nanosleep(&nap, NULL);
		pool_run(p, 2, meet_job, &m);
		assert_true(m.met[0] && m.met[1]);
	}
	pool_free(p);
}

/* pool_warm ends a sleeping worker's sleep: after 20 ms without a batch
 * the worker sleeps, and only the warm's wake-up can count it. */
static void warm_wakes_a_sleeping_worker(void **state)
{
	struct timespec nap = { 0, 20 * 1000 * 1000 };
	struct pool *p;
	(void)state;

	assert_int_equal(pool_new(2, &p), 0);
	nanosleep(&nap, NULL);
	assert_int_equal(pool_warmed(p), 0);
	pool_warm(p);
	for (int i = 0; i < 5000 && pool_warmed(p) == 0; i++) {
		struct timespec ms = { 0, 1000 * 1000 };

		nanosleep(&ms, NULL);
	}
	assert_int_equal(pool_warmed(p), 1);
	pool_free(p);
}

/* Warms before batches, between them, twice in a row and right before the
 * end, with sleeps that leave the worker polling, asleep or in its warm
 * poll: every job still runs exactly once and nothing hangs. */
static void warm_and_batches_interleave(void **state)
{
	static struct batch b;
	const long naps[] = { 0, 50 * 1000, 3 * 1000 * 1000 };
	struct pool *p;
	(void)state;

	for (int th = 2; th <= 4; th += 2) {
		assert_int_equal(pool_new(th, &p), 0);
		for (int k = 0; k < 300; k++) {
			struct timespec nap = { 0, naps[k % 3] };
			int n = 1 + (k * 7) % 50;

			if (k % 4 != 3)
				pool_warm(p);
			if (k % 5 == 0)
				pool_warm(p);
			nanosleep(&nap, NULL);
			memset(&b, 0, sizeof(b));
			b.tag = k;
			pool_run(p, n, count_job, &b);
			for (int i = 0; i < MAXJ; i++) {
				assert_int_equal(atomic_load(&b.runs[i]), i < n ? 1 : 0);
				if (i < n)
					assert_int_equal(b.seen_tag[i], k);
			}
		}
		pool_warm(p);
		pool_free(p);
	}
}

/* meet_job that also notes the CPUs its thread may run on. */
struct pinned {
	struct meet m;
	cpu_set_t on[2];
};

static void pinned_job(void *arg, int i)
{
	struct pinned *pn = arg;

	pthread_getaffinity_np(pthread_self(), sizeof(pn->on[i]), &pn->on[i]);
	meet_job(&pn->m, i);
}

static void pin_gives_each_thread_a_cpu_of_its_own(void **state)
{
	cpu_set_t before, now;
	struct pinned pn;
	struct pool *p;
	int first = -1;
	(void)state;

	assert_int_equal(pthread_getaffinity_np(pthread_self(), sizeof(before), &before), 0);
	if (CPU_COUNT(&before) < 2)
		skip();         /* one CPU: nothing to spread over */
	for (int c = CPU_SETSIZE - 1; c >= 0; c--)
		if (CPU_ISSET(c, &before))
			first = c;
	assert_int_equal(pool_new(2, &p), 0);
	assert_int_equal(pool_pin(p), 0);
	memset(&pn, 0, sizeof(pn));
	/* the two jobs meet: one ran on the worker, one on the caller */
	pool_run(p, 2, pinned_job, &pn);
	assert_true(pn.m.met[0] && pn.m.met[1]);
	assert_int_equal(CPU_COUNT(&pn.on[0]), 1);
	assert_int_equal(CPU_COUNT(&pn.on[1]), 1);
	assert_false(CPU_EQUAL(&pn.on[0], &pn.on[1]));
	/* the caller keeps the first of its CPUs */
	assert_int_equal(pthread_getaffinity_np(pthread_self(), sizeof(now), &now), 0);
	assert_int_equal(CPU_COUNT(&now), 1);
	assert_true(CPU_ISSET(first, &now));
	pool_free(p);
	assert_int_equal(pthread_setaffinity_np(pthread_self(), sizeof(before), &before), 0);
}

static void pin_refuses_more_threads_than_cpus(void **state)
{
	cpu_set_t before, now;
	struct pool *p;
	(void)state;

	assert_int_equal(pthread_getaffinity_np(pthread_self(), sizeof(before), &before), 0);
	assert_int_equal(pool_new(CPU_COUNT(&before) + 1, &p), 0);
	assert_int_equal(pool_pin(p), -ERANGE);
	assert_int_equal(pthread_getaffinity_np(pthread_self(), sizeof(now), &now), 0);
	assert_true(CPU_EQUAL(&before, &now));
	pool_free(p);
}

/* pool_task: the job runs on its own thread, at the same time as the
 * caller: each side waits (at most 2 s) for the other's flag, which a job
 * run in line, before or at the join, could not see. */
struct handshake {
	atomic_int caller, task, task_saw_caller;
};

static int wait_flag(atomic_int *f)
{
	for (int i = 0; i < 2000; i++) {
		struct timespec nap = { 0, 1000 * 1000 };

		if (atomic_load(f))
			return 1;
		nanosleep(&nap, NULL);
	}
	return 0;
}

static void handshake_job(void *arg)
{
	struct handshake *h = arg;

	atomic_store(&h->task, 1);
	atomic_store(&h->task_saw_caller, wait_flag(&h->caller));
}

static void a_task_runs_beside_the_caller(void **state)
{
	struct handshake h;
	struct pool_task *t;
	(void)state;

	atomic_init(&h.caller, 0);
	atomic_init(&h.task, 0);
	atomic_init(&h.task_saw_caller, 0);
	assert_int_equal(pool_task_start(handshake_job, &h, &t), 0);
	assert_non_null(t);
	assert_true(wait_flag(&h.task));
	atomic_store(&h.caller, 1);
	pool_task_join(t);
	assert_int_equal(atomic_load(&h.task_saw_caller), 1);
	pool_task_join(NULL);
}

/* Jobs that wait: even job i writes tag into val[i] after a few
 * microseconds of work; odd job i waits for job i - 1 and for job 0, then
 * reads both values, which must be this batch's tag (plain ints: only the
 * wait makes the writes visible). */
struct waits {
	struct pool *pool;
	int tag;
	int val[MAXJ];
	atomic_int bad, runs;
};

static void wait_job(void *arg, int i)
{
	struct waits *w = arg;

	atomic_fetch_add(&w->runs, 1);
	if (i % 2 == 0) {
		uint64_t t0 = pool_now();

		while (pool_now() - t0 < 20000)
			;
		w->val[i] = w->tag;
		return;
	}
	pool_wait_job(w->pool, i - 1);
	pool_wait_job(w->pool, 0);
	if (w->val[i - 1] != w->tag || w->val[0] != w->tag)
		atomic_fetch_add(&w->bad, 1);
}

/* A batch longer than a ticket holds (run in chunks): job 7 writes after a
 * few microseconds, and the last job, in the last chunk, waits for it. */
static void far_wait_job(void *arg, int i)
{
	struct waits *w = arg;

	atomic_fetch_add(&w->runs, 1);
	if (i == 7) {
		uint64_t t0 = pool_now();

		while (pool_now() - t0 < 20000)
			;
		w->val[7] = w->tag;
	} else if (i == 69999) {
		pool_wait_job(w->pool, 7);
		if (w->val[7] != w->tag)
			atomic_fetch_add(&w->bad, 1);
	}
}

/* 200 batches of 2..100 such jobs on pools of 1, 2 and 4 threads: no odd
 * job ever read a value before its even job wrote it, and every job ran
 * once. Then a batch of 70,000 where a job of its last chunk waits for one
 * of its first (a stamp per chunk would never match: it would hang). */
static void a_job_waits_for_the_lower_job_it_names(void **state)
{
	static const int sizes[] = { 1, 2, 4 };
	static struct waits w;
	(void)state;

	for (size_t z = 0; z < sizeof(sizes) / sizeof(sizes[0]); z++) {
		struct pool *p;

		assert_int_equal(pool_new(sizes[z], &p), 0);
		w.pool = p;
		for (int k = 0; k < 200; k++) {
			int n = 2 + (k * 37) % 99;

			w.tag = k * 7 + 1 + (int)z * 10000;
			atomic_store(&w.runs, 0);
			pool_run(p, n, wait_job, &w);
			assert_int_equal(atomic_load(&w.runs), n);
		}
		w.tag = 424242 + (int)z;
		atomic_store(&w.runs, 0);
		/* a wait that never ends kills the binary (counted failed)
		 * instead of hanging the suite */
		alarm(60);
		pool_run(p, 70000, far_wait_job, &w);
		alarm(0);
		assert_int_equal(atomic_load(&w.runs), 70000);
		assert_int_equal(atomic_load(&w.bad), 0);
		pool_free(p);
	}
}

static void nothing_to_do_returns_at_once(void **state)
{
	struct pool *p;
	static struct batch b;
	(void)state;

	assert_int_equal(pool_new(2, &p), 0);
	pool_run(p, 0, count_job, &b);
	assert_int_equal(atomic_load(&b.runs[0]), 0);
	pool_free(p);
}

static void r_par_points_at_the_pool(void **state)
{
	struct pool *p;
	struct r_par par;
	static struct batch b;
	(void)state;

	assert_int_equal(pool_new(2, &p), 0);
	pool_r_par(p, &par);
	assert_ptr_equal(par.pool, p);
	assert_ptr_equal(par.warm, pool_warm);
	assert_ptr_equal(par.wait, pool_wait_job);
	assert_int_equal(par.wait_jobs, POOL_WAIT_JOBS);
	par.run(par.pool, 3, count_job, &b);
	assert_int_equal(atomic_load(&b.runs[0]) + atomic_load(&b.runs[1]) +
			 atomic_load(&b.runs[2]), 3);
	pool_free(p);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(new_rejects_bad_sizes_and_free_takes_null),
		cmocka_unit_test(every_job_runs_exactly_once_per_batch),
		cmocka_unit_test(a_batch_of_70000_jobs_runs_each_once),
		cmocka_unit_test(two_threads_run_two_jobs_at_once),
		cmocka_unit_test(warm_wakes_a_sleeping_worker),
		cmocka_unit_test(warm_and_batches_interleave),
		cmocka_unit_test(pin_gives_each_thread_a_cpu_of_its_own),
		cmocka_unit_test(pin_refuses_more_threads_than_cpus),
		cmocka_unit_test(a_job_waits_for_the_lower_job_it_names),
		cmocka_unit_test(a_task_runs_beside_the_caller),
		cmocka_unit_test(nothing_to_do_returns_at_once),
		cmocka_unit_test(r_par_points_at_the_pool),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
