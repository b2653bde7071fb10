/* Tests for engine/game/g_enemy.c: waking by hearing (g_noise, the
 * player's shot): idle enemies in the sectors the sound reaches wake
 * unless deaf (the map's ambush flag); a closed sector stops the sound.
 * The grunt's wind-up (its telegraph before the shot); the flyer's height,
 * circling and fall, and its own cries (sight, charge, pain, death). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "g_fixture.h"

static const struct sim_settings normal = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
static const struct sim_cmd fire = { .buttons = SIM_BT_FIRE };

/* In one room, behind a pillar (out of sight) and 1800 units away: the
 * shot wakes the grunt that can hear, not the deaf one beside it. */
static void a_shot_wakes_the_hearing_not_the_deaf(void **state)
{
	static const struct gf_box pillar = { 1000, 0, 1100, 480 };
	static const struct gf_thing t[] = { { 1900, 100, 0, 3004, 0 },
					     { 1900, 300, 0, 3004, G_TF_AMBUSH } };
	struct map *m = gf_arena(t, 2, &pillar, 1);
	struct sim s;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.en[0].state, G_E_IDLE);
	assert_int_equal(s.g.en[1].state, G_E_IDLE);
	assert_false(g_sight(&s, s.pl.x, s.pl.y, s.pl.viewz, s.g.en[0].x, s.g.en[0].y,
			     s.g.en[0].z + g_kinds[G_GRUNT].eye));
	sim_tick(&s, &fire);                    /* the shot hits the pillar */
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_int_equal(s.g.en[0].state, G_E_CHASE);
	assert_int_equal(s.g.en[1].state, G_E_IDLE);
	map_free(m);
}

/* ARENA2: four arms round the court. With the north arm shut (its ceiling
 * down on its floor, as a closed door), the player's shot in the south arm
 * wakes the enemies of the other arms, and none in the north. */
static void a_closed_sector_stops_the_sound(void **state)
{
	struct map *m;
	struct sim s;
	int north = 0, woke = 0;
	(void)state;
	assert_int_equal(lvl_builtin(1, &m), 0);
	sim_init(&s, m, &normal);
	s.w.sec[3].ceil_h = s.w.sec[3].floor_h;    /* NORTH, the 4th sector */
	for (int i = 0; i < s.g.num_enemies; i++)
		assert_int_equal(s.g.en[i].state, G_E_IDLE);
	g_noise(&s);
	for (int i = 0; i < s.g.num_enemies; i++) {
		const struct g_enemy *e = &s.g.en[i];
		if (e->sector == 3) {
			north++;
			assert_int_equal(e->state, G_E_IDLE);
		} else {
			woke++;
			assert_int_equal(e->state, G_E_CHASE);
		}
	}
	assert_int_equal(north, 3);             /* 2 grunts and the thrower */
	assert_true(woke >= 4);
	/* open again: the north hears too */
	s.w.sec[3].ceil_h = s.w.sec[3].floor_h + 128 * FX_ONE;
	g_noise(&s);
	for (int i = 0; i < s.g.num_enemies; i++)
		assert_int_equal(s.g.en[i].state, G_E_CHASE);
	map_free(m);
}

static const struct sim_cmd idle_cmd = { 0 };

static int g_channels_playing(const struct sim *s, int sfx)
{
	int n = 0;

	for (int k = 0; k < G_SND_CHANNELS; k++)
		n += s->snd.ch[k].sfx == sfx;
	return n;
}

/* Every wind-up fits in its countdowns (g_kind.c's rule): the cry at
 * `windup` left is after the attack starts and before it ends. */
static void every_windup_is_shorter_than_its_countdowns(void **state)
{
	(void)state;
	assert_int_equal(g_kinds[G_GRUNT].windup, G_GRUNT_WINDUP);
	for (int k = 0; k < G_KINDS; k++) {
		if (!g_kinds[k].windup)
			continue;
		assert_true(g_kinds[k].windup < g_kinds[k].reaction);
		assert_true(g_kinds[k].windup < g_kinds[k].period);
	}
}

/* A grunt 472 units east of the player (its range is 512), in sight: it
 * stands in its attack `reaction - windup` ticks, then winds up (the
 * aiming frame, g_enemy_winding, and its wind-up cry start together) for
 * G_GRUNT_WINDUP ticks with the player unhurt, and shoots at their end:
 * the player loses the grunt's damage (5 at difficulty 1) on the tick
 * after the last wind-up tick, `reaction` ticks after the attack began. */
static void the_grunt_winds_up_then_shoots(void **state)
{
	static const struct gf_thing t[] = { { 600, 256, ANG180, 3004, 0 } };
	struct map *m = gf_arena(t, 1, NULL, 0);
	const struct g_kind_info *k = &g_kinds[G_GRUNT];
	struct sim s;
	int n = 0, wound = -1, shot = -1;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	while (s.g.en[0].state != G_E_ATTACK && n++ < 100)
		sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].state, G_E_ATTACK);
	assert_false(g_enemy_winding(&s.g.en[0]));
	for (int t2 = 1; t2 <= k->reaction; t2++) {
		sim_tick(&s, &idle_cmd);
		if (wound < 0 && g_enemy_winding(&s.g.en[0])) {
			wound = t2;
			assert_int_equal(g_channels_playing(&s, SFX_GRUNT_WINDUP), 1);
		}
		if (shot < 0 && s.pl.health < G_HEALTH_MAX * FX_ONE)
			shot = t2;
		if (wound < 0)
			assert_int_equal(g_channels_playing(&s, SFX_GRUNT_WINDUP), 0);
	}
	assert_int_equal(wound, k->reaction - k->windup);
	assert_int_equal(shot, k->reaction);
	assert_int_equal(s.pl.health, (G_HEALTH_MAX - k->damage) * FX_ONE);
	assert_false(g_enemy_winding(&s.g.en[0]));
	assert_int_equal(s.g.en[0].flash, 8);     /* the firing frame */
	map_free(m);
}

/* The player gone out of its range during the wind-up (moved 1400 units
 * away): the grunt goes back to the chase, and no shot comes at the
 * wind-up's end. (Out of sight instead: tests/script/grunt_dodge.scr.) */
static void a_grunt_whose_target_leaves_does_not_shoot(void **state)
{
	static const struct gf_thing t[] = { { 600, 256, ANG180, 3004, 0 } };
	struct map *m = gf_arena(t, 1, NULL, 0);
	const struct g_kind_info *k = &g_kinds[G_GRUNT];
	struct sim s;
	int n = 0;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	while (!g_enemy_winding(&s.g.en[0]) && n++ < 200)
		sim_tick(&s, &idle_cmd);
	assert_true(g_enemy_winding(&s.g.en[0]));
	s.pl.x = fx_from_int(2000);
	for (int t2 = 0; t2 < k->windup + 4; t2++)
		sim_tick(&s, &idle_cmd);
	assert_int_equal(s.pl.health, G_HEALTH_MAX * FX_ONE);
	assert_int_equal(s.g.en[0].state, G_E_CHASE);
	map_free(m);
}

/* The flyer (3006) spawns G_FLY_SPAWN over its floor; awake, it sinks or
 * climbs G_FLY_CLIMB a tick to G_FLY_ABOVE over the player's feet, never
 * above its ceiling less its body's height. */
static void a_flyer_flies_to_the_players_height(void **state)
{
	static const struct gf_thing t[] = { { 900, 256, ANG180, 3006, 0 } };
	struct map *m = gf_arena(t, 1, NULL, 0);
	struct sim s;
	fx_t z0;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.en[0].kind, G_FLYER);
	assert_int_equal(s.g.en[0].z, G_FLY_SPAWN);
	for (int n = 0; n < 10 && s.g.en[0].state == G_E_IDLE; n++)
		sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].state, G_E_CHASE);
	for (int n = 0; n < 8; n++)
		sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].z, s.pl.z + G_FLY_ABOVE);   /* 24 -> 16 in 4 ticks */
	/* the player lifted (as on a lift): the flyer climbs 2 a tick ... */
	s.pl.z = 40 * FX_ONE;
	z0 = s.g.en[0].z;
	sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].z, z0 + G_FLY_CLIMB);
	/* ... up to the ceiling (128) less its 56-unit body, not above */
	s.pl.z = 100 * FX_ONE;
	for (int n = 0; n < 60; n++)
		sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].z, 128 * FX_ONE - G_BODY_HEIGHT);
	map_free(m);
}

/* Bearing of enemy e from the player, in degrees. */
static int bearing(const struct sim *s, const struct g_enemy *e)
{
	return (int)(((uint64_t)tab_atan2(e->y - s->pl.y, e->x - s->pl.x) * 360u) >> 32);
}

/* Within G_FLY_ORBIT the flyer circles in: from 180 units east of the
 * player it comes nearer while going round (its bearing turns by more
 * than 45 degrees before it is in bite range), where a brute on the same
 * spot walks straight in (its bearing stays). Then it bites. */
static void a_flyer_circles_in_and_bites(void **state)
{
	static const struct gf_thing t[] = { { 308, 256, ANG180, 3006, 0 } };
	static const struct gf_thing b[] = { { 308, 256, ANG180, 3002, 0 } };
	struct map *m = gf_arena(t, 1, NULL, 0), *mb = gf_arena(b, 1, NULL, 0);
	struct sim s;
	int turned = 0, bit = 0;
	(void)state;
	assert_non_null(m);
	assert_non_null(mb);
	sim_init(&s, m, &normal);
	for (int n = 0; n < 300 && !bit; n++) {
		int a;
		sim_tick(&s, &idle_cmd);
		a = bearing(&s, &s.g.en[0]);
		if (a > 180)
			a = 360 - a;
		if (a > turned && s.g.en[0].state == G_E_CHASE)
			turned = a;
		bit = s.pl.health < G_HEALTH_MAX * FX_ONE;
	}
	assert_true(turned > 45);
	assert_true(bit);
	assert_int_equal(s.pl.health, (G_HEALTH_MAX - g_kinds[G_FLYER].damage) * FX_ONE);
	map_free(m);
	/* the brute: straight in, bearing 0 */
	sim_init(&s, mb, &normal);
	for (int n = 0; n < 60; n++) {
		int a;
		sim_tick(&s, &idle_cmd);
		a = bearing(&s, &s.g.en[0]);
		assert_true(a <= 1 || a >= 359);
	}
	map_free(mb);
}

/* The sound enemy i is making now (its source's channel), SFX_NONE for
 * none. */
static int g_cry_of(const struct sim *s, int i)
{
	for (int k = 0; k < G_SND_CHANNELS; k++)
		if (s->snd.ch[k].sfx != SFX_NONE && s->snd.ch[k].src == G_SRC_ENEMY(i))
			return s->snd.ch[k].sfx;
	return SFX_NONE;
}

/* The flyer cries its own sounds where the other kinds cry theirs: its
 * sight as it wakes, its charge as it bites, its pain when it flinches,
 * its death when it dies; never another kind's. */
static void a_flyer_cries_its_own_sounds(void **state)
{
	static const struct gf_thing t[] = { { 308, 256, ANG180, 3006, 0 } };
	struct map *m = gf_arena(t, 1, NULL, 0);
	struct sim s;
	int n = 0;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	assert_int_equal(g_cry_of(&s, 0), SFX_NONE);
	while (s.g.en[0].state == G_E_IDLE && n++ < 20)
		sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].state, G_E_CHASE);
	assert_int_equal(g_cry_of(&s, 0), SFX_FLYER_SIGHT);
	assert_int_equal(g_channels_playing(&s, SFX_SENTRY_SIGHT), 0);
	while (s.pl.health == G_HEALTH_MAX * FX_ONE && n++ < 400)
		sim_tick(&s, &idle_cmd);
	assert_true(s.pl.health < G_HEALTH_MAX * FX_ONE);
	assert_int_equal(g_cry_of(&s, 0), SFX_FLYER_ATTACK);
	assert_int_equal(g_channels_playing(&s, SFX_BRUTE_ATTACK), 0);
	g_hurt_enemy(&s, 0, 1);                   /* flinch chance 255/256 */
	assert_int_equal(s.g.en[0].state, G_E_PAIN);
	assert_int_equal(g_cry_of(&s, 0), SFX_FLYER_PAIN);
	g_hurt_enemy(&s, 0, 1000);
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	assert_int_equal(g_cry_of(&s, 0), SFX_FLYER_DEATH);
	sim_tick(&s, &idle_cmd);                  /* heard on the next tick too */
	assert_int_equal(g_cry_of(&s, 0), SFX_FLYER_DEATH);
	assert_int_equal(g_channels_playing(&s, SFX_SENTRY_DEATH), 0);
	map_free(m);
}

/* Killed in the air, the flyer falls G_FLY_FALL a tick to the floor. */
static void a_dead_flyer_falls(void **state)
{
	static const struct gf_thing t[] = { { 900, 256, ANG180, 3006, 0 } };
	struct map *m = gf_arena(t, 1, NULL, 0);
	struct sim s;
	(void)state;
	assert_non_null(m);
	sim_init(&s, m, &normal);
	assert_int_equal(s.g.en[0].z, G_FLY_SPAWN);
	g_hurt_enemy(&s, 0, 1000);
	assert_int_equal(s.g.en[0].state, G_E_DEAD);
	sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].z, G_FLY_SPAWN - G_FLY_FALL);
	for (int n = 0; n < 10; n++)
		sim_tick(&s, &idle_cmd);
	assert_int_equal(s.g.en[0].z, 0);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(every_windup_is_shorter_than_its_countdowns),
		cmocka_unit_test(the_grunt_winds_up_then_shoots),
		cmocka_unit_test(a_grunt_whose_target_leaves_does_not_shoot),
		cmocka_unit_test(a_flyer_flies_to_the_players_height),
		cmocka_unit_test(a_flyer_circles_in_and_bites),
		cmocka_unit_test(a_dead_flyer_falls),
		cmocka_unit_test(a_flyer_cries_its_own_sounds),
		cmocka_unit_test(a_shot_wakes_the_hearing_not_the_deaf),
		cmocka_unit_test(a_closed_sector_stops_the_sound),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
