/*
 * con: the virtual console under a display that takes the whole screen
 * (dp_fbdev.c, dp_kms.c). Not a backend: the helper both share, so the
 * console is handled one way.
 *
 * Entering puts the tty (default /dev/tty0, the foreground virtual
 * terminal, which the fd then stays bound to) in KD_GRAPHICS, so fbcon
 * stops drawing text and the cursor over the game, and its keyboard in
 * K_OFF, so keys meant for the game (read through evdev) do not reach the
 * shell or the kernel's console handling. With vt_signals the terminal is
 * also put in VT_PROCESS mode: a switch to another virtual terminal
 * (Ctrl-Alt-Fn, chvt) then waits until the display has let go of the
 * screen (con_vt_release), and a switch back is announced so it can take
 * the screen again (con_vt_acquire). The kernel announces both with
 * signals (SIGRTMIN + 2 and SIGRTMIN + 3) whose handlers, installed
 * here, only set flags that con_vt_requests reads: the VT protocol belongs
 * to the display that asked for it, not to the app's signals (app/sig.c).
 *
 * One console at a time per process: the state lives at file scope, the
 * one place the fatal-signal handler can find it (con_emergency). Written
 * outside signal handlers only.
 */
#ifndef ARCADED_DISPLAY_CON_H
#define ARCADED_DISPLAY_CON_H

#include <stddef.h>

/* What con_vt_requests reports. */
#define CON_VT_RELEASE 1 /* another terminal is to be shown: let go, then con_vt_release */
#define CON_VT_ACQUIRE 2 /* this terminal is shown again: con_vt_acquire, take the screen */

/* Takes the console tty (NULL: /dev/tty0; "": leave it alone). Failures
 * are not errors: the game runs, note says what was left as it was.
 * Returns 1 when this caller now holds the console (and must call
 * con_leave), 0 when it was left alone (empty tty, held by another
 * display, cannot be opened or switched). note gets one line either way
 * ("console /dev/tty0 graphics, keyboard off, VT switching by signals"). */
int con_enter(const char *tty, int vt_signals, char *note, size_t notelen);

/* Puts the console back as it was (text mode, keyboard mode, VT_AUTO)
 * and closes it. Only by the holder. */
void con_leave(void);

/* Async-signal-safe (ioctl only): the same as con_leave without closing,
 * if a console is held. For fatal-signal handlers. */
void con_emergency(void);

/* CON_VT_* bits the kernel asked for since the last call (0 when the
 * console is not held with vt_signals). Both bits may be set after a
 * quick switch away and back: handle RELEASE first. */
int con_vt_requests(void);

/* Lets the switch away happen (the display has stopped using the screen).
 * 0 or -errno. */
int con_vt_release(void);

/* Acknowledges the switch back to this terminal. 0 or -errno. */
int con_vt_acquire(void);

#endif
