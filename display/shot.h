/*
 * shot: PNG screenshots of indexed frames (libpng).
 */
#ifndef ARCADED_DISPLAY_SHOT_H
#define ARCADED_DISPLAY_SHOT_H

#include <stdint.h>

/* Writes the frame (w*h indices, row stride pitch) as an RGB PNG at path,
 * atomically (temporary file + rename). 0 or -errno. */
int shot_png(const char *path, const uint8_t *px, int w, int h, int pitch,
	     const uint8_t rgb[256][3]);

#endif
