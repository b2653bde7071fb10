/*
 * ctl: from the controls of devices to the game's actions. Loads the
 * bindings (config/bind.h: built-in defaults < CONFIG_DIR/bindings.ini <
 * STATE_DIR/bindings.ini, which the wizard saves < input.bindings <
 * --bindings) and the autoconfig profiles (config/prof.h: CONFIG_DIR's
 * first, they win ties, then the shipped ones); identifies each device a
 * slot opens (a profile's section and decoder options when the operator
 * gave it none); turns key changes into actions for the command
 * (app/cmd.h), with input.log's line per change; and hooks up the input
 * configuration wizard (app/wiz.h, docs/wizard.md): while it runs, raw
 * controls go to it instead of the game; it starts from the service menu,
 * or by itself on a first boot for a pad nothing names; its result is
 * saved as STATE_DIR/bindings.ini.
 *
 * Its slot hooks (ctl_hooks, with the struct ctl as context) are what the
 * input slots (app/slot.h) report to.
 */
#ifndef ARCADED_APP_CTL_H
#define ARCADED_APP_CTL_H

#include "app/cmd.h"
#include "app/slot.h"
#include "app/wiz.h"
#include "config/bind.h"
#include "config/cfg.h"
#include "config/prof.h"

struct stats;
struct tape;

#define CTL_RAW 8                  /* control changes kept for the input test */
#define CTL_RAW_LEN 256            /* the whole line (a screen line shows 79) */

struct ctl {
	const struct cfg *cfg;
	struct bind_table binds;
	struct prof_set profs;     /* autoconfig profiles by VID:PID and name */
	struct cmd_state cs;       /* the actions the next command is built from */
	struct stats *stats;       /* borrowed: input latency */
	const struct tape *tape;   /* borrowed: no wizard while it records */
	int live;                  /* a cabinet, not a script or replay: the wizard may run */
	int persist;               /* the wizard's bindings are saved */
	struct wiz wiz;
	int wiz_on;                /* it runs: raw controls go to it, not to the game */
	int wiz_auto;              /* it may still start by itself (first boot) */
	/* Device sections profiles added at run time, with their profile: the
	 * wizard's file leaves them out while they are as the profile made
	 * them (a newer profile then still applies). */
	int nprof_secs;
	struct {
		char id[BIND_ID_MAX];
		const struct prof *p;
	} prof_secs[BIND_DEVICES];
	/* The last CTL_RAW control changes of the devices (not those the
	 * wizard takes), as the service menu's input test shows them: "evdev
	 * usb-1-1.2 KEY_LEFTCTRL down -> fire" (the input.log line's words);
	 * the newest is raw[(raw_n - 1) % CTL_RAW]. */
	char raw[CTL_RAW][CTL_RAW_LEN];
	unsigned raw_n;            /* changes ever kept */
};

/* The slot hooks; their context is a struct ctl. */
extern const struct slot_hooks ctl_hooks;

/* Loads the bindings and profiles (problems are logged with file:line)
 * into c, for configuration cfg and the --bindings file extra (NULL
 * none); config_dir NULL: none. live and persist as in struct ctl; stats
 * and tape are borrowed. Until the wizard has saved STATE_DIR/bindings.ini
 * (a first boot) on a cabinet that persists, it may start by itself. */
void ctl_load(struct ctl *c, const struct cfg *cfg, const char *config_dir, const char *extra,
	      int live, int persist, struct stats *stats, const struct tape *tape);

/* Loads into b the bindings a run uses, as ctl_load does: the defaults,
 * CONFIG_DIR/bindings.ini (config_dir NULL: none), STATE_DIR/bindings.ini
 * (*saved: whether the wizard ever saved it), cfg's input.bindings and
 * extra (--bindings, NULL none). Problems are logged. */
void ctl_bindings_load(struct bind_table *b, const struct cfg *cfg, const char *config_dir,
		       const char *extra, int *saved);

/* Whether control code of the device id does something in bindings b (a
 * struct bind_table *): its own [device] section's, else [keyboard]'s. In
 * the form in_backend.set_bound takes. */
int ctl_bound(void *b, const struct in_ident *id, int code);

/* Starts the wizard (why is logged) unless it runs, the cabinet is not
 * live, or a recording is being made (its screens would not replay). */
void ctl_wizard_start(struct ctl *c, const char *why);

/* Once per tick: the wizard's time; at its end, its bindings take effect
 * (and are saved) or nothing changes. */
void ctl_wizard_tick(struct ctl *c);

#endif
