/* libFuzzer target: Doom's sound lumps (engine/sound/snd.c snd_ds_parse,
 * snd_ds_decode) and the mixer over what they hold (engine/sound/mix.c).
 * Any bytes are a DS lump; if they parse, the count fits the bytes, the
 * samples decode, and a few ticks of them mix (at an output rate and an
 * age taken from the lump's own bytes) without reading past the samples
 * (ASan) or overflowing (UBSan); every mixed sample is one of the 16-bit
 * values and the buffer's frame count is the tick's. A malformed lump
 * must have a reason. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "engine/sound/mix.h"
#include "engine/sound/snd.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	static int16_t out[2 * MIX_FRAMES_MAX];
	struct snd_ds d;
	struct snd s;
	char why[160] = "";
	int16_t *pcm;
	uint32_t rate, age;

	if (snd_ds_parse(data, len, &d, why, sizeof(why)) < 0) {
		if (!why[0])
			abort();
		return 0;
	}
	if (d.count == 0 || d.count > len - 8 || d.u8 < data || d.u8 + d.count > data + len)
		abort();
	pcm = malloc(d.count * sizeof(*pcm));
	if (!pcm)
		return 0;
	snd_ds_decode(&d, pcm);
	s = (struct snd){ pcm, d.count, d.rate };
	/* an output rate and an age from the lump's header bytes */
	rate = MIX_RATE_MIN + (uint32_t)(data[4] * 997u + data[5] * 131u) %
				      (MIX_RATE_MAX - MIX_RATE_MIN + 1);
	age = data[6];
	for (uint32_t t = 0; t < 3; t++) {
		struct mix_voice v[2] = { { &s, age + t, 255, 255 }, { &s, t, 128, 64 } };
		uint32_t n = mix_tick(rate, 1000 + t, 100, v, 2, out);
		if (n != mix_frames(rate, 1000 + t) || n > MIX_FRAMES_MAX)
			abort();
		(void)mix_hash(out, n);
	}
	free(pcm);
	return 0;
}
