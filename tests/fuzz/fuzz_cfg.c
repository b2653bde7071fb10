/* libFuzzer target: the INI reader, settings and bindings (config/cini.c,
 * cfg.c, bind.c). Whatever the bytes, loading must keep every setting
 * within its documented range, and the bindings loaded, written back by
 * bind_format and read again, must be the same table. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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

/* bind_format's text read over a table binding nothing gives b again. */
static void round_trip(const struct bind_table *b)
{
	static struct bind_table back;
	size_t n = bind_format(b, NULL, 0);
	char *text = malloc(n + 1);

	if (!text)
		abort();
	if (bind_format(b, text, n + 1) != n || strlen(text) != n)
		abort();
	memset(&back, 0, sizeof(back));
	for (int a = 0; a < ACT_COUNT; a++)
		for (int k = 0; k < BIND_MAX; k++)
			back.key[a][k] = -1;
	if (bind_load_text(&back, text, n, "format", quiet, NULL) != 0)
		abort();
	free(text);
	if (memcmp(back.key, b->key, sizeof(b->key)) != 0 || back.ndev != b->ndev)
		abort();
	for (int d = 0; d < b->ndev; d++)
		if (strcmp(back.dev[d].id, b->dev[d].id) != 0 ||
		    memcmp(back.dev[d].key, b->dev[d].key, sizeof(b->dev[d].key)) != 0)
			abort();
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
	for (int d = -1; d < b.ndev; d++)
		for (int a = 0; a < ACT_COUNT; a++)
			for (int k = 0; k < BIND_MAX; k++) {
				int code = d < 0 ? b.key[a][k] : b.dev[d].key[a][k];

				if (code != -1 && (code < BIND_CODE_MIN || code > BIND_CODE_MAX))
					abort();
			}
	round_trip(&b);
	return 0;
}
