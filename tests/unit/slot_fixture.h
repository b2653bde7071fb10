/*
 * Test fixture: fake input backends and slot hooks that write down what
 * they are told, for the tests of the app's input slots and outputs
 * (test_slot, test_out). A fake stands in for a device only in unit
 * tests. Include after cmocka.h.
 *
 * fake_be opens a device per call (after fk.fail failed opens), reads
 * what fake_key queued, then -ENODEV once fk.gone is set; fake_lines is
 * the same with outputs, which return fk.outputs_rc. The slots' clock is
 * clock_ns. Hooks append "opened VVVV:PID ", "key CODE DOWN ", "released
 * CODE ", "gone " to seen; the bound hook binds KEY_1 only.
 */
#ifndef ARCADED_TESTS_SLOT_FIXTURE_H
#define ARCADED_TESTS_SLOT_FIXTURE_H

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/slot.h"

#define FAKE_Q 32

struct in_dev {
	int n;                   /* which open made it */
	char path[64];
};

static struct fake {
	int opens, open_calls, closes;
	int fail;                /* opens that fail before one succeeds */
	char last_path[64];      /* "(auto)" for NULL */
	struct in_event q[FAKE_Q];   /* what the next read returns */
	int nq;
	int gone;                /* once q is read: -ENODEV */
	int outputs_calls, outputs_rc;
	struct gpo_state got;    /* what the last outputs call was given */
	uint64_t at;
} fk;

static uint64_t clock_ns;
static char seen[2048];
static struct slot_set set;

static inline uint64_t fake_now(void)
{
	return clock_ns;
}

static inline int fake_open(const char *path, struct in_dev **out, char *why, size_t whylen)
{
	fk.open_calls++;
	snprintf(fk.last_path, sizeof(fk.last_path), "%s", path ? path : "(auto)");
	if (fk.fail > 0) {
		fk.fail--;
		snprintf(why, whylen, "no such device");
		return -ENODEV;
	}
	*out = calloc(1, sizeof(**out));
	assert_non_null(*out);
	(*out)->n = ++fk.opens;
	snprintf((*out)->path, sizeof((*out)->path), "%s", fk.last_path);
	fk.gone = 0;
	return 0;
}

static inline int fake_read(struct in_dev *d, struct in_event *ev, int max)
{
	int n = fk.nq < max ? fk.nq : max;

	(void)d;
	if (n == 0)
		return fk.gone ? -ENODEV : 0;
	memcpy(ev, fk.q, (size_t)n * sizeof(ev[0]));
	memmove(fk.q, fk.q + n, (size_t)(fk.nq - n) * sizeof(fk.q[0]));
	fk.nq -= n;
	return n;
}

static inline void fake_close(struct in_dev *d)
{
	if (!d)
		return;
	fk.closes++;
	free(d);
}

static inline const char *fake_describe(struct in_dev *d)
{
	return d->path;
}

static inline void fake_ident(struct in_dev *d, struct in_ident *id)
{
	id->vid = 0x1209;
	id->pid = (uint16_t)d->n;
}

static inline int fake_outputs(struct in_dev *d, const struct gpo_state *s, uint64_t now)
{
	(void)d;
	fk.outputs_calls++;
	fk.got = *s;
	fk.at = now;
	return fk.outputs_rc;
}

__attribute__((unused)) static const struct in_backend fake_be = {
	.name = "fake",
	.open = fake_open,
	.read = fake_read,
	.close = fake_close,
	.describe = fake_describe,
	.ident = fake_ident,
};

__attribute__((unused)) static const struct in_backend fake_lines = {
	.name = "lines",
	.open = fake_open,
	.read = fake_read,
	.close = fake_close,
	.describe = fake_describe,
	.ident = fake_ident,
	.outputs = fake_outputs,
};

/* Queues a key event stamped now for the next read. */
static inline void fake_key(int code, int value)
{
	assert_true(fk.nq < FAKE_Q);
	fk.q[fk.nq++] = (struct in_event){ .time_ns = clock_ns, .type = IN_KEY,
					   .code = (uint16_t)code, .value = value };
}

static inline void fake_seen(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static inline void fake_seen(const char *fmt, ...)
{
	size_t n = strlen(seen);
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(seen + n, sizeof(seen) - n, fmt, ap);
	va_end(ap);
}

static inline void fake_opened(void *ctx, struct slot *s)
{
	(void)ctx;
	/* the slot asked the backend who the device is before telling */
	fake_seen("opened %04x:%u ", s->id.vid, s->id.pid);
}

static inline void fake_changed(void *ctx, struct slot *s, int code, int down, uint64_t t)
{
	(void)ctx;
	(void)s;
	assert_int_equal(t, clock_ns);   /* the event's own stamp */
	fake_seen("key %d %d ", code, down);
}

static inline void fake_released(void *ctx, struct slot *s, int code)
{
	(void)ctx;
	assert_non_null(s->dev);         /* released before the close */
	fake_seen("released %d ", code);
}

static inline void fake_gone(void *ctx, struct slot *s)
{
	(void)ctx;
	assert_non_null(s->dev);
	fake_seen("gone ");
}

/* The bindings: KEY_1 is bound, nothing else. */
static inline int fake_bound(void *ctx, const struct in_ident *id, int code)
{
	(void)ctx;
	(void)id;
	return code == 2;   /* KEY_1 */
}

__attribute__((unused)) static const struct slot_hooks fake_hooks = {
	fake_opened, fake_changed, fake_released, fake_gone, fake_bound,
};

/* cmocka set-up and tear-down: everything fresh, the clock at 1 s. */
static inline int fake_setup(void **state)
{
	(void)state;
	memset(&fk, 0, sizeof(fk));
	seen[0] = '\0';
	clock_ns = 1000000000ull;
	slot_init(&set, &fake_hooks, NULL);
	set.now = fake_now;
	return 0;
}

static inline int fake_teardown(void **state)
{
	(void)state;
	slot_close(&set);
	return 0;
}

#endif
