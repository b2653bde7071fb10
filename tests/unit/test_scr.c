/*
 * scr: the test-script format. A full example is parsed and every step
 * checked against what scr.h says it means; every error names its line;
 * decimals are converted to 16.16 by hand arithmetic.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine/game/sim.h"
#include "input/act.h"
#include "input/scr.h"

static struct scr *parse_ok(const char *text)
{
	struct scr *s = NULL;
	char err[256] = "";
	int ret = scr_parse(text, strlen(text), "t.scr", &s, err, sizeof(err));

	if (ret != 0)
		fail_msg("unexpected error %d: %s", ret, err);
	assert_non_null(s);
	return s;
}

static void expect_error_n(const char *text, size_t len, const char *want)
{
	struct scr *s = NULL;
	char err[256] = "";

	assert_int_equal(scr_parse(text, len, "t.scr", &s, err, sizeof(err)), -EINVAL);
	assert_null(s);
	assert_string_equal(err, want);
}

static void expect_error(const char *text, const char *want)
{
	expect_error_n(text, strlen(text), want);
}

static void check_step(const struct scr_step *st, uint32_t tick, uint32_t line,
		       enum scr_op op, int action)
{
	assert_int_equal(st->tick, tick);
	assert_int_equal(st->line, line);
	assert_int_equal(st->op, op);
	if (op == SCR_PRESS || op == SCR_RELEASE)
		assert_int_equal(st->action, action);
}

static void check_expect(const struct scr_step *st, uint32_t tick, uint32_t line,
			 enum scr_field f, enum scr_cmp c, int64_t v)
{
	check_step(st, tick, line, SCR_EXPECT, 0);
	assert_int_equal(st->field, f);
	assert_int_equal(st->cmp, c);
	assert_true(st->value == v);
}

static void test_full_example(void **state)
{
	static const char text[] =
		"# walk forward and check\n"             /* 1 */
		"0 tap coin\n"                           /* 2 */
		"2 tap start          # start a game\n"  /* 3 */
		"10 hold forward 30\n"                   /* 4 */
		"10 press turn_left\n"                   /* 5 */
		"20\trelease turn_left\r\n"              /* 6 */
		"40 expect x > 96.5\n"                   /* 7 */
		"40 expect mode == play\n"               /* 8 */
		"40 expect credits == 0\n"               /* 9 */
		"41 expect angle >= -90\n"               /* 10 */
		"41 expect sector != 3\n"                /* 11 */
		"\n"                                     /* 12 */
		"50 snapshot\n"                          /* 13 */
		"50 screenshot  shots/level one.png  \n" /* 14 */
		"60 end";                                /* 15 */
	struct scr *s = parse_ok(text);
	const struct scr_step *st = s->steps;

	(void)state;
	assert_int_equal(s->n, 16);
	assert_int_equal(s->end_tick, 60);
	check_step(&st[0], 0, 2, SCR_PRESS, ACT_COIN);
	check_step(&st[1], 1, 2, SCR_RELEASE, ACT_COIN);
	check_step(&st[2], 2, 3, SCR_PRESS, ACT_START);
	check_step(&st[3], 3, 3, SCR_RELEASE, ACT_START);
	check_step(&st[4], 10, 4, SCR_PRESS, ACT_FORWARD);
	check_step(&st[5], 10, 5, SCR_PRESS, ACT_TURN_LEFT);
	check_step(&st[6], 20, 6, SCR_RELEASE, ACT_TURN_LEFT);
	/* hold's release (line 4) sorts before line 7's check at tick 40. */
	check_step(&st[7], 40, 4, SCR_RELEASE, ACT_FORWARD);
	check_expect(&st[8], 40, 7, SCR_F_X, SCR_GT, 96 * 65536 + 32768);
	check_expect(&st[9], 40, 8, SCR_F_MODE, SCR_EQ, SIM_PLAY);
	check_expect(&st[10], 40, 9, SCR_F_CREDITS, SCR_EQ, 0);
	check_expect(&st[11], 41, 10, SCR_F_ANGLE, SCR_GE, -90);
	check_expect(&st[12], 41, 11, SCR_F_SECTOR, SCR_NE, 3);
	check_step(&st[13], 50, 13, SCR_SNAPSHOT, 0);
	check_step(&st[14], 50, 14, SCR_SCREENSHOT, 0);
	assert_string_equal(st[14].path, "shots/level one.png");
	check_step(&st[15], 60, 15, SCR_END, 0);
	scr_free(s);
}

static void test_end_tick_without_end_is_last_step(void **state)
{
	struct scr *s;

	(void)state;
	s = parse_ok("5 snapshot\n3 hold fire 10\n");
	assert_int_equal(s->end_tick, 13);   /* hold's release at 3 + 10 */
	scr_free(s);
	s = parse_ok("# nothing\n\n");
	assert_int_equal(s->n, 0);
	assert_int_equal(s->end_tick, 0);
	scr_free(s);
	s = parse_ok("");
	assert_int_equal(s->n, 0);
	scr_free(s);
	/* A release after end is fine: it cannot hide a check. */
	s = parse_ok("0 hold fire 100\n10 end\n");
	assert_int_equal(s->end_tick, 10);
	check_step(&s->steps[2], 100, 1, SCR_RELEASE, ACT_FIRE);
	scr_free(s);
}

static void test_hold_and_tap_expand(void **state)
{
	struct scr *s = parse_ok("7 tap use\n100 hold strafe_left 1\n0 hold fire 4294967295\n");

	(void)state;
	assert_int_equal(s->n, 6);
	check_step(&s->steps[0], 0, 3, SCR_PRESS, ACT_FIRE);
	check_step(&s->steps[1], 7, 1, SCR_PRESS, ACT_USE);
	check_step(&s->steps[2], 8, 1, SCR_RELEASE, ACT_USE);
	check_step(&s->steps[3], 100, 2, SCR_PRESS, ACT_STRAFE_LEFT);
	check_step(&s->steps[4], 101, 2, SCR_RELEASE, ACT_STRAFE_LEFT);
	check_step(&s->steps[5], 4294967295u, 3, SCR_RELEASE, ACT_FIRE);
	scr_free(s);
}

static void test_every_error_names_its_line(void **state)
{
	(void)state;
	expect_error("0 snapshot\n5 press jump\n", "t.scr:2: unknown action 'jump'");
	expect_error("0 snapshot\nfive press fire\n",
		     "t.scr:2: expected a tick number, got 'five'");
	expect_error("-1 snapshot\n", "t.scr:1: expected a tick number, got '-1'");
	expect_error("4294967296 snapshot\n",
		     "t.scr:1: expected a tick number, got '4294967296'");
	expect_error("\n\n7\n", "t.scr:3: expected a command after the tick");
	expect_error("1 jump\n", "t.scr:1: unknown command 'jump'");
	expect_error("1 press\n", "t.scr:1: expected an action");
	expect_error("1 press fire now\n", "t.scr:1: unexpected 'now' after the command");
	expect_error("1 hold fire\n", "t.scr:1: hold needs a number of ticks (1 or more)");
	expect_error("1 hold fire 0\n", "t.scr:1: hold needs a number of ticks (1 or more)");
	expect_error("1 hold fire x\n", "t.scr:1: hold needs a number of ticks (1 or more)");
	expect_error("1 hold fire 4294967295\n", "t.scr:1: release tick 4294967296 is too large");
	expect_error("1 tap fire 3\n", "t.scr:1: unexpected '3' after the command");
	expect_error("1 expect\n", "t.scr:1: expected FIELD OP VALUE after expect");
	expect_error("1 expect hp == 3\n", "t.scr:1: unknown field 'hp'");
	expect_error("1 expect Score == 3\n", "t.scr:1: unknown field 'Score'");
	expect_error("1 expect x\n", "t.scr:1: expected a comparison (== != < <= > >=)");
	expect_error("1 expect x = 3\n",
		     "t.scr:1: unknown comparison '=' (== != < <= > >=)");
	expect_error("1 expect x ==\n", "t.scr:1: expected a value");
	expect_error("1 expect x == abc\n", "t.scr:1: bad value 'abc' for x");
	expect_error("1 expect sector == -1\n", "t.scr:1: bad value '-1' for sector");
	expect_error("1 expect mode == pause\n", "t.scr:1: bad value 'pause' for mode");
	expect_error("1 expect mode < play\n", "t.scr:1: mode compares only with == or !=");
	expect_error("1 expect page >= demo\n", "t.scr:1: page compares only with == or !=");
	expect_error("1 expect page == play\n", "t.scr:1: bad value 'play' for page");
	expect_error("1 expect score > -1\n", "t.scr:1: bad value '-1' for score");
	expect_error("1 expect angle == 1.5\n", "t.scr:1: bad value '1.5' for angle");
	expect_error("1 expect tick == 1 2\n", "t.scr:1: unexpected '2' after the command");
	expect_error("1 screenshot   # no file\n", "t.scr:1: expected a file name");
	expect_error("1 end\n2 end\n", "t.scr:2: second end (the first is on line 1)");
	expect_error("1 snapshot\n9 expect tick == 9\n5 end\n",
		     "t.scr:2: tick 9 is after end (tick 5, line 3)");
	expect_error("6 press fire\n5 end\n", "t.scr:1: tick 6 is after end (tick 5, line 2)");
	expect_error_n("1 snapshot\n2 snap\0shot\n", 22, "t.scr:2: line contains a NUL byte");
	expect_error("1 Press fire\n", "t.scr:1: unknown command 'Press'");
}

static void test_long_tokens_are_cut_in_messages(void **state)
{
	char text[300], want[128];

	(void)state;
	memset(text, 'q', sizeof(text));
	memcpy(text, "1 press ", 8);
	text[sizeof(text) - 1] = '\0';
	snprintf(want, sizeof(want), "t.scr:1: unknown action '%.40s'", text + 8);
	expect_error(text, want);
}

static int64_t fixed_of(const char *v)
{
	char text[128];
	struct scr *s;
	int64_t r;

	snprintf(text, sizeof(text), "0 expect z == %s\n", v);
	s = parse_ok(text);
	r = s->steps[0].value;
	scr_free(s);
	return r;
}

static void test_decimals_become_16_16(void **state)
{
	(void)state;
	assert_true(fixed_of("1.5") == 98304);               /* 1.5 * 65536 */
	assert_true(fixed_of("-0.25") == -16384);
	assert_true(fixed_of("96") == 96 * 65536);
	assert_true(fixed_of("+2") == 2 * 65536);
	assert_true(fixed_of("-12.5") == -819200);
	assert_true(fixed_of("0") == 0);
	assert_true(fixed_of("-0") == 0);
	/* 0.00001 * 65536 = 0.65536: rounds up to 1. 0.000007 -> 0.4588: 0. */
	assert_true(fixed_of("0.00001") == 1);
	assert_true(fixed_of("0.000007") == 0);
	assert_true(fixed_of("-0.00001") == -1);
	/* 0.1 * 65536 = 6553.6 -> 6554; twelve digits are accepted. */
	assert_true(fixed_of("0.1") == 6554);
	assert_true(fixed_of("0.100000000000") == 6554);
	/* The ends of fx_t: 32767.99999 -> 32767 * 65536 + 65535 (65535.3). */
	assert_true(fixed_of("32767.99999") == INT32_MAX);
	assert_true(fixed_of("-32768") == INT32_MIN);
	assert_true(fixed_of("-32768.0") == INT32_MIN);
}

static void test_bad_decimals(void **state)
{
	(void)state;
	expect_error("0 expect y == 32768\n", "t.scr:1: bad value '32768' for y");
	expect_error("0 expect y == 32767.99999999\n",
		     "t.scr:1: bad value '32767.99999999' for y");  /* rounds to 32768 */
	expect_error("0 expect y == -32768.5\n", "t.scr:1: bad value '-32768.5' for y");
	expect_error("0 expect y == 1.\n", "t.scr:1: bad value '1.' for y");
	expect_error("0 expect y == .5\n", "t.scr:1: bad value '.5' for y");
	expect_error("0 expect y == 1.2.3\n", "t.scr:1: bad value '1.2.3' for y");
	expect_error("0 expect y == 1e3\n", "t.scr:1: bad value '1e3' for y");
	expect_error("0 expect y == 0.1234567890123\n",
		     "t.scr:1: bad value '0.1234567890123' for y");
	expect_error("0 expect y == --1\n", "t.scr:1: bad value '--1' for y");
	expect_error("0 expect y == 99999999999999999999\n",
		     "t.scr:1: bad value '99999999999999999999' for y");
}

static void test_integer_fields_and_ranges(void **state)
{
	struct scr *s = parse_ok("0 expect tick == 4294967295\n0 expect coins >= 2\n"
				 "0 expect angle < -2147483648\n0 expect angle <= 2147483647\n"
				 "0 expect mode != attract\n");

	(void)state;
	check_expect(&s->steps[0], 0, 1, SCR_F_TICK, SCR_EQ, 4294967295LL);
	check_expect(&s->steps[1], 0, 2, SCR_F_COINS, SCR_GE, 2);
	check_expect(&s->steps[2], 0, 3, SCR_F_ANGLE, SCR_LT, INT32_MIN);
	check_expect(&s->steps[3], 0, 4, SCR_F_ANGLE, SCR_LE, INT32_MAX);
	check_expect(&s->steps[4], 0, 5, SCR_F_MODE, SCR_NE, SIM_ATTRACT);
	scr_free(s);
	expect_error("0 expect tick == 4294967296\n", "t.scr:1: bad value '4294967296' for tick");
	expect_error("0 expect angle == 2147483648\n",
		     "t.scr:1: bad value '2147483648' for angle");
}

/* The game's fields come from the sim's table, with their kinds. */
static void test_game_fields(void **state)
{
	struct scr *s = parse_ok("5 expect score >= 1500\n"
				 "5 expect page == scores\n"
				 "6 expect mode == initials\n"
				 "6 expect lives == 0\n"
				 "7 expect countdown < 10\n");
	(void)state;
	assert_int_equal(s->n, 5);
	check_expect(&s->steps[0], 5, 1, (enum scr_field)sim_field_find("score"), SCR_GE, 1500);
	check_expect(&s->steps[1], 5, 2, (enum scr_field)sim_field_find("page"), SCR_EQ,
		     SIM_PAGE_SCORES);
	check_expect(&s->steps[2], 6, 3, SCR_F_MODE, SCR_EQ, SIM_INITIALS);
	check_expect(&s->steps[3], 6, 4, (enum scr_field)sim_field_find("lives"), SCR_EQ, 0);
	check_expect(&s->steps[4], 7, 5, (enum scr_field)sim_field_find("countdown"), SCR_LT, 10);
	assert_string_equal(scr_field_name(s->steps[0].field), "score");
	/* the first nine are the built-in enum's, in order */
	assert_int_equal(sim_field_find("x"), SCR_F_X);
	assert_int_equal(sim_field_find("tick"), SCR_F_TICK);
	assert_int_equal(sim_field_find("mode"), SCR_F_MODE);
	scr_free(s);
}

static void test_sort_is_stable_by_tick(void **state)
{
	enum { N = 3000 };
	char *text = malloc(N * 16);
	uint32_t seed = 1, count[20] = { 0 };
	size_t n = 0;
	struct scr *s;

	(void)state;
	assert_non_null(text);
	for (int i = 0; i < N; i++) {
		uint32_t t;

		seed = seed * 1103515245u + 12345u;
		t = (seed >> 16) % 20;
		count[t]++;
		n += (size_t)sprintf(text + n, "%u snapshot\n", t);
	}
	s = parse_ok(text);
	assert_int_equal(s->n, N);
	for (size_t i = 0; i < s->n; i++) {
		if (i > 0) {
			const struct scr_step *a = &s->steps[i - 1], *b = &s->steps[i];

			/* Ticks ascend; within a tick, file lines ascend. */
			assert_true(a->tick < b->tick || (a->tick == b->tick && a->line < b->line));
		}
		count[s->steps[i].tick]--;
	}
	for (int t = 0; t < 20; t++)
		assert_int_equal(count[t], 0);
	scr_free(s);
	free(text);
}

static void test_huge_lines_and_random_bytes(void **state)
{
	size_t big = 500000;
	char *text = malloc(big + 32);
	uint32_t seed = 3;
	struct scr *s;
	char err[256];

	(void)state;
	assert_non_null(text);
	/* Half a megabyte of blanks before a step is still one line. */
	memset(text, ' ', big);
	strcpy(text + big, "5 snapshot\n6 end");
	s = parse_ok(text);
	assert_int_equal(s->n, 2);
	check_step(&s->steps[0], 5, 1, SCR_SNAPSHOT, 0);
	scr_free(s);

	for (int round = 0; round < 3000; round++) {
		static const char alpha[] = "0123 tap hold x==.-#\n\0endexpect fire";
		size_t len = (size_t)(round % 200);
		int ret;

		for (size_t i = 0; i < len; i++) {
			seed = seed * 1103515245u + 12345u;
			text[i] = alpha[(seed >> 16) % (sizeof(alpha) - 1)];
		}
		s = NULL;
		err[0] = '\0';
		ret = scr_parse(text, len, "r", &s, err, sizeof(err));
		if (ret == 0) {
			assert_non_null(s);
			for (size_t i = 0; i < s->n; i++)
				assert_true(i == 0 || s->steps[i - 1].tick <= s->steps[i].tick);
			scr_free(s);
		} else {
			assert_int_equal(ret, -EINVAL);
			assert_null(s);
			assert_int_equal(strncmp(err, "r:", 2), 0);
		}
	}
	free(text);
}

static void test_compare_and_names(void **state)
{
	(void)state;
	assert_true(scr_compare(3, SCR_EQ, 3));
	assert_false(scr_compare(3, SCR_EQ, 4));
	assert_true(scr_compare(3, SCR_NE, 4));
	assert_false(scr_compare(3, SCR_NE, 3));
	assert_true(scr_compare(-5, SCR_LT, -4));
	assert_false(scr_compare(-4, SCR_LT, -4));
	assert_true(scr_compare(-4, SCR_LE, -4));
	assert_false(scr_compare(-3, SCR_LE, -4));
	assert_true(scr_compare(INT64_MAX, SCR_GT, 0));
	assert_false(scr_compare(0, SCR_GT, 0));
	assert_true(scr_compare(0, SCR_GE, 0));
	assert_false(scr_compare(-1, SCR_GE, 0));
	assert_string_equal(scr_field_name(SCR_F_X), "x");
	assert_string_equal(scr_field_name(SCR_F_MODE), "mode");
	assert_string_equal(scr_cmp_name(SCR_LE), "<=");
	assert_string_equal(scr_cmp_name(SCR_NE), "!=");
	assert_null(scr_field_name((enum scr_field)99));
	assert_null(scr_cmp_name((enum scr_cmp)99));
}

static void test_load_reads_files_and_names_them(void **state)
{
	char dir[] = "/tmp/test_scr.XXXXXX";
	char path[64], want[128], err[256];
	struct scr *s = NULL;
	int fd;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/missing.scr", dir);
	assert_int_equal(scr_load(path, &s, err, sizeof(err)), -ENOENT);
	snprintf(want, sizeof(want), "%s: %s", path, strerror(ENOENT));
	assert_string_equal(err, want);

	snprintf(path, sizeof(path), "%s/a.scr", dir);
	fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, "1 tap coin\n2 tap jump\n", 22), 22);
	close(fd);
	assert_int_equal(scr_load(path, &s, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s:2: unknown action 'jump'", path);
	assert_string_equal(err, want);

	assert_int_equal(truncate(path, 11), 0);
	assert_int_equal(scr_load(path, &s, err, sizeof(err)), 0);
	assert_int_equal(s->n, 2);
	scr_free(s);
	scr_free(NULL);

	assert_int_equal(truncate(path, (1 << 20) + 1), 0);
	assert_int_equal(scr_load(path, &s, err, sizeof(err)), -EFBIG);
	snprintf(want, sizeof(want), "%s: file is larger than 1048576 bytes", path);
	assert_string_equal(err, want);
	unlink(path);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_full_example),
		cmocka_unit_test(test_end_tick_without_end_is_last_step),
		cmocka_unit_test(test_hold_and_tap_expand),
		cmocka_unit_test(test_every_error_names_its_line),
		cmocka_unit_test(test_long_tokens_are_cut_in_messages),
		cmocka_unit_test(test_decimals_become_16_16),
		cmocka_unit_test(test_bad_decimals),
		cmocka_unit_test(test_integer_fields_and_ranges),
		cmocka_unit_test(test_game_fields),
		cmocka_unit_test(test_sort_is_stable_by_tick),
		cmocka_unit_test(test_huge_lines_and_random_bytes),
		cmocka_unit_test(test_compare_and_names),
		cmocka_unit_test(test_load_reads_files_and_names_them),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
