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
