/*
 * cfgerr: configuration errors for the screen (contract in cfgerr.h).
 */
#include "app/cfgerr.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/say.h"
#include "config/st.h"

void cfgerr_clear(struct cfgerr *e)
{
	memset(e, 0, sizeof(*e));
}

void cfgerr_add(void *user, const char *file, int line, const char *msg)
{
	say_cfg(NULL, file, line, msg);
	if (user)
		cfgerr_keep(user, file, line, msg);
}

void cfgerr_keep(struct cfgerr *e, const char *file, int line, const char *msg)
{
	if (e->n == CFGERR_MAX) {
		e->more++;
		return;
	}
	if (line > 0)
		snprintf(e->text[e->n], CFGERR_LEN, "%s:%d: %s", file, line, msg);
	else
		snprintf(e->text[e->n], CFGERR_LEN, "%s: %s", file, msg);
	e->n++;
}

uint32_t cfgerr_hash(const struct cfgerr *e)
{
	uint32_t h = 0;
	uint8_t more[4];

	if (e->n == 0 && e->more == 0)
		return 0;
	for (int i = 0; i < e->n; i++)
		h = st_crc32(h, e->text[i], strlen(e->text[i]) + 1);  /* with the NUL: a separator */
	for (int i = 0; i < 4; i++)
		more[i] = (uint8_t)((unsigned)e->more >> (8 * i));
	h = st_crc32(h, more, sizeof(more));
	return h ? h : 1;   /* 0 means none */
}

int cfgerr_acked(const struct cfgerr *e, const char *dir)
{
	uint32_t want = cfgerr_hash(e), got = 0;
	void *buf = NULL;
	size_t len = 0;
	int rc;

	if (!want)
		return 1;
	if (!dir || !dir[0])
		return 0;
	rc = st_load(dir, CFGERR_ACK_FILE, &buf, &len, NULL, NULL, 0);
	if (rc == 0 && len == 4) {
		const uint8_t *b = buf;
		got = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 |
		      (uint32_t)b[3] << 24;
	}
	free(buf);
	return rc == 0 && got == want;
}

int cfgerr_ack(const struct cfgerr *e, const char *dir)
{
	uint32_t h = cfgerr_hash(e);
	uint8_t b[4] = { (uint8_t)h, (uint8_t)(h >> 8), (uint8_t)(h >> 16), (uint8_t)(h >> 24) };

	if (!dir || !dir[0])
		return -ENOENT;
	return st_save(dir, CFGERR_ACK_FILE, b, sizeof(b));
}
