# make fuzz, make fuzz-smoke: libFuzzer harnesses (issue 7). Included by the Makefile.
# Each harness in fuzz/ is built with clang -fsanitize=fuzzer,address,undefined
# together with the library sources, and runs from its seed corpus in the repo
# (fuzz/corpus/NAME) plus what it finds (build/fuzz/corpus/NAME). A failed
# invariant or a sanitizer report stops the run and leaves the input in
# build/fuzz/crash-NAME-*; replay it with build/fuzz/fuzz_NAME FILE.
#   make fuzz                 each harness for FUZZ_SECONDS (default 180 s), then
#                             fuzz-merge: the repo corpus keeps what the run found
#   make fuzz-smoke           each harness for 20 s (CI; leaves fuzz/ untouched)
#   make fuzz-merge           fold build/fuzz/corpus/NAME into fuzz/corpus/NAME,
#                             keeping only inputs that add coverage (libFuzzer
#                             -merge=1); commit fuzz/corpus afterwards
#   make fuzz FUZZ_NAMES=hull only one harness
FUZZ_CC ?= clang
FUZZ_SECONDS ?= 180
# a fixed seed makes a run repeatable (libFuzzer picks one from the clock otherwise)
FUZZ_SEED ?= 1
FUZZ_NAMES ?= hull manifold api
FUZZ_DIR := build/fuzz
FUZZ_CFLAGS := -std=c17 $(WARN) -ffp-contract=off -O1 -g -Iinclude -Ifuzz \
  -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_BIN := $(FUZZ_NAMES:%=$(FUZZ_DIR)/fuzz_%)
# Invariants of fuzz_api.c can be switched off here (-DFUZZ_CHECK_<NAME>=0)
# while a defect they catch is being fixed; none is off now. The switches:
#   FUZZ_CHECK_SPEED_CAP         speed caps on every path (issue 23 items 3, 5)
#   FUZZ_CHECK_TINY_STEP         steps whose reciprocals overflow refused (item 6)
#   FUZZ_CHECK_ENGINE_LIMITS     states within TB_MAX_LENGTH / TB_MAX_VALUE (item 7)
#   FUZZ_CHECK_REFUSED_CHAIN     a refused tb_create_chain leaves the hash (item 4)
#   FUZZ_CHECK_DRAW_VALUES       draw bounds and colours checked (item 9)
#   FUZZ_CHECK_MIX_RESULTS       mix callback results checked (item 9)
#   FUZZ_CHECK_FIELD_STATE       the force field sees finite states only (item 8)
#   FUZZ_CHECK_USER_DATA_LOCKED  user data setters refused inside callbacks
# Reproducers of each, from before its fix: fuzz/known_bugs/.
FUZZ_KNOWN_BUGS ?=
FORMATTED += fuzz/*.c fuzz/*.h

$(FUZZ_DIR)/fuzz_%: fuzz/fuzz_%.c fuzz/fuzz_common.h $(LIB_SRC) $(wildcard src/*.h) include/tumble.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(FUZZ_KNOWN_BUGS) -o $@ $< $(LIB_SRC) -lm

# $(call fuzz_run,NAME,SECONDS)
define fuzz_run
	@mkdir -p $(FUZZ_DIR)/corpus/$(1)
	@echo "== fuzz_$(1): $(2) s"
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  $(FUZZ_DIR)/fuzz_$(1) $(FUZZ_DIR)/corpus/$(1) fuzz/corpus/$(1) -max_total_time=$(2) -seed=$(FUZZ_SEED) -timeout=10 \
	  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=$(FUZZ_DIR)/crash-$(1)- 2>$(FUZZ_DIR)/fuzz_$(1).log \
	  || { grep -E 'invariant failed|ERROR|SUMMARY|Test unit written' $(FUZZ_DIR)/fuzz_$(1).log; echo $(1) >> $(FUZZ_DIR)/failed; }
	@grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+ +DONE' $(FUZZ_DIR)/fuzz_$(1).log | tr '\n' ' '; echo

endef

# $(call fuzz_merge,NAME): new inputs of the run that add coverage go to the repo
define fuzz_merge
	@mkdir -p $(FUZZ_DIR)/corpus/$(1) fuzz/corpus/$(1)
	@before=$$(ls fuzz/corpus/$(1) | wc -l); \
	  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 $(FUZZ_DIR)/fuzz_$(1) -merge=1 fuzz/corpus/$(1) $(FUZZ_DIR)/corpus/$(1) \
	  2>$(FUZZ_DIR)/merge_$(1).log || { tail -n 20 $(FUZZ_DIR)/merge_$(1).log; exit 1; }; \
	  echo "== fuzz-merge $(1): fuzz/corpus/$(1) $$before -> $$(ls fuzz/corpus/$(1) | wc -l) inputs"

endef

.PHONY: fuzz fuzz-smoke fuzz-build fuzz-merge fuzz-coverage fuzz-api-list
# line coverage of src/ by fuzz/corpus/api and the public functions it never
# calls: results/FUZZ_COVERAGE.md (clang source-based coverage)
fuzz-coverage:
	@tools/deps.sh fuzz
	@tools/fuzz_coverage.sh "$(FUZZ_KNOWN_BUGS)"

# the functions of include/tumble.h that fuzz/fuzz_api.c never names (none)
fuzz-api-list:
	@fuzz/api_coverage.sh && echo "fuzz_api.c names every function of include/tumble.h"

fuzz-build:
	@tools/deps.sh fuzz
	@$(MAKE) --no-print-directory $(FUZZ_BIN)

# every harness runs even when one fails; the target fails at the end
fuzz: fuzz-build
	@rm -f $(FUZZ_DIR)/failed
	$(foreach n,$(FUZZ_NAMES),$(call fuzz_run,$(n),$(FUZZ_SECONDS)))
	@if [ -f $(FUZZ_DIR)/failed ]; then echo "== fuzz: failed: $$(cat $(FUZZ_DIR)/failed | tr '\n' ' ')"; exit 1; fi
	@$(MAKE) --no-print-directory fuzz-merge

fuzz-merge: fuzz-build
	$(foreach n,$(FUZZ_NAMES),$(call fuzz_merge,$(n)))

fuzz-smoke: fuzz-build fuzz-api-list
	@rm -f $(FUZZ_DIR)/failed
	$(foreach n,$(FUZZ_NAMES),$(call fuzz_run,$(n),20))
	@if [ -f $(FUZZ_DIR)/failed ]; then echo "== fuzz-smoke: failed: $$(cat $(FUZZ_DIR)/failed | tr '\n' ' ')"; exit 1; fi
