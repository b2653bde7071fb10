/* Tests for engine/core/lim.c: counting steps against a limit, polling the
 * stop hook every LIM_POLL steps, sticky errors. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <errno.h>
#include <cmocka.h>

#include "engine/core/lim.h"

/* A stop hook that counts its calls and says stop from call `at` on. */
struct probe {
	int calls, at;
};

static int probe_fn(void *ctx)
{
	struct probe *p = ctx;

	return ++p->calls >= p->at;
}

static void steps_within_the_limit_pass_and_one_more_fails(void **state)
{
	struct lim l;
	(void)state;
	lim_init(&l, NULL, 10);
	assert_int_equal(lim_take(&l, 4), 0);
	assert_int_equal(lim_take(&l, 6), 0);      /* exactly max: still within */
	assert_int_equal(l.used, 10);
	assert_int_equal(lim_take(&l, 1), -E2BIG);
	/* sticky: nothing more is counted, the same error comes back */
	assert_int_equal(lim_take(&l, 0), -E2BIG);
	assert_int_equal(l.used, 11);
}

static void a_huge_count_saturates_instead_of_wrapping(void **state)
{
	struct lim l;
	(void)state;
	lim_init(&l, NULL, UINT64_MAX - 1);
	assert_int_equal(lim_take(&l, UINT64_MAX - 5), 0);
	assert_int_equal(lim_take(&l, 100), -E2BIG);
	assert_true(l.used == UINT64_MAX);
}

static void the_hook_is_polled_once_every_lim_poll_steps(void **state)
{
	struct probe p = { 0, 1000 };
	struct lim_stop s = { probe_fn, &p, NULL };
	struct lim l;
	(void)state;
	lim_init(&l, &s, UINT64_MAX);
	for (uint32_t i = 0; i < 10 * LIM_POLL; i++)
		assert_int_equal(lim_take(&l, 1), 0);
	assert_int_equal(p.calls, 10);
	/* a big step polls once, not once per LIM_POLL it spans */
	assert_int_equal(lim_take(&l, 5 * LIM_POLL), 0);
	assert_int_equal(p.calls, 11);
}

static void a_stop_ends_the_count_within_lim_poll_steps(void **state)
{
	struct probe p = { 0, 3 };                 /* says stop at its third call */
	struct lim_stop s = { probe_fn, &p, NULL };
	struct lim l;
	uint64_t steps = 0;
	int r = 0;
	(void)state;
	lim_init(&l, &s, UINT64_MAX);
	while (r == 0 && steps < 100 * LIM_POLL) {
		r = lim_take(&l, 1);
		steps++;
	}
	assert_int_equal(r, -ECANCELED);
	assert_true(steps == 3 * LIM_POLL);
	assert_int_equal(lim_take(&l, 1), -ECANCELED);
	assert_int_equal(lim_check(&l), -ECANCELED);
	assert_int_equal(p.calls, 3);              /* sticky: not asked again */
}

static void check_asks_the_hook_now(void **state)
{
	struct probe p = { 0, 2 };
	struct lim_stop s = { probe_fn, &p, NULL };
	struct lim_stop none = { NULL, NULL, NULL };
	struct lim l;
	(void)state;
	lim_init(&l, &s, 5);
	assert_int_equal(lim_check(&l), 0);
	assert_int_equal(lim_check(&l), -ECANCELED);
	lim_init(&l, &none, 5);                    /* a hook without fn never stops */
	assert_int_equal(lim_check(&l), 0);
	lim_init(&l, NULL, 5);
	assert_int_equal(lim_check(&l), 0);
}

static void the_hooks_counter_sums_every_count(void **state)
{
	uint64_t steps = 0;
	struct lim_stop s = { NULL, NULL, &steps };
	struct lim a, b;
	(void)state;
	lim_init(&a, &s, 100);
	lim_init(&b, &s, 100);
	assert_int_equal(lim_take(&a, 30), 0);
	assert_int_equal(lim_take(&b, 50), 0);
	assert_int_equal(lim_take(&a, 71), -E2BIG);
	assert_true(steps == 151);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(steps_within_the_limit_pass_and_one_more_fails),
		cmocka_unit_test(a_huge_count_saturates_instead_of_wrapping),
		cmocka_unit_test(the_hook_is_polled_once_every_lim_poll_steps),
		cmocka_unit_test(a_stop_ends_the_count_within_lim_poll_steps),
		cmocka_unit_test(check_asks_the_hook_now),
		cmocka_unit_test(the_hooks_counter_sums_every_count),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
