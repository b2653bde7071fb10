/*
 * hidd: the HID report descriptor parser (HID 1.11, section 6.2.2). Pure:
 * bytes in, a list of input fields out; no I/O.
 *
 * What it understands:
 *   - short items of every type; long items (prefix 0xFE) are skipped whole
 *     (the spec defines no long item tags); reserved-type items are skipped;
 *   - global items: usage page, logical and physical min/max, unit and
 *     exponent (read, unused), report size, report id, report count,
 *     push and pop;
 *   - local items: usage, usage minimum/maximum (ranges), designators and
 *     strings (read, unused), delimiters (only the first usage of a
 *     delimited set counts, as in Linux). A 4-byte usage is an extended
 *     usage (page in the high 16 bits); a shorter one takes the usage page
 *     in effect when the usage item is read;
 *   - main items: input, output, feature, collection, end collection. Only
 *     input items become fields; output and feature items are checked for
 *     the same size limits and otherwise ignored. A main item with another
 *     tag (tag 0: the single 0x00 some Bluetooth firmware puts after the
 *     last End Collection) is ignored, as Linux does.
 *   - Logical Minimum is signed; Logical Maximum is signed when the minimum
 *     is negative and unsigned otherwise (so "15 00 25 ff" is 0..255 and
 *     "15 81 25 7f" is -127..127), decided when the main item is read.
 *
 * Fields: each input item becomes one or more fields. A variable item is
 * split where the kind of its usages changes (an item listing X, Y and a
 * hat switch gives an axis field of 2 and a hat field of 1), so each field
 * has one kind. Element i of a variable field has the i-th usage of the
 * field; elements past the last usage repeat it (HID 1.11, 6.2.2.8). An
 * array field's usages are what its element values select: value v means
 * usage number (v - logical minimum).
 *
 * Errors (the descriptor is refused, the message names the byte offset of
 * the item at fault): an item cut short by the end of the buffer; End
 * Collection with no open collection; collections left open at the end;
 * Pop with nothing pushed; Push nested deeper than HIDD_MAX_PUSH;
 * collections nested deeper than HIDD_MAX_DEPTH; Report ID 0 or above 255;
 * a main item with Report Size above HIDD_MAX_SIZE bits or Report Count
 * above HIDD_MAX_COUNT; a data (non-constant) input item with Report Size
 * 0 (a constant one is zero-width padding and skipped: a real Saitek pad
 * has one); an input report longer than HIDD_MAX_REPORT_BYTES; more than
 * HIDD_MAX_FIELDS fields or HIDD_MAX_SPANS usage spans; a usage range with
 * its minimum above its maximum; a descriptor longer than HIDD_MAX_DESC.
 * Work and memory are bounded by these limits whatever the bytes.
 */
#ifndef ARCADED_INPUT_HIDD_H
#define ARCADED_INPUT_HIDD_H

#include <stddef.h>
#include <stdint.h>

#define HIDD_MAX_DESC 65536          /* bytes of descriptor (Linux allows 4096) */
#define HIDD_MAX_PUSH 16             /* Push depth */
#define HIDD_MAX_DEPTH 64            /* collection nesting */
#define HIDD_MAX_SIZE 256            /* bits per element (Linux's limit) */
#define HIDD_MAX_COUNT 12288         /* elements per main item (Linux's HID_MAX_USAGES) */
#define HIDD_MAX_REPORT_BYTES 4096   /* input report payload, without the id byte */
#define HIDD_MAX_FIELDS 1024
#define HIDD_MAX_SPANS 8192          /* usage spans over all fields */
#define HIDD_MAX_LOCAL 1024          /* usage items before one main item */

/* Extended usage: page in the high 16 bits, usage id in the low 16. */
#define HIDD_USAGE(page, id) (((uint32_t)(page) << 16) | (uint32_t)(id))
#define HIDD_PAGE(u) ((uint16_t)((u) >> 16))
#define HIDD_ID(u) ((uint16_t)((u) & 0xffffu))

/* Usage pages and usages the decoder and the tests name. */
#define HIDD_PAGE_DESKTOP 0x01
#define HIDD_PAGE_SIM 0x02
#define HIDD_PAGE_KEYBOARD 0x07
#define HIDD_PAGE_BUTTON 0x09
#define HIDD_PAGE_VENDOR 0xff00       /* 0xff00..0xffff */
#define HIDD_GD_JOYSTICK 0x04
#define HIDD_GD_GAMEPAD 0x05
#define HIDD_GD_KEYBOARD 0x06
#define HIDD_GD_X 0x30                /* X, Y, Z, Rx, Ry, Rz, Slider, Dial, Wheel: 0x30..0x38 */
#define HIDD_GD_HAT 0x39
#define HIDD_GD_DPAD_UP 0x90          /* D-pad up, down, right, left: 0x90..0x93 */

/* Input item flags (bits of the item's data, HID 1.11 6.2.2.5). */
#define HIDD_F_CONST 0x001
#define HIDD_F_VAR 0x002
#define HIDD_F_REL 0x004
#define HIDD_F_WRAP 0x008
#define HIDD_F_NONLINEAR 0x010
#define HIDD_F_NOPREF 0x020
#define HIDD_F_NULL 0x040
#define HIDD_F_BUFBYTES 0x100

enum hidd_kind {
	HIDD_PAD,            /* constant: padding or fixed bits, carries nothing */
	HIDD_BUTTON,         /* variable, Button page, or Generic Desktop D-pad usages */
	HIDD_AXIS,           /* variable, GD X..Wheel or Simulation rudder, throttle,
				accelerator, brake, steering */
	HIDD_HAT,            /* variable, GD Hat switch */
	HIDD_KEY,            /* variable, Keyboard page: one bit per key (modifiers) */
	HIDD_KEY_ARRAY,      /* array, Keyboard page: each element holds a key's usage */
	HIDD_ARRAY,          /* any other array (button or consumer selectors) */
	HIDD_VENDOR,         /* vendor-defined page 0xFF00..0xFFFF */
	HIDD_OTHER,          /* anything else: LEDs, consumer controls, sensors, no usage */
};

/* usages first..last (extended, inclusive) in order */
struct hidd_span {
	uint32_t first, last;
};

struct hidd_field {
	uint32_t bit;        /* offset of element 0 in the report, after the id byte */
	uint16_t size;       /* bits per element, 0..HIDD_MAX_SIZE */
	uint16_t count;      /* elements */
	uint8_t report_id;   /* 0 when the descriptor declares no report ids */
	uint8_t kind;        /* enum hidd_kind */
	uint16_t flags;      /* HIDD_F_* */
	int64_t lmin, lmax;  /* logical range (lmax < lmin: no usable range) */
	uint32_t span0;      /* this field's usages: span[span0 .. span0+nspan-1] */
	uint32_t nspan;
	uint16_t app;        /* index of the enclosing application collection, in
				descriptor order, or HIDD_NO_APP */
	uint32_t app_usage;  /* usage of that collection (HIDD_USAGE(1, 4): joystick) */
	uint16_t coll;       /* index of the innermost enclosing collection, or HIDD_NO_APP */
};

#define HIDD_NO_APP 0xffffu

struct hidd_report {
	uint8_t id;          /* 0 when the descriptor declares no report ids */
	uint32_t bits;       /* payload length in bits, without the id byte */
};

struct hidd_desc {
	struct hidd_field *field;    /* input fields in report and bit order of declaration */
	size_t nfield;
	struct hidd_span *span;
	size_t nspan;
	struct hidd_report *report;  /* input reports in order of first appearance */
	size_t nreport;
	int has_ids;                 /* reports start with their id byte */
	uint16_t ncoll;              /* collections */
	uint16_t napp;               /* application collections */
	size_t ignored;              /* main items with an unknown tag that were skipped */
};

/* Parses len bytes of descriptor into a new *out (free with hidd_free).
 * Returns 0, or -EINVAL (malformed), -E2BIG (a limit above exceeded) or
 * -ENOMEM, with the reason in err ("offset 12: ..."; err may be NULL). */
int hidd_parse(const uint8_t *buf, size_t len, struct hidd_desc **out, char *err,
	       size_t errlen);

/* NULL-safe. */
void hidd_free(struct hidd_desc *d);

/* Usage number i of field f (element i of a variable field, repeating the
 * last usage past the end; index i of an array field), or 0 when an array
 * has no usage number i or the field has no usages. */
uint32_t hidd_usage(const struct hidd_desc *d, const struct hidd_field *f, uint32_t i);

/* Input report id's length as hidraw delivers it: payload bytes plus the id
 * byte when the descriptor declares ids. 0 if there is no such report. */
size_t hidd_report_len(const struct hidd_desc *d, uint8_t id);

/* Short name of a kind ("button", "axis", ...). */
const char *hidd_kind_name(int kind);

/* Appends a readable line per field ("report 1 bit 8: axis 4 x 8 bit,
 * 0..255: X Y Z Rz") to buf (NUL-terminated, truncated to len). Returns the
 * length the whole text needs, like snprintf. */
size_t hidd_describe(const struct hidd_desc *d, char *buf, size_t len);

#endif
