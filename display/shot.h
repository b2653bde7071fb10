/*
 * shot: PNG screenshots of indexed frames (libpng).
 */
#ifndef ARCADED_DISPLAY_SHOT_H
#define ARCADED_DISPLAY_SHOT_H

#include <stddef.h>
#include <stdint.h>

/* Writes the frame (w*h indices, row stride pitch) as an RGB PNG at path,
 * atomically (temporary file "<path>.tmp" + rename). 0 or -errno; -EEXIST
 * when path or "<path>.tmp" exists and is not a regular file (a device
 * node, FIFO, symbolic link, directory or socket): it is left alone, and
 * shot_target_kind says what it is. */
int shot_png(const char *path, const uint8_t *px, int w, int h, int pitch,
	     const uint8_t rgb[256][3]);

/* NULL when path is missing or a regular file, else what it is ("a
 * symbolic link", "a FIFO", "a device node", "a directory", "a socket"),
 * without following a link. */
const char *shot_target_kind(const char *path);

/* Why shot_png(path) returned rc, for a message after "PATH: ": the kind of
 * file in the way for -EEXIST ("is a FIFO, not a regular file: not
 * replaced"), else strerror. */
void shot_why(const char *path, int rc, char *why, size_t whylen);

#endif
