/*
 * cmd: turns the state of logical actions into the one struct sim_cmd per
 * tick that the sim reads and recordings store. Live play and scripts both
 * go through here, so both produce the same bytes for the same actions.
 */
#ifndef ARCADED_APP_CMD_H
#define ARCADED_APP_CMD_H

#include <stddef.h>
#include <stdint.h>

#include "engine/game/sim.h"
#include "input/act.h"

/* Turn speed while a turn action is held: 1/65536 turns per tick
 * (about 2.1 degrees per tick, 127 degrees per second at 60 Hz). */
#define CMD_TURN_SPEED 384
/* Forward/side thrust while a move action is held (full speed). */
#define CMD_MOVE 127

struct cmd_state {
	uint16_t held[ACT_COUNT];      /* how many controls hold each action */
	uint16_t presses[ACT_COUNT];   /* press edges since the last cmd_build */
};

void cmd_reset(struct cmd_state *s);

/* One control bound to action a went down (down=1) or up (down=0). An
 * action is held while any of its controls is; a press edge is counted
 * when the first control goes down. Releases without a press are ignored. */
void cmd_action(struct cmd_state *s, int a, int down);

/* The command for the next tick. A button pressed and released between two
 * builds still shows as pressed for one tick; each coin press edge is one
 * coin. Consumes the press counts. */
void cmd_build(struct cmd_state *s, struct sim_cmd *out);

/* cmd_build for the player whose turn it is (struct sim's up: 0 player 1,
 * 1 player 2): moves, turns, FIRE, USE and WEAPON come from that player's
 * actions (player 2's: ACT_P2_*); START, START2, COIN and SERVICE are the
 * cabinet's, whoever is up. cmd_build is cmd_build_for player 1. */
void cmd_build_for(struct cmd_state *s, int up, struct sim_cmd *out);

/* The actions held now, for the operator's summary: "none", or each held
 * action's name with the number of controls holding it, as
 * "fire (1), turn_left (2)". Always NUL-terminated; cut short (ending in
 * "...") if len is too small. Returns buf. */
char *cmd_held_text(const struct cmd_state *s, char *buf, size_t len);

#endif
