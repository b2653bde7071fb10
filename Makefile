# arcaded build. `make run` and `make test` are the two entry points (README).
#
# Variables: BUILD (output folder), CC, OPT (optimisation flags), SAN
# (sanitizer flags). Several builds live side by side: build/ (default),
# build/asan (sanitizers), build/O0, build/clang ...

BUILD ?= build
CC ?= cc
OPT ?= -O2 -g
SAN ?=
PKGS := libevdev libpng libsystemd hidapi-hidraw libgpiod libusb-1.0 libdrm alsa
TEST_PKGS := cmocka

WARN := -Wall -Wextra -Werror -Wshadow -Wvla -Wstrict-prototypes -Wmissing-prototypes
CPPFLAGS += -I. -D_GNU_SOURCE -DARCADED_DATADIR='"$(PREFIX)/share/arcaded"' \
	-DARCADED_LIBDIR='"$(PREFIX)/lib/arcaded"'
CFLAGS += -std=c11 $(OPT) $(SAN) $(WARN) -fno-strict-aliasing
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS))
PKG_LIBS = $(shell pkg-config --libs $(PKGS))
TEST_CFLAGS = $(shell pkg-config --cflags $(TEST_PKGS))
TEST_LIBS = $(shell pkg-config --libs $(TEST_PKGS))
LDLIBS += $(PKG_LIBS) -lpthread -lm -ldl

# Every .c of the layers is part of the library the daemon and tests link,
# except engine/gl: the OSMesa renderer is a plugin (app/glr.h), built
# position-independent and linked with OSMesa on its own.
ENGINE_DIRS := core map sound game render ui
LIB_SRC := $(sort $(wildcard $(ENGINE_DIRS:%=engine/%/*.c) input/*.c display/*.c audio/*.c \
	config/*.c systemd/*.c))
GL_SRC := $(sort $(wildcard engine/gl/*.c))
GL_OBJ := $(GL_SRC:%.c=$(BUILD)/pic/%.o)
GL_SO := $(BUILD)/arcaded-gl.so
APP_SRC := $(sort $(wildcard app/*.c))
APP_MAIN := app/main.c
APP_LIB_SRC := $(filter-out $(APP_MAIN),$(APP_SRC))
TEST_SRC := $(sort $(wildcard tests/unit/test_*.c))
TOOL_SRC := $(sort $(wildcard tools/*.c))
FUZZ_SRC := $(sort $(wildcard tests/fuzz/fuzz_*.c))

LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/%.o) $(APP_LIB_SRC:%.c=$(BUILD)/%.o)
LIB := $(BUILD)/libarcaded.a
BIN := $(BUILD)/arcaded
TEST_BIN := $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/%)
TOOL_BIN := $(TOOL_SRC:tools/%.c=$(BUILD)/tools/%)
FUZZ_BIN := $(FUZZ_SRC:tests/fuzz/%.c=$(BUILD)/fuzz/%)
FUZZ_SECONDS ?= 60
FUZZ_BUILD := build/fuzz
FUZZ_VARS := BUILD=$(FUZZ_BUILD) CC=clang OPT="-O1 -g -fno-omit-frame-pointer" \
	SAN="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=all"

PREFIX ?= /usr/local
DESTDIR ?=
SYSTEMD_UNITDIR ?= /lib/systemd/system
UDEV_RULESDIR ?= /lib/udev/rules.d
SYSUSERSDIR ?= /usr/lib/sysusers.d
TMPFILESDIR ?= /usr/lib/tmpfiles.d

.PHONY: all setup setup-test run test deb image test-image test-pkg test-unit test-asan test-script \
	test-replay test-clang check-layers check-state check-tables check-systemd check-install \
	check-levels test-vm docs-shots docs-pinout check-docs fuzz fuzzers bench bench-pacing install clean tests tools

all: $(BIN) $(GL_SO) tools

setup:
	@scripts/setup.sh

# What the tests, the package and the image need as well.
setup-test:
	@scripts/setup.sh test

# `make run` goes straight into play; RUN_ARGS= (empty) boots into attract.
RUN_ARGS ?= --play
run: setup
	@$(MAKE) --no-print-directory all
	./$(BIN) $(RUN_ARGS)

test: setup-test
	@tests/run_all.sh

# The Debian package (debian/, debhelper) of the work tree, version from git:
# build/deb/arcaded_VERSION_ARCH.deb, linked as build/deb/arcaded.deb;
# lintian's findings in build/deb/lintian.txt (docs/packaging.md).
deb: setup-test
	@scripts/deb.sh

# The cabinet's disk image (mmdebstrap, no loop device, no mount) with that
# package installed: build/image/arcaded.img (docs/packaging.md). Cached in
# ~/.cache/arcaded-image by its inputs.
image: deb
	@scripts/image.sh build/deb/arcaded.deb build/image

# The image boots in QEMU (UEFI) to the attract screen and survives
# POWERCUTS hard power cuts (default 20).
POWERCUTS ?= 20
test-image: image
	@POWERCUTS=$(POWERCUTS) tests/image/run.sh build/image/arcaded.img

# Install, start, stop, remove and purge of the package in a clean chroot.
test-pkg: deb
	@tests/pkg/run.sh build/deb/arcaded.deb

$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PKG_CFLAGS) -MMD -MP -c $< -o $@

$(LIB): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

# -rdynamic: the plugin's calls into the engine resolve against the daemon.
$(BIN): $(BUILD)/$(APP_MAIN:.c=.o) $(LIB)
	$(CC) $(CFLAGS) $(LDFLAGS) -rdynamic -o $@ $^ $(LDLIBS)

$(BUILD)/pic/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -fPIC $(shell pkg-config --cflags osmesa) -MMD -MP -c $< -o $@

$(GL_SO): $(GL_OBJ)
	$(CC) $(CFLAGS) $(LDFLAGS) -shared -o $@ $^ $(shell pkg-config --libs osmesa) -lm

$(BUILD)/tests/%: tests/unit/%.c $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PKG_CFLAGS) $(TEST_CFLAGS) -MMD -MP -o $@ $< $(LIB) \
		$(LDLIBS) $(TEST_LIBS)

# Test tools that link the library: sndfind finds a sound in a recording of
# what was played (the script and VM sound tests); autopilot writes the
# scripts of the Freedoom exit goldens from their routes (tests/replay).
TEST_TOOLS := $(BUILD)/tests/sndfind $(BUILD)/tests/autopilot
$(BUILD)/tests/sndfind: tests/sound/sndfind.c $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -MMD -MP -o $@ $< $(LIB) $(LDLIBS)
AUTOPILOT_SRC := tests/replay/autopilot.c tests/replay/ap_walk.c tests/replay/ap_way.c
$(BUILD)/tests/autopilot: $(AUTOPILOT_SRC) tests/replay/ap.h $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -o $@ $(AUTOPILOT_SRC) $(LIB) $(LDLIBS)

$(BUILD)/tools/%: tools/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -o $@ $< -lm

# mkmeshes reads the OBJ files with the engine's own reader: linked with the
# library (engine/map/mesh_builtin.c is its committed output).
$(BUILD)/tools/mkmeshes: tools/mkmeshes.c $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# pinout draws with the daemon's own code (the GPIO spec parser, v_video,
# the PNG writer): linked with the library.
$(BUILD)/tools/pinout: tools/pinout.c $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PKG_CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# libFuzzer targets (tests/fuzz/fuzz_<parser>.c, each defining
# LLVMFuzzerTestOneInput), linked against the library built for fuzzing.
$(BUILD)/fuzz/%: tests/fuzz/%.c $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(PKG_CFLAGS) -fsanitize=fuzzer -o $@ $< $(LIB) $(LDLIBS)

tests: $(TEST_BIN) $(TEST_TOOLS)
tools: $(TOOL_BIN)
fuzzers: $(FUZZ_BIN)

# Every fuzz target for FUZZ_SECONDS each (make fuzz FUZZ_SECONDS=3600),
# starting from its seed corpus tests/fuzz/corpus/<target>/.
fuzz:
	@$(MAKE) --no-print-directory $(FUZZ_VARS) fuzzers
	@tests/fuzz/run.sh $(FUZZ_BUILD)/fuzz $(FUZZ_SECONDS)

# Unit tests of this build; prints cmocka's summaries.
test-unit: $(TEST_BIN)
	@tests/run_unit.sh $(TEST_BIN)

check-tables: $(BUILD)/tools/gentab
	@$(BUILD)/tools/gentab > $(BUILD)/tab_data.c.new
	@cmp -s $(BUILD)/tab_data.c.new engine/core/tab_data.c || \
		{ echo "engine/core/tab_data.c differs from tools/gentab output"; exit 1; }
	@echo "check-tables: engine/core/tab_data.c matches tools/gentab"

check-layers:
	@tests/check_layers.sh

# A member of the sim's state outside its struct's field list stops the build.
check-state:
	@tests/check_state.sh

# Appliance tests in a QEMU VM: systemd, the installed unit, real devices (docs/vm.md).
test-vm: setup-test
	@BUILD=$(BUILD) tests/vm/run.sh

check-systemd:
	@tests/check_systemd.sh

# Installs into a temporary DESTDIR and checks the layout.
check-install: $(BIN)
	@tests/check_install.sh

# The screenshots in docs/ are made by the daemon's own screenshot command
# (maps, the game flow, every service menu page) and tools/pinout.
docs-shots: $(BIN) docs-pinout
	@scripts/docs-shots.sh $(BIN)
	@scripts/game-shots.sh $(BIN)
	@scripts/service-shots.sh $(BIN)

# The GPIO wiring picture of docs/operator.md: the example spec of the
# shipped config/arcaded.ini (its `; gpio:gpiochip0:...` line; the shipped
# default is gpio = none) drawn on a Raspberry Pi's 40-pin header.
PINOUT_SPEC = $(shell sed -n 's/^; *\(gpio:gpiochip0:[^ ]*\)$$/\1/p' config/arcaded.ini)
docs-pinout: $(BUILD)/tools/pinout
	@test -n "$(PINOUT_SPEC)" || { echo "docs-pinout: no '; gpio:gpiochip0:...' line in config/arcaded.ini"; exit 1; }
	$(BUILD)/tools/pinout '$(PINOUT_SPEC)' docs/images/gpio-pinout.png

# docs/operator.md names only images, options, keys, targets, pages and
# profiles that exist.
check-docs: $(BIN)
	@BIN=$(BIN) tests/check_docs.sh

# engine/map/lvl_wad.c is exactly what tools/mklevels makes of levels/*.txt.
check-levels: $(BUILD)/tools/mklevels $(BUILD)/tools/mkmeshes
	@BUILD=$(BUILD) tests/check_levels.sh

bench: all
	@tests/bench.sh $(BIN)

# Frame pacing: 10 minutes of play replayed in real time at 1920x1080
# (PACING_SECONDS to change it); figures and targets, not a test.
PACING_SECONDS ?= 600
bench-pacing: all
	@tests/bench/pacing.sh $(BIN) $(PACING_SECONDS)

install: $(BIN) $(GL_SO)
	install -D -m 0755 $(BIN) $(DESTDIR)$(PREFIX)/bin/arcaded
	install -D -m 0644 $(GL_SO) $(DESTDIR)$(PREFIX)/lib/arcaded/arcaded-gl.so
	install -D -m 0644 systemd/arcaded.service $(DESTDIR)$(SYSTEMD_UNITDIR)/arcaded.service
	sed -i 's|@BINDIR@|$(PREFIX)/bin|g' $(DESTDIR)$(SYSTEMD_UNITDIR)/arcaded.service
	install -D -m 0644 systemd/70-arcaded.rules $(DESTDIR)$(UDEV_RULESDIR)/70-arcaded.rules
	install -D -m 0644 systemd/arcaded.sysusers $(DESTDIR)$(SYSUSERSDIR)/arcaded.conf
	install -D -m 0644 systemd/arcaded.tmpfiles $(DESTDIR)$(TMPFILESDIR)/arcaded.conf
	install -D -m 0644 config/arcaded.ini $(DESTDIR)/etc/arcaded/arcaded.ini
	install -D -m 0644 config/bindings.ini $(DESTDIR)/etc/arcaded/bindings.ini
	install -d $(DESTDIR)$(PREFIX)/share/arcaded/profiles
	install -m 0644 config/profiles/*.ini $(DESTDIR)$(PREFIX)/share/arcaded/profiles/

clean:
	rm -rf build

-include $(shell find $(BUILD) -type f -name '*.d' 2>/dev/null)
