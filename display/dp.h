/*
 * dp: displays. Every backend is one file (dp_fbdev.c, dp_file.c,
 * dp_term.c, dp_null.c) implementing struct dp_backend; dp.c holds the
 * ordered list and the automatic choice. Only backend files include Linux
 * headers.
 *
 * A display takes 8-bit palette-indexed frames of the game's render size,
 * converts them to the panel's pixel format through one 256-entry table
 * (px.h), scales (integer with letterbox, or fill) and rotates (0/90/180/
 * 270) in one pass, and shows them (page flip by panning where possible).
 */
#ifndef ARCADED_DISPLAY_DP_H
#define ARCADED_DISPLAY_DP_H

#include <stddef.h>
#include <stdint.h>

struct dp;

enum dp_scale {
	DP_SCALE_INTEGER,  /* largest integer factor, centred, black letterbox */
	DP_SCALE_FILL,     /* stretch to the whole panel (nearest neighbour) */
};

struct dp_config {
	const char *backend;     /* "auto" or NULL, "fbdev", "file", "term", "null" */
	const char *device;      /* fbdev: device path, default /dev/fb0 */
	const char *tty;         /* fbdev: console put in graphics mode, default /dev/tty0; "" none */
	const char *file;        /* file: path of the framebuffer file */
	int file_w, file_h;      /* file: geometry in pixels */
	int file_stride;         /* file: bytes per line; 0 = packed */
	const char *file_format; /* file: "rgb565", "bgr565", "xrgb8888", "xbgr8888", "rgb888" */
	int rotate;              /* 0, 90, 180, 270 degrees clockwise */
	enum dp_scale scale;
	int render_w, render_h;  /* size of the frames that will be presented */
};

struct dp_backend {
	const char *name;
	/* Opens the display; 0 or -errno, with a reason in why. */
	int (*open)(const struct dp_config *cfg, struct dp **out, char *why, size_t whylen);
	/* Sets the palette used by the next presents (rebuilds the table). */
	void (*set_palette)(struct dp *d, const uint8_t rgb[256][3]);
	/* Converts, scales, rotates and shows one frame; 0 or -errno. */
	int (*present)(struct dp *d, const uint8_t *px, int w, int h, int pitch);
	/* NULL-safe; restores whatever open changed (console mode, terminal). */
	void (*close)(struct dp *d);
	/* One line describing the output ("fbdev /dev/fb0 1280x800 xrgb8888 ..."). */
	const char *(*describe)(struct dp *d);
	/* Optional (NULL: none): the name of the input backend (input/in.h)
	 * that reads the keys typed at this display, which the app opens with
	 * it: dp_term's terminal is also the keyboard ("tty"). */
	const char *input;
	/* Optional (NULL: none): where this backend's device nodes appear, a
	 * directory and a name prefix ("/dev/fb"; a DRM backend's would be
	 * "/dev/dri/card"). A node created or changed there (a driver that
	 * loaded late, udev granting access) is when a display that was
	 * missing is worth trying again (the app watches these, input/hp.h). */
	const char *node;
	unsigned flags;          /* DP_* below */
};

/* dp_backend.flags. */
enum {
	/* Frames go nowhere (dp_null): a stand-in. Chosen by "auto" only when
	 * every real display failed, in which case the app keeps looking for
	 * one; named in the configuration, it is what was asked for. */
	DP_SHOWS_NOTHING = 1,
};

extern const struct dp_backend dp_fbdev, dp_file, dp_term, dp_null;

/* The node patterns (dp_backend.node) of the backends "auto" tries, in
 * its order, into out[0..max); returns how many. */
int dp_nodes(const char **out, int max);

/* Opens the display that shows nothing (DP_SHOWS_NOTHING), to stand in
 * for a missing one; *be is it. 0 or -ENOMEM. */
int dp_open_stand_in(const struct dp_config *cfg, const struct dp_backend **be, struct dp **out);

/* Opens the backend named by cfg->backend, or with "auto"/NULL the first of
 * fbdev (if the device opens), term (if stdout is a terminal), file (if
 * cfg->file is set), null. On success *be is the backend used. */
int dp_open(const struct dp_config *cfg, const struct dp_backend **be, struct dp **out,
	    char *why, size_t whylen);

/* Async-signal-safe: puts any console this process switched to graphics
 * mode back in text mode and restores the terminal. For fatal-signal
 * handlers; normal exits use close. */
void dp_emergency_restore(void);

#endif
