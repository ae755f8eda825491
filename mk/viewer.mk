# make viewer and the viewer's smoke test (issue 5). Included by the Makefile.
#
# tumble-viewer shows the scene catalogue in an SDL2 window with an OpenGL
# context: SDL2 and the system's libGL (never OSMesa, whose symbols would
# clash), and the renderer's GL drawing, camera and font: objects of
# libtumble-render's sources (render/), not the library, which brings OSMesa.
# It is optional: without SDL2 (pkg-config sdl2), `make`, `make viewer` and
# `make viewer-test` print one line and go on.
VIEWER_BIN := $(BUILD)/tumble-viewer
VIEWER_SRC := $(wildcard demos/viewer/*.c)
VIEWER_OBJ := $(VIEWER_SRC:%.c=$(BUILD)/obj/%.o)
VIEWER_RENDER_OBJ := $(patsubst %,$(BUILD)/obj/render/%.o,gl_draw camera font) $(DEMO_CLI_OBJ)
VIEWER_HAVE_SDL := $(shell pkg-config --exists sdl2 2>/dev/null && echo yes)
VIEWER_CFLAGS = $(shell pkg-config --cflags sdl2 2>/dev/null)
VIEWER_LIBS = $(shell pkg-config --libs sdl2 2>/dev/null) $(shell pkg-config --libs gl 2>/dev/null || echo -lGL)
VIEWER_SKIPPED := tumble-viewer skipped: SDL2 not found (install libsdl2-dev or run tools/deps.sh viewer)
VIEWER_SMOKE := $(BUILD)/tests/viewer/run_viewer_smoke

.PHONY: viewer viewer-test
all: viewer

ifeq ($(VIEWER_HAVE_SDL),yes)
viewer: $(VIEWER_BIN)

$(BUILD)/obj/demos/viewer/%.o: demos/viewer/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) $(VIEWER_CFLAGS) -I. -Idemos -c $< -o $@

$(VIEWER_BIN): $(VIEWER_OBJ) $(VIEWER_RENDER_OBJ) $(SCENE_CATALOGUE_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) -o $@ $^ $(VIEWER_LIBS) $(LDLIBS_ALL)

# run_tests.sh runs this wrapper: the scripted offscreen run, checked by
# tools/viewer_smoke.sh.
EXTRA_TEST_BIN += $(VIEWER_SMOKE)
EXTRA_SAN_BIN += $(VIEWER_SMOKE)
$(VIEWER_SMOKE): $(VIEWER_BIN) tools/viewer_smoke.sh
	@mkdir -p $(dir $@)
	@printf '#!/bin/sh\nexec "%s" "%s" "$$@"\n' "$(abspath tools/viewer_smoke.sh)" "$(abspath $(VIEWER_BIN))" > $@
	@chmod +x $@

viewer-test: $(VIEWER_SMOKE)
	$(VIEWER_SMOKE)
else
viewer viewer-test:
	@echo "$(VIEWER_SKIPPED)"
endif

FORMATTED += demos/viewer/*.c demos/viewer/*.h
