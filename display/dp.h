/*
 * dp: displays. Every backend is one file (dp_kms.c, dp_fbdev.c, dp_file.c,
 * dp_term.c, dp_null.c) implementing struct dp_backend; dp.c holds the
 * ordered list and the automatic choice. Only backend files (and con.c,
 * the console helper of kms and fbdev) include Linux or libdrm headers.
 *
 * A display takes 8-bit palette-indexed frames of the game's render size,
 * converts them to the panel's pixel format through one 256-entry table
 * (px.h), scales (integer with letterbox, or fill) and rotates (0/90/180/
 * 270) in one pass, and shows them (a page flip at vblank with KMS, by
 * panning where possible with fbdev).
 */
#ifndef ARCADED_DISPLAY_DP_H
#define ARCADED_DISPLAY_DP_H

#include <stddef.h>
#include <stdint.h>

struct dp;
struct px_par;

enum dp_scale {
	DP_SCALE_INTEGER,  /* largest integer factor, centred, black letterbox */
	DP_SCALE_FILL,     /* stretch to the whole panel (nearest neighbour) */
};

struct dp_config {
	const char *backend;     /* "auto" or NULL, "kms", "fbdev", "file", "term", "null" */
	const char *card;        /* kms: DRM card path; NULL or "": the first with a
				  * connected connector */
	const char *mode;        /* kms: "WxH" or "WxH@Hz"; NULL or "": preferred */
	int buffers;             /* kms: 2 or 3 (0: 3) */
	const char *device;      /* fbdev: device path, default /dev/fb0 */
	const char *tty;         /* kms, fbdev: console put in graphics mode, default
				  * /dev/tty0; "" none */
	const char *file;        /* file: path of the framebuffer file */
	int file_w, file_h;      /* file: geometry in pixels */
	int file_stride;         /* file: bytes per line; 0 = packed */
	const char *file_format; /* file: "rgb565", "bgr565", "xrgb8888", "xbgr8888", "rgb888" */
	int rotate;              /* 0, 90, 180, 270 degrees clockwise */
	enum dp_scale scale;
	int render_w, render_h;  /* size of the frames that will be presented */
	const struct px_par *par; /* kms, fbdev, file: threads for the present's row
				   * ranges (display/px.h), NULL: the caller's
				   * alone; borrowed, must outlive the display */
};

/* A frame the screen took (dp_backend.event), CLOCK_MONOTONIC. */
struct dp_flip {
	uint64_t presented_ns;   /* the present that drew it returned */
	uint64_t shown_ns;       /* its page flip completed (scan-out began) */
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
	/* Optional (NULL: the display never waits for the screen): the fd the
	 * loop polls while it waits for the next tick; readable means event
	 * has work (a page flip completed). */
	int (*wait_fd)(struct dp *d);
	/* Optional, with wait_fd: takes what the fd has without blocking (a
	 * frame drawn while a flip was pending gets its flip now) and copies
	 * up to max of the flips completed since the last call into done
	 * (older ones beyond max are dropped). Their count, or -errno. */
	int (*event)(struct dp *d, struct dp_flip *done, int max);
	/* Optional: one line of counters since open, for the summary. */
	const char *(*status)(struct dp *d);
};

/* dp_backend.flags. */
enum {
	/* Frames go nowhere (dp_null): a stand-in. Chosen by "auto" only when
	 * every real display failed, in which case the app keeps looking for
	 * one; named in the configuration, it is what was asked for. */
	DP_SHOWS_NOTHING = 1,
};

extern const struct dp_backend dp_kms, dp_fbdev, dp_file, dp_term, dp_null;

/* The node patterns (dp_backend.node) of the backends "auto" tries, in
 * its order, into out[0..max); returns how many. */
int dp_nodes(const char **out, int max);

/* Opens the display that shows nothing (DP_SHOWS_NOTHING), to stand in
 * for a missing one; *be is it. 0 or -ENOMEM. */
int dp_open_stand_in(const struct dp_config *cfg, const struct dp_backend **be, struct dp **out);

/* Opens the backend named by cfg->backend, or with "auto"/NULL the first of
 * kms (if a card opens with a connected connector and the mode is set),
 * fbdev (if the device opens), term (if stdout is a terminal), file (if
 * cfg->file is set), null. On success *be is the backend used. */
int dp_open(const struct dp_config *cfg, const struct dp_backend **be, struct dp **out,
	    char *why, size_t whylen);

/* Async-signal-safe: puts any console this process switched to graphics
 * mode back in text mode and restores the terminal. For fatal-signal
 * handlers; normal exits use close. */
void dp_emergency_restore(void);

#endif
