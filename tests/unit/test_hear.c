/*
 * hear: a tick of the game's sound, mixed and hashed, as the daemon and the
 * cross-build replayer both do it: silence is zeros; a coin's clink starts
 * in the tick of the coin with its first audible sample at the front (the
 * built-in clink is audible within its first millisecond, test_syn); the
 * master volume is the sim's; the frames follow the sim's tick at a rate 60
 * does not divide.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "app/hear.h"
#include "engine/game/sim.h"
#include "engine/sound/snd.h"
#include "tests/unit/g_fixture.h"

static struct hear h;

static void a_coin_is_heard_in_its_tick(void **state)
{
	static const struct gf_thing t[] = { { 64, 64, 0, 1, 0 } };
	struct sim_settings set = { 1, 0, 0, 1, 3, 100, 0, 0, 0, 0 };
	struct map *m = gf_room(256, 256, t, 1, NULL, 0);
	struct snd_set *sounds;
	struct sim s;
	int16_t zero[2 * 800] = { 0 };

	(void)state;
	assert_non_null(m);
	assert_int_equal(snd_builtin(&sounds), 0);
	sim_init(&s, m, &set);
	sim_set_sounds(&s, sounds);
	hear_init(&h, sounds, 48000);
	sim_tick(&s, &(struct sim_cmd){ 0 });
	hear_tick(&h, &s, NULL);
	assert_int_equal(h.frames, 800);
	assert_memory_equal(h.buf, zero, sizeof(zero));   /* attract sound off: silence */
	assert_true(h.hash == mix_hash(zero, 800));
	assert_int_equal(h.onset, -1);
	sim_tick(&s, &(struct sim_cmd){ .coins = 1 });
	hear_tick(&h, &s, NULL);
	assert_true(h.onset >= 0 && h.onset < 48);         /* 1 ms at 48 kHz */
	assert_true(h.hash != mix_hash(zero, 800));
	assert_true(h.hash == mix_hash(h.buf, h.frames));
	/* the next tick: still the clink, no new sound */
	sim_tick(&s, &(struct sim_cmd){ 0 });
	hear_tick(&h, &s, NULL);
	assert_int_equal(h.onset, -1);
	assert_true(h.hash != mix_hash(zero, 800));
	/* volume 0: silent */
	s.set.volume = 0;
	hear_tick(&h, &s, NULL);
	assert_memory_equal(h.buf, zero, sizeof(zero));
	/* 22050 Hz: the frames of the tick that ran (s.tick - 1 = 2: 367) */
	hear_init(&h, sounds, 22050);
	hear_tick(&h, &s, NULL);
	assert_int_equal(h.frames, mix_frames(22050, 2));
	assert_int_equal(h.frames, 367);
	snd_free(sounds);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(a_coin_is_heard_in_its_tick),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
