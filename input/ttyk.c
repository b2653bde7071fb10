/*
 * ttyk: terminal bytes to key presses and synthesized releases. The rules
 * are in ttyk.h.
 */
#include "input/ttyk.h"

#include <assert.h>
#include <string.h>

#include <linux/input-event-codes.h>

#define ESC 0x1b

/* Room an event-producing step may need: evicting the oldest held key and
 * pressing a new one. */
#define STEP_ROOM 2
/* Room ttyk_expire may need: a pending ESC pressed (with an eviction),
 * then every held key released. */
#define EXPIRE_ROOM (TTYK_HELD + STEP_ROOM)

static const uint16_t letter_key[26] = {
	KEY_A, KEY_B, KEY_C, KEY_D, KEY_E, KEY_F, KEY_G, KEY_H, KEY_I,
	KEY_J, KEY_K, KEY_L, KEY_M, KEY_N, KEY_O, KEY_P, KEY_Q, KEY_R,
	KEY_S, KEY_T, KEY_U, KEY_V, KEY_W, KEY_X, KEY_Y, KEY_Z,
};

static const uint16_t digit_key[10] = {
	KEY_0, KEY_1, KEY_2, KEY_3, KEY_4, KEY_5, KEY_6, KEY_7, KEY_8, KEY_9,
};

/* Key of a byte outside escape sequences, or 0 when it is dropped. */
static uint16_t byte_key(uint8_t c)
{
	if (c >= 'a' && c <= 'z')
		return letter_key[c - 'a'];
	if (c >= 'A' && c <= 'Z')
		return letter_key[c - 'A'];
	if (c >= '0' && c <= '9')
		return digit_key[c - '0'];
	switch (c) {
	case ' ': return KEY_SPACE;
	case ',': return KEY_COMMA;
	case '.': return KEY_DOT;
	case '-': return KEY_MINUS;
	case '=': return KEY_EQUAL;
	case '/': return KEY_SLASH;
	case ';': return KEY_SEMICOLON;
	case '\'': return KEY_APOSTROPHE;
	case '[': return KEY_LEFTBRACE;
	case ']': return KEY_RIGHTBRACE;
	case '\\': return KEY_BACKSLASH;
	case '`': return KEY_GRAVE;
	case '\r': case '\n': return KEY_ENTER;
	case '\t': return KEY_TAB;
	case 0x7f: case 0x08: return KEY_BACKSPACE;
	default: return 0;
	}
}

/* Key of the final byte shared by CSI and SS3 cursor keys, or 0. */
static uint16_t cursor_key(uint8_t final)
{
	switch (final) {
	case 'A': return KEY_UP;
	case 'B': return KEY_DOWN;
	case 'C': return KEY_RIGHT;
	case 'D': return KEY_LEFT;
	case 'H': return KEY_HOME;
	case 'F': return KEY_END;
	default: return 0;
	}
}

/* Key of "ESC [ n ~", or 0. */
static uint16_t tilde_key(unsigned n)
{
	static const uint16_t fkey[] = {
		[11] = KEY_F1, [12] = KEY_F2, [13] = KEY_F3, [14] = KEY_F4, [15] = KEY_F5,
		[17] = KEY_F6, [18] = KEY_F7, [19] = KEY_F8, [20] = KEY_F9, [21] = KEY_F10,
		[23] = KEY_F11, [24] = KEY_F12,
	};

	switch (n) {
	case 1: case 7: return KEY_HOME;
	case 2: return KEY_INSERT;
	case 3: return KEY_DELETE;
	case 4: case 8: return KEY_END;
	case 5: return KEY_PAGEUP;
	case 6: return KEY_PAGEDOWN;
	default: return n < sizeof(fkey) / sizeof(fkey[0]) ? fkey[n] : 0;
	}
}

/* Parses p[0..n) as digits, then optionally ";" and digits (a modifier,
 * ignored). Returns the first number, or -1 if p is not of that form or is
 * empty. */
static long params_number(const uint8_t *p, size_t n)
{
	size_t i = 0;
	long v = 0;

	if (n == 0)
		return -1;
	while (i < n && p[i] >= '0' && p[i] <= '9') {
		if (v < 1000)
			v = v * 10 + (p[i] - '0');
		i++;
	}
	if (i == 0)
		return -1;
	if (i == n)
		return v;
	if (p[i] != ';' || i + 1 == n)
		return -1;
	for (i++; i < n; i++)
		if (p[i] < '0' || p[i] > '9')
			return -1;
	return v;
}

/* Key of a complete sequence seq[0..n) (ESC, '[' or 'O', parameters) with
 * its final byte, or 0. */
static uint16_t seq_key(const uint8_t *seq, size_t n, uint8_t final)
{
	const uint8_t *p = seq + 2;
	size_t np = n - 2;
	long num;

	if (seq[1] == 'O') {
		/* SS3: parameters (a modifier in old xterms) are ignored. */
		for (size_t i = 0; i < np; i++)
			if (p[i] < '0' || p[i] > '9')
				return 0;
		if (final >= 'P' && final <= 'S')
			return (uint16_t)(KEY_F1 + (final - 'P'));
		return cursor_key(final);
	}
	/* CSI. */
	if (np == 1 && p[0] == '[')
		return final >= 'A' && final <= 'E' ? (uint16_t)(KEY_F1 + (final - 'A')) : 0;
	if (final == '~') {
		num = params_number(p, np);
		return num < 0 ? 0 : tilde_key((unsigned)num);
	}
	if (cursor_key(final) == 0)
		return 0;
	/* No parameters, or "1;MOD": a modified cursor key is the key. */
	if (np == 0 || params_number(p, np) == 1)
		return cursor_key(final);
	return 0;
}

static int room(const struct ttyk *k)
{
	return TTYK_QUEUE - k->qlen;
}

static void push(struct ttyk *k, uint16_t code, int32_t value, uint64_t t)
{
	struct in_event *e;

	assert(k->qlen < TTYK_QUEUE);
	e = &k->q[(k->qhead + k->qlen) % TTYK_QUEUE];
	e->time_ns = t;
	e->type = IN_KEY;
	e->code = code;
	e->value = value;
	k->qlen++;
}

/* A byte (or sequence) of key code arrived at t. */
static void key_byte(struct ttyk *k, uint16_t code, uint64_t t)
{
	int i;

	if (k->nheld > 0 && k->held[k->nheld - 1] == code) {
		k->repeat_ns = t;
		k->repeated = 1;
		return;
	}
	for (i = 0; i < k->nheld; i++)
		if (k->held[i] == code)
			break;
	if (i < k->nheld) {
		/* Held already: pressed again, now the one the terminal repeats. */
		memmove(&k->held[i], &k->held[i + 1], (size_t)(k->nheld - 1 - i) * sizeof(k->held[0]));
		k->held[k->nheld - 1] = code;
	} else {
		if (k->nheld == TTYK_HELD) {
			push(k, k->held[0], 0, t);
			memmove(&k->held[0], &k->held[1], (TTYK_HELD - 1) * sizeof(k->held[0]));
			k->nheld--;
		}
		k->held[k->nheld++] = code;
		push(k, code, 1, t);
	}
	k->press_ns = t;
	k->repeated = 0;
}

static void seq_reset(struct ttyk *k)
{
	k->nseq = 0;
	k->skipping = 0;
}

/* Decodes one byte at t. The caller guarantees STEP_ROOM free slots. */
static void decode(struct ttyk *k, uint8_t c, uint64_t t)
{
	uint16_t code;

	if (k->nseq == 0) {
		if (c == ESC) {
			k->seq[0] = ESC;
			k->nseq = 1;
			k->seq_ns = t;
			return;
		}
		code = byte_key(c);
		if (code)
			key_byte(k, code, t);
		return;
	}
	if (k->nseq == 1) {
		if (c == '[' || c == 'O') {
			k->seq[k->nseq++] = c;
		} else if (c == ESC) {
			/* The first ESC stood alone; the second may start a sequence. */
			key_byte(k, KEY_ESC, k->seq_ns);
			k->seq_ns = t;
		} else {
			/* Alt+key: not a key of ours; drop both bytes. */
			seq_reset(k);
		}
		return;
	}
	/* In a CSI or SS3 sequence. */
	if (c >= 0x40 && c <= 0x7e) {
		int console_fkey = k->seq[1] == '[' && k->nseq == 2 && c == '[';

		if (console_fkey) {
			k->seq[k->nseq++] = c;
			return;
		}
		code = k->skipping ? 0 : seq_key(k->seq, k->nseq, c);
		seq_reset(k);
		if (code)
			key_byte(k, code, t);
		return;
	}
	if (c >= 0x20 && c <= 0x3f) {
		/* Parameter or intermediate byte. */
		if (k->nseq < TTYK_SEQ_MAX)
			k->seq[k->nseq++] = c;
		else
			k->skipping = 1;
		return;
	}
	/* A byte no sequence contains (a control byte, DEL, >= 0x80): the
	 * sequence was broken off; drop it and take the byte on its own. */
	seq_reset(k);
	decode(k, c, t);
}

void ttyk_init(struct ttyk *k)
{
	memset(k, 0, sizeof(*k));
	k->first_hold_ns = TTYK_FIRST_HOLD_NS;
	k->repeat_hold_ns = TTYK_REPEAT_HOLD_NS;
	k->esc_wait_ns = TTYK_ESC_WAIT_NS;
}

uint64_t ttyk_deadline(const struct ttyk *k)
{
	if (k->nheld == 0)
		return 0;
	return k->repeated ? k->repeat_ns + k->repeat_hold_ns : k->press_ns + k->first_hold_ns;
}

static void release_held(struct ttyk *k, uint64_t t)
{
	while (k->nheld > 0)
		push(k, k->held[--k->nheld], 0, t);
	k->repeated = 0;
}

void ttyk_expire(struct ttyk *k, uint64_t now_ns)
{
	if (room(k) < EXPIRE_ROOM)
		return;
	if (k->nseq > 0 && now_ns - k->seq_ns >= k->esc_wait_ns) {
		/* Nothing continued it in time. A lone ESC is the Esc key, at
		 * the time its byte was read; a partial sequence is dropped. */
		if (k->nseq == 1)
			key_byte(k, KEY_ESC, k->seq_ns);
		seq_reset(k);
	}
	if (k->nheld > 0 && now_ns >= ttyk_deadline(k))
		release_held(k, now_ns);
}

size_t ttyk_feed(struct ttyk *k, const uint8_t *b, size_t n, uint64_t now_ns)
{
	size_t i;

	/* Releases due before these bytes came must come out first, else a
	 * late read would take a fresh press for a repeat. */
	if (room(k) < EXPIRE_ROOM)
		return 0;
	ttyk_expire(k, now_ns);
	for (i = 0; i < n && room(k) >= STEP_ROOM; i++)
		decode(k, b[i], now_ns);
	return i;
}

int ttyk_take(struct ttyk *k, struct in_event *ev, int max)
{
	int n = 0;

	while (n < max && k->qlen > 0) {
		ev[n++] = k->q[k->qhead];
		k->qhead = (k->qhead + 1) % TTYK_QUEUE;
		k->qlen--;
	}
	return n;
}
