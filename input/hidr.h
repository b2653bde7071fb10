/*
 * hidr: turns HID input reports into control events (struct in_event),
 * using the fields hidd_parse found. Pure: bytes and times in, events out.
 *
 * Events are changes against the previous reports: a report identical to
 * the last one of its id gives nothing. Before the first report every
 * control is released and every axis centred.
 *
 * Controls and their codes (Linux input codes, so bindings name them as
 * they name evdev controls):
 *   - Buttons (Button page usage N, variable or array): player 1
 *     BTN_TRIGGER_HAPPY1 + N - 1, up to N = 36 (N = 20 when the device is
 *     split into two players); player 2 BTN_TRIGGER_HAPPY21 + N - 1 up to
 *     N = 16. Buttons beyond are not reported.
 *   - Directions: player 1 BTN_DPAD_UP, _DOWN, _LEFT, _RIGHT; player 2
 *     BTN_TRIGGER_HAPPY37..40 (up, down, left, right: Linux has no second
 *     d-pad). A direction is held while any of its sources holds it: the
 *     hat switch (8-way, or 4-way when its range has 4 values; diagonals
 *     hold two directions; a value outside the range, the null state, is
 *     centred), the Generic Desktop D-pad usages, and the X and Y axes
 *     through the digital thresholds (joystick as d-pad).
 *   - Keys (Keyboard page, variable bits or arrays): KEY_* by the usual
 *     USB-to-Linux table (hidr.c); a usage with no Linux key is
 *     KEY_UNKNOWN, as in Linux. An array holding ErrorRollOver (too many
 *     keys down) leaves the whole report ignored.
 *   - Axes (IN_ABS): X, Y, Z, Rx, Ry, Rz, Slider, Dial, Wheel give ABS_X,
 *     ABS_Y, ABS_Z, ABS_RX, ABS_RY, ABS_RZ, ABS_THROTTLE, ABS_RUDDER,
 *     ABS_WHEEL; Simulation rudder, throttle, accelerator, brake, steering
 *     give ABS_RUDDER, ABS_THROTTLE, ABS_GAS, ABS_BRAKE, ABS_WHEEL. An axis
 *     whose code a previous axis of the same player took gets the next
 *     free one of those 11 codes (DragonRise pads declare X four times).
 *     Player 2's axes are player 1's code + 16 (ABS_HAT0X..ABS_HAT3Y), for
 *     codes up to ABS_RUDDER. The value is calibrated: -32767 at the
 *     calibration minimum, 0 at its centre, +32767 at its maximum (clamped
 *     beyond), and 0 inside the deadzone. The default calibration is the
 *     logical range with the centre in its middle (rounded down), except
 *     for throttle, accelerator and brake, which rest at their minimum.
 *
 * The look axis (vertical aim, a pad's second stick): player 1's first
 * axis declared as Rz, else as Ry (the second stick's vertical axis on
 * most pads: Z and Rz, or Rx and Ry), or as the Generic Desktop usage the
 * option look names (HIDR_LOOK_NONE: no look axis); by the declared
 * usage, so a repeated X renumbered to ABS_RY is not one; never an axis
 * read as X or Y. It keeps its IN_ABS events and
 * gives two more controls through the digital thresholds, as Y gives up
 * and down: BTN_GEAR_UP when pushed up (negative), BTN_GEAR_DOWN when
 * pulled down (Linux has no code for a second stick's directions; no pad
 * uses these two). The bindings name them (look_up = BTN_GEAR_UP).
 *
 * Digital thresholds: with v the calibrated value, a direction is pressed
 * when |v| reaches press (per mille of full deflection) and released when
 * it falls below release (hysteresis: no chatter at the threshold). Y grows
 * downwards (HID's convention). An axis gives no directions until it has
 * been seen inside its deadzone once, so a dummy axis stuck at one end (the
 * Buzz dongle's X and Y read 0 for ever) or a stick held while the device
 * is plugged in never holds a direction on its own.
 *
 * Two players in one device (only buttons, directions and axes are split;
 * keys stay as they are):
 *   - HIDR_SPLIT_AUTO (default): when two or more application collections
 *     are joysticks or gamepads with inputs, the first is player 1, the
 *     second player 2, and further ones are not reported.
 *   - HIDR_SPLIT_USAGE: in one collection, the second element with the
 *     same usage (a second X, a second Button 1) is player 2's; a third is
 *     not reported.
 *   - HIDR_SPLIT_NONE: everything is player 1.
 *   - Independently, p2_first_button moves buttons N >= p2_first_button to
 *     player 2 as button N - p2_first_button + 1, and p2_x / p2_y name the
 *     Generic Desktop usages (0x30..0x38) read as player 2's X and Y (the
 *     Xin-Mo dual encoder reports player 2 on Z and Rx).
 */
#ifndef ARCADED_INPUT_HIDR_H
#define ARCADED_INPUT_HIDR_H

#include <stddef.h>
#include <stdint.h>

#include "input/hidd.h"
#include "input/in.h"

#define HIDR_FULL 32767             /* calibrated value at full deflection */

enum hidr_split {
	HIDR_SPLIT_AUTO,
	HIDR_SPLIT_NONE,
	HIDR_SPLIT_USAGE,
};

struct hidr_opts {
	int split;                  /* enum hidr_split */
	uint16_t deadzone;          /* per mille of full deflection; default 150 */
	uint16_t press;             /* per mille; default 500 */
	uint16_t release;           /* per mille, <= press; default 350 */
	uint16_t p2_first_button;   /* 0: none */
	uint16_t p2_x, p2_y;        /* Generic Desktop usage ids, 0: none */
	uint16_t look;              /* the look axis: a Generic Desktop usage id,
				       0 auto, HIDR_LOOK_NONE none */
};

#define HIDR_LOOK_NONE 0xffff

struct hidr;

/* The defaults above. */
void hidr_default_opts(struct hidr_opts *o);

/* A decoder for descriptor d, which must outlive it. opts NULL: defaults.
 * 0, -EINVAL (opts out of range: deadzone, press or release above 1000,
 * release above press) or -ENOMEM. */
int hidr_new(const struct hidd_desc *d, const struct hidr_opts *opts, struct hidr **out);

/* NULL-safe. */
void hidr_free(struct hidr *r);

/* The most events one report can give: the size hidr_decode's out needs. */
int hidr_max_events(const struct hidr *r);

/* Decodes one report as hidraw delivers it (the id byte first when the
 * descriptor declares ids). A short report is padded with zeros (as Linux
 * does), extra bytes are ignored. Stores the changes in out (max at least
 * hidr_max_events) stamped time_ns and returns how many; -ENOENT for a
 * report id with no input fields (nothing changes), -EINVAL for an empty
 * report, -ENOSPC when max is too small (nothing changes). */
int hidr_decode(struct hidr *r, const uint8_t *buf, size_t len, uint64_t time_ns,
		struct in_event *out, int max);

/* Replaces the calibration of the axis reported as abs_code (the code
 * events carry, so player 2's are + 16) with raw logical values min <
 * centre < max (min <= centre <= max with min < max). 0, -ENOENT (no such
 * axis), -EINVAL. */
int hidr_calibrate(struct hidr *r, int abs_code, int64_t min, int64_t centre, int64_t max);

/* Appends one line per reported control ("button 3 -> BTN_TRIGGER_HAPPY3 p1")
 * to buf like snprintf; returns the length the whole text needs. */
size_t hidr_describe(const struct hidr *r, char *buf, size_t len);

/* Linux key code of Keyboard page usage id: 0 for the non-key usages 0..3
 * (none, ErrorRollOver, POSTFail, ErrorUndefined), KEY_UNKNOWN for a usage
 * with no Linux key. */
int hidr_key_code(uint32_t usage_id);

#endif
