# make valgrind: memcheck over the whole test suite (issue 7). Included by the Makefile.
# Every suite of `make test` (unit, reference and the EXTRA_TEST_BIN hook) runs
# in-process (CK_FORK=no, so memcheck sees every test's allocations) under
# memcheck; a suite fails on any memory error or on a definite or indirect leak.
# tools/valgrind.supp suppresses exactly one known leak outside tumble (OSMesa's
# context creation), nothing else. Logs: $(BUILD)/valgrind/<suite>.log.
VALGRIND_SUPP := tools/valgrind.supp
# --trace-children: the render suite runs through a /bin/sh wrapper that execs
# the test binary; without it memcheck watched only the shell.
VALGRIND_FLAGS := --tool=memcheck --error-exitcode=97 --leak-check=full --show-leak-kinds=definite,indirect \
  --errors-for-leak-kinds=definite,indirect --suppressions=$(VALGRIND_SUPP) --num-callers=30 --trace-children=yes
# The viewer's smoke test is left out: it is a bash script that runs the SDL
# viewer (EGL on llvmpipe) under a 120 s timeout and greps its output, several
# processes of which only the viewer is ours. `make sanitize` covers the viewer.
VALGRIND_BIN = $(UNIT_BIN) $(REF_BIN) $(filter-out $(VIEWER_SMOKE),$(EXTRA_TEST_BIN))

.PHONY: valgrind
valgrind:
	@tools/deps.sh test valgrind $(EXTRA_TEST_DEPS)
	@$(MAKE) --no-print-directory $(VALGRIND_BIN)
	@mkdir -p $(BUILD)/valgrind
	@failed=""; n=0; for t in $(VALGRIND_BIN); do n=$$((n + 1)); log=$(BUILD)/valgrind/$$(basename $$t).log; \
	  if CK_FORK=no valgrind $(VALGRIND_FLAGS) --log-file=$$log $$t >$$log.out 2>&1; then r=ok; else r=FAILED; fi; \
	  grep -q 'ERROR SUMMARY' $$log || r="FAILED (memcheck did not watch the suite to its end)"; \
	  [ "$$r" = ok ] || failed="$$failed $$t"; \
	  echo "== $$t: $$r; $$(grep -h 'ERROR SUMMARY' $$log | sed 's/==[0-9]*== //'); $$(grep -h 'definitely lost:' $$log | sed 's/==[0-9]*== *//')"; \
	  [ "$$r" = ok ] || tail -n 30 $$log.out; done; \
	echo "== valgrind: $$n suites run, $$(echo $$failed | wc -w) failed$$failed"; [ -z "$$failed" ]
