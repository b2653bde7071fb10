/*
 * hidr: HID report decoder. Rules in hidr.h.
 *
 * Each report id has a slot holding the codes its last report held (a
 * bitmap over the key code space). A code may be held by several sources
 * (a hat and a stick both holding up; the same key in two arrays): held[]
 * counts the slots holding it, so a press is reported when the first
 * source takes it and a release when the last lets go.
 *
 * The key code names come from linux/input-event-codes.h, a header of
 * constants only: the table below is kept readable, and the file does no
 * I/O (like ttyk.c).
 */
#include "input/hidr.h"

#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <linux/input-event-codes.h>

#include "engine/core/le.h"
#include "input/txt.h"

#define HIDR_CODES 0x300                 /* key codes below KEY_MAX */
#define HIDR_WORDS (HIDR_CODES / 64)
#define HIDR_AXES 11                     /* ABS_X .. ABS_BRAKE */
#define HIDR_P2_ABS 16                   /* player 2 axis code offset */

/* USB HID Usage Tables, Keyboard/Keypad page (0x07), to Linux KEY_*.
 * Unlisted usages from 4 up have no Linux key (KEY_UNKNOWN). */
static const uint16_t hidr_keys[256] = {
	[0x04] = KEY_A, [0x05] = KEY_B, [0x06] = KEY_C, [0x07] = KEY_D,
	[0x08] = KEY_E, [0x09] = KEY_F, [0x0a] = KEY_G, [0x0b] = KEY_H,
	[0x0c] = KEY_I, [0x0d] = KEY_J, [0x0e] = KEY_K, [0x0f] = KEY_L,
	[0x10] = KEY_M, [0x11] = KEY_N, [0x12] = KEY_O, [0x13] = KEY_P,
	[0x14] = KEY_Q, [0x15] = KEY_R, [0x16] = KEY_S, [0x17] = KEY_T,
	[0x18] = KEY_U, [0x19] = KEY_V, [0x1a] = KEY_W, [0x1b] = KEY_X,
	[0x1c] = KEY_Y, [0x1d] = KEY_Z,
	[0x1e] = KEY_1, [0x1f] = KEY_2, [0x20] = KEY_3, [0x21] = KEY_4,
	[0x22] = KEY_5, [0x23] = KEY_6, [0x24] = KEY_7, [0x25] = KEY_8,
	[0x26] = KEY_9, [0x27] = KEY_0,
	[0x28] = KEY_ENTER, [0x29] = KEY_ESC, [0x2a] = KEY_BACKSPACE, [0x2b] = KEY_TAB,
	[0x2c] = KEY_SPACE, [0x2d] = KEY_MINUS, [0x2e] = KEY_EQUAL,
	[0x2f] = KEY_LEFTBRACE, [0x30] = KEY_RIGHTBRACE, [0x31] = KEY_BACKSLASH,
	[0x32] = KEY_BACKSLASH,          /* Non-US # and ~: same key position */
	[0x33] = KEY_SEMICOLON, [0x34] = KEY_APOSTROPHE, [0x35] = KEY_GRAVE,
	[0x36] = KEY_COMMA, [0x37] = KEY_DOT, [0x38] = KEY_SLASH, [0x39] = KEY_CAPSLOCK,
	[0x3a] = KEY_F1, [0x3b] = KEY_F2, [0x3c] = KEY_F3, [0x3d] = KEY_F4,
	[0x3e] = KEY_F5, [0x3f] = KEY_F6, [0x40] = KEY_F7, [0x41] = KEY_F8,
	[0x42] = KEY_F9, [0x43] = KEY_F10, [0x44] = KEY_F11, [0x45] = KEY_F12,
	[0x46] = KEY_SYSRQ,              /* PrintScreen */
	[0x47] = KEY_SCROLLLOCK, [0x48] = KEY_PAUSE, [0x49] = KEY_INSERT,
	[0x4a] = KEY_HOME, [0x4b] = KEY_PAGEUP, [0x4c] = KEY_DELETE, [0x4d] = KEY_END,
	[0x4e] = KEY_PAGEDOWN, [0x4f] = KEY_RIGHT, [0x50] = KEY_LEFT, [0x51] = KEY_DOWN,
	[0x52] = KEY_UP, [0x53] = KEY_NUMLOCK,
	[0x54] = KEY_KPSLASH, [0x55] = KEY_KPASTERISK, [0x56] = KEY_KPMINUS,
	[0x57] = KEY_KPPLUS, [0x58] = KEY_KPENTER,
	[0x59] = KEY_KP1, [0x5a] = KEY_KP2, [0x5b] = KEY_KP3, [0x5c] = KEY_KP4,
	[0x5d] = KEY_KP5, [0x5e] = KEY_KP6, [0x5f] = KEY_KP7, [0x60] = KEY_KP8,
	[0x61] = KEY_KP9, [0x62] = KEY_KP0, [0x63] = KEY_KPDOT,
	[0x64] = KEY_102ND,              /* Non-US \ and | */
	[0x65] = KEY_COMPOSE,            /* Application */
	[0x66] = KEY_POWER, [0x67] = KEY_KPEQUAL,
	[0x68] = KEY_F13, [0x69] = KEY_F14, [0x6a] = KEY_F15, [0x6b] = KEY_F16,
	[0x6c] = KEY_F17, [0x6d] = KEY_F18, [0x6e] = KEY_F19, [0x6f] = KEY_F20,
	[0x70] = KEY_F21, [0x71] = KEY_F22, [0x72] = KEY_F23, [0x73] = KEY_F24,
	[0x74] = KEY_OPEN,               /* Execute */
	[0x75] = KEY_HELP,
	[0x76] = KEY_PROPS,              /* Menu */
	[0x77] = KEY_FRONT,              /* Select */
	[0x78] = KEY_STOP, [0x79] = KEY_AGAIN, [0x7a] = KEY_UNDO, [0x7b] = KEY_CUT,
	[0x7c] = KEY_COPY, [0x7d] = KEY_PASTE, [0x7e] = KEY_FIND, [0x7f] = KEY_MUTE,
	[0x80] = KEY_VOLUMEUP, [0x81] = KEY_VOLUMEDOWN,
	[0x85] = KEY_KPCOMMA,
	[0x87] = KEY_RO,                 /* International1 .. 6 */
	[0x88] = KEY_KATAKANAHIRAGANA, [0x89] = KEY_YEN, [0x8a] = KEY_HENKAN,
	[0x8b] = KEY_MUHENKAN, [0x8c] = KEY_KPJPCOMMA,
	[0x90] = KEY_HANGEUL,            /* LANG1 .. 5 */
	[0x91] = KEY_HANJA, [0x92] = KEY_KATAKANA, [0x93] = KEY_HIRAGANA,
	[0x94] = KEY_ZENKAKUHANKAKU,
	[0xb6] = KEY_KPLEFTPAREN, [0xb7] = KEY_KPRIGHTPAREN,
	[0xe0] = KEY_LEFTCTRL, [0xe1] = KEY_LEFTSHIFT, [0xe2] = KEY_LEFTALT,
	[0xe3] = KEY_LEFTMETA, [0xe4] = KEY_RIGHTCTRL, [0xe5] = KEY_RIGHTSHIFT,
	[0xe6] = KEY_RIGHTALT, [0xe7] = KEY_RIGHTMETA,
};

int hidr_key_code(uint32_t usage_id)
{
	if (usage_id < 4)
		return 0;
	if (usage_id < 256 && hidr_keys[usage_id])
		return hidr_keys[usage_id];
	return KEY_UNKNOWN;
}

enum {
	HIDR_C_KEY,         /* one element holding code while non-zero */
	HIDR_C_AXIS,
	HIDR_C_HAT,
	HIDR_C_ARRAY,       /* a key or button array field: count elements */
};

enum { HIDR_UP, HIDR_DOWN, HIDR_LEFT, HIDR_RIGHT };

struct hidr_ctl {
	const struct hidd_field *f;
	uint32_t bit;
	uint16_t size;
	uint8_t what;          /* HIDR_C_* */
	uint8_t player;        /* 1 or 2 */
	uint16_t code;         /* key: key code; axis: abs code */
	uint32_t usage;
	/* axes */
	int64_t cmin, ccen, cmax;
	int32_t last;          /* value last reported */
	int32_t cur;           /* value of the report being decoded */
	int8_t dir;            /* -1, 0, +1 from the digital thresholds */
	int8_t axis;           /* 0: X gives left/right, 1: Y gives up/down,
				  2: the look axis gives look up/down, -1: none */
	bool armed;
};

struct hidr_slot {
	uint8_t id;
	size_t bytes;          /* payload bytes */
	uint32_t ctl0, nctl;
	uint64_t held[HIDR_WORDS];
};

struct hidr {
	const struct hidd_desc *d;
	struct hidr_opts o;
	struct hidr_ctl *ctl;
	size_t nctl, capctl;
	struct hidr_slot *slot;
	size_t nslot;
	uint8_t slot_of[256];  /* 0xff: none */
	uint16_t count[HIDR_CODES]; /* slots holding each code */
	uint8_t *payload;      /* scratch: the largest report, zero-padded */
	size_t maxbytes;
	int naxes;
	bool split;            /* two players: player 1 buttons stop at 20 */
	int split_app[2];      /* AUTO: the application indices of players 1 and 2 */
};

void hidr_default_opts(struct hidr_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->split = HIDR_SPLIT_AUTO;
	o->deadzone = 150;
	o->press = 500;
	o->release = 350;
}

/* The look axis's codes (hidr.h): Linux has no code for a second stick's
 * directions, and no pad uses these two. */
static const uint16_t hidr_look[2] = { BTN_GEAR_UP, BTN_GEAR_DOWN };

static const uint16_t hidr_dirs[2][4] = {
	{ BTN_DPAD_UP, BTN_DPAD_DOWN, BTN_DPAD_LEFT, BTN_DPAD_RIGHT },
	{ BTN_TRIGGER_HAPPY37, BTN_TRIGGER_HAPPY38, BTN_TRIGGER_HAPPY39, BTN_TRIGGER_HAPPY40 },
};

static bool reported_kind(int k)
{
	return k == HIDD_BUTTON || k == HIDD_AXIS || k == HIDD_HAT;
}

static bool game_app(uint32_t app_usage)
{
	return app_usage == HIDD_USAGE(HIDD_PAGE_DESKTOP, HIDD_GD_JOYSTICK) ||
	       app_usage == HIDD_USAGE(HIDD_PAGE_DESKTOP, HIDD_GD_GAMEPAD);
}

/* AUTO split: the first two joystick/gamepad application collections with
 * buttons, axes or hats, if there are two. */
static void find_split_apps(struct hidr *r)
{
	int n = 0;

	r->split_app[0] = r->split_app[1] = -1;
	for (size_t i = 0; i < r->d->nfield && n < 2; i++) {
		const struct hidd_field *f = &r->d->field[i];

		if (!reported_kind(f->kind) || f->app == HIDD_NO_APP || !game_app(f->app_usage))
			continue;
		if (n == 1 && r->split_app[0] == f->app)
			continue;
		r->split_app[n++] = f->app;
	}
	if (n < 2)
		r->split_app[0] = r->split_app[1] = -1;
}

/* Player of an element by its application collection: 1, 2, or 0 (not
 * reported: a third game collection). */
static int app_player(const struct hidr *r, const struct hidd_field *f)
{
	if (r->split_app[0] < 0 || !game_app(f->app_usage))
		return 1;
	if (f->app == r->split_app[0])
		return 1;
	if (f->app == r->split_app[1])
		return 2;
	return 0;
}

static int add_ctl(struct hidr *r, const struct hidd_field *f, uint32_t bit, uint8_t what,
		   int player, int code, uint32_t usage)
{
	struct hidr_ctl *c;

	if (r->nctl == r->capctl) {
		size_t n = r->capctl ? r->capctl * 2 : 32;
		struct hidr_ctl *nc = realloc(r->ctl, n * sizeof(*nc));

		if (!nc)
			return -ENOMEM;
		r->ctl = nc;
		r->capctl = n;
	}
	c = &r->ctl[r->nctl++];
	memset(c, 0, sizeof(*c));
	c->f = f;
	c->bit = bit;
	c->size = f->size;
	c->what = what;
	c->player = (uint8_t)player;
	c->code = (uint16_t)code;
	c->usage = usage;
	c->axis = -1;
	return 0;
}

/* Code of button number n (1-based) of player p, or -1 if not reported. */
static int button_code(const struct hidr *r, int p, uint32_t n)
{
	if (n == 0)
		return -1;
	if (p == 1 && n <= (r->split ? 20u : 36u))
		return BTN_TRIGGER_HAPPY1 + (int)n - 1;
	if (p == 2 && n <= 16)
		return BTN_TRIGGER_HAPPY21 + (int)n - 1;
	return -1;
}

static int natural_abs(uint32_t u)
{
	static const int8_t sim[][2] = {
		{ 0xba, ABS_RUDDER }, { 0xbb, ABS_THROTTLE }, { 0xc4, ABS_GAS },
		{ 0xc5, ABS_BRAKE }, { 0xc8, ABS_WHEEL },
	};
	uint16_t page = HIDD_PAGE(u), id = HIDD_ID(u);

	if (page == HIDD_PAGE_DESKTOP && id >= HIDD_GD_X && id <= HIDD_GD_X + 8)
		return id - HIDD_GD_X;   /* X..Wheel are ABS_X..ABS_WHEEL in order */
	for (size_t i = 0; page == HIDD_PAGE_SIM && i < sizeof(sim) / sizeof(sim[0]); i++)
		if ((uint8_t)sim[i][0] == id)
			return sim[i][1];
	return -1;
}

struct hidr_build {
	uint16_t abs_used[3];        /* per player, bit per code 0..10 */
	uint8_t *seen;               /* USAGE split: bit per usage of pages 1 and 9 */
};

/* USAGE split: 1 for the first element with usage u, 2 for the second, 0
 * after; pages other than Generic Desktop and Button stay player 1. */
static int usage_player(struct hidr_build *b, uint32_t u)
{
	uint16_t page = HIDD_PAGE(u);
	size_t i;

	if (!b->seen || (page != HIDD_PAGE_DESKTOP && page != HIDD_PAGE_BUTTON))
		return 1;
	i = ((size_t)(page == HIDD_PAGE_BUTTON) << 17) | ((size_t)HIDD_ID(u) << 1);
	if (!(b->seen[i / 8] & (1u << (i % 8)))) {
		b->seen[i / 8] |= (uint8_t)(1u << (i % 8));
		return 1;
	}
	i++;
	if (!(b->seen[i / 8] & (1u << (i % 8)))) {
		b->seen[i / 8] |= (uint8_t)(1u << (i % 8));
		return 2;
	}
	return 0;
}

static int add_axis(struct hidr *r, struct hidr_build *b, const struct hidd_field *f,
		    uint32_t bit, int player, uint32_t u)
{
	uint16_t id = HIDD_ID(u);
	int code = natural_abs(u), rc;
	struct hidr_ctl *c;

	if (HIDD_PAGE(u) == HIDD_PAGE_DESKTOP && (id == r->o.p2_x || id == r->o.p2_y)) {
		player = 2;
		code = id == r->o.p2_x ? ABS_X : ABS_Y;
	}
	if (code < 0 || f->lmax <= f->lmin || f->size > 32)
		return 0;
	while (code < HIDR_AXES && (b->abs_used[player] & (1u << code)))
		code++;
	if (code >= HIDR_AXES || (player == 2 && code > ABS_RUDDER))
		return 0;
	b->abs_used[player] |= (uint16_t)(1u << code);
	rc = add_ctl(r, f, bit, HIDR_C_AXIS, player, player == 2 ? code + HIDR_P2_ABS : code, u);
	if (rc < 0)
		return rc;
	c = &r->ctl[r->nctl - 1];
	c->cmin = f->lmin;
	c->cmax = f->lmax;
	/* Pedals and throttles rest at one end; sticks and wheels in the middle. */
	if (HIDD_PAGE(u) == HIDD_PAGE_SIM && (id == 0xbb || id == 0xc4 || id == 0xc5))
		c->ccen = f->lmin;
	else
		c->ccen = f->lmin + (f->lmax - f->lmin) / 2;
	c->axis = code == ABS_X ? 0 : code == ABS_Y ? 1 : -1;
	r->naxes++;
	return 0;
}

/* Controls of variable field f, element by element. */
static int add_variable(struct hidr *r, struct hidr_build *b, const struct hidd_field *f)
{
	int player = app_player(r, f);

	if (player == 0 || f->size == 0 || f->size > 32)
		return 0;
	for (uint32_t i = 0; i < f->count; i++) {
		uint32_t u = hidd_usage(r->d, f, i), bit = f->bit + i * f->size;
		uint16_t page = HIDD_PAGE(u), id = HIDD_ID(u);
		int p = player, rc = 0, code;

		if (r->o.split == HIDR_SPLIT_USAGE && f->kind != HIDD_KEY) {
			p = usage_player(b, u);
			if (p == 0)
				continue;
		}
		switch (f->kind) {
		case HIDD_BUTTON:
			if (page == HIDD_PAGE_DESKTOP) {
				/* D-pad usages 0x90..0x93: up, down, right, left */
				static const int map[4] = { HIDR_UP, HIDR_DOWN, HIDR_RIGHT, HIDR_LEFT };

				rc = add_ctl(r, f, bit, HIDR_C_KEY, p,
					     hidr_dirs[p - 1][map[id - HIDD_GD_DPAD_UP]], u);
				break;
			}
			if (r->o.p2_first_button && id >= r->o.p2_first_button) {
				p = 2;
				id = (uint16_t)(id - r->o.p2_first_button + 1);
			}
			code = button_code(r, p, id);
			if (code >= 0)
				rc = add_ctl(r, f, bit, HIDR_C_KEY, p, code, u);
			break;
		case HIDD_KEY:
			code = hidr_key_code(id);
			if (code > 0)
				rc = add_ctl(r, f, bit, HIDR_C_KEY, 1, code, u);
			break;
		case HIDD_AXIS:
			rc = add_axis(r, b, f, bit, p, u);
			break;
		case HIDD_HAT:
			if (f->lmax > f->lmin)
				rc = add_ctl(r, f, bit, HIDR_C_HAT, p, 0, u);
			break;
		default:
			break;
		}
		if (rc < 0)
			return rc;
	}
	return 0;
}

static int build(struct hidr *r, struct hidr_build *b)
{
	const struct hidd_desc *d = r->d;
	int rc;

	memset(r->slot_of, 0xff, sizeof(r->slot_of));
	r->slot = calloc(d->nreport ? d->nreport : 1, sizeof(*r->slot));
	if (!r->slot)
		return -ENOMEM;
	for (size_t s = 0; s < d->nreport; s++) {
		struct hidr_slot *sl = &r->slot[r->nslot];

		sl->id = d->report[s].id;
		sl->bytes = (d->report[s].bits + 7) / 8;
		sl->ctl0 = (uint32_t)r->nctl;
		if (sl->bytes > r->maxbytes)
			r->maxbytes = sl->bytes;
		for (size_t i = 0; i < d->nfield; i++) {
			const struct hidd_field *f = &d->field[i];

			if (f->report_id != sl->id)
				continue;
			if (f->kind == HIDD_KEY_ARRAY || f->kind == HIDD_ARRAY) {
				if (f->size == 0 || f->size > 32 || app_player(r, f) == 0)
					continue;
				rc = add_ctl(r, f, f->bit, HIDR_C_ARRAY, app_player(r, f), 0, 0);
			} else {
				rc = add_variable(r, b, f);
			}
			if (rc < 0)
				return rc;
		}
		sl->nctl = (uint32_t)(r->nctl - sl->ctl0);
		r->slot_of[sl->id] = (uint8_t)r->nslot;
		r->nslot++;
	}
	r->payload = calloc(r->maxbytes ? r->maxbytes : 1, 1);
	return r->payload ? 0 : -ENOMEM;
}

/* The look axis (hidr.h): player 1's first axis declared with the Generic
 * Desktop usage the options name, else (auto) Rz, else Ry; never one that
 * gives directions already. By the declared usage, not the code: a
 * repeated X renumbered to ABS_RY (DragonRise) is no second stick. */
static struct hidr_ctl *look_axis(struct hidr *r, uint16_t usage_id)
{
	for (size_t i = 0; i < r->nctl; i++) {
		struct hidr_ctl *c = &r->ctl[i];

		if (c->what == HIDR_C_AXIS && c->player == 1 && c->axis < 0 &&
		    HIDD_PAGE(c->usage) == HIDD_PAGE_DESKTOP && HIDD_ID(c->usage) == usage_id)
			return c;
	}
	return NULL;
}

static void find_look(struct hidr *r)
{
	struct hidr_ctl *c;

	if (r->o.look == HIDR_LOOK_NONE)
		return;
	if (r->o.look)
		c = look_axis(r, r->o.look);
	else if (!(c = look_axis(r, HIDD_GD_X + 5)))        /* Rz */
		c = look_axis(r, HIDD_GD_X + 4);            /* Ry */
	if (c)
		c->axis = 2;
}

int hidr_new(const struct hidd_desc *d, const struct hidr_opts *opts, struct hidr **out)
{
	struct hidr_build b = { { 0 }, NULL };
	struct hidr *r;
	int rc;

	*out = NULL;
	r = calloc(1, sizeof(*r));
	if (!r)
		return -ENOMEM;
	r->d = d;
	if (opts)
		r->o = *opts;
	else
		hidr_default_opts(&r->o);
	if (r->o.deadzone > 1000 || r->o.press > 1000 || r->o.release > r->o.press ||
	    r->o.split < HIDR_SPLIT_AUTO || r->o.split > HIDR_SPLIT_USAGE) {
		rc = -EINVAL;
		goto fail;
	}
	r->split_app[0] = r->split_app[1] = -1;
	if (r->o.split == HIDR_SPLIT_AUTO)
		find_split_apps(r);
	r->split = r->split_app[0] >= 0 || r->o.split == HIDR_SPLIT_USAGE ||
		   r->o.p2_first_button || r->o.p2_x || r->o.p2_y;
	if (r->o.split == HIDR_SPLIT_USAGE) {
		/* two bits (seen once, seen twice) per usage id of 2 pages */
		b.seen = calloc(1, 2u * 65536u * 2u / 8u);
		if (!b.seen) {
			rc = -ENOMEM;
			goto fail;
		}
	}
	rc = build(r, &b);
	free(b.seen);
	if (rc < 0)
		goto fail;
	find_look(r);
	*out = r;
	return 0;
fail:
	hidr_free(r);
	return rc;
}

void hidr_free(struct hidr *r)
{
	if (!r)
		return;
	free(r->ctl);
	free(r->slot);
	free(r->payload);
	free(r);
}

int hidr_max_events(const struct hidr *r)
{
	return HIDR_CODES + r->naxes;
}

/* size bits at bit offset bit of p (bit + size within the buffer). */
static uint32_t get_bits(const uint8_t *p, uint32_t bit, uint32_t size)
{
	uint32_t first = bit / 8, n = (bit % 8 + size + 7) / 8;
	uint64_t v = le_getn(p + first, (int)n) >> bit % 8;

	return (uint32_t)(size == 32 ? v : v & ((1ull << size) - 1));
}

static int64_t value_of(const struct hidr_ctl *c, const uint8_t *p, uint32_t bit)
{
	uint32_t v = get_bits(p, bit, c->size);

	if (c->f->lmin < 0 && c->size < 32 && (v & (1u << (c->size - 1))))
		return (int64_t)v - ((int64_t)1 << c->size);
	if (c->f->lmin < 0)
		return (int32_t)v;
	return v;
}

static void hold(uint64_t *bits, int code)
{
	if (code > 0 && code < HIDR_CODES)
		bits[code / 64] |= 1ull << (code % 64);
}

static int32_t calibrate(const struct hidr_ctl *c, int64_t v)
{
	int64_t n;

	if (v < c->ccen) {
		if (c->ccen <= c->cmin)
			return 0;
		n = -(c->ccen - v) * HIDR_FULL / (c->ccen - c->cmin);
		return (int32_t)(n < -HIDR_FULL ? -HIDR_FULL : n);
	}
	if (c->cmax <= c->ccen)
		return 0;
	n = (v - c->ccen) * HIDR_FULL / (c->cmax - c->ccen);
	return (int32_t)(n > HIDR_FULL ? HIDR_FULL : n);
}

static void axis_dirs(const struct hidr *r, struct hidr_ctl *c, int32_t v, uint64_t *bits)
{
	int32_t press = r->o.press * HIDR_FULL / 1000, rel = r->o.release * HIDR_FULL / 1000;
	int32_t dz = r->o.deadzone * HIDR_FULL / 1000;
	int32_t mag = v < 0 ? -v : v;

	if (c->axis < 0)
		return;
	if (!c->armed) {
		if (mag > dz)
			return;
		c->armed = true;
	}
	if (c->dir != 0 && (mag < rel || (v < 0) != (c->dir < 0)))
		c->dir = 0;
	if (c->dir == 0 && mag >= press && mag > 0)
		c->dir = v < 0 ? -1 : 1;
	if (c->dir != 0 && c->axis == 2) {
		hold(bits, hidr_look[c->dir < 0 ? 0 : 1]);
	} else if (c->dir != 0) {
		int d = c->axis == 0 ? (c->dir < 0 ? HIDR_LEFT : HIDR_RIGHT)
				     : (c->dir < 0 ? HIDR_UP : HIDR_DOWN);

		hold(bits, hidr_dirs[c->player - 1][d]);
	}
}

static void hat_dirs(const struct hidr_ctl *c, int64_t v, uint64_t *bits)
{
	/* 8-way positions from north, clockwise: bit 0 up, 1 down, 2 left, 3 right */
	static const uint8_t eight[8] = { 1, 1 | 8, 8, 2 | 8, 2, 2 | 4, 4, 1 | 4 };
	static const uint8_t four[4] = { 1, 8, 2, 4 };
	int64_t pos = v - c->f->lmin, n = c->f->lmax - c->f->lmin + 1;
	uint8_t m;

	if (v < c->f->lmin || v > c->f->lmax || pos >= 8)
		return;   /* null state: centred */
	m = n == 4 ? four[pos] : eight[pos];
	for (int d = 0; d < 4; d++)
		if (m & (1u << d))
			hold(bits, hidr_dirs[c->player - 1][d]);
}

/* Array field: the codes its elements select. false on ErrorRollOver. */
static bool array_keys(const struct hidr *r, const struct hidr_ctl *c, const uint8_t *p,
		       uint64_t *bits)
{
	const struct hidd_field *f = c->f;

	for (uint32_t i = 0; i < f->count; i++) {
		int64_t v = value_of(c, p, f->bit + i * f->size);
		uint32_t u;

		if (v < f->lmin || v > f->lmax)
			continue;
		u = hidd_usage(r->d, f, (uint32_t)(v - f->lmin));
		if (HIDD_PAGE(u) == HIDD_PAGE_KEYBOARD) {
			if (HIDD_ID(u) >= 1 && HIDD_ID(u) <= 3)
				return false;
			hold(bits, hidr_key_code(HIDD_ID(u)));
		} else if (HIDD_PAGE(u) == HIDD_PAGE_BUTTON) {
			hold(bits, button_code(r, c->player, HIDD_ID(u)));
		}
	}
	return true;
}

/* Reports the codes that changed between the slot's last state and now,
 * releases first, counting sources (file comment). Returns how many. */
static int key_changes(struct hidr *r, struct hidr_slot *sl, const uint64_t *now,
		       uint64_t time_ns, struct in_event *out)
{
	int n = 0;

	for (int down = 0; down < 2; down++) {
		for (int w = 0; w < HIDR_WORDS; w++) {
			uint64_t ch = down ? now[w] & ~sl->held[w] : sl->held[w] & ~now[w];

			while (ch) {
				int code = w * 64 + __builtin_ctzll(ch);

				ch &= ch - 1;
				if (!down && --r->count[code] > 0)
					continue;
				if (down && r->count[code]++ > 0)
					continue;
				out[n].type = IN_KEY;
				out[n].code = (uint16_t)code;
				out[n].value = down;
				out[n].time_ns = time_ns;
				n++;
			}
		}
	}
	memcpy(sl->held, now, sizeof(sl->held));
	return n;
}

int hidr_decode(struct hidr *r, const uint8_t *buf, size_t len, uint64_t time_ns,
		struct in_event *out, int max)
{
	uint64_t now[HIDR_WORDS] = { 0 };
	int32_t dz = r->o.deadzone * HIDR_FULL / 1000;
	struct hidr_slot *sl;
	int n;

	if (len == 0)
		return -EINVAL;
	if (max < hidr_max_events(r))
		return -ENOSPC;
	if (r->d->has_ids) {
		if (r->slot_of[buf[0]] == 0xff)
			return -ENOENT;
		sl = &r->slot[r->slot_of[buf[0]]];
		buf++;
		len--;
	} else {
		if (r->nslot == 0)
			return -ENOENT;
		sl = &r->slot[0];
	}
	memset(r->payload, 0, sl->bytes);
	memcpy(r->payload, buf, len < sl->bytes ? len : sl->bytes);
	for (uint32_t k = 0; k < sl->nctl; k++) {
		const struct hidr_ctl *c = &r->ctl[sl->ctl0 + k];

		if (c->what == HIDR_C_ARRAY && !array_keys(r, c, r->payload, now))
			return 0;   /* phantom state: keep everything as it was */
	}
	for (uint32_t k = 0; k < sl->nctl; k++) {
		struct hidr_ctl *c = &r->ctl[sl->ctl0 + k];
		int64_t v;

		if (c->what == HIDR_C_ARRAY)
			continue;
		v = value_of(c, r->payload, c->bit);
		if (c->what == HIDR_C_KEY) {
			if (v > 0 && v > c->f->lmin)
				hold(now, c->code);
		} else if (c->what == HIDR_C_HAT) {
			hat_dirs(c, v, now);
		} else {
			c->cur = calibrate(c, v);
			if ((c->cur < 0 ? -c->cur : c->cur) <= dz)
				c->cur = 0;
			axis_dirs(r, c, c->cur, now);
		}
	}
	n = key_changes(r, sl, now, time_ns, out);
	for (uint32_t k = 0; k < sl->nctl; k++) {
		struct hidr_ctl *c = &r->ctl[sl->ctl0 + k];

		if (c->what != HIDR_C_AXIS || c->cur == c->last)
			continue;
		c->last = c->cur;
		out[n].type = IN_ABS;
		out[n].code = c->code;
		out[n].value = c->cur;
		out[n].time_ns = time_ns;
		n++;
	}
	return n;
}

int hidr_calibrate(struct hidr *r, int abs_code, int64_t min, int64_t centre, int64_t max)
{
	if (!(min <= centre && centre <= max && min < max))
		return -EINVAL;
	for (size_t i = 0; i < r->nctl; i++) {
		struct hidr_ctl *c = &r->ctl[i];

		if (c->what == HIDR_C_AXIS && c->code == abs_code) {
			c->cmin = min;
			c->ccen = centre;
			c->cmax = max;
			return 0;
		}
	}
	return -ENOENT;
}

size_t hidr_describe(const struct hidr *r, char *buf, size_t len)
{
	struct txt t = { .buf = buf, .len = len };

	if (len)
		buf[0] = '\0';
	for (size_t s = 0; s < r->nslot; s++) {
		const struct hidr_slot *sl = &r->slot[s];

		for (uint32_t k = 0; k < sl->nctl; k++) {
			const struct hidr_ctl *c = &r->ctl[sl->ctl0 + k];

			txt_put(&t, "report %u bit %u: ", sl->id, c->bit);
			switch (c->what) {
			case HIDR_C_KEY:
				txt_put(&t, "%04x:%04x -> key %u", HIDD_PAGE(c->usage),
					HIDD_ID(c->usage), c->code);
				break;
			case HIDR_C_AXIS:
				txt_put(&t, "axis %04x:%04x -> abs %u, %lld/%lld/%lld%s",
					HIDD_PAGE(c->usage), HIDD_ID(c->usage), c->code,
					(long long)c->cmin, (long long)c->ccen, (long long)c->cmax,
					c->axis == 0 ? ", left/right" :
					c->axis == 1 ? ", up/down" :
					c->axis == 2 ? ", look up/down" : "");
				break;
			case HIDR_C_HAT:
				txt_put(&t, "hat -> directions");
				break;
			default:
				txt_put(&t, "%s x%u", hidd_kind_name(c->f->kind),
					c->f->count);
				break;
			}
			txt_put(&t, " p%u\n", c->player);
		}
	}
	return t.n;
}
