/*
 * op: the app's side of CONTENT PACK, SCREEN and CONFIG ERRORS, driven
 * through per-tick commands as the main loop drives it: the request page
 * starts the page, the commands' controls go to it (the sim gets none but
 * the coins), a choice is saved in a state directory made here (read back
 * with st_load: the payload is the INI text a later start reads) and asks
 * for the run to start again; the controls held at the end reach the sim
 * only once released; nothing runs while recording.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/op.h"
#include "app/tape.h"
#include "config/st.h"
#include "engine/game/menu.h"
#include "engine/game/sim.h"

static char dir[64];
static struct sim sim;            /* only mode and menu.page are read */
static struct tape tape;
static struct cfg cfg;

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/test_op.XXXXXX");
	if (!mkdtemp(dir))
		return -1;
	cfg_defaults(&cfg);
	snprintf(cfg.paths.state_dir, sizeof(cfg.paths.state_dir), "%s", dir);
	/* no WADs there: CONTENT lists BUILT-IN LEVELS and BACK */
	snprintf(cfg.game.content_dirs, sizeof(cfg.game.content_dirs), "%s/none", dir);
	return 0;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

/* One tick: cmd built with these controls, then the menu's page after the
 * sim's tick. Returns the command the sim got. */
static struct sim_cmd tick(struct op *o, int8_t forward, int16_t turn, uint8_t buttons,
			   uint8_t coins, int page)
{
	struct sim_cmd c = { .forward = forward, .turn = turn, .buttons = buttons, .coins = coins };

	op_command(o, &c);
	sim.mode = SIM_SERVICE;
	sim.menu.page = (uint8_t)page;
	op_request(o, &sim);
	return c;
}

static char *load(const char *name)
{
	void *buf = NULL;
	size_t len = 0;
	char *s;

	if (st_load(dir, name, &buf, &len, NULL, NULL, 0) < 0)
		return NULL;
	s = malloc(len + 1);
	memcpy(s, buf, len);
	s[len] = '\0';
	free(buf);
	return s;
}

static void test_screen_choice_is_saved_and_asks_for_a_restart(void **state)
{
	static struct op o;
	struct sim_cmd c;
	char *ini;

	(void)state;
	op_init(&o, &cfg, NULL, &tape, 1, "built-in");
	/* FIRE chose SCREEN: its request page for one tick, FIRE still held */
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_SCREEN);
	assert_int_equal(o.on, 1);
	assert_int_equal(o.pick.page, PICK_SCREEN);
	/* the held FIRE is not a press on the page */
	c = tick(&o, 0, 0, SIM_BT_FIRE, 1, MENU_MAIN);
	assert_int_equal(o.pick.rotate, 0);
	/* the sim gets the coin and nothing else */
	assert_int_equal(c.buttons, 0);
	assert_int_equal(c.coins, 1);
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	c = tick(&o, 0, -1, 0, 0, MENU_MAIN);      /* right: turn < 0 */
	assert_int_equal(c.turn, 0);
	assert_int_equal(o.pick.rotate, 90);
	tick(&o, 0, -1, 0, 0, MENU_MAIN);          /* held: no repeat yet */
	assert_int_equal(o.pick.rotate, 90);
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	tick(&o, -1, 0, 0, 0, MENU_MAIN);          /* down: SCALE */
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	tick(&o, -1, 0, 0, 0, MENU_MAIN);          /* down: APPLY */
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	assert_int_equal(o.reload, 0);
	c = tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_MAIN);
	assert_int_equal(o.on, 0);
	assert_int_equal(o.reload, 1);
	assert_int_equal(c.buttons, 0);
	/* FIRE still held after the page: the sim does not see it... */
	c = tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_MAIN);
	assert_int_equal(c.buttons, 0);
	/* ...until released and pressed again */
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	c = tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_MAIN);
	assert_int_equal(c.buttons, SIM_BT_FIRE);
	ini = load(OP_SCREEN_FILE);
	assert_non_null(ini);
	assert_string_equal(ini, "[display]\nrotate = 90\nscale = integer\n");
	free(ini);
}

static void test_built_in_levels_saved_as_empty_wad_and_maps(void **state)
{
	static struct op o;
	char *ini;

	(void)state;
	op_init(&o, &cfg, NULL, &tape, 1, "built-in");
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_CONTENT);
	assert_int_equal(o.on, 1);
	assert_int_equal(o.wads.n, 0);
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_MAIN);
	assert_int_equal(o.reload, 1);
	ini = load(OP_CONTENT_FILE);
	assert_non_null(ini);
	assert_string_equal(ini, "[game]\nwad = \nmaps = \n");
	free(ini);
}

static void test_a_script_run_keeps_and_reloads_nothing(void **state)
{
	static struct op o;
	static struct cfg c2;

	(void)state;
	c2 = cfg;
	snprintf(c2.paths.state_dir, sizeof(c2.paths.state_dir), "%s/script", dir);
	op_init(&o, &c2, NULL, &tape, 0, NULL);
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_SCREEN);
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	tick(&o, 1, 0, 0, 0, MENU_MAIN);           /* up: BACK */
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	tick(&o, 1, 0, 0, 0, MENU_MAIN);           /* up: APPLY */
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_MAIN);
	assert_int_equal(o.on, 0);
	assert_int_equal(o.reload, 0);
}

static void test_config_errors_acknowledged_and_not_while_recording(void **state)
{
	static struct op o;
	struct cfgerr e;

	(void)state;
	cfgerr_clear(&e);
	cfgerr_keep(&e, "/etc/arcaded/x.ini", 2, "lives: 12 out of range 1..9");
	op_init(&o, &cfg, &e, &tape, 1, NULL);
	assert_string_equal(op_notice(&o), "/etc/arcaded/x.ini:2: lives: 12 out of range 1..9");
	/* while recording: no notice, and the page is refused */
	tape.rec = (struct rec_writer *)&o;      /* any non-NULL: "recording" */
	assert_null(op_notice(&o));
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_CONFIG);
	assert_int_equal(o.on, 0);
	tape.rec = NULL;
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_CONFIG);
	assert_int_equal(o.on, 1);
	tick(&o, 0, 0, 0, 0, MENU_MAIN);
	tick(&o, 0, 0, SIM_BT_FIRE, 0, MENU_MAIN);  /* ACKNOWLEDGE */
	assert_null(op_notice(&o));
	assert_int_equal(o.reload, 0);
	/* a restart with the same errors: still acknowledged */
	op_init(&o, &cfg, &e, &tape, 1, NULL);
	assert_null(op_notice(&o));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_screen_choice_is_saved_and_asks_for_a_restart),
		cmocka_unit_test(test_built_in_levels_saved_as_empty_wad_and_maps),
		cmocka_unit_test(test_a_script_run_keeps_and_reloads_nothing),
		cmocka_unit_test(test_config_errors_acknowledged_and_not_while_recording),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
