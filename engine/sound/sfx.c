/*
 * sfx: the table of sounds (contract in sfx.h). Data from SFX_LIST only.
 */
#include "engine/sound/sfx.h"

#define SFX_ROW(id, shown, dslump, prio) [SFX_##id] = { shown, dslump, prio },

const struct sfx_info sfx_table[SFX_COUNT] = {
	[SFX_NONE] = { "", "", 255 },
	SFX_LIST(SFX_ROW)
};

const struct sfx_info *sfx_info(int id)
{
	return id > SFX_NONE && id < SFX_COUNT ? &sfx_table[id] : &sfx_table[SFX_NONE];
}
