/*
 * num: checked decimal numbers from text (configuration values, device
 * options, command-line arguments), with a range; hex digits.
 *
 * Why here: the users are in input/ (GPIO and HID options, evdev node
 * numbers), config/ (settings) and app/ (the command line), all above the
 * engine; engine/core is the one place each of them may include. It is
 * pure C library (strtoll), no I/O, no state of its own.
 */
#ifndef ARCADED_ENGINE_NUM_H
#define ARCADED_ENGINE_NUM_H

#include <stdint.h>

/* s as a decimal integer: an optional '+' or '-', then digits, and nothing
 * else (no blanks before or after, no base prefix). Returns 0 and sets
 * *out; -EINVAL, *out unchanged, when s is not such a number; -ERANGE,
 * *out unchanged, when it is outside lo..hi (or int64_t). */
int num_parse(const char *s, int64_t lo, int64_t hi, int64_t *out);

/* The value 0..15 of hex digit c (0-9, a-f, A-F), or -1 for any other
 * character. */
int num_hex(int c);

#endif
