/*
 * Tests of autoconfiguration profiles (config/prof.c): the shipped files in
 * config/profiles/ load without a problem and match the devices they are
 * written for, the matching order of prof.h, errors with file:line, and
 * the bindings a profile gives a device.
 */
#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <linux/input-event-codes.h>

#include "config/prof.h"
#include "input/in_hid.h"

struct errs {
	char text[4096];
	size_t n;
	int count;
};

static void on_err(void *user, const char *file, int line, const char *msg)
{
	struct errs *e = user;
	int w = snprintf(e->text + e->n, sizeof(e->text) - e->n, "%s:%d: %s\n", file, line, msg);

	assert_true(w > 0 && (size_t)w < sizeof(e->text) - e->n);
	e->n += (size_t)w;
	e->count++;
}

static struct in_ident ident(const char *port, uint16_t vid, uint16_t pid, const char *name)
{
	struct in_ident id;

	memset(&id, 0, sizeof(id));
	snprintf(id.port, sizeof(id.port), "%s", port);
	id.vid = vid;
	id.pid = pid;
	snprintf(id.name, sizeof(id.name), "%s", name);
	return id;
}

static struct prof_set *shipped(void)
{
	struct prof_set *s = malloc(sizeof(*s));
	struct errs e;

	assert_non_null(s);
	memset(&e, 0, sizeof(e));
	prof_init(s);
	assert_int_equal(prof_load_dir(s, "config/profiles", on_err, &e), 0);
	assert_string_equal(e.text, "");
	return s;
}

static const char *matched(const struct prof_set *s, const char *backend, struct in_ident id)
{
	const struct prof *p = prof_match(s, backend, &id);

	return p ? p->file : NULL;
}

static void test_shipped_profiles_load_in_name_order(void **state)
{
	struct prof_set *s = shipped();

	(void)state;
	assert_int_equal(s->n, 4);
	assert_string_equal(s->p[0].file, "dragonrise-0079-0006.ini");
	assert_string_equal(s->p[1].file, "ultimarc-ipac.ini");
	assert_string_equal(s->p[2].file, "xinmo-16c0-05e1.ini");
	assert_string_equal(s->p[3].file, "zz-generic-gamepad.ini");
	assert_string_equal(s->p[0].name, "DragonRise Zero Delay encoder");
	/* the generic gamepad looks with the HID decoder's look axis (hidr.h) */
	assert_int_equal(s->p[3].key[ACT_LOOK_UP][0], BTN_GEAR_UP);
	assert_int_equal(s->p[3].key[ACT_LOOK_DOWN][0], BTN_GEAR_DOWN);
	/* every HID option string is a valid set of HID spec terms */
	for (int i = 0; i < s->n; i++) {
		struct in_hid_spec spec;
		char why[200];

		assert_int_equal(in_hid_parse_spec(s->p[i].hid, &spec, why, sizeof(why)), 0);
		assert_false(in_hid_spec_names_device(&spec));
	}
	free(s);
}

static void test_shipped_profiles_match_their_devices(void **state)
{
	struct prof_set *s = shipped();

	(void)state;
	assert_string_equal(matched(s, "hid", ident("1-1.2", 0x0079, 0x0006,
						    "DragonRise Inc.   Generic   USB  Joystick  ")),
			    "dragonrise-0079-0006.ini");
	assert_string_equal(matched(s, "hid", ident("1-2", 0x16c0, 0x05e1, "Xin-Mo Dual Arcade")),
			    "xinmo-16c0-05e1.ini");
	assert_string_equal(matched(s, "evdev", ident("1-3", 0xd209, 0x0420, "Ultimarc I-PAC 2")),
			    "ultimarc-ipac.ini");
	/* another Ultimarc product that is no PAC, and the I-PAC seen as HID */
	assert_null(matched(s, "evdev", ident("1-3", 0xd209, 0x1601, "Ultimarc U-HID")));
	assert_string_equal(matched(s, "hid", ident("1-3", 0xd209, 0x0420, "Ultimarc I-PAC 2")),
			    "zz-generic-gamepad.ini");
	/* any other pad through HID: the generic profile; through evdev none */
	assert_string_equal(matched(s, "hid", ident("", 0x054c, 0x0268, "Sony PLAYSTATION(R)3")),
			    "zz-generic-gamepad.ini");
	assert_null(matched(s, "evdev", ident("", 0x054c, 0x0268, "Sony PLAYSTATION(R)3")));
	assert_null(prof_match(s, "hid", NULL));
	free(s);
}

static void test_profile_gives_bindings_unless_the_user_has_some(void **state)
{
	struct prof_set *s = shipped();
	struct in_ident dr = ident("1-1.2", 0x0079, 0x0006, "DragonRise");
	const struct prof *p = prof_match(s, "hid", &dr);
	struct bind_table b;
	struct errs e;
	int acts[ACT_COUNT];

	(void)state;
	bind_defaults(&b);
	assert_int_equal(prof_bind(p, &b, &dr), 1);
	assert_string_equal(b.dev[0].id, "0079:0006");
	assert_int_equal(bind_lookup_dev(&b, &dr, BTN_TRIGGER_HAPPY1, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_FIRE);
	assert_int_equal(bind_lookup_dev(&b, &dr, BTN_TRIGGER_HAPPY10, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_START);
	assert_int_equal(bind_lookup_dev(&b, &dr, BTN_DPAD_LEFT, acts, ACT_COUNT), 1);
	assert_int_equal(acts[0], ACT_TURN_LEFT);
	assert_int_equal(prof_bind(p, &b, &dr), 0);
	assert_int_equal(b.ndev, 1);
	/* the user's section for this port wins */
	bind_defaults(&b);
	memset(&e, 0, sizeof(e));
	{
		static const char user[] = "[device usb-1-1.2]\nfire = BTN_TRIGGER_HAPPY7\n";

		assert_int_equal(bind_load_text(&b, user, strlen(user), "b.ini", on_err, &e), 0);
	}
	assert_int_equal(prof_bind(p, &b, &dr), 0);
	assert_int_equal(bind_lookup_dev(&b, &dr, BTN_TRIGGER_HAPPY1, acts, ACT_COUNT), 0);
	/* no identity at all */
	dr = ident("", 0, 0, "");
	assert_int_equal(prof_bind(p, &b, &dr), -EINVAL);
	free(s);
}

static void test_matching_order(void **state)
{
	static const char any[] = "[profile]\nmatch = any\n";
	static const char glob[] = "[profile]\nmatch_name = *stick*\n";
	static const char ids[] = "[profile]\nmatch = 1234:*\n";
	static const char both[] = "[profile]\nmatch = 1234:0001\nmatch_name = *STICK*\n";
	static const char ids2[] = "[profile]\nmatch = 1234:0001\n";
	struct prof_set *s = malloc(sizeof(*s));
	struct in_ident stick = ident("", 0x1234, 0x0001, "Joystick"), pad = ident("", 0x1234, 2,
										    "Pad");

	(void)state;
	assert_non_null(s);
	prof_init(s);
	assert_int_equal(prof_load_text(s, any, strlen(any), "d/any.ini", NULL, NULL), 0);
	assert_string_equal(matched(s, "evdev", stick), "any.ini");
	assert_int_equal(prof_load_text(s, glob, strlen(glob), "glob.ini", NULL, NULL), 0);
	assert_string_equal(matched(s, "evdev", stick), "glob.ini");
	assert_int_equal(prof_load_text(s, ids, strlen(ids), "ids.ini", NULL, NULL), 0);
	assert_string_equal(matched(s, "evdev", stick), "ids.ini");
	assert_int_equal(prof_load_text(s, both, strlen(both), "both.ini", NULL, NULL), 0);
	assert_string_equal(matched(s, "evdev", stick), "both.ini");
	/* a tie goes to the profile loaded first */
	assert_int_equal(prof_load_text(s, ids2, strlen(ids2), "ids2.ini", NULL, NULL), 0);
	assert_string_equal(matched(s, "evdev", pad), "ids.ini");
	/* a profile whose name glob fails does not match on its ids */
	assert_string_equal(matched(s, "evdev", ident("", 0x1234, 1, "Wheel")), "ids.ini");
	free(s);
}

static void test_profile_errors_name_file_and_line(void **state)
{
	static const char in[] = "name = early\n"                     /* 1 */
				 "[profile]\n"                        /* 2 */
				 "match = 0079:0006, zz, 12345:1, 1234:*\n" /* 3 */
				 "backend = usb\n"                    /* 4 */
				 "colour = red\n"                     /* 5 */
				 "[bindings]\n"                       /* 6 */
				 "jump = BTN_TRIGGER_HAPPY1\n"        /* 7 */
				 "fire = nosuchkey\n"                 /* 8 */
				 "use = BTN_TRIGGER_HAPPY2\n"         /* 9 */
				 "[extra]\n";                         /* 10 */
	static const char want[] =
		"p.ini:1: key 'name' is outside [profile] and [bindings]\n"
		"p.ini:3: match: 'zz' is not VVVV:PPPP (hex), VVVV:* or any\n"
		"p.ini:3: match: '12345:1' is not VVVV:PPPP (hex), VVVV:* or any\n"
		"p.ini:4: backend: 'usb' is not one of hid, evdev, gpio, any\n"
		"p.ini:5: unknown key 'colour' in [profile]\n"
		"p.ini:7: unknown action 'jump'\n"
		"p.ini:8: fire: unknown key name 'nosuchkey'\n"
		"p.ini:10: unknown section [extra] (only [profile] and [bindings])\n";
	static const char none[] = "[bindings]\nfire = x\n";
	struct prof_set *s = malloc(sizeof(*s));
	struct errs e;

	(void)state;
	assert_non_null(s);
	prof_init(s);
	memset(&e, 0, sizeof(e));
	assert_int_equal(prof_load_text(s, in, strlen(in), "p.ini", on_err, &e), 8);
	assert_string_equal(e.text, want);
	assert_int_equal(s->n, 1);
	assert_int_equal(s->p[0].nids, 2);
	assert_int_equal(s->p[0].pid[1], -1);
	assert_int_equal(s->p[0].key[ACT_FIRE][0], -1);
	assert_int_equal(s->p[0].key[ACT_USE][0], BTN_TRIGGER_HAPPY2);
	assert_string_equal(s->p[0].name, "p.ini");
	memset(&e, 0, sizeof(e));
	assert_int_equal(prof_load_text(s, none, strlen(none), "q.ini", on_err, &e), 1);
	assert_string_equal(e.text, "q.ini:0: no match or match_name: profile not used\n");
	assert_int_equal(s->n, 1);
	assert_int_equal(prof_load_dir(s, "/nonexistent/profiles", on_err, &e), -ENOENT);
	assert_int_equal(e.count, 1);
	free(s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_shipped_profiles_load_in_name_order),
		cmocka_unit_test(test_shipped_profiles_match_their_devices),
		cmocka_unit_test(test_profile_gives_bindings_unless_the_user_has_some),
		cmocka_unit_test(test_matching_order),
		cmocka_unit_test(test_profile_errors_name_file_and_line),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
