/*
 * pool: a persistent pool of worker threads that runs batches of jobs, for
 * the renderer's strips (engine/render/r_main.h struct r_par; the engine has no
 * threads of its own).
 *
 * A pool of t threads is the caller plus t - 1 workers started once. A
 * batch (pool_run) hands out job indices 0..n-1 one at a time to whoever
 * asks first, the caller included, and returns when all have returned.
 * Between batches a worker spins briefly (the next frame's batch usually
 * comes within a fraction of a millisecond), then sleeps on a condition
 * variable. One thread at a time may call pool_run on a pool.
 */
#ifndef ARCADED_APP_POOL_H
#define ARCADED_APP_POOL_H

#include <stdint.h>

struct pool;
struct px_par;
struct r_par;

/* Largest pool. */
#define POOL_MAX_THREADS 64

/* Online CPUs (at least 1, at most POOL_MAX_THREADS): what "auto" means. */
int pool_cpus(void);

/* New pool of threads (1..POOL_MAX_THREADS) threads, the caller counted:
 * starts threads - 1 workers. 0, -EINVAL or -errno of the thread start
 * (nothing left running). Owned by the caller: pool_free. */
int pool_new(int threads, struct pool **out);

/* Stops and joins the workers. NULL-safe. Not during a pool_run. */
void pool_free(struct pool *p);

/* Threads of the pool, the caller counted. */
int pool_threads(const struct pool *p);

/* Gives each of the pool's threads a CPU of its own: the caller the first
 * of the CPUs it may run on, worker i the (i + 2)-th. Why: a worker that
 * slept between frames must be running again when the next frame's first
 * batch comes, and a scheduler that packs idle threads onto one CPU (seen
 * on a VM: the worker then waited behind the caller's whole job, 1.5 ms
 * at the median after 10 ms asleep) or moves them about delays it; pinned,
 * it wakes where it is (about 0.1 ms there). Threads the caller starts
 * afterwards inherit its one CPU. 0; -ERANGE when the caller may run on
 * fewer CPUs than the pool has threads, or -errno: nothing pinned then. */
int pool_pin(struct pool *p);

/* A batch comes soon: workers asleep wake now and poll for it for up to
 * 2 ms before sleeping again, so their wake-up (0.1 ms on a VM even when
 * pinned) overlaps the caller's serial work instead of the batch. Cheap
 * when none sleeps. p is a struct pool * (void * for struct r_par). Same
 * thread rule as pool_run. */
void pool_warm(void *p);

/* How many times a worker's sleep was ended by pool_warm (diagnostics and
 * tests). */
unsigned pool_warmed(const struct pool *p);

/* Calls job(arg, i) exactly once for each i in 0..n-1 (n >= 0) on the
 * pool's threads and the calling one, and returns when every call has
 * returned; their writes are then visible to the caller. Blocks. p is a
 * struct pool * (void * to fit struct r_par). */
void pool_run(void *p, int n, void (*job)(void *arg, int i), void *arg);

/* Largest job index pool_wait_job can wait for, plus one. */
#define POOL_WAIT_JOBS 1024

/* From inside a job of the running batch: returns once job i of that
 * batch has returned, its writes then visible. i must be lower than the
 * calling job's own index and below POOL_WAIT_JOBS. Jobs are handed out
 * in index order, so job i was claimed before the caller's and is running
 * or done; since every wait points to a lower index, waits never close a
 * loop. Spins (yielding the CPU now and then). p is a struct pool *. */
void pool_wait_job(void *p, int i);

/* One job on a thread of its own, for work that overlaps the caller's
 * (the content loader's light maps, app/ct.c). pool_task_start runs
 * fn(arg) on a new thread: 0 with *out, or -errno when no thread could be
 * started (the caller then does the work itself). pool_task_join waits
 * for fn to return (its writes are then visible) and frees the task;
 * NULL-safe. */
struct pool_task;
int pool_task_start(void (*fn)(void *arg), void *arg, struct pool_task **out);
void pool_task_join(struct pool_task *t);

/* CLOCK_MONOTONIC in ns (the renderer measures its strips with it). */
uint64_t pool_now(void);

/* The renderer's view of the pool: out->run = pool_run, out->pool = p,
 * out->threads = pool_threads(p), out->now = pool_now, out->warm =
 * pool_warm, out->wait = pool_wait_job, out->wait_jobs = POOL_WAIT_JOBS. */
void pool_r_par(struct pool *p, struct r_par *out);

/* The same for the display's present (display/px.h). */
void pool_px_par(struct pool *p, struct px_par *out);

#endif
