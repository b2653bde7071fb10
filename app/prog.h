/*
 * prog: the game's progress as the daemon logs it: a map's exit, with what
 * the intermission page shows (engine/ui/hud_page.c), so the log of a
 * cabinet, a script or a replay says which maps were finished and how,
 * without looking at the screen (the golden exit recordings' check,
 * tests/replay/run.sh).
 */
#ifndef ARCADED_APP_PROG_H
#define ARCADED_APP_PROG_H

#include <stddef.h>

struct sim;

/* When the tick just run took the current map's exit (the sim entered the
 * intermission on it: phase G_PH_INTER, phase_t 0), writes
 *   "map E1M1: exit taken after 0:01:06 (3977 ticks), kills 13 of 24,
 *    items 3 of 10, secrets 0 of 3, score 3300; next E1M2"
 * (one line; "secret exit taken" for a secret exit; the next map is the
 * stage the exit leads to) to buf, always NUL-terminated, and returns 1;
 * else returns 0 and leaves buf alone. */
int prog_exit(const struct sim *s, char *buf, size_t len);

#endif
