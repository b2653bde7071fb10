/*
 * pool: worker threads for batches of jobs (contracts in pool.h).
 *
 * One 64-bit ticket says which batch is current (bits 63..32: its
 * generation), how many jobs it has (31..16) and which index is handed out
 * next (15..0). A thread claims index i of generation g by compare-and-swap
 * from (g, n, i) to (g, n, i + 1) when i < n, all read from that one word:
 * a thread that wakes late, after its batch ended, can never claim a job of
 * the next batch, since its swap fails on the generation, and it can never
 * see the next batch's count beside its own generation. (Keeping the count
 * apart from the ticket let a late thread pair its old generation with the
 * next batch's larger count and claim an index twice: test_pool caught it.)
 * The batch's function, argument and first index are read only after a
 * claim succeeded, and the caller cannot publish the next batch before
 * every claimed job has returned (left reaches 0), so they are the claim's.
 * Batches of more than POOL_CHUNK jobs are run as several.
 *
 * Waiting for a job (pool_wait_job): when job i of pool_run's batch b
 * returns, fin[i] becomes b (a release store, before left counts it), and
 * a waiter spins until it reads b (acquire): the job's writes are then
 * visible. The stamp is the batch's, not a chunk's generation, so a job of
 * a later chunk can wait for one of the first. Stale stamps are older
 * batches, never equal to the current one.
 *
 * Sleeping: a worker that saw no new generation for POOL_SPIN polls takes
 * the lock, counts itself in sleepers and waits; pool_run stores the new
 * ticket and then wakes the sleepers if there are any. Both are sequentially
 * consistent atomics, so either pool_run sees the sleeper or the sleeper
 * sees the new ticket before it waits: no lost wake-up.
 */
#include "app/pool.h"

#include <assert.h>
#include <errno.h>
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "display/px.h"
#include "engine/render/r_main.h"

/* Polls before sleeping, between batches and while waiting for the last
 * job: a few tens of microseconds. */
#define POOL_SPIN 4000
/* How long a worker woken by pool_warm polls for the batch before it
 * sleeps again: longer than a frame's serial walk. */
#define POOL_WARM_NS 2000000u
/* Most jobs in one ticket (16 bits of count). */
#define POOL_CHUNK 65535

#define POOL_GEN(v) ((uint32_t)((v) >> 32))
#define POOL_N(v) ((uint32_t)((v) >> 16) & 0xffffu)
#define POOL_NEXT(v) ((uint32_t)(v) & 0xffffu)

struct pool {
	pthread_mutex_t mu;
	pthread_cond_t wake, done;
	pthread_t th[POOL_MAX_THREADS];
	int nth;                        /* workers started */
	_Atomic uint64_t ticket;        /* generation << 32 | jobs << 16 | next */
	atomic_int left;                /* jobs of the batch not yet returned */
	atomic_int sleepers;
	atomic_int stop;
	atomic_uint warm;               /* bumped by pool_warm */
	atomic_uint warmed;             /* sleeps a pool_warm ended (pool_warmed) */
	/* the current batch, written by pool_run before the ticket */
	void (*job)(void *arg, int i);
	void *arg;
	int base;                       /* index of the chunk's first job */
	uint32_t gen;                   /* pool_run's side: the last generation */
	uint32_t batch;                 /* pool_run's count of batches, 0 before the first */
	_Atomic uint32_t fin[POOL_WAIT_JOBS]; /* batch each job index last returned in */
};

static inline void pool_relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
	__builtin_ia32_pause();
#elif defined(__aarch64__) || defined(__arm__)
	__asm__ __volatile__("yield");
#endif
}

int pool_cpus(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);

	if (n < 1)
		return 1;
	return n > POOL_MAX_THREADS ? POOL_MAX_THREADS : (int)n;
}

/* Wakes the sleeping workers, after a store to the ticket or warm: that
 * store comes before this look at sleepers (both sequentially
 * consistent), so a worker either is counted here or sees the store
 * before it waits. */
static void pool_wake(struct pool *p)
{
	if (atomic_load(&p->sleepers) > 0) {
		pthread_mutex_lock(&p->mu);
		pthread_cond_broadcast(&p->wake);
		pthread_mutex_unlock(&p->mu);
	}
}

/* Job i of the current batch has returned (pool_wait_job). */
static void pool_stamp(struct pool *p, int i)
{
	if (i < POOL_WAIT_JOBS)
		atomic_store_explicit(&p->fin[i], p->batch, memory_order_release);
}

/* Claims and runs jobs of generation g until none is left. */
static void pool_work(struct pool *p, uint32_t g)
{
	for (;;) {
		uint64_t v = atomic_load(&p->ticket);
		int i;

		if (POOL_GEN(v) != g || POOL_NEXT(v) >= POOL_N(v))
			return;
		if (!atomic_compare_exchange_weak(&p->ticket, &v, v + 1))
			continue;
		i = p->base + (int)POOL_NEXT(v);
		p->job(p->arg, i);
		pool_stamp(p, i);
		if (atomic_fetch_sub(&p->left, 1) == 1) {
			pthread_mutex_lock(&p->mu);
			pthread_cond_signal(&p->done);
			pthread_mutex_unlock(&p->mu);
		}
	}
}

/* After pool_warm woke it: polls for a new generation for POOL_WARM_NS.
 * The generation then current. */
static uint32_t pool_warm_poll(struct pool *p, uint32_t seen)
{
	uint64_t t0 = pool_now();
	uint32_t g;

	while ((g = POOL_GEN(atomic_load(&p->ticket))) == seen && !atomic_load(&p->stop)) {
		for (int k = 0; k < 64; k++)
			pool_relax();
		if (pool_now() - t0 > POOL_WARM_NS)
			break;
	}
	return g;
}

static void *pool_main(void *arg)
{
	struct pool *p = arg;
	/* pool_new set warm to 0 before starting the workers: a pool_warm
	 * before this thread ran still ends its first sleep */
	uint32_t seen = 0, seen_warm = 0;

	/* named for top -H, ps -L and the VM's check of its CPU */
	pthread_setname_np(pthread_self(), "arcaded-pool");
	for (;;) {
		uint32_t g = POOL_GEN(atomic_load(&p->ticket));

		for (int k = 0; g == seen && k < POOL_SPIN && !atomic_load(&p->stop); k++) {
			pool_relax();
			g = POOL_GEN(atomic_load(&p->ticket));
		}
		if (g == seen) {
			uint32_t w = seen_warm;

			pthread_mutex_lock(&p->mu);
			atomic_fetch_add(&p->sleepers, 1);
			while ((g = POOL_GEN(atomic_load(&p->ticket))) == seen &&
			       (w = atomic_load(&p->warm)) == seen_warm && !atomic_load(&p->stop))
				pthread_cond_wait(&p->wake, &p->mu);
			atomic_fetch_sub(&p->sleepers, 1);
			pthread_mutex_unlock(&p->mu);
			if (g == seen && !atomic_load(&p->stop)) {
				/* woken early: poll for the batch a while */
				seen_warm = w;
				atomic_fetch_add(&p->warmed, 1);
				g = pool_warm_poll(p, seen);
				if (g == seen)
					continue;
			}
		}
		/* a warm seen while awake needs no wake-up later */
		seen_warm = atomic_load(&p->warm);
		if (atomic_load(&p->stop))
			return NULL;
		seen = g;
		pool_work(p, g);
	}
}

int pool_new(int threads, struct pool **out)
{
	struct pool *p;
	int rc;

	*out = NULL;
	if (threads < 1 || threads > POOL_MAX_THREADS)
		return -EINVAL;
	p = calloc(1, sizeof(*p));
	if (!p)
		return -ENOMEM;
	pthread_mutex_init(&p->mu, NULL);
	pthread_cond_init(&p->wake, NULL);
	pthread_cond_init(&p->done, NULL);
	atomic_init(&p->ticket, 0);
	atomic_init(&p->left, 0);
	atomic_init(&p->sleepers, 0);
	atomic_init(&p->stop, 0);
	atomic_init(&p->warm, 0);
	atomic_init(&p->warmed, 0);
	for (int i = 0; i < POOL_WAIT_JOBS; i++)
		atomic_init(&p->fin[i], 0);
	for (int i = 0; i < threads - 1; i++) {
		rc = pthread_create(&p->th[i], NULL, pool_main, p);
		if (rc != 0) {
			pool_free(p);
			return -rc;
		}
		p->nth++;
	}
	*out = p;
	return 0;
}

void pool_free(struct pool *p)
{
	if (!p)
		return;
	pthread_mutex_lock(&p->mu);
	atomic_store(&p->stop, 1);
	pthread_cond_broadcast(&p->wake);
	pthread_mutex_unlock(&p->mu);
	for (int i = 0; i < p->nth; i++)
		pthread_join(p->th[i], NULL);
	pthread_cond_destroy(&p->done);
	pthread_cond_destroy(&p->wake);
	pthread_mutex_destroy(&p->mu);
	free(p);
}

int pool_threads(const struct pool *p)
{
	return p->nth + 1;
}

void pool_warm(void *pool)
{
	struct pool *p = pool;

	atomic_fetch_add(&p->warm, 1);
	pool_wake(p);
}

unsigned pool_warmed(const struct pool *p)
{
	return atomic_load(&((struct pool *)p)->warmed);
}

/* One chunk: jobs base..base + n - 1, n <= POOL_CHUNK. */
static void pool_chunk(struct pool *p, int base, int n, void (*job)(void *arg, int i), void *arg)
{
	p->job = job;
	p->arg = arg;
	p->base = base;
	atomic_store(&p->left, n);
	p->gen++;
	atomic_store(&p->ticket, (uint64_t)p->gen << 32 | (uint64_t)n << 16);
	pool_wake(p);
	pool_work(p, p->gen);
	for (int k = 0; k < POOL_SPIN && atomic_load(&p->left) > 0; k++)
		pool_relax();
	if (atomic_load(&p->left) > 0) {
		pthread_mutex_lock(&p->mu);
		while (atomic_load(&p->left) > 0)
			pthread_cond_wait(&p->done, &p->mu);
		pthread_mutex_unlock(&p->mu);
	}
}

void pool_run(void *pool, int n, void (*job)(void *arg, int i), void *arg)
{
	struct pool *p = pool;

	if (n <= 0)
		return;
	p->batch++;
	if (p->nth == 0 || n == 1) {
		for (int i = 0; i < n; i++) {
			job(arg, i);
			pool_stamp(p, i);
		}
		return;
	}
	for (int base = 0; base < n; base += POOL_CHUNK)
		pool_chunk(p, base, n - base < POOL_CHUNK ? n - base : POOL_CHUNK, job, arg);
}

uint64_t pool_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

void pool_wait_job(void *pool, int i)
{
	struct pool *p = pool;
	/* set before the chunk's ticket was published, which this job's
	 * claim read */
	uint32_t b = p->batch;

	assert(i >= 0 && i < POOL_WAIT_JOBS);
	for (unsigned k = 1; atomic_load_explicit(&p->fin[i], memory_order_acquire) != b; k++) {
		pool_relax();
		/* the job's thread may be off its CPU: give it the CPU */
		if ((k & 1023) == 0)
			sched_yield();
	}
}

void pool_r_par(struct pool *p, struct r_par *out)
{
	out->run = pool_run;
	out->pool = p;
	out->threads = pool_threads(p);
	out->now = pool_now;
	out->warm = pool_warm;
	out->wait = pool_wait_job;
	out->wait_jobs = POOL_WAIT_JOBS;
}

void pool_px_par(struct pool *p, struct px_par *out)
{
	out->run = pool_run;
	out->pool = p;
	out->threads = pool_threads(p);
}

struct pool_task {
	pthread_t th;
	void (*fn)(void *arg);
	void *arg;
};

static void *pool_task_main(void *p)
{
	struct pool_task *t = p;

	t->fn(t->arg);
	return NULL;
}

int pool_pin(struct pool *p)
{
	cpu_set_t all, one;
	int cpus[POOL_MAX_THREADS], n = 0, rc;

	if (sched_getaffinity(0, sizeof(all), &all) < 0)
		return -errno;
	for (int c = 0; c < CPU_SETSIZE && n < POOL_MAX_THREADS; c++)
		if (CPU_ISSET(c, &all))
			cpus[n++] = c;
	if (n < p->nth + 1)
		return -ERANGE;
	for (int i = 0; i <= p->nth; i++) {
		/* the caller last: a failure leaves it as it was */
		pthread_t th = i < p->nth ? p->th[i] : pthread_self();

		CPU_ZERO(&one);
		CPU_SET(cpus[i < p->nth ? i + 1 : 0], &one);
		rc = pthread_setaffinity_np(th, sizeof(one), &one);
		if (rc != 0) {
			for (int k = 0; k < i; k++)
				pthread_setaffinity_np(p->th[k], sizeof(all), &all);
			return -rc;
		}
	}
	return 0;
}

int pool_task_start(void (*fn)(void *arg), void *arg, struct pool_task **out)
{
	struct pool_task *t = calloc(1, sizeof(*t));
	int rc;

	*out = NULL;
	if (!t)
		return -ENOMEM;
	t->fn = fn;
	t->arg = arg;
	rc = pthread_create(&t->th, NULL, pool_task_main, t);
	if (rc != 0) {
		free(t);
		return -rc;
	}
	*out = t;
	return 0;
}

void pool_task_join(struct pool_task *t)
{
	if (!t)
		return;
	pthread_join(t->th, NULL);
	free(t);
}
