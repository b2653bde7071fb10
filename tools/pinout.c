/*
 * pinout: draws the 40-pin header of a Raspberry Pi (the common cabinet
 * single-board computer) with the lines a GPIO device spec uses, as a PNG
 * for docs/operator.md:
 *
 *   pinout 'gpio:gpiochip0:5=coin,6=start,7=p1_fire;meter=12;lamp_start=13' out.png
 *
 * The spec is parsed by the daemon's own parser (in_gpio_parse_spec), so the
 * picture shows what the daemon would open; each input is labelled with
 * the key it reports and the actions the default [keyboard] bindings give
 * that key (bind_defaults). Drawing is the engine's 2D module (v_video:
 * boxes and the 8x8 font) into an 8-bit frame, written by the daemon's
 * screenshot writer (shot_png), so the same build makes the same bytes.
 *
 * Line offsets are taken as Broadcom GPIO numbers, which is what gpiochip0
 * numbers on a Raspberry Pi 1..4; a line given by name must be "GPIOn"
 * (the Pi's line names). A chip other than gpiochip0 / 0, or a line the
 * header does not carry, is refused with the reason.
 *
 * Exit status 0, 1 on a spec the picture cannot show, 2 on bad usage or an
 * I/O error.
 */
#include <ctype.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "config/bind.h"
#include "display/shot.h"
#include "engine/render/r_main.h"
#include "engine/ui/v_video.h"
#include "input/act.h"
#include "input/in.h"
#include "input/in_gpio.h"

#define PO_W 1040
#define PO_ROWS 20
#define PO_TOP 96                      /* first pin row */
#define PO_ROW 26                      /* row pitch */
#define PO_PIN 18                      /* pin square */
#define PO_HX 488                      /* header's left edge */
#define PO_HW 64                       /* header width */
#define PO_H (PO_TOP + PO_ROWS * PO_ROW + 112)

/* Physical pin (1..40) to Broadcom GPIO number; power and ground as
 * negative codes. */
enum { PO_3V3 = -1, PO_5V = -2, PO_GND = -3 };
static const int po_pins[40] = {
	PO_3V3, PO_5V, 2, PO_5V, 3, PO_GND, 4, 14, PO_GND, 15,
	17, 18, 27, PO_GND, 22, 23, PO_3V3, 24, 10, PO_GND,
	9, 25, 11, 8, PO_GND, 7, 0, 1, 5, PO_GND,
	6, 12, 13, PO_GND, 19, 16, 26, 20, PO_GND, 21,
};

enum { C_BG, C_BOARD, C_TEXT, C_DIM, C_GND, C_3V3, C_5V, C_GPIO, C_IN, C_COIN, C_OUT, C_COUNT };
static const uint8_t po_rgb[C_COUNT][3] = {
	[C_BG] = { 250, 250, 245 }, [C_BOARD] = { 20, 90, 50 },  [C_TEXT] = { 20, 20, 20 },
	[C_DIM] = { 140, 140, 140 }, [C_GND] = { 0, 0, 0 },      [C_3V3] = { 230, 140, 20 },
	[C_5V] = { 210, 30, 30 },    [C_GPIO] = { 190, 190, 190 }, [C_IN] = { 40, 160, 60 },
	[C_COIN] = { 200, 170, 0 },  [C_OUT] = { 40, 90, 220 },
};

/* What a Broadcom line does in the spec: its colour and label (""
 * when unused). */
struct po_use {
	int colour;
	char label[48];
};

/* The Broadcom number of a spec line, or -1. */
static int po_bcm(const struct in_gpio_line *l)
{
	const char *p = l->name;

	if (l->offset >= 0)
		return l->offset;
	if (strncmp(p, "GPIO", 4) != 0 || !isdigit((unsigned char)p[4]))
		return -1;
	return atoi(p + 4);
}

static int po_on_header(int bcm)
{
	for (int i = 0; i < 40; i++)
		if (po_pins[i] == bcm)
			return 1;
	return 0;
}

static void po_upper(char *s)
{
	for (; *s; s++)
		*s = *s == '_' ? ' ' : (char)toupper((unsigned char)*s);
}

/* Label of an input: "COIN  KEY_5" (the actions its key triggers with the
 * default bindings, then the key). */
static void po_input_label(const struct bind_table *b, const struct in_gpio_line *l, char *out,
			   size_t len)
{
	int acts[ACT_COUNT];
	int n = bind_lookup(b, l->code, acts, ACT_COUNT);
	const char *key = in_key_name(l->code);
	char what[32] = "";

	for (int i = 0; i < n; i++) {
		size_t k = strlen(what);
		snprintf(what + k, sizeof(what) - k, "%s%s", k ? "/" : "", act_name(acts[i]));
	}
	if (!n)
		snprintf(what, sizeof(what), "unbound");
	po_upper(what);
	snprintf(out, len, "%s  %s", what, key ? key : "?");
}

static int po_fill_uses(const struct in_gpio_spec *sp, struct po_use use[64], char *why,
			size_t whylen)
{
	struct bind_table b;
	const struct in_gpio_line *outs[2] = { &sp->meter, &sp->lamp_start };
	static const char *const out_names[2] = { "COIN METER (OUTPUT)", "START LAMP (OUTPUT)" };

	bind_defaults(&b);
	for (int i = 0; i < sp->nin + 2; i++) {
		const struct in_gpio_line *l = i < sp->nin ? &sp->in[i] : outs[i - sp->nin];
		int bcm;

		if (i >= sp->nin && l->offset < 0 && !l->name[0])
			continue;      /* output not set */
		bcm = po_bcm(l);
		if (bcm < 0 || bcm >= 64 || !po_on_header(bcm)) {
			if (l->offset >= 0)
				snprintf(why, whylen, "line %d is not a GPIO of the 40-pin header",
					 l->offset);
			else
				snprintf(why, whylen, "line '%.31s' is not a GPIO of the 40-pin header",
					 l->name);
			return -1;
		}
		if (i < sp->nin) {
			use[bcm].colour = l->coin ? C_COIN : C_IN;
			po_input_label(&b, l, use[bcm].label, sizeof(use[bcm].label));
		} else {
			use[bcm].colour = C_OUT;
			snprintf(use[bcm].label, sizeof(use[bcm].label), "%s", out_names[i - sp->nin]);
		}
	}
	return 0;
}

/* One pin: its square, its number inside the header, and its label
 * outside (left of odd pins, right of even ones). */
static void po_pin(struct r_frame *f, int pin, const struct po_use *use)
{
	int code = po_pins[pin - 1];
	int row = (pin - 1) / 2, left = pin % 2;
	int y = PO_TOP + row * PO_ROW;
	int px = left ? PO_HX + 8 : PO_HX + PO_HW - 8 - PO_PIN;
	int colour = C_GPIO, tc = C_DIM;
	char label[64], num[12];

	if (code == PO_GND) {
		colour = C_GND;
		tc = C_TEXT;
		snprintf(label, sizeof(label), "GND");
	} else if (code == PO_3V3 || code == PO_5V) {
		colour = code == PO_3V3 ? C_3V3 : C_5V;
		tc = C_TEXT;
		snprintf(label, sizeof(label), "%s", code == PO_3V3 ? "3.3V" : "5V");
	} else if (use[code].label[0]) {
		colour = use[code].colour;
		tc = C_TEXT;
		if (left)
			snprintf(label, sizeof(label), "%s  GPIO%d", use[code].label, code);
		else
			snprintf(label, sizeof(label), "GPIO%d  %s", code, use[code].label);
	} else {
		snprintf(label, sizeof(label), "GPIO%d", code);
	}
	v_fill(f, px, y, PO_PIN, PO_PIN, (uint8_t)colour);
	v_box(f, px, y, PO_PIN, PO_PIN, C_TEXT);
	snprintf(num, sizeof(num), "%d", pin);
	if (left) {
		v_text(f, PO_HX - 6 - v_text_width(num, 1), y + 5, 1, C_DIM, num);
		v_text(f, PO_HX - 32 - v_text_width(label, 2), y + 1, 2, (uint8_t)tc, label);
	} else {
		v_text(f, PO_HX + PO_HW + 6, y + 5, 1, C_DIM, num);
		v_text(f, PO_HX + PO_HW + 32, y + 1, 2, (uint8_t)tc, label);
	}
}

static void po_legend(struct r_frame *f, int x, int y, int colour, const char *text)
{
	v_fill(f, x, y, 16, 16, (uint8_t)colour);
	v_box(f, x, y, 16, 16, C_TEXT);
	v_text(f, x + 24, y, 2, C_TEXT, text);
}

static void po_draw(struct r_frame *f, const char *spec, const struct in_gpio_spec *sp,
		    const struct po_use *use)
{
	int y = PO_TOP + PO_ROWS * PO_ROW + 14;
	char line[128];

	v_fill(f, 0, 0, f->w, f->h, C_BG);
	v_text(f, 16, 12, 3, C_TEXT, "ARCADED GPIO WIRING");
	v_text(f, 16, 44, 2, C_TEXT, "RASPBERRY PI 40-PIN HEADER, PIN 1 AS MARKED ON THE BOARD");
	snprintf(line, sizeof(line), "SPEC %.110s", spec);
	v_text(f, 16, 70, 1, C_DIM, line);
	v_fill(f, PO_HX, PO_TOP - 8, PO_HW, PO_ROWS * PO_ROW + 8, C_BOARD);
	for (int pin = 1; pin <= 40; pin++)
		po_pin(f, pin, use);
	snprintf(line, sizeof(line), "SWITCHES: PIN TO GND, ACTIVE %s, BIAS %s",
		 sp->active_low ? "LOW" : "HIGH",
		 sp->bias == IN_GPIO_BIAS_PULL_UP     ? "PULL-UP" :
		 sp->bias == IN_GPIO_BIAS_PULL_DOWN   ? "PULL-DOWN" :
		 sp->bias == IN_GPIO_BIAS_DISABLE     ? "NONE" : "AS IS");
	if (!sp->active_low)
		snprintf(line, sizeof(line), "SWITCHES: PIN TO 3.3V, ACTIVE HIGH");
	v_text(f, 16, y, 2, C_TEXT, line);
	v_text(f, 16, y + 22, 2, C_TEXT, "OUTPUTS ARE 3.3V LOGIC: DRIVE THE METER COIL");
	v_text(f, 16, y + 40, 2, C_TEXT, "AND THE LAMP THROUGH A TRANSISTOR OR RELAY BOARD");
	po_legend(f, 16, y + 70, C_IN, "BUTTON");
	po_legend(f, 176, y + 70, C_COIN, "COIN SWITCH");
	po_legend(f, 400, y + 70, C_OUT, "OUTPUT");
	po_legend(f, 560, y + 70, C_GND, "GND");
	po_legend(f, 672, y + 70, C_3V3, "3.3V");
	po_legend(f, 800, y + 70, C_5V, "5V");
	po_legend(f, 896, y + 70, C_GPIO, "FREE");
}

int main(int argc, char **argv)
{
	static struct in_gpio_spec sp;
	static struct po_use use[64];
	static uint8_t px[PO_W * PO_H];
	uint8_t rgb[256][3] = { { 0 } };
	struct r_frame f = { px, PO_W, PO_H, PO_W, NULL };
	char why[160];
	int rc;

	if (argc != 3) {
		fprintf(stderr, "usage: pinout 'gpio:gpiochip0:LINE=WHAT,...' out.png\n");
		return 2;
	}
	if (in_gpio_parse_spec(argv[1], &sp, why, sizeof(why)) < 0) {
		fprintf(stderr, "pinout: %s: %s\n", argv[1], why);
		return 1;
	}
	if (sp.chip[0] && strcmp(sp.chip, "gpiochip0") && strcmp(sp.chip, "/dev/gpiochip0") &&
	    strcmp(sp.chip, "0")) {
		fprintf(stderr, "pinout: chip '%s': only gpiochip0 (the header's chip on a Pi 1..4) is drawn\n",
			sp.chip);
		return 1;
	}
	if (po_fill_uses(&sp, use, why, sizeof(why)) < 0) {
		fprintf(stderr, "pinout: %s\n", why);
		return 1;
	}
	memcpy(rgb, po_rgb, sizeof(po_rgb));
	po_draw(&f, argv[1], &sp, use);
	rc = shot_png(argv[2], px, PO_W, PO_H, PO_W, (const uint8_t(*)[3])rgb);
	if (rc < 0) {
		fprintf(stderr, "pinout: %s: %s\n", argv[2], strerror(-rc));
		return 2;
	}
	return 0;
}
