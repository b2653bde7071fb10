/*
 * hud: everything drawn over (or instead of) the 3D view, as a pure
 * function of the sim state: the same state and frame size give the same
 * pixels. In play: crosshair, health, ammo, score, lives, stage, credits,
 * the weapon with its firing animation, the minimap, and the banners
 * (stage start, stage clear, death); the full-screen pages of the arcade
 * flow: attract (title, high scores, the demo's banner), game over with
 * the continue countdown, initials entry; and the service menu
 * (menu_draw, engine/game/menu.h).
 *
 * Colours are picked by RGB from the palette in use (pal_nearest), so the
 * HUD looks the same over the built-in palette and a WAD's. Text is the
 * built-in font (v_video.h), scaled by the frame height (1 per 240 lines).
 */
#ifndef ARCADED_ENGINE_HUD_H
#define ARCADED_ENGINE_HUD_H

#include <stdint.h>

struct sim;
struct pal;
struct tex_set;
struct r_frame;
struct r_par;

/* Text of the service menu's diagnostics (the DEVICES and LATENCY pages,
 * INPUT TEST's raw controls; see engine/game/menu.h), supplied by the app
 * for the frame: facts of the
 * machine and of the main loop, never sim state. Lines are drawn as given
 * (in the font's upper case, cut at the frame's edge, as many as fit); a
 * line that starts with a non-blank is a heading (yellow), the others are
 * white. */
#define HUD_DIAG_LINES 32
#define HUD_DIAG_COLS 80
struct hud_diag {
	int n;                         /* lines used, 0..HUD_DIAG_LINES */
	char line[HUD_DIAG_LINES][HUD_DIAG_COLS];
};

/* What the HUD needs besides the state; all borrowed, read only. */
struct hud_env {
	const struct pal *pal;         /* required: the palette the frame is in */
	const struct tex_set *tex;     /* optional: weapon pictures (PISG/PISF, SHTG/SHTF,
					 * CHGG/CHGF) if it has them */
	int rotate;                    /* the display's rotation in degrees, shown by the
					* service menu's orientation screen; -1 unknown */
	const struct r_par *par;       /* optional: threads the large darkened areas are
					* split on (the renderer's pool); NULL: none */
	const struct hud_diag *diag;   /* optional: the service menu's diagnostics
					* text; NULL: none (DEVICES and LATENCY say so) */
	const char *notice;            /* optional: the first configuration error the
					* operator has not acknowledged (app text, never
					* sim state): the attract pages show "CONFIG ERROR:
					* SEE SERVICE MENU", the service menu's MAIN page
					* the text itself; NULL: none */
	const struct hud_colours *colours; /* optional: hud_colours(pal) made once by
					* the caller (13 nearest-colour searches of
					* the palette, 49,000 instructions, at every
					* frame otherwise); NULL: made here */
};

/* The colours the HUD uses, nearest to fixed RGB values in a palette. */
struct hud_colours {
	uint8_t white, grey, dark, black, red, orange, yellow, green, blue, cyan, purple;
	uint8_t skin, steel;
	const uint8_t *dim;            /* colormap that darkens the picture behind text */
	const struct r_par *par;       /* not a colour: hud_env.par, for the darkening */
};

void hud_colours(const struct pal *pal, struct hud_colours *c);

/* Whether the 3D view belongs under this state's HUD (PLAY, GAMEOVER, the
 * attract pages). When 0 (INITIALS, SERVICE) hud_draw paints the whole
 * frame itself and the app may skip r_render. */
int hud_world(const struct sim *s);

/* Draws the HUD, page or menu for s's mode into f, over what the frame
 * holds (the 3D view when hud_world). ATTRACT's DEMO page draws only its
 * banner (DEMO, INSERT COIN, credits): the app draws the demo sim's view
 * and its hud_draw first. */
void hud_draw(const struct sim *s, const struct hud_env *env, struct r_frame *f);

/* Marks in want_pics (tex_want_sprite) the sprites the HUD draws: the
 * weapons and their flashes. For a set loaded by tex_load_wad_names. */
void hud_want(const struct tex_set *t, uint8_t *want_pics);

/* Text scale for a frame: 1 per 240 lines (and per 320 columns), at least 1. */
int hud_scale(const struct r_frame *f);

/* The minimap's square on the frame: top right, a third of the height. */
void hud_minimap_rect(const struct r_frame *f, int *x, int *y, int *size);

#endif
