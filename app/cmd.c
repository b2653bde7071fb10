#include "app/cmd.h"

#include <stdio.h>
#include <string.h>

void cmd_reset(struct cmd_state *s)
{
	memset(s, 0, sizeof(*s));
}

void cmd_action(struct cmd_state *s, int a, int down)
{
	if (a < 0 || a >= ACT_COUNT)
		return;
	if (down) {
		if (s->held[a] == 0 && s->presses[a] < UINT16_MAX)
			s->presses[a]++;
		if (s->held[a] < UINT16_MAX)
			s->held[a]++;
	} else if (s->held[a] > 0) {
		s->held[a]--;
	}
}

/* Held now, or pressed at some point since the last build. */
static int active(const struct cmd_state *s, int a)
{
	return s->held[a] > 0 || s->presses[a] > 0;
}

static int axis(const struct cmd_state *s, int pos, int neg, int full)
{
	return (active(s, pos) ? full : 0) - (active(s, neg) ? full : 0);
}

void cmd_build(struct cmd_state *s, struct sim_cmd *out)
{
	uint16_t coins = s->presses[ACT_COIN];

	out->forward = (int8_t)axis(s, ACT_FORWARD, ACT_BACK, CMD_MOVE);
	out->side = (int8_t)axis(s, ACT_STRAFE_RIGHT, ACT_STRAFE_LEFT, CMD_MOVE);
	out->turn = (int16_t)axis(s, ACT_TURN_LEFT, ACT_TURN_RIGHT, CMD_TURN_SPEED);
	out->buttons = (uint8_t)((active(s, ACT_FIRE) ? SIM_BT_FIRE : 0) |
				 (active(s, ACT_USE) ? SIM_BT_USE : 0) |
				 (active(s, ACT_START) ? SIM_BT_START : 0) |
				 (active(s, ACT_SERVICE) ? SIM_BT_SERVICE : 0) |
				 (active(s, ACT_WEAPON) ? SIM_BT_WEAPON : 0) |
				 (active(s, ACT_LOOK_UP) ? SIM_BT_LOOK_UP : 0) |
				 (active(s, ACT_LOOK_DOWN) ? SIM_BT_LOOK_DOWN : 0));
	out->coins = (uint8_t)(coins > UINT8_MAX ? UINT8_MAX : coins);
	memset(s->presses, 0, sizeof(s->presses));
}

char *cmd_held_text(const struct cmd_state *s, char *buf, size_t len)
{
	size_t at = 0;

	if (!len)
		return buf;
	buf[0] = '\0';
	for (int a = 0; a < ACT_COUNT; a++) {
		int n;

		if (!s->held[a])
			continue;
		n = snprintf(buf + at, len - at, "%s%s (%u)", at ? ", " : "", act_name(a),
			     (unsigned)s->held[a]);
		if (n < 0 || (size_t)n >= len - at) {
			/* cut: end in "..." where it fits */
			if (len >= 4)
				memcpy(buf + len - 4, "...", 4);
			return buf;
		}
		at += (size_t)n;
	}
	if (!at)
		snprintf(buf, len, "none");
	return buf;
}
