/*
 * ttyk: the terminal key decoder behind in_tty. Pure: no I/O, no clock;
 * the caller feeds the bytes a read returned together with the time of the
 * read, and asks for synthesized releases as time passes.
 *
 * Bytes to keys (Linux KEY_* codes):
 *   a-z and A-Z           KEY_A..KEY_Z (shift is not reported)
 *   0-9                   KEY_0..KEY_9
 *   space , . - = / ; ' [ ] \ `   their US-layout keys
 *   \r or \n              KEY_ENTER
 *   \t                    KEY_TAB
 *   0x7f or 0x08          KEY_BACKSPACE
 *   ESC alone             KEY_ESC (see esc_wait_ns)
 *   ESC [ A/B/C/D, ESC O A/B/C/D       arrows (CSI form may carry "1;mod",
 *                                      the modifier is ignored)
 *   ESC [ H/F, ESC O H/F               home, end
 *   ESC O P/Q/R/S, ESC [ [ A..E        F1-F4, F1-F5 (Linux console)
 *   ESC [ n ~ (optionally n;mod ~)     1/7 home, 2 insert, 3 delete,
 *                                      4/8 end, 5 pgup, 6 pgdn, 11-15 F1-F5,
 *                                      17-21 F6-F10, 23-24 F11-F12
 * Everything else is consumed and dropped: other control bytes, bytes >=
 * 0x80 (UTF-8), ESC followed by a printable byte (Alt+key), and any CSI or
 * SS3 sequence not listed (terminal replies, bracketed-paste markers, ...).
 *
 * A terminal sends bytes for key presses and autorepeat only, never for a
 * release, and repeats only the most recently pressed key. So:
 *   - A key's first byte is its press. A byte of the newest held key is a
 *     repeat (nothing delivered). A byte of an older held key makes it the
 *     newest again (nothing delivered: it is already down).
 *   - A different key does not release the keys already down (holding
 *     forward while tapping turn keeps going forward); the terminal stops
 *     repeating them, so their state is unknown from then on.
 *   - When the newest key's hold-off expires, every held key is released:
 *     first_hold_ns after its press if no repeat came (shorter than the
 *     menu's repeat delay, so a tap moves its cursor once; see
 *     TTYK_FIRST_HOLD_NS), else repeat_hold_ns after its last repeat (a
 *     few missed repeat intervals). The first repeat of a key released so
 *     is its press again.
 *   - At most TTYK_HELD keys are down; a press beyond that releases the
 *     oldest first.
 * Consequence: a tap reads as a press of about first_hold_ns; a held key
 * reads as a press, a release between first_hold_ns and the terminal's
 * first repeat, and a press again; a key held while another is tapped is
 * released with the tapped one.
 *
 * A lone ESC is ambiguous with the start of a sequence split across reads:
 * it stays pending, and becomes KEY_ESC when no byte continued it within
 * esc_wait_ns (or when the next byte cannot continue a sequence, such as
 * another ESC). An unfinished sequence older than esc_wait_ns is dropped.
 *
 * Decoded events go to an internal queue the caller drains with ttyk_take;
 * ttyk_feed consumes only as many bytes as the queue has room for. Times
 * passed in must never decrease.
 */
#ifndef ARCADED_INPUT_TTYK_H
#define ARCADED_INPUT_TTYK_H

#include <stddef.h>
#include <stdint.h>

#include "input/in.h"

/* 200 ms: a tap must read as a press shorter than the service menu's
 * repeat delay (20 ticks, 333 ms, engine/game/sim.c), with room for a late
 * tick or two, so that one tap moves the cursor once. Terminals start
 * repeating a held key later (250 ms on the Linux console, 500 ms in
 * GNOME): a held key reads as a press of 200 ms, a release, and a press
 * again from its first repeat on. */
#define TTYK_FIRST_HOLD_NS  200000000u
#define TTYK_REPEAT_HOLD_NS 150000000u   /* 150 ms: repeat intervals are 30-100 ms */
#define TTYK_ESC_WAIT_NS     50000000u   /* 50 ms: bytes of one key arrive together */

#define TTYK_HELD 8       /* keys down at once */
#define TTYK_SEQ_MAX 16   /* longest escape sequence kept; longer ones are skipped */
#define TTYK_QUEUE 64     /* decoded events not yet taken */

struct ttyk {
	/* Timing, set to the defaults above by ttyk_init; the caller may
	 * change them before feeding. */
	uint64_t first_hold_ns, repeat_hold_ns, esc_wait_ns;

	/* Escape sequence in progress (starts with ESC), its first byte's time. */
	uint8_t seq[TTYK_SEQ_MAX];
	size_t nseq;
	uint64_t seq_ns;
	int skipping;             /* overlong CSI: drop bytes up to its final byte */

	/* Keys down, oldest first; the last is the one the terminal repeats. */
	uint16_t held[TTYK_HELD];
	int nheld;
	uint64_t press_ns;        /* newest key's (re)press */
	uint64_t repeat_ns;       /* newest key's last repeat */
	int repeated;             /* a repeat of the newest key arrived */

	struct in_event q[TTYK_QUEUE];
	int qhead, qlen;
};

/* Resets k: nothing held, nothing pending, default timing. */
void ttyk_init(struct ttyk *k);

/* Decodes up to n bytes read at now_ns. Returns how many were consumed
 * (fewer than n only when the event queue is full: take, then feed the
 * rest). Releases due at now_ns are queued before the bytes are decoded. */
size_t ttyk_feed(struct ttyk *k, const uint8_t *b, size_t n, uint64_t now_ns);

/* Queues what time alone decides at now_ns: the releases whose hold-off
 * has passed, a pending lone ESC, the drop of a stale partial sequence. */
void ttyk_expire(struct ttyk *k, uint64_t now_ns);

/* Moves up to max queued events, oldest first, into ev; returns how many. */
int ttyk_take(struct ttyk *k, struct in_event *ev, int max);

/* Time at which the held keys will be released (0: none held), for a
 * caller that sleeps instead of polling every tick. */
uint64_t ttyk_deadline(const struct ttyk *k);

#endif
