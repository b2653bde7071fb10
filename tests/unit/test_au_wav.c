/*
 * au_wav: the WAV file output, byte by byte: the 44-byte header of
 * RIFF/WAVE PCM (written out here from the format's layout), samples as
 * little-endian 16-bit, sizes right at close and about once a second
 * before.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "audio/au.h"

static char dir[64];

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/test_au_wav.XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static size_t slurp(const char *path, uint8_t *b, size_t max)
{
	FILE *fp = fopen(path, "rb");
	size_t n;

	assert_non_null(fp);
	n = fread(b, 1, max, fp);
	fclose(fp);
	return n;
}

static void the_file_is_a_pcm_wav(void **state)
{
	static const uint8_t head[44] = {
		'R', 'I', 'F', 'F', 44, 0, 0, 0,      /* 36 + 8 data bytes */
		'W', 'A', 'V', 'E', 'f', 'm', 't', ' ',
		16, 0, 0, 0, 1, 0, 2, 0,              /* fmt size, PCM, 2 channels */
		0x22, 0x56, 0, 0,                     /* 22050 Hz */
		0x88, 0x58, 0x01, 0,                  /* 88200 bytes a second */
		4, 0, 16, 0,                          /* 4 bytes a frame, 16 bits */
		'd', 'a', 't', 'a', 8, 0, 0, 0,
	};
	const int16_t frames[4] = { 1, -2, 0x1234, -32768 };
	const uint8_t data[8] = { 0x01, 0x00, 0xfe, 0xff, 0x34, 0x12, 0x00, 0x80 };
	struct au_dev *d;
	struct au_status st;
	char path[128], why[256] = "";
	uint8_t b[256];

	(void)state;
	snprintf(path, sizeof(path), "%s/a.wav", dir);
	assert_int_equal(au_wav.open(path, 22050, &d, why, sizeof(why)), 0);
	assert_non_null(strstr(au_wav.describe(d), "22050 Hz"));
	assert_int_equal(au_wav.write(d, frames, 2, &st), 0);
	assert_int_equal(st.delay, 0);
	assert_int_equal(st.underruns, 0);
	assert_int_equal(st.dropped, 0);
	/* before the close: an empty file's sizes */
	assert_int_equal(slurp(path, b, sizeof(b)), 52);
	assert_int_equal(b[40], 0);
	au_wav.close(d);
	assert_int_equal(slurp(path, b, sizeof(b)), 52);
	assert_memory_equal(b, head, 44);
	assert_memory_equal(b + 44, data, 8);
}

static void sizes_are_set_about_once_a_second(void **state)
{
	static int16_t frames[2 * 800];
	struct au_dev *d;
	struct au_status st;
	char path[128], why[256] = "";
	uint8_t b[64];
	uint32_t size;

	(void)state;
	snprintf(path, sizeof(path), "%s/b.wav", dir);
	assert_int_equal(au_wav.open(path, 48000, &d, why, sizeof(why)), 0);
	for (int t = 0; t < 60; t++)
		assert_int_equal(au_wav.write(d, frames, 800, &st), 0);
	/* 60 ticks of 800 frames: 192000 bytes, set without a close (a crash
	 * then leaves a file that says how much of it is whole) */
	slurp(path, b, sizeof(b));
	size = b[40] | b[41] << 8 | b[42] << 16 | (uint32_t)b[43] << 24;
	assert_int_equal(size, 192000);
	au_wav.close(d);
}

static void an_unwritable_path_is_refused(void **state)
{
	struct au_dev *d = NULL;
	char why[256] = "";

	(void)state;
	assert_int_equal(au_wav.open("/nonexistent-dir/x.wav", 48000, &d, why, sizeof(why)),
			 -ENOENT);
	assert_string_equal(why, "No such file or directory");
	au_wav.close(NULL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(the_file_is_a_pcm_wav),
		cmocka_unit_test(sizes_are_set_about_once_a_second),
		cmocka_unit_test(an_unwritable_path_is_refused),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
