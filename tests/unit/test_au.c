/*
 * au: the sound outputs' list and the spec that picks one.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <string.h>

#include "audio/au.h"

static void specs_name_a_backend_and_its_argument(void **state)
{
	const struct au_backend *be;
	const char *arg;
	char why[128] = "";

	(void)state;
	assert_int_equal(au_parse("alsa", "default", &be, &arg, why, sizeof(why)), 0);
	assert_ptr_equal(be, &au_alsa);
	assert_string_equal(arg, "default");
	assert_int_equal(au_parse("alsa:plughw:1,0", "default", &be, &arg, why, sizeof(why)), 0);
	assert_ptr_equal(be, &au_alsa);
	assert_string_equal(arg, "plughw:1,0");
	assert_int_equal(au_parse("wav:/tmp/a:b.wav", "default", &be, &arg, why, sizeof(why)), 0);
	assert_ptr_equal(be, &au_wav);
	assert_string_equal(arg, "/tmp/a:b.wav");
	assert_int_equal(au_parse("null", "default", &be, &arg, why, sizeof(why)), 0);
	assert_ptr_equal(be, &au_null);
	assert_string_equal(arg, "");
}

static void bad_specs_say_why(void **state)
{
	const struct au_backend *be = NULL;
	const char *arg;
	char why[128] = "";

	(void)state;
	assert_int_equal(au_parse("oss", "default", &be, &arg, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "unknown sound output \"oss\" (alsa, alsa:DEVICE, wav:FILE, null)");
	assert_int_equal(au_parse("wav", "default", &be, &arg, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "wav needs a file: wav:FILE");
	assert_int_equal(au_parse("wav:", "default", &be, &arg, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "wav needs a file: wav:FILE");
	assert_int_equal(au_parse("null:x", "default", &be, &arg, why, sizeof(why)), -EINVAL);
	assert_string_equal(why, "null takes no argument");
	assert_int_equal(au_parse("", "default", &be, &arg, why, sizeof(why)), -EINVAL);
	assert_int_equal(au_parse("alsax", "default", &be, &arg, why, sizeof(why)), -EINVAL);
	assert_null(be);
}

static void the_list_has_every_backend_once(void **state)
{
	int n = 0, live = 0;

	(void)state;
	for (int i = 0; au_backends[i]; i++) {
		n++;
		live += au_backends[i]->live;
		assert_non_null(au_backends[i]->open);
		assert_non_null(au_backends[i]->write);
		assert_non_null(au_backends[i]->close);
		assert_non_null(au_backends[i]->describe);
	}
	assert_int_equal(n, 3);
	assert_int_equal(live, 1);                  /* only ALSA comes and goes */
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(specs_name_a_backend_and_its_argument),
		cmocka_unit_test(bad_specs_say_why),
		cmocka_unit_test(the_list_has_every_backend_once),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
