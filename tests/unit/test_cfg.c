/*
 * cfg: defaults, layering, every kind of error with its file:line, the
 * directory order, --set and cfg_format.
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

#include "config/cfg.h"

/* Every reported problem as "FILE:LINE: MSG\n". */
struct errs {
	char text[16384];
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

static int load(struct cfg *c, const char *text, struct errs *e)
{
	memset(e, 0, sizeof(*e));
	return cfg_load_text(c, text, strlen(text), "t.ini", on_err, e);
}

static void write_file(const char *path, const char *text)
{
	int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);

	assert_true(fd >= 0);
	assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
	close(fd);
}

static void test_defaults_match_the_documented_values(void **state)
{
	struct cfg c;

	(void)state;
	unsetenv("STATE_DIRECTORY");
	cfg_defaults(&c);
	assert_string_equal(c.display.backend, "auto");
	assert_string_equal(c.display.device, "/dev/fb0");
	assert_string_equal(c.display.tty, "/dev/tty0");
	assert_string_equal(c.display.file, "");
	assert_int_equal(c.display.file_width, 640);
	assert_int_equal(c.display.file_height, 480);
	assert_int_equal(c.display.file_stride, 0);
	assert_string_equal(c.display.file_format, "xrgb8888");
	assert_int_equal(c.display.rotate, 0);
	assert_int_equal(c.display.fill, 0);
	assert_int_equal(c.game.render_width, 320);
	assert_int_equal(c.game.render_height, 240);
	assert_int_equal(c.game.render_threads, 0);
	assert_int_equal(c.game.coins_per_credit, 1);
	assert_int_equal(c.game.freeplay, 0);
	assert_int_equal(c.game.start_in_play, 0);
	assert_int_equal(c.game.level, 1);
	assert_string_equal(c.input.evdev, "auto");
	assert_string_equal(c.input.bindings, "");
	assert_string_equal(c.paths.state_dir, "/var/lib/arcaded");
	assert_int_equal(c.recorder.keep, 20);
	assert_int_equal(c.recorder.max_mb, 64);
}

static void test_recorder_keys_and_their_limits(void **state)
{
	struct errs e;
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_set(&c, "recorder.keep=0", on_err, &e), 0);
	assert_int_equal(cfg_set(&c, "recorder.max_mb = 1024", on_err, &e), 0);
	assert_int_equal(c.recorder.keep, 0);
	assert_int_equal(c.recorder.max_mb, 1024);
	assert_int_equal(cfg_set(&c, "recorder.keep=1001", on_err, &e), -EINVAL);
	assert_int_equal(cfg_set(&c, "recorder.max_mb=-1", on_err, &e), -EINVAL);
	assert_int_equal(c.recorder.keep, 0);
	assert_int_equal(c.recorder.max_mb, 1024);
	assert_int_equal(e.count, 2);
}

static void test_kms_keys_and_their_limits(void **state)
{
	struct errs e;
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	assert_string_equal(c.display.card, "");
	assert_string_equal(c.display.mode, "");
	assert_int_equal(c.display.buffers, 3);
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_set(&c, "display.backend=kms", on_err, &e), 0);
	assert_int_equal(cfg_set(&c, "display.card=/dev/dri/card1", on_err, &e), 0);
	assert_int_equal(cfg_set(&c, "display.mode=1920x1080@60", on_err, &e), 0);
	assert_int_equal(cfg_set(&c, "display.buffers=2", on_err, &e), 0);
	assert_string_equal(c.display.backend, "kms");
	assert_string_equal(c.display.card, "/dev/dri/card1");
	assert_string_equal(c.display.mode, "1920x1080@60");
	assert_int_equal(c.display.buffers, 2);
	assert_int_equal(cfg_set(&c, "display.buffers=4", on_err, &e), -EINVAL);
	assert_int_equal(cfg_set(&c, "display.buffers=1", on_err, &e), -EINVAL);
	assert_int_equal(c.display.buffers, 2);
	assert_int_equal(e.count, 2);
}

static void test_state_dir_is_first_of_state_directory(void **state)
{
	struct cfg c;

	(void)state;
	setenv("STATE_DIRECTORY", "/var/lib/arcaded-a:/var/lib/other", 1);
	cfg_defaults(&c);
	assert_string_equal(c.paths.state_dir, "/var/lib/arcaded-a");
	setenv("STATE_DIRECTORY", "/srv/x", 1);
	cfg_defaults(&c);
	assert_string_equal(c.paths.state_dir, "/srv/x");
	setenv("STATE_DIRECTORY", "", 1);
	cfg_defaults(&c);
	assert_string_equal(c.paths.state_dir, "/var/lib/arcaded");
	unsetenv("STATE_DIRECTORY");
}

static void test_every_key_is_applied(void **state)
{
	static const char in[] = "[display]\nbackend = FILE\ndevice = /dev/fb1\ntty =\n"
				 "file = /tmp/fb\nfile_width = 800\nfile_height = 600\n"
				 "file_stride = 3328\nfile_format = rgb565\nrotate = 270\n"
				 "scale = fill\n[game]\nrender_width = 640\nrender_height = 480\n"
				 "render_threads = 3\ncoins_per_credit = 3\nfreeplay = yes\nstart_in_play = On\n"
				 "level = 2\n[input]\nevdev = /dev/input/event3\n"
				 "bindings = /etc/arcaded/extra.ini\n[paths]\nstate_dir = /srv/a\n";
	struct errs e;
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	assert_int_equal(load(&c, in, &e), 0);
	assert_string_equal(c.display.backend, "file");
	assert_string_equal(c.display.device, "/dev/fb1");
	assert_string_equal(c.display.tty, "");
	assert_string_equal(c.display.file, "/tmp/fb");
	assert_int_equal(c.display.file_width, 800);
	assert_int_equal(c.display.file_height, 600);
	assert_int_equal(c.display.file_stride, 3328);
	assert_string_equal(c.display.file_format, "rgb565");
	assert_int_equal(c.display.rotate, 270);
	assert_int_equal(c.display.fill, 1);
	assert_int_equal(c.game.render_width, 640);
	assert_int_equal(c.game.render_height, 480);
	assert_int_equal(c.game.render_threads, 3);
	assert_int_equal(c.game.coins_per_credit, 3);
	assert_int_equal(c.game.freeplay, 1);
	assert_int_equal(c.game.start_in_play, 1);
	assert_int_equal(c.game.level, 2);
	assert_string_equal(c.input.evdev, "/dev/input/event3");
	assert_string_equal(c.input.bindings, "/etc/arcaded/extra.ini");
	assert_string_equal(c.paths.state_dir, "/srv/a");
}

static void test_every_error_kind_names_its_line(void **state)
{
	static const char in[] = "[display]\n"                  /* 1 */
				 "rotate = 45\n"                /* 2 */
				 "bar = 1\n"                    /* 3 */
				 "backend = vga\n"              /* 4 */
				 "scale = stretch\n"            /* 5 */
				 "[foo]\n"                      /* 6 */
				 "anything = 1\n"               /* 7: covered by line 6 */
				 "[game]\n"                     /* 8 */
				 "render_width = 5000\n"        /* 9 */
				 "render_height = 12abc\n"      /* 10 */
				 "freeplay = maybe\n"           /* 11 */
				 "this is not ini\n"            /* 12 */
				 "level = 99999999999999999999\n" /* 13 */
				 "[input]\n"                    /* 14 */
				 "evdev = event3\n";            /* 15 */
	static const char want[] =
		"t.ini:2: rotate: 45 is not one of 0, 90, 180, 270\n"
		"t.ini:3: unknown key 'bar' in [display]\n"
		"t.ini:4: backend: 'vga' is not one of auto, kms, fbdev, file, term, null\n"
		"t.ini:5: scale: 'stretch' is not one of integer, fill\n"
		"t.ini:6: unknown section [foo]\n"
		"t.ini:9: render_width: 5000 out of range 64..4096\n"
		"t.ini:10: render_height: '12abc' is not an integer\n"
		"t.ini:11: freeplay: 'maybe' is not a boolean (yes/no, true/false, on/off, 1/0)\n"
		"t.ini:12: line is neither [section] nor key = value\n"
		"t.ini:13: level: 99999999999999999999 out of range 1..99\n"
		"t.ini:15: evdev: 'event3' is not auto, none or a device path\n";
	struct errs e;
	struct cfg c, d;

	(void)state;
	cfg_defaults(&c);
	cfg_defaults(&d);
	assert_int_equal(load(&c, in, &e), 11);
	assert_string_equal(e.text, want);
	/* Nothing was applied: every entry kept its default. */
	assert_memory_equal(&c, &d, sizeof(c));
}

static void test_too_long_values_keep_the_previous_value(void **state)
{
	char in[2200];
	struct errs e;
	struct cfg c;
	int n;

	(void)state;
	cfg_defaults(&c);
	/* 256 bytes: one more than display.device holds. */
	n = snprintf(in, sizeof(in), "[display]\ndevice = /");
	memset(in + n, 'd', 255);
	n += 255;
	/* 1024 bytes: more than any INI value may be. */
	n += snprintf(in + n, sizeof(in) - (size_t)n, "\nfile = ");
	memset(in + n, 'f', 1024);
	n += 1024;
	in[n] = '\0';
	assert_int_equal(load(&c, in, &e), 2);
	assert_string_equal(e.text, "t.ini:2: device: value too long (at most 255 bytes)\n"
				    "t.ini:3: value too long\n");
	assert_string_equal(c.display.device, "/dev/fb0");
	assert_string_equal(c.display.file, "");
}

static void test_key_outside_section_and_nul_bytes(void **state)
{
	static const char in[] = "level = 3\n[game]\nlevel = 4\0junk\nlevel = 5";
	struct errs e;
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_load_text(&c, in, sizeof(in) - 1, "t.ini", on_err, &e), 2);
	assert_string_equal(e.text, "t.ini:1: key 'level' is outside any [section]\n"
				    "t.ini:3: line contains a NUL byte\n");
	/* Line 4 has no final newline and still counts. */
	assert_int_equal(c.game.level, 5);
}

static void test_later_layer_overrides_and_bad_value_keeps_previous(void **state)
{
	struct errs e;
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	assert_int_equal(load(&c, "[display]\nrotate = 90\n[game]\nlevel = 4\n", &e), 0);
	assert_int_equal(c.display.rotate, 90);
	assert_int_equal(c.game.level, 4);
	/* Second layer: level changes, the bad rotate keeps layer one's 90. */
	assert_int_equal(load(&c, "[display]\nrotate = 45\n[game]\nlevel = 7\n", &e), 1);
	assert_string_equal(e.text, "t.ini:2: rotate: 45 is not one of 0, 90, 180, 270\n");
	assert_int_equal(c.display.rotate, 90);
	assert_int_equal(c.game.level, 7);
	/* Within one file the last line wins. */
	assert_int_equal(load(&c, "[game]\nlevel = 8\nlevel = 9\n", &e), 0);
	assert_int_equal(c.game.level, 9);
}

static void test_load_dir_reads_ini_files_in_byte_order(void **state)
{
	char dir[] = "/tmp/test_cfg.XXXXXX";
	const char *files[][2] = {
		{ "20-b.ini", "[game]\nlevel = 20\nb = 1\n" },
		{ "10-a.ini", "[game]\nlevel = 10\na = 1\n" },
		/* Byte order puts "Z" (0x5a) before "a" (0x61); a locale's
		 * dictionary order would not. */
		{ "a.ini", "[game]\nlevel = 30\nc = 1\n" },
		{ "Z.ini", "[game]\nlevel = 40\nz = 1\n" },
		{ "notes.txt", "[game]\nlevel = 50\n" },
		{ ".hidden.ini", "[game]\nlevel = 60\n" },
		/* bind_load's file, in the same directory. */
		{ "bindings.ini", "[keyboard]\nfire = x\n" },
	};
	char path[128], want[512];
	struct errs e;
	struct cfg c;

	(void)state;
	assert_non_null(mkdtemp(dir));
	for (size_t i = 0; i < sizeof(files) / sizeof(files[0]); i++) {
		snprintf(path, sizeof(path), "%s/%s", dir, files[i][0]);
		write_file(path, files[i][1]);
	}
	cfg_defaults(&c);
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_load_dir(&c, dir, on_err, &e), 4);
	snprintf(want, sizeof(want),
		 "%s/10-a.ini:3: unknown key 'a' in [game]\n"
		 "%s/20-b.ini:3: unknown key 'b' in [game]\n"
		 "%s/Z.ini:3: unknown key 'z' in [game]\n"
		 "%s/a.ini:3: unknown key 'c' in [game]\n",
		 dir, dir, dir, dir);
	assert_string_equal(e.text, want);
	assert_int_equal(c.game.level, 30);

	for (size_t i = 0; i < sizeof(files) / sizeof(files[0]); i++) {
		snprintf(path, sizeof(path), "%s/%s", dir, files[i][0]);
		unlink(path);
	}
	rmdir(dir);
	/* Gone: not an error, nothing reported. */
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_load_dir(&c, dir, on_err, &e), 0);
	assert_int_equal(e.count, 0);
}

static void test_load_file_missing_is_silent_unreadable_is_reported(void **state)
{
	char dir[] = "/tmp/test_cfg.XXXXXX";
	char path[128], want[256];
	struct errs e;
	struct cfg c;

	(void)state;
	assert_non_null(mkdtemp(dir));
	cfg_defaults(&c);
	memset(&e, 0, sizeof(e));
	snprintf(path, sizeof(path), "%s/none.ini", dir);
	assert_int_equal(cfg_load_file(&c, path, on_err, &e), -ENOENT);
	assert_int_equal(e.count, 0);
	/* A directory cannot be read as a file: reported with line 0. */
	assert_int_equal(cfg_load_file(&c, dir, on_err, &e), -EISDIR);
	snprintf(want, sizeof(want), "%s:0: cannot read: %s\n", dir, strerror(EISDIR));
	assert_string_equal(e.text, want);

	snprintf(path, sizeof(path), "%s/ok.ini", dir);
	write_file(path, "[game]\nfreeplay = true\nlevel = 0\n");
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_load_file(&c, path, on_err, &e), 1);
	snprintf(want, sizeof(want), "%s:3: level: 0 out of range 1..99\n", path);
	assert_string_equal(e.text, want);
	assert_int_equal(c.game.freeplay, 1);
	unlink(path);
	rmdir(dir);
}

static void test_set_applies_and_reports_as_set_line_0(void **state)
{
	struct errs e;
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_set(&c, "game.level=5", on_err, &e), 0);
	assert_int_equal(cfg_set(&c, " display.rotate = 180 ", on_err, &e), 0);
	assert_int_equal(cfg_set(&c, "display.file=/tmp/a=b", on_err, &e), 0);
	assert_int_equal(c.game.level, 5);
	assert_int_equal(c.display.rotate, 180);
	assert_string_equal(c.display.file, "/tmp/a=b");
	assert_int_equal(e.count, 0);

	assert_int_equal(cfg_set(&c, "level=6", on_err, &e), -EINVAL);
	assert_int_equal(cfg_set(&c, "game.level", on_err, &e), -EINVAL);
	assert_int_equal(cfg_set(&c, "foo.bar=1", on_err, &e), -EINVAL);
	assert_int_equal(cfg_set(&c, "game.nope=1", on_err, &e), -EINVAL);
	assert_int_equal(cfg_set(&c, "game.level=100", on_err, &e), -EINVAL);
	assert_string_equal(e.text, "--set:0: expected section.key=value, got 'level=6'\n"
				    "--set:0: expected section.key=value, got 'game.level'\n"
				    "--set:0: unknown section [foo]\n"
				    "--set:0: unknown key 'nope' in [game]\n"
				    "--set:0: level: 100 out of range 1..99\n");
	assert_int_equal(c.game.level, 5);
}

static void test_format_round_trips_every_key(void **state)
{
	struct cfg a, b;
	struct errs e;
	char buf[4096], small[16];
	size_t n;

	(void)state;
	cfg_defaults(&a);
	assert_int_equal(load(&a, "[display]\nbackend = null\nrotate = 90\nscale = fill\n"
				  "file = /tmp/f\n[game]\nfreeplay = 1\nlevel = 3\n"
				  "[input]\nevdev = none\n",
			      &e),
			 0);
	n = cfg_format(&a, buf, sizeof(buf));
	assert_int_equal(n, strlen(buf));
	assert_non_null(strstr(buf, "[display]\nbackend = null\n"));
	assert_non_null(strstr(buf, "\nrotate = 90\nscale = fill\n"));
	assert_non_null(strstr(buf, "\n\n[game]\n"));
	assert_non_null(strstr(buf, "\nfreeplay = yes\n"));
	assert_non_null(strstr(buf, "\n[paths]\nstate_dir = "));
	/* 42 keys, one line each, plus 6 section headers and 5 blank lines. */
	{
		int lines = 0;

		for (const char *p = buf; *p; p++)
			lines += *p == '\n';
		assert_int_equal(lines, 42 + 6 + 5);  /* keys, section headers, blank lines */
	}
	/* Reading the text back gives the same settings. */
	memset(&b, 0x55, sizeof(b));
	cfg_defaults(&b);
	assert_int_equal(load(&b, buf, &e), 0);
	assert_memory_equal(&a, &b, sizeof(a));
	/* A short buffer gets a truncated string and the full length. */
	assert_int_equal(cfg_format(&a, small, sizeof(small)), n);
	assert_int_equal(strlen(small), sizeof(small) - 1);
	assert_memory_equal(small, buf, sizeof(small) - 1);
	assert_int_equal(cfg_format(&a, NULL, 0), n);
}

/* config/arcaded.ini (installed to /etc/arcaded) shows every key at its
 * default, commented out. Run from the repository root, as make does. */
static void test_shipped_arcaded_ini_lists_every_key_at_its_default(void **state)
{
	static const char path[] = "config/arcaded.ini";
	char text[16384], out[16384];
	struct cfg c, d;
	struct errs e;
	size_t n = 0, o = 0;
	int fd, keys = 0;
	ssize_t r;

	(void)state;
	unsetenv("STATE_DIRECTORY");
	fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		fail_msg("%s: cannot open (run from the repository root)", path);
	while ((r = read(fd, text + n, sizeof(text) - 1 - n)) > 0)
		n += (size_t)r;
	close(fd);
	text[n] = '\0';
	cfg_defaults(&c);
	cfg_defaults(&d);
	/* As shipped: nothing to complain about, nothing changed. */
	memset(&e, 0, sizeof(e));
	assert_int_equal(cfg_load_file(&c, path, on_err, &e), 0);
	assert_memory_equal(&c, &d, sizeof(c));
	/* Uncomment every "; key = value" line: still the defaults, and every
	 * key is there. */
	for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
		size_t k = 2;

		if (strncmp(line, "; ", 2) == 0) {
			while ((line[k] >= 'a' && line[k] <= 'z') || line[k] == '_')
				k++;
			if (k > 2 && strncmp(line + k, " =", 2) == 0) {
				line += 2;
				keys++;
			}
		}
		o += (size_t)snprintf(out + o, sizeof(out) - o, "%s\n", line);
	}
	assert_int_equal(keys, 42);   /* every key of the schema (docs/config.md) */
	assert_int_equal(load(&c, out, &e), 0);
	assert_memory_equal(&c, &d, sizeof(c));
}

static void test_random_bytes_never_crash(void **state)
{
	uint32_t seed = 99;
	char buf[400];
	int n;
	struct errs e;
	struct cfg c;

	(void)state;
	for (int round = 0; round < 3000; round++) {
		size_t len = (size_t)(round % (int)sizeof(buf));

		for (size_t i = 0; i < len; i++) {
			static const char alpha[] = "[]=;# \n\0gamedisplylvrot9-0.";

			seed = seed * 1103515245u + 12345u;
			buf[i] = alpha[(seed >> 16) % (sizeof(alpha) - 1)];
		}
		cfg_defaults(&c);
		memset(&e, 0, sizeof(e));
		/* The count returned is the number of messages reported. */
		n = cfg_load_text(&c, buf, len, "r", on_err, &e);
		assert_int_equal(n, e.count);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_defaults_match_the_documented_values),
		cmocka_unit_test(test_state_dir_is_first_of_state_directory),
		cmocka_unit_test(test_every_key_is_applied),
		cmocka_unit_test(test_every_error_kind_names_its_line),
		cmocka_unit_test(test_too_long_values_keep_the_previous_value),
		cmocka_unit_test(test_key_outside_section_and_nul_bytes),
		cmocka_unit_test(test_later_layer_overrides_and_bad_value_keeps_previous),
		cmocka_unit_test(test_load_dir_reads_ini_files_in_byte_order),
		cmocka_unit_test(test_load_file_missing_is_silent_unreadable_is_reported),
		cmocka_unit_test(test_set_applies_and_reports_as_set_line_0),
		cmocka_unit_test(test_format_round_trips_every_key),
		cmocka_unit_test(test_recorder_keys_and_their_limits),
		cmocka_unit_test(test_kms_keys_and_their_limits),
		cmocka_unit_test(test_shipped_arcaded_ini_lists_every_key_at_its_default),
		cmocka_unit_test(test_random_bytes_never_crash),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
