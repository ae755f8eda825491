# make bench-v3 BOX2D_V3_DIR=<a Box2D v3 source tree> (issue 21). Included by the Makefile.
# Box2D v3 is not in Debian and is never committed: point BOX2D_V3_DIR at a
# tree you fetched (e.g. a clone of erincatto/box2d). It is built under
# $(BUILD)/box2d-v3 with its own CMake (Release, its default SSE2 path, float,
# single precision; samples and unit tests off: they download), and its
# benchmark scenes (its shared/benchmarks.c, from that tree) are timed beside
# tumble's by tools/bench_v3.sh: interleaved run by run, one process per run,
# process CPU time, the ratio of the minimums. BENCH_V3_RUNS (default 5) runs
# per engine and scene; BENCH_V3_SCENES to choose scenes.
BOX2D_V3_DIR ?=
BENCH_V3_RUNS ?= 5
BENCH_V3_SCENES ?=
V3_BUILD := $(BUILD)/box2d-v3

$(BENCH)/bench_v3_tumble: $(BUILD)/obj/tools/bench_v3/tumble_driver.o $(SCENE_CATALOGUE_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LDLIBS_ALL)

.PHONY: bench-v3
bench-v3:
	@test -n "$(BOX2D_V3_DIR)" && test -f "$(BOX2D_V3_DIR)/include/box2d/box2d.h" && \
	  test -f "$(BOX2D_V3_DIR)/shared/benchmarks.c" || { \
	  echo "make bench-v3: set BOX2D_V3_DIR to a Box2D v3 source tree (with include/box2d/box2d.h and shared/benchmarks.c)" >&2; \
	  exit 2; }
	cmake -S "$(BOX2D_V3_DIR)" -B $(V3_BUILD) -DCMAKE_BUILD_TYPE=Release -DBOX2D_SAMPLES=OFF -DBOX2D_UNIT_TESTS=OFF \
	  -DBOX2D_BENCHMARKS=ON -DBOX2D_DOCS=OFF >$(V3_BUILD).cmake.log 2>&1 || { cat $(V3_BUILD).cmake.log; exit 1; }
	cmake --build $(V3_BUILD) --target box2d shared -j2
	@mkdir -p $(BENCH)
	$(CC) -std=c17 -O2 -DNDEBUG -I"$(BOX2D_V3_DIR)/include" -I"$(BOX2D_V3_DIR)/shared" \
	  tools/bench_v3/v3_driver.c -o $(BENCH)/bench_v3_box2d \
	  $$(find $(V3_BUILD) -name libshared.a | head -n 1) $$(find $(V3_BUILD) -name libbox2d.a | head -n 1) -lm -lpthread
	@$(MAKE) --no-print-directory $(BENCH)/bench_v3_tumble
	tools/bench_v3.sh $(BENCH) $(BENCH_V3_RUNS) "$(BOX2D_V3_DIR)" $(BENCH_V3_SCENES)
