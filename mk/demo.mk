# make demo, make docs-images and the renderer tests (issue 5). Included by the Makefile.
#
# tumble-demo renders the scene catalogue headless through libtumble-render
# (render/, include/tumble_render.h; built by the Makefile), linked statically
# like libtumble. demos/cli_args.c holds the command-line parsing it shares
# with the viewer.
DEMO_BIN := $(BUILD)/tumble-demo
DEMO_CLI_OBJ := $(BUILD)/obj/demos/cli_args.o

# Mesa would otherwise write shader caches under $HOME on every run.
DEMO_ENV := MESA_SHADER_CACHE_DISABLE=true

$(BUILD)/obj/demos/tumble_demo.o: demos/tumble_demo.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -Idemos -c $< -o $@

$(DEMO_BIN): $(BUILD)/obj/demos/tumble_demo.o $(DEMO_CLI_OBJ) $(SCENE_CATALOGUE_OBJ) $(RENDER_LIB_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) -o $@ $^ $(RENDER_LIBS) $(LDLIBS_ALL)

# The gallery: every scene of the catalogue, one 960x540 PNG each after 1.5 s,
# the six performance scenes at half scale (a quarter of the bodies) so that
# the whole run stays under a minute on one core.
DEMO_ARGS ?= --size 960x540 --scale 0.5 --out out
.PHONY: demo docs-images deps-demo
deps-demo:
	@tools/deps.sh demo

demo: deps-demo
	@$(MAKE) --no-print-directory $(DEMO_BIN)
	$(DEMO_ENV) $(DEMO_BIN) $(DEMO_ARGS)

# Small pictures of every scene for the README, and one animated GIF.
DOCS_IMAGES := docs/images
DOCS_GIF_SCENE := tumbler_mixed
docs-images: deps-demo
	@tools/deps.sh video
	@$(MAKE) --no-print-directory $(DEMO_BIN)
	$(DEMO_ENV) $(DEMO_BIN) --size 480x270 --scale 0.5 --out $(DOCS_IMAGES)
	$(DEMO_ENV) $(DEMO_BIN) --scene $(DOCS_GIF_SCENE) --size 480x270 --frames 120 --every 2 --video --out build/docs-gif
	cp build/docs-gif/$(DOCS_GIF_SCENE).gif $(DOCS_IMAGES)/$(DOCS_GIF_SCENE).gif
	@echo $(DOCS_IMAGES)/$(DOCS_GIF_SCENE).gif

# ---- renderer tests -------------------------------------------------------------
RENDER_TEST := $(BUILD)/tests/render/test_render
$(BUILD)/obj/tests/render/%.o: tests/render/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) $(CHECK_CFLAGS) $(RENDER_CFLAGS) -Idemos -Irender -c $< -o $@

$(RENDER_TEST): $(BUILD)/obj/tests/render/test_render.o $(SCENE_CATALOGUE_OBJ) $(TEST_UTIL_OBJ) $(RENDER_LIB_A) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) -o $@ $^ $(CHECK_LIBS) $(RENDER_LIBS) $(LDLIBS_ALL)

# run_tests.sh runs the suite; Mesa's shader cache stays off through this wrapper.
EXTRA_TEST_BIN += $(BUILD)/tests/render/run_test_render
EXTRA_SAN_BIN += $(BUILD)/tests/render/run_test_render
EXTRA_TEST_DEPS += demo
$(BUILD)/tests/render/run_test_render: $(RENDER_TEST)
	@printf '#!/bin/sh\nMESA_SHADER_CACHE_DISABLE=true exec "%s" "$$@"\n' "$(abspath $(RENDER_TEST))" > $@
	@chmod +x $@

FORMATTED += render/*.c render/*.h include/tumble_render.h tests/render/*.c
