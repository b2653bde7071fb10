/*
 * file_fixture: test files in a test's temporary directory, for the unit
 * tests of modules that read them (test_wads.c, test_mdir.c). Include after
 * <cmocka.h>: a file that cannot be written fails the test.
 */
#ifndef ARCADED_TESTS_FILE_FIXTURE_H
#define ARCADED_TESTS_FILE_FIXTURE_H

#include <stdio.h>

/* Writes text as the file dir/name, replacing any. */
static inline void ff_put(const char *dir, const char *name, const char *text)
{
	char path[256];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	assert_int_equal(fclose(f), 0);
}

#endif
