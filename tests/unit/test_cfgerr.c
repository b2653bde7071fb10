/*
 * cfgerr: errors kept as cfg reports them, their hash, and the
 * acknowledgement kept in a state directory made here: the same errors
 * stay acknowledged after a "restart" (a fresh struct), changed ones do
 * not.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/cfgerr.h"
#include "config/cfg.h"

static char dir[64];

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/test_cfgerr.XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void test_errors_are_kept_as_file_line_reason(void **state)
{
	struct cfgerr e;
	struct cfg c;

	(void)state;
	cfgerr_clear(&e);
	cfg_defaults(&c);
	/* through cfg itself, as main.c collects them */
	assert_int_equal(cfg_load_text(&c, "[game]\nlives = 12\nbogus = 1\n", 27, "/etc/x.ini",
				       cfgerr_add, &e), 2);
	assert_int_equal(e.n, 2);
	assert_non_null(strstr(e.text[0], "/etc/x.ini:2: "));
	assert_non_null(strstr(e.text[1], "/etc/x.ini:3: "));
	cfgerr_keep(&e, "--set", 0, "no '='");
	assert_string_equal(e.text[2], "--set: no '='");
}

static void test_more_than_the_kept_are_counted(void **state)
{
	struct cfgerr e;

	(void)state;
	cfgerr_clear(&e);
	for (int i = 0; i < CFGERR_MAX + 3; i++)
		cfgerr_keep(&e, "f", i + 1, "bad");
	assert_int_equal(e.n, CFGERR_MAX);
	assert_int_equal(e.more, 3);
}

static void test_acknowledged_survives_a_restart_for_the_same_errors_only(void **state)
{
	struct cfgerr e, again, other;

	(void)state;
	cfgerr_clear(&e);
	assert_int_equal(cfgerr_hash(&e), 0);
	assert_int_equal(cfgerr_acked(&e, dir), 1);          /* none: nothing to show */
	cfgerr_keep(&e, "/etc/arcaded/a.ini", 3, "unknown key 'x'");
	assert_int_not_equal(cfgerr_hash(&e), 0);
	assert_int_equal(cfgerr_acked(&e, dir), 0);
	assert_int_equal(cfgerr_acked(&e, NULL), 0);
	assert_int_equal(cfgerr_ack(&e, dir), 0);
	assert_int_equal(cfgerr_acked(&e, dir), 1);
	/* after a restart: the same text collected again */
	cfgerr_clear(&again);
	cfgerr_keep(&again, "/etc/arcaded/a.ini", 3, "unknown key 'x'");
	assert_int_equal(cfgerr_acked(&again, dir), 1);
	/* the same error on another line is another error */
	cfgerr_clear(&other);
	cfgerr_keep(&other, "/etc/arcaded/a.ini", 4, "unknown key 'x'");
	assert_int_equal(cfgerr_acked(&other, dir), 0);
	/* one more error: not acknowledged either */
	cfgerr_keep(&again, "/etc/arcaded/b.ini", 1, "bad value");
	assert_int_equal(cfgerr_acked(&again, dir), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_errors_are_kept_as_file_line_reason),
		cmocka_unit_test(test_more_than_the_kept_are_counted),
		cmocka_unit_test(test_acknowledged_survives_a_restart_for_the_same_errors_only),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
