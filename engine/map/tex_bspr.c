/*
 * tex_bspr: the sprites of the project's own texture set (tex_builtin),
 * drawn by integer code under Doom's sprite names, so the thing types the
 * game and the built-in levels use find pictures (th.h, g_thing.c):
 *
 *   POSS, SPOS   grunts (a soldier with a pistol; one with a helmet and a rifle)
 *   TROO         the thrower (a horned clawed imp)
 *   SARG         the brute (a hunched, round-bodied horned demon with a jaw
 *                of teeth, long clawed arms and hooves: tb_brute)
 *   HEAD         the sentry (a hovering one-eyed drone)
 *   SKUL         the flyer (a flaming skull)
 *   MEDI, STIM   health (a medikit; a small blue-cross pack)
 *   CLIP, AMMO   ammunition (a magazine; a box of bullets)
 *   BAR1 barrel, COLU lamp, CBRA candelabra, TRED torch
 *   PUFF, BLUD   a shot's spark on a wall, and blood on an enemy (4 frames)
 *   BAL1         the thrower's missile: a fireball (A, B) and its burst (C..E)
 *   PISG, PISF   the player's pistol on the HUD (5 frames) and its flash
 *
 * The monsters have every frame the game shows (g_thing.c's table): four
 * walking frames in five pictures each (rotations 1..5; 6..8 mirror 4..2),
 * then the attack (wind-up, aim, firing flash), pain, and a death that
 * falls over into a corpse, each one picture for every view. Sprites stand
 * on their feet (left offset half the width, top offset the height);
 * the drone hovers; the puff and blood are centred; the pistol carries
 * Doom's weapon offsets (its top left at (1 - left, 32 - top) on the
 * 320x168 view, hud.c).
 */
#include <stdint.h>
#include <string.h>

#include "engine/map/tex_local.h"
#include "engine/map/tex_paint.h"

/* ---- tones, looks ---------------------------------------------------------- */

struct tb_tone {
	uint8_t ramp, shade;
};

static uint8_t tb_t(struct tb_tone t, int d)
{
	return tp_c(t.ramp, t.shade + d);
}

enum { TB_HEAD_BARE, TB_HEAD_HELMET, TB_HEAD_HORNS, TB_HEAD_JAW };
enum { TB_ARM_PISTOL, TB_ARM_RIFLE, TB_ARM_CLAWS };

/* How a monster looks; TB_L_ORB is the drone (tb_orb), TB_L_SKULL the
 * flyer (tb_skull): neither walks. */
struct tb_look {
	struct tb_tone skin, cloth, legs, trim;
	uint8_t eye;                   /* palette index */
	uint8_t hw;                    /* torso half width seen from the front */
	uint8_t head, arm;
};

enum { TB_L_GRUNT, TB_L_GUNNER, TB_L_IMP, TB_L_DEMON, TB_L_ORB, TB_L_SKULL };

static const struct tb_look tb_looks[] = {
	[TB_L_GRUNT] = { { PAL_TAN, 4 }, { PAL_GREEN, 7 }, { PAL_GREEN, 11 }, { PAL_BROWN, 8 },
			 PAL_RGB(PAL_RED, 3), 8, TB_HEAD_BARE, TB_ARM_PISTOL },
	[TB_L_GUNNER] = { { PAL_TAN, 5 }, { PAL_SLATE, 8 }, { PAL_SLATE, 12 }, { PAL_BLACKRAMP, 4 },
			  PAL_RGB(PAL_RED, 3), 8, TB_HEAD_HELMET, TB_ARM_RIFLE },
	[TB_L_IMP] = { { PAL_BROWN, 6 }, { PAL_BROWN, 7 }, { PAL_BROWN, 10 }, { PAL_BROWN, 12 },
		       PAL_RGB(PAL_YELLOW, 1), 8, TB_HEAD_HORNS, TB_ARM_CLAWS },
	[TB_L_DEMON] = { { PAL_PINK, 6 }, { PAL_PINK, 5 }, { PAL_PINK, 9 }, { PAL_PURPLE, 10 },
			 PAL_RGB(PAL_YELLOW, 1), 11, TB_HEAD_JAW, TB_ARM_CLAWS },
	[TB_L_ORB] = { { PAL_SLATE, 5 }, { PAL_SLATE, 9 }, { PAL_GREY, 6 }, { PAL_YELLOW, 3 },
		       PAL_RGB(PAL_RED, 3), 0, 0, 0 },
	[TB_L_SKULL] = { { PAL_TAN, 1 }, { PAL_ORANGE, 2 }, { PAL_RED, 3 }, { PAL_YELLOW, 1 },
			 PAL_RGB(PAL_RED, 2), 0, 0, 0 },
};

/* Poses: walking (rotations 1..5), and the one-picture frames. */
enum { TB_P_WALK, TB_P_WINDUP, TB_P_AIM, TB_P_FIRE, TB_P_HURT, TB_P_DEAD };

/* ---- the walking monsters ---------------------------------------------------- */

static void tb_disc(struct tex_pic *p, int cx, int cy, int r2, uint8_t c)
{
	for (int y = -8; y <= 8; y++)
		for (int x = -8; x <= 8; x++)
			if (x * x + y * y <= r2)
				tp_set(p, cx + x, cy + y, c);
}

static int tb_abs(int v)
{
	return v < 0 ? -v : v;
}

/* A filled ellipse centred (cx, cy) with radii rx, ry >= 2, in tone t lit
 * from the upper left (d added to every shade), its rim darker. */
static void tb_blob(struct tex_pic *p, int cx, int cy, int rx, int ry, struct tb_tone t, int d)
{
	for (int y = -ry; y <= ry; y++)
		for (int x = -rx; x <= rx; x++)
			if (x * x * ry * ry + y * y * rx * rx <= rx * rx * ry * ry) {
				/* the rim (outside the ellipse one smaller) darker */
				int rim = (rx - 1) * (rx - 1) * (ry - 1) * (ry - 1) <
					  x * x * (ry - 1) * (ry - 1) + y * y * (rx - 1) * (rx - 1);

				tp_set(p, cx + x, cy + y,
				       tb_t(t, d + (2 * x + y) * 4 / (rx + ry + 1) + 3 * rim));
			}
}

/* A rounded limb of radius r from (x0, y0) to (x1, y1), its left side lit,
 * its edge darker. */
static void tb_limb(struct tex_pic *p, int x0, int y0, int x1, int y1, int r, struct tb_tone t,
		    int d)
{
	int n = tb_abs(x1 - x0) > tb_abs(y1 - y0) ? tb_abs(x1 - x0) : tb_abs(y1 - y0);

	if (n == 0)
		n = 1;
	for (int k = 0; k <= n; k++) {
		int cx = x0 + (x1 - x0) * k / n, cy = y0 + (y1 - y0) * k / n;

		for (int y = -r; y <= r; y++)
			for (int x = -r; x <= r; x++)
				if (x * x + y * y <= r * r + r / 2)
					tp_set(p, cx + x, cy + y,
					       tb_t(t, d + (2 * x > r) - (2 * x < -r) +
							  2 * (x * x + y * y > (r - 1) * (r - 1))));
	}
}

/* The muzzle flash or fireball: a bright diamond with rays. */
static void tb_flash(struct tex_pic *p, int cx, int cy, int r)
{
	for (int y = -r - 2; y <= r + 2; y++) {
		for (int x = -r - 2; x <= r + 2; x++) {
			int d = (x < 0 ? -x : x) + (y < 0 ? -y : y);

			if (d <= r / 2)
				tp_set(p, cx + x, cy + y, tp_c(PAL_GREY, 0));
			else if (d <= r)
				tp_set(p, cx + x, cy + y, tp_c(PAL_YELLOW, 1 + d - r / 2));
			else if ((x == 0 || y == 0) && d <= r + 2)
				tp_set(p, cx + x, cy + y, tp_c(PAL_ORANGE, 2));
		}
	}
}

static void tb_head(struct tex_pic *p, const struct tb_look *lk, int pose, int rot, int cx,
		    int hy)
{
	static const int8_t eyes[6][2] = { { 0, 0 }, { -2, 2 }, { -3, 1 }, { -4, 99 }, { 99, 99 },
					   { 99, 99 } };
	int jaw = lk->head == TB_HEAD_JAW, r2 = jaw ? 42 : 30, hx = rot == 3 ? -1 : 0;
	int shut = pose == TB_P_HURT || pose == TB_P_DEAD;

	for (int y = -7; y <= 7; y++) {
		for (int x = -7; x <= 7; x++) {
			uint8_t c = tb_t(lk->skin, x > 2 ? 1 : x < -2 ? -1 : 0);

			if (x * x + y * y > r2)
				continue;
			if (rot == 5 && lk->head == TB_HEAD_BARE)
				c = tp_c(PAL_BROWN, 9);
			if (lk->head == TB_HEAD_HELMET && y <= -2)
				c = tb_t(lk->legs, y == -2 ? 1 : 0);
			tp_set(p, cx + hx + x, hy + y, c);
		}
	}
	if (lk->head == TB_HEAD_HORNS || jaw) {
		int spread = jaw ? 5 : 4;

		for (int k = 0; k < 4; k++) {
			uint8_t c = tp_c(PAL_GREY, 2 + k);

			if (rot != 3)
				tp_set(p, cx + hx + spread + k / 2, hy - 4 - k, c);
			if (rot != 3 || k < 2)
				tp_set(p, cx + hx - spread - k / 2, hy - 4 - k, c);
		}
	}
	for (int e = 0; e < 2; e++) {
		int ex = eyes[pose == TB_P_WALK ? rot : 1][e];

		if (ex == 99)
			continue;
		tp_set(p, cx + hx + ex, hy - 1, shut ? tb_t(lk->skin, 4) : lk->eye);
		if (!shut && lk->head >= TB_HEAD_HORNS)
			tp_set(p, cx + hx + ex, hy - 2, lk->eye);
	}
	if (jaw && rot <= 3) {
		for (int x = -4; x <= 4; x++) {
			tp_set(p, cx + hx + x - (rot == 3 ? 2 : 0), hy + 3,
			       (x & 1) ? tp_c(PAL_GREY, 1) : tp_c(PAL_RED, 10));
			tp_set(p, cx + hx + x - (rot == 3 ? 2 : 0), hy + 4, tp_c(PAL_RED, 11));
		}
	}
}

/* A walking monster in a w x 56 picture, feet on the bottom row. rot 1
 * faces the viewer, 5 shows the back; the weapon hand is the monster's
 * right, which the viewer sees on the left at rotation 1. phase 0..3:
 * the walk (1 and 3 a step with each foot). The poses past walking are
 * seen from the front. */
static void tb_human(struct tex_pic *p, const struct tb_look *lk, int pose, int rot, int phase)
{
	static const int8_t narrow[6] = { 0, 0, 1, 3, 1, 0 };
	int front = pose != TB_P_WALK, r = front ? 1 : rot;
	int cx = p->w / 2, hw = lk->hw - narrow[r], bob = !front && (phase & 1);
	int side = r == 2 || r == 4 ? 1 : r == 3 ? 2 : 0;
	int swing = front ? 0 : phase == 1 ? 1 : phase == 3 ? -1 : 0;
	int ty = 15 + bob, claws = lk->arm == TB_ARM_CLAWS, len = lk->arm == TB_ARM_RIFLE ? 11 : 5;
	uint8_t gun = tp_c(PAL_BLACKRAMP, 6);

	for (int leg = 0; leg < 2; leg++) {
		int lw = side == 2 ? 4 : hw - 2 < 3 ? 3 : hw - 2, sgn = leg ? -1 : 1;
		int x0 = leg ? cx + 1 : cx - 1 - lw, dx = sgn * swing * (side == 2 ? 4 : side);
		int lift = side < 2 && swing * sgn > 0 ? 2 : 0;

		int hipx, fx, kx;

		if (side == 2)
			x0 = cx - lw / 2 - 1 + leg * 2;
		/* a rounded thigh and shin bending at the knee (the hip moves
		 * half as far as the foot), on a boot with its toe forward */
		hipx = x0 + lw / 2 + dx / 2;
		fx = x0 + lw / 2 + dx;
		kx = (hipx + fx) / 2 - (side == 2 ? 1 : 0);
		tb_limb(p, hipx, 43, kx, 48 - lift, lw / 2, lk->legs, leg);
		tb_limb(p, kx, 48 - lift, fx, p->h - 4 - lift, (lw - 1) / 2, lk->legs, leg + 1);
		tp_rect(p, fx - lw / 2 - (side == 2 ? 2 : 0), p->h - 3 - lift, lw + 1 + (side == 2 ? 2 : 0),
			3, tb_t(lk->legs, 4 + leg));
	}
	for (int y = ty; y < 42; y++) {                                /* torso, lit from the left */
		/* rounded shoulders, a narrower waist, its edges darker */
		int in = y == ty ? 2 : y == ty + 1 ? 1 : y >= 35 ? 1 : 0;

		for (int x = cx - hw + in; x < cx + hw - in; x++)
			tp_set(p, x, y, tb_t(lk->cloth, x == cx - hw + in ? 1
							: x >= cx + hw - in - 1 ? 3
							: x >= cx + hw - in - 3 ? 1
							: x < cx - hw + in + 3 ? -1 : 0));
	}
	if (!claws && side < 2)                                        /* the collar */
		tp_rect(p, cx - 1, ty, 2, 2, tb_t(lk->skin, 1));
	tp_rect(p, cx - hw, 38, 2 * hw, 3, tb_t(lk->trim, 0));         /* belt */
	if (pose == TB_P_HURT || pose == TB_P_DEAD)                    /* wounds */
		for (int k = 0; k < 9; k++)
			tp_set(p, cx - hw + 2 + (int)(tp_hash((uint32_t)k, 1, 7) % (uint32_t)(2 * hw - 4)),
			       ty + 4 + (int)(tp_hash((uint32_t)k, 2, 7) % 16), tp_c(PAL_RED, 5 + k % 4));
	/* arms: the near ones beside the torso; raised for the claws'
	 * attack, forward round the gun when aiming, flung up in pain */
	if (front && pose != TB_P_DEAD && pose != TB_P_HURT) {
		int up = claws && pose == TB_P_AIM ? 14 : claws && pose == TB_P_WINDUP ? 6 : 0;

		for (int s = -1; s <= 1; s += 2) {
			int ax = s < 0 ? cx - hw - 3 : cx + hw;

			if (claws && up) {
				tp_rect(p, ax, ty - up, 3, 14, tb_t(lk->cloth, 2));
				for (int k = 0; k < 3; k++)
					tp_set(p, ax + k, ty - up - 1 - (k & 1), tp_c(PAL_GREY, 1));
			} else if (claws) {
				tb_limb(p, ax + 1, ty + 3, ax + 1 + s * -1, ty + 9, 1, lk->cloth, 1);
				tp_rect(p, ax + (s < 0 ? 2 : -2), ty + 9, 3, 4, tb_t(lk->skin, 0));
			} else {
				/* both arms forward, the hands meeting round the gun */
				tb_limb(p, cx + s * (hw - 1), ty + 2, cx + s * (hw + 1), ty + 8, 1,
					lk->cloth, 1);
				tb_limb(p, cx + s * (hw + 1), ty + 8, cx + s * 4, ty + 10, 1, lk->cloth, 2);
				tp_rect(p, cx + (s < 0 ? -6 : 3), ty + 8, 3, 4, tb_t(lk->skin, s < 0 ? 0 : 1));
			}
		}
		if (!claws) {
			/* the gun end-on: a dark block lit along its top, the
			 * muzzle a black hole in a grey ring */
			tp_rect(p, cx - 3, ty + 7, 6, 6, gun);
			tp_rect(p, cx - 3, ty + 7, 6, 1, tp_c(PAL_GREY, 8));
			tp_rect(p, cx - 2, ty + 8, 4, 4, tp_c(PAL_GREY, 10));
			tp_rect(p, cx - 1, ty + 9, 2, 2, PAL_BLACK);
		}
		if (pose == TB_P_FIRE)
			tb_flash(p, cx, ty + 10, claws ? 6 : 5);
	} else if (front) {
		int up = pose == TB_P_HURT ? 8 : 0;

		tp_rect(p, cx - hw - 3, ty + 1 - up, 3, 18, tb_t(lk->cloth, 2));
		tp_rect(p, cx + hw, ty + 1 - up, 3, 18, tb_t(lk->cloth, 2));
	} else {
		/* the arms in view: both from the front and the back, the near
		 * one from the sides (the viewer's left at 2, right at 4), one
		 * swinging over the body in profile */
		int show[2] = { r != 4, r == 1 || r == 4 || r == 5 };
		int sw = side == 2 ? -swing * 2 : 0;

		for (int s = 0; s < 2; s++) {
			int ax = side == 2 ? cx - 1 : s == 0 ? cx - hw - 3 : cx + hw;

			if (!show[s])
				continue;
			tb_limb(p, ax + 1, ty + 3, ax + 1 + sw / 2, ty + 17, 1, lk->cloth,
				side == 2 ? 2 : 1);
			tp_rect(p, ax + sw, ty + 18, 3, 3, tb_t(lk->skin, 0));
			if (claws)
				for (int k = 0; k < 3; k += 2)
					tp_set(p, ax + sw + k, ty + 21, tp_c(PAL_GREY, 1));
		}
		if (!claws) {
			if (r == 1)
				tp_rect(p, cx - hw - 4, ty + 12, 4, 4, gun);
			else if (r == 2)
				tp_rect(p, cx - hw - 3 - len, ty + 13, len + 3, 3, gun);
			else if (r == 3)
				tp_rect(p, cx - 2 - len, ty + 12, len + 2, 3, gun);
			else if (r == 4)
				tp_rect(p, cx - hw - 2, ty + 11, 3, 3, gun);
		}
	}
	tb_head(p, lk, pose, r, cx, 8 + bob - (pose == TB_P_HURT));
}

/* ---- the brute ----------------------------------------------------------------- */

/* An arm from the shoulder (sx, sy) to the hand (hx, hy), the elbow bent
 * away from the body (out: -1 to the viewer's left, 1 right), ending in
 * three claws that point on from the forearm. */
static void tb_arm(struct tex_pic *p, const struct tb_look *lk, int sx, int sy, int hx, int hy,
		   int out, int d)
{
	int ex = (sx + hx) / 2 + 3 * out, ey = (sy + hy) / 2;
	int dx = hx - ex, dy = hy - ey, n = tb_abs(dx) > tb_abs(dy) ? tb_abs(dx) : tb_abs(dy);

	tb_limb(p, sx, sy, ex, ey, 3, lk->cloth, d);
	tb_limb(p, ex, ey, hx, hy, 2, lk->skin, d);
	if (n == 0)
		n = 1;
	for (int c = -1; c <= 1; c++)
		for (int k = 1; k <= 3; k++)
			tp_set(p, hx + dx * (2 + k) / n + (dy ? c : 0), hy + dy * (2 + k) / n + (dy ? 0 : c),
			       tp_c(PAL_GREY, k));
}

/* The brute: a hunched, heavy demon. A round barrel of a body with a pale
 * belly (a ridge of spines down its back), its horned head sunk between
 * the shoulders with a jaw of teeth, long clawed arms, thick bent legs on
 * hooves. Walking (rot 1 faces the viewer, 3 is the profile facing left,
 * 5 the back; phase 1 and 3 a step with each leg, the arms swinging
 * against the legs); then, seen from the front: the wind-up (arms spread,
 * jaw opening), the aim (claws high over the head, jaw wide), the strike
 * (claws swept down across the body, jaw agape, slashes in the air), pain
 * (thrown back, eyes shut, wounds) and the dead pose tb_death turns. */
static void tb_brute(struct tex_pic *p, int pose, int rot, int phase)
{
	/* the head's lean towards where it faces, per rotation; the jaw's
	 * gape per pose */
	static const int8_t lean[6] = { 0, 0, -3, -7, 2, 0 };
	static const int8_t gape[6] = { 2, 3, 5, 7, 1, 0 };
	const struct tb_look *lk = &tb_looks[TB_L_DEMON];
	int walk = pose == TB_P_WALK, r = walk ? rot : 1, bob = walk && (phase & 1);
	int swing = !walk ? 0 : phase == 1 ? 1 : phase == 3 ? -1 : 0;
	int side = r == 3, back = r >= 4, cx = p->w / 2;
	int rx = side ? 10 : r == 2 || r == 4 ? 12 : 14, ty = 31 + bob;
	int hx = cx + lean[r], hy = 17 + bob + (pose == TB_P_FIRE ? 3 : 0) - (pose == TB_P_HURT ? 2 : 0);
	int shut = pose == TB_P_HURT || pose == TB_P_DEAD, g = gape[pose];

	for (int leg = 0; leg < 2; leg++) {                            /* legs on hooves */
		int sgn = leg ? 1 : -1, st = swing * sgn, d = side && leg ? 2 : 0;
		int spread = side ? 1 : r == 1 || r == 5 ? 7 : 5;
		int hipx = cx + sgn * spread, fx = hipx - (side ? st * 5 : 0);
		int lift = st > 0 ? 2 : 0, kx = (hipx + fx) / 2 + (side ? -3 : sgn);
		int ky = 47 - lift;

		tb_limb(p, hipx, 40 + bob, kx, ky, 3, lk->legs, d);
		tb_limb(p, kx, ky, fx, 51 - lift, 2, lk->legs, d + 1);
		tp_rect(p, fx - 3, 53 - lift, 7, 3, tb_t(lk->trim, d));
		if (!back)
			for (int k = 0; k < 3; k++)
				tp_set(p, fx - 3 + 3 * k - (side ? 1 : 0), 55 - lift, tp_c(PAL_GREY, 3));
	}
	if (back) {                                                    /* the head behind the hump */
		tb_blob(p, hx, hy, 9, 7, lk->skin, 1);
	}
	tb_blob(p, cx + lean[r] / 3, ty, rx, 12, lk->cloth, 0);        /* the body */
	if (back) {
		for (int y = ty - 10; y <= ty + 8; y += 3) {           /* spines down the back */
			int sx = cx + lean[r] / 3 + (r == 4 ? 3 : 0);

			tp_rect(p, sx - 1, y, 3, 2, tb_t(lk->trim, 0));
			tp_set(p, sx, y - 1, tp_c(PAL_GREY, 4));
		}
	} else {
		int bx = cx + lean[r] / 2 - (side ? 3 : 0);

		tb_blob(p, bx, ty + 4, side ? 4 : rx / 2, 7, lk->skin, -3);   /* the belly */
		for (int k = -1; k <= 1; k += 2)                       /* the chest's muscles */
			for (int x = 2; x < rx - 3; x++)
				if (!side || k < 0)
					tp_set(p, bx + k * x, ty - 6 + x * x / (2 * rx), tb_t(lk->cloth, 3));
	}
	if (shut)                                                      /* wounds */
		for (int k = 0; k < 11; k++)
			tp_set(p, cx - rx + 3 + (int)(tp_hash((uint32_t)k, 1, 8) % (uint32_t)(2 * rx - 6)),
			       ty - 8 + (int)(tp_hash((uint32_t)k, 2, 8) % 18), tp_c(PAL_RED, 4 + k % 5));
	/* the arms: at the sides swinging against the legs, spread for the
	 * wind-up, high for the aim, swept down across the body striking,
	 * flung out in pain, limp dead; in profile the near arm only */
	for (int s = -1; s <= 1; s += 2) {
		int sx = side ? cx - 2 : cx + s * (rx - 2), sy = ty - 7, ax, ay;

		if (side && s > 0)
			continue;
		switch (pose) {
		case TB_P_WINDUP: ax = cx + s * (rx + 5); ay = ty - 12; break;
		case TB_P_AIM: ax = cx + s * (rx - 1); ay = ty - 24; break;
		case TB_P_FIRE: ax = cx - s * 4; ay = ty + 6; break;
		case TB_P_HURT: ax = cx + s * (rx + 6); ay = ty - 3; break;
		case TB_P_DEAD: ax = cx + s * (rx + 1); ay = ty + 11; break;
		default:
			ax = side ? cx - 2 - swing * 5 : cx + s * (rx + 2);
			ay = ty + 10 + (side ? 0 : s * swing * 2);
			break;
		}
		tb_arm(p, lk, sx, sy, ax, ay, side ? 0 : s, s > 0 && !side);
	}
	if (back)
		return;
	tb_blob(p, hx, hy, side ? 8 : 9, 7, lk->skin, 0);              /* the head */
	for (int k = 0; k < 4; k++) {                                  /* horns curving up and out */
		if (!side)
			tp_set(p, hx + 6 + k / 2 + (k == 3), hy - 5 - k, tp_c(PAL_GREY, 1 + k));
		tp_set(p, hx - 6 - k / 2 - (k == 3) + (side ? 8 : 0), hy - 5 - k, tp_c(PAL_GREY, 1 + k));
	}
	for (int x = -7; x <= 7; x++)                                  /* the brow */
		if (!side || x < 2)
			tp_set(p, hx + x, hy - 3, tb_t(lk->trim, tb_abs(x) < 2 ? 1 : 0));
	for (int e = -1; e <= 1; e += 2) {                             /* eyes */
		int ex = hx + e * 4 - (side ? 1 : 0);

		if (side && e > 0)
			continue;
		tp_rect(p, ex - 1, hy - 2, 2, shut ? 1 : 2, shut ? tb_t(lk->skin, 4) : lk->eye);
	}
	{
		/* the jaw: a mouth g deep with teeth above and below, the lower
		 * jaw under it (in profile, jutting to the left) */
		int x0 = side ? hx - 8 : hx - 6, x1 = side ? hx + 1 : hx + 6, my = hy + 3;

		for (int x = x0; x <= x1; x++) {
			for (int y = 0; y < g; y++)
				tp_set(p, x, my + y, y == 0 || y == g - 1 ? tp_c(PAL_RED, 11) : tp_c(PAL_RED, 9));
			if ((x - x0) % 2 == 0) {
				tp_set(p, x, my, tp_c(PAL_GREY, 0));
				tp_set(p, x, my + g, tp_c(PAL_GREY, 1));
			}
		}
		for (int x = x0 + 1; x < x1; x++)
			for (int y = 1; y <= 2; y++)
				tp_set(p, x, my + g + y, tb_t(lk->skin, y));
	}
	if (pose == TB_P_FIRE)                                         /* the claws' slashes */
		for (int k = 0; k < 3; k++)
			for (int t = 0; t < 9; t++)
				tp_set(p, cx + 9 + 3 * k - t, ty - 16 + 2 * k + t,
				       tp_c(PAL_GREY, t < 3 ? 0 : t < 6 ? 2 : 5));
}

/* ---- the drone ----------------------------------------------------------------- */

/* The sentry: a hovering slate sphere with one eye, fins and an aerial.
 * crack > 0 breaks it (its death). */
static void tb_orb(struct tex_pic *p, int pose, int rot, int crack)
{
	static const int8_t eye_x[4] = { 0, 0, -8, -14 }, eye_w[4] = { 0, 7, 6, 3 };
	const struct tb_look *lk = &tb_looks[TB_L_ORB];
	int cx = p->w / 2, cy = p->h / 2, r = p->w / 2 - 4;
	int ex = rot <= 3 ? cx + eye_x[rot] : 0, ew = rot <= 3 ? eye_w[rot] : 0;

	for (int k = 0; k < 4; k++) {                                  /* fins and aerial */
		tp_rect(p, cx - r - 3 + k, cy - 3 + k, 1, 7 - 2 * k, tb_t(lk->legs, k));
		tp_rect(p, cx + r + 2 - k, cy - 3 + k, 1, 7 - 2 * k, tb_t(lk->legs, k + 1));
	}
	tp_rect(p, cx, cy - r - 4, 1, 5, tb_t(lk->legs, 0));
	tp_set(p, cx, cy - r - 4, crack ? tp_c(PAL_GREY, 12) : tp_c(PAL_RED, 2));
	for (int y = -r; y <= r; y++) {
		for (int x = -r; x <= r; x++) {
			int d2 = x * x + y * y, shade = 5 + (x + y) * 4 / r;

			if (d2 > r * r)
				continue;
			if (d2 > (r - 2) * (r - 2))
				shade += 2;
			if (y >= 2 && y <= 4)
				shade += 3;
			tp_set(p, cx + x, cy + y, tp_c(lk->cloth.ramp, shade));
		}
	}
	if (rot >= 4) {                                                /* the vent at the back */
		int vx = rot == 5 ? cx : cx + 9;

		for (int y = -5; y <= 5; y += 2)
			tp_rect(p, vx - 5 + (rot == 4) * 2, cy + y - 6, rot == 5 ? 11 : 6, 1,
				tp_c(PAL_SLATE, 13));
		if (rot == 5)
			tb_disc(p, cx, cy + 8, 4, crack ? tp_c(PAL_SLATE, 12) : tp_c(PAL_CYAN, 2));
	} else {
		for (int y = -7; y <= 7; y++) {
			for (int x = -7; x <= 7; x++) {
				int sx = x * 7 / ew, d2 = sx * sx + y * y;
				uint8_t c = tp_c(PAL_GREY, 1);

				if (d2 > 49)
					continue;
				if (d2 <= 16)
					c = pose == TB_P_FIRE ? tp_c(PAL_GREY, 0)
					    : pose == TB_P_AIM ? tp_c(PAL_YELLOW, 2)
					    : pose == TB_P_WINDUP ? tp_c(PAL_ORANGE, 2) : lk->eye;
				if (d2 <= 2 && pose != TB_P_FIRE)
					c = PAL_BLACK;
				if (pose == TB_P_FIRE && d2 > 16)
					c = tp_c(PAL_YELLOW, 1);
				if ((pose == TB_P_HURT && y < 1) || crack)
					c = y < 1 || crack > 2 ? tp_c(PAL_SLATE, 11) : c;
				tp_set(p, ex + x, cy - 1 + y, c);
			}
		}
		if (pose == TB_P_FIRE)                                 /* a glow round the eye */
			for (int y = -11; y <= 11; y++)
				for (int x = -11; x <= 11; x++) {
					int sx = x * 7 / ew, d2 = sx * sx + y * y;

					if (d2 > 64 && d2 <= 110)
						tp_set(p, ex + x, cy - 1 + y, tp_c(PAL_YELLOW, d2 > 90 ? 5 : 3));
				}
	}
	/* cracks: random walks from points on the shell, longer as it breaks;
	 * sparks where it hurts */
	for (int k = 0; k < crack * 3; k++) {
		uint32_t h = tp_hash((uint32_t)k, 3, 91);
		int x = cx - r / 2 + (int)(h % (uint32_t)r), y = cy - r / 2 + (int)((h >> 8) % (uint32_t)r);

		for (int s = 0; s < 3 + crack * 2; s++) {
			uint32_t g = tp_hash((uint32_t)k, (uint32_t)s, 92);

			tp_set(p, x, y, PAL_BLACK);
			x += (int)(g % 3) - 1;
			y += (int)((g >> 4) % 3) - 1;
		}
	}
	if (pose == TB_P_HURT || (crack && crack < 5))
		for (int k = 0; k < 8; k++) {
			uint32_t h = tp_hash((uint32_t)k, (uint32_t)crack, 93);

			tp_set(p, cx - r + (int)(h % (uint32_t)(2 * r)),
			       cy - r + (int)((h >> 8) % (uint32_t)(2 * r)),
			       tp_c(PAL_YELLOW, 1 + k % 3));
		}
}

/* ---- the flyer ------------------------------------------------------------------ */

/* The flyer: a bone skull in a crown of flames, its eye sockets glowing
 * (red walking, yellow aiming, white with the jaw dropped biting, shut in
 * pain); rot 4..5 show the back of the cranium. phase flickers the flames;
 * crack > 0 breaks it (its death), the flames going out. */
static void tb_skull(struct tex_pic *p, int pose, int rot, int phase, int crack)
{
	const struct tb_look *lk = &tb_looks[TB_L_SKULL];
	static const int8_t face_x[6] = { 0, 0, -3, -6, 0, 0 };
	int cx = p->w / 2, cy = p->h - 16, rx = 11, ry = 10;
	int fx = cx + face_x[rot], bite = pose == TB_P_FIRE ? 4 : 0;

	for (int k = 0; k < 90 - crack * 18; k++) {                    /* the flames */
		uint32_t h = tp_hash((uint32_t)k, (uint32_t)(phase + 2 * pose), 95);
		int x = (int)(h % 27u) - 13, y = -(int)((h >> 8) % 18u) - 2;
		int tall = 16 - (x < 0 ? -x : x);

		if (-y > tall + 4)
			continue;
		tp_set(p, cx + x, cy - ry / 2 + y,
		       tp_c(-y > tall / 2 ? lk->legs.ramp : lk->cloth.ramp, (int)((h >> 16) % 3u) + 1));
	}
	for (int y = -ry; y <= ry; y++) {                              /* the cranium */
		for (int x = -rx; x <= rx; x++) {
			if (x * x * ry * ry + y * y * rx * rx > rx * rx * ry * ry)
				continue;
			tp_set(p, cx + x, cy + y, tb_t(lk->skin, (x + y) * 3 / rx + (y > ry - 3)));
		}
	}
	for (int x = -6; x <= 6; x++) {                                /* the jaw and teeth */
		for (int y = 0; y < 5; y++)
			tp_set(p, fx + x, cy + ry - 1 + y + (y >= 2 ? bite : 0),
			       y == 1 && (x & 1) ? tp_c(PAL_GREY, 9) : tb_t(lk->skin, 2 + y / 2));
		if (bite)
			for (int y = 0; y < bite; y++)
				tp_set(p, fx + x, cy + ry + 1 + y, PAL_BLACK);
	}
	if (rot <= 3) {                                                /* sockets, nose */
		for (int e = 0; e < 2; e++) {
			int ex = fx + (e ? 5 : -5);
			uint8_t glow = pose == TB_P_FIRE ? tp_c(PAL_GREY, 0)
				       : pose == TB_P_AIM ? tp_c(PAL_YELLOW, 1) : lk->eye;

			if (rot == 3 && e == 0)
				continue;
			for (int y = -3; y <= 3; y++)
				for (int x = -3; x <= 3; x++)
					if (x * x + y * y <= 9)
						tp_set(p, ex + x, cy - 2 + y,
						       x * x + y * y <= 2 && pose != TB_P_HURT && !crack
						       ? glow : PAL_BLACK);
		}
		tp_rect(p, fx - 1, cy + 3, 3, 3, PAL_BLACK);
	}
	for (int k = 0; k < crack * 3; k++) {                          /* cracks */
		uint32_t h = tp_hash((uint32_t)k, 5, 96);
		int x = cx - rx / 2 + (int)(h % (uint32_t)rx), y = cy - ry / 2 + (int)((h >> 8) % (uint32_t)ry);

		for (int st = 0; st < 3 + crack * 2; st++) {
			uint32_t g = tp_hash((uint32_t)k, (uint32_t)st, 97);

			tp_set(p, x, y, PAL_BLACK);
			x += (int)(g % 3) - 1;
			y += (int)((g >> 4) % 3) - 1;
		}
	}
	if (pose == TB_P_HURT)                                         /* sparks */
		for (int k = 0; k < 8; k++) {
			uint32_t h = tp_hash((uint32_t)k, 7, 98);

			tp_set(p, cx - rx + (int)(h % (uint32_t)(2 * rx)),
			       cy - ry + (int)((h >> 8) % (uint32_t)(2 * ry)), tp_c(PAL_YELLOW, 1 + k % 3));
		}
}

/* ---- turning and squashing pictures ---------------------------------------------- */

static int tb_fdiv(int a, int b)
{
	return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/* Draws src into dst by inverse mapping: the dst pixel at offset (ox, oy)
 * from (dx0, dy0) shows the src pixel at offset ((a*ox + b*oy) / 256,
 * (c*ox + d*oy) / 256) from (sx0, sy0), rounded; transparent src pixels
 * leave dst alone. */
static void tb_warp(struct tex_pic *dst, const struct tex_pic *src, int sx0, int sy0, int dx0,
		    int dy0, int a, int b, int c, int d)
{
	for (int y = 0; y < dst->h; y++) {
		for (int x = 0; x < dst->w; x++) {
			int ox = x - dx0, oy = y - dy0;
			int sx = sx0 + tb_fdiv(a * ox + b * oy + 128, 256);
			int sy = sy0 + tb_fdiv(c * ox + d * oy + 128, 256);
			size_t i = (size_t)sx * (size_t)src->h + (size_t)sy;

			if (sx >= 0 && sy >= 0 && sx < src->w && sy < src->h && src->opaque[i])
				tp_set(dst, x, y, src->px[i]);
		}
	}
}

/* A pool of blood (or the drone's fluid) on the bottom rows. */
static void tb_pool(struct tex_pic *p, int cx, int half, int ramp)
{
	for (int y = 0; y < 3; y++) {
		for (int x = -half + y * 2; x <= half - y * 2; x++) {
			int shade = 9 + (int)(tp_hash((uint32_t)x, (uint32_t)y, 94) % 3);

			tp_set(p, cx + x, p->h - 1 - y, tp_c(ramp, shade));
		}
	}
}

#define TB_SCRATCH_W 48
#define TB_SCRATCH_H 56

/* Death frame k of n: the monster drawn shut-eyed and turned clockwise
 * about its right foot by 90 * (k + 1) / n degrees (in 15-degree steps),
 * over a growing pool; the last is the corpse lying on the floor. The
 * thing's spot stays where the standing monster's middle was. The drone
 * breaks and sinks instead, and its corpse is the shell squashed on the
 * floor. */
static void tb_death(struct tex_pic *p, int look, int k, int n, int w, int h)
{
	static const int16_t cs[7][2] = { { 256, 0 }, { 247, 66 }, { 222, 128 }, { 181, 181 },
					  { 128, 222 }, { 66, 247 }, { 0, 256 } };
	uint8_t px[TB_SCRATCH_W * TB_SCRATCH_H], op[TB_SCRATCH_W * TB_SCRATCH_H];
	struct tex_pic s = { .w = (int16_t)w, .h = (int16_t)h, .px = px, .opaque = op };
	int step = 6 * (k + 1) / n;

	memset(op, 0, sizeof op);
	if (look == TB_L_SKULL) {
		/* the flyer cracks as it falls (the sim drops it to the floor);
		 * its corpse is the broken skull lying there */
		tb_skull(&s, TB_P_DEAD, 1, k, k + 1);
		if (k + 1 < n) {
			tb_warp(p, &s, 0, 0, 0, 0, 256, 0, 0, 256);
		} else {
			tb_warp(p, &s, w / 2, h - 16, w / 2, h - 11, 256, 0, 0, 384);
		}
		return;
	}
	if (look == TB_L_ORB) {
		tb_orb(&s, TB_P_DEAD, 1, k + 1);
		if (k + 1 < n) {
			tb_warp(p, &s, 0, 0, 0, 0, 256, 0, 0, 256);
			p->top = (int16_t)(h + 12 - 12 * (k + 1) / n);
		} else {
			tb_pool(p, w / 2, w / 2 - 2, PAL_GREEN);
			tb_warp(p, &s, w / 2, h / 2 + w / 2 - 4, w / 2, h - 1, 256, 0, 0, 512);
		}
		return;
	}
	{
		const struct tb_look *lk = &tb_looks[look];
		int pivot = w / 2 + lk->hw, px0 = 2 * lk->hw + 4;

		if (look == TB_L_DEMON)
			tb_brute(&s, TB_P_DEAD, 1, 0);
		else
			tb_human(&s, lk, TB_P_DEAD, 1, 0);
		if (k > 0)
			tb_pool(p, px0 + h * k / (2 * n), 4 + 5 * k, PAL_RED);
		tb_warp(p, &s, pivot, h - 1, px0, h - 1, cs[step][0], cs[step][1], -cs[step][1],
			cs[step][0]);
		p->left = (int16_t)(px0 - lk->hw);
	}
}

/* ---- pickups, decorations, effects, the pistol ------------------------------------ */

/* A barrel: a shaded cylinder with two bands; arg 1 makes its top glow. */
static void tb_barrel(struct tex_pic *p, int arg)
{
	int cx = p->w / 2;

	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int d = x - cx < 0 ? cx - x : x - cx;
			int shade = 4 + d * 8 / cx;

			if ((y < 3 || y >= p->h - 2) && d > cx - 2)
				continue;
			if (y < 3)
				tp_set(p, x, y, arg ? tp_c(PAL_GREEN, 1) : tp_c(PAL_GREEN, 6));
			else if (y == 6 || y == p->h - 6)
				tp_set(p, x, y, tp_c(PAL_GREY, shade + 2));
			else
				tp_set(p, x, y, tp_c(PAL_OLIVE, shade));
		}
	}
}

static void tb_lamp(struct tex_pic *p)
{
	int cx = p->w / 2;

	for (int y = 0; y < p->h; y++) {
		for (int x = 0; x < p->w; x++) {
			int dx = x - cx, dy = y - 7;

			if (dx * dx + dy * dy <= 36)
				tp_set(p, x, y, tp_c(PAL_YELLOW, (dx * dx + dy * dy) / 12));
			else if (y > 12 && dx >= -1 && dx <= 1)
				tp_set(p, x, y, tp_c(PAL_GREY, 7 + dx));
			else if (y >= p->h - 4 && dx >= -5 && dx <= 5)
				tp_set(p, x, y, tp_c(PAL_GREY, 9));
		}
	}
}

/* A small flame with its tip at (cx, y0), h rows tall. */
static void tb_flame(struct tex_pic *p, int cx, int y0, int h, int ramp)
{
	for (int y = 0; y < h; y++) {
		int half = y * 3 / h + (y > h / 2);

		for (int x = -half; x <= half; x++)
			tp_set(p, cx + x, y0 + y, x == 0 && y > h / 3 ? tp_c(PAL_YELLOW, 0)
						  : tp_c(ramp, 1 + (x < 0 ? -x : x)));
	}
}

static void tb_candelabra(struct tex_pic *p)
{
	int cx = p->w / 2;

	tp_rect(p, cx - 1, 14, 3, p->h - 14, tp_c(PAL_YELLOW, 9));     /* stem, brass */
	tp_rect(p, cx - 6, p->h - 3, 13, 3, tp_c(PAL_YELLOW, 10));     /* foot */
	tp_rect(p, cx - 9, 18, 19, 2, tp_c(PAL_YELLOW, 8));            /* arms */
	for (int k = -1; k <= 1; k++) {
		tp_rect(p, cx + k * 9 - 1, 10 - (k == 0) * 3, 3, 8 + (k == 0) * 3, tp_c(PAL_GREY, 2));
		tb_flame(p, cx + k * 9, 2 - (k == 0) * 3 + 3, 6, PAL_ORANGE);
	}
}

static void tb_torch(struct tex_pic *p)
{
	int cx = p->w / 2;

	tp_rect(p, cx - 1, 16, 3, p->h - 16, tp_c(PAL_BROWN, 9));
	tp_rect(p, cx - 3, 14, 7, 4, tp_c(PAL_GREY, 8));
	tb_flame(p, cx, 0, 15, PAL_RED);
}

static void tb_medikit(struct tex_pic *p, int ramp)
{
	tp_rect(p, 0, 0, p->w, p->h, tp_c(PAL_GREY, 1));
	tp_rect(p, 0, p->h - 2, p->w, 2, tp_c(PAL_GREY, 8));
	tp_rect(p, p->w / 2 - 2, 2, 4, p->h - 5, tp_c(ramp, 4));
	tp_rect(p, p->w / 2 - p->w / 4, p->h / 2 - 2, p->w / 2, 4, tp_c(ramp, 4));
}

static void tb_clip(struct tex_pic *p)
{
	tp_rect(p, 0, 3, p->w, p->h - 3, tp_c(PAL_BLACKRAMP, 5));
	tp_rect(p, 1, 4, 1, p->h - 5, tp_c(PAL_GREY, 9));
	for (int k = 0; k < 2; k++) {
		tp_rect(p, 1 + k * 4, 1, 3, 3, tp_c(PAL_YELLOW, 5));
		tp_set(p, 2 + k * 4, 0, tp_c(PAL_YELLOW, 3));
	}
}

static void tb_ammo(struct tex_pic *p)
{
	for (int k = 0; k < 6; k++) {                                  /* bullets on top */
		tp_rect(p, 2 + k * 4, 0, 3, 4, tp_c(PAL_YELLOW, 5));
		tp_set(p, 3 + k * 4, 0, tp_c(PAL_YELLOW, 2));
	}
	tp_rect(p, 0, 4, p->w, p->h - 4, tp_c(PAL_OLIVE, 8));
	tp_rect(p, 0, p->h - 2, p->w, 2, tp_c(PAL_OLIVE, 12));
	tp_rect(p, 0, 8, p->w, 3, tp_c(PAL_YELLOW, 3));
}

/* A spark on a wall, frame 0..3: a bright flash that turns to smoke. */
static void tb_puff(struct tex_pic *p, int f)
{
	int c = p->w / 2;

	for (int k = 0; k < 24; k++) {
		uint32_t h = tp_hash((uint32_t)k, (uint32_t)f, 95);
		int r = 1 + f * 2, x = (int)(h % (uint32_t)(2 * r + 1)) - r;
		int y = (int)((h >> 8) % (uint32_t)(2 * r + 1)) - r - f;

		if (k < 16 - f * 4)
			tp_set(p, c + x, c + y, f == 0 ? tp_c(PAL_YELLOW, 1) : tp_c(PAL_GREY, 4 + f * 2));
	}
	if (f < 2)
		tb_disc(p, c, c - f, 2 - f, f ? tp_c(PAL_YELLOW, 2) : tp_c(PAL_GREY, 0));
}

/* Blood from a hit, frame 0..3: a splash that flies apart into drops. */
static void tb_blood(struct tex_pic *p, int f)
{
	int c = p->w / 2;

	if (f == 0)
		tb_disc(p, c, c, 5, tp_c(PAL_RED, 5));
	for (int k = 0; k < 10 - f * 2; k++) {
		uint32_t h = tp_hash((uint32_t)k, (uint32_t)f, 96);
		int r = 2 + f * 2, x = (int)(h % (uint32_t)(2 * r + 1)) - r;
		int y = (int)((h >> 8) % (uint32_t)(2 * r + 1)) - r + f;

		tp_set(p, c + x, c + y, tp_c(PAL_RED, 5 + f));
		tp_set(p, c + x, c + y + 1, tp_c(PAL_RED, 8 + f));
	}
}

/* The thrower's missile, frame 0..4: a fireball with a white-hot core and
 * flames licking up (A, B), then its burst, growing and going dark
 * (C, D, E). Drawn full bright by the game. */
static void tb_ball(struct tex_pic *p, int f)
{
	int c = p->w / 2;

	if (f < 2) {
		tb_disc(p, c, c, 30, tp_c(PAL_RED, 4));
		tb_disc(p, c, c, 16, tp_c(PAL_ORANGE, 2));
		tb_disc(p, c, c, 5, tp_c(PAL_YELLOW, 0));
		for (int k = 0; k < 10; k++) {
			uint32_t h = tp_hash((uint32_t)k, (uint32_t)f, 97);
			int x = (int)(h % 11u) - 5, y = -(int)((h >> 8) % 4u) - 5;

			tp_set(p, c + x, c + y, tp_c(PAL_ORANGE, 1 + (int)((h >> 16) % 3u)));
		}
		return;
	}
	f -= 2;
	for (int k = 0; k < 60 - f * 15; k++) {
		uint32_t h = tp_hash((uint32_t)k, (uint32_t)f, 98);
		int r = 5 + f * 3, x = (int)(h % (uint32_t)(2 * r + 1)) - r;
		int y = (int)((h >> 8) % (uint32_t)(2 * r + 1)) - r;

		if (x * x + y * y <= r * r)
			tp_set(p, c + x, c + y, tp_c(f ? PAL_RED : PAL_ORANGE, 1 + f * 3));
	}
	if (f == 0)
		tb_disc(p, c, c, 9, tp_c(PAL_YELLOW, 1));
}

/* The player's pistol seen from behind and above: the slide's top narrowing
 * towards the muzzle, its back face with the rear sight, and the hand
 * round the grip with the thumb along the side. The recoil frames B..E
 * are taller pictures (70 rows plus the kick: 8, 5, 2, 1) with the gun at
 * their top, so the wrist still reaches the bottom of the view. */
static void tb_pistol(struct tex_pic *p)
{
	int cx = p->w / 2;

	for (int y = 2; y < 32; y++) {                                 /* top of the slide */
		int half = 4 + (y - 2) * 5 / 30;

		for (int x = -half; x < half; x++) {
			int shade = x < -half + 2 ? 6 : x >= half - 2 ? 11 : 8;

			if (x >= -1 && x < 1)
				shade = 5;                             /* the rib */
			else if (y >= 24 && (y & 1) && shade == 8)
				shade = 10;                            /* serrations */
			tp_set(p, cx + x, y, tp_c(PAL_GREY, shade));
		}
	}
	tp_rect(p, cx - 2, 0, 4, 3, tp_c(PAL_GREY, 3));                /* front sight */
	tp_rect(p, cx - 9, 32, 18, 10, tp_c(PAL_GREY, 11));            /* back face */
	tp_rect(p, cx - 9, 32, 18, 1, tp_c(PAL_GREY, 7));
	tp_rect(p, cx - 8, 28, 5, 4, tp_c(PAL_GREY, 12));              /* rear sight */
	tp_rect(p, cx + 3, 28, 5, 4, tp_c(PAL_GREY, 12));
	tp_rect(p, cx - 6, 40, 12, 6, tp_c(PAL_BLACKRAMP, 5));         /* grip */
	for (int y = 44; y < p->h; y++) {                              /* hand and wrist */
		int half = 13 + (y - 44) / 8, off = (y - 44) / 6;

		for (int x = -half; x < half; x++)
			tp_set(p, cx + off + x, y, tp_c(PAL_TAN, x < -half + 3 ? 3 : x >= half - 4 ? 6 : 4));
	}
	tp_rect(p, cx - 12, 48, 25, 1, tp_c(PAL_TAN, 7));              /* knuckles */
	tp_rect(p, cx - 12, 52, 25, 1, tp_c(PAL_TAN, 6));
	for (int y = 34; y < 50; y++)                                  /* thumb */
		tp_rect(p, cx - 15 + (y - 34) / 5, y, 6, 1, tp_c(PAL_TAN, y < 37 ? 3 : 5));
}

/* ---- the list ------------------------------------------------------------------------ */

enum {
	TB_BARREL, TB_LAMP, TB_CANDELABRA, TB_TORCH, TB_MEDIKIT, TB_CLIP, TB_AMMO, TB_PUFF, TB_BALL,
	TB_BLOOD, TB_PISTOL, TB_PFLASH,
};

/* Pictures with one name each. Offsets: bottom-centred unless kind says. */
struct tb_one {
	char name[9];
	int16_t w, h;
	uint8_t kind;
	int8_t arg;
};

static const struct tb_one tb_ones[] = {
	{ "BAR1A0", 23, 32, TB_BARREL, 0 },  { "BAR1B0", 23, 32, TB_BARREL, 1 },
	{ "COLUA0", 23, 48, TB_LAMP, 0 },    { "CBRAA0", 28, 56, TB_CANDELABRA, 0 },
	{ "TREDA0", 12, 64, TB_TORCH, 0 },   { "MEDIA0", 28, 19, TB_MEDIKIT, PAL_RED },
	{ "STIMA0", 16, 12, TB_MEDIKIT, PAL_BLUE }, { "CLIPA0", 9, 15, TB_CLIP, 0 },
	{ "AMMOA0", 28, 16, TB_AMMO, 0 },
	{ "PUFFA0", 16, 16, TB_PUFF, 0 },    { "PUFFB0", 16, 16, TB_PUFF, 1 },
	{ "PUFFC0", 16, 16, TB_PUFF, 2 },    { "PUFFD0", 16, 16, TB_PUFF, 3 },
	{ "BLUDA0", 16, 16, TB_BLOOD, 0 },   { "BLUDB0", 16, 16, TB_BLOOD, 1 },
	{ "BLUDC0", 16, 16, TB_BLOOD, 2 },   { "BLUDD0", 16, 16, TB_BLOOD, 3 },
	{ "BAL1A0", 24, 24, TB_BALL, 0 },    { "BAL1B0", 24, 24, TB_BALL, 1 },
	{ "BAL1C0", 32, 32, TB_BALL, 2 },    { "BAL1D0", 32, 32, TB_BALL, 3 },
	{ "BAL1E0", 32, 32, TB_BALL, 4 },
	{ "PISGA0", 48, 70, TB_PISTOL, 0 },  { "PISGB0", 48, 78, TB_PISTOL, 0 },
	{ "PISGC0", 48, 75, TB_PISTOL, 0 },  { "PISGD0", 48, 72, TB_PISTOL, 0 },
	{ "PISGE0", 48, 71, TB_PISTOL, 0 },  { "PISFA0", 28, 22, TB_PFLASH, 0 },
};

/* The monsters: their frames as g_thing.c numbers them (walking frames
 * from A; the attack's aim, its flash the frame after; pain; the death's
 * first and last frame). Frames between them repeat a neighbour's pose. */
struct tb_mon {
	char name[5];
	uint8_t look, walk, attack, pain, death0, death1;
	int16_t w, h;
};

static const struct tb_mon tb_mons[] = {
	{ "POSS", TB_L_GRUNT, 4, 4, 6, 7, 11, 32, 56 },
	{ "SPOS", TB_L_GUNNER, 4, 4, 6, 7, 11, 32, 56 },
	{ "TROO", TB_L_IMP, 4, 5, 7, 8, 12, 34, 56 },
	{ "SARG", TB_L_DEMON, 4, 5, 7, 8, 13, 44, 56 },
	{ "HEAD", TB_L_ORB, 1, 2, 4, 6, 11, 44, 44 },
	{ "SKUL", TB_L_SKULL, 2, 2, 4, 5, 10, 36, 40 },
};

#define TB_N(a) ((int)(sizeof(a) / sizeof((a)[0])))

static void tb_make_one(struct tex_pic *p, const struct tb_one *o)
{
	p->left = (int16_t)(p->w / 2);
	p->top = p->h;
	switch (o->kind) {
	case TB_BARREL: tb_barrel(p, o->arg); break;
	case TB_LAMP: tb_lamp(p); break;
	case TB_CANDELABRA: tb_candelabra(p); break;
	case TB_TORCH: tb_torch(p); break;
	case TB_MEDIKIT: tb_medikit(p, o->arg); break;
	case TB_CLIP: tb_clip(p); break;
	case TB_AMMO: tb_ammo(p); break;
	case TB_PUFF:
	case TB_BLOOD:
	case TB_BALL:
		if (o->kind == TB_PUFF)
			tb_puff(p, o->arg);
		else if (o->kind == TB_BLOOD)
			tb_blood(p, o->arg);
		else
			tb_ball(p, o->arg);
		p->top = (int16_t)(p->h / 2);
		break;
	case TB_PISTOL:
		/* top left at (156, 168 - h) on Doom's 320x168 view */
		tb_pistol(p);
		p->left = 1 - 156;
		p->top = (int16_t)(32 - (168 - p->h));
		break;
	default:
		/* the flash over the front sight of frame B (its top at row
		 * 168 - 78 = 90) */
		tb_flash(p, p->w / 2, p->h / 2, 9);
		p->left = 1 - 166;
		p->top = 32 - (90 - p->h / 2);
		break;
	}
}

/* Frame f of monster m: its pose, and for walking the phase. */
static int tb_pose(const struct tb_mon *m, int f)
{
	if (f < m->walk)
		return TB_P_WALK;
	if (f < m->attack)
		return TB_P_WINDUP;
	if (f == m->attack + 1)
		return TB_P_FIRE;
	if (f < m->pain)
		return TB_P_AIM;
	if (f < m->death0)
		return TB_P_HURT;
	return TB_P_DEAD;
}

/* Names the picture: "POSSA1", "POSSA2A8" (rot 2..4 mirrored as 8..6),
 * "POSSE0" (rot 0: every view). */
static void tb_mon_name(char out[9], const char *base, int f, int rot)
{
	char l = (char)('A' + f);

	memset(out, 0, 9);
	memcpy(out, base, 4);
	out[4] = l;
	out[5] = (char)('0' + rot);
	if (rot >= 2 && rot <= 4) {
		out[6] = l;
		out[7] = (char)('0' + 10 - rot);
	}
}

static void tb_make_mon(struct tex_pic *p, const struct tb_mon *m, int f, int rot)
{
	int pose = tb_pose(m, f);

	p->left = (int16_t)(p->w / 2);
	p->top = p->h;
	if (pose == TB_P_DEAD) {
		tb_death(p, m->look, f - m->death0, m->death1 - m->death0 + 1, m->w, m->h);
		return;
	}
	if (m->look == TB_L_ORB) {
		tb_orb(p, pose, rot ? rot : 1, 0);
		p->top = (int16_t)(p->h + 12);
	} else if (m->look == TB_L_SKULL) {
		/* the flyer's height is the sim's: its picture stands on its spot */
		tb_skull(p, pose, rot ? rot : 1, f & 1, 0);
	} else if (m->look == TB_L_DEMON) {
		tb_brute(p, pose, rot ? rot : 1, f & 3);
	} else {
		tb_human(p, &tb_looks[m->look], pose, rot ? rot : 1, f & 3);
	}
}

/* Walks every picture: counts them, and makes each into pics[i] when pics
 * is not NULL. Returns the count, or a negative errno from tex_pic_new. */
static int tb_walk(struct tex_pic *pics, uint64_t *budget)
{
	int n = 0, r;

	for (int i = 0; i < TB_N(tb_ones); i++, n++) {
		if (!pics)
			continue;
		r = tex_pic_new(&pics[n], tb_ones[i].name, tb_ones[i].w, tb_ones[i].h, budget);
		if (r)
			return r;
		tb_make_one(&pics[n], &tb_ones[i]);
		tex_pic_seal(&pics[n]);
	}
	for (int i = 0; i < TB_N(tb_mons); i++) {
		const struct tb_mon *m = &tb_mons[i];

		for (int f = 0; f <= m->death1; f++) {
			int dead = f >= m->death0, walk = f < m->walk;
			int w = dead && m->look < TB_L_ORB ? 2 * tb_looks[m->look].hw + 6 + m->h : m->w;

			for (int rot = walk ? 1 : 0; rot <= (walk ? 5 : 0); rot++, n++) {
				char name[9];

				if (!pics)
					continue;
				tb_mon_name(name, m->name, f, rot);
				r = tex_pic_new(&pics[n], name, w, m->h, budget);
				if (r)
					return r;
				tb_make_mon(&pics[n], m, f, rot);
				tex_pic_seal(&pics[n]);
			}
		}
	}
	return n;
}

int tex_bspr_count(void)
{
	return tb_walk(NULL, NULL);
}

int tex_bspr_make(struct tex_pic *pics, uint64_t *budget)
{
	int r = tb_walk(pics, budget);

	return r < 0 ? r : 0;
}
