# make bench-v3 BOX2D_V3_DIR=<a Box2D v3 source tree> (issue 21). Included by the Makefile.
# Box2D v3 is not in Debian and is never committed: point BOX2D_V3_DIR at a
# tree you fetched (e.g. a clone of erincatto/box2d). It is built under
# $(BUILD)/box2d-v3 with its own CMake (Release, its default SSE2 path, float,
# single precision; samples and unit tests off: they download), and its
# benchmark scenes (its shared/benchmarks.c, from that tree) are timed beside
# tumble's by tools/bench_v3.sh: interleaved run by run, one process per run,
# process CPU time, the ratio of the minimums. BENCH_V3_RUNS (default 5) runs
# per engine and scene; BENCH_V3_SCENES to choose scenes.
#
# Then the accuracy scenes of make bench on tumble, Box2D 2.4.1 and v3
# (bench_accuracy built again with -DBENCH_WITH_V3 and tools/bench_engine_v3.c;
# v3 at 60 Hz x 4 substeps by default, swept over substeps 1, 2, 4, 8 and
# 30 to 240 Hz), through tools/bench_run.sh: the CSV, report and Pareto plots
# go to $(BENCH)/v3/accuracy/ (nothing is written to docs/). BENCH_V3_ACCURACY:
# 1 (default) both parts, 0 the speed part only, only the accuracy part only;
# BENCH_V3_QUICK=1 runs the accuracy part's --quick sweep.
BOX2D_V3_DIR ?=
BENCH_V3_RUNS ?= 5
BENCH_V3_SCENES ?=
BENCH_V3_ACCURACY ?= 1
BENCH_V3_QUICK ?=
V3_BUILD := $(BUILD)/box2d-v3
V3_LIB := $(V3_BUILD)/src/libbox2d.a

# Only bench_engine_v3.c sees v3's headers (2.4.1's are the system's box2d/box2d.h);
# they compile under the project's warnings (-Wpedantic -Werror) as they are.
$(BUILD)/obj/tools/bench_engine_v3.o: tools/bench_engine_v3.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -I"$(BOX2D_V3_DIR)/include" -c $< -o $@
$(BUILD)/obj/tools/bench_accuracy_v3.o: tools/bench_accuracy.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -DBENCH_WITH_V3 -c $< -o $@
# v3 is C (b2World_Step, ...), 2.4.1 C++ (mangled names): they link side by side.
$(BENCH)/bench_accuracy_v3: $(BUILD)/obj/tools/bench_accuracy_v3.o $(BUILD)/obj/tools/bench_engine_tumble.o \
  $(BUILD)/obj/tools/bench_engine_b2.o $(BUILD)/obj/tools/bench_engine_v3.o $(LIB_A) $(V3_LIB)
	@mkdir -p $(dir $@)
	$(CXX) -o $@ $^ -lbox2d $(LDLIBS_ALL) -lpthread

$(BENCH)/bench_v3_tumble: $(BUILD)/obj/tools/bench_v3/tumble_driver.o $(SCENE_CATALOGUE_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LDLIBS_ALL)

.PHONY: bench-v3
bench-v3:
	@case "$(BENCH_V3_ACCURACY)" in 0 | 1 | only) ;; *) \
	  echo "make bench-v3: BENCH_V3_ACCURACY is 1 (both parts), 0 (speed only) or only (accuracy only)" >&2; exit 2;; esac
	@test -n "$(BOX2D_V3_DIR)" && test -f "$(BOX2D_V3_DIR)/include/box2d/box2d.h" && \
	  test -f "$(BOX2D_V3_DIR)/shared/benchmarks.c" || { \
	  echo "make bench-v3: set BOX2D_V3_DIR to a Box2D v3 source tree (with include/box2d/box2d.h and shared/benchmarks.c)" >&2; \
	  exit 2; }
	@mkdir -p $(BUILD)
	cmake -S "$(BOX2D_V3_DIR)" -B $(V3_BUILD) -DCMAKE_BUILD_TYPE=Release -DBOX2D_SAMPLES=OFF -DBOX2D_UNIT_TESTS=OFF \
	  -DBOX2D_BENCHMARKS=ON -DBOX2D_DOCS=OFF >$(V3_BUILD).cmake.log 2>&1 || { cat $(V3_BUILD).cmake.log; exit 1; }
	cmake --build $(V3_BUILD) --target box2d shared -j2
ifneq ($(BENCH_V3_ACCURACY),only)
	@mkdir -p $(BENCH)
	$(CC) -std=c17 -O2 -DNDEBUG -I"$(BOX2D_V3_DIR)/include" -I"$(BOX2D_V3_DIR)/shared" \
	  tools/bench_v3/v3_driver.c -o $(BENCH)/bench_v3_box2d \
	  $$(find $(V3_BUILD) -name libshared.a | head -n 1) $$(find $(V3_BUILD) -name libbox2d.a | head -n 1) -lm -lpthread
	@$(MAKE) --no-print-directory $(BENCH)/bench_v3_tumble
	tools/bench_v3.sh $(BENCH) $(BENCH_V3_RUNS) "$(BOX2D_V3_DIR)" $(BENCH_V3_SCENES)
endif
ifneq ($(BENCH_V3_ACCURACY),0)
	@tools/deps.sh bench
	@$(MAKE) --no-print-directory $(BENCH)/bench_accuracy_v3 $(BENCH)/bench_report
	tools/bench_run.sh $(BENCH) $(BENCH)/v3/accuracy $(if $(BENCH_V3_QUICK),v3-quick,v3) "$(BOX2D_V3_DIR)"
endif
