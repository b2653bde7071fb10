/*
 * vm_host: the host-side helper of the VM tests (tests/vm/run.sh).
 *
 *   vm_host qmp SOCKET JSON      send one QMP command (after the
 *                                capabilities handshake), print its reply;
 *                                exit 1 if the reply is an error
 *   vm_host shot SOCKET FILE     QMP screendump of the guest's screen to
 *                                FILE (PPM); returns once QEMU wrote it
 *   vm_host match REF.png DUMP.ppm BPP
 *                                does the screen show the daemon's frame?
 *                                REF is the frame the daemon rendered
 *                                headless (--screenshot). The expected screen
 *                                is REF scaled the way display/px.c does with
 *                                display.scale = integer: the largest whole
 *                                factor k with k*w <= W and k*h <= H, centred
 *                                (an odd spare pixel right/bottom), every
 *                                other pixel black. BPP 32: colours must be
 *                                exact; BPP 16: each channel quantized to
 *                                RGB565 as px.c does ((c * max + 127) / 255)
 *                                must equal the screen channel's top bits.
 *                                Prints the mismatch count; exit 0 on none
 *   vm_host differ A.ppm B.ppm [N]
 *                                print how many pixels differ; exit 0 if
 *                                any do, 1 if the images are identical;
 *                                with N, only the bottom 1/N of the rows
 *                                (the HUD's status line, away from
 *                                decorations that turn by themselves)
 *   vm_host picture DUMP.ppm W H a frame of WxH is on screen: outside the
 *                                integer-scaled picture area everything is
 *                                black and inside it at least 8 colours
 *                                show; prints the counts
 *   vm_host text DUMP.ppm        the screen shows console text, not a
 *                                picture: some pixels are lit, fewer than
 *                                a tenth of them; prints the count
 *   vm_host topng DUMP.ppm OUT.png
 *                                convert a screendump to PNG to look at
 */
#include <errno.h>
#include <poll.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <time.h>
#include <unistd.h>

struct img {
	int w, h;
	uint8_t *rgb; /* w * h * 3 */
};

static int usage(void)
{
	fputs("usage: vm_host qmp SOCKET JSON | shot SOCKET FILE | match REF.png DUMP.ppm BPP |\n"
	      "       differ A.ppm B.ppm [N] | picture DUMP.ppm W H | text DUMP.ppm |\n"
	      "       topng DUMP.ppm OUT.png\n",
	      stderr);
	return 2;
}

/* ---- QMP ------------------------------------------------------------- */

/* Reads one JSON message (QMP sends one per line) into buf; 0 or -1. */
static int qmp_line(int fd, char *buf, size_t len)
{
	size_t n = 0;

	while (n + 1 < len) {
		struct pollfd p = { .fd = fd, .events = POLLIN };
		ssize_t r;

		if (poll(&p, 1, 60000) <= 0)
			return -1;
		r = read(fd, buf + n, 1);
		if (r <= 0)
			return -1;
		if (buf[n] == '\n') {
			buf[n] = '\0';
			return 0;
		}
		n++;
	}
	return -1;
}

/* Reads messages until a reply (return or error), skipping events. */
static int qmp_reply(int fd, char *buf, size_t len)
{
	for (;;) {
		if (qmp_line(fd, buf, len) < 0)
			return -1;
		if (strstr(buf, "\"return\"") || strstr(buf, "\"error\""))
			return strstr(buf, "\"error\"") && !strstr(buf, "\"return\"") ? 1 : 0;
	}
}

static int qmp(const char *sock, const char *cmd, char *reply, size_t len)
{
	static const char caps[] = "{\"execute\":\"qmp_capabilities\"}\n";
	struct sockaddr_un sa;
	int fd, rc;

	memset(&sa, 0, sizeof(sa));
	sa.sun_family = AF_UNIX;
	if (strlen(sock) >= sizeof(sa.sun_path)) {
		fprintf(stderr, "vm_host: socket path too long: %s\n", sock);
		return -1;
	}
	strcpy(sa.sun_path, sock);
	fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
	if (fd < 0 || connect(fd, (struct sockaddr *)&sa, sizeof(sa)) < 0) {
		fprintf(stderr, "vm_host: %s: %s\n", sock, strerror(errno));
		if (fd >= 0)
			close(fd);
		return -1;
	}
	/* greeting, capabilities, then the command */
	rc = qmp_line(fd, reply, len);
	if (rc == 0 && write(fd, caps, sizeof(caps) - 1) != (ssize_t)(sizeof(caps) - 1))
		rc = -1;
	if (rc == 0)
		rc = qmp_reply(fd, reply, len);
	if (rc == 0 && (write(fd, cmd, strlen(cmd)) != (ssize_t)strlen(cmd) || write(fd, "\n", 1) != 1))
		rc = -1;
	if (rc == 0)
		rc = qmp_reply(fd, reply, len);
	close(fd);
	if (rc < 0)
		fprintf(stderr, "vm_host: %s: no reply\n", sock);
	return rc;
}

static int cmd_qmp(const char *sock, const char *json)
{
	char reply[8192];
	int rc = qmp(sock, json, reply, sizeof(reply));

	if (rc >= 0)
		puts(reply);
	return rc == 0 ? 0 : 1;
}

static int cmd_shot(const char *sock, const char *file)
{
	char cmd[4096 + 64], reply[8192];
	int rc;

	if (strchr(file, '"') || strchr(file, '\\') || strlen(file) > 4096)
		return usage();
	snprintf(cmd, sizeof(cmd), "{\"execute\":\"screendump\",\"arguments\":{\"filename\":\"%s\"}}",
		 file);
	rc = qmp(sock, cmd, reply, sizeof(reply));
	if (rc > 0)
		fprintf(stderr, "vm_host: screendump: %s\n", reply);
	return rc == 0 ? 0 : 1;
}

/* ---- images ---------------------------------------------------------- */

/* Skips blanks and # comments of a PPM header; reads one number. */
static int ppm_num(FILE *f, int *v)
{
	int c;

	for (;;) {
		c = fgetc(f);
		if (c == '#')
			while (c != '\n' && c != EOF)
				c = fgetc(f);
		else if (c != ' ' && c != '\t' && c != '\n' && c != '\r')
			break;
	}
	if (c < '0' || c > '9')
		return -1;
	*v = 0;
	while (c >= '0' && c <= '9') {
		if (*v > 100000)
			return -1;
		*v = *v * 10 + (c - '0');
		c = fgetc(f);
	}
	return 0; /* the one blank after the number is consumed */
}

static int ppm_read(const char *path, struct img *im)
{
	FILE *f = fopen(path, "rbe");
	int maxv;
	size_t n;

	if (!f) {
		fprintf(stderr, "vm_host: %s: %s\n", path, strerror(errno));
		return -1;
	}
	if (fgetc(f) != 'P' || fgetc(f) != '6' || ppm_num(f, &im->w) < 0 || ppm_num(f, &im->h) < 0 ||
	    ppm_num(f, &maxv) < 0 || maxv != 255 || im->w <= 0 || im->h <= 0) {
		fprintf(stderr, "vm_host: %s: not an 8-bit P6 PPM\n", path);
		fclose(f);
		return -1;
	}
	n = (size_t)im->w * (size_t)im->h * 3;
	im->rgb = malloc(n);
	if (!im->rgb || fread(im->rgb, 1, n, f) != n) {
		fprintf(stderr, "vm_host: %s: short file\n", path);
		free(im->rgb);
		fclose(f);
		return -1;
	}
	fclose(f);
	return 0;
}

static int png_read(const char *path, struct img *im)
{
	png_image p;

	memset(&p, 0, sizeof(p));
	p.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&p, path)) {
		fprintf(stderr, "vm_host: %s: %s\n", path, p.message);
		return -1;
	}
	p.format = PNG_FORMAT_RGB;
	im->w = (int)p.width;
	im->h = (int)p.height;
	im->rgb = malloc(PNG_IMAGE_SIZE(p));
	if (!im->rgb || !png_image_finish_read(&p, NULL, im->rgb, 0, NULL)) {
		fprintf(stderr, "vm_host: %s: %s\n", path, p.message);
		free(im->rgb);
		png_image_free(&p);
		return -1;
	}
	return 0;
}

static int cmd_topng(const char *in, const char *out)
{
	struct img im;
	png_image p;
	int ok;

	if (ppm_read(in, &im) < 0)
		return 1;
	memset(&p, 0, sizeof(p));
	p.version = PNG_IMAGE_VERSION;
	p.width = (png_uint_32)im.w;
	p.height = (png_uint_32)im.h;
	p.format = PNG_FORMAT_RGB;
	ok = png_image_write_to_file(&p, out, 0, im.rgb, 0, NULL);
	if (!ok)
		fprintf(stderr, "vm_host: %s: %s\n", out, p.message);
	free(im.rgb);
	return ok ? 0 : 1;
}

/* The integer-scale layout of a w x h frame on a W x H panel (px.c). */
struct layout {
	int k, x0, y0;
};

static int layout(int W, int H, int w, int h, struct layout *l)
{
	l->k = W / w < H / h ? W / w : H / h;
	if (l->k < 1)
		return -1;
	l->x0 = (W - l->k * w) / 2;
	l->y0 = (H - l->k * h) / 2;
	return 0;
}

static int inside(const struct layout *l, int w, int h, int x, int y)
{
	return x >= l->x0 && x < l->x0 + l->k * w && y >= l->y0 && y < l->y0 + l->k * h;
}

/* A palette channel as the panel stores it, in `len` bits (px.c's rule). */
static unsigned quant(unsigned c, int len)
{
	unsigned max = (1u << len) - 1;

	return (c * max + 127) / 255;
}

static int cmd_match(const char *refp, const char *dumpp, int bpp)
{
	static const int len16[3] = { 5, 6, 5 };
	struct img ref, d;
	struct layout l;
	long bad = 0, bad_in = 0;
	int first_x = -1, first_y = -1;

	if (bpp != 16 && bpp != 32)
		return usage();
	if (png_read(refp, &ref) < 0)
		return 1;
	if (ppm_read(dumpp, &d) < 0) {
		free(ref.rgb);
		return 1;
	}
	if (layout(d.w, d.h, ref.w, ref.h, &l) < 0) {
		fprintf(stderr, "vm_host: %dx%d frame does not fit a %dx%d screen\n", ref.w, ref.h,
			d.w, d.h);
		free(ref.rgb);
		free(d.rgb);
		return 1;
	}
	for (int y = 0; y < d.h; y++) {
		for (int x = 0; x < d.w; x++) {
			const uint8_t *s = d.rgb + ((size_t)y * (size_t)d.w + (size_t)x) * 3;
			uint8_t want[3] = { 0, 0, 0 };
			int in = inside(&l, ref.w, ref.h, x, y), diff = 0;

			if (in) {
				size_t sx = (size_t)((x - l.x0) / l.k), sy = (size_t)((y - l.y0) / l.k);
				memcpy(want, ref.rgb + (sy * (size_t)ref.w + sx) * 3, 3);
			}
			for (int c = 0; c < 3; c++) {
				if (bpp == 32)
					diff |= s[c] != want[c];
				else
					diff |= (unsigned)(s[c] >> (8 - len16[c])) !=
						quant(want[c], len16[c]);
			}
			if (diff) {
				if (bad++ == 0) {
					first_x = x;
					first_y = y;
				}
				bad_in += in;
			}
		}
	}
	printf("screen %dx%d, frame %dx%d at scale %d offset %d,%d, %d bpp: %ld of %ld pixels differ"
	       " (%ld inside the picture)",
	       d.w, d.h, ref.w, ref.h, l.k, l.x0, l.y0, bpp, bad, (long)d.w * d.h, bad_in);
	if (bad) {
		const uint8_t *s = d.rgb + ((size_t)first_y * (size_t)d.w + (size_t)first_x) * 3;
		printf(", first at %d,%d: screen %u,%u,%u", first_x, first_y, s[0], s[1], s[2]);
	}
	putchar('\n');
	free(ref.rgb);
	free(d.rgb);
	return bad ? 1 : 0;
}

static int cmd_differ(const char *ap, const char *bp, int part)
{
	struct img a, b;
	long n = 0;

	if (ppm_read(ap, &a) < 0)
		return 2;
	if (ppm_read(bp, &b) < 0) {
		free(a.rgb);
		return 2;
	}
	if (a.w != b.w || a.h != b.h) {
		printf("sizes differ: %dx%d and %dx%d\n", a.w, a.h, b.w, b.h);
		n = 1;
	} else {
		int y0 = part > 0 ? a.h - a.h / part : 0;
		for (size_t i = (size_t)y0 * (size_t)a.w; i < (size_t)a.w * (size_t)a.h; i++)
			n += memcmp(a.rgb + i * 3, b.rgb + i * 3, 3) != 0;
		printf("%ld of %ld pixels differ%s\n", n, (long)a.w * (a.h - y0),
		       part > 0 ? " (the bottom rows)" : "");
	}
	free(a.rgb);
	free(b.rgb);
	return n ? 0 : 1;
}

static int cmd_picture(const char *dumpp, int w, int h)
{
	struct img d;
	struct layout l;
	long outside_lit = 0;
	uint32_t seen[8];
	int colours = 0;

	if (w <= 0 || h <= 0)
		return usage();
	if (ppm_read(dumpp, &d) < 0)
		return 1;
	if (layout(d.w, d.h, w, h, &l) < 0) {
		free(d.rgb);
		return 1;
	}
	for (int y = 0; y < d.h; y++) {
		for (int x = 0; x < d.w; x++) {
			const uint8_t *s = d.rgb + ((size_t)y * (size_t)d.w + (size_t)x) * 3;
			uint32_t v = (uint32_t)s[0] << 16 | (uint32_t)s[1] << 8 | s[2];
			int known = 0;

			if (!inside(&l, w, h, x, y)) {
				outside_lit += v != 0;
				continue;
			}
			for (int i = 0; i < colours; i++)
				known |= seen[i] == v;
			if (!known && colours < 8)
				seen[colours++] = v;
		}
	}
	printf("screen %dx%d: %ld lit pixels outside the %dx%d picture at scale %d, "
	       "%s8 colours inside\n",
	       d.w, d.h, outside_lit, l.k * w, l.k * h, l.k, colours >= 8 ? ">= " : "< ");
	free(d.rgb);
	return outside_lit == 0 && colours >= 8 ? 0 : 1;
}

static int cmd_text(const char *dumpp)
{
	struct img d;
	long lit = 0, all;

	if (ppm_read(dumpp, &d) < 0)
		return 1;
	all = (long)d.w * d.h;
	for (long i = 0; i < all; i++)
		lit += d.rgb[i * 3] || d.rgb[i * 3 + 1] || d.rgb[i * 3 + 2];
	printf("screen %dx%d: %ld of %ld pixels lit\n", d.w, d.h, lit, all);
	free(d.rgb);
	return lit > 0 && lit < all / 10 ? 0 : 1;
}

int main(int argc, char **argv)
{
	if (argc == 4 && strcmp(argv[1], "qmp") == 0)
		return cmd_qmp(argv[2], argv[3]);
	if (argc == 4 && strcmp(argv[1], "shot") == 0)
		return cmd_shot(argv[2], argv[3]);
	if (argc == 5 && strcmp(argv[1], "match") == 0)
		return cmd_match(argv[2], argv[3], atoi(argv[4]));
	if (argc == 4 && strcmp(argv[1], "differ") == 0)
		return cmd_differ(argv[2], argv[3], 0);
	if (argc == 5 && strcmp(argv[1], "differ") == 0 && atoi(argv[4]) > 0)
		return cmd_differ(argv[2], argv[3], atoi(argv[4]));
	if (argc == 5 && strcmp(argv[1], "picture") == 0)
		return cmd_picture(argv[2], atoi(argv[3]), atoi(argv[4]));
	if (argc == 3 && strcmp(argv[1], "text") == 0)
		return cmd_text(argv[2]);
	if (argc == 4 && strcmp(argv[1], "topng") == 0)
		return cmd_topng(argv[2], argv[3]);
	return usage();
}
