/* libFuzzer target: the INI reader, settings and bindings (config/cini.c,
 * cfg.c, bind.c). Whatever the bytes, loading must keep every setting
 * within its documented range. */
#include <stdint.h>
#include <stdlib.h>

#include "config/bind.h"
#include "config/cfg.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

static void quiet(void *user, const char *file, int line, const char *msg)
{
	(void)user;
	(void)file;
	(void)line;
	(void)msg;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	struct cfg c;
	struct bind_table b;

	cfg_defaults(&c);
	cfg_load_text(&c, (const char *)data, len, "fuzz.ini", quiet, NULL);
	if (c.game.render_width < 64 || c.game.render_width > 4096 ||
	    c.game.coins_per_credit < 1 || c.game.coins_per_credit > 9 ||
	    (c.display.rotate % 90) != 0 || c.display.rotate < 0 || c.display.rotate > 270)
		abort();
	bind_defaults(&b);
	bind_load_text(&b, (const char *)data, len, "fuzz.ini", quiet, NULL);
	for (int a = 0; a < ACT_COUNT; a++)
		for (int k = 0; k < BIND_MAX; k++)
			if (b.key[a][k] < -1 || b.key[a][k] > 0x2ff)
				abort();
	return 0;
}
