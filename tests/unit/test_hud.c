/* Tests for engine/ui/hud.c, hud_page.c and menu_draw.c: what the HUD draws
 * from the sim state (the minimap arrow, crosshair, warnings, weapon
 * flash, pages), and that it is a pure function of the state. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/pal.h"
#include "engine/core/tab.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/render/r_main.h"
#include "engine/ui/hud.h"
#include "engine/ui/v_video.h"
#include "g_fixture.h"

#define W 320
#define H 240
#define BG PAL_RGB(PAL_PINK, 8)        /* a colour the HUD never uses */

static struct pal pal;
static struct hud_colours col;
static struct map *room;
static uint8_t pix[W * H];
static struct r_frame frame = { pix, W, H, W, NULL };
static const struct sim_settings play = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };

static int setup(void **state)
{
	static const struct gf_thing t[] = { { 1024, 1024, 0, 1, 0 } };
	(void)state;
	pal_builtin(&pal);
	hud_colours(&pal, &col);
	room = gf_room(2048, 2048, t, 1, NULL, 0);
	return room ? 0 : -1;
}

static int teardown(void **state)
{
	(void)state;
	map_free(room);
	return 0;
}

static const struct hud_diag *diag;   /* the diagnostics text draw() passes */
static const char *notice;            /* and the configuration error's notice */
static const struct hud_colours *colours; /* and the colours made once, or NULL */

static void draw(const struct sim *s)
{
	struct hud_env env = { &pal, NULL, 0, NULL, diag, notice, colours };
	memset(pix, BG, sizeof(pix));
	hud_draw(s, &env, &frame);
}

static uint8_t at(int x, int y)
{
	return pix[y * W + x];
}

static int count_in(int x0, int y0, int w, int h, uint8_t c)
{
	int n = 0;
	for (int y = y0; y < y0 + h; y++)
		for (int x = x0; x < x0 + w; x++)
			n += at(x, y) == c;
	return n;
}

static void colours_are_distinct_and_from_the_palette(void **state)
{
	(void)state;
	assert_int_equal(pal.rgb[col.white][0], 255);
	assert_true(pal.rgb[col.red][0] > 150 && pal.rgb[col.red][1] < 100);
	assert_true(col.white != col.red && col.red != col.yellow && col.green != col.white);
	assert_true(col.white != BG && col.red != BG && col.black != BG);
}

/* The minimap's square in the test frame and the player's pixel in it. */
struct mm {
	int x, y, size, cx, cy;
};

static struct mm mm_square(void)
{
	struct mm m;

	hud_minimap_rect(&frame, &m.x, &m.y, &m.size);
	m.cx = m.x + m.size / 2;
	m.cy = m.y + m.size / 2;
	return m;
}

/* The arrow points along the view, north up: its tip 6 pixels (a twelfth
 * of the 80-pixel map) from the centre, its tail corners 4.5 pixels back
 * at 145 degrees, so about 3.7 behind. Its axis runs along pixel edges, so
 * the pixels tested are 3 ahead (inside) and 5 behind (outside). */
static void the_minimap_arrow_points_along_the_view(void **state)
{
	static const struct { ang_t a; int dx, dy; } dir[4] = {
		{ 0, 1, 0 }, { ANG90, 0, -1 }, { ANG180, -1, 0 }, { ANG270, 0, 1 },
	};
	struct mm m = mm_square();
	int cx = m.cx, cy = m.cy;
	struct sim s;
	(void)state;
	assert_int_equal(m.size, H / 3);
	for (int i = 0; i < 4; i++) {
		sim_init(&s, room, &play);
		s.pl.angle = dir[i].a;
		draw(&s);
		assert_int_equal(at(cx + 3 * dir[i].dx, cy + 3 * dir[i].dy), col.white);
		assert_true(at(cx - 5 * dir[i].dx, cy - 5 * dir[i].dy) != col.white);
		/* nothing white beyond the tip */
		assert_true(at(cx + 8 * dir[i].dx, cy + 8 * dir[i].dy) != col.white);
	}
}

static void the_minimap_shows_enemies_in_red_at_their_place(void **state)
{
	struct mm m = mm_square();
	int cx = m.cx, cy = m.cy;
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.g.num_enemies = 1;
	s.g.en[0] = (struct g_enemy){ .x = fx_from_int(1024 + 256), .y = fx_from_int(1024 + 128),
				      .kind = G_GRUNT, .state = G_E_IDLE };
	draw(&s);
	/* 1024 units across 80 pixels: +256 east is +20 x, +128 north is -10 y */
	assert_int_equal(at(cx + 20, cy - 10), col.red);
	s.g.en[0].state = G_E_DEAD;
	draw(&s);
	assert_true(at(cx + 20, cy - 10) != col.red);
}

/* The minimap skips a map line before projecting it when both ends lie
 * off its square on one side (hud_mm_far): a wall 500 units away, the
 * square's last column or row (it shows 512 either side), must still be
 * drawn. */
static void the_minimap_draws_walls_inside_its_square(void **state)
{
	struct mm m = mm_square();
	int cx = m.cx, cy = m.cy;
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	/* the room's walls are 1024 units from its middle: off the square */
	draw(&s);
	assert_true(at(cx + 39, cy) != col.grey);
	assert_true(at(cx, cy - 39) != col.grey);
	/* 500 units from the east wall (x 2048) and the north wall (y 2048):
	 * 500 of 1024 units across 80 pixels is 39.06, so 39 pixels: the
	 * square's last column and its second row (under the border) */
	s.pl.x = fx_from_int(2048 - 500);
	s.pl.y = fx_from_int(2048 - 500);
	draw(&s);
	assert_int_equal(cx + 39, m.x + m.size - 1);
	assert_int_equal(at(cx + 39, cy), col.grey);
	assert_int_equal(at(cx, cy - 39), col.grey);
	/* and the west and south walls, 1548 units away, are not */
	assert_true(at(m.x, cy) != col.grey);
	assert_true(at(cx, m.y + m.size - 1) != col.grey);
}

/* hud_env.colours: the caller's colours made once draw what the palette
 * gives when they are hud_colours' own, and are the ones used. */
static void colours_made_once_are_the_ones_drawn(void **state)
{
	static uint8_t a[W * H];
	struct hud_colours mine;
	struct mm m = mm_square();
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.pl.x = fx_from_int(2048 - 400);
	s.g.score = 4242;
	draw(&s);
	memcpy(a, pix, sizeof(a));
	hud_colours(&pal, &mine);
	colours = &mine;
	draw(&s);
	assert_memory_equal(a, pix, sizeof(a));
	mine.grey = BG;
	draw(&s);
	colours = NULL;
	assert_int_equal(at(m.cx + 31, m.cy), BG);
	assert_int_equal(a[m.cy * W + m.cx + 31], col.grey);
}

static void the_crosshair_marks_the_centre(void **state)
{
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	draw(&s);
	assert_int_equal(at(W / 2, H / 2 - 4), col.white);
	assert_int_equal(at(W / 2 - 4, H / 2), col.white);
	assert_int_equal(at(W / 2, H / 2), BG);    /* open in the middle */
	/* red for a few ticks after a hit */
	s.g.shot = G_SHOT_ENEMY;
	s.g.shot_t = 2;
	draw(&s);
	assert_int_equal(at(W / 2, H / 2 - 4), col.red);
}

static void low_health_and_damage_show_in_red(void **state)
{
	struct sim s;
	int bar = 12, normal, low;
	(void)state;
	sim_init(&s, room, &play);
	draw(&s);
	normal = count_in(0, H - bar, W / 2, bar, col.red);
	assert_int_equal(at(0, 0), BG);
	s.pl.health = fx_from_int(20);
	draw(&s);
	low = count_in(0, H - bar, W / 2, bar, col.red);
	assert_true(low > normal + 20);
	s.pl.hurt = 5;
	draw(&s);
	assert_int_equal(at(0, 0), col.red);       /* the damage border */
	assert_int_equal(at(W - 1, H / 2), col.red);
}

static void a_shot_flashes_at_the_muzzle(void **state)
{
	struct sim s;
	int idle, fired;
	(void)state;
	sim_init(&s, room, &play);
	draw(&s);
	idle = count_in(W / 4, H / 2, W / 2, H / 2 - 12, col.yellow);
	s.g.shot_t = 0;
	s.g.shot = G_SHOT_WALL;
	draw(&s);
	fired = count_in(W / 4, H / 2, W / 2, H / 2 - 12, col.yellow);
	assert_true(fired > idle + 20);
}

static void the_score_is_drawn(void **state)
{
	struct sim s;
	uint8_t before[W * 12];
	(void)state;
	sim_init(&s, room, &play);
	draw(&s);
	memcpy(before, pix, sizeof(before));
	s.g.score = 123456;
	draw(&s);
	assert_true(memcmp(before, pix, sizeof(before)) != 0);
}

static void hud_is_a_pure_function_of_the_state(void **state)
{
	struct hud_env env = { &pal, NULL, 0, NULL, NULL, NULL, NULL };
	static uint8_t a[W * H];
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.g.score = 4242;
	draw(&s);
	memcpy(a, pix, sizeof(a));
	draw(&s);
	assert_memory_equal(a, pix, sizeof(a));
	/* pages without the world paint every pixel themselves */
	s.mode = SIM_INITIALS;
	s.ini_rank = 2;
	draw(&s);
	memcpy(a, pix, sizeof(a));
	memset(pix, 3, sizeof(pix));
	hud_draw(&s, &env, &frame);
	assert_memory_equal(a, pix, sizeof(a));
}

static void the_world_shows_under_play_gameover_and_attract_only(void **state)
{
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	assert_true(hud_world(&s));
	s.mode = SIM_GAMEOVER;
	assert_true(hud_world(&s));
	s.mode = SIM_ATTRACT;
	assert_true(hud_world(&s));
	s.mode = SIM_INITIALS;
	assert_false(hud_world(&s));
	s.mode = SIM_SERVICE;
	assert_false(hud_world(&s));
}

static void the_countdown_number_changes_the_picture(void **state)
{
	static uint8_t a[W * H];
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.mode = SIM_GAMEOVER;
	s.countdown = 600;
	draw(&s);
	memcpy(a, pix, sizeof(a));
	s.countdown = 599;                     /* still "10" on screen */
	draw(&s);
	assert_memory_equal(a, pix, sizeof(a));
	s.countdown = 540;                     /* "9" */
	draw(&s);
	assert_true(memcmp(a, pix, sizeof(a)) != 0);
}

static void the_input_test_lights_held_controls_green(void **state)
{
	struct sim s;
	int none, held;
	(void)state;
	sim_init(&s, room, &play);
	s.mode = SIM_SERVICE;
	s.menu.page = MENU_INPUT;
	draw(&s);
	none = count_in(0, 0, W, H, col.green);
	s.cmd.forward = 100;
	s.cmd.buttons = SIM_BT_FIRE;
	draw(&s);
	held = count_in(0, 0, W, H, col.green);
	assert_true(held > none + 2 * 40);     /* two names and two "ON" */
}

/* Pixels s draws at scale 1: its glyphs' set bits. */
static int text_pixels(const char *s)
{
	int n = 0;

	for (; *s; s++)
		for (int y = 0; y < 8; y++)
			for (int x = 0; x < 8; x++)
				n += v_glyph_bit(*s, x, y);
	return n;
}

/* The look buttons share one row, the twelfth (34 + 11 x 10 = 144 at
 * scale 1): "LOOK" and its state in green while held (UP, DOWN, CENTRE
 * for both, as the sim reads them), nothing green when neither is. */
static void the_input_test_shows_the_look_buttons(void **state)
{
	static const struct {
		uint8_t buttons;
		const char *state;
	} cases[] = {
		{ 0, NULL },
		{ SIM_BT_LOOK_UP, "UP" },
		{ SIM_BT_LOOK_DOWN, "DOWN" },
		{ SIM_BT_LOOK_UP | SIM_BT_LOOK_DOWN, "CENTRE" },
		{ SIM_BT_FIRE | SIM_BT_LOOK_DOWN, "DOWN" },
	};
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.mode = SIM_SERVICE;
	s.menu.page = MENU_INPUT;
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		s.cmd.buttons = cases[i].buttons;
		draw(&s);
		assert_int_equal(count_in(0, 144, W, 10, col.green),
				 cases[i].state ? text_pixels("LOOK") + text_pixels(cases[i].state) : 0);
		assert_true(count_in(0, 144, W, 10, col.white) >=
			    (cases[i].state ? 0 : text_pixels("LOOK")));
	}
}

/* The app gives d, a heading and a line, to the next draw(). */
static void give_lines(struct hud_diag *d, const char *heading, const char *line)
{
	memset(d, 0, sizeof(*d));
	strcpy(d->line[0], heading);
	strcpy(d->line[1], line);
	d->n = 2;
	diag = d;
}

/* The input test prints the app's lines (the devices' raw controls) under
 * the coins line: twelve action rows (LOOK the last) 10 lines apart
 * from 34, 4 more, the coins line (12): from line 170 at scale 1. */
static void the_input_test_prints_the_apps_lines_under_the_actions(void **state)
{
	static struct hud_diag d;
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.mode = SIM_SERVICE;
	s.menu.page = MENU_INPUT;
	diag = NULL;
	draw(&s);
	assert_true(count_in(0, 158, W, 10, col.yellow) > 20);        /* COINS 0 */
	assert_int_equal(count_in(0, 170, W, H - 170 - 14, col.yellow), 0);
	assert_int_equal(count_in(0, 170, W, H - 170 - 14, col.white), 0);
	give_lines(&d, "CONTROLS", "  EVDEV - KEY_UP DOWN -> FORWARD");
	draw(&s);
	assert_true(count_in(0, 170, W, 10, col.yellow) > 8 * 8);
	assert_true(count_in(0, 180, W, 10, col.white) > 20 * 8);
	assert_int_equal(count_in(0, 190, W, H - 190 - 14, col.white), 0);
	diag = NULL;
}

static void every_menu_page_draws_something(void **state)
{
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.mode = SIM_SERVICE;
	for (int p = 0; p < MENU_PAGES; p++) {
		for (int d = 0; d < MENU_D_COUNT; d++) {
			s.menu.page = (uint8_t)p;
			s.menu.display = (uint8_t)d;
			draw(&s);
			assert_int_equal(count_in(0, 0, W, H, BG), 0);    /* all repainted */
			assert_true(count_in(0, 0, W, H, col.black) < W * H - 500);
		}
	}
}

/* DEVICES and LATENCY print the app's lines below the title (34 lines
 * down at scale 1), 10 lines apart at scale 1: a heading (no blank first)
 * in yellow, the others in white; without lines, NOTHING TO SHOW in grey. */
static void the_diagnostics_pages_print_the_apps_lines(void **state)
{
	static struct hud_diag d;
	static const uint8_t pages[2] = { MENU_DEVICES, MENU_LATENCY };
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	s.mode = SIM_SERVICE;
	for (int p = 0; p < 2; p++) {
		s.menu.page = pages[p];
		diag = NULL;
		draw(&s);
		assert_true(count_in(0, 34, W, 10, col.grey) > 40);
		assert_int_equal(count_in(0, 34, W, H - 60, col.yellow), 0);
		assert_int_equal(count_in(0, 34, W, H - 60, col.white), 0);
		give_lines(&d, "EVDEV", "  /DEV/INPUT/EVENT3");
		draw(&s);
		assert_int_equal(count_in(0, 34, W, 10, col.grey), 0);
		assert_true(count_in(0, 34, W, 10, col.yellow) > 5 * 8);
		assert_int_equal(count_in(0, 34, W, 10, col.white), 0);
		assert_true(count_in(0, 44, W, 10, col.white) > 17 * 8);
		assert_int_equal(count_in(0, 44, W, 10, col.yellow), 0);
		assert_int_equal(count_in(0, 54, W, H - 80, col.white), 0);  /* nothing more */
		d.n = 1;                       /* only the lines given */
		draw(&s);
		assert_int_equal(count_in(0, 44, W, 10, col.white), 0);
	}
	diag = NULL;
}

/* A configuration error not acknowledged (app text, hud_env.notice): red
 * text in a black band at the attract screen's foot (the 11 lines of one
 * text row at scale 1, with a line above it), and on the service menu's
 * MAIN page the text itself in red above the help line; nothing of it
 * without a notice. */
static void a_config_notice_shows_on_attract_and_main(void **state)
{
	struct sim s;
	int red_with, red_without;
	(void)state;
	sim_init(&s, room, &play);
	s.mode = SIM_ATTRACT;
	notice = NULL;
	draw(&s);
	red_without = count_in(0, H - 11, W, 11, col.red);
	notice = "/etc/arcaded/x.ini:2: lives: 12 out of range 1..9";
	draw(&s);
	red_with = count_in(0, H - 11, W, 11, col.red);
	assert_true(red_with > red_without + 100);
	/* the band: black where the text is not, from the first of its lines */
	assert_int_equal(at(0, H - 11), col.black);
	assert_int_equal(at(W - 1, H - 1), col.black);
	/* MAIN: the text's row is 24 lines above the bottom at scale 1 */
	s.mode = SIM_SERVICE;
	menu_enter(&s.menu);
	draw(&s);
	assert_true(count_in(0, H - 24, W, 8, col.red) > 100);
	notice = NULL;
	draw(&s);
	assert_int_equal(count_in(0, H - 24, W, 8, col.red), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(colours_are_distinct_and_from_the_palette),
		cmocka_unit_test(the_minimap_arrow_points_along_the_view),
		cmocka_unit_test(the_minimap_shows_enemies_in_red_at_their_place),
		cmocka_unit_test(the_minimap_draws_walls_inside_its_square),
		cmocka_unit_test(colours_made_once_are_the_ones_drawn),
		cmocka_unit_test(the_crosshair_marks_the_centre),
		cmocka_unit_test(low_health_and_damage_show_in_red),
		cmocka_unit_test(a_shot_flashes_at_the_muzzle),
		cmocka_unit_test(the_score_is_drawn),
		cmocka_unit_test(hud_is_a_pure_function_of_the_state),
		cmocka_unit_test(the_world_shows_under_play_gameover_and_attract_only),
		cmocka_unit_test(the_countdown_number_changes_the_picture),
		cmocka_unit_test(the_input_test_lights_held_controls_green),
		cmocka_unit_test(the_input_test_shows_the_look_buttons),
		cmocka_unit_test(every_menu_page_draws_something),
		cmocka_unit_test(the_diagnostics_pages_print_the_apps_lines),
		cmocka_unit_test(the_input_test_prints_the_apps_lines_under_the_actions),
		cmocka_unit_test(a_config_notice_shows_on_attract_and_main),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
