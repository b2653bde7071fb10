/*
 * in_gpio: the libgpiod v1 backend. Spec syntax and behaviour are in
 * in_gpio.h; debounce and coin counting are deb.c, output timing gpo.c.
 */
#include "input/in_gpio.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/epoll.h>
#include <time.h>
#include <unistd.h>

#include <gpiod.h>
#include <linux/input-event-codes.h>

#include "engine/core/num.h"
#include "input/deb.h"

#define GPIO_MAGIC 0x6770696fu        /* "gpio": in_gpio_update checks its device */
#define GPIO_QUEUE 256
#define GPIO_BATCH 16                 /* kernel events read per call and line */
#define GPIO_STAMP_SLACK 10000000000ull
#define GPIO_CONSUMER "arcaded"

static const struct {
	const char *role;
	int code;
	int coin;
} gpio_roles[] = {
	{ "coin", KEY_5, 1 }, { "coin2", KEY_6, 1 }, { "start", KEY_1, 0 },
	{ "start2", KEY_2, 0 }, { "service", KEY_9, 0 }, { "test", KEY_F2, 0 },
	{ "tilt", KEY_T, 0 }, { "p1_up", KEY_UP, 0 }, { "p1_down", KEY_DOWN, 0 },
	{ "p1_left", KEY_LEFT, 0 }, { "p1_right", KEY_RIGHT, 0 },
	{ "p1_fire", KEY_LEFTCTRL, 0 }, { "p1_button1", KEY_LEFTCTRL, 0 },
	{ "p1_button2", KEY_LEFTALT, 0 }, { "p1_button3", KEY_SPACE, 0 },
	{ "p1_button4", KEY_LEFTSHIFT, 0 }, { "p1_button5", KEY_Z, 0 },
	{ "p1_button6", KEY_X, 0 }, { "p2_up", KEY_R, 0 }, { "p2_down", KEY_F, 0 },
	{ "p2_left", KEY_D, 0 }, { "p2_right", KEY_G, 0 }, { "p2_button1", KEY_A, 0 },
	{ "p2_button2", KEY_S, 0 }, { "p2_button3", KEY_Q, 0 }, { "p2_button4", KEY_W, 0 },
};

struct gpio_in {
	struct gpiod_line *line;
	bool found;                  /* from gpiod_line_find: owns its chip */
	int fd;
	int code;
	int coin;
	struct deb deb;
	struct deb_coin cd;
};

struct gpio_out {
	struct gpiod_line *line;
	bool found;
	int level;
};

struct in_dev {
	uint32_t magic;
	struct in_gpio_spec spec;
	struct gpiod_chip *chip;
	struct gpio_in in[IN_GPIO_MAX_LINES];
	int nin;
	struct gpio_out meter, lamp;
	int epfd;
	struct gpo out;
	struct in_event q[GPIO_QUEUE];
	int qhead, qn;
	char base[448];              /* chip and lines, set at open */
	char text[512];              /* base and the coin counters */
};

/* ---- spec ------------------------------------------------------------ */

static int parse_line(const char *t, size_t len, struct in_gpio_line *l)
{
	bool digits = len > 0;

	memset(l, 0, sizeof(*l));
	l->offset = -1;
	if (len == 0 || len >= sizeof(l->name))
		return -1;
	for (size_t i = 0; i < len; i++) {
		char c = t[i];

		if (!(c >= '0' && c <= '9'))
			digits = false;
		if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
		      c == '_' || c == '-' || c == '.'))
			return -1;
	}
	if (digits) {
		l->offset = (int)strtol(t, NULL, 10);
		return l->offset <= 65535 && len <= 5 ? 0 : -1;
	}
	memcpy(l->name, t, len);
	l->name[len] = '\0';
	return 0;
}

static bool same_line(const struct in_gpio_line *a, const struct in_gpio_line *b)
{
	return a->offset == b->offset && strcmp(a->name, b->name) == 0;
}

static bool line_set(const struct in_gpio_line *l)
{
	return l->offset >= 0 || l->name[0];
}

/* Removes the blanks around the first '=' of t (already trimmed at both
 * ends); returns that '=' or NULL. */
static char *tight_eq(char *t)
{
	char *eq = strchr(t, '='), *a, *b;

	if (!eq)
		return NULL;
	for (a = eq; a > t && (a[-1] == ' ' || a[-1] == '\t'); a--)
		;
	for (b = eq + 1; *b == ' ' || *b == '\t'; b++)
		;
	*a = '=';
	memmove(a + 1, b, strlen(b) + 1);
	return a;
}

/* "LINE=WHAT" */
static int parse_map(struct in_gpio_spec *s, char *t, char *why, size_t whylen)
{
	char *eq = tight_eq(t);
	struct in_gpio_line *l;
	int code = -1, coin = 0;

	if (s->nin == IN_GPIO_MAX_LINES) {
		in_say(why, whylen, "more than %d input lines", IN_GPIO_MAX_LINES);
		return -EINVAL;
	}
	l = &s->in[s->nin];
	if (!eq || parse_line(t, (size_t)(eq - t), l) < 0) {
		in_say(why, whylen, "bad line '%s' (LINE=ROLE with LINE an offset or a name)", t);
		return -EINVAL;
	}
	for (size_t i = 0; i < sizeof(gpio_roles) / sizeof(gpio_roles[0]); i++) {
		if (strcmp(eq + 1, gpio_roles[i].role) == 0) {
			code = gpio_roles[i].code;
			coin = gpio_roles[i].coin;
		}
	}
	if (code < 0)
		code = in_key_from_name(eq + 1);
	if (code < 0) {
		in_say(why, whylen, "unknown role or key '%s'", eq + 1);
		return -EINVAL;
	}
	l->code = code;
	l->coin = coin;
	for (int i = 0; i < s->nin; i++) {
		if (same_line(&s->in[i], l)) {
			in_say(why, whylen, "line '%.*s' given twice", (int)(eq - t), t);
			return -EINVAL;
		}
	}
	s->nin++;
	return 0;
}

static int ms_option(const char *v, long lo, long hi, uint64_t *out)
{
	int64_t n;

	if (num_parse(v, lo, hi, &n) < 0)
		return -1;
	*out = (uint64_t)n * 1000000u;
	return 0;
}

static int parse_option(struct in_gpio_spec *s, char *t, char *why, size_t whylen)
{
	char *eq = tight_eq(t);
	const char *v;
	int bad = 0;

	if (!eq)
		goto bad;
	*eq = '\0';
	v = eq + 1;
	if (strcmp(t, "meter") == 0 || strcmp(t, "lamp_start") == 0) {
		struct in_gpio_line *l = t[0] == 'm' ? &s->meter : &s->lamp_start;

		bad = parse_line(v, strlen(v), l);
	} else if (strcmp(t, "active") == 0 || strcmp(t, "out_active") == 0) {
		int low = strcmp(v, "low") == 0;

		bad = !low && strcmp(v, "high") != 0;
		if (t[0] == 'a')
			s->active_low = low;
		else
			s->out_active_low = low;
	} else if (strcmp(t, "bias") == 0) {
		static const char *const b[] = { "pull-up", "pull-down", "disable", "as-is" };

		bad = 1;
		for (int i = 0; i < 4; i++) {
			if (strcmp(v, b[i]) == 0) {
				s->bias = i;
				bad = 0;
			}
		}
	} else if (strcmp(t, "holdoff_ms") == 0) {
		bad = ms_option(v, 1, 1000, &s->holdoff_ns);
	} else if (strcmp(t, "coin_min_ms") == 0) {
		bad = ms_option(v, 1, 10000, &s->coin_min_ns);
	} else if (strcmp(t, "coin_max_ms") == 0) {
		bad = ms_option(v, 1, 10000, &s->coin_max_ns);
	} else if (strcmp(t, "meter_ms") == 0) {
		bad = ms_option(v, 1, 10000, &s->meter_ns);
	} else if (strcmp(t, "blink_ms") == 0) {
		bad = ms_option(v, 1, 10000, &s->blink_ns);
	} else {
		bad = 1;
	}
	if (!bad)
		return 0;
	*eq = '=';
bad:
	in_say(why, whylen, "bad option '%s'", t);
	return -EINVAL;
}

/* Splits s at sep into trimmed, non-empty pieces, calling fn on each. */
static int each_piece(char *s, char sep, int (*fn)(struct in_gpio_spec *, char *, char *, size_t),
		      struct in_gpio_spec *sp, char *why, size_t whylen)
{
	while (s) {
		char *next = strchr(s, sep), *e;
		int rc;

		if (next)
			*next++ = '\0';
		while (*s == ' ' || *s == '\t')
			s++;
		e = s + strlen(s);
		while (e > s && (e[-1] == ' ' || e[-1] == '\t'))
			*--e = '\0';
		if (*s) {
			rc = fn(sp, s, why, whylen);
			if (rc < 0)
				return rc;
		}
		s = next;
	}
	return 0;
}

int in_gpio_parse_spec(const char *s, struct in_gpio_spec *out, char *why, size_t whylen)
{
	char buf[1024];
	char *map, *opts, *colon, *eq;
	int rc;

	if (whylen)
		why[0] = '\0';
	memset(out, 0, sizeof(*out));
	out->meter.offset = out->lamp_start.offset = -1;
	out->active_low = 1;
	out->bias = IN_GPIO_BIAS_PULL_UP;
	out->holdoff_ns = DEB_HOLDOFF_NS;
	out->coin_min_ns = DEB_COIN_MIN_NS;
	out->coin_max_ns = DEB_COIN_MAX_NS;
	out->meter_ns = GPO_METER_ON_NS;
	out->blink_ns = GPO_BLINK_NS;
	if (s && strncmp(s, "gpio:", 5) == 0)
		s += 5;
	if (!s || !*s) {
		in_say(why, whylen, "a GPIO device needs a spec (gpio:CHIP:LINE=ROLE,...)");
		return -EINVAL;
	}
	if (strlen(s) >= sizeof(buf)) {
		in_say(why, whylen, "GPIO spec longer than %zu bytes", sizeof(buf) - 1);
		return -EINVAL;
	}
	strcpy(buf, s);
	map = buf;
	opts = strchr(buf, ';');
	if (opts)
		*opts++ = '\0';
	colon = strchr(map, ':');
	eq = strchr(map, '=');
	if (colon && (!eq || colon < eq)) {
		*colon = '\0';
		if (!*map || strlen(map) >= sizeof(out->chip)) {
			in_say(why, whylen, "bad chip '%s'", map);
			return -EINVAL;
		}
		strcpy(out->chip, map);
		map = colon + 1;
	}
	rc = each_piece(map, ',', parse_map, out, why, whylen);
	if (rc == 0)
		rc = each_piece(opts, ';', parse_option, out, why, whylen);
	if (rc < 0)
		return rc;
	if (out->nin == 0 && !line_set(&out->meter) && !line_set(&out->lamp_start)) {
		in_say(why, whylen, "no lines in GPIO spec");
		return -EINVAL;
	}
	if (out->coin_min_ns > out->coin_max_ns) {
		in_say(why, whylen, "coin_min_ms above coin_max_ms");
		return -EINVAL;
	}
	for (int i = 0; i < out->nin + 2; i++) {
		const struct in_gpio_line *l = i < out->nin ? &out->in[i]
					       : i == out->nin ? &out->meter : &out->lamp_start;

		if (!out->chip[0] && l->offset >= 0) {
			in_say(why, whylen, "line offset %d needs a chip (gpio:CHIP:...)", l->offset);
			return -EINVAL;
		}
		if (i < out->nin && ((line_set(&out->meter) && same_line(l, &out->meter)) ||
				     (line_set(&out->lamp_start) && same_line(l, &out->lamp_start))))
			goto twice;
	}
	if (line_set(&out->meter) && same_line(&out->meter, &out->lamp_start))
		goto twice;
	return 0;
twice:
	in_say(why, whylen, "an output line is also used for something else");
	return -EINVAL;
}

/* ---- device ---------------------------------------------------------- */

static int input_flags(const struct in_gpio_spec *s)
{
	static const int bias[] = {
		[IN_GPIO_BIAS_PULL_UP] = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP,
		[IN_GPIO_BIAS_PULL_DOWN] = GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN,
		[IN_GPIO_BIAS_DISABLE] = GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE,
		[IN_GPIO_BIAS_AS_IS] = 0,
	};

	return (s->active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0) | bias[s->bias];
}

static void line_text(const struct in_gpio_line *l, char *buf, size_t len)
{
	if (l->name[0])
		snprintf(buf, len, "%s", l->name);
	else
		snprintf(buf, len, "%d", l->offset);
}

static struct gpiod_line *find_line(struct in_dev *d, const struct in_gpio_line *l, bool *found,
				    char *why, size_t whylen)
{
	struct gpiod_line *line;
	char name[40];

	*found = false;
	errno = 0;
	if (d->chip) {
		line = l->offset >= 0 ? gpiod_chip_get_line(d->chip, (unsigned)l->offset)
				      : gpiod_chip_find_line(d->chip, l->name);
	} else {
		line = gpiod_line_find(l->name);
		*found = line != NULL;
	}
	if (!line) {
		line_text(l, name, sizeof(name));
		in_say(why, whylen, "line %s: %s", name,
		    errno && errno != ENOENT ? strerror(errno) : "not found");
	}
	return line;
}

static void drop_line(struct gpiod_line *line, bool found)
{
	if (!line)
		return;
	if (found)
		gpiod_line_close_chip(line);   /* releases the line and closes its chip */
	else
		gpiod_line_release(line);
}

static void gpio_close(struct in_dev *d)
{
	if (!d)
		return;
	for (int i = 0; i < d->nin; i++)
		drop_line(d->in[i].line, d->in[i].found);
	if (d->meter.line)
		gpiod_line_set_value(d->meter.line, 0);
	if (d->lamp.line)
		gpiod_line_set_value(d->lamp.line, 0);
	drop_line(d->meter.line, d->meter.found);
	drop_line(d->lamp.line, d->lamp.found);
	if (d->chip)
		gpiod_chip_close(d->chip);
	if (d->epfd >= 0)
		close(d->epfd);
	free(d);
}

static void queue(struct in_dev *d, uint64_t t, int code, int value)
{
	struct in_event *e;

	if (d->qn == GPIO_QUEUE)
		return;   /* cannot happen: reads stop while the queue lacks room */
	e = &d->q[(d->qhead + d->qn++) % GPIO_QUEUE];
	e->time_ns = t;
	e->type = IN_KEY;
	e->code = (uint16_t)code;
	e->value = value;
}

static int open_input(struct in_dev *d, int i, char *why, size_t whylen)
{
	struct gpio_in *g = &d->in[i];
	const struct in_gpio_line *l = &d->spec.in[i];
	struct epoll_event ev = { .events = EPOLLIN };
	char name[40];
	int v;

	line_text(l, name, sizeof(name));
	g->fd = -1;
	g->code = l->code;
	g->coin = l->coin;
	g->line = find_line(d, l, &g->found, why, whylen);
	if (!g->line)
		return -ENODEV;
	if (gpiod_line_request_both_edges_events_flags(g->line, GPIO_CONSUMER,
						       input_flags(&d->spec)) < 0) {
		int rc = -errno;

		in_say(why, whylen, "line %s: edge events: %s", name, strerror(-rc));
		return rc;
	}
	g->fd = gpiod_line_event_get_fd(g->line);
	if (g->fd < 0 || fcntl(g->fd, F_SETFL, fcntl(g->fd, F_GETFL) | O_NONBLOCK) < 0) {
		in_say(why, whylen, "line %s: no event fd", name);
		return -EIO;
	}
	ev.data.u32 = (uint32_t)i;
	if (epoll_ctl(d->epfd, EPOLL_CTL_ADD, g->fd, &ev) < 0) {
		int rc = -errno;

		in_say(why, whylen, "line %s: epoll: %s", name, strerror(-rc));
		return rc;
	}
	v = gpiod_line_get_value(g->line);
	if (g->coin) {
		deb_coin_init(&g->cd, d->spec.holdoff_ns, d->spec.coin_min_ns, d->spec.coin_max_ns);
		if (v == 1) {
			uint64_t when;

			deb_coin_edge(&g->cd, in_now_ns(), 1, &when);
		}
	} else {
		deb_init(&g->deb, d->spec.holdoff_ns, 0);
		if (v == 1) {
			struct deb_ev e[2];
			uint64_t now = in_now_ns();

			if (deb_edge(&g->deb, now, 1, e) > 0)
				queue(d, now, g->code, 1);
		}
	}
	return 0;
}

static int open_output(struct in_dev *d, const struct in_gpio_line *l, struct gpio_out *o,
		       char *why, size_t whylen)
{
	char name[40];

	if (!line_set(l))
		return 0;
	line_text(l, name, sizeof(name));
	o->line = find_line(d, l, &o->found, why, whylen);
	if (!o->line)
		return -ENODEV;
	if (gpiod_line_request_output_flags(o->line, GPIO_CONSUMER,
					    d->spec.out_active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW
								   : 0,
					    0) < 0) {
		int rc = -errno;

		/* not requested: release only what find_line took */
		drop_line(o->line, o->found);
		o->line = NULL;
		in_say(why, whylen, "line %s: output: %s", name, strerror(-rc));
		return rc;
	}
	return 0;
}

static void describe_dev(struct in_dev *d)
{
	char name[40];
	const char *label = d->chip ? gpiod_chip_label(d->chip) : NULL;

	snprintf(d->base, sizeof(d->base), "gpio %s%s%s:",
		 d->chip ? gpiod_chip_name(d->chip) : "(lines by name)", label ? " " : "",
		 label ? label : "");
	for (int i = 0; i < d->nin; i++) {
		const char *key = in_key_name(d->in[i].code);

		line_text(&d->spec.in[i], name, sizeof(name));
		in_say(d->base, sizeof(d->base), "%s %s=%s%s", i ? "," : "", name, key ? key : "?",
		    d->in[i].coin ? " (coin)" : "");
	}
	if (d->meter.line) {
		line_text(&d->spec.meter, name, sizeof(name));
		in_say(d->base, sizeof(d->base), "; meter %s", name);
	}
	if (d->lamp.line) {
		line_text(&d->spec.lamp_start, name, sizeof(name));
		in_say(d->base, sizeof(d->base), "; start lamp %s", name);
	}
}

static int gpio_open(const char *path, struct in_dev **out, char *why, size_t whylen)
{
	struct in_dev *d;
	int rc;

	*out = NULL;
	d = calloc(1, sizeof(*d));
	if (!d)
		return -ENOMEM;
	d->magic = GPIO_MAGIC;
	d->epfd = -1;
	rc = in_gpio_parse_spec(path, &d->spec, why, whylen);
	if (rc < 0)
		goto fail;
	d->epfd = epoll_create1(EPOLL_CLOEXEC);
	if (d->epfd < 0) {
		rc = -errno;
		goto fail;
	}
	if (d->spec.chip[0]) {
		errno = 0;
		d->chip = gpiod_chip_open_lookup(d->spec.chip);
		if (!d->chip) {
			rc = errno ? -errno : -ENODEV;
			in_say(why, whylen, "%s: %s", d->spec.chip, strerror(-rc));
			goto fail;
		}
	}
	for (int i = 0; i < d->spec.nin; i++) {
		d->nin = i + 1;   /* so close releases what this one took */
		rc = open_input(d, i, why, whylen);
		if (rc < 0)
			goto fail;
	}
	rc = open_output(d, &d->spec.meter, &d->meter, why, whylen);
	if (rc == 0)
		rc = open_output(d, &d->spec.lamp_start, &d->lamp, why, whylen);
	if (rc < 0)
		goto fail;
	gpo_init(&d->out, d->spec.meter_ns, d->spec.meter_ns, d->spec.blink_ns);
	describe_dev(d);
	*out = d;
	return 0;
fail:
	gpio_close(d);
	/* a missing chip or line may appear later: the app retries */
	return rc == -ENOENT ? -ENODEV : rc;
}

static int gpio_fd(struct in_dev *d)
{
	return d->epfd;
}

static uint64_t stamp(const struct timespec *ts, uint64_t now)
{
	uint64_t t = (uint64_t)ts->tv_sec * 1000000000u + (uint64_t)ts->tv_nsec;

	/* Kernels before 5.7 stamp with CLOCK_REALTIME. */
	if (t > now + GPIO_STAMP_SLACK || t + GPIO_STAMP_SLACK < now)
		return now;
	return t;
}

/* Feeds one line's kernel events through its debounce. */
static int read_line(struct in_dev *d, struct gpio_in *g, uint64_t now)
{
	struct gpiod_line_event ev[GPIO_BATCH];

	while (GPIO_QUEUE - d->qn >= 2 * GPIO_BATCH) {
		int k = gpiod_line_event_read_fd_multiple(g->fd, ev, GPIO_BATCH);

		if (k < 0 && errno == EINTR)
			continue;
		if (k < 0)
			return errno == EAGAIN ? 0 : -ENODEV;
		for (int i = 0; i < k; i++) {
			uint64_t t = stamp(&ev[i].ts, now), when;
			int level = ev[i].event_type == GPIOD_LINE_EVENT_RISING_EDGE;
			struct deb_ev e[2];

			if (g->coin) {
				if (deb_coin_edge(&g->cd, t, level, &when)) {
					queue(d, when, g->code, 1);
					queue(d, when, g->code, 0);
				}
				continue;
			}
			for (int n = deb_edge(&g->deb, t, level, e), j = 0; j < n; j++)
				queue(d, e[j].time_ns, g->code, e[j].level);
		}
		if (k < GPIO_BATCH)
			return 0;
	}
	return 0;
}

static int gpio_read(struct in_dev *d, struct in_event *out, int max)
{
	uint64_t now = in_now_ns();
	int n = 0;

	for (int i = 0; i < d->nin; i++) {
		struct gpio_in *g = &d->in[i];
		struct deb *db = g->coin ? &g->cd.d : &g->deb;
		struct deb_ev e;
		uint64_t when;
		int v = -1, got;

		if (read_line(d, g, now) < 0)
			return -ENODEV;
		if (GPIO_QUEUE - d->qn < 2)
			continue;
		now = in_now_ns();   /* not before the edges just read */
		/* The v1 interface samples the level when its IRQ thread runs,
		 * and close edges can merge: the last event may not carry the
		 * level the line settled at. Once the hold-off is over, the
		 * line's own level is the truth. */
		if (now >= db->until_ns)
			v = gpiod_line_get_value(g->line);
		if (g->coin) {
			got = v >= 0 ? deb_coin_settle(&g->cd, now, v, &when)
				     : deb_coin_poll(&g->cd, now, &when);
			if (got) {
				queue(d, when, g->code, 1);
				queue(d, when, g->code, 0);
			}
		} else {
			got = v >= 0 ? deb_settle(&g->deb, now, v, &e) : deb_poll(&g->deb, now, &e);
			if (got)
				queue(d, e.time_ns, g->code, e.level);
		}
	}
	while (n < max && d->qn > 0) {
		out[n++] = d->q[d->qhead];
		d->qhead = (d->qhead + 1) % GPIO_QUEUE;
		d->qn--;
	}
	return n;
}

static const char *gpio_describe(struct in_dev *d)
{
	uint32_t coins = 0, rejected = 0;

	for (int i = 0; i < d->nin; i++) {
		if (d->in[i].coin) {
			coins += d->in[i].cd.coins;
			rejected += d->in[i].cd.rejected;
		}
	}
	snprintf(d->text, sizeof(d->text), "%s", d->base);
	if (coins || rejected)
		in_say(d->text, sizeof(d->text), " [coins %u, rejected pulses %u]", coins, rejected);
	return d->text;
}

static void gpio_ident(struct in_dev *d, struct in_ident *id)
{
	memset(id, 0, sizeof(*id));
	snprintf(id->name, sizeof(id->name), "gpio %s", d->spec.chip[0] ? d->spec.chip : "lines");
}

int in_gpio_update(struct in_dev *d, const struct gpo_state *s, uint64_t now_ns)
{
	int meter, lamp;

	if (!d || d->magic != GPIO_MAGIC)
		return -EINVAL;
	gpo_update(&d->out, s, now_ns, &meter, &lamp);
	if (d->meter.line && meter != d->meter.level) {
		if (gpiod_line_set_value(d->meter.line, meter) < 0)
			return -ENODEV;
		d->meter.level = meter;
	}
	if (d->lamp.line && lamp != d->lamp.level) {
		if (gpiod_line_set_value(d->lamp.line, lamp) < 0)
			return -ENODEV;
		d->lamp.level = lamp;
	}
	return 0;
}

static int gpio_list_out(FILE *out, const char *(*profile)(void *u, const struct in_ident *id),
			 void *u);

const struct in_backend in_gpio = {
	.name = "gpio",
	.open = gpio_open,
	.fd = gpio_fd,
	.read = gpio_read,
	.close = gpio_close,
	.describe = gpio_describe,
	.ident = gpio_ident,
	.outputs = in_gpio_update,
	.node = "/dev/gpiochip",
	.list = gpio_list_out,
};

struct gpio_text {
	char *buf;
	size_t len, cap;
	int failed;
};

__attribute__((format(printf, 2, 3)))
static void text_add(struct gpio_text *t, const char *fmt, ...)
{
	va_list ap;
	int n;

	if (t->failed)
		return;
	for (;;) {
		va_start(ap, fmt);
		n = vsnprintf(t->buf ? t->buf + t->len : NULL, t->buf ? t->cap - t->len : 0, fmt,
			      ap);
		va_end(ap);
		if (n < 0) {
			t->failed = 1;
			return;
		}
		if (t->buf && t->len + (size_t)n < t->cap) {
			t->len += (size_t)n;
			return;
		}
		{
			size_t cap = (t->cap ? t->cap : 1024) * 2 + (size_t)n;
			char *b = realloc(t->buf, cap);

			if (!b) {
				t->failed = 1;
				return;
			}
			t->buf = b;
			t->cap = cap;
		}
	}
}

int in_gpio_list(char **text)
{
	struct gpio_text t = { NULL, 0, 0, 0 };
	struct gpiod_chip_iter *it = gpiod_chip_iter_new();
	struct gpiod_chip *chip;

	*text = NULL;
	text_add(&t, "%s", "");
	if (it) {
		while ((chip = gpiod_chip_iter_next(it)) != NULL) {
			unsigned n = gpiod_chip_num_lines(chip);

			text_add(&t, "%s [%s] %u lines\n", gpiod_chip_name(chip),
				 gpiod_chip_label(chip) ? gpiod_chip_label(chip) : "", n);
			for (unsigned i = 0; i < n; i++) {
				struct gpiod_line *l = gpiod_chip_get_line(chip, i);
				const char *name = l ? gpiod_line_name(l) : NULL;
				const char *user = l ? gpiod_line_consumer(l) : NULL;

				if (!l)
					continue;
				text_add(&t, "  %u %s %s", i, name ? name : "-",
					 gpiod_line_direction(l) == GPIOD_LINE_DIRECTION_OUTPUT ? "output"
												: "input");
				if (gpiod_line_is_used(l))
					text_add(&t, ", used by %s", user ? user : "the kernel");
				text_add(&t, "\n");
			}
		}
		gpiod_chip_iter_free(it);
	}
	if (t.failed) {
		free(t.buf);
		return -ENOMEM;
	}
	*text = t.buf;
	return 0;
}

/* in_gpio.list: every chip and line (no profiles: lines have no ids). */
static int gpio_list_out(FILE *out, const char *(*profile)(void *u, const struct in_ident *id),
			 void *u)
{
	char *text = NULL;
	int rc = in_gpio_list(&text);

	(void)profile;
	(void)u;
	fprintf(out, "GPIO chips:%s\n%s", rc < 0 ? " (listing failed)" : "", text ? text : "");
	free(text);
	return rc;
}
