/*
 * cfgerr: the configuration's errors, kept to be shown on screen (the
 * service menu's CONFIG ERRORS page and MAIN page, a notice on the attract
 * screen: engine/ui/hud.h hud_env.notice) until the operator acknowledges
 * them, not only logged. What the configuration layers report (file:line
 * and reason, config/cfg.h) is collected here as main.c loads them, and so
 * is a [game] wad / maps that could not be loaded (the built-in levels
 * then play).
 *
 * Acknowledged: the CRC-32 of the errors' text is kept in the state file
 * STATE_DIR/config-ack (config/st.h, power-cut safe); the same errors after
 * a restart are then not shown again, a new or changed one is. App text,
 * never sim state.
 */
#ifndef ARCADED_APP_CFGERR_H
#define ARCADED_APP_CFGERR_H

#include <stddef.h>
#include <stdint.h>

#define CFGERR_MAX 16           /* errors kept (more are counted, not kept) */
#define CFGERR_LEN 160          /* one error's text, cut */
#define CFGERR_ACK_FILE "config-ack"

struct cfgerr {
	int n;                      /* kept, 0..CFGERR_MAX */
	int more;                   /* reported beyond those */
	char text[CFGERR_MAX][CFGERR_LEN];  /* "/etc/arcaded/a.ini:3: unknown key 'x'" */
};

/* Empties e. */
void cfgerr_clear(struct cfgerr *e);

/* A cfg_err_fn (config/cfg.h) with user a struct cfgerr: logs the problem
 * as say_cfg does and keeps it. line 0: no line. */
void cfgerr_add(void *user, const char *file, int line, const char *msg);

/* Keeps the problem without logging it (the caller logged it). */
void cfgerr_keep(struct cfgerr *e, const char *file, int line, const char *msg);

/* The CRC-32 of every kept error's text (with the count of the others);
 * 0 when there are none. */
uint32_t cfgerr_hash(const struct cfgerr *e);

/* Whether e's errors were acknowledged: STATE_DIR/config-ack holds
 * cfgerr_hash(e). No errors count as acknowledged; dir NULL or "" (nothing
 * kept) or an unreadable file: not acknowledged. */
int cfgerr_acked(const struct cfgerr *e, const char *dir);

/* Keeps cfgerr_hash(e) in dir/config-ack. 0 or -errno (st_save's). */
int cfgerr_ack(const struct cfgerr *e, const char *dir);

#endif
