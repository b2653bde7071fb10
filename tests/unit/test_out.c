/*
 * out: every open input device with outputs (in_backend.outputs) gets the
 * game's coins, credits and whether a game is being played, once per tick
 * at the slots' clock; devices without outputs and closed slots are left
 * alone; a device whose outputs went away is dropped with its controls
 * released, as after a read's -ENODEV. Fake backends (unit test only).
 *
 * Sound: each tick's frames go to the output the spec names; "auto" is no
 * output for scripts and replays; a sound card that is not there is not an
 * error (silent, said once, looked for again) - through ALSA itself, with
 * a card number no machine has; a WAV file gets every frame, and the
 * input-to-sound latency of a sound that began is measured from the
 * tick's first input to its first audible frame.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <unistd.h>

#include "app/hear.h"
#include "app/out.h"
#include "app/stats.h"
#include "engine/game/sim.h"
#include "input/in.h"
#include "slot_fixture.h"

static struct sim sim;

static const struct slot_kind kinds[] = { { &fake_lines, NULL, 0, 1 }, { &fake_be, NULL, 0, 1 } };

static void outputs_follow_the_game(void **state)
{
	(void)state;
	slot_add(&set, kinds, 1, NULL, 0);     /* no outputs: skipped */
	slot_add(&set, kinds, 0, NULL, 0);
	memset(&sim, 0, sizeof(sim));
	clock_ns = 777;
	sim.coins_total = 7;
	sim.credits = 3;
	sim.mode = SIM_ATTRACT;
	out_update(&set, &sim);
	assert_int_equal(fk.outputs_calls, 1);
	assert_int_equal(fk.got.coins_total, 7);
	assert_int_equal(fk.got.credits, 3);
	assert_int_equal(fk.got.playing, 0);
	assert_int_equal(fk.at, 777);
	/* playing: every mode but attract and the continue countdown */
	sim.mode = SIM_PLAY;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 1);
	sim.mode = SIM_GAMEOVER;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 0);
	sim.mode = SIM_INITIALS;
	out_update(&set, &sim);
	assert_int_equal(fk.got.playing, 1);
	assert_int_equal(fk.outputs_calls, 4);
}

static void a_device_whose_outputs_went_away_is_dropped(void **state)
{
	(void)state;
	slot_add(&set, kinds, 0, NULL, 0);
	memset(&sim, 0, sizeof(sim));
	fake_key(6, 1);            /* coin held */
	slot_read(&set);
	seen[0] = '\0';
	fk.outputs_rc = -ENODEV;
	out_update(&set, &sim);
	assert_string_equal(seen, "released 6 gone ");
	assert_int_equal(fk.closes, 1);
	assert_null(set.s[0].dev);
	/* closed: no outputs until it is back */
	out_update(&set, &sim);
	assert_int_equal(fk.outputs_calls, 1);
	/* another error is not a drop */
	fk.outputs_rc = -EIO;
	slot_close(&set);
	slot_init(&set, &fake_hooks, NULL);
	slot_add(&set, kinds, 0, NULL, 0);
	out_update(&set, &sim);
	assert_non_null(set.s[0].dev);
}

static struct out_audio oa;
static struct hear h;
static struct stats st;

static void no_sound_card_plays_silent_and_says_so_once_after_the_first_frame(void **state)
{
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	snprintf(c.audio.output, sizeof(c.audio.output), "alsa");
	snprintf(c.audio.device, sizeof(c.audio.device), "hw:77");
	assert_int_equal(out_audio_open(&oa, &c, 48000, 0), 0);
	/* the daemon's card is opened after the first frame: silent till then */
	assert_null(oa.dev);
	assert_int_equal(oa.silent_said, 0);
	h.frames = 800;
	out_audio_play(&oa, &h, &st);
	assert_null(oa.dev);
	assert_int_equal(oa.silent_said, 0);
	out_audio_start(&oa);                       /* tries now, and says so */
	assert_null(oa.dev);
	assert_int_equal(oa.silent_said, 1);
	assert_true(oa.retry_ns > 0);
	out_audio_start(&oa);                       /* once only: a retry is play's */
	out_audio_play(&oa, &h, &st);               /* before the retry time: nothing */
	assert_null(oa.dev);
	oa.retry_ns = 0;                            /* due: looks again, says nothing new */
	out_audio_play(&oa, &h, &st);
	assert_null(oa.dev);
	assert_int_equal(oa.silent_said, 1);
	assert_true(oa.retry_ns > in_now_ns());
	out_audio_close(&oa);
}

static void auto_is_nothing_for_scripts_and_a_bad_spec_is_refused(void **state)
{
	struct cfg c;

	(void)state;
	cfg_defaults(&c);
	assert_int_equal(out_audio_open(&oa, &c, 48000, 1), 0);
	assert_null(oa.be);
	out_audio_play(&oa, &h, &st);
	snprintf(c.audio.output, sizeof(c.audio.output), "oss");
	assert_int_equal(out_audio_open(&oa, &c, 48000, 0), -EINVAL);
	assert_null(oa.be);
	snprintf(c.audio.output, sizeof(c.audio.output), "wav:/nonexistent-dir/a.wav");
	assert_int_equal(out_audio_open(&oa, &c, 48000, 1), -EIO);
}

static void a_wav_file_gets_every_frame_and_the_latency_is_measured(void **state)
{
	char dir[] = "/tmp/test_out.XXXXXX", path[64];
	const char *names[1] = { "script" };
	uint8_t b[44 + 4 * 800 * 2];
	struct cfg c;
	FILE *fp;
	uint64_t t0;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/a.wav", dir);
	cfg_defaults(&c);
	snprintf(c.audio.output, sizeof(c.audio.output), "wav:%s", path);
	assert_int_equal(out_audio_open(&oa, &c, 48000, 1), 0);
	stats_init(&st, names, 1);
	for (int i = 0; i < 1600; i++)
		h.buf[i] = (int16_t)(i - 800);
	h.frames = 800;
	h.rate = 48000;
	h.onset = -1;
	out_audio_play(&oa, &h, &st);
	/* a sound begins 480 frames (10 ms) into the tick; its input came
	 * 5 ms before the tick was written: about 15 ms */
	h.onset = 480;
	t0 = in_now_ns();
	stats_input(&st, 0, t0 - 5000000);
	out_audio_play(&oa, &h, &st);
	assert_int_equal(st.sound.count, 1);
	assert_true(lat_percentile(&st.sound, 50) >= 15000);
	assert_true(lat_percentile(&st.sound, 50) < 15000 + (in_now_ns() - t0) / 1000 + 1);
	out_audio_close(&oa);
	fp = fopen(path, "rb");
	assert_non_null(fp);
	assert_int_equal(fread(b, 1, sizeof(b), fp), sizeof(b));
	fclose(fp);
	/* the second tick's first frame: -800 left, -799 right, little-endian */
	assert_int_equal(b[44 + 3200], 0xe0);
	assert_int_equal(b[44 + 3201], 0xfc);
	assert_int_equal(b[44 + 3202], 0xe1);
	assert_int_equal(b[44 + 3203], 0xfc);
	unlink(path);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(outputs_follow_the_game, fake_setup, fake_teardown),
		cmocka_unit_test_setup_teardown(a_device_whose_outputs_went_away_is_dropped, fake_setup,
						fake_teardown),
		cmocka_unit_test(no_sound_card_plays_silent_and_says_so_once_after_the_first_frame),
		cmocka_unit_test(auto_is_nothing_for_scripts_and_a_bad_spec_is_refused),
		cmocka_unit_test(a_wav_file_gets_every_frame_and_the_latency_is_measured),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
