/* Tests for engine/render/r_game.c: the sprites handed to the renderer, with the
 * project's own texture set (its own pictures, stand-ins for the monsters
 * and pickups it has none of, and the fallback). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_game.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/tex.h"
#include "engine/map/mesh_builtin.h"
#include "engine/map/th.h"
#include "engine/render/r_game.h"
#include "engine/render/r_main.h"
#include "g_fixture.h"
#include "map_fixture.h"

static const struct sim_settings play = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };

static void sprites_follow_the_state(void **state)
{
	static const struct gf_thing t[] = {
		{ 100, 100, 0, 1, 0 },
		{ 300, 100, ANG180, 3004, 0 },               /* zombieman: POSS */
		{ 400, 100, ANG180, 3001, 0 },               /* imp: TROO */
		{ 460, 100, ANG180, 3003, 0 },               /* baron: BOSS, not in the set */
		{ 500, 100, 0, 2012, 0 },                    /* medikit */
		{ 600, 100, 0, 2048, 0 },                    /* bullets: AMMO */
		{ 650, 100, 0, 2008, 0 },                    /* shells: SHEL, not in the set */
		{ 700, 100, 0, 2028, 0 },                    /* floor lamp: a mesh */
		{ 800, 100, 0, TH_LIGHT_FIRST + 7, 0 },      /* arcaded light: invisible */
		{ 900, 100, 0, 11, 0 },                      /* deathmatch start: not in this game */
	};
	struct map *m = gf_room(1024, 256, t, 10, NULL, 0);
	struct tex_set *ts;
	struct r_sprite out[16];
	struct sim s;
	int n, poss, troo, medi, ammo, clip, colu, keep;
	(void)state;
	assert_non_null(m);
	assert_int_equal(tex_builtin(&ts), 0);
	poss = tex_find_sprite(ts, "POSS");
	troo = tex_find_sprite(ts, "TROO");
	medi = tex_find_sprite(ts, "MEDI");
	ammo = tex_find_sprite(ts, "AMMO");
	clip = tex_find_sprite(ts, "CLIP");
	colu = tex_find_sprite(ts, "COLU");
	assert_true(poss >= 0 && troo >= 0 && medi >= 0 && ammo >= 0 && clip >= 0 && colu >= 0);
	/* else the stand-ins are not tested */
	assert_true(tex_find_sprite(ts, "BOSS") < 0 && tex_find_sprite(ts, "SHEL") < 0);
	sim_init(&s, m, &play);
	assert_int_equal(r_game_sprites(&s, NULL, NULL, out, 16), 0);
	n = r_game_sprites(&s, ts, NULL, out, 16);
	assert_int_equal(n, 7);                         /* 3 enemies, 3 pickups, the lamp */
	assert_int_equal(out[0].sprite, poss);
	assert_int_equal(out[0].x, fx_from_int(300));
	assert_int_equal(out[0].angle, ANG180);
	assert_int_equal(out[0].frame, 0);
	assert_int_equal(out[1].sprite, troo);
	assert_int_equal(out[2].sprite, poss);          /* the baron's stand-in */
	assert_int_equal(out[3].sprite, medi);
	assert_int_equal(out[4].sprite, ammo);
	assert_int_equal(out[5].sprite, clip);          /* the shells' stand-in */
	/* the lamp is its mesh, in brass, lit by its sector (not full bright:
	 * the Lambert term shows its shape), turned by the tick alone: a
	 * quarter turn (less the rounding of ANG90 / 35) a second */
	assert_int_equal(out[6].mesh, MESH_B_LAMP);
	assert_int_equal(out[6].colour, pal_nearest(&ts->pal, 232, 176, 64));
	assert_int_equal(out[6].flags, 0);
	assert_int_equal(out[6].x, fx_from_int(700));
	assert_int_equal(out[6].angle, (ang_t)(s.tick * (ANG90 / 35)));
	for (int i = 0; i < 6; i++)
		assert_int_equal(out[i].mesh, 0);
	s.tick += 35;
	n = r_game_sprites(&s, ts, NULL, out, 16);
	assert_int_equal(out[6].angle - (ang_t)(s.tick * (ANG90 / 35)), 0);
	assert_true(out[6].angle - (ang_t)((s.tick - 35) * (ANG90 / 35)) == ANG90 - ANG90 % 35);
	s.tick -= 35;
	(void)colu;
	/* max is respected */
	assert_int_equal(r_game_sprites(&s, ts, NULL, out, 2), 2);
	/* a taken pickup is not drawn; a corpse is drawn at its last death
	 * frame (Doom's dead zombieman, thing 18, is POSS frame L), unless the
	 * sprite has no such frame (the baron's corpse, frame O, on POSS) */
	s.g.pk[0].taken = 1;
	s.g.en[0].state = G_E_DEAD;
	s.g.en[0].anim = 1000;
	s.g.en[2].state = G_E_DEAD;
	s.g.en[2].anim = 1000;
	n = r_game_sprites(&s, ts, NULL, out, 16);
	assert_int_equal(n, 5);
	assert_int_equal(out[0].x, fx_from_int(300));
	assert_int_equal(out[0].frame, th_find(18)->frame - 'A');
	assert_int_equal(out[1].x, fx_from_int(400));
	assert_int_equal(out[2].x, fx_from_int(600));
	/* attacking with the muzzle flash: the frame after the attack's,
	 * full bright (the imp's attack is Doom's F, its flash G) */
	s.g.en[1].state = G_E_ATTACK;
	s.g.en[1].flash = 3;
	n = r_game_sprites(&s, ts, NULL, out, 16);
	assert_int_equal(out[1].frame, 'G' - 'A');
	assert_int_equal(out[1].flags, R_SPR_FULLBRIGHT);
	/* a frame the stand-in lacks is drawn as frame A (an arch-vile's pain,
	 * frame Q, on POSS, which ends at L) */
	s.g.en[2].state = G_E_PAIN;
	s.g.en[2].type = 64;
	n = r_game_sprites(&s, ts, NULL, out, 16);
	assert_int_equal(n, 6);
	assert_int_equal(out[2].sprite, poss);
	assert_int_equal(out[2].frame, 0);
	/* a set without the sprite or its stand-in: one past the end, which
	 * the renderer draws as its fallback checker */
	keep = ts->num_sprites;
	ts->num_sprites = 0;
	n = r_game_sprites(&s, ts, NULL, out, 16);
	assert_int_equal(n, 6);
	for (int i = 0; i < n; i++)
		assert_int_equal(out[i].sprite, 0);
	ts->num_sprites = keep;
	tex_free(ts);
	map_free(m);
}

/* The built-in set draws every frame the game asks of the monsters the
 * built-in levels hold (g_thing_info: walking, attack and flash, pain,
 * every death frame to the corpse): each of its own, none the fallback,
 * and the walking frames seen from the front and the back differ. */
static void builtin_monsters_have_every_frame_the_game_shows(void **state)
{
	static const uint16_t types[] = { 3004, 9, 3001, 3002, 3005 };
	struct tex_set *ts;
	(void)state;
	assert_int_equal(tex_builtin(&ts), 0);
	for (size_t i = 0; i < sizeof types / sizeof types[0]; i++) {
		struct g_thing_info ti;
		const struct tex_sprite *sp;
		int k;
		g_thing_info(types[i], &ti);
		k = tex_find_sprite(ts, ti.sprite);
		assert_true(k >= 0);
		sp = &ts->sprites[k];
		assert_int_equal(sp->num_frames, ti.death1 + 1);
		assert_true(ti.attack + 1 < ti.death1 && ti.pain < ti.death1);
		for (int f = 0; f < sp->num_frames; f++)
			for (int r = 0; r < 8; r++)
				assert_int_not_equal(sp->frames[f].pic[r], 0);
		for (int f = 0; f < ti.frames; f++)
			assert_int_not_equal(sp->frames[f].pic[0], sp->frames[f].pic[4]);
	}
	assert_int_equal(ts->missing, 0);
	tex_free(ts);
}

/* Two rooms side by side, 0..128 and 128..256 by 0..128, sectors 0 and 1,
 * the line at x = 128 the portal between them. */
static const int two_v[][2] = {
	{ 0, 0 }, { 0, 128 }, { 128, 128 }, { 128, 0 }, { 256, 128 }, { 256, 0 },
};
static const struct fix_line two_l[] = {
	{ 0, 1, 0, -1 }, { 1, 2, 0, -1 }, { 2, 3, 0, 1 }, { 3, 0, 0, -1 },
	{ 2, 4, 1, -1 }, { 4, 5, 1, -1 }, { 5, 3, 1, -1 },
};

/* Issue 13 item 9: heights at the bound map_finish allows (+/-16383
 * units) play and draw with no overflow: the eye height, the renderer's
 * height differences, sight and shots between a floor at the bottom and a
 * ceiling at the top. Run by the sanitizer build, where any signed
 * overflow aborts the test. Two rooms (a portal at x = 128), the player in
 * one and a zombieman in the other, once with the player low and once
 * high; 120 ticks walking forward and firing, each drawn. */
static void heights_at_the_bound_play_and_draw_without_overflow(void **state)
{
	static const struct fix_sector low[] = { { -16383, 16383, 160 }, { 16300, 16383, 200 } };
	static const struct fix_sector high[] = { { 16300, 16383, 160 }, { -16383, 16383, 200 } };
	const struct fix_sector *sets[2] = { low, high };
	struct tex_set *ts;
	struct r_ctx *r;
	struct r_frame f = { 0 };
	(void)state;
	assert_int_equal(tex_builtin(&ts), 0);
	assert_int_equal(r_new(160, 120, &r), 0);
	f.w = 160;
	f.h = 120;
	f.pitch = 160;
	f.px = malloc(160 * 120);
	assert_non_null(f.px);
	for (int k = 0; k < 2; k++) {
		struct fix_map fm = { two_v, 6, sets[k], 2, two_l, 7, 32, 64, 0 };
		char err[160];
		struct map *m = fix_alloc(&fm);
		struct sim s;

		assert_non_null(m);
		/* a zombieman in the second room, facing the player */
		m->num_things = 1;
		assert_int_equal(map_finish(m, err, sizeof err), 0);
		m->things = realloc(m->things, 2 * sizeof *m->things);
		assert_non_null(m->things);
		m->things[1] = (struct map_thing){ fx_from_int(200), fx_from_int(64), ANG180, 3004, 7 };
		m->num_things = 2;
		sim_init(&s, m, &play);
		for (int t = 0; t < 120; t++) {
			struct sim_cmd c = { 40, 0, (int16_t)(t % 40 < 20 ? 200 : -200),
					     (uint8_t)(t % 10 == 0), 0 };
			struct r_view rv;

			sim_tick(&s, &c);
			r_game_view(&s, f.w, &rv);
			r_render(r, m, ts, &rv, NULL, 0, &f);
		}
		assert_true(s.pl.viewz == s.pl.z + SIM_VIEW_HEIGHT || s.pl.health <= 0);
		map_free(m);
	}
	free(f.px);
	r_free(r);
	tex_free(ts);
}

/* A decoration stands on the floor of the room it is in: two rooms with
 * floors 0 and 64 (a portal at x = 128), a candle in each. (The renderer
 * takes its sector from map_finish's thing_sec.) */
static void decorations_stand_on_their_own_floor(void **state)
{
	static const struct fix_sector sec[] = { { 0, 128, 160 }, { 64, 192, 200 } };
	static const struct fix_thing th[] = {
		{ 64, 96, 0, 34, 7 }, { 200, 96, 0, 34, 7 },   /* candles */
	};
	struct fix_map fm = { two_v, 6, sec, 2, two_l, 7, 32, 32, 0 };
	struct map *m = fix_alloc_things(&fm, th, 2);
	struct tex_set *ts;
	struct r_sprite out[8];
	struct sim s;
	int n, seen = 0;
	(void)state;

	assert_non_null(m);
	assert_int_equal(map_finish(m, NULL, 0), 0);
	assert_int_equal(tex_builtin(&ts), 0);
	sim_init(&s, m, &play);
	n = r_game_sprites(&s, ts, NULL, out, 8);
	for (int i = 0; i < n; i++) {
		if (out[i].y != fx_from_int(96))
			continue;
		assert_int_equal(out[i].z, out[i].x < fx_from_int(128) ? 0 : fx_from_int(64));
		seen++;
	}
	assert_int_equal(seen, 2);
	map_free(m);
	tex_free(ts);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sprites_follow_the_state),
		cmocka_unit_test(builtin_monsters_have_every_frame_the_game_shows),
		cmocka_unit_test(heights_at_the_bound_play_and_draw_without_overflow),
		cmocka_unit_test(decorations_stand_on_their_own_floor),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
