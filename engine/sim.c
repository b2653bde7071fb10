/*
 * sim: modes, coins and credits, and Doom-like player movement with wall
 * collision, in 16.16 fixed point.
 */
#include "engine/sim.h"

#include <stddef.h>
#include <string.h>

#include "engine/hash.h"
#include "engine/map.h"
#include "engine/r_main.h"
#include "engine/tab.h"

/*
 * Movement constants. Each tick: thrust from the command, move by the
 * momentum (with collision), then friction. At steady state the move per
 * tick is thrust / (1 - friction) = thrust * 65536 / 6144, so forward 127
 * (127 * 384 = 48768 = 0.744 units of thrust) gives 7.94 units per tick,
 * 476 units per second at 60 Hz.
 */
#define SIM_FRICTION 0xe800            /* Doom's FRICTION */
#define SIM_STOPSPEED 0x1000           /* Doom's STOPSPEED: below it, stop */
#define SIM_THRUST 384                 /* thrust per unit of forward/side */
#define SIM_MAX_MOVE (16 * FX_ONE)     /* momentum clamp per axis */
#define SIM_SUBSTEP (SIM_PLAYER_RADIUS / 2)
#define SIM_PUSH_ITERS 4
#define SIM_PUSH_MARGIN 2              /* fx units left between player and wall */
#define SIM_ATTRACT_TURN (ANG90 / (8 * SIM_TICRATE))  /* a turn in 32 s */
#define SIM_RNG_SEED 0x2545f491u
#define SIM_SPAWN_INSET (32 * FX_ONE)  /* no player start: this far off a wall */

const char *sim_mode_name(enum sim_mode m)
{
	switch (m) {
	case SIM_ATTRACT: return "attract";
	case SIM_PLAY: return "play";
	default: return NULL;
	}
}

int sim_mode_from_name(const char *name)
{
	int i;

	for (i = 0; i < SIM_MODE_COUNT; i++)
		if (strcmp(name, sim_mode_name((enum sim_mode)i)) == 0)
			return i;
	return -1;
}

static void sim_settle(struct sim *s)
{
	struct sim_player *p = &s->pl;

	p->sector = map_point_sector(s->map, p->x, p->y);
	p->z = s->map->sectors[p->sector].floor_h;
	p->viewz = p->z + SIM_VIEW_HEIGHT;
}

/* Puts the player at the map's player 1 start, or, without one, SPAWN_INSET
 * in front of the middle of the first line whose front side faces sector 0,
 * facing along that line. */
static void sim_spawn(struct sim *s)
{
	const struct map *m = s->map;
	struct sim_player *p = &s->pl;
	uint32_t i;

	memset(p, 0, sizeof *p);
	for (i = 0; i < m->num_things; i++) {
		if (m->things[i].type == 1) {
			p->x = m->things[i].x;
			p->y = m->things[i].y;
			p->angle = m->things[i].angle;
			sim_settle(s);
			return;
		}
	}
	for (i = 0; i < m->num_lines; i++) {
		const struct map_line *l = &m->lines[i];
		if (m->sides[l->side[0]].sector == 0) {
			const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
			ang_t in;
			p->angle = tab_atan2(b->y - a->y, b->x - a->x);
			in = p->angle - ANG90;         /* the front side is the right */
			p->x = (fx_t)(((int64_t)a->x + b->x) / 2) + fx_mul(SIM_SPAWN_INSET, tab_cos(in));
			p->y = (fx_t)(((int64_t)a->y + b->y) / 2) + fx_mul(SIM_SPAWN_INSET, tab_sin(in));
			break;
		}
	}
	sim_settle(s);
}

void sim_init(struct sim *s, const struct map *m, const struct sim_settings *set)
{
	memset(s, 0, sizeof *s);
	s->map = m;
	s->set = *set;
	s->mode = set->start_in_play ? SIM_PLAY : SIM_ATTRACT;
	s->rng = SIM_RNG_SEED;
	sim_spawn(s);
}

/* Whether line l stops a player whose feet are at z: one-sided and blocking
 * lines always; a portal when the higher floor is more than a step above z,
 * or the opening (lower ceiling - higher floor) or the room above z is lower
 * than the player. */
static int sim_blocks(const struct map *m, const struct map_line *l, fx_t z)
{
	const struct map_sector *f, *b;
	int64_t floor, ceil;

	if (l->side[1] == MAP_NONE || (l->flags & ML_BLOCKING))
		return 1;
	f = &m->sectors[m->sides[l->side[0]].sector];
	b = &m->sectors[m->sides[l->side[1]].sector];
	floor = f->floor_h > b->floor_h ? f->floor_h : b->floor_h;
	ceil = f->ceil_h < b->ceil_h ? f->ceil_h : b->ceil_h;
	return floor - z > SIM_MAX_STEP || ceil - floor < SIM_PLAYER_HEIGHT ||
	       ceil - z < SIM_PLAYER_HEIGHT;
}

/* |n / d| rounded up, for d > 0: pushes round away from the wall. */
static int64_t sim_div_up(int64_t n, int64_t d)
{
	return n >= 0 ? (n + d - 1) / d : -((-n + d - 1) / d);
}

/* Pushes (*x, *y) radially away from point (ax, ay) to the player radius
 * (plus margin) if closer; (fdx, fdy) is the way out if it is exactly on it.
 * Returns whether it was closer. */
static int sim_push_point(fx_t *x, fx_t *y, fx_t ax, fx_t ay, int64_t fdx, int64_t fdy,
			  int apply)
{
	int64_t vx = (int64_t)*x - ax, vy = (int64_t)*y - ay;
	int64_t out = SIM_PLAYER_RADIUS + SIM_PUSH_MARGIN;
	int64_t d;

	if (vx <= -SIM_PLAYER_RADIUS || vx >= SIM_PLAYER_RADIUS || vy <= -SIM_PLAYER_RADIUS ||
	    vy >= SIM_PLAYER_RADIUS || vx * vx + vy * vy >= (int64_t)SIM_PLAYER_RADIUS * SIM_PLAYER_RADIUS)
		return 0;
	if (!apply)
		return 1;
	if (vx == 0 && vy == 0) {
		vx = fdx;
		vy = fdy;
	}
	d = fx_len((fx_t)vx, (fx_t)vy);
	*x = (fx_t)(ax + sim_div_up(vx * out, d));
	*y = (fx_t)(ay + sim_div_up(vy * out, d));
	return 1;
}

/*
 * Whether the player circle at (*x, *y) overlaps segment a-b; with apply,
 * moves it out to SIM_PLAYER_RADIUS + margin: along the segment's normal
 * when the nearest point is inside the segment (which is what makes the
 * player slide along walls), radially from an end point otherwise. A centre
 * exactly on the line goes to the front (right) side.
 */
static int sim_push(fx_t *x, fx_t *y, const struct map_vertex *a, const struct map_vertex *b,
		    int apply)
{
	int64_t dx = (int64_t)b->x - a->x, dy = (int64_t)b->y - a->y;
	int64_t px = (int64_t)*x - a->x, py = (int64_t)*y - a->y;
	int64_t t = px * dx + py * dy, len2 = dx * dx + dy * dy;
	int64_t cross, mag, len, need;

	if (t <= 0)
		return sim_push_point(x, y, a->x, a->y, -dx, -dy, apply);
	if (t >= len2)
		return sim_push_point(x, y, b->x, b->y, dx, dy, apply);
	len = fx_len((fx_t)dx, (fx_t)dy);
	cross = dx * py - dy * px;     /* > 0: left of a->b */
	mag = cross < 0 ? -cross : cross;
	if (mag >= SIM_PLAYER_RADIUS * len)
		return 0;
	if (!apply)
		return 1;
	/* left normal (-dy, dx) / len; the centre moves by (R - dist) along it */
	need = SIM_PLAYER_RADIUS + SIM_PUSH_MARGIN - mag / len;
	if (cross <= 0)
		need = -need;
	*x = (fx_t)(*x + sim_div_up(-dy * need, len));
	*y = (fx_t)(*y + sim_div_up(dx * need, len));
	return 1;
}

/* Pushes the player at (*x, *y) out of every wall it overlaps. Returns 1 if
 * it then fits and moved no more than a radius per axis from (ox, oy) (so a
 * push can never carry it through a wall), else 0. Lines are tested only
 * when their bounding box, grown by the radius, contains the centre. */
static int sim_fit(const struct map *m, fx_t z, fx_t ox, fx_t oy, fx_t *x, fx_t *y)
{
	int iter, apply;

	for (iter = 0; iter <= SIM_PUSH_ITERS; iter++) {
		int hit = 0;
		apply = iter < SIM_PUSH_ITERS;
		for (uint32_t i = 0; i < m->num_lines && !(hit && !apply); i++) {
			const struct map_line *l = &m->lines[i];
			const struct map_vertex *a = &m->vertices[l->v1], *b = &m->vertices[l->v2];
			int64_t lo, hi;
			lo = (a->x < b->x ? a->x : b->x) - (int64_t)SIM_PLAYER_RADIUS;
			hi = (a->x > b->x ? a->x : b->x) + (int64_t)SIM_PLAYER_RADIUS;
			if (*x <= lo || *x >= hi)
				continue;
			lo = (a->y < b->y ? a->y : b->y) - (int64_t)SIM_PLAYER_RADIUS;
			hi = (a->y > b->y ? a->y : b->y) + (int64_t)SIM_PLAYER_RADIUS;
			if (*y <= lo || *y >= hi)
				continue;
			if (sim_blocks(m, l, z) && sim_push(x, y, a, b, apply))
				hit = 1;
		}
		if (!hit)
			break;
		if (!apply)
			return 0;
	}
	return (int64_t)*x - ox <= SIM_PLAYER_RADIUS && ox - (int64_t)*x <= SIM_PLAYER_RADIUS &&
	       (int64_t)*y - oy <= SIM_PLAYER_RADIUS && oy - (int64_t)*y <= SIM_PLAYER_RADIUS;
}

/* Tries to move the player by (dx, dy); updates its position on success. */
static int sim_try(struct sim *s, fx_t dx, fx_t dy)
{
	struct sim_player *p = &s->pl;
	fx_t x = p->x + dx, y = p->y + dy;

	if (!sim_fit(s->map, p->z, p->x, p->y, &x, &y))
		return 0;
	p->x = x;
	p->y = y;
	return 1;
}

/* Momentum after a blocked move: no more than what was actually moved, and
 * never reversed. */
static fx_t sim_limit(fx_t mom, fx_t moved)
{
	if ((mom > 0 && moved <= 0) || (mom < 0 && moved >= 0))
		return 0;
	return fx_abs(moved) < fx_abs(mom) ? moved : mom;
}

/*
 * Moves the player by its momentum in sub-steps of at most half a radius per
 * axis (so it cannot pass through a wall), each pushed out of the walls it
 * touches (sliding). A sub-step that does not fit is retried along x only,
 * then y only (Doom's fallback); if neither fits the player stops there.
 */
static void sim_move(struct sim *s)
{
	struct sim_player *p = &s->pl;
	int64_t mx = p->momx, my = p->momy;
	int64_t ax = mx < 0 ? -mx : mx, ay = my < 0 ? -my : my;
	int64_t n = (ax > ay ? ax : ay) / SIM_SUBSTEP + 1, i;
	fx_t x0 = p->x, y0 = p->y;
	int blocked = 0;

	for (i = 0; i < n; i++) {
		fx_t dx = (fx_t)(mx * (i + 1) / n - mx * i / n);
		fx_t dy = (fx_t)(my * (i + 1) / n - my * i / n);
		fx_t want_x = p->x + dx, want_y = p->y + dy;
		if (sim_try(s, dx, dy)) {
			if (p->x != want_x || p->y != want_y)
				blocked = 1;
			continue;
		}
		blocked = 1;
		if (dx && sim_try(s, dx, 0))
			continue;
		if (dy && sim_try(s, 0, dy))
			continue;
		break;
	}
	if (blocked) {
		p->momx = sim_limit(p->momx, p->x - x0);
		p->momy = sim_limit(p->momy, p->y - y0);
	}
	sim_settle(s);
}

static fx_t sim_clamp_mom(int64_t v)
{
	return (fx_t)(v > SIM_MAX_MOVE ? SIM_MAX_MOVE : v < -SIM_MAX_MOVE ? -SIM_MAX_MOVE : v);
}

/* Friction, symmetric in sign (fx_mul rounds towards minus infinity). */
static fx_t sim_friction(fx_t v)
{
	int64_t a = ((int64_t)fx_abs(v) * SIM_FRICTION) >> FX_SHIFT;
	return (fx_t)(v < 0 ? -a : a);
}

static void sim_player_tick(struct sim *s, const struct sim_cmd *cmd)
{
	struct sim_player *p = &s->pl;
	int64_t mx = p->momx, my = p->momy;

	p->angle += (uint32_t)cmd->turn * 65536u;
	if (cmd->forward) {
		fx_t f = cmd->forward * SIM_THRUST;
		mx += fx_mul(f, tab_cos(p->angle));
		my += fx_mul(f, tab_sin(p->angle));
	}
	if (cmd->side) {
		fx_t f = cmd->side * SIM_THRUST;
		mx += fx_mul(f, tab_cos(p->angle - ANG90));
		my += fx_mul(f, tab_sin(p->angle - ANG90));
	}
	p->momx = sim_clamp_mom(mx);
	p->momy = sim_clamp_mom(my);
	if (p->momx || p->momy)
		sim_move(s);
	if (!cmd->forward && !cmd->side && fx_abs(p->momx) < SIM_STOPSPEED &&
	    fx_abs(p->momy) < SIM_STOPSPEED) {
		p->momx = 0;
		p->momy = 0;
	} else {
		p->momx = sim_friction(p->momx);
		p->momy = sim_friction(p->momy);
	}
}

static void sim_coins(struct sim *s, uint8_t coins)
{
	uint32_t per = s->set.coins_per_credit ? s->set.coins_per_credit : 1;

	s->coins_total += coins;
	s->coin_rem += coins;
	while (s->coin_rem >= per) {
		s->coin_rem -= per;
		s->credits++;
	}
}

void sim_tick(struct sim *s, const struct sim_cmd *cmd)
{
	uint8_t pressed = (uint8_t)(cmd->buttons & ~s->prev_buttons);

	s->prev_buttons = cmd->buttons;
	sim_coins(s, cmd->coins);
	switch (s->mode) {
	case SIM_ATTRACT:
		if ((pressed & SIM_BT_START) && (s->set.freeplay || s->credits > 0)) {
			if (!s->set.freeplay)
				s->credits--;
			s->plays++;
			s->mode = SIM_PLAY;
			sim_spawn(s);
		} else {
			s->pl.angle += SIM_ATTRACT_TURN;
		}
		break;
	case SIM_PLAY:
	default:
		sim_player_tick(s, cmd);
		break;
	}
	/* xorshift32, stepped every tick so every tick's hash covers it */
	s->rng ^= s->rng << 13;
	s->rng ^= s->rng >> 17;
	s->rng ^= s->rng << 5;
	s->tick++;
}

uint64_t sim_hash(const struct sim *s)
{
	const struct sim_player *p = &s->pl;
	uint64_t h = HASH_INIT;

	h = hash_u64(h, s->map ? s->map->content_hash : 0);
	h = hash_u8(h, s->set.coins_per_credit);
	h = hash_u8(h, s->set.freeplay);
	h = hash_u8(h, s->set.start_in_play);
	h = hash_u32(h, s->tick);
	h = hash_u32(h, (uint32_t)s->mode);
	h = hash_u32(h, s->credits);
	h = hash_u32(h, s->coin_rem);
	h = hash_u32(h, s->coins_total);
	h = hash_u32(h, s->plays);
	h = hash_u8(h, s->prev_buttons);
	h = hash_u32(h, s->rng);
	h = hash_i32(h, p->x);
	h = hash_i32(h, p->y);
	h = hash_i32(h, p->z);
	h = hash_i32(h, p->viewz);
	h = hash_i32(h, p->momx);
	h = hash_i32(h, p->momy);
	h = hash_u32(h, p->angle);
	h = hash_u32(h, p->sector);
	return h;
}

void sim_view(const struct sim *s, struct r_view *v)
{
	v->x = s->pl.x;
	v->y = s->pl.y;
	v->z = s->pl.viewz;
	v->angle = s->pl.angle;
	v->shear = 0;
}
