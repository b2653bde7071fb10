/*
 * scr: test scripts (format in scr.h). Parsing stops at the first error,
 * which names NAME:LINE: a script is a test, and a test with a typo must
 * fail loudly rather than run half of itself.
 */
#include "input/scr.h"

#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/game/sim.h"
#include "input/act.h"
#include "input/io.h"

#define SCR_FILE_MAX (1 << 20)
#define SCR_PATH_MAX 4096

/* The fields are the sim's named values (sim_field_*, engine/game/sim_field.c):
 * the first nine are SCR_F_X .. SCR_F_MODE in that order. */
_Static_assert(SCR_F_MODE == 8, "scr_field follows the sim's field order");

static const char *const scr_cmps[] = {
	[SCR_EQ] = "==", [SCR_NE] = "!=", [SCR_LT] = "<",
	[SCR_LE] = "<=", [SCR_GT] = ">",  [SCR_GE] = ">=",
};

const char *scr_field_name(enum scr_field f)
{
	return sim_field_name((int)f);
}

const char *scr_cmp_name(enum scr_cmp c)
{
	if ((unsigned)c >= sizeof(scr_cmps) / sizeof(scr_cmps[0]))
		return NULL;
	return scr_cmps[c];
}

int scr_compare(int64_t actual, enum scr_cmp cmp, int64_t expected)
{
	switch (cmp) {
	case SCR_EQ: return actual == expected;
	case SCR_NE: return actual != expected;
	case SCR_LT: return actual < expected;
	case SCR_LE: return actual <= expected;
	case SCR_GT: return actual > expected;
	case SCR_GE: return actual >= expected;
	}
	return 0;
}

struct scr_tok {
	const char *b, *e;
};

struct scr_parser {
	const char *name;
	char *err;
	size_t errlen;
	uint32_t line;
	struct scr *s;
	size_t cap;
	bool has_end;
	uint32_t end_line;
};

__attribute__((format(printf, 2, 3)))
static int scr_fail(struct scr_parser *p, const char *fmt, ...)
{
	char msg[256];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	if (p->err && p->errlen)
		snprintf(p->err, p->errlen, "%s:%u: %s", p->name, p->line, msg);
	return -EINVAL;
}

static bool scr_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\r';
}

static bool scr_digit(char c)
{
	return c >= '0' && c <= '9';
}

/* Next blank-separated token of [*p, e); false at the end of the line. */
static bool scr_next(const char **p, const char *e, struct scr_tok *t)
{
	while (*p < e && scr_blank(**p))
		(*p)++;
	if (*p == e)
		return false;
	t->b = *p;
	while (*p < e && !scr_blank(**p))
		(*p)++;
	t->e = *p;
	return true;
}

static bool scr_is(const struct scr_tok *t, const char *word)
{
	size_t n = strlen(word);

	return (size_t)(t->e - t->b) == n && memcmp(t->b, word, n) == 0;
}

/* Token for messages: at most 40 bytes of it. */
#define SCR_TOK_FMT "%.*s"
#define SCR_TOK_ARG(t) ((t)->e - (t)->b > 40 ? 40 : (int)((t)->e - (t)->b)), (t)->b

/* Unsigned decimal up to max; no sign, no other characters. */
static bool scr_uint(const struct scr_tok *t, uint64_t max, uint64_t *out)
{
	uint64_t v = 0;

	if (t->b == t->e)
		return false;
	for (const char *c = t->b; c < t->e; c++) {
		if (!scr_digit(*c))
			return false;
		v = v * 10 + (uint64_t)(*c - '0');
		if (v > max)
			return false;
	}
	*out = v;
	return true;
}

static bool scr_int32(const struct scr_tok *t, int64_t *out)
{
	struct scr_tok m = *t;
	bool neg = m.b < m.e && *m.b == '-';
	uint64_t v;

	if (m.b < m.e && (*m.b == '-' || *m.b == '+'))
		m.b++;
	if (!scr_uint(&m, neg ? 2147483648u : 2147483647u, &v))
		return false;
	*out = neg ? -(int64_t)v : (int64_t)v;
	return true;
}

/* "-12.5" to 16.16 without floating point: integer part, then up to 12
 * fraction digits as num/den, rounded to the nearest 1/65536 (halves away
 * from zero). The result must fit an int32 (fx_t). */
static bool scr_fixed(const struct scr_tok *t, int64_t *out)
{
	const char *c = t->b, *e = t->e;
	int64_t ip = 0, num = 0, den = 1, v;
	bool neg = false;

	if (c < e && (*c == '-' || *c == '+'))
		neg = *c++ == '-';
	if (c == e || !scr_digit(*c))
		return false;
	for (; c < e && scr_digit(*c); c++) {
		ip = ip * 10 + (*c - '0');
		if (ip > 32768)
			return false;
	}
	if (c < e && *c == '.') {
		c++;
		if (c == e)
			return false;
		for (; c < e; c++) {
			if (!scr_digit(*c) || den == 1000000000000)
				return false;
			num = num * 10 + (*c - '0');
			den *= 10;
		}
	}
	if (c != e)
		return false;
	v = ip * 65536 + (num * 65536 * 2 + den) / (den * 2);
	if (neg)
		v = -v;
	if (v < INT32_MIN || v > INT32_MAX)
		return false;
	*out = v;
	return true;
}

/* The token as a NUL-terminated word in buf; "" when it does not fit. */
static const char *scr_word(const struct scr_tok *t, char *buf, size_t len)
{
	size_t n = (size_t)(t->e - t->b);

	if (n >= len)
		n = 0;
	memcpy(buf, t->b, n);
	buf[n] = '\0';
	return buf;
}

/* Mode and page names are the sim's own (sim_mode_from_name,
 * sim_page_from_name). */
static int scr_mode(const struct scr_tok *t)
{
	char name[16];

	return sim_mode_from_name(scr_word(t, name, sizeof(name)));
}

static int scr_page(const struct scr_tok *t)
{
	char name[16];

	return sim_page_from_name(scr_word(t, name, sizeof(name)));
}

static struct scr_step *scr_add(struct scr_parser *p, uint32_t tick, enum scr_op op)
{
	struct scr *s = p->s;
	struct scr_step *st;

	if (s->n == p->cap) {
		size_t ncap = p->cap ? p->cap * 2 : 32;
		struct scr_step *ns = realloc(s->steps, ncap * sizeof(*ns));

		if (!ns)
			return NULL;
		s->steps = ns;
		p->cap = ncap;
	}
	st = &s->steps[s->n++];
	memset(st, 0, sizeof(*st));
	st->tick = tick;
	st->line = p->line;
	st->op = op;
	return st;
}

static int scr_action(struct scr_parser *p, const char **c, const char *e, int *act)
{
	struct scr_tok t;
	char name[32];
	size_t n;

	if (!scr_next(c, e, &t))
		return scr_fail(p, "expected an action");
	n = (size_t)(t.e - t.b);
	*act = -1;
	if (n < sizeof(name)) {
		memcpy(name, t.b, n);
		name[n] = '\0';
		*act = act_from_name(name);
	}
	if (*act < 0)
		return scr_fail(p, "unknown action '" SCR_TOK_FMT "'", SCR_TOK_ARG(&t));
	return 0;
}

static int scr_expect(struct scr_parser *p, uint32_t tick, const char **c, const char *e)
{
	struct scr_tok f, o, v;
	struct scr_step *st;
	int field, cmp = -1, mode;
	int64_t val = 0;
	uint64_t u = 0;
	char name[32];
	bool ok;

	if (!scr_next(c, e, &f))
		return scr_fail(p, "expected FIELD OP VALUE after expect");
	field = sim_field_find(scr_word(&f, name, sizeof(name)));
	if (field < 0)
		return scr_fail(p, "unknown field '" SCR_TOK_FMT "'", SCR_TOK_ARG(&f));
	if (!scr_next(c, e, &o))
		return scr_fail(p, "expected a comparison (== != < <= > >=)");
	for (int i = 0; i < (int)(sizeof(scr_cmps) / sizeof(scr_cmps[0])); i++)
		if (scr_is(&o, scr_cmps[i]))
			cmp = i;
	if (cmp < 0)
		return scr_fail(p, "unknown comparison '" SCR_TOK_FMT "' (== != < <= > >=)",
				SCR_TOK_ARG(&o));
	if (!scr_next(c, e, &v))
		return scr_fail(p, "expected a value");
	switch (sim_field_kind(field)) {
	case SIM_FK_FX:
		ok = scr_fixed(&v, &val);
		break;
	case SIM_FK_ANGLE:
		ok = scr_int32(&v, &val);
		break;
	case SIM_FK_MODE:
	case SIM_FK_PAGE:
		if (cmp != SCR_EQ && cmp != SCR_NE)
			return scr_fail(p, "%s compares only with == or !=", sim_field_name(field));
		mode = sim_field_kind(field) == SIM_FK_MODE ? scr_mode(&v) : scr_page(&v);
		ok = mode >= 0;
		val = mode;
		break;
	case SIM_FK_INT:
	default:
		ok = scr_uint(&v, UINT32_MAX, &u);
		val = (int64_t)u;
		break;
	}
	if (!ok)
		return scr_fail(p, "bad value '" SCR_TOK_FMT "' for %s", SCR_TOK_ARG(&v),
				sim_field_name(field));
	st = scr_add(p, tick, SCR_EXPECT);
	if (!st)
		return -ENOMEM;
	st->field = (enum scr_field)field;
	st->cmp = (enum scr_cmp)cmp;
	st->value = val;
	return 0;
}

static int scr_screenshot(struct scr_parser *p, uint32_t tick, const char *c, const char *e)
{
	struct scr_step *st;
	size_t n;

	while (c < e && scr_blank(*c))
		c++;
	while (e > c && scr_blank(e[-1]))
		e--;
	n = (size_t)(e - c);
	if (n == 0)
		return scr_fail(p, "expected a file name");
	if (n >= SCR_PATH_MAX)
		return scr_fail(p, "file name too long");
	st = scr_add(p, tick, SCR_SCREENSHOT);
	if (!st)
		return -ENOMEM;
	st->path = malloc(n + 1);
	if (!st->path)
		return -ENOMEM;
	memcpy(st->path, c, n);
	st->path[n] = '\0';
	return 0;
}

static int scr_line(struct scr_parser *p, const char *c, const char *e)
{
	const char *hash = memchr(c, '#', (size_t)(e - c));
	struct scr_tok t, op, extra;
	uint64_t tick, n;
	int act, ret = 0;

	if (memchr(c, '\0', (size_t)(e - c)))
		return scr_fail(p, "line contains a NUL byte");
	if (hash)
		e = hash;
	if (!scr_next(&c, e, &t))
		return 0;
	if (!scr_uint(&t, UINT32_MAX, &tick))
		return scr_fail(p, "expected a tick number, got '" SCR_TOK_FMT "'",
				SCR_TOK_ARG(&t));
	if (!scr_next(&c, e, &op))
		return scr_fail(p, "expected a command after the tick");
	if (scr_is(&op, "press") || scr_is(&op, "release")) {
		ret = scr_action(p, &c, e, &act);
		if (ret == 0) {
			struct scr_step *st = scr_add(p, (uint32_t)tick,
						      scr_is(&op, "press") ? SCR_PRESS : SCR_RELEASE);
			if (!st)
				return -ENOMEM;
			st->action = act;
		}
	} else if (scr_is(&op, "hold") || scr_is(&op, "tap")) {
		struct scr_step *st;

		ret = scr_action(p, &c, e, &act);
		if (ret < 0)
			return ret;
		n = 1;
		if (scr_is(&op, "hold") &&
		    (!scr_next(&c, e, &t) || !scr_uint(&t, UINT32_MAX, &n) || n == 0))
			return scr_fail(p, "hold needs a number of ticks (1 or more)");
		if (tick + n > UINT32_MAX)
			return scr_fail(p, "release tick %llu is too large",
					(unsigned long long)(tick + n));
		st = scr_add(p, (uint32_t)tick, SCR_PRESS);
		if (!st)
			return -ENOMEM;
		st->action = act;
		st = scr_add(p, (uint32_t)(tick + n), SCR_RELEASE);
		if (!st)
			return -ENOMEM;
		st->action = act;
	} else if (scr_is(&op, "expect")) {
		ret = scr_expect(p, (uint32_t)tick, &c, e);
	} else if (scr_is(&op, "snapshot")) {
		if (!scr_add(p, (uint32_t)tick, SCR_SNAPSHOT))
			return -ENOMEM;
	} else if (scr_is(&op, "screenshot")) {
		return scr_screenshot(p, (uint32_t)tick, c, e);
	} else if (scr_is(&op, "end")) {
		if (p->has_end)
			return scr_fail(p, "second end (the first is on line %u)", p->end_line);
		p->has_end = true;
		p->end_line = p->line;
		p->s->end_tick = (uint32_t)tick;
		if (!scr_add(p, (uint32_t)tick, SCR_END))
			return -ENOMEM;
	} else {
		return scr_fail(p, "unknown command '" SCR_TOK_FMT "'", SCR_TOK_ARG(&op));
	}
	if (ret == 0 && scr_next(&c, e, &extra))
		return scr_fail(p, "unexpected '" SCR_TOK_FMT "' after the command",
				SCR_TOK_ARG(&extra));
	return ret;
}

/* Stable bottom-up merge sort by tick: steps of one tick keep file order
 * (qsort promises no stability). */
static int scr_sort(struct scr_step *a, size_t n)
{
	struct scr_step *tmp, *src = a, *dst;

	if (n < 2)
		return 0;
	tmp = malloc(n * sizeof(*tmp));
	if (!tmp)
		return -ENOMEM;
	dst = tmp;
	for (size_t w = 1; w < n; w *= 2) {
		for (size_t lo = 0; lo < n; lo += 2 * w) {
			size_t mid = lo + w < n ? lo + w : n;
			size_t hi = lo + 2 * w < n ? lo + 2 * w : n;
			size_t i = lo, j = mid, k = lo;

			while (i < mid && j < hi)
				dst[k++] = src[j].tick < src[i].tick ? src[j++] : src[i++];
			while (i < mid)
				dst[k++] = src[i++];
			while (j < hi)
				dst[k++] = src[j++];
		}
		struct scr_step *t = src;
		src = dst;
		dst = t;
	}
	if (src != a)
		memcpy(a, src, n * sizeof(*a));
	free(tmp);
	return 0;
}

static int scr_finish(struct scr_parser *p)
{
	struct scr *s = p->s;

	if (p->has_end) {
		/* A check after the end would never run: a test that cannot fail. */
		for (size_t i = 0; i < s->n; i++) {
			const struct scr_step *st = &s->steps[i];

			if (st->tick > s->end_tick && st->op != SCR_RELEASE) {
				p->line = st->line;
				return scr_fail(p, "tick %u is after end (tick %u, line %u)",
						st->tick, s->end_tick, p->end_line);
			}
		}
	} else {
		for (size_t i = 0; i < s->n; i++)
			if (s->steps[i].tick > s->end_tick)
				s->end_tick = s->steps[i].tick;
	}
	return scr_sort(s->steps, s->n);
}

int scr_parse(const char *text, size_t len, const char *name, struct scr **out, char *err,
	      size_t errlen)
{
	struct scr_parser p = { .name = name, .err = err, .errlen = errlen };
	const char *c = text, *end = text + len;
	int ret = 0;

	p.s = calloc(1, sizeof(*p.s));
	if (!p.s)
		goto nomem;
	while (c < end && ret == 0) {
		const char *nl = memchr(c, '\n', (size_t)(end - c));
		const char *le = nl ? nl : end;

		p.line++;
		ret = scr_line(&p, c, le);
		c = nl ? nl + 1 : end;
	}
	if (ret == 0)
		ret = scr_finish(&p);
	if (ret == -ENOMEM)
		goto nomem;
	if (ret < 0) {
		scr_free(p.s);
		return ret;
	}
	*out = p.s;
	return 0;
nomem:
	if (err && errlen)
		snprintf(err, errlen, "%s: out of memory", name);
	scr_free(p.s);
	return -ENOMEM;
}

void scr_free(struct scr *s)
{
	if (!s)
		return;
	for (size_t i = 0; i < s->n; i++)
		free(s->steps[i].path);
	free(s->steps);
	free(s);
}

int scr_load(const char *path, struct scr **out, char *err, size_t errlen)
{
	uint8_t *buf;
	size_t n;
	int ret = io_read_file(path, SCR_FILE_MAX, 0, &buf, &n);

	if (ret == -EFBIG) {
		if (err && errlen)
			snprintf(err, errlen, "%s: file is larger than %d bytes", path, SCR_FILE_MAX);
		return ret;
	}
	if (ret < 0) {
		if (err && errlen)
			snprintf(err, errlen, "%s: %s", path, strerror(-ret));
		return ret;
	}
	ret = scr_parse((const char *)buf, n, path, out, err, errlen);
	free(buf);
	return ret;
}
