/* libFuzzer target: sim_restore (engine/game/sim_hash.c), which reads the start
 * snapshot a recording carries: outside bytes that become the whole sim
 * state. Random bytes almost never pass the stages hash at the front, so
 * the input is a list of changes to a real snapshot (the built-in stages,
 * a game under way): a count byte, then that many (2-byte offset, byte)
 * changes; the rest of the input is commands, 6 bytes each. A snapshot the
 * restore accepts must snapshot again to exactly its bytes, and the sim
 * must then run (under ASan and UBSan) on those commands: whatever the
 * checks let through, the rules must be able to take. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/game/sim.h"
#include "engine/map/lvl_builtin.h"
#include "engine/map/map.h"
#include "input/rec.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

#define FZ_TICKS 60                     /* ticks run after an accepted restore */

static struct map *maps[G_MAX_STAGES];
static int nmaps;
static uint8_t *base;                   /* the real snapshot */
static size_t size;
static uint8_t *work, *back;

static void fz_setup(void)
{
	static const struct sim_settings set = { 1, 0, 0, 1, 3, 100, 1, 0, 0, 0 };
	const struct sim_cmd coin = { .coins = 1 }, start = { .buttons = SIM_BT_START };
	struct sim_cmd go = { .forward = 100, .turn = 90 };
	struct sim s;

	nmaps = lvl_builtin_count();
	for (int i = 0; i < nmaps; i++)
		if (lvl_builtin(i, &maps[i]) < 0)
			abort();
	sim_init_stages(&s, (const struct map *const *)maps, nmaps, &set, NULL, NULL);
	sim_tick(&s, &coin);
	sim_tick(&s, &start);
	for (int t = 0; t < 300; t++) {
		go.buttons = t % 3 == 0 ? SIM_BT_FIRE : 0;
		sim_tick(&s, &go);
	}
	size = sim_snapshot_size();
	base = malloc(size);
	work = malloc(size);
	back = malloc(size);
	if (!base || !work || !back)
		abort();
	sim_snapshot(&s, base);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	struct sim s;
	size_t i = 0, n;

	if (!base)
		fz_setup();
	memcpy(work, base, size);
	n = len ? data[i++] % 32 : 0;
	for (; n > 0 && i + 3 <= len; n--, i += 3)
		work[(data[i] | (size_t)data[i + 1] << 8) % size] = data[i + 2];
	sim_init_stages(&s, (const struct map *const *)maps, nmaps, &(struct sim_settings){ 0 },
			NULL, NULL);
	if (sim_restore(&s, work, size) != 0)
		return 0;
	sim_snapshot(&s, back);
	if (memcmp(back, work, size) != 0)
		abort();
	for (int t = 0; t < FZ_TICKS; t++) {
		struct sim_cmd c = { 0 };

		if (i + REC_CMD_SIZE <= len) {
			rec_cmd_decode(data + i, &c);
			i += REC_CMD_SIZE;
		}
		sim_tick(&s, &c);
		(void)sim_hash(&s);
	}
	return 0;
}
