/*
 * r_game: what the renderer takes from the game and the map: the camera
 * of the current tick and the sprites to draw (enemies, pickups, the map's
 * lights and decorations, the last shot's puff), and the map's things as
 * sprites for still views. Pure functions of the sim state, the map and
 * the texture set (for sprite numbers); the game itself never calls the
 * renderer (engine/README.md).
 */
#include "engine/render/r_game.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "engine/game/g_game.h"
#include "engine/game/sim.h"
#include "engine/map/map.h"
#include "engine/map/mesh_builtin.h"
#include "engine/map/tex.h"
#include "engine/map/th.h"
#include "engine/render/r_main.h"

#define R_ANIM 8                       /* ticks per frame of standing and walking cycles */
#define R_DEATH_TICKS 6                /* ticks per frame of a death */
#define R_PUFF_TICKS 8

/* Sprites drawn whatever the map's things are: the stand-ins for a thing
 * whose own sprite the set lacks, and the shot's puff and blood. */
#define R_STANDIN_ENEMY "POSS"
#define R_STANDIN_HEALTH "MEDI"
#define R_STANDIN_PICKUP "CLIP"
#define R_STANDIN_LIGHT "COLU"
#define R_STANDIN_DECOR "BAR1"
#define R_SPR_PUFF "PUFF"
#define R_SPR_BLOOD "BLUD"
#define R_SPR_MISSILE "BAL1"           /* Doom's imp ball: A, B flying; C, D, E exploding */
#define R_MISSILE_ANIM 4               /* ticks per flying frame */
#define R_MESH_TURN (ANG90 / 35u)      /* a mesh's turn per tick: a quarter a second */

struct r_out {
	const struct tex_set *t;
	const struct mesh_set *ms;     /* loaded meshes, may be NULL */
	struct r_sprite *out;
	int n, max;
};

/* Sprite number for name, else for the class's stand-in (the project's
 * own set has few sprites), else one past the end (the renderer draws its
 * fallback checker there and counts it). */
static int r_sprite_index(const struct tex_set *t, const char *name, const char *standin)
{
	int i = name[0] ? tex_find_sprite(t, name) : -1;

	if (i < 0 && standin)
		i = tex_find_sprite(t, standin);
	return i < 0 ? t->num_sprites : i;
}

/* Adds a sprite; a frame the sprite lacks is drawn as frame A unless
 * need_frame (then nothing is drawn: a corpse must not stand up). */
static void r_put(struct r_out *o, fx_t x, fx_t y, fx_t z, ang_t a, int spr, int frame,
		  int bright, int need_frame)
{
	struct r_sprite *r;

	if (o->n >= o->max)
		return;
	if (spr < o->t->num_sprites && frame >= o->t->sprites[spr].num_frames) {
		if (need_frame)
			return;
		frame = 0;
	}
	r = &o->out[o->n++];
	r->x = x;
	r->y = y;
	r->z = z;
	r->angle = a;
	r->sprite = (uint16_t)spr;
	r->frame = (uint16_t)frame;
	r->flags = bright ? R_SPR_FULLBRIGHT : 0;
	r->mesh = 0;
	r->colour = 0;
	r->mp = NULL;
}

/* The built-in mesh thing type `type` is drawn with (0: its sprite) and
 * the colour (r, g, b) it is drawn in: the keys (cards and skulls alike,
 * in their key's colour) and the floor lamp. */
static int r_mesh_of(uint16_t type, int *r, int *g, int *b)
{
	switch (type) {
	case 5: case 40:                /* blue card, blue skull */
		*r = 40, *g = 80, *b = 255;
		return MESH_B_KEY;
	case 6: case 39:                /* yellow */
		*r = 255, *g = 224, *b = 0;
		return MESH_B_KEY;
	case 13: case 38:               /* red */
		*r = 255, *g = 32, *b = 32;
		return MESH_B_KEY;
	case 2028:                      /* floor lamp: brass */
		*r = 232, *g = 176, *b = 64;
		return MESH_B_LAMP;
	default:
		return 0;
	}
}

int r_game_mesh_colour(uint16_t type, int *r, int *g, int *b)
{
	return r_mesh_of(type, r, g, b) != 0;
}

int r_game_mesh(const struct tex_set *t, const struct mesh_set *ms, uint16_t type, uint32_t tick,
		fx_t x, fx_t y, fx_t z, struct r_sprite *out)
{
	const struct mesh_thing *mt = mesh_set_find(ms, type);
	int cr, cg, cb, mesh;

	if (mt) {
		/* a loaded mesh wins over the built-in one and the sprite */
		cr = mt->r, cg = mt->g, cb = mt->b;
		mesh = R_MESH_LOADED;
	} else {
		mesh = r_mesh_of(type, &cr, &cg, &cb);
	}
	if (!mesh)
		return 0;
	memset(out, 0, sizeof(*out));
	out->mp = mt ? &mt->m : NULL;
	out->x = x;
	out->y = y;
	out->z = z;
	out->angle = (ang_t)(tick * R_MESH_TURN);
	out->mesh = (uint8_t)mesh;
	out->colour = pal_nearest(&t->pal, cr, cg, cb);
	return 1;
}

/* Adds thing type `type` at (x, y, z) as its mesh when it has one
 * (r_game_mesh, at the sim's tick); 1 when it has one. */
static int r_put_mesh(struct r_out *o, const struct sim *s, uint16_t type, fx_t x, fx_t y, fx_t z)
{
	struct r_sprite sp;

	if (!r_game_mesh(o->t, o->ms, type, s->tick, x, y, z, &sp))
		return 0;
	if (o->n < o->max)
		o->out[o->n++] = sp;
	return 1;
}

static void r_put_enemy(struct r_out *o, const struct g_enemy *e)
{
	struct g_thing_info ti;
	int spr, frame = 0, bright = 0, need = 0;

	g_thing_info(e->type, &ti);
	spr = r_sprite_index(o->t, ti.sprite, R_STANDIN_ENEMY);
	switch (e->state) {
	case G_E_CHASE:
		frame = ti.frames ? e->anim / R_ANIM % ti.frames : 0;
		break;
	case G_E_ATTACK:
		/* a kind with a wind-up stands (frame A) until it starts, so
		 * the aiming frame is its telegraph */
		if (g_kinds[e->kind % G_KINDS].windup && !e->flash && !g_enemy_winding(e))
			frame = 0;
		else
			frame = ti.attack + (e->flash ? 1 : 0);
		bright = e->flash != 0;
		break;
	case G_E_PAIN:
		frame = ti.pain;
		break;
	case G_E_DEAD:
		frame = ti.death0 + e->anim / R_DEATH_TICKS;
		if (frame > ti.death1)
			frame = ti.death1;
		need = 1;
		break;
	default:
		break;
	}
	r_put(o, e->x, e->y, e->z, e->angle, spr, frame, bright, need);
}

/* The sector thing i of m stands in: map_finish's, or found now for a
 * thing it did not see. */
static uint32_t r_thing_sector(const struct map *m, uint32_t i)
{
	return i < m->num_thing_sec ? m->thing_sec[i]
				    : map_point_sector(m, m->things[i].x, m->things[i].y);
}

int r_game_sprites(const struct sim *s, const struct tex_set *t, const struct mesh_set *meshes,
		   struct r_sprite *out, int max)
{
	const struct map *m = s->map;
	struct r_out o = { t, meshes, out, 0, max };

	if (!t || !m)
		return 0;
	for (int i = 0; i < s->g.num_enemies; i++)
		r_put_enemy(&o, &s->g.en[i]);
	for (int i = 0; i < s->g.num_pickups; i++) {
		const struct g_pickup *p = &s->g.pk[i];
		struct g_thing_info ti;
		fx_t floor_h;

		if (p->taken)
			continue;
		g_thing_info(p->type, &ti);
		/* on its floor as it is now (a lift carries it) */
		floor_h = s->w.sec[map_point_sector(m, p->x, p->y)].floor_h;
		if (r_put_mesh(&o, s, p->type, p->x, p->y, floor_h))
			continue;
		r_put(&o, p->x, p->y, floor_h, 0,
		      r_sprite_index(t, ti.sprite, p->kind == G_P_HEALTH ? R_STANDIN_HEALTH : R_STANDIN_PICKUP),
		      ti.stand + (ti.frames > 1 ? (int)(s->tick / R_ANIM % ti.frames) : 0),
		      ti.bright, 0);
	}
	for (uint32_t i = 0; i < m->num_things; i++) {
		const struct map_thing *th = &m->things[i];
		struct g_thing_info ti;
		fx_t floor_h;

		g_thing_info(th->type, &ti);
		if ((ti.cls != G_C_LIGHT && ti.cls != G_C_DECOR) || !ti.sprite[0])
			continue;
		/* the sector map_finish found, not a BSP descent per thing
		 * a frame: the daemon makes this list beside the renderer's
		 * walk, and a list slower than the walk holds up the frame */
		floor_h = s->w.sec[r_thing_sector(m, i)].floor_h;
		if (r_put_mesh(&o, s, th->type, th->x, th->y, floor_h))
			continue;
		r_put(&o, th->x, th->y, floor_h,
		      th->angle, r_sprite_index(t, ti.sprite, ti.cls == G_C_LIGHT ? R_STANDIN_LIGHT : R_STANDIN_DECOR),
		      ti.stand + (ti.frames > 1 ? (int)(s->tick / R_ANIM % ti.frames) : 0),
		      ti.bright, 0);
	}
	for (int i = 0; i < s->g.num_missiles; i++) {
		const struct g_missile *ms = &s->g.ms[i];
		/* flying: A and B in turn; exploding: C, D, E over G_MISSILE_BOOM */
		int frame = ms->boom ? 2 + (G_MISSILE_BOOM - ms->boom) * 3 / G_MISSILE_BOOM
				     : (int)(s->tick / R_MISSILE_ANIM % 2);
		/* the pictures are centred (BAL1's offsets): at the ball's middle */
		r_put(&o, ms->x, ms->y, ms->z + G_MISSILE_HEIGHT / 2, 0,
		      r_sprite_index(t, R_SPR_MISSILE, R_SPR_PUFF), frame, 1, 0);
	}
	if ((s->g.shot == G_SHOT_WALL || s->g.shot == G_SHOT_ENEMY) && s->g.shot_t < R_PUFF_TICKS) {
		int spr = tex_find_sprite(t, s->g.shot == G_SHOT_WALL ? R_SPR_PUFF : R_SPR_BLOOD);
		if (spr >= 0)
			r_put(&o, s->g.shot_x, s->g.shot_y, s->g.shot_z - 8 * FX_ONE, 0, spr,
			      s->g.shot_t / 2, s->g.shot == G_SHOT_WALL, 1);
	}
	return o.n;
}

/* r_map_sprites and r_map_things: meshes when with_meshes. */
static int r_map_list(const struct map *m, const struct tex_set *t, int with_meshes,
		      uint32_t tick, struct r_sprite *out)
{
	int n = 0;

	for (uint32_t i = 0; i < m->num_things; i++) {
		const struct map_thing *th = &m->things[i];
		const struct th_info *in = th_find(th->type);
		const struct map_sector *sec;
		int s;

		if (!in || (in->flags & (TH_PLAYER | TH_INVISIBLE)) || !in->sprite[0])
			continue;
		sec = &m->sectors[r_thing_sector(m, i)];
		/* on its floor, as the game puts pickups and decorations */
		if (with_meshes && r_game_mesh(t, NULL, th->type, tick, th->x, th->y, sec->floor_h, &out[n])) {
			n++;
			continue;
		}
		s = tex_find_sprite(t, in->sprite);
		if (s < 0)
			continue;
		out[n].x = th->x;
		out[n].y = th->y;
		out[n].z = (in->flags & TH_HANGING) ? sec->ceil_h - in->height * FX_ONE : sec->floor_h;
		out[n].angle = th->angle;
		out[n].sprite = (uint16_t)s;
		out[n].frame = (uint16_t)(in->frame - 'A');
		out[n].flags = (in->flags & TH_LIGHT) ? R_SPR_FULLBRIGHT : 0;
		out[n].mesh = 0;
		out[n].colour = 0;
		out[n].mp = NULL;
		n++;
	}
	return n;
}

int r_map_sprites(const struct map *m, const struct tex_set *t, struct r_sprite *out)
{
	return r_map_list(m, t, 0, 0, out);
}

int r_map_things(const struct map *m, const struct tex_set *t, uint32_t tick, struct r_sprite *out)
{
	return r_map_list(m, t, 1, tick, out);
}

/* Grows *p (of *cap elements of size elem) to n. 0 or -1. */
static int r_live_grow(void **p, uint32_t *cap, size_t elem, uint32_t n)
{
	void *q;

	if (n <= *cap)
		return 0;
	q = realloc(*p, (size_t)n * elem);
	if (!q)
		return -1;
	*p = q;
	*cap = n;
	return 0;
}

const struct map *r_game_live(struct r_live *l, const struct sim *s, const struct tex_set *t)
{
	const struct map *m = s->map;
	/* the scroll: a unit a Doom tic (35 Hz) of the stage's ticks */
	fx_t scroll = (fx_t)((int64_t)s->g.stage_t * 35 * FX_ONE / 60);

	if (r_live_grow((void **)&l->sectors, &l->cap_sectors, sizeof(*l->sectors),
			m->num_sectors) < 0 ||
	    r_live_grow((void **)&l->sides, &l->cap_sides, sizeof(*l->sides), m->num_sides) < 0 ||
	    s->w.num_sectors != m->num_sectors)
		return m;
	l->map = *m;
	l->map.sectors = l->sectors;
	l->map.sides = l->sides;
	memcpy(l->sectors, m->sectors, (size_t)m->num_sectors * sizeof(*l->sectors));
	memcpy(l->sides, m->sides, (size_t)m->num_sides * sizeof(*l->sides));
	for (uint32_t i = 0; i < m->num_sectors; i++) {
		const struct g_sector *g = &s->w.sec[i];
		l->sectors[i].floor_h = g->floor_h;
		l->sectors[i].ceil_h = g->ceil_h;
		l->sectors[i].floor_tex = g->floor_tex;
		l->sectors[i].light = g->light;
		l->sectors[i].special = g->special;
	}
	for (uint32_t k = 0; k < m->num_spec_lines; k++) {
		uint32_t i = m->spec_lines[k];
		const struct map_line *ln = &m->lines[i];
		struct map_side *sd = &l->sides[ln->side[0]];
		if (ln->special == 48)
			sd->xoff += scroll;
		else if (ln->special == 85)
			sd->xoff -= scroll;
		if (t && g_world_bit(s->w.switched, i)) {
			/* Doom's order: the upper, middle, then lower texture */
			uint16_t *part[3] = { &sd->top_tex, &sd->mid_tex, &sd->bot_tex };
			for (int p = 0; p < 3; p++) {
				int o = tex_switch_partner(t, *part[p]);
				if (o > 0) {
					*part[p] = (uint16_t)o;
					break;
				}
			}
		}
	}
	return &l->map;
}

void r_live_free(struct r_live *l)
{
	if (!l)
		return;
	free(l->sectors);
	free(l->sides);
	memset(l, 0, sizeof(*l));
}

void r_game_view(const struct sim *s, int w, struct r_view *v)
{
	v->x = s->pl.x;
	v->y = s->pl.y;
	v->z = s->pl.viewz;
	v->angle = s->pl.angle;
	/* the pitch's slope times the focal length (w / 2 pixels): the point
	 * straight ahead along the pitch lands on the middle row, as the shot
	 * goes; the same angle at every resolution */
	v->shear = (int32_t)(((int64_t)s->pl.pitch * (w > 0 ? w / 2 : 0)) >> FX_SHIFT);
}

void r_game_want(const struct tex_set *t, const struct map *m, uint8_t *want_pics)
{
	static const char fixed[][5] = { R_STANDIN_ENEMY, R_STANDIN_HEALTH, R_STANDIN_PICKUP,
					 R_STANDIN_LIGHT, R_STANDIN_DECOR, R_SPR_PUFF,
					 R_SPR_BLOOD, R_SPR_MISSILE };

	for (size_t i = 0; i < sizeof(fixed) / sizeof(fixed[0]); i++)
		tex_want_sprite(t, fixed[i], want_pics);
	for (uint32_t i = 0; i < m->num_things; i++) {
		struct g_thing_info ti;

		g_thing_info(m->things[i].type, &ti);
		if (ti.sprite[0])
			tex_want_sprite(t, ti.sprite, want_pics);
	}
}
