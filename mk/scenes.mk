# The scene catalogue's test suite (issue 5, the scene gallery). Included by
# the Makefile. The catalogue is every demos/scenes/*.c (scenes.c lists the
# scenes, gallery.c builds the demo ones); whatever links scenes.o needs them all.
SCENE_CATALOGUE_OBJ = $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard demos/scenes/*.c))
SCENES_TEST := $(BUILD)/tests/scenes/test_scenes

# bench.mk links only scenes.o into the dynamics bench: add the other catalogue
# objects as prerequisites (its recipe links $^).
$(BUILD)/bench/bench_dynamics: $(filter-out %/scenes.o,$(SCENE_CATALOGUE_OBJ))

$(SCENES_TEST): $(BUILD)/obj/tests/scenes/test_scenes.o $(SCENE_CATALOGUE_OBJ) $(TEST_UTIL_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) -o $@ $^ $(CHECK_LIBS) $(LDLIBS_ALL)

EXTRA_TEST_BIN += $(SCENES_TEST)
EXTRA_SAN_BIN += $(SCENES_TEST)
FORMATTED += tests/scenes/*.c
