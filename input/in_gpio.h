/*
 * in_gpio: buttons, coin switches, a coin meter and lamps on GPIO lines,
 * through libgpiod 1.6 (the v1 API Debian 12 ships). The backend is
 * in_gpio (input/in.h); this header has its spec parser and the per-tick
 * output call.
 *
 * Device spec (the path given to in_gpio.open; no blanks needed):
 *   gpio:[CHIP:]LINE=WHAT[,LINE=WHAT...][;OPTION=VALUE...]
 * CHIP: gpiochipN, /dev/gpiochipN, the chip's label or number (as
 * gpiod_chip_open_lookup takes it). Without a chip every LINE must be a
 * line name, looked up on all chips.
 * LINE: an offset on CHIP (decimal) or a line name (gpio-line-names).
 * WHAT: a role, which reports the key MAME's default layout gives it (so
 * the default bindings of config/bind.h already work):
 *   coin KEY_5, coin2 KEY_6 (coin lines: pulse counting, see below),
 *   start KEY_1, start2 KEY_2, service KEY_9, test KEY_F2, tilt KEY_T,
 *   p1_up/down/left/right the arrow keys, p1_button1..6 (p1_fire is
 *   p1_button1) LEFTCTRL LEFTALT SPACE LEFTSHIFT Z X, p2_up/down/left/right
 *   R F D G, p2_button1..4 A S Q W;
 * or any key name in_key_from_name accepts (KEY_E, BTN_TRIGGER_HAPPY3, e).
 * OPTION:
 *   meter=LINE        output: coin meter coil, one pulse per coin the game
 *                     accepts (in_gpio_update)
 *   lamp_start=LINE   output: start button lamp (blinks with credits)
 *   active=low|high   inputs (default low: a switch to ground)
 *   bias=pull-up|pull-down|disable|as-is   inputs (default pull-up)
 *   out_active=high|low   outputs (default high)
 *   holdoff_ms=N      debounce hold-off, 1..1000 (default 5)
 *   coin_min_ms=N, coin_max_ms=N   accepted coin pulse widths (10, 250)
 *   meter_ms=N        meter pulse and gap, 1..10000 (default 50)
 *   blink_ms=N        start lamp half period, 1..10000 (default 250)
 * Example: gpio:gpiochip0:5=coin,6=start,7=p1_fire;meter=12;lamp_start=13
 *
 * Inputs are requested for both edges with the bias and active-low flags,
 * so a pressed switch reads 1 and the kernel stamps each edge
 * (CLOCK_MONOTONIC since Linux 5.7; a stamp more than 10 s from
 * in_now_ns() is replaced by in_now_ns()). Each edge goes through the
 * software debounce of input/deb.h (first edge reported at once, no added
 * latency). The v1 interface samples a line's level when its IRQ thread
 * runs, so edges close together can merge and the last event may not
 * carry the level the line settled at: once a line's hold-off is over,
 * each read also reads the line's level and takes it as the truth
 * (deb_settle: a change is stamped with its edge's time when the last
 * event agrees, else with the time of the read), so a lost edge costs at
 * most one tick and never leaves a button stuck. A coin line reports
 * nothing while the pulse runs: each pulse
 * within the accepted widths gives one press and one release of its key,
 * both stamped at the pulse's end; others are counted as rejected (in
 * describe). A line that is active when the device opens (a held button)
 * is reported pressed at the first read.
 *
 * Polling: every line has its own event fd; fd() returns one epoll fd that
 * holds them all (readable when any line has an edge), so the app polls
 * one fd per GPIO device. The app must still call read every tick even
 * when that fd is quiet: releases that settle inside a hold-off and coin
 * pulse ends are found by time, not by edges. Unplugging the chip (a
 * gpio-sim bank going away) reads as -ENODEV.
 *
 * Outputs are driven only from in_gpio_update (the backend's outputs
 * entry), which the app calls every tick with the game's state
 * (input/gpo.h): the meter pulses once per new coin, the start lamp
 * blinks while credits are available outside play. close() switches them
 * off.
 */
#ifndef ARCADED_INPUT_IN_GPIO_H
#define ARCADED_INPUT_IN_GPIO_H

#include <stddef.h>
#include <stdint.h>

#include "input/gpo.h"
#include "input/in.h"

#define IN_GPIO_MAX_LINES 32

enum in_gpio_bias {
	IN_GPIO_BIAS_PULL_UP,
	IN_GPIO_BIAS_PULL_DOWN,
	IN_GPIO_BIAS_DISABLE,
	IN_GPIO_BIAS_AS_IS,
};

struct in_gpio_line {
	char name[32];           /* line name; "" when given by offset */
	int offset;              /* -1 when given by name (or absent: an output not set) */
	int code;                /* inputs: the key code reported */
	int coin;                /* inputs: a coin line */
};

struct in_gpio_spec {
	char chip[64];           /* "": lines by name on any chip */
	struct in_gpio_line in[IN_GPIO_MAX_LINES];
	int nin;
	struct in_gpio_line meter, lamp_start;   /* absent: offset -1 and name "" */
	int active_low;
	int bias;                /* enum in_gpio_bias */
	int out_active_low;
	uint64_t holdoff_ns, coin_min_ns, coin_max_ns, meter_ns, blink_ns;
};

/* Parses spec s into out (defaults filled). 0 or -EINVAL with the reason
 * in why. */
int in_gpio_parse_spec(const char *s, struct in_gpio_spec *out, char *why, size_t whylen);

/* Lists every GPIO chip and its lines for `arcaded devices`, one chip per
 * line ("gpiochip0 [pinctrl-bcm2711] 58 lines") and one line per GPIO line
 * ("  5 COIN1 input, used by arcaded"; an unnamed line shows "-"), into a
 * new NUL-terminated *text (free()); "" when there is no chip. 0 or
 * -ENOMEM. */
int in_gpio_list(char **text);

/* Drives d's output lines for the game state s at time now_ns (call once
 * per tick; d must come from in_gpio.open). 0, or -ENODEV when a line
 * could not be set (the chip went away). */
int in_gpio_update(struct in_dev *d, const struct gpo_state *s, uint64_t now_ns);

#endif
