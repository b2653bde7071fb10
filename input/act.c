/*
 * act: names of the logical actions, as bindings files and scripts spell
 * them.
 */
#include "input/act.h"

#include <stddef.h>
#include <strings.h>

static const char *const act_names[ACT_COUNT] = {
	[ACT_FORWARD] = "forward",
	[ACT_BACK] = "back",
	[ACT_TURN_LEFT] = "turn_left",
	[ACT_TURN_RIGHT] = "turn_right",
	[ACT_STRAFE_LEFT] = "strafe_left",
	[ACT_STRAFE_RIGHT] = "strafe_right",
	[ACT_FIRE] = "fire",
	[ACT_USE] = "use",
	[ACT_START] = "start",
	[ACT_COIN] = "coin",
	[ACT_SERVICE] = "service",
	[ACT_WEAPON] = "weapon",
	[ACT_LOOK_UP] = "look_up",
	[ACT_LOOK_DOWN] = "look_down",
	[ACT_START2] = "start2",
	[ACT_P2_FORWARD] = "p2_forward",
	[ACT_P2_BACK] = "p2_back",
	[ACT_P2_TURN_LEFT] = "p2_turn_left",
	[ACT_P2_TURN_RIGHT] = "p2_turn_right",
	[ACT_P2_STRAFE_LEFT] = "p2_strafe_left",
	[ACT_P2_STRAFE_RIGHT] = "p2_strafe_right",
	[ACT_P2_FIRE] = "p2_fire",
	[ACT_P2_USE] = "p2_use",
	[ACT_P2_WEAPON] = "p2_weapon",
};

const char *act_name(int a)
{
	if (a < 0 || a >= ACT_COUNT)
		return NULL;
	return act_names[a];
}

int act_from_name(const char *name)
{
	if (!name)
		return -1;
	for (int a = 0; a < ACT_COUNT; a++)
		if (strcasecmp(act_names[a], name) == 0)
			return a;
	return -1;
}
