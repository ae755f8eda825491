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
# `make bench-quick` runs them at scale 0.5, one run each (about a minute).
# Extra options go through BENCH_ARGS, e.g. BENCH_ARGS="--csv build/bench/dynamics.csv".
$(BENCH)/bench_dynamics: $(BUILD)/obj/tools/bench_dynamics.o $(BUILD)/obj/demos/scenes/scenes.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $^ $(LDLIBS_ALL)
$(BENCH)/bench_dynamics_b2: tools/bench_dynamics_b2.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS_ALL) -o $@ $< -lbox2d

.PHONY: bench bench-quick
bench: deps-test
	@$(MAKE) --no-print-directory $(BENCH)/bench_tree $(BENCH)/bench_tree_b2 $(BENCH)/bench_manifold \
	  $(BENCH)/bench_dynamics $(BENCH)/bench_dynamics_b2
	$(BENCH)/bench_tree
	$(BENCH)/bench_tree_b2
	$(BENCH)/bench_manifold
	$(BENCH)/bench_dynamics $(BENCH_ARGS)
	$(BENCH)/bench_dynamics_b2 $(BENCH_ARGS)

bench-quick: deps-test
	@$(MAKE) --no-print-directory $(BENCH)/bench_dynamics $(BENCH)/bench_dynamics_b2
	$(BENCH)/bench_dynamics --quick $(BENCH_ARGS)
	$(BENCH)/bench_dynamics_b2 --quick $(BENCH_ARGS)

