/*
 * in_hid: the hidapi backend. Spec syntax, sysfs lookups and reading rules
 * are in in_hid.h; parsing and decoding are hidd.c and hidr.c.
 */
#include "input/in_hid.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>
#include <wchar.h>

#include <hidapi.h>

#include "engine/core/num.h"
#include "input/hidd.h"
#include "input/hidsys.h"
#include "input/in.h"
#include "input/io.h"

#define HID_SYSFS "/sys"
#define HID_MAX_READS 256        /* reports per read call: bounds the work of a tick */
#define HID_RING 64              /* reports the reader thread may hold for the loop */
#define HID_WAIT_MS 50           /* reader's read timeout: how soon it sees a stop */

#define HID_MAGIC 0x68696472u       /* "hidr": in_hid_configure checks its device */

struct in_dev {
	uint32_t magic;
	hid_device *h;
	struct hidr_opts opts;
	struct hidd_desc *desc;
	struct hidr *dec;
	struct in_event *q;          /* the events of the last report not yet delivered */
	int qhead, qn, qcap;
	struct in_ident id;
	char node[64];
	char text[400];
	/* Reports with their arrival times, from the reader thread to read():
	 * slot (head + k) % HID_RING for k < n. The slot at head belongs to
	 * read() while n > 0, the one at head + n to the thread while n <
	 * HID_RING; mu guards head, n, stop and gone. */
	pthread_t th;
	bool th_on;
	pthread_mutex_t mu;
	pthread_cond_t cv;           /* signalled when a slot frees or stop is set */
	unsigned head, n;
	bool stop, gone;
	uint64_t t[HID_RING];
	uint32_t len[HID_RING];
	uint8_t *ring;               /* HID_RING * slot bytes */
	size_t slot;
	struct in_dev *next;         /* hid_open_devs */
};

/* hidapi keeps global state (hid_init/hid_exit); count the open devices
 * so the last close releases it. */
static int hid_users;
/* The devices open in this process: an open never takes a node another
 * slot has (two auto slots get two pads; two slots never share one). Used
 * by the thread that opens and closes (the main loop's). */
static struct in_dev *hid_open_devs;

static bool node_in_use(const char *node)
{
	for (const struct in_dev *o = hid_open_devs; o; o = o->next)
		if (strcmp(o->node, node) == 0)
			return true;
	return false;
}

static int axis_usage(const char *v)
{
	static const char *const names[] = { "x", "y", "z", "rx", "ry", "rz", "slider", "dial",
					     "wheel" };

	for (int i = 0; i < 9; i++)
		if (strcasecmp(v, names[i]) == 0)
			return HIDD_GD_X + i;
	return -1;
}

static int hex16(const char *v, size_t len)
{
	int n = 0;

	if (len == 0 || len > 4)
		return -1;
	for (size_t i = 0; i < len; i++) {
		int d = num_hex(v[i]);

		if (d < 0)
			return -1;
		n = n * 16 + d;
	}
	return n;
}

static int copy_term(char *dst, size_t len, const char *v)
{
	if (!*v || strlen(v) >= len)
		return -1;
	strcpy(dst, v);
	return 0;
}

/* One term of a spec (NUL-terminated, blanks trimmed). */
static int spec_term(struct in_hid_spec *s, char *t, char *why, size_t whylen)
{
	char *eq = strchr(t, '=');
	const char *v = eq ? eq + 1 : "";
	const char *colon = strchr(t, ':');
	int64_t n;
	int a;

	if (eq)
		*eq = '\0';
	if (!eq && t[0] == '/') {
		if (copy_term(s->node, sizeof(s->node), t) < 0)
			goto bad;
		return 0;
	}
	if (!eq && colon) {
		s->vid = hex16(t, (size_t)(colon - t));
		s->pid = hex16(colon + 1, strlen(colon + 1));
		if (s->vid < 0 || s->pid < 0)
			goto bad;
		return 0;
	}
	if (!eq)
		goto bad;
	if (strcmp(t, "port") == 0) {
		if (copy_term(s->port, sizeof(s->port), v) < 0)
			goto bad;
	} else if (strcmp(t, "serial") == 0) {
		if (copy_term(s->serial, sizeof(s->serial), v) < 0)
			goto bad;
	} else if (strcmp(t, "node") == 0) {
		if (copy_term(s->node, sizeof(s->node), v) < 0)
			goto bad;
	} else if (strcmp(t, "if") == 0) {
		if (num_parse(v, 0, 255, &n) < 0)
			goto bad;
		s->iface = (int)n;
	} else if (strcmp(t, "split") == 0) {
		if (strcmp(v, "auto") == 0)
			s->opts.split = HIDR_SPLIT_AUTO;
		else if (strcmp(v, "none") == 0)
			s->opts.split = HIDR_SPLIT_NONE;
		else if (strcmp(v, "usage") == 0)
			s->opts.split = HIDR_SPLIT_USAGE;
		else
			goto bad;
	} else if (strcmp(t, "deadzone") == 0 || strcmp(t, "press") == 0 ||
		   strcmp(t, "release") == 0) {
		if (num_parse(v, 0, 1000, &n) < 0)
			goto bad;
		if (t[0] == 'd')
			s->opts.deadzone = (uint16_t)n;
		else if (t[0] == 'p')
			s->opts.press = (uint16_t)n;
		else
			s->opts.release = (uint16_t)n;
	} else if (strcmp(t, "p2_button") == 0) {
		if (num_parse(v, 1, 65535, &n) < 0)
			goto bad;
		s->opts.p2_first_button = (uint16_t)n;
	} else if (strcmp(t, "look") == 0) {
		a = strcasecmp(v, "none") == 0 ? HIDR_LOOK_NONE :
		    strcasecmp(v, "auto") == 0 ? 0 : axis_usage(v);
		if (a < 0)
			goto bad;
		s->opts.look = (uint16_t)a;
	} else if (strcmp(t, "p2_x") == 0 || strcmp(t, "p2_y") == 0) {
		a = axis_usage(v);
		if (a < 0)
			goto bad;
		if (t[3] == 'x')
			s->opts.p2_x = (uint16_t)a;
		else
			s->opts.p2_y = (uint16_t)a;
	} else {
		goto bad;
	}
	return 0;
bad:
	if (eq)
		*eq = '=';
	in_say(why, whylen, "bad term '%s' in HID device spec", t);
	return -EINVAL;
}

/* Applies the terms of s (NULL: none) to out. */
static int apply_terms(const char *s, struct in_hid_spec *out, char *why, size_t whylen)
{
	char buf[256];
	char *p, *save = NULL;

	if (!s)
		return 0;
	if (strncmp(s, "hid", 3) == 0 && (s[3] == '\0' || s[3] == ':'))
		s += s[3] ? 4 : 3;
	if (strlen(s) >= sizeof(buf)) {
		in_say(why, whylen, "HID device spec longer than %zu bytes", sizeof(buf) - 1);
		return -EINVAL;
	}
	strcpy(buf, s);
	for (p = strtok_r(buf, ",", &save); p; p = strtok_r(NULL, ",", &save)) {
		char *e = p + strlen(p);
		int rc;

		while (*p == ' ' || *p == '\t')
			p++;
		while (e > p && (e[-1] == ' ' || e[-1] == '\t'))
			*--e = '\0';
		if (!*p)
			continue;
		rc = spec_term(out, p, why, whylen);
		if (rc < 0)
			return rc;
	}
	if (out->opts.release > out->opts.press) {
		in_say(why, whylen, "release (%u) above press (%u)", out->opts.release,
		    out->opts.press);
		return -EINVAL;
	}
	return 0;
}

int in_hid_parse_spec(const char *s, struct in_hid_spec *out, char *why, size_t whylen)
{
	if (whylen)
		why[0] = '\0';
	memset(out, 0, sizeof(*out));
	out->vid = out->pid = out->iface = -1;
	hidr_default_opts(&out->opts);
	return apply_terms(s, out, why, whylen);
}

int in_hid_spec_names_device(const struct in_hid_spec *s)
{
	return s->vid >= 0 || s->port[0] || s->serial[0] || s->node[0] || s->iface >= 0;
}

static const char *node_base(const char *node)
{
	const char *b = strrchr(node, '/');

	return b ? b + 1 : node;
}

int in_hid_port(const char *sysroot, const char *node, char *port, size_t len)
{
	char link[PATH_MAX];

	if (len)
		port[0] = '\0';
	if (snprintf(link, sizeof(link), "%s/class/hidraw/%s/device", sysroot, node_base(node)) >=
	    (int)sizeof(link))
		return -ENAMETOOLONG;
	return in_usb_port(link, 0, port, len);
}

int in_hid_read_desc(const char *sysroot, const char *node, uint8_t **buf, size_t *len)
{
	char path[PATH_MAX];

	*buf = NULL;
	*len = 0;
	if (snprintf(path, sizeof(path), "%s/class/hidraw/%s/device/report_descriptor", sysroot,
		     node_base(node)) >= (int)sizeof(path))
		return -ENAMETOOLONG;
	return io_read_file(path, HIDD_MAX_DESC, 0, buf, len);
}

static int enumerate(struct in_hid_info **out, size_t *count)
{
	int rc = hidsys_scan(HID_SYSFS, out, count);

	for (size_t i = 0; rc == 0 && i < *count; i++)
		in_hid_port(HID_SYSFS, (*out)[i].node, (*out)[i].port, sizeof((*out)[i].port));
	return rc;
}

static bool matches(const struct in_hid_spec *s, const struct in_hid_info *i)
{
	return (s->vid < 0 || (s->vid == i->vid && s->pid == i->pid)) &&
	       (!s->port[0] || strcmp(s->port, i->port) == 0) &&
	       (!s->serial[0] || strcmp(s->serial, i->serial) == 0) &&
	       (!s->node[0] || strcmp(node_base(s->node), node_base(i->node)) == 0) &&
	       (s->iface < 0 || s->iface == i->iface);
}

/* A joystick or gamepad: the auto-detection rule of in_hid.h. */
static bool game_device(const struct hidd_desc *d)
{
	for (size_t i = 0; i < d->nfield; i++) {
		const struct hidd_field *f = &d->field[i];

		if ((f->kind == HIDD_BUTTON || f->kind == HIDD_AXIS || f->kind == HIDD_HAT) &&
		    (f->app_usage == HIDD_USAGE(HIDD_PAGE_DESKTOP, HIDD_GD_JOYSTICK) ||
		     f->app_usage == HIDD_USAGE(HIDD_PAGE_DESKTOP, HIDD_GD_GAMEPAD)))
			return true;
	}
	return false;
}

/* The reader: blocks in hidapi's read (hidraw has no timestamps, so the
 * time a report arrives is taken as soon as the read returns, not at the
 * next tick) and queues each report for hid_rd. A full queue waits: the
 * kernel keeps what arrives meanwhile, and no release is ever dropped. */
static void *hid_reader(void *arg)
{
	struct in_dev *d = arg;

	for (;;) {
		unsigned tail;
		int r;

		pthread_mutex_lock(&d->mu);
		while (d->n == HID_RING && !d->stop)
			pthread_cond_wait(&d->cv, &d->mu);
		if (d->stop) {
			pthread_mutex_unlock(&d->mu);
			return NULL;
		}
		tail = (d->head + d->n) % HID_RING;
		pthread_mutex_unlock(&d->mu);
		r = hid_read_timeout(d->h, d->ring + (size_t)tail * d->slot, d->slot, HID_WAIT_MS);
		uint64_t t = in_now_ns();
		pthread_mutex_lock(&d->mu);
		if (r < 0) {
			d->gone = true;
			pthread_mutex_unlock(&d->mu);
			return NULL;
		}
		if (r > 0) {
			d->t[tail] = t;
			d->len[tail] = (uint32_t)r;
			d->n++;
		}
		pthread_mutex_unlock(&d->mu);
	}
}

/* Starts the reader with every signal blocked: signals are the main
 * loop's (its sleeps end on SIGTERM). */
static int hid_start_reader(struct in_dev *d)
{
	sigset_t all, old;
	int rc;

	sigfillset(&all);
	pthread_sigmask(SIG_SETMASK, &all, &old);
	rc = pthread_create(&d->th, NULL, hid_reader, d);
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	if (rc != 0)
		return -rc;
	d->th_on = true;
	return 0;
}

static void hid_close_dev(struct in_dev *d)
{
	if (!d)
		return;
	for (struct in_dev **p = &hid_open_devs; *p; p = &(*p)->next)
		if (*p == d) {
			*p = d->next;
			break;
		}
	if (d->th_on) {
		pthread_mutex_lock(&d->mu);
		d->stop = true;
		pthread_cond_signal(&d->cv);
		pthread_mutex_unlock(&d->mu);
		pthread_join(d->th, NULL);
	}
	pthread_cond_destroy(&d->cv);
	pthread_mutex_destroy(&d->mu);
	free(d->ring);
	if (d->h)
		hid_close(d->h);
	hidr_free(d->dec);
	hidd_free(d->desc);
	free(d->q);
	free(d);
	if (--hid_users == 0)
		hid_exit();
}

/* Opens candidate i into d: descriptor, decoder, device. */
static int open_one(struct in_dev *d, const struct in_hid_info *i, const struct in_hid_spec *s,
		    bool need_game, char *why, size_t whylen)
{
	char err[160];
	uint8_t *raw;
	size_t len;
	int rc = in_hid_read_desc(HID_SYSFS, i->node, &raw, &len);

	if (rc < 0) {
		in_say(why, whylen, "%s: report descriptor: %s", i->node, strerror(-rc));
		return rc;
	}
	rc = hidd_parse(raw, len, &d->desc, err, sizeof(err));
	free(raw);
	if (rc < 0) {
		in_say(why, whylen, "%s: report descriptor refused: %s", i->node, err);
		return rc;
	}
	if (need_game && !game_device(d->desc)) {
		in_say(why, whylen, "%s (%04x:%04x): not a joystick or gamepad", i->node, i->vid,
		    i->pid);
		rc = -ENODEV;
		goto fail;
	}
	d->opts = s->opts;
	rc = hidr_new(d->desc, &s->opts, &d->dec);
	if (rc < 0) {
		in_say(why, whylen, "%s: decoder: %s", i->node, strerror(-rc));
		goto fail;
	}
	d->qcap = hidr_max_events(d->dec);
	d->q = calloc((size_t)d->qcap, sizeof(*d->q));
	if (!d->q) {
		rc = -ENOMEM;
		goto fail;
	}
	errno = 0;
	d->h = hid_open_path(i->node);
	if (!d->h) {
		rc = errno ? -errno : -EIO;
		in_say(why, whylen, "%s: %s", i->node, strerror(-rc));
		goto fail;
	}
	/* A slot holds the longest input report the descriptor declares, with
	 * its id byte (at least 64: devices send more than they declare, and
	 * hidraw cuts a report to the buffer). */
	d->slot = 64;
	for (size_t k = 0; k < d->desc->nreport; k++) {
		size_t b = (d->desc->report[k].bits + 7) / 8 + 1;
		if (b > d->slot)
			d->slot = b;
	}
	if (d->slot > HIDD_MAX_REPORT_BYTES + 1)
		d->slot = HIDD_MAX_REPORT_BYTES + 1;
	d->ring = malloc(HID_RING * d->slot);
	if (!d->ring) {
		rc = -ENOMEM;
		goto fail;
	}
	rc = hid_start_reader(d);
	if (rc < 0) {
		in_say(why, whylen, "%s: reader thread: %s", i->node, strerror(-rc));
		goto fail;
	}
	return 0;
fail:
	if (d->h)
		hid_close(d->h);
	d->h = NULL;
	free(d->ring);
	d->ring = NULL;
	hidr_free(d->dec);
	hidd_free(d->desc);
	free(d->q);
	d->dec = NULL;
	d->desc = NULL;
	d->q = NULL;
	return rc;
}

static int hid_open_dev(const char *path, struct in_dev **out, char *why, size_t whylen)
{
	struct in_hid_spec s;
	struct in_hid_info *l = NULL;
	struct in_dev *d;
	size_t n = 0;
	bool any = false, need_game;
	int rc;

	*out = NULL;
	rc = in_hid_parse_spec(path, &s, why, whylen);
	if (rc < 0)
		return rc;
	need_game = !in_hid_spec_names_device(&s);
	d = calloc(1, sizeof(*d));
	if (!d)
		return -ENOMEM;
	d->magic = HID_MAGIC;
	pthread_mutex_init(&d->mu, NULL);
	pthread_cond_init(&d->cv, NULL);
	if (hid_users++ == 0 && hid_init() < 0) {
		in_say(why, whylen, "hidapi: initialisation failed");
		rc = -EIO;
		goto fail;
	}
	rc = enumerate(&l, &n);
	if (rc < 0)
		goto fail;
	rc = -ENODEV;
	for (size_t k = 0; k < n; k++) {
		if (!matches(&s, &l[k]))
			continue;
		if (any)
			in_say(why, whylen, "; ");
		any = true;
		if (node_in_use(l[k].node)) {
			in_say(why, whylen, "%s: already open", l[k].node);
			continue;
		}
		rc = open_one(d, &l[k], &s, need_game, why, whylen);
		if (rc < 0)
			continue;
		strcpy(d->node, l[k].node);
		d->next = hid_open_devs;
		hid_open_devs = d;
		snprintf(d->id.port, sizeof(d->id.port), "%s", l[k].port);
		snprintf(d->id.name, sizeof(d->id.name), "%s", l[k].name);
		d->id.vid = l[k].vid;
		d->id.pid = l[k].pid;
		snprintf(d->text, sizeof(d->text), "%s (%04x:%04x, %s%s%s%s)",
			 l[k].name[0] ? l[k].name : "unnamed", l[k].vid, l[k].pid,
			 l[k].port[0] ? "port " : "", l[k].port, l[k].port[0] ? ", " : "",
			 d->node);
		free(l);
		if (whylen)
			why[0] = '\0';
		*out = d;
		return 0;
	}
	if (!any)
		in_say(why, whylen, "no HID device matches '%s' (%zu hidraw device(s) found)",
		    path ? path : "hid", n);
	free(l);
fail:
	hid_close_dev(d);
	return rc == -ENOMEM ? rc : -ENODEV;
}

int in_hid_configure(struct in_dev *d, const char *terms, char *why, size_t whylen)
{
	struct in_hid_spec s;
	struct hidr *dec;
	struct in_event *q;
	int rc;

	if (whylen)
		why[0] = '\0';
	if (!d || d->magic != HID_MAGIC) {
		in_say(why, whylen, "not a HID device");
		return -EINVAL;
	}
	memset(&s, 0, sizeof(s));
	s.vid = s.pid = s.iface = -1;
	s.opts = d->opts;
	rc = apply_terms(terms, &s, why, whylen);
	if (rc < 0)
		return rc;
	if (in_hid_spec_names_device(&s)) {
		in_say(why, whylen, "'%s' names a device: only decoder options can be changed", terms);
		return -EINVAL;
	}
	rc = hidr_new(d->desc, &s.opts, &dec);
	if (rc < 0) {
		in_say(why, whylen, "decoder options refused");
		return rc;
	}
	q = calloc((size_t)hidr_max_events(dec), sizeof(*q));
	if (!q) {
		hidr_free(dec);
		return -ENOMEM;
	}
	hidr_free(d->dec);
	free(d->q);
	d->dec = dec;
	d->q = q;
	d->qcap = hidr_max_events(dec);
	d->qhead = d->qn = 0;
	d->opts = s.opts;
	return 0;
}

static int hid_fd(struct in_dev *d)
{
	(void)d;
	return -1;
}

static int hid_rd(struct in_dev *d, struct in_event *out, int max)
{
	int n = 0;

	for (int reads = 0;; reads++) {
		int k = d->qn < max - n ? d->qn : max - n;
		unsigned have, head;
		bool gone;

		memcpy(out + n, d->q + d->qhead, (size_t)k * sizeof(*out));
		d->qhead += k;
		d->qn -= k;
		n += k;
		if (n == max || reads == HID_MAX_READS)
			return n;
		pthread_mutex_lock(&d->mu);
		have = d->n;
		head = d->head;
		gone = d->gone;
		pthread_mutex_unlock(&d->mu);
		if (!have)   /* after the last report: gone, and the next call fails again */
			return n > 0 || !gone ? n : -ENODEV;
		k = hidr_decode(d->dec, d->ring + (size_t)head * d->slot, d->len[head], d->t[head],
				d->q, d->qcap);
		d->qhead = 0;
		d->qn = k > 0 ? k : 0;
		pthread_mutex_lock(&d->mu);
		d->head = (head + 1) % HID_RING;
		d->n--;
		pthread_cond_signal(&d->cv);
		pthread_mutex_unlock(&d->mu);
	}
}

static const char *hid_describe(struct in_dev *d)
{
	return d->text;
}

static void hid_ident(struct in_dev *d, struct in_ident *id)
{
	*id = d->id;
}

static int hid_list_out(FILE *out, const char *(*profile)(void *u, const struct in_ident *id),
			void *u);

const struct in_backend in_hid = {
	.name = "hid",
	.open = hid_open_dev,
	.fd = hid_fd,
	.read = hid_rd,
	.close = hid_close_dev,
	.describe = hid_describe,
	.ident = hid_ident,
	.configure = in_hid_configure,
	.node = "/dev/hidraw",
	.list = hid_list_out,
	.flags = IN_NEEDS_BINDINGS,
};

int in_hid_list(struct in_hid_info **out, size_t *count)
{
	struct in_hid_info *l;
	size_t n;
	int rc;

	*out = NULL;
	*count = 0;
	if (hid_users++ == 0 && hid_init() < 0) {
		hid_users--;
		return -EIO;
	}
	rc = enumerate(&l, &n);
	if (--hid_users == 0)
		hid_exit();
	if (rc < 0)
		return rc;
	for (size_t i = 0; i < n; i++) {
		struct hidd_desc *d;
		uint8_t *raw;
		size_t len, need;
		char err[160];

		rc = in_hid_read_desc(HID_SYSFS, l[i].node, &raw, &len);
		if (rc < 0) {
			in_say(l[i].why, sizeof(l[i].why), "report descriptor: %s", strerror(-rc));
			continue;
		}
		rc = hidd_parse(raw, len, &d, err, sizeof(err));
		free(raw);
		if (rc < 0) {
			in_say(l[i].why, sizeof(l[i].why), "report descriptor refused: %s", err);
			continue;
		}
		need = hidd_describe(d, NULL, 0) + 1;
		l[i].fields = malloc(need);
		if (l[i].fields)
			hidd_describe(d, l[i].fields, need);
		else
			in_say(l[i].why, sizeof(l[i].why), "out of memory");
		hidd_free(d);
	}
	*out = l;
	*count = n;
	return 0;
}

void in_hid_list_free(struct in_hid_info *l, size_t n)
{
	if (!l)
		return;
	for (size_t i = 0; i < n; i++)
		free(l[i].fields);
	free(l);
}

/* in_hid.list: every device with its ids, port, serial, the bindings
 * sections that name it, its profile and its decoded report fields. */
static int hid_list_out(FILE *out, const char *(*profile)(void *u, const struct in_ident *id),
			void *u)
{
	struct in_hid_info *hid = NULL;
	size_t n = 0;
	int rc = in_hid_list(&hid, &n);

	fprintf(out, "HID devices (hidraw): %zu%s\n", n, rc < 0 ? " (listing failed)" : "");
	for (size_t i = 0; i < n; i++) {
		struct in_ident id = { .vid = hid[i].vid, .pid = hid[i].pid };
		const char *p;

		snprintf(id.port, sizeof(id.port), "%s", hid[i].port);
		snprintf(id.name, sizeof(id.name), "%s", hid[i].name);
		p = profile(u, &id);
		fprintf(out, "  %s  %04x:%04x  \"%s\"  port %s  serial %s\n    bindings section: "
			"[device \"usb-%s\"] or [device \"%04x:%04x\"]; profile: %s\n",
			hid[i].node, hid[i].vid, hid[i].pid, hid[i].name,
			hid[i].port[0] ? hid[i].port : "-", hid[i].serial[0] ? hid[i].serial : "-",
			hid[i].port[0] ? hid[i].port : "?", hid[i].vid, hid[i].pid, p ? p : "none");
		if (hid[i].fields)
			fprintf(out, "%s", hid[i].fields);
		else
			fprintf(out, "    fields: %s\n", hid[i].why);
	}
	in_hid_list_free(hid, n);
	return rc < 0 ? rc : 0;
}
