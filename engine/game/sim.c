/*
 * sim: the mode machine (attract, play, game over, initials, service),
 * coins and credits, stages, lives and the player, in 16.16 fixed point.
 * The rules of the fight live in the g_*.c files, the service menu in
 * menu.c; this file sequences them, one tick at a time.
 */
#include "engine/game/sim.h"

#include <assert.h>
#include <stddef.h>
#include <string.h>

#include "engine/core/hash.h"
#include "engine/core/tab.h"
#include "engine/game/g_local.h"
#include "engine/map/map.h"
#include "engine/sound/snd.h"
#include "engine/sound/syn.h"

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
#define SIM_ATTRACT_TURN (ANG90 / (8 * SIM_TICRATE))  /* a turn in 32 s */
#define SIM_RNG_SEED 0x2545f491u
#define SIM_SPAWN_INSET (32 * FX_ONE)  /* no player start: this far off a wall */
#define SIM_DEAD_VIEW (8 * FX_ONE)     /* eye height of a dead player */
#define SIM_FANFARE_AT 30              /* the stage fanfare: ticks into the CLEAR phase */

/* Names as arrays, not pointers: the tables stay read-only data. */
static const char sim_modes[SIM_MODE_COUNT][10] = {
	[SIM_ATTRACT] = "attract", [SIM_PLAY] = "play", [SIM_GAMEOVER] = "gameover",
	[SIM_INITIALS] = "initials", [SIM_SERVICE] = "service",
};

static const char sim_pages[SIM_PAGE_COUNT][8] = {
	[SIM_PAGE_TITLE] = "title", [SIM_PAGE_SCORES] = "scores", [SIM_PAGE_DEMO] = "demo",
};

const char *sim_mode_name(enum sim_mode m)
{
	return (unsigned)m < SIM_MODE_COUNT ? sim_modes[m] : NULL;
}

int sim_mode_from_name(const char *name)
{
	for (int i = 0; i < SIM_MODE_COUNT; i++)
		if (strcmp(name, sim_modes[i]) == 0)
			return i;
	return -1;
}

const char *sim_page_name(int page)
{
	return page >= 0 && page < SIM_PAGE_COUNT ? sim_pages[page] : NULL;
}

int sim_page_from_name(const char *name)
{
	for (int i = 0; i < SIM_PAGE_COUNT; i++)
		if (strcmp(name, sim_pages[i]) == 0)
			return i;
	return -1;
}

static void sim_settle(struct sim *s)
{
	struct sim_player *p = &s->pl;

	p->sector = map_point_sector(s->map, p->x, p->y);
	p->z = s->w.sec[p->sector].floor_h;
	p->viewz = p->z + SIM_VIEW_HEIGHT;
}

/* Puts the player at the map's player 1 start, or, without one, SPAWN_INSET
 * in front of the middle of the first line whose front side faces sector 0,
 * facing along that line. Keeps health, ammo and weapons. */
static void sim_spawn(struct sim *s)
{
	const struct map *m = s->map;
	struct sim_player *p = &s->pl;
	fx_t health = p->health;
	uint16_t ammo = p->ammo;
	uint8_t weapons = p->weapons, weapon = p->weapon;
	uint32_t i;

	memset(p, 0, sizeof *p);
	p->health = health;
	p->ammo = ammo;
	p->weapons = weapons;
	p->weapon = weapon;
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

/* Loads stage i: its map, enemies and pickups, the player at its start. */
static void sim_start_stage(struct sim *s, int i)
{
	s->g.stage = (uint8_t)i;
	s->map = s->stages[i];
	s->g.phase = G_PH_PLAY;
	s->g.phase_t = 0;
	s->g.stage_t = 0;
	s->g.shot = G_SHOT_NONE;
	s->g.shot_t = UINT16_MAX;
	/* a new stage: its world's sounds stop, the cabinet's play on */
	g_sound_clear(s, 1);
	g_spec_start(s);
	g_spawn_stage(s);
	sim_spawn(s);
	g_pace_start(s);
}

/* The other player's turn (g_turn.c changed the seats): their stage from
 * its start, behind the "PLAYER n" page. */
static void sim_turn_start(struct sim *s)
{
	s->mode = SIM_PLAY;
	s->mode_t = 0;
	sim_start_stage(s, s->g.stage);
	s->g.phase = G_PH_TURN;
}

/* g_turn_pass and g_turn_over, and the new player's stage when the turn
 * passed. */
static int sim_turn_pass(struct sim *s)
{
	if (!g_turn_pass(s))
		return 0;
	sim_turn_start(s);
	return 1;
}

static int sim_turn_over(struct sim *s)
{
	if (!g_turn_over(s))
		return 0;
	sim_turn_start(s);
	return 1;
}

static void sim_full_health(struct sim *s)
{
	s->pl.health = G_HEALTH_MAX * FX_ONE;
	if (s->pl.ammo < G_AMMO_START)
		s->pl.ammo = G_AMMO_START;
}

static void sim_new_game(struct sim *s, int players)
{
	memset(&s->g, 0, sizeof s->g);
	s->g.lives = (uint8_t)g_lives_setting(s);
	s->pl.ammo = 0;
	g_weapon_reset(s);
	sim_full_health(s);
	s->new_rank = -1;
	s->mode = SIM_PLAY;
	s->mode_t = 0;
	sim_start_stage(s, 0);
	g_turn_begin(s, players);
}

/* Back to attract at `page`: the world is stage 0 again, seen by the idle
 * camera. */
static void sim_attract(struct sim *s, int page)
{
	s->mode = SIM_ATTRACT;
	s->page = (uint8_t)page;
	s->mode_t = 0;
	sim_start_stage(s, 0);
}

void sim_init_stages(struct sim *s, const struct map *const *maps, int n,
		     const struct sim_settings *set, const struct g_scores *scores,
		     const struct g_books *books)
{
	assert(n >= 1 && n <= G_MAX_STAGES);
	memset(s, 0, sizeof *s);
	for (int i = 0; i < n; i++)
		s->stages[i] = maps[i];
	s->num_stages = (uint8_t)n;
	s->set = *set;
	s->rng = SIM_RNG_SEED;
	g_weapon_reset(s);
	for (int id = 1; id < SFX_COUNT; id++) {
		/* the built-in set's lengths until the app gives its own */
		struct snd b = { NULL, syn_len(id), SYN_RATE };
		s->snd.len[id] = snd_ticks(&b);
	}
	s->new_rank = -1;
	s->ini_rank = -1;
	if (scores)
		s->scores = *scores;
	else
		g_scores_default(&s->scores);
	if (books)
		s->books = *books;
	if (set->start_in_play)
		sim_new_game(s, 1);
	else
		sim_attract(s, SIM_PAGE_TITLE);
}

void sim_set_sounds(struct sim *s, const struct snd_set *set)
{
	for (int id = 1; id < SFX_COUNT; id++)
		s->snd.len[id] = snd_ticks(&set->s[id]);
}

void sim_init(struct sim *s, const struct map *m, const struct sim_settings *set)
{
	sim_init_stages(s, &m, 1, set, NULL, NULL);
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

/* The pitch from the look buttons (g_game.h G_PITCH_*): held moves it,
 * both centre it; it turns even while the player is held still. */
static void sim_look(struct sim_player *p, uint8_t buttons)
{
	uint8_t look = buttons & (SIM_BT_LOOK_UP | SIM_BT_LOOK_DOWN);

	if (look == (SIM_BT_LOOK_UP | SIM_BT_LOOK_DOWN))
		p->pitch = 0;
	else if (look == SIM_BT_LOOK_UP)
		p->pitch = p->pitch + G_PITCH_STEP > G_PITCH_MAX ? G_PITCH_MAX
								 : p->pitch + G_PITCH_STEP;
	else if (look == SIM_BT_LOOK_DOWN)
		p->pitch = p->pitch - G_PITCH_STEP < -G_PITCH_MAX ? -G_PITCH_MAX
								   : p->pitch - G_PITCH_STEP;
}

static void sim_player_move(struct sim *s, const struct sim_cmd *cmd)
{
	struct sim_player *p = &s->pl;
	int64_t mx = p->momx, my = p->momy;

	sim_look(p, cmd->buttons);
	if (p->freeze) {
		/* held still after a teleport (Doom's reactiontime) */
		p->freeze--;
		return;
	}
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
	if (p->momx || p->momy) {
		struct g_body b = { p->x, p->y, p->z, p->momx, p->momy, SIM_PLAYER_RADIUS, -1 };
		fx_t ox = p->x, oy = p->y;
		g_move(s, &b);
		p->x = b.x;
		p->y = b.y;
		p->momx = b.momx;
		p->momy = b.momy;
		sim_settle(s);
		/* the walk-over specials (a teleport moves the player on) */
		g_cross(s, G_WHO_PLAYER, ox, oy, p->x, p->y, SIM_PLAYER_RADIUS);
	}
	if (!cmd->forward && !cmd->side && fx_abs(p->momx) < SIM_STOPSPEED &&
	    fx_abs(p->momy) < SIM_STOPSPEED) {
		p->momx = 0;
		p->momy = 0;
	} else {
		p->momx = sim_friction(p->momx);
		p->momy = sim_friction(p->momy);
	}
}

/* The player lost a life (the death phase ended). */
static void sim_life_lost(struct sim *s)
{
	struct g_game *g = &s->g;

	if (g->lives > 0)
		g->lives--;
	if (g->lives > 0) {
		sim_full_health(s);
		g_weapon_reset(s);
		if (sim_turn_pass(s))
			return;                /* the other player's turn */
		g_enemies_reset(s);
		g->phase = G_PH_PLAY;
		g->phase_t = 0;
		sim_spawn(s);
		g_pace_start(s);
		return;
	}
	s->mode = SIM_GAMEOVER;
	s->mode_t = 0;
	s->countdown = G_CONTINUE_TICKS;
	g_sound_play(s, SFX_GAME_OVER, G_SRC_ANNOUNCE);
}

/* An extra life for every G_EXTRA_LIFE_SCORE points (up to 9 lives). */
static void sim_extra_life(struct sim *s, uint32_t before)
{
	struct g_game *g = &s->g;

	if (g->score / G_EXTRA_LIFE_SCORE == before / G_EXTRA_LIFE_SCORE || g->lives >= 9)
		return;
	g->lives++;
	g_sound_play(s, SFX_EXTRA_LIFE, G_SRC_BONUS);
}

/* The next stage after the intermission (or a cleared stage): one loop
 * harder when the game comes back to the first. */
static void sim_next_stage(struct sim *s, int next)
{
	struct g_game *g = &s->g;

	if (s->pl.ammo < G_AMMO_START)
		s->pl.ammo = G_AMMO_START;
	if (next == 0 && g->loop < UINT8_MAX)
		g->loop++;
	sim_start_stage(s, next);
}

static void sim_play_tick(struct sim *s, const struct sim_cmd *cmd, uint8_t pressed)
{
	struct g_game *g = &s->g;
	struct sim_player *p = &s->pl;
	uint32_t score = g->score;

	if (g->stage_t < UINT32_MAX)
		g->stage_t++;
	if (g->shot_t < UINT16_MAX)
		g->shot_t++;
	if (p->refire)
		p->refire--;
	if (p->hurt)
		p->hurt--;
	if (p->bonus)
		p->bonus--;
	switch (g->phase) {
	case G_PH_PLAY:
		sim_player_move(s, cmd);
		if ((pressed & SIM_BT_USE) && g->phase == G_PH_PLAY)
			g_use(s);
		if ((pressed & SIM_BT_WEAPON) && g->phase == G_PH_PLAY)
			g_weapon_next(s);
		if ((cmd->buttons & SIM_BT_FIRE) && g_weapon_can_fire(s) && g->phase == G_PH_PLAY)
			g_fire(s);
		g_pickups_tick(s);
		g_pace_tick(s, cmd);
		g_enemies_tick(s);
		g_spec_tick(s);
		/* a map with an exit ends there; one without when it is cleared */
		if (g->phase == G_PH_PLAY && !s->w.has_exit && g->num_enemies > 0 && g->alive == 0) {
			g->score += G_STAGE_BONUS * ((uint32_t)g->stage + 1);
			g_pace_bonus(s);
			g->phase = G_PH_CLEAR;
			g->phase_t = 0;
			g_sound_play(s, SFX_STAGE_CLEAR, G_SRC_ANNOUNCE);
		}
		sim_extra_life(s, score);
		break;
	case G_PH_DEAD:
		g->phase_t++;
		g_spec_tick(s);
		p->momx = p->momy = 0;
		if (p->viewz - p->z > SIM_DEAD_VIEW)
			p->viewz -= FX_ONE;
		if (g->phase_t >= G_DEAD_TICKS)
			sim_life_lost(s);
		break;
	case G_PH_CLEAR:
		/* the player may walk about while the banner shows */
		g->phase_t++;
		if (g->phase_t == SIM_FANFARE_AT)
			g_sound_play(s, SFX_FANFARE, G_SRC_MUSIC);
		sim_player_move(s, cmd);
		g_spec_tick(s);
		g_enemies_tick(s);             /* the last kill, a flyer, falls */
		if (g->phase_t >= G_CLEAR_TICKS)
			sim_next_stage(s, g->stage + 1 < s->num_stages ? g->stage + 1 : 0);
		break;
	case G_PH_TURN:
		/* the "PLAYER n" page: the stage waits, its clock full */
		g->phase_t++;
		if (g->phase_t >= G_TURN_TICKS) {
			g->phase = G_PH_PLAY;
			g->phase_t = 0;
			g->stage_t = 0;        /* the STAGE banner after the page */
			g_pace_start(s);
		}
		break;
	case G_PH_INTER:
	default:
		/* the intermission: FIRE or USE goes on after a second */
		g->phase_t++;
		if (g->phase_t >= G_INTER_TICKS ||
		    (g->phase_t >= G_INTER_MIN && (pressed & (SIM_BT_FIRE | SIM_BT_USE))))
			sim_next_stage(s, s->w.next < s->num_stages ? s->w.next : 0);
		break;
	}
}

static void sim_gameover_tick(struct sim *s, uint8_t pressed)
{
	int rank;

	/* either start button continues the game of the player up */
	if ((pressed & (SIM_BT_START | SIM_BT_START2)) && sim_pay(s, 1)) {
		struct g_game *g = &s->g;
		if (g->continues < UINT8_MAX)
			g->continues++;
		g->lives = (uint8_t)g_lives_setting(s);
		sim_full_health(s);
		g_weapon_reset(s);
		g_enemies_reset(s);
		g->phase = G_PH_PLAY;
		g->phase_t = 0;
		/* a life was lost: the other player's turn, if they are in */
		if (!sim_turn_pass(s)) {
			sim_spawn(s);
			s->mode = SIM_PLAY;
			s->mode_t = 0;
		}
		g_sound_play(s, SFX_START, G_SRC_ANNOUNCE);
		return;
	}
	if (pressed & SIM_BT_FIRE)
		s->countdown = s->countdown > SIM_TICRATE ? (uint16_t)(s->countdown - SIM_TICRATE) : 0;
	else if (s->countdown)
		s->countdown--;
	/* a tick for each whole second of the countdown */
	if (s->countdown && s->countdown % SIM_TICRATE == 0)
		g_sound_play(s, SFX_COUNTDOWN, G_SRC_TICKER);
	if (s->countdown)
		return;
	rank = g_scores_rank(&s->scores, s->g.score);
	if (rank < 0) {
		if (!sim_turn_over(s))
			sim_attract(s, SIM_PAGE_TITLE);
		return;
	}
	s->mode = SIM_INITIALS;
	s->mode_t = 0;
	s->ini_pos = 0;
	memset(s->ini, 0, sizeof s->ini);
	s->ini_rank = (int8_t)rank;
}

static void sim_initials_done(struct sim *s)
{
	char name[G_NAME_LEN];

	for (int i = 0; i < G_NAME_LEN; i++)
		name[i] = G_ALPHABET[s->ini[i] % G_ALPHABET_LEN];
	g_scores_insert(&s->scores, s->ini_rank, name, s->g.score, (uint8_t)(s->g.stage + 1));
	s->scores_gen++;
	s->new_rank = s->ini_rank;
	s->ini_rank = -1;
	if (!sim_turn_over(s))
		sim_attract(s, SIM_PAGE_SCORES);
}

static void sim_initials_tick(struct sim *s, uint8_t pressed, uint8_t nav)
{
	uint8_t *c = &s->ini[s->ini_pos];

	if (nav & (MENU_NAV_UP | MENU_NAV_RIGHT))
		*c = (uint8_t)((*c + 1) % G_ALPHABET_LEN);
	else if (nav & (MENU_NAV_DOWN | MENU_NAV_LEFT))
		*c = (uint8_t)((*c + G_ALPHABET_LEN - 1) % G_ALPHABET_LEN);
	if (nav)
		g_sound_play(s, SFX_MENU_MOVE, G_SRC_MENU);
	if (pressed & SIM_BT_FIRE) {
		g_sound_play(s, SFX_MENU_SELECT, G_SRC_MENU);
		s->ini_pos++;
		if (s->ini_pos >= G_NAME_LEN) {
			sim_initials_done(s);
			return;
		}
		s->ini[s->ini_pos] = s->ini[s->ini_pos - 1];  /* start from the last letter */
	}
	if (s->mode_t >= G_INITIALS_TICKS)
		sim_initials_done(s);
}

static void sim_attract_tick(struct sim *s, uint8_t pressed)
{
	static const uint32_t len[SIM_PAGE_COUNT] = { SIM_TITLE_TICKS, SIM_SCORES_TICKS,
						      SIM_DEMO_TICKS };

	/* 2P start: two players' credits; plays count a game a player */
	int players = (pressed & SIM_BT_START2) && sim_pay(s, 2) ? 2
		      : (pressed & SIM_BT_START) && sim_pay(s, 1) ? 1 : 0;

	if (players) {
		s->plays += (uint32_t)players;
		s->books.plays += (uint32_t)players;
		s->books_gen++;
		sim_new_game(s, players);
		g_sound_play(s, SFX_START, G_SRC_ANNOUNCE);
		return;
	}
	if (s->page == SIM_PAGE_TITLE && s->mode_t == 1) {
		/* a new attract cycle: its jingle, when the setting has sound now */
		s->attract_cycle++;
		g_sound_play(s, SFX_JINGLE, G_SRC_MUSIC);
	}
	s->pl.angle += SIM_ATTRACT_TURN;
	if (s->mode_t >= len[s->page % SIM_PAGE_COUNT]) {
		s->page = (uint8_t)((s->page + 1) % SIM_PAGE_COUNT);
		s->mode_t = 0;
	}
}

void sim_tick(struct sim *s, const struct sim_cmd *cmd)
{
	uint8_t pressed = (uint8_t)(cmd->buttons & ~s->prev_buttons);
	uint8_t nav = sim_nav(s, cmd);

	s->prev_buttons = cmd->buttons;
	s->cmd = *cmd;
	s->books.on_ticks++;
	if (s->mode_t < UINT32_MAX)
		s->mode_t++;
	g_sound_age(s);
	sim_coins(s, cmd->coins);
	if ((pressed & SIM_BT_SERVICE) && s->mode != SIM_SERVICE) {
		s->mode = SIM_SERVICE;
		s->mode_t = 0;
		menu_enter(&s->menu);
		g_sound_clear(s, 1);
		pressed = 0;
	}
	switch (s->mode) {
	case SIM_ATTRACT:
		sim_attract_tick(s, pressed);
		break;
	case SIM_PLAY:
		s->books.play_ticks++;
		sim_play_tick(s, cmd, pressed);
		break;
	case SIM_GAMEOVER:
		sim_gameover_tick(s, pressed);
		break;
	case SIM_INITIALS:
		sim_initials_tick(s, pressed, nav);
		break;
	case SIM_SERVICE:
	default:
		if (menu_tick(s, pressed, nav))
			sim_attract(s, SIM_PAGE_TITLE);
		break;
	}
	g_sound_follow(s);
	g_random(s);                   /* stepped every tick so every tick's hash covers it */
	s->tick++;
}

uint64_t sim_stages_hash(const struct map *const *maps, int n)
{
	uint64_t h = HASH_INIT;

	for (int i = 0; i < n; i++)
		h = hash_u64(h, maps[i] ? maps[i]->content_hash : 0);
	return h;
}

