/*
 * dp_int: declarations shared by the display files only (not for callers
 * outside display/).
 *
 * Each backend file defines struct dp for itself; a handle is only ever
 * dereferenced by the backend that created it (dp.c just passes it on).
 */
#ifndef ARCADED_DISPLAY_DP_INT_H
#define ARCADED_DISPLAY_DP_INT_H

/* Async-signal-safe part of dp_emergency_restore for the terminal preview:
 * undoes what it changed (terminal mode and screen) if one is open, using
 * only tcsetattr and write. The console of fbdev and KMS is con.h's
 * (con_emergency). */
void dp_term_emergency(void);

#endif
