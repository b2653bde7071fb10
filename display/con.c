/*
 * con: the console under a full-screen display (contract in con.h).
 */
#include "display/con.h"

#include <errno.h>
#include <fcntl.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

/* The console this process switched, for con_leave and the signal
 * handlers. Written only outside signal handlers, before/after con_active
 * is raised/cleared. */
static volatile sig_atomic_t con_active;
static volatile sig_atomic_t con_fd = -1;
static volatile sig_atomic_t con_kd;       /* mode before KD_GRAPHICS */
static volatile sig_atomic_t con_kb = -1;  /* keyboard mode before K_OFF; -1 kept */
static volatile sig_atomic_t con_vt;       /* VT_PROCESS set: put VT_AUTO back */
/* Raised by the VT signals' handlers, cleared by con_vt_requests. */
static volatile sig_atomic_t con_rel, con_acq;

static void con_on_release(int sig)
{
	(void)sig;
	con_rel = 1;
}

static void con_on_acquire(int sig)
{
	(void)sig;
	con_acq = 1;
}

/* VT_PROCESS with our two signals; 0 or -errno. */
static int con_vt_process(int fd)
{
	struct sigaction sa;
	struct vt_mode m;

	memset(&sa, 0, sizeof(sa));
	sigemptyset(&sa.sa_mask);
	/* SA_RESTART: a switch must not make another thread's read fail */
	sa.sa_flags = SA_RESTART;
	sa.sa_handler = con_on_release;
	if (sigaction(SIGRTMIN + 2, &sa, NULL) < 0)
		return -errno;
	sa.sa_handler = con_on_acquire;
	if (sigaction(SIGRTMIN + 3, &sa, NULL) < 0)
		return -errno;
	memset(&m, 0, sizeof(m));
	m.mode = VT_PROCESS;
	m.relsig = (short)(SIGRTMIN + 2);
	m.acqsig = (short)(SIGRTMIN + 3);
	if (ioctl(fd, VT_SETMODE, &m) < 0)
		return -errno;
	con_rel = con_acq = 0;
	return 0;
}

int con_enter(const char *tty, int vt_signals, char *note, size_t notelen)
{
	int fd, kd, kb, rc;
	char kbd[96];

	if (!tty)
		tty = "/dev/tty0";
	if (!tty[0]) {
		snprintf(note, notelen, "console left alone");
		return 0;
	}
	if (con_active) {
		snprintf(note, notelen, "console left alone (held by another display)");
		return 0;
	}
	fd = open(tty, O_RDWR | O_CLOEXEC | O_NOCTTY);
	if (fd < 0) {
		snprintf(note, notelen, "console %s: %s (left alone)", tty, strerror(errno));
		return 0;
	}
	if (ioctl(fd, KDGETMODE, &kd) < 0 || ioctl(fd, KDGKBMODE, &kb) < 0 ||
	    ioctl(fd, KDSETMODE, (unsigned long)KD_GRAPHICS) < 0) {
		snprintf(note, notelen, "console %s: %s (left alone)", tty, strerror(errno));
		close(fd);
		return 0;
	}
	/* A console already in graphics mode or with the keyboard off was
	 * left so by an earlier run that was killed (SIGKILL cannot be
	 * handled): give it back as text with a Unicode keyboard. */
	if (kd == KD_GRAPHICS)
		kd = KD_TEXT;
	if (kb == K_OFF)
		kb = K_UNICODE;
	con_fd = fd;
	con_kd = kd;
	con_kb = -1;
	con_vt = 0;
	if (ioctl(fd, KDSKBMODE, (unsigned long)K_OFF) == 0) {
		con_kb = kb;
		snprintf(kbd, sizeof(kbd), "keyboard off");
	} else {
		snprintf(kbd, sizeof(kbd), "keyboard left on (%s)", strerror(errno));
	}
	con_active = 1;
	if (!vt_signals) {
		snprintf(note, notelen, "console %s graphics, %s", tty, kbd);
		return 1;
	}
	rc = con_vt_process(fd);
	if (rc == 0)
		con_vt = 1;
	snprintf(note, notelen, "console %s graphics, %s, VT switching %s%s", tty, kbd,
		 rc == 0 ? "by signals" : "not handled: ", rc == 0 ? "" : strerror(-rc));
	return 1;
}

/* Async-signal-safe: ioctl only. */
static void con_restore(void)
{
	struct vt_mode m;

	if (con_vt) {
		memset(&m, 0, sizeof(m));
		m.mode = VT_AUTO;
		ioctl(con_fd, VT_SETMODE, &m);
	}
	if (con_kb >= 0)
		ioctl(con_fd, KDSKBMODE, (unsigned long)con_kb);
	ioctl(con_fd, KDSETMODE, (unsigned long)con_kd);
}

void con_emergency(void)
{
	if (con_active)
		con_restore();
}

void con_leave(void)
{
	if (!con_active)
		return;
	con_active = 0;
	con_restore();
	close(con_fd);
	con_fd = -1;
	con_kb = -1;
	con_vt = 0;
}

int con_vt_requests(void)
{
	int r = 0;

	if (!con_active || !con_vt)
		return 0;
	if (con_rel) {
		con_rel = 0;
		r |= CON_VT_RELEASE;
	}
	if (con_acq) {
		con_acq = 0;
		r |= CON_VT_ACQUIRE;
	}
	return r;
}

int con_vt_release(void)
{
	if (!con_active || !con_vt)
		return -EBADF;
	return ioctl(con_fd, VT_RELDISP, 1) < 0 ? -errno : 0;
}

int con_vt_acquire(void)
{
	if (!con_active || !con_vt)
		return -EBADF;
	return ioctl(con_fd, VT_RELDISP, VT_ACKACQ) < 0 ? -errno : 0;
}
