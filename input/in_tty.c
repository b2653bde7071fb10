/*
 * in_tty: keys typed in a terminal (the terminal preview's input). The
 * bytes are decoded by ttyk (ttyk.h), which also synthesizes the
 * releases a terminal never sends.
 *
 * Terminal modes belong to the display (dp_term puts the terminal in raw
 * mode); this backend only reads. It does not set O_NONBLOCK on standard
 * input: that flag lives in the open file description, which a shell
 * usually shares between stdin and stdout, so it would make the display's
 * writes to stdout fail with EAGAIN. Instead every read is preceded by a
 * poll with a zero timeout, which never blocks whatever the flags.
 */
#include "input/in.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "input/ttyk.h"

struct in_dev {
	int fd;
	int own;                 /* fd opened here (closed at close) */
	uint8_t in[64];          /* bytes read but not yet decoded */
	size_t inoff, inlen;
	struct ttyk k;
	char desc[128];
};

static int tty_open(const char *path, struct in_dev **out, char *why, size_t whylen)
{
	struct in_dev *d;
	char name[64];
	int rc;

	*out = NULL;
	if (whylen)
		why[0] = '\0';
	d = calloc(1, sizeof(*d));
	if (!d) {
		snprintf(why, whylen, "out of memory");
		return -ENOMEM;
	}
	if (path) {
		d->fd = open(path, O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
		if (d->fd < 0) {
			rc = -errno;
			snprintf(why, whylen, "%s: %s", path, strerror(-rc));
			goto fail;
		}
		d->own = 1;
		if (!isatty(d->fd)) {
			rc = -ENOTTY;
			snprintf(why, whylen, "%s: not a terminal", path);
			goto fail_fd;
		}
		snprintf(d->desc, sizeof(d->desc), "terminal (%s)", path);
	} else {
		d->fd = 0;
		if (!isatty(0)) {
			rc = -ENOTTY;
			snprintf(why, whylen, "standard input is not a terminal");
			goto fail;
		}
		if (ttyname_r(0, name, sizeof(name)) != 0)
			snprintf(name, sizeof(name), "stdin");
		snprintf(d->desc, sizeof(d->desc), "terminal (%s)", name);
	}
	ttyk_init(&d->k);
	*out = d;
	return 0;

fail_fd:
	close(d->fd);
fail:
	free(d);
	return rc;
}

static int tty_fd(struct in_dev *d)
{
	return d->fd;
}

/* Reads what the terminal has into d->in. 1: bytes read; 0: none waiting;
 * -ENODEV: the terminal hung up; other -errno. */
static int fill(struct in_dev *d)
{
	struct pollfd p = { .fd = d->fd, .events = POLLIN };
	ssize_t got;
	int r;

	do
		r = poll(&p, 1, 0);
	while (r < 0 && errno == EINTR);
	if (r < 0)
		return -errno;
	if (r == 0)
		return 0;
	if (!(p.revents & POLLIN))
		return (p.revents & (POLLHUP | POLLERR | POLLNVAL)) ? -ENODEV : 0;
	got = read(d->fd, d->in, sizeof(d->in));
	if (got < 0) {
		if (errno == EAGAIN || errno == EINTR)
			return 0;
		/* A terminal that hung up reads as EIO. */
		return errno == EIO ? -ENODEV : -errno;
	}
	/* Readable yet nothing: end of file, the terminal is gone. */
	if (got == 0)
		return -ENODEV;
	d->inoff = 0;
	d->inlen = (size_t)got;
	return 1;
}

static int tty_read(struct in_dev *d, struct in_event *ev, int max)
{
	uint64_t now = in_now_ns();
	int n = 0, rc;

	for (;;) {
		if (d->inoff < d->inlen)
			d->inoff += ttyk_feed(&d->k, d->in + d->inoff, d->inlen - d->inoff, now);
		n += ttyk_take(&d->k, ev + n, max - n);
		if (n == max)
			return n;
		/* The queue is empty now, so a further feed makes progress. */
		if (d->inoff < d->inlen)
			continue;
		rc = fill(d);
		if (rc < 0)
			return rc;
		if (rc == 0)
			break;
	}
	/* Releases fall due with no byte arriving: the caller reads every
	 * tick, so they come out on time. */
	ttyk_expire(&d->k, now);
	n += ttyk_take(&d->k, ev + n, max - n);
	return n;
}

static void tty_close(struct in_dev *d)
{
	if (!d)
		return;
	if (d->own)
		close(d->fd);
	free(d);
}

static const char *tty_describe(struct in_dev *d)
{
	return d->desc;
}

const struct in_backend in_tty = {
	.name = "tty",
	.open = tty_open,
	.fd = tty_fd,
	.read = tty_read,
	.close = tty_close,
	.describe = tty_describe,
};
