/*
 * g_sound: the sim's sounds. Volume and separation are Doom's rules with
 * numbers worked out by hand (g_sound.h: 127 within 200 units, 127 * (1200
 * - dist) / 1000 to 1200, separation 128 - 96 sin(angle)); one sound per
 * source; priorities and stealing; lengths; attract mode's setting; the
 * game's events start their sounds.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "engine/game/g_local.h"
#include "engine/game/g_sound.h"
#include "engine/game/sim.h"
#include "engine/sound/mix.h"
#include "engine/sound/snd.h"
#include "tests/unit/g_fixture.h"

#define U(v) fx_from_int(v)

static const struct sim_settings play = { 1, 0, 1, 1, 3, 100, 1, 0, 0, 0 };
static const struct sim_cmd idle = { 0 };

static struct map *room;

static int setup(void **state)
{
	/* player at (128, 256) facing east (angle 0); a grunt at (1900, 60) */
	static const struct gf_thing t[] = { { 128, 256, 0, 1, 0 }, { 1900, 60, 0, 3004, 0 } };

	(void)state;
	room = gf_room(2048, 512, t, 2, NULL, 0);
	return room ? 0 : -1;
}

static int teardown(void **state)
{
	(void)state;
	map_free(room);
	return 0;
}

static int playing(const struct sim *s)
{
	int n = 0;

	for (int i = 0; i < G_SND_CHANNELS; i++)
		n += s->snd.ch[i].sfx != SFX_NONE;
	return n;
}

/* The channel playing id, or NULL. */
static const struct g_schan *find(const struct sim *s, int id)
{
	for (int i = 0; i < G_SND_CHANNELS; i++)
		if (s->snd.ch[i].sfx == id)
			return &s->snd.ch[i];
	return NULL;
}

static void doom_volume_and_separation(void **state)
{
	struct sim s;
	const struct g_schan *c;
	(void)state;
	sim_init(&s, room, &play);
	/* 100 ahead: full volume, centred */
	c = &s.snd.ch[g_sound_start(&s, SFX_WALLHIT, U(228), U(256), 100)];
	assert_int_equal(c->vol, 127);
	assert_int_equal(c->sep, 128);
	/* 700 ahead: 127 * 500 / 1000 = 63.5 -> 63 */
	c = &s.snd.ch[g_sound_start(&s, SFX_WALLHIT, U(828), U(256), 101)];
	assert_int_equal(c->vol, 63);
	assert_int_equal(c->sep, 128);
	/* 500 to the left (north, the player faces east): 127 * 700 / 1000 =
	 * 88.9 -> 88; separation 128 - 96 = 32 */
	c = &s.snd.ch[g_sound_start(&s, SFX_WALLHIT, U(128), U(756), 102)];
	assert_int_equal(c->vol, 88);
	assert_int_equal(c->sep, 32);
	/* 500 to the right: 128 + 96 */
	c = &s.snd.ch[g_sound_start(&s, SFX_WALLHIT, U(128), U(-244), 103)];
	assert_int_equal(c->sep, 224);
	/* 600, 600 ahead-left: Doom's distance 600 + 600 - 300 = 900, volume
	 * 127 * 300 / 1000 = 38.1 -> 38; 45 degrees: 96 * 0.7071 = 67.9 ->
	 * 67, separation 61 */
	c = &s.snd.ch[g_sound_start(&s, SFX_WALLHIT, U(728), U(856), 104)];
	assert_int_equal(c->vol, 38);
	assert_int_equal(c->sep, 61);
	/* past 1200: not started */
	assert_int_equal(g_sound_start(&s, SFX_WALLHIT, U(1329), U(256), 105), -1);
	assert_int_equal(playing(&s), 5);
	/* the player's own: full and centred */
	c = &s.snd.ch[g_sound_play(&s, SFX_PISTOL, G_SRC_WEAPON)];
	assert_int_equal(c->vol, 127);
	assert_int_equal(c->sep, 128);
	assert_int_equal(c->at, 0);
}

static void gains_are_sdl_panning(void **state)
{
	uint16_t l, r;

	(void)state;
	/* left (254 - sep) * vol / 127, right sep * vol / 127 */
	g_sound_gains(127, 128, &l, &r);
	assert_int_equal(l, 126);
	assert_int_equal(r, 128);
	g_sound_gains(127, 32, &l, &r);
	assert_int_equal(l, 222);
	assert_int_equal(r, 32);
	g_sound_gains(63, 224, &l, &r);              /* 30 * 63 / 127 = 14.9, 224 * 63 / 127 = 111.1 */
	assert_int_equal(l, 14);
	assert_int_equal(r, 111);
	g_sound_gains(127, 0, &l, &r);               /* the channel test, left */
	assert_int_equal(l, 254);
	assert_int_equal(r, 0);
	g_sound_gains(127, 254, &l, &r);
	assert_int_equal(l, 0);
	assert_int_equal(r, 254);
}

static void the_sound_follows_the_listener(void **state)
{
	struct sim s;
	const struct g_schan *c;
	(void)state;
	sim_init(&s, room, &play);
	c = &s.snd.ch[g_sound_start(&s, SFX_WALLHIT, U(828), U(256), 100)];
	assert_int_equal(c->vol, 63);
	s.pl.x = U(628);                             /* 200 away now */
	g_sound_follow(&s);
	assert_int_equal(c->vol, 127);
	s.pl.angle = ANG90;                          /* facing north: it is on the right */
	g_sound_follow(&s);
	assert_int_equal(c->sep, 224);
	s.pl.x = U(-600);                            /* 1428 away: out of hearing, stopped */
	g_sound_follow(&s);
	assert_int_equal(playing(&s), 0);
}

static void one_sound_per_source(void **state)
{
	struct sim s;
	(void)state;
	sim_init(&s, room, &play);
	g_sound_play(&s, SFX_GRUNT_PAIN, G_SRC_ENEMY(0));
	g_sound_play(&s, SFX_GRUNT_DEATH, G_SRC_ENEMY(0));    /* cuts the cry */
	assert_int_equal(playing(&s), 1);
	assert_non_null(find(&s, SFX_GRUNT_DEATH));
	g_sound_play(&s, SFX_GRUNT_PAIN, G_SRC_ENEMY(1));
	g_sound_play(&s, SFX_PISTOL, G_SRC_NONE);
	g_sound_play(&s, SFX_PISTOL, G_SRC_NONE);             /* no source: never replaced */
	assert_int_equal(playing(&s), 4);
	g_sound_stop(&s, G_SRC_ENEMY(0));
	assert_null(find(&s, SFX_GRUNT_DEATH));
	assert_int_equal(playing(&s), 3);
}

static void priorities_and_stealing(void **state)
{
	struct sim s;
	int ch;
	(void)state;
	sim_init(&s, room, &play);
	s.snd.len[SFX_PICKUP] = 1000;
	s.snd.len[SFX_PLAYER_DEATH] = 1000;
	/* 16 pickups (priority 78), the one on channel 5 the oldest */
	for (int i = 0; i < G_SND_CHANNELS; i++)
		assert_int_equal(g_sound_play(&s, SFX_PICKUP, (uint16_t)(200 + i)), i);
	for (int i = 0; i < G_SND_CHANNELS; i++)
		s.snd.ch[i].age = (uint16_t)(i == 5 ? 50 : 10);
	/* a pistol (64, more important) takes the oldest pickup's channel */
	ch = g_sound_play(&s, SFX_PISTOL, 300);
	assert_int_equal(ch, 5);
	assert_int_equal(s.snd.ch[5].age, 0);
	/* a sight cry (98, less important than every one) finds none */
	assert_int_equal(g_sound_play(&s, SFX_GRUNT_SIGHT, 301), -1);
	/* an equal one takes the least important and oldest: a pickup, not
	 * the pistol; of the pickups (age 10) the lowest channel */
	assert_int_equal(g_sound_play(&s, SFX_PICKUP, 302), 0);
	/* all more important: a pickup is dropped */
	for (int i = 0; i < G_SND_CHANNELS; i++)
		g_sound_play(&s, SFX_PLAYER_DEATH, (uint16_t)(400 + i));
	assert_int_equal(g_sound_play(&s, SFX_PICKUP, 303), -1);
	assert_int_equal(playing(&s), G_SND_CHANNELS);
}

static void sounds_end_after_their_length(void **state)
{
	struct sim s;
	int len;
	(void)state;
	sim_init(&s, room, &play);
	/* the built-in pistol: 5512 samples at 22050 Hz: 5513 * 60 / 22050 =
	 * 15.0 -> 16 ticks (snd_ticks rounds up, one sample more) */
	len = s.snd.len[SFX_PISTOL];
	assert_int_equal(len, 16);
	g_sound_play(&s, SFX_PISTOL, G_SRC_WEAPON);
	for (int t = 1; t < len; t++) {
		sim_tick(&s, &idle);
		assert_int_equal(find(&s, SFX_PISTOL)->age, t);
	}
	sim_tick(&s, &idle);
	assert_null(find(&s, SFX_PISTOL));
}

static void attract_sound_setting(void **state)
{
	struct sim_settings set = { 1, 0, 0, 1, 3, 100, 0, 0, 0, 0 };
	const uint32_t cycle = SIM_TITLE_TICKS + SIM_SCORES_TICKS + SIM_DEMO_TICKS;
	struct sim s;
	(void)state;
	/* off: no jingle, but a coin is heard */
	sim_init(&s, room, &set);
	sim_tick(&s, &idle);
	assert_int_equal(s.attract_cycle, 1);
	assert_null(find(&s, SFX_JINGLE));
	assert_int_equal(g_sound_attract_on(&s), 0);
	sim_tick(&s, &(struct sim_cmd){ .coins = 1 });
	assert_non_null(find(&s, SFX_COIN));
	/* on: the jingle as the first cycle begins */
	set.attract_sound = 1;
	sim_init(&s, room, &set);
	sim_tick(&s, &idle);
	assert_non_null(find(&s, SFX_JINGLE));
	assert_int_equal(find(&s, SFX_JINGLE)->age, 0);
	/* once every 2 cycles: cycles 1 and 3, not 2 */
	set.attract_sound = 2;
	sim_init(&s, room, &set);
	for (int c = 1; c <= 3; c++) {
		sim_tick(&s, &idle);
		assert_int_equal(s.attract_cycle, c);
		assert_int_equal(find(&s, SFX_JINGLE) != NULL, c != 2);
		assert_int_equal(g_sound_attract_on(&s), c != 2);
		for (uint32_t t = 1; t < cycle; t++)
			sim_tick(&s, &idle);
		assert_int_equal(s.page, SIM_PAGE_TITLE);
	}
}

static void game_events_start_their_sounds(void **state)
{
	struct sim_settings set = { 1, 0, 0, 1, 3, 100, 0, 0, 0, 0 };
	struct sim s;
	(void)state;
	sim_init(&s, room, &set);
	/* a coin: the clink now, the credit's chime G_CREDIT_DELAY ticks later */
	sim_tick(&s, &(struct sim_cmd){ .coins = 1 });
	assert_non_null(find(&s, SFX_COIN));
	assert_null(find(&s, SFX_CREDIT));
	for (int t = 1; t < G_CREDIT_DELAY; t++)
		sim_tick(&s, &idle);
	assert_null(find(&s, SFX_CREDIT));
	sim_tick(&s, &idle);
	assert_non_null(find(&s, SFX_CREDIT));
	/* start: the game's start sound */
	sim_tick(&s, &(struct sim_cmd){ .buttons = SIM_BT_START });
	assert_int_equal(s.mode, SIM_PLAY);
	assert_non_null(find(&s, SFX_START));
	/* fire: the pistol, and the wall it hit far away is too far to hear */
	sim_tick(&s, &idle);
	sim_tick(&s, &(struct sim_cmd){ .buttons = SIM_BT_FIRE });
	assert_non_null(find(&s, SFX_PISTOL));
	assert_int_equal(s.g.shot, G_SHOT_WALL);
	assert_null(find(&s, SFX_WALLHIT));          /* the wall at x 2048: 1920 away */
	/* the grunt hurt to death: its death cry where it stands */
	g_hurt_enemy(&s, 0, 1000);
	assert_int_equal(find(&s, SFX_GRUNT_DEATH) == NULL, 1);  /* 1776 + away: not heard */
	s.pl.x = U(1800);
	s.pl.y = U(100);
	g_sound_play(&s, SFX_PICKUP, G_SRC_ITEM);
	s.g.en[0].state = G_E_CHASE;
	s.g.en[0].health = 10;
	g_hurt_enemy(&s, 0, 1000);
	assert_non_null(find(&s, SFX_GRUNT_DEATH));
	assert_int_equal(find(&s, SFX_GRUNT_DEATH)->src, G_SRC_ENEMY(0));
	assert_int_equal(find(&s, SFX_GRUNT_DEATH)->x, s.g.en[0].x);
	/* the player hurt, then killed */
	g_hurt_player(&s, U(10));
	assert_non_null(find(&s, SFX_PLAYER_HURT));
	g_hurt_player(&s, U(200));
	assert_non_null(find(&s, SFX_PLAYER_DEATH));
	assert_null(find(&s, SFX_PLAYER_HURT));      /* the same source: cut */
}

static void the_demo_is_heard_only_with_attract_sound(void **state)
{
	struct sim_settings set = { 1, 0, 0, 1, 3, 100, 0, 0, 0, 0 };
	struct mix_voice v[MIX_VOICES_MAX];
	struct snd_set *sounds;
	struct sim s, demo;
	(void)state;
	assert_int_equal(snd_builtin(&sounds), 0);
	sim_init(&s, room, &set);
	sim_tick(&s, &idle);
	sim_init(&demo, room, &play);
	g_sound_play(&demo, SFX_PISTOL, G_SRC_WEAPON);
	assert_int_equal(g_sound_voices(&s, &demo, sounds, v, MIX_VOICES_MAX), 0);
	s.set.attract_sound = 1;
	assert_int_equal(g_sound_voices(&s, &demo, sounds, v, MIX_VOICES_MAX), 1);
	assert_ptr_equal(v[0].snd, &sounds->s[SFX_PISTOL]);
	assert_int_equal(v[0].left, 126);
	assert_int_equal(v[0].right, 128);
	/* the main sim's own sounds always */
	g_sound_play(&s, SFX_COIN, G_SRC_COIN);
	s.set.attract_sound = 0;
	assert_int_equal(g_sound_voices(&s, &demo, sounds, v, MIX_VOICES_MAX), 1);
	assert_ptr_equal(v[0].snd, &sounds->s[SFX_COIN]);
	snd_free(sounds);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(doom_volume_and_separation),
		cmocka_unit_test(gains_are_sdl_panning),
		cmocka_unit_test(the_sound_follows_the_listener),
		cmocka_unit_test(one_sound_per_source),
		cmocka_unit_test(priorities_and_stealing),
		cmocka_unit_test(sounds_end_after_their_length),
		cmocka_unit_test(attract_sound_setting),
		cmocka_unit_test(game_events_start_their_sounds),
		cmocka_unit_test(the_demo_is_heard_only_with_attract_sound),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
