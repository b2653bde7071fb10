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

/* cmd_build_for's offset: player 2's moves in player 1's order */
_Static_assert(ACT_P2_BACK - ACT_P2_FORWARD == ACT_BACK - ACT_FORWARD &&
		       ACT_P2_TURN_LEFT - ACT_P2_FORWARD == ACT_TURN_LEFT - ACT_FORWARD &&
		       ACT_P2_TURN_RIGHT - ACT_P2_FORWARD == ACT_TURN_RIGHT - ACT_FORWARD &&
		       ACT_P2_STRAFE_LEFT - ACT_P2_FORWARD == ACT_STRAFE_LEFT - ACT_FORWARD &&
		       ACT_P2_STRAFE_RIGHT - ACT_P2_FORWARD == ACT_STRAFE_RIGHT - ACT_FORWARD,
	       "player 2's move actions follow player 1's order");

void cmd_build(struct cmd_state *s, struct sim_cmd *out)
{
	cmd_build_for(s, 0, out);
}

void cmd_build_for(struct cmd_state *s, int up, struct sim_cmd *out)
{
	uint16_t coins = s->presses[ACT_COIN];
	/* player 2's actions sit ACT_P2_FORWARD - ACT_FORWARD further on, in
	 * player 1's order */
	int o = up ? ACT_P2_FORWARD - ACT_FORWARD : 0;

	out->forward = (int8_t)axis(s, o + ACT_FORWARD, o + ACT_BACK, CMD_MOVE);
	out->side = (int8_t)axis(s, o + ACT_STRAFE_RIGHT, o + ACT_STRAFE_LEFT, CMD_MOVE);
	out->turn = (int16_t)axis(s, o + ACT_TURN_LEFT, o + ACT_TURN_RIGHT, CMD_TURN_SPEED);
	out->buttons = (uint8_t)((active(s, up ? ACT_P2_FIRE : ACT_FIRE) ? SIM_BT_FIRE : 0) |
				 (active(s, up ? ACT_P2_USE : ACT_USE) ? SIM_BT_USE : 0) |
				 (active(s, ACT_START) ? SIM_BT_START : 0) |
				 (active(s, ACT_START2) ? SIM_BT_START2 : 0) |
				 (active(s, ACT_SERVICE) ? SIM_BT_SERVICE : 0) |
				 (active(s, up ? ACT_P2_WEAPON : ACT_WEAPON) ? SIM_BT_WEAPON : 0) |
				 /* one pair of look controls for whoever is up */
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
