# make stress: the stress suite of issue 7 (tests/stress/). Included by the Makefile.
# `make stress` builds the suite at -O3 and at -O0 (DEBUG=1), compares the two
# builds' hashes of the stress scenes (the -O0 build runs each scene once, the
# -O3 build twice, both runs compared), runs every test and writes
# results/STRESS.md; it exits non-zero when a test fails. `make test` runs the
# fast subset (stress_fast: the tests marked fast in tests/stress/stress_runner.c).
STRESS_DIR := $(BUILD)/stress
STRESS_SRC := $(filter-out tests/stress/stress_main.c tests/stress/stress_fast.c,$(wildcard tests/stress/*.c))
STRESS_OBJ := $(STRESS_SRC:%.c=$(BUILD)/obj/%.o)
# heap_count.c counts the heap through the linker's --wrap (memory checks)
STRESS_WRAP := -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free

$(STRESS_DIR)/stress: $(BUILD)/obj/tests/stress/stress_main.o $(STRESS_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) $(STRESS_WRAP) -o $@ $^ $(LDLIBS_ALL)

$(STRESS_DIR)/stress_fast: $(BUILD)/obj/tests/stress/stress_fast.o $(STRESS_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) $(STRESS_WRAP) -o $@ $^ $(LDLIBS_ALL)

EXTRA_TEST_BIN += $(STRESS_DIR)/stress_fast
EXTRA_SAN_BIN += $(STRESS_DIR)/stress_fast
FORMATTED += tests/stress/*.c tests/stress/*.h

.PHONY: stress
stress:
	@$(MAKE) --no-print-directory $(STRESS_DIR)/stress
	@$(MAKE) --no-print-directory DEBUG=1 build/debug/stress/stress
	@mkdir -p results
	build/debug/stress/stress --hashes-once > $(STRESS_DIR)/hashes-O0.txt
	$(STRESS_DIR)/stress --report results/STRESS.md --o0-hashes $(STRESS_DIR)/hashes-O0.txt
