/*
 * cfg: the daemon's settings, layered: built-in defaults < /etc/arcaded/
 * *.ini (in name order) < the state directory's settings.ini < command line
 * (--set section.key=value). INI read by config/cini.c (see there why not
 * inih).
 *
 * A bad line, key or value is reported through the error callback with
 * file:line and a reason; that entry keeps its previous value and loading
 * goes on, so a cabinet always boots.
 */
#ifndef ARCADED_CONFIG_CFG_H
#define ARCADED_CONFIG_CFG_H

#include <stddef.h>

#define CFG_PATH_MAX 256

struct sim_settings;

struct cfg {
	struct {
		char backend[16];            /* auto kms fbdev file term null */
		char device[CFG_PATH_MAX];   /* /dev/fb0 */
		char card[CFG_PATH_MAX];     /* kms: "" the first connected card */
		char mode[32];               /* kms: "" preferred, WxH or WxH@Hz */
		int buffers;                 /* kms: 2 or 3 (3) */
		char tty[CFG_PATH_MAX];      /* /dev/tty0; "" leaves the console alone */
		char file[CFG_PATH_MAX];     /* file framebuffer path */
		int file_width, file_height; /* 640x480 */
		int file_stride;             /* 0 = packed */
		char file_format[16];        /* xrgb8888 */
		int rotate;                  /* 0 90 180 270 */
		int fill;                    /* scale = integer (0) | fill (1) */
	} display;
	struct {
		int render_width, render_height; /* 320x240 */
		int render_threads;          /* 0 = every online CPU (0) */
		int coins_per_credit;        /* 1 */
		int freeplay;                /* 0 */
		int start_in_play;           /* 0 */
		int level;                   /* built-in level, 1-based */
		int difficulty;              /* 0 easy .. 3 brutal (1) */
		int lives;                   /* 1..9 (3) */
		int volume;                  /* master volume 0..100 percent (80) */
		int attract_sound;           /* 0 off, 1 on, N: once every N attract cycles (1) */
		int stage_time;              /* the stage clock, minutes 1..30, 0 off (5) */
		int idle_out;                /* a player gone 30 s: life (0) | end (1) | off (2) */
		int autoaim;                 /* vertical auto-aim 0/1 (1) */
		char wad[512];               /* WAD files, blank-separated, IWAD first ("" none) */
		char maps[256];              /* maps or episodes from them ("" the first map) */
		char content_dirs[512];      /* where the service menu's content picker looks
					      * for WADs, blank-separated
					      * ("/usr/share/games/doom /var/lib/arcaded/content") */
		char meshes[CFG_PATH_MAX];   /* directory of NNNN.obj meshes ("" none; app/mdir.h) */
	} game;
	struct {
		char output[CFG_PATH_MAX];   /* auto | alsa | alsa:DEVICE | wav:FILE | null */
		char device[CFG_PATH_MAX];   /* ALSA device for auto and alsa (default) */
		int rate;                    /* output rate, Hz (48000) */
	} audio;
	struct {
		char evdev[CFG_PATH_MAX];    /* auto | none | /dev/input/eventN */
		char bindings[CFG_PATH_MAX]; /* extra bindings file, "" none */
		char hid[CFG_PATH_MAX];      /* auto | none | HID device specs, blank-separated */
		char gpio[CFG_PATH_MAX];     /* none | a GPIO spec (docs/input.md) */
		int log;                     /* log every control press and release (0) */
	} input;
	struct {
		char state_dir[CFG_PATH_MAX]; /* $STATE_DIRECTORY or /var/lib/arcaded */
	} paths;
	struct {
		int keep;                    /* games kept by the flight recorder, 0 off (20) */
		int max_mb;                  /* MiB they may take, 0 no cap (64) */
	} recorder;
};

/* Reports one problem: file may be "--set" for the command line; line 0
 * when there is no line (a file that cannot be read, a --set). msg is valid
 * during the call only. */
typedef void (*cfg_err_fn)(void *user, const char *file, int line, const char *msg);

/* The game's rules from c's [game] section (the sim's settings, which
 * recordings store); set is overwritten whole. */
void cfg_settings(const struct cfg *c, struct sim_settings *set);

/* game.idle_out's name for enum g_idle value idle ("life", "end", "off");
 * out of range: "off", as the sim counts it. */
const char *cfg_idle_name(int idle);

/* Built-in defaults (listed in docs/config.md). paths.state_dir is the first
 * directory of $STATE_DIRECTORY when set, else /var/lib/arcaded. */
void cfg_defaults(struct cfg *c);

/* Applies INI text (len bytes, any bytes, need not be NUL-terminated) named
 * name in messages. Returns the number of problems reported through fn (fn
 * may be NULL); every rejected entry keeps its previous value. */
int cfg_load_text(struct cfg *c, const char *text, size_t len, const char *name,
		  cfg_err_fn fn, void *user);

/* Applies one INI file. Returns the number of problems reported (>= 0), or
 * -errno if the file cannot be read (-ENOENT is not reported through fn;
 * other errors are, with line 0; files above 1 MiB give -EFBIG). */
int cfg_load_file(struct cfg *c, const char *path, cfg_err_fn fn, void *user);

/* The bindings file in the configuration directory (config/bind.h); it
 * shares the directory with the settings files and cfg_load_dir skips it. */
#define CFG_BINDINGS_FILE "bindings.ini"

/* Applies every *.ini in dir (not starting with '.', not CFG_BINDINGS_FILE)
 * in byte order of their names; a missing dir is not an error. Returns the
 * total number of problems reported, a file that cannot be read counting
 * as one. */
int cfg_load_dir(struct cfg *c, const char *dir, cfg_err_fn fn, void *user);

/* Applies "section.key=value" (blanks around the parts ignored); 0, or
 * -EINVAL reported through fn with file "--set", line 0. */
int cfg_set(struct cfg *c, const char *assignment, cfg_err_fn fn, void *user);

/* Writes every key with its current value as INI text to buf (for
 * --print-config and the docs); returns the length needed, excluding the
 * NUL, like snprintf (output truncated when len is too small). */
size_t cfg_format(const struct cfg *c, char *buf, size_t len);

#endif
