/*
 * g_door: doors (Doom's p_doors.c): a door is a sector whose ceiling rises
 * from its floor to 4 units below the lowest neighbouring ceiling, waits
 * and comes down again (or stays, or closes first: enum g_door). Normal
 * doors move 2 units a Doom tic (70 a second), blazing ones four times as
 * fast; the wait is Doom's 150 tics. A body under a closing door sends it
 * back up (but for the close-only types). Locked doors and switches want
 * the card or the skull key of their colour; without it the player is told
 * which key is missing.
 */
#include "engine/game/g_local.h"
#include "engine/map/map.h"

#define G_DOOR_SPEED G_PER_TICK(2 * FX_ONE)
#define G_DOOR_WAIT G_TICS(150)
#define G_DOOR_30S G_TICS(30 * 35)
#define G_DOOR_5MIN G_TICS(5 * 60 * 35)

/* The top of a door in sector sec: 4 below the lowest ceiling around. */
static fx_t g_door_top(const struct sim *s, uint32_t sec)
{
	fx_t c = g_lowest_ceil_around(s, sec);

	return c < FX_MIN + 4 * FX_ONE ? c : c - 4 * FX_ONE;
}

/* The key colour (G_KEY_BLUE, _YELLOW, _RED: the card's bit) line special
 * t wants, 0 for none. */
static int g_door_key(uint16_t t)
{
	switch (t) {
	case 26: case 32: case 99: case 133:
		return G_KEY_BLUE;
	case 27: case 34: case 136: case 137:
		return G_KEY_YELLOW;
	case 28: case 33: case 134: case 135:
		return G_KEY_RED;
	default:
		return 0;
	}
}

/* Whether who may pass line special t's lock: enemies never, the player
 * with the card or skull of its colour; else the message naming the key
 * (a door's, or with `object` a switch's). */
static int g_unlock(struct sim *s, uint16_t t, int who, int object)
{
	int key = g_door_key(t), have;

	if (!key)
		return 1;
	if (who != G_WHO_PLAYER)
		return 0;
	/* the skull's bit is the card's shifted by 3 */
	have = s->w.keys & (key | (key << 3));
	if (have)
		return 1;
	g_message(s, (key == G_KEY_BLUE ? G_MSG_BLUE_DOOR
				       : key == G_KEY_YELLOW ? G_MSG_YELLOW_DOOR : G_MSG_RED_DOOR) +
			     (object ? G_MSG_BLUE_OBJECT - G_MSG_BLUE_DOOR : 0));
	g_event(s, G_EV_LOCKED, MAP_NONE);
	return 0;
}

/* Starts a door of `type` in sector sec (which has no mover). */
static void g_door_start(struct sim *s, uint32_t sec, int type)
{
	struct g_mover *d = g_mover_new(s, sec, G_MV_DOOR, type);
	fx_t ceil = s->w.sec[sec].ceil_h;

	if (!d)
		return;
	d->wait = G_DOOR_WAIT;
	d->speed = G_DOOR_SPEED;
	switch (type) {
	case G_DOOR_BLAZE_CLOSE:
	case G_DOOR_CLOSE:
		d->low = g_door_top(s, sec);
		d->dir = G_DIR_DOWN;
		if (type == G_DOOR_BLAZE_CLOSE)
			d->speed = 4 * G_DOOR_SPEED;
		g_event(s, type == G_DOOR_CLOSE ? G_EV_DOOR_CLOSE : G_EV_BLAZE_CLOSE, sec);
		break;
	case G_DOOR_CLOSE30:
		d->low = ceil;
		d->dir = G_DIR_DOWN;
		g_event(s, G_EV_DOOR_CLOSE, sec);
		break;
	case G_DOOR_BLAZE_RAISE:
	case G_DOOR_BLAZE_OPEN:
		d->dir = G_DIR_UP;
		d->low = g_door_top(s, sec);
		d->speed = 4 * G_DOOR_SPEED;
		if (d->low != ceil)
			g_event(s, G_EV_BLAZE_OPEN, sec);
		break;
	case G_DOOR_NORMAL:
	case G_DOOR_OPEN:
	default:
		d->dir = G_DIR_UP;
		d->low = g_door_top(s, sec);
		if (d->low != ceil)
			g_event(s, G_EV_DOOR_OPEN, sec);
		break;
	}
}

int g_door_tagged(struct sim *s, const struct map_line *l, int type)
{
	int sec = -1, rtn = 0;

	while ((sec = g_tagged(s, l->tag, sec)) >= 0) {
		if (g_mover_of(s, (uint32_t)sec))
			continue;
		rtn = 1;
		g_door_start(s, (uint32_t)sec, type);
	}
	return rtn;
}

int g_door_locked(struct sim *s, uint32_t line, int type, int who)
{
	const struct map_line *l = &s->map->lines[line];

	if (who != G_WHO_PLAYER || !g_unlock(s, l->special, who, 1))
		return 0;
	return g_door_tagged(s, l, type);
}

int g_door_manual(struct sim *s, uint32_t line, int who)
{
	const struct map_line *l = &s->map->lines[line];
	struct g_mover *d;
	uint32_t sec;
	int type;

	if (!g_unlock(s, l->special, who, 0) || l->side[1] == MAP_NONE)
		return 0;
	sec = s->map->sides[l->side[1]].sector;
	d = g_mover_of(s, sec);
	if (d) {
		/* a raise door in motion: down goes back up; else the player
		 * (never an enemy) closes it now */
		if (l->special != 1 && l->special != 26 && l->special != 27 && l->special != 28 &&
		    l->special != 117)
			return 0;
		if (d->kind != G_MV_DOOR)
			return 0;
		if (d->dir == G_DIR_DOWN) {
			d->dir = G_DIR_UP;
			g_event(s, l->special == 117 ? G_EV_BLAZE_OPEN : G_EV_DOOR_OPEN, sec);
		} else if (who == G_WHO_PLAYER) {
			d->dir = G_DIR_DOWN;
			g_event(s, l->special == 117 ? G_EV_BLAZE_CLOSE : G_EV_DOOR_CLOSE, sec);
		}
		return 1;
	}
	switch (l->special) {
	case 117:
		type = G_DOOR_BLAZE_RAISE;
		break;
	case 118:
		type = G_DOOR_BLAZE_OPEN;
		break;
	case 31: case 32: case 33: case 34:
		type = G_DOOR_OPEN;
		break;
	default:
		type = G_DOOR_NORMAL;
		break;
	}
	d = g_mover_new(s, sec, G_MV_DOOR, type);
	if (!d)
		return 0;
	g_event(s, type == G_DOOR_BLAZE_RAISE || type == G_DOOR_BLAZE_OPEN ? G_EV_BLAZE_OPEN
									   : G_EV_DOOR_OPEN, sec);
	d->dir = G_DIR_UP;
	d->speed = type == G_DOOR_BLAZE_RAISE || type == G_DOOR_BLAZE_OPEN ? 4 * G_DOOR_SPEED
									 : G_DOOR_SPEED;
	d->wait = G_DOOR_WAIT;
	d->low = g_door_top(s, sec);
	return 1;
}

void g_door_spawn(struct sim *s, uint32_t sec, int raise5)
{
	struct g_mover *d = g_mover_new(s, sec, G_MV_DOOR, raise5 ? G_DOOR_RAISE5 : G_DOOR_NORMAL);

	s->w.sec[sec].special = 0;
	if (!d)
		return;
	d->speed = G_DOOR_SPEED;
	if (raise5) {
		d->dir = G_DIR_INIT;
		d->low = g_door_top(s, sec);
		d->wait = G_DOOR_WAIT;
		d->count = G_DOOR_5MIN;
	} else {
		/* open now, closing in 30 s (and staying closed) */
		d->dir = G_DIR_WAIT;
		d->low = s->w.sec[sec].ceil_h;
		d->count = G_DOOR_30S;
	}
}

/* Counts a wait down: 1 when it runs out this tick. */
static int g_count_down(struct g_mover *d)
{
	if (d->count > 0)
		d->count--;
	return d->count == 0;
}

int g_door_tick(struct sim *s, struct g_mover *d)
{
	uint32_t sec = d->sector;
	int res;

	switch (d->dir) {
	case G_DIR_WAIT:
		if (!g_count_down(d))
			return 0;
		if (d->type == G_DOOR_BLAZE_RAISE || d->type == G_DOOR_NORMAL) {
			d->dir = G_DIR_DOWN;
			g_event(s, d->type == G_DOOR_NORMAL ? G_EV_DOOR_CLOSE : G_EV_BLAZE_CLOSE, sec);
		} else if (d->type == G_DOOR_CLOSE30) {
			d->dir = G_DIR_UP;
			g_event(s, G_EV_DOOR_OPEN, sec);
		}
		return 0;
	case G_DIR_INIT:
		if (g_count_down(d) && d->type == G_DOOR_RAISE5) {
			d->dir = G_DIR_UP;
			d->type = G_DOOR_NORMAL;
			g_event(s, G_EV_DOOR_OPEN, sec);
		}
		return 0;
	case G_DIR_DOWN:
		res = g_plane_move(s, sec, d->speed, s->w.sec[sec].floor_h, 0, 1, G_DIR_DOWN);
		if (res == G_RES_PASTDEST) {
			switch (d->type) {
			case G_DOOR_BLAZE_RAISE:
			case G_DOOR_BLAZE_CLOSE:
				g_event(s, G_EV_BLAZE_CLOSE, sec);
				g_mover_remove(s, d);
				return 1;
			case G_DOOR_NORMAL:
			case G_DOOR_CLOSE:
				g_mover_remove(s, d);
				return 1;
			case G_DOOR_CLOSE30:
				d->dir = G_DIR_WAIT;
				d->count = G_DOOR_30S;
				return 0;
			default:
				return 0;
			}
		}
		if (res == G_RES_CRUSHED && d->type != G_DOOR_BLAZE_CLOSE && d->type != G_DOOR_CLOSE) {
			d->dir = G_DIR_UP;
			g_event(s, G_EV_DOOR_OPEN, sec);
		}
		return 0;
	case G_DIR_UP:
	default:
		res = g_plane_move(s, sec, d->speed, d->low, 0, 1, G_DIR_UP);
		if (res != G_RES_PASTDEST)
			return 0;
		switch (d->type) {
		case G_DOOR_BLAZE_RAISE:
		case G_DOOR_NORMAL:
			d->dir = G_DIR_WAIT;
			d->count = d->wait;
			return 0;
		case G_DOOR_CLOSE30:
		case G_DOOR_BLAZE_OPEN:
		case G_DOOR_OPEN:
			g_mover_remove(s, d);
			return 1;
		default:
			return 0;
		}
	}
}
