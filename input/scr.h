/*
 * scr: the test-script format that drives the daemon headless.
 *
 * One step per line; '#' starts a comment; blank lines are ignored.
 *   TICK press ACTION          action held from TICK on
 *   TICK release ACTION        released at TICK
 *   TICK hold ACTION N         pressed at TICK, released at TICK+N
 *   TICK tap ACTION            pressed at TICK, released at TICK+1
 *   TICK expect FIELD OP VALUE check after TICK's tick ran
 *   TICK snapshot              print the frame hash of TICK
 *   TICK screenshot FILE       write TICK's frame as PNG
 *   TICK end                   stop after TICK
 * FIELD: the sim's named values (sim_field_*, engine/game/sim_field.c; listed in
 * docs/game.md): x y z (map units, decimals allowed), angle (degrees,
 * integer), sector, credits, coins, tick, mode (attract|play|gameover|
 * initials|service), and the game's: score, lives, health, ammo, stage,
 * enemies, kills, continues, countdown, page (title|scores|demo), phase,
 * plays, rank, hiscore, menu, difficulty. OP: == != < <= > >=.
 * Steps run in tick order; steps of one tick in file order. A run without
 * `end` stops after the last step's tick.
 *
 * Details: TICK is a decimal 0..4294967295; words are separated by blanks
 * and are case-sensitive; hold needs N >= 1 and becomes a press and a
 * release step (tap: N = 1). x/y/z take up to 12 fraction digits and are
 * rounded to the nearest 1/65536 (halves away from zero), range
 * -32768..32767.99998; angle is an int32; the other numbers are
 * 0..4294967295; mode and page take == and != only. FILE is the rest of the line,
 * blanks trimmed ('#' still starts a comment). A second `end`, and a
 * press/expect/snapshot/screenshot after `end`, are errors (they would
 * never run); releases after it are allowed.
 */
#ifndef ARCADED_INPUT_SCR_H
#define ARCADED_INPUT_SCR_H

#include <stddef.h>
#include <stdint.h>

enum scr_op { SCR_PRESS, SCR_RELEASE, SCR_EXPECT, SCR_SNAPSHOT, SCR_SCREENSHOT, SCR_END };
/* The first fields by name; a step's field is any sim field index
 * (0 .. sim_field_count() - 1), these nine being the first. */
enum scr_field { SCR_F_X, SCR_F_Y, SCR_F_Z, SCR_F_ANGLE, SCR_F_SECTOR, SCR_F_CREDITS,
		 SCR_F_COINS, SCR_F_TICK, SCR_F_MODE };
enum scr_cmp { SCR_EQ, SCR_NE, SCR_LT, SCR_LE, SCR_GT, SCR_GE };

struct scr_step {
	uint32_t tick;
	uint32_t line;           /* source line, for messages */
	enum scr_op op;
	int action;              /* press/release: enum act */
	enum scr_field field;    /* expect: a sim field index (sim_field_value) */
	enum scr_cmp cmp;        /* expect */
	int64_t value;           /* expect: as sim_field_value gives it (16.16, degrees,
				  * enum sim_mode / sim_page, else the integer) */
	char *path;              /* screenshot: owned by the script */
};

struct scr {
	struct scr_step *steps;  /* sorted by tick, stable */
	size_t n;
	uint32_t end_tick;       /* last tick to run */
};

/* Parses text (len bytes, need not be NUL-terminated, any bytes). Stops at
 * the first error: -EINVAL with "NAME:LINE: reason" in err ("unknown action
 * 'jump'", "expected a tick number, got 'x'", "unknown field 'hp'", "bad
 * value 'abc' for x", ...); -ENOMEM. On success *out is the caller's, freed
 * with scr_free. */
int scr_parse(const char *text, size_t len, const char *name, struct scr **out, char *err,
	      size_t errlen);
/* Reads (at most 1 MiB, else -EFBIG) and parses a file; -errno with
 * "PATH: reason" in err, or scr_parse's errors with NAME = path. */
int scr_load(const char *path, struct scr **out, char *err, size_t errlen);
/* NULL-safe. */
void scr_free(struct scr *s);

/* Evaluates a comparison: returns 1 if (actual OP expected) holds. */
int scr_compare(int64_t actual, enum scr_cmp cmp, int64_t expected);
const char *scr_field_name(enum scr_field f);
const char *scr_cmp_name(enum scr_cmp c);

#endif
