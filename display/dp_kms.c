/*
 * dp_kms: DRM/KMS (libdrm), with page flips at vertical blank.
 *
 * Card: the configured one (display.card), or the first /dev/dri/cardN (by
 * number) with a connected connector that has modes. Connector: the first
 * connected one with modes. Mode: the configured one ("WxH" or "WxH@Hz":
 * among the modes of that size the preferred one, else the highest rate)
 * or the connector's preferred mode (else its first). CRTC: the one the
 * connector's encoder drives now, else the first any of its encoders can
 * drive. Opening the card makes this process DRM master when no one else
 * is; the first mode set proves it (it fails with EACCES otherwise).
 *
 * Buffers: two or three dumb buffers (display.buffers), xrgb8888, mapped
 * and drawn by px_panel_draw like every other panel. Frames:
 * - shown: the buffer scanned out; pending: the one a page flip was issued
 *   for (DRM_MODE_PAGE_FLIP_EVENT), until its event says it is shown;
 *   queued: a frame drawn while a flip was pending. A flip is never issued
 *   while one is pending: the queued frame's flip is issued when the
 *   pending one's event arrives (the loop polls wait_fd between ticks and
 *   calls event), and a newer frame replaces a queued one (counted: that
 *   frame was never shown).
 * - with two buffers there is no room for a queued frame: present waits
 *   for the pending flip's event first (counted).
 * The kernel refuses a flip while one is pending with EBUSY; every such
 * refusal is counted (status): the proof that the bookkeeping above holds.
 * A flip whose event has not come after KMS_FLIP_OVERDUE_NS is overdue
 * (counted): a blocking mode set then shows the newest frame, which the
 * kernel holds back until the flip in flight is done, so a driver that
 * loses events cannot freeze the screen, and no flip is issued while one
 * is pending even then (the late event, if it comes, is ignored).
 * A driver without page flips gets drmModeSetCrtc per frame (which may
 * tear; describe says so once it happened).
 *
 * Console: display/con.h, as fbdev, and VT switching by signals: on a
 * switch away the master is dropped (the other terminal's fbcon or session
 * can set its mode), the switch acknowledged and frames are not shown;
 * on the switch back the master is taken again and the mode set anew with
 * the newest frame. The requests are seen at the next present or event.
 *
 * Close restores the CRTC as it was at open (fbcon's framebuffer), then the
 * console.
 */
#include "display/con.h"
#include "display/dp.h"
#include "display/px.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>
#include <drm_fourcc.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#define KMS_MAX_BUFS 3
#define KMS_MAX_CARDS 16
/* A flip whose event has not come after this is overdue (an emulated GPU
 * under load took up to 1 s). */
#define KMS_FLIP_OVERDUE_NS 2000000000ull
/* Completed flips kept for event (more than arrive between two calls). */
#define KMS_RING 16

struct kms_buf {
	struct dp *d;                   /* a flip's event carries its buffer */
	int idx;
	uint32_t handle, fb;
	uint32_t pitch;
	uint64_t size;
	uint8_t *map;
};

struct dp {
	int fd;
	char card[64];
	char conn_name[32];
	uint32_t conn, crtc;
	drmModeModeInfo mode;
	drmModeCrtc *saved;             /* the CRTC at open, restored at close */
	int mono;                       /* event times are CLOCK_MONOTONIC */
	struct kms_buf buf[KMS_MAX_BUFS];
	int nbuf;
	int shown, pending, queued;     /* buffer indices, -1 none */
	int hold;                       /* may still be on screen (overdue flip), -1 */
	uint64_t pending_ns, queued_ns; /* when the present of that frame returned */
	int modeset;                    /* the next frame is shown by drmModeSetCrtc */
	int con;                        /* holds the console (con.h) */
	int away;                       /* VT switched away: master dropped */
	int noflip;                     /* the driver refused page flips: SetCrtc */
	struct dp_flip ring[KMS_RING];
	int nring;
	/* counters, for status */
	uint64_t flips, completed, busy, replaced, waits, overdue, stale, setcrtc, hidden;
	uint64_t vt_away, vt_back, vt_fail;
	struct px_panel panel;
	char con_note[160];
	char desc[512];
	char stat[384];
};

static void kms_close(struct dp *d);

static uint64_t kms_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

/* ---- choosing card, connector, mode and CRTC ---------------------------- */

/* "WxH" or "WxH@Hz" into w, h, hz (0: any); 0 or -EINVAL. */
static int kms_parse_mode(const char *s, int *w, int *h, int *hz)
{
	int n = 0;

	*hz = 0;
	if (sscanf(s, "%5dx%5d%n", w, h, &n) != 2 || *w < 1 || *h < 1)
		return -EINVAL;
	if (s[n] == '@') {
		int m = 0;

		if (sscanf(s + n + 1, "%4d%n", hz, &m) != 1 || *hz < 1)
			return -EINVAL;
		n += 1 + m;
	}
	return s[n] ? -EINVAL : 0;
}

/* The mode to use of connector c: 0 and *out, or -ENOENT with why. */
static int kms_pick_mode(const drmModeConnector *c, const char *want, drmModeModeInfo *out,
			 const char *where, char *why, size_t whylen)
{
	int w, h, hz, best = -1;

	if (!want || !want[0]) {
		for (int i = 0; i < c->count_modes; i++)
			if (c->modes[i].type & DRM_MODE_TYPE_PREFERRED) {
				*out = c->modes[i];
				return 0;
			}
		*out = c->modes[0];
		return 0;
	}
	if (kms_parse_mode(want, &w, &h, &hz) < 0) {
		snprintf(why, whylen, "display.mode \"%s\": not WxH or WxH@Hz", want);
		return -EINVAL;
	}
	for (int i = 0; i < c->count_modes; i++) {
		const drmModeModeInfo *m = &c->modes[i];

		if (m->hdisplay != w || m->vdisplay != h || (hz && (int)m->vrefresh != hz))
			continue;
		if (best < 0 || (m->type & DRM_MODE_TYPE_PREFERRED) ||
		    (!(c->modes[best].type & DRM_MODE_TYPE_PREFERRED) &&
		     m->vrefresh > c->modes[best].vrefresh))
			best = i;
	}
	if (best < 0) {
		size_t n = (size_t)snprintf(why, whylen, "%s: no mode %s (has", where, want);

		for (int i = 0; i < c->count_modes && n < whylen; i++)
			n += (size_t)snprintf(why + n, whylen - n, " %ux%u@%u",
					      c->modes[i].hdisplay, c->modes[i].vdisplay,
					      c->modes[i].vrefresh);
		if (n < whylen)
			snprintf(why + n, whylen - n, ")");
		return -ENOENT;
	}
	*out = c->modes[best];
	return 0;
}

/* A CRTC for connector c: the current one, else the first an encoder of c
 * can drive. 0 or -ENOENT. */
static int kms_pick_crtc(int fd, const drmModeRes *res, const drmModeConnector *c, uint32_t *crtc)
{
	drmModeEncoder *e;

	if (c->encoder_id && (e = drmModeGetEncoder(fd, c->encoder_id)) != NULL) {
		*crtc = e->crtc_id;
		drmModeFreeEncoder(e);
		if (*crtc)
			return 0;
	}
	for (int i = 0; i < c->count_encoders; i++) {
		e = drmModeGetEncoder(fd, c->encoders[i]);
		if (!e)
			continue;
		for (int k = 0; k < res->count_crtcs && k < 32; k++) {
			if (e->possible_crtcs & (1u << k)) {
				*crtc = res->crtcs[k];
				drmModeFreeEncoder(e);
				return 0;
			}
		}
		drmModeFreeEncoder(e);
	}
	return -ENOENT;
}

/* Opens card path and finds a connected connector, its mode and a CRTC.
 * 0, or -errno with why ("/dev/dri/card0: no connected connector"). */
static int kms_probe(struct dp *d, const char *path, const char *want, char *why, size_t whylen)
{
	drmModeRes *res = NULL;
	drmModeConnector *c = NULL;
	int rc = -ENOENT;

	snprintf(d->card, sizeof(d->card), "%s", path);
	d->fd = open(path, O_RDWR | O_CLOEXEC);
	if (d->fd < 0) {
		rc = -errno;
		snprintf(why, whylen, "%s: %s", path, strerror(-rc));
		return rc;
	}
	res = drmModeGetResources(d->fd);
	if (!res) {
		rc = errno ? -errno : -ENODEV;
		snprintf(why, whylen, "%s: not a KMS device (%s)", path, strerror(-rc));
		goto out;
	}
	snprintf(why, whylen, "%s: no connected connector with modes", path);
	for (int i = 0; i < res->count_connectors; i++) {
		c = drmModeGetConnector(d->fd, res->connectors[i]);
		if (c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0)
			break;
		drmModeFreeConnector(c);
		c = NULL;
	}
	if (!c)
		goto out;
	snprintf(d->conn_name, sizeof(d->conn_name), "%s-%u",
		 drmModeGetConnectorTypeName(c->connector_type) ?
			 drmModeGetConnectorTypeName(c->connector_type) : "unknown",
		 c->connector_type_id);
	d->conn = c->connector_id;
	{
		char where[128];

		snprintf(where, sizeof(where), "%s %s", path, d->conn_name);
		rc = kms_pick_mode(c, want, &d->mode, where, why, whylen);
		if (rc < 0)
			goto out;
		rc = kms_pick_crtc(d->fd, res, c, &d->crtc);
		if (rc < 0) {
			snprintf(why, whylen, "%s: no CRTC can drive it", where);
			goto out;
		}
	}
	rc = 0;
out:
	drmModeFreeConnector(c);
	drmModeFreeResources(res);
	if (rc < 0) {
		close(d->fd);
		d->fd = -1;
	}
	return rc;
}

/* Without display.card: /dev/dri/card0, card1, ... the first that probes.
 * why lists each card's reason when none does. */
static int kms_find(struct dp *d, const char *want, char *why, size_t whylen)
{
	size_t len = 0;
	int rc = -ENODEV;

	snprintf(why, whylen, "/dev/dri: no card");
	for (int i = 0; i < KMS_MAX_CARDS; i++) {
		char path[32], r[256];

		snprintf(path, sizeof(path), "/dev/dri/card%d", i);
		if (access(path, F_OK) < 0)
			continue;
		rc = kms_probe(d, path, want, r, sizeof(r));
		if (rc == 0)
			return 0;
		if (len + 1 < whylen)
			len += (size_t)snprintf(why + len, whylen - len, "%s%s", len ? "; " : "", r);
	}
	return rc;
}

/* ---- buffers ------------------------------------------------------------- */

static int kms_buf_new(struct dp *d, struct kms_buf *b)
{
	uint64_t off;
	uint32_t handles[4] = { 0 }, pitches[4] = { 0 }, offsets[4] = { 0 };
	int rc;

	rc = drmModeCreateDumbBuffer(d->fd, d->mode.hdisplay, d->mode.vdisplay, 32, 0, &b->handle,
				     &b->pitch, &b->size);
	if (rc < 0)
		return rc;
	handles[0] = b->handle;
	pitches[0] = b->pitch;
	if (drmModeAddFB2(d->fd, d->mode.hdisplay, d->mode.vdisplay, DRM_FORMAT_XRGB8888,
			  handles, pitches, offsets, &b->fb, 0) < 0)
		return -errno;
	rc = drmModeMapDumbBuffer(d->fd, b->handle, &off);
	if (rc < 0)
		return rc;
	b->map = mmap(NULL, b->size, PROT_READ | PROT_WRITE, MAP_SHARED, d->fd, (off_t)off);
	if (b->map == MAP_FAILED) {
		b->map = NULL;
		return -errno;
	}
	memset(b->map, 0, b->size);
	return 0;
}

static void kms_buf_free(struct dp *d, struct kms_buf *b)
{
	if (b->map)
		munmap(b->map, b->size);
	if (b->fb)
		drmModeRmFB(d->fd, b->fb);
	if (b->handle)
		drmModeDestroyDumbBuffer(d->fd, b->handle);
	memset(b, 0, sizeof(*b));
}

/* ---- flips and their events ---------------------------------------------- */

static int kms_setcrtc(struct dp *d, int b)
{
	if (drmModeSetCrtc(d->fd, d->crtc, d->buf[b].fb, 0, 0, &d->conn, 1, &d->mode) < 0)
		return -errno;
	d->shown = b;
	return 0;
}

/* Shows buffer b (drawn at t): a page flip, or a SetCrtc without flips. */
static void kms_flip(struct dp *d, int b, uint64_t t)
{
	if (!d->noflip) {
		if (drmModePageFlip(d->fd, d->crtc, d->buf[b].fb, DRM_MODE_PAGE_FLIP_EVENT,
				    &d->buf[b]) == 0) {
			d->pending = b;
			d->pending_ns = t;
			d->flips++;
			return;
		}
		if (errno == EBUSY) {
			/* a flip is pending after all: this one waits for it */
			d->busy++;
			d->queued = b;
			d->queued_ns = t;
			return;
		}
		if (errno == EACCES || errno == EPERM) {
			d->hidden++;  /* master lost without a VT signal */
			return;
		}
		d->noflip = 1;
	}
	if (kms_setcrtc(d, b) == 0)
		d->setcrtc++;
}

static void kms_on_flip(int fd, unsigned seq, unsigned sec, unsigned usec, void *data)
{
	struct kms_buf *fb = data;
	struct dp *d = fb->d;
	uint64_t t = d->mono ? (uint64_t)sec * 1000000000u + (uint64_t)usec * 1000u : kms_now();
	int q = d->queued;

	(void)fd;
	(void)seq;
	if (d->pending != fb->idx) {
		d->stale++;  /* an overdue flip's: shown by a mode set already */
		return;
	}
	d->shown = d->pending;
	d->pending = -1;
	d->completed++;
	if (d->nring < KMS_RING) {
		d->ring[d->nring].presented_ns = d->pending_ns;
		d->ring[d->nring].shown_ns = t;
		d->nring++;
	}
	if (q >= 0 && !d->away) {
		d->queued = -1;
		kms_flip(d, q, d->queued_ns);
	}
}

/* Reads the flip events there are, waiting up to ms for the first. */
static void kms_read_events(struct dp *d, int ms)
{
	drmEventContext ev = { .version = 2, .page_flip_handler = kms_on_flip };
	struct pollfd p = { .fd = d->fd, .events = POLLIN };

	while (poll(&p, 1, ms) == 1 && (p.revents & POLLIN)) {
		if (drmHandleEvent(d->fd, &ev) != 0)
			break;
		ms = 0;
	}
}

/* The pending flip is overdue: the next frame is shown by a mode set,
 * which the kernel completes only after the flip in flight. */
static void kms_overdue(struct dp *d)
{
	if (d->pending < 0 || kms_now() - d->pending_ns < KMS_FLIP_OVERDUE_NS)
		return;
	d->overdue++;
	d->hold = d->shown;   /* on screen until the overdue flip lands */
	d->shown = d->pending;
	d->pending = -1;
	d->modeset = 1;
}

/* The kernel's VT requests: let go of the screen, or take it again. */
static void kms_vt(struct dp *d)
{
	int r = d->con ? con_vt_requests() : 0;

	if (r & CON_VT_RELEASE) {
		/* the pending flip, if any, completes without us */
		d->queued = -1;
		drmDropMaster(d->fd);
		if (con_vt_release() < 0)
			d->vt_fail++;
		d->away = 1;
		d->vt_away++;
	}
	if ((r & CON_VT_ACQUIRE) && d->away) {
		con_vt_acquire();
		if (drmSetMaster(d->fd) < 0) {
			d->vt_fail++;
			return;  /* frames stay hidden; tried again on the next switch */
		}
		/* the mode set must not race a flip still in flight */
		if (d->pending >= 0)
			kms_read_events(d, 100);
		d->away = 0;
		d->modeset = 1;
		d->vt_back++;
	}
}

/* A buffer to draw the next frame in: the queued frame's (it is replaced),
 * else one neither shown nor pending; -1 when none (two buffers, a flip
 * pending). */
static int kms_back(const struct dp *d)
{
	if (d->queued >= 0)
		return d->queued;
	for (int i = 0; i < d->nbuf; i++)
		if (i != d->shown && i != d->pending && i != d->hold)
			return i;
	/* two buffers after an overdue flip: the one that may still show */
	return d->hold;
}

/* ---- the table ------------------------------------------------------------ */

static void kms_describe_update(struct dp *d)
{
	snprintf(d->desc, sizeof(d->desc),
		 "kms %s %s %ux%u@%u xrgb8888 pitch %u, %d buffers, page flips%s, rotate %d %s; %s",
		 d->card, d->conn_name, d->mode.hdisplay, d->mode.vdisplay, d->mode.vrefresh,
		 d->buf[0].pitch, d->nbuf,
		 d->noflip ? " refused by the driver (mode set per frame, may tear)" : " at vblank",
		 d->panel.layout.rotate, d->panel.layout.fill ? "fill" : "integer", d->con_note);
}

static int kms_open(const struct dp_config *cfg, struct dp **out, char *why, size_t whylen)
{
	struct px_format f;
	struct dp *d;
	uint64_t cap = 0;
	int rc;

	*out = NULL;
	d = calloc(1, sizeof(*d));
	if (!d) {
		snprintf(why, whylen, "%s", strerror(ENOMEM));
		return -ENOMEM;
	}
	d->fd = -1;
	d->shown = d->pending = d->queued = d->hold = -1;
	d->nbuf = cfg->buffers == 2 ? 2 : KMS_MAX_BUFS;
	if (cfg->buffers && cfg->buffers != 2 && cfg->buffers != 3) {
		snprintf(why, whylen, "display.buffers %d: 2 or 3", cfg->buffers);
		rc = -EINVAL;
		goto fail;
	}
	if (cfg->card && cfg->card[0])
		rc = kms_probe(d, cfg->card, cfg->mode, why, whylen);
	else
		rc = kms_find(d, cfg->mode, why, whylen);
	if (rc < 0)
		goto fail;
	if (drmGetCap(d->fd, DRM_CAP_DUMB_BUFFER, &cap) < 0 || !cap) {
		rc = -EOPNOTSUPP;
		snprintf(why, whylen, "%s: no dumb buffers", d->card);
		goto fail;
	}
	d->mono = drmGetCap(d->fd, DRM_CAP_TIMESTAMP_MONOTONIC, &cap) == 0 && cap;
	px_format_by_name("xrgb8888", &f);
	for (int i = 0; i < d->nbuf; i++) {
		d->buf[i].d = d;
		d->buf[i].idx = i;
		rc = kms_buf_new(d, &d->buf[i]);
		if (rc < 0) {
			snprintf(why, whylen, "%s: dumb buffer %ux%u: %s", d->card,
				 d->mode.hdisplay, d->mode.vdisplay, strerror(-rc));
			goto fail;
		}
	}
	rc = px_panel_init(&d->panel, &f, d->mode.hdisplay, d->mode.vdisplay, d->buf[0].pitch,
			   cfg->rotate, cfg->scale == DP_SCALE_FILL, cfg->render_w, cfg->render_h);
	if (rc < 0) {
		snprintf(why, whylen, "%s: %ux%u panel, rotation %d, render size %dx%d refused",
			 d->card, d->mode.hdisplay, d->mode.vdisplay, cfg->rotate, cfg->render_w,
			 cfg->render_h);
		goto fail;
	}
	px_panel_set_par(&d->panel, cfg->par);
	d->saved = drmModeGetCrtc(d->fd, d->crtc);
	/* the first mode set shows a black buffer and proves we are master */
	rc = kms_setcrtc(d, 0);
	if (rc < 0) {
		snprintf(why, whylen, "%s %s: mode set %ux%u: %s%s", d->card, d->conn_name,
			 d->mode.hdisplay, d->mode.vdisplay, strerror(-rc),
			 rc == -EACCES || rc == -EPERM ? " (another process is DRM master)" : "");
		goto fail;
	}
	d->con = con_enter(cfg->tty, 1, d->con_note, sizeof(d->con_note));
	kms_describe_update(d);
	*out = d;
	return 0;
fail:
	kms_close(d);
	return rc;
}

static void kms_set_palette(struct dp *d, const uint8_t rgb[256][3])
{
	px_panel_palette(&d->panel, rgb);
}

static int kms_present(struct dp *d, const uint8_t *px, int w, int h, int pitch)
{
	uint64_t t;
	int b, rc, noflip = d->noflip;

	kms_read_events(d, 0);
	kms_vt(d);
	if (d->away) {
		d->hidden++;
		return 0;
	}
	kms_overdue(d);
	b = kms_back(d);
	if (b < 0) {
		d->waits++;
		kms_read_events(d, (int)(KMS_FLIP_OVERDUE_NS / 1000000u) + 1);
		kms_overdue(d);
		b = kms_back(d);
		if (b < 0)
			return -ETIMEDOUT;  /* not reached: the flip is overdue by now */
	}
	rc = px_panel_draw(&d->panel, d->buf[b].map, px, w, h, pitch);
	if (rc < 0)
		return rc;
	t = kms_now();
	if (d->modeset) {
		if (kms_setcrtc(d, b) == 0) {
			d->modeset = 0;
			d->queued = -1;
			d->hold = -1;
		}
	} else if (d->pending >= 0) {
		if (d->queued == b)
			d->replaced++;
		d->queued = b;
		d->queued_ns = t;
	} else {
		d->queued = -1;
		kms_flip(d, b, t);
	}
	if (d->noflip != noflip)
		kms_describe_update(d);
	return 0;
}

static int kms_wait_fd(struct dp *d)
{
	return d->fd;
}

static int kms_event(struct dp *d, struct dp_flip *done, int max)
{
	int n;

	kms_read_events(d, 0);
	kms_vt(d);
	n = d->nring < max ? d->nring : max;
	memcpy(done, d->ring, (size_t)n * sizeof(*done));
	/* the rest (more than max) is dropped: the caller asks often */
	d->nring = 0;
	return n;
}

static const char *kms_status(struct dp *d)
{
	typedef unsigned long long ull;

	snprintf(d->stat, sizeof(d->stat),
		 "kms %s: %llu flips issued, %llu completed, %llu refused as busy (a flip while "
		 "one was pending), %llu overdue (%llu came later), %llu frames replaced before "
		 "their flip, %llu waits for a flip, %llu mode sets for frames, %llu frames hidden "
		 "(VT away), VT switches %llu away %llu back %llu failed",
		 d->card, (ull)d->flips, (ull)d->completed, (ull)d->busy, (ull)d->overdue,
		 (ull)d->stale, (ull)d->replaced, (ull)d->waits, (ull)d->setcrtc, (ull)d->hidden,
		 (ull)d->vt_away, (ull)d->vt_back, (ull)d->vt_fail);
	return d->stat;
}

static void kms_close(struct dp *d)
{
	if (!d)
		return;
	if (d->fd >= 0) {
		if (d->pending >= 0)
			kms_read_events(d, 200);
		if (d->saved && d->saved->mode_valid && !d->away)
			drmModeSetCrtc(d->fd, d->saved->crtc_id, d->saved->buffer_id, d->saved->x,
				       d->saved->y, &d->conn, 1, &d->saved->mode);
	}
	if (d->con)
		con_leave();
	drmModeFreeCrtc(d->saved);
	for (int i = 0; i < KMS_MAX_BUFS; i++)
		kms_buf_free(d, &d->buf[i]);
	if (d->fd >= 0)
		close(d->fd);
	free(d);
}

static const char *kms_describe(struct dp *d)
{
	return d->desc;
}

const struct dp_backend dp_kms = {
	.name = "kms",
	.open = kms_open,
	.set_palette = kms_set_palette,
	.present = kms_present,
	.close = kms_close,
	.describe = kms_describe,
	.node = "/dev/dri/card",
	.wait_fd = kms_wait_fd,
	.event = kms_event,
	.status = kms_status,
};
