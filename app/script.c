/*
 * script: a test script's steps and checks (contract in script.h).
 */
#include "app/script.h"

#include <inttypes.h>
#include <string.h>

#include "app/cmd.h"
#include "app/say.h"
#include "app/stats.h"
#include "display/shot.h"
#include "engine/core/hash.h"
#include "engine/game/sim.h"
#include "engine/render/r_main.h"
#include "input/in.h"

int script_load(struct script *s, const char *path, FILE *out)
{
	char err[512] = "";
	int rc = scr_load(path, &s->scr, err, sizeof(err));

	if (rc < 0) {
		say_err("%s", err[0] ? err : strerror(-rc));
		return rc;
	}
	s->path = path;
	s->out = out;
	return 0;
}

int script_over(const struct script *s, uint32_t t)
{
	return t > s->scr->end_tick;
}

/* Renders a script value the way the script wrote it. */
static void format_value(enum scr_field f, int64_t v, char *buf, size_t len)
{
	switch (sim_field_kind((int)f)) {
	case SIM_FK_FX: {
		/* 16.16 to decimal with 4 places, exact enough to read */
		int64_t m = v < 0 ? -v : v;
		snprintf(buf, len, "%s%" PRId64 ".%04" PRId64, v < 0 ? "-" : "", m >> 16,
			 ((m & 0xffff) * 10000) >> 16);
		break;
	}
	case SIM_FK_MODE: {
		const char *n = sim_mode_name((enum sim_mode)v);
		snprintf(buf, len, "%s", n ? n : "?");
		break;
	}
	case SIM_FK_PAGE: {
		const char *n = sim_page_name((int)v);
		snprintf(buf, len, "%s", n ? n : "?");
		break;
	}
	case SIM_FK_INT:
	case SIM_FK_ANGLE:
		snprintf(buf, len, "%" PRId64, v);
		break;
	}
}

void script_inputs(struct script *s, uint32_t t, struct cmd_state *cs, struct stats *st, int src)
{
	for (size_t i = s->next; i < s->scr->n && s->scr->steps[i].tick == t; i++) {
		const struct scr_step *sp = &s->scr->steps[i];
		if (sp->op == SCR_PRESS || sp->op == SCR_RELEASE) {
			cmd_action(cs, sp->action, sp->op == SCR_PRESS);
			if (sp->op == SCR_PRESS && st->pending_ns == 0)
				stats_input(st, src, in_now_ns());
		}
	}
}

void script_checks(struct script *s, uint32_t t, const struct sim *sim, const struct r_frame *f,
		   const uint8_t (*rgb)[3])
{
	char got[64], want[64];

	for (; s->next < s->scr->n && s->scr->steps[s->next].tick == t; s->next++) {
		const struct scr_step *sp = &s->scr->steps[s->next];
		switch (sp->op) {
		case SCR_EXPECT: {
			int64_t v = sim_field_value(sim, (int)sp->field);
			if (!scr_compare(v, sp->cmp, sp->value)) {
				format_value(sp->field, v, got, sizeof(got));
				format_value(sp->field, sp->value, want, sizeof(want));
				say_err("%s:%u: expect %s %s %s failed: %s is %s", s->path, sp->line,
				    sim_field_name((int)sp->field), scr_cmp_name(sp->cmp), want,
				    sim_field_name((int)sp->field), got);
				s->failures++;
			}
			break;
		}
		case SCR_SNAPSHOT:
			fprintf(s->out, "snapshot tick %u frame %016" PRIx64 " state %016" PRIx64 "\n",
				t, hash_frame(f->px, f->w, f->h, f->pitch), sim_hash(sim));
			break;
		case SCR_SCREENSHOT: {
			int rc = shot_png(sp->path, f->px, f->w, f->h, f->pitch, rgb);
			if (rc < 0) {
				say_err("%s:%u: screenshot %s: %s", s->path, sp->line, sp->path,
				    strerror(-rc));
				s->failures++;
			}
			break;
		}
		case SCR_PRESS:
		case SCR_RELEASE:
		case SCR_END:
			break;
		}
	}
}

void script_free(struct script *s)
{
	scr_free(s->scr);
	s->scr = NULL;
}
