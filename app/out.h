/*
 * out: the cabinet's outputs follow the game, once per tick: each input
 * device with outputs (in_backend.outputs: GPIO's coin meter and start
 * lamp, input/gpo.h) gets the game's coins, credits and whether a game is
 * being played. A device whose outputs went away is dropped like one whose
 * read did (its controls released, reopened later). Sound will join here.
 */
#ifndef ARCADED_APP_OUT_H
#define ARCADED_APP_OUT_H

struct sim;
struct slot_set;

/* Drives every open slot's outputs for the state of s. */
void out_update(struct slot_set *set, const struct sim *s);

#endif
