/*
 * sim_hash: the per-tick hash of the whole sim state, field by field in
 * declaration order (never struct bytes, which carry padding). Enemy and
 * pickup slots past the counts are not state (spawning overwrites them)
 * and are not hashed.
 */
#include "engine/sim.h"

#include "engine/hash.h"
#include "engine/map.h"

static uint64_t sim_hash_settings(uint64_t h, const struct sim_settings *t)
{
	h = hash_u8(h, t->coins_per_credit);
	h = hash_u8(h, t->freeplay);
	h = hash_u8(h, t->start_in_play);
	h = hash_u8(h, t->difficulty);
	return hash_u8(h, t->lives);
}

static uint64_t sim_hash_player(uint64_t h, const struct sim_player *p)
{
	h = hash_i32(h, p->x);
	h = hash_i32(h, p->y);
	h = hash_i32(h, p->z);
	h = hash_i32(h, p->viewz);
	h = hash_i32(h, p->momx);
	h = hash_i32(h, p->momy);
	h = hash_u32(h, p->angle);
	h = hash_u32(h, p->sector);
	h = hash_i32(h, p->health);
	h = hash_u16(h, p->ammo);
	h = hash_u16(h, p->refire);
	h = hash_u16(h, p->hurt);
	return hash_u16(h, p->bonus);
}

static uint64_t sim_hash_enemy(uint64_t h, const struct g_enemy *e)
{
	h = hash_i32(h, e->x);
	h = hash_i32(h, e->y);
	h = hash_i32(h, e->z);
	h = hash_u32(h, e->angle);
	h = hash_u32(h, e->sector);
	h = hash_i32(h, e->sx);
	h = hash_i32(h, e->sy);
	h = hash_u32(h, e->sangle);
	h = hash_u16(h, e->type);
	h = hash_u8(h, e->kind);
	h = hash_u8(h, e->state);
	h = hash_u16(h, (uint16_t)e->health);
	h = hash_u16(h, e->timer);
	h = hash_u16(h, e->anim);
	h = hash_u32(h, e->wander);
	h = hash_u8(h, e->stuck);
	return hash_u8(h, e->flash);
}

static uint64_t sim_hash_pickup(uint64_t h, const struct g_pickup *p)
{
	h = hash_i32(h, p->x);
	h = hash_i32(h, p->y);
	h = hash_i32(h, p->z);
	h = hash_u16(h, p->type);
	h = hash_u8(h, p->kind);
	h = hash_u8(h, p->taken);
	return hash_u16(h, p->amount);
}

static uint64_t sim_hash_game(uint64_t h, const struct g_game *g)
{
	h = hash_u32(h, g->score);
	h = hash_u8(h, g->lives);
	h = hash_u8(h, g->continues);
	h = hash_u8(h, g->stage);
	h = hash_u8(h, g->loop);
	h = hash_u8(h, g->phase);
	h = hash_u16(h, g->phase_t);
	h = hash_u32(h, g->stage_t);
	h = hash_u32(h, g->kills);
	h = hash_u16(h, g->num_enemies);
	h = hash_u16(h, g->num_pickups);
	h = hash_u16(h, g->alive);
	for (int i = 0; i < g->num_enemies && i < G_MAX_ENEMIES; i++)
		h = sim_hash_enemy(h, &g->en[i]);
	for (int i = 0; i < g->num_pickups && i < G_MAX_PICKUPS; i++)
		h = sim_hash_pickup(h, &g->pk[i]);
	h = hash_i32(h, g->shot_x);
	h = hash_i32(h, g->shot_y);
	h = hash_i32(h, g->shot_z);
	h = hash_u8(h, g->shot);
	return hash_u16(h, g->shot_t);
}

static uint64_t sim_hash_scores(uint64_t h, const struct g_scores *t)
{
	for (int i = 0; i < G_SCORES; i++) {
		h = hash_bytes(h, t->e[i].name, G_NAME_LEN);
		h = hash_u32(h, t->e[i].score);
		h = hash_u8(h, t->e[i].stage);
	}
	return h;
}

static uint64_t sim_hash_menu(uint64_t h, const struct menu *m)
{
	h = hash_u8(h, m->page);
	h = hash_u8(h, m->cursor);
	h = hash_u8(h, m->main_cursor);
	h = hash_u8(h, m->display);
	h = hash_u8(h, m->confirm);
	h = hash_u8(h, m->yes);
	h = hash_u8(h, m->res);
	h = hash_u8(h, m->done);
	h = hash_u16(h, m->done_t);
	h = hash_u32(h, m->coins_seen);
	return hash_u32(h, m->t);
}

uint64_t sim_hash(const struct sim *s)
{
	uint64_t h = HASH_INIT;

	h = hash_u64(h, sim_stages_hash(s->stages, s->num_stages));
	h = hash_u64(h, s->map ? s->map->content_hash : 0);
	h = hash_u8(h, s->num_stages);
	h = sim_hash_settings(h, &s->set);
	h = hash_u32(h, s->tick);
	h = hash_u32(h, (uint32_t)s->mode);
	h = hash_u8(h, s->page);
	h = hash_u32(h, s->mode_t);
	h = hash_u32(h, s->credits);
	h = hash_u32(h, s->coin_rem);
	h = hash_u32(h, s->coins_total);
	h = hash_u32(h, s->plays);
	h = hash_u8(h, s->prev_buttons);
	h = hash_u8(h, s->prev_nav);
	h = hash_u16(h, s->nav_t);
	h = hash_u8(h, (uint8_t)s->cmd.forward);
	h = hash_u8(h, (uint8_t)s->cmd.side);
	h = hash_u16(h, (uint16_t)s->cmd.turn);
	h = hash_u8(h, s->cmd.buttons);
	h = hash_u8(h, s->cmd.coins);
	h = hash_u32(h, s->rng);
	h = sim_hash_player(h, &s->pl);
	h = sim_hash_game(h, &s->g);
	h = hash_u16(h, s->countdown);
	h = hash_u8(h, s->ini_pos);
	h = hash_bytes(h, s->ini, G_NAME_LEN);
	h = hash_u8(h, (uint8_t)s->ini_rank);
	h = hash_u8(h, (uint8_t)s->new_rank);
	h = sim_hash_scores(h, &s->scores);
	h = hash_u32(h, s->books.coins);
	h = hash_u32(h, s->books.plays);
	h = hash_u64(h, s->books.play_ticks);
	h = hash_u64(h, s->books.on_ticks);
	h = hash_u32(h, s->set_gen);
	h = hash_u32(h, s->scores_gen);
	h = hash_u32(h, s->books_gen);
	return sim_hash_menu(h, &s->menu);
}
