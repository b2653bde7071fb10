/* libFuzzer target: the HID report descriptor parser and the report
 * decoder (input/hidd.c, input/hidr.c).
 *
 * Input: 2 bytes little-endian descriptor length L, L descriptor bytes,
 * then reports, each one length byte and that many bytes. Whatever the
 * bytes, a parsed descriptor's fields must lie inside their reports, and
 * the decoder must never press a held code or release a free one, nor
 * report a value outside -32767..32767 or a code outside the key space. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "input/hidd.h"
#include "input/hidr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

static void check_desc(const struct hidd_desc *d)
{
	for (size_t i = 0; i < d->nfield; i++) {
		const struct hidd_field *f = &d->field[i];
		size_t rlen = hidd_report_len(d, f->report_id);
		uint64_t end = f->bit + (uint64_t)f->size * f->count;

		if (rlen == 0 || end > (uint64_t)(rlen - (d->has_ids ? 1 : 0)) * 8)
			abort();
		if (f->nspan && f->span0 + f->nspan > d->nspan)
			abort();
	}
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	static uint8_t held[0x300];
	static struct in_event ev[0x300 + HIDD_MAX_FIELDS * 8];
	struct hidd_desc *d = NULL;
	struct hidr *r = NULL;
	struct hidr_opts o;
	size_t dlen, pos;
	char err[128];

	if (len < 3)
		return 0;
	dlen = (size_t)data[0] | (size_t)data[1] << 8;
	if (dlen > len - 2)
		dlen = len - 2;
	if (hidd_parse(data + 2, dlen, &d, err, sizeof(err)) < 0)
		return 0;
	check_desc(d);
	hidr_default_opts(&o);
	o.split = data[2] % 3;
	if (hidr_new(d, &o, &r) < 0 || hidr_max_events(r) > (int)(sizeof(ev) / sizeof(ev[0])))
		abort();
	memset(held, 0, sizeof(held));
	pos = 2 + dlen;
	while (pos < len) {
		size_t n = data[pos++];
		int k;

		if (n > len - pos)
			n = len - pos;
		k = hidr_decode(r, data + pos, n, 1, ev, (int)(sizeof(ev) / sizeof(ev[0])));
		pos += n;
		for (int i = 0; i < k; i++) {
			if (ev[i].type == IN_KEY) {
				if (ev[i].code >= 0x300 || held[ev[i].code] == ev[i].value)
					abort();
				held[ev[i].code] = (uint8_t)ev[i].value;
			} else if (ev[i].type != IN_ABS || ev[i].value < -HIDR_FULL ||
				   ev[i].value > HIDR_FULL) {
				abort();
			}
		}
	}
	hidr_free(r);
	hidd_free(d);
	return 0;
}
