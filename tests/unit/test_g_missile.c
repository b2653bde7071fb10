/* Tests for engine/game/g_missile.c: the thrower's missile flies at its
 * speed, hits the player only when it arrives, explodes on walls (also on a
 * two-sided line whose opening it does not fit in), on the floor, and is
 * removed after its explosion. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "g_fixture.h"

#define U(v) fx_from_int(v)

static const struct sim_settings normal = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
static const struct sim_cmd idle = { 0 };

static struct map *arena(const struct gf_thing *th, int n)
{
	struct map *m = gf_arena(th, n, NULL, 0);

	assert_non_null(m);
	return m;
}

/* A missile placed by hand at (x, y, z) with momentum (mx, 0, mz). */
static void put(struct sim *s, fx_t x, fx_t y, fx_t z, fx_t mx, fx_t mz)
{
	s->g.num_missiles = 1;
	s->g.ms[0] = (struct g_missile){ 0 };
	s->g.ms[0].x = x;
	s->g.ms[0].y = y;
	s->g.ms[0].z = z;
	s->g.ms[0].momx = mx;
	s->g.ms[0].momz = mz;
	s->g.ms[0].damage = U(10);
}

/* The imp is a thrower; 500 units east of the player it throws, and the
 * missile takes the distance over its speed to arrive: the player's body
 * (radius 16) meets the ball's (6) when the centres are 22 apart, i.e.
 * after (500 - 22) / 5.833 = 81.9, so on its 82nd step. It makes its
 * first step on the throw's tick, so the 82nd is 81 ticks later. Until
 * then the player is unhurt; then the kind's 10 points go. */
static void a_thrown_missile_hits_when_it_arrives(void **state)
{
	static const struct gf_thing t[] = { { 628, 256, ANG180, 3001, 0 } };
	struct map *m = arena(t, 1);
	struct sim s;
	fx_t x0;
	int n;
	(void)state;
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.en[0].kind, G_THROWER);
	for (n = 0; n < 200 && s.g.num_missiles == 0; n++)
		sim_tick(&s, &idle);
	assert_int_equal(s.g.num_missiles, 1);
	assert_int_equal(g_missiles_flying(&s), 1);
	/* thrown from the thrower's centre, at G_MISSILE_LAUNCH, straight
	 * west, one step made */
	assert_int_equal(s.g.ms[0].x, U(628) - G_MISSILE_SPEED);
	/* level: the player's feet are on the thrower's floor */
	assert_int_equal(s.g.ms[0].momz, 0);
	assert_int_equal(s.g.ms[0].z, G_MISSILE_LAUNCH);
	assert_int_equal(s.g.ms[0].momx, -G_MISSILE_SPEED);
	assert_int_equal(s.g.ms[0].momy, 0);
	assert_int_equal(s.pl.health, G_HEALTH_MAX * FX_ONE);
	/* no second throw while this one is followed */
	s.g.en[0].timer = 1000;
	x0 = s.g.ms[0].x;
	sim_tick(&s, &idle);
	assert_int_equal(s.g.ms[0].x, x0 - G_MISSILE_SPEED);
	for (n = 2; n < 81; n++)
		sim_tick(&s, &idle);
	assert_int_equal(g_missiles_flying(&s), 1);
	assert_int_equal(s.pl.health, G_HEALTH_MAX * FX_ONE);
	sim_tick(&s, &idle);                    /* 81 ticks after the throw */
	assert_int_equal(g_missiles_flying(&s), 0);
	assert_int_equal(s.g.mend, G_MEND_PLAYER);
	assert_int_equal(s.pl.health, (G_HEALTH_MAX - 10) * FX_ONE);
	/* its explosion shows, harmless, then it is gone */
	assert_int_equal(s.g.num_missiles, 1);
	assert_int_equal(s.g.ms[0].boom, G_MISSILE_BOOM);
	for (n = 0; n < G_MISSILE_BOOM - 1; n++)
		sim_tick(&s, &idle);
	assert_int_equal(s.g.num_missiles, 1);
	sim_tick(&s, &idle);
	assert_int_equal(s.g.num_missiles, 0);
	assert_int_equal(s.pl.health, (G_HEALTH_MAX - 10) * FX_ONE);
	map_free(m);
}

/* Flying east from x 1900 towards the wall at 2048: the ball (radius 6)
 * would touch it past x 2042, which the 25th step (1900 + 25 * 5.833 =
 * 2045.8) reaches: it explodes where the 24th left it, before the wall. */
static void a_missile_explodes_on_a_wall(void **state)
{
	struct map *m = arena(NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	put(&s, U(1900), U(400), U(32), G_MISSILE_SPEED, 0);
	for (int n = 0; n < 24; n++)
		sim_tick(&s, &idle);
	assert_int_equal(g_missiles_flying(&s), 1);
	assert_int_equal(s.g.mend, G_MEND_NONE);
	sim_tick(&s, &idle);
	assert_int_equal(g_missiles_flying(&s), 0);
	assert_int_equal(s.g.mend, G_MEND_WALL);
	assert_int_equal(s.g.ms[0].x, U(1900) + 24 * G_MISSILE_SPEED);
	assert_true(s.g.ms[0].x < U(2048 - 6));
	assert_int_equal(s.pl.health, G_HEALTH_MAX * FX_ONE);
	map_free(m);
}

/* Falling 4 units a tick from 32: below the floor on the 9th tick. */
static void a_missile_explodes_on_the_floor(void **state)
{
	struct map *m = arena(NULL, 0);
	struct sim s;
	(void)state;
	sim_init(&s, m, &normal);
	put(&s, U(1000), U(400), U(32), 0, -U(4));
	for (int n = 0; n < 8; n++)
		sim_tick(&s, &idle);
	assert_int_equal(g_missiles_flying(&s), 1);
	sim_tick(&s, &idle);
	assert_int_equal(g_missiles_flying(&s), 0);
	assert_int_equal(s.g.mend, G_MEND_PLANE);
	assert_int_equal(s.g.ms[0].z, 0);
	map_free(m);
}

/* ARENA1's window (x 640..656, y 128..256; floor 40, ceiling 88, between
 * the hall and the yard, both lower and higher): a ball at 60 (60..68)
 * fits its opening and flies through into the yard; one at 20 meets the
 * window's lower wall (40 above it) and explodes in the hall. */
static void a_window_passes_a_missile_that_fits_it(void **state)
{
	struct map *m;
	struct sim s;
	(void)state;
	assert_int_equal(lvl_builtin(0, &m), 0);
	sim_init(&s, m, &normal);
	put(&s, U(600), U(192), U(60), G_MISSILE_SPEED, 0);
	for (int n = 0; n < 20; n++)
		sim_tick(&s, &idle);
	assert_int_equal(g_missiles_flying(&s), 1);
	assert_true(s.g.ms[0].x > U(656 + 6));
	put(&s, U(600), U(192), U(20), G_MISSILE_SPEED, 0);
	for (int n = 0; n < 20; n++)
		sim_tick(&s, &idle);
	assert_int_equal(g_missiles_flying(&s), 0);
	assert_int_equal(s.g.mend, G_MEND_WALL);
	assert_true(s.g.ms[0].x < U(640));
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_thrown_missile_hits_when_it_arrives),
		cmocka_unit_test(a_missile_explodes_on_a_wall),
		cmocka_unit_test(a_missile_explodes_on_the_floor),
		cmocka_unit_test(a_window_passes_a_missile_that_fits_it),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
