/*
 * msg: appending to a message buffer (msg.c).
 *
 * Every function appends to the NUL-terminated text already in buf (of
 * size len), truncating at len; they do nothing when buf is NULL or len is
 * 0. They call nothing else in the engine.
 */
#ifndef ARCADED_ENGINE_MSG_H
#define ARCADED_ENGINE_MSG_H

#include <stddef.h>
#include <stdint.h>

#include "engine/core/fx.h"

/* Appends s. */
void msg_cat(char *buf, size_t len, const char *s);
/* Appends v in decimal. */
void msg_int(char *buf, size_t len, int64_t v);
/* Appends a 16.16 value in decimal, up to 5 decimals, truncated, trailing
 * zeros dropped ("-1.5", "3"). */
void msg_fx(char *buf, size_t len, fx_t v);

#endif
