/*
 * v_local: what v_video.c and v_font.c share.
 */
#ifndef ARCADED_ENGINE_V_LOCAL_H
#define ARCADED_ENGINE_V_LOCAL_H

#define V_FONT_FIRST 32                /* ' ' */
#define V_FONT_GLYPHS 64               /* ' ' .. '_' */

/* Glyph art: v_font[ch - V_FONT_FIRST][row] is 8 characters, '#' a pixel. */
extern const char v_font[V_FONT_GLYPHS][8][9];

#endif
