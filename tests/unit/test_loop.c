/*
 * loop: the main loop runs its steps in the order loop.h and
 * docs/architecture.md document, driven here with hooks that write down
 * their names. The order has reasons a change would break: the command is
 * built from the inputs read in the same tick; the flight recorder's
 * snapshot comes before the sim's tick and the recording after it; the
 * tick's sound is written right after the tick (and its audio hash is
 * there for the flight recorder's record); the
 * service menu's render size is followed before the frame is drawn; the
 * hashes are of the frame just presented; READY=1 follows the first
 * present. begin and input stop the loop before anything else of their
 * tick runs; every tick starts from a zero command.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "app/loop.h"

/* The documented order of one whole tick. */
#define TICK "begin wait input command wizard flight_before sim sound flight_after requests " \
	     "outputs persist present hashes checks notify "

struct run {
	char log[4096];
	size_t n;
	uint32_t stop_begin;     /* begin says stop at this tick (UINT32_MAX: never) */
	uint32_t stop_input;     /* input says end at this tick */
	uint32_t last_t;         /* the tick the steps saw, checked equal within one */
	int begun;
};

static void note(void *ctx, const char *name, const struct loop_tick *k)
{
	struct run *r = ctx;
	int w = snprintf(r->log + r->n, sizeof(r->log) - r->n, "%s ", name);

	assert_true(w > 0 && (size_t)w < sizeof(r->log) - r->n);
	r->n += (size_t)w;
	if (strcmp(name, "begin") != 0 && strcmp(name, "end") != 0)
		assert_int_equal(k->t, r->last_t);
}

static int begin(void *ctx, struct loop_tick *k)
{
	struct run *r = ctx;
	static const struct rec_tick zero;

	note(ctx, "begin", k);
	/* ticks count up by one from 0, each from a zero command */
	assert_int_equal(k->t, r->begun++ ? r->last_t + 1 : 0);
	assert_memory_equal(&k->rt, &zero, sizeof(zero));
	r->last_t = k->t;
	return k->t != r->stop_begin;
}

static int input(void *ctx, struct loop_tick *k)
{
	struct run *r = ctx;

	note(ctx, "input", k);
	return k->t != r->stop_input;
}

static void command(void *ctx, struct loop_tick *k)
{
	note(ctx, "command", k);
	/* what a real command step does: the next tick must not see it */
	k->rt.cmd.buttons = 0xff;
	k->rt.cmd.forward = 100;
	k->rt.state_hash = 1;
}

#define STEP(name) \
	static void name(void *ctx, struct loop_tick *k) { note(ctx, #name, k); }
STEP(wait)
STEP(wizard)
STEP(flight_before)
STEP(sim)
STEP(sound)
STEP(flight_after)
STEP(requests)
STEP(outputs)
STEP(persist)
STEP(present)
STEP(hashes)
STEP(checks)
STEP(notify)
STEP(end)

static const struct loop_ops ops = {
	.begin = begin,
	.wait = wait,
	.input = input,
	.command = command,
	.wizard = wizard,
	.flight_before = flight_before,
	.sim = sim,
	.sound = sound,
	.flight_after = flight_after,
	.requests = requests,
	.outputs = outputs,
	.persist = persist,
	.present = present,
	.hashes = hashes,
	.checks = checks,
	.notify = notify,
	.end = end,
};

static void ticks_run_the_steps_in_the_documented_order(void **state)
{
	struct run r = { .stop_begin = 3, .stop_input = UINT32_MAX };

	(void)state;
	assert_int_equal(loop_run(&ops, &r), 3);
	assert_string_equal(r.log, TICK TICK TICK "begin end ");
}

static void begin_stops_before_anything_of_its_tick(void **state)
{
	struct run r = { .stop_begin = 0, .stop_input = UINT32_MAX };

	(void)state;
	assert_int_equal(loop_run(&ops, &r), 0);
	assert_string_equal(r.log, "begin end ");
}

static void the_end_of_input_stops_before_the_command(void **state)
{
	struct run r = { .stop_begin = UINT32_MAX, .stop_input = 2 };

	(void)state;
	/* a replay's end: tick 2 has no command, so nothing after input runs */
	assert_int_equal(loop_run(&ops, &r), 2);
	assert_string_equal(r.log, TICK TICK "begin wait input end ");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(ticks_run_the_steps_in_the_documented_order),
		cmocka_unit_test(begin_stops_before_anything_of_its_tick),
		cmocka_unit_test(the_end_of_input_stops_before_the_command),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
