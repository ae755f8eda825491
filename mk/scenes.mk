# The scene catalogue's test suite (issue 5, the scene gallery). Included by
# the Makefile, which defines SCENE_CATALOGUE_OBJ.
SCENES_TEST := $(BUILD)/tests/scenes/test_scenes

$(SCENES_TEST): $(BUILD)/obj/tests/scenes/test_scenes.o $(SCENE_CATALOGUE_OBJ) $(TEST_UTIL_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) -o $@ $^ $(CHECK_LIBS) $(LDLIBS_ALL)

EXTRA_TEST_BIN += $(SCENES_TEST)
EXTRA_SAN_BIN += $(SCENES_TEST)
FORMATTED += tests/scenes/*.c
