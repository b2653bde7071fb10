/*
 * ctl: what the slots report, turned into actions, through nothing but the
 * backend's table (fake backends; unit test only). A matching profile's
 * decoder options reach the device through in_backend.configure, and a
 * backend without one is left alone; on a first boot a device nothing
 * names starts the wizard only when its backend says its controls need
 * bindings (IN_NEEDS_BINDINGS), not on a script or replay; key changes
 * reach the bound actions (a press is an input of the slot's source for
 * the latency statistics) or, while the wizard runs, the wizard alone; a
 * device that goes away has its held controls released.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include <linux/input-event-codes.h>

#include "app/ctl.h"
#include "app/stats.h"

struct in_dev {
	int unused;
};

static struct in_dev dev;
static char configured[128];
static int configure_rc;

static const char *fake_describe(struct in_dev *d)
{
	(void)d;
	return "fake pad";
}

static int fake_configure(struct in_dev *d, const char *terms, char *why, size_t whylen)
{
	assert_ptr_equal(d, &dev);
	snprintf(configured, sizeof(configured), "%s", terms);
	if (configure_rc < 0)
		snprintf(why, whylen, "refused");
	return configure_rc;
}

static const struct in_backend pad = {
	.name = "pad", .describe = fake_describe, .configure = fake_configure,
	.flags = IN_NEEDS_BINDINGS,
};
static const struct in_backend keyboard = { .name = "keys", .describe = fake_describe };

static const char profiles[] =
	"[profile]\nname = Known pad\nmatch = 1209:0001\nhid = split=none, deadzone=300\n"
	"[bindings]\nfire = BTN_TRIGGER_HAPPY1\n";
static const char generic[] = "[profile]\nname = Generic guess\nmatch = any\n"
			      "[bindings]\nfire = BTN_TRIGGER_HAPPY2\n";

static struct ctl c;
static struct cfg cf;
static struct stats st;

static void start(const char *text)
{
	static const char *const names[] = { "keys", "pad", "script" };

	memset(&c, 0, sizeof(c));
	cfg_defaults(&cf);
	cf.paths.state_dir[0] = '\0';
	stats_init(&st, names, 3);
	c.cfg = &cf;
	c.stats = &st;
	c.live = 1;
	c.wiz_auto = 1;            /* a first boot */
	bind_defaults(&c.binds);
	prof_init(&c.profs);
	if (text)
		assert_int_equal(prof_load_text(&c.profs, text, strlen(text), "t.ini", NULL, NULL), 0);
	configured[0] = '\0';
	configure_rc = 0;
}

static struct slot slot_of(const struct in_backend *be, uint16_t vid, uint16_t pid, int kind)
{
	struct slot s = { .be = be, .dev = &dev, .kind = kind };

	s.id.vid = vid;
	s.id.pid = pid;
	return s;
}

static void a_profile_configures_the_device_through_its_table(void **state)
{
	struct slot s = slot_of(&pad, 0x1209, 1, 1);

	(void)state;
	start(profiles);
	ctl_hooks.opened(&c, &s);
	assert_string_equal(configured, "split=none, deadzone=300");
	/* named by a profile: no wizard; its section gives the bindings */
	assert_int_equal(c.wiz_on, 0);
	assert_non_null(bind_find_device(&c.binds, &s.id));
	/* a refusal is logged, not fatal */
	configure_rc = -EINVAL;
	ctl_hooks.opened(&c, &s);
	assert_int_equal(c.wiz_on, 0);
	/* a backend without configure gets nothing, and nothing breaks */
	s = slot_of(&keyboard, 0x1209, 1, 0);
	configured[0] = '\0';
	ctl_hooks.opened(&c, &s);
	assert_string_equal(configured, "");
}

static void a_first_boot_asks_for_a_pad_nothing_names(void **state)
{
	struct slot s = slot_of(&pad, 0x1209, 2, 1);

	(void)state;
	/* only the generic guess matches: ask the operator */
	start(generic);
	ctl_hooks.opened(&c, &s);
	assert_int_equal(c.wiz_on, 1);
	assert_int_equal(c.wiz_auto, 0);
	/* a keyboard-like backend's keys are bound by default: no wizard */
	start(generic);
	s = slot_of(&keyboard, 0x1209, 2, 0);
	ctl_hooks.opened(&c, &s);
	assert_int_equal(c.wiz_on, 0);
	/* not on a script or replay, and not after the first boot */
	start(NULL);
	c.live = 0;
	s = slot_of(&pad, 0x1209, 2, 1);
	ctl_hooks.opened(&c, &s);
	assert_int_equal(c.wiz_on, 0);
	start(NULL);
	c.wiz_auto = 0;
	ctl_hooks.opened(&c, &s);
	assert_int_equal(c.wiz_on, 0);
}

static void keys_go_to_actions_or_to_the_wizard_alone(void **state)
{
	struct slot s = slot_of(&keyboard, 0, 0, 0);

	(void)state;
	start(NULL);
	ctl_hooks.key(&c, &s, KEY_UP, 1, 5000);
	assert_int_equal(c.cs.held[ACT_FORWARD], 1);
	assert_int_equal(st.src_pending_ns[0], 5000);
	assert_int_equal(st.src_pending_ns[1], 0);
	/* the slot went away holding it */
	ctl_hooks.released(&c, &s, KEY_UP);
	ctl_hooks.gone(&c, &s);
	assert_int_equal(c.cs.held[ACT_FORWARD], 0);
	/* unbound: no action, no latency sample due */
	st.src_pending_ns[0] = 0;
	st.pending_ns = 0;
	ctl_hooks.key(&c, &s, KEY_F12, 1, 6000);
	assert_int_equal(st.pending_ns, 0);
	/* while the wizard runs the game sees nothing */
	ctl_wizard_start(&c, "test");
	assert_int_equal(c.wiz_on, 1);
	ctl_hooks.key(&c, &s, KEY_UP, 1, 7000);
	assert_int_equal(c.cs.held[ACT_FORWARD], 0);
	assert_int_equal(st.pending_ns, 0);
}

/* Every control change of a device is kept in words for the input test,
 * the input.log line's (the VM tests read those: 'evdev 0001:0001 KEY_5
 * down -> coin'), the last CTL_RAW of them; the wizard's are not. */
static void control_changes_are_kept_in_words(void **state)
{
	struct slot s = slot_of(&keyboard, 0x1209, 0x0001, 0);
	struct slot p = slot_of(&pad, 0, 0, 1);

	(void)state;
	start(NULL);
	strcpy(p.id.port, "1-1.2");
	ctl_hooks.key(&c, &s, KEY_UP, 1, 5000);
	assert_int_equal(c.raw_n, 1);
	assert_string_equal(c.raw[0], "keys 1209:0001 KEY_UP down -> forward");
	ctl_hooks.key(&c, &s, KEY_F12, 1, 6000);
	assert_string_equal(c.raw[1], "keys 1209:0001 KEY_F12 down -> unbound");
	ctl_hooks.released(&c, &p, KEY_LEFTCTRL);
	assert_string_equal(c.raw[2], "pad usb-1-1.2 KEY_LEFTCTRL up -> fire");
	s.id.vid = 0;
	s.id.pid = 0;
	ctl_hooks.key(&c, &s, 0x2ff, 1, 7000);     /* no name, no id */
	assert_string_equal(c.raw[3], "keys - code 767 down -> unbound");
	for (int i = 0; i < CTL_RAW; i++)
		ctl_hooks.key(&c, &s, KEY_UP, i & 1, 8000);
	assert_int_equal(c.raw_n, 4 + CTL_RAW);
	assert_string_equal(c.raw[(c.raw_n - 1) % CTL_RAW], "keys - KEY_UP down -> forward");
	assert_string_equal(c.raw[(c.raw_n - 2) % CTL_RAW], "keys - KEY_UP up -> forward");
	ctl_wizard_start(&c, "test");
	ctl_hooks.key(&c, &s, KEY_DOWN, 1, 9000);
	assert_int_equal(c.raw_n, 4 + CTL_RAW);
}

/* Auto-detection asks ctl which codes do something: the defaults' keys for
 * any device, a device's own section's for it alone. */
static void the_bound_hook_is_what_the_bindings_use(void **state)
{
	static const char text[] = "[device \"usb-1-1\"]\nfire = BTN_TRIGGER\n";
	struct in_ident kbd = { .vid = 1, .pid = 1 }, joy = { .port = "1-1", .vid = 0x79 };

	(void)state;
	start(NULL);
	assert_int_equal(bind_load_text(&c.binds, text, strlen(text), "t.ini", NULL, NULL), 0);
	assert_int_equal(ctl_hooks.bound(&c, &kbd, KEY_5), 1);          /* coin */
	assert_int_equal(ctl_hooks.bound(&c, &kbd, KEY_LEFTCTRL), 1);   /* fire */
	assert_int_equal(ctl_hooks.bound(&c, &kbd, KEY_POWER), 0);
	assert_int_equal(ctl_hooks.bound(&c, &kbd, BTN_TRIGGER), 0);
	/* the pad's own section replaces [keyboard] for it */
	assert_int_equal(ctl_hooks.bound(&c, &joy, BTN_TRIGGER), 1);
	assert_int_equal(ctl_hooks.bound(&c, &joy, KEY_5), 0);
	/* ctl_bound on a table of its own, as `arcaded devices` uses it */
	assert_int_equal(ctl_bound(&c.binds, &joy, BTN_TRIGGER), 1);
	assert_int_equal(ctl_bound(&c.binds, &kbd, KEY_1), 1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_profile_configures_the_device_through_its_table),
		cmocka_unit_test(a_first_boot_asks_for_a_pad_nothing_names),
		cmocka_unit_test(keys_go_to_actions_or_to_the_wizard_alone),
		cmocka_unit_test(control_changes_are_kept_in_words),
		cmocka_unit_test(the_bound_hook_is_what_the_bindings_use),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
