/*
 * dp_int: declarations shared by the display files only (not for callers
 * outside display/).
 *
 * Each backend file defines struct dp for itself; a handle is only ever
 * dereferenced by the backend that created it (dp.c just passes it on).
 */
#ifndef ARCADED_DISPLAY_DP_INT_H
#define ARCADED_DISPLAY_DP_INT_H

/* Async-signal-safe halves of dp_emergency_restore: each undoes what its
 * backend changed (console mode; terminal mode and screen) if a display of
 * that backend is open, using only ioctl, tcsetattr and write. */
void dp_fbdev_emergency(void);
void dp_term_emergency(void);

#endif
