/*
 * The main loop and everything it wires together. This is the one place
 * that logs: library code returns errors, the app names the file or device
 * and carries on where it can.
 */
#include "app/app.h"

#include <dirent.h>
#include <errno.h>
#include <inttypes.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "app/cmd.h"
#include "app/ct.h"
#include "app/demo.h"
#include "app/glr.h"
#include "app/lat.h"
#include "app/pool.h"
#include "app/view.h"
#include "app/wiz.h"
#include "config/bind.h"
#include "config/fr.h"
#include "config/prof.h"
#include "config/st.h"
#include "display/dp.h"
#include "display/shot.h"
#include "engine/core/hash.h"
#include "engine/core/pal.h"
#include "engine/game/g_game.h"
#include "engine/game/menu.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud.h"
#include "input/gpo.h"
#include "input/hp.h"
#include "input/in.h"
#include "input/in_gpio.h"
#include "input/in_hid.h"
#include "input/rec.h"
#include "input/scr.h"
#include "systemd/svc.h"

#define APP_MAX_IN 8
#define APP_HID_AUTO 4            /* pads input.hid = auto opens: a 4-player cabinet */
#define APP_KEYS 1024             /* key codes tracked per device (KEY_CNT is 768) */
#define APP_TICK_NS(t) ((uint64_t)(t) * 1000000000ull / SIM_TICRATE)
#define APP_RESYNC_NS 250000000ull /* further behind than this: drop the backlog */
/* Rescan for lost or absent devices this often; hotplug notices (hp.h)
 * make a slot retry at once, this is the fallback. */
#define APP_REOPEN_NS 1000000000ull

/* Latency is kept per kind of input source as well as overall. */
enum app_src { APP_SRC_EVDEV, APP_SRC_TTY, APP_SRC_HID, APP_SRC_GPIO, APP_SRC_SCRIPT, APP_SRCS };
static const char *const app_src_name[APP_SRCS] = { "evdev", "tty", "hid", "gpio", "script" };

/* Set by signal handlers only; read by the loop. File-scope because a
 * handler has no other way to reach the loop. */
static volatile sig_atomic_t app_stop_sig;
static volatile sig_atomic_t app_summary_req;
static volatile sig_atomic_t app_fault_req;

struct app_in {
	const struct in_backend *be;
	struct in_dev *dev;
	const char *path;          /* what to (re)open; NULL: auto-detect */
	char spec[CFG_PATH_MAX];   /* the path's storage when split from a list */
	struct in_ident id;        /* who the open device is (per-device bindings) */
	uint64_t retry_ns;         /* when to try reopening a lost device */
	uint8_t down[APP_KEYS / 8];
};

struct app {
	const struct cfg *cfg;
	const struct app_opts *o;
	struct sim sim;
	struct sim_settings set;
	struct r_ctx *r;
	struct ct ct;              /* stage maps, texture set, light maps */
	const struct map *map;     /* = ct.map, the first stage */
	struct tex_set *tex;       /* = ct.tex: what r draws with */
	uint64_t map_hash;         /* of every stage: what recordings are tied to */
	struct view view;          /* draws the sim's frame */
	struct pool *pool;         /* render worker threads, NULL: one thread */
	struct glr glr;            /* --renderer gl: the OSMesa renderer plugin */
	struct rgl_ctx *gl;        /* its context */
	struct r_par par;
	struct demo demo;          /* the attract mode's demo */
	struct fr *fr;             /* flight recorder: the last games, NULL when off */
	struct rec_writer *game;   /* the game being recorded by fr */
	uint8_t *snap;             /* sim_snapshot before a tick that may start a game */
	int snap_taken;
	uint32_t snap_plays;       /* plays when the snapshot was taken */
	uint32_t set_gen, scores_gen, books_gen;  /* last persisted generations */
	uint8_t res;               /* render size choice in effect (menu) */
	int persist;               /* live cabinet: save settings, scores, books */
	struct r_frame frame;
	const struct dp_backend *dpb;
	struct dp *dp;
	struct app_in in[APP_MAX_IN];
	int nin;
	struct bind_table binds;
	struct prof_set profs;     /* autoconfig profiles by VID:PID and name */
	struct cmd_state cs;
	struct rec_writer *rec;
	struct rec_reader *rep;
	struct rec_verify verify;  /* --verify: stored hashes against the replay's */
	struct scr *scr;
	size_t scr_next;
	struct hp *hp;             /* hotplug notices, NULL: periodic rescans only */
	struct wiz wiz;            /* the input configuration wizard (app/wiz.h) */
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
	struct lat_series frame_time, latency;
	struct lat_series src_latency[APP_SRCS];
	uint64_t pending_ns;       /* earliest unpresented input event, 0 none */
	uint64_t src_pending_ns[APP_SRCS];  /* the same per kind of source */
	uint64_t start_ns, ticks_run, frames, dropped;
	int failures;
	int ready;
};

static void logf_(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void logf_(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	fputs("arcaded: ", stderr);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
	va_end(ap);
}

static void on_stop(int sig)
{
	app_stop_sig = sig;
}

static void sleep_until(uint64_t deadline_ns);

static void on_summary(int sig)
{
	(void)sig;
	app_summary_req = 1;
}

static void on_fault(int sig)
{
	(void)sig;
	app_fault_req = 1;
}

/* Fault injection for the watchdog test, off unless the environment asks:
 *   ARCADED_FAULT=hang-at:N   the main loop hangs after tick N
 *   ARCADED_FAULT=sigusr2     the main loop hangs when SIGUSR2 arrives
 * A hung loop stops sending WATCHDOG=1, so systemd must kill and restart
 * the service. Returns the tick to hang at, or UINT32_MAX. */
static uint32_t fault_setup(void)
{
	const char *f = getenv("ARCADED_FAULT");
	struct sigaction sa;

	if (!f || !*f)
		return UINT32_MAX;
	if (strncmp(f, "hang-at:", 8) == 0) {
		char *end;
		unsigned long n = strtoul(f + 8, &end, 10);
		if (*end == '\0' && end != f + 8 && n < UINT32_MAX) {
			logf_("fault injection: the main loop hangs after tick %lu", n);
			return (uint32_t)n;
		}
	} else if (strcmp(f, "sigusr2") == 0) {
		memset(&sa, 0, sizeof(sa));
		sigemptyset(&sa.sa_mask);
		sa.sa_handler = on_fault;
		sigaction(SIGUSR2, &sa, NULL);
		logf_("fault injection: SIGUSR2 hangs the main loop");
		return UINT32_MAX;
	}
	logf_("ARCADED_FAULT=%s not understood (hang-at:N or sigusr2); ignored", f);
	return UINT32_MAX;
}

/* The injected hang: sleeps forever without pinging, until a stop signal
 * (systemd's watchdog sends SIGABRT, which is fatal, not this). */
static void fault_hang(void)
{
	logf_("fault injection: main loop hung");
	while (!app_stop_sig)
		sleep_until(in_now_ns() + 1000000000ull);
}

/* A crash must not leave the console in graphics mode: restore it (only
 * async-signal-safe calls), then die of the same signal with the default
 * action (SA_RESETHAND put it back). */
static void on_fatal(int sig)
{
	dp_emergency_restore();
	raise(sig);
}

static void install_signals(void)
{
	struct sigaction sa;
	static const int fatal[] = { SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT };

	memset(&sa, 0, sizeof(sa));
	sigemptyset(&sa.sa_mask);
	sa.sa_handler = on_stop;
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	sigaction(SIGHUP, &sa, NULL);
	sa.sa_handler = on_summary;
	sa.sa_flags = SA_RESTART;
	sigaction(SIGUSR1, &sa, NULL);
	sa.sa_handler = SIG_IGN;
	sigaction(SIGPIPE, &sa, NULL);
	sa.sa_handler = on_fatal;
	sa.sa_flags = (int)SA_RESETHAND;
	for (size_t i = 0; i < sizeof(fatal) / sizeof(fatal[0]); i++)
		sigaction(fatal[i], &sa, NULL);
}

static int headless(const struct app *a)
{
	return a->o->script || a->o->replay;
}

static void report_cfg_error(void *user, const char *file, int line, const char *msg)
{
	(void)user;
	if (line > 0)
		logf_("%s:%d: %s", file, line, msg);
	else
		logf_("%s: %s", file, msg);
}

/* ---- input ---------------------------------------------------------- */

/* ---- the input configuration wizard (app/wiz.h, docs/wizard.md) ----- */

static void wizard_start(struct app *a, const char *why)
{
	if (a->wiz_on || headless(a))
		return;
	if (a->rec) {
		/* its screens are not the sim's: they would not replay */
		logf_("input wizard: not while recording (%s)", a->o->record);
		return;
	}
	a->wiz_auto = 0;
	cmd_reset(&a->cs);   /* nothing stays held for the game meanwhile */
	wiz_start(&a->wiz, &a->binds, in_now_ns());
	a->wiz_on = 1;
	logf_("input wizard: started (%s)", why);
}

/* Saves the bindings as STATE_DIR/bindings.ini, replaced atomically (a
 * power cut leaves the old file or the new one). */
static void wizard_save(struct app *a)
{
	const char *dir = a->cfg->paths.state_dir;
	struct bind_table *t = malloc(sizeof(*t));
	size_t n;
	char *text;
	int rc;

	if (!t) {
		logf_("input wizard: bindings not saved: out of memory");
		return;
	}
	/* What the operator set: [keyboard] and every device section except
	 * those a profile made and nobody changed. */
	*t = a->binds;
	for (int k = 0; k < a->nprof_secs; k++)
		for (int d = 0; d < t->ndev; d++) {
			if (strcmp(t->dev[d].id, a->prof_secs[k].id) != 0 ||
			    memcmp(t->dev[d].key, a->prof_secs[k].p->key, sizeof(t->dev[d].key)) != 0)
				continue;
			memmove(&t->dev[d], &t->dev[d + 1], (size_t)(t->ndev - d - 1) * sizeof(t->dev[0]));
			t->ndev--;
			break;
		}
	n = bind_format(t, NULL, 0);
	text = malloc(n + 1);

	if (!text) {
		logf_("input wizard: bindings not saved: out of memory");
		free(t);
		return;
	}
	bind_format(t, text, n + 1);
	free(t);
	rc = dir[0] ? st_write_plain(dir, "bindings.ini", text, n) : -ENOENT;
	if (rc < 0)
		logf_("input wizard: %s/bindings.ini not saved: %s (the bindings apply until the "
		      "daemon stops)", dir, strerror(-rc));
	else
		logf_("input wizard: bindings saved in %s/bindings.ini", dir);
	free(text);
}

static void wizard_tick(struct app *a)
{
	struct bind_table t;
	enum wiz_status st;

	if (!a->wiz_on)
		return;
	st = wiz_tick(&a->wiz, in_now_ns());
	if (st == WIZ_RUNNING)
		return;
	a->wiz_on = 0;
	if (st == WIZ_DONE && wiz_result(&a->wiz, &t)) {
		a->binds = t;
		logf_("input wizard: done: new bindings in effect");
		if (a->persist)
			wizard_save(a);
	} else {
		logf_("input wizard: %s: bindings unchanged", st == WIZ_DONE ? "done" : "cancelled");
	}
}

/* A device just opened: who it is, and a profile's bindings when the
 * operator has none for it (a known encoder works without configuration). */
static void identify(struct app *a, struct app_in *in)
{
	const struct prof *p;
	char why[160];
	int named;

	memset(&in->id, 0, sizeof(in->id));
	if (in->be->ident)
		in->be->ident(in->dev, &in->id);
	p = prof_match(&a->profs, in->be->name, &in->id);
	/* Checked before the profile adds its section: whether anything but
	 * the generic guess names this device. */
	named = (p && !p->any) || bind_find_device(&a->binds, &in->id);
	if (p) {
		if (prof_bind(p, &a->binds, &in->id) == 1 && a->nprof_secs < BIND_DEVICES) {
			const struct bind_dev *d = bind_find_device(&a->binds, &in->id);
			snprintf(a->prof_secs[a->nprof_secs].id, BIND_ID_MAX, "%s", d->id);
			a->prof_secs[a->nprof_secs++].p = p;
		}
		if (in->be == &in_hid && p->hid[0] &&
		    in_hid_configure(in->dev, p->hid, why, sizeof(why)) < 0)
			logf_("input hid: profile %s: %s", p->name, why);
		logf_("input %s: %s: profile %s", in->be->name, in->be->describe(in->dev), p->name);
	}
	if (!named && a->wiz_auto && in->be == &in_hid) {
		/* First boot (the wizard never saved): a pad nothing names (no
		 * section of its own, no profile but the generic guess): ask
		 * the operator, starting from that guess. */
		logf_("input %s: %s: no bindings and no profile for it", in->be->name,
		      in->be->describe(in->dev));
		wizard_start(a, "first boot");
	}
}

static void add_input(struct app *a, const struct in_backend *be, const char *path, int quiet)
{
	char why[512] = "";
	struct app_in *in;
	int rc;

	if (a->nin >= APP_MAX_IN)
		return;
	in = &a->in[a->nin++];
	memset(in, 0, sizeof(*in));
	in->be = be;
	if (path) {
		/* the slot keeps its own copy: it is reopened by it */
		snprintf(in->spec, sizeof(in->spec), "%s", path);
		path = in->path = in->spec;
	}
	rc = be->open(path, &in->dev, why, sizeof(why));
	if (rc < 0) {
		/* Not there yet (an encoder plugged in after boot, a named
		 * device that is unplugged): keep the slot and retry once a
		 * second. */
		if (!quiet)
			logf_("input %s: %s; retrying as devices appear, and every second", be->name,
			      why[0] ? why : strerror(-rc));
		in->dev = NULL;
		in->retry_ns = in_now_ns() + APP_REOPEN_NS;
		return;
	}
	logf_("input %s: %s", be->name, be->describe(in->dev));
	identify(a, in);
}

/* Opens every device of a blank-separated list of specs. */
static void add_inputs(struct app *a, const struct in_backend *be, const char *list)
{
	char buf[CFG_PATH_MAX], *save = NULL;

	snprintf(buf, sizeof(buf), "%s", list);
	for (char *tok = strtok_r(buf, " \t", &save); tok; tok = strtok_r(NULL, " \t", &save)) {
		if (a->nin >= APP_MAX_IN) {
			logf_("input %s: more than %d devices; %s ignored", be->name, APP_MAX_IN, tok);
			return;
		}
		add_input(a, be, tok, 0);
	}
}

static void open_inputs(struct app *a)
{
	const char *ev = a->cfg->input.evdev;

	if (headless(a))
		return;
	/* In the terminal preview the keys come from the terminal. Grabbing
	 * an auto-detected evdev keyboard there would take the developer's
	 * own keyboard away from every other window: only a device named in
	 * the configuration is opened. */
	if (a->dpb == &dp_term && strcmp(ev, "auto") == 0)
		logf_("input evdev: not auto-detected in the terminal preview (set input.evdev)");
	else if (strcmp(ev, "none") != 0)
		add_input(a, &in_evdev, strcmp(ev, "auto") == 0 ? NULL : ev, 0);
	if (a->dpb == &dp_term)
		add_input(a, &in_tty, NULL, 0);
	/* USB encoders and pads: auto opens every joystick or gamepad, up to
	 * APP_HID_AUTO of them (each slot takes one no other slot has;
	 * retried quietly: they may be plugged in later). */
	if (strcmp(a->cfg->input.hid, "auto") == 0)
		for (int k = 0; k < APP_HID_AUTO; k++)
			add_input(a, &in_hid, NULL, 1);
	else if (strcmp(a->cfg->input.hid, "none") != 0)
		add_inputs(a, &in_hid, a->cfg->input.hid);
	if (strcmp(a->cfg->input.gpio, "none") != 0)
		add_inputs(a, &in_gpio, a->cfg->input.gpio);
	if (a->nin == 0) {
		logf_("no input device configured: the game runs, but nothing controls it");
		return;
	}
	char why[256];
	if (hp_open(NULL, 0, HP_INOTIFY | HP_LIBUSB, &a->hp, why, sizeof(why)) < 0)
		logf_("input hotplug: %s; devices are looked for every second", why);
	else
		logf_("input hotplug: %s", hp_sources(a->hp));
}

/* input.log: one line per press and release, with who sent it and what it
 * does (the operator's view of a device; the VM tests read it too). */
static void log_key(const struct app_in *in, int code, int down, const int *acts, int n)
{
	char dev[48], what[160] = "";
	const char *name = in_key_name(code);
	size_t len = 0;

	if (in->id.port[0])
		snprintf(dev, sizeof(dev), "usb-%s", in->id.port);
	else if (in->id.vid || in->id.pid)
		snprintf(dev, sizeof(dev), "%04x:%04x", in->id.vid, in->id.pid);
	else
		snprintf(dev, sizeof(dev), "-");
	for (int i = 0; i < n && len < sizeof(what); i++)
		len += (size_t)snprintf(what + len, sizeof(what) - len, "%s%s", i ? "," : "",
					act_name(acts[i]));
	if (name)
		logf_("input: %s %s %s %s -> %s", in->be->name, dev, name, down ? "down" : "up",
		      n ? what : "unbound");
	else
		logf_("input: %s %s code %d %s -> %s", in->be->name, dev, code,
		      down ? "down" : "up", n ? what : "unbound");
}

/* A device went away: release every control it held so nothing stays
 * pressed, then close it and try again later. */
static void drop_input(struct app *a, struct app_in *in)
{
	int acts[ACT_COUNT];

	for (int code = 0; code < APP_KEYS; code++) {
		if (!(in->down[code / 8] & (1u << (code % 8))))
			continue;
		int n = bind_lookup_dev(&a->binds, &in->id, code, acts, ACT_COUNT);
		if (a->cfg->input.log)
			log_key(in, code, 0, acts, n);
		for (int i = 0; i < n; i++)
			cmd_action(&a->cs, acts[i], 0);
	}
	memset(in->down, 0, sizeof(in->down));
	if (a->wiz_on)
		wiz_drop(&a->wiz, &in->id);
	logf_("input %s: %s went away; its controls are released", in->be->name,
	      in->be->describe(in->dev));
	in->be->close(in->dev);
	in->dev = NULL;
	in->retry_ns = in_now_ns() + APP_REOPEN_NS;
}

static enum app_src src_of(const struct in_backend *be)
{
	if (be == &in_hid)
		return APP_SRC_HID;
	if (be == &in_gpio)
		return APP_SRC_GPIO;
	if (be == &in_tty)
		return APP_SRC_TTY;
	return APP_SRC_EVDEV;
}

/* An input event of source k at time t (kernel stamp) changed an action:
 * its effect is due on the next presented frame. */
static void input_pending(struct app *a, enum app_src k, uint64_t t)
{
	if (a->pending_ns == 0 || t < a->pending_ns)
		a->pending_ns = t;
	if (a->src_pending_ns[k] == 0 || t < a->src_pending_ns[k])
		a->src_pending_ns[k] = t;
}

static void key_event(struct app *a, struct app_in *in, const struct in_event *e)
{
	int acts[ACT_COUNT], n, down = e->value != 0;
	uint8_t bit;

	if (e->code >= APP_KEYS)
		return;
	bit = (uint8_t)(1u << (e->code % 8));
	/* Ignore a press of a key already down (and a release of one that is
	 * up): repeats and resyncs must not count twice. */
	if (!!(in->down[e->code / 8] & bit) == down)
		return;
	if (down)
		in->down[e->code / 8] |= bit;
	else
		in->down[e->code / 8] &= (uint8_t)~bit;
	if (a->wiz_on) {
		wiz_event(&a->wiz, in->be->name, in->be->ident ? &in->id : NULL, e->code, down,
			  e->time_ns);
		return;
	}
	n = bind_lookup_dev(&a->binds, &in->id, e->code, acts, ACT_COUNT);
	if (a->cfg->input.log)
		log_key(in, e->code, down, acts, n);
	for (int i = 0; i < n; i++)
		cmd_action(&a->cs, acts[i], down);
	if (n > 0)
		input_pending(a, src_of(in->be), e->time_ns);
}

static void read_inputs(struct app *a)
{
	struct in_event ev[64];
	uint64_t now = 0;

	/* A device node appeared or changed (udev grants access right after
	 * the kernel creates it): every closed slot tries now. */
	if (hp_poll(a->hp))
		for (int i = 0; i < a->nin; i++)
			a->in[i].retry_ns = 0;

	for (int i = 0; i < a->nin; i++) {
		struct app_in *in = &a->in[i];
		if (!in->dev) {
			if (!now)
				now = in_now_ns();
			if (now < in->retry_ns)
				continue;
			char why[256];
			if (in->be->open(in->path, &in->dev, why, sizeof(why)) < 0) {
				in->dev = NULL;
				in->retry_ns = now + APP_REOPEN_NS;
				continue;
			}
			logf_("input %s: attached %s", in->be->name, in->be->describe(in->dev));
			identify(a, in);
		}
		for (;;) {
			int n = in->be->read(in->dev, ev, (int)(sizeof(ev) / sizeof(ev[0])));
			if (n == -ENODEV) {
				drop_input(a, in);
				break;
			}
			if (n <= 0)
				break;
			for (int k = 0; k < n; k++)
				if (ev[k].type == IN_KEY)
					key_event(a, in, &ev[k]);
			if (n < (int)(sizeof(ev) / sizeof(ev[0])))
				break;
		}
	}
}

/* GPIO outputs follow the game each tick: a meter pulse per coin, the
 * start lamp blinking while credits wait. */
static void update_outputs(struct app *a)
{
	struct gpo_state gs = {
		.coins_total = a->sim.coins_total,
		.credits = a->sim.credits,
		.playing = a->sim.mode != SIM_ATTRACT && a->sim.mode != SIM_GAMEOVER,
	};
	uint64_t now = 0;

	for (int i = 0; i < a->nin; i++) {
		struct app_in *in = &a->in[i];
		if (in->be != &in_gpio || !in->dev)
			continue;
		if (!now)
			now = in_now_ns();
		if (in_gpio_update(in->dev, &gs, now) == -ENODEV)
			drop_input(a, in);
	}
}

/* ---- script --------------------------------------------------------- */

static int64_t field_value(const struct sim *s, enum scr_field f)
{
	return sim_field_value(s, (int)f);
}

/* Renders a script value the way the script wrote it. */
static void format_value(enum scr_field f, int64_t v, char *buf, size_t len)
{
	switch (sim_field_kind((int)f)) {
	case SIM_FK_FX: {
		/* 16.16 to decimal with 4 places, exact enough to read */
		int64_t m = v < 0 ? -v : v;
		snprintf(buf, len, "%s%" PRId64 ".%04" PRId64, v < 0 ? "-" : "", m >> 16,
			 ((m & 0xffff) * 10000) >> 16);
		break;
	}
	case SIM_FK_MODE: {
		const char *n = sim_mode_name((enum sim_mode)v);
		snprintf(buf, len, "%s", n ? n : "?");
		break;
	}
	case SIM_FK_PAGE: {
		const char *n = sim_page_name((int)v);
		snprintf(buf, len, "%s", n ? n : "?");
		break;
	}
	case SIM_FK_INT:
	case SIM_FK_ANGLE:
		snprintf(buf, len, "%" PRId64, v);
		break;
	}
}

/* Applies the script's press/release steps of tick t (before the tick). */
static void script_inputs(struct app *a, uint32_t t)
{
	for (size_t i = a->scr_next; i < a->scr->n && a->scr->steps[i].tick == t; i++) {
		const struct scr_step *st = &a->scr->steps[i];
		if (st->op == SCR_PRESS || st->op == SCR_RELEASE) {
			cmd_action(&a->cs, st->action, st->op == SCR_PRESS);
			if (st->op == SCR_PRESS && a->pending_ns == 0)
				input_pending(a, APP_SRC_SCRIPT, in_now_ns());
		}
	}
}

/* Runs the checks and outputs of tick t (after the tick ran). */
static void script_checks(struct app *a, uint32_t t)
{
	char got[64], want[64];

	for (; a->scr_next < a->scr->n && a->scr->steps[a->scr_next].tick == t; a->scr_next++) {
		const struct scr_step *st = &a->scr->steps[a->scr_next];
		switch (st->op) {
		case SCR_EXPECT: {
			int64_t v = field_value(&a->sim, st->field);
			if (!scr_compare(v, st->cmp, st->value)) {
				format_value(st->field, v, got, sizeof(got));
				format_value(st->field, st->value, want, sizeof(want));
				logf_("%s:%u: expect %s %s %s failed: %s is %s", a->o->script,
				      st->line, sim_field_name((int)st->field), scr_cmp_name(st->cmp),
				      want, sim_field_name((int)st->field), got);
				a->failures++;
			}
			break;
		}
		case SCR_SNAPSHOT:
			fprintf(a->o->out, "snapshot tick %u frame %016" PRIx64 " state %016" PRIx64 "\n",
				t, hash_frame(a->frame.px, a->frame.w, a->frame.h, a->frame.pitch),
				sim_hash(&a->sim));
			break;
		case SCR_SCREENSHOT: {
			int rc = shot_png(st->path, a->frame.px, a->frame.w, a->frame.h,
					  a->frame.pitch, a->tex->pal.rgb);
			if (rc < 0) {
				logf_("%s:%u: screenshot %s: %s", a->o->script, st->line, st->path,
				      strerror(-rc));
				a->failures++;
			}
			break;
		}
		case SCR_PRESS:
		case SCR_RELEASE:
		case SCR_END:
			break;
		}
	}
}

/* ---- set-up and tear-down ------------------------------------------- */

static int open_display(struct app *a)
{
	const struct cfg *c = a->cfg;
	struct dp_config dc;
	char why[1024] = "";
	int rc;

	memset(&dc, 0, sizeof(dc));
	dc.backend = c->display.backend;
	/* Scripts and replays run headless unless a display is named. */
	if (headless(a) && strcmp(dc.backend, "auto") == 0)
		dc.backend = c->display.file[0] ? "file" : "null";
	dc.device = c->display.device;
	dc.tty = c->display.tty;
	dc.file = c->display.file;
	dc.file_w = c->display.file_width;
	dc.file_h = c->display.file_height;
	dc.file_stride = c->display.file_stride;
	dc.file_format = c->display.file_format;
	dc.rotate = c->display.rotate;
	dc.scale = c->display.fill ? DP_SCALE_FILL : DP_SCALE_INTEGER;
	dc.render_w = a->frame.w;
	dc.render_h = a->frame.h;
	rc = dp_open(&dc, &a->dpb, &a->dp, why, sizeof(why));
	if (rc < 0) {
		logf_("display %s: %s", dc.backend, why[0] ? why : strerror(-rc));
		return rc;
	}
	logf_("display: %s", a->dpb->describe(a->dp));
	if (why[0])
		logf_("display: skipped %s", why);
	a->dpb->set_palette(a->dp, a->tex->pal.rgb);
	return 0;
}

/* ---- flight recorder -------------------------------------------------- */

/* Opens the recorder of a live cabinet ([recorder] keep games, max_mb). */
static void flight_setup(struct app *a)
{
	char dir[CFG_PATH_MAX + 16], msg[512] = "";
	int rc;

	if (!a->persist || a->cfg->recorder.keep <= 0)
		return;
	snprintf(dir, sizeof(dir), "%s/recordings", a->cfg->paths.state_dir);
	rc = fr_open(dir, a->cfg->recorder.keep, (uint64_t)a->cfg->recorder.max_mb << 20, &a->fr,
		     msg, sizeof(msg));
	if (msg[0])
		logf_("%s: %s", dir, msg);
	if (rc < 0) {
		logf_("%s: %s; games are not recorded", dir, strerror(-rc));
		a->fr = NULL;
		return;
	}
	a->snap = malloc(sim_snapshot_size());
	if (!a->snap) {
		fr_close(a->fr);
		a->fr = NULL;
	}
}

/* Before a tick: a START in attract may begin a game, so the state it
 * begins from is kept (the recording replays from it). */
static void flight_before(struct app *a, const struct sim_cmd *cmd)
{
	a->snap_taken = 0;
	if (a->fr && !a->game && a->sim.mode == SIM_ATTRACT && (cmd->buttons & SIM_BT_START)) {
		sim_snapshot(&a->sim, a->snap);
		a->snap_taken = 1;
		a->snap_plays = a->sim.plays;
	}
}

static void flight_finish(struct app *a)
{
	int rc = rec_writer_close(a->game);
	a->game = NULL;
	if (rc < 0)
		logf_("flight recorder: %s", strerror(-rc));
	rc = fr_end_game(a->fr, rc == 0);
	if (rc < 0)
		logf_("flight recorder: %s", strerror(-rc));
}

/* After a tick: start a game's recording when the game began this tick,
 * add the tick to it, end it when the cabinet is back in attract. */
static void flight_after(struct app *a, const struct sim_cmd *cmd)
{
	if (!a->fr)
		return;
	/* a game began: plays grew (a START that opened the service menu
	 * on the same tick is no game) */
	if (!a->game && a->snap_taken && a->sim.plays != a->snap_plays) {
		char path[CFG_PATH_MAX + 96];
		struct rec_header h = {
			.version = REC_VERSION_2,
			.tick_rate = SIM_TICRATE,
			.map_hash = a->map_hash,
			.engine_version = REC_ENGINE_VERSION,
			.set = a->sim.set,             /* as the service menu left them */
			.count = REC_COUNT_UNKNOWN,
			.render_w = (uint16_t)a->frame.w,
			.render_h = (uint16_t)a->frame.h,
			.render_version = REC_RENDER_VERSION,
			.hash_flags = REC_HAS_STATE,   /* state hashes are cheap; frames are not */
			.level = (uint8_t)(a->o->content.nwads || a->o->content.grid ? 0
										 : a->o->content.level),
			.start_time = (int64_t)time(NULL),
			.snapshot = a->snap,
			.snapshot_len = (uint32_t)sim_snapshot_size(),
		};
		int rc;
		if (a->o->content.map)
			snprintf(h.map_name, sizeof(h.map_name), "%s", a->o->content.map);
		rc = fr_begin_game(a->fr, time(NULL), path, sizeof(path));
		if (rc < 0) {
			logf_("flight recorder: %s", strerror(-rc));
			return;
		}
		rc = rec_writer_open(path, &h, &a->game);
		if (rc < 0) {
			/* give the slot back, or every later game would be refused */
			logf_("flight recorder: %s: %s", path, strerror(-rc));
			a->game = NULL;
			fr_end_game(a->fr, 0);
			return;
		}
	}
	if (!a->game)
		return;
	struct rec_tick t = { *cmd, sim_hash(&a->sim), 0 };
	if (rec_writer_put_tick(a->game, &t) < 0) {
		logf_("flight recorder: write failed; this game is not kept whole");
		flight_finish(a);
		return;
	}
	/* back in attract, or left for the service menu: the game is over */
	if (a->sim.mode == SIM_ATTRACT || a->sim.mode == SIM_SERVICE)
		flight_finish(a);
}

/* ---- persistence -------------------------------------------------- */

/* Loads a state file's payload; NULL when missing or unusable (reported). */
static void *load_state(struct app *a, const char *name, size_t *len)
{
	char msg[256] = "";
	void *buf = NULL;
	int rc = st_load(a->cfg->paths.state_dir, name, &buf, len, NULL, msg, sizeof(msg));

	if (msg[0] && rc != -ENOENT)
		logf_("%s/%s: %s", a->cfg->paths.state_dir, name, msg);
	if (rc < 0) {
		if (rc != -ENOENT)
			logf_("%s/%s: %s; using defaults", a->cfg->paths.state_dir, name,
			      strerror(-rc));
		return NULL;
	}
	return buf;
}

static void save_state(struct app *a, const char *name, const void *data, size_t len)
{
	int rc = st_save(a->cfg->paths.state_dir, name, data, len);
	if (rc < 0)
		logf_("%s/%s: not saved: %s (the previous copy is intact)", a->cfg->paths.state_dir,
		      name, strerror(-rc));
}

/* Starts the sim on every stage, with the cabinet's high scores and
 * bookkeeping when it keeps them. */
static void start_sim(struct app *a)
{
	struct g_scores scores, *sp = NULL;
	struct g_books books, *bp = NULL;
	size_t len = 0;
	void *buf;

	if (a->persist) {
		buf = load_state(a, "scores", &len);
		if (buf && g_scores_decode(buf, len, &scores) == 0)
			sp = &scores;
		else if (buf)
			logf_("%s/scores: not a high-score table; using the defaults",
			      a->cfg->paths.state_dir);
		free(buf);
		buf = load_state(a, "books", &len);
		if (buf && g_books_decode(buf, len, &books) == 0)
			bp = &books;
		else if (buf)
			logf_("%s/books: not bookkeeping; starting from zero", a->cfg->paths.state_dir);
		free(buf);
	}
	sim_init_stages(&a->sim, (const struct map *const *)a->ct.maps, a->ct.nmaps, &a->set, sp,
			bp);
	a->set_gen = a->sim.set_gen;
	a->scores_gen = a->sim.scores_gen;
	a->books_gen = a->sim.books_gen;
}

/* Settings changed in the service menu go to the state directory's
 * settings.ini (a state file whose payload is INI text), the layer main.c
 * reads after /etc/arcaded. */
static void save_settings(struct app *a)
{
	const struct sim_settings *st = &a->sim.set;
	char ini[256];
	int n = snprintf(ini, sizeof(ini),
			 "[game]\ncoins_per_credit = %u\nfreeplay = %s\ndifficulty = %u\nlives = %u\n"
			 "render_width = %d\nrender_height = %d\n",
			 st->coins_per_credit, st->freeplay ? "yes" : "no", st->difficulty,
			 st->lives, a->frame.w, a->frame.h);
	save_state(a, "settings.ini", ini, (size_t)n);
}

static void gl_world(void *ctx, const struct map *m, const struct tex_set *t,
		     const struct r_view *v, const struct r_sprite *spr, int nspr, struct r_frame *f)
{
	struct app *a = ctx;

	a->glr.render(a->gl, m, t, v, spr, nspr, f);
}

/* (Re)allocates the frame and the renderer for w x h. */
static int resize(struct app *a, int w, int h)
{
	struct r_ctx *r = NULL;
	uint8_t *px;
	int rc = r_new(w, h, &r);

	if (rc < 0) {
		logf_("renderer %dx%d: %s", w, h, strerror(-rc));
		return rc;
	}
	px = calloc((size_t)w * (size_t)h, 1);
	if (!px) {
		r_free(r);
		return -ENOMEM;
	}
	if (a->pool)
		r_set_par(r, &a->par);
	if (a->o->gl) {
		/* the OSMesa renderer, the software one's oracle, as the game's */
		char gerr[1024] = "";
		struct rgl_ctx *g = NULL;
		rc = a->glr.so ? 0 : glr_load(&a->glr, gerr, sizeof(gerr));
		if (rc == 0)
			rc = a->glr.create(w, h, &g, gerr, sizeof(gerr));
		if (rc < 0) {
			logf_("renderer gl %dx%d: %s", w, h, gerr[0] ? gerr : strerror(-rc));
			r_free(r);
			free(px);
			return rc;
		}
		if (a->gl)
			a->glr.destroy(a->gl);
		a->gl = g;
		a->view.world = gl_world;
		a->view.world_ctx = a;
		logf_("renderer: gl (%s, %s)", a->glr.name(g), a->glr.path);
	}
	r_free(a->r);
	free(a->frame.px);
	a->r = r;
	a->frame.px = px;
	a->frame.w = a->frame.pitch = w;
	a->frame.h = h;
	view_set_renderer(&a->view, r);
	return 0;
}

/* After each tick: what the service menu or the game changed that a live
 * cabinet keeps. */
static void persist_tick(struct app *a)
{
	uint8_t buf[G_SCORES_BYTES > G_BOOKS_BYTES ? G_SCORES_BYTES : G_BOOKS_BYTES];

	if (a->sim.menu.res != a->res) {
		int w = a->cfg->game.render_width, h = a->cfg->game.render_height;
		a->res = a->sim.menu.res;
		if (a->res)
			menu_res_size(a->res, &w, &h);
		if (resize(a, w, h) == 0)
			logf_("render size %dx%d", w, h);
		if (a->persist)
			save_settings(a);
	}
	if (!a->persist)
		return;
	if (a->sim.set_gen != a->set_gen) {
		a->set_gen = a->sim.set_gen;
		save_settings(a);
	}
	if (a->sim.scores_gen != a->scores_gen) {
		a->scores_gen = a->sim.scores_gen;
		g_scores_encode(&a->sim.scores, buf);
		save_state(a, "scores", buf, G_SCORES_BYTES);
	}
	if (a->sim.books_gen != a->books_gen) {
		a->books_gen = a->sim.books_gen;
		g_books_encode(&a->sim.books, buf);
		save_state(a, "books", buf, G_BOOKS_BYTES);
	}
}

static int setup(struct app *a)
{
	const struct cfg *c = a->cfg;
	char err[512] = "";
	int rc;

	struct ct_spec spec = a->o->content;
	int rw = c->game.render_width, rh_h = c->game.render_height;
	int sized = a->o->size_w > 0;

	if (a->o->replay) {
		struct rec_run run;
		rc = rec_reader_open(a->o->replay, &a->rep, err, sizeof(err));
		if (rc < 0) {
			logf_("%s", err[0] ? err : strerror(-rc));
			return rc;
		}
		/* A recording says which built-in level and frame size it was
		 * made with (format 2); the replay uses them. */
		rec_run_from_header(rec_reader_header(a->rep), &run);
		if (run.level && spec.nwads == 0 && !spec.grid)
			spec.level = run.level;
		if (run.render_w && run.render_h && !sized) {
			rw = run.render_w;
			rh_h = run.render_h;
		}
	}
	if (sized) {
		rw = a->o->size_w;
		rh_h = a->o->size_h;
	}
	spec.stop = &app_stop_sig;      /* a stop signal ends a long load */
	rc = ct_load(&a->ct, &spec, err, sizeof(err));
	if (rc < 0) {
		logf_("%s", err);
		return rc;
	}
	if (a->ct.note[0])
		logf_("%s", a->ct.note);
	a->map = a->ct.map;
	a->tex = a->ct.tex;
	logf_("content: %s, %u sectors, %u lines, %d light(s)%s", a->ct.what, a->map->num_sectors,
	      a->map->num_lines, a->ct.nlights,
	      a->map->missing_textures ? ", some textures missing (drawn as a checker)" : "");
	a->map_hash = sim_stages_hash((const struct map *const *)a->ct.maps, a->ct.nmaps);
	a->set.coins_per_credit = (uint8_t)c->game.coins_per_credit;
	a->set.freeplay = (uint8_t)c->game.freeplay;
	a->set.start_in_play = (uint8_t)c->game.start_in_play;
	a->set.difficulty = (uint8_t)c->game.difficulty;
	a->set.lives = (uint8_t)c->game.lives;
	/* Scripts and replays start from the defaults, so they replay the
	 * same anywhere; only a live cabinet keeps its tables. */
	a->persist = !headless(a) && c->paths.state_dir[0];

	if (a->rep) {
		const struct rec_header *rh = rec_reader_header(a->rep);
		struct rec_run run = {
			.map_hash = a->map_hash,
			.set = rh->set,
			.render_w = (uint16_t)(a->o->no_render ? 0 : rw),
			.render_h = (uint16_t)(a->o->no_render ? 0 : rh_h),
			.level = (uint8_t)(a->o->content.nwads || a->o->content.grid ? 0 : spec.level),
			.map_name = a->o->content.map,
		};
		/* --verify wants the very run the recording was made with;
		 * a plain replay needs the same map and engine only. */
		rc = a->o->verify ? rec_check_run(rh, &run, err, sizeof(err))
				  : rec_check(rh, a->map_hash, err, sizeof(err));
		if (rc < 0) {
			logf_("%s: refused: %s", a->o->replay, err);
			return rc;
		}
		if (a->o->verify)
			rec_verify_init(&a->verify, rh, &run);
		/* The game's rules come from the recording, not from this
		 * cabinet's settings. */
		a->set = rec_reader_header(a->rep)->set;
	}
	if (a->o->script) {
		rc = scr_load(a->o->script, &a->scr, err, sizeof(err));
		if (rc < 0) {
			logf_("%s", err[0] ? err : strerror(-rc));
			return rc;
		}
	}
	start_sim(a);
	if (a->rep && rec_reader_header(a->rep)->snapshot_len) {
		/* a recording of one game (flight recorder): it starts from
		 * the state the cabinet was in */
		const struct rec_header *rh = rec_reader_header(a->rep);
		rc = sim_restore(&a->sim, rh->snapshot, rh->snapshot_len);
		if (rc < 0) {
			logf_("%s: refused: its start state does not fit this build's game",
			      a->o->replay);
			return rc;
		}
	}
	flight_setup(a);

	rc = demo_init(&a->demo, &a->ct, err, sizeof(err));
	if (rc < 0) {
		logf_("%s", err);
		return rc;
	}
	rc = view_init(&a->view, &a->ct, NULL, c->display.rotate);
	if (rc == 0) {
		/* render threads: game.render_threads, 0 = one per CPU; frames
		 * are the same bytes whatever the count */
		int n = c->game.render_threads ? c->game.render_threads : pool_cpus();
		if (n > 1) {
			int prc = pool_new(n, &a->pool);
			if (prc < 0) {
				logf_("render threads: %s; drawing on one", strerror(-prc));
				a->pool = NULL;
			} else {
				pool_r_par(a->pool, &a->par);
			}
		}
		rc = resize(a, rw, rh_h);
	}
	if (rc < 0)
		return rc;
	rc = open_display(a);
	if (rc < 0)
		return rc;

	bind_defaults(&a->binds);
	/* Until the wizard has saved STATE_DIR/bindings.ini the cabinet was
	 * never configured on screen (a first boot): the wizard then starts
	 * by itself for a pad nothing names (identify). The shipped
	 * CONFIG_DIR/bindings.ini only repeats the keyboard defaults. */
	int saved = 0;
	if (a->o->config_dir) {
		char path[CFG_PATH_MAX + 32];
		snprintf(path, sizeof(path), "%s/bindings.ini", a->o->config_dir);
		bind_load(&a->binds, path, report_cfg_error, NULL);
	}
	if (c->paths.state_dir[0]) {
		/* what the wizard saved: the operator's choice on screen wins
		 * over the configuration directory's file */
		char path[CFG_PATH_MAX + 32];
		snprintf(path, sizeof(path), "%s/bindings.ini", c->paths.state_dir);
		saved = bind_load(&a->binds, path, report_cfg_error, NULL) != -ENOENT;
	}
	if (c->input.bindings[0]) {
		rc = bind_load(&a->binds, c->input.bindings, report_cfg_error, NULL);
		if (rc == -ENOENT)
			logf_("%s: %s", c->input.bindings, strerror(-rc));
	}
	if (a->o->bindings) {
		rc = bind_load(&a->binds, a->o->bindings, report_cfg_error, NULL);
		if (rc < 0)
			logf_("%s: %s", a->o->bindings, strerror(-rc));
	}
	a->wiz_auto = a->persist && !saved;
	prof_init(&a->profs);
	if (a->o->config_dir) {
		/* the operator's profiles first: they win ties */
		char path[CFG_PATH_MAX + 32];
		snprintf(path, sizeof(path), "%s/profiles", a->o->config_dir);
		prof_load_dir(&a->profs, path, report_cfg_error, NULL);
	}
	prof_load_dir(&a->profs, ARCADED_DATADIR "/profiles", report_cfg_error, NULL);
	cmd_reset(&a->cs);
	open_inputs(a);

	if (a->o->record) {
		/* Format 2: the run it was made with and every tick's state
		 * and frame hashes, so `--verify` can prove a replay. */
		struct rec_header h = {
			.version = REC_VERSION_2,
			.tick_rate = SIM_TICRATE,
			.map_hash = a->map_hash,
			.engine_version = REC_ENGINE_VERSION,
			.set = a->set,
			.count = REC_COUNT_UNKNOWN,
			.render_w = (uint16_t)a->frame.w,
			.render_h = (uint16_t)a->frame.h,
			.render_version = REC_RENDER_VERSION,
			.hash_flags = REC_HAS_STATE | REC_HAS_FRAME,
			.level = (uint8_t)(a->o->content.nwads || a->o->content.grid ? 0
										 : a->o->content.level),
			.start_time = (int64_t)time(NULL),
		};
		if (a->o->content.map)
			snprintf(h.map_name, sizeof(h.map_name), "%s", a->o->content.map);
		rc = rec_writer_open(a->o->record, &h, &a->rec);
		if (rc < 0) {
			logf_("%s: %s", a->o->record, strerror(-rc));
			return rc;
		}
	}
	lat_reset(&a->frame_time);
	lat_reset(&a->latency);
	for (int k = 0; k < APP_SRCS; k++)
		lat_reset(&a->src_latency[k]);
	return 0;
}

/* Open file descriptors of this process (the soak test compares them). */
static int count_fds(void)
{
	DIR *d = opendir("/proc/self/fd");
	int n = 0;

	if (!d)
		return -1;
	while (readdir(d))
		n++;
	closedir(d);
	return n - 3;  /* ".", ".." and the directory's own fd */
}

static void print_summary(struct app *a)
{
	char line[256];
	struct rusage ru;
	uint64_t el = in_now_ns() - a->start_ns;

	getrusage(RUSAGE_SELF, &ru);
	fprintf(stderr, "arcaded: summary: %" PRIu64 " ticks, %" PRIu64 " frames in %" PRIu64
		".%03" PRIu64 " s (%.1f frames/s), %" PRIu64 " ticks dropped, peak RSS %ld KiB, "
		"%d open fds\n",
		a->ticks_run, a->frames, el / 1000000000u, el / 1000000u % 1000u,
		el ? (double)a->frames * 1e9 / (double)el : 0.0, a->dropped, ru.ru_maxrss,
		count_fds());
	lat_format(&a->frame_time, "frame time (render+present)", line, sizeof(line));
	fprintf(stderr, "arcaded: summary: %s\n", line);
	lat_format(&a->latency, "input-to-present latency", line, sizeof(line));
	fprintf(stderr, "arcaded: summary: %s\n", line);
	for (int k = 0; k < APP_SRCS; k++) {
		char name[64];
		if (!a->src_latency[k].count)
			continue;   /* only the kinds that gave input */
		snprintf(name, sizeof(name), "input-to-present latency (%s)", app_src_name[k]);
		lat_format(&a->src_latency[k], name, line, sizeof(line));
		fprintf(stderr, "arcaded: summary: %s\n", line);
	}
}

static void teardown(struct app *a)
{
	hp_close(a->hp);
	for (int i = 0; i < a->nin; i++)
		if (a->in[i].dev)
			a->in[i].be->close(a->in[i].dev);
	if (a->dpb)
		a->dpb->close(a->dp);
	if (a->rec) {
		int rc = rec_writer_close(a->rec);
		if (rc < 0)
			logf_("%s: %s", a->o->record, strerror(-rc));
	}
	rec_reader_close(a->rep);
	scr_free(a->scr);
	if (a->game)
		flight_finish(a);   /* a game cut by a stop is kept too */
	fr_close(a->fr);
	free(a->snap);
	if (a->persist && a->ticks_run) {
		/* play and power-on time count up without a generation bump */
		uint8_t buf[G_BOOKS_BYTES];
		g_books_encode(&a->sim.books, buf);
		save_state(a, "books", buf, G_BOOKS_BYTES);
	}
	r_free(a->r);
	if (a->gl)
		a->glr.destroy(a->gl);
	glr_unload(&a->glr);
	pool_free(a->pool);
	free(a->frame.px);
	view_free(&a->view);
	demo_free(&a->demo);
	ct_free(&a->ct);
}

/* ---- the loop ------------------------------------------------------- */

static void sleep_until(uint64_t deadline_ns)
{
	struct timespec ts = {
		.tv_sec = (time_t)(deadline_ns / 1000000000u),
		.tv_nsec = (long)(deadline_ns % 1000000000u),
	};
	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR)
		if (app_stop_sig)
			break;
}

/* Gets the command of the next tick. Returns 0 at the end of a replay. */
/* Gets the next tick: its command and, from a recording, the hashes it
 * stored. Returns 0 at the end of a replay. */
static int next_tick(struct app *a, uint32_t t, struct rec_tick *rt)
{
	memset(rt, 0, sizeof(*rt));
	if (a->rep) {
		int rc = rec_reader_next_tick(a->rep, rt);
		if (rc < 0)
			logf_("%s: tick %u: %s", a->o->replay, t,
			      rc == -EIO ? "the recording ends before its header's count" :
			      strerror(-rc));
		return rc > 0;
	}
	if (a->scr)
		script_inputs(a, t);
	else
		read_inputs(a);
	cmd_build(&a->cs, &rt->cmd);
	return 1;
}

static int render_and_present(struct app *a)
{
	uint64_t t0 = in_now_ns(), t1;
	int rc;

	if (a->wiz_on)
		wiz_draw(&a->wiz, &a->tex->pal, &a->frame);
	else
		view_draw(&a->view, &a->sim, demo_under(&a->demo, &a->sim), &a->frame);
	rc = a->dpb->present(a->dp, a->frame.px, a->frame.w, a->frame.h, a->frame.pitch);
	t1 = in_now_ns();
	a->frames++;
	lat_add_ns(&a->frame_time, t1 - t0);
	if (a->pending_ns) {
		if (t1 > a->pending_ns)
			lat_add_ns(&a->latency, t1 - a->pending_ns);
		a->pending_ns = 0;
	}
	for (int k = 0; k < APP_SRCS; k++) {
		if (!a->src_pending_ns[k])
			continue;
		if (t1 > a->src_pending_ns[k])
			lat_add_ns(&a->src_latency[k], t1 - a->src_pending_ns[k]);
		a->src_pending_ns[k] = 0;
	}
	return rc;
}

static int loop(struct app *a)
{
	uint64_t wd_interval = headless(a) ? 0 : svc_watchdog_interval_ns(), wd_next = 0;
	uint64_t base = in_now_ns();
	uint32_t hang_at = fault_setup();
	int present_errors = 0;
	uint32_t t = 0;

	a->start_ns = base;
	for (;; t++) {
		struct rec_tick rt;

		if (app_stop_sig) {
			logf_("signal %d: stopping", (int)app_stop_sig);
			break;
		}
		if (app_summary_req) {
			app_summary_req = 0;
			print_summary(a);
		}
		if (a->o->ticks && t >= a->o->ticks)
			break;
		if (t == hang_at || app_fault_req)
			fault_hang();
		if (a->scr && t > a->scr->end_tick)
			break;
		if (!a->o->fast && !headless(a)) {
			uint64_t deadline = base + APP_TICK_NS(t), now = in_now_ns();
			if (now > deadline + APP_RESYNC_NS) {
				/* Far behind (suspended, debugger): do not
				 * fast-forward the game, start the clock again. */
				a->dropped += (now - deadline) / APP_TICK_NS(1);
				base = now - APP_TICK_NS(t);
			} else if (now < deadline) {
				sleep_until(deadline);
			}
		}
		if (!next_tick(a, t, &rt))
			break;
		wizard_tick(a);
		flight_before(a, &rt.cmd);
		sim_tick(&a->sim, &rt.cmd);
		flight_after(a, &rt.cmd);
		/* CONFIGURE INPUTS: the menu shows its request for one tick */
		if (a->sim.mode == SIM_SERVICE && a->sim.menu.page == MENU_WIZARD)
			wizard_start(a, "service menu");
		demo_tick(&a->demo, &a->sim);
		update_outputs(a);
		a->ticks_run++;
		persist_tick(a);

		if (!a->o->no_render) {
			int rc = render_and_present(a);
			if (rc < 0 && present_errors++ == 0)
				logf_("display %s: present: %s", a->dpb->name, strerror(-rc));
		}
		if (a->rep || a->rec) {
			uint64_t sh = sim_hash(&a->sim);
			uint64_t fh = a->o->no_render ? 0 : hash_frame(a->frame.px, a->frame.w,
								     a->frame.h, a->frame.pitch);
			if (a->rep && !a->o->quiet)
				fprintf(a->o->out, "%u %016" PRIx64 " %016" PRIx64 "\n", t, sh, fh);
			if (a->o->verify)
				rec_verify_tick(&a->verify, t, &rt, sh, fh);
			if (a->rec) {
				struct rec_tick nt = { rt.cmd, sh, fh };
				if (rec_writer_put_tick(a->rec, &nt) < 0) {
					logf_("%s: write failed; recording stopped", a->o->record);
					rec_writer_close(a->rec);
					a->rec = NULL;
				}
			}
		}
		if (a->scr)
			script_checks(a, t);
		if (!a->ready && !headless(a)) {
			/* READY=1 only once the first frame is on the screen. */
			svc_ready();
			a->ready = 1;
		}
		if (wd_interval) {
			uint64_t now = in_now_ns();
			if (now >= wd_next) {
				svc_watchdog_ping();
				wd_next = now + wd_interval;
			}
		}
	}
	if (!headless(a))
		svc_stopping();
	return 0;
}

int app_run(const struct cfg *c, const struct app_opts *o)
{
	struct app *a = calloc(1, sizeof(*a));
	int rc, code = APP_OK;

	if (!a) {
		logf_("out of memory");
		return APP_SETUP_FAILED;
	}
	a->cfg = c;
	a->o = o;
	install_signals();
	rc = setup(a);
	if (rc < 0) {
		/* stopped by a signal while loading: an ordinary end */
		code = rc == -ECANCELED && app_stop_sig ? APP_OK : APP_SETUP_FAILED;
		goto out;
	}
	loop(a);
	if (o->screenshot) {
		rc = shot_png(o->screenshot, a->frame.px, a->frame.w, a->frame.h, a->frame.pitch,
			      a->tex->pal.rgb);
		if (rc < 0) {
			logf_("%s: %s", o->screenshot, strerror(-rc));
			code = APP_SETUP_FAILED;
		}
	}
	if (o->verify && a->rep) {
		char sum[512];
		int bad = rec_verify_summary(&a->verify, sum, sizeof(sum));
		logf_("%s: %s", o->replay, sum);
		if (bad)
			code = APP_EXPECT_FAILED;
	}
	if (a->scr) {
		if (a->failures)
			logf_("%s: %d check(s) failed", o->script, a->failures);
		code = a->failures ? APP_EXPECT_FAILED : APP_OK;
	}
	/* The summary while everything is still open: its fd count is the
	 * running daemon's (the soak test compares runs by it). */
	if (a->ticks_run && ((!o->replay && !o->script) || getenv("ARCADED_SUMMARY")))
		print_summary(a);
out:
	teardown(a);
	free(a);
	return code;
}
