/*
 * act: the logical actions controls are bound to.
 */
#ifndef ARCADED_INPUT_ACT_H
#define ARCADED_INPUT_ACT_H

enum act {
	ACT_FORWARD,
	ACT_BACK,
	ACT_TURN_LEFT,
	ACT_TURN_RIGHT,
	ACT_STRAFE_LEFT,
	ACT_STRAFE_RIGHT,
	ACT_FIRE,
	ACT_USE,
	ACT_START,
	ACT_COIN,
	ACT_SERVICE,
	ACT_WEAPON,                     /* change to the next weapon owned */
	ACT_LOOK_UP,                    /* vertical aim: held raises the view */
	ACT_LOOK_DOWN,                  /* held lowers it; both centre it */
	ACT_START2,                     /* the 2P start: a two-player game */
	/* Player 2's controls: the command reads them instead of player 1's
	 * while it is player 2's turn (app/cmd.h) */
	ACT_P2_FORWARD,
	ACT_P2_BACK,
	ACT_P2_TURN_LEFT,
	ACT_P2_TURN_RIGHT,
	ACT_P2_STRAFE_LEFT,
	ACT_P2_STRAFE_RIGHT,
	ACT_P2_FIRE,
	ACT_P2_USE,
	ACT_P2_WEAPON,
	ACT_COUNT
};

/* "forward", "back", "turn_left", "turn_right", "strafe_left",
 * "strafe_right", "fire", "use", "start", "coin", "service", "weapon",
 * "look_up", "look_down", "start2", then player 2's "p2_forward" ..
 * "p2_weapon" (player 1's names with "p2_" before them); NULL if out of
 * range. */
const char *act_name(int a);
/* Action by name (case-insensitive), or -1. */
int act_from_name(const char *name);

#endif
