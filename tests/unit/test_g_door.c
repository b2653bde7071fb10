/*
 * Tests for engine/game/g_door.c (with USE from g_line.c, which starts the
 * manual doors): a door behind a DR line opens to 4 below the lowest
 * neighbouring ceiling, waits and closes; keys; the player walks through.
 *
 * Expected values come from Doom's rules, not from this code: a normal
 * door moves 2 units a Doom tic (35 Hz) and waits 150 tics. At the sim's
 * 60 Hz that is 2 * 35 / 60 units a tick, so 124 units take 62 tics =
 * 62 * 60 / 35 = 106.3 ticks (the top is reached on tick 107), and the
 * wait is 150 * 60 / 35 = 257.1 ticks (257).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "engine/game/g_local.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/sound/snd.h"
#include "map_fixture.h"

static const struct sim_settings play = { 1, 0, 1, 0, 0, 100, 1, 0, 0, 0 };

/* Room A (x 0..256, sector 0) | door (256..272, sector 1, floor and
 * ceiling 0) | room B (272..528, sector 2); ceilings 128 but B's 100, so
 * the lowest neighbour ceiling is 100 when `low_b`. Line 2 (x = 256, front
 * A, back the door) has `special`. The player starts at (sx, 64) facing
 * east. */
static struct map *door_map(int special, int sx, int low_b)
{
	static const int w[] = { 256, 16, 256 };
	struct fix_sector s[] = { { 0, 128, 160 }, { 0, 0, 160 }, { 0, low_b ? 100 : 128, 160 } };
	struct map *m = fix_row(w, s, 3, 128, sx, 64, 0, NULL, 0);

	assert_non_null(m);
	m->lines[2].special = (uint16_t)special;
	assert_int_equal(map_finish(m, NULL, 0), 0);
	return m;
}

static void run(struct sim *s, const struct sim_cmd *c, int ticks)
{
	for (int i = 0; i < ticks; i++)
		sim_tick(s, c);
}

static void use(struct sim *s)
{
	const struct sim_cmd u = { .buttons = SIM_BT_USE }, none = { 0 };

	sim_tick(s, &u);
	sim_tick(s, &none);
}

static fx_t door_ceil(const struct sim *s)
{
	return s->w.sec[1].ceil_h;
}

static void dr_door_opens_waits_and_closes(void **state)
{
	struct map *m = door_map(1, 200, 0);       /* DR: 56 units from the line */
	struct sim s;
	const struct sim_cmd u = { .buttons = SIM_BT_USE }, none = { 0 };
	int t;
	(void)state;
	sim_init(&s, m, &play);
	assert_int_equal(s.mode, SIM_PLAY);
	assert_int_equal(door_ceil(&s), 0);
	sim_tick(&s, &u);                          /* tick 1: the door starts */
	assert_int_equal(s.w.num_movers, 1);
	assert_int_equal(s.w.mv[0].kind, G_MV_DOOR);
	assert_true(door_ceil(&s) > 0);
	run(&s, &none, 105);                       /* tick 106: not yet */
	assert_true(door_ceil(&s) < 124 * FX_ONE);
	assert_true(door_ceil(&s) > 120 * FX_ONE);
	run(&s, &none, 1);                         /* tick 107: the top */
	assert_int_equal(door_ceil(&s), 124 * FX_ONE);
	/* it stays open for the wait, then comes down */
	for (t = 0; t < 257 && door_ceil(&s) == 124 * FX_ONE; t++)
		sim_tick(&s, &none);
	assert_in_range(t, 256, 257);
	/* and closes fully in about the time it took to open */
	for (t = 0; t < 200 && s.w.num_movers > 0; t++)
		sim_tick(&s, &none);
	assert_in_range(t, 106, 109);
	assert_int_equal(door_ceil(&s), 0);
	map_free(m);
}

static void door_top_is_lowest_neighbour_ceiling_minus_4(void **state)
{
	struct map *m = door_map(1, 200, 1);       /* room B's ceiling 100 */
	struct sim s;
	const struct sim_cmd none = { 0 };
	(void)state;
	sim_init(&s, m, &play);
	use(&s);
	run(&s, &none, 150);
	assert_int_equal(door_ceil(&s), 96 * FX_ONE);
	map_free(m);
}

static void use_reaches_64_units_only(void **state)
{
	struct map *m = door_map(1, 190, 0);       /* 66 units away */
	struct sim s;
	const struct sim_cmd none = { 0 };
	(void)state;
	sim_init(&s, m, &play);
	use(&s);
	run(&s, &none, 30);
	assert_int_equal(s.w.num_movers, 0);
	assert_int_equal(door_ceil(&s), 0);
	map_free(m);
}

static void open_stay_door_stays_open(void **state)
{
	struct map *m = door_map(31, 200, 0);      /* D1 open stay */
	struct sim s;
	const struct sim_cmd none = { 0 };
	(void)state;
	sim_init(&s, m, &play);
	use(&s);
	run(&s, &none, 1000);
	assert_int_equal(door_ceil(&s), 124 * FX_ONE);
	assert_int_equal(s.w.num_movers, 0);
	map_free(m);
}

static void locked_door_wants_its_key(void **state)
{
	struct map *m = door_map(26, 200, 0);      /* DR blue */
	struct sim s;
	const struct sim_cmd none = { 0 };
	(void)state;
	sim_init(&s, m, &play);
	use(&s);
	run(&s, &none, 30);
	assert_int_equal(door_ceil(&s), 0);
	assert_int_equal(s.w.msg, G_MSG_BLUE_DOOR);
	s.w.keys = G_KEY_RED | G_KEY_YELLOW;       /* the wrong colours */
	use(&s);
	run(&s, &none, 30);
	assert_int_equal(door_ceil(&s), 0);
	s.w.keys = G_KEY_BLUE_SKULL;               /* a skull of its colour will do */
	use(&s);
	run(&s, &none, 150);
	assert_int_equal(door_ceil(&s), 124 * FX_ONE);
	map_free(m);
}

static void the_player_walks_through_the_opened_door(void **state)
{
	struct map *m = door_map(1, 200, 0);
	struct sim s;
	const struct sim_cmd fwd = { .forward = 127 }, none = { 0 };
	(void)state;
	sim_init(&s, m, &play);
	/* closed: walking east stops at the door line */
	run(&s, &fwd, 60);
	assert_int_equal(s.pl.sector, 0);
	assert_true(s.pl.x <= 256 * FX_ONE - SIM_PLAYER_RADIUS);
	use(&s);
	run(&s, &none, 110);
	run(&s, &fwd, 60);
	assert_int_equal(s.pl.sector, 2);
	map_free(m);
}

/* The channel playing sound id, or NULL. */
static const struct g_schan *playing(const struct sim *s, int id)
{
	for (int i = 0; i < G_SND_CHANNELS; i++)
		if (s->snd.ch[i].sfx == id)
			return &s->snd.ch[i];
	return NULL;
}

/* Doom's door sounds at the door sector's sound origin: the door (sector
 * 1) spans x 256..272, y 0..128, so its centre is (264, 64). Nothing
 * plays a door's sound before the door moves; it opens with DSDOROPN,
 * closes after its wait (257 ticks, above) with DSDORCLS from the same
 * source, which replaces the opening's sound. */
static void the_door_sounds_at_its_centre(void **state)
{
	struct map *m = door_map(1, 200, 0);
	struct snd_set *set;
	struct sim s;
	const struct sim_cmd u = { .buttons = SIM_BT_USE }, none = { 0 };
	const struct g_schan *c;
	(void)state;
	assert_int_equal(snd_builtin(&set), 0);
	sim_init(&s, m, &play);
	sim_set_sounds(&s, set);
	run(&s, &none, 10);
	assert_null(playing(&s, SFX_DOOR_OPEN));
	sim_tick(&s, &u);
	c = playing(&s, SFX_DOOR_OPEN);
	assert_non_null(c);
	assert_int_equal(c->at, 1);
	assert_int_equal(c->x, 264 * FX_ONE);
	assert_int_equal(c->y, 64 * FX_ONE);
	assert_int_equal(c->src, G_SRC_SECTOR(1));
	assert_int_equal(c->vol, G_SND_VOL);       /* 64 units away: within 200 */
	assert_null(playing(&s, SFX_DOOR_CLOSE));
	/* open (107 ticks), wait (257): closing then */
	run(&s, &none, 107 + 257 + 5);
	c = playing(&s, SFX_DOOR_CLOSE);
	assert_non_null(c);
	assert_int_equal(c->x, 264 * FX_ONE);
	assert_int_equal(c->src, G_SRC_SECTOR(1));
	assert_null(playing(&s, SFX_DOOR_OPEN));
	snd_free(set);
	map_free(m);
}

/* A locked door refused: Doom's "oof" (DSOOF) from the player, and no
 * door sound. */
static void a_locked_door_says_oof(void **state)
{
	struct map *m = door_map(26, 200, 0);      /* DR blue */
	struct snd_set *set;
	struct sim s;
	const struct sim_cmd u = { .buttons = SIM_BT_USE };
	const struct g_schan *c;
	(void)state;
	assert_int_equal(snd_builtin(&set), 0);
	sim_init(&s, m, &play);
	sim_set_sounds(&s, set);
	sim_tick(&s, &u);
	c = playing(&s, SFX_LOCKED);
	assert_non_null(c);
	assert_int_equal(c->at, 0);
	assert_int_equal(c->src, G_SRC_PLAYER);
	assert_null(playing(&s, SFX_DOOR_OPEN));
	snd_free(set);
	map_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(dr_door_opens_waits_and_closes),
		cmocka_unit_test(door_top_is_lowest_neighbour_ceiling_minus_4),
		cmocka_unit_test(use_reaches_64_units_only),
		cmocka_unit_test(open_stay_door_stays_open),
		cmocka_unit_test(locked_door_wants_its_key),
		cmocka_unit_test(the_player_walks_through_the_opened_door),
		cmocka_unit_test(the_door_sounds_at_its_centre),
		cmocka_unit_test(a_locked_door_says_oof),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
