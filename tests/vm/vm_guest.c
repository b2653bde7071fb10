/*
 * vm_guest: the guest-side helper of the VM tests (tests/vm/guest.sh runs
 * it inside the VM; it is built on the host, whose root the VM boots).
 *
 *   vm_guest kbd FIFO       create a uinput keyboard ("arcaded-vm keyboard",
 *                           every key code 1..255), then read commands from
 *                           FIFO, one per line, until end of file:
 *                             tap KEY MS    press, hold MS ms, release
 *                             down KEY      press and hold
 *                             up KEY        release
 *                           KEY is a libevdev name (KEY_5) or a number.
 *                           Prints "ready /dev/input/eventN" once created.
 *   vm_guest kdmode TTY     print the console's display and keyboard mode:
 *                           "kd text|graphics kb raw|xlate|mediumraw|unicode|off"
 *   vm_guest chvt N SECONDS switch to virtual terminal N (VT_ACTIVATE on
 *                           /dev/tty0) and wait until it is shown: a
 *                           process holding the current one in VT_PROCESS
 *                           mode must let go first. Prints "from A to N
 *                           after S s"; exit 1 if N is not shown in time
 *   vm_guest open PATH r|w|rw
 *                           open PATH; print "ok" or the errno name; exit 0
 *                           if it opened, 1 if not
 *   vm_guest probe CGROUP USER PATH:MODE:WANT...
 *                           move into the cgroup (its directory under
 *                           /sys/fs/cgroup), become USER (name; "root"
 *                           stays root) with USER's group and no others,
 *                           then open each PATH (MODE r|w|rw); WANT is
 *                           "ok" or the errno name expected. Prints one
 *                           line per path; exit 0 if every WANT was met
 *   vm_guest waitfd PID PATH SECONDS
 *                           wait until process PID has PATH open; prints
 *                           how long it took; exit 1 on timeout
 *   vm_guest waitdev PID NAME SECONDS
 *                           wait until an input device whose name contains
 *                           NAME exists and process PID has its event node
 *                           open; prints the node and how long it took;
 *                           exit 1 on timeout
 *   vm_guest hidwrite PATH HEX
 *                           write the bytes HEX (pairs of hex digits, blanks
 *                           allowed) to PATH in one write(): a report to a
 *                           gadget's /dev/hidgN, a descriptor to configfs
 *   vm_guest hidtap PATH DOWN UP MS
 *                           hidsend DOWN, MS milliseconds, hidsend UP (5 s
 *                           each): a button tap in one process
 *   vm_guest hidsend PATH HEX SECONDS
 *                           write the bytes HEX to a gadget's /dev/hidgN in
 *                           one write(), waiting up to SECONDS for the
 *                           gadget to take it (a report is taken once the
 *                           host polls: only while the host has the device
 *                           open); exit 1 on timeout, with nothing written
 *   vm_guest replug PID CLASS GADGET UDC HIDG N HOLD_MS IDLE HELD
 *                           N unplug/replug cycles of configfs gadget
 *                           directory GADGET on UDC (dummy_udc.K), whose
 *                           device must be open in process PID at the
 *                           start: the node is the first of sysfs class
 *                           CLASS (hidraw, or input for its eventN) whose
 *                           device lies under dummy_hcd.K. Each cycle
 *                           sends reports IDLE then HELD (hex) through
 *                           HIDG, waits HOLD_MS, unbinds the UDC, waits
 *                           until PID has closed the node and the node is
 *                           gone, binds the UDC
 *                           again and waits until PID has the new node
 *                           open. One line per cycle: "plug I closed S
 *                           node S udev S open S": unbind to closed, bind
 *                           to node, node to its ctime (when udev last
 *                           changed it), node to opened, in seconds (the
 *                           waits poll every 2 ms). Exit 1 at the first
 *                           cycle that times out, saying where
 *   vm_guest waitnofd PID PATH SECONDS
 *                           wait until process PID no longer has PATH open;
 *                           prints how long it took; exit 1 on timeout
 *   vm_guest pulls DIR STEP...
 *                           drive a gpio-sim line from outside: each STEP
 *                           is "d" (write pull-down to DIR/pull: the line
 *                           reads 0) or "u" (pull-up: 1), optionally
 *                           ":MS" to stay so for MS milliseconds (busy
 *                           waiting on the clock after a sleep, so the
 *                           time is close). Prints the time the steps
 *                           took: "steps N total MS ms", for each step
 *                           with a hold, "hold K MS ms" (measured), and
 *                           last "apart MS ms": the longest time between
 *                           two writes with no hold between them (how far
 *                           apart a bounce's edges really were)
 *   vm_guest meter FILE SECONDS OUT
 *                           poll FILE (a gpio-sim line's value, "0"/"1")
 *                           every millisecond for SECONDS and write to OUT
 *                           "rises N polls P maxgap MS ms" and one line
 *                           "pulse MS ms" per high period seen (measured
 *                           from the first poll that read 1 to the first
 *                           that read 0); "ready" is written to OUT.ready
 *                           once polling started
 *   vm_guest books FILE     check a bookkeeping state file written by the
 *                           daemon (docs/persistence.md): magic "ARCDSTA",
 *                           version 1, header size 24, payload length 28,
 *                           both CRC-32s (zlib's); payload "GB", format 1,
 *                           then little-endian coins, plays (u32) and
 *                           play_ticks, on_ticks (u64). Prints them; exit 1
 *                           if anything does not check out
 *   vm_guest fbinfo DEV     print the framebuffer's geometry and format
 *   vm_guest now            CLOCK_MONOTONIC in seconds (9 decimals), the
 *                           clock of the journal's -o short-monotonic
 *
 * Exit status 0 on success, 1 on a failed check or error, 2 on bad usage.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <limits.h>
#include <poll.h>
#include <pwd.h>
#include <linux/fb.h>
#include <linux/kd.h>
#include <linux/uinput.h>
#include <linux/vt.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <libevdev/libevdev.h>
#include <zlib.h>

static int usage(void)
{
	fputs("usage: vm_guest kbd FIFO | kdmode TTY | chvt N SECONDS | open PATH r|w|rw |\n"
	      "       probe CGROUP USER PATH:MODE:WANT... | waitfd PID PATH SECONDS |\n"
	      "       waitnofd PID PATH SECONDS | waitdev PID NAME SECONDS |\n"
	      "       hidwrite PATH HEX | hidsend PATH HEX SECONDS | hidtap PATH DOWN UP MS |\n"
	      "       pulls DIR STEP... |\n"
	      "       meter FILE SECONDS OUT |\n"
	      "       replug PID CLASS GADGET UDC HIDG N HOLD_MS IDLE HELD |\n"
	      "       books FILE | fbinfo DEV | now\n",
	      stderr);
	return 2;
}

static double mono(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static int emit(int fd, int type, int code, int value)
{
	struct input_event e;

	memset(&e, 0, sizeof(e));
	e.type = (unsigned short)type;
	e.code = (unsigned short)code;
	e.value = value;
	return write(fd, &e, sizeof(e)) == (ssize_t)sizeof(e) ? 0 : -1;
}

static int key(int fd, int code, int down)
{
	if (emit(fd, EV_KEY, code, down) < 0 || emit(fd, EV_SYN, SYN_REPORT, 0) < 0)
		return -1;
	return 0;
}

static int key_code(const char *name)
{
	char *end;
	long v = strtol(name, &end, 0);

	if (*end == '\0' && end != name)
		return v > 0 && v < KEY_CNT ? (int)v : -1;
	return libevdev_event_code_from_name(EV_KEY, name);
}

static void sleep_ms(long ms)
{
	struct timespec ts = { .tv_sec = ms / 1000, .tv_nsec = (ms % 1000) * 1000000L };

	while (nanosleep(&ts, &ts) < 0 && errno == EINTR)
		;
}

/* The event node the kernel made for our uinput device (sysfs name). */
static void print_node(int fd)
{
	char sys[64] = "";

	if (ioctl(fd, UI_GET_SYSNAME(sizeof(sys)), sys) < 0) {
		printf("ready (sysname: %s)\n", strerror(errno));
		return;
	}
	printf("ready /sys/devices/virtual/input/%s\n", sys);
}

static int cmd_kbd(const char *fifo)
{
	struct uinput_setup us;
	char line[128];
	FILE *in;
	int fd, rc = 0;

	fd = open("/dev/uinput", O_WRONLY | O_CLOEXEC);
	if (fd < 0) {
		fprintf(stderr, "vm_guest: /dev/uinput: %s\n", strerror(errno));
		return 1;
	}
	if (ioctl(fd, UI_SET_EVBIT, EV_KEY) < 0) {
		fprintf(stderr, "vm_guest: UI_SET_EVBIT: %s\n", strerror(errno));
		close(fd);
		return 1;
	}
	for (int k = 1; k < 256; k++)
		ioctl(fd, UI_SET_KEYBIT, k);
	memset(&us, 0, sizeof(us));
	us.id.bustype = BUS_VIRTUAL;
	us.id.vendor = 0x1209;
	us.id.product = 0x0001;
	snprintf(us.name, sizeof(us.name), "arcaded-vm keyboard");
	if (ioctl(fd, UI_DEV_SETUP, &us) < 0 || ioctl(fd, UI_DEV_CREATE) < 0) {
		fprintf(stderr, "vm_guest: uinput create: %s\n", strerror(errno));
		close(fd);
		return 1;
	}
	print_node(fd);
	fflush(stdout);
	in = fopen(fifo, "re");
	if (!in) {
		fprintf(stderr, "vm_guest: %s: %s\n", fifo, strerror(errno));
		rc = 1;
		goto out;
	}
	while (fgets(line, sizeof(line), in)) {
		char op[16], name[64];
		long ms = 0;
		int n = sscanf(line, "%15s %63s %ld", op, name, &ms), code;

		if (n < 2 || (code = key_code(name)) < 0) {
			fprintf(stderr, "vm_guest: bad command: %s", line);
			rc = 1;
			continue;
		}
		if (strcmp(op, "tap") == 0 && n == 3) {
			if (key(fd, code, 1) < 0)
				rc = 1;
			sleep_ms(ms);
			if (key(fd, code, 0) < 0)
				rc = 1;
		} else if (strcmp(op, "down") == 0) {
			rc |= key(fd, code, 1) < 0;
		} else if (strcmp(op, "up") == 0) {
			rc |= key(fd, code, 0) < 0;
		} else {
			fprintf(stderr, "vm_guest: bad command: %s", line);
			rc = 1;
		}
	}
	fclose(in);
out:
	ioctl(fd, UI_DEV_DESTROY);
	close(fd);
	return rc;
}

static int cmd_kdmode(const char *tty)
{
	static const char *const kbn[] = { "raw", "xlate", "mediumraw", "unicode", "off" };
	int fd = open(tty, O_RDONLY | O_NOCTTY | O_CLOEXEC), kd, kb;

	if (fd < 0) {
		fprintf(stderr, "vm_guest: %s: %s\n", tty, strerror(errno));
		return 1;
	}
	if (ioctl(fd, KDGETMODE, &kd) < 0 || ioctl(fd, KDGKBMODE, &kb) < 0) {
		fprintf(stderr, "vm_guest: %s: KDGETMODE/KDGKBMODE: %s\n", tty, strerror(errno));
		close(fd);
		return 1;
	}
	close(fd);
	printf("kd %s kb %s\n", kd == KD_TEXT ? "text" : kd == KD_GRAPHICS ? "graphics" : "?",
	       kb >= 0 && kb <= K_OFF ? kbn[kb] : "?");
	return 0;
}

static int cmd_chvt(const char *n, const char *secs)
{
	int fd = open("/dev/tty0", O_RDWR | O_NOCTTY | O_CLOEXEC), vt = atoi(n);
	struct vt_stat st;
	double t0 = mono(), limit = atof(secs);
	unsigned short from;

	if (fd < 0 || ioctl(fd, VT_GETSTATE, &st) < 0) {
		fprintf(stderr, "vm_guest: /dev/tty0: %s\n", strerror(errno));
		return 1;
	}
	from = st.v_active;
	if (ioctl(fd, VT_ACTIVATE, vt) < 0) {
		fprintf(stderr, "vm_guest: VT_ACTIVATE %d: %s\n", vt, strerror(errno));
		close(fd);
		return 1;
	}
	/* VT_WAITACTIVE would block for good if the switch never happens */
	while (ioctl(fd, VT_GETSTATE, &st) == 0 && st.v_active != vt && mono() - t0 < limit)
		usleep(20000);
	close(fd);
	printf("from %u to %u after %.3f s\n", from, st.v_active, mono() - t0);
	return st.v_active == vt ? 0 : 1;
}

/* Opens path with mode r|w|rw; "ok", the errno name, or NULL (bad mode). */
static const char *try_open(const char *path, const char *mode)
{
	int flags, fd;
	const char *n;

	if (strcmp(mode, "r") == 0)
		flags = O_RDONLY;
	else if (strcmp(mode, "w") == 0)
		flags = O_WRONLY;
	else if (strcmp(mode, "rw") == 0)
		flags = O_RDWR;
	else
		return NULL;
	fd = open(path, flags | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
	if (fd < 0) {
		n = strerrorname_np(errno);
		return n ? n : "error";
	}
	close(fd);
	return "ok";
}

static int cmd_open(const char *path, const char *mode)
{
	const char *r = try_open(path, mode);

	if (!r)
		return usage();
	puts(r);
	return strcmp(r, "ok") == 0 ? 0 : 1;
}

static int cmd_probe(const char *cg, const char *user, char **specs, int n)
{
	char procs[PATH_MAX];
	int fd, bad = 0;

	snprintf(procs, sizeof(procs), "%s/cgroup.procs", cg);
	fd = open(procs, O_WRONLY | O_CLOEXEC);
	if (fd < 0 || write(fd, "0\n", 2) != 2) {
		fprintf(stderr, "vm_guest: %s: %s\n", procs, strerror(errno));
		return 1;
	}
	close(fd);
	if (strcmp(user, "root") != 0) {
		struct passwd *pw = getpwnam(user);

		if (!pw) {
			fprintf(stderr, "vm_guest: no user %s\n", user);
			return 1;
		}
		if (setgroups(0, NULL) < 0 || setgid(pw->pw_gid) < 0 || setuid(pw->pw_uid) < 0) {
			fprintf(stderr, "vm_guest: become %s: %s\n", user, strerror(errno));
			return 1;
		}
	}
	for (int i = 0; i < n; i++) {
		char spec[PATH_MAX], *mode, *want;
		const char *got;

		snprintf(spec, sizeof(spec), "%s", specs[i]);
		want = strrchr(spec, ':');
		if (!want)
			return usage();
		*want++ = '\0';
		mode = strrchr(spec, ':');
		if (!mode)
			return usage();
		*mode++ = '\0';
		got = try_open(spec, mode);
		if (!got)
			return usage();
		printf("%s %s %s %s: %s %s\n", user, spec, mode, got,
		       strcmp(got, want) == 0 ? "as wanted" : "WANTED", want);
		bad |= strcmp(got, want) != 0;
	}
	return bad;
}

/* Does process pid have path open? */
static int holds(const char *pid, const char *path)
{
	char dir[64], link[PATH_MAX], target[PATH_MAX];
	struct dirent *de;
	DIR *d;
	int found = 0;

	snprintf(dir, sizeof(dir), "/proc/%s/fd", pid);
	d = opendir(dir);
	if (!d)
		return 0;
	while (!found && (de = readdir(d)) != NULL) {
		ssize_t n;

		if (de->d_name[0] == '.')
			continue;
		snprintf(link, sizeof(link), "%s/%s", dir, de->d_name);
		n = readlink(link, target, sizeof(target) - 1);
		if (n <= 0)
			continue;
		target[n] = '\0';
		found = strcmp(target, path) == 0;
	}
	closedir(d);
	return found;
}

/* The event node of the first input device whose name contains name. */
static int find_input(const char *name, char *node, size_t len)
{
	DIR *d = opendir("/sys/class/input");
	struct dirent *de;
	int found = 0;

	if (!d)
		return 0;
	while (!found && (de = readdir(d)) != NULL) {
		char path[PATH_MAX], text[256];
		FILE *f;

		if (strncmp(de->d_name, "event", 5) != 0)
			continue;
		snprintf(path, sizeof(path), "/sys/class/input/%s/device/name", de->d_name);
		f = fopen(path, "re");
		if (!f)
			continue;
		if (fgets(text, sizeof(text), f) && strstr(text, name)) {
			snprintf(node, len, "/dev/input/%s", de->d_name);
			found = 1;
		}
		fclose(f);
	}
	closedir(d);
	return found;
}

static int cmd_waitdev(const char *pid, const char *name, const char *secs)
{
	double t0 = mono(), limit = atof(secs);
	char node[PATH_MAX];

	while (!find_input(name, node, sizeof(node)) || !holds(pid, node)) {
		if (mono() - t0 > limit) {
			printf("none %.2f (timeout)\n", mono() - t0);
			return 1;
		}
		sleep_ms(20);
	}
	printf("%s %.2f\n", node, mono() - t0);
	return 0;
}

/* waitfd (want 1) and waitnofd (want 0): polls until process pid has
 * path open (or no longer), printing the seconds it took. */
static int cmd_waitfd(const char *pid, const char *path, const char *secs, int want)
{
	double t0 = mono(), limit = atof(secs);

	while (holds(pid, path) != want) {
		if (mono() - t0 > limit) {
			printf("%.2f (timeout)\n", mono() - t0);
			return 1;
		}
		sleep_ms(20);
	}
	printf("%.2f\n", mono() - t0);
	return 0;
}

/* Pairs of hex digits (blanks allowed) into b; the count, or -1. */
static int parse_hex(const char *hex, uint8_t *b, size_t cap)
{
	size_t n = 0;

	while (*hex) {
		unsigned v;
		int used;

		if (*hex == ' ') {
			hex++;
			continue;
		}
		if (n == cap || sscanf(hex, "%2x%n", &v, &used) != 1 || used != 2)
			return -1;
		b[n++] = (uint8_t)v;
		hex += 2;
	}
	return (int)n;
}

/* Writes report b (n bytes) to gadget node path in one write, waiting up
 * to limit seconds for the gadget to take it; 0, or -1 with a message. */
static int send_report(const char *path, const uint8_t *b, int n, double limit)
{
	double t0 = mono();
	int fd;

	fd = open(path, O_WRONLY | O_NONBLOCK | O_CLOEXEC);
	if (fd < 0) {
		fprintf(stderr, "vm_guest: %s: %s\n", path, strerror(errno));
		return 1;
	}
	for (;;) {
		struct pollfd p = { .fd = fd, .events = POLLOUT };
		ssize_t w = write(fd, b, (size_t)n);

		if (w == n)
			break;
		/* EAGAIN: the last report is not taken yet; ESHUTDOWN: the
		 * gadget is not bound (yet). */
		if (w >= 0 || (errno != EAGAIN && errno != EINTR && errno != ESHUTDOWN)) {
			fprintf(stderr, "vm_guest: %s: %s\n", path,
				w >= 0 ? "short write" : strerror(errno));
			close(fd);
			return 1;
		}
		if (mono() - t0 > limit) {
			fprintf(stderr, "vm_guest: %s: not taken within %.1f s (%s)\n", path, limit,
				strerror(errno));
			close(fd);
			return 1;
		}
		poll(&p, 1, 20);
	}
	close(fd);
	return 0;
}

static int cmd_hidsend(const char *path, const char *hex, const char *secs)
{
	uint8_t b[4096];
	int n = parse_hex(hex, b, sizeof(b));

	if (n <= 0)
		return usage();
	return send_report(path, b, n, atof(secs)) < 0 ? 1 : 0;
}

/* A tap in one process: the down report, MS milliseconds, the up report
 * (under a loaded emulator two process starts alone can take longer than
 * the wizard's 1 s hold). */
static int cmd_hidtap(const char *path, const char *down, const char *up, const char *ms)
{
	uint8_t d[4096], u[4096];
	int nd = parse_hex(down, d, sizeof(d)), nu = parse_hex(up, u, sizeof(u));
	long t = atol(ms);
	struct timespec ts = { .tv_sec = t / 1000, .tv_nsec = t % 1000 * 1000000L };

	if (nd <= 0 || nu <= 0 || t < 0)
		return usage();
	if (send_report(path, d, nd, 5) < 0)
		return 1;
	nanosleep(&ts, NULL);
	return send_report(path, u, nu, 5) < 0 ? 1 : 0;
}

/* The node (/dev/...) of the first device of sysfs class cls (for "input"
 * only its eventN) whose device lies under platform device dummy_hcd.k and
 * whose node exists; 0 if there is none. */
static int find_on_hcd(const char *cls, int k, char *node, size_t len)
{
	char dir[64], want[32];
	struct dirent *de;
	int input = strcmp(cls, "input") == 0, found = 0;
	DIR *d;

	snprintf(dir, sizeof(dir), "/sys/class/%s", cls);
	snprintf(want, sizeof(want), "/dummy_hcd.%d/", k);
	d = opendir(dir);
	if (!d)
		return 0;
	while (!found && (de = readdir(d)) != NULL) {
		char path[PATH_MAX], real[PATH_MAX];

		if (de->d_name[0] == '.' || (input && strncmp(de->d_name, "event", 5) != 0))
			continue;
		snprintf(path, sizeof(path), "%s/%s", dir, de->d_name);
		if (!realpath(path, real) || !strstr(real, want))
			continue;
		snprintf(node, len, "/dev/%s%s", input ? "input/" : "", de->d_name);
		found = access(node, F_OK) == 0;
	}
	closedir(d);
	return found;
}

/* When path's inode last changed (udev's chown and chmod), on the
 * CLOCK_MONOTONIC scale; -1 if it cannot be read. */
static double ctime_mono(const char *path)
{
	struct timespec rt, mt;
	struct stat st;

	if (stat(path, &st) < 0)
		return -1;
	clock_gettime(CLOCK_REALTIME, &rt);
	clock_gettime(CLOCK_MONOTONIC, &mt);
	return (double)st.st_ctim.tv_sec + (double)st.st_ctim.tv_nsec / 1e9 -
	       ((double)rt.tv_sec + (double)rt.tv_nsec / 1e9 - (double)mt.tv_sec -
		(double)mt.tv_nsec / 1e9);
}

static int put_str(const char *path, const char *v)
{
	int fd = open(path, O_WRONLY | O_CLOEXEC);
	ssize_t w;

	if (fd < 0)
		return -1;
	w = write(fd, v, strlen(v));
	close(fd);
	return w == (ssize_t)strlen(v) ? 0 : -1;
}

static int cmd_replug(char **a)
{
	const char *pid = a[0], *cls = a[1], *gadget = a[2], *udc = a[3], *hidg = a[4];
	const char *dot = strrchr(udc, '.');
	int n = atoi(a[5]), k, ni, nh;
	long hold = atol(a[6]);
	uint8_t idle[64], held[64];
	char udcfile[PATH_MAX], node[PATH_MAX];

	ni = parse_hex(a[7], idle, sizeof(idle));
	nh = parse_hex(a[8], held, sizeof(held));
	if (!dot || ni <= 0 || nh <= 0 || n <= 0)
		return usage();
	k = atoi(dot + 1);
	snprintf(udcfile, sizeof(udcfile), "%s/UDC", gadget);
	if (!find_on_hcd(cls, k, node, sizeof(node)) || !holds(pid, node)) {
		printf("not attached at the start\n");
		return 1;
	}
	for (int i = 1; i <= n; i++) {
		double t_un, t_closed, t_pl, t_node, t_open, c;

		if (send_report(hidg, idle, ni, 5) < 0 || send_report(hidg, held, nh, 5) < 0) {
			printf("plug %d: a report was not taken\n", i);
			return 1;
		}
		sleep_ms(hold);
		t_un = mono();
		if (put_str(udcfile, "\n") < 0) {
			printf("plug %d: unbind: %s\n", i, strerror(errno));
			return 1;
		}
		while (holds(pid, node)) {
			if (mono() - t_un > 5) {
				printf("plug %d: %s still open 5 s after the unplug\n", i, node);
				return 1;
			}
			sleep_ms(2);
		}
		t_closed = mono();
		/* The old node gone too, so the next one found is the new one. */
		while (find_on_hcd(cls, k, node, sizeof(node))) {
			if (mono() - t_un > 5) {
				printf("plug %d: %s still there 5 s after the unplug\n", i, node);
				return 1;
			}
			sleep_ms(2);
		}
		t_pl = mono();
		if (put_str(udcfile, udc) < 0) {
			printf("plug %d: bind %s: %s\n", i, udc, strerror(errno));
			return 1;
		}
		while (!find_on_hcd(cls, k, node, sizeof(node))) {
			if (mono() - t_pl > 10) {
				printf("plug %d: no %s node 10 s after the plug\n", i, cls);
				return 1;
			}
			sleep_ms(2);
		}
		t_node = mono();
		while (!holds(pid, node)) {
			if (mono() - t_node > 10) {
				printf("plug %d: %s not opened within 10 s\n", i, node);
				return 1;
			}
			sleep_ms(2);
		}
		t_open = mono();
		c = ctime_mono(node);
		printf("plug %d closed %.3f node %.3f udev %.3f open %.3f\n", i, t_closed - t_un,
		       t_node - t_pl, c - t_node, t_open - t_node);
		fflush(stdout);
	}
	return 0;
}

static int cmd_pulls(const char *dir, char **steps, int n)
{
	char path[PATH_MAX];
	double t0 = mono(), tw = 0, gap = 0;
	int fd, held = 1;

	for (int i = 0; i < n; i++)
		if ((steps[i][0] != 'd' && steps[i][0] != 'u') ||
		    (steps[i][1] != '\0' && steps[i][1] != ':'))
			return usage();
	snprintf(path, sizeof(path), "%s/pull", dir);
	fd = open(path, O_WRONLY | O_CLOEXEC);
	if (fd < 0) {
		fprintf(stderr, "vm_guest: %s: %s\n", path, strerror(errno));
		return 1;
	}
	for (int i = 0; i < n; i++) {
		const char *v, *st = steps[i];
		long ms = 0;
		double tnow;

		v = st[0] == 'd' ? "pull-down" : "pull-up";
		if (st[1] == ':')
			ms = atol(st + 2);
		/* sysfs ignores the offset: each write is one store. */
		if (pwrite(fd, v, strlen(v), 0) != (ssize_t)strlen(v)) {
			fprintf(stderr, "vm_guest: %s: %s\n", path, strerror(errno));
			close(fd);
			return 1;
		}
		/* the spacing of writes meant back to back (a bounce) */
		tnow = mono();
		if (!held && tnow - tw > gap)
			gap = tnow - tw;
		tw = tnow;
		held = ms > 0;
		if (ms > 0) {
			double t = mono();

			if (ms > 2)
				sleep_ms(ms - 2);
			while (mono() - t < (double)ms / 1000)
				;
			printf("hold %d %.2f ms\n", i, (mono() - t) * 1000);
		}
	}
	close(fd);
	printf("steps %d total %.2f ms\n", n, (mono() - t0) * 1000);
	printf("apart %.2f ms\n", gap * 1000);
	return 0;
}

static int cmd_meter(const char *file, const char *secs, const char *out)
{
	double t0 = mono(), limit = atof(secs), last = 0, maxgap = 0, rise = 0;
	double pulse[64];
	char ready[PATH_MAX];
	int fd, prev = -1, rises = 0, np = 0, ffd;
	long polls = 0;
	FILE *o;

	fd = open(file, O_RDONLY | O_CLOEXEC);
	o = fopen(out, "we");
	if (fd < 0 || !o) {
		fprintf(stderr, "vm_guest: %s / %s: %s\n", file, out, strerror(errno));
		if (fd >= 0)
			close(fd);
		if (o)
			fclose(o);
		return 1;
	}
	snprintf(ready, sizeof(ready), "%s.ready", out);
	for (double now; (now = mono()) - t0 < limit; sleep_ms(1)) {
		char c[8];
		int v;

		/* A read at offset 0 shows the attribute afresh. */
		if (pread(fd, c, sizeof(c), 0) < 1) {
			fprintf(o, "read error: %s\n", strerror(errno));
			break;
		}
		v = c[0] == '1';
		if (polls++ == 0) {
			ffd = open(ready, O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
			if (ffd >= 0)
				close(ffd);
		} else if (now - last > maxgap) {
			maxgap = now - last;
		}
		last = now;
		if (prev == 0 && v == 1) {
			rises++;
			rise = now;
		} else if (prev == 1 && v == 0 && rise > 0 && np < 64) {
			pulse[np++] = now - rise;
		}
		prev = v;
	}
	close(fd);
	fprintf(o, "rises %d polls %ld maxgap %.2f ms\n", rises, polls, maxgap * 1000);
	for (int i = 0; i < np; i++)
		fprintf(o, "pulse %.1f ms\n", pulse[i] * 1000);
	fclose(o);
	return 0;
}

static int cmd_hidwrite(const char *path, const char *hex)
{
	uint8_t b[4096];
	int n = parse_hex(hex, b, sizeof(b)), fd;

	if (n < 0)
		return usage();
	fd = open(path, O_WRONLY | O_CLOEXEC);
	if (fd < 0 || write(fd, b, (size_t)n) != (ssize_t)n) {
		fprintf(stderr, "vm_guest: %s: %s\n", path, strerror(errno));
		if (fd >= 0)
			close(fd);
		return 1;
	}
	close(fd);
	return 0;
}

static uint64_t le(const uint8_t *p, int n)
{
	uint64_t v = 0;

	for (int i = n - 1; i >= 0; i--)
		v = v << 8 | p[i];
	return v;
}

static int cmd_books(const char *path)
{
	uint8_t b[64];
	ssize_t n;
	int fd = open(path, O_RDONLY | O_CLOEXEC);

	if (fd < 0) {
		printf("%s: %s\n", path, strerror(errno));
		return 1;
	}
	n = read(fd, b, sizeof(b));
	close(fd);
	if (n != 24 + 28) {
		printf("%s: %zd bytes, want 52\n", path, n);
		return 1;
	}
	if (memcmp(b, "ARCDSTA", 8) != 0 || le(b + 8, 2) != 1 || le(b + 10, 2) != 24 ||
	    le(b + 12, 4) != 28) {
		printf("%s: bad header\n", path);
		return 1;
	}
	if (le(b + 20, 4) != crc32(0, b, 20) || le(b + 16, 4) != crc32(0, b + 24, 28)) {
		printf("%s: checksum mismatch\n", path);
		return 1;
	}
	if (b[24] != 'G' || b[25] != 'B' || b[26] != 1 || b[27] != 0) {
		printf("%s: not bookkeeping\n", path);
		return 1;
	}
	printf("coins %llu plays %llu play_ticks %llu on_ticks %llu\n",
	       (unsigned long long)le(b + 28, 4), (unsigned long long)le(b + 32, 4),
	       (unsigned long long)le(b + 36, 8), (unsigned long long)le(b + 44, 8));
	return 0;
}

static int cmd_fbinfo(const char *dev)
{
	struct fb_var_screeninfo v;
	struct fb_fix_screeninfo f;
	int fd = open(dev, O_RDONLY | O_CLOEXEC);

	if (fd < 0 || ioctl(fd, FBIOGET_VSCREENINFO, &v) < 0 ||
	    ioctl(fd, FBIOGET_FSCREENINFO, &f) < 0) {
		fprintf(stderr, "vm_guest: %s: %s\n", dev, strerror(errno));
		if (fd >= 0)
			close(fd);
		return 1;
	}
	close(fd);
	printf("id %.16s xres %u yres %u xres_virtual %u yres_virtual %u bpp %u "
	       "r %u/%u g %u/%u b %u/%u line_length %u smem_len %u ypanstep %u visual %u\n",
	       f.id, v.xres, v.yres, v.xres_virtual, v.yres_virtual, v.bits_per_pixel,
	       v.red.offset, v.red.length, v.green.offset, v.green.length, v.blue.offset,
	       v.blue.length, f.line_length, f.smem_len, f.ypanstep, f.visual);
	return 0;
}

static int cmd_now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	printf("%lld.%09ld\n", (long long)ts.tv_sec, ts.tv_nsec);
	return 0;
}

int main(int argc, char **argv)
{
	if (argc == 3 && strcmp(argv[1], "kbd") == 0)
		return cmd_kbd(argv[2]);
	if (argc == 3 && strcmp(argv[1], "kdmode") == 0)
		return cmd_kdmode(argv[2]);
	if (argc == 4 && strcmp(argv[1], "chvt") == 0)
		return cmd_chvt(argv[2], argv[3]);
	if (argc == 4 && strcmp(argv[1], "open") == 0)
		return cmd_open(argv[2], argv[3]);
	if (argc >= 5 && strcmp(argv[1], "probe") == 0)
		return cmd_probe(argv[2], argv[3], argv + 4, argc - 4);
	if (argc == 5 && strcmp(argv[1], "waitfd") == 0)
		return cmd_waitfd(argv[2], argv[3], argv[4], 1);
	if (argc == 5 && strcmp(argv[1], "waitdev") == 0)
		return cmd_waitdev(argv[2], argv[3], argv[4]);
	if (argc == 5 && strcmp(argv[1], "waitnofd") == 0)
		return cmd_waitfd(argv[2], argv[3], argv[4], 0);
	if (argc == 4 && strcmp(argv[1], "hidwrite") == 0)
		return cmd_hidwrite(argv[2], argv[3]);
	if (argc == 5 && strcmp(argv[1], "hidsend") == 0)
		return cmd_hidsend(argv[2], argv[3], argv[4]);
	if (argc == 6 && strcmp(argv[1], "hidtap") == 0)
		return cmd_hidtap(argv[2], argv[3], argv[4], argv[5]);
	if (argc >= 4 && strcmp(argv[1], "pulls") == 0)
		return cmd_pulls(argv[2], argv + 3, argc - 3);
	if (argc == 11 && strcmp(argv[1], "replug") == 0)
		return cmd_replug(argv + 2);
	if (argc == 5 && strcmp(argv[1], "meter") == 0)
		return cmd_meter(argv[2], argv[3], argv[4]);
	if (argc == 3 && strcmp(argv[1], "books") == 0)
		return cmd_books(argv[2]);
	if (argc == 3 && strcmp(argv[1], "fbinfo") == 0)
		return cmd_fbinfo(argv[2]);
	if (argc == 2 && strcmp(argv[1], "now") == 0)
		return cmd_now();
	return usage();
}
