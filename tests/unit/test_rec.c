/*
 * rec: the recording format. Byte layouts are written out by hand from the
 * table in rec.h; round trips cover the extremes of every field; cut and
 * damaged files replay what they hold.
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
#include <sys/stat.h>
#include <unistd.h>

#include "input/rec.h"

static char tmpdir[64];

static int setup(void **state)
{
	(void)state;
	snprintf(tmpdir, sizeof(tmpdir), "/tmp/test_rec.XXXXXX");
	return mkdtemp(tmpdir) ? 0 : -1;
}

static int teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmpdir);
	return system(cmd) == 0 ? 0 : -1;
}

static void tmp_path(char *buf, size_t len, const char *name)
{
	snprintf(buf, len, "%s/%s", tmpdir, name);
}

static struct rec_header sample_header(void)
{
	struct rec_header h = {
		.version = 1,
		.tick_rate = 60,
		.map_hash = 0x0102030405060708ull,
		.engine_version = 1,
		.set = { .coins_per_credit = 3, .freeplay = 1, .start_in_play = 0 },
		.count = 0x11223344u,
	};
	return h;
}

static const uint8_t sample_bytes[REC_HEADER_SIZE] = {
	'A', 'R', 'C', 'D', 'R', 'E', 'C', 0,   /* 0 magic */
	0x01, 0x00,                             /* 8 version 1 */
	0x3c, 0x00,                             /* 10 tick rate 60 */
	0x28, 0x00, 0x00, 0x00,                 /* 12 header size 40 */
	0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01, /* 16 map hash */
	0x01, 0x00, 0x00, 0x00,                 /* 24 engine version 1 */
	0x03, 0x01, 0x00, 0x00,                 /* 28 coins 3, freeplay 1, start 0, 0 */
	0x44, 0x33, 0x22, 0x11,                 /* 32 count */
	0x00, 0x00, 0x00, 0x00,                 /* 36 reserved */
};

static void write_bytes(const char *path, const uint8_t *p, size_t n)
{
	int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);

	assert_true(fd >= 0);
	assert_int_equal(write(fd, p, n), (ssize_t)n);
	close(fd);
}

static size_t read_bytes(const char *path, uint8_t *p, size_t max)
{
	int fd = open(path, O_RDONLY | O_CLOEXEC);
	ssize_t n;

	assert_true(fd >= 0);
	n = read(fd, p, max);
	assert_true(n >= 0);
	close(fd);
	return (size_t)n;
}

static void test_header_encode_is_byte_exact(void **state)
{
	struct rec_header h = sample_header();
	uint8_t out[REC_HEADER_SIZE];

	(void)state;
	memset(out, 0xaa, sizeof(out));
	rec_header_encode(out, &h);
	assert_memory_equal(out, sample_bytes, REC_HEADER_SIZE);
}

static void test_header_decode_round_trip(void **state)
{
	struct rec_header h;
	char err[128] = "";

	(void)state;
	assert_int_equal(rec_header_decode(sample_bytes, sizeof(sample_bytes), &h, err,
					   sizeof(err)),
			 0);
	assert_int_equal(h.version, 1);
	assert_int_equal(h.tick_rate, 60);
	assert_int_equal(h.header_size, 40);
	assert_true(h.map_hash == 0x0102030405060708ull);
	assert_int_equal(h.engine_version, 1);
	assert_int_equal(h.set.coins_per_credit, 3);
	assert_int_equal(h.set.freeplay, 1);
	assert_int_equal(h.set.start_in_play, 0);
	assert_int_equal(h.count, 0x11223344u);
}

/* Decodes sample_bytes with byte off set to v; returns the message. */
static int decode_patched(size_t off, uint8_t v, size_t len, char *err, size_t errlen)
{
	uint8_t b[REC_HEADER_SIZE];
	struct rec_header h;

	memcpy(b, sample_bytes, sizeof(b));
	b[off] = v;
	if (err)
		err[0] = '\0';
	return rec_header_decode(b, len, &h, err, errlen);
}

static void test_header_errors(void **state)
{
	char err[128];

	(void)state;
	assert_int_equal(decode_patched(0, 'A', 39, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "file too short (39 bytes, the header needs 40)");
	assert_int_equal(decode_patched(3, 'X', 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "bad magic (not an arcaded recording)");
	assert_int_equal(decode_patched(7, 1, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "bad magic (not an arcaded recording)");
	assert_int_equal(decode_patched(8, 2, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "version 2 is newer than this build (1)");
	assert_int_equal(decode_patched(8, 0, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "version 0 is not a valid version");
	assert_int_equal(decode_patched(12, 39, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "header size 39 is smaller than 40");
	assert_int_equal(decode_patched(14, 1, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "header size 65576 is larger than 65536");
	assert_int_equal(decode_patched(10, 50, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "tick rate 50 is not 60");
	assert_int_equal(decode_patched(28, 0, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "coins_per_credit 0 out of range 1..9");
	assert_int_equal(decode_patched(28, 10, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "coins_per_credit 10 out of range 1..9");
	assert_int_equal(decode_patched(30, 2, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "freeplay 1 / start_in_play 2 is not 0 or 1");
	/* A larger header from a later minor addition is accepted. */
	assert_int_equal(decode_patched(12, 48, 40, err, sizeof(err)), 0);
	/* No room for a message is fine too. */
	assert_int_equal(decode_patched(3, 'X', 40, NULL, 0), -EINVAL);
}

static void test_cmd_encode_is_byte_exact(void **state)
{
	struct sim_cmd c = { .forward = -1, .side = -128, .turn = -2, .buttons = 0x0f, .coins = 2 };
	struct sim_cmd d = { .forward = 127, .side = 0, .turn = INT16_MIN, .buttons = 0xff,
			     .coins = 255 };
	struct sim_cmd e = { .forward = 1, .side = 5, .turn = 300, .buttons = 0, .coins = 0 };
	const uint8_t want_c[REC_CMD_SIZE] = { 0xff, 0x80, 0xfe, 0xff, 0x0f, 0x02 };
	const uint8_t want_d[REC_CMD_SIZE] = { 0x7f, 0x00, 0x00, 0x80, 0xff, 0xff };
	const uint8_t want_e[REC_CMD_SIZE] = { 0x01, 0x05, 0x2c, 0x01, 0x00, 0x00 };
	uint8_t out[REC_CMD_SIZE];

	(void)state;
	rec_cmd_encode(out, &c);
	assert_memory_equal(out, want_c, REC_CMD_SIZE);
	rec_cmd_encode(out, &d);
	assert_memory_equal(out, want_d, REC_CMD_SIZE);
	rec_cmd_encode(out, &e);
	assert_memory_equal(out, want_e, REC_CMD_SIZE);
}

/* Command i of a test sequence that walks every field through its extremes. */
static struct sim_cmd nth_cmd(uint32_t i)
{
	static const int8_t s8[] = { -128, -127, -1, 0, 1, 126, 127 };
	static const int16_t s16[] = { INT16_MIN, INT16_MIN + 1, -256, -1, 0, 1, 255, 256,
				       INT16_MAX };
	struct sim_cmd c = {
		.forward = s8[i % 7],
		.side = s8[(i / 7) % 7],
		.turn = s16[i % 9],
		.buttons = (uint8_t)(i * 37),
		.coins = (uint8_t)(255 - i % 256),
	};
	return c;
}

static void write_recording(const char *path, uint32_t n)
{
	struct rec_header h = sample_header();
	struct rec_writer *w;

	assert_int_equal(rec_writer_open(path, &h, &w), 0);
	for (uint32_t i = 0; i < n; i++) {
		struct sim_cmd c = nth_cmd(i);

		assert_int_equal(rec_writer_put(w, &c), 0);
	}
	assert_int_equal(rec_writer_close(w), 0);
}

/* Reads path and checks that commands 0..n-1 come back; returns the final
 * rec_reader_next result. */
static int replay(const char *path, uint32_t n)
{
	struct rec_reader *r;
	struct sim_cmd c;
	char err[256];
	int ret;

	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), 0);
	assert_int_equal(rec_reader_count(r), n);
	for (uint32_t i = 0; i < n; i++) {
		struct sim_cmd want = nth_cmd(i);

		assert_int_equal(rec_reader_next(r, &c), 1);
		assert_int_equal(c.forward, want.forward);
		assert_int_equal(c.side, want.side);
		assert_int_equal(c.turn, want.turn);
		assert_int_equal(c.buttons, want.buttons);
		assert_int_equal(c.coins, want.coins);
	}
	ret = rec_reader_next(r, &c);
	/* The end stays the end. */
	assert_int_equal(rec_reader_next(r, &c), ret);
	rec_reader_close(r);
	return ret;
}

static void test_writer_reader_round_trip(void **state)
{
	const uint32_t n = 5000; /* several writer buffers */
	uint8_t buf[REC_HEADER_SIZE + 5000 * REC_CMD_SIZE + 1];
	struct rec_reader *r;
	char path[128], err[128];

	(void)state;
	tmp_path(path, sizeof(path), "round.rec");
	write_recording(path, n);
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), REC_HEADER_SIZE + n * REC_CMD_SIZE);
	/* The count 5000 = 0x1388 at offset 32; the rest as given. */
	assert_int_equal(buf[32], 0x88);
	assert_int_equal(buf[33], 0x13);
	assert_int_equal(buf[34], 0);
	assert_int_equal(buf[35], 0);
	assert_memory_equal(buf, sample_bytes, 32);
	assert_int_equal(replay(path, n), 0);

	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), 0);
	assert_int_equal(rec_reader_header(r)->count, n);
	assert_true(rec_reader_header(r)->map_hash == 0x0102030405060708ull);
	rec_reader_close(r);
}

static void test_unfinished_recording_says_count_unknown(void **state)
{
	struct rec_header h = sample_header();
	uint8_t buf[REC_HEADER_SIZE + 3 * REC_CMD_SIZE];
	struct rec_writer *w;
	char path[128];

	(void)state;
	tmp_path(path, sizeof(path), "open.rec");
	assert_int_equal(rec_writer_open(path, &h, &w), 0);
	for (uint32_t i = 0; i < 3; i++) {
		struct sim_cmd c = nth_cmd(i);

		assert_int_equal(rec_writer_put(w, &c), 0);
	}
	assert_int_equal(rec_writer_flush(w), 0);
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), sizeof(buf));
	assert_memory_equal(buf + 32, "\xff\xff\xff\xff", 4);
	/* What a power cut leaves replays. */
	assert_int_equal(replay(path, 3), 0);
	assert_int_equal(rec_writer_close(w), 0);
	assert_int_equal(replay(path, 3), 0);
	assert_int_equal(rec_writer_close(NULL), 0);
	rec_reader_close(NULL);
}

static void test_cut_mid_command_replays_whole_commands(void **state)
{
	uint8_t buf[REC_HEADER_SIZE + 100 * REC_CMD_SIZE];
	char path[128];

	(void)state;
	tmp_path(path, sizeof(path), "cut.rec");
	write_recording(path, 100);
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), sizeof(buf));
	/* As a power cut leaves it: count unknown, 37 commands and 3 bytes. */
	memcpy(buf + 32, "\xff\xff\xff\xff", 4);
	write_bytes(path, buf, REC_HEADER_SIZE + 37 * REC_CMD_SIZE + 3);
	assert_int_equal(replay(path, 37), 0);
	/* Header only. */
	write_bytes(path, buf, REC_HEADER_SIZE);
	assert_int_equal(replay(path, 0), 0);
}

static void test_finished_but_short_replays_then_reports_eio(void **state)
{
	uint8_t buf[REC_HEADER_SIZE + 100 * REC_CMD_SIZE + 10];
	char path[128];

	(void)state;
	tmp_path(path, sizeof(path), "short.rec");
	write_recording(path, 100);
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), REC_HEADER_SIZE + 100 * REC_CMD_SIZE);
	/* Count says 100, the file holds 50 and 2 bytes. */
	write_bytes(path, buf, REC_HEADER_SIZE + 50 * REC_CMD_SIZE + 2);
	assert_int_equal(replay(path, 50), -EIO);
	/* Extra bytes after the counted commands are not commands. */
	memset(buf + REC_HEADER_SIZE + 100 * REC_CMD_SIZE, 0x11, 10);
	write_bytes(path, buf, sizeof(buf));
	assert_int_equal(replay(path, 100), 0);
}

static void test_larger_header_is_skipped(void **state)
{
	uint8_t buf[REC_HEADER_SIZE + 8 + 2 * REC_CMD_SIZE];
	struct sim_cmd c0 = nth_cmd(0), c1 = nth_cmd(1);
	char path[128];

	(void)state;
	memcpy(buf, sample_bytes, REC_HEADER_SIZE);
	buf[12] = 48;                               /* header size 48 */
	memcpy(buf + 32, "\x02\0\0\0", 4);          /* count 2 */
	memset(buf + REC_HEADER_SIZE, 0xee, 8);     /* the unknown addition */
	rec_cmd_encode(buf + 48, &c0);
	rec_cmd_encode(buf + 48 + REC_CMD_SIZE, &c1);
	tmp_path(path, sizeof(path), "big.rec");
	write_bytes(path, buf, sizeof(buf));
	assert_int_equal(replay(path, 2), 0);
}

static void test_reader_open_errors_name_the_file(void **state)
{
	struct rec_reader *r = NULL;
	char path[128], want[256], err[256];
	uint8_t b[REC_HEADER_SIZE];

	(void)state;
	tmp_path(path, sizeof(path), "missing.rec");
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -ENOENT);
	snprintf(want, sizeof(want), "%s: %s", path, strerror(ENOENT));
	assert_string_equal(err, want);

	tmp_path(path, sizeof(path), "empty.rec");
	write_bytes(path, b, 0);
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s: file too short (0 bytes, the header needs 40)", path);
	assert_string_equal(err, want);

	memcpy(b, sample_bytes, sizeof(b));
	b[0] = 'P';
	tmp_path(path, sizeof(path), "magic.rec");
	write_bytes(path, b, sizeof(b));
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s: bad magic (not an arcaded recording)", path);
	assert_string_equal(err, want);

	memcpy(b, sample_bytes, sizeof(b));
	b[8] = 7;
	write_bytes(path, b, sizeof(b));
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s: version 7 is newer than this build (1)", path);
	assert_string_equal(err, want);

	memcpy(b, sample_bytes, sizeof(b));
	b[12] = 64;
	write_bytes(path, b, sizeof(b));
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s: file too short (40 bytes, the header says 64)", path);
	assert_string_equal(err, want);
	assert_null(r);
}

static void test_writer_open_fails_cleanly(void **state)
{
	struct rec_header h = sample_header();
	struct rec_writer *w = NULL;
	char path[128];

	(void)state;
	tmp_path(path, sizeof(path), "no/such/dir.rec");
	assert_int_equal(rec_writer_open(path, &h, &w), -ENOENT);
	assert_null(w);
}

static void test_check_names_every_difference(void **state)
{
	struct rec_header h = sample_header();
	char err[256];

	(void)state;
	h.engine_version = REC_ENGINE_VERSION;
	assert_int_equal(rec_check(&h, 0x0102030405060708ull, err, sizeof(err)), 0);

	assert_int_equal(rec_check(&h, 0xabcull, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "map content differs: recording 0x0102030405060708, "
				 "loaded 0x0000000000000abc");

	h.engine_version = 2;
	assert_int_equal(rec_check(&h, 0x0102030405060708ull, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "engine version differs: recording 2, this build 1");

	assert_int_equal(rec_check(&h, 0xabcull, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "map content differs: recording 0x0102030405060708, "
				 "loaded 0x0000000000000abc; engine version differs: "
				 "recording 2, this build 1");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_header_encode_is_byte_exact),
		cmocka_unit_test(test_header_decode_round_trip),
		cmocka_unit_test(test_header_errors),
		cmocka_unit_test(test_cmd_encode_is_byte_exact),
		cmocka_unit_test(test_writer_reader_round_trip),
		cmocka_unit_test(test_unfinished_recording_says_count_unknown),
		cmocka_unit_test(test_cut_mid_command_replays_whole_commands),
		cmocka_unit_test(test_finished_but_short_replays_then_reports_eio),
		cmocka_unit_test(test_larger_header_is_skipped),
		cmocka_unit_test(test_reader_open_errors_name_the_file),
		cmocka_unit_test(test_writer_open_fails_cleanly),
		cmocka_unit_test(test_check_names_every_difference),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
