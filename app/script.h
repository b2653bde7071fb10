/*
 * script: a test script (input/scr.h) driving the daemon headless: its
 * press and release steps go to the actions before their tick, like a
 * control's would; after the tick its expects are checked (a failure is
 * logged with file:line and counted), snapshots print the frame and state
 * hashes, screenshots are written.
 */
#ifndef ARCADED_APP_SCRIPT_H
#define ARCADED_APP_SCRIPT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "input/scr.h"

struct cmd_state;
struct r_frame;
struct sim;
struct stats;

struct script {
	const char *path;
	struct scr *scr;
	size_t next;               /* first step not done */
	int failures;              /* expects and screenshots that failed */
	FILE *out;                 /* snapshot lines */
};

/* Loads script path; snapshots print to out. 0 or -errno (logged). */
int script_load(struct script *s, const char *path, FILE *out);

/* Whether tick t is past the script's end. */
int script_over(const struct script *s, uint32_t t);

/* Applies the press/release steps of tick t (before the tick) to cs; a
 * press is an input of source src for the latency statistics st. */
void script_inputs(struct script *s, uint32_t t, struct cmd_state *cs, struct stats *st, int src);

/* Runs the checks and outputs of tick t (after the tick ran, sim s, frame
 * f drawn with palette rgb). */
void script_checks(struct script *s, uint32_t t, const struct sim *sim, const struct r_frame *f,
		   const uint8_t (*rgb)[3]);

/* NULL-safe members. */
void script_free(struct script *s);

#endif
