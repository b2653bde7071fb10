/*
 * txt: printf-style text into a caller's buffer, the one copy of each way
 * the project builds messages and descriptions there:
 *   txt_set   a message into err/why buffers that may be absent (NULL or
 *             0 bytes: nothing is written);
 *   txt_put   appending to a struct txt, counting what does not fit, so a
 *             describe function can return the length it needs
 *             (snprintf's rule).
 * (in_say, input/in.h, appends a reason after what a buffer already
 * holds, for the backends.)
 *
 * Why in input/: the users are in input/ (recordings, HID descriptors and
 * decoders) and config/ (settings, bindings, state files), and config is
 * above input; the engine, below, has no stdio (it builds texts with
 * engine/core/msg.h).
 */
#ifndef ARCADED_INPUT_TXT_H
#define ARCADED_INPUT_TXT_H

#include <stddef.h>

/* Formats into buf (len bytes, cut to fit, always NUL-terminated); buf
 * NULL or len 0: nothing. */
void txt_set(char *buf, size_t len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Text built in buf (len bytes; NULL with len 0 only measures). n counts
 * the whole text, also what did not fit; buf holds its first len - 1
 * bytes and a NUL (once anything was put). */
struct txt {
	char *buf;
	size_t len;
	size_t n;
};

/* Appends to t what snprintf would, counting all of it in t->n. */
void txt_put(struct txt *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
