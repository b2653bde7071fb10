/*
 * Test fixture: the HID descriptor and report captures in tests/data/hid/
 * (formats in its README: hex bytes separated by blanks, one report per
 * line). Paths are relative to the repository root, where the test runners
 * start the tests. Shared by test_hidd and test_hidr.
 */
#ifndef ARCADED_TESTS_HID_FIXTURE_H
#define ARCADED_TESTS_HID_FIXTURE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/core/num.h"

#define FIX_DIR "tests/data/hid/"
#define FIX_MAX_REPORTS 512
#define FIX_REPORT_MAX 64

struct fix_reports {
	int n;
	size_t len[FIX_MAX_REPORTS];
	uint8_t b[FIX_MAX_REPORTS][FIX_REPORT_MAX];
};

/* Reads the hex bytes of FIX_DIR name into buf; a newline ends a report
 * when lines is set. Returns bytes read (all lines), or -1 if the file is
 * missing or malformed. */
static inline long fix_read(const char *name, uint8_t *buf, size_t cap, struct fix_reports *lines)
{
	char path[256];
	FILE *f;
	int c, hi = -1;
	long n = 0;

	snprintf(path, sizeof(path), FIX_DIR "%s", name);
	f = fopen(path, "r");
	if (!f) {
		fprintf(stderr, "cannot open %s (run from the repository root)\n", path);
		return -1;
	}
	if (lines)
		memset(lines, 0, sizeof(*lines));
	while ((c = fgetc(f)) != EOF) {
		int v = num_hex(c);

		if (v >= 0) {
			if (hi < 0) {
				hi = v;
				continue;
			}
			v |= hi << 4;
			hi = -1;
			if (lines) {
				if (lines->n >= FIX_MAX_REPORTS || lines->len[lines->n] >= FIX_REPORT_MAX)
					break;
				lines->b[lines->n][lines->len[lines->n]++] = (uint8_t)v;
			} else {
				if ((size_t)n >= cap)
					break;
				buf[n] = (uint8_t)v;
			}
			n++;
		} else if (hi >= 0) {
			break;   /* odd digit count */
		} else if (c == '\n' && lines && lines->n < FIX_MAX_REPORTS &&
			   lines->len[lines->n] > 0) {
			lines->n++;
		}
	}
	fclose(f);
	if (c != EOF || hi >= 0)
		return -1;
	if (lines && lines->n < FIX_MAX_REPORTS && lines->len[lines->n] > 0)
		lines->n++;
	return n;
}

/* Every descriptor fixture, with the input report lengths its source README
 * lists ("In" column: id:bytes, the id byte counted). */
static const struct fix_desc {
	const char *name;
	int bytes;
	struct { int id, len; } in[7];
} fix_descs[] = {
	{ "054C_0268_dualshock3-usb", 148, { { 1, 49 } } },
	{ "054C_09CC_dualshock4-v2-usb", 507, { { 1, 64 } } },
	{ "054C_0CE6_dualsense-usb", 273, { { 1, 64 } } },
	{ "057E_2009_switch-pro-usb", 203, { { 0x21, 64 }, { 0x30, 64 }, { 0x81, 64 } } },
	{ "18D1_9400_stadia-usb", 156, { { 3, 10 } } },
	{ "1949_0419_luna-usb-hid", 93, { { 1, 10 } } },
	{ "045E_02FD_xbox-one-s-bt", 334, { { 1, 17 }, { 2, 2 }, { 4, 2 } } },
	{ "045E_0B13_xbox-series-ble", 283, { { 1, 17 } } },
	{ "045E_02E0_gamesir-nova-lite-2-bt", 306, { { 1, 16 }, { 2, 2 }, { 4, 2 } } },
	{ "06A3_FF0D_saitek-ff-gamepad", 625, { { 1, 7 }, { 2, 3 } } },
	{ "18D1_2C40_asus-gamepad", 193, { { 1, 9 }, { 3, 8 } } },
	{ "046D_C283_wingman-force-3d", 171, { { 0, 7 } } },
	{ "054C_1000_buzz-4p", 78, { { 0, 5 } } },
	{ "0458_4018_genius-imperator-keyboard", 62, { { 0, 8 } } },
	{ "046A_0011_cherry-keyboard", 66, { { 0, 8 } } },
	{ "quirks/045E_02E0_gulikit-es-pro-bt-trailing-nul", 307, { { 1, 16 }, { 2, 2 }, { 4, 2 } } },
	{ "quirks/15E4_0132_ion-icade-bt", 261,
	  { { 1, 9 }, { 2, 4 }, { 3, 2 }, { 4, 2 }, { 5, 2 }, { 0xff, 2 } } },
};

#define FIX_NDESC (sizeof(fix_descs) / sizeof(fix_descs[0]))

/* Loads descriptor fixture name (without .rdesc). */
static inline long fix_desc(const char *name, uint8_t *buf, size_t cap)
{
	char file[200];

	snprintf(file, sizeof(file), "%s.rdesc", name);
	return fix_read(file, buf, cap, NULL);
}

/* Loads report fixture name (without .reports). */
static inline int fix_reports(const char *name, struct fix_reports *r)
{
	char file[200];

	snprintf(file, sizeof(file), "%s.reports", name);
	return fix_read(file, NULL, 0, r) < 0 ? -1 : r->n;
}

#endif
