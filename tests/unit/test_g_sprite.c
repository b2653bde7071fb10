/* Tests for engine/g_sprite.c: the sprites handed to the renderer, with the
 * project's own texture set (few sprites: stand-ins and fallbacks). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/map.h"
#include "engine/r_main.h"
#include "engine/sim.h"
#include "engine/tex.h"
#include "engine/th.h"
#include "g_fixture.h"

static const struct sim_settings play = { 1, 0, 1, 1, 3 };

static void sprites_follow_the_state(void **state)
{
	static const struct gf_thing t[] = {
		{ 100, 100, 0, 1, 0 },
		{ 300, 100, ANG180, 3004, 0 },               /* zombieman: POSS */
		{ 400, 100, ANG180, 3001, 0 },               /* imp: TROO, not in the set */
		{ 500, 100, 0, 2012, 0 },                    /* medikit */
		{ 600, 100, 0, 2048, 0 },                    /* bullets: AMMO, not in the set */
		{ 700, 100, 0, 2028, 0 },                    /* floor lamp COLU */
		{ 800, 100, 0, TH_LIGHT_FIRST + 7, 0 },      /* arcaded light: invisible */
		{ 900, 100, 0, 5, 0 },                       /* a key: not in this game */
	};
	struct map *m = gf_room(1024, 256, t, 8, NULL, 0);
	struct tex_set *ts;
	struct r_sprite out[16];
	struct sim s;
	int n, poss, medi, colu;
	(void)state;
	assert_non_null(m);
	assert_int_equal(tex_builtin(&ts), 0);
	poss = tex_find_sprite(ts, "POSS");
	medi = tex_find_sprite(ts, "MEDI");
	colu = tex_find_sprite(ts, "COLU");
	assert_true(poss >= 0 && medi >= 0 && colu >= 0);
	assert_true(tex_find_sprite(ts, "TROO") < 0);   /* else the stand-in is not tested */
	sim_init(&s, m, &play);
	assert_int_equal(g_sprites(&s, NULL, out, 16), 0);
	n = g_sprites(&s, ts, out, 16);
	assert_int_equal(n, 5);                         /* 2 enemies, 2 pickups, the lamp */
	assert_int_equal(out[0].sprite, poss);
	assert_int_equal(out[0].x, fx_from_int(300));
	assert_int_equal(out[0].angle, ANG180);
	assert_int_equal(out[0].frame, 0);
	assert_int_equal(out[1].sprite, poss);          /* the imp's stand-in */
	assert_int_equal(out[2].sprite, medi);
	assert_int_equal(tex_find_sprite(ts, "CLIP") < 0 ? 1 : 0, 1);
	assert_int_equal(out[3].sprite, ts->num_sprites);   /* no AMMO, no CLIP: fallback */
	assert_int_equal(out[4].sprite, colu);
	assert_int_equal(out[4].flags, R_SPR_FULLBRIGHT);
	/* max is respected */
	assert_int_equal(g_sprites(&s, ts, out, 2), 2);
	/* a taken pickup and a corpse the set has no frame for are not drawn */
	s.g.pk[0].taken = 1;
	s.g.en[0].state = G_E_DEAD;
	n = g_sprites(&s, ts, out, 16);
	assert_int_equal(n, 3);
	assert_int_equal(out[0].x, fx_from_int(400));
	/* attacking with the muzzle flash: the firing frame, full bright,
	 * drawn as frame A where the set lacks it */
	s.g.en[1].state = G_E_ATTACK;
	s.g.en[1].flash = 3;
	n = g_sprites(&s, ts, out, 16);
	assert_int_equal(out[0].frame, 0);
	assert_int_equal(out[0].flags, R_SPR_FULLBRIGHT);
	tex_free(ts);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(sprites_follow_the_state),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
