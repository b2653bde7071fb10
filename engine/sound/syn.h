/*
 * syn: the project's own sound synthesizer, which makes the built-in
 * sound set (like the built-in textures: no sound data is shipped).
 *
 * Each sound (enum sfx_id, sfx.h) is a recipe: a few parts, each one
 * waveform (square, triangle, sawtooth, sine from the engine's sine
 * table, or noise from a fixed-seed xorshift) gliding linearly from one
 * frequency to another, under an envelope that rises linearly for
 * `attack` ms, holds, and falls linearly to silence at the part's end.
 * The parts are summed and clipped to 16 bits. Integer arithmetic only:
 * every build, compiler and CPU makes the same samples, so they can take
 * part in the audio hash of every replay.
 */
#ifndef ARCADED_ENGINE_SYN_H
#define ARCADED_ENGINE_SYN_H

#include <stdint.h>

/* The built-in sounds' sample rate. */
#define SYN_RATE 22050

/* Samples of sound id (0 for SFX_NONE and ids out of range). */
uint32_t syn_len(int id);

/* Writes sound id's syn_len(id) samples to out, summing its parts in acc
 * (both with room for syn_len(id) values); returns that count. */
uint32_t syn_make(int id, int16_t *out, int32_t *acc);

#endif
