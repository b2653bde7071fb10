/*
 * hidd: HID report descriptor parser. The rules, limits and errors are in
 * hidd.h; this file says why where the code alone would not.
 */
#include "input/hidd.h"

#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/le.h"
#include "input/txt.h"

/* Element steps the variable-item splitter may take over one descriptor:
 * keeps a descriptor of thousands of maximal items from costing seconds. */
#define HIDD_MAX_WORK (1u << 20)

struct hidd_global {
	uint16_t page;
	uint32_t lmin, lmax;         /* raw item data; signedness is settled at the main item */
	uint8_t lmin_len, lmax_len;  /* data bytes of those items (0: not given) */
	uint32_t size, count;
	uint32_t report_id;
};

struct hidd_parser {
	const uint8_t *buf;
	size_t len;
	size_t at;                   /* offset of the item being handled */
	struct hidd_desc *d;
	char *err;
	size_t errlen;
	struct hidd_global g;
	struct hidd_global stack[HIDD_MAX_PUSH];
	int sp;
	struct hidd_span local[HIDD_MAX_LOCAL];
	size_t nlocal;
	bool have_min, have_max;
	uint32_t umin, umax;
	int delim;                   /* open delimiter sets */
	bool delim_taken;            /* the open set already gave its usage */
	int depth;
	uint16_t coll[HIDD_MAX_DEPTH];
	uint16_t app[HIDD_MAX_DEPTH + 1];      /* app index in effect at each depth */
	uint32_t app_usage[HIDD_MAX_DEPTH + 1];
	uint32_t bits[256];          /* input payload bits per report id */
	bool seen[256];
	size_t cap_field, cap_span, cap_report;
	uint32_t work;
};

__attribute__((format(printf, 3, 4)))
static int fail(struct hidd_parser *p, int rc, const char *fmt, ...)
{
	va_list ap;
	int n;

	if (!p->err || p->errlen == 0)
		return rc;
	n = snprintf(p->err, p->errlen, "offset %zu: ", p->at);
	if (n < 0 || (size_t)n >= p->errlen)
		return rc;
	va_start(ap, fmt);
	vsnprintf(p->err + n, p->errlen - (size_t)n, fmt, ap);
	va_end(ap);
	return rc;
}

/* Grows *arr (elements of size sz, capacity *cap) to hold need elements. */
static int grow(void **arr, size_t *cap, size_t need, size_t sz)
{
	size_t n = *cap ? *cap : 16;
	void *a;

	if (need <= *cap)
		return 0;
	while (n < need)
		n *= 2;
	a = realloc(*arr, n * sz);
	if (!a)
		return -ENOMEM;
	*arr = a;
	*cap = n;
	return 0;
}

static int64_t sext(uint32_t v, uint8_t len)
{
	switch (len) {
	case 1: return (int8_t)(uint8_t)v;
	case 2: return (int16_t)(uint16_t)v;
	case 4: return (int32_t)v;
	default: return 0;
	}
}

static int usage_kind(uint32_t u, bool var)
{
	uint16_t page = HIDD_PAGE(u), id = HIDD_ID(u);

	if (page >= HIDD_PAGE_VENDOR)
		return HIDD_VENDOR;
	if (!var)
		return page == HIDD_PAGE_KEYBOARD ? HIDD_KEY_ARRAY : HIDD_ARRAY;
	switch (page) {
	case HIDD_PAGE_BUTTON:
		return HIDD_BUTTON;
	case HIDD_PAGE_KEYBOARD:
		return HIDD_KEY;
	case HIDD_PAGE_DESKTOP:
		if (id >= HIDD_GD_X && id <= HIDD_GD_X + 8)
			return HIDD_AXIS;
		if (id == HIDD_GD_HAT)
			return HIDD_HAT;
		if (id >= HIDD_GD_DPAD_UP && id <= HIDD_GD_DPAD_UP + 3)
			return HIDD_BUTTON;
		return HIDD_OTHER;
	case HIDD_PAGE_SIM:
		/* rudder, throttle, accelerator, brake, steering */
		if (id == 0xba || id == 0xbb || id == 0xc4 || id == 0xc5 || id == 0xc8)
			return HIDD_AXIS;
		return HIDD_OTHER;
	default:
		return HIDD_OTHER;
	}
}

static void clear_local(struct hidd_parser *p)
{
	p->nlocal = 0;
	p->have_min = p->have_max = false;
	p->delim = 0;
	p->delim_taken = false;
}

static int add_local(struct hidd_parser *p, uint32_t first, uint32_t last)
{
	if (first > last)
		return fail(p, -EINVAL, "usage minimum 0x%08x above usage maximum 0x%08x", first,
			    last);
	if (p->delim > 0) {
		/* Only the first usage of a delimited set counts. */
		if (p->delim_taken)
			return 0;
		p->delim_taken = true;
	}
	if (p->nlocal == HIDD_MAX_LOCAL)
		return fail(p, -E2BIG, "more than %d usages before one main item", HIDD_MAX_LOCAL);
	p->local[p->nlocal].first = first;
	p->local[p->nlocal].last = last;
	p->nlocal++;
	return 0;
}

static int local_item(struct hidd_parser *p, uint8_t tag, uint32_t v, uint8_t len)
{
	/* Short usages take the page in effect now (see hidd.h). */
	uint32_t u = len == 4 ? v : HIDD_USAGE(p->g.page, v & 0xffffu);
	int rc = 0;

	switch (tag) {
	case 0x0:
		rc = add_local(p, u, u);
		break;
	case 0x1:
		p->umin = u;
		p->have_min = true;
		break;
	case 0x2:
		p->umax = u;
		p->have_max = true;
		break;
	case 0xa:
		if (v) {
			p->delim++;
			p->delim_taken = false;
		} else if (p->delim > 0) {
			p->delim--;
		}
		break;
	default:
		break;   /* designators, strings: not needed */
	}
	if (rc == 0 && p->have_min && p->have_max) {
		p->have_min = p->have_max = false;
		rc = add_local(p, p->umin, p->umax);
	}
	return rc;
}

static int global_item(struct hidd_parser *p, uint8_t tag, uint32_t v, uint8_t len)
{
	switch (tag) {
	case 0x0:
		p->g.page = (uint16_t)v;
		break;
	case 0x1:
		p->g.lmin = v;
		p->g.lmin_len = len;
		break;
	case 0x2:
		p->g.lmax = v;
		p->g.lmax_len = len;
		break;
	case 0x7:
		p->g.size = v;
		break;
	case 0x8:
		if (v == 0 || v > 255)
			return fail(p, -EINVAL, "report id %u (must be 1..255)", v);
		p->g.report_id = v;
		p->d->has_ids = 1;
		break;
	case 0x9:
		p->g.count = v;
		break;
	case 0xa:
		if (p->sp == HIDD_MAX_PUSH)
			return fail(p, -E2BIG, "push nested deeper than %d", HIDD_MAX_PUSH);
		p->stack[p->sp++] = p->g;
		break;
	case 0xb:
		if (p->sp == 0)
			return fail(p, -EINVAL, "pop with nothing pushed");
		p->g = p->stack[--p->sp];
		break;
	default:
		break;   /* physical range, unit, exponent, reserved tags */
	}
	return 0;
}

static int new_field(struct hidd_parser *p, struct hidd_field **out)
{
	struct hidd_desc *d = p->d;

	if (d->nfield == HIDD_MAX_FIELDS)
		return fail(p, -E2BIG, "more than %d input fields", HIDD_MAX_FIELDS);
	if (grow((void **)&d->field, &p->cap_field, d->nfield + 1, sizeof(*d->field)) < 0)
		return -ENOMEM;
	*out = &d->field[d->nfield++];
	memset(*out, 0, sizeof(**out));
	return 0;
}

/* Appends usage span [first, last] to field f (the last field), merging
 * with its previous span when they touch. */
static int field_span(struct hidd_parser *p, struct hidd_field *f, uint32_t first, uint32_t last)
{
	struct hidd_desc *d = p->d;

	if (f->nspan > 0) {
		struct hidd_span *s = &d->span[f->span0 + f->nspan - 1];

		if (s->last != UINT32_MAX && s->last + 1 == first) {
			s->last = last;
			return 0;
		}
	}
	if (d->nspan == HIDD_MAX_SPANS)
		return fail(p, -E2BIG, "more than %d usage spans", HIDD_MAX_SPANS);
	if (grow((void **)&d->span, &p->cap_span, d->nspan + 1, sizeof(*d->span)) < 0)
		return -ENOMEM;
	if (f->nspan == 0)
		f->span0 = (uint32_t)d->nspan;
	d->span[d->nspan].first = first;
	d->span[d->nspan].last = last;
	d->nspan++;
	f->nspan++;
	return 0;
}

/* Starts a field of kind k covering elements [from, ...) of the item. */
static int start_field(struct hidd_parser *p, struct hidd_field **f, int k, uint32_t base,
		       uint32_t from, uint16_t flags, int64_t lmin, int64_t lmax)
{
	int rc = new_field(p, f);

	if (rc < 0)
		return rc;
	(*f)->bit = base + from * p->g.size;
	(*f)->size = (uint16_t)p->g.size;
	(*f)->report_id = (uint8_t)p->g.report_id;
	(*f)->kind = (uint8_t)k;
	(*f)->flags = flags;
	(*f)->lmin = lmin;
	(*f)->lmax = lmax;
	(*f)->app = p->app[p->depth];
	(*f)->app_usage = p->app_usage[p->depth];
	(*f)->coll = p->depth > 0 ? p->coll[p->depth - 1] : HIDD_NO_APP;
	return 0;
}

/* A variable item: one field per run of elements whose usages have the
 * same kind. The last run also takes the elements past the last usage. */
static int variable_fields(struct hidd_parser *p, uint32_t base, uint16_t flags, int64_t lmin,
			   int64_t lmax)
{
	uint32_t count = p->g.count, i = 0, run = 0;
	struct hidd_field *f = NULL;
	int kind = -1, rc;

	for (size_t s = 0; s < p->nlocal && i < count; s++) {
		for (uint64_t u = p->local[s].first; u <= p->local[s].last && i < count; u++, i++) {
			int k = usage_kind((uint32_t)u, true);

			if (++p->work > HIDD_MAX_WORK)
				return fail(p, -E2BIG, "descriptor needs more than %u usage steps",
					    HIDD_MAX_WORK);
			if (k != kind) {
				if (f)
					f->count = (uint16_t)(i - run);
				rc = start_field(p, &f, k, base, i, flags, lmin, lmax);
				if (rc < 0)
					return rc;
				kind = k;
				run = i;
			}
			rc = field_span(p, f, (uint32_t)u, (uint32_t)u);
			if (rc < 0)
				return rc;
		}
	}
	if (!f) {
		rc = start_field(p, &f, HIDD_OTHER, base, 0, flags, lmin, lmax);
		if (rc < 0)
			return rc;
	}
	f->count = (uint16_t)(count - run);
	return 0;
}

static int input_item(struct hidd_parser *p, uint32_t data)
{
	uint16_t flags = (uint16_t)(data & 0x1ff);
	uint32_t id = p->g.report_id, base, bits;
	int64_t lmin = sext(p->g.lmin, p->g.lmin_len), lmax;
	struct hidd_field *f;
	int rc;

	lmax = lmin < 0 ? sext(p->g.lmax, p->g.lmax_len) : (int64_t)p->g.lmax;
	if (p->g.count == 0)
		return 0;
	if (p->g.size == 0) {
		if (flags & HIDD_F_CONST)
			return 0;   /* zero-width padding */
		return fail(p, -EINVAL, "input item with report size 0");
	}
	bits = p->g.size * p->g.count;    /* both bounded by the checks in main_item */
	if (p->bits[id] + bits > HIDD_MAX_REPORT_BYTES * 8u)
		return fail(p, -E2BIG, "input report %u longer than %d bytes", id,
			    HIDD_MAX_REPORT_BYTES);
	base = p->bits[id];
	p->bits[id] += bits;
	if (!p->seen[id]) {
		struct hidd_desc *d = p->d;

		if (grow((void **)&d->report, &p->cap_report, d->nreport + 1,
			 sizeof(*d->report)) < 0)
			return -ENOMEM;
		d->report[d->nreport].id = (uint8_t)id;
		d->report[d->nreport].bits = 0;
		d->nreport++;
		p->seen[id] = true;
	}
	if (flags & HIDD_F_CONST) {
		rc = start_field(p, &f, HIDD_PAD, base, 0, flags, lmin, lmax);
		if (rc == 0)
			f->count = (uint16_t)p->g.count;
		return rc;
	}
	if (flags & HIDD_F_VAR)
		return variable_fields(p, base, flags, lmin, lmax);
	rc = start_field(p, &f, p->nlocal ? usage_kind(p->local[0].first, false) : HIDD_OTHER,
			 base, 0, flags, lmin, lmax);
	if (rc < 0)
		return rc;
	f->count = (uint16_t)p->g.count;
	for (size_t s = 0; s < p->nlocal; s++) {
		rc = field_span(p, f, p->local[s].first, p->local[s].last);
		if (rc < 0)
			return rc;
	}
	return 0;
}

static int collection(struct hidd_parser *p, uint32_t type)
{
	struct hidd_desc *d = p->d;

	if (p->depth == HIDD_MAX_DEPTH)
		return fail(p, -E2BIG, "collections nested deeper than %d", HIDD_MAX_DEPTH);
	if (d->ncoll == HIDD_NO_APP - 1)
		return fail(p, -E2BIG, "more than %d collections", HIDD_NO_APP - 1);
	p->coll[p->depth] = d->ncoll++;
	p->app[p->depth + 1] = p->app[p->depth];
	p->app_usage[p->depth + 1] = p->app_usage[p->depth];
	if (type == 1) {
		p->app[p->depth + 1] = d->napp++;
		p->app_usage[p->depth + 1] = p->nlocal ? p->local[0].first : 0;
	}
	p->depth++;
	return 0;
}

static int main_item(struct hidd_parser *p, uint8_t tag, uint32_t v)
{
	int rc = 0;

	switch (tag) {
	case 0x8:   /* input */
	case 0x9:   /* output */
	case 0xb:   /* feature */
		if (p->g.count > HIDD_MAX_COUNT)
			return fail(p, -E2BIG, "report count %u above %d", p->g.count,
				    HIDD_MAX_COUNT);
		if (p->g.size > HIDD_MAX_SIZE)
			return fail(p, -E2BIG, "report size %u above %d bits", p->g.size,
				    HIDD_MAX_SIZE);
		if (tag == 0x8)
			rc = input_item(p, v);
		break;
	case 0xa:
		rc = collection(p, v);
		break;
	case 0xc:
		if (p->depth == 0)
			return fail(p, -EINVAL, "end collection without an open collection");
		p->depth--;
		break;
	default:
		p->d->ignored++;
		break;
	}
	clear_local(p);
	return rc;
}

static int parse(struct hidd_parser *p)
{
	size_t pos = 0;

	while (pos < p->len) {
		uint8_t b = p->buf[pos];
		uint8_t len = (uint8_t)((b & 3) == 3 ? 4 : (b & 3));
		uint8_t type = (b >> 2) & 3, tag = b >> 4;
		uint32_t v;
		int rc = 0;

		p->at = pos;
		if (b == 0xfe) {
			/* Long item: size byte, tag byte, data. Nothing uses them. */
			if (p->len - pos < 3)
				return fail(p, -EINVAL, "long item truncated");
			if (p->len - pos - 3 < p->buf[pos + 1])
				return fail(p, -EINVAL, "long item needs %u data bytes, %zu left",
					    p->buf[pos + 1], p->len - pos - 3);
			pos += 3u + p->buf[pos + 1];
			continue;
		}
		if (p->len - pos - 1 < len)
			return fail(p, -EINVAL, "item 0x%02x needs %u data bytes, %zu left", b, len,
				    p->len - pos - 1);
		v = (uint32_t)le_getn(p->buf + pos + 1, len);
		switch (type) {
		case 0: rc = main_item(p, tag, v); break;
		case 1: rc = global_item(p, tag, v, len); break;
		case 2: rc = local_item(p, tag, v, len); break;
		default: break;   /* reserved item type */
		}
		if (rc < 0)
			return rc;
		pos += 1u + len;
	}
	p->at = p->len;
	if (p->depth > 0)
		return fail(p, -EINVAL, "%d collection(s) left open at the end", p->depth);
	for (size_t i = 0; i < p->d->nreport; i++)
		p->d->report[i].bits = p->bits[p->d->report[i].id];
	return 0;
}

int hidd_parse(const uint8_t *buf, size_t len, struct hidd_desc **out, char *err,
	       size_t errlen)
{
	struct hidd_parser *p;
	int rc;

	*out = NULL;
	if (err && errlen)
		err[0] = '\0';
	p = calloc(1, sizeof(*p));
	if (!p)
		return -ENOMEM;
	p->buf = buf;
	p->len = len;
	p->err = err;
	p->errlen = errlen;
	p->app[0] = HIDD_NO_APP;
	p->d = calloc(1, sizeof(*p->d));
	if (!p->d) {
		rc = -ENOMEM;
		goto out;
	}
	if (len > HIDD_MAX_DESC)
		rc = fail(p, -E2BIG, "descriptor longer than %d bytes", HIDD_MAX_DESC);
	else
		rc = parse(p);
	if (rc == -ENOMEM)
		fail(p, rc, "out of memory");
	if (rc < 0) {
		hidd_free(p->d);
		goto out;
	}
	*out = p->d;
out:
	free(p);
	return rc;
}

void hidd_free(struct hidd_desc *d)
{
	if (!d)
		return;
	free(d->field);
	free(d->span);
	free(d->report);
	free(d);
}

uint32_t hidd_usage(const struct hidd_desc *d, const struct hidd_field *f, uint32_t i)
{
	uint64_t left = i;

	for (uint32_t s = 0; s < f->nspan; s++) {
		const struct hidd_span *sp = &d->span[f->span0 + s];
		uint64_t n = (uint64_t)sp->last - sp->first + 1;

		if (left < n)
			return sp->first + (uint32_t)left;
		left -= n;
	}
	if ((f->flags & HIDD_F_VAR) && f->nspan > 0)
		return d->span[f->span0 + f->nspan - 1].last;
	return 0;
}

size_t hidd_report_len(const struct hidd_desc *d, uint8_t id)
{
	for (size_t i = 0; i < d->nreport; i++)
		if (d->report[i].id == id)
			return (d->report[i].bits + 7) / 8 + (d->has_ids ? 1u : 0u);
	return 0;
}

const char *hidd_kind_name(int kind)
{
	static const char *const names[] = {
		[HIDD_PAD] = "padding", [HIDD_BUTTON] = "button", [HIDD_AXIS] = "axis",
		[HIDD_HAT] = "hat", [HIDD_KEY] = "key", [HIDD_KEY_ARRAY] = "key array",
		[HIDD_ARRAY] = "array", [HIDD_VENDOR] = "vendor", [HIDD_OTHER] = "other",
	};

	if (kind < 0 || kind >= (int)(sizeof(names) / sizeof(names[0])))
		return "?";
	return names[kind];
}

static void put_usage(struct txt *o, uint32_t u)
{
	static const char *const gd[] = { "X", "Y", "Z", "Rx", "Ry", "Rz", "Slider", "Dial",
					  "Wheel", "Hat" };
	uint16_t page = HIDD_PAGE(u), id = HIDD_ID(u);

	if (page == HIDD_PAGE_DESKTOP && id >= HIDD_GD_X && id <= HIDD_GD_HAT)
		txt_put(o, "%s", gd[id - HIDD_GD_X]);
	else if (page == HIDD_PAGE_BUTTON)
		txt_put(o, "Button%u", id);
	else
		txt_put(o, "%04x:%04x", page, id);
}

size_t hidd_describe(const struct hidd_desc *d, char *buf, size_t len)
{
	struct txt o = { .buf = buf, .len = len };

	if (len)
		buf[0] = '\0';
	for (size_t i = 0; i < d->nfield; i++) {
		const struct hidd_field *f = &d->field[i];

		txt_put(&o, "report %u bit %u: %s %ux%u bit, %lld..%lld", f->report_id, f->bit,
			hidd_kind_name(f->kind), f->count, f->size, (long long)f->lmin,
			(long long)f->lmax);
		if (f->app != HIDD_NO_APP)
			txt_put(&o, ", app %u", f->app);
		for (uint32_t s = 0; s < f->nspan && s < 8; s++) {
			const struct hidd_span *sp = &d->span[f->span0 + s];

			txt_put(&o, s ? " " : ": ");
			put_usage(&o, sp->first);
			if (sp->last != sp->first) {
				txt_put(&o, "-");
				put_usage(&o, sp->last);
			}
		}
		if (f->nspan > 8)
			txt_put(&o, " ...");
		txt_put(&o, "\n");
	}
	return o.n;
}
