/*
 * arcaded: command line, configuration layers, then the main loop.
 */
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app/app.h"
#include "app/cfgerr.h"
#include "app/diag.h"
#include "app/pspec.h"
#include "app/say.h"
#include "audio/au.h"
#include "config/cfg.h"
#include "config/st.h"
#include "engine/core/num.h"

#define ARCADED_VERSION "0.1.0"
#define MAX_SETS 64

static void usage(FILE *f)
{
	fputs("usage: arcaded [options]\n"
	      "       arcaded replay FILE [options]   (same as --replay FILE)\n"
	      "       arcaded devices                 (HID, evdev, GPIO devices, their profiles;\n"
	      "                                        sound cards)\n"
	      "Runs the arcade cabinet daemon: input, game, framebuffer.\n"
	      "\n"
	      "  --config-dir DIR   read DIR/*.ini in name order (default /etc/arcaded)\n"
	      "  --state-dir DIR    state directory (default $STATE_DIRECTORY or /var/lib/arcaded)\n"
	      "  --set S.K=V        set one configuration key (repeatable; last layer)\n"
	      "  --display NAME     auto, kms, fbdev, file, term or null (= --set display.backend=NAME)\n"
	      "  --audio SPEC       sound output: auto, alsa, alsa:DEVICE, wav:FILE or null\n"
	      "                     (= --set audio.output=SPEC; scripts and replays: none by default)\n"
	      "  --level N          built-in level N (= --set game.level=N)\n"
	      "  --wad FILE         play Doom-format maps from FILE (repeatable: IWAD first,\n"
	      "                     then PWADs, later ones override)\n"
	      "  --map NAME         the map to play from the WADs (E1M1, MAP01; default: the first)\n"
	      "  --print-specials   with --wad: list the line and sector specials of --map NAME\n"
	      "                     with counts, marking those the game does not play, then\n"
	      "                     exit; without --map (or --map all) every map of the WADs\n"
	      "                     and the supported share over all of them\n"
	      "  --grid FILE        play a grid (tile) map; \"builtin\" is the built-in GRID1\n"
	      "  --no-lights        no shadowed point-light maps\n"
	      "  --play             start in play, skipping attract (= --set game.start_in_play=1)\n"
	      "  --bindings FILE    extra key bindings file, applied last\n"
	      "  --script FILE      run a test script headless, as fast as possible\n"
	      "  --record FILE      record every tick's command to FILE\n"
	      "  --replay FILE      replay a recording headless; print per-tick hashes\n"
	      "  --no-render        with --replay: state hashes only, no rendering\n"
	      "  --verify           with --replay: compare with the hashes the recording stores;\n"
	      "                     exit 1 at a difference (prints the first)\n"
	      "  --until TICK       stop after tick TICK (with --screenshot: that tick's frame)\n"
	      "  --size WxH         render size, over the configuration and a recording's own\n"
	      "  --renderer NAME    software (default) or gl: the OSMesa oracle renderer\n"
	      "  --quiet            with --replay: print no per-tick hashes (benchmarks)\n"
	      "  --ticks N          stop after N ticks\n"
	      "  --fast             do not wait for the 60 Hz clock\n"
	      "  --realtime         with --replay or --script: follow the 60 Hz clock as\n"
	      "                     live play does (pacing tests); prints the summary\n"
	      "  --screenshot FILE  write the last frame as PNG at exit\n"
	      "  --print-config     print the effective configuration and exit\n"
	      "  --version, --help\n"
	      "\n"
	      "SIGUSR1 prints frame-time and latency statistics; they are printed at exit too.\n",
	      f);
}

/* One state file of the state directory whose payload is INI text,
 * applied as a layer (settings.ini: the menu's settings; content.ini and
 * screen.ini: the app's service pages, app/op.h). */
static void main_state_layer(struct cfg *c, const char *file, struct cfgerr *e)
{
	char msg[256] = "", name[CFG_PATH_MAX + 32];
	size_t len = 0;
	void *buf = NULL;
	int rc = st_load(c->paths.state_dir, file, &buf, &len, NULL, msg, sizeof(msg));

	snprintf(name, sizeof(name), "%s/%s", c->paths.state_dir, file);
	if (msg[0] && rc != -ENOENT)
		say_warn("%s: %s", name, msg);
	if (rc == 0)
		cfg_load_text(c, buf, len, name, cfgerr_add, e);
	else if (rc != -ENOENT)
		say_warn("%s: %s; using the other layers", name, strerror(-rc));
	free(buf);
}

/* The configuration, layered: defaults < config dir < the state
 * directory's settings.ini, content.ini, screen.ini < command line. Its
 * errors are logged and kept in e (for the screen: app/cfgerr.h). */
static void main_layers(struct cfg *c, const char *config_dir, const char *state_dir,
			char (*sets)[CFG_PATH_MAX + 32], int nsets, struct cfgerr *e)
{
	static const char *const state_files[] = { "settings.ini", "content.ini", "screen.ini" };

	cfgerr_clear(e);
	cfg_defaults(c);
	if (state_dir)
		snprintf(c->paths.state_dir, sizeof(c->paths.state_dir), "%s", state_dir);
	if (config_dir)
		cfg_load_dir(c, config_dir, cfgerr_add, e);
	for (size_t i = 0; c->paths.state_dir[0] && i < sizeof(state_files) / sizeof(*state_files);
	     i++)
		main_state_layer(c, state_files[i], e);
	for (int i = 0; i < nsets; i++)
		cfg_set(c, sets[i], cfgerr_add, e);
}

int main(int argc, char **argv)
{
	enum { O_CONFIG_DIR = 256, O_STATE_DIR, O_SET, O_DISPLAY, O_AUDIO, O_LEVEL, O_PLAY, O_BINDINGS,
	       O_SCRIPT, O_RECORD, O_REPLAY, O_NO_RENDER, O_QUIET, O_TICKS, O_FAST, O_SCREENSHOT,
	       O_PRINT_CONFIG, O_VERSION, O_HELP, O_WAD, O_MAP, O_GRID, O_NO_LIGHTS, O_VERIFY,
	       O_UNTIL, O_SIZE, O_RENDERER, O_REALTIME, O_PRINT_SPECIALS };
	static const struct option opts[] = {
		{ "config-dir", required_argument, NULL, O_CONFIG_DIR },
		{ "state-dir", required_argument, NULL, O_STATE_DIR },
		{ "set", required_argument, NULL, O_SET },
		{ "display", required_argument, NULL, O_DISPLAY },
		{ "audio", required_argument, NULL, O_AUDIO },
		{ "level", required_argument, NULL, O_LEVEL },
		{ "play", no_argument, NULL, O_PLAY },
		{ "bindings", required_argument, NULL, O_BINDINGS },
		{ "script", required_argument, NULL, O_SCRIPT },
		{ "record", required_argument, NULL, O_RECORD },
		{ "replay", required_argument, NULL, O_REPLAY },
		{ "no-render", no_argument, NULL, O_NO_RENDER },
		{ "quiet", no_argument, NULL, O_QUIET },
		{ "ticks", required_argument, NULL, O_TICKS },
		{ "fast", no_argument, NULL, O_FAST },
		{ "realtime", no_argument, NULL, O_REALTIME },
		{ "screenshot", required_argument, NULL, O_SCREENSHOT },
		{ "print-config", no_argument, NULL, O_PRINT_CONFIG },
		{ "wad", required_argument, NULL, O_WAD },
		{ "map", required_argument, NULL, O_MAP },
		{ "print-specials", no_argument, NULL, O_PRINT_SPECIALS },
		{ "grid", required_argument, NULL, O_GRID },
		{ "no-lights", no_argument, NULL, O_NO_LIGHTS },
		{ "verify", no_argument, NULL, O_VERIFY },
		{ "until", required_argument, NULL, O_UNTIL },
		{ "size", required_argument, NULL, O_SIZE },
		{ "renderer", required_argument, NULL, O_RENDERER },
		{ "version", no_argument, NULL, O_VERSION },
		{ "help", no_argument, NULL, O_HELP },
		{ NULL, 0, NULL, 0 },
	};
	/* --set values and the shortcuts that expand to them, applied in
	 * command-line order after the files. */
	static char sets[MAX_SETS][CFG_PATH_MAX + 32];
	static struct cfgerr errs;     /* the configuration's, for the screen */
	struct app_opts o = { .out = stdout, .config_dir = "/etc/arcaded" };
	const char *state_dir = NULL;
	int nsets = 0, print_config = 0, print_specials = 0, no_lights = 0, devices = 0, opt;
	struct cfg c;

	/* under systemd, lines carry their priority for the journal */
	say_open();
	while ((opt = getopt_long(argc, argv, "", opts, NULL)) != -1) {
		const char *prefix = NULL;
		switch (opt) {
		case O_CONFIG_DIR: o.config_dir = optarg; break;
		case O_STATE_DIR: state_dir = optarg; break;
		case O_SET: prefix = ""; break;
		case O_DISPLAY: prefix = "display.backend="; break;
		case O_AUDIO: prefix = "audio.output="; break;
		case O_LEVEL: prefix = "game.level="; break;
		case O_PLAY: prefix = "game.start_in_play="; optarg = "1"; break;
		case O_BINDINGS: o.bindings = optarg; break;
		case O_SCRIPT: o.script = optarg; break;
		case O_RECORD: o.record = optarg; break;
		case O_REPLAY: o.replay = optarg; break;
		case O_NO_RENDER: o.no_render = 1; break;
		case O_QUIET: o.quiet = 1; break;
		case O_TICKS:
		case O_UNTIL: {
			int64_t v;
			if (num_parse(optarg, 0, 0xfffffffe, &v) < 0) {
				say_err("--%s: '%s' is not a tick number",
					opt == O_TICKS ? "ticks" : "until", optarg);
				return 2;
			}
			/* --until T: stop after tick T has run (T + 1 ticks) */
			o.ticks = (uint32_t)v + (opt == O_UNTIL);
			break;
		}
		case O_VERIFY: o.verify = 1; break;
		case O_RENDERER:
			if (strcmp(optarg, "gl") == 0) {
				o.gl = 1;
			} else if (strcmp(optarg, "software") != 0) {
				say_err("--renderer: '%s' is not software or gl",
					optarg);
				return 2;
			}
			break;
		case O_SIZE: {
			char x;
			if (sscanf(optarg, "%d%c%d", &o.size_w, &x, &o.size_h) != 3 || x != 'x' ||
			    o.size_w < 64 || o.size_w > 4096 || o.size_h < 48 || o.size_h > 4096) {
				say_err("--size: '%s' is not WxH within 64x48..4096x4096",
					optarg);
				return 2;
			}
			break;
		}
		case O_FAST: o.fast = 1; break;
		case O_REALTIME: o.realtime = 1; break;
		case O_SCREENSHOT: o.screenshot = optarg; break;
		case O_PRINT_CONFIG: print_config = 1; break;
		case O_WAD:
			if (o.content.nwads == CT_MAX_WADS) {
				say_err("more than %d --wad files", CT_MAX_WADS);
				return 2;
			}
			o.content.wads[o.content.nwads++] = optarg;
			break;
		case O_MAP: o.content.map = optarg; break;
		case O_PRINT_SPECIALS: print_specials = 1; break;
		case O_GRID: o.content.grid = optarg; break;
		case O_NO_LIGHTS: no_lights = 1; break;
		case O_VERSION: puts("arcaded " ARCADED_VERSION); return 0;
		case O_HELP: usage(stdout); return 0;
		default: usage(stderr); return 2;
		}
		if (prefix) {
			if (nsets == MAX_SETS) {
				say_err("more than %d --set options", MAX_SETS);
				return 2;
			}
			snprintf(sets[nsets++], sizeof(sets[0]), "%s%s", prefix, optarg);
		}
	}
	if (optind + 1 == argc && strcmp(argv[optind], "devices") == 0) {
		devices = 1;
		optind++;
	}
	/* Subcommand form: `arcaded replay FILE [options]`. */
	if (optind + 2 == argc && strcmp(argv[optind], "replay") == 0 && !o.replay) {
		o.replay = argv[optind + 1];
		optind += 2;
	}
	if (optind < argc) {
		say_err("unexpected argument '%s'", argv[optind]);
		usage(stderr);
		return 2;
	}
	if (print_specials) {
		/* a tool: no configuration, no devices */
		if (o.content.nwads == 0) {
			say_err("--print-specials goes with --wad");
			return 2;
		}
		return pspec_print(o.content.wads, o.content.nwads, o.content.map, stdout);
	}
	if (o.gl && (o.replay || o.script || o.record)) {
		/* llvmpipe's frames are not bit-exact: hashes, recordings and
		 * scripts stay on the deterministic software renderer */
		say_err("--renderer gl is for play; scripts, recordings and replays use the "
			"software renderer");
		return 2;
	}
	if (o.verify && !o.replay) {
		say_err("--verify goes with --replay");
		return 2;
	}
	if (o.script && o.replay) {
		say_err("--script and --replay cannot be combined");
		return 2;
	}
	if (o.no_render && !o.replay) {
		say_err("--no-render goes with --replay");
		return 2;
	}

	if (state_dir && strlen(state_dir) >= sizeof(c.paths.state_dir)) {
		/* cut short it would name another directory: refused, as
		 * paths.state_dir set in a file or by --set is */
		say_err("--state-dir: path too long (at most %zu bytes)",
			sizeof(c.paths.state_dir) - 1);
		return 2;
	}
	o.errs = &errs;
	for (;;) {
		int code;

		main_layers(&c, o.config_dir, state_dir, sets, nsets, &errs);
		if (devices)
			return diag_list(stdout, &c, o.config_dir, o.bindings) < 0 ? 2 : 0;
		if (print_config) {
			size_t n = cfg_format(&c, NULL, 0);
			char *buf = malloc(n + 1);
			if (!buf)
				return 2;
			cfg_format(&c, buf, n + 1);
			fputs(buf, stdout);
			free(buf);
			return 0;
		}
		o.content.level = c.game.level;
		o.content.lights = !no_lights;
		if (o.content.map && o.content.nwads == 0) {
			say_err("--map goes with --wad");
			return 2;
		}
		code = app_run(&c, &o);
		if (code != APP_RELOAD)
			return code;
		say("service menu: the content or the screen changed: starting again");
	}
}
