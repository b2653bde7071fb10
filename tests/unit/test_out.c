/*
 * out: every open input device with outputs (in_backend.outputs) gets the
 * game's coins, credits and whether a game is being played, once per tick
 * at the slots' clock; devices without outputs and closed slots are left
 * alone; a device whose outputs went away is dropped with its controls
 * released, as after a read's -ENODEV. Fake backends (unit test only).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "app/out.h"
#include "app/slot.h"
#include "engine/game/sim.h"

struct in_dev {
	int unused;
};

static struct {
	int calls, closes, rc;
	struct gpo_state got;
	uint64_t at;
	struct in_event q[4];
	int nq;
} fk;

static int fake_open(const char *path, struct in_dev **out, char *why, size_t whylen)
{
	(void)path;
	(void)why;
	(void)whylen;
	*out = calloc(1, sizeof(**out));
	return *out ? 0 : -ENOMEM;
}

static int fake_read(struct in_dev *d, struct in_event *ev, int max)
{
	int n = fk.nq < max ? fk.nq : max;

	(void)d;
	memcpy(ev, fk.q, (size_t)n * sizeof(ev[0]));
	fk.nq = 0;
	return n;
}

static void fake_close(struct in_dev *d)
{
	fk.closes += d != NULL;
	free(d);
}

static const char *fake_describe(struct in_dev *d)
{
	(void)d;
	return "fake";
}

static int fake_outputs(struct in_dev *d, const struct gpo_state *s, uint64_t now)
{
	(void)d;
	fk.calls++;
	fk.got = *s;
	fk.at = now;
	return fk.rc;
}

static const struct in_backend with_outputs = {
	.name = "lines", .open = fake_open, .read = fake_read, .close = fake_close,
	.describe = fake_describe, .outputs = fake_outputs,
};
static const struct in_backend without = {
	.name = "keys", .open = fake_open, .read = fake_read, .close = fake_close,
	.describe = fake_describe,
};
static const struct slot_kind kinds[] = { { &with_outputs, NULL, 0, 1 }, { &without, NULL, 0, 1 } };

static char seen[256];

static void h_opened(void *ctx, struct slot *s)
{
	(void)ctx;
	(void)s;
}

static void h_key(void *ctx, struct slot *s, int code, int down, uint64_t t)
{
	(void)ctx;
	(void)s;
	(void)code;
	(void)down;
	(void)t;
}

static void h_released(void *ctx, struct slot *s, int code)
{
	(void)ctx;
	(void)s;
	snprintf(seen + strlen(seen), sizeof(seen) - strlen(seen), "released %d ", code);
}

static void h_gone(void *ctx, struct slot *s)
{
	(void)ctx;
	(void)s;
	snprintf(seen + strlen(seen), sizeof(seen) - strlen(seen), "gone ");
}

static const struct slot_hooks hooks = { h_opened, h_key, h_released, h_gone };

static uint64_t fake_now(void)
{
	return 777;
}

static struct slot_set set;
static struct sim sim;

static int setup(void **state)
{
	(void)state;
	memset(&fk, 0, sizeof(fk));
	memset(&sim, 0, sizeof(sim));
	seen[0] = '\0';
	slot_init(&set, &hooks, NULL);
	set.now = fake_now;
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	slot_close(&set);
	return 0;
}

static void outputs_follow_the_game(void **state)
{
	(void)state;
	slot_add(&set, kinds, 1, NULL, 0);     /* no outputs: skipped */
	slot_add(&set, kinds, 0, NULL, 0);
	sim.coins_total = 7;
	sim.credits = 3;
	sim.mode = SIM_ATTRACT;
	out_update(&set, &sim);
	assert_int_equal(fk.calls, 1);
	assert_int_equal(fk.got.coins_total, 7);
	assert_int_equal(fk.got.credits, 3);
	assert_int_equal(fk.got.playing, 0);
	assert_int_equal(fk.at, 777);
	/* playing: every mode but attract and the continue countdown */
	sim.mode = SIM_PLAY;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 1);
	sim.mode = SIM_GAMEOVER;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 0);
	sim.mode = SIM_INITIALS;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 1);
	assert_int_equal(fk.calls, 4);
}

static void a_device_whose_outputs_went_away_is_dropped(void **state)
{
	(void)state;
	slot_add(&set, kinds, 0, NULL, 0);
	fk.q[0] = (struct in_event){ .type = IN_KEY, .code = 6, .value = 1 };   /* coin held */
	fk.nq = 1;
	slot_read(&set);
	fk.rc = -ENODEV;
	out_update(&set, &sim);
	assert_string_equal(seen, "released 6 gone ");
	assert_int_equal(fk.closes, 1);
	assert_null(set.s[0].dev);
	/* closed: no outputs until it is back */
	out_update(&set, &sim);
	assert_int_equal(fk.calls, 1);
	/* another error is not a drop */
	fk.rc = -EIO;
	slot_close(&set);
	slot_init(&set, &hooks, NULL);
	slot_add(&set, kinds, 0, NULL, 0);
	out_update(&set, &sim);
	assert_non_null(set.s[0].dev);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(outputs_follow_the_game, setup, teardown),
		cmocka_unit_test_setup_teardown(a_device_whose_outputs_went_away_is_dropped, setup,
						teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
