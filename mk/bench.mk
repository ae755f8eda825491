# make bench, make bench-quick (issue 6). Included by the Makefile.
# ---- bench ---------------------------------------------------------------------
# Micro benchmarks of the collision issue, tumble and Box2D 2.4.1 side by side:
# broad-phase tree (10,000 moving proxies) and manifold throughput per pair type.
BENCH := $(BUILD)/bench
$(BENCH)/bench_tree: tools/bench_tree.c $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -o $@ $< $(LIB_A) $(LDLIBS_ALL)
$(BENCH)/bench_tree_b2: tools/bench_tree_b2.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS_ALL) -o $@ $< -lbox2d
$(BENCH)/bench_manifold: $(BUILD)/obj/tools/bench_manifold.o $(BUILD)/obj/tools/bench_manifold_b2.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CXX) -o $@ $^ -lbox2d $(LDLIBS_ALL)
# Dynamics bench: the six performance scenes of demos/scenes (large_pyramid,
# many_pyramids, joint_grid, rain, smash, tumbler), tumble at 60 Hz / 4 substeps
# and Box2D 2.4.1 at 8/3 and 4/2 iterations (see tools/bench_dynamics.c).
# `make bench` and `make bench-quick` run them through tools/bench_run.sh
# (perf.csv, profile.csv); --quick is scale 0.5, one run each.
$(BENCH)/bench_dynamics: $(BUILD)/obj/tools/bench_dynamics.o $(SCENE_CATALOGUE_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LDLIBS_ALL)
$(BENCH)/bench_dynamics_b2: tools/bench_dynamics_b2.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS_ALL) -o $@ $< -lbox2d

# Accuracy sweep and body-count scaling (tools/bench_accuracy.c), one scene
# code for both engines through tools/bench/engine.h.
BENCH_ACCURACY_OBJ := $(BUILD)/obj/tools/bench_accuracy.o $(BUILD)/obj/tools/bench_engine_tumble.o \
  $(BUILD)/obj/tools/bench_engine_b2.o
$(BENCH)/bench_accuracy: $(BENCH_ACCURACY_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CXX) -o $@ $^ -lbox2d $(LDLIBS_ALL)
$(BENCH)/bench_skip: $(BUILD)/obj/tools/bench_skip.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LDLIBS_ALL)
$(BENCH)/bench_report: $(BUILD)/obj/tools/bench_report.o
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LDLIBS_ALL)

# ---- make bench, make bench-quick, make bench-docs --------------------------------
# make bench: the micro benchmarks, then tools/bench_run.sh: performance scenes,
# accuracy sweep, scaling, skip costs -> results/ (bench.csv, REPORT.md, plots),
# then the report and plots copied to docs/bench/ (about 15 minutes).
# make bench-quick: smaller scenes, fewer settings and runs, into
# $(BUILD)/bench/quick/ (about a minute); fails on a failed build, step or NaN.
BENCH_RESULTS ?= results
BENCH_TOOLS := $(BENCH)/bench_dynamics $(BENCH)/bench_dynamics_b2 $(BENCH)/bench_accuracy $(BENCH)/bench_skip \
  $(BENCH)/bench_report
FORMATTED += tools/bench/*.h tools/bench_v3/*.c

.PHONY: bench bench-quick bench-docs deps-bench
deps-bench:
	@tools/deps.sh bench

bench: deps-bench
	@$(MAKE) --no-print-directory $(BENCH)/bench_tree $(BENCH)/bench_tree_b2 $(BENCH)/bench_manifold $(BENCH_TOOLS)
	$(BENCH)/bench_tree
	$(BENCH)/bench_tree_b2
	$(BENCH)/bench_manifold
	tools/bench_run.sh $(BENCH) $(BENCH_RESULTS)
	@$(MAKE) --no-print-directory bench-docs

bench-quick: deps-bench
	@$(MAKE) --no-print-directory $(BENCH_TOOLS)
	tools/bench_run.sh $(BENCH) $(BENCH)/quick quick

# The committed copy of the last full run's report and plots.
bench-docs:
	@test -f $(BENCH_RESULTS)/REPORT.md || { echo "no $(BENCH_RESULTS)/REPORT.md: run make bench" >&2; exit 1; }
	@mkdir -p docs/bench/plots
	rm -f docs/bench/plots/*.png
	cp $(BENCH_RESULTS)/REPORT.md $(BENCH_RESULTS)/bench.csv docs/bench/
	cp $(BENCH_RESULTS)/plots/*.png docs/bench/plots/
