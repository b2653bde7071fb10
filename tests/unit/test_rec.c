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
		.set = { .coins_per_credit = 3, .freeplay = 1, .start_in_play = 0, .difficulty = 2,
			 .lives = 5 },
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
	0x03, 0x01, 0x00, 0x02,                 /* 28 coins 3, freeplay 1, start 0, difficulty 2 */
	0x44, 0x33, 0x22, 0x11,                 /* 32 count */
	0x05, 0x00, 0x00, 0x00,                 /* 36 lives 5, reserved */
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
	assert_int_equal(h.set.difficulty, 2);
	assert_int_equal(h.set.lives, 5);
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
	assert_int_equal(decode_patched(8, 4, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "version 4 is newer than this build (3)");
	/* Versions 2 and 3 need their longer headers. */
	assert_int_equal(decode_patched(8, 2, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "file too short (40 bytes, the header needs 80)");
	assert_int_equal(decode_patched(8, 3, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "file too short (40 bytes, the header needs 104)");
	assert_int_equal(decode_patched(8, 0, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "version 0 is not a valid version");
	assert_int_equal(decode_patched(12, 39, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "header size 39 is smaller than 40");
	assert_int_equal(decode_patched(14, 0x10, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "header size 1048616 is larger than 1048576");
	assert_int_equal(decode_patched(10, 50, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "tick rate 50 is not 60");
	assert_int_equal(decode_patched(28, 0, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "coins_per_credit 0 out of range 1..9");
	assert_int_equal(decode_patched(28, 10, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "coins_per_credit 10 out of range 1..9");
	assert_int_equal(decode_patched(30, 2, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "freeplay 1 / start_in_play 2 is not 0 or 1");
	assert_int_equal(decode_patched(31, 4, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "difficulty 4 out of range 0..3");
	assert_int_equal(decode_patched(36, 10, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "lives 10 out of range 0..9");
	assert_int_equal(decode_patched(31, 3, 40, err, sizeof(err)), 0);
	assert_int_equal(decode_patched(36, 0, 40, err, sizeof(err)), 0);
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
	/* Extra bytes after the counted commands are not commands, but the
	 * file is not the length its count says: the 100 replay, then -EIO. */
	memset(buf + REC_HEADER_SIZE + 100 * REC_CMD_SIZE, 0x11, 10);
	write_bytes(path, buf, sizeof(buf));
	assert_int_equal(replay(path, 100), -EIO);
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
	snprintf(want, sizeof(want), "%s: version 7 is newer than this build (3)", path);
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

	/* a recording made before sound (engine 2): refused, naming it */
	h.engine_version = 2;
	assert_int_equal(rec_check(&h, 0x0102030405060708ull, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "engine version differs: recording 2, this build 9");

	assert_int_equal(rec_check(&h, 0xabcull, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "map content differs: recording 0x0102030405060708, "
				 "loaded 0x0000000000000abc; engine version differs: "
				 "recording 2, this build 9");
}

/* ---- version 2 ------------------------------------------------------ */

static struct rec_header sample_header_v2(void)
{
	struct rec_header h = sample_header();

	h.version = 2;
	h.render_w = 320;
	h.render_h = 240;
	h.hash_flags = REC_HAS_STATE | REC_HAS_FRAME;
	h.level = 2;
	h.render_version = 0x0a0b0c0d;
	memcpy(h.map_name, "MAP01", 6);
	h.start_time = 0x0000000063a1b2c3ll;
	return h;
}

static const uint8_t sample_bytes_v2[REC_HEADER_SIZE_V2] = {
	'A', 'R', 'C', 'D', 'R', 'E', 'C', 0,   /* 0 magic */
	0x02, 0x00,                             /* 8 version 2 */
	0x3c, 0x00,                             /* 10 tick rate 60 */
	0x50, 0x00, 0x00, 0x00,                 /* 12 header size 80 */
	0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01, /* 16 map hash */
	0x01, 0x00, 0x00, 0x00,                 /* 24 engine version 1 */
	0x03, 0x01, 0x00, 0x02,                 /* 28 coins 3, freeplay 1, start 0, difficulty 2 */
	0x44, 0x33, 0x22, 0x11,                 /* 32 count */
	0x05, 0x00, 0x00, 0x00,                 /* 36 lives 5, reserved */
	0x40, 0x01, 0xf0, 0x00,                 /* 40 render 320 x 240 */
	0x03, 0x02, 0x00, 0x00,                 /* 44 hash flags 3, level 2, reserved */
	0x0d, 0x0c, 0x0b, 0x0a,                 /* 48 renderer version */
	0x00, 0x00, 0x00, 0x00,                 /* 52 reserved */
	'M', 'A', 'P', '0', '1', 0, 0, 0,       /* 56 map name */
	0xc3, 0xb2, 0xa1, 0x63, 0, 0, 0, 0,     /* 64 start time */
	0, 0, 0, 0, 0, 0, 0, 0,                 /* 72 reserved */
};

static void test_v2_header_encode_is_byte_exact(void **state)
{
	struct rec_header h = sample_header_v2();
	uint8_t out[REC_HEADER_MAX];

	(void)state;
	memset(out, 0xaa, sizeof(out));
	assert_int_equal(rec_header_encode(out, &h), REC_HEADER_SIZE_V2);
	assert_memory_equal(out, sample_bytes_v2, REC_HEADER_SIZE_V2);
	/* Version 1 writes its 40 bytes only. */
	h.version = 1;
	memset(out, 0xaa, sizeof(out));
	assert_int_equal(rec_header_encode(out, &h), REC_HEADER_SIZE);
	assert_int_equal(out[REC_HEADER_SIZE], 0xaa);
}

static void test_v2_header_decode_round_trip(void **state)
{
	struct rec_header h;
	char err[128] = "";

	(void)state;
	assert_int_equal(rec_header_decode(sample_bytes_v2, sizeof(sample_bytes_v2), &h, err,
					   sizeof(err)), 0);
	assert_int_equal(h.version, 2);
	assert_int_equal(h.header_size, 80);
	assert_int_equal(h.render_w, 320);
	assert_int_equal(h.render_h, 240);
	assert_int_equal(h.hash_flags, 3);
	assert_int_equal(h.level, 2);
	assert_int_equal(h.render_version, 0x0a0b0c0d);
	assert_string_equal(h.map_name, "MAP01");
	assert_true(h.start_time == 0x63a1b2c3ll);
	assert_int_equal(h.set.coins_per_credit, 3);
	/* Version 1 leaves the version 2 fields zero. */
	assert_int_equal(rec_header_decode(sample_bytes, sizeof(sample_bytes), &h, err,
					   sizeof(err)), 0);
	assert_int_equal(h.hash_flags, 0);
	assert_int_equal(h.render_w, 0);
	assert_string_equal(h.map_name, "");
}

/* Bytes no field reads are checked too (issue 13 item 11): reserved bytes
 * must be 0, the map name holds nothing after its first NUL, the start
 * time fits 32 bits. */
static void test_v2_header_unused_bytes_are_checked(void **state)
{
	static const int reserved[] = { 37, 38, 39, 46, 47, 52, 53, 54, 55,
					72, 73, 74, 75, 76, 77, 78, 79 };
	uint8_t b[REC_HEADER_SIZE_V2];
	struct rec_header h;
	char err[128], want[64];

	(void)state;
	for (size_t i = 0; i < sizeof(reserved) / sizeof(reserved[0]); i++) {
		memcpy(b, sample_bytes_v2, sizeof(b));
		b[reserved[i]] = 0x20;
		assert_int_equal(rec_header_decode(b, sizeof(b), &h, err, sizeof(err)), -EINVAL);
		snprintf(want, sizeof(want), "reserved byte %d is 0x20, not 0", reserved[i]);
		assert_string_equal(err, want);
	}
	memcpy(b, sample_bytes_v2, sizeof(b));
	b[62] = 'X';                          /* "MAP01\0\0X" */
	assert_int_equal(rec_header_decode(b, sizeof(b), &h, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "map name padding is not all NUL");
	for (int off = 68; off < 72; off++) {
		memcpy(b, sample_bytes_v2, sizeof(b));
		b[off] = 1;
		assert_int_equal(rec_header_decode(b, sizeof(b), &h, err, sizeof(err)), -EINVAL);
		assert_non_null(strstr(err, "start time"));
	}
}

/* Version 3: every header byte but the count is covered by a check (the
 * header sum covers what no range check can, as the start time's low
 * bytes); the count is checked against the records (the reader). */
static void test_v3_header_every_byte_is_checked(void **state)
{
	struct rec_header h, back;
	uint8_t b[REC_HEADER_MAX], f[REC_HEADER_MAX];
	char err[128];
	size_t n;

	(void)state;
	memset(&h, 0, sizeof(h));
	h.version = REC_VERSION_3;
	h.tick_rate = 60;
	h.map_hash = 0x0102030405060708ull;
	h.engine_version = REC_ENGINE_VERSION;
	h.set.coins_per_credit = 1;
	h.set.lives = 3;
	h.set.volume = 80;
	h.set.attract_sound = 1;
	h.set.stage_time = 7;
	h.set.idle_out = G_IDLE_END;
	h.set.free_aim = 1;
	h.count = 7;
	h.render_w = 320;
	h.render_h = 240;
	h.hash_flags = REC_HAS_STATE | REC_HAS_FRAME | REC_HAS_AUDIO;
	h.render_version = REC_RENDER_VERSION;
	memcpy(h.map_name, "E1M1", 5);
	h.start_time = 1764115200;
	h.audio_rate = 48000;
	h.audio_version = REC_AUDIO_VERSION;
	h.sound_hash = 0x1122334455667788ull;
	n = rec_header_encode(b, &h);
	assert_int_equal(n, REC_HEADER_SIZE_V3);
	assert_int_equal(rec_header_decode(b, n, &back, err, sizeof(err)), 0);
	assert_true(back.start_time == 1764115200);
	assert_int_equal(b[37], 7);            /* the pacing settings' bytes */
	assert_int_equal(b[38], G_IDLE_END);
	assert_int_equal(back.set.stage_time, 7);
	assert_int_equal(back.set.idle_out, G_IDLE_END);
	assert_int_equal(b[39], 1);            /* auto-aim off */
	assert_int_equal(back.set.free_aim, 1);
	/* out of range, with a good sum: refused by name */
	h.set.stage_time = G_STAGE_TIME_MAX + 1;
	assert_int_equal(rec_header_decode(f, rec_header_encode(f, &h), &back, err, sizeof(err)),
			 -EINVAL);
	assert_string_equal(err, "stage_time 31 out of range 0..30 or 255 (off)");
	h.set.stage_time = 7;
	h.set.idle_out = G_IDLE_COUNT;
	assert_int_equal(rec_header_decode(f, rec_header_encode(f, &h), &back, err, sizeof(err)),
			 -EINVAL);
	assert_string_equal(err, "idle_out 3 out of range 0..2");
	h.set.idle_out = G_IDLE_END;
	h.set.free_aim = 2;
	assert_int_equal(rec_header_decode(f, rec_header_encode(f, &h), &back, err, sizeof(err)),
			 -EINVAL);
	assert_string_equal(err, "free_aim 2 out of range 0..1");
	h.set.free_aim = 1;
	for (size_t i = 0; i < n; i++) {
		memcpy(f, b, n);
		f[i] ^= 0x01;
		err[0] = '\0';
		if (i >= 32 && i < 36) {
			assert_int_equal(rec_header_decode(f, n, &back, err, sizeof(err)), 0);
			continue;
		}
		if (rec_header_decode(f, n, &back, err, sizeof(err)) != -EINVAL)
			fail_msg("byte %zu flipped: the header was accepted", i);
	}
	/* the start time's low byte, which only the sum covers */
	memcpy(f, b, n);
	f[64] ^= 0x01;
	assert_int_equal(rec_header_decode(f, n, &back, err, sizeof(err)), -EINVAL);
	assert_non_null(strstr(err, "header damaged (sum 0x"));
}

static int decode_v2_patched(size_t off, uint8_t v, char *err, size_t errlen)
{
	uint8_t b[REC_HEADER_SIZE_V2];
	struct rec_header h;

	memcpy(b, sample_bytes_v2, sizeof(b));
	b[off] = v;
	err[0] = '\0';
	return rec_header_decode(b, sizeof(b), &h, err, errlen);
}

static void test_v2_header_errors(void **state)
{
	char err[128];

	(void)state;
	assert_int_equal(decode_v2_patched(44, 0x08, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "hash flags 0x08 unknown");
	/* the snapshot flag needs a snapshot length (bytes 52..55) */
	assert_int_equal(decode_v2_patched(44, 0x04, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "snapshot of 0 bytes");
	assert_int_equal(decode_v2_patched(41, 0x20, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "render size 8256x240 out of range");
	{
		uint8_t b[REC_HEADER_SIZE_V2];
		struct rec_header h;

		memcpy(b, sample_bytes_v2, sizeof(b));
		b[42] = 0;                      /* 320 x 0 */
		assert_int_equal(rec_header_decode(b, sizeof(b), &h, err, sizeof(err)), -EINVAL);
		assert_string_equal(err, "render size 320x0 out of range");
	}
	assert_int_equal(decode_v2_patched(57, ' ', err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "map name is not printable ASCII");
	assert_int_equal(decode_v2_patched(12, 40, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "header size 40 is smaller than 80");
}

static uint64_t nth_state(uint32_t i)
{
	return 0x1000000000000001ull * (i + 1);
}

static uint64_t nth_frame(uint32_t i)
{
	return ~(uint64_t)i << 7;
}

static void write_v2(const char *path, uint8_t flags, uint32_t n)
{
	struct rec_header h = sample_header_v2();
	struct rec_writer *w;

	h.hash_flags = flags;
	assert_int_equal(rec_writer_open(path, &h, &w), 0);
	for (uint32_t i = 0; i < n; i++) {
		struct rec_tick t = { .cmd = nth_cmd(i), .state_hash = nth_state(i),
				      .frame_hash = nth_frame(i) };

		assert_int_equal(rec_writer_put_tick(w, &t), 0);
	}
	assert_int_equal(rec_writer_close(w), 0);
}

/* Replays path (written by write_v2 with flags) expecting n ticks. */
static int replay_v2(const char *path, uint8_t flags, uint32_t n)
{
	struct rec_reader *r;
	struct rec_tick t;
	char err[256];
	int ret;

	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), 0);
	assert_int_equal(rec_reader_count(r), n);
	for (uint32_t i = 0; i < n; i++) {
		struct sim_cmd want = nth_cmd(i);

		assert_int_equal(rec_reader_next_tick(r, &t), 1);
		assert_memory_equal(&t.cmd, &want, sizeof(want));
		assert_true(t.state_hash == (flags & REC_HAS_STATE ? nth_state(i) : 0));
		assert_true(t.frame_hash == (flags & REC_HAS_FRAME ? nth_frame(i) : 0));
	}
	ret = rec_reader_next_tick(r, &t);
	rec_reader_close(r);
	return ret;
}

static void test_v2_round_trip_for_every_hash_choice(void **state)
{
	static const size_t recsize[4] = { 6, 14, 14, 22 };
	char path[128];

	(void)state;
	for (uint8_t flags = 0; flags < 4; flags++) {
		const uint32_t n = 700; /* several writer buffers */
		struct stat sb;

		assert_int_equal(rec_record_size(flags), recsize[flags]);
		tmp_path(path, sizeof(path), "v2.rec");
		write_v2(path, flags, n);
		assert_int_equal(stat(path, &sb), 0);
		assert_int_equal(sb.st_size, 80 + n * recsize[flags]);
		assert_int_equal(replay_v2(path, flags, n), 0);
	}
	/* The state hash comes first, then the frame hash, little-endian. */
	{
		uint8_t b[80 + 22];

		write_v2(path, 3, 1);
		assert_int_equal(read_bytes(path, b, sizeof(b)), sizeof(b));
		assert_memory_equal(b + 86, "\x01\0\0\0\0\0\0\x10", 8);
		assert_memory_equal(b + 94, "\x80\xff\xff\xff\xff\xff\xff\xff", 8);
	}
}

static void test_v2_put_without_hashes_is_refused(void **state)
{
	struct rec_header h = sample_header_v2();
	struct sim_cmd c = nth_cmd(0);
	struct rec_writer *w;
	char path[128];

	(void)state;
	tmp_path(path, sizeof(path), "v2put.rec");
	assert_int_equal(rec_writer_open(path, &h, &w), 0);
	assert_int_equal(rec_writer_put(w, &c), -EINVAL);
	assert_int_equal(rec_writer_close(w), 0);
	/* A header the reader would refuse is never written. */
	h.hash_flags = 0x10;
	assert_int_equal(rec_writer_open(path, &h, &w), -EINVAL);
}

static void test_v2_cut_mid_record_replays_whole_records(void **state)
{
	uint8_t buf[80 + 50 * 22];
	char path[128];

	(void)state;
	tmp_path(path, sizeof(path), "v2cut.rec");
	write_v2(path, 3, 50);
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), sizeof(buf));
	memcpy(buf + 32, "\xff\xff\xff\xff", 4);
	write_bytes(path, buf, 80 + 20 * 22 + 21);
	assert_int_equal(replay_v2(path, 3, 20), 0);
	/* Finished (count 50) but holding 20 and a half: 20, then -EIO. */
	memcpy(buf + 32, "\x32\0\0\0", 4);
	write_bytes(path, buf, 80 + 20 * 22 + 21);
	assert_int_equal(replay_v2(path, 3, 20), -EIO);
}

static struct rec_run sample_run(const struct rec_header *h)
{
	struct rec_run run;

	rec_run_from_header(h, &run);
	run.map_hash = h->map_hash;
	return run;
}

static void test_check_run_names_each_difference(void **state)
{
	struct rec_header h = sample_header_v2();
	struct rec_run run;
	char err[512], want[512];

	(void)state;
	h.engine_version = REC_ENGINE_VERSION;
	h.render_version = REC_RENDER_VERSION;
	run = sample_run(&h);
	assert_int_equal(rec_check_run(&h, &run, err, sizeof(err)), 0);

	run.set.coins_per_credit = 1;
	run.set.freeplay = 0;
	run.set.start_in_play = 1;
	run.set.difficulty = 1;
	run.set.lives = 3;
	assert_int_equal(rec_check_run(&h, &run, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "settings differ: coins_per_credit recording 3, this run 1; "
				 "settings differ: freeplay recording 1, this run 0; "
				 "settings differ: start_in_play recording 0, this run 1; "
				 "settings differ: difficulty recording 2, this run 1; "
				 "settings differ: lives recording 5, this run 3");

	run = sample_run(&h);
	run.level = 1;
	run.map_name = NULL;
	run.render_w = 640;
	run.render_h = 480;
	h.render_version = REC_RENDER_VERSION + 1;
	assert_int_equal(rec_check_run(&h, &run, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "level differs: recording 2, loaded 1; "
		 "map differs: recording MAP01, loaded (a built-in level); "
		 "render size differs: recording 320x240, this run 640x480; "
		 "renderer version differs: recording %d, this build %d",
		 REC_RENDER_VERSION + 1, REC_RENDER_VERSION);
	assert_string_equal(err, want);
	/* Not rendering: size and renderer do not matter. */
	run = sample_run(&h);
	run.render_w = run.render_h = 0;
	assert_int_equal(rec_check_run(&h, &run, err, sizeof(err)), 0);
	/* Nor without stored frame hashes. */
	h.hash_flags = REC_HAS_STATE;
	run = sample_run(&h);
	run.render_w = 64;
	assert_int_equal(rec_check_run(&h, &run, err, sizeof(err)), 0);

	run.map_hash = 0xabc;
	h.engine_version = 10;
	assert_int_equal(rec_check_run(&h, &run, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "map content differs: recording 0x0102030405060708, loaded "
				 "0x0000000000000abc; engine version differs: recording 10, this "
				 "build 9");
	/* A message longer than the buffer is cut, not overrun. */
	assert_int_equal(rec_check_run(&h, &run, err, 20), -EINVAL);
	assert_int_equal(strlen(err), 19);
}

/* rec_verify_tick with the replay's state and frame hashes s and f. */
static int vtick(struct rec_verify *v, uint32_t tick, const struct rec_tick *t, uint64_t s,
		 uint64_t f)
{
	struct rec_tick run = { .state_hash = s, .frame_hash = f };

	return rec_verify_tick(v, tick, t, &run);
}

static void test_verify_finds_the_first_difference(void **state)
{
	struct rec_header h = sample_header_v2();
	struct rec_verify v;
	struct rec_run run;
	char line[512];

	(void)state;
	h.render_version = REC_RENDER_VERSION;
	run = sample_run(&h);
	rec_verify_init(&v, &h, &run);
	assert_string_equal(v.note, "");
	for (uint32_t i = 0; i < 10; i++) {
		struct rec_tick t = { .state_hash = nth_state(i), .frame_hash = nth_frame(i) };
		uint64_t s = nth_state(i), f = nth_frame(i);

		if (i == 7)
			f++;
		if (i >= 8)
			s++;
		assert_int_equal(vtick(&v, i, &t, s, f), i >= 7 ? -EDOM : 0);
	}
	assert_int_equal(rec_verify_summary(&v, line, sizeof(line)), -EDOM);
	assert_string_equal(line, "verify: FAILED: first difference at tick 7: frame hash "
				  "recording 0xfffffffffffffc00, replay 0xfffffffffffffc01 "
				  "(state hashes equal); 2 state, 1 frame and 0 audio hashes differ "
				  "of 10 ticks");

	rec_verify_init(&v, &h, &run);
	for (uint32_t i = 0; i < 3; i++) {
		struct rec_tick t = { .state_hash = nth_state(i), .frame_hash = nth_frame(i) };

		assert_int_equal(vtick(&v, i, &t, nth_state(i), nth_frame(i)), 0);
	}
	assert_int_equal(rec_verify_summary(&v, line, sizeof(line)), 0);
	assert_string_equal(line, "verify: 3 ticks, 3 state, 3 frame and 0 audio hashes equal");
}

static void test_verify_says_why_frames_are_not_compared(void **state)
{
	struct rec_header h = sample_header_v2();
	struct rec_tick t = { .state_hash = 1, .frame_hash = 2 };
	struct rec_verify v;
	char want[256];
	struct rec_run run;
	char line[512];

	(void)state;
	h.render_version = REC_RENDER_VERSION;
	run = sample_run(&h);
	run.render_w = run.render_h = 0;
	rec_verify_init(&v, &h, &run);
	assert_int_equal(vtick(&v, 0, &t, 1, 999), 0);
	assert_int_equal(rec_verify_summary(&v, line, sizeof(line)), 0);
	assert_string_equal(line, "verify: 1 ticks, 1 state, 0 frame and 0 audio hashes equal "
				  "(frame hashes not compared: not rendering)");

	run = sample_run(&h);
	run.render_w = 640;
	rec_verify_init(&v, &h, &run);
	assert_string_equal(v.note, "frame hashes not compared: recorded at 320x240, "
				    "rendering 640x240");
	h.render_version = REC_RENDER_VERSION + 1;
	run = sample_run(&h);
	rec_verify_init(&v, &h, &run);
	snprintf(want, sizeof(want), "frame hashes not compared: drawn by renderer version %d, "
		 "this build draws version %d", REC_RENDER_VERSION + 1, REC_RENDER_VERSION);
	assert_string_equal(v.note, want);
	assert_int_equal(vtick(&v, 0, &t, 5, 2), -EDOM);

	/* A recording without hashes verifies nothing, and says so. */
	h.hash_flags = 0;
	rec_verify_init(&v, &h, &run);
	assert_int_equal(vtick(&v, 0, &t, 5, 6), 0);
	assert_int_equal(rec_verify_summary(&v, line, sizeof(line)), 1);
	assert_string_equal(line, "verify: 1 ticks, nothing compared: the recording holds no "
				  "hashes");
}

static void test_repair_finishes_a_cut_recording_only(void **state)
{
	uint8_t buf[80 + 50 * 22];
	struct stat sb;
	char path[128], err[256];
	uint32_t count = 0;

	(void)state;
	tmp_path(path, sizeof(path), "repair.rec");
	write_v2(path, 3, 50);
	/* Finished: left as it is. */
	assert_int_equal(rec_repair(path, &count, err, sizeof(err)), 0);
	assert_int_equal(count, 50);
	assert_int_equal(stat(path, &sb), 0);
	assert_int_equal(sb.st_size, 80 + 50 * 22);
	/* Cut: 20 whole records and 21 bytes; the count was never written. */
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), sizeof(buf));
	memcpy(buf + 32, "\xff\xff\xff\xff", 4);
	write_bytes(path, buf, 80 + 20 * 22 + 21);
	assert_int_equal(rec_repair(path, &count, err, sizeof(err)), 0);
	assert_int_equal(count, 20);
	assert_int_equal(stat(path, &sb), 0);
	assert_int_equal(sb.st_size, 80 + 20 * 22);
	assert_int_equal(read_bytes(path, buf, 40), 40);
	assert_memory_equal(buf + 32, "\x14\0\0\0", 4);
	assert_int_equal(replay_v2(path, 3, 20), 0);
	/* Not a recording. */
	write_bytes(path, (const uint8_t *)"ARCD", 4);
	assert_int_equal(rec_repair(path, &count, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "file too short (4 bytes, the header needs 40)");
	tmp_path(path, sizeof(path), "none.rec");
	assert_int_equal(rec_repair(path, &count, err, sizeof(err)), -ENOENT);
}

/* ---- version 2 with a start snapshot --------------------------------- */

/* The sim's snapshot is the size its engine version says: a state field
 * added without a new REC_ENGINE_VERSION fails here (rec.h). */
static void test_the_engine_version_names_the_snapshot_size(void **state)
{
	(void)state;
	assert_int_equal(sim_snapshot_size(), REC_ENGINE_SNAPSHOT);
}

#define SNAP_LEN REC_ENGINE_SNAPSHOT     /* as big as a sim snapshot */

static uint8_t snap_byte(uint32_t i)
{
	return (uint8_t)(i * 7 + (i >> 8));
}

static void write_snap(const char *path, uint8_t flags, uint32_t n)
{
	static uint8_t snap[SNAP_LEN];
	struct rec_header h = sample_header_v2();
	struct rec_writer *w;

	for (uint32_t i = 0; i < SNAP_LEN; i++)
		snap[i] = snap_byte(i);
	h.hash_flags = flags;
	h.snapshot = snap;
	h.snapshot_len = SNAP_LEN;
	assert_int_equal(rec_writer_open(path, &h, &w), 0);
	for (uint32_t i = 0; i < n; i++) {
		struct rec_tick t = { .cmd = nth_cmd(i), .state_hash = nth_state(i),
				      .frame_hash = nth_frame(i) };

		assert_int_equal(rec_writer_put_tick(w, &t), 0);
	}
	assert_int_equal(rec_writer_close(w), 0);
}

static void check_snap(const char *path)
{
	const struct rec_header *h;
	struct rec_reader *r;
	char err[256];

	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), 0);
	h = rec_reader_header(r);
	assert_true(h->hash_flags & REC_HAS_SNAPSHOT);
	assert_int_equal(h->header_size, 80 + SNAP_LEN);
	assert_int_equal(h->snapshot_len, SNAP_LEN);
	assert_non_null(h->snapshot);
	for (uint32_t i = 0; i < SNAP_LEN; i++)
		if (h->snapshot[i] != snap_byte(i))
			fail_msg("snapshot byte %u", i);
	rec_reader_close(r);
}

/* The snapshot's header fields, by hand: header size 80 + 5, flag 0x04,
 * length 5 at 52, FNV-1a of "ABCDE" at 72 (0x65f9a54a4f1d65c8, computed
 * apart from engine/core/hash.c). */
static void test_snapshot_header_encode_is_byte_exact(void **state)
{
	struct rec_header h = sample_header_v2(), d;
	uint8_t out[REC_HEADER_MAX], want[REC_HEADER_SIZE_V2];
	char err[128];

	(void)state;
	memcpy(want, sample_bytes_v2, sizeof(want));
	want[12] = 85;
	want[44] = 0x07;
	want[52] = 5;
	memcpy(want + 72, "\xc8\x65\x1d\x4f\x4a\xa5\xf9\x65", 8);
	h.snapshot = (const uint8_t *)"ABCDE";
	h.snapshot_len = 5;
	assert_int_equal(rec_header_encode(out, &h), REC_HEADER_SIZE_V2);
	assert_memory_equal(out, want, sizeof(want));
	assert_int_equal(rec_header_decode(out, REC_HEADER_SIZE_V2, &d, err, sizeof(err)), 0);
	assert_int_equal(d.header_size, 85);
	assert_int_equal(d.hash_flags, 0x07);
	assert_int_equal(d.snapshot_len, 5);
	assert_true(d.snapshot_sum == 0x65f9a54a4f1d65c8ull);
	assert_null(d.snapshot);
	/* a length past the header size */
	want[52] = 6;
	assert_int_equal(rec_header_decode(want, sizeof(want), &d, err, sizeof(err)), -EINVAL);
	assert_string_equal(err, "snapshot of 6 bytes does not fit in header size 85");
	/* a recording without one decodes none */
	assert_int_equal(rec_header_decode(sample_bytes_v2, sizeof(sample_bytes_v2), &d, err,
					   sizeof(err)), 0);
	assert_int_equal(d.snapshot_len, 0);
	assert_null(d.snapshot);
}

static void test_snapshot_round_trip(void **state)
{
	char path[128];
	struct stat sb;

	(void)state;
	tmp_path(path, sizeof(path), "snap.rec");
	for (uint8_t flags = 0; flags < 4; flags++) {
		write_snap(path, flags, 700);
		assert_int_equal(stat(path, &sb), 0);
		assert_int_equal(sb.st_size, 80 + SNAP_LEN + 700 * rec_record_size(flags));
		check_snap(path);
		/* the records after it are what was written */
		assert_int_equal(replay_v2(path, flags, 700), 0);
	}
	/* no records at all: the snapshot alone */
	write_snap(path, 0, 0);
	check_snap(path);
	assert_int_equal(replay_v2(path, 0, 0), 0);
}

static void test_snapshot_cut_or_damaged_is_refused(void **state)
{
	static uint8_t buf[80 + SNAP_LEN + 10 * 22];
	struct rec_reader *r;
	char path[128], err[256], want[256];

	(void)state;
	tmp_path(path, sizeof(path), "snapcut.rec");
	write_snap(path, 3, 10);
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), sizeof(buf));
	/* cut inside the snapshot (as a power cut while the header was written) */
	write_bytes(path, buf, 80 + 100);
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s: snapshot cut short (100 of %d bytes)", path, SNAP_LEN);
	assert_string_equal(err, want);
	write_bytes(path, buf, 80);
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s: snapshot cut short (0 of %d bytes)", path, SNAP_LEN);
	assert_string_equal(err, want);
	/* one byte changed inside it */
	buf[80 + 3000] ^= 0x40;
	write_bytes(path, buf, sizeof(buf));
	assert_int_equal(rec_reader_open(path, &r, err, sizeof(err)), -EINVAL);
	snprintf(want, sizeof(want), "%s: snapshot damaged (checksum 0x", path);
	assert_memory_equal(err, want, strlen(want));
	assert_non_null(strstr(err, ", the header says 0x"));
	/* whole again: reads */
	buf[80 + 3000] ^= 0x40;
	write_bytes(path, buf, sizeof(buf));
	check_snap(path);
}

static void test_snapshot_writer_refuses_what_it_cannot_write(void **state)
{
	struct rec_header h = sample_header_v2();
	struct rec_writer *w;
	char path[128];

	(void)state;
	tmp_path(path, sizeof(path), "snapw.rec");
	h.snapshot_len = 10;                    /* no bytes */
	assert_int_equal(rec_writer_open(path, &h, &w), -EINVAL);
	h.snapshot = (const uint8_t *)"0123456789";
	h.version = 1;                          /* version 1 has no room for it */
	assert_int_equal(rec_writer_open(path, &h, &w), -EINVAL);
	h.version = 2;
	h.snapshot_len = 0;
	h.hash_flags = REC_HAS_SNAPSHOT;        /* the flag without a snapshot */
	assert_int_equal(rec_writer_open(path, &h, &w), -EINVAL);
	h.hash_flags = 0;
	h.snapshot_len = 10;
	assert_int_equal(rec_writer_open(path, &h, &w), 0);
	/* plain commands are fine: the snapshot is not a per-tick hash */
	{
		struct sim_cmd c = nth_cmd(3);

		assert_int_equal(rec_writer_put(w, &c), 0);
	}
	assert_int_equal(rec_writer_close(w), 0);
}

/* A game cut by a power cut is repaired with its snapshot kept. */
static void test_snapshot_recording_is_repaired_after_a_cut(void **state)
{
	static uint8_t buf[80 + SNAP_LEN + 50 * 22];
	char path[128], err[256];
	uint32_t count = 0;

	(void)state;
	tmp_path(path, sizeof(path), "snaprep.rec");
	write_snap(path, 3, 50);
	assert_int_equal(read_bytes(path, buf, sizeof(buf)), sizeof(buf));
	memcpy(buf + 32, "\xff\xff\xff\xff", 4);
	write_bytes(path, buf, 80 + SNAP_LEN + 20 * 22 + 21);
	assert_int_equal(rec_repair(path, &count, err, sizeof(err)), 0);
	assert_int_equal(count, 20);
	check_snap(path);
	assert_int_equal(replay_v2(path, 3, 20), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_header_encode_is_byte_exact),
		cmocka_unit_test(test_the_engine_version_names_the_snapshot_size),
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
		cmocka_unit_test(test_v2_header_encode_is_byte_exact),
		cmocka_unit_test(test_v2_header_decode_round_trip),
		cmocka_unit_test(test_v2_header_unused_bytes_are_checked),
		cmocka_unit_test(test_v3_header_every_byte_is_checked),
		cmocka_unit_test(test_v2_header_errors),
		cmocka_unit_test(test_v2_round_trip_for_every_hash_choice),
		cmocka_unit_test(test_v2_put_without_hashes_is_refused),
		cmocka_unit_test(test_v2_cut_mid_record_replays_whole_records),
		cmocka_unit_test(test_check_run_names_each_difference),
		cmocka_unit_test(test_verify_finds_the_first_difference),
		cmocka_unit_test(test_verify_says_why_frames_are_not_compared),
		cmocka_unit_test(test_repair_finishes_a_cut_recording_only),
		cmocka_unit_test(test_snapshot_header_encode_is_byte_exact),
		cmocka_unit_test(test_snapshot_round_trip),
		cmocka_unit_test(test_snapshot_cut_or_damaged_is_refused),
		cmocka_unit_test(test_snapshot_writer_refuses_what_it_cannot_write),
		cmocka_unit_test(test_snapshot_recording_is_repaired_after_a_cut),
	};

	return cmocka_run_group_tests(tests, setup, teardown);
}
