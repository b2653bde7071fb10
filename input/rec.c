/*
 * rec: recordings. Every multi-byte field is put together and taken apart
 * by shifts, so the file is the same on any CPU and never depends on a
 * struct's layout or padding.
 */
#include "input/rec.h"

#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "engine/core/hash.h"
#include "engine/core/le.h"
#include "input/io.h"
#include "input/txt.h"

static const uint8_t rec_magic[8] = { 'A', 'R', 'C', 'D', 'R', 'E', 'C', '\0' };

/* Header sizes above this are refused as garbage rather than skipped. */
#define REC_HEADER_SIZE_MAX 1048576u
/* Bytes buffered by the writer and the reader. Records go in whole, so
 * every flush ends on a record boundary. */
#define REC_BUF 4096
/* Largest render size a header may name (r_new's limit). */
#define REC_RENDER_MAX 4096

size_t rec_record_size(uint8_t hash_flags)
{
	return REC_CMD_SIZE + (hash_flags & REC_HAS_STATE ? 8u : 0u) +
	       (hash_flags & REC_HAS_FRAME ? 8u : 0u) + (hash_flags & REC_HAS_AUDIO ? 8u : 0u);
}

/* The fixed header of a version: where its snapshot starts. */
static size_t rec_fixed_size(uint16_t version)
{
	return version >= REC_VERSION_3 ? REC_HEADER_SIZE_V3
	       : version >= REC_VERSION_2 ? REC_HEADER_SIZE_V2
					  : REC_HEADER_SIZE;
}

/* Version 3's header sum: bytes 0..95 but the count (32..35), which the
 * writer puts last. */
static uint64_t rec_header_sum(const uint8_t *buf)
{
	return hash_bytes(hash_bytes(HASH_INIT, buf, 32), buf + 36, 96 - 36);
}

size_t rec_header_encode(uint8_t *out, const struct rec_header *h)
{
	size_t size = rec_fixed_size(h->version);
	uint32_t snap = size == REC_HEADER_SIZE ? 0 : h->snapshot_len;

	memset(out, 0, size);
	memcpy(out, rec_magic, sizeof(rec_magic));
	le_put16(out + 8, h->version);
	le_put16(out + 10, h->tick_rate);
	le_put32(out + 12, (uint32_t)size + snap);
	le_put64(out + 16, h->map_hash);
	le_put32(out + 24, h->engine_version);
	out[28] = h->set.coins_per_credit;
	out[29] = h->set.freeplay;
	out[30] = h->set.start_in_play;
	out[31] = h->set.difficulty;
	le_put32(out + 32, h->count);
	out[36] = h->set.lives;
	if (size == REC_HEADER_SIZE)
		return size;
	le_put16(out + 40, h->render_w);
	le_put16(out + 42, h->render_h);
	out[44] = h->hash_flags;
	out[45] = h->level;
	le_put32(out + 48, h->render_version);
	memcpy(out + 56, h->map_name, strnlen(h->map_name, 8));
	le_put64(out + 64, (uint64_t)h->start_time);
	if (size >= REC_HEADER_SIZE_V3) {
		out[46] = h->set.volume;
		out[47] = h->set.attract_sound;
		out[37] = h->set.stage_time;
		out[38] = h->set.idle_out;
		out[39] = h->set.free_aim;
		le_put32(out + 80, h->audio_rate);
		le_put32(out + 84, h->audio_version);
		le_put64(out + 88, h->sound_hash);
	} else {
		out[44] &= (uint8_t)~REC_HAS_AUDIO;
	}
	if (snap) {
		out[44] |= REC_HAS_SNAPSHOT;
		le_put32(out + 52, snap);
		le_put64(out + 72, h->snapshot ? hash_bytes(HASH_INIT, h->snapshot, snap)
						: h->snapshot_sum);
	}
	if (size >= REC_HEADER_SIZE_V3)
		le_put64(out + 96, rec_header_sum(out));
	return size;
}

/* 1 (with the reason in err) when a byte of buf[from..to) is not 0. */
static int rec_nonzero(const uint8_t *buf, int from, int to, char *err, size_t errlen)
{
	for (int i = from; i < to; i++) {
		if (buf[i]) {
			txt_set(err, errlen, "reserved byte %d is 0x%02x, not 0", i, buf[i]);
			return 1;
		}
	}
	return 0;
}

int rec_header_decode(const uint8_t *buf, size_t len, struct rec_header *h, char *err,
		      size_t errlen)
{
	struct rec_header d;
	size_t fixed;
	uint8_t known;

	if (len < REC_HEADER_SIZE) {
		txt_set(err, errlen, "file too short (%zu bytes, the header needs %d)", len,
			REC_HEADER_SIZE);
		return -EINVAL;
	}
	if (memcmp(buf, rec_magic, sizeof(rec_magic)) != 0) {
		txt_set(err, errlen, "bad magic (not an arcaded recording)");
		return -EINVAL;
	}
	memset(&d, 0, sizeof(d));
	d.version = le_get16(buf + 8);
	d.tick_rate = le_get16(buf + 10);
	d.header_size = le_get32(buf + 12);
	d.map_hash = le_get64(buf + 16);
	d.engine_version = le_get32(buf + 24);
	d.set.coins_per_credit = buf[28];
	d.set.freeplay = buf[29];
	d.set.start_in_play = buf[30];
	d.set.difficulty = buf[31];
	d.count = le_get32(buf + 32);
	d.set.lives = buf[36];
	if (d.version == 0) {
		txt_set(err, errlen, "version 0 is not a valid version");
		return -EINVAL;
	}
	if (d.version > REC_VERSION_MAX) {
		txt_set(err, errlen, "version %u is newer than this build (%d)", d.version,
			REC_VERSION_MAX);
		return -EINVAL;
	}
	fixed = rec_fixed_size(d.version);
	if (len < fixed) {
		txt_set(err, errlen, "file too short (%zu bytes, the header needs %zu)", len, fixed);
		return -EINVAL;
	}
	if (d.header_size < fixed) {
		txt_set(err, errlen, "header size %" PRIu32 " is smaller than %zu", d.header_size,
			fixed);
		return -EINVAL;
	}
	if (d.header_size > REC_HEADER_SIZE_MAX) {
		txt_set(err, errlen, "header size %" PRIu32 " is larger than %u", d.header_size,
			REC_HEADER_SIZE_MAX);
		return -EINVAL;
	}
	if (d.tick_rate != SIM_TICRATE) {
		txt_set(err, errlen, "tick rate %u is not %d", d.tick_rate, SIM_TICRATE);
		return -EINVAL;
	}
	if (d.set.coins_per_credit < 1 || d.set.coins_per_credit > 9) {
		txt_set(err, errlen, "coins_per_credit %u out of range 1..9",
			d.set.coins_per_credit);
		return -EINVAL;
	}
	if (d.set.freeplay > 1 || d.set.start_in_play > 1) {
		txt_set(err, errlen, "freeplay %u / start_in_play %u is not 0 or 1",
			d.set.freeplay, d.set.start_in_play);
		return -EINVAL;
	}
	if (d.set.difficulty > 3) {
		txt_set(err, errlen, "difficulty %u out of range 0..3", d.set.difficulty);
		return -EINVAL;
	}
	if (d.set.lives > 9) {
		txt_set(err, errlen, "lives %u out of range 0..9", d.set.lives);
		return -EINVAL;
	}
	/* Reserved bytes are 0 as written: a flip there is damage, not a
	 * field this build may skip. */
	if (d.version < REC_VERSION_3 && rec_nonzero(buf, 37, 40, err, errlen))
		return -EINVAL;
	if (d.version >= REC_VERSION_2) {
		d.render_w = le_get16(buf + 40);
		d.render_h = le_get16(buf + 42);
		d.hash_flags = buf[44];
		d.level = buf[45];
		d.render_version = le_get32(buf + 48);
		memcpy(d.map_name, buf + 56, 8);
		d.map_name[8] = '\0';
		d.start_time = (int64_t)le_get64(buf + 64);
		known = REC_HAS_STATE | REC_HAS_FRAME | REC_HAS_SNAPSHOT;
		if (d.version >= REC_VERSION_3)
			known |= REC_HAS_AUDIO;
		if (d.hash_flags & ~known) {
			txt_set(err, errlen, "hash flags 0x%02x unknown", d.hash_flags);
			return -EINVAL;
		}
		/* 46..47: the sound settings from version 3 on */
		if (d.version < REC_VERSION_3 && rec_nonzero(buf, 46, 48, err, errlen))
			return -EINVAL;
		if (!(d.hash_flags & REC_HAS_SNAPSHOT) &&
		    (rec_nonzero(buf, 52, 56, err, errlen) || rec_nonzero(buf, 72, 80, err, errlen)))
			return -EINVAL;
		/* start time: 0 (unknown) or a time_t that fits 32 bits (until
		 * 2106); the high bytes are checked, the low ones cannot be */
		if ((uint64_t)d.start_time > UINT32_MAX) {
			txt_set(err, errlen, "start time %" PRIu64 " out of range",
				(uint64_t)d.start_time);
			return -EINVAL;
		}
		if (d.hash_flags & REC_HAS_SNAPSHOT) {
			d.snapshot_len = le_get32(buf + 52);
			d.snapshot_sum = le_get64(buf + 72);
			if (d.snapshot_len == 0) {
				txt_set(err, errlen, "snapshot of 0 bytes");
				return -EINVAL;
			}
			if (d.snapshot_len > d.header_size - fixed) {
				txt_set(err, errlen,
					"snapshot of %" PRIu32 " bytes does not fit in header size %" PRIu32,
					d.snapshot_len, d.header_size);
				return -EINVAL;
			}
		}
		if (d.render_w > REC_RENDER_MAX || d.render_h > REC_RENDER_MAX ||
		    (d.render_w == 0) != (d.render_h == 0)) {
			txt_set(err, errlen, "render size %ux%u out of range", d.render_w,
				d.render_h);
			return -EINVAL;
		}
		for (int i = 0; i < 8; i++) {
			unsigned char ch = (unsigned char)d.map_name[i];
			if (ch != 0 && (ch < 0x21 || ch > 0x7e)) {
				txt_set(err, errlen, "map name is not printable ASCII");
				return -EINVAL;
			}
			/* NUL-padded: nothing after the first NUL */
			if (ch != 0 && i > 0 && d.map_name[i - 1] == 0) {
				txt_set(err, errlen, "map name padding is not all NUL");
				return -EINVAL;
			}
		}
	}
	if (d.version >= REC_VERSION_3) {
		uint64_t sum = rec_header_sum(buf), stored = le_get64(buf + 96);

		if (sum != stored) {
			txt_set(err, errlen,
				"header damaged (sum 0x%016" PRIx64 ", the header says 0x%016" PRIx64 ")",
				sum, stored);
			return -EINVAL;
		}
		d.set.volume = buf[46];
		d.set.attract_sound = buf[47];
		d.set.stage_time = buf[37];
		d.set.idle_out = buf[38];
		d.set.free_aim = buf[39];
		d.audio_rate = le_get32(buf + 80);
		d.audio_version = le_get32(buf + 84);
		d.sound_hash = le_get64(buf + 88);
		if (d.set.volume > 100) {
			txt_set(err, errlen, "volume %u out of range 0..100", d.set.volume);
			return -EINVAL;
		}
		if (d.set.attract_sound > 9) {
			txt_set(err, errlen, "attract_sound %u out of range 0..9",
				d.set.attract_sound);
			return -EINVAL;
		}
		if (d.set.stage_time > G_STAGE_TIME_MAX && d.set.stage_time != G_STAGE_TIME_OFF) {
			txt_set(err, errlen, "stage_time %u out of range 0..%d or %d (off)",
				d.set.stage_time, G_STAGE_TIME_MAX, G_STAGE_TIME_OFF);
			return -EINVAL;
		}
		if (d.set.idle_out >= G_IDLE_COUNT) {
			txt_set(err, errlen, "idle_out %u out of range 0..%d", d.set.idle_out,
				G_IDLE_COUNT - 1);
			return -EINVAL;
		}
		if (d.set.free_aim > 1) {
			txt_set(err, errlen, "free_aim %u out of range 0..1", d.set.free_aim);
			return -EINVAL;
		}
		if ((d.hash_flags & REC_HAS_AUDIO) &&
		    (d.audio_rate < REC_AUDIO_RATE_MIN || d.audio_rate > REC_AUDIO_RATE_MAX)) {
			txt_set(err, errlen, "audio rate %" PRIu32 " out of range %d..%d",
				d.audio_rate, REC_AUDIO_RATE_MIN, REC_AUDIO_RATE_MAX);
			return -EINVAL;
		}
	}
	*h = d;
	return 0;
}

void rec_cmd_encode(uint8_t out[REC_CMD_SIZE], const struct sim_cmd *c)
{
	/* Two's complement by conversion to the unsigned type: defined in C. */
	out[0] = (uint8_t)c->forward;
	out[1] = (uint8_t)c->side;
	le_put16(out + 2, (uint16_t)c->turn);
	out[4] = c->buttons;
	out[5] = c->coins;
}

/* The unsigned-to-signed conversion is done by arithmetic, so it does not
 * rest on implementation-defined behaviour. */
static int8_t rec_s8(uint8_t v)
{
	return (int8_t)(v < 128 ? (int)v : (int)v - 256);
}

void rec_cmd_decode(const uint8_t in[REC_CMD_SIZE], struct sim_cmd *c)
{
	c->forward = rec_s8(in[0]);
	c->side = rec_s8(in[1]);
	c->turn = le_s16(in + 2);
	c->buttons = in[4];
	c->coins = in[5];
}

/* Reads up to n bytes, fewer only at end of file. Returns the count or -errno. */
static ssize_t rec_read_all(int fd, uint8_t *p, size_t n)
{
	size_t got = 0;

	while (got < n) {
		ssize_t r = read(fd, p + got, n - got);

		if (r < 0) {
			if (errno == EINTR)
				continue;
			return -errno;
		}
		if (r == 0)
			break;
		got += (size_t)r;
	}
	return (ssize_t)got;
}

struct rec_writer {
	int fd;
	int err;                 /* first failure, returned from then on */
	uint32_t count;
	uint8_t flags;           /* hash flags of the header */
	size_t recsize;
	size_t n;                /* bytes pending in buf */
	uint8_t buf[REC_BUF];
};

int rec_writer_open(const char *path, const struct rec_header *h, struct rec_writer **out)
{
	uint8_t hdr[REC_HEADER_MAX];
	struct rec_header hh = *h, back;
	struct rec_writer *w;
	size_t size;
	int ret;

	if (hh.version < REC_VERSION_2)
		hh.hash_flags = 0;
	if (hh.snapshot_len && (hh.version < REC_VERSION_2 || !hh.snapshot))
		return -EINVAL;
	hh.count = REC_COUNT_UNKNOWN;
	size = rec_header_encode(hdr, &hh);
	/* Never write what the reader would refuse. */
	if (rec_header_decode(hdr, size, &back, NULL, 0) < 0)
		return -EINVAL;
	w = calloc(1, sizeof(*w));
	if (!w)
		return -ENOMEM;
	w->flags = back.hash_flags & (REC_HAS_STATE | REC_HAS_FRAME | REC_HAS_AUDIO);
	w->recsize = rec_record_size(back.hash_flags);
	w->fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
	if (w->fd < 0) {
		ret = -errno;
		goto fail_free;
	}
	ret = io_write_all(w->fd, hdr, size);
	if (ret == 0 && hh.snapshot_len)
		ret = io_write_all(w->fd, hh.snapshot, hh.snapshot_len);
	if (ret < 0)
		goto fail_close;
	*out = w;
	return 0;
fail_close:
	close(w->fd);
fail_free:
	free(w);
	return ret;
}

int rec_writer_flush(struct rec_writer *w)
{
	if (w->err)
		return w->err;
	w->err = io_write_all(w->fd, w->buf, w->n);
	w->n = 0;
	return w->err;
}

int rec_writer_put_tick(struct rec_writer *w, const struct rec_tick *t)
{
	uint8_t *p;

	if (w->err)
		return w->err;
	/* The count must never reach the "unknown" marker. */
	if (w->count >= REC_COUNT_UNKNOWN - 1)
		return -EFBIG;
	if (w->n + w->recsize > sizeof(w->buf) && rec_writer_flush(w) < 0)
		return w->err;
	p = w->buf + w->n;
	rec_cmd_encode(p, &t->cmd);
	p += REC_CMD_SIZE;
	if (w->flags & REC_HAS_STATE) {
		le_put64(p, t->state_hash);
		p += 8;
	}
	if (w->flags & REC_HAS_FRAME) {
		le_put64(p, t->frame_hash);
		p += 8;
	}
	if (w->flags & REC_HAS_AUDIO)
		le_put64(p, t->audio_hash);
	w->n += w->recsize;
	w->count++;
	return 0;
}

int rec_writer_put(struct rec_writer *w, const struct sim_cmd *c)
{
	struct rec_tick t = { .cmd = *c };

	if (w->flags)
		return -EINVAL;
	return rec_writer_put_tick(w, &t);
}

int rec_writer_close(struct rec_writer *w)
{
	uint8_t cnt[4];
	int ret;

	if (!w)
		return 0;
	ret = rec_writer_flush(w);
	if (ret == 0) {
		ssize_t pw;

		le_put32(cnt, w->count);
		pw = pwrite(w->fd, cnt, sizeof(cnt), 32);
		if (pw < 0)
			ret = -errno;
		else if (pw != (ssize_t)sizeof(cnt))
			ret = -EIO;
	}
	if (ret == 0 && fsync(w->fd) < 0)
		ret = -errno;
	if (close(w->fd) < 0 && ret == 0 && errno != EINTR)
		ret = -errno;
	free(w);
	return ret;
}

struct rec_reader {
	int fd;
	struct rec_header h;
	uint8_t *snap;           /* the snapshot (h.snapshot), owned */
	size_t recsize;
	uint32_t total;          /* records next returns in all */
	uint32_t pos;            /* records returned so far */
	bool damaged;            /* finished, yet not the length its count says */
	size_t bn, bi;           /* bytes in buf, next byte */
	uint8_t buf[REC_BUF];
};

/* Reads and checks the snapshot of r's header from the file of size
 * `size`; 0 or -errno / -EINVAL with the reason in err. */
static int rec_read_snapshot(struct rec_reader *r, const char *path, uint64_t size, char *err,
			     size_t errlen)
{
	uint32_t len = r->h.snapshot_len;
	uint64_t sum;
	ssize_t got;

	uint64_t at = rec_fixed_size(r->h.version);

	if (size < at + (uint64_t)len) {
		txt_set(err, errlen, "%s: snapshot cut short (%" PRIu64 " of %" PRIu32 " bytes)",
			path, size > at ? size - at : 0, len);
		return -EINVAL;
	}
	r->snap = malloc(len);
	if (!r->snap) {
		txt_set(err, errlen, "%s: out of memory", path);
		return -ENOMEM;
	}
	if (lseek(r->fd, (off_t)at, SEEK_SET) < 0) {
		int e = errno;

		txt_set(err, errlen, "%s: %s", path, strerror(e));
		return -e;
	}
	got = rec_read_all(r->fd, r->snap, len);
	if (got < 0) {
		txt_set(err, errlen, "%s: %s", path, strerror((int)-got));
		return (int)got;
	}
	if ((size_t)got < len) {
		txt_set(err, errlen, "%s: snapshot cut short (%zd of %" PRIu32 " bytes)", path, got,
			len);
		return -EINVAL;
	}
	sum = hash_bytes(HASH_INIT, r->snap, len);
	if (sum != r->h.snapshot_sum) {
		txt_set(err, errlen,
			"%s: snapshot damaged (checksum 0x%016" PRIx64 ", the header says 0x%016" PRIx64
			")", path, sum, r->h.snapshot_sum);
		return -EINVAL;
	}
	r->h.snapshot = r->snap;
	return 0;
}

int rec_reader_open(const char *path, struct rec_reader **out, char *err, size_t errlen)
{
	uint8_t hdr[REC_HEADER_MAX];
	char why[160];
	struct rec_reader *r;
	struct stat sb;
	uint64_t whole;
	ssize_t got;
	int ret;

	r = calloc(1, sizeof(*r));
	if (!r) {
		txt_set(err, errlen, "%s: out of memory", path);
		return -ENOMEM;
	}
	r->fd = open(path, O_RDONLY | O_CLOEXEC);
	if (r->fd < 0) {
		ret = -errno;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto fail_free;
	}
	if (fstat(r->fd, &sb) < 0) {
		ret = -errno;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto fail_close;
	}
	got = rec_read_all(r->fd, hdr, sizeof(hdr));
	if (got < 0) {
		ret = (int)got;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto fail_close;
	}
	ret = rec_header_decode(hdr, (size_t)got, &r->h, why, sizeof(why));
	if (ret < 0) {
		txt_set(err, errlen, "%s: %s", path, why);
		goto fail_close;
	}
	if (r->h.snapshot_len) {
		ret = rec_read_snapshot(r, path, (uint64_t)sb.st_size, err, errlen);
		if (ret < 0)
			goto fail_close;
	}
	if ((uint64_t)sb.st_size < r->h.header_size) {
		ret = -EINVAL;
		txt_set(err, errlen, "%s: file too short (%jd bytes, the header says %" PRIu32 ")",
			path, (intmax_t)sb.st_size, r->h.header_size);
		goto fail_close;
	}
	if (lseek(r->fd, r->h.header_size, SEEK_SET) < 0) {
		ret = -errno;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto fail_close;
	}
	r->recsize = rec_record_size(r->h.hash_flags);
	whole = ((uint64_t)sb.st_size - r->h.header_size) / r->recsize;
	if (r->h.count == REC_COUNT_UNKNOWN) {
		/* Cut short while recording: everything whole replays. */
		r->total = whole < REC_COUNT_UNKNOWN ? (uint32_t)whole : REC_COUNT_UNKNOWN - 1;
	} else if (whole < r->h.count) {
		r->total = (uint32_t)whole;
		r->damaged = true;
	} else {
		/* finished: exactly the counted records (rec_repair truncates
		 * a cut recording to whole records); more bytes mean the count
		 * or the file was damaged */
		r->total = r->h.count;
		r->damaged = (uint64_t)sb.st_size !=
			     r->h.header_size + (uint64_t)r->h.count * r->recsize;
	}
	*out = r;
	return 0;
fail_close:
	close(r->fd);
	free(r->snap);
fail_free:
	free(r);
	return ret;
}

const struct rec_header *rec_reader_header(const struct rec_reader *r)
{
	return &r->h;
}

uint32_t rec_reader_count(const struct rec_reader *r)
{
	return r->total;
}

int rec_reader_next_tick(struct rec_reader *r, struct rec_tick *t)
{
	const uint8_t *p;

	if (r->pos == r->total)
		return r->damaged ? -EIO : 0;
	if (r->bn - r->bi < r->recsize) {
		/* Refill, keeping a partial command's bytes at the front. */
		size_t keep = r->bn - r->bi;
		ssize_t got;

		memmove(r->buf, r->buf + r->bi, keep);
		r->bn = keep;
		r->bi = 0;
		got = rec_read_all(r->fd, r->buf + keep, sizeof(r->buf) - keep);
		if (got < 0)
			return (int)got;
		r->bn += (size_t)got;
		/* The file shrank since open. */
		if (r->bn < r->recsize)
			return -EIO;
	}
	p = r->buf + r->bi;
	rec_cmd_decode(p, &t->cmd);
	p += REC_CMD_SIZE;
	t->state_hash = 0;
	t->frame_hash = 0;
	t->audio_hash = 0;
	if (r->h.hash_flags & REC_HAS_STATE) {
		t->state_hash = le_get64(p);
		p += 8;
	}
	if (r->h.hash_flags & REC_HAS_FRAME) {
		t->frame_hash = le_get64(p);
		p += 8;
	}
	if (r->h.hash_flags & REC_HAS_AUDIO)
		t->audio_hash = le_get64(p);
	r->bi += r->recsize;
	r->pos++;
	return 1;
}

int rec_reader_next(struct rec_reader *r, struct sim_cmd *c)
{
	struct rec_tick t;
	int ret = rec_reader_next_tick(r, &t);

	if (ret > 0)
		*c = t.cmd;
	return ret;
}

void rec_reader_close(struct rec_reader *r)
{
	if (!r)
		return;
	close(r->fd);
	free(r->snap);
	free(r);
}

int rec_repair(const char *path, uint32_t *count, char *err, size_t errlen)
{
	uint8_t hdr[REC_HEADER_MAX], cnt[4];
	struct rec_header h;
	struct stat sb;
	uint64_t whole;
	ssize_t got;
	int fd, ret;

	fd = open(path, O_RDWR | O_CLOEXEC | O_NOFOLLOW);
	if (fd < 0) {
		ret = -errno;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		return ret;
	}
	if (fstat(fd, &sb) < 0) {
		ret = -errno;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto out;
	}
	got = rec_read_all(fd, hdr, sizeof(hdr));
	if (got < 0) {
		ret = (int)got;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto out;
	}
	ret = rec_header_decode(hdr, (size_t)got, &h, err, errlen);
	if (ret < 0)
		goto out;
	if ((uint64_t)sb.st_size < h.header_size) {
		ret = -EINVAL;
		txt_set(err, errlen, "file too short for its header");
		goto out;
	}
	if (h.count != REC_COUNT_UNKNOWN) {
		*count = h.count;
		goto out;
	}
	whole = ((uint64_t)sb.st_size - h.header_size) / rec_record_size(h.hash_flags);
	if (whole > REC_COUNT_UNKNOWN - 1)
		whole = REC_COUNT_UNKNOWN - 1;
	if (ftruncate(fd, (off_t)(h.header_size + whole * rec_record_size(h.hash_flags))) < 0) {
		ret = -errno;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto out;
	}
	le_put32(cnt, (uint32_t)whole);
	errno = 0;
	if (pwrite(fd, cnt, sizeof(cnt), 32) != (ssize_t)sizeof(cnt) || fsync(fd) < 0) {
		ret = errno ? -errno : -EIO;
		txt_set(err, errlen, "%s: %s", path, strerror(-ret));
		goto out;
	}
	*count = (uint32_t)whole;
out:
	close(fd);
	return ret;
}
